"""Body parts of a robot, read from what its joints do: wheels, rotors, thrusters, limbs, hands.

:func:`detect_body` reads a :class:`~solver.identify.readers.urdf.Urdf` with the profile's patterns
and
thresholds, actuation first and names last:

1. *Joint roles* (:mod:`solver.identify.roles`): every moving joint a plugin names (a drive
   plugin's wheels, a motor model's rotors, a thruster plugin's thrusters, a fin plugin's fins),
   then shapes (a vertical swivel carrying one wheel is a caster) and names. Wheels without
   names are told by where they are. Joints that cannot move (fixed, or revolute/prismatic with
   lower == upper) and mimic joints (they follow another joint) are not actuated.
2. The remaining actuated joints form a contracted tree (fixed joints squeezed out). Maximal
   unbranched paths in it are *chains*: a chain that ends in a leaf is a *limb*, one that ends
   where the tree branches is *trunk* (a waist, a torso lift).
3. Each limb is a *leg*, *head* or *arm* by which pattern most of its joints and links match,
   within the profile's thresholds; an unnamed chain of at least ``arm_min_joints`` joints, or
   one ending in a gripper, is an arm; on a flying body any chain of two joints or more is. A
   limb carrying wheels, rotors or thrusters (Pepper's hip/knee over its wheeled base, a
   tilt-rotor unit, a boat's steered engine) is a *mount*, not a limb, except legs that each
   end in a wheel, three or more of them (a wheel-legged robot walks on them). Anything else
   (a flipper, a 2-joint pan unit without a name) is *other*.
4. Gazebo model plugins add drive, track, flight and water evidence (a quadrotor modelled with
   no rotor joints is still flying; a hull's buoyancy says it floats).

The result, :class:`Body`, holds the parts, each joint's :class:`~solver.identify.roles.Role`
with the evidence that decided it, the counts the structure rules read (:meth:`Body.features`)
and one plain sentence of evidence per finding.

Not here: deciding the structure (:mod:`solver.identify.classifier`).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from solver.identify.profile import PartMatcher, Profile
from solver.identify.readers.urdf import Joint, Urdf
from solver.identify.roles import Role, RoleReader, main_axis
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.identify.readers.srdf import Srdf

__all__ = ["Body", "Limb", "detect_body"]

_ROTATING = ("continuous", "revolute")
# A spherical (ball) joint is outside the URDF spec but real files have it: a shoulder, a hip.
_LIMB_JOINTS = ("revolute", "continuous", "prismatic", "spherical")
LIMB_KINDS = ("leg", "arm", "head")
# An unnamed pair of chains on the root this long, beside named arms higher up, are legs.
_LEG_BY_PLACE_JOINTS = 5
# Legs that each end in a wheel are legs (a wheel-legged robot) when there are this many.
_WHEEL_LEGS = 3
# On a flying body, a chain this long hanging from it is an arm (an aerial manipulator's arm).
_FLYING_ARM_JOINTS = 2
# Roles a single joint plays that make it part of the base, not of a limb.
_MOUNTED = ("wheel", "steering", "caster", "rotor", "thruster")
# Limbs whose joints a person commands one by one (Joint control); not heads, not mounts.
_COMMANDED = ("arm", "leg", "other")
_Z_AXIS = 2


@dataclass(frozen=True, slots=True)
class Limb:
    """A terminal chain of actuated joints, proximal to distal."""

    kind: str  # leg, arm, head, mount, other
    joints: tuple[str, ...]
    base: str
    tip: str
    gripper: bool = False
    named: bool = False  # some joint or link of the chain names a leg, arm or head
    why: str = ""  # the evidence that decided its kind

    def describe(self) -> str:
        first, last = shown(self.joints[0]), shown(self.joints[-1])
        span = first if len(self.joints) == 1 else f"{first} .. {last}"
        chain = f"{shown(self.base)} -> {shown(self.tip)}"
        text = f"{self.kind}: {len(self.joints)}-joint chain {chain} ({span})"
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
    # Fixed rotor-named leaf links on the body (a trimmed multirotor): flying, with doubt.
    fixed_rotors: tuple[str, ...] = ()
    thrusters: tuple[str, ...] = ()
    fins: tuple[str, ...] = ()
    casters: tuple[str, ...] = ()
    # Wings and ailerons: fixed links (a fixed-wing model without joints) or moving surfaces.
    wings: tuple[str, ...] = ()
    # Plugins of a body in water (thrusters, hydrodynamics, buoyancy) and hints of a hull at
    # the surface (a surface plugin, <metacentric_width>, wind on its buoyancy).
    marine_plugins: tuple[str, ...] = ()
    surface_hints: tuple[str, ...] = ()
    # What a body below the surface has: a buoyancy or hydrodynamics plugin, a thruster plugin,
    # a DVL or pressure sensor. A body in water by thruster names alone has none.
    underwater_hints: tuple[str, ...] = ()
    # Flying known only from a model plugin's parameters (a vehicle plugin of its own).
    flight_hints: tuple[str, ...] = ()
    finger_motions: int = 0
    # Every moving joint's role and the evidence that decided it.
    roles: tuple[Role, ...] = field(default=(), compare=False)

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
            or self.casters
        )

    @property
    def weak_base(self) -> bool:
        """A mobile base known only from fixed wheels or planar (virtual) joints."""
        return self.mobile_base and not (
            self.wheels or self.tracks or self.drive_plugins or self.casters
        )

    @property
    def marine(self) -> bool:
        return bool(self.thrusters or self.marine_plugins)

    @property
    def flying(self) -> bool:
        if self.marine:
            return False
        return bool(
            self.rotors
            or self.flight_plugins
            or self.fixed_rotors
            or self.aero
            or self.flight_hints
        )

    @property
    def aero(self) -> bool:
        """Wings and control surfaces, two or more, one of them a wing: a fixed-wing craft."""
        return bool(self.wings) and len({*self.wings, *self.fins}) >= 2

    @property
    def weak_flight(self) -> bool:
        """Flying known only from fixed rotor links, wing names or a plugin's parameters."""
        return self.flying and not (self.rotors or self.flight_plugins or self.fins)

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
            "thrusters": len(self.thrusters),
            "fins": len(self.fins),
            "casters": len(self.casters),
            "finger_motions": self.finger_motions,
            "marine": int(self.marine),
            "surface": int(bool(self.surface_hints)),
            "underwater": int(bool(self.underwater_hints)),
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
                f"{len(self.fixed_rotors)} fixed rotor link(s) on the body (a trimmed model): "
                f"{_names(self.fixed_rotors)}"
            )
        if self.wings:
            lines.append(f"wing and control-surface link(s): {_names(self.wings)}")
        if self.flight_hints:
            lines.append(f"flight named in plugin parameters: {_names(self.flight_hints)}")
        return lines

    def _water(self) -> list[str]:
        lines = []
        if self.thrusters:
            lines.append(f"{len(self.thrusters)} thruster(s): {_names(self.thrusters)}")
        if self.marine_plugins:
            lines.append(f"water plugin(s): {_names(self.marine_plugins)}")
        if self.surface_hints:
            lines.append(f"floats at the surface: {_names(self.surface_hints)}")
        elif self.underwater_hints:
            lines.append(f"below the surface: {_names(self.underwater_hints)}")
        elif self.marine:
            lines.append(
                "in water by thruster names alone: no buoyancy or hydrodynamics plugin, "
                "no thruster plugin, no DVL or pressure sensor"
            )
        return lines

    def _ground(self) -> list[str]:
        lines = []
        if self.wheels:
            lines.append(f"{len(self.wheels)} wheel joint(s): {_names(self.wheels)}")
        if self.casters:
            lines.append(f"{len(self.casters)} caster joint(s): {_names(self.casters)}")
        if self.tracks:
            lines.append(f"tracks: {_names(self.tracks)}")
        if self.drive_plugins:
            lines.append(f"drive plugin(s): {_names(self.drive_plugins)}")
        return lines

    def evidence(self, root: str) -> tuple[str, ...]:
        """Plain sentences a person can check against the URDF."""
        lines = self._ground()
        if self.rotors:
            lines.append(f"{len(self.rotors)} rotor joint(s): {_names(self.rotors)}")
        if self.flight_plugins:
            lines.append(f"flight plugin(s): {_names(self.flight_plugins)}")
        if self.fins:
            lines.append(f"{len(self.fins)} fin / control-surface joint(s): {_names(self.fins)}")
        lines += self._water()
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

    def role_lines(self) -> tuple[str, ...]:
        """One line per role: its joints and the evidence that decided the first of them."""
        grouped: dict[str, list[Role]] = {}
        for role in self.roles:
            grouped.setdefault(role.role, []).append(role)
        lines = []
        for name, roles in grouped.items():
            reasons = list(dict.fromkeys(r.evidence for r in roles))
            because = reasons[0] + (f"; and {len(reasons) - 1} more" if len(reasons) > 1 else "")
            lines.append(f"{name}: {_names(r.joint for r in roles)} ({because})")
        return tuple(lines)


def _names(items: Iterable[str], limit: int = 4) -> str:
    names = list(items)
    listed = ", ".join(shown(name) for name in names[:limit])
    return listed + (f", ... ({len(names)} in all)" if len(names) > limit else "")


def detect_body(urdf: Urdf, profile: Profile, srdf: Srdf | None = None) -> Body:
    """The parts of ``urdf`` (see the module docstring); ``srdf`` adds its virtual joint."""
    return _Detector(urdf, profile).detect(srdf)


@dataclass
class _Parts:
    """What :meth:`_Detector.detect` gathers, step by step, before it becomes a :class:`Body`."""

    roles: dict[str, Role] = field(default_factory=dict)
    limbs: list[Limb] = field(default_factory=list)
    trunk: list[str] = field(default_factory=list)
    grippers: set[str] = field(default_factory=set)
    hosts: set[str] = field(default_factory=set)
    floating: list[str] = field(default_factory=list)
    planar: list[str] = field(default_factory=list)
    placing: list[str] = field(default_factory=list)

    def of(self, role: str) -> list[str]:
        return [name for name, r in self.roles.items() if r.role == role]


class _Detector:
    def __init__(self, urdf: Urdf, profile: Profile) -> None:
        self.urdf = urdf
        self.profile = profile
        # Document order of each joint, for deterministic listings (one pass, not one per ask).
        self.index = {joint.name: i for i, joint in enumerate(urdf.joints)}
        self.parts_of = PartMatcher(profile.patterns)
        self.reader = RoleReader(urdf, profile, self.parts_of)
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

    def labels(self, part: str) -> tuple[str, ...]:
        return tuple(
            dict.fromkeys(self.reader.plugin_label(p) for p in self.reader.plugins_of(part))
        )

    def detect(self, srdf: Srdf | None) -> Body:
        parts = _Parts(roles=self._joint_roles())
        self._placing(parts, srdf)
        self._body_parts(parts)
        finger_tips = self._finger_tips(parts.grippers)
        controlled = self.urdf.controlled_joints
        wheels = parts.of("wheel")
        return Body(
            wheels=tuple(wheels),
            rotors=tuple(parts.of("rotor")),
            tracks=self._tracks(),
            drive_plugins=self.labels("drive"),
            flight_plugins=self.labels("flight"),
            limbs=tuple(parts.limbs),
            trunk=tuple(parts.trunk),
            fingers=tuple(finger_tips),
            grippers=len(parts.hosts),
            floating_base=tuple(parts.floating),
            planar_base=tuple(parts.planar),
            controlled_wheels=tuple(w for w in wheels if w in controlled),
            controlled_joints=tuple(j for j in self._commanded(parts) if j in controlled),
            not_rotors=tuple(self._not_rotors(parts)),
            fixed_wheels=tuple(self._fixed_wheels(parts)),
            fixed_rotors=tuple(self._fixed_rotors()),
            thrusters=tuple(parts.of("thruster") + self._listed_thrusters(parts)),
            fins=tuple(parts.of("fin")),
            casters=tuple(parts.of("caster")),
            wings=tuple(self._wings(parts)),
            marine_plugins=(*self.labels("thruster"), *self.labels("marine")),
            surface_hints=self._surface_hints(),
            underwater_hints=self._underwater_hints(),
            flight_hints=self._flight_hints(parts),
            finger_motions=sum(
                1 for name in parts.grippers if (j := self.urdf.joint(name)) and j.actuated
            ),
            roles=self._all_roles(parts),
        )

    def _commanded(self, parts: _Parts) -> list[str]:
        """Joints a person commands one by one: those of arms, legs and other limbs, and the
        trunk joints that carry one. A head points a sensor (a pan/tilt camera); a mount and a
        trunk carrying only mounts move wheels, rotors or thrusters (a transformable
        multirotor's frame, a tilting rotor): the vehicle's own motion, not joint control.
        """
        limbs = [limb for limb in parts.limbs if limb.kind in _COMMANDED]
        joints = [name for limb in limbs for name in limb.joints]
        firsts = {limb.joints[0] for limb in limbs}
        for name in parts.trunk:
            trunk = self.urdf.joint(name)
            if trunk is not None and any(
                j.name in firsts for j in self.urdf.subtree_joints(trunk.child)
            ):
                joints.append(name)
        return joints

    # -- single-joint roles ------------------------------------------------------------------

    def _joint_roles(self) -> dict[str, Role]:
        """Wheels, casters, rotors, thrusters, fins and gripper joints, each with its evidence."""
        roles: dict[str, Role] = {}
        for joint in self.urdf.joints:
            role = self.reader.read(joint, self.moving_below)
            if role is not None:
                roles[joint.name] = role
        for name in self._unnamed_wheels(set(roles)):
            roles[name] = Role(
                name, "wheel", "an unnamed endless leaf below its link, wheels on both sides"
            )
        roles.update(self.reader.casters({n: r for n, r in roles.items() if r.role == "wheel"}))
        for name, role in list(roles.items()):
            driven = self.urdf.joint(name)
            if role.role == "caster" and driven is not None and name in self.urdf.controlled_joints:
                # A driven caster is no caster: its swivel steers, its wheels drive.
                if main_axis(driven.axis) == _Z_AXIS:
                    roles[name] = Role(name, "steering", "a vertical swivel with a transmission")
                else:
                    roles[name] = Role(name, "wheel", "a caster's wheel with a transmission")
        rotors = [n for n, r in roles.items() if r.role == "rotor"]
        if rotors and len(rotors) < self.profile.limb("min_rotors"):
            for name in rotors:  # one spinning leaf is a motor or a tool, not flight
                del roles[name]
        grippers = self._gripper_closure({n for n, r in roles.items() if r.role == "gripper"})
        for name in grippers - set(roles):
            roles[name] = Role(name, "gripper", "moves a finger: below a gripper joint")
        return roles

    def _not_rotors(self, parts: _Parts) -> list[str]:
        return [
            j.name
            for j in self.urdf.joints
            if j.movable
            and j.type in _ROTATING
            and j.name not in parts.roles
            and self.matches("rotor", j)
            and not self.matches("wheel", j)
            and j.child not in self.moving_below
        ]

    def _listed_thrusters(self, parts: _Parts) -> list[str]:
        """Thrusters a thruster plugin lists by a link of no moving joint (a hull's list)."""
        links = {link.name for link in self.urdf.links}
        found = []
        for plugin in self.reader.plugins_of("thruster"):
            named = [text for tag, text in plugin.params if text in links]
            joints = [self.urdf.parent_joint(link) for link in named]
            if not any(j is not None and j.name in parts.roles for j in joints):
                found += [f"{link} ({self.reader.plugin_label(plugin)})" for link in named][:1]
        return found

    def _tracks(self) -> tuple[str, ...]:
        tracks = list(self.labels("track"))
        tracks += [j.name for j in self.urdf.joints if self.matches("track", j)]
        return tuple(dict.fromkeys(tracks))

    def _fixed_wheels(self, parts: _Parts) -> list[str]:
        if parts.of("wheel"):
            return []
        return [j.name for j in self.urdf.joints if j.type == "fixed" and self.matches("wheel", j)]

    def _fixed_rotors(self) -> list[str]:
        """Rotor-named leaf links fixed to a part no joint moves (a trimmed multirotor).

        Not on a body with legs or wheels: there a fixed ``*_rotor`` link is a motor's.
        """
        legs_or_wheels = any(
            j.movable and (self.matches("leg", j) or self.matches("wheel", j))
            for j in self.urdf.joints
        )
        if self.reader.marine or legs_or_wheels:
            return []
        moved = self._moved_links()
        found = [
            j.name
            for j in self.urdf.joints
            if j.type == "fixed"
            and not self.urdf.children(j.child)
            and j.parent not in moved
            and self.matches("rotor", j)
        ]
        return found if len(found) >= self.profile.limb("min_rotors") else []

    def _moved_links(self) -> set[str]:
        """Links some movable joint moves (below a movable joint)."""
        moved: set[str] = set()
        stack = [(self.urdf.root, False)]
        while stack:
            link, inside = stack.pop()
            if inside:
                moved.add(link)
            for joint in self.urdf.children(link):
                stack.append((joint.child, inside or joint.movable))
        return moved

    def _wings(self, parts: _Parts) -> list[str]:
        """Wings and ailerons (fixed links, or fin joints named so) and, beside a wing, fixed
        control surfaces (a tail, a rudder)."""
        if self.reader.marine:
            return []
        fixed = [j for j in self.urdf.joints if not j.movable]
        wings = [j.child for j in fixed if "wing" in self.parts_of(j.child)]
        wings += [
            n for n in parts.of("fin") if (j := self.urdf.joint(n)) and self.matches("wing", j)
        ]
        surfaces = [j.child for j in fixed if "fin" in self.parts_of(j.child)]
        return wings + surfaces if wings else []

    def _surface_hints(self) -> tuple[str, ...]:
        pattern = self.profile.plugin_pattern("surface")
        if pattern is None or not (self.reader.marine):
            return ()
        hints = list(self.labels("surface"))
        hints += sorted(tag for tag in self.urdf.tags if pattern.search(tag))
        return tuple(dict.fromkeys(hints))

    def _underwater_hints(self) -> tuple[str, ...]:
        """Thruster and underwater plugins, and sensors (by type, name or plugin) the profile's
        ``underwater`` pattern reads: a DVL, a pressure sensor."""
        pattern = self.profile.plugin_pattern("underwater")
        if not self.reader.marine:
            return ()
        hints = [*self.labels("thruster"), *self.labels("underwater")]
        if pattern is not None:
            hints += [
                sensor.name
                for sensor in self.urdf.sensors
                if pattern.search(f"{sensor.type} {sensor.device_text}")
            ]
        return tuple(dict.fromkeys(hints))

    def _flight_hints(self, parts: _Parts) -> tuple[str, ...]:
        """Plugins whose parameters use the flight vocabulary (a vehicle plugin of its own that
        sets a drone's topics). Not on a body that moves on the ground or walks: there a word
        such as ``drone`` in a parameter is a name (another robot's namespace), not flight.
        """
        pattern = self.profile.plugin_pattern("flight")
        walks = any(limb.kind == "leg" for limb in parts.limbs)
        if pattern is None or self.labels("flight") or walks or self._grounded(parts):
            return ()
        return tuple(
            self.reader.plugin_label(p)
            for p in self.urdf.plugins
            if any(pattern.search(text) for _, text in p.params)
        )

    # -- where the body is -------------------------------------------------------------------

    def _placing(self, parts: _Parts, srdf: Srdf | None) -> None:
        parts.floating = [j.name for j in self.urdf.joints if j.type == "floating"]
        parts.planar = [j.name for j in self.urdf.joints if j.type == "planar"]
        parts.placing = self._root_axes()
        if len(parts.placing) == 6:
            parts.floating.append(
                f"root joints {', '.join(parts.placing)} (x, y, z and three turns)"
            )
        elif len(parts.placing) == 3:
            parts.planar.append(f"root joints {', '.join(parts.placing)} (x, y and a turn about z)")
        for virtual in srdf.virtual_joints if srdf is not None else ():
            if virtual.type in ("planar", "floating"):
                (parts.planar if virtual.type == "planar" else parts.floating).append(
                    f"SRDF virtual joint {virtual.name} ({virtual.type})"
                )

    def _root_axes(self) -> list[str]:
        """Joints at the root that only place the body: x, y and a turn about z (planar), or
        x, y, z and three turns (a simulated floating base); [] when the root is not so.
        """
        chain = self._root_chain()
        if len(chain) >= 3 and _moves(chain[:3]) == ({0, 1}, [2]):
            return [j.name for j in chain[:3]]
        if len(chain) == 6 and _moves(chain) == ({0, 1, 2}, [0, 1, 2]):
            return [j.name for j in chain]
        return []

    def _root_chain(self) -> list[Joint]:
        """The unbranched actuated joints right below the root (at most six)."""
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
        return chain

    # -- limbs -------------------------------------------------------------------------------

    def _body_parts(self, parts: _Parts) -> None:
        """Limbs, trunk and gripper joints, fingers found by place included."""
        special = {n for n, r in parts.roles.items() if r.role != "gripper"} | set(parts.placing)
        parts.grippers = {n for n, r in parts.roles.items() if r.role == "gripper"}
        flying = (
            bool(parts.of("rotor")) or bool(self.labels("flight")) or bool(self._fixed_rotors())
        )
        parts.limbs, parts.trunk, parts.hosts = self._limbs(
            special | parts.grippers, parts.grippers, parts.roles, flying
        )
        fingers = self._finger_groups(parts.limbs, grounded=self._grounded(parts))
        if fingers:
            for name in fingers:
                parts.roles[name] = Role(
                    name, "gripper", "a short unnamed chain beside two more on one link (a finger)"
                )
            parts.grippers = self._gripper_closure(parts.grippers | fingers)
            parts.limbs, parts.trunk, parts.hosts = self._limbs(
                special | parts.grippers, parts.grippers, parts.roles, flying
            )
        parts.limbs = self._legs_at_the_pelvis(parts.limbs)

    def _all_roles(self, parts: _Parts) -> tuple[Role, ...]:
        """Every movable joint's role: single-joint roles, limb roles, trunk, passive."""
        found = {n: r for n, r in parts.roles.items() if r.role != "gripper"}
        for name in parts.grippers:
            joint = self.urdf.joint(name)
            if joint is not None and joint.movable:
                role = parts.roles.get(name)
                found[name] = Role(name, "finger", role.evidence if role else "below a gripper")
        for limb in parts.limbs:
            for name in limb.joints:
                found[name] = Role(name, limb.kind, limb.why)
        for name in parts.trunk:
            found[name] = Role(name, "trunk", "below where limbs branch off")
        for name in parts.placing:
            found[name] = Role(name, "base", "a root joint that only places the body")
        for joint in self.urdf.joints:
            if joint.movable and joint.name not in found:
                why = f"follows {joint.mimic} (mimic)" if joint.mimic else "not part of a limb"
                found[joint.name] = Role(joint.name, "passive", why)
        return tuple(sorted(found.values(), key=lambda r: self._order(r.joint)))

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
        why = "one of two equal unnamed chains on the root, below named arms (legs by place)"
        legs = [replace(limb, kind="leg", why=why) for limb in pelvis]
        return self._sorted([limb for limb in limbs if limb not in pelvis] + legs)

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

    def _grounded(self, parts: _Parts) -> bool:
        """The body moves on the ground: wheels, casters, tracks or a drive plugin."""
        return bool(
            parts.of("wheel") or parts.of("caster") or self._tracks() or self.labels("drive")
        )

    def _finger_groups(self, limbs: list[Limb], *, grounded: bool = False) -> set[str]:
        """Joints of unnamed short chains hanging from one link in threes or more: fingers
        (also where each ends in a named fingertip).

        A claw or a hand whose fingers carry no names still has them side by side on a palm;
        arms and legs on one link come in ones and twos. On a body that moves on the ground,
        chains on its root link are the base's own (a tracked vehicle's flippers), not fingers.
        """
        by_base: dict[str, list[Limb]] = {}
        longest = self.profile.limb("finger_max_joints")
        for limb in limbs:
            if grounded and limb.base == self.urdf.root:
                continue
            if limb.kind in ("arm", "other") and not limb.named and len(limb.joints) <= longest:
                by_base.setdefault(limb.base, []).append(limb)
        found: set[str] = set()
        for group in by_base.values():
            if len(group) >= self.profile.limb("hand_min_fingers"):
                found.update(name for limb in group for name in limb.joints)
        return found

    def _limbs(
        self, special: set[str], grippers: set[str], roles: dict[str, Role], flying: bool
    ) -> tuple[list[Limb], list[str], set[str]]:
        """Limbs and trunk joints of the contracted tree of actuated, non-special joints."""
        children, carries, hosts = self._contracted(special, grippers, roles)
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
            limbs.append(self._classify(chain, chain[0].parent, marks, flying))
        wheel_legs = sum(1 for limb in limbs if limb.kind == "wheel_leg")
        limbs = [
            replace(limb, kind="leg" if wheel_legs >= _WHEEL_LEGS else "mount")
            if limb.kind == "wheel_leg"
            else limb
            for limb in limbs
        ]
        return self._sorted(limbs), trunk, hosts

    def _contracted(
        self, special: set[str], grippers: set[str], roles: dict[str, Role]
    ) -> tuple[dict[str, list[Joint]], dict[str, set[str]], set[str]]:
        """The limb joints below each anchor ("" = root), what each anchor carries (wheel,
        rotor, thruster, gripper, ...) and the anchors that hold a gripper."""
        children: dict[str, list[Joint]] = {}
        carries: dict[str, set[str]] = {}
        hosts: set[str] = set()
        stack: list[tuple[str, str]] = [(self.urdf.root, "")]
        while stack:
            link, anchor = stack.pop()
            for joint in reversed(self.urdf.children(link)):
                below = anchor
                if joint.name in special:
                    role = roles.get(joint.name)
                    kind = "gripper" if joint.name in grippers else role.role if role else "base"
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
        return children, carries, hosts

    def _sorted(self, limbs: list[Limb]) -> list[Limb]:
        return sorted(
            limbs,
            key=lambda limb: (
                LIMB_KINDS.index(limb.kind) if limb.kind in LIMB_KINDS else len(LIMB_KINDS),
                self._order(limb.joints[0]),
            ),
        )

    def _classify(self, chain: list[Joint], base: str, marks: set[str], flying: bool) -> Limb:
        names = tuple(j.name for j in chain)
        tip = self._tip(chain[-1])
        gripper = "gripper" in marks
        mounted = sorted(marks & set(_MOUNTED))
        named_parts = [self.parts_of(j.name) | self.parts_of(j.child) for j in chain]
        scores = {kind: sum(1 for parts in named_parts if kind in parts) for kind in LIMB_KINDS}
        if self._tip_matches("leg", chain[-1]):
            scores["leg"] += 1
        named = any(scores.values())
        # Degrees of freedom, not joints: a ball-joint shoulder moves like three hinges.
        length = sum(3 if j.type == "spherical" else 1 for j in chain)
        kind, why = self._named_kind(scores, length, gripper)
        if mounted:
            if mounted == ["wheel"] and kind == "leg":
                return Limb("wheel_leg", names, base, tip, gripper, named, f"{why}, on a wheel")
            return Limb("mount", names, base, tip, gripper, named, f"carries {', '.join(mounted)}")
        if kind is not None:
            return Limb(kind, names, base, tip, gripper, named, why)
        if length >= self.profile.limb("arm_min_joints") or (gripper and length >= 2):
            why = "ends in a gripper" if gripper else f"an unnamed chain of {length} joints"
            return Limb("arm", names, base, tip, gripper, named, why)
        if flying and length >= _FLYING_ARM_JOINTS and not named:
            why = f"a chain of {length} joints hanging from a flying body"
            return Limb("arm", names, base, tip, gripper, named, why)
        return Limb("other", names, base, tip, gripper, named, "no name or shape of a limb")

    def _named_kind(
        self, scores: dict[str, int], length: int, gripper: bool
    ) -> tuple[str | None, str]:
        """The limb kind the names say, within the profile's thresholds, and why."""
        ranked = sorted(LIMB_KINDS, key=lambda k: -scores[k])  # stable: leg, arm, head on ties
        for kind in ranked:
            if scores[kind] == 0:
                break
            why = f"{scores[kind]} {kind} name(s) on its joints and links"
            # Leg names win over a gripper at the end: a leg may end in a gripper.
            if kind == "leg" and length >= self.profile.limb("leg_min_joints"):
                return "leg", why
            if kind == "head" and length <= self.profile.limb("head_max_joints") and not gripper:
                return "head", why
            if kind == "arm" and (length >= self.profile.limb("arm_min_joints") or gripper):
                return "arm", why
        return None, ""

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


def _moves(chain: list[Joint]) -> tuple[set[int], list[int]]:
    """The axes a chain slides along and (sorted) the axes it turns about."""
    slides = {main_axis(j.axis) for j in chain if j.type == "prismatic"}
    turns = sorted(main_axis(j.axis) for j in chain if j.type != "prismatic")
    return slides, turns
