"""Where the body is: a floating or planar joint, root joints that only place the body (x, y
and a turn, or all six motions), an SRDF's virtual joint; the root joints are then no limb."""

from __future__ import annotations

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.placement import Placement, placement
from solver.identify.readers.urdf import parse_urdf
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText


def tree_of(robot: RobotText) -> JointTree:
    return JointTree(parse_urdf(robot.text(), strict=False), load_profile())


def on_rails(axes: list[tuple[str, str, str]]) -> RobotText:
    """Joints at the root, one below the other: (name, type, axis) each, then a 3-joint arm."""
    robot = RobotText("on rails", root="odom")
    link = "odom"
    for name, kind, axis in axes:
        link = robot.joint(name, kind, link, f"{name}_link", f'<axis xyz="{axis}"/>')
    builders.arm(robot, link, joints=3, gripper=False)
    return robot


def test_a_planar_base_joint_is_a_mobile_base() -> None:
    robot = RobotText("planar", root="odom")
    base = robot.joint("base_planar", "planar", "odom", "base_link")
    builders.arm(robot, base)
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_root_x_y_theta_joints_are_a_planar_mobile_base_with_doubt() -> None:
    robot = RobotText("sim_base", root="odom")
    robot.joint("x", "prismatic", "odom", "x_link", '<axis xyz="1 0 0"/>')
    robot.joint("y", "prismatic", "x_link", "y_link", '<axis xyz="0 1 0"/>')
    robot.joint("theta", "continuous", "y_link", "base_link", '<axis xyz="0 0 1"/>')
    builders.arm(robot, "base_link")
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert result.body.planar_base == ("root joints x, y, theta (x, y and a turn about z)",)
    assert result.confidence == pytest.approx(0.9 * 0.8, abs=0.01)


def test_a_six_joint_virtual_floating_root_is_not_an_arm() -> None:
    robot = RobotText("floating_hand", root="world")
    link = "world"
    for i, (kind, axis) in enumerate(
        [
            ("prismatic", "1 0 0"),
            ("prismatic", "0 1 0"),
            ("prismatic", "0 0 1"),
            ("revolute", "1 0 0"),
            ("revolute", "0 1 0"),
            ("revolute", "0 0 1"),
        ]
    ):
        link = robot.joint(
            f"root_{i}",
            kind,
            link,
            f"root_{i}_link",
            f'<axis xyz="{axis}"/><limit lower="-20" upper="20"/>',
        )
    for finger in ("index", "middle", "ring", "thumb"):
        robot.chain(link, [f"{finger}_1", f"{finger}_2"])
    result = identify_urdf(robot.text())
    assert result.structure == "Hand"
    assert result.body is not None
    assert result.body.floating_base


def test_root_joints_along_x_and_y_and_about_z_place_a_planar_base() -> None:
    robot = on_rails(
        [("x", "prismatic", "1 0 0"), ("y", "prismatic", "0 1 0"), ("t", "continuous", "0 0 1")]
    )
    assert placement(tree_of(robot)) == Placement(
        planar=("root joints x, y, t (x, y and a turn about z)",), placing=("x", "y", "t")
    )


def xy_stage(x_travel: float, y_travel: float | None = None, turn: str = "") -> RobotText:
    """Slides along x and y from the world, travelling ``x_travel`` and ``y_travel`` metres
    (the same by default), turning a round tool about z at the end (a whiteboard gantry's
    duster; ``turn``: the turn's limit, none for a continuous joint); nothing below it."""
    robot = RobotText("stage", root="world")
    for axis, parent, travel in (("x", "world", x_travel), ("y", "x_link", y_travel or x_travel)):
        limit = f'<limit lower="0" upper="{travel}" effort="100" velocity="1"/>'
        xyz = "1 0 0" if axis == "x" else "0 1 0"
        robot.joint(
            f"{axis}_joint", "prismatic", parent, f"{axis}_link", f'<axis xyz="{xyz}"/>{limit}'
        )
    kind = "revolute" if turn else "continuous"
    robot.joint("tool_joint", kind, "y_link", "tool_link", f'<axis xyz="0 0 1"/>{turn}')
    return robot


def test_slides_that_travel_as_a_machines_axes_place_no_body() -> None:
    # A gantry's axes travel a metre: they move its tool, an arm of three joints.
    gantry = xy_stage(0.9)
    assert placement(tree_of(gantry)) == Placement(machine=("x_joint", "y_joint"))
    result = identify_urdf(gantry.text())
    assert result.structure == "Manipulator"
    assert result.evidence[0] == (
        "root slides x_joint, y_joint travel as a machine's axes do (less than 2 m each): "
        "no base placed in the world"
    )
    assert placement(tree_of(xy_stage(1.9))).machine == ("x_joint", "y_joint")
    # The slides are told by their type wherever the turn is among the three.
    turned = RobotText("turned_stage", root="world")
    limit = '<limit lower="0" upper="0.9" effort="100" velocity="1"/>'
    link = turned.joint("turn", "continuous", "world", "turn_link", '<axis xyz="0 0 1"/>')
    link = turned.joint("x_joint", "prismatic", link, "x_link", f'<axis xyz="1 0 0"/>{limit}')
    turned.joint("y_joint", "prismatic", link, "y_link", f'<axis xyz="0 1 0"/>{limit}')
    assert placement(tree_of(turned)).machine == ("x_joint", "y_joint")


def test_a_cartesian_gantrys_three_slides_and_a_turn_are_an_arm() -> None:
    # x, y and z slides of under a metre and a tool turning about z: no hovering body.
    robot = RobotText("cartesian", root="world")
    link = "world"
    for name, axis in (("x", "1 0 0"), ("y", "0 1 0"), ("z", "0 0 1")):
        limit = '<limit lower="0.8" upper="0" effort="1" velocity="1"/>'  # written in reverse
        link = robot.joint(name, "prismatic", link, f"{name}_link", f'<axis xyz="{axis}"/>{limit}')
    turn = '<axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>'
    robot.joint("spindle", "revolute", link, "tool", turn)
    assert placement(tree_of(robot)).machine == ("x", "y", "z")
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_short_slides_of_a_body_that_travels_otherwise_still_place_it() -> None:
    # A simulated base in a small world: a drive, flight or water plugin, or rotors, say the
    # body travels, and the slides place it however short.
    plugins = (
        builders.model_plugin("drive", "libgazebo_ros_planar_move.so"),
        builders.model_plugin("flight", "libhector_quadrotor_propulsion.so"),
        builders.model_plugin("water", "libuuv_underwater_object_ros_plugin.so"),
    )
    for plugin in plugins:
        stage = xy_stage(0.9)
        stage.add(plugin)
        assert placement(tree_of(stage)).placing == ("x_joint", "y_joint", "tool_joint")
    rotor = xy_stage(0.9)
    rotor.chain("tool_link", ["rotor_0_joint"], "continuous")
    assert placement(tree_of(rotor)).machine == ()


def test_a_planar_base_placed_over_a_simulators_world_stays_one() -> None:
    placed = ("x_joint", "y_joint", "tool_joint")
    # Slides of tens of metres; one slide of a machine's travel beside one of a world's; a
    # turn with limits beside long slides.
    for stage in (
        xy_stage(20.0),
        xy_stage(2.1),
        xy_stage(0.9, 20.0),
        xy_stage(20.0, turn='<limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>'),
    ):
        assert placement(tree_of(stage)).placing == placed
    # Limits written in reverse travel as far.
    reversed_limits = (
        xy_stage(20.0).text().replace('lower="0" upper="20.0"', 'lower="20.0" upper="0"')
    )
    tree = JointTree(parse_urdf(reversed_limits, strict=False), load_profile())
    assert placement(tree).placing == placed


def test_a_hovering_body_placed_with_a_short_lift_still_floats() -> None:
    # x and y over a world, z a few metres up, a turn about z: a drone's four freedoms.
    robot = RobotText("hover", root="world")
    link = "world"
    for name, kind, axis, limit in (
        ("x", "prismatic", "1 0 0", (-50, 50)),
        ("y", "prismatic", "0 1 0", (-50, 50)),
        ("z", "prismatic", "0 0 1", (0, 3)),
        ("yaw", "continuous", "0 0 1", None),
    ):
        bounds = "" if limit is None else f'<limit lower="{limit[0]}" upper="{limit[1]}"/>'
        link = robot.joint(name, kind, link, f"{name}_link", f'<axis xyz="{axis}"/>{bounds}')
    robot.fixed(link, "imu_link")
    robot.fixed(link, "camera_link")
    assert placement(tree_of(robot)).floating == (
        "root joints x, y, z, yaw (x, y, z and a turn about z)",
    )


def test_root_joints_that_lift_and_tilt_place_nothing() -> None:
    robot = on_rails(
        [("z", "prismatic", "0 0 1"), ("y", "prismatic", "0 1 0"), ("t", "revolute", "1 0 0")]
    )
    assert placement(tree_of(robot)) == Placement()


def test_a_floating_joint_that_carries_the_body_is_a_floating_base() -> None:
    robot = RobotText("both", root="world")
    base = robot.joint("world_float", "floating", "world", "base_link")
    builders.arm(robot, base, joints=3, gripper=False)
    assert placement(tree_of(robot)) == Placement(floating=("world_float",))


def test_a_part_sliding_on_a_planar_joint_beside_an_arm_places_no_body() -> None:
    # A contest field's box slides on a planar joint beside a gantry arm fixed to the world:
    # it carries a part of its own, but none of the arm's joints.
    robot = RobotText("contest_cell", root="world")
    robot.joint("world_fixed", "fixed", "world", "base_link")
    box = robot.joint("box_slide", "planar", "base_link", "box")
    robot.joint("box_lid", "fixed", box, "box_lid")
    builders.arm(robot, "base_link", joints=3, gripper=True)
    assert placement(tree_of(robot)) == Placement()
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_a_planar_joint_carrying_the_arm_beside_a_fixed_part_is_still_a_base() -> None:
    robot = RobotText("planar_beside", root="world")
    base = robot.joint("world_planar", "planar", "world", "base_link")
    robot.joint("stand", "fixed", "world", "stand_link")
    builders.arm(robot, base, joints=3, gripper=False)
    assert placement(tree_of(robot)) == Placement(planar=("world_planar",))


def test_two_robots_placed_side_by_side_each_keep_their_base() -> None:
    # Another robot's planar joint is no joint of this one's body: each carries its own arm.
    robot = RobotText("two_mobile_arms", root="odom")
    for name in ("a", "b"):
        base = robot.joint(f"{name}_planar", "planar", "odom", f"{name}_base")
        builders.arm(robot, base, joints=3, gripper=False, prefix=f"{name}_")
    assert placement(tree_of(robot)) == Placement(planar=("a_planar", "b_planar"))


def test_an_srdf_virtual_joint_places_nothing() -> None:
    # MoveIt's setup assistant writes a planar virtual joint for an arm bolted to a table.
    robot = builders.manipulator()
    urdf = parse_urdf(robot.text(), strict=False)
    srdf = (
        '<robot name="arm6"><virtual_joint name="odom_joint" type="planar" '
        'parent_frame="odom" child_link="base_link"/></robot>'
    )
    result = identify_urdf(robot.text(), srdf_text=srdf)
    assert placement(JointTree(urdf, load_profile())) == Placement()
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert not result.body.mobile_base


def test_propellers_a_simulator_poses_on_floating_joints_are_no_floating_base() -> None:
    robot = RobotText("posed_quad")
    for i in range(4):
        robot.joint(f"propeller_{i}_joint", "floating", "base_link", f"propeller_{i}")
    result = identify_urdf(robot.text())
    assert placement(tree_of(robot)) == Placement()
    assert (result.structure, result.kinematic_type) == ("UAV", "UAV")
    assert result.body is not None
    assert len(result.body.rotors) == 4


def test_a_single_posed_propeller_still_flies() -> None:
    robot = RobotText("posed_plane")
    robot.joint("prop_joint", "floating", "base_link", "prop")
    assert identify_urdf(robot.text()).structure == "UAV"


def test_root_joints_along_x_y_z_and_about_z_place_a_hovering_body() -> None:
    # A simulator's drone: a box slid along x, y and z and turned about z, rotors fixed to it.
    drone = RobotText("mydrone", root="world")
    link = "world"
    for name, kind, axis in (
        ("flightx", "prismatic", "1 0 0"),
        ("flighty", "prismatic", "0 1 0"),
        ("flightz", "prismatic", "0 0 1"),
        ("yaw", "continuous", "0 0 1"),
    ):
        link = drone.joint(
            name, kind, link, f"{name}_link", f'<axis xyz="{axis}"/><limit lower="-20" upper="20"/>'
        )
    found = placement(tree_of(drone))
    assert found.placing == ("flightx", "flighty", "flightz", "yaw")
    assert found.floating == (
        "root joints flightx, flighty, flightz, yaw (x, y, z and a turn about z)",
    )
    result = identify_urdf(drone.text())
    assert result.structure == "UAV"
    assert result.body is not None
    assert not result.body.limbs  # the chain places the body: no arm
