"""What each joint does alone: wheels by plugin, by name and by place, driven casters, rotors
too few to fly, the joints below a gripper."""

from __future__ import annotations

import math

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.actuation import joint_roles, with_role
from solver.identify.body import detect_body
from solver.identify.readers.urdf import parse_urdf
from solver.identify.roles import Role
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText, placed


def roles_of(robot: RobotText) -> dict[str, Role]:
    return joint_roles(JointTree(parse_urdf(robot.text()), load_profile()))


def test_wheels_named_only_by_a_drive_plugin_are_wheels() -> None:
    robot = RobotText("plain")
    robot.joint("left_motor", "continuous", "base_link", "l")
    robot.joint("right_motor", "continuous", "base_link", "r")
    robot.add(
        builders.model_plugin(
            "drive",
            "libgazebo_ros_diff_drive.so",
            "<leftJoint>left_motor</leftJoint><rightJoint>right_motor</rightJoint>",
        )
    )
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert body.wheels == ("left_motor", "right_motor")


def corner_leaves(name: str) -> RobotText:
    """Four endless leaves on upright axes at a body's corners, named ``name`` and a number."""
    robot = RobotText("corners")
    for i, xyz in enumerate(("0.1 0.1 0", "0.1 -0.1 0", "-0.1 0.1 0", "-0.1 -0.1 0"), 1):
        placed(robot, f"base_to_{name}_{i}", "continuous", "base_link", f"{name}_{i}", xyz=xyz)
    return robot


def test_endless_leaves_named_as_modules_round_a_body_are_a_swerve_drive_not_rotors() -> None:
    # A swerve drive drawn without its wheels: each module turns a wheel's heading and drives it.
    swerve = identify_urdf(corner_leaves("module").text())
    assert swerve.structure == "UGV"
    assert [c.motion_control for c in swerve.motion_controls] == ["Driving"]
    # The same leaves with no part's name, or named as motor modules, are a multirotor's
    # propellers.
    assert identify_urdf(corner_leaves("link").text()).structure == "UAV"
    assert identify_urdf(corner_leaves("motor_module").text()).structure == "UAV"


def test_a_chain_of_modules_is_no_swerve_drive() -> None:
    snake = RobotText("snake")
    snake.chain(snake.root, [f"module_{i}" for i in range(1, 9)])
    assert not any(role.role == "wheel" for role in roles_of(snake).values())


def test_one_continuous_prop_joint_in_an_arm_is_never_flight() -> None:
    robot = builders.manipulator()
    robot.joint("prop_joint", "continuous", "wrist_3_link", "prop_link")
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert any(line.startswith("not flight: 1 rotor-named joint") for line in result.evidence)


def test_motor_links_named_rotor_on_wheeled_legs_make_no_uav() -> None:
    robot = RobotText("wheel_biped")
    for side in ("left", "right"):
        knee = robot.chain("base_link", [f"{side}_hip", f"{side}_knee"])
        robot.joint(f"{side}_wheel", "continuous", knee, f"{side}_wheel_motor_rotor")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, result.body.wheels) == (
        "UGV",
        ("left_wheel", "right_wheel"),
    )


def _four_spinning_leaves(
    robot: RobotText, height: float, limits: str = "", axis: str = "0 1 0"
) -> None:
    for corner, (x, y) in {"fl": (1, 1), "fr": (1, -1), "rl": (-1, 1), "rr": (-1, -1)}.items():
        kind = "revolute" if limits else "continuous"
        origin = f'<origin xyz="{0.2 * x} {0.15 * y} {height}"/><axis xyz="{axis}"/>{limits}'
        robot.joint(f"{corner}_joint", kind, "base_link", f"{corner}_Link", origin)


def _cube_with_a_disc(height: float) -> str:
    """A 15 cm box and one endless joint named for a wheel, turning a 4 cm disc ``height``
    below the box's middle (its side face), and a hinged flap on top (so the wheel is not the
    robot's only moving joint, which alone moves no vehicle)."""
    robot = RobotText("cube")
    placed(robot, "flap_joint", "revolute", "base_link", "flap", xyz="0 0 0.08", axis="1 0 0")
    robot.joint(
        "motor_joint",
        "continuous",
        "base_link",
        "wheel_link",
        f'<origin xyz="0.08 0 {-height}"/><axis xyz="1 0 0"/>',
    )
    box = '<visual><geometry><box size="0.15 0.15 0.15"/></geometry></visual>'
    disc = '<visual><geometry><cylinder radius="0.04" length="0.01"/></geometry></visual>'
    return (
        robot.text()
        .replace('<link name="base_link"/>', f'<link name="base_link">{box}</link>')
        .replace('<link name="wheel_link"/>', f'<link name="wheel_link">{disc}</link>')
    )


def test_a_bodys_only_wheel_whose_rim_stays_inside_its_box_is_a_flywheel() -> None:
    # A reaction-wheel cube: the disc turns beside the box's middle, its rim 3.5 cm above the
    # box's bottom; nothing reaches the ground.
    inside = identify_urdf(_cube_with_a_disc(0.0))
    assert inside.body is not None
    assert (inside.structure, inside.body.wheels) == ("Other", ())
    # The same disc hung low enough to reach below the box: a wheel.
    below = identify_urdf(_cube_with_a_disc(0.05))
    assert below.body is not None
    assert below.body.wheels == ("motor_joint",)


def test_unnamed_endless_joints_below_a_body_on_both_sides_are_wheels() -> None:
    robot = RobotText("rover")
    _four_spinning_leaves(robot, -0.1)
    result = identify_urdf(robot.text())
    assert (result.structure, result.kinematic_type) == ("UGV", "UGV")
    assert result.body is not None
    assert result.body.wheels == ("fl_joint", "fr_joint", "rl_joint", "rr_joint")


def test_two_unnamed_endless_joints_at_the_ends_of_one_axle_are_wheels_on_a_body_facing_y() -> None:
    # A balancing robot drawn facing along y: its two wheels apart along x, both on y = 0, so
    # no side of y tells them; at either end of one level axle, the body between them.
    robot = RobotText("balancer")
    for name, x in (("a", -0.06), ("b", 0.06)):
        builders.placed(
            robot,
            f"{name}_joint",
            "continuous",
            "base_link",
            f"{name}_link",
            xyz=f"{x} 0 -0.06",
            axis="1 0 0",
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, result.body.wheels) == ("UGV", ("a_joint", "b_joint"))
    # The same two joints one above the other's axle, not at its ends: no wheels.
    off = RobotText("balancer")
    for name, x, z in (("a", -0.06, -0.06), ("b", 0.06, 0.1)):
        builders.placed(
            off,
            f"{name}_joint",
            "continuous",
            "base_link",
            f"{name}_link",
            xyz=f"{x} 0 {z}",
            axis="1 0 0",
        )
    assert identify_urdf(off.text()).structure != "UGV"


def _hull(places: tuple[float, ...]) -> tuple[str | None, tuple[str, ...]]:
    """The structure and the wheels read on a hull drawn facing along y, with one unnamed
    endless joint about x at each of ``places`` along x, all on one level axle 0.6 m below."""
    robot = RobotText("hull")
    for index, x in enumerate(places):
        builders.placed(
            robot, f"j{index}_joint", "continuous", "base_link", f"j{index}_link",
            xyz=f"{x} 0 -0.6", axis="1 0 0",
        )  # fmt: skip
    result = identify_urdf(robot.text())
    assert result.body is not None
    return result.structure, result.body.wheels


def test_two_unnamed_endless_joints_at_each_end_of_one_axle_are_a_tracked_hulls_wheels() -> None:
    # A tank's hull drawn facing along y (fresh set 1248's, named in Turkish): at each end of
    # one level axle along x a sprocket and a road wheel drawn at one place.
    structure, wheels = _hull((-1.0, -1.0, 1.0, 1.0))
    assert (structure, len(wheels)) == ("UGV", 4)
    # All four at one end of the axle, or a hand's four knuckles in a row along it (found in
    # review): no wheels.
    assert _hull((0.5, 0.5, 1.0, 1.0))[1] == ()
    assert _hull((-0.03, -0.01, 0.01, 0.03))[1] == ()


def test_a_spinner_square_to_the_axle_the_wheels_share_is_no_wheel() -> None:
    # Four wheels about axles across the body, and at its nose a spinner about the line the
    # body rolls along: a propeller, no wheel (it would roll the body sideways).
    robot = RobotText("rover")
    _four_spinning_leaves(robot, -0.1)
    robot.joint(
        "nose", "continuous", "base_link", "spinner", '<origin xyz="0.4 0 0"/><axis xyz="1 0 0"/>'
    )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.wheels == ("fl_joint", "fr_joint", "rl_joint", "rr_joint")
    # An omni base's four wheels at its sides' middles, two axles along it and two across,
    # each pointing in: no axle most of them share, all four wheels.
    omni = RobotText("omni")
    for name, (x, y), axis in (
        ("f", (0.2, 0), "1 0 0"),
        ("b", (-0.2, 0), "1 0 0"),
        ("l", (0, 0.2), "0 1 0"),
        ("r", (0, -0.2), "0 1 0"),
    ):
        place = f'<origin xyz="{x} {y} -0.1"/><axis xyz="{axis}"/>'
        omni.joint(f"{name}_joint", "continuous", "base_link", f"{name}_link", place)
    found = identify_urdf(omni.text())
    assert found.body is not None
    assert sorted(found.body.wheels) == ["b_joint", "f_joint", "l_joint", "r_joint"]


def _with_masses(text: str, centres: dict[str, str]) -> str:
    """``text`` with each link named in ``centres`` given a mass there (its inertial origin)."""
    inertia = '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
    for link, centre in centres.items():
        text = text.replace(
            f'<link name="{link}"/>',
            f'<link name="{link}"><inertial><origin xyz="{centre}"/><mass value="1"/>'
            f"{inertia}</inertial></link>",
        )
    return text


BLANK = '<axis xyz="0 0 1"/><limit lower="0" upper="0" effort="0" velocity="0"/>'


def test_a_cad_exports_blank_wheels_are_told_by_sides_of_the_bodys_mass_centre() -> None:
    # A small tracked rover exported from CAD: its only joints four unnamed revolute leaves
    # written 0..0 with zero effort (no limits given: they move, how far unsaid), axles across
    # the body, below it, each turning a part balanced on its axle; the body's origin at its
    # right-hand corner, so every wheel lies left of the origin, and its mass centre in the
    # middle, with wheels on both sides of it.
    robot = RobotText("explorer")
    places = {"a": (0, 0.05), "b": (0.2, 0.05), "c": (0, 0.25), "d": (0.2, 0.25)}
    for corner, (x, y) in places.items():
        origin = f'<origin xyz="{x} {y} -0.02" rpy="1.5708 0 0"/>'
        robot.joint(f"{corner}_joint", "revolute", "base_link", f"{corner}_link", origin + BLANK)
    wheels = {f"{corner}_link": "0 0 0" for corner in places}
    result = identify_urdf(_with_masses(robot.text(), {"base_link": "0.1 0.15 0", **wheels}))
    assert result.body is not None
    assert (result.structure, result.body.wheels) == (
        "UGV",
        ("a_joint", "b_joint", "c_joint", "d_joint"),
    )
    # A body whose file gives no mass centre is told from its origin: all on one side.
    assert identify_urdf(_with_masses(robot.text(), wheels)).structure != "UGV"


def _with_bodies(text: str, bodies: dict[str, str]) -> str:
    """``text`` with each link named in ``bodies`` given that inner XML."""
    for link, body in bodies.items():
        text = text.replace(f'<link name="{link}"/>', f'<link name="{link}">{body}</link>')
    return text


INERTIA = '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
TYRE = (
    '<visual><origin rpy="1.5708 0 0"/>'
    '<geometry><cylinder radius="0.08" length="0.04"/></geometry></visual>'
)
SHANK = (
    '<visual><origin xyz="0 0 -0.08"/>'
    '<geometry><cylinder radius="0.02" length="0.16"/></geometry></visual>'
)


def _swing_legs(part: str) -> str:
    """A body with a hinge about a level axis at each corner, driven, carrying an unnamed
    endless leaf about a parallel axle 15 cm below it, the leaf's link ``part`` (inner XML)."""
    robot = RobotText("rover")
    bodies = {}
    for i, (x, y) in enumerate(((0.12, 0.14), (0.12, -0.14), (-0.12, 0.14), (-0.12, -0.14))):
        arm = builders.placed(
            robot, f"h{i}", "revolute", robot.root, f"a{i}", xyz=f"{x} {y} -0.05", axis="0 1 0"
        )
        builders.placed(robot, f"w{i}", "continuous", arm, f"b{i}", xyz="0 0 -0.15", axis="0 1 0")
        robot.add(builders.transmission(f"h{i}"))
        bodies[f"b{i}"] = part
    return _with_bodies(robot.text(), bodies)


def test_round_leaves_each_on_a_driven_hinge_about_a_parallel_axis_ride_on_swing_arms() -> None:
    # A rover whose corners are legs of one hinge raising a wheel, nothing named: the wheels
    # are drawn round their axles, their mass on them, and one hinge makes no leg to walk on.
    mass = f'<inertial><origin xyz="0 0 0"/><mass value="1"/>{INERTIA}</inertial>'
    result = identify_urdf(_swing_legs(TYRE + mass))
    assert result.body is not None
    assert (result.structure, result.body.wheels) == ("UGV", ("w0", "w1", "w2", "w3"))
    # A walker's knee turning for ever is drawn along its shank, its mass written at the knee
    # or not: legs.
    assert identify_urdf(_swing_legs(SHANK + mass)).structure == "Quadruped"
    # A tyre hanging its mass off its axle is known to be none.
    off = f'<inertial><origin xyz="0 0 -0.08"/><mass value="1"/>{INERTIA}</inertial>'
    assert identify_urdf(_swing_legs(TYRE + off)).structure == "Quadruped"


def whole_turn_export(*, arm_bounds: str = 'lower="-3.14159" upper="3.14159"') -> str:
    """An export that bounds every joint +-pi: four unnamed leaves at a base's corners, axles
    across it, each turning a part balanced on its axle, and a three-joint arm on top (bounded
    ``arm_bounds``)."""
    robot = RobotText("rover")
    whole = '<axis xyz="0 0 1"/><limit lower="-3.14159" upper="3.14159" effort="1" velocity="1"/>'
    for corner, (x, y) in {
        "a": (0, 0.05),
        "b": (0.3, 0.05),
        "c": (0, 0.35),
        "d": (0.3, 0.35),
    }.items():
        origin = f'<origin xyz="{x} {y} -0.02" rpy="1.5708 0 0"/>'
        robot.joint(f"{corner}_joint", "revolute", "base_link", f"{corner}_link", origin + whole)
    arm = f'<axis xyz="0 1 0"/><limit {arm_bounds} effort="1" velocity="1"/>'
    parent = "base_link"
    for i in range(3):
        robot.joint(f"j{i}", "revolute", parent, f"l{i}", f'<origin xyz="0.15 0.2 0.2"/>{arm}')
        parent = f"l{i}"
    wheels = {f"{corner}_link": "0 0 0" for corner in "abcd"}
    return _with_masses(robot.text(), {"base_link": "0.15 0.2 0", **wheels})


def test_balanced_leaves_on_level_axles_of_an_export_bounding_every_joint_alike_are_wheels() -> (
    None
):
    # Onshape's export writes +-pi on every revolute joint, the wheels' too: their limits say
    # nothing, their place and balance do.
    result = identify_urdf(whole_turn_export())
    assert result.body is not None
    assert (result.structure, result.body.wheels) == (
        "Mobile Manipulator",
        ("a_joint", "b_joint", "c_joint", "d_joint"),
    )
    # Flanges at two arms' ends, balanced and turning about level axles left and right, are
    # no wheels: many joints move them.
    torso = RobotText("torso")
    whole = '<limit lower="-3.14159" upper="3.14159" effort="1" velocity="1"/>'
    for side, y in (("a", 0.3), ("b", -0.3)):
        parent = "base_link"
        for i, axis in enumerate(("0 0 1", "0 1 0", "0 1 0", "0 1 0")):
            child = f"{side}{i}"
            origin = f'<origin xyz="0.1 {y if i == 0 else 0} 0.3"/><axis xyz="{axis}"/>'
            torso.joint(f"{side}j{i}", "revolute", parent, child, origin + whole)
            parent = child
    flanges = _with_masses(torso.text(), {"a3": "0 0 0", "b3": "0 0 0"})
    found = identify_urdf(flanges)
    assert found.body is not None
    assert (found.structure, found.body.wheels) == ("Torso", ())
    # Where the arm's joints are bounded otherwise, a whole turn may be a stop: no wheels.
    other = identify_urdf(whole_turn_export(arm_bounds='lower="-1.5" upper="1.5"'))
    assert other.body is not None
    assert other.body.wheels == ()


def bicopter(*, second: str = "0 -0.15 0.2") -> RobotText:
    """Two unnamed servos left and right of the body, each tilting a motor on an endless joint
    (``m1``, ``m2``, the second at ``second``); a motor model plugin for ``m1`` only, as an
    unfinished model writes it."""
    robot = RobotText("r")
    for i, xyz in ((1, "0 0.15 0.2"), (2, second)):
        builders.placed(robot, f"s{i}", "revolute", robot.root, f"servo{i}", xyz=xyz, axis="0 1 0")
        builders.placed(robot, f"m{i}", "continuous", f"servo{i}", f"motor{i}", xyz="0 0 0.04")
    plugin = "<jointName>m1</jointName><linkName>motor1</linkName><motorNumber>0</motorNumber>"
    robot.add(builders.model_plugin("motor_1", "librotors_gazebo_motor_model.so", plugin))
    return robot


def test_the_mirror_image_of_a_rotor_a_motor_plugin_names_is_its_twin_rotor() -> None:
    result = identify_urdf(bicopter().text())
    assert result.structure == "UAV"
    found = {r.joint: r for r in result.roles}
    assert found["m2"].role == "rotor"
    assert found["m2"].evidence.startswith("the mirror image of rotor m1")
    # Elsewhere on the body (not where m1 is seen in a mirror) it is no twin: one rotor is
    # too few to fly.
    elsewhere = identify_urdf(bicopter(second="0.1 -0.05 0.2").text())
    assert "m2" not in {r.joint for r in elsewhere.roles if r.role == "rotor"}
    # A PX4-style motor (revolute, +-1e16 rad) is endless too: a twin.
    px4 = (
        bicopter()
        .text()
        .replace('<joint name="m2" type="continuous"', '<joint name="m2" type="revolute"')
    )
    px4 = px4.replace(
        '<child link="motor2"/>',
        '<child link="motor2"/><limit lower="-1e16" upper="1e16" effort="1" velocity="1"/>',
    )
    assert 'name="m2" type="revolute"' in px4
    assert "1e16" in px4
    assert identify_urdf(px4).structure == "UAV"


def test_a_quadcopter_whose_plugins_name_one_rotor_keeps_all_four() -> None:
    # An X quadcopter's four propeller discs; a motor model plugin for the first only. The
    # other three are rotors by their ring round the body.
    inertia = '<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>'
    parts = [f'<link name="base"><inertial><mass value="1.5"/>{inertia}</inertial></link>']
    for i, (x, y) in enumerate(((0.2, 0.2), (-0.2, -0.2), (0.2, -0.2), (-0.2, 0.2)), start=1):
        disc = '<geometry><cylinder radius="0.1" length="0.005"/></geometry>'
        parts.append(
            f'<link name="p{i}"><inertial><mass value="0.01"/>{inertia}</inertial>'
            f"<visual>{disc}</visual></link>"
            f'<joint name="m{i}" type="continuous"><parent link="base"/><child link="p{i}"/>'
            f'<origin xyz="{x} {y} 0.05"/><axis xyz="0 0 1"/></joint>'
        )
    parts.append(
        '<gazebo><plugin name="motor_1" filename="librotors_gazebo_motor_model.so">'
        "<jointName>m1</jointName><linkName>p1</linkName><motorNumber>1</motorNumber>"
        "</plugin></gazebo>"
    )
    result = identify_urdf(f'<robot name="r">{"".join(parts)}</robot>')
    assert result.body is not None
    assert (result.structure, sorted(result.body.rotors)) == ("UAV", ["m1", "m2", "m3", "m4"])


def three_spinning_leaves(yaws: tuple[float, ...]) -> RobotText:
    """Three unnamed endless leaves below a base whose origin is at a corner of them (none on
    its left), at 120 degrees round their middle (0.2, -0.2), each frame turned a quarter
    about y (its z axle level) and then by ``yaws``."""
    robot = RobotText("kiwi")
    for index, bearing in enumerate((90, 210, 330)):
        x = 0.2 + 0.2 * math.cos(math.radians(bearing))
        y = -0.2 + 0.2 * math.sin(math.radians(bearing))
        turned = f'<origin xyz="{x:.4f} {y:.4f} -0.03" rpy="0 1.5708 {yaws[index]:.4f}"/>'
        turned += '<axis xyz="0 0 1"/>'
        robot.joint(f"j{index}", "continuous", "base_link", f"l{index}", turned)
    return robot


def test_three_unnamed_endless_joints_whose_axles_point_at_their_middle_are_an_omni_base() -> None:
    # A kiwi drive exported with its origin at a corner: sides of it say nothing, but each
    # wheel's axle points at the middle of the three, all round it.
    pointing_in = tuple(math.radians(b + 180) for b in (90, 210, 330))
    result = identify_urdf(three_spinning_leaves(pointing_in).text())
    assert result.body is not None
    assert (result.structure, result.body.wheels) == ("UGV", ("j0", "j1", "j2"))
    # The same three with their axles all one way (across one line) are no omni base.
    across = identify_urdf(three_spinning_leaves((0.0, 0.0, 0.0)).text())
    assert across.body is not None
    assert across.body.wheels == ()


def test_blank_jaws_hanging_their_mass_off_their_hinges_are_no_wheels() -> None:
    # A claw exported blank, no part named: a wrist and two jaws below the link it turns, one
    # on each side, each jaw's mass 5 cm out from its hinge. Written so, every joint moves, but
    # nothing says a jaw turns for ever: it is no wheel, balanced on no axle.
    robot = RobotText("claw")
    robot.joint("joint1", "revolute", "base_link", "link1", BLANK)
    for side, y in (("l", 0.03), ("r", -0.03)):
        origin = f'<origin xyz="0 {y} -0.02" rpy="1.5708 0 0"/>'
        robot.joint(f"joint_{side}", "revolute", "link1", f"link_{side}", origin + BLANK)
    jaws = {"link_l": "0 -0.05 0", "link_r": "0 -0.05 0"}
    result = identify_urdf(_with_masses(robot.text(), jaws))
    assert result.body is not None
    assert result.body.wheels == ()
    assert result.structure != "UGV"
    # Balanced on their hinges, the same two are a pair of wheels on a turning mount.
    balanced = identify_urdf(_with_masses(robot.text(), dict.fromkeys(jaws, "0 0 0")))
    assert balanced.body is not None
    assert balanced.body.wheels == ("joint_l", "joint_r")


def test_unnamed_endless_joints_carrying_sensors_are_turning_mounts_not_wheels() -> None:
    robot = RobotText("rover")
    _four_spinning_leaves(robot, -0.1)
    for corner in ("fl", "fr", "rl", "rr"):
        robot.add(builders.gazebo_sensor(f"{corner}_Link", "camera", f"{corner}_camera"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.wheels == ()


@pytest.mark.parametrize("kind", ["contact", "imu", "force_torque"])
def test_a_sensor_that_turns_with_a_wheel_leaves_it_a_wheel(kind: str) -> None:
    robot = RobotText("rover")
    _four_spinning_leaves(robot, -0.1)
    for corner in ("fl", "fr", "rl", "rr"):
        robot.add(builders.gazebo_sensor(f"{corner}_Link", kind, f"{corner}_{kind}"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.wheels == ("fl_joint", "fr_joint", "rl_joint", "rr_joint")


def test_unnamed_endless_joints_on_level_axles_above_the_origin_are_wheels_too() -> None:
    # A base whose origin is low (a wheel's axle 3 cm above it): the axles are level across
    # the body, so these turn as wheels do, whatever the origin's height.
    robot = RobotText("low_origin")
    _four_spinning_leaves(robot, 0.03)
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert len(result.body.wheels) == 4


def drop_wheels(slide: str) -> RobotText:
    """Two unnamed endless leaves on suspension links whose frames are turned a quarter about
    x (a wheel-drop: each slides, or turns when ``slide`` says revolute, along its own y): in
    those frames the wheels turn about z, in the body's about y, level."""
    robot = RobotText("drops")
    for index, y in enumerate((0.12, -0.12)):
        limit = '<limit lower="0" upper="0.03" effort="0" velocity="0"/>'
        turned = f'<origin rpy="-1.5707963 0 0" xyz="0 {y} 0.04"/><axis xyz="0 1 0"/>{limit}'
        robot.joint(f"d{index}", slide, "base_link", f"drop{index}", turned)
        robot.joint(f"s{index}", "continuous", f"drop{index}", f"l{index}", '<axis xyz="0 0 1"/>')
    return robot


def test_unnamed_wheels_on_sliding_suspension_links_turn_about_level_axles_in_the_body() -> None:
    result = identify_urdf(drop_wheels("prismatic").text())
    assert result.body is not None
    assert (result.structure, result.body.wheels) == ("UGV", ("s0", "s1"))
    # Below a joint that turns (a limb), the body's frame at rest says nothing of an axle.
    turned = identify_urdf(drop_wheels("revolute").text())
    assert turned.body is not None
    assert turned.body.wheels == ()


def arms_with_endless_wrists(wrist_axis: str) -> RobotText:
    """A trunk with two unnamed arms of four limited hinges hanging at its sides, each ending
    in an endless leaf below its forearm about ``wrist_axis``."""
    robot = RobotText("trunk")
    for side, y in (("a", 0.2), ("b", -0.2)):
        parent = robot.root
        for index, xyz in enumerate((f"0 {y} 0.3", "0 0 0", "0 0 0", "0 0 -0.2")):
            axis = "0 1 0" if index % 2 == 0 else "1 0 0"
            child = f"{side}{index}"
            builders.placed(robot, f"j{side}{index}", "revolute", parent, child, xyz=xyz, axis=axis)
            parent = child
        builders.placed(
            robot, f"w{side}", "continuous", parent, f"h{side}", xyz="0 0 -0.07", axis=wrist_axis
        )
    return robot


def test_endless_leaves_turning_about_an_upright_axis_at_the_end_of_arms_are_no_wheels() -> None:
    # A humanoid's wrist yaw drawn without limits points down under the forearm: no axle.
    result = identify_urdf(arms_with_endless_wrists("0 0 1").text())
    assert result.body is not None
    assert result.body.wheels == ()
    # About a level axle, the same leaves roll: wheels on two short legs.
    rolling = identify_urdf(arms_with_endless_wrists("0 1 0").text())
    assert rolling.body is not None
    assert sorted(rolling.body.wheels) == ["wa", "wb"]


def twin_screws(*, gps: bool = False, axis: str = "1 0 0", named: str = "m") -> RobotText:
    """Two endless leaves (``<named>0_joint`` ..) hanging below a hull at its stern, side by
    side, turning about ``axis`` (x: the line the body travels along); ``gps`` adds a GPS
    frame."""
    robot = RobotText("hull")
    for index, y in enumerate((1.0, -1.0)):
        place = f'<origin xyz="-1.5 {y} -0.5"/><axis xyz="{axis}"/>'
        joint = "m" + str(index) if named == "m" else f"{named}{index}_joint"
        robot.joint(joint, "continuous", "base_link", f"p{index}", place)
    if gps:
        robot.fixed("base_link", "gps")
    return robot


def test_unnamed_spinners_side_by_side_below_a_hull_turning_along_it_are_its_screws() -> None:
    result = identify_urdf(twin_screws().text())
    assert result.body is not None
    assert (result.body.wheels, result.body.thrusters) == ((), ("m0", "m1"))
    assert result.structure == "Surface Vessel"  # in water by its screws: nothing dives it
    assert identify_urdf(twin_screws(gps=True).text()).structure == "Surface Vessel"


def airframe(*, rudder: bool = True) -> RobotText:
    """Four unnamed limited hinges on one body, carrying nothing: two mirrored across it about
    axes across it (ailerons), and behind them on its middle line one about an axis across it
    (an elevator) and, with ``rudder``, one about an upright axis."""
    robot = RobotText("craft")
    limit = '<limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>'
    hinges = [("0 0.3 0", "0 1 0"), ("0 -0.3 0", "0 1 0"), ("-0.6 0 0", "0 1 0")]
    if rudder:
        hinges.append(("-0.65 0 0.05", "0 0 1"))
    for index, (place, axis) in enumerate(hinges):
        shape = f'<origin xyz="{place}"/><axis xyz="{axis}"/>{limit}'
        robot.joint(f"j{index}", "revolute", "base_link", f"l{index}", shape)
    return robot


def test_unnamed_ailerons_a_rudder_and_an_elevator_are_an_airframes_control_surfaces() -> None:
    result = identify_urdf(airframe().text())
    assert result.body is not None
    assert sorted(result.body.fins) == ["j0", "j1", "j2", "j3"]
    assert result.body.wings == ("l0", "l1")  # the ailerons' surfaces: a wing's
    assert result.structure == "UAV"
    # Mirrored hinges about axes across the body with no rudder behind (a tracked robot's
    # flippers, a tail's one hinge): nothing flies.
    flippers = identify_urdf(airframe(rudder=False).text())
    assert flippers.body is not None
    assert (flippers.body.fins, flippers.structure) == ((), "Other")


def catamaran(*, across: float = 0.4) -> RobotText:
    """Two hulls fixed either side of a deck, each with one unnamed endless leaf below its
    stern turning about x; the right one ``across`` from the middle."""
    robot = RobotText("catamaran")
    for index, (hull, y) in enumerate((("h0", across), ("h1", -0.4))):
        robot.joint(f"f{index}", "fixed", "base_link", hull, f'<origin xyz="0 {y} 0.1"/>')
        place = '<origin xyz="-1 0 -0.1"/><axis xyz="1 0 0"/>'
        robot.joint(f"m{index}", "continuous", hull, f"p{index}", place)
    return robot


def test_one_spinner_below_each_hull_of_a_catamaran_turning_along_it_are_its_screws() -> None:
    result = identify_urdf(catamaran().text())
    assert result.body is not None
    assert (result.body.wheels, result.body.thrusters) == ((), ("m0", "m1"))
    assert result.structure == "Surface Vessel"
    # Not mirrored across the deck: no pair of screws.
    lopsided = identify_urdf(catamaran(across=0.9).text())
    assert lopsided.body is not None
    assert lopsided.body.thrusters == ()


def test_spinners_below_a_body_a_drive_plugin_moves_or_with_control_surfaces_are_no_screws() -> (
    None
):
    driven = twin_screws()
    driven.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    plane = twin_screws()
    limit = '<limit lower="-0.3" upper="0.3" effort="1" velocity="1"/>'
    plane.joint("aileron_joint", "revolute", "base_link", "aileron", limit)
    for robot in (driven, plane):
        result = identify_urdf(robot.text())
        assert result.body is not None
        assert result.body.thrusters == ()
        assert result.structure not in ("Surface Vessel", "Underwater Vehicle")


def one_screw(*, water: bool, y: float = 0.0) -> RobotText:
    """A hull steered by a rudder, one unnamed endless leaf below its stern at ``y`` across
    it, turning about x; ``water`` adds a surface vessel's dynamics plugin."""
    robot = RobotText("sloop")
    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    robot.joint("rudder_joint", "revolute", "base_link", "rudder", limit)
    place = f'<origin xyz="-1.5 {y} -0.5"/><axis xyz="1 0 0"/>'
    robot.joint("m0", "continuous", "base_link", "p0", place)
    if water:
        robot.add(builders.model_plugin("dynamics", "libusv_gazebo_dynamics_plugin.so"))
    return robot


@pytest.mark.parametrize("first", [0, 2])
def test_overflowing_places_make_no_omni_base_whatever_the_order(first: int) -> None:
    # A mount 1e308 out, three leaves 1e308 back (two at 0, one at infinity): no middle.
    robot = RobotText("overflow")
    robot.joint("mount_joint", "fixed", "base_link", "mount", '<origin xyz="1e308 0 0"/>')
    places = [("-1e308", "1"), ("-1e308", "2"), ("1e308", "0")]
    order = places[first:] + places[:first]
    for index, (x, y) in enumerate(order):
        place = f'<origin xyz="{x} {y} -0.1"/><axis xyz="1 0 0"/>'
        robot.joint(f"j{index}", "continuous", "mount", f"l{index}", place)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.wheels == ()


def test_a_lone_spinner_below_a_hull_in_water_on_its_middle_line_is_its_screw() -> None:
    result = identify_urdf(one_screw(water=True).text())
    assert result.body is not None
    assert (result.structure, result.body.thrusters) == ("Surface Vessel", ("m0",))
    assert {c.motion_control for c in result.motion_controls} == {"Driving"}
    # Off the middle line, or on a body no water plugin names (an aircraft with one
    # propeller and a rudder has the same parts), it is no screw.
    for robot in (one_screw(water=True, y=0.4), one_screw(water=False)):
        other = identify_urdf(robot.text())
        assert other.body is not None
        assert other.body.thrusters == ()


def screw_and_rudder(
    *, screw_x: float = -3.0, rudder_x: float = -3.5, more: bool = False
) -> RobotText:
    """A hull with no water plugin: one unnamed endless leaf at ``screw_x`` on its middle line,
    turning about x, and one limited hinge about z at ``rudder_x``; ``more`` adds an elevator."""
    robot = RobotText("ship")
    builders.placed(robot, "j0", "continuous", robot.root, "l0", xyz=f"{screw_x} 0 0", axis="1 0 0")
    builders.placed(
        robot, "j1", "revolute", robot.root, "l1", xyz=f"{rudder_x} 0 0.5", axis="0 0 1"
    )
    if more:
        builders.placed(robot, "j2", "revolute", robot.root, "l2", xyz="-3.6 0 0.6", axis="0 1 0")
    return robot


def test_a_lone_spinner_at_the_stern_with_only_a_rudder_behind_it_is_a_ships_screw() -> None:
    result = identify_urdf(screw_and_rudder().text())
    assert result.body is not None
    assert (result.structure, result.body.thrusters) == ("Surface Vessel", ("j0",))
    # A propeller at the nose ahead of the rudder (an aircraft's), a rudder ahead of the
    # spinner, or an elevator beside the rudder: no screw.
    for robot in (
        screw_and_rudder(screw_x=1.0),
        screw_and_rudder(rudder_x=-2.0),
        screw_and_rudder(more=True),
    ):
        other = identify_urdf(robot.text())
        assert other.body is not None
        assert other.body.thrusters == ()


def test_a_row_of_spinners_below_a_body_is_no_pair_of_screws() -> None:
    # Three in a row across the body (not mirrored pairs), turning about x.
    robot = RobotText("row")
    for index, y in enumerate((0.5, 0.2, -0.3)):
        place = f'<origin xyz="-1.0 {y} -0.5"/><axis xyz="1 0 0"/>'
        robot.joint(f"m{index}", "continuous", "base_link", f"p{index}", place)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.thrusters == ()


def test_propeller_named_joints_side_by_side_below_a_hull_are_screws_not_rotors() -> None:
    result = identify_urdf(twin_screws(named="prop", gps=True).text())
    assert result.body is not None
    assert (result.body.rotors, result.body.thrusters) == ((), ("prop0_joint", "prop1_joint"))
    assert result.structure == "Surface Vessel"
    # Turning about upright axes, they lift: a bicopter's rotors.
    lifting = identify_urdf(twin_screws(named="prop", axis="0 0 1").text())
    assert lifting.body is not None
    assert lifting.body.thrusters == ()


def test_propeller_named_joints_stay_rotors_with_no_axis_written_or_on_an_aircraft() -> None:
    unwritten = twin_screws(named="rotor")
    unwritten.joints = [j.replace('<axis xyz="1 0 0"/>', "") for j in unwritten.joints]
    winged = twin_screws(named="prop")
    winged.fixed("base_link", "left_wing")
    flown = twin_screws(named="prop")
    flown.add(builders.model_plugin("fdm", "libArduPilotPlugin_aircraft.so"))
    for robot in (unwritten, winged, flown):
        result = identify_urdf(robot.text())
        assert result.body is not None
        assert result.body.thrusters == ()


def test_spinners_turning_about_a_line_across_the_body_are_wheels_not_screws() -> None:
    # A left and a right wheel on one axle; and a front and a rear wheel on one side (a
    # bogie's), apart across their axle as twin screws are across theirs.
    axle = identify_urdf(twin_screws(axis="0 1 0").text())
    assert axle.body is not None
    assert (axle.structure, axle.body.thrusters) == ("UGV", ())
    bogies = RobotText("bogies")
    for side, y in (("a", 0.5), ("b", -0.5)):
        limit = '<limit lower="-0.3" upper="0.3" effort="1" velocity="1"/>'
        pivot = f'<origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>{limit}'
        bogies.joint(f"{side}p", "revolute", "base_link", f"{side}_unit", pivot)
        for index, x in enumerate((0.4, -0.4)):
            place = f'<origin xyz="{x} 0 -0.2"/><axis xyz="0 1 0"/>'
            bogies.joint(f"{side}{index}", "continuous", f"{side}_unit", f"{side}w{index}", place)
    result = identify_urdf(bogies.text())
    assert result.body is not None
    assert (result.structure, result.body.thrusters, len(result.body.wheels)) == ("UGV", (), 4)


def test_unnamed_spinning_leaves_on_upright_axes_or_limited_are_no_wheels() -> None:
    upright = RobotText("upright")
    _four_spinning_leaves(upright, 0.0, axis="0 0 1")  # a rotor's axis
    limited = RobotText("limited")
    _four_spinning_leaves(limited, -0.1, '<limit lower="-1" upper="1" effort="1" velocity="1"/>')
    for robot in (upright, limited):
        result = identify_urdf(robot.text())
        assert result.body is not None
        assert result.body.wheels == ()
        assert result.structure != "UGV"


def test_a_caster_with_a_transmission_steers_with_its_swivel_and_drives_its_wheel() -> None:
    robot = builders.caster_base()
    robot.add(builders.transmission("front_swivel"))
    robot.add(builders.transmission("front_roller", "VelocityJointInterface"))
    found = roles_of(robot)
    assert found["front_swivel"] == Role(
        "front_swivel", "steering", "a vertical swivel with a transmission"
    )
    assert found["front_roller"] == Role(
        "front_roller", "wheel", "a caster's wheel with a transmission"
    )
    assert found["rear_swivel"].role == "caster"


def test_one_rotor_plays_no_role_and_two_are_rotors() -> None:
    assert "rotor_0_joint" not in roles_of(builders.quadrotor(1))
    found = roles_of(builders.quadrotor(2))
    assert [found[f"rotor_{i}_joint"].role for i in range(2)] == ["rotor", "rotor"]


def test_every_movable_joint_below_a_gripper_joint_moves_a_finger() -> None:
    robot = RobotText("claw")
    jaw = robot.chain("base_link", ["gripper_finger_left"], "prismatic")
    robot.fixed(jaw, "segment")
    robot.chain("segment", ["p2"])
    found = roles_of(robot)
    assert found["gripper_finger_left"].role == "gripper"
    assert found["p2"] == Role("p2", "gripper", "moves a finger: below a gripper joint")


def test_with_role_lists_the_joints_of_one_role_in_the_order_found() -> None:
    roles = {
        "b": Role("b", "wheel", "named"),
        "a": Role("a", "rotor", "named"),
        "c": Role("c", "wheel", "by place"),
    }
    assert with_role(roles, "wheel") == ["b", "c"]
    assert with_role(roles, "fin") == []


def test_a_motor_whose_mimic_followers_are_wheels_drives_them() -> None:
    robot = RobotText("geared_base")
    builders.placed(robot, "motor", "continuous", "base_link", "motor_link")
    for side in ("left", "right"):
        robot.joint(
            f"wheel_{side}_joint",
            "continuous",
            "base_link",
            f"wheel_{side}",
            '<mimic joint="motor"/>',
        )
    robot.add(builders.transmission("motor", "VelocityJointInterface"))
    result = identify_urdf(robot.text())
    roles = {role.joint: role.role for role in result.roles}
    assert roles["motor"] == "wheel"
    assert [c.motion_control for c in result.motion_controls] == ["Driving"]


def test_propellers_a_simulator_poses_are_rotors_even_alone() -> None:
    robot = RobotText("single_prop")
    robot.joint("propeller_joint", "floating", "base_link", "propeller")
    roles = joint_roles(JointTree(parse_urdf(robot.text(), strict=False), load_profile()))
    assert with_role(roles, "rotor") == ["propeller_joint"]


def ackermann_car(*, virtual: bool) -> RobotText:
    """Two steered front wheels under driven vertical swivels, two rear wheels; with
    ``virtual``, a bicycle's steering joint beside them that carries no wheel."""
    robot = RobotText("car")
    for side in ("left", "right"):
        knuckle = robot.joint(
            f"front_{side}_steer_joint", "revolute", robot.root, f"front_{side}_knuckle",
            '<axis xyz="0 0 1"/><limit lower="-0.7" upper="0.7" effort="1" velocity="1"/>',
        )  # fmt: skip
        robot.joint(f"front_{side}_wheel_joint", "continuous", knuckle, f"front_{side}_wheel")
        robot.joint(f"rear_{side}_wheel_joint", "continuous", robot.root, f"rear_{side}_wheel")
        robot.add(builders.transmission(f"front_{side}_steer_joint"))
    if virtual:
        robot.joint(
            "bicycle_steer_joint", "revolute", robot.root, "bicycle_steer_link",
            '<axis xyz="0 0 1"/><limit lower="-0.7" upper="0.7" effort="1" velocity="1"/>',
        )  # fmt: skip
        robot.add(builders.transmission("bicycle_steer_joint"))
    return robot


def test_a_driven_swivel_beside_a_cars_steered_wheels_steers_the_car() -> None:
    roles = roles_of(ackermann_car(virtual=True))
    assert roles["bicycle_steer_joint"].role == "steering"
    result = identify_urdf(ackermann_car(virtual=True).text())
    assert result.structure == "UGV"
    assert "Joint" not in {c.motion_control for c in result.motion_controls}


def test_an_arms_last_driven_swivel_on_a_steered_base_stays_the_arms() -> None:
    robot = ackermann_car(virtual=False)
    link = robot.root
    for i in range(6):
        axis = "0 0 1" if i in (0, 5) else "0 1 0"
        link = builders.placed(
            robot, f"a{i}", "revolute", link, f"a{i}_link", xyz="0 0 0.1", axis=axis
        )
        robot.add(builders.transmission(f"a{i}"))
    assert "a5" not in with_role(roles_of(robot), "steering")
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_an_arm_drawn_about_its_parents_z_axes_keeps_its_last_swivel_on_a_steered_base() -> None:
    # Each joint turns about its parent's z axis, each frame turned a quarter about x: upright
    # in its parent's frame, level or upright as the arm rests. The wrist's last joint is
    # upright at rest, the one below it level: it is lifted, no swivel of the base.
    robot = ackermann_car(virtual=False)
    link = robot.root
    for i in range(5):
        link = builders.placed(
            robot, f"a{i}", "revolute", link, f"a{i}_link",
            xyz="0 0 0.1", rpy="-1.5707963267949 0 0", axis="0 -1 0",
        )  # fmt: skip
        robot.add(builders.transmission(f"a{i}"))
    assert "a4" not in with_role(roles_of(robot), "steering")
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_a_driven_swivel_on_a_base_with_no_steering_is_not_read_as_steering() -> None:
    robot = builders.ugv()
    robot.joint(
        "turret_joint", "revolute", robot.root, "turret",
        '<axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>',
    )  # fmt: skip
    robot.add(builders.transmission("turret_joint"))
    assert "turret_joint" not in with_role(roles_of(robot), "steering")


def ball_caster_base(*, offset: str = "0 0 0", driven: bool = False) -> RobotText:
    """Two drive wheels and a ball caster written as yaw, roll and pitch hinges through one
    point (``offset``: where the roll and pitch joints sit on their parents)."""
    robot = RobotText("boat_like")
    builders.wheeled_base(robot)
    link = robot.root
    for name, axis in (("yaw", "0 0 1"), ("roll", "1 0 0"), ("pitch", "0 1 0")):
        origin = "0.3 0 -0.1" if name == "yaw" else offset
        link = robot.joint(
            f"ball_{name}_joint", "continuous", link, f"ball_{name}_link",
            f'<origin xyz="{origin}"/><axis xyz="{axis}"/>',
        )  # fmt: skip
        if driven:
            robot.add(builders.transmission(f"ball_{name}_joint"))
    return robot


def test_three_undriven_endless_hinges_through_one_point_on_a_wheeled_base_are_a_ball_caster() -> (
    None
):
    roles = roles_of(ball_caster_base())
    assert with_role(roles, "caster") == ["ball_pitch_joint", "ball_roll_joint", "ball_yaw_joint"]
    result = identify_urdf(ball_caster_base().text())
    assert result.structure == "UGV"  # not a mobile manipulator: the caster is no arm
    assert "Joint" not in {c.motion_control for c in result.motion_controls}


def test_hinges_apart_or_driven_are_no_ball_caster() -> None:
    for robot in (ball_caster_base(offset="0 0 0.2"), ball_caster_base(driven=True)):
        assert not with_role(roles_of(robot), "caster")


def test_a_driven_scanner_on_a_steered_base_is_a_head_not_steering() -> None:
    parts = ['<link name="base_link"/>']
    for i, (x, y) in enumerate([(0.3, 0.2), (0.3, -0.2), (-0.3, 0.2), (-0.3, -0.2)]):
        parts += [f'<link name="s{i}"/>', f'<link name="w{i}"/>']
        parts += [
            builders.joint_xml(f"steer{i}", "revolute", "base_link", f"s{i}", f"{x} {y} 0", "0 0 1")
        ]
        parts += [
            builders.joint_xml(
                f"wheel{i}_joint", "continuous", f"s{i}", f"w{i}", "0 0 -0.1", "0 1 0"
            )
        ]
        parts += [builders.transmission(f"steer{i}"), builders.transmission(f"wheel{i}_joint")]
    parts += ['<link name="scanner"/>']
    parts += [
        builders.joint_xml(
            "scanner_joint", "continuous", "base_link", "scanner", "0 0 0.3", "0 0 1"
        )
    ]
    parts += [builders.transmission("scanner_joint")]
    parts += ['<gazebo reference="scanner"><sensor name="l" type="ray"/></gazebo>']
    found = identify_urdf('<robot name="r">' + "".join(parts) + "</robot>")
    assert {r.role for r in found.roles if r.joint == "scanner_joint"} != {"steering"}


def test_a_three_axis_camera_gimbal_is_no_ball_caster() -> None:
    parts = ['<link name="base_link"/>', '<link name="lw"/>', '<link name="rw"/>']
    parts += [
        builders.joint_xml("left_wheel_joint", "continuous", "base_link", "lw", "0 0.2 0", "0 1 0")
    ]
    parts += [
        builders.joint_xml(
            "right_wheel_joint", "continuous", "base_link", "rw", "0 -0.2 0", "0 1 0"
        )
    ]
    above = "base_link"
    for k, axis in enumerate(["0 0 1", "0 1 0", "1 0 0"]):
        xyz = "0.2 0 0.3" if k == 0 else "0 0 0"
        parts += [
            f'<link name="g{k}"/>',
            builders.joint_xml(f"gimbal{k}", "continuous", above, f"g{k}", xyz, axis),
        ]
        above = f"g{k}"
    parts += [
        '<link name="cam"/>',
        builders.joint_xml("cam_fixed", "fixed", above, "cam", "0.05 0 0", "1 0 0"),
    ]
    parts += ['<gazebo reference="cam"><sensor name="c" type="camera"/></gazebo>']
    found = identify_urdf('<robot name="r">' + "".join(parts) + "</robot>")
    assert not {r.role for r in found.roles if r.joint.startswith("gimbal")} & {"caster"}


def kiwi_base(*, hubs: bool = False, corners: bool = False) -> RobotText:
    """Three unnamed rims at 120 degrees, each turning about a level radial axle and carrying
    six free rollers on endless joints (omni wheels), no name of a wheel anywhere; ``hubs``
    hangs each rim's rollers from a hub link fixed to the rim (a CAD export's housing);
    ``corners`` names each rim, its link and its rollers for the corner it is at
    (``rim_front_right``, a word legs are named by too) instead of its number."""
    robot = RobotText("kiwi")
    for i, (x, y) in enumerate(((0.2, 0.0), (-0.1, 0.17), (-0.1, -0.17))):
        place = f"{x} {y} 0"
        rim_name = f"rim_{('front_right', 'back_left', 'back_right')[i] if corners else i}"
        rim = builders.placed(
            robot, rim_name, "continuous", robot.root, f"{rim_name}_link", xyz=place, axis=place
        )
        if hubs:
            rim = robot.fixed(rim, f"hub{i}")
        for k in range(6):
            builders.placed(
                robot,
                f"{rim_name}_r{k}",
                "continuous",
                rim,
                f"r{i}_{k}",
                xyz="0 0 0.03",
                axis="0 0 1",
            )
    return robot


@pytest.mark.parametrize("hubs", [False, True], ids=["on-the-rim", "on-a-hub-fixed-to-it"])
def test_unnamed_rims_carrying_free_rollers_are_omni_wheels_and_the_rollers_passive(
    hubs: bool,
) -> None:
    result = identify_urdf(kiwi_base(hubs=hubs).text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.wheels == ("rim_0", "rim_1", "rim_2")
    roles = {role.joint: role.role for role in result.body.roles}
    assert {roles[f"rim_{i}_r{k}"] for i in range(3) for k in range(6)} == {"passive"}
    assert {c.motion_control for c in result.motion_controls} == {"Driving"}


def test_rims_named_for_a_corner_carrying_free_rollers_are_omni_wheels_not_legs() -> None:
    # A corner's word names a leg as often as a wheel; a rim of free rollers is a wheel.
    result = identify_urdf(kiwi_base(corners=True).text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.wheels == ("rim_front_right", "rim_back_left", "rim_back_right")
    assert not result.body.limbs
    roles = {role.joint: role.role for role in result.body.roles}
    assert {roles[f"rim_back_left_r{k}"] for k in range(6)} == {"passive"}


def rims_of_rollers(*, upright: bool = False, one_side: bool = False, count: int = 2) -> str:
    """Unnamed endless hubs on a body, each carrying six endless leaves across its axis: on a
    level axle at both sides (wheels), or turning about upright axes, or all on one side."""
    robot = RobotText("hubs")
    for i in range(count):
        y = 0.2 if one_side else (0.2 if i % 2 == 0 else -0.2)
        place = f"{0.3 * i} {y} 0"
        hub = builders.placed(
            robot,
            f"hub_{i}",
            "continuous",
            robot.root,
            f"h{i}",
            xyz=place,
            axis="0 0 1" if upright else "0 1 0",
        )
        for k in range(6):
            builders.placed(
                robot, f"hub_{i}_b{k}", "continuous", hub, f"h{i}_{k}", xyz="0.05 0 0", axis="1 0 0"
            )
    return robot.text()


@pytest.mark.parametrize(
    "text",
    [
        rims_of_rollers(upright=True),
        rims_of_rollers(one_side=True),
        rims_of_rollers(count=1),
    ],
    ids=["upright-hubs", "all-on-one-side", "a-single-rim"],
)
def test_hubs_of_rollers_that_turn_upright_sit_on_one_side_or_alone_are_no_rims(text: str) -> None:
    result = identify_urdf(text)
    assert result.body is not None
    evidence = {role.joint: role.evidence for role in result.body.roles}
    assert all("rollers round" not in evidence.get(f"hub_{i}", "") for i in range(2))


def test_a_level_pair_of_rims_of_rollers_on_both_sides_are_wheels() -> None:
    # The cases above fail on what they change alone: this one is read as wheels.
    result = identify_urdf(rims_of_rollers())
    assert result.body is not None
    assert set(result.body.wheels) == {"hub_0", "hub_1"}


@pytest.mark.parametrize(
    ("wrist", "finger"),
    [("wrist_roll", "finger"), ("j3", "finger"), ("wrist_roll", "j4")],
    ids=[
        "a-wrist-carrying-fingers",
        "an-unnamed-joint-carrying-fingers",
        "a-wrist-carrying-joints",
    ],
)
def test_wrists_that_roll_for_ever_carrying_endless_fingers_are_no_wheels(
    wrist: str, finger: str
) -> None:
    # A two-arm robot's wrist rolls (endless) each carry three endless joints across their
    # axis: named a wrist, or carrying fingers, they are no rims of rollers.
    robot = RobotText("two_arms")
    for side, y in (("left", 0.3), ("right", -0.3)):
        upper = builders.placed(
            robot,
            f"{side}_shoulder",
            "revolute",
            robot.root,
            f"{side}_upper",
            xyz=f"0 {y} 1",
            axis="0 1 0",
        )
        fore = builders.placed(
            robot, f"{side}_elbow", "revolute", upper, f"{side}_fore", xyz="0.3 0 0", axis="0 1 0"
        )
        palm = builders.placed(
            robot,
            f"{side}_{wrist}",
            "continuous",
            fore,
            f"{side}_link3",
            xyz="0.3 0 0",
            axis="1 0 0",
        )
        for k, axis in enumerate(("0 0 1", "0 -0.866 -0.5", "0 0.866 -0.5")):
            builders.placed(
                robot,
                f"{side}_{finger}_{k}",
                "continuous",
                palm,
                f"{side}_{finger}_{k}_link",
                xyz="0.05 0 0",
                axis=axis,
            )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not {f"left_{wrist}", f"right_{wrist}"} & set(result.body.wheels)


def flippers_with_road_wheels() -> RobotText:
    """A tracked base's two flippers: an endless bar joint on each side, level across the body,
    carrying three unnamed endless road wheels whose axles are parallel to the bar's."""
    robot = RobotText("tracked")
    for side, y in (("left", 0.25), ("right", -0.25)):
        bar = builders.placed(
            robot,
            f"front_{side}_flipper",
            "continuous",
            robot.root,
            f"{side}_bar",
            xyz=f"0.3 {y} 0",
            axis="0 1 0",
        )
        for k in range(3):
            builders.placed(
                robot,
                f"{side}_bar_{k}",
                "continuous",
                bar,
                f"{side}_road_{k}",
                xyz=f"{0.08 * (k + 1)} 0 -0.02",
                axis="0 1 0",
            )
    return robot


def test_a_flippers_road_wheels_are_not_a_rims_rollers() -> None:
    # Its leaves turn about axles parallel to the bar's: a flipper, not an omni wheel.
    result = identify_urdf(flippers_with_road_wheels().text())
    assert result.body is not None
    assert not {"front_left_flipper", "front_right_flipper"} & set(result.body.wheels)


def test_ankles_that_turn_for_ever_carrying_toes_are_no_wheels() -> None:
    # A leg's last joint named for a foot's part (an ankle) turns a foot, whatever it carries.
    robot = RobotText("dog")
    for corner, (x, y) in {"lf": (0.3, 0.2), "rf": (0.3, -0.2), "lh": (-0.3, 0.2)}.items():
        hip = builders.placed(
            robot,
            f"{corner}_hip",
            "revolute",
            robot.root,
            f"{corner}_thigh",
            xyz=f"{x} {y} 0",
            axis="0 1 0",
        )
        shin = builders.placed(
            robot,
            f"{corner}_knee",
            "revolute",
            hip,
            f"{corner}_shin",
            xyz="0 0 -0.2",
            axis="0 1 0",
        )
        foot = builders.placed(
            robot,
            f"{corner}_leg_ankle",
            "continuous",
            shin,
            f"{corner}_foot",
            xyz="0 0 -0.2",
            axis="0 1 0",
        )
        for k in range(3):
            builders.placed(
                robot,
                f"{corner}_toe{k}",
                "continuous",
                foot,
                f"{corner}_toe{k}_link",
                xyz="0.03 0 0",
                axis="1 0 0",
            )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not {"lf_leg_ankle", "rf_leg_ankle", "lh_leg_ankle"} & set(result.body.wheels)


def base_on_casters(robot: RobotText | None = None, base: str = "base_link") -> RobotText:
    """Two unnamed driven wheels on the axle line, and four unnamed casters at the corners: a
    vertical endless swivel each, carrying one endless wheel below it (on ``base`` of
    ``robot``, by default a robot of its own)."""
    robot = robot if robot is not None else RobotText("r", root=base)
    for side, y in (("a", 0.2), ("b", -0.2)):
        builders.placed(
            robot,
            f"d{side}",
            "continuous",
            base,
            f"d{side}_l",
            xyz=f"0 {y} -0.05",
            axis="0 1 0",
        )
        robot.add(builders.transmission(f"d{side}", "VelocityJointInterface"))
    for i, (x, y) in enumerate(((0.3, 0.15), (0.3, -0.15), (-0.3, 0.15), (-0.3, -0.15))):
        swivel = builders.placed(
            robot, f"s{i}", "continuous", base, f"s{i}_l", xyz=f"{x} {y} -0.02", axis="0 0 1"
        )
        builders.placed(
            robot, f"w{i}", "continuous", swivel, f"w{i}_l", xyz="-0.03 0 -0.05", axis="0 1 0"
        )
    return robot


def test_unnamed_caster_wheels_one_on_each_swivel_are_told_by_sides_across_the_body() -> None:
    result = identify_urdf(base_on_casters().text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert set(result.body.wheels) >= {"da", "db"}
    assert len(result.body.casters) >= 4
    assert "leg" not in [limb.kind for limb in result.body.limbs]


def test_the_endless_last_joints_of_two_long_unnamed_chains_are_wrists_not_wheels() -> None:
    # Two seven-joint chains of endless joints on a fixed base, one on each side (a tutorial's
    # dual arm drawn without limits): each last joint ends an arm, six joints below the body.
    robot = RobotText("dual", root="root")
    for side, y in (("r", -0.2), ("l", 0.2)):
        parent = "root"
        for i in range(1, 8):
            axis = "1 0 0" if i % 2 else "0 0 1"
            xyz = f"0 {y} 0.1" if i == 1 else "0 0 0.1"
            parent = builders.placed(
                robot, f"j{side}{i}", "continuous", parent, f"{side}{i}", xyz=xyz, axis=axis
            )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.wheels == ()
    assert result.structure == "Torso"


def test_two_endless_jaws_on_the_link_an_unlimited_arm_ends_in_are_no_pair_of_wheels() -> None:
    # A five-joint arm drawn without limits ends in a link carrying two endless jaws on both
    # sides of it, about one level axis (fresh set 1879): five endless joints above them, more
    # than a wheel hangs from.
    arm = RobotText("eureka", root="dummy_root")
    parent = arm.joint("dummy_root_to_base", "fixed", "dummy_root", "base_link")
    joints = (
        ("0 0 0.104", "0 0 1"), ("-0.15 0 0.14", "0 1 0"), ("0 0 0.35", "0 -1 0"),
        ("0 0.0125 0.135", "0 1 0"), ("0 -0.012 0.104", "0 0 1"),
    )  # fmt: skip
    for i, (xyz, axis) in enumerate(joints, start=1):
        if i == 4:  # a rigid link between the elbow and the wrist
            parent = builders.placed(arm, "rigid1", "fixed", parent, "link3b",
                                     xyz="0.045 -0.028 0.226")  # fmt: skip
        parent = builders.placed(arm, f"joint{i}", "continuous", parent, f"link{i}",
                                 xyz=xyz, axis=axis)  # fmt: skip
    for side, x, axis in (("a", 0.04, "0 1 0"), ("b", -0.04, "0 -1 0")):  # the jaws, unnamed
        builders.placed(arm, f"joint6{side}", "continuous", parent, f"link7{side}",
                        xyz=f"{x} {x / 4.5} 0.023", axis=axis)  # fmt: skip
    result = identify_urdf(arm.text())
    assert result.body is not None
    assert result.body.wheels == ()
    assert result.structure != "UGV"


def test_the_endless_last_joints_of_two_seven_joint_arms_on_a_wheeled_base_are_no_wheels() -> None:
    # Two unnamed seven-joint arms on a wheeled base, one on each side, their odd joints endless
    # and their even ones limited (a Kinova Gen3's): only three endless joints hang above each
    # last one, but six joints of one chain do, more than any wheel's leg or suspension.
    robot = builders.ugv()
    for side, y in (("r", -0.2), ("l", 0.2)):
        parent = robot.root
        for i in range(1, 8):
            kind = "continuous" if i % 2 else "revolute"
            xyz = f"0 {y} 0.3" if i == 1 else "0 0 0.1"
            axis = "0 1 0" if i == 7 else "0 0 1"  # the last one about a level axle at rest
            parent = builders.placed(
                robot, f"{side}{i}", kind, parent, f"{side}{i}_l", xyz=xyz, axis=axis
            )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not {"r7", "l7"} & set(result.body.wheels)
    assert result.structure == "Mobile Manipulator"


def limbs_ending_in_endless_leaves(limbs: int, joints: int, *, fork: bool = False) -> RobotText:
    """A body with ``limbs`` unnamed chains of ``joints`` limited joints round it, each ending
    in an endless leaf turning about a level axle (with ``fork``, each chain's fourth link also
    carries a second joint)."""
    robot = RobotText("limbs")
    for i in range(limbs):
        y = 0.3 if i % 2 else -0.3
        parent = robot.root
        for j in range(1, joints + 1):
            xyz = f"{0.2 * (i // 2)} {y} 0" if j == 1 else "0 0 -0.1"
            parent = builders.placed(robot, f"l{i}_{j}", "revolute", parent, f"l{i}_{j}_l", xyz=xyz)
            if fork and j == 4:
                builders.placed(robot, f"l{i}_side", "revolute", parent, f"l{i}_side_l")
        builders.placed(robot, f"l{i}_hub", "continuous", parent, f"l{i}_hub_l", axis="0 1 0")
    return robot


def test_two_endless_leaves_ending_six_joints_of_one_chain_are_wrists_five_or_a_fork_wheels() -> (
    None
):
    def wheels(robot: RobotText) -> set[str]:
        body = identify_urdf(robot.text()).body
        assert body is not None
        return {name for name in body.wheels if name.endswith("_hub")}

    assert wheels(limbs_ending_in_endless_leaves(2, 6)) == set()
    assert wheels(limbs_ending_in_endless_leaves(2, 5)) == {"l0_hub", "l1_hub"}
    # Counted from the nearest link that carries another moving part (a fork at the fourth).
    assert wheels(limbs_ending_in_endless_leaves(2, 6, fork=True)) == {"l0_hub", "l1_hub"}
    # Four or more so deep are a walker's wheeled feet (six-joint legs, each with a wheel).
    assert len(wheels(limbs_ending_in_endless_leaves(4, 6))) == 4


def test_caster_wheels_below_a_planners_virtual_root_joints_are_still_wheels() -> None:
    # A whole-body planner's x, y and yaw joints above the base: only endless joints count
    # against a wheel, and the planner's slides and limited yaw do not.
    robot = RobotText("r", root="world")
    builders.placed(robot, "x", "prismatic", "world", "x_l", axis="1 0 0")
    builders.placed(robot, "y", "prismatic", "x_l", "y_l", axis="0 1 0")
    builders.placed(robot, "yaw", "revolute", "y_l", "base", axis="0 0 1")
    result = identify_urdf(base_on_casters(robot, "base").text())
    assert result.body is not None
    assert set(result.body.wheels) == {"da", "db", "w0", "w1", "w2", "w3"}


def test_many_road_wheels_of_a_tracked_body_are_wheels_not_a_walkers_legs() -> None:
    robot = RobotText("r")
    for i in range(8):
        x, y = 0.1 * (i % 4) - 0.15, 0.2 if i < 4 else -0.2
        builders.placed(
            robot, f"r{i}", "continuous", robot.root, f"r{i}_l", xyz=f"{x} {y} 0", axis="0 1 0"
        )
    robot.add(builders.model_plugin("tracks", "libSimpleTrackedVehiclePlugin.so"))
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]


def test_unnamed_endless_leaves_on_upright_axes_all_round_a_body_are_its_rotors() -> None:
    robot = RobotText("r")
    _four_spinning_leaves(robot, 0.02, axis="0 0 1")
    result = identify_urdf(robot.text())
    assert result.structure == "UAV"
    assert result.body is not None
    assert len(result.body.rotors) == 4
    # Three on one side of the body are no rotors all round it (a row of spinning tools).
    row = RobotText("row")
    for i in range(3):
        builders.placed(row, f"s{i}", "continuous", row.root, f"s{i}_l", xyz=f"{0.1 * i} 0.1 0.02")
    assert identify_urdf(row.text()).structure != "UAV"


def _wheels_and_spinners(centre: str) -> str:
    """Two wheels a drive plugin names, axles 5 cm up, and four unnamed endless leaves about
    upright axes all round the body 1 cm above the axles, each part's mass at ``centre`` in
    its own frame."""
    robot = RobotText("r")
    for side, y in (("l", 0.1), ("r", -0.1)):
        builders.placed(
            robot, f"{side}_motor", "continuous", robot.root, f"{side}_disc", xyz=f"0 {y} 0.05",
            axis="0 1 0",
        )  # fmt: skip
    params = "<leftJoint>l_motor</leftJoint><rightJoint>r_motor</rightJoint>"
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so", params))
    for i, (x, y) in enumerate(((0.15, 0.1), (0.15, -0.1), (-0.15, 0.1), (-0.15, -0.1))):
        builders.placed(robot, f"s{i}", "continuous", robot.root, f"p{i}", xyz=f"{x} {y} 0.06")
    return _with_masses(robot.text(), {f"p{i}": centre for i in range(4)})


def test_unnamed_spinners_of_a_wheeled_body_trailing_their_mass_are_casters_not_rotors() -> None:
    # Casters' swivels drawn without their wheels trail their fork and wheel behind and below.
    result = identify_urdf(_wheels_and_spinners("-0.02 0 -0.04"))
    assert result.body is not None
    assert (result.structure, result.body.rotors) == ("UGV", ())
    # A wheeled drone's propellers are balanced on their shafts, however low they turn.
    assert identify_urdf(_wheels_and_spinners("0 0 0")).structure == "UAV"


def test_two_unnamed_endless_leaves_on_one_upright_line_are_a_coaxial_helicopters_rotors() -> None:
    # Contra-rotating rotors, one above the other on the body's mast; four landing legs that
    # fold about level axes beside them, and nothing named.
    robot = RobotText("r")
    builders.placed(robot, "s0", "continuous", robot.root, "top", xyz="0 0 0.12")
    builders.placed(robot, "s1", "continuous", robot.root, "bottom", xyz="0 0 0.08")
    for i, (x, y) in enumerate(((0.08, 0.09), (0.08, -0.09), (-0.08, 0.09), (-0.08, -0.09))):
        builders.placed(
            robot, f"g{i}", "revolute", robot.root, f"g{i}_l", xyz=f"{x} {y} 0", axis="1 0 0"
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, set(result.body.rotors)) == ("UAV", {"s0", "s1"})
    # A model that leaves its rotors' places to its simulator writes all four at its centre.
    centred = RobotText("centred")
    for i in range(4):
        builders.placed(centred, f"s{i}", "continuous", centred.root, f"p{i}", xyz="0 0 0.01")
    assert identify_urdf(centred.text()).structure == "UAV"
    # A wheeled base's mast stacking two spinning sensors is no helicopter.
    rover = builders.ugv()
    builders.placed(rover, "s0", "continuous", rover.root, "radar", xyz="0 0 0.3")
    builders.placed(rover, "s1", "continuous", rover.root, "scanner", xyz="0 0 0.1")
    assert identify_urdf(rover.text()).structure == "UGV"
    # Two upright spinners side by side are not on one line: no lift from them.
    apart = RobotText("apart")
    builders.placed(apart, "s0", "continuous", apart.root, "a", xyz="0 0.1 0.1")
    builders.placed(apart, "s1", "continuous", apart.root, "b", xyz="0 -0.1 0.1")
    assert identify_urdf(apart.text()).structure != "UAV"


def test_unnamed_rotors_on_mounts_swivelling_about_their_shafts_are_rotors_not_wheels() -> None:
    # A hexacopter's motor mounts, each turned a quarter so its x is upright and written as a
    # joint about that x, carry shafts turning about the same line: turning a mount leaves its
    # shaft upright, so the shafts are no wheels on level axles, and the mounts carry them
    # where the frame does (all round it).
    robot = RobotText("r")
    for i in range(6):
        yaw = i * math.pi / 3
        x, y = 0.29 * math.cos(yaw), 0.29 * math.sin(yaw)
        mount = builders.placed(
            robot,
            f"m{i}",
            "revolute",
            robot.root,
            f"mount{i}",
            xyz=f"{x} {y} 0.01",
            rpy="0 -1.5708 0",
            axis="1 0 0",
        )
        builders.placed(robot, f"s{i}", "continuous", mount, f"p{i}", xyz="0.005 0 0", axis="1 0 0")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors), result.body.wheels) == ("UAV", 6, ())


def test_unnamed_rotors_each_on_a_servo_tilting_it_about_its_arm_are_all_round_one_body() -> None:
    # A tilt-rotor: each propeller spins about an upright shaft on a servo that tilts it about
    # its arm's level line, one servo under each, nothing named; the servos carry the
    # propellers where the frame does, so they are rotors all round it, not four folded legs.
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.18, 0.18), (-0.18, 0.18), (-0.18, -0.18), (0.18, -0.18))):
        arm = builders.placed(
            robot,
            f"a{i}",
            "fixed",
            robot.root,
            f"arm{i}",
            xyz=f"{x} {y} 0.02",
            rpy=f"0 0 {math.atan2(y, x)}",
        )
        servo = builders.placed(robot, f"t{i}", "revolute", arm, f"servo{i}", axis="1 0 0")
        builders.placed(robot, f"s{i}", "continuous", servo, f"p{i}", xyz="0.02 0 0")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors)) == ("UAV", 4)
    # A simulator's floating joint placing the whole body moves no servo.
    floating = robot.text().replace(
        '<link name="base_link"/>',
        '<link name="world"/><link name="base_link"/><joint name="pose" type="floating">'
        '<parent link="world"/><child link="base_link"/></joint>',
    )
    assert identify_urdf(floating).structure == "UAV"
    # A servo with a hip turning above it is a leg's knee, no tilt-rotor's servo: four legs
    # whose knees tilt a spinning foot each are no rotors all round the body.
    legs = RobotText("legs")
    for i, (x, y) in enumerate(((0.18, 0.18), (-0.18, 0.18), (-0.18, -0.18), (0.18, -0.18))):
        hip = builders.placed(
            legs, f"h{i}", "revolute", legs.root, f"hip{i}", xyz=f"{x} {y} 0.02", axis="0 0 1"
        )
        knee = builders.placed(legs, f"k{i}", "revolute", hip, f"knee{i}", axis="1 0 0")
        builders.placed(legs, f"s{i}", "continuous", knee, f"p{i}", xyz="0.02 0 0")
    assert identify_urdf(legs.text()).structure != "UAV"


def test_unnamed_rotors_each_on_an_arm_fixed_to_the_frame_are_all_round_one_body() -> None:
    # A frame whose four arms are links of their own, fixed to it, one rotor at each arm's end.
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.2, 0.2), (0.2, -0.2), (-0.2, 0.2), (-0.2, -0.2))):
        arm = builders.placed(robot, f"a{i}", "fixed", robot.root, f"arm{i}", xyz=f"{x} {y} 0")
        builders.placed(robot, f"s{i}", "continuous", arm, f"p{i}", xyz="0 0 0.03")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors)) == ("UAV", 4)


def test_unnamed_rotors_on_motor_mounts_tipped_upright_turn_about_upright_axes() -> None:
    """A frame's motor mounts turned a quarter about y (their x upright), each spinning its
    leaf about its own x: upright in the body's frame, so rotors, not wheels on level axles."""
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.2, 0.2), (0.2, -0.2), (-0.2, 0.2), (-0.2, -0.2))):
        mount = builders.placed(
            robot, f"m{i}", "fixed", robot.root, f"mount{i}", xyz=f"{x} {y} 0", rpy="0 -1.5708 0"
        )
        builders.placed(robot, f"s{i}", "continuous", mount, f"p{i}", xyz="0.01 0 0", axis="1 0 0")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors), result.body.wheels) == ("UAV", 4, ())


def revolute_rotors(bound: str, name: str = "s") -> RobotText:
    """Four revolute leaves ``<name><i>`` on upright axes all round a body, limited to
    +-``bound``."""
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.2, 0.2), (0.2, -0.2), (-0.2, 0.2), (-0.2, -0.2))):
        robot.joint(
            f"{name}{i}",
            "revolute",
            robot.root,
            f"p{i}",
            f'<origin xyz="{x} {y} 0.03"/><axis xyz="0 0 1"/>'
            f'<limit lower="-{bound}" upper="{bound}" effort="1" velocity="1"/>',
        )
    return robot


def test_revolute_leaves_with_a_range_no_stop_has_spin_as_rotors_and_limited_ones_do_not() -> None:
    # PX4's models write rotors as revolute joints of +-1e16 rad.
    endless = identify_urdf(revolute_rotors("1e+16").text())
    assert endless.body is not None
    assert (endless.structure, len(endless.body.rotors)) == ("UAV", 4)
    limited = identify_urdf(revolute_rotors("2").text())
    assert limited.body is not None
    assert not limited.body.rotors


def test_unnamed_leaves_of_a_whole_turn_spaced_round_their_middle_are_rotors() -> None:
    # A CAD export: every joint bounded at +-3.14, the frame's origin at a corner of the body,
    # so the four propellers all sit before and right of it, spaced round their own middle.
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.16, -0.04), (-0.03, -0.04), (-0.03, -0.22), (0.16, -0.22))):
        robot.joint(
            f"j{i}",
            "revolute",
            robot.root,
            f"l{i}",
            f'<origin xyz="{x} {y} 0.11" rpy="1.5708 0 0"/><axis xyz="0 1 0"/>'
            '<limit lower="-3.14" upper="3.14" effort="0" velocity="0"/>',
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors)) == ("UAV", 4)
    # Three leaves in a row are not spaced round their middle (the two ends are twice as far
    # from it as the middle one): spinning tools, no rotors.
    row = RobotText("row")
    for i in range(3):
        row.joint(
            f"j{i}",
            "revolute",
            row.root,
            f"l{i}",
            f'<origin xyz="{0.1 * i} 0.1 0.1"/><axis xyz="0 0 1"/>'
            '<limit lower="-3.14" upper="3.14" effort="0" velocity="0"/>',
        )
    assert identify_urdf(row.text()).structure != "UAV"
    # Nor are leaves that stop short of a whole turn, wherever they are.
    short = identify_urdf(revolute_rotors("3.1").text())
    assert short.body is not None
    assert not short.body.rotors


def test_limited_leaves_named_as_motors_all_round_a_body_are_its_rotors() -> None:
    result = identify_urdf(revolute_rotors("2", name="motor_").text())
    assert result.body is not None
    assert (result.structure, len(result.body.rotors)) == ("UAV", 4)
    # A word that only begins with motor is none.
    assert identify_urdf(revolute_rotors("2", name="motorcycle_").text()).structure != "UAV"


def _hung_drone(turn: str, *, frame_turn: str = "") -> RobotText:
    """A load carried by a drone on a rod: a ball joint written as hinges, the drone on the
    rod's end turned by ``turn`` (and a frame link fixed on it turned by ``frame_turn``), four
    unnamed propellers 6 cm up the frame's own axis, round its middle."""
    robot = RobotText("load")
    builders.placed(robot, "bx", "continuous", robot.root, "rod", axis="1 0 0")
    builders.placed(robot, "by", "continuous", "rod", "knot", xyz="0 0 1", axis="0 1 0")
    builders.placed(robot, "bz", "continuous", "knot", "drone", rpy=turn, axis="0 1 0")
    frame = "drone"
    if frame_turn:
        frame = builders.placed(robot, "mount", "fixed", "drone", "frame", rpy=frame_turn)
    for i, (x, y) in enumerate(((0.08, 0.08), (0.08, -0.08), (-0.08, 0.08), (-0.08, -0.08))):
        builders.placed(robot, f"s{i}", "continuous", frame, f"p{i}", xyz=f"{x} {y} 0.06")
    return robot


@pytest.mark.parametrize(
    "hung",
    [
        # Turned a radian about x at rest: the propellers, all round the drone's own frame,
        # lie all on one side of it across the ground.
        {"turn": "-1 0 0"},
        # Level at rest, but the body turned a quarter and its frame link turned back on it
        # (a CAD export's y-up frame): upright in the frame's own axes, all round it there.
        {"turn": "1.5708 0 0", "frame_turn": "-1.5708 0 0"},
    ],
)
def test_unnamed_rotors_of_a_drone_hung_from_ball_joints_are_read_in_its_frames_axes(
    hung: dict[str, str],
) -> None:
    result = identify_urdf(_hung_drone(**hung).text())
    assert result.body is not None
    assert (result.structure, set(result.body.rotors)) == ("UAV", {"s0", "s1", "s2", "s3"})


def test_unnamed_upright_spinners_all_on_one_side_of_a_frame_are_no_rotors() -> None:
    # Three fans off a straight line, all before and left of the frame's origin.
    robot = RobotText("fans")
    for i, (x, y) in enumerate(((0.1, 0.1), (0.2, 0.15), (0.3, 0.12))):
        builders.placed(robot, f"s{i}", "continuous", robot.root, f"s{i}_l", xyz=f"{x} {y} 0.02")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.rotors == ()


def test_unnamed_wheels_on_driven_steering_knuckles_are_wheels_and_a_flippers_are_not() -> None:
    # A car: two unnamed rear wheels on the body, two front ones each on its own driven
    # knuckle turning about an upright axis (steering). Driven joints about level axes instead
    # (flippers) carry their sprockets, no wheels of the body.
    car = RobotText("car")
    for side, y in (("a", 0.2), ("b", -0.2)):
        builders.placed(
            car,
            f"r{side}",
            "continuous",
            car.root,
            f"r{side}_l",
            xyz=f"-0.3 {y} -0.05",
            axis="0 1 0",
        )
        knuckle = builders.placed(
            car, f"k{side}", "revolute", car.root, f"k{side}_l", xyz=f"0.3 {y} 0", axis="0 0 1"
        )
        car.add(builders.transmission(f"k{side}"))
        builders.placed(
            car, f"f{side}", "continuous", knuckle, f"f{side}_l", xyz="0 0 -0.05", axis="0 1 0"
        )
    result = identify_urdf(car.text())
    assert result.structure == "UGV"
    assert result.body is not None
    roles = {role.joint: role.role for role in result.body.roles}
    # The front wheels roll under their steering (no transmission of their own): casters'.
    assert [roles[name] for name in ("ra", "rb", "ka", "kb", "fa", "fb")] == (
        ["wheel", "wheel", "steering", "steering", "caster", "caster"]
    )
    flippers = car.text().replace('axis xyz="0 0 1"', 'axis xyz="0 1 0"')
    body = identify_urdf(flippers).body
    assert body is not None
    roles = {role.joint: role.role for role in body.roles}
    assert roles["fa"] not in ("wheel", "caster")


def driven_rocker(rover: RobotText, name: str, parent: str, xyz: str) -> str:
    """A joint ``name`` about a level axle across the body, with a transmission, at ``xyz``
    on ``parent``; its link."""
    link = builders.placed(rover, name, "revolute", parent, f"{name}_l", xyz=xyz, axis="0 1 0")
    rover.add(builders.transmission(name))
    return link


def unnamed_rocker_rover(front: str = "0.35", back: str = "-0.35") -> RobotText:
    """A rover written blank: on each side a driven joint about a level axle (a rocker, its
    suspension driven in a simulator) carrying two driven steering swivels, ``front`` and
    ``back`` of its pivot (m), each with a driven unnamed wheel below it."""
    rover = RobotText("rover")
    for side, y in (("a", 0.3), ("b", -0.3)):
        rocker = driven_rocker(rover, f"r{side}", rover.root, f"0 {y} -0.1")
        for end, x in (("f", front), ("h", back)):
            swivel = builders.placed(
                rover, f"s{side}{end}", "revolute", rocker, f"s{side}{end}_l", xyz=f"{x} 0 0"
            )
            rover.add(builders.transmission(f"s{side}{end}"))
            builders.placed(
                rover, f"w{side}{end}", "continuous", swivel, f"w{side}{end}_l",
                xyz="0 0 -0.25", axis="0 1 0",
            )  # fmt: skip
            rover.add(builders.transmission(f"w{side}{end}", "VelocityJointInterface"))
    return rover


def test_a_driven_rocker_lifts_none_of_the_wheels_it_carries_ahead_of_it_and_behind_it() -> None:
    result = identify_urdf(unnamed_rocker_rover().text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert sorted(result.body.wheels) == ["waf", "wah", "wbf", "wbh"]
    # Both wheels ahead of the driven joint's pivot: a flipper's, no wheels of the body.
    flippers = identify_urdf(unnamed_rocker_rover(front="0.35", back="0.05").text())
    assert flippers.body is not None
    assert not set(flippers.body.wheels) & {"waf", "wah", "wbf", "wbh"}


def test_a_driven_rocker_over_a_driven_bogie_lifts_none_of_their_six_wheels() -> None:
    # A rocker-bogie written blank, both driven: the rocker carries a front wheel of its own
    # and the bogie, whose two wheels straddle its pivot; with the bogie passed over, the
    # rocker's three wheels straddle its own.
    rover = RobotText("rover")
    for side, y in (("a", 0.3), ("b", -0.3)):
        rocker = driven_rocker(rover, f"r{side}", rover.root, f"0 {y} -0.1")
        bogie = driven_rocker(rover, f"g{side}", rocker, "-0.2 0 -0.05")
        for name, parent, x in ((f"w{side}f", rocker, 0.35), (f"w{side}m", bogie, 0.15)):
            builders.placed(
                rover, name, "continuous", parent, f"{name}_l", xyz=f"{x} 0 -0.2", axis="0 1 0"
            )
        builders.placed(
            rover, f"w{side}h", "continuous", bogie, f"w{side}h_l", xyz="-0.15 0 -0.2",
            axis="0 1 0",
        )  # fmt: skip
    result = identify_urdf(rover.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert len(result.body.wheels) == 6


def test_a_steering_joint_whose_link_is_named_like_a_finger_still_steers_its_wheel() -> None:
    # A rover model names each wheel-walking joint's link wrist_* and each driven steering
    # knuckle's link finger_*: a joint named for steering, about an upright axis, carrying
    # only a named wheel on a level axle, steers it (a wheel hangs from no gripper), on both
    # sides of the body, and the joint above it mounts the wheel (no arm).
    rover = RobotText("rover")
    for side, y in (("left", 0.3), ("right", -0.3)):
        for end, x in (("front", 0.4), ("back", -0.4)):
            corner = f"{end}_{side}"
            parent = rover.root
            for joint, kind, link, xyz, axis in (
                ("ww", "revolute", "wrist", f"{x} {y} 0", "0 1 0"),
                ("steer", "revolute", "finger", "0 0 -0.1", "0 0 1"),
                ("drive", "continuous", "wheel", "0 0 -0.1", "0 1 0"),
            ):
                name = f"joint_{joint}_{corner}"
                parent = builders.placed(
                    rover, name, kind, parent, f"{link}_{corner}", xyz=xyz, axis=axis
                )
                rover.add(builders.transmission(name))
    result = identify_urdf(rover.text())
    assert result.body is not None
    roles = {role.joint: role.role for role in result.body.roles}
    assert roles["joint_steer_front_left"] == "steering"
    assert roles["joint_drive_front_left"] == "wheel"
    assert (result.structure, result.body.grippers) == ("UGV", 0)


def swivelled_discs(shape: str, *, height: float = 0.0) -> str:
    """A box with, at each corner, ``height`` metres up, a swivel about the upright
    (``<corner>_arm_turn``) carrying one endless joint about a level axle (``<corner>_arm``)
    that turns a part drawn as ``shape`` (a disc stood on its edge, or a bar hanging down),
    its mass at the joint: names a four-legged body's corners and an arm's, no wheel's or
    steering's."""
    parts = ['<link name="base_link"/>']
    for corner, x, y in (("front_right", 0.6, -0.6), ("front_left", 0.6, 0.6),
                         ("back_right", -0.6, -0.6), ("back_left", -0.6, 0.6)):  # fmt: skip
        parts += [
            f'<link name="{corner}_arm_turn"/>',
            f'<link name="{corner}_arm"><visual><origin rpy="1.5708 0 0"/><geometry>{shape}'
            '</geometry></visual><inertial><mass value="1"/>'
            '<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>',
            builders.joint_xml(
                f"base_to_{corner}_arm_turn", "continuous", "base_link", f"{corner}_arm_turn",
                f"{x} {y} {height}", "0 0 1",
            ),
            builders.joint_xml(
                f"base_to_{corner}_arm", "continuous", f"{corner}_arm_turn", f"{corner}_arm",
                "0 0 0", "0 1 0",
            ),
        ]  # fmt: skip
    return '<robot name="discs">' + "".join(parts) + "</robot>"


def test_discs_on_swivels_at_the_corners_are_steered_wheels_whatever_their_names_say() -> None:
    # Fresh set 588: a student's four-wheel-steered robot names its wheels front_right_arm
    # (a leg's corner and an arm's word) and its swivels front_right_arm_turn; each turns a
    # cylinder about its own axis, a tyre, about a level axle below an upright swivel.
    result = identify_urdf(swivelled_discs('<cylinder radius="0.5" length="0.125"/>'))
    assert result.body is not None
    roles = {role.joint: role for role in result.body.roles}
    assert roles["base_to_front_right_arm_turn"].role == "steering"
    assert "tyre" in roles["base_to_front_right_arm_turn"].evidence
    assert roles["base_to_front_right_arm"].role == "wheel"
    assert (result.structure, result.body.count("leg")) == ("UGV", 0)


def test_discs_on_swivels_high_above_the_body_are_no_steered_wheels() -> None:
    # Drums on two pan/tilt heads, a wrist's flange on each of two arms: a cylinder round the
    # last joint's axle, under a swivel about the upright, on both sides of the body, whose
    # bottom hangs above the body's lowest frame: no tyre on the ground (found in review).
    result = identify_urdf(swivelled_discs('<cylinder radius="0.5" length="0.125"/>', height=0.8))
    assert result.body is not None
    assert not [role for role in result.body.roles if role.role in ("steering", "wheel")]


def test_a_bar_on_a_swivel_is_no_steered_wheel() -> None:
    # The same joints turning a bar stood across the axle (no cylinder round it): nothing
    # says a wheel, and a swivel that steers no wheel steers nothing.
    result = identify_urdf(swivelled_discs('<box size="0.05 1.0 0.05"/>'))
    assert result.body is not None
    assert not [role for role in result.body.roles if role.role in ("steering", "wheel")]


def test_unnamed_wheels_steered_by_joints_upright_only_as_the_body_rests_are_wheels() -> None:
    # A planetary rover: each wheel on a driven steering joint hung from a passive deployment
    # link whose frame is turned (a quarter about x, then about z), so the steering axis,
    # (0, -1, 0) in its parent's frame, stands upright as the body rests, and the wheel below
    # it turns about a level axle.
    rover = RobotText("rover")
    for i, (x, y) in enumerate(((0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3))):
        deploy = builders.placed(
            rover, f"d{i}", "revolute", rover.root, f"d{i}_l", xyz=f"{x} {y} 0",
            rpy="-1.5707963 0 1.5707963", axis="1 0 0",
        )  # fmt: skip
        steer = builders.placed(rover, f"s{i}", "revolute", deploy, f"s{i}_l", axis="0 -1 0")
        builders.placed(
            rover, f"w{i}", "continuous", steer, f"w{i}_l", xyz="0 0.09 0", axis="1 0 0"
        )
        rover.add(builders.transmission(f"s{i}") + builders.transmission(f"w{i}"))
    result = identify_urdf(rover.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.wheels == ("w0", "w1", "w2", "w3")
    assert [c.motion_control for c in result.motion_controls] == ["Driving"]


def test_a_spinner_upright_at_rest_under_joints_upright_at_rest_is_a_tool_not_a_wheel() -> None:
    # Two SCARA arms on a wheeled base, written with frames turned a quarter about x: every
    # joint, the endless tool's too, turns about an upright axis as the body rests, none in
    # its parent's frame. The tool spins about its arm's axes, as no wheel does.
    robot = RobotText("scara_bot")
    builders.wheeled_base(robot)
    for side, y in (("l", 0.25), ("r", -0.25)):
        link = builders.placed(
            robot, f"{side}mount", "fixed", robot.root, f"{side}mount_l", xyz=f"0 {y} 0.5",
            rpy="1.5707963 0 0",
        )  # fmt: skip
        for i, kind in enumerate(("revolute", "revolute", "continuous")):
            name = f"{side}s{i}"
            xyz = "0.3 0 0" if i else "0 0 0"
            link = builders.placed(robot, name, kind, link, f"{name}_l", xyz=xyz, axis="0 1 0")
            robot.add(builders.transmission(name))
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert result.body.wheels == ("wheel_left_joint", "wheel_right_joint")


def test_a_chain_of_20000_endless_joints_is_read_in_one_walk() -> None:
    # Whether each joint carries only rollers is told from its own child's joints, not the
    # whole subtree below it (which took a minute on such a chain).
    robot = RobotText("r")
    link = robot.root
    for i in range(20_000):
        link = builders.placed(robot, f"j{i}", "continuous", link, f"c{i}", axis="0 1 0")
    assert identify_urdf(robot.text()).structure


def test_10000_casters_under_a_deep_fixed_chain_are_placed_in_one_walk() -> None:
    # Whether a swivel is on the still base is one set, made once, not a walk up per wheel.
    robot = RobotText("r")
    link = robot.root
    for i in range(20_000):
        link = robot.fixed(link, f"f{i}")
    for i in range(10_000):
        y = 0.1 if i % 2 else -0.1
        swivel = builders.placed(robot, f"s{i}", "continuous", link, f"s{i}_l", xyz=f"0 {y} -0.1")
        builders.placed(
            robot, f"w{i}", "continuous", swivel, f"w{i}_l", xyz="0 0 -0.1", axis="0 1 0"
        )
    assert identify_urdf(robot.text()).structure == "UGV"


def legs_ending_in_spinners(
    *,
    last: str = "revolute",
    upper: str = "1e5",
    above: tuple[str, ...] = ("revolute", "revolute", "revolute"),
    sides: tuple[str, ...] = ("left", "right"),
    beyond: bool = False,
    name: str = "leg_4",
    axis: str = "0 1 0",
    extra: str = "",
) -> RobotText:
    """Leg-named chains on ``sides`` (``left_leg_1`` .. ``left_leg_3``, each of the kind in
    ``above``, ``spinning`` for a revolute one with placeholder limits, turning about y, the
    knee's axis) ending in a joint ``left_<name>`` of kind
    ``last`` about ``axis``, turning through +-``upper`` radians when revolute (a wheel written
    with placeholder limits, as an RL export writes it); ``beyond``: a toe joint below the last
    one; ``extra``: more of the last joint's elements (a ``<mimic>``)."""
    robot = RobotText("r")
    for side, y in (("left", 0.1), ("right", -0.1), ("mid", 0.0)):
        if side not in sides:
            continue
        link = robot.root
        places = (f"0 {y} 0", "0 0 -0.2", "0 0 -0.2")
        for i, (kind, xyz) in enumerate(zip(above, places, strict=True), start=1):
            if kind == "spinning":  # revolute with placeholder limits: it turns for ever
                link = robot.joint(
                    f"{side}_leg_{i}",
                    "revolute",
                    link,
                    f"{side}_l{i}",
                    f'<origin xyz="{xyz}"/><axis xyz="0 1 0"/>'
                    '<limit lower="-1e5" upper="1e5" effort="1" velocity="1"/>',
                )
                continue
            link = builders.placed(
                robot, f"{side}_leg_{i}", kind, link, f"{side}_l{i}", xyz=xyz, axis="0 1 0"
            )
        limit = f'<limit lower="-{upper}" upper="{upper}" effort="1" velocity="1"/>'
        robot.joint(
            f"{side}_{name}",
            last,
            link,
            f"{side}_l4",
            f'<origin xyz="0 0 -0.2"/><axis xyz="{axis}"/>'
            + (limit if last == "revolute" else "")
            + extra,
        )
        if beyond:
            builders.placed(robot, f"{side}_toe", "revolute", f"{side}_l4", f"{side}_t")
    return robot


def test_an_endless_leaf_ending_a_leg_of_limited_joints_is_a_wheel_whatever_its_name() -> None:
    # A wheel-legged biped: two legs on wheels it rolls on, a UGV, driven.
    result = identify_urdf(legs_ending_in_spinners().text())
    assert [r.joint for r in result.roles if r.role == "wheel"] == ["left_leg_4", "right_leg_4"]
    assert result.structure == "UGV"
    assert identify_urdf(legs_ending_in_spinners(last="continuous").text()).structure == "UGV"
    # An ankle with stops is a leg's: a biped.
    assert identify_urdf(legs_ending_in_spinners(upper="1").text()).structure == "Biped"


@pytest.mark.parametrize(
    "robot",
    [
        legs_ending_in_spinners(above=("continuous",) * 3),  # a chain that spins all along
        legs_ending_in_spinners(above=("revolute", "prismatic", "revolute")),  # a slide above
        legs_ending_in_spinners(above=("revolute", "revolute", "prismatic")),
        legs_ending_in_spinners(above=("revolute", "revolute", "spinning")),  # a knee that spins
        legs_ending_in_spinners(beyond=True),  # the joint carries more
        legs_ending_in_spinners(sides=("left",)),  # one leg alone
        legs_ending_in_spinners(sides=("left", "right", "mid")),  # three
        legs_ending_in_spinners(name="arm_4"),  # another part's name
        legs_ending_in_spinners(name="leg_ankle_roll"),  # an ankle's
        legs_ending_in_spinners(axis="1 0 0"),  # rolling across the knee: an ankle's roll
        legs_ending_in_spinners(extra='<mimic joint="left_leg_3"/>'),  # it follows a joint
    ],
    ids=[
        "spinning",
        "slide",
        "slide-knee",
        "spinning-knee",
        "beyond",
        "one",
        "three",
        "arm-named",
        "ankle",
        "across",
        "mimic",
    ],
)
def test_an_endless_leaf_is_no_legs_wheel_unless_it_ends_a_limited_leg_about_its_knees_axis(
    robot: RobotText,
) -> None:
    evidence = " ".join(r.evidence for r in identify_urdf(robot.text()).roles)
    assert "an endless leaf ending a leg" not in evidence


# A four-wheeled vehicle's corners and where each is on the body (x forward, y to the left).
CORNERS = {
    "front_left": (1, 0.6),
    "front_right": (1, -0.6),
    "back_left": (-1, 0.6),
    "back_right": (-1, -0.6),
}


def four_wheel_steered(steer: str = "steer") -> RobotText:
    """A farm vehicle's four corners, each a swivel named ``steer`` (upright axis) carrying one
    endless leaf on a level axle, every name carrying its corner's words (``front_left``)."""
    robot = RobotText("double_ackermann")
    for corner, (x, y) in CORNERS.items():
        knuckle = builders.placed(
            robot,
            f"{steer}_{corner}_j",
            "continuous",
            robot.root,
            f"{steer}_{corner}_link",
            xyz=f"{x} {y} -0.4",
        )
        builders.placed(
            robot,
            f"drive_{corner}_j",
            "continuous",
            knuckle,
            f"drive_{corner}_link",
            xyz="0 0 -0.3",
            axis="0 1 0",
        )
    return robot


def test_leaves_below_swivels_named_for_steering_are_steered_wheels_whatever_their_corners() -> (
    None
):
    roles = roles_of(four_wheel_steered())
    assert with_role(roles, "steering") == [f"steer_{c}_j" for c in CORNERS]
    assert with_role(roles, "wheel") == [f"drive_{c}_j" for c in CORNERS]
    assert identify_urdf(four_wheel_steered().text()).structure == "UGV"


def test_corners_under_swivels_named_for_nothing_are_a_quadrupeds_legs() -> None:
    roles = roles_of(four_wheel_steered(steer="hip"))
    assert not with_role(roles, "steering")
    assert identify_urdf(four_wheel_steered(steer="hip").text()).structure == "Quadruped"


def base_on_corner_leaves(word: str = "", joint: str = "_joint", prefix: str = "") -> RobotText:
    """A CAD export's base: four endless leaves named only for the corner they sit at
    (``rear_left_joint`` turning ``rear_left_link``), below the body about axles across it;
    ``word`` added to each name (``leg``) says what they are; ``joint`` ends the joints' and
    ``prefix`` begins them."""
    robot = RobotText("export", root="base_link")
    for corner, (x, y) in CORNERS.items():
        builders.placed(
            robot,
            f"{prefix}{corner}{word}{joint}",
            "continuous",
            "base_link",
            f"{corner}{word}_link",
            xyz=f"{x * 0.2} {y / 3} -0.02",
            axis="0 1 0",
        )
    return robot


@pytest.mark.parametrize("joint", ["_joint", "_rev", "_revolute", "_cont", "_continuous"])
def test_endless_leaves_named_only_for_their_corner_are_wheels(joint: str) -> None:
    # The joint's name ends in a word for a joint or for its type (``right_front_rev``).
    roles = roles_of(base_on_corner_leaves(joint=joint))
    assert with_role(roles, "wheel") == [f"{c}{joint}" for c in CORNERS]
    assert identify_urdf(base_on_corner_leaves(joint=joint).text()).structure == "UGV"


@pytest.mark.parametrize("prefix", ["base_to_", "chassis_link_to_"])
def test_endless_leaves_named_for_the_body_they_hang_from_and_their_corner_are_wheels(
    prefix: str,
) -> None:
    # The URDF tutorial's parent_to_child names (``base_to_front_left``) say where, not what.
    robot = base_on_corner_leaves(joint="", prefix=prefix)
    assert with_role(roles_of(robot), "wheel") == [f"{prefix}{c}" for c in CORNERS]
    assert identify_urdf(robot.text()).structure == "UGV"


def test_endless_leaves_named_from_a_part_of_a_limb_to_their_corner_are_no_wheels() -> None:
    # A thigh's joint to a corner is a leg's (``thigh_to_front_left``): a part's name, no body.
    robot = base_on_corner_leaves(joint="", prefix="thigh_to_")
    assert not with_role(roles_of(robot), "wheel")


def test_endless_leaves_named_for_a_leg_beside_their_corner_are_no_wheels_by_place() -> None:
    assert not with_role(roles_of(base_on_corner_leaves("_leg")), "wheel")


def two_wagons(word: str = "body_angle") -> RobotText:
    """A field robot of two wagons steered by an upright joint ``word`` between them, each
    wagon's axle carrying two endless leaves named only for their corner (``joint_frontLeft``
    turning ``frontLeft``), level with the axle."""
    robot = RobotText("wagons", root="base_link")
    robot.fixed(robot.root, "axesFront")
    builders.placed(robot, word, "revolute", "axesFront", "axesRear", xyz="-0.7 0 0")
    for axle, end in (("axesFront", "front"), ("axesRear", "rear")):
        for side, y in (("Left", 0.17), ("Right", -0.17)):
            builders.placed(
                robot,
                f"joint_{end}{side}",
                "continuous",
                axle,
                f"{end}{side}",
                xyz=f"0 {y} 0",
                axis="0 1 0",
            )
    return robot


def test_leaves_named_for_their_corner_on_wagons_steered_by_an_unnamed_joint_are_wheels() -> None:
    assert len(with_role(roles_of(two_wagons()), "wheel")) == 4
    assert identify_urdf(two_wagons().text()).structure == "UGV"


def test_leaves_named_for_their_corner_below_a_hip_are_not_wheels_by_place() -> None:
    wheels = with_role(roles_of(two_wagons("hip")), "wheel")
    assert not {"joint_rearLeft", "joint_rearRight"} & set(wheels)


@pytest.mark.parametrize("swivel", ["continuous", "revolute"])
def test_leaves_named_for_their_corner_alone_on_steering_swivels_are_steered_wheels(
    swivel: str,
) -> None:
    # Alone on a part that turns, the corner's word is kept: the steered-wheel rules read them.
    robot = RobotText("double_ackermann")
    for i, (corner, (x, y)) in enumerate(CORNERS.items()):
        knuckle = builders.placed(
            robot, f"steer_{i}", swivel, robot.root, f"steer_{i}_link", xyz=f"{x} {y} -0.4"
        )
        builders.placed(
            robot,
            f"{corner}_joint",
            "continuous",
            knuckle,
            f"{corner}_link",
            xyz="0 0 -0.3",
            axis="0 1 0",
        )
    roles = roles_of(robot)
    assert with_role(roles, "steering") == [f"steer_{i}" for i in range(4)]
    assert with_role(roles, "wheel") == [f"{c}_joint" for c in CORNERS]
    assert not with_role(roles, "caster")


def caster_base(leaf_mass_at: str, leaf_at: str = "-0.02 0.07 0") -> str:
    """An unnamed base: two drive wheels below it, and at its four corners a swivel about the
    upright (its frame turned a quarter about x, its axis y) carrying one leaf that turns about
    its own z, level as the base rests; each leaf's mass centre at ``leaf_mass_at`` on its link,
    each leaf at ``leaf_at`` in its swivel's frame (its y is down as the base rests).
    """
    robot = RobotText("cart", root="b")
    for i, y in enumerate((0.17, -0.17)):
        builders.placed(
            robot, f"d{i}", "continuous", "b", f"dw{i}", xyz=f"0 {y} -0.08", axis="0 1 0"
        )
    corners = ((0.19, 0.17), (0.19, -0.17), (-0.19, -0.17), (-0.19, 0.17))
    for i, (x, y) in enumerate(corners):
        swivel = builders.placed(
            robot,
            f"s{i}",
            "continuous",
            "b",
            f"sw{i}",
            xyz=f"{x} {y} -0.04",
            rpy="-1.57 0 0",
            axis="0 1 0",
        )
        builders.placed(robot, f"c{i}", "continuous", swivel, f"cw{i}", xyz=leaf_at)
    text = robot.text()
    for i in range(4):
        text = text.replace(
            f'<link name="cw{i}"/>',
            f'<link name="cw{i}"><inertial><origin xyz="{leaf_mass_at}"/><mass value="0.1"/>'
            '<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>'
            "</inertial></link>",
        )
    return text


@pytest.mark.parametrize("mass_at", ["0 0 0", "0 0 0.01"])
def test_a_leaf_on_a_swivel_about_the_upright_carrying_its_mass_on_its_level_axle_is_a_wheel(
    mass_at: str,
) -> None:
    text = caster_base(mass_at)
    roles = joint_roles(JointTree(parse_urdf(text), load_profile()))
    assert {name for name, role in roles.items() if role.role == "wheel"} >= {
        "c0",
        "c1",
        "c2",
        "c3",
    }
    assert identify_urdf(text).structure == "UGV"


@pytest.mark.parametrize(
    "drawn",
    [{"leaf_mass_at": "0.05 0 0"}, {"leaf_mass_at": "0 0 0", "leaf_at": "-0.02 -0.07 0"}],
    ids=["its mass off its axle", "above its swivel (a head's tilt)"],
)
def test_a_leaf_on_a_swivel_hanging_its_mass_off_its_axle_or_above_it_is_no_wheel(
    drawn: dict[str, str],
) -> None:
    roles = joint_roles(JointTree(parse_urdf(caster_base(**drawn)), load_profile()))
    assert {name for name, role in roles.items() if role.role == "wheel"} == {"d0", "d1"}


def bicycle(
    *,
    front_mass_at: str = "0 0 0",
    front_axis: str = "0 1 0",
    fork: str = "0 0 1",
    front_at: str = "0 0 -0.2",
) -> str:
    """An unnamed bicycle: a rear leaf on the frame and a front leaf below a fork turning about
    ``fork``, both about y (the front about ``front_axis``), 0.8 m apart along x, the front
    one at ``front_at`` from the fork's pivot; each wheel's mass centre on its axle, the
    front's at ``front_mass_at``."""
    robot = RobotText("two", root="f")
    builders.placed(robot, "r", "continuous", "f", "rw", xyz="-0.4 0 0", axis="0 1 0")
    fork_link = builders.placed(robot, "s", "revolute", "f", "fk", xyz="0.4 0 0.2", axis=fork)
    builders.placed(robot, "w", "continuous", fork_link, "fw", xyz=front_at, axis=front_axis)
    text = robot.text()
    for link, centre in (("rw", "0 0 0"), ("fw", front_mass_at)):
        text = text.replace(
            f'<link name="{link}"/>',
            f'<link name="{link}"><inertial><origin xyz="{centre}"/><mass value="1"/>'
            '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.01"/>'
            "</inertial></link>",
        )
    return text


def test_two_balanced_leaves_in_line_the_front_one_below_an_upright_swivel_are_wheels() -> None:
    roles = joint_roles(JointTree(parse_urdf(bicycle()), load_profile()))
    # The front wheel on its fork, undriven, is read as a caster's (a swivel carrying one wheel).
    assert (roles["r"].role, roles["w"].role) == ("wheel", "caster")
    assert identify_urdf(bicycle()).structure == "UGV"


@pytest.mark.parametrize(
    "drawn",
    [
        {"front_mass_at": "0 0 -0.1"},  # a pendulum's bob, not a wheel
        {"front_axis": "0.23 1 0"},  # axles 13 degrees apart: not parallel, yet in line
        {"fork": "0 1 0"},  # hung from a hinge about a level axis: an arm's joint
        {"front_at": "0 0 0.1"},  # above its swivel: a head's tilt, no fork's wheel
    ],
)
def test_two_leaves_in_line_that_are_unbalanced_askew_or_below_a_level_hinge_are_no_wheels(
    drawn: dict[str, str],
) -> None:
    roles = joint_roles(JointTree(parse_urdf(bicycle(**drawn)), load_profile()))
    assert not any(role.role == "wheel" for role in roles.values())


def lift_and_gripper(*, coupled: bool = False) -> RobotText:
    """A wheeled base whose lift raises a slide and a servo, both named for the gripper they
    carry, and at the end two jaws side by side; when ``coupled``, the second jaw mimics the
    first and the slide mimics the lift."""
    robot = RobotText("lifter")
    builders.wheeled_base(robot)
    lift = builders.placed(robot, "mast_lift", "prismatic", robot.root, "carriage", xyz="0 0 0.5")
    slide = builders.placed(robot, "gripper_slide", "prismatic", lift, "gripper_arm", axis="1 0 0")
    palm = builders.placed(robot, "gripper_wrist", "revolute", slide, "gripper_palm", xyz="0.3 0 0")
    builders.placed(robot, "gripper_left", "prismatic", palm, "jaw_l", xyz="0 0.03 0", axis="0 1 0")
    mimic = '<mimic joint="gripper_left" multiplier="-1"/>' if coupled else ""
    builders.placed(
        robot, "gripper_right", "prismatic", palm, "jaw_r", xyz="0 -0.03 0", axis="0 1 0",
        extra=mimic,
    )  # fmt: skip
    if coupled:  # the slide's joint, before the wrist's and the two jaws'
        robot.joints[-4] = robot.joints[-4].replace(
            "</joint>", '<mimic joint="mast_lift"/></joint>'
        )
    return robot


def test_gripper_named_joints_that_carry_the_jaws_alone_are_the_arms_not_fingers() -> None:
    roles = roles_of(lift_and_gripper())
    assert "gripper_slide" not in roles
    assert "gripper_wrist" not in roles
    assert (roles["gripper_left"].role, roles["gripper_right"].role) == ("gripper", "gripper")
    result = identify_urdf(lift_and_gripper().text())
    assert result.structure == "Mobile Manipulator"


def test_a_gripper_named_joint_carrying_the_jaws_that_a_mimic_couples_stays_the_grippers() -> None:
    roles = roles_of(lift_and_gripper(coupled=True))
    assert roles["gripper_slide"].role == "gripper"
    assert roles["gripper_wrist"].role == "gripper"  # below a gripper joint: a finger's


def test_a_gripper_alone_whose_first_joint_carries_the_jaws_stays_a_gripper_opened_on_command() -> (
    None
):
    robot = RobotText("rotating_gripper", root="base")
    palm = builders.placed(robot, "gripper_rotate", "revolute", "base", "gripper_palm")
    for side, y in (("left", 0.03), ("right", -0.03)):
        builders.placed(
            robot, f"gripper_{side}", "prismatic", palm, f"jaw_{side}", xyz=f"0 {y} 0.05",
            axis="0 1 0",
        )  # fmt: skip
    assert roles_of(robot)["gripper_rotate"].role == "gripper"
    result = identify_urdf(robot.text())
    assert result.structure == "Gripper"
    assert {c.motion_control for c in result.motion_controls} == {"Joint"}


def named_gripper_arms(wrist_joints: int) -> RobotText:
    """A wheeled base carrying, on each side, a chain of ``wrist_joints`` hinges named for the
    gripper they carry, ending in two jaws side by side (a competition robot's small arms, its
    files calling each arm a gripper)."""
    robot = RobotText("picker")
    builders.wheeled_base(robot)
    for side, y in (("left", 0.2), ("right", -0.2)):
        link = robot.root
        for index in range(wrist_joints):
            link = builders.placed(
                robot, f"{side}_gripper_df{index}", "revolute", link, f"{side}_gripper_l{index}",
                xyz=f"0 {y if index == 0 else 0} 0.1", axis="0 1 0" if index else "0 0 1",
            )  # fmt: skip
        for jaw, offset in (("a", 0.03), ("b", -0.03)):
            builders.placed(
                robot, f"{side}_{jaw}_gripper_hand", "prismatic", link, f"{side}_jaw_{jaw}",
                xyz=f"0 {offset} 0.05", axis="0 1 0",
            )  # fmt: skip
    return robot


def test_a_gripper_named_chain_as_long_as_an_arm_is_an_arm_ending_in_a_gripper() -> None:
    # Three hinges from the base to the jaws: an arm's worth, each side (the first two beside
    # each other on the base). Two hinges are a gripper's own wrist: it stays the gripper's.
    roles = roles_of(named_gripper_arms(3))
    assert "left_gripper_df0" not in roles
    assert "right_gripper_df0" not in roles
    result = identify_urdf(named_gripper_arms(3).text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints), limb.gripper) for limb in result.body.limbs] == [
        ("arm", 3, True),
        ("arm", 3, True),
    ]
    short = roles_of(named_gripper_arms(2))
    assert short["left_gripper_df0"].role == "gripper"
    assert identify_urdf(named_gripper_arms(2).text()).structure == "UGV"


def test_a_gripper_alone_with_a_drive_train_as_long_as_an_arm_stays_a_gripper() -> None:
    # A motor, a crank and a slider named for the gripper, then two jaws: nothing else moves
    # on the body, so the chain is the gripper's own drive, no arm.
    robot = RobotText("gripper", root="base")
    link = "base"
    for part in ("motor", "crank", "slider"):
        link = builders.placed(robot, f"gripper_{part}", "revolute", link, f"{part}_link")
    for side, y in (("left", 0.03), ("right", -0.03)):
        builders.placed(
            robot, f"gripper_{side}", "prismatic", link, f"jaw_{side}", xyz=f"0 {y} 0.05",
            axis="0 1 0",
        )  # fmt: skip
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not any(limb.kind == "arm" for limb in result.body.limbs)


def spoked_rover(*, ahead: float = 0.0) -> RobotText:
    """Four unnamed wheels, each carrying five unnamed slides spread round its axle (a
    transformable wheel's spokes), starting ``ahead`` along the axle from the wheel's centre."""
    robot = RobotText("spokes")
    limit = '<limit lower="0" upper="0.05" effort="1" velocity="1"/>'
    for index, (x, y) in enumerate(((0.15, 0.2), (0.15, -0.2), (-0.15, 0.2), (-0.15, -0.2))):
        place = f'<origin xyz="{x} {y} 0"/><axis xyz="0 1 0"/>'
        hub = robot.joint(f"j{index}", "continuous", "base_link", f"hub{index}", place)
        for spoke in range(5):
            turn = 2 * math.pi * spoke / 5
            body = f'<origin xyz="0 {ahead} 0" rpy="0 {turn:.4f} 0"/><axis xyz="1 0 0"/>{limit}'
            robot.joint(f"s{index}_{spoke}", "prismatic", hub, f"spoke{index}_{spoke}", body)
    return robot


def test_unnamed_wheels_extending_spokes_spread_round_their_axles_are_wheels() -> None:
    result = identify_urdf(spoked_rover().text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.wheels == ("j0", "j1", "j2", "j3")
    roles = {role.joint: role.role for role in result.body.roles}
    assert {roles[f"s{i}_{k}"] for i in range(4) for k in range(5)} == {"passive"}
    # Slides starting ahead of the part that turns them (a chuck's jaws on its flange) are no
    # spokes: those spinners are no wheels.
    chucks = identify_urdf(spoked_rover(ahead=0.05).text())
    assert chucks.body is not None
    assert chucks.body.wheels == ()


def _corner_hubs(word: str, centre: str = "0 0 0") -> str:
    """A base with an endless joint about a level axle at each corner, each named for its
    corner and ``word`` (``Front_left_<word>_continuous_joint`` on ``Front_left_<word>_link``),
    each part's mass centred at ``centre`` in its frame (on its axle unless told)."""
    robot = RobotText("omni")
    for corner, (x, y) in {
        "Front_left": (1, 1),
        "Front_right": (1, -1),
        "Rear_left": (-1, 1),
        "Rear_right": (-1, -1),
    }.items():
        origin = f'<origin xyz="{0.2 * x} {0.15 * y} -0.04"/><axis xyz="0 1 0"/>'
        robot.joint(
            f"{corner}_{word}_continuous_joint",
            "continuous",
            "base_link",
            f"{corner}_{word}_link",
            origin,
        )
    text = robot.text()
    for corner in ("Front_left", "Front_right", "Rear_left", "Rear_right"):
        text = builders.weighted(text, f"{corner}_{word}_link", centre, "")
    return text


def test_corner_named_endless_joints_with_words_of_no_part_are_wheels() -> None:
    # A mecanum wheel's hub (``plate``) named for its corner: the corner says where, not what.
    assert identify_urdf(_corner_hubs("plate")).structure == "UGV"
    # A corner with a leg's word (``hip``) names a part: no wheel by place.
    assert identify_urdf(_corner_hubs("hip")).structure != "UGV"


def _wheels_about(*turns: tuple[str, str]) -> str:
    """A box carrying one endless joint named for a wheel per ``turns`` (its place and its
    axis), no drive plugin."""
    robot = RobotText("craft")
    for i, (xyz, axis) in enumerate(turns):
        robot.joint(
            f"wheel_{i}_joint",
            "continuous",
            "base_link",
            f"wheel_{i}",
            f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>',
        )
    return robot.text()


# An omni base's four wheels on level axles pointing two ways (place, axis).
OMNI_WHEELS = (
    ("0 -0.2 -0.05", "0 1 0"),
    ("0 0.2 -0.05", "0 1 0"),
    ("0.2 0 -0.05", "1 0 0"),
    ("-0.2 0 -0.05", "1 0 0"),
)


def test_wheels_turning_about_three_square_axes_are_a_spacecrafts_reaction_wheels() -> None:
    # A CubeSat's attitude testbed: a pair of wheels about each of its axes turns it in place.
    cubesat = _wheels_about(
        ("0 -0.05 0", "0 1 0"),
        ("0 0.05 0", "0 1 0"),
        ("0.05 0 0", "1 0 0"),
        ("-0.05 0 0", "1 0 0"),
        ("0 0 0.15", "0 0 1"),
        ("0 0 -0.15", "0 0 1"),
    )
    assert identify_urdf(cubesat).structure == "Other"
    # The same wheels on level axles alone, two ways: an omni base rolls on them.
    omni = _wheels_about(*OMNI_WHEELS)
    assert identify_urdf(omni).structure == "UGV"


def test_a_wheel_that_is_the_robots_only_moving_joint_moves_no_vehicle() -> None:
    # A wheel on a test stand: one wheel alone can neither steer nor stand.
    stand = _wheels_about(("0 0 0.3", "0 1 0"))
    assert identify_urdf(stand).structure == "Other"
    # The same wheel beside a second one rolls a base.
    pair = _wheels_about(("0 0.2 -0.05", "0 1 0"), ("0 -0.2 -0.05", "0 1 0"))
    assert identify_urdf(pair).structure == "UGV"


def test_an_omni_base_with_an_upright_wheel_beside_it_is_no_spacecraft() -> None:
    # Four level wheels pointing two ways and one upright (a turntable named a wheel): not as
    # many about each axis, so no reaction wheels.
    base = _wheels_about(*OMNI_WHEELS, ("0 0 0.2", "0 0 1"))
    assert identify_urdf(base).structure == "UGV"


def test_corner_named_leaves_that_hang_their_mass_out_are_no_wheels() -> None:
    # A flipper at each corner, its mass 0.15 m out along it: no hub, so no wheel by place.
    assert identify_urdf(_corner_hubs("flipper", centre="0.15 0 0")).structure != "UGV"
    # The same leaves carrying their mass on their axles are hubs: wheels.
    assert identify_urdf(_corner_hubs("flipper")).structure == "UGV"
