"""Limbs: chains of the actuated joints no single-joint role takes, read as legs, arms, heads,
mounts or other by their names, their length and what they carry; trunk where they branch."""

from __future__ import annotations

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.body import detect_body
from solver.identify.limbs import Limb, find_limbs, sort_limbs
from solver.identify.readers.urdf import parse_urdf
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText


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
