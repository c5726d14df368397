"""The body of a robot, read from what its joints do: wheels, rotors, thrusters, limbs, hands.

:func:`detect_body` reads a :class:`~solver.identify.readers.urdf.Urdf` with the profile's
patterns and thresholds, actuation first and names last, one step per module:

1. *What each joint does* (:mod:`solver.identify.actuation`): every moving joint a plugin names
   (a drive plugin's wheels, a motor model's rotors, a thruster plugin's thrusters, a fin
   plugin's fins), then shapes (a vertical swivel carrying one wheel is a caster) and names.
   Wheels without names are told by where they are. Joints that cannot move (fixed, or
   revolute/prismatic with lower == upper, unless :attr:`Joint.unlocked`) and mimic joints
   (they follow another) are not actuated.
2. *Where the body is* (:mod:`solver.identify.placement`): a floating or planar base, and the
   root joints that only place the body.
3. *Limbs* (:mod:`solver.identify.limbs`): the remaining actuated joints form a contracted tree
   whose chains are limbs (a *leg*, *arm* or *head*, a *mount* carrying wheels, rotors or
   thrusters, or *other*) or *trunk*; a mimic coupling is one actuator, read where it acts
   (:mod:`solver.identify.couplings`); *hands* (:mod:`solver.identify.hands`): fingers by name
   and, where chains carry no names, by place, after which the limbs are read again; legs,
   a snake's spine and a hand's wrist are read by place and shape where names say nothing.
4. *How the body travels* (:mod:`solver.identify.vehicle`): Gazebo model plugins add drive,
   track, flight and water evidence (a quadrotor modelled with no rotor joints is still flying;
   a hull's buoyancy says it floats), and a model trimmed of its moving parts still shows its
   fixed wheels and rotors.

Every step reads the description through one :class:`~solver.identify.tree.JointTree`. The
result, :class:`Body`, holds the parts, each joint's :class:`~solver.identify.roles.Role` with
the evidence that decided it, the counts the structure rules read (:meth:`Body.features`) and
one plain sentence of evidence per finding.

Not here: deciding the structure (:mod:`solver.identify.classifier`).
"""

from __future__ import annotations

import itertools
from collections import Counter
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, replace

from solver.identify.actuation import joint_roles, with_role
from solver.identify.hands import (
    finger_groups,
    finger_tips,
    gripper_closure,
    limbs_named_for_a_hand,
    stacked_grippers,
)
from solver.identify.limbs import (
    Limb,
    arms_beside_legs,
    bolted_chain,
    camera_arm,
    closed_arms,
    closed_loops,
    drive_rods,
    drives_beside_legs,
    find_limbs,
    five_bars,
    flippers,
    gripping_leg,
    holding_tools,
    joints_above,
    legs_alike,
    legs_at_the_pelvis,
    legs_by_place,
    legs_by_reach,
    legs_through_linkages,
    lone_leg,
    meeting_tips,
    moved_by,
    named_pan_tilt,
    named_wheeled_snake,
    names_a_tool,
    nearest_above,
    one_joint_legs,
    open_linkages,
    parallel_robot,
    pendulum,
    planar_arm,
    raised_legs,
    small_pan_tilt,
    spine,
    sprawling,
    swinging_booms,
    wheeled_spine,
    wrist,
)
from solver.identify.placement import MACHINE_TRAVEL, Placement, placement
from solver.identify.pose import cross, distance, dot, minus, parallel
from solver.identify.profile import GROUND, Profile
from solver.identify.readers.urdf import Joint, Urdf
from solver.identify.roles import Role
from solver.identify.tree import JointTree
from solver.identify.vehicle import (
    THRUSTERS_ALONE,
    fixed_rotors,
    fixed_thrusters,
    fixed_wheels,
    flight_hints,
    grounded,
    listed_thrusters,
    not_rotors,
    propellers,
    pushing_rotors,
    surface_hints,
    tracks,
    underwater_hints,
    vessel_name,
    water_frames,
    wings,
)
from solver.untrusted import shown

__all__ = ["Body", "detect_body"]

# Limbs whose joints a person commands one by one (Joint control); not heads, not mounts.
_COMMANDED = ("arm", "leg", "other", "spine")
# Legs a body walks on: their joints follow its gait controller, not an operator.
_WALKING_LEGS = 2


# The media the robot's packages may put a body in that are water (solver.identify.shipped).
_WATER = ("underwater", "surface")
# A leg of this many movable joints or more is a serial leg (the profile's ``serial_legs``):
# no half of a five-bar leg drawn open, which is a chain of two.
_SERIAL_LEG_JOINTS = 3


@dataclass(frozen=True)
class Body:
    """The parts found in one robot description, with the evidence for each."""

    wheels: tuple[str, ...] = ()
    rotors: tuple[str, ...] = ()
    tracks: tuple[str, ...] = ()
    drive_plugins: tuple[str, ...] = ()
    # Drive plugins that move the body itself, no wheel turning (a planar move).
    mover_plugins: tuple[str, ...] = ()
    flight_plugins: tuple[str, ...] = ()
    limbs: tuple[Limb, ...] = ()
    trunk: tuple[str, ...] = ()
    fingers: tuple[str, ...] = ()
    grippers: int = 0
    # A joint of its grippers, or the link it moves, is named for one (a finger, a jaw, a
    # claw): a gripper built to hold, not a mirrored pair of hinges read as jaws (a drone's
    # landing gear, a bay's doors).
    named_gripper: bool = False
    floating_base: tuple[str, ...] = ()
    planar_base: tuple[str, ...] = ()
    # Root slides that travel as a machine's axes (an XY table's, a Cartesian gantry's): no base.
    machine_axes: tuple[str, ...] = ()
    controlled_wheels: tuple[str, ...] = ()
    # Fins (rudders, control surfaces) a controller drives (a transmission or ros2_control).
    controlled_fins: tuple[str, ...] = ()
    controlled_joints: tuple[str, ...] = ()
    # Finger and gripper joints a controller drives (a transmission or ros2_control command).
    controlled_fingers: tuple[str, ...] = ()
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
    # Endless leaves about the body's long axis beside a wing drawn as a board: a plane's
    # propellers, whatever their names.
    propellers: tuple[str, ...] = ()
    # Plugins of a body in water (thrusters, hydrodynamics, buoyancy) and hints of a hull at
    # the surface (a surface plugin, <metacentric_width>, wind on its buoyancy).
    marine_plugins: tuple[str, ...] = ()
    surface_hints: tuple[str, ...] = ()
    # What a body below the surface has: a buoyancy or hydrodynamics plugin, a thruster plugin,
    # a DVL or pressure sensor. A body in water by thruster names alone has none.
    underwater_hints: tuple[str, ...] = ()
    # Plugins of a craft its thrusters fly in air or space (a reaction wheel, air thrusters;
    # plugins that give its medium air's density), nothing of water beside them
    # (RoleReader.spaceborne).
    space_plugins: tuple[str, ...] = ()
    # Frames fixed to the body named as an underwater sensor's (a DVL), with nothing behind them:
    # a body in water below the surface, though no plugin says so.
    water_frames: tuple[str, ...] = ()
    # The robot's name in water words, when nothing else says how the body travels.
    vessel_name: tuple[str, ...] = ()
    # Flying known only from a model plugin's parameters (a vehicle plugin of its own).
    flight_hints: tuple[str, ...] = ()
    # The robot's name as a rig of sensors a vehicle carries (a sensor kit, a sensor rack), when
    # nothing else says how the body travels: its packages' vehicle is not it.
    rig_name: tuple[str, ...] = ()
    # The medium the robot's packages say the body travels in (flight, underwater, surface),
    # when its description shows no way, and the file that says it (solver.identify.shipped).
    shipped_as: str = ""
    shipped_by: str = ""
    # The file of the robot's packages whose teleop node drives the body (a description trimmed
    # to a base's sensor head: no pan/tilt unit alone).
    driven_by: str = ""
    finger_motions: int = 0
    # Three legs or more slung out from the body, each first swung about the vertical (a
    # hexapod's, a spider's: limbs.sprawling).
    sprawled: bool = False
    # On a flying body, a link the profile's `tool` pattern names that no joint moves: held on
    # fixed joints to the body that carries it (a drone's boom ending in a claw).
    rigid_tool: str = ""
    # Links the profile's `tool` pattern names (two or more) in a description where nothing
    # moves: an end effector alone whose cups or jaws no joint moves (a vacuum gripper), counted
    # as one gripper.
    fixed_gripper: str = ""
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
            or self.shipped_as == GROUND
        )

    @property
    def weak_base(self) -> bool:
        """A mobile base known only from fixed wheels, planar root joints or its packages' words
        (an SRDF's virtual joint is not read: :mod:`solver.identify.placement`)."""
        return self.mobile_base and not (
            self.wheels or self.tracks or self.drive_plugins or self.casters
        )

    @property
    def marine(self) -> bool:
        return bool(
            (self.thrusters and not self.space_plugins)
            or self.marine_plugins
            or self.water_frames
            or self.vessel_name
            or self.shipped_as in _WATER
        )

    @property
    def travels_no_way(self) -> bool:
        """Nothing in the description says how the body travels: no wheel, track, caster or
        drive plugin, no rotor, wing or flight cue, nothing of water, no arm, leg or spine, no
        gripper or finger (one link and its mesh, a few sensor frames, a camera's pan-tilt)."""
        return not (
            self.mobile_base
            or self.flying
            or self.marine
            or self.grippers
            or self.fingers
            or any(limb.kind in ("arm", "leg", "spine") for limb in self.limbs)
        )

    @property
    def carries_itself(self) -> bool:
        """The body moves by itself, whatever carries an arm on it: a drive plugin moves it, or
        it walks on two legs or more (an arm there may be only drawn: nothing commands it)."""
        return bool(self.drive_plugins) or self.count("leg") >= _WALKING_LEGS

    @property
    def carried_rig(self) -> bool:
        """A rig of sensors by its name (:attr:`rig_name`: a sensor kit a vehicle carries) that
        travels no way of its own, or only as a simulator slides it: its packages are its
        vehicle's, and what they ship moves the vehicle, not the rig."""
        return bool(self.rig_name) and (self.travels_no_way or self.moved_by_plugin_alone)

    @property
    def moved_by_plugin_alone(self) -> bool:
        """Plugins that move the body itself move it (a planar move, a velocity control: the
        profile's ``mover`` plugins; no diff-drive or other wheel drive among its drive
        plugins), and without them it travels no way (:attr:`travels_no_way`: no wheel,
        track, caster or planar root joint, no flight or water cue, no gripper, finger, arm,
        leg or spine). The simulator slides it; what it travels in is not said."""
        return (
            bool(self.mover_plugins)
            and set(self.drive_plugins) <= set(self.mover_plugins)
            and replace(self, drive_plugins=()).travels_no_way
        )

    @property
    def head_alone(self) -> bool:
        """A pan/tilt unit with nothing else: heads only, no mobile or floating base, vehicle,
        gripper or finger, and no teleop node of its packages driving the body (a camera's
        pan/tilt on a fixed base, aimed by its joints)."""
        return (
            bool(self.limbs)
            and all(limb.kind == "head" for limb in self.limbs)
            and not (self.grippers or self.fingers or self.mobile_base or self.floating_base)
            and not (self.flying or self.marine or self.driven_by)
        )

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
            or (self.space_plugins and self.thrusters)
            or self.shipped_as == "flight"
        )

    @property
    def aero(self) -> bool:
        """Wings and control surfaces, two or more, one of them a wing, or a wing and a
        propeller that pulls along the body: a fixed-wing craft."""
        return bool(self.wings) and (len({*self.wings, *self.fins}) >= 2 or bool(self.propellers))

    @property
    def weak_flight(self) -> bool:
        """Flying known only from fixed rotor links, wing names or a plugin's parameters."""
        return self.flying and not (
            self.rotors
            or self.flight_plugins
            or self.fins
            or (self.space_plugins and self.thrusters)
        )

    def features(self) -> dict[str, int]:
        """The counts and flags the profile's structure rules read."""
        return {
            "wheels": len(self.wheels),
            "tracks": len(self.tracks),
            "rotors": len(self.rotors),
            "arms": self.count("arm"),
            "tools": self.count("arm") + int(bool(self.rigid_tool) or self.named_gripper),
            "legs": self.count("leg"),
            "serial_legs": sum(
                1
                for limb in self.limbs
                if limb.kind == "leg" and len(limb.joints) >= _SERIAL_LEG_JOINTS
            ),
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
            "weak_water": int(
                bool(self.vessel_name)
                or self.shipped_as in _WATER
                or self.surface_hints == (THRUSTERS_ALONE,)
            ),
            "thrusters": len(self.thrusters),
            "fins": len(self.fins),
            "casters": len(self.casters),
            "finger_motions": self.finger_motions,
            "marine": int(self.marine),
            "surface": int(bool(self.surface_hints) or self.shipped_as == "surface"),
            "underwater": int(
                bool(self.underwater_hints or self.water_frames) or self.shipped_as == "underwater"
            ),
            "serpentine": int(self.count("spine") > 0),
            "head_alone": int(self.head_alone),
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
        if self.propellers:
            lines.append(f"propeller joint(s) pulling along the body: {_names(self.propellers)}")
        if self.flight_hints:
            lines.append(f"flight named in: {_names(self.flight_hints)}")
        if self.shipped_as == "flight":
            lines.append(f"a flying body by its packages alone: {self.shipped_by}")
        return lines

    def _tools(self) -> list[str]:
        """The evidence of what the body holds: a rigid tool, fingers and grippers."""
        lines = []
        if self.rigid_tool:
            lines.append(f"a rigid tool: {shown(self.rigid_tool)}, held on fixed joints")
        if self.fixed_gripper:
            lines.append(
                f"a gripper no joint moves: {shown(self.fixed_gripper)} (nothing in it moves)"
            )
        if self.fingers:
            lines.append(
                f"{len(self.fingers)} finger/gripper joint chain(s) on "
                f"{self.grippers} hand(s)/gripper(s): {_names(self.fingers)}"
            )
        return lines

    def _water(self) -> list[str]:
        lines = []
        if self.thrusters:
            lines.append(f"{len(self.thrusters)} thruster(s): {_names(self.thrusters)}")
        if self.marine_plugins:
            lines.append(f"water plugin(s): {_names(self.marine_plugins)}")
        if self.vessel_name:
            lines.append(f"a vessel by its name alone: {_names(self.vessel_name)}")
        if self.shipped_as in _WATER:
            where = "below the surface" if self.shipped_as == "underwater" else "at the surface"
            lines.append(f"in water {where} by its packages alone: {self.shipped_by}")
        if self.surface_hints:
            lines.append(f"floats at the surface: {_names(self.surface_hints)}")
        elif self.underwater_hints:
            lines.append(f"below the surface: {_names(self.underwater_hints)}")
        elif self.water_frames:
            lines.append(f"an underwater sensor's frame on the body: {_names(self.water_frames)}")
        elif self.marine_plugins:  # a buoyancy plugin: in water, nothing says how deep
            lines.append(
                "in water, nothing says below or at the surface: no hydrodynamics or thruster "
                "plugin, no DVL or pressure sensor, no surface cue"
            )
        elif self.marine and not self.shipped_as:
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
        if self.shipped_as == GROUND:
            lines.append(f"a ground vehicle by its packages alone: {self.shipped_by}")
        if self.carried_rig:
            lines.append(
                f"a rig of sensors by its name: {_names(self.rig_name)} (no vehicle its "
                "packages name is read as it, no control they ship)"
            )
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
        if self.space_plugins:
            lines.append(f"thrusters flown in air or space: {_names(self.space_plugins)}")
        lines += self._water()
        lines += self._trimmed()
        if self.planar_base:
            lines.append(f"planar base: {_names(self.planar_base)}")
        if self.floating_base:
            lines.append(f"floating base: {_names(self.floating_base)}")
        if self.driven_by:
            lines.append(f"a base driven by its packages' teleop node: {self.driven_by}")
        if self.machine_axes:
            lines.append(
                f"root slides {_names(self.machine_axes)} travel as a machine's axes do (less "
                f"than {MACHINE_TRAVEL:g} m each): no base placed in the world"
            )
        if self.trunk:
            lines.append(f"trunk joint(s) below the limbs: {_names(self.trunk)}")
        lines += [limb.describe() for limb in self.limbs]
        lines += self._tools()
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


def detect_body(urdf: Urdf, profile: Profile) -> Body:
    """The parts of ``urdf`` (see the module docstring). The SRDF is not read for the body: its
    virtual joint is a planning convention, its groups are the classifier's to weigh."""
    tree = JointTree(urdf, profile)
    parts = _Parts(
        roles=joint_roles(tree), placement=placement(tree), fixed_rotors=tuple(fixed_rotors(tree))
    )
    parts.roles.update(pushing_rotors(tree, parts.roles))
    parts.roles.update(_rollers(tree, parts.roles))
    parts.roles.update(_loop_linkages(tree, parts.roles))
    grippers = parts.of("gripper")
    for name in {*stacked_grippers(tree, grippers), *limbs_named_for_a_hand(tree, grippers)}:
        del parts.roles[name]  # an arm's joint, though named as a gripper's
    _body_parts(tree, parts)
    controlled = urdf.controlled_joints
    wheels = parts.of("wheel")
    track_names = tracks(tree)
    thrusters = (
        *parts.of("thruster"),
        *listed_thrusters(tree, parts.roles),
        *fixed_thrusters(tree),
    )
    fixed_gripper = _fixed_gripper(tree)
    body = Body(
        wheels=tuple(wheels),
        rotors=tuple(parts.of("rotor")),
        tracks=track_names,
        drive_plugins=tree.labels("drive"),
        mover_plugins=tree.labels("mover"),
        flight_plugins=tree.labels("flight"),
        limbs=tuple(parts.limbs),
        trunk=tuple(parts.trunk),
        fingers=tuple(finger_tips(tree, parts.grippers)),
        grippers=len(parts.hosts) or int(bool(fixed_gripper)),
        named_gripper=any(
            "gripper" in tree.parts_of(name) | tree.parts_of(joint.child)
            for name in parts.grippers
            if (joint := urdf.joint(name)) is not None
        ),
        floating_base=parts.placement.floating,
        planar_base=parts.placement.planar,
        machine_axes=parts.placement.machine,
        controlled_wheels=tuple(w for w in wheels if w in controlled),
        controlled_fins=tuple(f for f in parts.of("fin") if f in controlled),
        controlled_joints=tuple(j for j in _commanded(tree, parts, track_names) if j in controlled),
        controlled_fingers=tuple(
            sorted(
                (j for j in parts.grippers if j in controlled and urdf.interfaces(j)),
                key=tree.order,
            )
        ),
        not_rotors=tuple(not_rotors(tree, parts.roles)),
        fixed_wheels=tuple(fixed_wheels(tree, parts.roles)),
        fixed_rotors=parts.fixed_rotors,
        thrusters=thrusters,
        fins=tuple(parts.of("fin")),
        casters=tuple(parts.of("caster")),
        wings=tuple(wings(tree, parts.roles)),
        propellers=tuple(propellers(tree, parts.roles)),
        marine_plugins=()
        if tree.reader.spaceborne
        else tuple(
            dict.fromkeys(
                (*tree.labels("thruster"), *tree.labels("marine"), *tree.labels("underwater"))
            )
        ),
        space_plugins=_space_plugins(tree),
        surface_hints=surface_hints(tree, thrusters=len(thrusters)),
        underwater_hints=underwater_hints(tree),
        water_frames=water_frames(tree),
        vessel_name=vessel_name(tree, parts.roles, parts.limbs),
        rig_name=(tree.reader.named_rig,) if tree.reader.named_rig else (),
        flight_hints=flight_hints(tree, parts.roles, parts.limbs),
        finger_motions=sum(1 for name in parts.grippers if (j := urdf.joint(name)) and j.actuated),
        sprawled=sprawling(tree, parts.limbs),
        fixed_gripper=fixed_gripper,
        roles=_all_roles(tree, parts),
    )
    # A flying body's rigid tool (a boom ending in a claw) makes it an aerial manipulator; on
    # anything else such a link is its arm's or its hand's, and not read.
    return replace(body, rigid_tool=_rigid_tool(tree)) if body.flying else body


def _rigid_tool(tree: JointTree) -> str:
    """The first link (document order) of :func:`_tool_links` held on fixed joints only, up
    from it to a link that carries a moving joint (the body) or to the root (a tree rooted at
    the tool's frame), and no empty leaf: a ``<link/>`` with nothing in it and nothing below it
    is a controller's reference frame (an ``end_effector`` point on the body), not a tool one
    could hold. Read on a flying body only (the caller): on an arm or a hand such a link is the
    arm's or the hand's. One walk up the tree for all links (:func:`_held`)."""
    urdf = tree.urdf
    carriers = {joint.parent for joint in urdf.joints if joint.movable}
    known: dict[str, bool] = {}
    return next(
        (
            name
            for name in _tool_links(tree)
            if not _empty_leaf(urdf, name) and _held(urdf, name, carriers, known)
        ),
        "",
    )


def _empty_leaf(urdf: Urdf, name: str) -> bool:
    """``name`` is a declared link with nothing in it from which no joint hangs: a frame."""
    link = urdf.link(name)
    return link is not None and link.empty and not urdf.children(name)


def _held(urdf: Urdf, link: str, carriers: set[str], known: dict[str, bool]) -> bool:
    """Only fixed joints lead up from ``link`` to one of ``carriers`` or to the root; every
    link walked is remembered in ``known``, so many links cost one walk of the tree at most."""
    walked = []
    current = link
    while current not in known:
        walked.append(current)
        joint = urdf.parent_joint(current)
        if joint is None or joint.movable or joint.parent in carriers:
            found = joint is None or not joint.movable
            break
        current = joint.parent
    else:
        found = known[current]
    for name in walked:
        known[name] = found
    return found


def _fixed_gripper(tree: JointTree) -> str:
    """The first of two or more links of :func:`_tool_links` (a vacuum gripper's cups, a
    gripper's jaws) in a description where no joint moves: the end effector is all there is.
    One such link is no gripper (a kit's `gripper_coupling`, an arm drawn rigid)."""
    if any(joint.movable for joint in tree.urdf.joints):
        return ""
    tools = list(itertools.islice(_tool_links(tree), 2))
    return tools[0] if len(tools) == 2 else ""


def _tool_links(tree: JointTree) -> Iterator[str]:
    """The links the profile's ``tool`` pattern names (a gripper, a claw, a suction cup, an end
    effector), in document order (:func:`~solver.identify.limbs.names_a_tool`)."""
    for link in tree.urdf.links:
        if names_a_tool(tree, link.name):
            yield link.name


def _loop_linkages(tree: JointTree, roles: dict[str, Role]) -> dict[str, Role]:
    """The movable joints of no role on the way down to each end of a loop an exporter cut
    (the frames a file names as its two ends, :attr:`Urdf.cut_loops`), from the nearest link
    above where another movable joint branches off: a parallel linkage's rods and cranks beside
    the limb they drive (a closed-chain leg's ankle and knee linkages), passive for the limb's
    shape, whatever transmission is written on them. (A loop a ``<gazebo>`` joint closes joins
    two chains instead: :func:`~solver.identify.limbs.closed_loops`.)"""
    found: dict[str, Role] = {}
    movable_children = Counter(j.parent for j in tree.urdf.joints if j.movable)
    for end in sorted({link for pair in tree.urdf.cut_loops for link in pair}):
        link = end
        for _ in range(_LINKAGE_JOINTS):
            joint = tree.urdf.parent_joint(link)
            if joint is None:
                break
            if joint.movable and joint.name not in roles:
                found[joint.name] = Role(joint.name, "passive", f"a linkage closed at {end}")
            link = joint.parent
            if movable_children[link] > 1:
                break
    return found


# The most joints a linkage's branch has from where it leaves its limb to a loop's end.
_LINKAGE_JOINTS = 4


def _rollers(tree: JointTree, roles: dict[str, Role]) -> dict[str, Role]:
    """Joints of no role that a wheel carries (through fixed joints): the rollers of a mecanum
    or omni wheel, turning with the ground, passive whatever transmission is written on them.
    One walk up the tree for all (``moved_by``'s shared memo)."""
    wheels = {name for name, role in roles.items() if role.role == "wheel"}
    if not wheels:
        return {}
    known: dict[str, str | None] = {}
    found: dict[str, Role] = {}
    for joint in tree.urdf.joints:
        if not joint.movable or joint.name in roles:
            continue
        wheel = moved_by(tree.urdf, joint.parent, known)
        if wheel in wheels:
            found[joint.name] = Role(joint.name, "passive", f"on wheel {wheel} (a roller)")
    return found


@dataclass
class _Parts:
    """What :func:`detect_body` gathers, step by step, before it becomes a :class:`Body`."""

    roles: dict[str, Role] = field(default_factory=dict)
    placement: Placement = field(default_factory=Placement)
    limbs: list[Limb] = field(default_factory=list)
    trunk: list[str] = field(default_factory=list)
    grippers: set[str] = field(default_factory=set)
    hosts: set[str] = field(default_factory=set)
    # Leaf links fixed where rotors would turn (:func:`fixed_rotors`), read once per body.
    fixed_rotors: tuple[str, ...] = ()

    def of(self, role: str) -> list[str]:
        return with_role(self.roles, role)


def _body_parts(tree: JointTree, parts: _Parts) -> None:
    """Limbs, trunk and gripper joints, fingers found by place included."""
    special = {n for n, r in parts.roles.items() if r.role != "gripper"} | set(
        parts.placement.placing
    )
    parts.grippers = {n for n, r in parts.roles.items() if r.role == "gripper"}
    flying = bool(parts.of("rotor")) or bool(tree.labels("flight")) or bool(parts.fixed_rotors)
    parts.limbs, parts.trunk, parts.hosts = find_limbs(
        tree, special | parts.grippers, parts.grippers, parts.roles, flying
    )
    parts.limbs = legs_by_place(tree, parts.limbs)
    # Legs where a walker's hang (at the pelvis, straight down): the trunk they hang from
    # carries no fingers.
    legged = legs_by_reach(tree, legs_at_the_pelvis(tree, parts.limbs))
    fingers = finger_groups(
        tree,
        parts.limbs,
        grounded=grounded(tree, parts.roles),
        flying=flying,
        walks_on=_trunks(tree, legged, parts.trunk),
        grippers=frozenset(parts.grippers),
    )
    if fingers:
        for name in fingers:
            parts.roles[name] = Role(
                name, "gripper", "a short unnamed chain beside others on one palm (a finger)"
            )
        parts.grippers = gripper_closure(tree, parts.grippers | fingers)
        parts.limbs, parts.trunk, parts.hosts = find_limbs(
            tree, special | parts.grippers, parts.grippers, parts.roles, flying
        )
        parts.limbs = legs_by_place(tree, parts.limbs)
        legged = legs_by_reach(tree, legs_at_the_pelvis(tree, parts.limbs))
    parts.limbs, parts.trunk = legs_through_linkages(tree, legged, parts.trunk)
    parts.limbs = five_bars(tree, parts.limbs)
    parts.limbs = arms_beside_legs(tree, legs_alike(tree, parts.limbs))
    parts.limbs = drives_beside_legs(tree, parts.limbs)
    parts.limbs = raised_legs(tree, flippers(tree, parts.limbs), parts.roles)
    parts.limbs = parallel_robot(tree, meeting_tips(tree, parts.limbs), flying=flying)
    parts.limbs = open_linkages(tree, closed_arms(tree, closed_loops(tree, parts.limbs)))
    parts.limbs = drive_rods(tree, parts.limbs)
    _snake(tree, parts)
    parts.limbs = wrist(tree, parts.limbs, finger_tips(tree, parts.grippers))
    moves = flying or grounded(tree, parts.roles)
    parts.limbs = small_pan_tilt(tree, parts.limbs, moves)
    parts.limbs = planar_arm(tree, bolted_chain(tree, parts.limbs, moves), moves)
    parts.limbs = gripping_leg(lone_leg(tree, parts.limbs, moves))
    parts.limbs = one_joint_legs(tree, parts.limbs, moves)
    if not parts.roles and not parts.trunk:
        # Read by the robot's name, once every chain has its kind (a short chain bolted to the
        # world is an arm by then): a pendulum rig's one chain, an arm's camera on its tip, a
        # pan/tilt unit's hinges.
        parts.limbs = named_pan_tilt(tree, camera_arm(tree, pendulum(tree, parts.limbs)))
    parts.limbs = swinging_booms(tree, holding_tools(tree, parts.limbs))


def _snake(tree: JointTree, parts: _Parts) -> None:
    """A snake's spine: its one chain with nothing else (:func:`spine`), or with side wheels
    on it (:func:`wheeled_spine`), or, on a robot named a snake, gliding on a wheel per module
    (:func:`named_wheeled_snake`); the wheels it carries passive."""
    if not parts.roles and not parts.trunk:  # a snake is its one chain, with nothing else
        parts.limbs = spine(tree, parts.limbs)
    elif not parts.roles and not parts.grippers:  # or its chain, with side wheels on it
        parts.limbs, parts.trunk, side = wheeled_spine(tree, parts.limbs, parts.trunk)
        for name in side:
            parts.roles[name] = Role(name, "passive", "a leaf joint beside a spine (a side wheel)")
    elif {role.role for role in parts.roles.values()} == {"wheel"} and not parts.trunk:
        parts.limbs, side = named_wheeled_snake(tree, parts.limbs, parts.of("wheel"))
        for name in side:
            parts.roles[name] = Role(name, "passive", "a wheel on a snake's module (passive)")


def _trunks(tree: JointTree, limbs: list[Limb], trunk: list[str]) -> frozenset[str | None]:
    """The rigid bodies two legs or more of ``limbs`` hang from, as :func:`finger_groups` is
    told them: the nearest joint above each leg's base that moves (None: the root's); and the
    bodies the ``trunk`` joints turn on them (a waist, its chest: where a walker's arms and
    neck hang), or that carry a trunk joint turning the legs' body (a file rooted in the chest,
    its waist turning the hips below)."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if len(legs) < 2:
        return frozenset()
    known: dict[str, str | None] = {}
    bodies = {moved_by(tree.urdf, limb.base, known) for limb in legs}
    waist = [joint for name in trunk if (joint := tree.urdf.joint(name)) is not None]
    on_body = Counter(moved_by(tree.urdf, joint.parent, known) for joint in waist)
    for joint in waist:  # in the tree's order: a waist's roll, then its pitch on it
        body = moved_by(tree.urdf, joint.parent, known)
        if body in bodies and on_body[body] == 1:  # one chain up: a waist, not two arms
            bodies.add(joint.name)
        elif joint.name in bodies:  # a waist turning the hips under a chest the file roots
            bodies.add(body)
    return frozenset(bodies)


def _commanded(tree: JointTree, parts: _Parts, track_names: tuple[str, ...]) -> list[str]:
    """Joints a person commands one by one: those of arms, legs and other limbs, and the trunk
    joints that carry one. A head points a sensor (a pan/tilt camera); a mount and a trunk
    carrying only mounts move wheels, rotors or thrusters (a transformable multirotor's frame,
    a tilting rotor): the vehicle's own motion, not joint control, but for a mount's slide
    commanded to a position (:func:`_placed_slides`). On a body that flies or
    swims, a short chain of no limb is the vehicle's too (a control surface, a gimbal). The
    legs of a body that walks (two or more) are driven by its gait controller: a transmission
    or ``ros2_control`` interface on them carries the gait's output to the motors, not an
    operator's command (the labelled sets count no Joint for it); a single leg is a limb. A
    track's sprocket spinning on a joint of no other role (a chain of its own) drives the
    vehicle too.
    """
    vehicle = _vehicle(tree, parts)
    walks = sum(1 for limb in parts.limbs if limb.kind == "leg") >= _WALKING_LEGS
    kinds = tuple(
        k for k in _COMMANDED if not (vehicle and k == "other") and not (walks and k == "leg")
    )
    sprockets = set(_sprockets(tree, track_names))
    limbs = [
        limb
        for limb in parts.limbs
        if limb.kind in kinds and not (limb.kind == "other" and set(limb.joints) <= sprockets)
    ]
    joints = [name for limb in limbs for name in limb.joints]
    joints += _placed_slides(tree, parts, vehicle)
    joints += _swung_mounts(tree, parts, vehicle)
    carrying = joints_above(tree, [limb.joints[0] for limb in limbs])
    return list(dict.fromkeys(joints + [name for name in parts.trunk if name in carrying]))


def _vehicle(tree: JointTree, parts: _Parts) -> bool:
    """The body flies or swims: rotors, control surfaces or a rudder, a flight plugin, or a
    body in water."""
    return bool(
        parts.of("rotor")
        or parts.of("fin")
        or tree.labels("flight")
        or parts.fixed_rotors
        or tree.reader.marine
    )


def _placed_slides(tree: JointTree, parts: _Parts, vehicle: bool) -> list[str]:
    """Mounts' joints that slide across the ground's vertical, commanded to a position (a
    climber's arms pressing its wheels to the pole): set one joint at a time, they do not move
    the vehicle as a steering or a drive joint does. A slide along the vertical holds its
    wheel to the ground (a suspension, whatever holds it), and a flying or swimming body's
    (``vehicle``) move its rotors or thrusters."""
    if vehicle:
        return []
    return [
        name
        for limb in parts.limbs
        if limb.kind == "mount"
        for name in limb.joints
        if (joint := tree.urdf.joint(name)) is not None
        and joint.type == "prismatic"
        and "position" in tree.urdf.interfaces(name)
        and abs(tree.poses.axis(joint)[2]) < _UPRIGHT
    ]


def _swung_mounts(tree: JointTree, parts: _Parts, vehicle: bool) -> list[str]:
    """Mounts' driven hinges that swing the wheels they carry, all on one side of the hinge,
    about an axis along the wheels' own (a track's flipper with the wheel at its end, on a
    spring or not): set one joint at a time, they do not move the vehicle as a steering hinge
    (its axis across the wheel's) or a drive joint does. A rocker's pivot lies between its
    front wheel and its bogie; a hinge on a wheel's own line spins with it; a flying or
    swimming body's (``vehicle``) move its rotors or thrusters. Each wheel is carried by the
    nearest driven joint above it (a transmission or ``ros2_control`` interface: a passive
    spring or bogie between is looked through); each driven joint that carries a wheel is a
    point its own nearest driven joint carries too (a driven bogie under a rocker). One walk of
    the tree for all (:func:`nearest_above`)."""
    if vehicle:
        return []
    urdf = tree.urdf
    driven = set(urdf.controlled_joints)
    known: dict[str, str | None] = {}

    def carrier(link: str) -> str | None:
        return nearest_above(urdf, link, known, lambda joint: joint.name in driven)

    wheels: dict[str, list[Joint]] = {}
    pivots: dict[str, list[Joint]] = {}
    marked: set[str] = set()
    for name in parts.of("wheel"):
        wheel = urdf.joint(name)
        hinge = None if wheel is None else carrier(wheel.parent)
        if wheel is not None and hinge is not None:
            wheels.setdefault(hinge, []).append(wheel)
        while hinge is not None and hinge not in marked:  # each driven joint once
            marked.add(hinge)
            joint = urdf.joint(hinge)
            above = None if joint is None else carrier(joint.parent)
            if joint is not None and above is not None:
                pivots.setdefault(above, []).append(joint)
            hinge = above
    return [
        name
        for limb in parts.limbs
        if limb.kind == "mount"
        for name in limb.joints
        if name in wheels
        and (joint := urdf.joint(name)) is not None
        and (
            joint.type == "revolute"
            or (joint.type == "continuous" and "position" in urdf.interfaces(name))
        )
        and _swings(tree, joint, wheels[name], pivots.get(name, []))
    ]


def _swings(tree: JointTree, hinge: Joint, wheels: list[Joint], pivots: list[Joint]) -> bool:
    """Some of the ``wheels`` ``hinge`` carries turn about axes parallel to its own, and those
    and the driven ``pivots`` it carries lie away from its axis (:data:`_SWUNG`), all on one
    side of it: every two within a quarter turn of each other about the axis (not a rocker
    between its front wheel and its bogie). More than :data:`_MOST_SWUNG` is no flipper."""
    axis = tree.poses.axis(hinge)
    origin = tree.poses.place(hinge.child)
    carried = [wheel for wheel in wheels if parallel(axis, tree.poses.axis(wheel))]
    points = [*carried, *pivots]
    if not carried or len(points) > _MOST_SWUNG:
        return False
    arms = [cross(axis, minus(tree.poses.place(point.child), origin)) for point in points]
    return all(distance(arm, (0.0, 0.0, 0.0)) > _SWUNG for arm in arms) and all(
        dot(one, other) > 0 for one in arms for other in arms
    )


# The most wheels and pivots a swinging hinge carries (a flipper's one to three wheels).
_MOST_SWUNG = 8


# How far (m) a wheel's centre is from a hinge's axis for the hinge to swing it, not spin it.
_SWUNG = 0.01


# How upright a slide's axis is (its cosine to the vertical) to hold a wheel to the ground.
_UPRIGHT = 0.9


def _sprockets(tree: JointTree, track_names: tuple[str, ...]) -> list[str]:
    """The track joints (:func:`tracks`) that spin without end (a track's drive sprocket or
    idler), not commanded to a position (a flipper on a track, drawn continuous, is)."""
    return [
        name
        for name in track_names
        if (joint := tree.urdf.joint(name)) is not None
        and joint.type == "continuous"
        and "position" not in tree.urdf.interfaces(name)
    ]


def _space_plugins(tree: JointTree) -> tuple[str, ...]:
    """The plugins that say a craft's thrusters fly it in air or space (RoleReader.spaceborne):
    a space plugin, or a plugin that gives its medium air's density."""
    if not tree.reader.spaceborne:
        return ()
    air = (tree.reader.plugin_label(p) for p in tree.reader.air_plugins)
    return tuple(dict.fromkeys((*tree.labels("space"), *air)))


def _all_roles(tree: JointTree, parts: _Parts) -> tuple[Role, ...]:
    """Every movable joint's role: single-joint roles, limb roles, trunk, passive."""
    found = {n: r for n, r in parts.roles.items() if r.role != "gripper"}
    for name in parts.grippers:
        joint = tree.urdf.joint(name)
        if joint is not None and joint.movable:
            role = parts.roles.get(name)
            found[name] = Role(name, "finger", role.evidence if role else "below a gripper")
    for limb in parts.limbs:
        for name in limb.joints:
            found[name] = Role(name, limb.kind, limb.why)
    for name in parts.trunk:
        found[name] = Role(name, "trunk", "below where limbs branch off")
    for name in parts.placement.placing:
        found[name] = Role(name, "base", "a root joint that only places the body")
    for joint in tree.urdf.joints:
        if joint.movable and joint.name not in found:
            why = f"follows {joint.mimic} (mimic)" if joint.mimic else "not part of a limb"
            found[joint.name] = Role(joint.name, "passive", why)
    return tuple(sorted(found.values(), key=lambda r: tree.order(r.joint)))
