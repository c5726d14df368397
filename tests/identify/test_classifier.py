"""Each kind of body is read as its structure, mapped to the rule set's kinematic type."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from solver.core.rules import load_rules
from solver.identify import identify_urdf, load_profile
from solver.identify.body import detect_body
from solver.identify.readers.urdf import parse_urdf
from tests.conftest import RULES
from tests.identify import builders
from tests.identify.builders import RobotText

CASES: list[tuple[Callable[[], RobotText], str, str | None]] = [
    (builders.ugv, "UGV", "UGV"),
    (builders.tracked, "UGV", "UGV"),
    (builders.quadrotor, "UAV", "UAV"),
    (builders.manipulator, "Manipulator", "Manipulator"),
    (builders.torso, "Torso", "Torso"),
    (builders.mobile_manipulator, "Mobile Manipulator", "Mobile Manipulator"),
    (builders.humanoid, "Humanoid", "Humanoid"),
    (builders.quadruped, "Quadruped", None),
    (builders.biped, "Biped", None),
    (builders.hand, "Hand", None),
    (builders.aerial_manipulator, "Aerial Manipulator", None),
    (builders.legged_manipulator, "Legged Mobile Manipulator", None),
    (builders.pan_tilt_only, "Other", None),
]


@pytest.mark.parametrize(
    ("build", "structure", "kinematic_type"), CASES, ids=[case[1] for case in CASES]
)
def test_identify_reads_each_body_under_the_paper_rules(
    build: Callable[[], RobotText], structure: str, kinematic_type: str | None
) -> None:
    result = identify_urdf(build().text())
    assert (result.structure, result.kinematic_type) == (structure, kinematic_type)
    assert 0 < result.confidence <= 1
    assert any(line.startswith(f"structure {structure}") for line in result.evidence)


def test_a_paper_rule_set_has_no_type_for_a_quadruped_and_says_so() -> None:
    result = identify_urdf(builders.quadruped().text())
    assert result.kinematic_type is None
    assert any("has no kinematic type for Quadruped" in line for line in result.evidence)


def test_a_rule_set_with_a_quadruped_type_classifies_quadrupeds(tmp_path: Path) -> None:
    text = (RULES / "paper.yaml").read_text(encoding="utf-8")
    text = text.replace(
        "      - Humanoid                # at least two arms, two legs and a head",
        "      - Humanoid\n      - Quadruped",
    )
    text = text.replace("bound: 900", "bound: 1050")
    (tmp_path / "legged.yaml").write_text(text, encoding="utf-8")
    rules = load_rules(tmp_path / "legged.yaml")
    result = identify_urdf(builders.quadruped().text(), rules=rules)
    assert result.kinematic_type == "Quadruped"


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


def test_zero_range_revolute_joints_are_fixed_and_mimic_joints_not_actuated() -> None:
    robot = builders.quadrotor()
    robot.joint(
        "imu_joint",
        "revolute",
        "base_link",
        "imu_link",
        '<limit lower="0" upper="0" effort="0" velocity="0"/>',
    )
    urdf = parse_urdf(robot.text())
    joint = urdf.joint("imu_joint")
    assert joint is not None
    assert not joint.movable
    arm = parse_urdf(builders.manipulator().text()).joint("gripper_finger_right")
    assert arm is not None
    assert arm.movable
    assert not arm.actuated


def test_a_chain_carrying_wheels_is_a_mount_not_a_leg() -> None:
    robot = RobotText("wheel_legged")
    robot.chain("base_link", ["hip_pitch", "knee_pitch"])
    robot.joint("wheel_joint", "continuous", "knee_pitch_link", "wheel")
    robot.chain("base_link", ["l_shoulder", "l_elbow", "l_wrist"])
    robot.chain("base_link", ["r_shoulder", "r_elbow", "r_wrist"])
    body = detect_body(parse_urdf(robot.text()), load_profile())
    assert [limb.kind for limb in body.limbs] == ["arm", "arm", "mount"]
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_flight_plugins_alone_make_a_uav() -> None:
    robot = RobotText("hector")
    robot.add(builders.model_plugin("propulsion", "libhector_gazebo_quadrotor_propulsion.so"))
    result = identify_urdf(robot.text())
    assert result.structure == "UAV"
    assert any("flight plugin" in line for line in result.evidence)


def test_a_humanoid_without_a_head_is_read_with_doubt() -> None:
    robot = builders.humanoid()
    robot.joints = [j for j in robot.joints if "neck" not in j and "head" not in j]
    robot.links = [link for link in robot.links if "neck" not in link and "head" not in link]
    result = identify_urdf(robot.text())
    assert result.structure == "Humanoid"
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)
    assert any(line.startswith("doubt:") for line in result.evidence)


def test_a_planar_base_joint_is_a_mobile_base() -> None:
    robot = RobotText("planar", root="odom")
    base = robot.joint("base_planar", "planar", "odom", "base_link")
    builders.arm(robot, base)
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"


def test_identification_prints_the_same_bytes_under_any_hash_seed(tmp_path: Path) -> None:
    path = tmp_path / "mm.urdf"
    path.write_text(builders.mobile_manipulator().text())
    outputs = {
        subprocess.run(
            [sys.executable, "-m", "solver", "identify", str(path), "--format", "json"],
            capture_output=True,
            check=True,
            timeout=600,
            env={**os.environ, "PYTHONHASHSEED": seed},
        ).stdout
        for seed in ("0", "1", "12345")
    }
    assert len(outputs) == 1
    assert b'"structure": "Mobile Manipulator"' in outputs.pop()


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
    assert (result.structure, result.body.wheels) == (  # type: ignore[union-attr]
        "UGV",
        ("left_wheel", "right_wheel"),
    )


def test_a_parallel_gripper_with_a_mimic_finger_is_a_gripper() -> None:
    robot = RobotText("gripper")
    robot.chain("base_link", ["left_finger_joint"], "prismatic")
    robot.joint(
        "right_finger_joint",
        "prismatic",
        "base_link",
        "right_finger",
        '<mimic joint="left_finger_joint"/><limit lower="0" upper="1"/>',
    )
    result = identify_urdf(robot.text())
    assert (result.structure, result.kinematic_type) == ("Gripper", None)
    assert len(result.body.fingers) == 2  # type: ignore[union-attr]


def test_a_hand_whose_finger_chains_carry_no_names_is_a_hand() -> None:
    robot = RobotText("claw")
    for f in range(3):
        robot.chain("base_link", [f"j{f}_{i}" for i in range(3)])
    result = identify_urdf(robot.text())
    assert result.structure == "Hand"
    assert len(result.body.fingers) == 3  # type: ignore[union-attr]


def _four_spinning_leaves(robot: RobotText, height: float, limits: str = "") -> None:
    for corner, (x, y) in {"fl": (1, 1), "fr": (1, -1), "rl": (-1, 1), "rr": (-1, -1)}.items():
        kind = "revolute" if limits else "continuous"
        origin = f'<origin xyz="{0.2 * x} {0.15 * y} {height}"/><axis xyz="0 1 0"/>{limits}'
        robot.joint(f"{corner}_joint", kind, "base_link", f"{corner}_Link", origin)


def test_unnamed_endless_joints_below_a_body_on_both_sides_are_wheels() -> None:
    robot = RobotText("rover")
    _four_spinning_leaves(robot, -0.1)
    result = identify_urdf(robot.text())
    assert (result.structure, result.kinematic_type) == ("UGV", "UGV")
    assert result.body.wheels == ("fl_joint", "fr_joint", "rl_joint", "rr_joint")  # type: ignore[union-attr]


def test_unnamed_spinning_leaves_level_with_the_body_or_limited_are_no_wheels() -> None:
    level = RobotText("level")
    _four_spinning_leaves(level, 0.0)
    limited = RobotText("limited")
    _four_spinning_leaves(limited, -0.1, '<limit lower="-1" upper="1" effort="1" velocity="1"/>')
    for robot in (level, limited):
        result = identify_urdf(robot.text())
        assert result.body.wheels == ()  # type: ignore[union-attr]
        assert result.structure != "UGV"


def test_unnamed_finger_chains_with_named_tips_on_an_arm_are_one_hand() -> None:
    robot = builders.manipulator()
    robot.joints.clear()
    robot.links[:] = [robot.root]
    tip = builders.arm(robot, robot.root, gripper=False)
    for f in range(4):
        knuckle = robot.chain(tip, [f"d{f}_base"])
        robot.chain(knuckle, [f"d{f}_finger_tip"])
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert (result.body.count("arm"), result.body.grippers) == (1, 1)  # type: ignore[union-attr]


def test_fingers_on_a_link_named_as_a_hand_make_the_arm_end_in_a_gripper() -> None:
    robot = RobotText("arm_hand")
    wrist = robot.chain("base_link", ["a1", "a2", "a3", "a4"])
    robot.fixed(wrist, "r_hand_base")
    for f in range(4):
        robot.chain("r_hand_base", [f"f{f}"])
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body.limbs[0].gripper  # type: ignore[union-attr]


def test_wrist_joints_into_links_named_as_the_hand_stay_arm_joints() -> None:
    robot = RobotText("arm into hand links")
    link = robot.chain("base_link", ["shoulder_pitch", "shoulder_roll", "elbow_pitch"])
    for axis in ("yaw", "roll", "pitch"):
        link = robot.joint(
            f"wrist_{axis}_joint",
            "revolute",
            link,
            f"hand_{axis}_link",
            '<limit lower="-1" upper="1" effort="1" velocity="1"/>',
        )
    result = identify_urdf(robot.text())
    assert result.body.grippers == 0  # type: ignore[union-attr]
    assert [len(limb.joints) for limb in result.body.limbs] == [6]  # type: ignore[union-attr]


def test_legs_that_end_in_a_gripper_are_legs() -> None:
    robot = builders.quadruped()
    robot.chain("FL_foot", ["FL_gripper_finger"], "prismatic")
    result = identify_urdf(robot.text())
    assert result.structure == "Quadruped"
    assert result.body.count("leg") == 4  # type: ignore[union-attr]


def test_legs_named_by_their_corner_are_legs() -> None:
    robot = RobotText("bracket_dog")
    for corner in ("left_front", "right_front", "left_back", "right_back"):
        robot.chain("base_link", [f"motor_{corner}_1", f"motor_{corner}_2", f"motor_{corner}_3"])
    assert identify_urdf(robot.text()).structure == "Quadruped"


def test_fixed_wheels_still_make_a_mobile_base_with_doubt() -> None:
    robot = RobotText("trimmed")
    robot.fixed("base_link", "left_wheel")
    robot.fixed("base_link", "right_wheel")
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)


def test_fixed_propellers_on_a_body_that_cannot_move_are_a_uav_with_doubt() -> None:
    trimmed = RobotText("trimmed quadrotor")
    for i in range(4):
        trimmed.fixed("base_link", f"prop{i}_link")
    result = identify_urdf(trimmed.text())
    assert (result.structure, result.kinematic_type) == ("UAV", "UAV")
    assert result.confidence == pytest.approx(0.95 * 0.8, abs=0.01)


def test_fixed_rotor_links_beside_moving_joints_are_motors_not_flight() -> None:
    legged = RobotText("legged")
    for corner in ("front_left", "front_right", "rear_left", "rear_right"):
        legged.chain("base_link", [f"{corner}_hip", f"{corner}_knee"])
        legged.fixed("base_link", f"{corner}_hip_rotor")
    result = identify_urdf(legged.text())
    assert result.structure == "Quadruped"
    assert result.body.fixed_rotors == ()  # type: ignore[union-attr]


def test_root_x_y_theta_joints_are_a_planar_mobile_base_with_doubt() -> None:
    robot = RobotText("sim_base", root="odom")
    robot.joint("x", "prismatic", "odom", "x_link", '<axis xyz="1 0 0"/>')
    robot.joint("y", "prismatic", "x_link", "y_link", '<axis xyz="0 1 0"/>')
    robot.joint("theta", "continuous", "y_link", "base_link", '<axis xyz="0 0 1"/>')
    builders.arm(robot, "base_link")
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body.planar_base == (  # type: ignore[union-attr]
        "root joints x, y, theta (x, y and a turn about z)",
    )
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
    assert result.body.floating_base  # type: ignore[union-attr]


def test_eight_leg_chains_of_paired_linkages_are_a_quadruped_with_doubt() -> None:
    robot = RobotText("linkage_dog")
    for corner in ("FL", "FR", "RL", "RR"):
        for half in ("a", "b"):
            builders.leg(robot, "base_link", f"{corner}{half}", ("hip", "knee"))
    result = identify_urdf(robot.text())
    assert result.structure == "Quadruped"
    assert result.confidence == pytest.approx(0.9 * 0.8, abs=0.01)


def test_a_body_no_structure_fits_is_other_with_the_parts_it_has() -> None:
    result = identify_urdf(builders.pan_tilt_only().text())
    assert result.structure == "Other"
    assert any(
        line.startswith(
            "structure Other: no other structure matched; the body has 1 heads, no mobile base"
        )
        for line in result.evidence
    )


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
    assert result.body.count("leg") == 2  # type: ignore[union-attr]


def test_two_unnamed_arms_on_the_root_stay_arms() -> None:
    robot = RobotText("dual_unnamed")
    for side in ("L", "R"):
        robot.chain("base_link", [f"{side}{i}" for i in range(6)])
    assert identify_urdf(robot.text()).structure == "Torso"
