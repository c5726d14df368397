"""Mimic couplings: one actuator per group of a driver and its followers, acting where it
acts (a gear pair reads as one joint of the arm, a linkage's crank as the leg's knee), and jaws
closed by one motion."""

from __future__ import annotations

from solver.identify import identify_urdf
from solver.identify.couplings import couplings, jaw_groups
from solver.identify.readers.urdf import parse_urdf
from tests.identify import builders
from tests.identify.builders import RobotText


def test_followers_of_followers_have_one_driver() -> None:
    robot = RobotText("chain_of_mimics")
    builders.placed(robot, "a", "revolute", "base_link", "a_link")
    builders.placed(robot, "b", "revolute", "base_link", "b_link", extra='<mimic joint="a"/>')
    builders.placed(robot, "c", "revolute", "base_link", "c_link", extra='<mimic joint="b"/>')
    found = couplings(parse_urdf(robot.text(), strict=False))
    assert found.followers == {"a": ("b", "c")}
    assert found.driver("c") == "a"


def test_a_mimic_loop_or_a_mimic_of_nothing_is_no_coupling() -> None:
    robot = RobotText("loops")
    builders.placed(robot, "a", "revolute", "base_link", "a_link", extra='<mimic joint="b"/>')
    builders.placed(robot, "b", "revolute", "base_link", "b_link", extra='<mimic joint="a"/>')
    builders.placed(robot, "c", "revolute", "base_link", "c_link", extra='<mimic joint="gone"/>')
    assert couplings(parse_urdf(robot.text(), strict=False)).followers == {}


def test_a_gear_pair_stands_in_for_its_drive_gear() -> None:
    found = couplings(parse_urdf(builders.geared_arm().text(), strict=False))
    assert found.stand_ins == {"drive1": "joint1", "drive2": "joint2", "drive3": "joint3"}


def test_an_arm_drawn_as_gear_pairs_is_one_arm_not_fragments() -> None:
    result = identify_urdf(builders.geared_arm().text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.joints for limb in result.body.limbs] == [("joint1", "joint2", "joint3", "drive4")]
    # A joint command names the gears a controller drives, not the joints that follow them.
    assert [start.name for start in result.joints] == ["drive1", "drive2", "drive3", "drive4"]


def test_a_linkage_crank_is_the_knee_it_works_not_an_extra_leg() -> None:
    result = identify_urdf(builders.linkage_biped().text())
    assert result.structure == "Biped"
    assert result.body is not None
    assert [limb.joints for limb in result.body.limbs] == [
        ("l_hip", "l_thigh", "l_knee"),
        ("r_hip", "r_thigh", "r_knee"),
    ]


def test_one_motion_closing_mirrored_jaws_is_a_jaw_group() -> None:
    urdf = parse_urdf(builders.one_motion_gripper().text(), strict=False)
    assert jaw_groups(urdf, couplings(urdf)) == [("l1", "l2", "r1", "r2")]


def test_a_gear_pair_is_no_pair_of_jaws() -> None:
    # The last gear pair sits side by side with nothing beyond it, as jaws do; its ratio of
    # one half says it is a gear.
    urdf = parse_urdf(builders.geared_arm().text(), strict=False)
    assert jaw_groups(urdf, couplings(urdf)) == []
