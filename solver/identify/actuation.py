"""What the joints do one at a time: wheels, steering, casters, rotors, thrusters, fins, grippers.

:func:`joint_roles` gives each moving joint that plays a single-joint role that role, with the
evidence that decided it, actuation first and names last:

1. what :class:`~solver.identify.roles.RoleReader` reads of the joint: a plugin that names it,
   then its shape, then its name. Joints that cannot move (fixed, or revolute/prismatic with
   lower == upper, unless their equal limits are placeholders: ``Joint.unlocked``) play none;
2. wheels without names, told by where they are: endless leaves hanging below a link, at least
   one on each side of it; and endless leaves that end legs of limited joints, two or more,
   whatever their names (a wheel-legged robot's);
3. casters, a vertical swivel carrying one wheel; a caster driven through a transmission is no
   caster (its swivel steers, its wheel drives); on a base so steered, another driven vertical
   swivel that carries nothing that moves steers too (the vehicle's steering input); three
   undriven endless joints about three axes through one point are a ball caster;
4. rotors too few to fly are dropped (one spinning leaf is a motor or a tool), unless a
   simulator poses them (a propeller on a floating joint is one however few);
5. jaws side by side, found by place (:func:`~solver.identify.hands.jaws`): one motion closing
   mirrored jaws, or two jaws at the end of a chain;
6. a motor whose mimic followers are all wheels (or rotors, or thrusters) turns them: it
   plays their role;
7. every movable joint below a gripper joint moves a finger.

Not here: the roles of the chains the other joints form (:mod:`solver.identify.limbs`).
"""

from __future__ import annotations

import itertools
import math
import re
from collections import Counter
from collections.abc import Iterable, Iterator, Mapping

from solver.identify.hands import endless_jaws, gripper_closure, jaws
from solver.identify.limbs import CORNER, joints_above, moved_by, nearest_above, points_a_sensor
from solver.identify.pose import (
    Vector,
    cross,
    distance,
    dot,
    local_axis,
    minus,
    off_axis,
    parallel,
    perpendicular,
    spread,
)
from solver.identify.readers.urdf import Joint, written_blank
from solver.identify.roles import POSED, Role, main_axis
from solver.identify.tree import JointTree

__all__ = ["MOTOR", "joint_roles", "mirrored_across", "with_role"]

_Z_AXIS = 2
# How far from level an axle may lean (the z part of its unit axis).
_LEVEL = 0.2
# A rocker's wheels lie ahead of its pivot and behind it, each more than this (m) across its axle.
_STRADDLE = 0.01
# Rockers are found this many levels up from the wheels at most (a rocker over a bogie).
_ROCKER_LEVELS = 3
# Twin screws sit apart across their axes; along them, at most this share of that (wheels on
# one axle sit apart along it).
_SCREWS_ALONG = 0.25
# A bicycle's wheels sit one behind the other: apart across their axles; along them, at most
# this share of that.
_IN_LINE = 0.25
# How many screws a vessel has, in mirrored pairs.
_SCREWS = (2, 4)
# How far (metres) two mirrored places may miss each other's mirror image.
_MIRROR_TOLERANCE = 0.02
# The fewest control surfaces an airframe's hinges are told by: two ailerons, a rudder and an
# elevator.
_CONTROL_SURFACES = 4
# The fewest free rollers on an omni or mecanum wheel's rim.
_ROLLERS = 3
# What a rim of rollers may be named for: a wheel, or a corner of the body (a leg's word too).
_A_RIMS_PARTS = frozenset({"leg", "wheel"})
# As many endless joints level with one link are a wheel-leg walker's legs, not its wheels.
_WHEEL_LEGS = 6
# A row of six or more is road wheels with this many known to carry their mass on their axles
# (by their inertials) for each one known to hang it off (a sprocket carrying its track drawn
# rigid on it).
_ON_AXLE_PER_OFF = 3
# How far (metres) a wheel's mass centre may lie off its axle (a CAD export's rounding); the
# whole-turning legs of the sets' wheel-leg walkers hang theirs 5 to 12 cm out.
_ON_THE_AXLE = 0.005
# A swing arm carries its wheel at least this far (metres) from its hinge's line (a flipper's
# motor turning on the flipper's own axis is no wheel it swings).
_SWING_ARM = 0.02
# The most endless joints above an unnamed wheel that hangs alone from its link (a caster's
# swivel; a rover's rocker, bogie and steering): below more, the endless leaf ends a limb drawn
# without limits (an arm's wrist that turns for ever), no wheel. Limited, sliding, planar and
# floating joints are not counted (a leg's, a suspension's, a planner's virtual root joints).
_MOST_ENDLESS_ABOVE_A_WHEEL = 3
# Nor below more movable joints than this in one unbranched chain, of any kind: a rover's
# steering, a wheel-leg's hip, thigh and knee; a seven-joint arm's last endless joint ends six.
# As many such leaves as this or more are wheeled feet (six-joint legs each ending in a wheel).
_MOST_JOINTS_ABOVE_A_WHEEL = 5
_WHEELED_FEET = 4
# A chain of this many movable joints or more from the body, its last a spinning leaf, may be a
# leg whose foot turns for ever (a hip, a thigh, a shin: :func:`_feet_dropped`).
_LEG_CHAIN_JOINTS = 3
# The most joints a walk up the tree takes (fixed ones included; a stranger's file is bounded).
_DEEPEST_WALK = 64
# A name that says only which corner of the body a part is at (``rear_left_joint``,
# ``front_right``): the leg pattern's word for a four-legged body's legs, and as often a wheel's.
# Matched whole, after any namespace (``robot1/rear_left_joint``), with a word for a joint or
# a link, or for the joint's type (``right_front_rev``), before or after, or the body it hangs
# from named first (``base_to_front_left``, the URDF tutorial's parent_to_child). Its corner
# words are the leg pattern's (rules/identification.yaml, ``leg``).
_JOINT_WORD = r"(?:joint|link|jnt|lnk|j|l|rev|revolute|cont|continuous)"
_FROM_THE_BODY = r"(?:(?:base|body|chassis|frame|hull|platform)(?:_link)?_to_)"
_ONLY_A_CORNER = re.compile(
    rf"(?:[\w.-]+/)*(?:{_FROM_THE_BODY}|{_JOINT_WORD}[_-]?)?"
    + CORNER
    + rf"(?:[_-]?{_JOINT_WORD})?[_\d]*",
    re.IGNORECASE,
)
_CORNER_WORDS = re.compile(CORNER, re.IGNORECASE)
# Wheel-legged robots roll on two legs' wheels or four (bipeds, quadrupeds).
_WHEEL_LEGGED = (2, 4)
# A leg's last joint named for a foot's part turns a foot, whatever its range (an ankle, a toe).
_FOOT_JOINT = re.compile(r"ankle|toe", re.IGNORECASE)
# Unnamed upright spinning leaves on one link are rotors from this many (a tricopter's).
_FEWEST_UNNAMED_ROTORS = 3
# ... and from this many when they are all on one upright line (a coaxial helicopter's).
_COAXIAL_ROTORS = 2
# Spinning leaves spaced round their own middle (:func:`_ring`): their distances from it, and
# their heights, differ by at most this share of the mean distance.
_RING_TOLERANCE = 0.1
# A revolute joint whose range spans this (a whole turn, pi rounded to 3.14 each way) may spin
# a propeller: an export that bounds every joint at +-pi writes its rotors so.
_WHOLE_TURN = 6.28
# How many revolute joints bounded alike a whole turn make an export's placeholder bounds.
_ALIKE_BOUNDED = 3
# How near a twin rotor is to the mirror image of a rotor a plugin names: this share of that
# rotor's distance from the root, at least this many metres.
_TWIN_SLACK = 0.05
_TWIN_FLOOR = 0.01
# An omni base's wheels, told by their axles alone: this many or more (a kiwi drive's three),
# each axle within this share of pointing at the middle of them all (the cosine of the angle
# between the axle and the line from the middle to the wheel, 0.95: 18 degrees).
_FEWEST_OMNI_WHEELS = 3
_POINTS_IN = 0.95
# A ball joint written as hinges: one about each axis.
_BALL_AXES = 3
# A motor named as such (``arm1_motor_link``, ``motor_2``), not ``motorcycle`` or ``rotor``.
MOTOR = re.compile(r"(^|[_/\s])motors?([_/\d\s]|$)", re.IGNORECASE)
# A joint named for steering (``fl_steer_motor``): it turns a wheel's heading, no propeller.
_STEER = re.compile(r"steer", re.IGNORECASE)
# A swerve drive's module (``module_1``, ``swerve_fl``, ``drive_module_2``): a wheel's heading
# and drive in one unit.
_MODULE = re.compile(r"swerve|(^|[_/])(drive_?)?modules?([_/\d]|$)", re.IGNORECASE)
# Roles a motor takes from the joints it turns through a coupling.
_DRIVEN = ("wheel", "rotor", "thruster")


def joint_roles(tree: JointTree) -> dict[str, Role]:
    """Wheels, casters, rotors, thrusters, fins and gripper joints, each with its evidence."""
    urdf = tree.urdf
    roles: dict[str, Role] = {}
    for joint in urdf.joints:
        role = tree.reader.read(joint, tree.moving_below)
        if role is not None:
            roles[joint.name] = role
    for name, why in jaws(tree, set(roles)).items():
        roles[name] = Role(name, "gripper", why)
    for name in _named_screws(tree, roles):
        roles[name] = Role(
            name,
            "thruster",
            f"named as a rotor ({roles[name].evidence}), but below the body beside its "
            "partner, turning about the line it pushes along (a screw)",
        )
    for name, why in _screws_by_place(tree, roles).items():
        roles[name] = Role(name, "thruster", why)
    for name, why in _unnamed_wheels(tree, roles).items():
        roles[name] = Role(name, "wheel", why)
    _give(
        roles,
        _roller_wheels(tree, roles),
        "wheel",
        "an endless joint on a level axle carrying free rollers round its rim (an omni or "
        "mecanum wheel), whatever its name",
    )
    _give(
        roles,
        _leg_wheels(tree, set(roles)),
        "wheel",
        "an endless leaf ending a leg of limited joints (a wheel-legged robot's wheel)",
    )
    roles.update(_control_surfaces(tree, roles))
    _give(
        roles,
        _drive_modules(tree, roles),
        "wheel",
        "a swerve drive's module (a wheel's heading and drive in one unit, its wheel not "
        "drawn): one of three or more endless leaves named as modules, on upright axes "
        "round their body",
    )
    _give(
        roles,
        _unnamed_rotors(tree, roles),
        "rotor",
        "an unnamed endless leaf on an upright axis, with others all round",
    )
    roles.update(tree.reader.casters({n: r for n, r in roles.items() if r.role == "wheel"}))
    roles.update(_steered_wheels(tree, roles))
    roles.update(_ball_casters(tree, roles))
    roles.update(_driven_casters(tree, roles))
    roles.update(_steering_beside(tree, roles))
    _drop_lone_rotors(tree, roles)
    _drop_flywheel(tree, roles)
    _drop_reaction_wheels(tree, roles)
    _drop_wheel_on_a_stand(tree, roles)
    roles.update(_coupled_drives(tree, roles))
    for name, why in endless_jaws(tree, set(roles)).items():
        roles[name] = Role(name, "gripper", why)
    for name in _gripper_carriers(tree, roles):
        del roles[name]
    grippers = gripper_closure(tree, {n for n, r in roles.items() if r.role == "gripper"})
    for name in grippers - set(roles):
        roles[name] = Role(name, "gripper", "moves a finger: below a gripper joint")
    return roles


def _control_surfaces(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """Unnamed limited hinges carrying nothing that moves, all on the root's rigid body, that
    are an airframe's control surfaces: a pair mirrored across the body turning about axes
    across it (ailerons), and behind them a hinge on the body's middle line about an upright
    axis (a rudder) and one more about an axis across the body (an elevator, on the middle line
    or mirrored). A tracked robot's flippers come in mirrored pairs too, about axes across the
    body, but no rudder turns behind them."""
    hinges = _lone_hinges(tree, roles)
    if len(hinges) < _CONTROL_SURFACES:
        return {}
    for first, second in mirrored_across(tree, hinges):
        ahead = tree.poses.place(first.child)[0]
        behind = [j for j in hinges if tree.poses.place(j.child)[0] < ahead]
        tail = _tail(tree, behind)
        if tail:
            why = (
                "an unnamed hinge of an airframe's control surfaces: ailerons mirrored across "
                "the body, a rudder and an elevator behind them"
            )
            return {j.name: Role(j.name, "fin", why) for j in (first, second, *tail)}
    return {}


def _lone_hinges(tree: JointTree, roles: Mapping[str, Role]) -> list[Joint]:
    """Limited hinges with no role, carrying nothing that moves, on the root's rigid body."""
    known: dict[str, str | None] = {}
    return [
        joint
        for joint in tree.urdf.joints
        if joint.name not in roles
        and joint.type == "revolute"
        and joint.child not in tree.moving_below
        and moved_by(tree.urdf, joint.parent, known) is None
    ]


def _tail(tree: JointTree, behind: list[Joint]) -> list[Joint]:
    """The rudders (on the middle line, about upright axes) and elevators (about axes across
    the body, on the middle line or mirrored) among ``behind``; none unless there are both."""
    rudders = [
        j
        for j in behind
        if abs(tree.poses.axis(j)[_Z_AXIS]) >= 1 - _LEVEL and _on_the_middle_line(tree, j)
    ]
    paired = {j.name for pair in mirrored_across(tree, behind) for j in pair}
    elevators = [
        j for j in behind if _across(tree, j) and (_on_the_middle_line(tree, j) or j.name in paired)
    ]
    return [*rudders, *elevators] if rudders and elevators else []


def mirrored_across(tree: JointTree, joints: list[Joint]) -> Iterator[tuple[Joint, Joint]]:
    """Each pair of ``joints`` mirrored across the body's middle (:func:`_mirrored_pairs`),
    both turning about axes across it (a wing's ailerons, a tracked robot's flippers)."""
    across = [j for j in joints if _across(tree, j)]
    for first, second in itertools.combinations(across, 2):
        if _mirrored_pairs(tree, [first, second]):
            yield first, second


def _across(tree: JointTree, joint: Joint) -> bool:
    """``joint`` turns about an axis across the body (y, level)."""
    return abs(tree.poses.axis(joint)[1]) >= 1 - _LEVEL


def _on_the_middle_line(tree: JointTree, joint: Joint) -> bool:
    """``joint`` sits on the body's middle line (y = 0 in its root's frame)."""
    return abs(tree.poses.place(joint.child)[1]) <= _MIRROR_TOLERANCE


def _ball_casters(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """Three endless joints in a row about three different axes through one point (no offset
    between them), none driven, carrying nothing that moves: a ball caster written as a ball
    joint, passive, not an arm, hanging from a base that has wheels (a wrist hangs from an arm).
    One walk up from each leaf: linear in the joints."""
    found: dict[str, Role] = {}
    if not any(r.role == "wheel" for r in roles.values()):
        return found
    known: dict[str, str | None] = {}  # one memo for every upward walk (as limbs.moved_by)
    for leaf in tree.urdf.joints:
        if leaf.type != "continuous" or leaf.child in tree.moving_below or leaf.name in roles:
            continue
        chain = [leaf]
        while len(chain) < _BALL_AXES:
            above = tree.urdf.parent_joint(chain[-1].parent)
            if above is None or above.type != "continuous" or above.name in roles:
                break
            chain.append(above)
        if (
            _ball(tree, chain)
            and not points_a_sensor(tree, chain[0])  # a three-axis gimbal carries a camera
            and moved_by(tree.urdf, chain[-1].parent, known) is None
        ):
            names = ", ".join(j.name for j in reversed(chain))
            for joint in chain:
                found[joint.name] = Role(joint.name, "caster", f"a ball joint ({names}), undriven")
    return found


def _ball(tree: JointTree, chain: list[Joint]) -> bool:
    """``chain`` (leaf first) turns about three axes through one point, and nothing drives it."""
    return (
        len(chain) == _BALL_AXES
        and {main_axis(j.axis) for j in chain} == {0, 1, _Z_AXIS}
        and all(j.origin == (0.0, 0.0, 0.0) for j in chain[:-1])
        and not any(j.name in tree.urdf.controlled_joints for j in chain)
    )


def _driven_casters(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """A driven caster is no caster: its swivel steers, its wheels drive."""
    found = {}
    for name, role in roles.items():
        driven = tree.urdf.joint(name)
        if role.role == "caster" and driven is not None and name in tree.urdf.controlled_joints:
            if main_axis(local_axis(driven)) == _Z_AXIS:
                found[name] = Role(name, "steering", "a vertical swivel with a transmission")
            else:
                found[name] = Role(name, "wheel", "a caster's wheel with a transmission")
    return found


def _steering_beside(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """On a base whose wheels are already steered, another vertical swivel with a transmission
    that carries nothing that moves (no wheel of its own, no limb name) and hangs from the base
    through no driven joint (not a wrist's last joint) steers too: the steering input of the
    vehicle (a virtual front wheel the hardware maps onto the steered wheels), not a limb to
    command joint by joint."""
    steered = [n for n, r in roles.items() if r.role == "steering"]
    if not steered:
        return {}
    found = {}
    # By whether a leaf's axle is level at rest: link -> the nearest driven joint above it.
    known: dict[bool, dict[str, str | None]] = {}
    for joint in tree.urdf.joints:
        if (
            joint.name not in roles
            and joint.type in ("revolute", "continuous")
            and joint.name in tree.urdf.controlled_joints
            and main_axis(local_axis(joint)) == _Z_AXIS
            and joint.child not in tree.moving_below
            and not (tree.parts_of(joint.name) | tree.parts_of(joint.child))
            and not points_a_sensor(tree, joint)  # a spinning scanner's mount is a head
            and _hangs_freely(tree, joint, known)  # not an arm's last joint
        ):
            why = f"a driven vertical swivel beside {len(steered)} steering joint(s)"
            found[joint.name] = Role(joint.name, "steering", why)
    return found


def _drop_lone_rotors(tree: JointTree, roles: dict[str, Role]) -> None:
    """Rotors too few to fly are none (one spinning leaf is a motor or a tool), unless a
    simulator poses them, or their twins make up the number (:func:`_rotor_twins`)."""
    rotors = [n for n, r in roles.items() if r.role == "rotor"]
    posed = any(roles[n].evidence.endswith(POSED) for n in rotors)
    if not rotors or posed or len(rotors) >= tree.profile.limb("min_rotors"):
        return
    twins = _rotor_twins(tree, roles, rotors)
    if len(rotors) + len(twins) >= tree.profile.limb("min_rotors"):
        roles.update(twins)
        return
    for name in rotors:
        del roles[name]


def _rotor_twins(tree: JointTree, roles: Mapping[str, Role], rotors: list[str]) -> dict[str, Role]:
    """Endless leaves of no role, each where one of the ``rotors`` a plugin names (too few to
    fly) is seen in a mirror through the root (left for right, front for back, or both),
    within :data:`_TWIN_SLACK` of that rotor's distance from it: its twin, a motor whose plugin
    its author did not write yet (a bicopter's second motor). Sought only for so few rotors."""
    named = [(n, tree.poses.place(j.child)) for n in rotors if (j := tree.urdf.joint(n))]
    found: dict[str, Role] = {}
    for joint in tree.urdf.joints:
        if (
            joint.name in roles
            or not (joint.endless and joint.actuated)
            or joint.child in tree.moving_below
        ):
            continue
        place = tree.poses.place(joint.child)
        twin = next((name for name, at in named if _mirror_image(place, at)), None)
        if twin is not None:
            why = f"the mirror image of rotor {twin}, an endless leaf no plugin names (its twin)"
            found[joint.name] = Role(joint.name, "rotor", why)
    return found


def _mirror_image(place: Vector, other: Vector) -> bool:
    """``place`` is ``other`` seen in a mirror through the root's origin (left for right, front
    for back, or both), within :data:`_TWIN_SLACK` of its distance from the origin (a CAD
    export's few millimetres; at least :data:`_TWIN_FLOOR`), and not ``other`` itself."""
    slack = max(_TWIN_FLOOR, _TWIN_SLACK * math.dist(other, (0.0, 0.0, 0.0)))
    if math.dist(place, other) <= slack:
        return False
    x, y, z = other
    return any(math.dist(place, image) <= slack for image in ((x, -y, z), (-x, y, z), (-x, -y, z)))


def _undriven_wheels(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """The joints ``roles`` reads as wheels, when no drive or track plugin moves the body (what
    the rules below may find turns no wheel that rolls); none when one does."""
    if tree.labels("drive") or tree.labels("track"):
        return []
    return [name for name, role in roles.items() if role.role == "wheel"]


def _drop_flywheel(tree: JointTree, roles: dict[str, Role]) -> None:
    """The body's only wheel, with no drive or track plugin, drawn as a disc whose rim stays
    above the bottom of the box its link is drawn as, is no wheel: nothing it turns reaches
    the ground (a reaction wheel in a balancing cube, a flywheel; a wheel's rim reaches below
    its body)."""
    wheels = _undriven_wheels(tree, roles)
    if len(wheels) != 1:
        return
    joint = tree.urdf.joint(wheels[0])
    body = None if joint is None else tree.urdf.link(joint.parent)
    disc = None if joint is None else tree.urdf.link(joint.child)
    if joint is None or body is None or body.box is None or disc is None or disc.cylinder is None:
        return
    box = body.box
    centre = (
        tree.poses.place(body.name)[2] + tree.poses.turned(body.name, (0.0, 0.0, 0.0), box.xyz)[2]
    )
    reach = tree.poses.extent(body.name, box.rpy, box.size)[2] / 2
    rim = tree.poses.place(disc.name)[2] - disc.cylinder.radius
    if rim > centre - reach + _GROUND_GAP:  # NaN compares false: a wheel still
        del roles[wheels[0]]


def _drop_reaction_wheels(tree: JointTree, roles: dict[str, Role]) -> None:
    """Wheels that turn about three square axes as the body rests, one of them upright, with
    no drive or track plugin, are no wheels: a spacecraft's reaction wheels, a pair or one per
    axis, turn it in place (a CubeSat's attitude testbed). A ground vehicle's wheels roll on
    level axles; an omni base's point two ways, both level."""
    wheels = _undriven_wheels(tree, roles)
    if len(wheels) < _AXES:
        return
    axes = [tree.poses.axis(joint) for name in wheels if (joint := tree.urdf.joint(name))]
    if _as_many_about_three_axes(axes):
        why = "a reaction wheel: the body's wheels turn about three square axes, none rolls"
        for name in wheels:
            roles[name] = Role(name, "passive", why)


def _as_many_about_three_axes(axes: list[Vector]) -> bool:
    """``axes`` lie along three square lines, one upright, as many along each (one or a pair
    each): an omni base's four level wheels and a turntable are no such set."""
    upright = [axis for axis in axes if _upright(axis)]
    level = [axis for axis in axes if _axle(axis)]
    if not upright or len(upright) + len(level) != len(axes):
        return False  # no wheel upright, or one tilted
    along = [axis for axis in level if parallel(axis, level[0])]
    across = [axis for axis in level if perpendicular(axis, level[0])]
    whole = len(along) + len(across) == len(level)
    return whole and len(along) == len(across) == len(upright)


def _drop_wheel_on_a_stand(tree: JointTree, roles: dict[str, Role]) -> None:
    """A wheel that is the robot's only moving joint, with no drive or track plugin, moves no
    vehicle: one wheel alone can neither steer nor stand (a wheel on a test stand, a rig a
    script spins). A unicycle or a monowheel balances on more joints than its wheel."""
    wheels = _undriven_wheels(tree, roles)
    if len(wheels) == 1 and sum(1 for joint in tree.urdf.joints if joint.movable) == 1:
        del roles[wheels[0]]


# A body turns about three axes.
_AXES = 3


def _coupled_drives(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """A motor whose mimic followers are all wheels, rotors or thrusters plays their role: it
    turns them through a gear (its transmission drives the vehicle, not a limb)."""
    found = {}
    for driver, followers in tree.couplings.followers.items():
        kinds = {roles[f].role for f in followers if f in roles}
        if driver in roles or len(kinds) != 1 or not kinds <= set(_DRIVEN):
            continue
        (kind,) = kinds
        names = ", ".join(followers[:3])
        found[driver] = Role(driver, kind, f"turns the {kind} joint(s) {names} (mimic coupling)")
    return found


def with_role(roles: Mapping[str, Role], role: str) -> list[str]:
    """The joints of ``roles`` that play ``role``, in the order they were found."""
    return [name for name, r in roles.items() if r.role == role]


def _axle(axis: tuple[float, float, float]) -> bool:
    """A level axis: a wheel's axle (a rotor turns about an upright one)."""
    return abs(axis[_Z_AXIS]) < _LEVEL


def _upright(axis: tuple[float, float, float]) -> bool:
    """An upright axis: a rotor's, a caster's or a steering knuckle's swivel."""
    return abs(axis[_Z_AXIS]) >= 1 - _LEVEL


def _hangs_freely(
    tree: JointTree,
    leaf: Joint,
    known: dict[bool, dict[str, str | None]],
    rockers: frozenset[str] = frozenset(),
) -> bool:
    """No joint above ``leaf`` (a wheel, a swivel) up to the root is driven (a transmission or
    ros2_control) but about an upright axis (steering): upright in its parent's frame, or as
    the body rests when ``leaf`` turns about a level axle as the body rests (a rover's steering
    joint on a deployment link whose frame is turned; above a leaf upright at rest too, a
    turned-frame SCARA's tool, it is no steering). Above a leaf not level at rest, a joint
    upright in its parent's frame but not as the body rests is no steering either (an arm
    drawn with every joint about its parent's z axis: its wrist's last joint is no swivel of
    the base). A driven rocker (``rockers``, :func:`_rockers`) lifts nothing. ``known`` caches
    the walks by that axle, for these ``rockers``."""
    rolls = _axle(tree.poses.axis(leaf))
    return _lifter(tree, leaf.parent, rolls, known, rockers) is None


def _on_a_swing_arm(tree: JointTree, leaf: Joint, known: dict[str, str | None]) -> bool:
    """``leaf`` turns about a level axle, drawn round it (:func:`_drawn_round`: a cylinder
    about the axle, centred on it) and not known to hang its mass off it (:func:`_balance`),
    and hangs from the body by one hinge about an axis parallel to it, more than
    :data:`_SWING_ARM` from its line, nothing moving above that hinge but a joint placing the
    whole body (:func:`_places_the_body`): a wheel on a swing arm that lifts it (a rover's
    leg raising a corner, a wheel-legged base's single-joint leg). A walker's knee turning for
    ever is drawn along its shank, not round its axis, and one hinge makes no leg to walk on
    (``known``: the walk's memo)."""
    axle = tree.poses.axis(leaf)
    above = moved_by(tree.urdf, leaf.parent, known)
    arm = tree.urdf.joint(above) if above is not None else None
    return (
        arm is not None
        and _turns(arm)
        and _axle(axle)
        and parallel(tree.poses.axis(arm), axle)
        and _places_the_body(tree, moved_by(tree.urdf, arm.parent, known))
        and off_axis(minus(tree.poses.place(leaf.child), tree.poses.place(arm.child)), axle)
        > _SWING_ARM
        and _drawn_round(tree, leaf)
        and _balance(tree, leaf) is not False
    )


def _lifter(
    tree: JointTree,
    link: str,
    rolls: bool,
    known: dict[bool, dict[str, str | None]],
    rockers: frozenset[str] = frozenset(),
) -> str | None:
    """The nearest driven joint above ``link`` that is no steering nor one of the ``rockers``
    (:func:`_hangs_freely`), for a leaf that turns about a level axle at rest (``rolls``) or
    not."""
    driven = tree.urdf.controlled_joints

    def lifts(joint: Joint) -> bool:
        if not (joint.movable and joint.name in driven) or joint.name in rockers:
            return False
        here, at_rest = _upright(local_axis(joint)), _upright(tree.poses.axis(joint))
        return not (here or at_rest) if rolls else not (here and at_rest)

    return nearest_above(tree.urdf, link, known.setdefault(rolls, {}), lifts)


def _rockers(tree: JointTree, leaves: list[Joint]) -> frozenset[str]:
    """Driven joints about a level axle, each the nearest driven joint above two or more of
    ``leaves`` (wheels to be), some ahead of its pivot and some behind as the body rests: a
    rover's rockers, whose suspension a simulator drives. A rocker balances what it carries on
    the ground and lifts none of it (a flipper's sprocket and idler lie on one side of its
    pivot, a wheel-legged robot's leg carries one wheel). Found from the wheels up, passing
    over the rockers found, at most :data:`_ROCKER_LEVELS` deep (a rocker carrying a bogie
    that is one, and a wheel of its own)."""
    found: frozenset[str] = frozenset()
    for _ in range(_ROCKER_LEVELS):
        known: dict[bool, dict[str, str | None]] = {}  # for these rockers
        carried: dict[str, list[Joint]] = {}
        for leaf in leaves:
            rolls = _axle(tree.poses.axis(leaf))
            lifter = _lifter(tree, leaf.parent, rolls, known, found)
            if lifter is not None:
                carried.setdefault(lifter, []).append(leaf)
        more = {name for name, below in carried.items() if _straddles(tree, name, below)}
        if not more:
            break
        found |= more
    return found


def _straddles(tree: JointTree, name: str, leaves: list[Joint]) -> bool:
    """The joint ``name`` turns about a level axle and ``leaves`` lie both ahead of its pivot
    and behind it (more than :data:`_STRADDLE` each way, across the axle, as the body rests; a
    place that overflows is neither)."""
    joint = tree.urdf.joint(name)
    if joint is None or len(leaves) < 2:
        return False
    axis = tree.poses.axis(joint)
    if not _axle(axis):
        return False
    ahead = (axis[1], -axis[0], 0.0)  # level, across the axle
    pivot = tree.poses.place(joint.child)
    reach = [dot(minus(tree.poses.place(leaf.child), pivot), ahead) for leaf in leaves]
    return any(r < -_STRADDLE for r in reach) and any(r > _STRADDLE for r in reach)


def _few_endless_above(tree: JointTree, leaf: Joint, known: dict[str, str | None]) -> bool:
    """At most :data:`_MOST_ENDLESS_ABOVE_A_WHEEL` endless joints between the root and
    ``leaf``'s link: each found by :func:`nearest_above`, whose walks ``known`` remembers, so
    many leaves cost one walk of the tree at most."""
    link = leaf.parent
    for _ in range(_MOST_ENDLESS_ABOVE_A_WHEEL + 1):
        above = nearest_above(tree.urdf, link, known, _endless)
        joint = tree.urdf.joint(above) if above is not None else None
        if joint is None:
            return True
        link = joint.parent
    return False


def _wrists_dropped(tree: JointTree, leaves: list[Joint], branching: frozenset[str]) -> list[Joint]:
    """``leaves`` but the last joints of arms: fewer than :data:`_WHEELED_FEET` leaves that
    each end more than :data:`_MOST_JOINTS_ABOVE_A_WHEEL` movable joints of one unbranched chain
    (up to the nearest link that carries another moving part: the body, a bogie) are wrists (a
    robot's one or two arms); four or more so deep are a walker's wheeled feet (six-joint legs,
    each ending in a wheel)."""
    deep = {j.name for j in leaves if _deep(tree, j, branching)}
    if not deep or len(deep) >= _WHEELED_FEET:
        return leaves
    return [j for j in leaves if j.name not in deep]


def _feet_dropped(tree: JointTree, leaves: list[Joint], branching: frozenset[str]) -> list[Joint]:
    """``leaves`` but a walker's feet: a leaf ending an unbranched chain of
    :data:`_LEG_CHAIN_JOINTS` movable joints or more from a link that carries other moving
    parts (the body), when that link carries more such chains with as many movable joints
    ending in no leaf of ``leaves`` than ending in one (a hexapod drawn without limits: two of
    its six feet turn about level axles, four do not). Chains are told alike by where they
    start and how many joints move in them. A wheel-legged robot's legs all end in wheels."""
    if not leaves:
        return leaves
    tips = (j for j in tree.urdf.joints if j.movable and j.child not in tree.moving_below)
    chains = {tip.name: _chain_from_branch(tree, tip, branching) for tip in tips}
    alike = Counter(chain for chain in chains.values() if chain is not None)
    rolling = Counter(chain for leaf in leaves if (chain := chains.get(leaf.name)) is not None)
    return [
        leaf
        for leaf in leaves
        if (chain := chains.get(leaf.name)) is None
        or chain[1] < _LEG_CHAIN_JOINTS
        or alike[chain] - rolling[chain] <= rolling[chain]
    ]


def _chain_from_branch(
    tree: JointTree, tip: Joint, branching: frozenset[str]
) -> tuple[str, int] | None:
    """The link of ``branching`` an unbranched chain ending in ``tip`` hangs from and how many
    movable joints it has; None when the walk finds none within :data:`_DEEPEST_WALK` joints."""
    movable = 0
    joint: Joint | None = tip
    for _ in range(_DEEPEST_WALK):
        if joint is None:
            return None
        movable += joint.movable
        if joint.parent in branching:
            return joint.parent, movable
        joint = tree.urdf.parent_joint(joint.parent)
    return None


def _grounded(tree: JointTree, leaves: list[Joint]) -> list[Joint]:
    """``leaves`` but those turning about an upright axis as the body rests: a wheel rolls on a
    level axle; a humanoid's wrists that turn for ever (a yaw under the forearm) point down."""
    return [j for j in leaves if not _upright(tree.poses.axis(j))]


def _deep(tree: JointTree, leaf: Joint, branching: frozenset[str]) -> bool:
    """More than :data:`_MOST_JOINTS_ABOVE_A_WHEEL` movable joints between ``leaf``'s link and
    the nearest link of ``branching`` above it (a walk of a few dozen joints at most)."""
    movable = 0
    link = leaf.parent
    for _ in range(_DEEPEST_WALK):
        joint = tree.urdf.parent_joint(link)
        if joint is None or link in branching:
            return False
        movable += joint.movable
        if movable > _MOST_JOINTS_ABOVE_A_WHEEL:
            return True
        link = joint.parent
    return False


def _branching_links(tree: JointTree) -> frozenset[str]:
    """Links on which more than one joint moves or carries something that moves, in one pass
    over the joints."""
    moving = Counter(
        j.parent for j in tree.urdf.joints if j.movable or j.child in tree.moving_below
    )
    return frozenset(link for link, count in moving.items() if count > 1)


def _endless(joint: Joint) -> bool:
    return joint.endless


def _rollers_only(tree: JointTree, joint: Joint, roles: Mapping[str, Role]) -> bool:
    """Everything that moves below ``joint`` is an endless leaf hanging from the part it turns
    (its child, or a hub fixed to it), three or more of them, none with a role but a wheel's (a
    finger, a rotor's blade): the free rollers on the rim of an omni or mecanum wheel."""
    rollers = 0
    for below in _carried(tree, joint):
        if not below.endless or below.child in tree.moving_below:
            return False  # a limited joint, or something moves deeper: no rim of rollers
        if below.name in roles and roles[below.name].role != "wheel":
            return False  # a finger on a wrist that rolls, a blade on a propeller's hub
        rollers += 1
    return rollers >= _ROLLERS


def _spokes_only(tree: JointTree, joint: Joint) -> bool:
    """Everything that moves below ``joint`` is a slide leaf of no name starting on its axle
    and sliding square to it, three or more of them spread all round it (no gap of half a turn
    between them): the spokes a transformable wheel extends (a wheel-leg's whegs). A chuck's
    jaws sit ahead of their flange, off the axle's point."""
    spokes = _carried(tree, joint)
    if len(spokes) < _ROLLERS:
        return False
    axis = tree.poses.axis(joint)
    start = tree.poses.place(joint.child)
    bearings: list[Vector] = []
    for spoke in spokes:
        if (
            spoke.type != "prismatic"
            or spoke.child in tree.moving_below
            or tree.parts_of(spoke.name) | tree.parts_of(spoke.child)
            or distance(tree.poses.place(spoke.child), start) > _ON_THE_AXLE
            or not perpendicular(tree.poses.axis(spoke), axis)
        ):
            return False
        bearings.append(tree.poses.axis(spoke))
    return _all_round(bearings, axis)


def _all_round(directions: list[Vector], axis: Vector) -> bool:
    """The ``directions`` (square to ``axis``) leave no gap of half a turn about it."""
    first = directions[0]
    side = cross(axis, first)
    return _no_half_turn_gap([math.atan2(dot(d, side), dot(d, first)) for d in directions])


def _no_half_turn_gap(angles: list[float]) -> bool:
    """The ``angles`` (radians) leave no gap of half a turn between neighbours, round the
    circle."""
    ordered = sorted(angles)
    gaps = [b - a for a, b in itertools.pairwise(ordered)]
    gaps.append(ordered[0] + 2 * math.pi - ordered[-1])
    return max(gaps) < math.pi


def _on_a_spinning_part(tree: JointTree, joint: Joint, known: dict[str, str | None]) -> bool:
    """``joint`` hangs from a part an endless joint turns about a level axle: a roller on a
    wheel's rim, no wheel (a caster's swivel turns about an upright axis and carries one)."""
    above = moved_by(tree.urdf, joint.parent, known)
    carrier = tree.urdf.joint(above) if above is not None else None
    return carrier is not None and carrier.type == "continuous" and _axle(local_axis(carrier))


_SIDES = "an unnamed endless joint below its link or on a level axle, wheels on both sides"
_AXLE_ENDS = "an unnamed endless joint at one end of a level axle, another at its other end"
_POINTING_IN = (
    "an unnamed endless joint on a level axle pointing at the middle of them all, the others "
    "all round it (an omni base's wheels)"
)


def _unnamed_wheels(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, str]:
    """Unnamed spinning leaves below a link, on both its sides: wheels.

    A base whose wheel joints carry no name (``fl_joint`` on ``fl_Link``) still has them where
    wheels are: continuous joints (no limits, they turn for ever) that carry nothing that
    moves, hanging below the link they are on or turning about a level axis across it (a
    wheel's axle, whatever the height of the link's origin; in the body's frame too on a link
    fixed to the body or sliding on it), at least one on each side of it.
    Sides are told from the link's mass centre when its file gives one (:func:`_middle`); three
    or more all round the middle of them, their axles pointing at it, are an omni base's wheels
    wherever the link's origin is (:func:`_pointing_in`). Each with its evidence. Fingers have
    limits; rotors sit level with or above their body and turn about an upright
    axis; a propeller on a wing turns about the axis it flies along. Six or more level with a
    link are a wheel-leg walker's whole-turning legs (:func:`~solver.identify.limbs.find_limbs`),
    unless they carry their mass on their axles (:func:`_mostly_balanced`): a leg that turns
    whole hangs its mass out along the leg, a wheel is round about its axle (an eight-wheeled
    skid-steer base, a tracked base's road wheels).
    """
    below, level = _wheel_candidates(tree, roles)
    driven = bool(tree.labels("drive") or tree.labels("track"))
    for link, joints in level.items():
        if len(joints) < _WHEEL_LEGS or driven or _mostly_balanced(tree, joints):
            below.setdefault(link, []).extend(joints)  # road wheels, not legs
    endless: dict[str, str | None] = {}  # link -> the nearest endless joint above it
    found, apart = _told_on_their_link(tree, below, endless)
    # One on a caster's swivel or a steering knuckle, two on a rocker, one on a swing arm:
    # sides told across the whole body instead, for those that hang from the body through no
    # driven joint but a steering one or a rocker (a driven flipper's sprocket is the
    # flipper's), or on a swing arm (:func:`_on_a_swing_arm`), and few that turn for ever
    # (:func:`_few_endless_above`: the last joints of two arms drawn without limits are no
    # wheels).
    # By whether a leaf's axle is level at rest: link -> the nearest driven joint above it.
    known: dict[bool, dict[str, str | None]] = {}
    rockers = _rockers(tree, apart)
    swung: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    apart = [
        j
        for j in apart
        if (_hangs_freely(tree, j, known, rockers) or _on_a_swing_arm(tree, j, swung))
        and _few_endless_above(tree, j, endless)
    ]
    branching = _branching_links(tree)  # links that carry more than one moving part
    apart = _wrists_dropped(tree, apart, branching)
    apart = _feet_dropped(tree, _grounded(tree, apart), branching)
    side_by_side = len(apart) >= 2 and _sides({tree.poses.place(j.child)[1] for j in apart})
    if side_by_side or _in_line(tree, apart):
        found.update(dict.fromkeys((j.name for j in apart), _SIDES))
    elif _axle_ends(tree, tree.urdf.root, apart):  # a steered pair, on a body facing along y
        found.update(dict.fromkeys((j.name for j in apart), _AXLE_ENDS))
    return found


def _told_on_their_link(
    tree: JointTree, below: dict[str, list[Joint]], endless: dict[str, str | None]
) -> tuple[dict[str, str], list[Joint]]:
    """The wheels among ``below`` (link -> the candidates it carries) told on their own link:
    two or more on both sides of its middle, or three or more pointing in
    (:func:`_pointing_in`), each with its evidence; and the rest, to be told across the body.
    Not on a link below more endless joints than a wheel hangs from
    (:func:`_few_endless_above`, whose walks ``endless`` remembers): two jaws that turn for
    ever at the end of an arm drawn without limits (fresh set 1879's five-joint arm)."""
    found: dict[str, str] = {}
    apart: list[Joint] = []
    for link, joints in below.items():
        if not _few_endless_above(tree, joints[0], endless):
            apart.extend(joints)  # told across the body, where such leaves are no wheels
            continue
        middle = _middle(tree, link)
        if len(joints) >= 2 and _sides({j.origin[1] - middle for j in joints}):
            found.update(dict.fromkeys((j.name for j in joints), _SIDES))
        elif _axle_ends(tree, link, joints):
            found.update(dict.fromkeys((j.name for j in joints), _AXLE_ENDS))
        elif _pointing_in(tree, joints):
            found.update(dict.fromkeys((j.name for j in joints), _POINTING_IN))
        else:
            apart.extend(joints)
    return found, apart


def _axle_ends(tree: JointTree, link: str, joints: list[Joint]) -> bool:
    """Two or more, about one level axle as the body rests, at its two ends (those at one end
    at one place) and the link's middle between them: a pair of wheels side by side on a body
    drawn facing another way than x (its wheels apart along x, not y: a balancing robot's CAD
    frame), where sides across y say nothing; a tracked hull's sprocket and road wheel drawn
    at one place at each end of its axle are two pairs. A hand's knuckles in a row along one
    line sit at as many places as there are fingers."""
    if len(joints) < 2:
        return False
    axes = [tree.poses.axis(joint) for joint in joints]
    if not all(_axle(axis) and parallel(axes[0], axis) for axis in axes):
        return False
    ends = [tree.poses.place(joint.child) for joint in joints]
    # NaN fails the test too.
    if not all(off_axis(minus(end, ends[0]), axes[0]) <= _AXLE_OFFSET for end in ends[1:]):
        return False
    middle = tree.poses.mass_centre(link) or tree.poses.place(link)
    sides = [dot(minus(end, middle), axes[0]) for end in ends]
    if not min(sides) < 0 < max(sides):
        return False
    for negative in (True, False):
        at_end = [end for end, side in zip(ends, sides, strict=True) if (side < 0) == negative]
        if any(distance(end, at_end[0]) > _AXLE_OFFSET for end in at_end[1:]):
            return False
    return True


# How far (metres) two wheels on one axle may lie off the line of the first one's axis.
_AXLE_OFFSET = 0.01


def _pointing_in(tree: JointTree, joints: list[Joint]) -> bool:
    """Three or more (:data:`_FEWEST_OMNI_WHEELS`) turning about level axles as the body
    rests, all round the middle of them (no gap of half a turn between them, seen from above),
    each axle pointing at that middle (:data:`_POINTS_IN`): an omni base's wheels (a kiwi
    drive's three at 120 degrees, four at the corners), wherever its link's origin is (a CAD
    export puts it at a corner, so sides of it say nothing). A car's axles lie across the
    body, a caster's behind its swivel; a hand's fingers stop, a rotor turns upright. Each
    test is written so that a stranger's overflowing numbers (NaN, infinite) fail it."""
    if len(joints) < _FEWEST_OMNI_WHEELS:
        return False
    places = [tree.poses.place(joint.child) for joint in joints]
    middle = [sum(place[k] for place in places) / len(places) for k in range(2)]
    bearings: list[float] = []
    for joint, place in zip(joints, places, strict=True):
        axis = tree.poses.axis(joint)
        out = (place[0] - middle[0], place[1] - middle[1])
        reach = math.hypot(*out) * math.hypot(axis[0], axis[1])
        if not (_axle(axis) and math.isfinite(reach) and reach > 0):
            return False
        if not abs(out[0] * axis[0] + out[1] * axis[1]) >= _POINTS_IN * reach:
            return False
        bearings.append(math.atan2(out[1], out[0]))
    return _no_half_turn_gap(bearings)


def _in_line(tree: JointTree, leaves: list[Joint]) -> bool:
    """Two leaves, each carrying its mass on its axle (:func:`_balanced`), about parallel
    level axles as the body rests, one behind the other (apart across their axles, not along
    them), one on the body and the other steered (:func:`_steered_by`; endless or limited: a
    fork steers within stops): a bicycle's or a scooter's wheels, the front one steered.
    Wheels side by side are told by :func:`_sides`."""
    if len(leaves) != 2 or not all(_balanced(tree, leaf) for leaf in leaves):
        return False
    axes = [tree.poses.axis(leaf) for leaf in leaves]
    if not all(_axle(axis) for axis in axes) or not parallel(axes[0], axes[1]):
        return False
    known: dict[str, str | None] = {}
    above = [nearest_above(tree.urdf, leaf.parent, known, _turns) for leaf in leaves]
    if above.count(None) != 1:
        return False
    steered = leaves[0] if above[0] is not None else leaves[1]
    if _steered_by(tree, steered, known) is None:
        return False
    gap = minus(tree.poses.place(leaves[0].child), tree.poses.place(leaves[1].child))
    across = off_axis(gap, axes[0])
    return across > 0 and abs(dot(gap, axes[0])) <= _IN_LINE * across


def _balanced(tree: JointTree, joint: Joint) -> bool:
    """The part ``joint`` turns is known to carry its mass on its axle (:func:`_balance`)."""
    return _balance(tree, joint) is True


def _mostly_balanced(tree: JointTree, joints: list[Joint]) -> bool:
    """More than half of the parts ``joints`` turn are known to carry their mass on the axle
    (:func:`_balance`) or, where the file leaves that out, drawn round it
    (:func:`_drawn_round`): a row of road wheels whose few idlers' files leave out where their
    mass is. A part known to hang its mass off its axle (a whole-turning leg hangs it out along
    the leg) is outvoted only by :data:`_ON_AXLE_PER_OFF` times as many whose mass is known on
    it, a drawing's guess aside: a tracked base's drive sprockets carrying the tracks drawn
    rigid on them among idlers that carry theirs on their axles."""
    known = [_balance(tree, joint) for joint in joints]
    verdicts = [
        (_drawn_round(tree, joint) or None) if verdict is None else verdict
        for verdict, joint in zip(known, joints, strict=True)
    ]
    on, off = known.count(True), known.count(False)
    return 2 * verdicts.count(True) > len(verdicts) and on >= _ON_AXLE_PER_OFF * off


def _drawn_round(tree: JointTree, joint: Joint) -> bool:
    """The part ``joint`` turns is drawn as a cylinder about the joint's axis and centred on
    it (within :data:`_ON_THE_AXLE`): a tyre round its axle, where the file leaves out where its
    mass is. A whole-turning leg is drawn out along the leg, or as a rod across its axle."""
    link = tree.urdf.link(joint.child)
    shape = None if link is None else link.cylinder
    if shape is None:
        return False
    axis = tree.poses.axis(joint)
    along = tree.poses.turned(joint.child, shape.rpy, (0.0, 0.0, 1.0))
    centre = tree.poses.turned(joint.child, (0.0, 0.0, 0.0), shape.xyz)
    return parallel(along, axis) and off_axis(centre, axis) <= _ON_THE_AXLE


def _balance(tree: JointTree, joint: Joint) -> bool | None:
    """Whether the part ``joint`` turns (its link and the links fixed below it) has its mass
    centre on the joint's axis (within :data:`_ON_THE_AXLE`), read as the body rests: a
    wheel's, round about its axle; a leg drawn as a motor's hub with the leg fixed below it
    hangs its mass out. None when nothing is known of it: a link of the part with a mass gives
    no place for it, or none has a mass."""
    total = 0.0
    moment = [0.0, 0.0, 0.0]
    for name in (joint.child, *tree.urdf.fixed_below(joint.child)):
        link = tree.urdf.link(name)
        if link is None or link.mass is None:
            continue
        place = tree.poses.mass_centre(name)
        if place is None:
            return None
        total += link.mass
        for k in range(3):
            moment[k] += link.mass * place[k]
    if total <= 0 or not math.isfinite(total):
        return None
    centre = (moment[0] / total, moment[1] / total, moment[2] / total)
    lever = minus(centre, tree.poses.place(joint.child))  # from the joint, on its axis
    return off_axis(lever, tree.poses.axis(joint)) <= _ON_THE_AXLE


def _roller_wheels(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Endless joints of no role yet, each turning about a level axle at rest and carrying
    nothing that moves but free rollers round the part it turns (:func:`_rollers_only`; none of
    them a finger, a rotor or anything but a wheel by its name), on both sides of the body, each
    roller about an axis across the joint's (:func:`_rolls_across`): an omni or mecanum base's
    wheels drawn with their rollers, named for what they are (``rim_front_right``: a corner's
    word names a leg as often) or not at all. A joint named as a part other than a leg's or a
    wheel's (a wrist, a propeller) or as a foot's (an ankle, a toe) is that part; a leg carries
    limited joints, a rotor's head turns about an upright axis, a flipper's road wheels turn
    about axles parallel to its own, a helicopter's tail hubs sit on one side."""
    known: dict[str, str | None] = {}  # link -> the nearest joint above it that turns
    found = [
        joint
        for joint in tree.urdf.joints
        if joint.endless
        and joint.name not in roles
        and (tree.parts_of(joint.name) | tree.parts_of(joint.child)) <= _A_RIMS_PARTS
        and not _FOOT_JOINT.search(joint.name)
        and _rollers_only(tree, joint, roles)
        and _rolls_across(tree, joint)
        and _axle(_resting_axis(tree, joint, known))
    ]
    if not _sides({tree.poses.place(joint.child)[1] for joint in found}):
        return []  # none, one, or all on one side
    return [joint.name for joint in found]


def _carried(tree: JointTree, joint: Joint) -> list[Joint]:
    """The movable joints on the part ``joint`` turns (its child, or links fixed to it)."""
    return [
        below
        for link in (joint.child, *tree.urdf.fixed_below(joint.child))
        for below in tree.urdf.children(link)
        if below.movable
    ]


def _rolls_across(tree: JointTree, joint: Joint) -> bool:
    """Everything that moves below ``joint`` turns about an axis across its own: a rim's
    rollers (tangent to it, or at an angle), not the road wheels a flipper's bar carries,
    which turn about axles parallel to the bar's."""
    axis = tree.poses.axis(joint)
    return not any(parallel(axis, tree.poses.axis(below)) for below in _carried(tree, joint))


def _steered_wheels(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, Role]:
    """Steered wheels (a wheel keeps the evidence it was found by) and their steering, each
    read by :func:`_steering_above`, when they are two or more on both sides of the body."""
    found: dict[str, Role] = {}
    wheels: list[Joint] = []
    for leaf in tree.urdf.joints:
        steered = _steering_above(tree, leaf, roles)
        if steered is None:
            continue
        steer, said = steered
        wheels.append(leaf)
        found[steer.name] = Role(
            steer.name, "steering", f"{said}, an upright axis carrying {leaf.name}"
        )
        found[leaf.name] = roles.get(leaf.name) or Role(
            leaf.name, "wheel", f"an endless leaf turning about a level axle below {steer.name}"
        )
    if len(wheels) < 2 or not _sides({tree.poses.place(j.child)[1] for j in wheels}):
        return {}
    return found


def _steering_above(
    tree: JointTree, leaf: Joint, roles: Mapping[str, Role]
) -> tuple[Joint, str] | None:
    """The joint that steers ``leaf`` and why, or None. ``leaf`` is endless, of no role yet or
    a wheel already, and the only moving joint on the link of a joint of no role yet, or read
    as a gripper's (a link named ``finger_*`` or ``knuckle``: a wheel hangs from no gripper),
    that turns about an upright axis, the leaf about a level one (both as the body rests);
    the joint above is named for steering (``steer_front_left_joint``), or the leaf turns a
    tyre that reaches the ground (:func:`_a_tyre`), whatever corner or limb words their names carry
    (``front_left`` names a leg's corner as well as a wheel's, ``front_right_arm`` a disc on a
    swivel; a leg is never steered; a wrist's flange or a camera's drum on a tilt is no
    tyre: it hangs above the body's lowest frames)."""
    if (
        not leaf.endless
        or _role(roles, leaf.name) not in (None, "wheel")
        or leaf.child in tree.moving_below
    ):
        return None
    steer = tree.urdf.parent_joint(leaf.parent)
    if (
        steer is None
        or _role(roles, steer.name) not in (None, "gripper")
        or not steer.movable
        or steer.type not in ("revolute", "continuous")
        or not _upright(tree.poses.axis(steer))
        or not _axle(tree.poses.axis(leaf))
        or len([j for j in tree.urdf.children(leaf.parent) if j.movable]) != 1
    ):
        return None
    if _STEER.search(steer.name):
        return steer, "named for steering"
    if _a_tyre(tree, leaf):
        return steer, "a swivel carrying a tyre"
    return None


def _a_tyre(tree: JointTree, joint: Joint) -> bool:
    """The part ``joint`` turns is drawn as a cylinder round its axle (:func:`_drawn_round`),
    is not known to hang its mass off it (:func:`_balance`) and reaches down to the body's
    lowest link frame (:attr:`JointTree.lowest_frame`, within :data:`_GROUND_GAP`): a tyre on
    the ground, whatever its name."""
    link = tree.urdf.link(joint.child)
    shape = None if link is None else link.cylinder
    return (
        shape is not None
        and tree.poses.place(joint.child)[2] - shape.radius <= tree.lowest_frame + _GROUND_GAP
        and _drawn_round(tree, joint)
        and _balance(tree, joint) is not False
    )


# How far above the body's lowest link frame a tyre's bottom may be (metres): a wheel's
# bottom is the ground, where a footprint frame is drawn, or below every frame.
_GROUND_GAP = 0.01


def _role(roles: Mapping[str, Role], name: str) -> str | None:
    """The role ``name`` was given so far, or None."""
    role = roles.get(name)
    return None if role is None else role.role


def _leg_wheels(tree: JointTree, taken: set[str]) -> list[str]:
    """Endless leaves named as a leg's (``joint_left_leg_4``, not an ankle's or a toe's), of no
    role yet, under two revolute joints with stops (the nearest movable ones, through fixed
    joints: a leg's hip and knee; a wheel turns for ever), turning about the nearest one's axis
    (a wheel rolls about its knee's axis; an ankle's roll or a swivel foot does not), two or
    four of them: the wheels a wheel-legged biped or quadruped rolls on, whatever a wheel's name
    would say. One walk up the tree serves all the leaves (``known``)."""
    known: dict[str, str | None] = {}
    found = []
    for joint in tree.urdf.joints:
        if not (
            joint.endless
            and joint.actuated
            and joint.name not in taken
            and joint.child not in tree.moving_below
            and "leg" in (tree.parts_of(joint.name) | tree.parts_of(joint.child))
            and not _FOOT_JOINT.search(f"{joint.name} {joint.child}")
        ):
            continue
        knee = _limited_above(tree, joint, known)
        if knee is not None and parallel(tree.poses.axis(joint), tree.poses.axis(knee)):
            found.append(joint.name)
    return found if len(found) in _WHEEL_LEGGED else []


def _limited_above(tree: JointTree, joint: Joint, known: dict[str, str | None]) -> Joint | None:
    """The nearest movable joint above ``joint`` when it and the next movable one above it both
    turn with stops (revolute, not endless), else None."""
    nearest = None
    link = joint.parent
    for _ in range(2):
        name = moved_by(tree.urdf, link, known)
        above = None if name is None else tree.urdf.joint(name)
        if above is None or above.endless or above.type != "revolute":
            return None
        nearest = nearest or above
        link = above.parent
    return nearest


def _named_screws(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Rotor-named joints (``left_prop_joint``) that are a vessel's screws by place: on one
    rigid body and below it, side by side, mirrored, turning about the line the body travels
    along as their written ``<axis>`` says (see :func:`_unnamed_screws`); a multirotor's rotors
    turn about upright axes, and a name outweighs a defaulted axis."""
    if not _may_have_screws(tree, roles):
        return []
    by_body: dict[str | None, list[Joint]] = {}
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    for name, role in roles.items():
        joint = tree.urdf.joint(name)
        if role.role == "rotor" and joint is not None and joint.axis_written:
            by_body.setdefault(moved_by(tree.urdf, joint.parent, known), []).append(joint)
    found: list[str] = []
    for carrier, joints in by_body.items():
        floor = _body_origin(tree, carrier)[_Z_AXIS]
        if all(tree.poses.place(j.child)[_Z_AXIS] < floor for j in joints) and _screws(
            tree, joints
        ):
            found.extend(j.name for j in joints)
    return found


def _may_have_screws(tree: JointTree, roles: Mapping[str, Role]) -> bool:
    """No drive, track or flight plugin moves the body, and it has no control surface nor a
    wing (an aircraft's propellers)."""
    if _plugin_moved(tree):
        return False
    if any(role.role == "fin" for role in roles.values()):
        return False
    return not any("wing" in tree.parts_of(joint.child) for joint in tree.urdf.joints)


def _plugin_moved(tree: JointTree) -> bool:
    """A drive, track or flight plugin moves the body (its spinning leaves are no screws)."""
    return any(tree.labels(kind) for kind in ("drive", "track", "flight"))


def _unnamed_screws(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Unnamed spinning leaves below one link (or each alone below its own link, all fixed to
    one body), two or more side by side, turning about the line the body travels along and
    sitting apart across it: a vessel's screws, pushing it.

    Wheels on axles sit apart along the axle they share (a left and a right wheel), or turn
    about lines that are not one (an omni base's rims); twin propellers under a hull turn about
    the line they push along and sit apart across it, two or four, mirrored across the body.
    Not on a body a drive, track or flight plugin moves, nor one with control surfaces (an
    aircraft's propellers).
    """
    if not _may_have_screws(tree, roles):
        return []
    below, _ = _wheel_candidates(tree, roles)
    found = [j.name for joints in below.values() if _screws(tree, joints) for j in joints]
    if found:
        return found
    # Each alone below a link of its own, fixed to one body (a catamaran's screw under each
    # hull): told on that body.
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    on_body: dict[str | None, list[Joint]] = {}
    for joints in below.values():
        if len(joints) == 1:
            on_body.setdefault(moved_by(tree.urdf, joints[0].parent, known), []).append(joints[0])
    return [j.name for joints in on_body.values() if _screws(tree, joints) for j in joints]


def _screws_by_place(tree: JointTree, roles: Mapping[str, Role]) -> dict[str, str]:
    """Unnamed screws (:func:`_unnamed_screws`, else :func:`_lone_screw`), each with its
    evidence."""
    twins = _unnamed_screws(tree, roles)
    if twins:
        why = (
            "unnamed endless joints below the body, side by side, turning about the line they "
            "push along (screws)"
        )
        return dict.fromkeys(twins, why)
    why = (
        "a lone unnamed endless joint below a body in water, on its middle line, turning about "
        "the line it travels along (a single screw)"
    )
    return dict.fromkeys(_lone_screw(tree, roles), why)


def _lone_screw(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """The one unnamed spinning leaf below a link (:func:`_wheel_candidates`), turning about
    the line the body travels along (x) as it rests and on its middle line, of a body a water
    plugin puts in water; or the one spinning leaf, unnamed or named as a rotor, of a body whose
    only other moving part is a rudder behind it (:func:`_rudder_behind`): a single screw at
    the stern, whatever steers beside it (a
    rudder, a sail). Twin screws are :func:`_unnamed_screws`'; a wheel turns about an axle
    across the body, and a body no water plugin names may be an aircraft with one propeller
    (its control surfaces beside the rudder)."""
    if _plugin_moved(tree):
        return []
    in_water = bool(tree.labels("marine"))
    if in_water:
        below, _ = _wheel_candidates(tree, roles)
        leaves = [joint for joints in below.values() for joint in joints]
    else:  # beside a rudder, at any height (a hull drawn with its origin on its keel), and
        # named as a rotor or not (a propeller)
        rotors = {name for name, role in roles.items() if role.role == "rotor"}
        spinners = [*_unnamed_spinners(tree, set(roles)), *map(tree.urdf.joint, sorted(rotors))]
        leaves = [j for j in spinners if j is not None and j.child not in tree.moving_below]
    if len(leaves) != 1:
        return []
    screw = leaves[0]
    axis = tree.poses.axis(screw)
    across = tree.poses.place(screw.child)[1]  # from the root's origin: the middle line
    # Written so that a stranger's overflowing numbers (NaN) fail it.
    if not (abs(axis[0]) >= 1 - _LEVEL and abs(across) <= _MIRROR_TOLERANCE):
        return []
    return [screw.name] if in_water or _rudder_behind(tree, screw) else []


def _rudder_behind(tree: JointTree, screw: Joint) -> bool:
    """``screw`` sits behind the body's origin (at the stern), and the body's only other
    movable joint is a limited hinge about an upright axis on its middle line behind it: a
    ship's rudder behind its screw. An aircraft's propeller turns at its nose, ahead of the
    rudder, and a pusher's comes with more control surfaces (an elevator, ailerons)."""
    others = [joint for joint in tree.urdf.joints if joint.movable and joint is not screw]
    if len(others) != 1 or others[0].type != "revolute":
        return False
    rudder = others[0]
    stern = tree.poses.place(screw.child)[0]
    return (
        stern < 0
        and abs(tree.poses.axis(rudder)[_Z_AXIS]) >= 1 - _LEVEL
        and _on_the_middle_line(tree, rudder)
        and tree.poses.place(rudder.child)[0] < stern
    )


def _screws(tree: JointTree, joints: list[Joint]) -> bool:
    """``joints`` are a vessel's screws by place: two or four, side by side turning about the
    line the body travels along, in mirrored pairs."""
    return len(joints) in _SCREWS and _side_by_side(tree, joints) and _mirrored_pairs(tree, joints)


def _body_origin(tree: JointTree, carrier: str | None) -> tuple[float, float, float]:
    """Where the rigid body a movable joint ``carrier`` moves (None: the root's) has its frame's
    origin, in the root's frame at rest."""
    body = tree.urdf.joint(carrier) if carrier is not None else None
    return tree.poses.place(body.child if body is not None else tree.urdf.root)


def _mirrored_pairs(tree: JointTree, joints: list[Joint]) -> bool:
    """Each of ``joints`` has a partner mirrored across the body's middle (y to -y, at one
    place along it and one height): a pair of screws or two, not a row."""
    places = [tree.poses.place(j.child) for j in joints]
    return all(
        any(
            math.isclose(a[1], -b[1], abs_tol=_MIRROR_TOLERANCE)
            and a[1] != 0
            and math.isclose(a[0], b[0], abs_tol=_MIRROR_TOLERANCE)
            and math.isclose(a[2], b[2], abs_tol=_MIRROR_TOLERANCE)
            for b in places
        )
        for a in places
    )


def _side_by_side(tree: JointTree, joints: list[Joint]) -> bool:
    """``joints`` turn about the line the body travels along (x, forward in a ROS body's
    frame) and sit apart across it, hardly at all along it (a front and a rear wheel on one
    side turn about lines across the body)."""
    axis = tree.poses.axis(joints[0])
    if abs(axis[0]) < 1 - _LEVEL or not all(parallel(axis, tree.poses.axis(j)) for j in joints):
        return False
    across = (-axis[1], axis[0], 0.0)  # level, at right angles to the axis
    places = [tree.poses.place(j.child) for j in joints]
    along_spread = spread([sum(a * b for a, b in zip(p, axis, strict=True)) for p in places])
    across_spread = spread([sum(a * b for a, b in zip(p, across, strict=True)) for p in places])
    return across_spread > 0 and along_spread <= _SCREWS_ALONG * across_spread


def _gripper_carriers(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Joints read as a gripper's by their names that carry the whole gripper: each alone on
    its link (no movable joint beside it), coupled to no joint (a mimic's driver or follower
    is the gripper's own drive), below a joint that moves (a lift, an arm's joint), with jaws
    below it (two gripper joints or more on one link). Such a joint moves the gripper, not a
    finger (a slide that reaches out with it, a servo that turns it): it is its arm's. Fingers
    hang from the palm beside each other, a finger's own phalanges carry no jaws, and the
    first joint of a gripper alone (nothing moves above it) stays the gripper's, unless it
    starts a serial chain of such joints as long as an arm (the profile's ``arm_min_joints``,
    :func:`_serial_carriers`) on a body where something else moves beside it (its twin, the
    base's wheels): a small arm named for the gripper it ends in. A gripper alone, its drive
    train or its own wrist however long, stays one."""
    grippers = {name for name, role in roles.items() if role.role == "gripper"}
    jaws_on = _jaw_links(tree, grippers)
    above_jaws = joints_above(tree, (j.name for j in tree.urdf.joints if j.parent in jaws_on))
    coupled = {*tree.couplings.driver_of, *tree.couplings.driver_of.values()}
    known: dict[str, str | None] = {}
    candidates = [
        joint
        for name in sorted(grippers, key=tree.order)
        if (joint := tree.urdf.joint(name)) is not None
        and joint.movable
        and name not in coupled
        and name in above_jaws
    ]
    on_own_link = {joint.name for joint in candidates if _alone_on_its_link(tree, joint)}
    alone = {
        joint.name
        for joint in candidates
        if joint.name in on_own_link and joint.parent not in jaws_on
    }
    arm = tree.profile.limb("arm_min_joints")
    return [
        joint.name
        for joint in candidates
        if (joint.name in alone and moved_by(tree.urdf, joint.parent, known) is not None)
        or (joint.name not in on_own_link and _serial_carriers(tree, joint, alone) >= arm)
    ]


def _serial_carriers(tree: JointTree, joint: Joint, alone: set[str]) -> int:
    """How many joints follow one another from ``joint`` down (itself counted), each after it
    one of ``alone`` and the only movable joint on the link the one before moves."""
    count, current = 1, joint
    while count <= len(alone):
        below = [j for j in tree.urdf.children(current.child) if j.movable]
        if len(below) != 1 or below[0].name not in alone:
            break
        count, current = count + 1, below[0]
    return count


def _jaw_links(tree: JointTree, grippers: set[str]) -> set[str]:
    """Links that carry two of the ``grippers`` joints or more (jaws)."""
    carriers = {joint.parent for joint in tree.urdf.joints if joint.name in grippers}
    return {
        link
        for link in carriers
        if sum(joint.name in grippers for joint in tree.urdf.children(link)) >= 2
    }


def _alone_on_its_link(tree: JointTree, joint: Joint) -> bool:
    """No other movable joint hangs from ``joint``'s parent link."""
    return not any(o.movable and o is not joint for o in tree.urdf.children(joint.parent))


def _unnamed_rotors(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Unnamed endless leaves turning about upright axes, three or more on one rigid body (a
    link, or links fixed to it: a frame's arms, one rotor on each) and all round its frame's
    origin (before and behind, left and right): a multirotor's propellers; or, on a body with
    no wheel, two or more on one upright line (:func:`_coaxial`): a coaxial helicopter's, one
    above the other (a wheeled base's mast stacks spinning sensors so). A wheel turns about a
    level axle, a caster's swivel carries its wheel, a spinning lidar is one."""
    taken = set(roles)
    wheeled = any(role.role == "wheel" for role in roles.values())
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    turning: dict[str, str | None] = {}  # link -> the nearest joint above it that turns
    spinning = _no_casters(
        tree, wheeled, (*_unnamed_spinners(tree, taken), *_motor_leaves(tree, taken))
    )
    around = _upright_by_carrier(tree, spinning, known, turning)
    seen = taken | {joint.name for joints in around.values() for joint in joints}
    whole = _no_casters(tree, wheeled, _whole_turn_leaves(tree, seen))
    whole_turns = _upright_by_carrier(tree, whole, known, turning)
    found = [
        joint.name
        for carrier, joints in around.items()
        if _round_its_origin(tree, carrier, joints, wheeled)
        for joint in joints
    ]
    found += [
        joint.name
        for joints in whole_turns.values()
        if _ring([tree.poses.place(joint.child) for joint in joints])
        for joint in joints
    ]
    return found


def _no_casters(tree: JointTree, wheeled: bool, leaves: Iterable[Joint]) -> list[Joint]:
    """``leaves`` but, on a body with wheels (``wheeled``), those whose part is known to hang
    its mass off the axis they turn about (:func:`_balance`): a caster's swivel drawn without
    its wheel trails its fork and wheel behind and below it; a propeller, a wheeled drone's
    too, is balanced on its shaft."""
    return [leaf for leaf in leaves if not wheeled or _balance(tree, leaf) is not False]


def _upright_by_carrier(
    tree: JointTree,
    joints: Iterable[Joint],
    known: dict[str, str | None],
    turning: dict[str, str | None],
) -> dict[str | None, list[Joint]]:
    """The ``joints`` that end the tree and turn about an upright axis, by the movable joint
    that moves the body they are on (:func:`_rotor_carrier`)."""
    by_carrier: dict[str | None, list[Joint]] = {}
    for joint in joints:
        if joint.child not in tree.moving_below and _upright(_resting_axis(tree, joint, turning)):
            by_carrier.setdefault(_rotor_carrier(tree, joint, known, turning), []).append(joint)
    return by_carrier


def _give(roles: dict[str, Role], names: Iterable[str], role: str, why: str) -> None:
    """Each of ``names`` takes ``role`` in ``roles``, for the one reason ``why``."""
    for name in list(names):
        roles[name] = Role(name, role, why)


def _drive_modules(tree: JointTree, roles: Mapping[str, Role]) -> list[str]:
    """Endless leaves of no role yet named as drive modules (:data:`_MODULE`), turning about
    upright axes, three or more round their body's origin (:func:`_round_its_origin`): a swerve
    drive's modules, each a wheel's heading and drive, drawn without their wheels. A propeller
    is no module, nor a motor module (a multirotor's); a snake's modules are chained, no
    leaves."""
    leaves = [
        joint
        for joint in tree.urdf.joints
        if joint.endless
        and joint.actuated
        and joint.name not in roles
        and _MODULE.search(words := f"{joint.name} {joint.child}")
        and not MOTOR.search(words)  # a multirotor's motor modules turn its propellers
    ]
    around = _upright_by_carrier(tree, leaves, {}, {})
    return [
        joint.name
        for carrier, joints in around.items()
        if _round_its_origin(tree, carrier, joints, wheeled=True)  # three or more, all round
        for joint in joints
    ]


def _round_its_origin(
    tree: JointTree, carrier: str | None, joints: list[Joint], wheeled: bool
) -> bool:
    """Three leaves or more before and behind, left and right of their body's origin; or, on
    a body with no wheel, two or more on one upright line (:func:`_coaxial`). On a body a
    joint that turns carries, the leaves' axes are read in the frame of the link they hang from
    (:func:`_resting_axis`), and so are their places and the body's origin here: a drone hung
    from a load by ball joints sits tilted at rest, its frame link perhaps turned on it as a
    CAD export writes one."""
    body = tree.urdf.joint(carrier) if carrier is not None else None
    places = [tree.poses.place(joint.child) for joint in joints]
    centre = _body_origin(tree, carrier)
    if body is not None and _turns(body):
        frame = joints[0].parent
        places = [tree.poses.seen_from(frame, place) for place in places]
        centre = tree.poses.seen_from(frame, centre)
    return (
        len(joints) >= _FEWEST_UNNAMED_ROTORS
        and _sides({place[0] - centre[0] for place in places})
        and _sides({place[1] - centre[1] for place in places})
    ) or (not wheeled and _coaxial(places))


def _whole_turn_leaves(tree: JointTree, taken: set[str]) -> Iterator[Joint]:
    """Revolute leaves of no role yet and no part's name that turn a whole turn but not for
    ever (an export that bounds every joint at +-pi), pointing no sensor: what could be
    propellers, told as such only when spaced round their own middle (:func:`_ring`). A
    finger or a jaw stops well short of a turn."""
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    named: dict[str, str | None] = {}  # link -> the nearest movable joint named for a part
    for joint in tree.urdf.joints:
        if (
            joint.type == "revolute"
            and not joint.endless
            and joint.turns(_WHOLE_TURN)
            and joint.actuated
            and joint.name not in taken
            and joint.child not in tree.moving_below
            and not _named_for_a_part(tree, joint, known, named)
            and not points_a_sensor(tree, joint)
        ):
            yield joint


def _ring(places: list[tuple[float, float, float]]) -> bool:
    """Three places or more at one height, each one distance from the middle of them all (a
    frame's corners): a multirotor's propellers, wherever its frame's origin is (a CAD export
    puts it at a corner of the body, so the test round the origin fails)."""
    if len(places) < _FEWEST_UNNAMED_ROTORS:
        return False
    middle = [sum(place[axis] for place in places) / len(places) for axis in range(3)]
    radii = [math.hypot(place[0] - middle[0], place[1] - middle[1]) for place in places]
    mean = sum(radii) / len(radii)
    spread = _RING_TOLERANCE * mean
    return (
        mean > _MIRROR_TOLERANCE
        and max(radii) - min(radii) <= spread
        and max(place[2] for place in places) - min(place[2] for place in places) <= spread
    )


def _rotor_carrier(
    tree: JointTree, joint: Joint, known: dict[str, str | None], turning: dict[str, str | None]
) -> str | None:
    """The movable joint that moves the body a spinning leaf ``joint`` is on (None: the
    root's), past a mount that swivels about an axis parallel to the leaf's, with nothing
    that turns above it (a motor mount written about its shaft, :func:`_shaft_mount`), or one
    that tilts it (a tilt-rotor's servo, :func:`_tilt_mount`): such a mount carries the rotor
    where the body does (``known`` and ``turning``: the walks' memos)."""
    carrier = moved_by(tree.urdf, joint.parent, known)
    mount = _rotor_mount(tree, joint, turning)
    if mount is not None and mount.name == carrier:
        return moved_by(tree.urdf, mount.parent, known)
    return carrier


def _rotor_mount(tree: JointTree, joint: Joint, turning: dict[str, str | None]) -> Joint | None:
    """The mount that carries a spinning leaf ``joint`` where the body is: one swivelling about
    its shaft (:func:`_shaft_mount`) or tilting it (:func:`_tilt_mount`); else None."""
    return _shaft_mount(tree, joint, turning) or _tilt_mount(tree, joint, turning)


def _shaft_mount(tree: JointTree, joint: Joint, turning: dict[str, str | None]) -> Joint | None:
    """The one joint that turns above ``joint`` when it turns about an axis parallel to
    ``joint``'s and nothing turns above it (a motor mount swivelling about the line of the
    shaft it carries: turning it leaves the shaft's direction as it is); else None
    (``turning``: the walks' memo)."""
    above = nearest_above(tree.urdf, joint.parent, turning, _turns)
    mount = tree.urdf.joint(above) if above is not None else None
    if (
        mount is not None
        and parallel(tree.poses.axis(mount), tree.poses.axis(joint))
        and nearest_above(tree.urdf, mount.parent, turning, _turns) is None
    ):
        return mount
    return None


def _tilt_mount(tree: JointTree, joint: Joint, turning: dict[str, str | None]) -> Joint | None:
    """The one joint that turns above ``joint`` when it tilts it about a level axis, the shaft
    upright at rest, and nothing turns above it but a joint that places the whole body (a
    floating or planar root: :func:`_places_the_body`): a tilt-rotor's servo, one under each
    propeller (tilting it turns the thrust, the propeller stays on the body's frame where it
    was); else None (``turning``: the walks' memo)."""
    above = nearest_above(tree.urdf, joint.parent, turning, _turns)
    mount = tree.urdf.joint(above) if above is not None else None
    if (
        mount is not None
        and _upright(tree.poses.axis(joint))
        and _axle(tree.poses.axis(mount))
        and _places_the_body(tree, nearest_above(tree.urdf, mount.parent, turning, _turns))
    ):
        return mount
    return None


def _places_the_body(tree: JointTree, name: str | None) -> bool:
    """``name`` is no joint (the root's body), or a floating or planar one: a simulator's or a
    planner's joint placing the whole body, no part of it."""
    joint = tree.urdf.joint(name) if name is not None else None
    return joint is None or joint.type in ("floating", "planar")


def _coaxial(places: list[tuple[float, float, float]]) -> bool:
    """Two upright spinning leaves or more, all on one upright line (one place across the
    ground, any height): contra-rotating rotors, the one lift a coaxial helicopter has (a
    model that leaves its rotors' places to its simulator writes them all at its centre).
    Nothing else turns two parts for ever about one upright line; a spinning lidar is one
    leaf."""
    return len(places) >= _COAXIAL_ROTORS and all(
        math.isclose(place[axis], places[0][axis], abs_tol=_MIRROR_TOLERANCE)
        for place in places[1:]
        for axis in (0, 1)
    )


def _middle(tree: JointTree, link: str) -> float:
    """Where across (y) the middle of ``link`` is in its own frame: its mass centre when its
    file gives one, else its origin (a CAD export puts a body's origin at a corner of it)."""
    found = tree.urdf.link(link)
    return found.mass_centre[1] if found is not None and found.mass_centre is not None else 0.0


def _sides(across: set[float]) -> bool:
    """Some of these places are on one side of a link's origin (> 0) and some on the other
    (of its middle, :func:`_middle`, when they are measured from there)."""
    return {y > 0 for y in across if y != 0} == {True, False}


def _wheel_candidates(
    tree: JointTree, roles: Mapping[str, Role]
) -> tuple[dict[str, list[Joint]], dict[str, list[Joint]]]:
    """Unnamed endless joints that could be wheels, by the link they hang from: those below it,
    and those level with or above it turning about a level axle."""
    below: dict[str, list[Joint]] = {}
    level: dict[str, list[Joint]] = {}
    known: dict[str, str | None] = {}  # link -> the nearest joint above it that turns
    spinners = [
        joint
        for joint in _unnamed_spinners(tree, set(roles))
        if joint.child not in tree.moving_below
        or _rollers_only(tree, joint, roles)
        or _spokes_only(tree, joint)
    ]
    square = _square_to_the_rest(tree, spinners, known)
    for joint in spinners:
        if joint.name in square:
            continue
        if joint.origin[2] < 0:
            below.setdefault(joint.parent, []).append(joint)
        elif _axle(_resting_axis(tree, joint, known)) or _caster_wheel(tree, joint, known):
            level.setdefault(joint.parent, []).append(joint)
    return below, level


def _square_to_the_rest(
    tree: JointTree, spinners: list[Joint], known: dict[str, str | None]
) -> set[str]:
    """The names of ``spinners`` on the hull (no joint that turns above them) whose axle, as
    the body rests, lies level and square to the axle more than half of those level ones share
    (two or more): wheels that roll together turn about one line, so a spinner across it pulls
    along the body (a plane's propeller beside its landing gear's wheels). None when they all
    point in (an omni base's wheels, :func:`_pointing_in`). Axles below a joint that turns
    (a steering knuckle, a rocker) are left out: their rest pose says nothing of the body's.
    The shared line is found by a majority vote, one pass and a count: linear in the joints."""
    on_the_hull = [j for j in spinners if nearest_above(tree.urdf, j.parent, known, _turns) is None]
    axes = {j.name: tree.poses.axis(j) for j in on_the_hull}
    level = [j for j in on_the_hull if _axle(axes[j.name])]
    leader: Vector | None = None
    votes = 0
    for joint in level:
        axis = axes[joint.name]
        if votes == 0:
            leader, votes = axis, 1
        else:
            votes += 1 if leader is not None and parallel(axis, leader) else -1
    if leader is None or _pointing_in(tree, level):
        return set()
    sharing = sum(1 for joint in level if parallel(axes[joint.name], leader))
    if sharing < 2 or 2 * sharing <= len(level):
        return set()
    return {joint.name for joint in level if perpendicular(axes[joint.name], leader)}


def _caster_wheel(tree: JointTree, joint: Joint, known: dict[str, str | None]) -> bool:
    """``joint`` turns a part that carries its mass on its axle (:func:`_balanced`) about a
    level axle as the body rests, steered by an endless swivel (:func:`_steered_by`): a
    caster's wheel. Turning about the upright keeps an axle level whatever the swivel's angle,
    so the rest pose says what the axle is (a leg's or an arm's does not); a leg's shin hangs
    its mass off its knee."""
    swivel = _steered_by(tree, joint, known)
    return (
        swivel is not None
        and swivel.endless
        and _axle(tree.poses.axis(joint))
        and _balanced(tree, joint)
    )


def _steered_by(tree: JointTree, leaf: Joint, known: dict[str, str | None]) -> Joint | None:
    """The swivel that steers ``leaf``: the only joint that turns between it and the body,
    about the upright as the body rests, with ``leaf``'s axle lower than its pivot (a caster's
    or a fork's wheel hangs below what steers it; a head's tilt sits above its pan). None when
    there is no such swivel. ``known`` remembers the walks up the tree (one per :func:`_turns`).
    """
    above = nearest_above(tree.urdf, leaf.parent, known, _turns)
    swivel = tree.urdf.joint(above) if above is not None else None
    if (
        swivel is None
        or nearest_above(tree.urdf, swivel.parent, known, _turns) is not None
        or not _upright(tree.poses.axis(swivel))
        or tree.poses.place(leaf.child)[2] >= tree.poses.place(swivel.child)[2]
    ):
        return None
    return swivel


def _resting_axis(tree: JointTree, joint: Joint, known: dict[str, str | None]) -> Vector:
    """``joint``'s axis as the body carries it: in the body's frame when nothing that turns is
    above it (a link fixed to the body or sliding on it: a motor mount tipped upright, a
    wheel-drop suspension's frame turned to slide along its own axis), or on a mount that
    swivels about its line or tilts it from upright (:func:`_rotor_mount`); else in its
    parent's frame (a leg's or a steering link's rest pose says nothing of the axle's)."""
    if (
        nearest_above(tree.urdf, joint.parent, known, _turns) is None
        or _rotor_mount(tree, joint, known) is not None
    ):
        return tree.poses.axis(joint)
    return local_axis(joint)


def _turns(joint: Joint) -> bool:
    return joint.movable and joint.type != "prismatic"


def _motor_leaves(tree: JointTree, taken: set[str]) -> Iterator[Joint]:
    """Limited revolute joints of no role yet named as motors (``motor_1_joint``), carrying
    nothing named (a swerve module's steering motor carries its wheel) and named for no
    steering: a model that turns its propellers on joints with limits, told as rotors by place
    like endless ones (a motor is what spins a propeller; a finger or a wheel is named
    otherwise)."""
    for joint in tree.urdf.joints:
        if (
            joint.type == "revolute"
            and not joint.endless
            and joint.actuated
            and joint.name not in taken
            and MOTOR.search(f"{joint.name} {joint.child}")
            and not _STEER.search(joint.name)
            and not (tree.parts_of(joint.name) | tree.parts_of(joint.child))
            and not _carries_a_named_part(tree, joint)
        ):
            yield joint


def _carries_a_named_part(tree: JointTree, joint: Joint) -> bool:
    """A link fixed below ``joint``'s child names a part (a wheel, a rotor, a gripper)."""
    return any(tree.parts_of(link) for link in tree.urdf.fixed_below(joint.child))


def _unnamed_spinners(tree: JointTree, taken: set[str]) -> Iterator[Joint]:
    """Endless joints of no role yet and no part's name, not on a part an endless joint turns
    about a level axle (a rim's rollers) nor carrying a sensor a mount points (a camera, a
    lidar or a range finder: a wheel's contact or IMU sensor turns with it): what could be
    wheels or rotors, told by place. An export that wrote no limits, or bounded every revolute
    joint alike a whole turn (:func:`_unbounded`), says nothing of how far a joint turns: one
    turning a part balanced on its axle is read so too."""
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    named: dict[str, str | None] = {}  # link -> the nearest movable joint named for a part
    whole = _bounded_alike(tree)
    for joint in tree.urdf.joints:
        if (
            (joint.endless or _unbounded(tree, joint, whole))
            and joint.actuated
            and joint.name not in taken
            and not _named_for_a_part(tree, joint, known, named)
            and not points_a_sensor(tree, joint)
            and not _on_a_spinning_part(tree, joint, known)
        ):
            yield joint


def _unbounded(tree: JointTree, joint: Joint, whole: bool = False) -> bool:
    """A revolute joint turning a part that carries its mass on its axle (:func:`_balanced`):
    a wheel, as far as the file says (a jaw or a finger hangs its mass off its hinge), when it
    is written blank (:func:`~solver.identify.readers.urdf.written_blank`) and unlocked as an
    export's (its range unwritten, not zero); when its limit writes no range at all and it
    hangs as a wheel does (:func:`_moved_by_few`: a hand-written file leaves `lower` and
    `upper` out beside an effort, and a linkage's free joints deep in a leg are written so
    too); or, with ``whole``, when it is bounded a whole turn as every revolute joint of the
    file is (:func:`_bounded_alike`) and hangs as a wheel does."""
    return (
        joint.type == "revolute"
        and (
            (joint.unlocked and written_blank(joint))
            or (joint.lower is None and joint.upper is None and _moved_by_few(tree, joint.parent))
            or (whole and joint.turns(_WHOLE_TURN) and _moved_by_few(tree, joint.parent))
        )
        and _balanced(tree, joint)
    )


def _moved_by_few(tree: JointTree, link: str) -> bool:
    """At most one movable joint moves ``link`` (a steering knuckle, a suspension's arm, or
    none: the body itself), as a wheel hangs, within :data:`_DEEPEST_WALK` joints of the root;
    a flange at an arm's end hangs below many."""
    moving = 0
    joint = tree.urdf.parent_joint(link)
    for _ in range(_DEEPEST_WALK):
        if joint is None:
            return True
        moving += joint.movable
        if moving > 1:
            return False
        joint = tree.urdf.parent_joint(joint.parent)
    return False


def _bounded_alike(tree: JointTree) -> bool:
    """Every revolute joint of the file is bounded alike, a whole turn (an export that writes
    +-pi on every joint, wheels and arm alike), three of them or more: the limits say nothing
    of which joints turn for ever."""
    revolute = [j for j in tree.urdf.joints if j.type == "revolute"]
    bounds = {(j.lower, j.upper) for j in revolute}
    if len(revolute) < _ALIKE_BOUNDED or len(bounds) != 1:
        return False
    lower, upper = next(iter(bounds))
    return lower is not None and upper is not None and upper - lower >= _WHOLE_TURN


def _only_a_corner(tree: JointTree, name: str, *, leaf: bool) -> bool:
    """``name`` names a corner of the body and no part: a corner and a joint's word
    (:data:`_ONLY_A_CORNER`); or, for a ``leaf`` (a hub: carrying nothing that moves, its mass
    known to lie on its axle), a corner beside words no part's pattern knows
    (``Front_left_plate_continuous_joint``, a mecanum wheel's hub whose rollers are fixed; a
    flipper carries road wheels, or hangs its mass out along itself)."""
    if _ONLY_A_CORNER.fullmatch(name):
        return True
    if not leaf or _CORNER_WORDS.search(name) is None:
        return False
    return not tree.parts_of(_CORNER_WORDS.sub("_", name))


def _named_for_a_part(
    tree: JointTree, joint: Joint, known: dict[str, str | None], named: dict[str, str | None]
) -> bool:
    """``joint`` or its link is named for a part; a leaf named only for a corner of the body
    (``front_right_j`` on ``front_right``, ``joint_frontLeft``) says where it is, not what it
    is, and is named for none when it hangs from the body itself or from a part carrying more
    than it that moves (a wagon's axle), below no joint named for a part (a hip above it makes
    the corner a leg's). One alone on a swivel (a steering knuckle, a caster) keeps its
    corner's word: the steered-wheel rules read it. ``known`` and ``named`` remember the walks
    up the tree (:func:`~solver.identify.limbs.nearest_above`)."""
    words = [name for name in (joint.name, joint.child) if tree.parts_of(name)]
    if not words:
        return False
    # A hub: a leaf whose part carries its mass on its axle (a flipper hangs it out).
    hub = joint.child not in tree.moving_below and _balanced(tree, joint)
    if not all(_only_a_corner(tree, name, leaf=hub) for name in words):
        return True
    alone = _alone_on_its_link(tree, joint)
    if alone and moved_by(tree.urdf, joint.parent, known) is not None:
        return True  # alone on a part that moves: a knuckle's or a swivel's wheel

    def part_named(above: Joint) -> bool:
        return above.movable and bool(tree.parts_of(above.name) or tree.parts_of(above.child))

    return nearest_above(tree.urdf, joint.parent, named, part_named) is not None
