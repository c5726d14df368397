"""The joints a joint command names: the limbs' actuated joints, each started within its limits."""

from __future__ import annotations

from solver.identify.body import detect_body
from solver.identify.joints import command_joints
from solver.identify.profile import load_profile
from solver.identify.readers.urdf import parse_urdf
from solver.ros.joints import JointStart
from tests.conftest import ROOT
from tests.identify.builders import RobotText


def _joints(text: str) -> tuple[JointStart, ...]:
    urdf = parse_urdf(text)
    return command_joints(urdf, detect_body(urdf, load_profile()))


def test_an_arm_commands_its_six_joints_not_the_fixed_mount_nor_the_mimic_finger() -> None:
    text = (ROOT / "examples" / "arm_gripper.urdf").read_text(encoding="utf-8")
    names = [joint.name for joint in _joints(text)]
    assert names[:6] == [
        "shoulder_pan_joint",
        "shoulder_lift_joint",
        "elbow_joint",
        "wrist_1_joint",
        "wrist_2_joint",
        "wrist_3_joint",
    ]
    assert "gripper_mount" not in names
    assert "right_finger_joint" not in names  # a mimic of the left finger


def test_a_joint_whose_limits_exclude_zero_starts_at_its_nearest_limit() -> None:
    robot = RobotText("arm")
    link = robot.chain("base_link", ["j1", "j2", "j3"])
    robot.joint(
        "j4", "revolute", link, "tool", '<limit lower="0.5" upper="1.5" effort="1" velocity="1"/>'
    )
    robot.joint(
        "j5", "prismatic", "tool", "tip", '<limit lower="-2" upper="-1" effort="1" velocity="1"/>'
    )
    assert _joints(robot.text()) == (
        JointStart("j1", 0.0),
        JointStart("j2", 0.0),
        JointStart("j3", 0.0),
        JointStart("j4", 0.5),
        JointStart("j5", -1.0),
    )


def test_a_robot_without_limbs_has_no_joints_to_command() -> None:
    text = (ROOT / "examples" / "diff_drive_lidar.urdf").read_text(encoding="utf-8")
    assert _joints(text) == ()
