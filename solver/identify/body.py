"""Body parts of a robot, read from its URDF tree: wheels, tracks, rotors, limbs, grippers.

:func:`detect_body` walks the joint/link tree of a :class:`~solver.identify.urdf.Urdf` with the
profile's patterns and thresholds:

1. Special joints first. *Wheels*: movable joints whose name or child link matches the wheel
   pattern, or that a drive plugin names (``<leftJoint>``). *Rotors*: the rotor pattern.
   *Gripper* joints: the gripper pattern, and everything below one (finger phalanges). Joints
   that cannot move (fixed, or revolute/prismatic with lower == upper, as RotorS mounts its
   sensors) and mimic joints (they follow another joint) are not actuated.
2. The remaining actuated joints form a contracted tree (fixed joints squeezed out). Maximal
   unbranched paths in it are *chains*: a chain that ends in a leaf is a *limb*, one that ends
   where the tree branches is *trunk* (a waist, a torso lift).
3. Each limb is a *leg*, *head* or *arm* by which pattern most of its joints and links match,
   within the profile's thresholds; an unnamed chain of at least ``arm_min_joints`` joints, or
   one ending in a gripper, is an arm. A limb carrying wheels, tracks or rotors (Pepper's
   hip/knee over its wheeled base, a tilt-rotor unit) is a *mount*, not a limb. Anything else
   (a flipper, a 2-joint pan unit without a name) is *other*.
4. Gazebo model plugins add drive, track and flight evidence (a quadrotor modelled with no
   rotor joints is still flying).

The result, :class:`Body`, holds the parts, the counts the structure rules read
(:meth:`Body.features`) and one plain sentence of evidence per finding.

Not here: deciding the structure (:mod:`solver.identify.structure`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from solver.identify.profile import Profile
from solver.identify.srdf import Srdf
from solver.identify.urdf import Joint, Urdf

__all__ = ["Body", "Limb", "detect_body"]

_ROTATING = ("continuous", "revolute")
_LIMB_JOINTS = ("revolute", "continuous", "prismatic")
LIMB_KINDS = ("leg", "arm", "head")


@dataclass(frozen=True, slots=True)
class Limb:
    """A terminal chain of actuated joints, proximal to distal."""

    kind: str  # leg, arm, head, mount, other
    joints: tuple[str, ...]
    base: str
    tip: str
    gripper: bool = False

    def describe(self) -> str:
        span = self.joints[0] if len(self.joints) == 1 else \
            f"{self.joints[0]} .. {self.joints[-1]}"
        text = f"{self.kind}: {len(self.joints)}-joint chain {self.base} -> {self.tip} ({span})"
        return text + (", ends in a gripper" if self.gripper else "")


@dataclass(frozen=True)
class Body:
    """The parts found in one robot description, with the evidence for each."""

    wheels: tuple[str, ...] = ()
    rotors: tuple[str, ...] = ()
    tracks: tuple[str, ...] = ()
    drive_plugins: tuple[str, ...] = ()
    flight_plugins: tuple[str, ...] = ()
    limbs: tuple[Limb, ...] = ()
    trunk: tuple[str, ...] = ()
    fingers: tuple[str, ...] = ()
    grippers: int = 0
    floating_base: tuple[str, ...] = ()
    planar_base: tuple[str, ...] = ()
    controlled_wheels: tuple[str, ...] = ()
    controlled_joints: tuple[str, ...] = ()

    def count(self, kind: str) -> int:
        return sum(1 for limb in self.limbs if limb.kind == kind)

    @property
    def mobile_base(self) -> bool:
        return bool(self.wheels or self.tracks or self.drive_plugins or self.planar_base)

    @property
    def flying(self) -> bool:
        return bool(self.rotors or self.flight_plugins)

    def features(self) -> dict[str, int]:
        """The counts and flags the profile's structure rules read."""
        return {
            "wheels": len(self.wheels), "tracks": len(self.tracks), "rotors": len(self.rotors),
            "arms": self.count("arm"), "legs": self.count("leg"), "heads": self.count("head"),
            "fingers": len(self.fingers), "grippers": self.grippers,
            "drive_plugins": len(self.drive_plugins),
            "flight_plugins": len(self.flight_plugins),
            "mobile_base": int(self.mobile_base), "flying": int(self.flying),
            "floating_base": int(bool(self.floating_base)),
        }

    def evidence(self, root: str) -> tuple[str, ...]:
        """Plain sentences a person can check against the URDF."""
        lines = []
        if self.wheels:
            lines.append(f"{len(self.wheels)} wheel joint(s): {_names(self.wheels)}")
        if self.tracks:
            lines.append(f"tracks: {_names(self.tracks)}")
        if self.drive_plugins:
            lines.append(f"drive plugin(s): {_names(self.drive_plugins)}")
        if self.rotors:
            lines.append(f"{len(self.rotors)} rotor joint(s): {_names(self.rotors)}")
        if self.flight_plugins:
            lines.append(f"flight plugin(s): {_names(self.flight_plugins)}")
        if self.planar_base:
            lines.append(f"planar base: {_names(self.planar_base)}")
        if self.floating_base:
            lines.append(f"floating base: {_names(self.floating_base)}")
        if self.trunk:
            lines.append(f"trunk joint(s) below the limbs: {_names(self.trunk)}")
        lines += [limb.describe() for limb in self.limbs]
        if self.fingers:
            lines.append(f"{len(self.fingers)} finger/gripper joint chain(s) on "
                         f"{self.grippers} hand(s)/gripper(s): {_names(self.fingers)}")
        if not lines:
            lines.append(f"no movable joints below {root}")
        return tuple(lines)


def _names(items: Iterable[str], limit: int = 4) -> str:
    names = list(items)
    shown = ", ".join(names[:limit])
    return shown + (f", ... ({len(names)} in all)" if len(names) > limit else "")


def detect_body(urdf: Urdf, profile: Profile, srdf: Srdf | None = None) -> Body:
    """The parts of ``urdf`` (see the module docstring); ``srdf`` adds its virtual joint."""
    return _Detector(urdf, profile).detect(srdf)


class _Detector:
    def __init__(self, urdf: Urdf, profile: Profile) -> None:
        self.urdf = urdf
        self.profile = profile

    def matches(self, part: str, joint: Joint) -> bool:
        pattern = self.profile.pattern(part)
        return pattern is not None and (pattern.search(joint.name)
                                        or pattern.search(joint.child))

    def plugin_matches(self, part: str, text: str) -> bool:
        pattern = self.profile.plugin_pattern(part)
        return pattern is not None and pattern.search(text)

    def detect(self, srdf: Srdf | None) -> Body:
        urdf = self.urdf
        drive = [p for p in urdf.plugins if self.plugin_matches("drive", f"{p.name} {p.filename}")]
        flight = [p for p in urdf.plugins
                  if self.plugin_matches("flight", f"{p.name} {p.filename}")]
        track_plugins = [p for p in urdf.plugins
                         if self.plugin_matches("track", f"{p.name} {p.filename}")]
        named_by_drive = {text for p in drive for _, text in p.params}
        wheels, rotors, grippers = [], [], set()
        for joint in urdf.joints:
            if not joint.movable or joint.type not in (*_ROTATING, "prismatic"):
                continue
            if joint.type in _ROTATING and self.matches("rotor", joint):
                rotors.append(joint.name)
            elif joint.type in _ROTATING and (self.matches("wheel", joint)
                                              or joint.name in named_by_drive):
                wheels.append(joint.name)
            elif self.matches("gripper", joint):
                grippers.add(joint.name)
        # Everything below a gripper joint belongs to the gripper (finger phalanges).
        for name in list(grippers):
            holder = urdf.joint(name)
            if holder is not None:
                grippers.update(j.name for j in urdf.subtree_joints(holder.child) if j.movable)
        tracks = [p.filename or p.name for p in track_plugins]
        tracks += [j.name for j in urdf.joints if self.matches("track", j)]
        special = set(wheels) | set(rotors) | grippers
        limbs, trunk, gripper_hosts = self._limbs(special, grippers)
        finger_roots = [name for name in sorted(grippers, key=self._order)
                        if (finger := urdf.joint(name)) is not None and finger.actuated
                        and not self._below_gripper(finger, grippers)]
        floating = [j.name for j in urdf.joints if j.type == "floating"]
        planar = [j.name for j in urdf.joints if j.type == "planar"]
        if srdf is not None:
            for virtual in srdf.virtual_joints:
                if virtual.type == "planar":
                    planar.append(f"SRDF virtual joint {virtual.name} (planar)")
                elif virtual.type == "floating":
                    floating.append(f"SRDF virtual joint {virtual.name} (floating)")
        controlled = urdf.controlled_joints
        limb_joints = [name for limb in limbs for name in limb.joints] + trunk
        return Body(
            wheels=tuple(wheels), rotors=tuple(rotors), tracks=tuple(dict.fromkeys(tracks)),
            drive_plugins=tuple(dict.fromkeys(p.filename or p.name for p in drive)),
            flight_plugins=tuple(dict.fromkeys(p.filename or p.name for p in flight)),
            limbs=tuple(limbs), trunk=tuple(trunk), fingers=tuple(finger_roots),
            grippers=len(gripper_hosts), floating_base=tuple(floating),
            planar_base=tuple(planar),
            controlled_wheels=tuple(w for w in wheels if w in controlled),
            controlled_joints=tuple(j for j in limb_joints if j in controlled))

    def _order(self, name: str) -> int:
        return next((i for i, j in enumerate(self.urdf.joints) if j.name == name), 0)

    def _below_gripper(self, joint: Joint, grippers: set[str]) -> bool:
        parent = self.urdf.parent_joint(joint.parent)
        while parent is not None:
            if parent.name in grippers and parent.actuated:
                return True
            parent = self.urdf.parent_joint(parent.parent)
        return False

    def _limbs(self, special: set[str], grippers: set[str]
               ) -> tuple[list[Limb], list[str], set[str]]:
        """Limbs and trunk joints of the contracted tree of actuated, non-special joints."""
        urdf = self.urdf
        children: dict[str, list[Joint]] = {}   # anchor ("" = root) -> limb joints below it
        carries: dict[str, set[str]] = {}       # anchor -> {"wheel", "rotor", "gripper", ...}
        hosts: set[str] = set()
        stack: list[tuple[str, str]] = [(urdf.root, "")]
        while stack:
            link, anchor = stack.pop()
            for joint in reversed(urdf.children(link)):
                below = anchor
                if joint.name in special:
                    kind = "gripper" if joint.name in grippers else \
                        ("rotor" if self.matches("rotor", joint) else "wheel")
                    carries.setdefault(anchor, set()).add(kind)
                    if kind == "gripper":
                        hosts.add(anchor)
                        continue  # the gripper's own subtree is not a limb
                elif joint.actuated and joint.type in _LIMB_JOINTS:
                    children.setdefault(anchor, []).append(joint)
                    below = joint.name
                stack.append((joint.child, below))
        for joints in children.values():
            joints.sort(key=lambda j: self._order(j.name))
        limbs: list[Limb] = []
        trunk: list[str] = []
        starts = list(children.get("", []))
        while starts:
            first = starts.pop(0)
            chain = [first]
            while len(children.get(chain[-1].name, [])) == 1:
                chain.append(children[chain[-1].name][0])
            branches = children.get(chain[-1].name, [])
            if branches:
                trunk.extend(j.name for j in chain)
                starts.extend(branches)
                continue
            marks = set().union(*(carries.get(j.name, set()) for j in chain))
            limbs.append(self._classify(chain, chain[0].parent, marks))
        limbs.sort(key=lambda limb: (LIMB_KINDS.index(limb.kind) if limb.kind in LIMB_KINDS
                                     else len(LIMB_KINDS), self._order(limb.joints[0])))
        return limbs, trunk, hosts

    def _classify(self, chain: list[Joint], base: str, marks: set[str]) -> Limb:
        names = tuple(j.name for j in chain)
        tip = self._tip(chain[-1])
        gripper = "gripper" in marks
        if marks & {"wheel", "rotor"}:
            return Limb("mount", names, base, tip, gripper)
        scores = {kind: sum(1 for j in chain if self.matches(kind, j)) for kind in LIMB_KINDS}
        if self._tip_matches("leg", chain[-1]):
            scores["leg"] += 1
        length = len(chain)
        ranked = sorted(LIMB_KINDS, key=lambda k: -scores[k])  # stable: leg, arm, head on ties
        for kind in ranked:
            if scores[kind] == 0:
                break
            if kind == "leg" and length >= self.profile.limb("leg_min_joints") and not gripper:
                return Limb("leg", names, base, tip, gripper)
            if kind == "head" and length <= self.profile.limb("head_max_joints") \
                    and not gripper:
                return Limb("head", names, base, tip, gripper)
            if kind == "arm" and (length >= self.profile.limb("arm_min_joints") or gripper):
                return Limb("arm", names, base, tip, gripper)
        if length >= self.profile.limb("arm_min_joints") or (gripper and length >= 2):
            return Limb("arm", names, base, tip, gripper)
        return Limb("other", names, base, tip, gripper)

    def _tip(self, joint: Joint) -> str:
        """The last link of a limb: follow fixed joints down while the path is unbranched."""
        link = joint.child
        while True:
            below = [j for j in self.urdf.children(link) if not j.movable]
            if len(self.urdf.children(link)) != 1 or len(below) != 1:
                return link
            link = below[0].child

    def _tip_matches(self, part: str, joint: Joint) -> bool:
        pattern = self.profile.pattern(part)
        if pattern is None:
            return False
        link = joint.child
        for below in self.urdf.subtree_joints(link):
            if not below.movable and pattern.search(below.child):
                return True
        return False
