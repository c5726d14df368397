"""Each kind of body is read as its structure, mapped to the rule set's kinematic type."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from solver.core.rules import load_rules
from solver.identify import identify_urdf
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
    (builders.pan_tilt_only, "Pan/Tilt Unit", "Manipulator"),
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


def test_limits_closer_than_a_tenth_of_a_millimetre_lock_a_joint_as_equal_ones_do() -> None:
    # A rover converted from SDF: its turret and camera frame on revolute joints of +-1e-16,
    # a pan/tilt head between them; no actuator places a part that finely.
    shut = '<axis xyz="0 0 1"/><limit lower="-1e-16" upper="1e-16" effort="1000" velocity="1"/>'
    turn = '<axis xyz="0 0 1"/><limit lower="-3.14" upper="3.14" effort="1000" velocity="1"/>'
    rover = builders.ugv()
    rover.joint("turret_mount", "revolute", rover.root, "turret", shut)
    rover.joint("turret_pan", "revolute", "turret", "tilt_base", turn)
    rover.joint("turret_tilt", "revolute", "tilt_base", "hinge", turn)
    rover.joint("camera_hinge", "revolute", "hinge", "depth_camera_link", shut)
    urdf = parse_urdf(rover.text())
    shut_joints = [urdf.joint(name) for name in ("turret_mount", "camera_hinge")]
    assert [joint is not None and joint.movable for joint in shut_joints] == [False, False]
    result = identify_urdf(rover.text())
    assert result.structure == "UGV"
    assert [control.motion_control for control in result.motion_controls] == ["Driving"]
    # A force sensor's joint left a gap of 1e-5 rad for the simulator to measure across it.
    gap = '<axis xyz="0 0 1"/><limit lower="0" upper="0.00001" effort="10" velocity="1"/>'
    arm = builders.manipulator()
    arm.joint("ft_sensor_joint", "revolute", "wrist_3_link", "ft_link", gap)
    sensor = parse_urdf(arm.text()).joint("ft_sensor_joint")
    assert sensor is not None
    assert not sensor.movable
    # A small range a joint can travel (a fifth of a millimetre) still moves.
    fine = '<axis xyz="1 0 0"/><limit lower="0" upper="0.0002" effort="10" velocity="1"/>'
    slide = RobotText("stage")
    slide.joint("stage_joint", "prismatic", slide.root, "stage", fine)
    stage = parse_urdf(slide.text()).joint("stage_joint")
    assert stage is not None
    assert stage.movable


def test_equal_limits_on_joints_coupled_by_mimic_are_placeholders_not_a_lock() -> None:
    # A kinematic simulator's gripper: limits all zero, one finger following the other.
    robot = RobotText("gripper", root="world")
    robot.joint("pose", "floating", "world", "hand", "")
    zero = '<axis xyz="0 1 0"/><limit lower="0" upper="0" effort="0" velocity="0"/>'
    robot.joint("left", "prismatic", "hand", "left_pad", zero)
    robot.joint(
        "right", "prismatic", "hand", "right_pad", zero + '<mimic joint="left" multiplier="-1"/>'
    )
    urdf = parse_urdf(robot.text())
    left, right = urdf.joint("left"), urdf.joint("right")
    assert left is not None
    assert right is not None
    assert (left.unlocked, left.movable, left.actuated) == (True, True, True)
    assert (right.movable, right.actuated) == (True, False)
    assert identify_urdf(robot.text()).structure == "Gripper"
    # A fixed joint couples nothing: a sensor mount naming it in <mimic> stays locked.
    mount = RobotText("m")
    mount.joint("drv", "fixed", mount.root, "a", "")
    mount.joint("f1", "revolute", mount.root, "b", zero + '<mimic joint="drv"/>')
    mount.joint("f2", "revolute", mount.root, "c", zero + '<mimic joint="f2"/>')  # itself
    locked = parse_urdf(mount.text())
    assert [locked.joint(n).movable for n in ("f1", "f2")] == [False, False]  # type: ignore[union-attr]


def test_a_multirotor_holding_a_gripper_on_a_rigid_boom_is_an_aerial_manipulator() -> None:
    # A boom fixed under the body ends in a claw that no joint moves: built to manipulate.
    drone = builders.quadrotor()
    boom = drone.fixed(drone.root, "boom")
    drone.fixed(boom, "claw_gripper")
    result = identify_urdf(builders.solid(drone.text(), "claw_gripper"))
    assert result.structure == "Aerial Manipulator"
    assert "a rigid tool: claw_gripper, held on fixed joints" in result.evidence
    # The same link as a frame with nothing in it (a controller's reference point) is no tool.
    assert identify_urdf(drone.text()).structure == "UAV"
    # A tree rooted at the tool's frame (a controller's reference) holds it the same way.
    rooted = RobotText("uam", root="end_effector")
    body = rooted.fixed(rooted.root, "vehicle")
    for i in range(4):
        rooted.joint(f"rotor_{i}_joint", "continuous", body, f"rotor_{i}")
    assert identify_urdf(rooted.text()).structure == "Aerial Manipulator"
    # On a body a floating joint places in the world, the tool is held up to the body.
    placed = RobotText("placed", root="world")
    placed.joint("pose", "floating", "world", "body", "")
    for i in range(4):
        placed.joint(f"rotor_{i}_joint", "continuous", "body", f"rotor_{i}")
    placed.fixed(placed.fixed("body", "boom"), "uav/eef_link")
    assert (
        identify_urdf(builders.solid(placed.text(), "uav/eef_link")).structure
        == "Aerial Manipulator"
    )
    # A boom carrying a camera, and a gripper a wheeled base carries, are no such thing.
    camera = builders.quadrotor()
    camera.fixed(camera.fixed(camera.root, "boom"), "camera_link")
    assert identify_urdf(camera.text()).structure == "UAV"
    rover = builders.ugv()
    rover.fixed(rover.root, "claw_gripper")
    result = identify_urdf(rover.text())
    assert result.structure == "UGV"
    assert not any("rigid tool" in line for line in result.evidence)


def test_a_multirotor_carrying_a_gripper_with_no_arm_is_an_aerial_manipulator() -> None:
    # A two-finger gripper on a slide that lowers it from the body: no arm, a gripper.
    drone = builders.quadrotor()
    palm = drone.chain(drone.root, ["palm_riser"], kind="prismatic")
    for side in ("left", "right"):
        drone.chain(palm, [f"{side}_finger_joint"])
    result = identify_urdf(drone.text())
    assert result.body is not None
    assert (result.structure, result.body.count("arm"), result.body.grippers) == (
        "Aerial Manipulator",
        0,
        1,
    )
    # Landing gear: a mirrored pair of hinges, one following the other, read as jaws but named
    # for no gripper, holds nothing.
    gear = builders.quadrotor()
    for side, y, extra in (("left", 0.1, ""), ("right", -0.1, '<mimic joint="gear_left"/>')):
        builders.placed(
            gear, f"gear_{side}", "revolute", gear.root, f"gear_{side}_leg", xyz=f"0 {y} -0.05",
            axis="1 0 0", extra=extra,
        )  # fmt: skip
    assert identify_urdf(gear.text()).structure == "UAV"


@pytest.mark.parametrize(
    "name",
    ["hand_launch", "palm", "jaw", "tool0", "tcp", "ee", "camera_tool_frame",
     "gripper_camera_mount", "gripper_mount", "end_effector_cam", "arm_1", "payload_hook"],
)  # fmt: skip
def test_a_multirotors_frames_and_mounts_of_no_tool_leave_it_a_uav(name: str) -> None:
    drone = builders.quadrotor()
    drone.fixed(drone.root, name)
    assert identify_urdf(drone.text()).structure == "UAV"


@pytest.mark.parametrize("shape", ["chain", "star"])
def test_a_rigid_tool_is_found_in_one_walk_of_many_fixed_tool_links(shape: str) -> None:
    # 20,000 links named as grippers, fixed one under the next (or all on one hub) on a
    # quadrotor: each link is walked up once, not once per link below it (which took minutes).
    parts = ['<robot name="r"><link name="base_link"/><link name="hub"/>',
             '<joint name="hub_joint" type="fixed"><parent link="base_link"/>'
             '<child link="hub"/></joint>']  # fmt: skip
    for i in range(4):
        parts.append(
            f'<link name="rotor_{i}"/><joint name="rotor_{i}_joint" type="continuous">'
            f'<parent link="base_link"/><child link="rotor_{i}"/></joint>'
        )
    for i in range(20_000):
        parent = "hub" if shape == "star" or i == 0 else f"gripper_{i - 1}"
        parts.append(
            f'<link name="gripper_{i}"><inertial><mass value="0.1"/></inertial></link>'
            f'<joint name="g{i}" type="fixed">'
            f'<parent link="{parent}"/><child link="gripper_{i}"/></joint>'
        )
    result = identify_urdf("".join(parts) + "</robot>")
    assert result.body is not None
    assert result.body.rigid_tool == "gripper_0"


def test_a_gripper_nothing_in_which_moves_is_a_gripper_alone() -> None:
    # A vacuum gripper: four suction cups on fixed joints, the end effector all there is.
    vacuum = RobotText("vgc10")
    plate = vacuum.fixed(vacuum.root, "suction")
    for i in range(1, 5):
        vacuum.fixed(plate, f"suction{i}")
    result = identify_urdf(vacuum.text())
    assert result.structure == "Gripper"
    assert "a gripper no joint moves: suction (nothing in it moves)" in result.evidence
    # No joint of it takes a command: its suction is switched, which no description says.
    assert result.motion_controls == ()
    # A tool of no gripper's name is none (a screwdriver's shank), nor is a named cup where a
    # joint moves (there the moving parts say what the body is).
    driver = RobotText("screwdriver")
    driver.fixed(driver.root, "shank")
    assert identify_urdf(driver.text()).structure == "Other"
    # Nor is one link of a tool's name (a sensor kit's coupling), a hand's camera, a palm tree.
    for names in (["ft300", "gripper_coupling"], ["hand_camera_link"], ["palm_tree"]):
        kit = RobotText("kit")
        for name in names:
            kit.fixed(kit.root, name)
        assert identify_urdf(kit.text()).structure == "Other"
    turned = RobotText("turned")
    turned.fixed(turned.chain(turned.root, ["wrist_roll"]), "suction_cup")
    assert identify_urdf(turned.text()).structure != "Gripper"


def test_limits_all_equal_on_every_joint_are_a_cad_exporters_placeholders_not_a_lock() -> None:
    # An aerial manipulator exported from CAD: every joint revolute with limits 0..0.
    zero = '<axis xyz="1 0 0"/><limit lower="0" upper="0" effort="0" velocity="0"/>'
    robot = RobotText("drone_with_arm")
    for i in range(1, 5):
        robot.joint(f"prop{i}", "revolute", robot.root, f"prop{i}", zero)
    robot.joint("manipulator_joint_1", "revolute", robot.root, "arm1", zero)
    robot.joint("manipulator_joint_2", "revolute", "arm1", "arm2", zero)
    urdf = parse_urdf(robot.text())
    assert all(joint.unlocked and joint.movable for joint in urdf.joints)
    assert identify_urdf(robot.text()).structure == "Aerial Manipulator"
    # Sensor mounts written so (RotorS, the UUV simulator) stay locked: each a leaf on the
    # body, beside rotors that spin or alone, or on a floating base in a chain.
    rotors = builders.quadrotor()
    rotors.joint("camera_mount", "revolute", rotors.root, "camera", zero)
    rotors.joint("gimbal_mount", "revolute", rotors.root, "gimbal", zero)
    rig = RobotText("sensor_rig")
    rig.joint("imu_joint", "revolute", rig.root, "imu_link", zero)
    rig.joint("gps_joint", "revolute", rig.root, "gps_link", zero)
    floating = RobotText("drone", root="world")
    floating.joint("pose", "floating", "world", "body", "")
    floating.joint("camera_mount", "revolute", "body", "camera", zero)
    floating.joint("gimbal_mount", "revolute", "camera", "gimbal", zero)
    for locked, names in [
        (rotors, ("camera_mount", "gimbal_mount")),
        (rig, ("imu_joint", "gps_joint")),
        (floating, ("camera_mount", "gimbal_mount")),
    ]:
        urdf = parse_urdf(locked.text())
        assert [urdf.joint(name).movable for name in names] == [False, False]  # type: ignore[union-attr]
    assert identify_urdf(rig.text()).structure == "Other"


def test_three_blank_joints_in_a_row_are_an_exporters_limbs_and_every_blank_joint_moves() -> None:
    # A service robot exported from CAD: its wheels continuous, its arm's joints written 0..0
    # with zero effort (no limits were given). A camera on a two-joint mount written so stays
    # locked, as sensor mounts are.
    blank = '<axis xyz="0 0 1"/><limit lower="0" upper="0" effort="0" velocity="0"/>'
    robot = builders.ugv()
    parent = robot.root
    for i in range(1, 5):
        robot.joint(f"j{i}", "revolute", parent, f"segment{i}", blank)
        parent = f"segment{i}"
    urdf = parse_urdf(robot.text())
    assert all(urdf.joint(f"j{i}").movable for i in range(1, 5))  # type: ignore[union-attr]
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"
    # Such an export writes its wheels' joints blank too: they turn.
    loader = RobotText("loader")
    for side in ("left", "right", "rear_left", "rear_right"):
        loader.joint(f"wheel_{side}_joint", "revolute", loader.root, f"wheel_{side}", blank)
    loader.joint("boom", "revolute", loader.root, "boom_link", blank)
    loader.joint("stick", "revolute", "boom_link", "stick_link", blank)
    loader.joint("bucket", "revolute", "stick_link", "bucket_link", blank)
    limited = '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="0" velocity="0"/>'
    loader.joint("camera_pan", "revolute", loader.root, "camera", limited)  # not all blank
    urdf = parse_urdf(loader.text())
    assert all(joint.movable for joint in urdf.joints)
    assert identify_urdf(loader.text()).structure == "Mobile Manipulator"
    mount = builders.ugv()
    mount.joint("m1", "revolute", mount.root, "bracket", blank)
    mount.joint("m2", "revolute", "bracket", "camera", blank)
    urdf = parse_urdf(mount.text())
    assert [urdf.joint(name).movable for name in ("m1", "m2")] == [False, False]  # type: ignore[union-attr]
    assert identify_urdf(mount.text()).structure == "UGV"


def ros2_control(*joints: tuple[str, str]) -> str:
    """A ``<ros2_control>`` block: each joint with a command interface of the kind given, or
    with a state interface only (kind ``""``)."""
    rows = "".join(
        f'<joint name="{name}">'
        + (f'<command_interface name="{kind}"/>' if kind else "")
        + '<state_interface name="position"/></joint>'
        for name, kind in joints
    )
    return f'<ros2_control name="hw" type="system">{rows}</ros2_control>'


def test_equal_limits_on_a_joint_a_controller_commands_are_placeholders_not_a_lock() -> None:
    # A CAD export of a cartesian arm on a rover: its slides written 0..0, beside wheels.
    zero = '<axis xyz="0 0 1"/><limit lower="0" upper="0" effort="1" velocity="1"/>'
    robot = builders.ugv()
    robot.joint("lift", "prismatic", robot.root, "carriage", zero)
    robot.joint("reach", "prismatic", "carriage", "boom", zero)
    robot.joint("wrist", "continuous", "boom", "tool", '<axis xyz="1 0 0"/>')
    robot.joint("imu_joint", "revolute", robot.root, "imu_link", zero)
    robot.add(ros2_control(("lift", "position"), ("reach", "position"), ("imu_joint", "")))
    urdf = parse_urdf(robot.text())
    assert [urdf.joint(n).movable for n in ("lift", "reach")] == [True, True]  # type: ignore[union-attr]
    # A joint the block only reads (no command interface) stays locked.
    assert not urdf.joint("imu_joint").movable  # type: ignore[union-attr]
    assert identify_urdf(robot.text()).structure == "Mobile Manipulator"
    # A transmission's hardware interface commands a joint too.
    geared = RobotText("g")
    geared.joint("slide", "prismatic", geared.root, "s", zero)
    geared.add(builders.transmission("slide"))
    assert parse_urdf(geared.text()).joint("slide").movable  # type: ignore[union-attr]


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


def test_eight_leg_chains_of_paired_linkages_are_a_quadruped_with_doubt() -> None:
    robot = RobotText("linkage_dog")
    for corner in ("FL", "FR", "RL", "RR"):
        for half in ("a", "b"):
            builders.leg(robot, "base_link", f"{corner}{half}", ("hip", "knee"))
    result = identify_urdf(robot.text())
    assert result.structure == "Quadruped"
    assert result.confidence == pytest.approx(0.9 * 0.8, abs=0.01)


def test_a_body_no_structure_fits_is_other_with_the_parts_it_has() -> None:
    robot = builders.pan_tilt_only()
    robot.chain(robot.root, ["j1"])  # a head beside a limb of no name
    result = identify_urdf(robot.text())
    assert result.structure == "Other"
    assert any(
        line.startswith(
            "structure Other: no other structure matched; the body has 1 heads, no mobile base"
        )
        for line in result.evidence
    )
