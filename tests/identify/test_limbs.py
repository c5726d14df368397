"""Limbs: chains of the actuated joints no single-joint role takes, read as legs, arms, heads,
mounts or other by their names, their length and what they carry; trunk where they branch."""

from __future__ import annotations

import math
import re
from typing import Any

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.body import detect_body
from solver.identify.limbs import Limb, find_limbs, parallel_robot, sort_limbs
from solver.identify.readers.urdf import parse_urdf
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText, placed


def tree_of(robot: RobotText) -> JointTree:
    return JointTree(parse_urdf(robot.text(), strict=False), load_profile())


def test_a_chain_carrying_wheels_is_a_mount_not_a_leg() -> None:
    robot = RobotText("wheel_legged")
    robot.chain("base_link", ["hip_pitch", "knee_pitch"])
    robot.joint("wheel_joint", "continuous", "knee_pitch_link", "wheel")
    robot.chain("base_link", ["l_shoulder", "l_elbow", "l_wrist"])
    robot.chain("base_link", ["r_shoulder", "r_elbow", "r_wrist"])
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert [limb.kind for limb in body.limbs] == ["arm", "arm", "mount"]
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_legs_that_end_in_a_gripper_are_legs() -> None:
    robot = builders.quadruped()
    robot.chain("FL_foot", ["FL_gripper_finger"], "prismatic")
    result = identify_urdf(robot.text())
    assert result.structure == "Quadruped"
    assert result.body is not None
    assert result.body.count("leg") == 4


def test_legs_named_by_their_corner_are_legs() -> None:
    robot = RobotText("bracket_dog")
    for corner in ("left_front", "right_front", "left_back", "right_back"):
        robot.chain("base_link", [f"motor_{corner}_1", f"motor_{corner}_2", f"motor_{corner}_3"])
    assert identify_urdf(robot.text()).structure == "Quadruped"


def modular_walker(tip: str) -> RobotText:
    """Six chains of actuator modules named as an arm's (base, shoulder, elbow), each ending
    in a link ``leg<i>__<tip>`` fixed below its last module."""
    robot = RobotText("modules")
    for i in range(1, 7):
        last = robot.chain("base_link", [f"base{i}", f"shoulder{i}", f"elbow{i}"])
        robot.fixed(last, f"leg{i}__{tip}")
    return robot


def test_chains_of_arm_named_modules_that_end_in_a_foot_are_legs() -> None:
    # A modular hexapod whose legs are built of arm modules: an arm never ends in a foot.
    assert identify_urdf(modular_walker("FOOT").text()).structure == "Hexapod"
    # The same chains ending in anything else stay six arms on a fixed body.
    assert identify_urdf(modular_walker("TOOL").text()).structure == "Torso"


def quadruped_with_a_chain_ending_in(tip: str) -> RobotText:
    """A four-legged body carrying an unnamed chain of three hinges on its back, a fixed frame
    named ``tip`` at its end."""
    robot = builders.quadruped()
    last = robot.chain(robot.root, ["joint1", "joint2", "joint3"])
    robot.fixed(last, tip)
    return robot


def test_an_unnamed_chain_on_a_walker_that_ends_in_a_tail_is_no_arm() -> None:
    # A walker's tail balances it, as an arm would move, and carries nothing.
    assert identify_urdf(quadruped_with_a_chain_ending_in("tail_end").text()).structure == (
        "Quadruped"
    )
    # The same chain ending in anything else is an arm on a walker.
    assert identify_urdf(quadruped_with_a_chain_ending_in("tool0").text()).structure == (
        "Legged Mobile Manipulator"
    )


def hand_on_a_wrist_with_rods(reach: float) -> RobotText:
    """A five-fingered hand on a two-hinge wrist fixed to a forearm, the wrist tilted by two
    rods: each a slide on the forearm, then three free hinges in a row (written blank, 0..0
    with no effort: an export's, unlocked) ending ``reach`` metres above the forearm, where
    the wrist's pins stand 0.21 m up."""
    robot = RobotText("dexhand", root="forearm")
    placed(robot, "wrist_1", "revolute", "forearm", "wrist_1_link", xyz="0 0 0.2", axis="1 0 0")
    placed(robot, "wrist_2", "revolute", "wrist_1_link", "palm", axis="0 1 0")
    for side, y in (("left", 0.02), ("right", -0.02)):
        robot.joint(f"{side}_pin", "fixed", "palm", f"{side}_pin", f'<origin xyz="0 {y} 0.01"/>')
        placed(robot, f"{side}_rod", "prismatic", "forearm", f"{side}_rod", xyz=f"0 {y} 0.1")
        blank = '<limit lower="0" upper="0" effort="0" velocity="0"/>'
        link = f"{side}_rod"
        for i, rise in enumerate((0.0, 0.05, reach - 0.15)):
            child = f"{side}_ball_{i}"
            robot.joint(
                f"{side}_ball_{i}",
                "revolute",
                link,
                child,
                f'<origin xyz="0 0 {rise}"/><axis xyz="1 0 0"/>{blank}',
            )
            link = child
    for finger in ("index", "middle", "ring", "little", "thumb"):
        robot.chain("palm", [f"{finger}_finger_{i}" for i in range(3)])
    return robot


def test_rods_whose_free_ends_meet_a_wrists_pins_drive_the_wrist_of_a_hand() -> None:
    # A dexterous hand's wrist tilted by two rods on slides: the loops a URDF cannot close.
    balls = [f"{side}_ball_{i}" for side in ("left", "right") for i in range(3)]
    closed = builders.solid(hand_on_a_wrist_with_rods(0.21).text(), *balls)
    assert identify_urdf(closed).structure == "Hand"
    # Rods ending 5 cm short of the pins close no loop: two more chains beside the wrist.
    short = builders.solid(hand_on_a_wrist_with_rods(0.16).text(), *balls)
    assert identify_urdf(short).structure != "Hand"


def test_six_legs_on_wheeled_feet_are_a_hexapod_with_doubt_not_a_quadruped() -> None:
    # Each of six legs ends in a driven wheel: the body rolls and steps, its legs are six.
    robot = RobotText("leg_wheel")
    for i in range(1, 7):
        foot = robot.chain("base_link", [f"leg{i}_hip", f"leg{i}_thigh", f"leg{i}_knee"])
        robot.joint(f"leg{i}_wheel_joint", "continuous", foot, f"leg{i}_wheel")
    result = identify_urdf(robot.text())
    assert result.structure == "Hexapod"
    assert result.confidence < identify_urdf(modular_walker("FOOT").text()).confidence


def test_unnamed_legs_on_the_pelvis_below_named_arms_make_a_humanoid() -> None:
    robot = RobotText("abbreviated", root="pelvis")
    for side in ("L", "R"):
        robot.chain("pelvis", [f"{side}{j}" for j in ("HY", "HR", "HP", "KP", "AP", "AR")])
    waist = robot.chain("pelvis", ["TSY"])
    builders.arm(robot, waist, "l_", 6)
    builders.arm(robot, waist, "r_", 6)
    robot.chain(waist, ["neck_yaw", "head_pitch"])
    result = identify_urdf(robot.text())
    assert result.structure == "Humanoid"
    assert result.body is not None
    assert result.body.count("leg") == 2


def test_two_unnamed_arms_on_the_root_stay_arms() -> None:
    robot = RobotText("dual_unnamed")
    for side in ("L", "R"):
        robot.chain("base_link", [f"{side}{i}" for i in range(6)])
    assert identify_urdf(robot.text()).structure == "Torso"


def test_joints_where_chains_branch_are_trunk_and_the_chains_below_are_limbs() -> None:
    robot = RobotText("waist")
    waist = robot.chain("base_link", ["waist_yaw"])
    robot.chain(waist, ["l1", "l2", "l3"])
    robot.chain(waist, ["r1", "r2", "r3"])
    limbs, trunk, hosts = find_limbs(tree_of(robot), set(), set(), {}, flying=False)
    assert trunk == ["waist_yaw"]
    assert [(limb.kind, limb.joints, limb.base) for limb in limbs] == [
        ("arm", ("l1", "l2", "l3"), "waist_yaw_link"),
        ("arm", ("r1", "r2", "r3"), "waist_yaw_link"),
    ]
    assert hosts == set()


def test_an_unnamed_two_joint_chain_is_an_arm_only_below_a_flying_body() -> None:
    robot = RobotText("pan")
    robot.chain("base_link", ["j1", "j2"])
    tree = tree_of(robot)
    grounded, _, _ = find_limbs(tree, set(), set(), {}, flying=False)
    flying, _, _ = find_limbs(tree, set(), set(), {}, flying=True)
    assert [(limb.kind, limb.why) for limb in grounded] == [("other", "no name or shape of a limb")]
    assert [(limb.kind, limb.why) for limb in flying] == [
        ("arm", "a chain of 2 joints hanging from a flying body")
    ]


def test_a_ball_joint_counts_as_three_joints_in_a_limb() -> None:
    robot = RobotText("ball")
    link = robot.joint("j1", "spherical", "base_link", "upper")
    robot.chain(link, ["j2"])
    limbs, _, _ = find_limbs(tree_of(robot), set(), set(), {}, flying=False)
    assert [(limb.kind, limb.why) for limb in limbs] == [("arm", "an unnamed chain of 4 joints")]


@pytest.mark.parametrize(("corners", "kind"), [(4, "leg"), (2, "mount")])
def test_legs_that_each_end_in_a_wheel_walk_when_three_or_more_else_they_are_mounts(
    corners: int, kind: str
) -> None:
    robot = RobotText("wheel legs")
    for corner in ("front_left", "front_right", "rear_left", "rear_right")[:corners]:
        tip = robot.chain(robot.root, [f"{corner}_hip", f"{corner}_knee", f"{corner}_ankle"])
        robot.joint(f"{corner}_wheel_joint", "continuous", tip, f"{corner}_wheel")
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert [limb.kind for limb in body.limbs] == [kind] * corners


def test_limbs_sort_legs_arms_heads_then_the_rest_each_in_document_order() -> None:
    robot = RobotText("order")
    for name in ("h", "o", "a2", "l", "a1", "m"):
        robot.chain("base_link", [name])
    tree = tree_of(robot)
    limbs = [
        Limb(kind, (name,), "base_link", f"{name}_link")
        for kind, name in [
            ("head", "h"),
            ("other", "o"),
            ("arm", "a2"),
            ("leg", "l"),
            ("arm", "a1"),
            ("mount", "m"),
        ]
    ]
    assert [limb.joints[0] for limb in sort_limbs(tree, limbs)] == ["l", "a2", "a1", "h", "o", "m"]


def test_a_limb_describes_itself_with_its_names_escaped() -> None:
    limb = Limb("arm", ("a", "b", "c"), "base_link", "tool0", gripper=True)
    assert limb.describe() == "arm: 3-joint chain base_link -> tool0 (a .. c), ends in a gripper"
    forged = Limb("head", ("pan\nstructure UAV",), "base_link", "cam")
    assert "\n" not in forged.describe()


def test_six_alike_unnamed_chains_ending_below_the_body_are_legs_of_a_hexapod() -> None:
    result = identify_urdf(builders.walker(6).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6
    assert result.structure == "Hexapod"
    assert "legs by place" in result.body.limbs[0].why


def test_four_alike_unnamed_chains_ending_below_the_body_are_a_quadrupeds_legs() -> None:
    assert identify_urdf(builders.walker(4).text()).structure == "Quadruped"


def test_eight_serial_legs_make_no_quadruped_and_eight_two_joint_chains_may() -> None:
    # An octopod's eight legs of three joints each are no four five-bar legs drawn open: no
    # structure of the profile names eight legs.
    assert identify_urdf(builders.walker(8).text()).structure == "Other"
    # Eight chains of two joints (motor and knee) are the halves of four five-bar legs whose
    # loops the file leaves open: a quadruped.
    halves = five_bar_legs(close="open")
    for corner, x, y in (("rear_left", -0.2, 0.1), ("rear_right", -0.2, -0.1)):
        for half, dy in (("a", -0.02), ("b", 0.02)):
            motor = builders.placed(
                halves, f"{corner}_{half}_motor", "revolute", halves.root,
                f"{corner}_{half}_motor_link", xyz=f"{x} {y + dy} 0", axis="0 1 0",
            )  # fmt: skip
            builders.placed(
                halves, f"{corner}_{half}_knee", "revolute", motor, f"{corner}_{half}_knee_link",
                xyz="0 0 -0.1", axis="0 1 0",
            )  # fmt: skip
    result = identify_urdf(halves.text())
    assert result.body is not None
    assert (result.structure, result.body.count("leg")) == ("Quadruped", 8)


@pytest.mark.parametrize("joints", [5, 6])
def test_six_alike_unnamed_chains_of_five_or_six_joints_below_the_body_are_a_hexapods_legs(
    joints: int,
) -> None:
    result = identify_urdf(builders.walker(6, joints=joints).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6
    assert result.structure == "Hexapod"


def test_four_alike_unnamed_chains_of_five_joints_on_one_body_are_no_legs_by_place() -> None:
    # Four long chains around one link may be a multi-arm cell's arms: only six or more
    # chains that long are a walker's legs by place.
    result = identify_urdf(builders.walker(4, joints=5).text())
    assert result.body is not None
    assert all("legs by place" not in limb.why for limb in result.body.limbs)


def test_seven_joint_chains_are_no_legs_by_place_however_many() -> None:
    result = identify_urdf(builders.walker(6, joints=7).text())
    assert result.body is not None
    assert all("legs by place" not in limb.why for limb in result.body.limbs)


def cornered_walker(hips: list[tuple[float, float]], *, tip_z: float) -> RobotText:
    """An unnamed four-legged CAD export: the body's origin at a corner of it (every hip on one
    side of it), a 3-joint chain at each of ``hips``, its tip ``tip_z`` from its last joint."""
    robot = RobotText("cad_export", root="l0")
    for i, (x, y) in enumerate(hips):
        first = builders.placed(robot, f"Rev{i}a", "revolute", "l0", f"l{i}a", xyz=f"{x} {y} 0")
        second = builders.placed(
            robot, f"Rev{i}b", "revolute", first, f"l{i}b", xyz="0.03 0 0", axis="0 1 0"
        )
        third = builders.placed(
            robot, f"Rev{i}c", "revolute", second, f"l{i}c", xyz="0.04 0 0", axis="0 1 0"
        )
        robot.joint(f"tip{i}", "fixed", third, f"tip{i}_link", f'<origin xyz="0.03 0 {tip_z}"/>')
    return robot


def test_legs_raised_at_rest_at_the_corners_of_a_body_whose_origin_is_a_corner_are_legs() -> None:
    # Hips at the corners around their own middle, the body's origin at one of them: the legs
    # are folded up in the zero pose, so only where they start says they are legs.
    robot = cornered_walker([(0.08, -0.03), (0.08, -0.11), (0.0, -0.03), (0.0, -0.11)], tip_z=0.06)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 4
    assert "corners" in result.body.limbs[0].why
    assert result.structure == "Quadruped"


def test_standing_legs_of_a_body_drawn_along_y_are_legs_though_its_hips_pair_across_x_too() -> None:
    # Four hips at the corners of a box 0.1 m wide and 0.27 m long along y: paired across x's
    # line too, but shorter that way than across; standing, they are read facing y.
    robot = cornered_walker([(0.07, 0.04), (-0.03, 0.04), (0.07, 0.31), (-0.03, 0.31)], tip_z=-0.15)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 4
    assert "ending below" in result.body.limbs[0].why
    assert result.structure == "Quadruped"


def test_four_chains_raised_at_rest_around_a_palm_whose_origin_lies_between_them_stay_fingers() -> (
    None
):
    # The origin inside the chains' box across y: no corner of them, and the chains are not
    # mirrored about it; a gripper's four fingers, not legs by their own middle.
    robot = cornered_walker([(0.08, 0.03), (0.08, -0.05), (0.0, 0.03), (0.0, -0.05)], tip_z=0.06)
    assert identify_urdf(robot.text()).structure == "Hand"


def test_chains_at_the_corners_of_a_wheeled_body_whose_origin_is_a_corner_are_no_legs() -> None:
    # A base on its own wheels with four flippers: not legs by the chains' own middle.
    robot = cornered_walker([(0.08, -0.03), (0.08, -0.11), (0.0, -0.03), (0.0, -0.11)], tip_z=0.06)
    for side, y in (("left", 0.0), ("right", -0.14)):
        builders.placed(
            robot, f"{side}_wheel_joint", "continuous", "l0", f"{side}_wheel", xyz=f"0.04 {y} 0",
            axis="0 1 0",
        )  # fmt: skip
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not [limb for limb in result.body.limbs if limb.kind == "leg"]


@pytest.mark.parametrize("tip_z", [0.06, -0.15])
def test_four_unnamed_fingers_in_a_row_on_a_palm_whose_origin_is_a_corner_stay_fingers(
    tip_z: float,
) -> None:
    # In a row along one edge of the palm, pointing up or hanging down: no corners either way.
    hips = [(0.0, -0.01), (0.0, -0.03), (0.0, -0.05), (0.0, -0.07)]
    assert identify_urdf(cornered_walker(hips, tip_z=tip_z).text()).structure == "Hand"


def test_fingers_on_a_palm_pointing_away_from_it_stay_fingers() -> None:
    # A hand's fingers are alike chains on one link too, but they do not end below it.
    assert identify_urdf(builders.hand().text()).structure == "Hand"


def test_a_chain_of_equal_modules_with_alternating_axes_is_a_snakes_spine() -> None:
    result = identify_urdf(builders.snake(8).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert result.structure == "Serpentine"
    assert result.kinematic_type is None  # the article has no snake


def test_a_snake_whose_file_roots_it_at_a_module_inside_is_one_spine_through_that_module() -> None:
    # A modular snake written from its second module: one joint out to its tail, nine along
    # the rest, the two chains meeting on the root's link. Read as one chain through it.
    robot = RobotText("module11", root="m0")
    placed(robot, "tail", "revolute", "m0", "t1", xyz="-0.1 0 0", axis="0 1 0")
    link = "m0"
    for i in range(1, 10):
        axis = "0 0 1" if i % 2 else "0 1 0"
        step = "0 0 0" if i == 1 else "0.1 0 0"  # the module's first joint is on its link
        link = placed(robot, f"j{i}", "revolute", link, f"m{i}", xyz=step, axis=axis)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("spine", 10)]
    assert result.structure == "Serpentine"
    # Two arms from one torso are no such chain: their modules differ, and they hold grippers.
    assert identify_urdf(builders.torso().text()).structure == "Torso"


def crawler(corners: tuple[str, ...]) -> str:
    """A body drawn y-up (as a physics engine's exporter leaves it): four two-joint chains
    hanging along -y from the corners of the x-z plane, every hinge about x, each chain's links
    named ``L1_<corner>``, ``L2_<corner>``."""
    robot = RobotText("crawly")
    places = ("0.09 0 0.07", "-0.09 0 0.07", "0.09 0 -0.07", "-0.09 0 -0.07")
    for i, (corner, xyz) in enumerate(zip(corners, places, strict=True), start=1):
        hip = placed(
            robot, f"th_{i}", "revolute", robot.root, f"L1_{corner}1", xyz=xyz, axis="1 0 0"
        )
        placed(robot, f"th_{i + 4}", "revolute", hip, f"L2_{corner}1", xyz="0 -0.1 0", axis="1 0 0")
    return robot.text()


def test_four_chains_named_for_a_bodys_four_corners_are_legs_whichever_way_it_stands() -> None:
    assert identify_urdf(crawler(("FL", "FR", "BL", "BR"))).structure == "Quadruped"
    assert identify_urdf(crawler(("LF", "RF", "LH", "RH"))).structure == "Quadruped"  # ANYmal's
    # One side's letters on every chain (a right hand's `rh_`), or no corner at all, name none.
    assert identify_urdf(crawler(("RH", "RH", "RH", "RH"))).structure != "Quadruped"
    assert identify_urdf(crawler(("A", "B", "C", "D"))).structure != "Quadruped"


def test_the_same_chain_on_a_rail_is_an_arm_not_a_snake() -> None:
    """Equal modules with alternating axes behind a slide (a linear rail carrying the chain):
    a snake's modules only turn, so the chain is an arm on a rail."""
    snake = builders.snake(6).text()
    rail = (
        '<link name="rail_base"/><joint name="rail" type="prismatic"><parent link="rail_base"/>'
        '<child link="m0"/><axis xyz="1 0 0"/><limit lower="0" upper="2" effort="1" '
        'velocity="1"/></joint></robot>'
    )
    result = identify_urdf(snake.replace("</robot>", rail))
    assert result.structure == "Manipulator"


def universal_chain(modules: int, *, length: str, along: str) -> RobotText:
    """Modules of two joints at one point (a turn about z, then about y, as a universal joint),
    ``length`` apart along ``along`` (x: a snake lying down; z: an arm standing up)."""
    robot = RobotText("universal", root="m0")
    link = "m0"
    step = {"x": f"{length} 0 0", "z": f"0 0 {length}"}[along]
    for i in range(1, modules + 1):
        z = builders.placed(robot, f"j{i}_z", "revolute", link, f"z{i}", xyz=step, axis="0 0 1")
        link = builders.placed(robot, f"j{i}_y", "revolute", z, f"m{i}", axis="0 1 0")
    return robot


def test_a_snake_whose_modules_turn_two_ways_at_one_point_is_a_spine() -> None:
    result = identify_urdf(universal_chain(4, length="0.16", along="x").text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert result.structure == "Serpentine"


def test_a_snake_whose_modules_pitch_joint_sits_above_its_yaw_joint_is_a_spine() -> None:
    """Stacked servos: each module's pitch joint 2 cm above its yaw joint, along the yaw axis;
    the chain still runs along x, module to module."""
    robot = RobotText("stacked", root="m0")
    link = "m0"
    for i in range(1, 7):
        yaw = builders.placed(
            robot, f"j{i}_yaw", "revolute", link, f"y{i}",
            xyz="0.16 0 -0.02" if i > 1 else "0.16 0 0", axis="0 0 1",
        )  # fmt: skip
        link = builders.placed(
            robot, f"j{i}_pitch", "revolute", yaw, f"m{i}", xyz="0 0 0.02", axis="0 1 0"
        )
    assert identify_urdf(robot.text()).structure == "Serpentine"


def test_an_arm_whose_joints_turn_about_its_own_links_is_no_spine() -> None:
    """The same modules stacked upwards: every other joint turns about the link above it (a
    roll joint, as a seven-axis arm has), which a snake's bending modules never do."""
    result = identify_urdf(universal_chain(4, length="0.4", along="z").text())
    assert result.structure == "Manipulator"


def wheeled_snake(modules: int = 4, *, names: str = "j") -> RobotText:
    """A snake of two-joint modules (a yaw joint, then 2.5 cm on a pitch joint, then 18 cm to
    the next module), each module carrying two leaf wheel joints, one on each side and one
    ahead of the other (revolute joints with limits, as a model of passive wheels may write
    them)."""
    robot = RobotText("wheeled_snake", root="m0")
    link = "m0"
    for i in range(1, modules + 1):
        yaw = builders.placed(
            robot, f"{names}{i}_yaw", "revolute", link, f"y{i}", xyz="0.18 0 0", axis="0 0 1"
        )
        link = builders.placed(
            robot, f"{names}{i}_pitch", "revolute", yaw, f"p{i}", xyz="0.025 0 0", axis="0 1 0"
        )
        for side, x, y in (("a", -0.03, 0.04), ("b", 0.03, -0.04)):
            builders.placed(
                robot, f"w{i}{side}", "revolute", link, f"w{i}{side}_link",
                xyz=f"{x} {y} -0.05", axis="0 1 0",
            )  # fmt: skip
    return robot


def test_a_snake_of_two_joint_modules_with_passive_side_wheels_is_still_a_spine() -> None:
    robot = wheeled_snake()
    for i in range(1, 5):  # every joint driven, the side wheels too
        for joint in (f"j{i}_yaw", f"j{i}_pitch", f"w{i}a", f"w{i}b"):
            robot.add(builders.transmission(joint))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert len(result.body.limbs[0].joints) == 8
    assert result.structure == "Serpentine"
    roles = {role.joint: role.role for role in result.roles}
    assert {roles[f"w{i}{side}"] for i in range(1, 5) for side in "ab"} == {"passive"}
    assert {c.motion_control: c.source for c in result.motion_controls} == {
        "Joint": "urdf: 8 limb joint(s) a controller drives"
    }


def yawing_snake_on_wheels(name: str, modules: int = 8, *, driven: bool = False) -> str:
    """``modules`` modules 0.1 m apart, each after the first on a hinge about the vertical, each
    gliding on one wheel named so (a continuous joint about its own axle): a planar snake on
    passive wheels, as Hirose's Active Cord Mechanism (``driven``: a transmission on each
    wheel)."""
    robot = RobotText(name, root="m1")
    link = "m1"
    for i in range(1, modules + 1):
        if i > 1:
            link = builders.placed(robot, f"h{i}", "revolute", link, f"m{i}", xyz="0.1 0 0")
        builders.placed(
            robot, f"wheel_{i}", "continuous", link, f"wheel_link_{i}", xyz="0 0 -0.03",
            axis="0 1 0",
        )  # fmt: skip
        if driven:
            robot.add(builders.transmission(f"wheel_{i}"))
    return robot.text()


def rover_named_a_snake_with_a_long_arm() -> str:
    """A base named ``snake_inspection_rover`` on four wheels, carrying an unnamed chain of six
    hinges 0.1 m apart: the wheels all on the base, none on the chain."""
    robot = RobotText("snake_inspection_rover")
    builders.wheeled_base(robot, 4)
    link = robot.root
    for i in range(6):
        axis = "0 0 1" if i % 2 == 0 else "0 1 0"
        link = builders.placed(robot, f"c{i}", "revolute", link, f"cl{i}", xyz="0.1 0 0", axis=axis)
    return robot.text()


def test_a_robot_named_a_snake_gliding_on_a_wheel_per_module_is_a_spine_not_a_base() -> None:
    result = identify_urdf(yawing_snake_on_wheels("snake_robot"))
    assert result.structure == "Serpentine"
    roles = {role.joint: role.role for role in result.roles}
    assert {roles[f"wheel_{i}"] for i in range(1, 9)} == {"passive"}
    # Not named a snake: the same wheels carry a base, its chain of hinges their mount.
    assert identify_urdf(yawing_snake_on_wheels("train")).structure == "UGV"
    # A snake's name, but too few modules for a snake's length: a base with its hinges.
    assert identify_urdf(yawing_snake_on_wheels("snake_robot", modules=4)).structure == "UGV"
    # Wheels a controller drives are a base's, not a gliding snake's.
    driven = yawing_snake_on_wheels("snake_robot", driven=True)
    assert identify_urdf(driven).structure == "UGV"


def test_a_base_named_a_snake_carrying_a_long_arm_keeps_its_wheels_and_its_arm() -> None:
    # Its wheels are all on the base, none on the chain: no snake's modules glide on them.
    assert identify_urdf(rover_named_a_snake_with_a_long_arm()).structure == "Mobile Manipulator"


@pytest.mark.parametrize("frame", ["tool0", "flange", "ee_link", "tcp"])
def test_a_chain_of_snake_modules_ending_in_an_arms_tool_frame_is_an_arm(frame: str) -> None:
    # Fresh set 1740's teaching arm: eight equal segments whose axes alternate, its tip a
    # flange and a tool0 that MoveIt plans to. A snake carries no tool.
    robot = builders.snake(8)
    robot.fixed("m8", frame)
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_a_snake_whose_tip_is_a_head_stays_a_spine() -> None:
    robot = builders.snake(8)
    robot.fixed("m8", "head")
    assert identify_urdf(robot.text()).structure == "Serpentine"


def test_a_chain_named_as_an_arm_with_leaves_on_it_is_no_spine() -> None:
    result = identify_urdf(wheeled_snake(names="arm").text())
    assert result.body is not None
    assert "spine" not in [limb.kind for limb in result.body.limbs]
    assert result.structure != "Serpentine"


def test_an_arm_of_unequal_links_is_no_spine() -> None:
    robot = builders.snake(7)
    text = robot.text().replace('<origin xyz="0.1 0 0"', '<origin xyz="0.3 0 0"', 2)
    assert identify_urdf(text).structure == "Manipulator"


def test_a_chain_of_modules_whose_axes_do_not_alternate_is_no_spine() -> None:
    text = builders.snake(7).text().replace('<axis xyz="0 1 0"/>', '<axis xyz="0 0 1"/>')
    assert identify_urdf(text).structure == "Manipulator"


def walker_with_opened_actuators(*, arm_on_the_body: bool = False) -> RobotText:
    """Four legs, each on a hip the body turns; each hip also carries its leg's linear
    actuator drawn open by a CAD export (a pivot, a second pivot, a slide; names that say
    nothing), as a large walker's hydraulic or electric cylinders are."""
    robot = RobotText("walker", root="center")
    for i in range(1, 5):
        hip = robot.chain("center", [f"l{i}_r2"])
        robot.chain(hip, [f"l{i}_femur", f"l{i}_tibia", f"l{i}_foot"])
        pivots = robot.chain(hip, [f"l{i}_r7", f"l{i}_r8"])
        robot.chain(pivots, [f"l{i}_c3"], "prismatic")
    if arm_on_the_body:
        builders.arm(robot, "center", joints=6)
    return robot


def test_chains_beside_each_leg_on_its_turning_hip_are_the_legs_drives_not_arms() -> None:
    result = identify_urdf(walker_with_opened_actuators().text())
    assert result.structure == "Quadruped"
    assert result.body is not None
    assert result.body.count("arm") == 0
    # An arm the body carries is still an arm, where the body is fixed and where a joint
    # moves it (a simulator's floating base: every leg starts there, no one leg's hip).
    armed = walker_with_opened_actuators(arm_on_the_body=True)
    assert identify_urdf(armed.text()).structure == "Legged Mobile Manipulator"
    armed.joints.append(
        '  <joint name="float" type="floating"><parent link="world"/><child link="center"/></joint>'
    )
    armed.links.append("world")
    assert identify_urdf(armed.text()).structure == "Legged Mobile Manipulator"
    # Beside a leg on its hip, a chain of turning joints only is no linear actuator: an arm.
    hinged = walker_with_opened_actuators().text().replace('type="prismatic"', 'type="revolute"')
    assert identify_urdf(hinged).structure == "Legged Mobile Manipulator"


def short_uneven_chain(name: str) -> str:
    """Two joints about one axis, links of unequal length named as an arm's parts (a CAD
    export's ``arm_1``, ``arm_2``): by its shape alone no snake's spine."""
    robot = RobotText(name, root="base_link")
    link = builders.placed(robot, "Rev1", "revolute", "base_link", "arm_1", axis="0 1 0")
    link = builders.placed(robot, "Rev2", "revolute", link, "arm_2", xyz="0.1 0 0", axis="0 1 0")
    builders.placed(robot, "Rev3", "revolute", link, "arm_3", xyz="0.3 0 0", axis="0 1 0")
    return robot.text()


@pytest.mark.parametrize(
    "name", ["snake", "robosnake", "edmo_snake", "snakebot", "sea_snake2", "Snake Robot"]
)
def test_a_robot_named_a_snake_crawls_on_its_one_chain_however_short_or_unevenly_drawn(
    name: str,
) -> None:
    result = identify_urdf(short_uneven_chain(name))
    assert result.structure == "Serpentine"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert "on a robot named a snake" in result.body.limbs[0].why


def test_without_a_snakes_name_the_same_chain_is_an_arm() -> None:
    assert identify_urdf(short_uneven_chain("modules")).structure == "Manipulator"


@pytest.mark.parametrize(
    "name",
    [
        "snake_arm_description",
        "snake2_arm",
        "snake_tool",
        "snake-like_manipulator",
        "serpent_7dof",
        "snake_continuum_robot",
        "snake_eyes",
    ],
)
def test_a_manipulator_named_for_a_snakes_shape_is_an_arm(name: str) -> None:
    assert identify_urdf(short_uneven_chain(name)).structure == "Manipulator"
    assert identify_urdf(builders.snake(3, name=name).text()).structure == "Manipulator"


def yawing_modules(name: str, plugin: str, spacings: tuple[float, ...] = (0.1,) * 9) -> str:
    """Modules ``spacings`` apart (by default nine, 0.1 m), each turning about the vertical
    (too few for a planar snake by shape alone), a plugin of file ``plugin`` in the
    description."""
    robot = RobotText(name, root="link_1")
    link = "link_1"
    for i, gap in enumerate(spacings, start=2):
        link = builders.placed(robot, f"j{i}", "revolute", link, f"link_{i}", xyz=f"{gap} 0 0")
    robot.add(builders.model_plugin("plugin", plugin))
    return robot.text()


def test_a_long_snake_named_so_that_a_plugin_slides_is_still_a_snake() -> None:
    # A simulator slides the body on velocity commands (a planar move, no wheel); the chain of
    # nine modules is the snake's own: a spine, Driving from the plugin.
    result = identify_urdf(yawing_modules("snakebot", "libgazebo_ros_planar_move.so"))
    assert result.structure == "Serpentine"
    assert "Driving" in {c.motion_control for c in result.motion_controls}
    # A wheel drive moves a base, whatever rides it; and a short chain a plugin slides is an
    # arm on a base (the test below).
    wheeled = yawing_modules("snakebot", "libgazebo_ros_diff_drive.so")
    assert identify_urdf(wheeled).structure == "Mobile Manipulator"
    # Links of unequal lengths are an arm's, not a snake's modules, whatever the robot's name.
    uneven = (0.1, 0.4, 0.1, 0.3, 0.1, 0.2)
    arm = yawing_modules("snakebot", "libgazebo_ros_planar_move.so", uneven)
    assert identify_urdf(arm).structure == "Mobile Manipulator"


def test_nine_unnamed_equal_modules_about_the_vertical_that_a_plugin_slides_are_a_snake() -> None:
    # Longer than any arm, every axis parallel: a planar snake, whatever its names say.
    result = identify_urdf(yawing_modules("robot", "libgazebo_ros_planar_move.so"))
    assert result.structure == "Serpentine"
    # Seven such modules are as long as an arm: an arm on a base the plugin slides.
    short = yawing_modules("robot", "libgazebo_ros_planar_move.so", (0.1,) * 6)
    assert identify_urdf(short).structure == "Mobile Manipulator"
    # A wheel drive moves a base, whatever chain rides it.
    wheeled = yawing_modules("robot", "libgazebo_ros_diff_drive.so")
    assert identify_urdf(wheeled).structure == "Mobile Manipulator"


def test_a_robot_named_a_snake_whose_joints_are_an_arms_or_a_plugin_drives_it_is_no_snake() -> None:
    # Shoulder, elbow and wrist joints name an arm, whatever the robot is called.
    robot = RobotText("snake_v2", root="base_link")
    builders.arm(robot, "base_link", joints=4, gripper=False)
    assert identify_urdf(robot.text()).structure == "Manipulator"
    # A drive plugin moves the body the short chain is on: a base that carries an arm.
    driven = short_uneven_chain("snake").replace(
        "</robot>", builders.model_plugin("drive", "libgazebo_ros_planar_move.so") + "</robot>"
    )
    assert identify_urdf(driven).structure == "Mobile Manipulator"


def test_a_snake_named_so_whose_chain_slides_or_ends_in_a_gripper_is_no_snake() -> None:
    sliding = short_uneven_chain("snake").replace(
        'name="Rev3" type="revolute"', 'name="Rev3" type="prismatic"'
    )
    assert identify_urdf(sliding).structure != "Serpentine"
    gripping = builders.snake(3, name="snake")
    builders.placed(gripping, "gripper_finger_joint", "prismatic", "m3", "gripper_finger")
    assert identify_urdf(gripping.text()).structure == "Manipulator"


def cart_pole(name: str) -> str:
    """A control course's cart-pole: a cart sliding on a rail bolted to the world, a pole
    hinged on it, both driven (a transmission on each), nothing else."""
    robot = RobotText(name, root="world")
    robot.fixed("world", "rail")
    cart = builders.placed(robot, "cart_joint", "prismatic", "rail", "cart", axis="1 0 0")
    pole = '<origin xyz="0 0 0.1"/><axis xyz="0 1 0"/>'
    robot.joint("pole_joint", "continuous", cart, "pole", pole)
    robot.add(builders.transmission("cart_joint", "EffortJointInterface"))
    robot.add(builders.transmission("pole_joint", "EffortJointInterface"))
    return robot.text()


@pytest.mark.parametrize(
    "name",
    ["cart_pole", "cartpole", "furuta_pendulum", "acrobot", "Pendubot", "double_pendulum_2dof"],
)
def test_a_robot_named_a_pendulum_rig_swings_its_one_chain_it_is_no_arm(name: str) -> None:
    result = identify_urdf(cart_pole(name))
    assert result.structure == "Other"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["other"]
    assert "a pendulum rig's links" in result.body.limbs[0].why
    # Its actuators are commanded one by one: the plant's joints take the controller's output.
    assert [c.motion_control for c in result.motion_controls] == ["Joint"]


def test_without_a_pendulums_name_the_same_chain_is_an_arm() -> None:
    assert identify_urdf(cart_pole("slider_arm")).structure == "Manipulator"


def test_a_pendulum_named_manipulator_or_one_ending_in_a_gripper_is_an_arm() -> None:
    assert identify_urdf(cart_pole("pendulum_arm")).structure == "Manipulator"
    gripping = cart_pole("cart_pole").replace(
        "</robot>",
        '<link name="gripper_finger"/><joint name="gripper_finger_joint" type="prismatic">'
        '<parent link="pole"/><child link="gripper_finger"/><axis xyz="0 0 1"/>'
        '<limit lower="0" upper="0.04" effort="1" velocity="1"/></joint></robot>',
    )
    assert identify_urdf(gripping).structure == "Manipulator"


def test_an_arm_balancing_a_pendulum_is_an_arm() -> None:
    # Six joints named as an arm's, and the pole's hinge at its tip: a UR5 balancing a pole.
    robot = RobotText("ur5_inverted_pendulum", root="base_link")
    tip = builders.arm(robot, "base_link", joints=6, gripper=False)
    robot.joint("pole_joint", "continuous", tip, "pole", '<axis xyz="0 1 0"/>')
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_a_robot_named_a_pendulum_that_balances_on_wheels_is_a_vehicle() -> None:
    robot = RobotText("inverted_pendulum_robot", root="base_link")
    builders.wheeled_base(robot)
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    assert identify_urdf(robot.text()).structure == "UGV"


@pytest.mark.parametrize("fixed_to_the_world", [False, True])
def test_a_short_chain_carrying_a_whole_hand_is_its_wrist_not_an_arm(
    fixed_to_the_world: bool,
) -> None:
    robot = builders.forearm_hand()
    text = robot.text()
    if fixed_to_the_world:  # the forearm bolted to a world link: the same hand
        text = text.replace(
            "</robot>",
            '<link name="world"/><joint name="world_fixed" type="fixed"><parent link="world"/>'
            '<child link="forearm"/></joint></robot>',
        )
    result = identify_urdf(text)
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["wrist"]
    assert result.structure == "Hand"


def scara(elbow: str = "0 -1 0.1") -> RobotText:
    """Two upright axes on a fixed base, the elbow at ``elbow`` from the shoulder, then a
    palm 0.8 m on with four sliding fingers 0.23 m below it (a conveyor-sorting SCARA)."""
    robot = RobotText("scara", root="base_link")
    builders.placed(robot, "rotation1", "revolute", "base_link", "arm1", xyz="0 0 0.4")
    builders.placed(robot, "rotation2", "revolute", "arm1", "arm2", xyz=elbow)
    builders.placed(robot, "palm_fixed", "fixed", "arm2", "palm", xyz="0 -0.8 0")
    for i, (x, y) in enumerate(((0, -0.04), (0.04, 0), (0, 0.04), (-0.04, 0)), start=1):
        axis = "0 1 0" if x == 0 else "1 0 0"
        builders.placed(
            robot,
            f"finger{i}_joint",
            "prismatic",
            "palm",
            f"finger{i}",
            xyz=f"{x} {y} -0.23",
            axis=axis,
        )
    return robot


def test_two_upright_axes_an_arms_length_apart_carrying_a_hand_are_an_arm_not_its_wrist() -> None:
    result = identify_urdf(scara().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert result.structure == "Manipulator"


def test_a_hinge_about_no_axis_in_a_hands_short_chain_is_not_compared() -> None:
    # A file's axis 0 0 0: the joint turns nothing; the one turning joint left is the wrist.
    text = scara(elbow="0 -0.05 0.1").text()
    text = text.replace(
        '<origin xyz="0 -0.05 0.1" rpy="0 0 0"/><axis xyz="0 0 1"/>',
        '<origin xyz="0 -0.05 0.1" rpy="0 0 0"/><axis xyz="0 0 0"/>',
    )
    assert '<axis xyz="0 0 0"/>' in text
    assert identify_urdf(text).structure == "Hand"


def test_two_axes_passing_within_the_hands_reach_carrying_it_are_its_wrist() -> None:
    result = identify_urdf(scara(elbow="0 -0.05 0.1").text())
    assert result.structure == "Hand"


def rover_with_a_camera_head(below: tuple[str, ...] = ("camera_1", "camera_2")) -> RobotText:
    """A wheeled base with a pan and a tilt joint in links named as an arm's (``arm_1`` ..
    ``arm_3``), the links ``below`` fixed to the last."""
    robot = RobotText("rover", root="base_link")
    builders.wheeled_base(robot)
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    robot.fixed(robot.root, "arm_1")
    builders.placed(robot, "joint_7", "revolute", "arm_1", "arm_2", xyz="0 0 0.1")
    builders.placed(robot, "joint_8", "revolute", "arm_2", "arm_3", xyz="0 0 0.04", axis="0 1 0")
    for link in below:
        robot.fixed("arm_3", link)
    return robot


def test_a_pan_and_tilt_named_as_an_arm_carrying_only_cameras_is_a_head() -> None:
    result = identify_urdf(rover_with_a_camera_head().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["head"]
    assert result.structure == "UGV"


def test_a_short_arm_carrying_a_tool_beside_its_camera_stays_an_arm() -> None:
    robot = rover_with_a_camera_head(("camera_1", "tool0"))
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def rover_with_a_camera_on(joints: tuple[str, str, str], tip: str = "arm_link_3") -> RobotText:
    """A wheeled base with a turn, a tilt and a roll named ``joints`` on a post, the last
    moving ``tip`` with a camera fixed to it (a patrol robot's camera arm)."""
    robot = RobotText("rover", root="base_link")
    builders.wheeled_base(robot)
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    robot.fixed(robot.root, "post")
    links = ("arm_link_1", "arm_link_2", tip)
    parent = "post"
    for name, link, axis in zip(joints, links, ("0 0 1", "1 0 0", "0 1 0"), strict=True):
        builders.placed(robot, name, "revolute", parent, link, xyz="0 0 0.15", axis=axis)
        parent = link
    robot.fixed(tip, "camera_link")
    return robot


def test_a_chain_whose_joints_are_named_an_arms_pointing_a_camera_is_an_arm() -> None:
    robot = rover_with_a_camera_on(("arm_joint_01", "arm_joint_02", "arm_joint_03"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert result.structure == "Mobile Manipulator"


def test_the_same_chain_with_only_its_links_named_an_arms_points_a_camera() -> None:
    robot = rover_with_a_camera_on(("joint_7", "joint_8", "joint_9"))
    assert identify_urdf(robot.text()).structure == "UGV"


def test_the_same_arm_named_chain_ending_in_a_head_is_a_head() -> None:
    robot = rover_with_a_camera_on(("arm_joint_01", "arm_joint_02", "arm_joint_03"), "head")
    assert identify_urdf(robot.text()).structure == "UGV"


def pair_of_hands(fingers: tuple[int, int] = (5, 5), joint: str = "wrist") -> RobotText:
    """Two hands on forearms fixed 0.4 m apart on one stand, each a one-joint chain named
    ``joint`` into its palm and ``fingers`` three-joint fingers (a bimanual hand rig, no arm)."""
    robot = RobotText("hands", root="stand")
    for (side, y), count in zip((("rh", -0.2), ("lh", 0.2)), fingers, strict=True):
        robot.joint(
            f"{side}_mount", "fixed", "stand", f"{side}_forearm", f'<origin xyz="0 {y} 0"/>'
        )
        wrist = robot.chain(f"{side}_forearm", [f"{side}_{joint}"])
        robot.joint(f"{side}_palm_fixed", "fixed", wrist, f"{side}_palm")
        for finger in ("ff", "mf", "rf", "lf", "th")[:count]:
            robot.chain(f"{side}_palm", [f"{side}_{finger}j{i}" for i in (3, 2, 1)])
    return robot


def test_two_short_chains_each_carrying_a_whole_hand_are_wrists_not_a_torsos_arms() -> None:
    result = identify_urdf(pair_of_hands().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["wrist", "wrist"]
    assert result.structure == "Hand"


@pytest.mark.parametrize(
    "hands",
    [
        {"fingers": (2, 2)},  # two grippers: no whole hand
        {"fingers": (5, 2)},  # a hand and a gripper: seven fingers, one whole hand
        {"joint": "shoulder"},  # short arms named as arms: a torso's, hands on them
    ],
)
def test_short_chains_not_each_a_wrist_of_a_whole_hand_stay_arms(hands: dict[str, Any]) -> None:
    result = identify_urdf(pair_of_hands(**hands).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm", "arm"]
    assert result.structure == "Torso"


def five_bar_legs(*, close: str = "ends") -> RobotText:
    """Two legs of two coaxial motors each, 4 cm apart on one line across the body; each leg's
    two knees close the loop (``ends``: both chains end at one foot point; ``mimic``: ends
    apart, the second knee written as a mimic partner of the first; ``open``: neither)."""
    robot = RobotText("five_bar")
    for corner, x, y in (("front_left", 0.2, 0.1), ("front_right", 0.2, -0.1)):
        for half, dy in (("a", -0.02), ("b", 0.02)):
            motor = builders.placed(
                robot, f"{corner}_{half}_motor", "revolute", robot.root,
                f"{corner}_{half}_motor_link", xyz=f"{x} {y + dy} 0", axis="0 1 0",
            )  # fmt: skip
            inward = -dy if close == "ends" else 0.0
            mimic = f'<mimic joint="{corner}_a_knee"/>' if close == "mimic" and half == "b" else ""
            kind = "continuous" if mimic else "revolute"
            builders.placed(
                robot, f"{corner}_{half}_knee", kind, motor, f"{corner}_{half}_knee_link",
                xyz=f"0 {inward} -0.1", axis="0 1 0", extra=mimic,
            )  # fmt: skip
    return robot


def test_two_coaxial_leg_chains_on_one_side_that_meet_at_the_foot_are_one_five_bar_leg() -> None:
    body = detect_body(parse_urdf(five_bar_legs().text()), load_profile())
    assert body.count("leg") == 2
    assert all(len(limb.joints) == 4 for limb in body.limbs)
    assert all("close a loop" in limb.why for limb in body.limbs)


def test_coaxial_leg_chains_whose_loop_is_written_as_a_mimic_partner_are_one_leg() -> None:
    body = detect_body(parse_urdf(five_bar_legs(close="mimic").text()), load_profile())
    assert body.count("leg") == 2


def test_coaxial_leg_chains_that_end_as_far_apart_as_they_start_are_two_legs() -> None:
    body = detect_body(parse_urdf(five_bar_legs(close="open").text()), load_profile())
    assert body.count("leg") == 4


def four_bar_legs(*, knee_axis: str = "0 1 0", apart: float = 0.0) -> RobotText:
    """Two legs, each of two motors about y at one hip point (``apart`` metres between them
    along y), one chain's knee 10 cm below, the other's 15 cm (its own knee about
    ``knee_axis``): a four-bar leg whose loop the file leaves open, its ends 5 cm apart."""
    robot = RobotText("four_bar")
    for side, y in (("left", 0.1), ("right", -0.1)):
        for half, depth, offset in (("a", 0.1, 0.0), ("b", 0.15, apart)):
            motor = builders.placed(
                robot, f"{side}_{half}_motor", "revolute", robot.root,
                f"{side}_{half}_motor_link", xyz=f"0 {y + offset} 0", axis="0 1 0",
            )  # fmt: skip
            axis = knee_axis if half == "b" else "0 1 0"
            builders.placed(
                robot, f"{side}_{half}_knee", "revolute", motor, f"{side}_{half}_knee_link",
                xyz=f"0 0 -{depth}", axis=axis,
            )  # fmt: skip
    return robot


def test_two_leg_chains_from_one_hip_point_hinged_in_one_plane_are_one_four_bar_leg() -> None:
    body = detect_body(parse_urdf(four_bar_legs().text()), load_profile())
    assert body.count("leg") == 2
    assert all(len(limb.joints) == 4 for limb in body.limbs)
    assert all("four-bar" in limb.why for limb in body.limbs)


def abducted_five_bar_legs(*, hip: str = "revolute") -> RobotText:
    """A biped (fresh set 585's, its five-bar legs drawn open): on each side an abduction
    joint about x (``hip``: its kind) carries two motors about y, side by side on one axle
    2 cm apart, their chains 18 and 24 cm long to their knees, ending far apart."""
    robot = RobotText("five_bar_biped")
    for side, sign in (("left", 1), ("right", -1)):
        abad = builders.placed(
            robot, f"{side}_abad_joint", hip, robot.root, f"leg_{side}_abad", axis="1 0 0"
        )
        for half, y, depth in (("front", 0.088, 0.182), ("rear", 0.109, 0.242)):
            top = builders.placed(
                robot, f"{side}_{half}_joint", "revolute", abad, f"leg_{side}_{half}_top",
                xyz=f"0 {sign * y} 0", axis="0 1 0",
            )  # fmt: skip
            builders.placed(
                robot, f"{side}_{half}_joint2", "revolute", top, f"leg_{side}_{half}_bot",
                xyz=f"0 0 -{depth}", axis="0 1 0",
            )  # fmt: skip
    return robot


def test_two_motors_side_by_side_on_one_axle_a_hips_abduction_carries_are_one_leg() -> None:
    body = detect_body(parse_urdf(abducted_five_bar_legs().text()), load_profile())
    assert body.count("leg") == 2
    assert all(len(limb.joints) == 4 for limb in body.limbs if limb.kind == "leg")


def pitches_down(
    robot: RobotText, side: str, parent: str, joints: tuple[tuple[str, str], ...]
) -> str:
    """A chain of hinges about y from ``parent``: ``{side}_{joint}`` at each ``xyz`` of
    ``joints`` turning ``{side}_{joint}_link``; the last link."""
    link = parent
    for joint, xyz in joints:
        link = placed(
            robot, f"{side}_{joint}", "revolute", link, f"{side}_{joint}_link", xyz=xyz,
            axis="0 1 0",
        )  # fmt: skip
    return link


def test_a_waists_two_hips_on_one_axle_either_side_of_it_are_two_legs() -> None:
    # A servo biped whose waist turns its pelvis, the torso's origin 10 cm to one side (an
    # export's): both hips hang on the body's one side of that origin, on one axle 10 cm
    # apart, hinged in one plane, but on either side of the waist: two legs (found in review).
    robot = RobotText("waist_biped", root="torso")
    pelvis = builders.placed(robot, "waist", "revolute", "torso", "pelvis", xyz="0 0.1 0")
    for side, y in (("left", 0.05), ("right", -0.05)):
        pitches_down(
            robot, side, pelvis,
            (("hip_pitch", f"0 {y} -0.02"), ("knee", "0 0 -0.07"), ("ankle_pitch", "0 0 -0.07")),
        )  # fmt: skip
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert body.count("leg") == 2
    assert all(len(limb.joints) == 3 for limb in body.limbs if limb.kind == "leg")


def test_motors_side_by_side_on_one_axle_of_a_sliding_part_are_two_legs_each() -> None:
    # Below a slide, no hip's hinge: the link is no leg's place, each chain a leg of its own.
    body = detect_body(parse_urdf(abducted_five_bar_legs(hip="prismatic").text()), load_profile())
    assert body.count("leg") == 4


def open_bar_biped() -> RobotText:
    """A biped (fresh set 1215's, its knee's linkage drawn open): on each side a hip's yaw
    carries a thigh chain (hip pitch, knee, ankle about y) and, 4.5 cm below the yaw, a
    two-joint bar of the thigh about y whose far end the file leaves free."""
    robot = RobotText("open_bar_biped")
    for side, y in (("left", 0.05), ("right", -0.05)):
        hip = builders.placed(
            robot, f"{side}_hip_yaw", "revolute", robot.root, f"{side}_hip", xyz=f"0 {y} -0.2",
            axis="0 0 1",
        )  # fmt: skip
        pitches_down(
            robot, side, hip,
            (("hip_pitch", "-0.03 0 -0.066"), ("knee", "0 0 -0.08"), ("ankle", "0 0 -0.0625")),
        )  # fmt: skip
        bar = builders.placed(
            robot, f"{side}_thigh_bar", "revolute", hip, f"{side}_thigh_bar_link", xyz="0 0 -0.045",
            axis="0 -1 0",
        )  # fmt: skip
        builders.placed(
            robot, f"{side}_thigh_bar_end", "revolute", bar, f"{side}_bar_end_link",
            xyz="0.025 0 0", axis="0 1 0",
        )  # fmt: skip
    return robot


def test_a_thigh_and_an_open_linkage_bar_from_one_hips_yaw_are_one_leg() -> None:
    body = detect_body(parse_urdf(open_bar_biped().text()), load_profile())
    assert body.count("leg") == 2
    assert all(len(limb.joints) == 5 for limb in body.limbs if limb.kind == "leg")
    assert identify_urdf(open_bar_biped().text()).structure == "Biped"


def hip_and_knee(robot: RobotText, leg: str, parent: str, *, xyz: str, shin: float = 0.2) -> str:
    """A leg of two hinges about y on ``parent``: ``{leg}_hip`` at ``xyz`` turning
    ``{leg}_thigh``, then ``{leg}_knee`` ``shin`` metres below turning ``{leg}_shin``."""
    thigh = placed(robot, f"{leg}_hip", "revolute", parent, f"{leg}_thigh", xyz=xyz, axis="0 1 0")
    return placed(
        robot, f"{leg}_knee", "revolute", thigh, f"{leg}_shin", xyz=f"0 0 {-shin}", axis="0 1 0"
    )


def test_a_rockers_front_and_rear_legs_alike_and_far_apart_stay_two_legs() -> None:
    # Found in review: on each side a passive rocker carries a front and a rear leg, all
    # hinges about y, side by side on its side: built alike and 40 cm apart, two legs each.
    robot = RobotText("rocker_walker")
    for side, y in (("left", 0.15), ("right", -0.15)):
        rocker = builders.placed(
            robot, f"{side}_rocker", "revolute", robot.root, f"{side}_rocker_link",
            xyz=f"0 {y} 0", axis="0 1 0",
        )  # fmt: skip
        for end, x in (("front", 0.2), ("rear", -0.2)):
            hip_and_knee(robot, f"{side}_{end}", rocker, xyz=f"{x} 0 -0.05")
    assert detect_body(parse_urdf(robot.text()), load_profile()).count("leg") == 4


def test_a_spine_joints_two_front_legs_on_either_side_of_the_body_stay_two_legs() -> None:
    # One hinge carries both front legs, as a hip's yaw carries a leg and its bar, but on
    # both sides of the body: two legs.
    robot = RobotText("spine_dog", root="rear_body")
    front = builders.placed(
        robot, "spine", "revolute", "rear_body", "front_body", xyz="0.2 0 0", axis="0 0 1"
    )
    for end, body_link, x in (("front", front, 0.1), ("rear", "rear_body", -0.1)):
        for side, y in (("left", 0.1), ("right", -0.1)):
            hip_and_knee(robot, f"{end}_{side}", body_link, xyz=f"{x} {y} -0.05")
    assert detect_body(parse_urdf(robot.text()), load_profile()).count("leg") == 4


def test_a_planar_walkers_two_legs_from_its_one_hip_point_stay_two_legs() -> None:
    robot = RobotText("planar_biped", root="torso")
    for side in ("left", "right"):
        hip_and_knee(robot, side, "torso", xyz="0 0 -0.1", shin=0.4)
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert body.count("leg") == 2


def test_a_side_views_left_and_right_legs_drawn_over_each_other_stay_two_legs() -> None:
    """A quadruped drawn in its plane: at the front hip and at the rear hip a left and a
    right leg, each of a hip and a knee, joint over joint."""
    robot = RobotText("side_view_dog", root="trunk")
    for end, x in (("front", 0.2), ("rear", -0.2)):
        for side in ("a", "b"):
            hip_and_knee(robot, f"{end}_{side}", "trunk", xyz=f"{x} 0 -0.05")
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert body.count("leg") == 4
    assert not any("four-bar" in limb.why for limb in body.limbs)


@pytest.mark.parametrize(
    "drawn", [{"knee_axis": "1 0 0"}, {"apart": 0.01}], ids=["out of plane", "hips apart"]
)
def test_leg_chains_out_of_one_plane_or_from_two_hip_points_are_no_four_bar_leg(
    drawn: dict[str, Any],
) -> None:
    body = detect_body(parse_urdf(four_bar_legs(**drawn).text()), load_profile())
    assert not any("four-bar" in limb.why for limb in body.limbs)


def test_front_and_rear_hips_turning_about_one_line_along_the_body_are_two_legs() -> None:
    """Four 3-joint legs whose hips roll about the body's long axis: on each side the front
    and the rear hip turn about one line, 12 cm apart, and their feet are as far apart."""
    robot = RobotText("small_dog")
    for corner, x, y in (("lf", 0.06, 0.04), ("lb", -0.06, 0.04), ("rf", 0.06, -0.04),
                         ("rb", -0.06, -0.04)):  # fmt: skip
        hip = builders.placed(
            robot, f"base_{corner}1", "revolute", robot.root, f"{corner}1", xyz=f"{x} {y} 0",
            axis="1 0 0",
        )  # fmt: skip
        upper = builders.placed(
            robot, f"{corner}1_{corner}2", "revolute", hip, f"{corner}2", xyz="0 0.02 0",
            axis="0 1 0",
        )  # fmt: skip
        lower = builders.placed(
            robot, f"{corner}2_{corner}3", "revolute", upper, f"{corner}3", xyz="0 0 -0.05",
            axis="0 1 0",
        )  # fmt: skip
        robot.joint(f"{corner}_foot", "fixed", lower, f"{corner}foot", '<origin xyz="0 0 -0.05"/>')
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.count("leg") == 4
    assert result.structure == "Quadruped"


def test_a_chain_whose_last_joint_turns_a_cameras_frame_is_a_gimbal_whatever_its_names() -> None:
    """A drone's gimbal whose joints are named as arms (arm_one, arm_two), its last joint
    turning the camera's own frame: a head, so the drone is no aerial manipulator."""
    drone = builders.quadrotor()
    first = drone.joint("arm_one_joint", "continuous", drone.root, "arm_one_link")
    second = drone.joint("arm_two_joint", "continuous", first, "arm_two_link")
    drone.joint("camera_joint", "continuous", second, "camera_link")
    result = identify_urdf(drone.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["head"]
    assert result.structure == "UAV"
    # An arm whose camera hangs fixed below its wrist is still an arm.
    arm = builders.manipulator()
    arm.fixed(arm.links[-1], "camera_link")
    assert identify_urdf(arm.text()).structure == "Manipulator"


def test_a_short_unnamed_chain_carrying_a_camera_is_a_head() -> None:
    robot = builders.ugv()
    tip = robot.chain(robot.root, ["j1", "j2"])
    robot.fixed(tip, "cam_frame")
    robot.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["head"]
    assert "a pan/tilt unit" in result.body.limbs[0].why


def test_an_unnamed_chain_swinging_a_camera_on_a_shoulder_and_an_elbow_is_an_arm() -> None:
    """A pan, then two hinges about parallel axes 1.5 m apart, the camera at the far end: it
    carries the camera round an object, where a pan/tilt unit turns it where it is."""
    robot = (
        '<robot name="scanner"><link name="world"/><link name="l1"/><link name="l2"/>'
        '<link name="l3"/><link name="kinect"/>'
        + builders.joint_xml("j0", "continuous", "world", "l1", "0 0 3.5", "0 0 1")
        + builders.joint_xml("j1", "continuous", "l1", "l2", "0 0.1 0.1", "0 1 0")
        + builders.joint_xml("j2", "continuous", "l2", "l3", "0 0.1 1.5", "0 1 0")
        + '<joint name="mount" type="fixed"><parent link="l3"/><child link="kinect"/>'
        '<origin xyz="0 0 1.8"/></joint>'
        '<gazebo reference="kinect"><sensor name="depth" type="depth"/></gazebo></robot>'
    )
    result = identify_urdf(robot)
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert result.structure == "Manipulator"
    # The same chain whose two hinges turn about one line is a pan/tilt unit's.
    one_line = robot.replace('"0 0.1 1.5"', '"0 0 0"')
    assert identify_urdf(one_line).structure == "Pan/Tilt Unit"


def pan_and_tilt(name: str) -> str:
    """A pan joint, a tilt joint and a camera fixed at the tip, bolted to the world."""
    return (
        f'<robot name="{name}"><link name="world"/><link name="l1"/><link name="l2"/>'
        '<link name="camera_link"/>'
        + builders.joint_xml("joint_1", "continuous", "world", "l1", "0 0 0.1", "0 0 1")
        + builders.joint_xml("joint_2", "continuous", "l1", "l2", "0 0 0.5", "0 1 0")
        + '<joint name="camera_joint" type="fixed"><parent link="l2"/><child link="camera_link"/>'
        '<origin xyz="0 0 0.5"/></joint>'
        '<gazebo reference="camera_link"><sensor name="cam" type="camera"/></gazebo></robot>'
    )


@pytest.mark.parametrize("name", ["simple_arm", "Arm", "SimpleArm", "camera_manipulator", "arm_v2"])
def test_a_robot_named_an_arm_carries_its_camera_on_that_short_chain_no_pan_tilt_unit(
    name: str,
) -> None:
    result = identify_urdf(pan_and_tilt(name))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert "on a robot named an arm" in result.body.limbs[0].why


def test_a_pan_tilt_camera_beside_a_base_or_an_arm_stays_a_head_whatever_the_robot_is_named() -> (
    None
):
    # Only a body's one limb is read by the robot's name: a rover's or an arm's pan/tilt
    # camera is still its head.
    rover = builders.ugv()
    rover.name = "arm_rover"
    tip = rover.chain(rover.root, ["j1", "j2"])
    rover.fixed(tip, "cam_frame")
    rover.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    assert identify_urdf(rover.text()).structure == "UGV"
    arm = builders.manipulator()
    arm.name = "robot_arm"
    tip = arm.chain(arm.root, ["j1", "j2"])
    arm.fixed(tip, "cam_frame")
    arm.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    assert identify_urdf(arm.text()).structure == "Manipulator"


@pytest.mark.parametrize("name", ["camera_rig", "xarm_head", "armadillo", "pan_tilt"])
def test_without_an_arms_name_the_chain_turning_a_camera_is_a_pan_tilt_unit(name: str) -> None:
    assert identify_urdf(pan_and_tilt(name)).structure == "Pan/Tilt Unit"


def bracket(name: str) -> str:
    """Fresh set 599's hobby unit: a pan about the upright, then a tilt about x 34 cm away on
    a link named ``lower_arm``, no sensor, ``name`` the robot's."""
    return (
        f'<robot name="{name}"><link name="base_link"/><link name="platform"/>'
        '<link name="lower_arm"/>'
        + builders.joint_xml("joint1", "revolute", "base_link", "platform", "0 0 0.48", "0 0 1")
        + builders.joint_xml("joint2", "revolute", "platform", "lower_arm", "0 0.19 0.28", "1 0 0")
        + "</robot>"
    )


@pytest.mark.parametrize("name", ["pan_tilt", "PanTilt", "pan-tilt unit", "ptu_d46"])
def test_a_robot_named_a_pan_tilt_unit_turns_its_one_short_chain_as_one(name: str) -> None:
    result = identify_urdf(bracket(name))
    assert result.structure == "Pan/Tilt Unit"
    assert result.body is not None
    assert "on a robot named a pan/tilt unit" in result.body.limbs[0].why


@pytest.mark.parametrize("name", ["two_link", "pan_tilt_arm", "captured"])
def test_without_a_pan_tilt_units_name_or_named_an_arm_the_same_chain_is_no_head(
    name: str,
) -> None:
    assert identify_urdf(bracket(name)).structure != "Pan/Tilt Unit"


def limb_kinds(robot: RobotText) -> list[str]:
    body = identify_urdf(robot.text()).body
    assert body is not None
    return [limb.kind for limb in body.limbs]


def test_a_slide_carrying_a_camera_points_nothing_it_is_no_head() -> None:
    # A forklift's carriage slides its camera up and down: its joint is commanded, not aimed.
    robot = builders.ugv()
    tip = robot.chain(robot.root, ["j1"], "prismatic")
    robot.fixed(tip, "cam_frame")
    robot.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    robot.add(builders.transmission("j1"))
    assert limb_kinds(robot) == ["other"]
    assert [c.motion_control for c in identify_urdf(robot.text()).motion_controls] == [
        "Driving",
        "Joint",
    ]
    # A slide whose child is the camera's own link is no gimbal either.
    robot = builders.ugv()
    robot.chain(robot.root, ["camera"], "prismatic")
    assert limb_kinds(robot) == ["other"]
    # Nor a carriage on a mast that tilts: the chain ends in the slide.
    robot = builders.ugv()
    tip = robot.chain(robot.root, ["j1"])
    tip = robot.chain(tip, ["j2"], "prismatic")
    robot.fixed(tip, "cam_frame")
    robot.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    assert limb_kinds(robot) == ["other"]


def test_a_pan_tilt_unit_on_a_lift_still_points_its_camera() -> None:
    robot = builders.ugv()
    tip = robot.chain(robot.root, ["j1"], "prismatic")
    tip = robot.chain(tip, ["j2", "j3"])
    robot.fixed(tip, "cam_frame")
    robot.add(builders.gazebo_sensor("cam_frame", "camera", "cam"))
    assert limb_kinds(robot) == ["head"]


def lone_leg(wheels: int = 0) -> RobotText:
    """A 3-joint chain named as a quadruped's front left leg, alone on a fixed base, its tip
    on a floating joint (a leg set up on a bench to reach); ``wheels`` under the base."""
    robot = RobotText("leg_rig")
    if wheels:
        builders.wheeled_base(robot, wheels)
    tip = robot.chain(robot.root, ["base_motor", "left_front_upper_leg", "left_front_lower_leg"])
    robot.joint("left_front_toe", "floating", tip, "left_front_toe_link")
    return robot


def test_a_leg_alone_on_a_still_body_is_an_arm_with_leg_names() -> None:
    result = identify_urdf(lone_leg().text())
    assert (result.structure, result.kinematic_type) == ("Manipulator", "Manipulator")
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("arm", 3)]
    assert "the body's only limb" in result.body.limbs[0].why
    # On a body that moves (wheels), a leg-named chain stays what it was read as; two legs
    # stay legs.
    rolling = identify_urdf(lone_leg(wheels=4).text()).body
    assert rolling is not None
    assert [limb.kind for limb in rolling.limbs] == ["leg"]
    assert identify_urdf(builders.biped().text()).structure == "Biped"


def test_a_lone_ball_joint_carrying_no_gripper_on_a_rover_is_no_arm() -> None:
    # A spherical robot's shell on a ball joint around the wheels that roll it from inside.
    robot = builders.ugv()
    robot.joint("shell_joint", "spherical", robot.root, "shell_link")
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["other"]
    # On a body with no wheels, unnamed balls on the pelvis stay a humanoid's shoulders.
    walker = builders.biped()
    for side in ("a", "b"):
        walker.joint(f"{side}_ball", "spherical", walker.root, f"{side}_upper")
    assert identify_urdf(walker.text()).structure == "Humanoid"


def gripping_legs(legs: int = 1, *, wheels: int = 4) -> RobotText:
    """``legs`` four-joint chains whose joints are numbered as a leg's segments
    (``leg1_2_joint``), each ending in a claw of two jaws, on a base with ``wheels``."""
    robot = RobotText("rover")
    if wheels:
        builders.wheeled_base(robot, wheels)
    for n in range(legs):
        tip = robot.chain(robot.root, [f"leg{n}_{i}_joint" for i in range(4)])
        robot.chain(tip, [f"claw{n}_top_joint"])
        robot.chain(tip, [f"claw{n}_bottom_joint"])
    return robot


def test_the_only_leg_named_chain_ending_in_a_gripper_on_a_rover_is_its_arm() -> None:
    result = identify_urdf(gripping_legs().text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    arms = [limb for limb in result.body.limbs if limb.kind == "arm"]
    assert [len(limb.joints) for limb in arms] == [4]
    assert "ending in a gripper" in arms[0].why
    # Two legs that grip (a climber's feet) stay legs.
    climber = identify_urdf(gripping_legs(2, wheels=0).text()).body
    assert climber is not None
    assert [limb.kind for limb in climber.limbs if len(limb.joints) == 4] == ["leg", "leg"]


def stretched_hexapod(legs: int = 6) -> RobotText:
    """A hexapod drawn with its legs stretched out flat (numbered joints, feet named
    ``end_effector_N``): each leg hangs from a bracket link fixed to the body, its three joints
    reach 0.3 m out from the body and end 5 cm above where they start."""
    robot = RobotText("numbered", root="body")
    for i in range(legs):
        x = 0.2 * (i % (legs // 2)) - 0.2
        y = 0.1 if i < legs // 2 else -0.1
        bracket = robot.joint(
            f"bracket_{i}", "fixed", "body", f"J{3 * i + 1}/body", f'<origin xyz="{x} {y} 0"/>'
        )
        out = f"0 {y} 0"  # 0.1 m further out from the body, on its side
        first = builders.placed(robot, f"J{3 * i + 1}", "continuous", bracket, f"a{i}")
        second = builders.placed(
            robot, f"J{3 * i + 2}", "continuous", first, f"b{i}", xyz=out, axis="1 0 0"
        )
        third = builders.placed(
            robot, f"J{3 * i + 3}", "continuous", second, f"c{i}", xyz=out, axis="1 0 0"
        )
        robot.joint(
            f"foot_{i}", "fixed", third, f"end_effector_{i + 1}",
            f'<origin xyz="0 {y} 0.05"/>',
        )  # fmt: skip
    return robot


def test_six_chains_on_brackets_fixed_to_one_body_reaching_out_flat_are_a_hexapods_legs() -> None:
    result = identify_urdf(stretched_hexapod().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6
    assert "reaching out flat" in result.body.limbs[0].why
    assert result.structure == "Hexapod"


def endless_hexapod(*, level_feet: tuple[int, ...] = (1, 4)) -> RobotText:
    """Six four-joint legs round a body, every joint continuous and numbered (an exporter's, no
    limits, no names): a hip turning about the vertical, two joints about axes slanted across
    the leg, and a foot joint at its end, about a level axle on the two middle legs and a
    slanted one on the others (as a CAD export's frames leave them); ``level_feet``: the legs
    whose foot turns about a level axle."""
    robot = RobotText("hexabot", root="base_link")
    for i in range(6):
        angle = math.pi / 6 + i * math.pi / 3
        out = (math.cos(angle), math.sin(angle))
        across = f"{-out[1]:.4f} {out[0]:.4f} 0"
        step = f"{0.06 * out[0]:.4f} {0.06 * out[1]:.4f} -0.02"
        slanted = f"{0.5 * out[0]:.4f} {0.5 * out[1]:.4f} 0.866"
        tilted = f"{-0.5 * out[1]:.4f} {0.5 * out[0]:.4f} 0.866"
        places = [
            (f"{0.07 * out[0]:.4f} {0.07 * out[1]:.4f} 0", "0 0 1"),
            (step, tilted),
            (step, tilted),
            ("0 0 -0.06", across if i in level_feet else slanted),
        ]
        link = "base_link"
        for k, (xyz, axis) in enumerate(places):
            n = 4 * i + k
            link = builders.placed(robot, f"j{n}", "continuous", link, f"l{n}", xyz=xyz, axis=axis)
    return robot


def test_level_axled_feet_of_two_of_six_alike_legs_are_no_wheels() -> None:
    # A student's hexapod drawn without limits: its two middle legs' feet turn about level
    # axles, nothing below them, and are feet as the other four legs' are, not wheels.
    result = identify_urdf(endless_hexapod().text())
    assert result.structure == "Hexapod"
    assert result.body is not None
    assert not result.body.wheels
    # Every leg ending in a leaf about a level axle: wheels on legs, kept.
    rolling = identify_urdf(endless_hexapod(level_feet=tuple(range(6))).text())
    assert rolling.body is not None
    assert len(rolling.body.wheels) == 6


def test_four_chains_reaching_out_flat_are_not_legs_by_that_rule() -> None:
    # The flat rule takes six or more at once; four reaching every way are legs by a later one
    # (below), but these four start in mirrored pairs at the body's corners, a walker's hips by
    # the rule read before it.
    result = identify_urdf(stretched_hexapod(4).text())
    assert result.body is not None
    legs = [limb for limb in result.body.limbs if limb.kind == "leg"]
    assert len(legs) == 4
    assert all("corners" in limb.why and "flat" not in limb.why for limb in legs)


def sprawled_spider(*, way: str = "every", rise: float = -0.01) -> RobotText:
    """Four unnamed three-joint chains, a yaw and two pitches each, each of two steps that
    rise by ``rise`` (2 cm down, at -0.01): with ``way`` "every", from hips around a body
    whose origin is off their middle (a CAD export's), out from its four sides (a spider's legs
    sprawled at rest); "one", from one edge of it, side by side, all out along x (a hand's
    fingers drawn flat); "sideways", two on each side reaching straight out along y (a
    torso's four arms held out)."""
    robot = RobotText("sprawled", root="body")
    hips = [(0.08, -0.1), (-0.12, -0.1), (0.08, 0.06), (-0.12, 0.06)]
    if way == "one":
        hips = [(0.1, y) for y in (-0.03, -0.01, 0.01, 0.03)]
    for i, (x, y) in enumerate(hips):
        out = {
            "every": (0.05 if x > 0 else -0.05, 0.05 if y > 0 else -0.05),
            "one": (0.07, 0.0),
            "sideways": (0.0, 0.07 if y > 0 else -0.07),
        }[way]
        step = f"{out[0]} {out[1]} {rise}"
        hip = builders.placed(robot, f"j{3 * i}", "revolute", "body", f"a{i}", xyz=f"{x} {y} 0")
        thigh = builders.placed(
            robot, f"j{3 * i + 1}", "revolute", hip, f"b{i}", xyz=step, axis="1 0 0"
        )
        builders.placed(robot, f"j{3 * i + 2}", "revolute", thigh, f"c{i}", xyz=step, axis="1 0 0")
    return robot


def test_four_chains_sprawled_flat_every_way_from_a_body_are_a_walkers_legs() -> None:
    result = identify_urdf(sprawled_spider().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 4
    assert "every way" in result.body.limbs[0].why
    assert result.structure == "Quadruped"


@pytest.mark.parametrize(
    "robot",
    [
        sprawled_spider(way="one"),
        sprawled_spider(way="sideways"),
        sprawled_spider(rise=0.025),
    ],
    ids=["a hand's fingers drawn flat", "a torso's arms held out", "chains rising every way"],
)
def test_four_chains_not_sprawled_flat_every_way_are_no_legs(robot: RobotText) -> None:
    body = identify_urdf(robot.text()).body
    assert body is not None
    assert not any(limb.kind == "leg" for limb in body.limbs)


def test_four_chains_sprawled_every_way_on_a_wheeled_body_are_no_legs() -> None:
    # On a body with wheels of its own, four chains reaching every way are a rover's flippers.
    rover = sprawled_spider()
    builders.placed(rover, "wheel_joint", "continuous", "body", "wheel", axis="0 1 0")
    body = identify_urdf(rover.text()).body
    assert body is not None
    assert not any(limb.kind == "leg" for limb in body.limbs)


def star_of_arms(count: int, *, fan: bool = False) -> RobotText:
    """``count`` alike three-joint chains whose makers named them as arms (``limb<i>_shoulder``,
    ``limb<i>_upper_arm``, ``limb<i>_lower_arm``), spaced evenly round a disc and reaching
    straight out from it, flat, a little down: a pentapod's legs drawn sprawled at rest; with
    ``fan``, spaced over its front half only (arms fanned out forward, not every way)."""
    robot = RobotText("star", root="disc")
    for i in range(count):
        turn = (i / (count - 1) - 0.5) * 0.9 * math.pi if fan else 2 * math.pi * i / count
        x, y = round(math.cos(turn), 4), round(math.sin(turn), 4)
        step = f"{0.06 * x} {0.06 * y} -0.01"
        shoulder = builders.placed(
            robot,
            f"limb{i}_shoulder",
            "revolute",
            "disc",
            f"limb{i}_shoulder_link",
            xyz=f"{0.1 * x} {0.1 * y} 0",
        )
        upper = builders.placed(
            robot,
            f"limb{i}_upper_arm_joint",
            "revolute",
            shoulder,
            f"limb{i}_upper_arm",
            xyz=step,
            axis=f"{-y} {x} 0",
        )
        builders.placed(
            robot,
            f"limb{i}_lower_arm_joint",
            "revolute",
            upper,
            f"limb{i}_lower_arm",
            xyz=step,
            axis=f"{-y} {x} 0",
        )
    return robot


def test_five_chains_named_as_arms_sprawled_flat_every_way_are_a_walkers_legs() -> None:
    result = identify_urdf(star_of_arms(5).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 5
    assert "named as arms" in result.body.limbs[0].why
    assert result.structure == "Hexapod"


@pytest.mark.parametrize(
    ("robot", "arms"),
    [(star_of_arms(4), 4), (star_of_arms(5, fan=True), 5)],
    ids=["four every way, a torso's arms may be", "five fanned out forward"],
)
def test_chains_named_as_arms_fewer_than_five_or_not_every_way_stay_arms(
    robot: RobotText, arms: int
) -> None:
    body = identify_urdf(robot.text()).body
    assert body is not None
    assert [limb.kind for limb in body.limbs] == ["arm"] * arms


def test_five_chains_named_as_arms_on_a_wheeled_body_stay_arms() -> None:
    rover = star_of_arms(5)
    builders.placed(rover, "wheel_joint", "continuous", "disc", "wheel", axis="0 1 0")
    body = identify_urdf(rover.text()).body
    assert body is not None
    assert [limb.kind for limb in body.limbs].count("arm") == 5


def tilted_hexapod(
    *,
    reach: float = 1.0,
    hips: int = 6,
    chains: int = 6,
    rpy: str = "0.7 0.5 0.3",
    down: float = 1.0,
    scale: float = 1.0,
) -> RobotText:
    """``chains`` unnamed three-joint chains on a circle of hips around a body drawn turned on
    its root by ``rpy`` (as a CAD export may draw it), each reaching out from the body's middle
    and down in the body's frame (``reach`` -1: in towards the middle; ``down`` -1: up);
    ``hips`` 2: on two places only, half the chains at each; ``scale``: every length."""
    robot = RobotText("r")
    body = robot.joint("mount", "fixed", robot.root, "body", f'<origin rpy="{rpy}"/>')
    for i in range(chains):
        angle = 2 * math.pi * (i if hips != 2 else i % 2 * chains / 2) / chains
        x, y = scale * math.cos(angle), scale * math.sin(angle)
        placed_chain(
            robot,
            body,
            f"k{i}_",
            start=f"{0.1 * x:.6g} {0.1 * y:.6g} 0",
            steps=[
                f"{0.05 * reach * x:.6g} {0.05 * reach * y:.6g} 0",
                f"{0.1 * reach * x:.6g} {0.1 * reach * y:.6g} {-0.06 * down * scale:.6g}",
                f"0 0 {-0.1 * down * scale:.6g}",
            ],
        )
    return robot


def test_six_chains_reaching_out_and_down_from_a_tilted_body_are_a_hexapods_legs() -> None:
    result = identify_urdf(tilted_hexapod().text())
    assert result.structure == "Hexapod"
    assert result.body is not None
    assert "tilted" in result.body.limbs[0].why
    # The same read at any scale, past squaring too (1e100 m): the hips' own scale is read.
    for scale in (1000.0, 1e100):
        assert identify_urdf(tilted_hexapod(scale=scale).text()).structure == "Hexapod"


def hexapod_drawn_from_a_corner(*, out: float = 1.0) -> RobotText:
    """Six unnamed three-joint chains in two rows of three hips 0.22 m apart across x, the
    body's link origin at the first row's end (a CAD export's): each reaches out along x,
    away from the other row (``out`` -1: towards it), dropping and rising a little."""
    robot = RobotText("r", root="body")
    for i, (x, y) in enumerate((x, y) for x in (0.0, 0.22) for y in (-0.03, 0.1, 0.23)):
        way = (1 if x else -1) * out
        placed_chain(
            robot,
            "body",
            f"k{i}_",
            start=f"{x:.6g} {y:.6g} 0.04",
            steps=[f"{0.07 * way:.6g} -0.03 -0.08", f"{0.07 * way:.6g} 0 0.07"],
        )
    return robot


def test_six_chains_reaching_out_flat_from_their_middle_away_from_the_origin_are_legs() -> None:
    # Out from their own middle, though the first row's far one reaches no farther from the
    # link's origin than it starts.
    assert identify_urdf(hexapod_drawn_from_a_corner().text()).structure == "Hexapod"
    assert identify_urdf(hexapod_drawn_from_a_corner(out=-1.0).text()).structure != "Hexapod"


@pytest.mark.parametrize(
    "drawn",
    [
        {"reach": -1.0},  # reaching in towards their middle (fingers closing)
        {"hips": 2},  # starting at two places only: no plane of hips
        {"down": -1.0},  # reaching up from the tilted body (an open hand)
        # Twelve on a level body, reaching up and out: the file's z is "up", and says fingers.
        {"chains": 12, "rpy": "0 0 0", "down": -1.0},
        # Numbers past squaring (1e100 m) reaching up: read at the hips' own scale, as at 1.
        {"scale": 1e100, "down": -1.0},
    ],
)
def test_chains_that_reach_in_up_or_from_no_plane_of_hips_are_no_tilted_walkers_legs(
    drawn: dict[str, Any],
) -> None:
    result = identify_urdf(tilted_hexapod(**drawn).text())
    assert result.body is not None
    assert not any("tilted" in limb.why for limb in result.body.limbs)


def whole_turn_legs(legs: int = 6, *, kind: str = "continuous", axis: str = "0 1 0") -> RobotText:
    """A body with ``legs`` one-joint chains, half on each side, in rows along it (RHex-like)."""
    robot = RobotText("six_spokes", root="body")
    rows = legs // 2
    for i in range(legs):
        x = 0.2 * (i % rows) - 0.2
        y = 0.1 if i < rows else -0.1
        builders.placed(robot, f"L{i}", kind, "body", f"spoke{i}", xyz=f"{x} {y} 0", axis=axis)
    return robot


def test_six_one_joint_chains_turning_whole_about_parallel_axes_are_a_wheel_leg_walker() -> None:
    result = identify_urdf(whole_turn_legs().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6
    assert "turning whole" in result.body.limbs[0].why
    assert result.structure == "Hexapod"
    assert "Walking" in {c.motion_control for c in result.motion_controls}


@pytest.mark.parametrize(
    ("legs", "kind", "axis"),
    [(4, "continuous", "0 1 0"), (6, "revolute", "0 1 0"), (6, "continuous", "0 0 1")],
)
def test_one_joint_chains_that_are_few_or_turn_partly_are_no_legs(
    legs: int, kind: str, axis: str
) -> None:
    text = whole_turn_legs(legs, kind=kind).text()
    if axis != "0 1 0":  # one spoke turns about another axis than the rest
        text = text.replace('<axis xyz="0 1 0"/>', f'<axis xyz="{axis}"/>', 1)
    result = identify_urdf(text)
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]


def with_masses(robot: RobotText, centre: str) -> str:
    """``robot``'s text with each spoke's mass centre at ``centre`` on its link."""
    text = robot.text()
    for i in range(len(robot.joints)):
        text = text.replace(
            f'<link name="spoke{i}"/>',
            f'<link name="spoke{i}"><inertial><origin xyz="{centre}"/><mass value="0.2"/>'
            '<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>'
            "</inertial></link>",
        )
    return text


@pytest.mark.parametrize("centre", ["0 0 0", "0 0.03 0", "0.001 0 0.002"])
def test_six_one_joint_chains_carrying_their_mass_on_their_axles_are_wheels(centre: str) -> None:
    result = identify_urdf(with_masses(whole_turn_legs(), centre))
    assert sorted(role.joint for role in result.roles if role.role == "wheel") == [
        f"L{i}" for i in range(6)
    ]
    assert result.structure == "UGV"


@pytest.mark.parametrize("centre", ["0 0 -0.08", "-0.06 0.007 -0.095", "0.01 0 0", None])
def test_six_one_joint_chains_hanging_their_mass_off_their_axles_stay_a_wheel_leg_walker(
    centre: str | None,
) -> None:
    text = with_masses(whole_turn_legs(), "0 0 0")
    if centre is None:  # an inertial that leaves its origin out says nothing of where
        text = text.replace('<origin xyz="0 0 0"/><mass', "<mass")
    else:
        text = with_masses(whole_turn_legs(), centre)
    assert identify_urdf(text).structure == "Hexapod"


def test_road_wheels_whose_few_idlers_leave_their_mass_unplaced_are_wheels() -> None:
    text = with_masses(whole_turn_legs(), "0 0 0")
    for i in (0, 3):  # two of six: an inertial with no origin says nothing of where
        text = text.replace(
            f'<link name="spoke{i}"><inertial><origin xyz="0 0 0"/>',
            f'<link name="spoke{i}"><inertial>',
        )
    assert identify_urdf(text).structure == "UGV"


def test_two_legs_known_to_hang_their_mass_out_keep_the_six_a_wheel_leg_walker() -> None:
    # Four carried on their axles for two off them: fewer than three for each one off.
    text = with_masses(whole_turn_legs(), "0 0 0")
    for i in (2, 5):
        text = text.replace(
            f'<link name="spoke{i}"><inertial><origin xyz="0 0 0"/>',
            f'<link name="spoke{i}"><inertial><origin xyz="0 0 -0.08"/>',
        )
    assert identify_urdf(text).structure == "Hexapod"


@pytest.mark.parametrize(("off", "structure"), [((0, 3, 6), "UGV"), ((0, 3, 6, 9), "Quadruped")])
def test_parts_known_on_their_axles_outvote_those_known_off_three_to_one(
    off: tuple[int, ...], structure: str
) -> None:
    # Twelve: nine on for three off is road wheels; eight on for four off, whole-turning legs.
    text = with_masses(whole_turn_legs(12), "0 0 0")
    for i in off:
        text = text.replace(
            f'<link name="spoke{i}"><inertial><origin xyz="0 0 0"/>',
            f'<link name="spoke{i}"><inertial><origin xyz="0 0 -0.08"/>',
        )
    assert identify_urdf(text).structure == structure


def test_parts_only_drawn_round_do_not_outvote_one_known_to_hang_its_mass_out() -> None:
    # Five whose file places no mass centre, drawn as cylinders about their axles (a leg's
    # hub), and one whose mass is known 8 cm off its axle: a drawing does not outvote a mass.
    mass = '<inertial><mass value="0.2"/></inertial>'
    text = with_shapes(whole_turn_legs(), rpy="1.5708 0 0", mass=mass)
    start = text.index('<link name="spoke2">')
    end = text.index("</link>", start)
    text = (
        text[:start]
        + text[start:end].replace(
            mass, '<inertial><origin xyz="0 0 -0.08"/><mass value="0.2"/></inertial>'
        )
        + text[end:]
    )
    assert identify_urdf(text).structure == "Hexapod"


def test_road_wheels_whose_sprockets_carry_a_track_drawn_rigid_on_them_are_wheels() -> None:
    # Twelve wheels, six a side: each side's sprocket carries its track as a link fixed on it,
    # its mass far off the axle; the ten idlers carry theirs on their axles.
    text = with_masses(whole_turn_legs(12), "0 0 0")
    for i in (0, 6):
        text = text.replace(
            f'<link name="spoke{i}"><inertial>',
            f'<link name="track{i}"><inertial><origin xyz="0.3 0 0"/><mass value="1"/>'
            '<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>'
            f'</link><joint name="T{i}" type="fixed"><parent link="spoke{i}"/>'
            f'<child link="track{i}"/></joint><link name="spoke{i}"><inertial>',
        )
    result = identify_urdf(text)
    assert len([role for role in result.roles if role.role == "wheel"]) == 12
    assert result.structure == "UGV"


def with_shapes(robot: RobotText, *, rpy: str, xyz: str = "0 0 0", mass: str = "") -> str:
    """``robot``'s text with each spoke drawn as a cylinder turned by ``rpy`` and placed at
    ``xyz`` on its link, with ``mass`` (an inertial's text) or none."""
    text = robot.text()
    for i in range(len(robot.joints)):
        text = text.replace(
            f'<link name="spoke{i}"/>',
            f'<link name="spoke{i}"><visual><origin rpy="{rpy}" xyz="{xyz}"/><geometry>'
            f'<cylinder radius="0.05" length="0.03"/></geometry></visual>{mass}</link>',
        )
    return text


@pytest.mark.parametrize("mass", ["", '<inertial><mass value="0.2"/></inertial>'])
def test_six_one_joint_chains_drawn_as_tyres_round_their_axles_are_wheels(mass: str) -> None:
    # A six-wheeled rover whose file says nothing of where its wheels' mass is: each is drawn
    # as a cylinder about its axle (turned a quarter about x, its z along the axle y).
    text = with_shapes(whole_turn_legs(), rpy="1.5708 0 0", mass=mass)
    assert identify_urdf(text).structure == "UGV"


@pytest.mark.parametrize(
    ("rpy", "xyz", "mass"),
    [
        ("0 0 0", "0 0 0", ""),  # a rod across the axle
        ("1.5708 0 0", "0 0 -0.08", ""),  # a tyre hung below the axle
        (  # a tyre, but the part's mass is known to hang out
            "1.5708 0 0",
            "0 0 0",
            '<inertial><origin xyz="0 0 -0.08"/><mass value="0.2"/></inertial>',
        ),
    ],
)
def test_six_one_joint_chains_drawn_off_or_across_their_axles_stay_a_wheel_leg_walker(
    rpy: str, xyz: str, mass: str
) -> None:
    text = with_shapes(whole_turn_legs(), rpy=rpy, xyz=xyz, mass=mass)
    assert identify_urdf(text).structure == "Hexapod"


def test_six_hubs_turning_legs_fixed_below_them_are_a_wheel_leg_walker() -> None:
    """Each joint turns a motor's hub balanced on its axle, and the leg, fixed to the hub,
    hangs 8 cm out: the part that turns is out of balance."""
    text = with_masses(whole_turn_legs(), "0 0 0")
    for i in range(6):
        text = text.replace(
            "</robot>",
            f'<link name="leg{i}"><inertial><origin xyz="0 0 -0.08"/><mass value="0.5"/>'
            '<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>'
            f'</link><joint name="leg{i}_fixed" type="fixed"><parent link="spoke{i}"/>'
            f'<child link="leg{i}"/></joint></robot>',
        )
    assert identify_urdf(text).structure == "Hexapod"


def planar_snake(modules: int) -> RobotText:
    """A chain of equal modules 0.15 m apart, every axis vertical, its first link fixed to a
    world link."""
    robot = RobotText("planar", root="world")
    link = robot.joint("world_joint", "fixed", "world", "m0")
    for i in range(1, modules + 1):
        link = builders.placed(robot, f"joint{i}", "revolute", link, f"m{i}", xyz="0.15 0 0")
    return robot


def test_a_long_chain_of_equal_modules_on_parallel_axes_fixed_to_the_world_is_a_planar_snake() -> (
    None
):
    result = identify_urdf(planar_snake(20).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert "parallel axes" in result.body.limbs[0].why
    assert result.structure == "Serpentine"


def test_a_short_planar_chain_of_equal_links_stays_an_arm() -> None:
    assert identify_urdf(planar_snake(6).text()).structure == "Manipulator"


def parallel_linkage_legs(*, meet: bool = True, yaw: str = "revolute") -> RobotText:
    """A humanoid whose legs each have a parallel copy: from one hip link (on a yaw joint of
    kind ``yaw``) a 3-joint leg and, 3.5 cm ahead of its first joint, a 2-joint copy turning
    about parallel axes whose end meets the leg's foot (``meet``) or stays 3.5 cm ahead of it."""
    robot = RobotText("parallel_legs", root="trunk")
    for side, y in (("left", 0.08), ("right", -0.08)):
        hip = builders.placed(
            robot, f"{side}_hip_yaw", yaw, "trunk", f"{side}_hip", xyz=f"0 {y} -0.05"
        )
        thigh = builders.placed(
            robot, f"{side}_hip_pitch", "revolute", hip, f"{side}_thigh", axis="0 1 0"
        )
        shank = builders.placed(
            robot,
            f"{side}_knee_pitch",
            "revolute",
            thigh,
            f"{side}_shank",
            xyz="0 0 -0.3",
            axis="0 1 0",
        )
        ankle = builders.placed(
            robot,
            f"{side}_ankle_pitch",
            "revolute",
            shank,
            f"{side}_ankle",
            xyz="0 0 -0.3",
            axis="0 1 0",
        )
        robot.joint(f"{side}_sole", "fixed", ankle, f"{side}_foot_plane")
        upper = builders.placed(
            robot,
            f"parallel_{side}_thigh",
            "revolute",
            hip,
            f"parallel_{side}_upper",
            xyz="0.035 0 0",
            axis="0 1 0",
        )
        lower = builders.placed(
            robot,
            f"parallel_{side}_shank",
            "revolute",
            upper,
            f"parallel_{side}_lower",
            xyz="0 0 -0.3",
            axis="0 1 0",
        )
        back = "-0.035" if meet else "0"
        robot.joint(
            f"parallel_{side}_sole",
            "fixed",
            lower,
            f"parallel_{side}_foot_plane",
            f'<origin xyz="{back} 0 -0.3"/>',
        )
    builders.arm(robot, "trunk", "l_", 3, gripper=False)
    builders.arm(robot, "trunk", "r_", 3, gripper=False)
    return robot


def test_a_legs_parallel_copy_whose_end_meets_its_foot_is_folded_into_the_leg() -> None:
    result = identify_urdf(parallel_linkage_legs().text())
    assert result.body is not None
    assert result.body.count("leg") == 2
    assert any("parallel-linkage" in limb.why for limb in result.body.limbs)
    assert result.structure == "Humanoid"


def test_a_legs_parallel_copy_whose_end_stays_apart_is_another_chain() -> None:
    # Bolted to the trunk, no hip's hinge of its own carries the two: only meeting ends join.
    result = identify_urdf(parallel_linkage_legs(meet=False, yaw="fixed").text())
    assert result.body is not None
    assert result.body.count("leg") == 4


def test_a_legs_parallel_copy_from_the_hinge_of_its_hip_is_folded_into_the_leg() -> None:
    result = identify_urdf(parallel_linkage_legs(meet=False).text())
    assert result.body is not None
    assert result.body.count("leg") == 2
    assert any("linkage's bar drawn open" in limb.why for limb in result.body.limbs)
    assert result.structure == "Humanoid"


def test_a_two_joint_chain_carrying_a_sensor_on_a_base_fixed_to_the_world_is_an_arm() -> None:
    """Two unnamed hinges on a link fixed to ``world``, a camera and a laser at the tip, nothing
    else: the base is bolted down and nothing else is there to point, so it is a short arm."""
    robot = RobotText("two_link", root="world")
    base = robot.fixed("world", "link1")
    tip = robot.chain(base, ["joint1", "joint2"])
    robot.fixed(tip, "cam")
    robot.add(builders.CAMERA)
    robot.add(builders.transmission("joint1"))
    robot.add(builders.transmission("joint2"))
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert "Joint" in {c.motion_control for c in result.motion_controls}


def test_a_two_joint_chain_of_no_limb_name_bolted_to_the_world_is_an_arm() -> None:
    """Two unnamed hinges on parallel axes from a link fixed to ``world``, nothing at the tip
    but an end link, driven through transmissions: a two-link teaching arm, not Other."""
    robot = RobotText("two_link", root="world")
    base = robot.fixed("world", "base_link")
    tip = robot.chain(base, ["joint_1", "joint_2"])
    robot.fixed(tip, "link_ee")
    robot.add(builders.transmission("joint_1"))
    robot.add(builders.transmission("joint_2"))
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert any("of no limb's name" in limb.why for limb in result.body.limbs)
    free = RobotText("two_link_free")
    free.fixed(free.chain(free.root, ["joint_1", "joint_2"]), "link_ee")
    assert identify_urdf(free.text()).structure == "Other"  # not bolted down: nothing says arm


@pytest.mark.parametrize("name", ["manipulator", "two_link_arm", "SimpleArm"])
def test_a_two_joint_chain_of_a_robot_named_an_arm_is_its_arm_though_not_bolted_down(
    name: str,
) -> None:
    # A class's teaching model: no world link, no controller, but its name says what it is.
    robot = RobotText(name)
    robot.fixed(robot.chain(robot.root, ["joint1", "joint2"]), "link_ee")
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert f"of a robot named {name}" in result.body.limbs[0].why


def test_a_two_joint_chain_named_as_an_arms_on_a_robot_named_an_arm_is_its_arm() -> None:
    # A turret and a boom: too short for its names (``arm_link``) to make it an arm, but the
    # robot's name says what it is.
    robot = RobotText("crane_arm")
    turret = robot.joint("joint_1", "revolute", robot.root, "turret_link")
    robot.joint("joint_2", "revolute", turret, "arm_link")
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert "named as an arm's" in result.body.limbs[0].why
    # Named as a head's, the same chain is no arm.
    head = RobotText("crane_arm")
    robot_neck = head.joint("neck_pan", "revolute", head.root, "neck_link")
    head.joint("head_tilt", "revolute", robot_neck, "head_link")
    assert identify_urdf(head.text()).structure != "Manipulator"


@pytest.mark.parametrize("name", ["leg_arm_rig", "double_pendulum"])
def test_a_two_joint_chain_of_a_robot_named_otherwise_or_for_a_walker_is_no_arm(name: str) -> None:
    robot = RobotText(name)
    robot.fixed(robot.chain(robot.root, ["joint1", "joint2"]), "link_ee")
    assert identify_urdf(robot.text()).structure != "Manipulator"


def test_a_two_joint_chain_every_joint_of_which_a_controller_drives_is_an_arm() -> None:
    # No world link: the controller on each joint says the base holds the chain to move it.
    robot = RobotText("leg_test_rig")
    robot.fixed(robot.chain(robot.root, ["rev1", "rev_2"]), "link_ee")
    for joint in ("rev1", "rev_2"):
        robot.add(builders.transmission(joint))
    assert identify_urdf(robot.text()).structure == "Manipulator"
    # One joint driven, the other free: no such evidence.
    half = RobotText("rig")
    half.fixed(half.chain(half.root, ["rev1", "rev_2"]), "link_ee")
    half.add(builders.transmission("rev1"))
    assert identify_urdf(half.text()).structure == "Other"


def base_with_two_hinges(*, second_axis: str = "0 1 0", reach: float = 0.3) -> RobotText:
    """A wheeled base carrying one unnamed chain of two hinges, the first about y, the second
    ``reach`` above it about ``second_axis``."""
    robot = builders.ugv()
    builders.placed(robot, "j1", "revolute", robot.root, "l1", xyz="0.3 0 0.2", axis="0 1 0")
    builders.placed(robot, "j2", "revolute", "l1", "l2", xyz=f"0 0 {reach}", axis=second_axis)
    return robot


def test_two_hinges_about_parallel_level_axes_on_a_wheeled_base_are_its_arm() -> None:
    result = identify_urdf(base_with_two_hinges().text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert "two-link arm" in result.body.limbs[0].why


def base_with_two_link_pair(*starts: str) -> RobotText:
    """A wheeled base carrying unnamed chains of two hinges about y, one starting at each of
    ``starts``, the second hinge 0.2 m above the first."""
    robot = builders.ugv()
    for side, xyz in zip("ab", starts, strict=True):
        link = builders.placed(
            robot, f"{side}1", "revolute", robot.root, f"{side}_l1", xyz=xyz, axis="0 1 0"
        )
        builders.placed(
            robot, f"{side}2", "revolute", link, f"{side}_l2", xyz="0 0 0.2", axis="0 1 0"
        )
    return robot


def test_two_two_link_arms_one_on_each_side_of_a_wheeled_base_are_its_arms() -> None:
    # A delivery base's two arms on its front corners, each two hinges about y, unnamed.
    robot = base_with_two_link_pair("0.3 0.2 0.2", "0.3 -0.2 0.2")
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm", "arm"]
    # Both on one side of the base: no pair of arms (a mast's hinges, a boom's).
    lopsided = base_with_two_link_pair("0.3 0.2 0.2", "-0.3 0.2 0.2")
    result = identify_urdf(lopsided.text())
    assert result.body is not None
    assert "arm" not in [limb.kind for limb in result.body.limbs]
    # On a tracked body the pair are its flippers.
    robot.add(builders.model_plugin("tracks", "libSimpleTrackedVehiclePlugin.so"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "arm" not in [limb.kind for limb in result.body.limbs]


@pytest.mark.parametrize(
    ("second_axis", "reach"),
    [
        ("0 0 1", 0.3),  # square axes: a pan and a tilt, no planar arm
        ("0 1 0", 0.03),  # two hinges on one bracket: no reach
    ],
)
def test_two_hinges_that_are_square_or_close_together_on_a_base_are_no_arm(
    second_axis: str, reach: float
) -> None:
    result = identify_urdf(base_with_two_hinges(second_axis=second_axis, reach=reach).text())
    assert result.body is not None
    assert "arm" not in [limb.kind for limb in result.body.limbs]


def waisted_humanoid(kind: str = "revolute") -> RobotText:
    """A small humanoid drawn from its feet up with every joint unnamed (``j0`` ..), each of
    ``kind`` with stops at +-90 degrees written: two six-joint legs hanging from the root to
    the floor, a waist turning a chest above them, and on the chest two four-joint arms and a
    neck."""
    robot = RobotText("kit")
    limit = '<limit lower="-1.5708" upper="1.5708" effort="1" velocity="1"/>'
    count = iter(range(100))

    def hinge(parent: str, xyz: str, axis: str) -> str:
        index = next(count)
        child = f"l{index}"
        shape = f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>{limit}'
        robot.joint(f"j{index}", kind, parent, child, shape)
        return child

    for y in (0.03, -0.03):
        link = hinge(robot.root, f"0 {y} 0.25", "0 0 1")
        for xyz, axis in (
            ("0.01 0 -0.02", "1 0 0"),
            ("0 0 -0.04", "0 1 0"),
            ("0 0 -0.065", "0 1 0"),
            ("0 0 -0.065", "0 1 0"),
            ("0.02 0 -0.04", "1 0 0"),
        ):
            link = hinge(link, xyz, axis)
    chest = hinge(robot.root, "0 0 0.3", "0 0 1")
    for y in (0.05, -0.05):
        link = hinge(chest, f"0 {y} 0.05", "0 1 0")
        for xyz, axis in (("0.015 0 0", "1 0 0"), ("0 0 -0.07", "0 0 1"), ("0 0 -0.015", "0 1 0")):
            link = hinge(link, xyz, axis)
    hinge(chest, "0 0 0.06", "0 0 1")
    return robot


@pytest.mark.parametrize("kind", ["revolute", "continuous"])
def test_a_small_unnamed_humanoid_whose_arms_hang_from_a_chest_on_a_waist_is_a_humanoid(
    kind: str,
) -> None:
    # Arms of four joints on a chest a waist turns are no hand's fingers: the legs' trunk
    # carries them. Continuous joints with stops written a quarter turn each way are hinges
    # (legs), not a caster's endless joints.
    result = identify_urdf(waisted_humanoid(kind).text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg", "other"]
    assert result.structure == "Humanoid"


def two_hinges_alone(
    *, axes: tuple[str, str] = ("0 0 1", "0 1 0"), reach: float = 0.02
) -> RobotText:
    """A body whose only limb is an unnamed chain of two hinges about ``axes``, the second
    ``reach`` above the first; no sensor, no world link."""
    robot = RobotText("bracket")
    builders.placed(robot, "j1", "revolute", robot.root, "l1", xyz="0 0 0.05", axis=axes[0])
    builders.placed(robot, "j2", "revolute", "l1", "l2", xyz=f"0 0 {reach}", axis=axes[1])
    return robot


@pytest.mark.parametrize("axes", [("0 0 1", "0 1 0"), ("0 1 0", "0 0 1")])
def test_two_square_hinges_close_together_as_a_bodys_only_limb_are_a_pan_tilt_unit(
    axes: tuple[str, str],
) -> None:
    # Pan then tilt, or tilt then pan, a servo bracket apart: no sensor named, still a head.
    result = identify_urdf(two_hinges_alone(axes=axes).text())
    assert result.structure == "Pan/Tilt Unit"
    assert result.body is not None
    assert "a pan/tilt unit" in result.body.limbs[0].why


def test_a_pan_on_the_base_tilting_what_it_holds_far_above_is_a_pan_tilt_unit() -> None:
    # A yoke: the upright hinge on the base, the square one 30 cm above it.
    result = identify_urdf(two_hinges_alone(axes=("0 0 1", "0 1 0"), reach=0.3).text())
    assert result.structure == "Pan/Tilt Unit"
    assert result.body is not None
    assert "the upright one on the base" in result.body.limbs[0].why


def locked(robot: RobotText, parent: str, child: str) -> None:
    """A hinge from ``parent`` to ``child`` 10 cm up, locked by limits of 0 to 0."""
    limits = '<limit lower="0" upper="0" effort="1" velocity="1"/>'
    robot.joint(f"{child}_lock", "revolute", parent, child, f'<origin xyz="0 0 0.1"/>{limits}')


def test_a_pan_and_a_tilt_with_a_third_hinge_locked_between_them_are_an_arm() -> None:
    # A modular arm's three modules, the middle one locked in its file.
    robot = RobotText("bracket")
    builders.placed(robot, "j1", "revolute", robot.root, "l1", xyz="0 0 0.05")
    locked(robot, "l1", "l2")
    builders.placed(robot, "j2", "revolute", "l2", "l3", xyz="0 0 0.15", axis="0 1 0")
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert "locked by its limits" in result.body.limbs[0].why
    # A mast's slide locked between them lifts the yoke: still a pan/tilt unit.
    mast = RobotText("bracket")
    builders.placed(mast, "j1", "revolute", mast.root, "l1", xyz="0 0 0.05")
    limits = '<limit lower="0" upper="0" effort="1" velocity="1"/>'
    mast.joint("lift", "prismatic", "l1", "l2", f'<origin xyz="0 0 0.1"/>{limits}')
    builders.placed(mast, "j2", "revolute", "l2", "l3", xyz="0 0 0.15", axis="0 1 0")
    assert identify_urdf(mast.text()).structure == "Pan/Tilt Unit"
    # Locked below the tilt (what it holds is bolted on so): still a yoke.
    yoke = two_hinges_alone(axes=("0 0 1", "0 1 0"), reach=0.3)
    locked(yoke, "l2", "l3")
    assert identify_urdf(yoke.text()).structure == "Pan/Tilt Unit"


@pytest.mark.parametrize(
    ("axes", "reach"),
    [
        (("0 1 0", "0 0 1"), 0.3),  # a tilt, then a pan far from it: no bracket, no yoke
        (("0 1 0", "0 1 0"), 0.02),  # parallel axes: no pan and tilt
    ],
)
def test_a_tilt_far_below_a_pan_or_parallel_hinges_alone_are_no_pan_tilt_unit(
    axes: tuple[str, str], reach: float
) -> None:
    result = identify_urdf(two_hinges_alone(axes=axes, reach=reach).text())
    assert result.structure != "Pan/Tilt Unit"


def test_the_same_chain_on_a_free_root_or_with_head_names_stays_a_pan_tilt_unit() -> None:
    free = RobotText("camera_mount")
    tip = free.chain(free.root, ["joint1", "joint2"])
    free.fixed(tip, "cam")
    free.add(builders.CAMERA)
    # Not bolted to the world, and no arm: a head aiming its camera.
    assert identify_urdf(free.text()).structure == "Pan/Tilt Unit"
    named = RobotText("ptu", root="world")
    tip = named.chain(named.fixed("world", "base"), ["pan_joint", "tilt_joint"])
    named.fixed(tip, "cam")
    named.add(builders.CAMERA)
    assert identify_urdf(named.text()).structure == "Pan/Tilt Unit"  # by its names


def concertina_snake(modules: int = 7, *, names: str = "revolute") -> RobotText:
    """A snake of one-joint modules 12 cm apart, every joint turning about z (it bends in the
    plane it crawls on), each module carrying two prismatic pads it presses down to anchor
    itself (a concertina gait). Only the last module's link has a word of a limb in its name
    (an author's label: a motor 'with no arms')."""
    robot = RobotText("concertina", root="m0")
    link = "m0"
    for i in range(1, modules + 1):
        for side, place in (("inner", "0.008 0.001 -0.057"), ("outer", "0.012 0.009 -0.057")):
            builders.placed(
                robot, f"{side}_pad_{i}", "prismatic", link, f"{side}_pad_link_{i}", xyz=place
            )
        if i < modules:
            child = "motor_with_no_arms" if i == modules - 1 else f"m{i}"
            link = builders.placed(robot, f"{names}_{i}", "revolute", link, child, xyz="0.12 0 0")
    return robot


def test_a_planar_chain_of_equal_modules_anchoring_on_sliding_pads_is_a_snakes_spine() -> None:
    result = identify_urdf(concertina_snake().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["spine"]
    assert len(result.body.limbs[0].joints) == 6
    assert result.structure == "Serpentine"
    roles = {role.joint: role.role for role in result.roles}
    assert {roles[f"{side}_pad_{i}"] for i in range(1, 8) for side in ("inner", "outer")} == {
        "passive"
    }


def test_a_planar_chain_named_as_an_arm_on_its_joints_is_no_spine_whatever_its_pads() -> None:
    result = identify_urdf(concertina_snake(names="arm").text())
    assert result.structure != "Serpentine"


def test_a_short_planar_chain_whose_leaves_turn_is_no_spine() -> None:
    # Leaf joints that turn (fingers, wheels) do not anchor a planar snake: 6 parallel joints of
    # equal links with them is no snake (planar snakes of bare modules need 8).
    text = concertina_snake().text().replace('type="prismatic"', 'type="revolute"')
    assert identify_urdf(text).structure != "Serpentine"


def test_a_spinning_leaf_beside_a_hexapods_legs_is_no_leg_of_it() -> None:
    parts = ['<link name="base_link"/>']
    for leg in range(6):
        x, y, above = (0.3, 0.0, -0.3)[leg // 2], (1, -1)[leg % 2], "base_link"
        for k, (xyz, axis) in enumerate(
            [
                (f"{x} {0.1 * y} 0", "0 0 1"),
                (f"0 {0.1 * y} 0", "1 0 0"),
                (f"0 {0.15 * y} 0", "1 0 0"),
            ]
        ):
            parts += [f'<link name="s{leg}_{k}"/>']
            parts += [
                builders.joint_xml(f"j{leg}_{k}", "revolute", above, f"s{leg}_{k}", xyz, axis)
            ]
            above = f"s{leg}_{k}"
        parts += [
            f'<link name="t{leg}"/>',
            builders.joint_xml(f"f{leg}", "fixed", above, f"t{leg}", "0 0 -0.2", "1 0 0"),
        ]
    parts += [
        '<link name="spin"/>',
        builders.joint_xml("spin_joint", "continuous", "base_link", "spin", "0 0 0.2", "0 0 1"),
    ]
    assert identify_urdf('<robot name="r">' + "".join(parts) + "</robot>").structure == "Hexapod"


def test_a_pan_tilt_unit_bolted_to_the_world_is_still_a_head() -> None:
    def bolted(first_axis: str) -> list[str]:
        text = (
            '<robot name="r"><link name="world"/><link name="l1"/><link name="l2"/>'
            + builders.joint_xml("joint1", "revolute", "world", "l1", "0 0 0.1", first_axis)
            + builders.joint_xml("joint2", "revolute", "l1", "l2", "0 0 0.1", "0 1 0")
            + '<gazebo reference="l2"><sensor name="cam" type="camera"/></gazebo></robot>'
        )
        body = identify_urdf(text).body
        assert body is not None
        return [limb.kind for limb in body.limbs]

    assert bolted("0 0 1") == ["head"]  # a pan, then a tilt: it points the camera
    assert bolted("0 1 0") == ["arm"]  # two parallel hinges carrying it: a short arm


def test_two_joints_both_named_as_an_arms_are_a_short_arm_on_a_base() -> None:
    """A tracked base carrying arm_1_joint and arm_2_joint (links arm1, arm2): a two-joint arm,
    so a mobile manipulator; the same two joints with no name of a limb stay the base's."""
    named = builders.ugv()
    named.chain(named.root, ["arm_1_joint", "arm_2_joint"])
    assert identify_urdf(named.text()).structure == "Mobile Manipulator"
    unnamed = builders.ugv()
    unnamed.chain(unnamed.root, ["joint_a", "joint_b"])
    assert identify_urdf(unnamed.text()).structure == "UGV"
    one = builders.ugv()
    one.chain(one.root, ["arm_joint", "tool_joint"])  # one arm word is a label, not a limb
    assert identify_urdf(one.text()).structure == "UGV"


def placed_chain(
    robot: RobotText,
    parent: str,
    prefix: str,
    *,
    start: str,
    steps: list[str],
    axis: str = "0 1 0",
    kind: str = "revolute",
) -> str:
    """Unnamed joints ``<prefix>0``.. of ``kind`` from ``parent``: the first at ``start``, then
    each at the offset of ``steps`` from the last."""
    link = builders.placed(robot, f"{prefix}0", kind, parent, f"{prefix}l0", xyz=start, axis=axis)
    for i, step in enumerate(steps, start=1):
        link = builders.placed(
            robot, f"{prefix}{i}", kind, link, f"{prefix}l{i}", xyz=step, axis=axis
        )
    return link


def nameless_humanoid(*, root: str = "pelvis", middle: float = 0.0) -> RobotText:
    """Links and joints named by letters only: from the root two six-joint chains hang 0.6 m
    straight down, two three-joint chains start 0.4 m higher and reach out sideways; the body's
    middle ``middle`` m across from the root's origin (a CAD export's frame off the middle)."""
    robot = RobotText("r", root=root)
    down = ["0 0 -0.1"] * 5
    for side, y in (("a", 0.1), ("b", -0.1)):
        placed_chain(robot, root, f"{side}j", start=f"0 {middle + y} -0.05", steps=down)
    for side, y in (("c", 0.2), ("d", -0.2)):
        placed_chain(
            robot,
            root,
            f"{side}j",
            start=f"0 {middle + y} 0.4",
            steps=[f"0 {y / 2} 0", f"0 {y / 2} 0"],
        )
    return robot


def test_two_unnamed_chains_hanging_straight_down_from_a_free_body_are_its_legs() -> None:
    result = identify_urdf(nameless_humanoid().text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]
    assert result.structure == "Humanoid"
    assert any("hanging straight down" in limb.why for limb in result.body.limbs)


def humanoid_rooted_in_its_chest() -> RobotText:
    """Letters only, the file's root the chest: a hinge about the vertical turns the hips
    0.2 m below it, two six-joint chains hang 0.6 m down from the hips; on the chest two
    three-joint chains start 0.15 m out each side and reach down, and a two-joint chain stands
    on top (arms and a neck)."""
    robot = RobotText("r", root="chest")
    hips = builders.placed(robot, "w", "revolute", "chest", "hips", xyz="0 0 -0.2", axis="0 0 1")
    for side, y in (("a", 0.08), ("b", -0.08)):
        placed_chain(robot, hips, f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.1"] * 5)
    for side, y in (("c", 0.15), ("d", -0.15)):
        placed_chain(robot, "chest", f"{side}j", start=f"0 {y} 0.1", steps=["0 0 -0.1"] * 2)
    placed_chain(robot, "chest", "n", start="0 0 0.15", steps=["0 0 0.05"])
    return robot


def test_arms_and_a_neck_on_a_chest_above_a_waist_turning_the_hips_are_no_fingers() -> None:
    # The legs hang from the hips a waist turns below the chest the file roots: the chains on
    # that chest are the walker's arms and neck, not a hand's fingers.
    result = identify_urdf(humanoid_rooted_in_its_chest().text())
    assert result.structure == "Humanoid"
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs).count("arm") == 2


def test_legs_whose_every_joint_is_written_continuous_with_no_limit_are_still_legs() -> None:
    # An old model writes every joint continuous: a chain of six endless joints is no caster
    # (a swivel and its wheel), and hangs as a leg does.
    text = nameless_humanoid().text().replace('type="revolute"', 'type="continuous"')
    text = re.sub("<limit [^>]*/>", "", text)
    assert 'type="revolute"' not in text
    assert "<limit" not in text
    result = identify_urdf(text)
    assert result.structure == "Humanoid"
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]


def test_endless_arms_hanging_at_rest_on_a_wheeled_base_stay_arms() -> None:
    # The same long endless chains beside wheels turning on the body: a base's arms at rest.
    robot = RobotText("r", root="torso")
    for side, y in (("a", 0.2), ("b", -0.2)):
        placed_chain(
            robot, "torso", f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.1"] * 4,
            kind="continuous",
        )  # fmt: skip
    for side, y in (("l", 0.25), ("r", -0.25)):
        builders.placed(
            robot, f"w{side}", "continuous", "torso", f"w{side}_link", xyz=f"0 {y} -0.6",
            axis="0 1 0",
        )  # fmt: skip
    assert identify_urdf(robot.text()).structure != "Biped"


def test_legs_hanging_side_by_side_about_a_middle_off_the_roots_origin_are_legs() -> None:
    # Hips at y = 0.16 and -0.04: not across the root's origin as far out each way, but at one
    # height and one place along the body, mirror images about the plane y = 0.06.
    result = identify_urdf(nameless_humanoid(middle=0.06).text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]
    assert result.structure == "Humanoid"


def test_legs_whose_first_joints_sit_at_the_pelvis_middle_are_told_apart_by_their_feet() -> None:
    # Both hips' first joints at one point on the middle line, each leg stepping out to its
    # side below it: the starts say no side, the feet do.
    robot = RobotText("r", root="pelvis")
    for side, y in (("a", 0.1), ("b", -0.1)):
        steps = [f"0 {y} -0.1", *["0 0 -0.1"] * 4]
        placed_chain(robot, "pelvis", f"{side}j", start="0 0 -0.05", steps=steps)
    for side, y in (("c", 0.2), ("d", -0.2)):
        placed_chain(
            robot, "pelvis", f"{side}j", start=f"0 {y} 0.4", steps=[f"0 {y / 2} 0", f"0 {y / 2} 0"]
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]
    assert result.structure == "Humanoid"


def test_a_bipeds_legs_are_found_though_its_hands_hang_lower_than_its_hips() -> None:
    # Arms hanging straight down at rest, each ending in a hand of three long fingers (five
    # joints each, as a hand with mimic knuckles has) whose bases are below the hips: chains
    # past an arm's joints are on no trunk, and say nothing of where arms start.
    robot = RobotText("r", root="pelvis")
    for side, y in (("a", 0.1), ("b", -0.1)):
        placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.1"] * 5)
    for side, y in (("c", 0.25), ("d", -0.25)):
        hand = placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} 0.4", steps=["0 0 -0.2"] * 3)
        for finger in range(3):
            placed_chain(
                robot,
                hand,
                f"{side}f{finger}",
                start=f"0.02 {0.01 * finger} -0.05",
                steps=["0 0 -0.01"] * 4,
            )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs].count("leg") == 2


def test_the_same_chains_on_a_body_bolted_to_the_world_stay_arms() -> None:
    robot = nameless_humanoid(root="world")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]


def test_a_world_holding_the_robot_fixed_beside_a_free_ball_still_bolts_it() -> None:
    robot = nameless_humanoid(root="world")
    builders.placed(robot, "ball_joint", "floating", "world", "ball", xyz="1 0 0.5")
    assert "leg" not in leg_kinds(robot)


def test_two_chains_hanging_from_a_body_a_world_holds_on_a_floating_joint_are_its_legs() -> None:
    # A simulator's world holds the free body it spawns 0.3 m up: the body, not the world, is
    # what the legs hang below; a floating joint bolts nothing.
    robot = RobotText("r", root="world")
    builders.placed(robot, "body_base", "floating", "world", "body", xyz="0 0 0.3")
    for side, y in (("a", 0.08), ("b", -0.08)):
        placed_chain(robot, "body", f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.12"] * 2)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg", "leg"]
    assert result.structure == "Biped"


def hanging_pair(name: str) -> RobotText:
    """A robot named ``name``: two unnamed six-joint chains hanging 0.6 m straight down, side
    by side, from a free body, nothing else."""
    robot = RobotText(name, root="body")
    for side, y in (("a", 0.1), ("b", -0.1)):
        placed_chain(robot, "body", f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.1"] * 5)
    return robot


def test_two_chains_hanging_from_a_free_body_are_a_bipeds_legs_when_no_name_says_otherwise() -> (
    None
):
    assert identify_urdf(hanging_pair("r").text()).structure == "Biped"


def test_the_same_chains_on_a_robot_named_for_its_arms_are_a_dual_arm_robots_arms() -> None:
    # A student's dual-arm robot (``two_arm_URDF``) drawn with its arms hanging at rest.
    result = identify_urdf(hanging_pair("two_arm_URDF").text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm", "arm"]
    assert result.structure == "Torso"


def test_a_robot_named_both_a_walker_and_an_arm_stands_on_its_hanging_chains() -> None:
    assert identify_urdf(hanging_pair("biped_with_arms").text()).structure == "Biped"


def pony(*, neck: bool = True) -> RobotText:
    """Four unnamed six-joint chains (too long for legs by place) hanging 0.3 m straight down
    from the corners of a free body, and a two-joint neck on its front pointing up."""
    robot = RobotText("r", root="body")
    for side, (x, y) in enumerate(((0.08, 0.04), (0.08, -0.04), (-0.08, 0.04), (-0.08, -0.04))):
        placed_chain(robot, "body", f"j{side}", start=f"{x} {y} -0.03", steps=["0 0 -0.05"] * 5)
    if neck:
        placed_chain(robot, "body", "n", start="0.09 0 0.02", steps=["0 0 0.05"])
    return robot


def test_four_unnamed_chains_hanging_straight_down_their_feet_level_are_a_quadrupeds_legs() -> None:
    # Four equal chains as low as one another: no biped's two legs beside two arms.
    result = identify_urdf(pony().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs].count("leg") == 4
    assert "feet level" in result.body.limbs[0].why
    assert result.structure == "Quadruped"


def test_a_nameless_humanoids_arms_hanging_straight_down_as_long_as_its_legs_stay_arms() -> None:
    # Six-joint arms hanging straight down from shoulders 0.45 m above the hips: their hands
    # end above the feet, so the body still stands on two legs.
    robot = RobotText("r", root="pelvis")
    for side, y in (("a", 0.1), ("b", -0.1)):
        placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} -0.05", steps=["0 0 -0.1"] * 5)
    for side, y in (("c", 0.25), ("d", -0.25)):
        placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} 0.4", steps=["0 0 -0.08"] * 5)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]
    assert result.structure == "Humanoid"


def hexapod_with_a_middle_pair_named_as_arms(*, middle_raised: bool = False) -> RobotText:
    """Six legs of a shoulder, an elbow and a knee spread flat from a box, the middle pair's
    words (``shoulder_middle_left``, ``elbow_middle_left``) an arm's; ``middle_raised``: the
    middle pair's knees held 0.3 m up."""
    robot = RobotText("hexapod", root="base_link")
    for row, x in (("front", 0.45), ("middle", 0.0), ("back", -0.45)):
        for side, y in (("left", 0.2), ("right", -0.2)):
            at = f"{row}_{side}"
            out = "0.24" if side == "left" else "-0.24"
            link = builders.placed(
                robot, f"shoulder_{at}_joint", "revolute", "base_link", f"shoulder_{at}",
                xyz=f"{x} {y} 0", axis="0 1 0",
            )  # fmt: skip
            lift = "0.3" if middle_raised and row == "middle" else "0"
            for part, z in (("elbow", "0"), ("knee", lift)):
                link = builders.placed(
                    robot, f"{part}_{at}_joint", "revolute", link, f"{part}_{at}",
                    xyz=f"0 {out} {z}", axis="-1 0 0",
                )  # fmt: skip
    return robot


def test_a_pair_built_as_the_legs_beside_it_and_standing_with_them_are_legs_whatever_their_words(
) -> None:  # fmt: skip
    result = identify_urdf(hexapod_with_a_middle_pair_named_as_arms().text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6
    assert any("built as the legs" in limb.why for limb in result.body.limbs)
    assert result.structure == "Hexapod"


def test_a_pair_built_as_the_legs_but_held_above_their_feet_stays_a_pair_of_arms() -> None:
    result = identify_urdf(hexapod_with_a_middle_pair_named_as_arms(middle_raised=True).text())
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm"] * 2 + ["leg"] * 4
    assert result.structure == "Legged Mobile Manipulator"


def test_an_arm_built_otherwise_than_the_legs_it_stands_beside_stays_an_arm() -> None:
    assert identify_urdf(builders.legged_manipulator().text()).structure == (
        "Legged Mobile Manipulator"
    )


def named_humanoid(*, lying: bool = False) -> RobotText:
    """A humanoid whose legs (hip, knee, ankle) and arms (shoulder, elbow, wrist) are built
    alike, three hinges 0.15 m apart each; ``lying``: drawn lying down, every limb reaching
    along -x and the torso 0.5 m along +x from the pelvis."""
    robot = RobotText("h", root="pelvis")
    torso = "0.5 0 0" if lying else "0 0 0.5"
    robot.joint("waist", "fixed", "pelvis", "torso", f'<origin xyz="{torso}"/>')
    step = "-0.15 0 0" if lying else "0 0 -0.15"
    for side, y in (("l", 0.1), ("r", -0.1)):
        for body, words, across in (
            ("pelvis", ("hip", "knee", "ankle"), y),
            ("torso", ("shoulder", "elbow", "wrist"), 2 * y),
        ):
            link, xyz = body, f"0 {across} 0"
            for word in words:
                link = builders.placed(
                    robot, f"{side}_{word}", "revolute", link, f"{side}_{word}_link", xyz=xyz,
                    axis="0 1 0",
                )  # fmt: skip
                xyz = step
            robot.joint(f"{side}_{words[-1]}_end", "fixed", link, f"{side}_{words[-1]}_tip",
                        f'<origin xyz="{step}"/>')  # fmt: skip
    return robot


def test_a_humanoid_drawn_lying_down_keeps_its_arms_built_as_its_legs() -> None:
    # Every tip is level when the body lies down: two legs reaching sideways say nothing of
    # where feet stand, and arms built as the legs stay arms.
    for lying in (False, True):
        assert identify_urdf(named_humanoid(lying=lying).text()).structure == "Humanoid"


def test_a_chain_named_as_an_arm_built_as_the_legs_stays_an_arm() -> None:
    robot = hexapod_with_a_middle_pair_named_as_arms()
    link = builders.placed(
        robot, "arm_base_joint", "revolute", "base_link", "arm_base", xyz="0.3 0 0", axis="0 1 0"
    )
    for part in ("arm_elbow", "arm_wrist"):
        link = builders.placed(
            robot, f"{part}_joint", "revolute", link, part, xyz="0 0.24 0", axis="-1 0 0"
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs].count("arm") == 1
    assert result.structure == "Legged Mobile Manipulator"


def small_humanoid() -> RobotText:
    """The nameless humanoid's legs, with two-joint arms (a small humanoid's) and a two-joint
    neck on the body: three short chains on one link, as a hand's fingers are."""
    robot = RobotText("r", root="pelvis")
    down = ["0 0 -0.1"] * 5
    for side, y in (("a", 0.1), ("b", -0.1)):
        placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} -0.05", steps=down)
    for side, y in (("c", 0.2), ("d", -0.2)):
        placed_chain(robot, "pelvis", f"{side}j", start=f"0 {y} 0.4", steps=[f"0 {y / 2} 0"])
    placed_chain(robot, "pelvis", "nj", start="0 0 0.5", steps=["0 0 0.05"], axis="0 0 1")
    return robot


def test_short_chains_on_the_trunk_a_bipeds_legs_hang_from_are_its_arms_and_neck() -> None:
    result = identify_urdf(small_humanoid().text())
    assert result.body is not None
    assert (result.body.grippers, result.body.fingers) == (0, ())  # no hand on a trunk on legs
    arms = [limb for limb in result.body.limbs if limb.kind == "arm"]
    assert sorted(limb.joints[0] for limb in arms) == ["cj0", "dj0"]
    assert all("mirrored" in limb.why for limb in arms)
    assert result.structure == "Humanoid"


def test_two_mirrored_chains_are_no_arms_without_a_bipeds_legs_below_them() -> None:
    robot = RobotText("r")
    for side, y in (("c", 0.2), ("d", -0.2)):
        placed_chain(robot, robot.root, f"{side}j", start=f"0 {y} 0.4", steps=[f"0 {y / 2} 0"])
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "arm" not in [limb.kind for limb in result.body.limbs]


def folded_quadruped(*, tracked: bool = False) -> RobotText:
    """Four unnamed three-joint chains at the corners of a body, each folded flat in the zero
    pose (the tip back level with the hip); ``tracked`` adds a tracked-vehicle plugin."""
    robot = RobotText("r")
    for i, (x, y) in enumerate(((0.3, 0.1), (0.3, -0.1), (-0.3, 0.1), (-0.3, -0.1))):
        placed_chain(
            robot,
            robot.root,
            f"k{i}_",
            start=f"{x} {y} 0",
            steps=[f"0 {y / 2} 0", "-0.2 0 0", "0.2 0 0"],
        )
    if tracked:
        robot.add(builders.model_plugin("tracks", "libSimpleTrackedVehiclePlugin.so"))
    return robot


def hexapod_facing_y() -> RobotText:
    """Six unnamed three-joint chains folded flat on a body drawn with its length along y, each
    tip back over its hip: the middle pair on the x line, the others at the corners (left and
    right along x)."""
    robot = RobotText("r")
    hips = ((0.064, 0.0), (0.057, 0.066), (0.057, -0.066))
    for i, (x, y) in enumerate([*hips, *((-x, y) for x, y in hips)]):
        placed_chain(
            robot,
            robot.root,
            f"k{i}_",
            start=f"{x} {y} 0",
            steps=[f"{x / 2} 0 0", "0 -0.05 0", f"{-x / 2} 0.05 0"],
        )
    return robot


def test_alike_chains_starting_in_mirrored_pairs_at_a_bodys_corners_are_legs_however_folded() -> (
    None
):
    result = identify_urdf(folded_quadruped().text())
    assert result.structure == "Quadruped"
    assert result.body is not None
    assert "corners" in result.body.limbs[0].why
    # Six drawn with the body's length along y (no pair mirrored across x's line): legs too.
    assert identify_urdf(hexapod_facing_y().text()).structure == "Hexapod"
    # Four in a square two fingers' width apart are paired across x's line and not spread
    # along it: not tried facing y, no walker's hips.
    square = RobotText("r")
    for i, (x, y) in enumerate(((0.01, 0.04), (0.01, -0.04), (-0.01, 0.04), (-0.01, -0.04))):
        placed_chain(
            square, square.root, f"k{i}_", start=f"{x} {y} 0", steps=[f"0 {y / 2} 0", "-0.02 0 0"]
        )
    assert identify_urdf(square.text()).structure != "Quadruped"
    # On a body tracks move, chains at its corners are flippers, not legs.
    tracked = identify_urdf(folded_quadruped(tracked=True).text())
    assert tracked.body is not None
    assert "leg" not in [limb.kind for limb in tracked.body.limbs]


def upright_four_limbs(*, facing_y: bool = False) -> RobotText:
    """Four alike unnamed four-joint chains on one torso link, z up: shoulders 0.1 m out at
    0.15 m, hips 0.05 m out at -0.1 m, every chain hanging down (``facing_y``: x and y
    swapped)."""
    robot = RobotText("mini")
    places = [(0.1, 0.15), (-0.1, 0.15), (0.05, -0.1), (-0.05, -0.1)]
    for i, (side, height) in enumerate(places):
        start = f"{side} 0 {height}" if facing_y else f"0 {side} {height}"
        drop = -0.06 if height > 0 else -0.08
        placed_chain(robot, robot.root, f"k{i}_", start=start, steps=[f"0 0 {drop}"] * 3)
    return robot


def test_four_alike_unnamed_chains_at_the_corners_of_an_upright_body_are_a_humanoids_limbs() -> (
    None
):
    # Shoulders and hips are at the corners of a plane too, the upright one: a reading of the
    # corners in any plane (a quadruped a CAD export drew y up) would make this a quadruped; it
    # was tried and taken back (docs/identify-journal.md, Fresh set 53).
    assert identify_urdf(upright_four_limbs().text()).structure == "Humanoid"
    assert identify_urdf(upright_four_limbs(facing_y=True).text()).structure == "Humanoid"


def test_a_hexapods_coxa_femur_and_tibia_abbreviated_are_leg_names() -> None:
    leg = load_profile().pattern("leg")
    assert leg is not None
    for name in ("R_M_COX_joint", "L_F_FEM_link", "r3/tib", "coxa_2"):
        assert leg.search(name), name
    for name in ("female_connector", "tibet_camera", "box_link"):
        assert not leg.search(name), name


def test_leg_inside_a_hand_makers_name_names_no_leg() -> None:
    leg = load_profile().pattern("leg")
    assert leg is not None
    for name in ("LLEG_JOINT0", "legRF_joint", "FL_leg", "left_leg", "leg", "rleg_ro"):
        assert leg.search(name), name
    for name in ("l_allegro_joint_12", "allegro_hand_link_3.0", "allegro"):
        assert not leg.search(name), name


def test_a_hand_named_for_its_maker_is_a_hand_not_four_legs() -> None:
    # Four fingers named l_allegro_joint_0 .. 15 on a palm: no leg word in them.
    robot = RobotText("hand", root="l_allegro_base_link")
    for finger in range(4):
        robot.chain(robot.root, [f"l_allegro_joint_{4 * finger + k}" for k in range(4)])
    assert identify_urdf(robot.text()).structure == "Hand"


def test_a_continuous_track_plugin_moves_a_body_on_tracks_too() -> None:
    """The ContinuousTrack Gazebo plugin drives tracks: chains at the corners are flippers."""
    robot = folded_quadruped()
    robot.add(builders.model_plugin("track", "libContinuousTrack.so"))
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]
    assert result.body.mobile_base


def test_corner_named_chains_on_a_body_tracks_move_are_flippers_not_legs() -> None:
    # Two crawler joints (track names) and four two-joint chains named by their corner
    # (front_left_flipper ..), each a flipper and its sprocket: a tracked base.
    robot = RobotText("crawler")
    for side, y in (("left", 0.1), ("right", -0.1)):
        builders.placed(
            robot,
            f"{side}_crawler_joint",
            "continuous",
            robot.root,
            f"{side}_crawler",
            xyz=f"0 {y} 0",
            axis="0 1 0",
        )
        for end, x in (("front", 0.2), ("rear", -0.2)):
            flipper = builders.placed(
                robot,
                f"{end}_{side}_flipper_joint",
                "revolute",
                robot.root,
                f"{end}_{side}_flipper",
                xyz=f"{x} {y * 1.6} 0",
                axis="0 1 0",
            )
            builders.placed(
                robot,
                f"{end}_{side}_sprocket",
                "continuous",
                flipper,
                f"{end}_{side}_sprocket_l",
                xyz="0.2 0 0",
                axis="0 1 0",
            )
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]
    assert any(limb.why.startswith("a flipper") for limb in result.body.limbs)


def rover_with_panels(
    *, panel_z: float | None, wheels: tuple[float, ...] = (0.5, 0.0, -0.5), front_z: float = -0.15
) -> RobotText:
    """A pair of wheels on the body's sides at each x of ``wheels`` (the first pair's axle at
    ``front_z``, the others' at -0.15; three wheels when one x is given as ``-x``: a tricycle's
    front wheel alone) and two two-joint panels named by their corner (``panel_back_left`` ..)
    hinged at ``panel_z`` above the body's origin (none: no panels)."""
    robot = RobotText("rover")
    for i, x in enumerate(wheels):
        sides = (("mid", 0.0),) if x < 0 and i == 0 else (("left", 0.4), ("right", -0.4))
        for side, y in sides:
            builders.placed(
                robot,
                f"drive_{i}_{side}",
                "continuous",
                robot.root,
                f"wheel_{i}_{side}",
                xyz=f"{abs(x)} {y} {front_z if i == 0 else -0.15}",
                axis="0 1 0",
            )
    robot.fixed(robot.root, "panel_top")
    for side, y in (("left", 0.3), ("right", -0.3)) if panel_z is not None else ():
        centre = builders.placed(
            robot,
            f"panel_center_{side}_joint",
            "revolute",
            "panel_top",
            f"panel_center_{side}",
            xyz=f"0 {y} {panel_z}",
            axis="1 0 0",
        )
        builders.placed(
            robot,
            f"panel_back_{side}_joint",
            "revolute",
            centre,
            f"panel_back_{side}",
            xyz=f"-0.4 {y} 0",
            axis="1 0 0",
        )
    return robot


def leg_kinds(robot: RobotText) -> list[str]:
    result = identify_urdf(robot.text())
    assert result.body is not None
    return [limb.kind for limb in result.body.limbs]


def test_corner_named_chains_above_the_axles_of_a_wheeled_body_are_no_legs() -> None:
    result = identify_urdf(rover_with_panels(panel_z=0.5).text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]
    # Hanging below the axles, they may reach the ground: legs still.
    assert leg_kinds(rover_with_panels(panel_z=-0.3)).count("leg") == 2
    # Three wheels are enough to roll on (a tricycle's front wheel and a rear pair).
    assert "leg" not in leg_kinds(rover_with_panels(panel_z=0.5, wheels=(-0.5, -0.5)))
    # Above every axle: a pair of wheels drawn higher (0.2) keeps tips at 0.0 legs.
    assert leg_kinds(rover_with_panels(panel_z=0.0, front_z=0.2)).count("leg") == 2


def test_legs_named_as_legs_above_the_axles_of_a_cart_stay_legs() -> None:
    # A humanoid standing on a four-wheeled cart: its hips, knees and ankles say legs.
    robot = rover_with_panels(panel_z=None, wheels=(0.3, -0.3))
    robot.fixed(robot.root, "pelvis")
    for side, y in (("left", 0.1), ("right", -0.1)):
        placed_chain(robot, "pelvis", f"{side}_hip", start=f"0 {y} 0.9", steps=["0 0 -0.3"] * 2)
        placed_chain(
            robot, "pelvis", f"{side}_shoulder", start=f"0 {y * 2} 1.4", steps=["0 0 -0.25"] * 2
        )
    assert leg_kinds(robot).count("leg") == 2


def test_legs_drawn_raised_beside_two_wheel_modules_are_still_legs() -> None:
    # Two wheel modules of two joints each (four joints read as wheels, two wheels that turn
    # as leaves) and four legs named by their corners drawn with their feet up: a leg-and-wheel
    # hybrid.
    robot = RobotText("hybrid")
    for side, y in (("a", 0.2), ("b", -0.2)):
        hip = builders.placed(
            robot,
            f"wheel_{side}_j1",
            "continuous",
            robot.root,
            f"wheel_{side}_l1",
            xyz=f"0 {y} 0",
            axis="0 1 0",
        )
        builders.placed(
            robot,
            f"wheel_{side}_j2",
            "continuous",
            hip,
            f"wheel_{side}_l2",
            xyz="0 0 -0.1",
            axis="0 1 0",
        )
    corners = {"front_left": (0.2, 0.15), "front_right": (0.2, -0.15)}
    corners |= {"rear_left": (-0.2, 0.15), "rear_right": (-0.2, -0.15)}
    for i, (x, y) in corners.items():
        top = builders.placed(robot, f"{i}_j1", "revolute", robot.root, f"{i}_l1", xyz=f"{x} {y} 0")
        knee = builders.placed(
            robot, f"{i}_j2", "revolute", top, f"{i}_l2", xyz="0.1 0 0.05", axis="0 1 0"
        )
        builders.placed(
            robot, f"{i}_j3", "revolute", knee, f"{i}_tip", xyz="0.1 0 0.05", axis="0 1 0"
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs].count("leg") == 4


def test_a_leg_named_chain_ending_in_a_gripper_above_the_wheels_is_still_an_arm() -> None:
    robot = rover_with_panels(panel_z=None)
    tip = robot.chain(robot.root, ["leg1_2_joint", "leg2_3_joint", "leg3_4_joint"])
    for jaw in ("claw_top_joint", "claw_bottom_joint"):
        builders.placed(robot, jaw, "prismatic", tip, jaw.replace("_joint", ""), xyz="0 0 0.6")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "arm" in [limb.kind for limb in result.body.limbs]


def forearm_hand_on(wrist_joints: list[str]) -> RobotText:
    """Five three-joint fingers on a palm, the palm on ``wrist_joints`` from a free forearm."""
    robot = RobotText("hand", root="forearm")
    wrist_link = robot.chain("forearm", wrist_joints)
    robot.joint("palm_fixed", "fixed", wrist_link, "palm")
    for finger in ("ff", "mf", "rf", "lf", "th"):
        robot.chain("palm", [f"{finger}j3", f"{finger}j2", f"{finger}j1"])
    return robot


def test_three_joints_named_as_a_wrists_under_a_whole_hand_are_its_wrist_not_an_arm() -> None:
    named = forearm_hand_on(["wrist_pitch_lower", "wrist_yaw", "wrist_pitch_upper"])
    assert identify_urdf(named.text()).structure == "Hand"
    # Three joints of no wrist's name under the same hand are an arm carrying it.
    assert identify_urdf(forearm_hand_on(["j1", "j2", "j3"]).text()).structure == "Manipulator"


def test_thousands_of_chains_above_a_bipeds_hips_are_read_without_comparing_every_pair() -> None:
    # Its arms are looked for among a few chains only (6,400 took 13 s pair by pair).
    crowd = small_humanoid()
    for i in range(5_000):
        placed_chain(
            crowd, "pelvis", f"x{i}", start=f"0.1 {0.3 + i / 1e4} 0.45", steps=["0 0.05 0"]
        )
    assert identify_urdf(crowd.text()).structure


def walker_drawn_from_a_corner(
    hips: tuple[tuple[float, float], ...] = (
        (0.0, -0.05),
        (0.0, -0.25),
        (0.25, -0.05),
        (0.25, -0.25),
    ),
) -> RobotText:
    """Four unnamed two-joint chains hanging down from ``hips`` (x, y), every hip on one side of
    the body link's origin (a CAD export whose origin is a corner of the body)."""
    robot = RobotText("Assem")
    for i, (x, y) in enumerate(hips):
        placed_chain(robot, robot.root, f"c{i}_", start=f"{x} {y} 0.1", steps=["0.02 0 -0.1"])
    return robot


def test_chains_hanging_down_left_and_right_of_their_middle_are_legs_wherever_the_origin_is() -> (
    None
):
    result = identify_urdf(walker_drawn_from_a_corner().text())
    assert result.structure == "Quadruped"
    assert result.body is not None
    assert "legs by place" in result.body.limbs[0].why
    # Four in one row along the body (one place across it) are no walker's hips.
    row = identify_urdf(
        walker_drawn_from_a_corner(tuple((x, -0.1) for x in (0, 0.1, 0.2, 0.3))).text()
    )
    assert row.structure != "Quadruped"


def nameless_humanoid_drawn_from_its_feet(
    *,
    arms: bool = True,
    facing_y: bool = False,
    hands: bool = False,
    upper: bool = True,
    aside: float = 0.0,
) -> RobotText:
    """Letters only, the root's frame at the feet: two six-joint chains hang straight down
    from hips 0.5 m up to 0.05 m; above them two five-joint chains hang from shoulders 0.75 m
    up (``arms``), or two one-joint ears turn on a head, or nothing (``upper`` False: a lower
    body). ``facing_y``: left and right along x; ``hands``: each arm ends in a gripper's jaw;
    ``aside``: the body's middle this far to the left of the root's frame (a CAD export)."""

    def across(offset: float) -> str:
        offset += aside
        return f"{offset} 0" if facing_y else f"0 {offset}"

    robot = RobotText("r")
    for side, y in (("a", 0.08), ("b", -0.08)):
        start = f"{across(y)} 0.5"
        placed_chain(robot, robot.root, f"{side}j", start=start, steps=["0 0 -0.09"] * 5)
    for side, y in (("c", 0.18), ("d", -0.18)) if upper else ():
        steps = ["0 0 -0.06"] * 4 if arms else []
        tip = placed_chain(robot, robot.root, f"{side}j", start=f"{across(y)} 0.75", steps=steps)
        if hands:
            robot.chain(tip, [f"{side}_gripper_joint"])
    return robot


def test_legs_hang_from_the_hips_below_a_pair_of_arms_though_the_root_is_drawn_at_the_feet() -> (
    None
):
    result = identify_urdf(nameless_humanoid_drawn_from_its_feet().text())
    assert result.structure == "Humanoid"
    # Drawn with left and right along x, its arms ending in grippers: the same humanoid.
    drawn = nameless_humanoid_drawn_from_its_feet(facing_y=True, hands=True)
    assert identify_urdf(drawn.text()).structure == "Humanoid"
    # Above them only a head's two one-joint ears: nothing says these are legs, not arms
    # hanging down a torso standing on its root.
    assert identify_urdf(
        nameless_humanoid_drawn_from_its_feet(arms=False).text()
    ).structure not in (
        "Biped",
        "Humanoid",
    )


def test_arms_mirrored_about_the_legs_middle_off_the_roots_frame_make_the_legs_a_humanoids() -> (
    None
):
    # A CAD export whose frame is at the feet and off to one side of the body: the arms are
    # mirrored about the plane the hips are, not about the frame.
    drawn = nameless_humanoid_drawn_from_its_feet(aside=0.3)
    assert identify_urdf(drawn.text()).structure == "Humanoid"
    drawn = nameless_humanoid_drawn_from_its_feet(aside=0.3, facing_y=True)
    assert identify_urdf(drawn.text()).structure == "Humanoid"
    # Ears on a head still say nothing, wherever the frame is; nor, off the frame, do two
    # chains of two hinges (a head's antennae or eyes as well as arms).
    ears = nameless_humanoid_drawn_from_its_feet(arms=False, aside=0.3)
    assert identify_urdf(ears.text()).structure not in ("Biped", "Humanoid")
    robot = nameless_humanoid_drawn_from_its_feet(upper=False, aside=0.3)
    for side, y in (("c", 0.48), ("d", 0.12)):
        placed_chain(robot, robot.root, f"{side}j", start=f"0 {y} 0.75", steps=["0 0 -0.06"])
    assert identify_urdf(robot.text()).structure not in ("Biped", "Humanoid")


def test_two_chains_hanging_to_the_feet_of_a_root_drawn_there_with_nothing_else_are_legs() -> None:
    # A lower body exported from the floor up: its two legs are all it has. Nothing hangs
    # beside them that could be a torso's arms, and they reach down to the root's frame.
    result = identify_urdf(nameless_humanoid_drawn_from_its_feet(upper=False).text())
    assert result.structure == "Biped"


def hanging_from(joints: list[tuple[str, str]]) -> RobotText:
    """Two six-joint chains hanging straight down from shoulders 0.5 m up to a hand's breadth
    below the root, on a body that ``joints`` (kind, axis each) carry from the root."""
    robot = RobotText("r")
    body = robot.root
    for i, (kind, axis) in enumerate(joints):
        body = builders.placed(robot, f"w{i}", kind, body, f"torso{i}", axis=axis)
    for side, y in (("a", 0.08), ("b", -0.08)):
        placed_chain(robot, body, f"{side}j", start=f"0 {y} 0.5", steps=["0 0 -0.09"] * 5)
    return robot


def test_two_chains_hanging_from_a_waist_that_turns_on_a_pedestal_are_a_torsos_arms() -> None:
    # A torso on a pedestal: one hinge about the vertical turns it on the root, and its two
    # six-joint arms hang at rest down to the pedestal. The same two chains on the root's own
    # body are a lower body drawn from the floor up (above).
    assert identify_urdf(hanging_from([("revolute", "0 0 1")]).text()).structure == "Torso"


@pytest.mark.parametrize(
    "joints",
    [
        [("revolute", "0 1 0")],
        [("prismatic", "0 0 1")],
        [("revolute", "0 1 0"), ("revolute", "0 0 1")],
    ],
    ids=["a hinge about a level axis", "a vertical slide", "a vertical hinge not on the root"],
)
def test_two_chains_hanging_from_a_body_no_waist_turns_on_the_root_stay_legs(
    joints: list[tuple[str, str]],
) -> None:
    assert identify_urdf(hanging_from(joints).text()).structure == "Biped"


def test_a_shoulder_written_shld_names_an_arm_as_shoulder_does() -> None:
    robot = RobotText("r")
    builders.wheeled_base(robot, 4)
    for side in ("lt", "rt"):
        robot.chain(robot.root, [f"joint_shld_{side}", f"joint_arm_{side}"])
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    # A word that only holds the letters is no shoulder.
    other = RobotText("r")
    builders.wheeled_base(other, 4)
    for side in ("lt", "rt"):
        other.chain(other.root, [f"joint_bshldr_{side}", f"joint_x_{side}"])
    assert identify_urdf(other.text()).structure == "UGV"


def fingers_hanging_down(
    *, level: bool, arm_joints: int = 0, arm_kind: str = "revolute"
) -> RobotText:
    """Five unnamed three-joint chains hanging down from a palm, their bases in a row across it;
    their tips end at their own lengths (a hand) or, with ``level``, at one height. The palm is
    the root, or the end of an unnamed arm of ``arm_joints`` joints of ``arm_kind`` reaching
    out sideways."""
    robot = RobotText("r")
    palm = robot.root
    if arm_joints:
        steps = ["0 0.1 0"] * (arm_joints - 1)
        palm = placed_chain(robot, palm, "a", start="0 0.2 0.3", steps=steps, kind=arm_kind)
    for i, y in enumerate((-0.04, -0.02, 0.0, 0.02, 0.04)):
        step = 0.03 if level else 0.015 + 0.01 * i
        placed_chain(robot, palm, f"f{i}_", start=f"0.25 {y} -0.05", steps=[f"0 0 -{step}"] * 2)
    return robot


def test_chains_hanging_down_are_legs_only_when_their_feet_are_level() -> None:
    assert identify_urdf(fingers_hanging_down(level=False).text()).structure == "Hand"
    assert identify_urdf(fingers_hanging_down(level=True).text()).structure == "Hexapod"


@pytest.mark.parametrize(("joints", "kind"), [(7, "revolute"), (4, "revolute"), (4, "continuous")])
def test_chains_hanging_level_from_the_end_of_an_arm_are_its_fingers_not_legs(
    joints: int, kind: str
) -> None:
    # Legs hang from the trunk (the body, a waist above it); past an arm's joints (more than
    # three that turn), alike chains hanging down are a hand's fingers, however level their tips.
    robot = fingers_hanging_down(level=True, arm_joints=joints, arm_kind=kind)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert "leg" not in [limb.kind for limb in result.body.limbs]
    assert result.structure != "Hexapod"


def test_a_walker_on_a_simulators_six_joint_floating_base_still_stands_on_its_legs() -> None:
    # Three slides and three turns above the body are how a simulator floats it, no arm.
    assert identify_urdf(builders.walker(4, simulated_base=True).text()).structure == "Quadruped"


def test_chains_hanging_in_a_row_are_no_walkers_legs_however_the_row_lies() -> None:
    # Four pick heads (a slide and a spin each) in a row across a carriage.
    tool = RobotText("pick_tool", root="carriage")
    for i, y in enumerate((0.05, 0.10, 0.15, 0.20)):
        head = builders.placed(
            tool, f"h{i}_z", "prismatic", "carriage", f"h{i}_slide", xyz=f"0 {y} -0.05"
        )
        builders.placed(tool, f"h{i}_r", "revolute", head, f"h{i}_nozzle", xyz="0 0 -0.1")
    assert identify_urdf(tool.text()).structure != "Quadruped"
    # Four fingers in a row along the palm, a CAD export's microns of jitter across it.
    hand = RobotText("hand", root="base")
    for i, x in enumerate((0.0, 0.02, 0.04, 0.06)):
        placed_chain(
            hand,
            "base",
            f"f{i}_",
            start=f"{x} {0.000002 * i} -0.08",
            steps=["0 0 -0.04", "0 0 -0.03"],
        )
    assert identify_urdf(hand.text()).structure != "Quadruped"


def test_a_hexapod_drawn_facing_y_from_a_corner_stands_on_six_legs() -> None:
    # Hips in two columns along x and three rows along y, the origin at a corner hip.
    robot = RobotText("r")
    for i, (x, y) in enumerate((x, y) for x in (0.01, 0.14) for y in (0.01, 0.125, 0.24)):
        placed_chain(
            robot, robot.root, f"c{i}_", start=f"{x} {y} 0.0", steps=["0 0 -0.05", "0 0 -0.05"]
        )
    assert identify_urdf(robot.text()).structure == "Hexapod"


def test_a_dual_arm_pedestal_with_camera_heads_above_is_no_biped() -> None:
    # The root on the floor; two six-joint arms hang from shoulders 1.2 m up, ending 0.7 m
    # above the root; above them two pan/tilt camera mounts.
    robot = RobotText("r", root="base")
    column = robot.fixed("base", "column")
    for side, y in (("a", 0.25), ("b", -0.25)):
        placed_chain(robot, column, f"{side}j", start=f"0 {y} 1.2", steps=["0 0 -0.1"] * 5)
    for side, y in (("c", 0.08), ("d", -0.08)):
        tip = placed_chain(
            robot, column, f"{side}j", start=f"0.1 {y} 1.5", steps=["0 0 0.05"], axis="0 0 1"
        )
        robot.add(builders.gazebo_sensor(tip, "camera", f"cam_{side}"))
    assert identify_urdf(robot.text()).structure not in ("Biped", "Humanoid")


def test_two_legs_hanging_side_by_side_across_x_are_a_biped_drawn_facing_y() -> None:
    robot = RobotText("r", root="torso")
    for side, x in (("a", 0.15), ("b", -0.15)):
        placed_chain(
            robot,
            robot.root,
            f"{side}j",
            start=f"{x} 0 0",
            steps=["0 0 -0.13", "0 0 -0.4", "0 0 -0.4"],
        )
    assert identify_urdf(robot.text()).structure == "Biped"


def delta_chains(legs: int, reach: float) -> tuple[list[str], list[str]]:
    """The links and joints of ``legs`` two-joint chains named as legs on ``base_link``, evenly
    around 0.2 m out, each ending ``reach`` of the way back in toward the middle, 0.3 m below
    (``reach`` 1: all tips at the middle, a delta holding one platform)."""
    links, joints = [], []
    for i in range(legs):
        angle = 2 * math.pi * i / legs
        x, y = 0.2 * math.cos(angle), 0.2 * math.sin(angle)
        back = (-x * reach, -y * reach)
        links += [f"upper_leg_{i}", f"lower_leg_{i}"]
        joints.append(
            builders.joint_xml(
                f"motor_{i}", "revolute", "base_link", f"upper_leg_{i}", f"{x} {y} 0", "0 1 0"
            )
        )
        joints.append(
            builders.joint_xml(
                f"elbow_{i}",
                "revolute",
                f"upper_leg_{i}",
                f"lower_leg_{i}",
                f"{back[0]} {back[1]} -0.3",
                "0 1 0",
            )
        )
    return links, joints


def delta(reach: float) -> str:
    """A base with three of :func:`delta_chains`, their tips ``reach`` of the way in."""
    links, joints = delta_chains(3, reach)
    body = "".join(f'<link name="{link}"/>' for link in ["base_link", *links]) + "".join(joints)
    return f'<robot name="parallel">{body}</robot>'


def test_three_legs_whose_tips_meet_are_one_parallel_manipulator() -> None:
    result = identify_urdf(delta(reach=1.0))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm", "other", "other"]


def tucked_hexapod() -> str:
    """Six legs named by their parts (a hip yaw about the vertical, two pitches), drawn folded
    so that every foot lies tucked under the middle of the body (a morphing hexapod's ball)."""

    def places(x: float, y: float) -> tuple[tuple[str, str], ...]:
        x, y = 0.1 * x, 0.1 * y
        return ((f"{x} {y} 0", "0 0 1"), ("0 0 0", "1 0 0"), (f"{-x} {-y} -0.05", "1 0 0"))

    return builders.ring_of_legs("morphing", 6, places)


def test_legs_whose_hips_turn_about_the_vertical_are_a_walkers_however_their_feet_are_tucked() -> (
    None
):
    # Their feet meet under the body as drawn, but a parallel robot's motors turn its arms up
    # and down about level axes (the delta above), and a five-bar leg's two motors too.
    result = identify_urdf(tucked_hexapod())
    assert result.structure == "Hexapod"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * 6


def test_legs_turning_only_about_the_vertical_whose_tips_meet_are_a_planar_parallel_robot() -> None:
    # Every joint about the vertical: a planar parallel robot's arms, no walker's legs (a
    # walker's hip yaw is followed by a lift about a level axis).
    planar = delta(reach=1.0).replace('<axis xyz="0 1 0"/>', '<axis xyz="0 0 1"/>')
    assert identify_urdf(planar).structure == "Manipulator"


def test_three_legs_whose_tips_stand_apart_stay_legs() -> None:
    result = identify_urdf(delta(reach=0.0))
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg", "leg", "leg"]


def bolted_delta(*, legs: int = 3, root: str = "world", platform: bool = True) -> str:
    """:func:`delta`'s chains standing apart (``legs`` of them, evenly around), on a base fixed
    to ``root``; with ``platform``, the platform a simulator moves on a chain of three slides
    from the root (the loop a URDF cannot close)."""
    chains, legs_joints = delta_chains(legs, reach=0.0)
    links = ["base_link", *chains]
    joints = [builders.joint_xml("bolt", "fixed", root, "base_link", "0 0 1", "1 0 0")]
    joints += legs_joints
    if platform:
        parent = root
        for axis, vector in (("x", "1 0 0"), ("y", "0 1 0"), ("z", "0 0 1")):
            links.append(f"platform_{axis}")
            joints.append(
                f'<joint name="{axis}" type="prismatic"><parent link="{parent}"/>'
                f'<child link="platform_{axis}"/><axis xyz="{vector}"/>'
                '<limit lower="-0.5" upper="0.5" effort="1" velocity="1"/></joint>'
            )
            parent = f"platform_{axis}"
    body = "".join(f'<link name="{link}"/>' for link in (root, *links)) + "".join(joints)
    return f'<robot name="delta">{body}</robot>'


def test_three_legs_on_a_base_bolted_to_the_world_are_a_deltas_arms() -> None:
    # The chains' tips stand apart: the platform they hold moves on slides of its own.
    result = identify_urdf(bolted_delta())
    assert result.structure == "Manipulator"
    assert result.body is not None
    kinds = {limb.joints[0]: limb.kind for limb in result.body.limbs}
    assert kinds == {"x": "arm", "motor_0": "other", "motor_1": "other", "motor_2": "other"}


def test_three_legs_bolted_to_the_world_with_no_platform_drawn_are_one_manipulator() -> None:
    result = identify_urdf(bolted_delta(platform=False))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "other", "other"]


@pytest.mark.parametrize("robot", [{"root": "stand"}, {"legs": 4}])
def test_legs_on_a_free_base_or_four_bolted_down_stay_legs(robot: dict[str, Any]) -> None:
    # A walker on a test stand is not a delta: its base is no world's, or it has four legs.
    result = identify_urdf(bolted_delta(**robot))
    assert result.body is not None
    assert result.body.count("leg") == robot.get("legs", 3)


def five_bar_arm(*, closed: bool, elbow: str = "1 0 0") -> RobotText:
    """Two two-joint arm chains starting 0.4 m apart on one table, their shoulders turning
    about x and their elbows about ``elbow``, their ends meeting 0.6 m above the middle
    (``closed``) or rising straight up, as far apart as they start."""
    robot = RobotText("five_bar", root="table")
    for side, y in (("left", 0.2), ("right", -0.2)):
        upper = builders.placed(
            robot,
            f"{side}_shoulder",
            "revolute",
            "table",
            f"{side}_upper",
            xyz=f"0 {y} 0.1",
            axis="1 0 0",
        )
        end = f"0 {-y if closed else 0} 0.3"
        builders.placed(
            robot, f"{side}_elbow", "revolute", upper, f"{side}_fore", xyz="0 0 0.3", axis=elbow
        )
        robot.joint(
            f"{side}_tip", "fixed", f"{side}_fore", f"{side}_tip_link", f'<origin xyz="{end}"/>'
        )
    return robot


def test_two_arm_chains_whose_ends_meet_are_one_five_bar_arm() -> None:
    result = identify_urdf(five_bar_arm(closed=True).text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("arm", 4)]


@pytest.mark.parametrize(
    "arms",
    [
        {"closed": False},  # ending as far apart as they start
        {"closed": True, "elbow": "0 1 0"},  # hands meeting, arms not in one plane (a YuMi)
    ],
)
def test_two_arms_apart_or_not_in_one_plane_stay_two_arms(arms: dict[str, Any]) -> None:
    result = identify_urdf(five_bar_arm(**arms).text())
    assert result.body is not None
    assert result.body.count("arm") == 2


def desktop_arm_drawn_open(
    *,
    gap: float = 0.05,
    side_end: bool = False,
    off_plane: float = 0.0,
    side_axis: str = "0 1 0",
    side_hinges: int = 3,
    side_name: str = "p",
) -> RobotText:
    """A desktop arm on a table, its base turning about z, then three hinges about y and the
    tool's turn about z; beside the arm's first hinge (``gap`` before it, ``off_plane`` across
    the plane it turns in) its parallelogram's other side, ``side_hinges`` hinges about
    ``side_axis`` named ``side_name`` and a number, ending in a bare link (or, with
    ``side_end``, in a fixed frame of its own)."""
    robot = RobotText("desktop", root="table")
    base = builders.placed(robot, "j1", "revolute", "table", "turret", xyz="0 0 0.1")
    link = base
    for index, xyz in enumerate(("0 0 0.1", "0 0 0.17", "0.17 0 0"), start=2):
        link = builders.placed(
            robot, f"j{index}", "revolute", link, f"arm{index}", xyz=xyz, axis="0 1 0"
        )
    tool = builders.placed(robot, "j5", "revolute", link, "flange", xyz="0.06 0 0")
    robot.fixed(tool, "tool")
    link = base
    steps = (f"{-gap} {off_plane} 0.12", "0 0 0.17", "0.07 0 0", "0.05 0 0")
    for index, xyz in enumerate(steps[:side_hinges]):
        link = builders.placed(
            robot, f"{side_name}{index}", "revolute", link, f"rod{index}", xyz=xyz, axis=side_axis
        )
    if side_end:
        robot.fixed(link, "rod_end")
    return robot


def test_an_arms_parallelogram_drawn_as_an_open_chain_beside_it_is_part_of_the_arm() -> None:
    result = identify_urdf(desktop_arm_drawn_open().text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("arm", 7)]


@pytest.mark.parametrize(
    "drawn",
    [
        {"gap": 0.4},  # starting far from the arm's first hinge: an arm of its own
        {"side_end": True},  # ending in a frame of its own, not in a bare link
        {"off_plane": 0.06},  # starting off the plane the arm turns in
        {"side_axis": "1 0 0"},  # turning about another axis than the arm's
        {"side_hinges": 4},  # as long as the arm
        {"side_name": "elbow_"},  # named as an arm's
    ],
)
def test_a_chain_beside_an_arm_far_from_it_or_unlike_a_linkage_stays_an_arm(
    drawn: dict[str, Any],
) -> None:
    result = identify_urdf(desktop_arm_drawn_open(**drawn).text())
    assert result.body is not None
    assert result.body.count("arm") == 2


@pytest.mark.parametrize("order", ["abc", "cab", "bac"])
def test_chains_each_beside_the_next_are_read_alike_whatever_their_order_in_the_file(
    order: str,
) -> None:
    # Three unnamed planar chains on one turret, of five, four and three hinges, each starting
    # 6 or 7 cm from the next: the longest takes the next as its parallelogram, the shortest,
    # 13 cm from the longest, stays an arm of its own; no joint is lost.
    robot = RobotText("nested", root="table")
    base = builders.placed(robot, "j0", "revolute", "table", "turret", xyz="0 0 0.1")
    chains = {"c": (5, 0.0), "a": (4, -0.06), "b": (3, -0.13)}
    for name in order:
        hinges, x = chains[name]
        link = base
        for index in range(hinges):
            xyz = f"{x} 0 0.1" if index == 0 else ("0.1 0 0" if index == hinges - 1 else "0 0 0.15")
            link = builders.placed(
                robot, f"{name}{index}", "revolute", link, f"{name}_l{index}", xyz=xyz, axis="0 1 0"
            )
        if name == "c":
            robot.fixed(link, "tool")
    result = identify_urdf(robot.text())
    assert result.body is not None
    arms = sorted(sorted(limb.joints) for limb in result.body.limbs)
    assert arms == [["a0", "a1", "a2", "a3", "c0", "c1", "c2", "c3", "c4"], ["b0", "b1", "b2"]]


def branching_biped(end: str = "foot") -> RobotText:
    """Two legs drawn open where their linkages branch off: hip yaw, hip roll and thigh, then a
    rod beside the knee and shin, then a servo's two-joint horn beside the last joint, whose
    link is named ``end``."""
    robot = RobotText("branching")
    for side in ("l", "r"):
        thigh = robot.chain("base_link", [f"{side}_hip_yaw", f"{side}_hip_roll", f"{side}_thigh"])
        shin = robot.chain(thigh, [f"{side}_knee", f"{side}_shin"])
        robot.chain(shin, [f"{side}_{end}"])
        robot.chain(shin, [f"{side}_servo", f"{side}_horn"])
        robot.chain(thigh, [f"{side}_rod"])
    return robot


def test_a_leg_whose_linkages_branch_off_is_one_leg_down_to_its_foot() -> None:
    result = identify_urdf(branching_biped().text())
    assert result.structure == "Biped"
    assert result.body is not None
    legs = [limb.joints for limb in result.body.limbs if limb.kind == "leg"]
    assert legs == [
        ("l_hip_yaw", "l_hip_roll", "l_thigh", "l_knee", "l_shin", "l_foot"),
        ("r_hip_yaw", "r_hip_roll", "r_thigh", "r_knee", "r_shin", "r_foot"),
    ]
    assert not result.body.trunk


def test_a_frame_fixed_under_the_foot_keeps_the_leg_through_its_linkage() -> None:
    robot = branching_biped()
    for side in ("l", "r"):
        robot.fixed(f"{side}_foot_link", f"{side}_sole_frame")
    result = identify_urdf(robot.text())
    assert result.structure == "Biped"


def test_a_trunk_joint_beside_the_leg_leaves_every_joint_where_it_was() -> None:
    # A rod off the thigh carrying two chains: no leg through a linkage, and no joint lost.
    robot = branching_biped()
    for side in ("l", "r"):
        rod = robot.chain(f"{side}_thigh_link", [f"{side}_rocker"])
        robot.chain(rod, [f"{side}_pin_a", f"{side}_pin_b"])
        robot.chain(rod, [f"{side}_pin_c", f"{side}_pin_d"])
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not any("linkage" in limb.why for limb in result.body.limbs)
    kept = {name for limb in result.body.limbs for name in limb.joints} | set(result.body.trunk)
    assert {"l_rocker", "r_rocker", "l_hip_yaw", "r_foot"} <= kept


def test_branches_that_end_in_no_foot_are_no_leg_through_a_linkage() -> None:
    result = identify_urdf(branching_biped(end="plate").text())
    assert result.body is not None
    assert not any("linkage" in limb.why for limb in result.body.limbs)


def test_a_leg_whose_foot_splits_into_a_camel_cased_toe_and_heel_is_one_leg() -> None:
    # A motion-capture body model: hip, knee and ankle down to the foot, where a ball-of-foot
    # joint to ``RightToe`` and a heel joint branch off (names camel-cased, no ``_``).
    robot = RobotText("human", root="Pelvis")
    for side in ("Right", "Left"):
        foot = robot.chain("Pelvis", [f"j{side}Hip", f"j{side}Knee", f"j{side}Ankle"])
        robot.joint(f"j{side}BallFoot", "revolute", foot, f"{side}Toe")
        robot.joint(f"j{side}Heel", "revolute", foot, f"{side}Heel")
    result = identify_urdf(robot.text())
    assert result.body is not None
    legs = [limb for limb in result.body.limbs if limb.kind == "leg"]
    assert [(limb.joints[0], limb.tip) for limb in legs] == [
        ("jRightHip", "RightToe"),
        ("jLeftHip", "LeftToe"),
    ]
    assert result.structure == "Biped"


def wheel_legged(*, closed: bool) -> RobotText:
    """Two five-bar legs drawn open: on each side a front chain (hip, knee) carrying the wheel
    and a passive rear chain (hip, knee) whose end a ``<gazebo>`` joint closes onto the wheel
    (with ``closed``; the loop a URDF cannot write)."""
    robot = RobotText("wheel_legged")
    axis = '<axis xyz="0 1 0"/>'
    for side, y in (("l", 0.2), ("r", -0.2)):
        for end, x in (("front", 0.05), ("rear", -0.05)):
            robot.joint(
                f"{side}_{end}_hip",
                "revolute",
                robot.root,
                f"{side}_{end}_thigh",
                f'<origin xyz="{x} {y} 0"/>{axis}<limit lower="-1" upper="1"/>',
            )
            robot.joint(
                f"{side}_{end}_knee",
                "continuous",
                f"{side}_{end}_thigh",
                f"{side}_{end}_shin",
                f'<origin xyz="{3 * x} 0 -0.1"/>{axis}',
            )
        robot.joint(
            f"{side}_wheel_joint",
            "continuous",
            f"{side}_front_shin",
            f"{side}_wheel",
            f'<origin xyz="-0.1 0 -0.2"/>{axis}',
        )
        if closed:
            robot.add(
                f'<gazebo><joint name="{side}_closure" type="revolute">'
                f"<parent>{side}_rear_shin</parent><child>{side}_wheel</child></joint></gazebo>"
            )
    return robot


def test_a_chain_a_gazebo_joint_closes_onto_another_is_part_of_that_linkage() -> None:
    result = identify_urdf(wheel_legged(closed=True).text())
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [
        ("mount", 4),
        ("mount", 4),
    ]
    assert result.structure == "UGV"
    assert any("closed by a loop joint" in limb.why for limb in result.body.limbs)
    # Drawn open, with nothing that closes the loop, the rear chains are legs of their own.
    assert identify_urdf(wheel_legged(closed=False).text()).structure == "Biped"


def test_the_urdf_keeps_only_the_gazebo_closures_between_its_own_links() -> None:
    robot = wheel_legged(closed=True)
    robot.add(
        "<gazebo><joint name='x' type='revolute'><parent>l_rear_shin</parent>"
        "<child>nowhere</child></joint></gazebo>"
    )
    closures = parse_urdf(robot.text()).closures
    assert closures == (("l_rear_shin", "l_wheel"), ("r_rear_shin", "r_wheel"))


def cut_loop_biped(*, marked: bool = True) -> RobotText:
    """Two legs (hip, knee, ankle down to a foot), each with a knee linkage and two ankle
    linkages an exporter cut open (a closed-chain biped's: two actuators tilt the foot): a
    motor crank and a rod per loop, ending in frames named as that loop's two ends
    (``closedloop_knee_<side>_A`` / ``_B``; with ``marked`` False, plain frames)."""
    robot = RobotText("walker")

    def hinge(name: str, parent: str, child: str, xyz: str) -> str:
        return builders.placed(robot, name, "revolute", parent, child, xyz=xyz, axis="0 1 0")

    for side, y in (("left", 0.1), ("right", -0.1)):
        thigh = hinge(f"hip_{side}", robot.root, f"thigh_{side}", f"0 {y} -0.1")
        shin = hinge(f"knee_{side}", thigh, f"shin_{side}", "0 0 -0.3")
        foot = hinge(f"ankle_{side}", shin, f"foot_{side}", "0 0 -0.3")
        loops = (("knee", (thigh, shin)), ("ankle1", (shin, foot)), ("ankle2", (shin, foot)))
        for loop, (crank_on, rod_on) in loops:
            a, b = (
                (f"closedloop_{loop}_{side}_A", f"closedloop_{loop}_{side}_B")
                if marked
                else (f"end_{loop}_{side}_1", f"end_{loop}_{side}_2")
            )
            robot.fixed(
                hinge(f"motor_{loop}_{side}", crank_on, f"crank_{loop}_{side}", "0.05 0 -0.05"), a
            )
            robot.fixed(
                hinge(f"free_{loop}_{side}", rod_on, f"rod_{loop}_{side}", "0.05 0 0.05"), b
            )
    return robot


def test_a_linkage_cut_open_at_frames_named_as_one_loops_ends_is_no_limb_of_its_own() -> None:
    urdf = parse_urdf(cut_loop_biped().text())
    assert len(urdf.cut_loops) == 6
    assert ("closedloop_ankle1_left_A", "closedloop_ankle1_left_B") in urdf.cut_loops
    result = identify_urdf(cut_loop_biped().text())
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("leg", 3), ("leg", 3)]
    assert result.structure == "Biped"
    # The same frames named as no loop's ends: the cranks and rods branch the legs.
    assert parse_urdf(cut_loop_biped(marked=False).text()).cut_loops == ()
    assert identify_urdf(cut_loop_biped(marked=False).text()).structure != "Biped"


def circle_of_arms(count: int, *, turn: float = 0.0, rise: float = 0.0) -> str:
    """``count`` alike two-joint chains named as arms on a circle 0.2 m out, evenly spaced
    (the first turned ``turn`` radians further; each ``rise`` metres above the one before)."""
    links = ["base_link"]
    joints = []
    for i in range(count):
        angle = 2 * math.pi * i / count + (turn if i == 0 else 0.0)
        x, y = 0.2 * math.cos(angle), 0.2 * math.sin(angle)
        links += [f"upper_arm_{i}", f"lower_arm_{i}"]
        joints.append(
            builders.joint_xml(
                f"shoulder_{i}",
                "revolute",
                "base_link",
                f"upper_arm_{i}",
                f"{x} {y} {i * rise}",
                "0 1 0",
            )
        )
        joints.append(
            builders.joint_xml(
                f"elbow_{i}", "revolute", f"upper_arm_{i}", f"lower_arm_{i}", "0.2 0 0", "0 1 0"
            )
        )
    body = "".join(f'<link name="{link}"/>' for link in links) + "".join(joints)
    return f'<robot name="parallel">{body}</robot>'


@pytest.mark.parametrize("count", [3, 6])
def test_alike_chains_a_third_of_a_turn_apart_are_one_parallel_manipulator(count: int) -> None:
    # A delta's three arms, a Stewart platform's six: one manipulator holding one platform.
    result = identify_urdf(circle_of_arms(count))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"] + ["other"] * (count - 1)


def test_chains_not_a_third_of_a_turn_apart_or_four_of_them_stay_arms() -> None:
    assert identify_urdf(circle_of_arms(3, turn=0.5)).structure == "Torso"
    assert identify_urdf(circle_of_arms(4)).structure == "Torso"


def test_alike_chains_on_a_circle_beside_a_platform_placed_by_slides_are_one_manipulator() -> None:
    # A thesis's delta: three arms driven at the base and the platform its author places on x, y
    # and z slides of its own, standing in for the loops the file cannot close.
    slides = "".join(
        builders.joint_xml(f"act_{axis}", "prismatic", parent, child, "0 0 0", direction)
        for axis, parent, child, direction in (
            ("x", "base_link", "aux1", "1 0 0"),
            ("y", "aux1", "aux2", "0 1 0"),
            ("z", "aux2", "platform", "0 0 1"),
        )
    )
    links = '<link name="aux1"/><link name="aux2"/><link name="platform"/>'
    delta = circle_of_arms(3).replace("</robot>", f"{links}{slides}</robot>")
    result = identify_urdf(delta)
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs].count("arm") == 1
    # The same slides beside four arms, or a fourth chain that turns, leave them arms.
    four = circle_of_arms(4).replace("</robot>", f"{links}{slides}</robot>")
    assert identify_urdf(four).structure == "Torso"
    turning = delta.replace('type="prismatic"', 'type="revolute"')
    assert identify_urdf(turning).structure == "Torso"
    # One slide alone is a lift beside three arms, no platform placed on slides.
    lift = builders.joint_xml("lift", "prismatic", "base_link", "platform", "0 0 0", "0 0 1")
    lifted = circle_of_arms(3).replace("</robot>", f'<link name="platform"/>{lift}</robot>')
    assert identify_urdf(lifted).structure == "Torso"


def test_a_chain_of_closures_drops_no_chain() -> None:
    # Two legs closed onto each other, and an arm closed onto the first: every joint stays in
    # a limb (a chain is closed onto one other, or keeps others, never both).
    robot = RobotText("r")
    for chain, x, y in (("a", 0.3, 0.1), ("b", 0.3, -0.1), ("c", -0.3, 0.0)):
        link = robot.root
        for i in range(3):
            xyz = f"{x} {y} 0" if i == 0 else "0 0 -0.2"
            link = builders.placed(
                robot, f"{chain}_j{i}", "revolute", link, f"{chain}_l{i}", xyz=xyz, axis="0 1 0"
            )
    for parent, child in (("a_l2", "b_l2"), ("c_l2", "a_l2")):
        robot.add(
            f"<gazebo><joint name='{parent}_{child}' type='revolute'><parent>{parent}</parent>"
            f"<child>{child}</child></joint></gazebo>"
        )
    result = identify_urdf(robot.text())
    assert result.body is not None
    in_limbs = sorted(name for limb in result.body.limbs for name in limb.joints)
    assert in_limbs == sorted(f"{c}_j{i}" for c in "abc" for i in range(3))


def test_only_alike_chains_on_a_level_circle_are_a_parallel_manipulator() -> None:
    delta = circle_of_arms(3)
    # Two chains longer than the rest (only the platform's chain may go on): three arms.
    longer = delta.replace(
        "</robot>",
        builders.joint_xml("w1", "revolute", "lower_arm_1", "h1", "0.1 0 0", "0 0 1")
        + builders.joint_xml("w2", "revolute", "lower_arm_2", "h2", "0.1 0 0", "0 0 1")
        + '<link name="h1"/><link name="h2"/></robot>',
    )
    assert identify_urdf(longer).structure == "Torso"
    # Chains at three heights are no level circle.
    assert identify_urdf(circle_of_arms(3, rise=0.1)).structure == "Torso"


def test_overflowing_places_read_no_circle() -> None:
    # A stranger's 1e308s: no symmetry can be read, the chains stay three arms.
    robot = circle_of_arms(3)
    places = [p.split('"')[0] for p in robot.split('<origin xyz="')[1:]]
    for place, far in zip(places[::2], ("1e+308 0 0", "1e+308 1e+308 0", "0.5 -3 1"), strict=True):
        robot = robot.replace(f'<origin xyz="{place}"/>', f'<origin xyz="{far}"/>', 1)
    assert identify_urdf(robot).structure == "Torso"


def strut_platform(
    *,
    root: str = "world",
    strut: str = "prismatic",
    rise: float = 0.1,
    hung: str = "",
    stiff: int = 0,
) -> RobotText:
    """Six legs named so, each a universal joint and a strut reaching ``rise`` up, on a circle
    a sixth of a turn apart (a Stewart platform whose moving platform is drawn elsewhere); the
    base is ``root``, or a body hung from it by a ``hung`` joint (a floating base); the first
    ``stiff`` legs turn at their end instead of sliding."""
    robot = RobotText("stewart", root=root)
    base = root
    if hung:
        base = builders.placed(robot, "base_joint", hung, root, "body")
    for i in range(6):
        angle = i * math.pi / 3
        xyz = f"{0.2 * math.cos(angle):.4f} {0.2 * math.sin(angle):.4f} 0"
        pitch = builders.placed(robot, f"leg{i}_pitch", "revolute", base, f"leg{i}_a", xyz=xyz)
        roll = builders.placed(robot, f"leg{i}_roll", "revolute", pitch, f"leg{i}_b", axis="1 0 0")
        builders.placed(
            robot,
            f"leg{i}_strut",
            "revolute" if i < stiff else strut,
            roll,
            f"leg{i}_tip",
            xyz=f"0 0 {rise}",
            axis="0 0 1",
        )
    return robot


def test_six_struts_named_legs_on_a_base_bolted_to_the_world_are_a_parallel_robot() -> None:
    result = identify_urdf(strut_platform().text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert "a parallel mechanism" in result.body.limbs[0].why


@pytest.mark.parametrize(
    "platform",
    [
        {"root": "body"},  # a free body
        {"strut": "revolute"},  # legs that do not slide
        {"stiff": 1},  # one leg that does not
        {"hung": "floating"},  # a walker's floating base hung from world
        {"rise": -0.1},  # feet hanging below the hips: a walker on a test stand
    ],
)
def test_legs_on_a_free_body_without_struts_or_hanging_stay_legs(
    platform: dict[str, Any],
) -> None:
    result = identify_urdf(strut_platform(**platform).text())
    assert result.body is not None
    assert result.body.count("leg") == 6


def upper_body_on_a_column() -> RobotText:
    """A humanoid's upper body on a fixed column: a waist of three turning joints, two arms of
    four (names saying nothing) going down, each ending in two hanging two-joint fingers, one
    longer: the long fingers' tips are the body's lowest, one on each side."""
    robot = RobotText("upper_body", root="column")
    link = "column"
    for name, axis in (("w1", "0 0 1"), ("w2", "0 1 0"), ("w3", "1 0 0")):
        link = builders.placed(robot, name, "revolute", link, f"{name}_link", axis=axis)
    for side, y in (("a", 0.2), ("b", -0.2)):
        arm = builders.placed(
            robot, f"{side}1", "revolute", link, f"{side}1_link", xyz=f"0 {y} 0.1", axis="0 1 0"
        )
        for n in range(2, 5):
            arm = builders.placed(
                robot, f"{side}{n}", "revolute", arm, f"{side}{n}_link", xyz="0 0 -0.1"
            )
        for finger, x, length in (("p", 0.01, 0.06), ("q", -0.01, 0.03)):
            tip = arm
            for n in (1, 2):
                tip = builders.placed(
                    robot,
                    f"{side}{finger}{n}",
                    "revolute",
                    tip,
                    f"{side}{finger}{n}_link",
                    xyz=f"{x if n == 1 else 0} 0 -{length}",
                    axis="0 1 0",
                )
            robot.joint(
                f"{side}{finger}_tip",
                "fixed",
                tip,
                f"{side}{finger}_tip_link",
                f'<origin xyz="0 0 -{length}"/>',
            )
    return robot


def test_fingers_hanging_from_arms_past_a_waist_are_no_legs_by_reach() -> None:
    result = identify_urdf(upper_body_on_a_column().text())
    assert result.body is not None
    assert result.body.count("leg") == 0
    assert result.structure != "Biped"


def gantry(side_joints: int = 1) -> RobotText:
    """A Cartesian gantry: X and Y carriages, a Z slide ending in a two-jaw gripper, and a
    camera's mount of ``side_joints`` joints beside the Z slide, on the Y carriage; joints
    named for their axes, nothing of an arm in their names."""
    robot = RobotText("gantry")
    carriage = robot.chain("base_link", ["base_to_x", "x_to_y"], "prismatic")
    tool = robot.chain(carriage, ["y_to_z"], "prismatic")
    robot.chain(tool, ["gripper"], "prismatic")
    robot.chain(tool, ["gripper_sub"], "prismatic")
    robot.chain(carriage, [f"camera_{n}" for n in range(side_joints)])
    return robot


def test_a_gantrys_carriages_carry_its_gripper_one_arm_with_a_cameras_mount_beside() -> None:
    robot = gantry()
    limbs = detect_body(parse_urdf(robot.text()), load_profile()).limbs
    arms = [limb for limb in limbs if limb.kind == "arm"]
    assert [arm.joints for arm in arms] == [("base_to_x", "x_to_y", "y_to_z")]
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_a_branch_of_two_joints_beside_the_gripper_leaves_the_carriages_a_trunk() -> None:
    limbs = detect_body(parse_urdf(gantry(side_joints=2).text()), load_profile()).limbs
    assert not [limb for limb in limbs if limb.kind == "arm" and limb.gripper]


def test_a_body_with_an_arm_keeps_its_trunk_beside_a_short_gripper_chain() -> None:
    robot = gantry()
    robot.chain("base_link", ["shoulder_pan", "shoulder_lift", "elbow"])
    limbs = detect_body(parse_urdf(robot.text()), load_profile()).limbs
    arms = [limb for limb in limbs if limb.kind == "arm"]
    assert [arm.joints for arm in arms] == [("shoulder_pan", "shoulder_lift", "elbow")]


def test_one_carriage_and_a_slide_carrying_a_gripper_are_a_two_joint_arm() -> None:
    robot = RobotText("slide")
    carriage = robot.chain("base_link", ["base_to_x"], "prismatic")
    tool = robot.chain(carriage, ["x_to_z"], "prismatic")
    robot.chain(tool, ["gripper"], "prismatic")
    robot.chain(tool, ["gripper_sub"], "prismatic")
    robot.chain(carriage, ["camera_0"])
    limbs = detect_body(parse_urdf(robot.text()), load_profile()).limbs
    assert [limb.joints for limb in limbs if limb.kind == "arm"] == [("base_to_x", "x_to_z")]


def test_trunk_joints_that_would_make_a_gripper_chain_no_arm_stay_the_trunk() -> None:
    # Joints named for a leg above a gripper's slide: joined, no arm; the trunk stays.
    robot = RobotText("odd")
    carriage = robot.chain("base_link", ["hip_x", "knee_y"], "prismatic")
    tool = robot.chain(carriage, ["y_to_z"], "prismatic")
    robot.chain(tool, ["gripper"], "prismatic")
    robot.chain(tool, ["gripper_sub"], "prismatic")
    robot.chain(carriage, ["camera_0"])
    limbs = detect_body(parse_urdf(robot.text()), load_profile()).limbs
    assert [limb.joints for limb in limbs if limb.gripper] == [("y_to_z",)]


def test_a_wrist_whose_palm_holds_fingers_beside_a_gripper_slide_stays_a_hand() -> None:
    # Two unnamed wrist joints, a palm with a slide ending in jaws and three one-joint fingers.
    robot = RobotText("palm")
    palm = robot.chain("base_link", ["j1", "j2"])
    tool = robot.chain(palm, ["j3"], "prismatic")
    robot.chain(tool, ["gripper"], "prismatic")
    robot.chain(tool, ["gripper_sub"], "prismatic")
    for n in range(3):
        robot.chain(palm, [f"f{n}"])
    limbs = detect_body(parse_urdf(robot.text()), load_profile()).limbs
    assert not [limb for limb in limbs if limb.kind == "arm"]


def toy_humanoid(legs: tuple[str, ...] = ("left", "right")) -> RobotText:
    """A beginner's humanoid: two arms of two joints named as arms, a head, and a leg of one
    hinge on each of ``legs`` (``hips_to_left_leg``)."""
    robot = RobotText("toy")
    for side in ("left", "right"):
        robot.chain(robot.root, [f"body_to_{side}_arm", f"{side}_arm_elbow"])
    robot.chain(robot.root, ["body_to_head"])
    for side in legs:
        robot.chain(robot.root, [f"hips_to_{side}_leg"])
    return robot


def test_one_hinge_legs_in_a_pair_beside_two_arms_are_legs() -> None:
    result = identify_urdf(toy_humanoid().text())
    assert result.body is not None
    assert (result.structure, result.body.count("leg")) == ("Humanoid", 2)
    assert identify_urdf(toy_humanoid(legs=("left",)).text()).structure != "Humanoid"
    assert identify_urdf(toy_humanoid(legs=("left", "right", "rear")).text()).structure != (
        "Humanoid"
    )


def test_one_hinge_shoulders_in_a_pair_on_a_biped_are_arms() -> None:
    robot = RobotText("biped")
    for side in ("left", "right"):
        builders.leg(robot, robot.root, f"{side}_leg", ("hip", "knee", "ankle"))
        robot.chain(robot.root, [f"base_to_{side}_shoulder"])
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert (result.structure, result.body.count("arm")) == ("Humanoid", 2)


def two_arms_one_with_a_suction_tool(
    second: list[str] | None = None,
    pipe_joints: int = 1,
    *,
    jaws: bool = False,
    finger: bool = False,
    pipe: str = "prismatic",
) -> str:
    """A waist carrying a seven-joint chain named as an arm and a ``second`` chain (default:
    another such arm) that ends in a suction tool whose two pipes slide (or move as ``pipe``
    says), each on ``pipe_joints`` joints of their own (no pair of jaws); with ``jaws``, each
    pipe carries a gripper's two jaws; with ``finger``, one hinged finger of a gripper."""
    robot = RobotText("picker")
    waist = robot.chain(robot.root, ["torso_turn"])
    robot.chain(waist, [f"left_arm_joint_{i}" for i in range(1, 8)])
    tool = robot.chain(waist, second or [f"right_arm_joint_{i}" for i in range(1, 8)])
    for side, axis in (("front", "0 0 1"), ("side", "1 0 0")):
        link = tool
        for i in range(pipe_joints):
            link = robot.joint(
                f"{side}_pipe_{i}",
                pipe,
                link,
                f"{side}_pipe_{i}_link",
                f'<axis xyz="{axis}"/><limit lower="0" upper="0.1" effort="1" velocity="1"/>',
            )
        if jaws:
            robot.chain(link, [f"{side}_gripper_finger_left"], "prismatic")
            robot.chain(link, [f"{side}_gripper_finger_right"], "prismatic")
        if finger:
            robot.chain(link, [f"{side}_gripper_joint"])
    return robot.text()


def kinds_of_long_chains(text: str) -> list[str]:
    result = identify_urdf(text)
    assert result.body is not None
    return [limb.kind for limb in result.body.limbs if len(limb.joints) == 7]


def test_an_arm_that_ends_in_a_tools_single_joints_is_an_arm_not_a_trunk() -> None:
    assert identify_urdf(two_arms_one_with_a_suction_tool()).structure == "Torso"
    assert kinds_of_long_chains(two_arms_one_with_a_suction_tool()) == ["arm", "arm"]


def test_a_chain_named_as_nothing_that_ends_in_two_slides_is_an_arm_with_its_jaws() -> None:
    unnamed = [f"j{i}" for i in range(1, 8)]
    assert kinds_of_long_chains(two_arms_one_with_a_suction_tool(unnamed)) == ["arm", "arm"]
    # Each slide may close a hinged finger of the gripper (fresh set 1428's telescoping arm).
    fingered = two_arms_one_with_a_suction_tool(unnamed, finger=True)
    assert kinds_of_long_chains(fingered) == ["arm", "arm"]


def test_a_chain_named_as_nothing_whose_two_slides_each_carry_a_gripper_stays_a_trunk() -> None:
    # Two slides each carrying a gripper of its own (two jaws): a trunk carrying two tools.
    unnamed = [f"j{i}" for i in range(1, 8)]
    result = identify_urdf(two_arms_one_with_a_suction_tool(unnamed, jaws=True))
    assert result.body is not None
    assert not any(limb.joints == tuple(unnamed) for limb in result.body.limbs)


@pytest.mark.parametrize(
    ("second", "pipe_joints"),
    [
        # A neck and head carrying two antennas: the body's, no arm.
        ([f"neck_head_joint_{i}" for i in range(1, 8)], 1),
        # Named more as a head's than an arm's.
        ([*(f"arm_{i}" for i in range(1, 3)), *(f"head_{i}" for i in range(3, 8))], 1),
        # Too short to be an arm.
        (["arm_lift", "arm_turn"], 1),
        # What it branches into are limbs of two joints: it is a trunk carrying them.
        ([f"right_arm_joint_{i}" for i in range(1, 8)], 2),
    ],
)
def test_a_chain_that_is_no_named_arm_or_branches_into_limbs_stays_a_trunk(
    second: list[str], pipe_joints: int
) -> None:
    result = identify_urdf(two_arms_one_with_a_suction_tool(second, pipe_joints))
    assert result.body is not None
    assert not any(limb.joints == tuple(second) for limb in result.body.limbs)


def test_a_chain_named_as_nothing_whose_two_leaves_turn_stays_a_trunk() -> None:
    # A neck's two turning leaves (a head's ears), no jaws: no word says it is an arm.
    unnamed = [f"j{i}" for i in range(1, 8)]
    result = identify_urdf(two_arms_one_with_a_suction_tool(unnamed, pipe="revolute"))
    assert result.body is not None
    assert not any(limb.joints == tuple(unnamed) for limb in result.body.limbs)


def unnamed_column(joints: int, step: float) -> tuple[RobotText, str]:
    """A robot of ``joints`` unnamed joints ``j1``.. rising ``step`` metres apart from its root,
    and the link they end on."""
    robot = RobotText("r", root="l0")
    link = "l0"
    for i in range(1, joints + 1):
        link = placed(robot, f"j{i}", "revolute", link, f"l{i}", xyz=f"0 0 {step}")
    return robot, link


def unnamed_arm_ending_in(fingers: list[tuple[int, float]]) -> str:
    """Six unnamed joints rising 0.15 m apart (0.9 m in all), then, on the link they end on,
    one unnamed chain per ``fingers`` entry: that many joints, each ``length`` metres past the
    one before, side by side 0.03 m apart."""
    robot, link = unnamed_column(6, 0.15)
    for f, (joints, length) in enumerate(fingers):
        below, offset = link, f"{0.03 * f} 0 {length}"
        for k in range(joints):
            below = placed(robot, f"f{f}{k}", "revolute", below, f"fl{f}{k}", xyz=offset)
            offset = f"0 0 {length}"
    return robot.text()


def test_an_unnamed_arm_ending_in_a_hands_short_fingers_is_an_arm_not_a_trunk() -> None:
    # A three-finger hand on a six-joint arm, no name anywhere (a gripper whose fingers'
    # first joints follow one actuator leave three short chains where the arm ends).
    text = unnamed_arm_ending_in([(2, 0.05), (1, 0.05), (1, 0.05)])
    result = identify_urdf(text)
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs if len(limb.joints) == 6] == ["arm"]


def test_an_unnamed_arm_ending_in_two_bending_fingers_is_an_arm_not_a_trunk() -> None:
    # A servo arm's two fingers of two joints each.
    result = identify_urdf(unnamed_arm_ending_in([(2, 0.05), (2, 0.05)]))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs if len(limb.joints) == 6] == ["arm"]


def test_an_unnamed_chain_branching_into_limbs_as_long_as_a_trunks_stays_a_trunk() -> None:
    # Three chains of three joints, each reaching 0.9 m: a trunk's arms, no hand's fingers.
    result = identify_urdf(unnamed_arm_ending_in([(3, 0.3), (3, 0.3), (3, 0.3)]))
    assert result.body is not None
    assert result.body.trunk == ("j1", "j2", "j3", "j4", "j5", "j6")


def test_short_limbs_named_as_arms_and_a_head_on_an_unnamed_chain_leave_it_a_trunk() -> None:
    # A small torso: six unnamed joints carrying two short named arms and a head.
    robot, link = unnamed_column(6, 0.15)
    for side, y in (("left", 0.05), ("right", -0.05)):
        below = placed(robot, f"{side}_shoulder", "revolute", link, f"{side}_s", xyz=f"0 {y} 0")
        placed(robot, f"{side}_elbow", "revolute", below, f"{side}_e", xyz="0 0 0.05")
    placed(robot, "head_pan", "revolute", link, "head", xyz="0 0 0.05")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.trunk == ("j1", "j2", "j3", "j4", "j5", "j6")


def test_a_rig_of_three_unnamed_joints_carrying_four_short_legs_stays_a_trunk() -> None:
    # Too few joints for an arm carrying a hand: a test rig's yaw, pitch and slide.
    robot, link = unnamed_column(3, 0.2)
    for k, (x, y) in enumerate(((0.05, 0.05), (0.05, -0.05), (-0.05, 0.05), (-0.05, -0.05))):
        below = placed(robot, f"a{k}", "revolute", link, f"a{k}_l", xyz=f"{x} {y} -0.02")
        placed(robot, f"b{k}", "revolute", below, f"b{k}_l", xyz="0 0 -0.05")
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.trunk == ("j1", "j2", "j3")


def test_an_arm_named_chain_whose_single_joints_carry_grippers_stays_a_trunk() -> None:
    # Each one-joint branch carries a gripper: they are chains the trunk carries, no tool's.
    second = [f"right_arm_joint_{i}" for i in range(1, 8)]
    result = identify_urdf(two_arms_one_with_a_suction_tool(second, jaws=True))
    assert result.body is not None
    assert not any(limb.joints == tuple(second) for limb in result.body.limbs)


def test_six_single_hinges_round_a_flying_bodys_airframe_are_no_parallel_mechanism() -> None:
    # Six one-joint chains a sixth of a turn apart on arms fixed to the root (a hexacopter's
    # propeller mounts, written alike): on the ground a parallel mechanism (a claw's jaws), on
    # a body that flies the craft's own.
    robot = RobotText("hexa")
    chains = []
    for i in range(6):
        angle = 2 * math.pi * i / 6
        arm = robot.fixed("base_link", f"arm{i}")
        place = f'<origin xyz="{0.25 * math.cos(angle):.4f} {0.25 * math.sin(angle):.4f} 0"/>'
        robot.joint(f"j{i}", "revolute", arm, f"l{i}", place + '<axis xyz="1 0 0"/>')
        chains.append(Limb("other", (f"j{i}",), arm, f"l{i}"))
    tree = tree_of(robot)
    assert "arm" in [limb.kind for limb in parallel_robot(tree, chains)]
    assert parallel_robot(tree, chains, flying=True) == chains


def base_on_two_swivel_casters(kind: str = "continuous") -> RobotText:
    """A body named by letters only on two drive wheels, left and right, and two swivel
    casters, front and back: each a swivel about the vertical and a wheel on it 0.1 m below,
    both of ``kind``."""
    robot = RobotText("r", root="b")
    for name, y in (("p", 0.2), ("q", -0.2)):
        builders.placed(robot, name, "continuous", "b", f"{name}l", xyz=f"0 {y} 0", axis="0 1 0")
    for name, x in (("s", 0.25), ("t", -0.25)):
        swivel = builders.placed(
            robot, f"{name}0", kind, "b", f"{name}l0", xyz=f"{x} 0 -0.02", axis="0 0 1"
        )
        builders.placed(
            robot, f"{name}1", kind, swivel, f"{name}l1", xyz="-0.03 0 -0.1", axis="0 1 0"
        )
    return robot


def test_two_chains_hanging_down_whose_joints_all_turn_for_ever_are_no_legs() -> None:
    # Two swivel casters, a swivel and a wheel each: no biped's legs.
    result = identify_urdf(base_on_two_swivel_casters().text())
    assert result.body is not None
    assert result.body.count("leg") == 0
    assert result.structure == "UGV"
    # The same chains on joints that stop hang as a lower body's legs.
    assert identify_urdf(base_on_two_swivel_casters("revolute").text()).structure == "Biped"


def two_joints_on(mount: str, *, camera: bool = False) -> RobotText:
    """A two-wheeled base carrying, on a link fixed to it named ``mount``, an unnamed chain of
    a yaw and a pitch (``joint1``, ``joint2``): a course's two-joint arm on its own mount;
    with ``camera``, a camera fixed at the chain's tip."""
    robot = RobotText("tb3_with_payload", root="base_link")
    builders.wheeled_base(robot)
    robot.fixed("base_link", mount)
    link1 = builders.placed(robot, "joint1", "revolute", mount, "link1", xyz="0 0 0.01")
    tip = builders.placed(robot, "joint2", "revolute", link1, "link2", xyz="0 0 0.2", axis="0 1 0")
    if camera:
        robot.fixed(tip, "camera_link")
        robot.add(builders.gazebo_sensor("camera_link", "camera", "cam"))
    return robot


@pytest.mark.parametrize(
    "mount", ["manipulator_base_link", "arm_base", "arm1_mount", "ArmMount", "arms_base"]
)
def test_a_two_joint_chain_on_a_link_named_as_an_arms_base_is_that_arm(mount: str) -> None:
    result = identify_urdf(two_joints_on(mount).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert "arm's base" in result.body.limbs[0].why
    assert result.structure == "Mobile Manipulator"


@pytest.mark.parametrize(
    ("mount", "camera", "kind"),
    [
        ("payload_mount", False, "other"),
        ("alarm_base", False, "other"),
        ("armature", False, "other"),
        ("arm_base", True, "head"),
    ],
    ids=[
        "a mount named for no arm",
        "arm inside another word",
        "an arm's word with no base or mount",
        "a camera at its tip: a pan/tilt unit",
    ],
)
def test_a_two_joint_chain_on_any_other_link_is_no_arm(mount: str, camera: bool, kind: str) -> None:
    result = identify_urdf(two_joints_on(mount, camera=camera).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == [kind]
    assert result.structure == "UGV"


def lift_and_roll_holding(*tools: str, joints: int = 2) -> RobotText:
    """A wheeled base carrying a lift (a slide up) and a roll about the lift's forward line,
    whose last link holds ``tools`` on fixed joints, each given a mass (a gripper whose body
    and jaws are drawn fixed); with ``joints=1``, the roll alone."""
    robot = RobotText("lift_car", root="base_link")
    builders.wheeled_base(robot)
    tip = "base_link"
    if joints == 2:
        tip = placed(robot, "link_slide", "prismatic", tip, "link_slide_1", xyz="0 0 0.1")
    tip = placed(robot, "link_rotate", "continuous", tip, "link_rotate_1", axis="1 0 0")
    for tool in tools:
        robot.fixed(tip, tool)
    return robot


def test_a_lift_and_roll_holding_a_gripper_drawn_fixed_is_an_arm() -> None:
    robot = lift_and_roll_holding("Gripper_1", "link_gripper_left_1", "link_gripper_right_1")
    result = identify_urdf(builders.solid(robot.text(), "Gripper_1", "link_gripper_left_1"))
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert "holding a tool fixed to its last link (Gripper_1)" in result.body.limbs[0].why
    assert result.structure == "Mobile Manipulator"


def test_a_pan_tilt_units_tip_frame_named_an_end_effector_leaves_it_a_pan_tilt_unit() -> None:
    robot = RobotText("pan_tilt", root="base_link")
    link = placed(robot, "joint1", "revolute", "base_link", "link1", xyz="0 0 0.05")
    tip = placed(robot, "joint2", "revolute", link, "link2", xyz="0 0 0.03", axis="0 1 0")
    robot.fixed(tip, "end_effector")
    result = identify_urdf(builders.solid(robot.text(), "end_effector"))
    assert result.structure == "Pan/Tilt Unit"
    # On a wheeled base, the same chain pointing a camera frame beside it is no arm either.
    rover = lift_and_roll_holding("camera_link", "end_effector")
    result = identify_urdf(builders.solid(rover.text(), "end_effector"))
    assert result.body is not None
    assert result.body.count("arm") == 0
    # A gripper it holds is grasped, whatever it points: an arm.
    rover = lift_and_roll_holding("camera_link", "gripper_link")
    result = identify_urdf(builders.solid(rover.text(), "gripper_link"))
    assert result.structure == "Mobile Manipulator"


def test_a_small_humanoids_arm_holding_a_tool_is_found_with_its_other_arm() -> None:
    robot = RobotText("minihum", root="base_link")
    for side, y in (("l", 1), ("r", -1)):
        hip_and_knee(robot, side, "base_link", xyz=f"0 {0.05 * y} -0.05", shin=0.1)
        shoulder = placed(
            robot,
            f"{side}_j1",
            "revolute",
            "base_link",
            f"{side}_a1",
            xyz=f"0 {0.1 * y} 0.15",
            axis="0 1 0",
        )
        placed(
            robot, f"{side}_j2", "revolute", shoulder, f"{side}_a2", xyz="0 0 -0.07", axis="1 0 0"
        )
    robot.fixed("l_a2", "l_gripper")
    result = identify_urdf(builders.solid(robot.text(), "l_gripper"))
    assert result.body is not None
    assert sorted(limb.kind for limb in result.body.limbs) == ["arm", "arm", "leg", "leg"]
    assert result.structure == "Humanoid"


@pytest.mark.parametrize(
    ("tool", "joints", "mass"),
    [
        ("end_effector", 2, False),
        ("gripper_camera_mount", 2, True),
        ("camera_link", 2, True),
        ("claw", 1, True),
    ],
    ids=[
        "a bare frame named for a tool",
        "a mount named for a gripper",
        "a camera",
        "one joint holding the claw",
    ],
)
def test_a_chain_holding_no_tool_or_too_short_stays_no_arm(
    tool: str, joints: int, mass: bool
) -> None:
    robot = lift_and_roll_holding(tool, joints=joints)
    text = builders.solid(robot.text(), tool) if mass else robot.text()
    result = identify_urdf(text)
    assert result.body is not None
    assert result.body.count("arm") == 0
    assert result.structure == "UGV"


def column_lifting_a_boom(
    *,
    reach: float = 0.23,
    swing: str = "0 0 1",
    swing_first: bool = False,
    tip: str = "",
    inertia: str = builders.ROD_ALONG_X,
    names: tuple[str, str] = ("khop_joint", "khau_2_joint"),
) -> str:
    """The text of a wheeled base with a fixed column, a lift up it and a swing about ``swing``
    (about the lift's line, by default; ``swing_first``: the swing below the lift), joints
    named ``names``, the last link a boom whose mass sits ``reach`` m out along x, with
    ``inertia``'s terms (a rod along x, by default), holding ``tip`` on a fixed joint when
    given."""
    robot = RobotText("tank", root="base_link")
    builders.wheeled_base(robot)
    robot.fixed(robot.root, "khau_1")
    kinds = [(names[0], "prismatic", "0 0 1"), (names[1], "continuous", swing)]
    link = "khau_1"
    for name, kind, axis in reversed(kinds) if swing_first else kinds:
        link = placed(robot, name, kind, link, f"{name}_link", axis=axis)
    if tip:
        robot.fixed(link, tip)
    return builders.weighted(robot.text(), link, f"{reach} 0 0", inertia)


@pytest.mark.parametrize(
    ("swing_first", "names"),
    [
        (False, ("khop_joint", "khau_2_joint")),
        (True, ("khop_joint", "khau_2_joint")),
        (False, ("boom_lift_joint", "boom_swing_joint")),
    ],
    ids=["lift then swing", "swing then lift", "named a lift and a swing, no wing"],
)
def test_a_lift_and_a_swing_about_its_axis_carrying_a_boom_out_is_an_arm(
    swing_first: bool, names: tuple[str, str]
) -> None:
    result = identify_urdf(column_lifting_a_boom(swing_first=swing_first, names=names))
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["arm"]
    assert "a lift and a swing about its axis" in result.body.limbs[0].why
    assert "a boom 0.23 m out" in result.body.limbs[0].why
    assert result.structure == "Mobile Manipulator"


_PLATE = 'ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.04"'
_MAST = 'ixx="0.025" ixy="0" ixz="0" iyy="0.025" iyz="0" izz="0.002"'


@pytest.mark.parametrize(
    ("reach", "swing", "tip", "inertia"),
    [
        (0.0, "0 0 1", "", builders.ROD_ALONG_X),
        (0.23, "0 0 1", "", _PLATE),
        (0.23, "0 0 1", "", _MAST),
        (0.23, "0 0 1", "", ""),
        (0.23, "0 1 0", "", builders.ROD_ALONG_X),
        (0.23, "0 0 1", "camera_link", builders.ROD_ALONG_X),
        (0.23, "0 0 1", "zed2_left_frame", builders.ROD_ALONG_X),
    ],
    ids=[
        "its mass on the axis",
        "flat: a jacking plate whose mass a CAD export puts off the axis",
        "long along the axis: a mast",
        "no inertia written",
        "a tilt square to the lift: a forklift's",
        "a camera on it: a mast's head",
        "a sensor's frame on it, named for its device",
    ],
)
def test_a_lift_and_a_turn_swinging_no_boom_stays_no_arm(
    reach: float, swing: str, tip: str, inertia: str
) -> None:
    text = column_lifting_a_boom(reach=reach, swing=swing, tip=tip, inertia=inertia)
    result = identify_urdf(text)
    assert result.body is not None
    assert result.body.count("arm") == 0
    assert result.structure == "UGV"


def base_on_caster_bogies(tip: str) -> RobotText:
    """A two-wheeled base whose body rides on a front and a back bogie, each a pitch then a
    roll, each roll's shaft holding two links named ``{end}_right_{tip}`` and
    ``{end}_left_{tip}`` on fixed joints (a self-levelling delivery robot's caster bogies)."""
    robot = RobotText("levelling_base", root="base_link")
    builders.wheeled_base(robot)
    for end, x in (("front", "0.11"), ("back", "-0.11")):
        pitch = placed(
            robot, f"{end}_pitch", "revolute", "base_link", f"{end}_pitch_link", xyz=f"{x} 0 0.05"
        )
        pitch = placed(robot, f"{end}_roll", "revolute", pitch, f"{end}_shaft", axis="1 0 0")
        for side in ("right", "left"):
            robot.fixed(pitch, f"{end}_{side}_{tip}")
    return robot


def test_bogies_whose_shafts_hold_casters_named_for_their_corners_are_no_legs() -> None:
    result = identify_urdf(base_on_caster_bogies("caster_link").text())
    assert result.body is not None
    assert result.body.count("leg") == 0
    assert result.structure == "UGV"
    # The same chains holding links named for their corners alone end in a leg's corner.
    result = identify_urdf(base_on_caster_bogies("link").text())
    assert result.body is not None
    assert result.body.count("leg") == 2


def body_on_one_hinge_legs(
    legs: int = 4,
    *,
    name: str = "leg",
    kind: str = "continuous",
    axes: tuple[str, str] = ("0 1 0", "0 1 0"),
    robot_name: str = "walker_toy",
) -> RobotText:
    """A robot ``robot_name``: a body on ``legs`` chains of one ``kind`` hinge each, named
    ``{name}_{i}_joint``, in mirrored pairs along the body (0.3 m apart, 0.2 m out to each
    side), the left ones turning about ``axes[0]`` and the right ones about ``axes[1]``: a toy
    walker's legs, each swinging round whole (continuous) or back and forth (revolute)."""
    robot = RobotText(robot_name, root="body")
    pairs = legs // 2
    for i in range(legs):
        x = 0.3 * (i % pairs) - 0.15 * (pairs - 1)
        left = i < pairs
        placed(
            robot,
            f"{name}_{i}_joint",
            kind,
            "body",
            f"{name}_{i}_link",
            xyz=f"{x} {0.2 if left else -0.2} 0",
            axis=axes[0] if left else axes[1],
        )
    return robot


@pytest.mark.parametrize(
    ("legs", "kind", "structure"),
    [(4, "continuous", "Quadruped"), (4, "revolute", "Quadruped"), (6, "revolute", "Hexapod")],
)
def test_one_hinge_chains_named_as_legs_at_the_corners_are_legs(
    legs: int, kind: str, structure: str
) -> None:
    # (Six or more turning whole are legs by place, named or not: a RHex's.)
    result = identify_urdf(body_on_one_hinge_legs(legs, kind=kind).text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg"] * legs
    assert f"one of {legs} one-hinge chains named as legs" in result.body.limbs[0].why
    assert result.structure == structure


def bolted(robot: RobotText) -> RobotText:
    """``robot`` with its root fixed to a ``world`` link (a test stand)."""
    robot.links.append("world")
    robot.joint("stand", "fixed", "world", robot.root)
    return robot


def with_a_fixed_wheel(robot: RobotText) -> RobotText:
    """``robot`` with a caster wheel link fixed under its root (a trimmed model's)."""
    robot.fixed(robot.root, "caster_wheel_link")
    return robot


def with_an_arm(robot: RobotText) -> RobotText:
    """``robot`` carrying a six-joint arm with a gripper on its root (a crane on outriggers)."""
    builders.arm(robot, robot.root)
    return robot


@pytest.mark.parametrize(
    "robot",
    [
        body_on_one_hinge_legs(4, name="flap"),
        body_on_one_hinge_legs(4, name="front_left"),
        body_on_one_hinge_legs(2),
        body_on_one_hinge_legs(8, kind="revolute"),
        body_on_one_hinge_legs(4, axes=("0 1 0", "0 0 1")),
        body_on_one_hinge_legs(4, axes=("0 0 1", "0 0 1")),
        body_on_one_hinge_legs(4, name="fold_leg"),
        body_on_one_hinge_legs(4, name="landing_leg"),
        body_on_one_hinge_legs(4, robot_name="FoldingTable"),
        body_on_one_hinge_legs(4, robot_name="quadcopter_x"),
        bolted(body_on_one_hinge_legs(4)),
        with_a_fixed_wheel(body_on_one_hinge_legs(4)),
        with_an_arm(body_on_one_hinge_legs(4)),
    ],
    ids=[
        "named otherwise",
        "named for their corners only",
        "two",
        "eight servos (eight turning whole are a RHex-like walker's, by place)",
        "about unlike axes",
        "about the vertical",
        "legs that fold",
        "a drone's landing legs by their name",
        "a table by its name",
        "a drone by its name",
        "bolted to the world",
        "beside a wheel, fixed",
        "beside an arm",
    ],
)
def test_one_hinge_chains_that_are_no_walkers_legs_stay_no_legs(robot: RobotText) -> None:
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.count("leg") == 0
    assert result.structure not in ("Quadruped", "Hexapod", "Legged Mobile Manipulator")


def test_one_hinge_legs_on_a_body_with_wheels_stay_what_they_were() -> None:
    # A wheeled base's four stabiliser legs, each one hinge: the base rolls, they hold it.
    robot = body_on_one_hinge_legs(4)
    builders.wheeled_base(robot)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.count("leg") == 0


def pair_bolted_up_in_the_air(name: str, *, start: float = -0.05) -> RobotText:
    """A robot ``name`` whose body is fixed to ``world`` 1 m up, two unnamed chains of six
    hinges (``a_m1`` .. ``b_m6``) hanging straight down from ``start`` m above its origin,
    0.12 m apart: a walker's legs shown in a viewer, or a torso's arms at rest."""
    robot = RobotText(name, root="world")
    robot.joint("mount", "fixed", "world", "body", '<origin xyz="0 0 1"/>')
    steps = tuple((f"m{i}", "0 0 -0.08") for i in range(2, 7))
    for side, y in (("a", 0.06), ("b", -0.06)):
        pitches_down(robot, side, "body", (("m1", f"0 {y} {start}"), *steps))
    return robot


def test_a_walker_bolted_in_the_air_by_its_name_hangs_its_legs() -> None:
    # A servo humanoid's legs (fresh set 1360's "UXALeg"), their pelvis fixed 1 m above the
    # world's origin for a viewer: the pair hangs straight down from the body as a biped's.
    result = identify_urdf(pair_bolted_up_in_the_air("UXALeg").text())
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["leg", "leg"]
    assert result.structure == "Biped"


@pytest.mark.parametrize(
    ("name", "start"),
    [
        ("stand", -0.05),
        ("two_arm_walker", -0.05),
        ("college_robot", -0.05),
        ("legacy_cell", -0.05),
        ("humanoid_upper", -0.05),
        ("UXALeg", 0.05),
    ],
    ids=[
        "no walker's name",
        "a name that also says arm",
        "leg inside a word",
        "leg starting a longer word",
        "an upper body",
        "hanging from above the body's origin: shoulders",
    ],
)
def test_a_pair_bolted_in_the_air_is_a_torsos_arms_unless_a_walkers_legs(
    name: str, start: float
) -> None:
    # Bolted to the world, a torso's arms may hang down too: only a walker's name, as a word and
    # no arm's nor an upper body's, with the pair hanging from the bottom of its body, is legs.
    result = identify_urdf(pair_bolted_up_in_the_air(name, start=start).text())
    assert result.body is not None
    assert result.body.count("leg") == 0
    assert result.structure == "Torso"


def test_a_long_arm_ending_in_a_link_named_tail_stays_an_arm() -> None:
    # A tail has a head's few joints at most; six joints ending in `tail_link` are an arm.
    robot = builders.quadruped()
    last = robot.chain(robot.root, [f"joint{i}" for i in range(1, 7)])
    robot.fixed(last, "tail_link")
    assert identify_urdf(robot.text()).structure == "Legged Mobile Manipulator"


def test_a_rod_whose_end_meets_another_rod_is_merged_into_no_rod() -> None:
    # Rod a ends on rod b's link, rod b on arm c's: b drives c, and a (closed onto a rod, no
    # limb) stays a chain of its own; no joint is lost from every limb.
    robot = RobotText("chained_rods")
    blank = '<limit lower="0" upper="0" effort="0" velocity="0"/>'
    driven = '<limit lower="-1" upper="1" effort="10" velocity="1"/>'
    joints = (
        ("a_slide", "prismatic", "base_link", "0.3 0.4 0", "0 0 1", driven),
        ("a_ball_0", "revolute", "a_slide", "0 0 0.01", "1 0 0", blank),
        ("a_ball_1", "revolute", "a_ball_0", "0 -0.2 0.04", "1 0 0", blank),
        ("b_slide", "prismatic", "base_link", "0.3 0.2 0", "0 0 1", driven),
        ("b_ball_0", "revolute", "b_slide", "0 0 0.05", "1 0 0", blank),
        ("b_ball_1", "revolute", "b_ball_0", "0 -0.1 0.1", "1 0 0", blank),
        ("b_ball_2", "revolute", "b_ball_1", "0 -0.1 0.15", "1 0 0", blank),
        ("c1", "revolute", "base_link", "0 0 0.1", "0 0 1", driven),
        ("c2", "revolute", "c1", "0 0 0.2", "0 1 0", driven),
        ("c3", "revolute", "c2", "0.3 0 0", "0 1 0", driven),
        ("c4", "revolute", "c3", "0 0 0", "1 0 0", driven),
    )
    for name, kind, parent, xyz, axis, limit in joints:
        robot.joint(name, kind, parent, name, f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>{limit}')
    text = builders.solid(robot.text(), *[name for name, *_ in joints])
    body = detect_body(parse_urdf(text), load_profile())
    in_limbs = {name for limb in body.limbs for name in limb.joints}
    assert in_limbs == {name for name, *_ in joints}
    assert any({"b_slide", "c1"} <= set(limb.joints) for limb in body.limbs)


def elbowed_walker(first_link: str) -> RobotText:
    """Fresh set 1772's servo quadruped, as drawn: at each corner of a box a chain of three
    hinges hanging down, its first link named ``<first_link>_<corner>_1`` and the others
    ``upper_<corner>_1`` and ``lower_<corner>_1``; the joints named by number."""
    robot = RobotText("spot_v1")
    number = 0
    corners = {"fl": (0.06, 0.14), "fr": (-0.06, 0.14), "bl": (0.06, -0.19), "br": (-0.06, -0.19)}
    for corner, (x, y) in corners.items():
        parent = robot.root
        steps = [(f"{x} {y} 0.17", "0 1 0"), ("0.04 0 0", "1 0 0"), ("0 0.02 -0.08", "1 0 0")]
        for (xyz, axis), part in zip(steps, (first_link, "upper", "lower"), strict=True):
            number += 1
            parent = builders.placed(
                robot, f"Revolute {number}", "revolute", parent, f"{part}_{corner}_1",
                xyz=xyz, axis=axis,
            )  # fmt: skip
        robot.joint(f"foot_{corner}", "fixed", parent, f"tip_{corner}", '<origin xyz="0 0 -0.08"/>')
    return robot


def test_four_chains_at_the_corners_named_only_by_an_elbow_are_told_by_place() -> None:
    # A four-legged animal's foreleg bends at an elbow too: the name says no arm on its own.
    assert identify_urdf(elbowed_walker("elbow").text()).structure == "Quadruped"


def test_four_chains_at_the_corners_named_as_shoulders_stay_arms() -> None:
    assert identify_urdf(elbowed_walker("shoulder").text()).structure != "Quadruped"
