"""Motion controls a robot description shows by itself, without a topic list.

Two kinds of evidence, the declared first:

* *Declared controllers.* From the URDF: a drive plugin (diff_drive, skid_steer, a tracked
  vehicle) or wheels driven through a transmission / ``ros2_control`` mean the robot is driven;
  rotors or flight plugins mean it is flown; joints of arms, legs and other limbs with a
  transmission mean its joints are commanded one by one (a head's pan/tilt points a sensor, a
  rotor or wheel mount moves the vehicle: neither is joint control; but a flown body whose
  packages, read whole, configure its rotors' joint controllers and ship no flight software
  has its rotors commanded one by one, and a head or a mount whose packages configure a
  controller of one of its joints' own has that joint commanded). From the SRDF: a MoveIt
  planning group over an arm means joint-space and end-effector goals; an ``<end_effector>`` not
  on a leg means end-effector goals (:mod:`solver.identify.planning_groups`). An SRDF whose end
  effectors are all feet models a walker's whole body for its balance controller: its arm
  groups mean joint-space goals only, and no end effector is guessed for its arms. So does an
  SRDF of a body on two legs that names no end effector on a hand, and no end effector is
  guessed for a biped's arms without one.
* *Roles.* What the joints do shows a control even where no controller is declared: wheels that
  turn (not a caster's) or a base the model moves in the plane (a planar joint, root joints
  along x, y and about z) mean the base is driven (not a flying body's: landing gear, the
  simulator's mover), thrusters that the vessel is, an arm of
  actuated joints that its joints are commanded, and an arm of six motions or more ending in a
  gripper (a telescope's segments sliding along one axis are one motion) that Cartesian
  (end-effector) goals can be solved for it, and two legs or more that
  the body walks; those last two are guesses and say so ("likely, not declared": a gait
  controller, like a Cartesian solver, is software), as are a gripper alone opened and closed
  and a pan/tilt unit alone aimed by its joints. An arm on a body that moves by itself (a
  drive plugin moves it, or it walks on two legs or more) that nothing commands (no controller
  in the description, no joint of it named by the robot's packages, read whole) is only drawn:
  no control. Roles are named only for a control no
  declared controller shows.

Which control each of these means is the profile's ``motion.description`` (data); this module
only says which of them a robot has.

Navigation (Waypoint) and walking live in launch and config files, not in the robot
description: topics show them (:mod:`solver.identify.interfaces`). A description shows only
that a vehicle *could* take waypoints: the profile's ``motion.navigation`` names, per source
that moves the body (wheels, a drive plugin, thrusters, flight; or a control, for every source
of it), the sensors navigation needs (a driven ground base and a lidar or a GPS; thrusters and
a lidar or a Doppler velocity log; a flown body and odometry or a GPS; no walker, whose file
does not tell). Such a Waypoint is a guess and says so.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from typing import TYPE_CHECKING

from solver.identify.body import Body
from solver.identify.interfaces import Control
from solver.identify.limbs import Limb
from solver.identify.planning_groups import arm_plans, hand_effectors, leg_plans
from solver.identify.profile import GROUND, ROLE_SOURCES, Profile
from solver.identify.readers.urdf import Joint, Urdf

if TYPE_CHECKING:
    from solver.identify.readers.srdf import EndEffector, Srdf

__all__ = ["controls_from_description"]

# (profile source, evidence): what one place of the description shows.
_Shown = list[tuple[str, str]]
# Legs a body stands and walks on (one leg is a tool, a leg rig or a tail).
_WALKING_LEGS = 2
# Joints from the base to a gripper that reach any pose (three for position, three to turn).
_CARTESIAN_JOINTS = 6
# Axes and turns this close (unit vector components, radians) are the same.
_SAME_AXIS = 1e-3


def _ground(body: Body, urdf_source: str) -> _Shown:
    """What drives a body on the ground: drive plugins and driven wheels (declared); wheels that
    turn, wheels that all hang under swivels, a ground vehicle by its packages with no wheel
    drawn, a base the model moves in the plane (roles). A flying body's wheels that turn are
    landing gear and a plugin or a planar base that moves it in the plane (a planar-move or
    velocity-control plugin) is the simulator's mover, its velocity commands flight: neither
    drives it (measured: no labelled aircraft is driven, docs/identify-journal.md). A drive
    plugin or wheels a controller drives still do (a robot that rolls and flies)."""
    movers = set(body.mover_plugins) if body.flying else set()
    drives = tuple(plugin for plugin in body.drive_plugins if plugin not in movers)
    found = []
    if drives or body.tracks:
        plugins = ", ".join((*drives, *body.tracks)[:3])
        found.append(("drive_plugin", f"{urdf_source}: drive plugin {plugins}"))
    if body.controlled_wheels:
        count = len(body.controlled_wheels)
        found.append(
            ("controlled_wheels", f"{urdf_source}: {count} wheel joint(s) a controller drives")
        )
    if body.wheels and not body.flying:
        found.append(("wheels", f"{urdf_source}: {len(body.wheels)} wheel joint(s) that turn"))
    if _steered_only(body):
        # Wheels that all hang under swivels, and no other wheel: casters cannot move a base
        # by themselves, so the swivels steer drive modules (an omnidirectional base).
        count = len(body.casters)
        found.append(
            ("steered_wheels", f"{urdf_source}: {count} swivel and wheel joint(s), no other wheel")
        )
    if body.shipped_as == GROUND:
        # A ground vehicle by its packages' words, nothing of it on the ground drawn (a body of
        # sensor frames): it is driven, as a vessel whose propulsion is not drawn is.
        found.append(("undrawn_wheels", f"{urdf_source}: a ground vehicle with no wheel drawn"))
    if body.planar_base and not body.flying:
        # The model moves its base in the plane (a planar joint, or root joints along x, y
        # and about z): what a planar-move plugin does, velocity commands in the plane.
        found.append(("planar_base", f"{urdf_source}: a base moved in the plane"))
    return found


def _steered_only(body: Body) -> bool:
    """Casters and no other wheel, drive plugin, track, leg or flight: a trimmed base's fixed
    wheels show no motion control either (see the tests' robots)."""
    return bool(body.casters) and not (
        body.wheels
        or body.fixed_wheels
        or body.drive_plugins
        or body.tracks
        or body.count("leg")
        or body.flying
    )


def _water(body: Body, urdf_source: str) -> _Shown:
    """Thrusters, a vessel whose propulsion is not drawn, or a rudder a controller drives."""
    found = []
    if _undrawn_vessel(body):
        # A vessel whose propulsion is not drawn (a hull and sensor frames, thrusters a
        # driver runs): it is driven, as a body flying by its packages is flown.
        found.append(("thrusters", f"{urdf_source}: a vessel with no thruster or fin drawn"))
    if body.thrusters and body.marine:  # a craft they fly in air or space is flown
        found.append(("thrusters", f"{urdf_source}: {len(body.thrusters)} thruster(s)"))
    elif body.marine and body.controlled_fins:
        # A vessel with no thruster steered by a rudder a controller drives (a sailboat): the
        # operator steers it, as thrusters take a vessel's velocity commands.
        count = len(body.controlled_fins)
        found.append(
            ("controlled_rudders", f"{urdf_source}: {count} rudder joint(s) a controller drives")
        )
    return found


def _undrawn_vessel(body: Body) -> bool:
    """A body in water with no thruster or fin drawn (a sailboat's rudder no controller drives
    steers nothing an operator commands). An arm or a gripper on it does not say otherwise: an
    ROV carrying an arm has its thrusters left out as often (measured: asking for no arm and no
    gripper lost two labelled vessels and kept none from a wrong Driving)."""
    return body.marine and not (body.thrusters or body.fins)


def _flight(body: Body, urdf_source: str, rotor_controllers: str | None = None) -> _Shown:
    """A flown body is flown; when the robot's packages configure its rotors' joint
    controllers and ship no flight software (``rotor_controllers``, the file that shows it),
    its rotors are commanded one by one instead, and no flight is guessed (as legs are walked
    by a gait, a body is flown by software its author did not ship)."""
    if not body.flying:
        return []
    if rotor_controllers is not None:  # found only for a body with rotors
        why = f"{rotor_controllers}: joint controllers naming its rotors, no flight software"
        return [("rotor_controllers", why)]
    if body.rotors:
        what = f"{len(body.rotors)} rotor joint(s)"
    elif body.flight_plugins:
        what = f"flight plugin {body.flight_plugins[0]}"
    elif body.fixed_rotors:
        what = f"{len(body.fixed_rotors)} fixed rotor joint(s) of a trimmed model"
    elif body.wings:
        what = f"{len(body.wings)} wing and control-surface link(s)"
    elif body.flight_hints:
        what = f"flight named in {body.flight_hints[0]}"
    elif body.space_plugins:
        space = body.space_plugins[0]
        what = f"{len(body.thrusters)} thruster(s) of a craft in air or space ({space})"
    else:
        what = f"flying by its packages ({body.shipped_by})"
    return [("flight", f"{urdf_source}: {what}")]


def _own_controller(source: str, shown_file: str | None, where: str) -> _Shown:
    """A part ``where`` names (a vehicle's mount, a pan/tilt head) with a controller of a
    joint's own in its packages (``shown_file``, the file that shows it): that joint takes
    commands by itself (beside the flight or the thrust; wherever the head is: a transmission
    alone says nothing of who commands it)."""
    return _shown_by(source, shown_file, f"a controller of a joint's own on {where}")


def _shown_by(source: str, shown_file: str | None, what: str) -> _Shown:
    """``source``, with ``what`` the file ``shown_file`` shows, when a file shows it."""
    return [] if shown_file is None else [(source, f"{shown_file}: {what}")]


def _motions(joints: tuple[str, ...], urdf: Urdf | None) -> int:
    """How many motions a chain of joints has: a prismatic joint that slides on the previous
    one along the same axis (no turn between them: a telescope's segments) adds none."""
    if urdf is None:
        return len(joints)
    count = 0
    previous = None
    for name in joints:
        joint = urdf.joint(name)
        count += not (joint is not None and previous is not None and _telescopes(previous, joint))
        previous = joint
    return count


def _telescopes(previous: Joint, joint: Joint) -> bool:
    """``joint`` slides on the link ``previous`` slides, along the same axis."""
    return (
        previous.type == joint.type == "prismatic"
        and joint.parent == previous.child
        and all(abs(angle) < _SAME_AXIS for angle in joint.rpy)
        and all(abs(a - b) < _SAME_AXIS for a, b in zip(previous.axis, joint.axis, strict=True))
    )


def _limbs(
    body: Body,
    urdf_source: str,
    urdf: Urdf | None = None,
    named: Collection[str] | None = None,
    *,
    leg_controllers: str | None = None,
    leg_joint_controllers: str | None = None,
) -> _Shown:
    """Limb joints a controller drives (declared); arms of actuated joints (roles), but for
    an arm nothing commands (:func:`_shown_only`); a pan/tilt unit alone
    (:attr:`Body.head_alone`); legs to walk on, or, when the robot's packages configure
    joint controllers and ship no gait (``leg_controllers``, the file that shows it), legs
    commanded joint by joint; legs with a controller of a joint's own in the packages
    (``leg_joint_controllers``, the file that shows it) take joint commands beside the gait;
    so do sprawled legs (:attr:`Body.sprawled`), a guess."""
    found = []
    if body.controlled_joints:
        count = len(body.controlled_joints)
        found.append(
            ("controlled_joints", f"{urdf_source}: {count} limb joint(s) a controller drives")
        )
    if body.controlled_fingers:
        count = len(body.controlled_fingers)
        found.append(
            (
                "controlled_fingers",
                f"{urdf_source}: {count} gripper joint(s) a controller drives",
            )
        )
    arms = [
        limb
        for limb in body.limbs
        if limb.kind == "arm" and not _shown_only(limb, body, urdf, named)
    ]
    if arms:
        found.append(("arm", f"{urdf_source}: {len(arms)} arm(s) of actuated joints"))
    for limb in body.limbs:
        if limb.kind == "spine":  # a snake moves by its joints: they take goals
            found.append(("arm", f"{urdf_source}: a spine of {len(limb.joints)} actuated joints"))
    # Six degrees of freedom reach any pose of the gripper: Cartesian goals can be solved. A
    # guess: whether the software offers them is not in the description.
    if any(limb.gripper and _motions(limb.joints, urdf) >= _CARTESIAN_JOINTS for limb in arms):
        found.append(
            (
                "arm_gripper",
                f"{urdf_source}: likely, not declared: an arm of {_CARTESIAN_JOINTS} joints or "
                "more ending in a gripper",
            )
        )
    # An end effector alone (no arm, leg or vehicle to carry it) is there to be opened and
    # closed (or its suction switched): its one command is its joints'. A guess when no
    # controller is declared on them.
    if not body.controlled_fingers and _end_effector_alone(body):
        found.append(
            (
                "gripper_alone",
                f"{urdf_source}: likely, not declared: a gripper or hand alone, "
                "opened and closed on command",
            )
        )
    # A pan/tilt unit alone (Body.head_alone: no vehicle, mobile or floating base, arm, leg or
    # gripper, and no teleop node of its packages driving it) is there to be aimed: its one
    # command is its joints'.
    if body.head_alone:
        found.append(
            (
                "head_alone",
                f"{urdf_source}: likely, not declared: a pan/tilt unit alone, aimed on command",
            )
        )
    legs = body.count("leg")
    # Legs are there to walk on; the gait that walks them is software, not in the description.
    # Packages read whole that configure joint controllers and ship no gait say it is not there.
    if legs >= _WALKING_LEGS and leg_controllers is not None:
        why = f"{leg_controllers}: joint controllers naming joints of {legs} legs, no gait shipped"
        found.append(("leg_controllers", why))
    elif legs >= _WALKING_LEGS:
        found.append(("legs", f"{urdf_source}: likely, not declared: {legs} legs to walk on"))
        # A body slung between sprawled legs (a hexapod's, a spider's) is a servo walker
        # whose joints are commanded one by one, gait or none.
        if body.sprawled:
            found.append(
                (
                    "sprawled_legs",
                    f"{urdf_source}: likely, not declared: {legs} sprawled legs, each swung "
                    "about the vertical first, commanded joint by joint",
                )
            )
        if leg_joint_controllers is not None:
            why = f"{leg_joint_controllers}: a controller of a joint's own on joints of {legs} legs"
            found.append(("leg_joint_controllers", why))
    return found


def _end_effector_alone(body: Body) -> bool:
    """A gripper or a hand with nothing else but its wrist (a wrist carrying a whole hand, or a
    chain of no limb's kind ending in the gripper: a forceps' pitch): no arm, leg, spine,
    mobile base or vehicle. Not a gripper nothing in which moves (:attr:`Body.fixed_gripper`):
    no joint of it takes a command (a vacuum gripper's suction is switched, not read from the
    description)."""
    limbs = [
        limb
        for limb in body.limbs
        if limb.kind != "wrist" and not (limb.kind == "other" and limb.gripper)
    ]
    return bool(body.fingers or (body.grippers and not body.fixed_gripper)) and not (
        limbs or body.mobile_base or body.flying or body.marine
    )


def _planned(
    body: Body,
    srdf: Srdf | None,
    profile: Profile,
    urdf: Urdf | None,
    srdf_source: str,
    *,
    effectors: tuple[EndEffector, ...],
) -> _Shown:
    """What an SRDF plans: arm groups, end effectors (``effectors``, its hand end effectors:
    :func:`~solver.identify.planning_groups.hand_effectors`)."""
    if srdf is None:
        return []
    found = []
    groups = arm_plans(body, srdf, profile.limb("arm_min_joints"), urdf)
    if groups:
        names = ", ".join(g.name for g in groups)
        if _feet_only(srdf, effectors):
            why = f"{srdf_source}: planning group(s) {names} (its end effectors are feet only)"
            found.append(("srdf_walker_group", why))
        elif _balances(body) and not effectors:
            why = f"{srdf_source}: planning group(s) {names} (on two legs, no hand end effector)"
            found.append(("srdf_walker_group", why))
        else:
            found.append(("srdf_group", f"{srdf_source}: planning group(s) {names}"))
    else:
        legs = leg_plans(body, srdf, profile.limb("arm_min_joints"), urdf)
        if legs:
            names = ", ".join(g.name for g in legs)
            why = f"{srdf_source}: planning group(s) {names} (each on a leg)"
            found.append(("srdf_walker_group", why))
    if effectors:
        names = ", ".join(e.name for e in effectors)
        found.append(("srdf_end_effector", f"{srdf_source}: end effector(s) {names}"))
    return found


def _balances(body: Body) -> bool:
    """The body stands on two legs: its arms move inside the balance of the whole body, so
    Cartesian goals for a hand are its whole-body controller's (software, not in the
    description); only an SRDF end effector on a hand says they are offered."""
    return body.count("leg") == _WALKING_LEGS


def _feet_only(srdf: Srdf | None, effectors: tuple[EndEffector, ...]) -> bool:
    """The SRDF names end effectors and every one is a foot (``effectors``, its hand end
    effectors, is empty): it models a walker's whole body for its balance and gait (where it
    stands), and plans no Cartesian goal for an arm."""
    return srdf is not None and bool(srdf.end_effectors) and not effectors


def _navigation(
    shown: _Shown,
    controls: tuple[Control, ...],
    sensor_kinds: Collection[str],
    profile: Profile,
    source: str,
) -> tuple[Control, ...]:
    """The profile's navigation control (Waypoint) as a guess: the body is moved by a source
    (or a control) the rule lists and carries a sensor that source's navigation needs."""
    rule = profile.navigation
    if rule is None or any(c.motion_control == rule.control for c in controls):
        return ()
    for shown_source, _ in shown:
        moved_by = profile.description_control(shown_source)
        for moving, kinds in rule.needs:
            carried = [kind for kind in kinds if kind in sensor_kinds]
            if carried and moving in (shown_source, *moved_by):
                control = moving if moving in moved_by else ", ".join(moved_by)
                why = f"{control} and a {carried[0]} sensor, what navigation needs"
                return (Control(rule.control, f"{source}: likely, not declared: {why}"),)
    return ()


def _shown_only(limb: Limb, body: Body, urdf: Urdf | None, named: Collection[str] | None) -> bool:
    """An arm only drawn, on a body that moves by itself (:attr:`Body.carries_itself`: a
    vehicle its description drives by a plugin, a walker): no transmission,
    ``ros2_control`` block or simulator's joint controller names a joint of it, no plugin
    plays joint trajectories, and the robot's packages, read whole (``named``: the joints
    their files name), name none (a model whose arm moves by the joint state publisher's
    sliders in RViz). Without the packages the arm is taken as commanded, a guess."""
    if named is None or urdf is None or not body.carries_itself:
        return False
    if any(_TRAJECTORIES.search(f"{p.name} {p.filename}") for p in urdf.plugins):
        return False
    joints = set(limb.joints)
    return joints.isdisjoint(urdf.controlled_joints) and joints.isdisjoint(named)


# A plugin that plays joint trajectories on the description's joints (Gazebo's
# joint_pose_trajectory): it names none of them, and commands them all.
_TRAJECTORIES = re.compile(r"joint[-_]?(pose[-_]?)?trajector", re.IGNORECASE)


def controls_from_description(
    body: Body,
    profile: Profile,
    srdf: Srdf | None = None,
    *,
    urdf: Urdf | None = None,
    sensor_kinds: Collection[str] = (),
    urdf_source: str = "urdf",
    srdf_source: str = "srdf",
    guess_software: bool = True,
    named: Collection[str] | None = None,
    leg_controllers: str | None = None,
    leg_joint_controllers: str | None = None,
    rotor_controllers: str | None = None,
    mount_joint_controllers: str | None = None,
    head_joint_controllers: str | None = None,
    vehicle_joint_controllers: str | None = None,
) -> tuple[Control, ...]:
    """The motion controls the body (and SRDF) show, each with what shows it; with the kinds
    of the sensors the description declares, the profile's navigation guess too; neither that
    guess nor an arm's guess of Cartesian goals with ``guess_software=False`` (the robot's
    packages were read whole, and say what software they ship). ``named``: the
    joints the robot's packages name, when they were read whole; ``leg_controllers`` and
    ``rotor_controllers``: the file of the robot's packages that configures joint controllers
    of its legs or rotors, when they ship no gait or no flight software
    (:func:`solver.identify.shipped.joint_controllers`); ``leg_joint_controllers``: the file
    that configures a controller of a leg joint's own
    (:func:`solver.identify.shipped.per_joint_controllers`); ``mount_joint_controllers`` and
    ``head_joint_controllers``: the same for a flown or swimming body's mount and for a head;
    ``vehicle_joint_controllers``: the file that configures joint controllers naming a ground
    vehicle's mount or head joint (:func:`solver.identify.shipped.controller_joints`)."""
    effectors = () if srdf is None else hand_effectors(body, srdf, urdf)  # once per SRDF
    shown = [
        *_ground(body, urdf_source),
        *_water(body, urdf_source),
        *_flight(body, urdf_source, rotor_controllers),
        *_own_controller(
            "mount_joint_controllers", mount_joint_controllers, "a rotor's or thruster's mount"
        ),
        *_own_controller("head_joint_controllers", head_joint_controllers, "a pan/tilt head"),
        # A ground vehicle's mount or head joints (a suspension, a steered axle, a wheel-leg's
        # hip, a sensor's pan or tilt) a joint controller of its packages is given: they take
        # commands one by one, beside the drive (a transmission or a ros2_control block alone
        # says nothing of who commands them).
        *_shown_by(
            "vehicle_joint_controllers",
            vehicle_joint_controllers,
            "joint controllers naming a ground vehicle's mount or head joint",
        ),
        *_limbs(
            body,
            urdf_source,
            urdf,
            named,
            leg_controllers=leg_controllers,
            leg_joint_controllers=leg_joint_controllers,
        ),
        *_planned(body, srdf, profile, urdf, srdf_source, effectors=effectors),
    ]
    if _feet_only(srdf, effectors) or _balances(body) or not guess_software:
        # The SRDF says where the end effectors are, and none is on an arm; or the arms are a
        # biped's (measured: no labelled biped of the development part offers them); or the
        # robot's packages, read whole, say whether Cartesian goals are shipped (a MoveIt
        # node, a Cartesian controller, inverse kinematics: shipped.py): no guess.
        shown = [(source, text) for source, text in shown if source != "arm_gripper"]
    found: dict[str, list[str]] = {}
    by_roles: dict[str, list[str]] = {}
    for source, text in shown:
        for control in profile.description_control(source):
            # Roles speak for a control only where no declared controller does.
            (by_roles if source in ROLE_SOURCES else found).setdefault(control, []).append(text)
    for control, texts in by_roles.items():
        found.setdefault(control, texts)
    order = [control for source, _ in shown for control in profile.description_control(source)]
    controls = tuple(
        Control(name, "; ".join(found[name])) for name in dict.fromkeys(order) if name in found
    )
    if not guess_software:
        return controls
    return controls + _navigation(shown, controls, sensor_kinds, profile, urdf_source)
