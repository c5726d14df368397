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

Not here: deciding the structure (:mod:`solver.identify.classifier`).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, replace

from solver.identify.profile import PartMatcher, Profile
from solver.identify.srdf import Srdf
from solver.identify.urdf import Joint, Urdf

__all__ = ["Body", "Limb", "detect_body"]

_ROTATING = ("continuous", "revolute")
# A spherical (ball) joint is outside the URDF spec but real files have it: a shoulder, a hip.
_LIMB_JOINTS = ("revolute", "continuous", "prismatic", "spherical")
LIMB_KINDS = ("leg", "arm", "head")
# An unnamed pair of chains on the root this long, beside named arms higher up, are legs.
_LEG_BY_PLACE_JOINTS = 5


@dataclass(frozen=True, slots=True)
class Limb:
    """A terminal chain of actuated joints, proximal to distal."""

    kind: str  # leg, arm, head, mount, other
    joints: tuple[str, ...]
    base: str
    tip: str
    gripper: bool = False
    named: bool = False  # some joint or link of the chain names a leg, arm or head

    def describe(self) -> str:
        span = self.joints[0] if len(self.joints) == 1 else f"{self.joints[0]} .. {self.joints[-1]}"
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
    # Rotor-named leaf joints too few to fly (one spinning leaf is a motor or a tool).
    not_rotors: tuple[str, ...] = ()
    # Wheel joints of type fixed (a trimmed model): a mobile base, read with doubt.
    fixed_wheels: tuple[str, ...] = ()
    # Fixed rotor-named leaf joints of a body with no movable joint (a trimmed multirotor).
    fixed_rotors: tuple[str, ...] = ()

    def count(self, kind: str) -> int:
        return sum(1 for limb in self.limbs if limb.kind == kind)

    @property
    def mobile_base(self) -> bool:
        return bool(
            self.wheels
            or self.tracks
            or self.drive_plugins
            or self.planar_base
            or self.fixed_wheels
        )

    @property
    def weak_base(self) -> bool:
        """A mobile base known only from fixed wheels or planar (virtual) joints."""
        return self.mobile_base and not (self.wheels or self.tracks or self.drive_plugins)

    @property
    def flying(self) -> bool:
        return bool(self.rotors or self.flight_plugins or self.fixed_rotors)

    @property
    def weak_flight(self) -> bool:
        """Flying known only from fixed rotor-named links (a trimmed model)."""
        return self.flying and not (self.rotors or self.flight_plugins)

    def features(self) -> dict[str, int]:
        """The counts and flags the profile's structure rules read."""
        return {
            "wheels": len(self.wheels),
            "tracks": len(self.tracks),
            "rotors": len(self.rotors),
            "arms": self.count("arm"),
            "legs": self.count("leg"),
            "heads": self.count("head"),
            "fingers": len(self.fingers),
            "grippers": self.grippers,
            "drive_plugins": len(self.drive_plugins),
            "flight_plugins": len(self.flight_plugins),
            "mobile_base": int(self.mobile_base),
            "flying": int(self.flying),
            "floating_base": int(bool(self.floating_base)),
            "weak_base": int(self.weak_base),
            "weak_flight": int(self.weak_flight),
        }

    def _trimmed(self) -> list[str]:
        """The evidence of a model trimmed of its moving parts: fixed wheels, fixed rotors."""
        lines = []
        if self.fixed_wheels:
            lines.append(
                f"{len(self.fixed_wheels)} fixed wheel joint(s) (a trimmed model): "
                f"{_names(self.fixed_wheels)}"
            )
        if self.fixed_rotors:
            lines.append(
                f"{len(self.fixed_rotors)} fixed rotor joint(s) on a body with no movable "
                f"joint (a trimmed model): {_names(self.fixed_rotors)}"
            )
        return lines

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
        lines += self._trimmed()
        if self.planar_base:
            lines.append(f"planar base: {_names(self.planar_base)}")
        if self.floating_base:
            lines.append(f"floating base: {_names(self.floating_base)}")
        if self.trunk:
            lines.append(f"trunk joint(s) below the limbs: {_names(self.trunk)}")
        lines += [limb.describe() for limb in self.limbs]
        if self.fingers:
            lines.append(
                f"{len(self.fingers)} finger/gripper joint chain(s) on "
                f"{self.grippers} hand(s)/gripper(s): {_names(self.fingers)}"
            )
        if self.not_rotors:
            lines.append(
                f"not flight: {len(self.not_rotors)} rotor-named joint(s) "
                f"({_names(self.not_rotors)}), too few to fly"
            )
        if not lines:
            lines.append(f"no movable joints below {root}")
        return tuple(lines)


def _main_axis(axis: tuple[float, float, float]) -> int:
    """0, 1 or 2 for an axis along x, y or z; -1 for a slanted one."""
    sizes = [abs(v) for v in axis]
    top = max(sizes)
    return sizes.index(top) if top > 0 and sorted(sizes)[1] < 1e-6 else -1


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
        # Document order of each joint, for deterministic listings (one pass, not one per ask).
        self.index = {joint.name: i for i, joint in enumerate(urdf.joints)}
        self.parts_of = PartMatcher(profile.patterns)
        # Links with a movable joint somewhere below them (a rotor is a leaf: none below).
        self.moving_below: set[str] = set()
        for joint in urdf.joints:
            if joint.movable:
                link: str | None = joint.parent
                while link is not None and link not in self.moving_below:
                    self.moving_below.add(link)
                    parent = urdf.parent_joint(link)
                    link = None if parent is None else parent.parent

    def matches(self, part: str, joint: Joint) -> bool:
        return part in self.parts_of(joint.name) or part in self.parts_of(joint.child)

    def plugin_matches(self, part: str, text: str) -> bool:
        pattern = self.profile.plugin_pattern(part)
        return pattern is not None and bool(pattern.search(text))

    def gripper_joint(self, joint: Joint) -> bool:
        """Named as a gripper, or on or into a link named as one; a joint whose own name says
        it is an arm joint (``left_wrist_roll_joint`` into ``left_hand_roll_link``) stays one."""
        own = self.parts_of(joint.name)
        if "gripper" in own:
            return True
        return "arm" not in own and ("gripper" in self.parts_of(joint.child) or self.on_palm(joint))

    def on_palm(self, joint: Joint) -> bool:
        """A movable joint on a link named as a hand or palm moves a finger."""
        return "gripper" in self.parts_of(joint.parent)

    def detect(self, srdf: Srdf | None) -> Body:
        urdf = self.urdf
        drive = [p for p in urdf.plugins if self.plugin_matches("drive", f"{p.name} {p.filename}")]
        flight = [
            p for p in urdf.plugins if self.plugin_matches("flight", f"{p.name} {p.filename}")
        ]
        track_plugins = [
            p for p in urdf.plugins if self.plugin_matches("track", f"{p.name} {p.filename}")
        ]
        named_by_drive = {text for p in drive for _, text in p.params}
        wheels, rotors, grippers = [], [], set()
        for joint in urdf.joints:
            if not joint.movable or joint.type not in (*_ROTATING, "prismatic"):
                continue
            # Wheels first: a wheel's motor link may be named *_rotor.
            if joint.type in _ROTATING and (
                self.matches("wheel", joint) or joint.name in named_by_drive
            ):
                wheels.append(joint.name)
            elif (
                joint.type in _ROTATING
                and self.matches("rotor", joint)
                and joint.child not in self.moving_below
            ):
                rotors.append(joint.name)
            elif self.gripper_joint(joint):
                grippers.add(joint.name)
        wheels += self._unnamed_wheels({*wheels, *rotors, *grippers})
        not_rotors: list[str] = []
        if len(rotors) < self.profile.limb("min_rotors"):
            # One spinning leaf is a motor or a tool, not flight.
            not_rotors, rotors = rotors, []
        tracks = [p.filename or p.name for p in track_plugins]
        tracks += [j.name for j in urdf.joints if self.matches("track", j)]
        fixed_wheels = (
            [j.name for j in urdf.joints if j.type == "fixed" and self.matches("wheel", j)]
            if not wheels
            else []
        )
        # A model trimmed of every movable joint may still name its propellers.
        fixed_rotors = [
            j.name
            for j in urdf.joints
            if j.type == "fixed" and not urdf.children(j.child) and self.matches("rotor", j)
        ]
        if any(j.movable for j in urdf.joints) or len(fixed_rotors) < self.profile.limb(
            "min_rotors"
        ):
            fixed_rotors = []
        floating = [j.name for j in urdf.joints if j.type == "floating"]
        planar = [j.name for j in urdf.joints if j.type == "planar"]
        placing = self._root_axes()
        if len(placing) == 6:
            floating.append(f"root joints {', '.join(placing)} (x, y, z and three turns)")
        elif len(placing) == 3:
            planar.append(f"root joints {', '.join(placing)} (x, y and a turn about z)")
        base = set(wheels) | set(rotors) | set(placing)
        grippers = self._gripper_closure(grippers)
        limbs, trunk, gripper_hosts = self._limbs(base | grippers, grippers)
        fingers = self._finger_groups(limbs)
        if fingers:
            grippers = self._gripper_closure(grippers | fingers)
            limbs, trunk, gripper_hosts = self._limbs(base | grippers, grippers)
        limbs = self._legs_at_the_pelvis(limbs)
        finger_tips = self._finger_tips(grippers)
        for virtual in srdf.virtual_joints if srdf is not None else ():
            if virtual.type in ("planar", "floating"):
                (planar if virtual.type == "planar" else floating).append(
                    f"SRDF virtual joint {virtual.name} ({virtual.type})"
                )
        controlled = urdf.controlled_joints
        limb_joints = [name for limb in limbs for name in limb.joints] + trunk
        return Body(
            wheels=tuple(wheels),
            rotors=tuple(rotors),
            tracks=tuple(dict.fromkeys(tracks)),
            drive_plugins=tuple(dict.fromkeys(p.filename or p.name for p in drive)),
            flight_plugins=tuple(dict.fromkeys(p.filename or p.name for p in flight)),
            limbs=tuple(limbs),
            trunk=tuple(trunk),
            fingers=tuple(finger_tips),
            grippers=len(gripper_hosts),
            floating_base=tuple(floating),
            planar_base=tuple(planar),
            controlled_wheels=tuple(w for w in wheels if w in controlled),
            controlled_joints=tuple(j for j in limb_joints if j in controlled),
            not_rotors=tuple(not_rotors),
            fixed_wheels=tuple(fixed_wheels),
            fixed_rotors=tuple(fixed_rotors),
        )

    def _unnamed_wheels(self, taken: set[str]) -> list[str]:
        """Unnamed spinning leaves below a link, on both its sides: wheels.

        A base whose wheel joints carry no name (``fl_joint`` on ``fl_Link``) still has them
        where wheels are: continuous joints (no limits, they turn for ever) that carry nothing
        that moves, hanging below the link they are on, at least one on each side of it.
        Fingers have limits; rotors sit level with or above their body.
        """
        below: dict[str, list[Joint]] = {}
        for joint in self.urdf.joints:
            if (
                joint.type == "continuous"
                and joint.actuated
                and joint.name not in taken
                and joint.child not in self.moving_below
                and not (self.parts_of(joint.name) | self.parts_of(joint.child))
                and joint.origin[2] < 0
            ):
                below.setdefault(joint.parent, []).append(joint)
        found: list[str] = []
        for joints in below.values():
            sides = {j.origin[1] > 0 for j in joints if j.origin[1] != 0}
            if len(joints) >= 2 and sides == {True, False}:
                found.extend(j.name for j in joints)
        return found

    def _legs_at_the_pelvis(self, limbs: list[Limb]) -> list[Limb]:
        """Two unnamed long chains on the root, below a body whose arms hang higher: legs.

        A humanoid's legs hang from its pelvis (the root) and its arms from the torso above
        the waist; when the joint names say nothing (``LHY``, ``LKP``), that is where they are.
        Only a pair of equal chains of at least five joints counts, and only beside two or more
        arms that are named or end in a gripper and do not hang from the root.
        """
        pelvis = [
            limb
            for limb in limbs
            if limb.kind == "arm"
            and not limb.named
            and not limb.gripper
            and limb.base == self.urdf.root
            and len(limb.joints) >= _LEG_BY_PLACE_JOINTS
        ]
        arms = [
            limb
            for limb in limbs
            if limb.kind == "arm" and (limb.named or limb.gripper) and limb.base != self.urdf.root
        ]
        if len(pelvis) != 2 or len(pelvis[0].joints) != len(pelvis[1].joints) or len(arms) < 2:
            return limbs
        legs = [replace(limb, kind="leg") for limb in pelvis]
        kept = [limb for limb in limbs if limb not in pelvis] + legs
        return sorted(
            kept,
            key=lambda limb: (
                LIMB_KINDS.index(limb.kind) if limb.kind in LIMB_KINDS else len(LIMB_KINDS),
                self._order(limb.joints[0]),
            ),
        )

    def _root_axes(self) -> list[str]:
        """Joints at the root that only place the body: x, y and a turn about z (planar), or
        x, y, z and three turns (a simulated floating base); [] when the root is not so.
        """
        chain: list[Joint] = []
        link = self.urdf.root
        while len(chain) < 6:
            below = self.urdf.children(link)
            if len(below) != 1:
                break
            joint = below[0]
            link = joint.child
            if joint.type == "fixed":
                continue
            if joint.type not in ("prismatic", "revolute", "continuous") or not joint.actuated:
                break
            chain.append(joint)
        slides = {_main_axis(j.axis) for j in chain[:3] if j.type == "prismatic"}
        turns = [_main_axis(j.axis) for j in chain[:3] if j.type != "prismatic"]
        if len(chain) >= 3 and slides == {0, 1} and turns == [2]:
            return [j.name for j in chain[:3]]
        slides = {_main_axis(j.axis) for j in chain if j.type == "prismatic"}
        turns = [_main_axis(j.axis) for j in chain if j.type != "prismatic"]
        if len(chain) == 6 and slides == {0, 1, 2} and sorted(turns) == [0, 1, 2]:
            return [j.name for j in chain]
        return []

    def _order(self, name: str) -> int:
        return self.index.get(name, 0)

    def _gripper_closure(self, grippers: set[str]) -> set[str]:
        """``grippers`` and every movable joint below one (finger phalanges); one pass."""
        found = set(grippers)
        stack = [(self.urdf.root, False)]
        while stack:
            link, inside = stack.pop()
            for joint in self.urdf.children(link):
                below = inside or joint.name in grippers
                if inside and joint.movable:
                    found.add(joint.name)
                stack.append((joint.child, below))
        return found

    def _finger_tips(self, grippers: set[str]) -> list[str]:
        """Gripper joints with no movable gripper joint below: one per finger."""
        above: set[str] = set()
        for name in grippers:
            joint = self.urdf.joint(name)
            if joint is None or not joint.movable:
                continue
            parent = self.urdf.parent_joint(joint.parent)
            while parent is not None and parent.name not in above:
                above.add(parent.name)
                parent = self.urdf.parent_joint(parent.parent)
        tips = [
            name
            for name in grippers
            if name not in above and (joint := self.urdf.joint(name)) is not None and joint.movable
        ]
        return sorted(tips, key=self._order)

    def _finger_groups(self, limbs: list[Limb]) -> set[str]:
        """Joints of unnamed short chains hanging from one link in threes or more: fingers
        (also where each ends in a named fingertip).

        A claw or a hand whose fingers carry no names still has them side by side on a palm;
        arms and legs on one link come in ones and twos.
        """
        by_base: dict[str, list[Limb]] = {}
        longest = self.profile.limb("finger_max_joints")
        for limb in limbs:
            if limb.kind in ("arm", "other") and not limb.named and len(limb.joints) <= longest:
                by_base.setdefault(limb.base, []).append(limb)
        found: set[str] = set()
        for group in by_base.values():
            if len(group) >= self.profile.limb("hand_min_fingers"):
                found.update(name for limb in group for name in limb.joints)
        return found

    def _limbs(
        self, special: set[str], grippers: set[str]
    ) -> tuple[list[Limb], list[str], set[str]]:
        """Limbs and trunk joints of the contracted tree of actuated, non-special joints."""
        urdf = self.urdf
        children: dict[str, list[Joint]] = {}  # anchor ("" = root) -> limb joints below it
        carries: dict[str, set[str]] = {}  # anchor -> {"wheel", "rotor", "gripper", ...}
        hosts: set[str] = set()
        stack: list[tuple[str, str]] = [(urdf.root, "")]
        while stack:
            link, anchor = stack.pop()
            for joint in reversed(urdf.children(link)):
                below = anchor
                if joint.name in special:
                    kind = (
                        "gripper"
                        if joint.name in grippers
                        else ("rotor" if self.matches("rotor", joint) else "wheel")
                    )
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
        starts = deque(children.get("", []))
        while starts:
            first = starts.popleft()
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
        limbs.sort(
            key=lambda limb: (
                LIMB_KINDS.index(limb.kind) if limb.kind in LIMB_KINDS else len(LIMB_KINDS),
                self._order(limb.joints[0]),
            )
        )
        return limbs, trunk, hosts

    def _classify(self, chain: list[Joint], base: str, marks: set[str]) -> Limb:
        names = tuple(j.name for j in chain)
        tip = self._tip(chain[-1])
        gripper = "gripper" in marks
        if marks & {"wheel", "rotor"}:
            return Limb("mount", names, base, tip, gripper)
        named_parts = [self.parts_of(j.name) | self.parts_of(j.child) for j in chain]
        scores = {kind: sum(1 for parts in named_parts if kind in parts) for kind in LIMB_KINDS}
        if self._tip_matches("leg", chain[-1]):
            scores["leg"] += 1
        named = any(scores.values())
        # Degrees of freedom, not joints: a ball-joint shoulder moves like three hinges.
        length = sum(3 if j.type == "spherical" else 1 for j in chain)
        ranked = sorted(LIMB_KINDS, key=lambda k: -scores[k])  # stable: leg, arm, head on ties
        for kind in ranked:
            if scores[kind] == 0:
                break
            # Leg names win over a gripper at the end: a leg may end in a gripper.
            if kind == "leg" and length >= self.profile.limb("leg_min_joints"):
                return Limb("leg", names, base, tip, gripper, named)
            if kind == "head" and length <= self.profile.limb("head_max_joints") and not gripper:
                return Limb("head", names, base, tip, gripper, named)
            if kind == "arm" and (length >= self.profile.limb("arm_min_joints") or gripper):
                return Limb("arm", names, base, tip, gripper, named)
        if length >= self.profile.limb("arm_min_joints") or (gripper and length >= 2):
            return Limb("arm", names, base, tip, gripper, named)
        return Limb("other", names, base, tip, gripper, named)

    def _tip(self, joint: Joint) -> str:
        """The last link of a limb: follow fixed joints down while the path is unbranched."""
        link = joint.child
        while True:
            below = [j for j in self.urdf.children(link) if not j.movable]
            if len(self.urdf.children(link)) != 1 or len(below) != 1:
                return link
            link = below[0].child

    def _tip_matches(self, part: str, joint: Joint) -> bool:
        return any(
            not below.movable and part in self.parts_of(below.child)
            for below in self.urdf.subtree_joints(joint.child)
        )
