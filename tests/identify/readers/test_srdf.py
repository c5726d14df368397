"""SRDF groups and end effectors: read, checked against the URDF, used as evidence."""

from __future__ import annotations

import pytest

from solver.errors import InputError
from solver.identify import identify_urdf
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


def test_a_planar_virtual_joint_is_a_planning_convention_not_a_mobile_base() -> None:
    # MoveIt's setup assistant writes a planar virtual joint for a bolted-down arm too.
    text = SRDF.replace('type="fixed"', 'type="planar"')
    result = identify_urdf(builders.manipulator().text(), srdf_text=text)
    assert result.structure == "Manipulator"
    assert any("a virtual joint is a planning convention" in e for e in result.evidence)


def test_an_unknown_virtual_joint_type_is_refused() -> None:
    with pytest.raises(InputError, match="unknown virtual joint type 'hover'"):
        parse_srdf(SRDF.replace('type="fixed"', 'type="hover"'))
