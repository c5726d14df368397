"""SRDF groups and end effectors: read, checked against the URDF, used as evidence."""

from __future__ import annotations

import pytest

from solver.errors import InputError
from solver.identify import identify_urdf
from solver.identify.plans import MOST_GROUPS
from solver.identify.readers.srdf import parse_srdf
from solver.identify.readers.urdf import parse_urdf
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


def test_srdf_groups_give_joint_and_end_effector_controls() -> None:
    result = identify_urdf(builders.manipulator().text(), srdf_text=SRDF, srdf_file="arm.srdf")
    assert [(c.motion_control, c.source) for c in result.motion_controls] == [
        ("Joint", "arm.srdf: planning group(s) manipulator"),
        (
            "End Effector",
            "arm.srdf: planning group(s) manipulator; arm.srdf: end effector(s) gripper",
        ),
    ]
    assert any(
        line.startswith("SRDF: 1 arm planning group(s) (manipulator)") for line in result.evidence
    )


def test_srdf_names_missing_from_the_urdf_are_all_reported() -> None:
    urdf = parse_urdf(builders.manipulator().text())
    text = SRDF.replace("wrist_3_link", "tool9").replace(
        'name="gripper_finger_left"', 'name="ghost_joint"'
    )
    with pytest.raises(InputError) as caught:
        parse_srdf(text, "arm.srdf", urdf)
    messages = [str(f) for f in caught.value.faults]
    assert len(messages) == 3
    assert any("arm.srdf:3: group[manipulator].chain.tip_link: link 'tool9'" in m for m in messages)
    assert any("joint 'ghost_joint'" in m for m in messages)


def test_an_srdf_that_disagrees_about_the_arms_lowers_confidence() -> None:
    one_arm = """<robot name="dual">
      <group name="left"><chain base_link="torso_waist_link" tip_link="left_wrist_3_link"/></group>
    </robot>"""
    both = one_arm.replace(
        "</robot>",
        '<group name="right"><chain base_link="torso_waist_link" '
        'tip_link="right_wrist_3_link"/></group></robot>',
    )
    agreed = identify_urdf(builders.torso().text(), srdf_text=both)
    doubted = identify_urdf(builders.torso().text(), srdf_text=one_arm)
    assert doubted.confidence < agreed.confidence
    assert any("the SRDF plans 1 arm(s), the tree shows 2" in e for e in doubted.evidence)


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


def test_leg_groups_and_feet_plan_no_arm_and_no_end_effector_goals() -> None:
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
    # The legs walk (a guess from the legs themselves); the SRDF adds no goal for them.
    assert planned.motion_controls == plain.motion_controls
    assert [c.motion_control for c in planned.motion_controls] == ["Walking"]


def test_many_copies_of_one_arm_group_plan_one_arm_and_the_rest_are_not_read() -> None:
    copies = "".join(
        f'<group name="copy{k}"><chain base_link="base_link" tip_link="wrist_3_link"/></group>'
        for k in range(MOST_GROUPS + 50)
    )
    result = identify_urdf(builders.manipulator().text(), srdf_text=f"<robot>{copies}</robot>")
    assert any(e.startswith("SRDF: 1 arm planning group(s) (copy0)") for e in result.evidence)
    assert result.confidence == identify_urdf(builders.manipulator().text()).confidence


def test_a_planar_virtual_joint_makes_a_mobile_base() -> None:
    text = SRDF.replace('type="fixed"', 'type="planar"')
    assert (
        identify_urdf(builders.manipulator().text(), srdf_text=text).structure
        == "Mobile Manipulator"
    )


def test_an_unknown_virtual_joint_type_is_refused() -> None:
    with pytest.raises(InputError, match="unknown virtual joint type 'hover'"):
        parse_srdf(SRDF.replace('type="fixed"', 'type="hover"'))
