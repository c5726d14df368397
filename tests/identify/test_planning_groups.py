"""What an SRDF plans, read against the body the URDF shows (solver.identify.planning_groups):
groups that move an arm (not legs, not a chain extending another arm's group, at most
MOST_GROUPS read), and end effectors that are not feet."""

from __future__ import annotations

from solver.identify import identify_urdf
from solver.identify.planning_groups import MOST_GROUPS
from tests.identify import builders

SRDF = """<?xml version="1.0"?>
<robot name="arm6">
  <group name="manipulator"><chain base_link="base_link" tip_link="wrist_3_link"/></group>
  <group name="hand"><joint name="gripper_finger_left"/></group>
  <end_effector name="gripper" parent_link="wrist_3_link" group="hand"/>
  <virtual_joint name="fixed_base" type="fixed" parent_frame="world" child_link="base_link"/>
  <group_state name="home" group="manipulator"><joint name="elbow" value="0"/></group_state>
</robot>
"""


def test_a_chain_group_that_extends_an_arm_group_plans_the_same_arm() -> None:
    text = SRDF.replace(
        '<group name="hand">',
        '<group name="arm_with_base"><chain base_link="base_link" '
        'tip_link="wrist_3_link"/><joint name="shoulder_pan"/></group>'
        '<group name="upper"><chain base_link="base_link" tip_link="elbow_link"/></group>'
        '<group name="hand">',
    )
    plain = identify_urdf(builders.manipulator().text(), srdf_text=SRDF)
    extended = identify_urdf(builders.manipulator().text(), srdf_text=text)
    assert extended.confidence == plain.confidence
    assert any(e.startswith("SRDF: 1 arm planning group(s) (upper)") for e in extended.evidence)


def test_leg_groups_and_feet_plan_no_arm_and_no_end_effector_goals_only_the_legs_joints() -> None:
    legs = "".join(
        f'<group name="{c}_leg"><chain base_link="base_link" tip_link="{c}_foot"/></group>'
        f'<end_effector name="{c}_foot" parent_link="{c}_foot" group="{c}_leg"/>'
        for c in ("FL", "FR", "RL", "RR")
    )
    text = (
        f'<robot name="dog">{legs}<group name="all">'
        + "".join(f'<group name="{c}_leg"/>' for c in ("FL", "FR", "RL", "RR"))
        + "</group></robot>"
    )
    plain = identify_urdf(builders.quadruped().text())
    planned = identify_urdf(builders.quadruped().text(), srdf_text=text)
    assert (planned.structure, planned.confidence) == (plain.structure, plain.confidence)
    # The legs walk (a guess from the legs themselves); the SRDF plans them joint by joint
    # (labelled Joint on the development part's hexapods), no Cartesian goal.
    assert [c.motion_control for c in plain.motion_controls] == ["Walking"]
    assert [c.motion_control for c in planned.motion_controls] == ["Walking", "Joint"]


def test_many_copies_of_one_arm_group_plan_one_arm_and_the_rest_are_not_read() -> None:
    copies = "".join(
        f'<group name="copy{k}"><chain base_link="base_link" tip_link="wrist_3_link"/></group>'
        for k in range(MOST_GROUPS + 50)
    )
    result = identify_urdf(builders.manipulator().text(), srdf_text=f"<robot>{copies}</robot>")
    assert any(e.startswith("SRDF: 1 arm planning group(s) (copy0)") for e in result.evidence)
    assert result.confidence == identify_urdf(builders.manipulator().text()).confidence


def test_groups_that_point_a_sensor_or_spin_a_lidar_plan_no_arm() -> None:
    robot = builders.mobile_manipulator()  # its head pans and tilts on the torso lift
    robot.chain(robot.root, ["lidar_motor_joint"], "continuous")
    groups = (
        '<group name="head"><chain base_link="base_link" tip_link="head_tilt_link"/></group>'
        '<group name="spinner"><chain base_link="base_link" tip_link="lidar_motor_joint_link"/>'
        "</group>"
    )
    plain = identify_urdf(robot.text())
    planned = identify_urdf(robot.text(), srdf_text=f'<robot name="r">{groups}</robot>')
    assert "SRDF: 0 arm planning group(s)" in planned.evidence
    assert planned.confidence == plain.confidence
    assert planned.motion_controls == plain.motion_controls


def test_a_rovers_group_of_its_wheels_plans_no_arm() -> None:
    # A rover's MoveIt set-up grouping its four wheels (and its fixed body): the wheels move
    # the body along, nothing plans their joints' goals.
    robot = builders.ugv()
    sides = ("left", "right", "rear_left", "rear_right")
    wheels = "".join(f'<joint name="wheel_{side}_joint"/>' for side in sides)
    groups = f'<group name="wheel">{wheels}</group>'
    plain = identify_urdf(robot.text())
    planned = identify_urdf(robot.text(), srdf_text=f'<robot name="r">{groups}</robot>')
    assert "SRDF: 0 arm planning group(s)" in planned.evidence
    assert planned.motion_controls == plain.motion_controls


def test_a_whole_body_group_of_wheels_and_an_arm_plans_the_arm() -> None:
    # The wheels are set aside, not counted against it: what is left is the arm's three joints.
    robot = builders.ugv()
    builders.arm(robot, robot.root, joints=3, gripper=False)
    sides = ("left", "right", "rear_left", "rear_right")
    joints = [f"wheel_{side}_joint" for side in sides] + ["shoulder_pan", "shoulder_lift", "elbow"]
    group = "".join(f'<joint name="{name}"/>' for name in joints)
    srdf = f'<robot name="r"><group name="whole_body">{group}</group></robot>'
    planned = identify_urdf(robot.text(), srdf_text=srdf)
    assert "SRDF: 1 arm planning group(s) (whole_body)" in planned.evidence
    assert "End Effector" in {control.motion_control for control in planned.motion_controls}
