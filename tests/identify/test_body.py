"""The body a description shows: every movable joint given one role, the joints a person
commands, and the counts and sentences of evidence the classifier and a person read."""

from __future__ import annotations

from dataclasses import replace

from solver.identify import identify_urdf, load_profile
from solver.identify.body import Body, detect_body
from solver.identify.limbs import Limb
from solver.identify.readers.urdf import parse_urdf
from solver.identify.roles import Role
from tests.identify import builders
from tests.identify.builders import RobotText


def body_of(robot: RobotText) -> Body:
    return detect_body(parse_urdf(robot.text(), strict=False), load_profile())


def test_a_body_with_no_movable_joint_says_so_and_counts_nothing() -> None:
    robot = RobotText("brick")
    robot.fixed("base_link", "camera")
    body = body_of(robot)
    assert body.evidence("base_link") == ("no movable joints below base_link",)
    assert set(body.features().values()) == {0}


def test_every_movable_joint_gets_one_role_from_its_step() -> None:
    robot = builders.mobile_manipulator()
    robot.joint("pulley", "revolute", "base_link", "pulley_link", '<mimic joint="torso_lift"/>')
    roles = {role.joint: role.role for role in body_of(robot).roles}
    assert roles == {
        "wheel_left_joint": "wheel",
        "wheel_right_joint": "wheel",
        "torso_lift": "trunk",
        "shoulder_pan": "arm",
        "shoulder_lift": "arm",
        "elbow": "arm",
        "wrist_1": "arm",
        "wrist_2": "arm",
        "wrist_3": "arm",
        "gripper_finger_left": "finger",
        "gripper_finger_right": "finger",
        "head_pan": "head",
        "head_tilt": "head",
        "pulley": "passive",
    }
    assert [role.evidence for role in body_of(robot).roles if role.joint == "pulley"] == [
        "follows torso_lift (mimic)"
    ]


def test_joints_of_arms_and_of_the_trunk_carrying_them_are_commanded_and_a_head_is_not() -> None:
    robot = builders.mobile_manipulator()
    for joint in ("wheel_left_joint", "torso_lift", "shoulder_pan", "head_pan"):
        robot.add(builders.transmission(joint))
    body = body_of(robot)
    assert body.controlled_joints == ("shoulder_pan", "torso_lift")
    assert body.controlled_wheels == ("wheel_left_joint",)


def test_the_features_count_each_kind_of_limb() -> None:
    body = Body(
        limbs=(
            Limb("leg", ("a",), "base", "a_link"),
            Limb("leg", ("b",), "base", "b_link"),
            Limb("arm", ("c",), "base", "c_link"),
        ),
        wheels=("w",),
    )
    features = body.features()
    assert (features["legs"], features["arms"], features["heads"]) == (2, 1, 0)
    assert (features["wheels"], features["mobile_base"], features["weak_base"]) == (1, 1, 0)


def test_evidence_names_four_parts_and_says_how_many_in_all() -> None:
    body = Body(wheels=tuple(f"w{i}" for i in range(1, 7)))
    assert body.evidence("base_link") == ("6 wheel joint(s): w1, w2, w3, w4, ... (6 in all)",)


def test_role_lines_group_joints_by_role_with_the_first_reason_and_how_many_more() -> None:
    body = Body(
        roles=(
            Role("a", "wheel", "wheel name (a)"),
            Role("c", "rotor", "rotor name (c)"),
            Role("b", "wheel", "by place"),
        )
    )
    assert body.role_lines() == (
        "wheel: a, b (wheel name (a); and 1 more)",
        "rotor: c (rotor name (c))",
    )


def test_joints_a_wheel_carries_are_its_rollers_passive_whatever_transmission_they_have() -> None:
    # A mecanum base: each wheel carries rollers on joints of their own, every one written with
    # a transmission as the wheels are. The rollers turn with the ground: no limb, no Joint.
    robot = builders.ugv()
    for side in ("left", "right", "rear_left", "rear_right"):
        robot.add(builders.transmission(f"wheel_{side}_joint", "VelocityJointInterface"))
        for i in range(3):
            robot.joint(f"{side}_roller{i}", "continuous", f"wheel_{side}_link", f"{side}_r{i}")
            robot.add(builders.transmission(f"{side}_roller{i}", "EffortJointInterface"))
    result = identify_urdf(robot.text())
    assert result.structure == "UGV"
    roles = {role.joint: role for role in result.roles}
    assert roles["left_roller0"].role == "passive"
    assert roles["left_roller0"].evidence == "on wheel wheel_left_joint (a roller)"
    assert "Joint" not in {c.motion_control for c in result.motion_controls}
    assert "Driving" in {c.motion_control for c in result.motion_controls}


def test_the_trunk_joints_above_limbs_are_found_in_one_walk_up_a_deep_chain() -> None:
    # 20,000 sliding joints one under the next, 2,000 spinning leaves on the last links: which
    # trunk joints carry a limb is known from one walk up from each limb, not a walk down the
    # subtree of every trunk joint (which took a minute and a half).
    parts = ['<robot name="r"><link name="l0"/>']
    for i in range(1, 20_000):
        parts.append(
            f'<link name="l{i}"/><joint name="f{i}" type="prismatic"><parent link="l{i - 1}"/>'
            f'<child link="l{i}"/><axis xyz="0 0 1"/>'
            '<limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
        )
    for i in range(2_000):
        parts.append(
            f'<link name="w{i}"/><joint name="s{i}" type="continuous">'
            f'<parent link="l{19_999 - i}"/><child link="w{i}"/><axis xyz="0 1 0"/></joint>'
        )
    result = identify_urdf("".join(parts) + "</robot>")
    assert result.body is not None
    assert len(result.body.roles) >= 20_000


def test_a_pan_tilt_head_is_alone_only_with_nothing_else_on_its_body() -> None:
    assert body_of(builders.pan_tilt_only()).head_alone
    beside_jaws = builders.pan_tilt_only()
    beside_jaws.chain(beside_jaws.root, ["gripper_finger_joint"], "prismatic")
    beside_fingers = builders.pan_tilt_only()
    beside_fingers.chain(beside_fingers.root, ["index_finger_joint"])
    floating = RobotText("floating_gimbal", root="world")
    base = floating.joint("world_joint", "floating", "world", "base_link")
    floating.chain(base, ["pan_joint", "tilt_joint"])
    drone = builders.quadrotor()
    drone.chain(drone.root, ["gimbal_pan", "gimbal_tilt"])
    rover = builders.ugv()
    rover.chain(rover.root, ["camera_pan_joint", "camera_tilt_joint"])
    mast = builders.underwater_vehicle()
    mast.chain(mast.root, ["pan_joint", "tilt_joint"])
    beside_limb = builders.pan_tilt_only()
    beside_limb.chain(beside_limb.root, ["j1"])
    for robot in (beside_jaws, beside_fingers, floating, drone, rover, mast, beside_limb):
        assert not body_of(robot).head_alone, robot.name


def test_a_camera_gimbal_on_a_rover_is_its_head_not_an_arm() -> None:
    # A height slide and two servos named for the gimbal they make, ending at the camera's
    # frame: no pan or tilt word, but a gimbal aims what it carries, as a head does.
    rover = builders.ugv()
    rover.chain(rover.root, ["gimbal_slider_joint", "gimbal_hservo_joint", "gimbal_vservo_joint"])
    result = identify_urdf(rover.text())
    assert (result.structure, result.kinematic_type) == ("UGV", "UGV")
    assert result.body is not None
    assert [limb.kind for limb in result.body.limbs] == ["head"]


def test_a_pan_tilt_head_driven_by_its_packages_teleop_node_is_no_unit_alone() -> None:
    driven = replace(body_of(builders.pan_tilt_only()), driven_by="bringup/teleop.launch")
    assert not driven.head_alone
    assert driven.features()["head_alone"] == 0
    assert "a base driven by its packages' teleop node: bringup/teleop.launch" in driven.evidence(
        "base_link"
    )
