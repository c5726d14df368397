"""Hands and grippers: the joints below a gripper move fingers, fingers without names are told
by where they hang, and a hand is counted by its fingers' tips."""

from __future__ import annotations

import math

import pytest

from solver.identify import identify_urdf, load_profile
from solver.identify.hands import (
    _MOST_SIZED_FINGERS,
    _finger_sized,
    _pair_on_one_body,
    _tips_meet,
    finger_groups,
    finger_tips,
    gripper_closure,
)
from solver.identify.limbs import Limb
from solver.identify.readers.urdf import Joint, parse_urdf
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText


def tree_of(robot: RobotText) -> JointTree:
    return JointTree(parse_urdf(robot.text(), strict=False), load_profile())


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
    assert result.body is not None
    assert len(result.body.fingers) == 2


@pytest.mark.parametrize("regulator", ["suction_regulator", "vacuum_cup_level"])
def test_a_vacuum_gripper_whose_one_joint_stands_for_its_suction_is_a_gripper(
    regulator: str,
) -> None:
    """Suction cups fixed to the body and one slide standing for the vacuum's level (a
    simulator's stand-in for the pump): a gripper, opened and closed on command."""
    robot = RobotText("vacuum_gripper")
    for cup in range(4):
        robot.fixed("base_link", f"suction{cup}")
    robot.chain("base_link", [regulator], "prismatic")
    result = identify_urdf(robot.text())
    assert result.structure == "Gripper"
    assert {c.motion_control for c in result.motion_controls} == {"Joint"}


def test_a_robot_vacuum_cleaners_brush_is_no_gripper() -> None:
    """A cleaner's vacuum is no cup: only a vacuum's cup, pad, gripper or tool holds a part."""
    robot = RobotText("cleaner")
    robot.chain("base_link", ["vacuum_brush_joint"], "continuous")
    assert identify_urdf(robot.text()).structure != "Gripper"
    with_wheels = builders.ugv()
    with_wheels.chain(with_wheels.root, ["vacuum_brush_joint"], "continuous")
    assert identify_urdf(with_wheels.text()).structure == "UGV"


def test_a_hand_whose_finger_chains_carry_no_names_is_a_hand() -> None:
    robot = RobotText("claw")
    for f in range(3):
        robot.chain("base_link", [f"j{f}_{i}" for i in range(3)])
    result = identify_urdf(robot.text())
    assert result.structure == "Hand"
    assert result.body is not None
    assert len(result.body.fingers) == 3


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
    assert result.body is not None
    assert (result.body.count("arm"), result.body.grippers) == (1, 1)


def test_chains_a_joint_longer_than_a_finger_ending_in_named_fingertips_are_fingers() -> None:
    # A four-finger hand of unnamed joints: two fingers of four joints, two of five (a
    # rotation at their base), each ending in a link fixed to a `fingertip_N` frame. Without
    # the fingertips' names the two long chains are arms beside two fingers.
    def hand(tip: str) -> RobotText:
        robot = RobotText("hand4", root="base")
        for f, joints in enumerate((5, 4, 4, 5), start=1):
            last = robot.chain("base", [f"q{f}{k}" for k in range(joints)])
            robot.joint(f"q{f}_end", "fixed", last, f"{tip}_{f}")
        return robot

    assert identify_urdf(hand("fingertip").text()).structure == "Hand"
    assert identify_urdf(hand("end").text()).structure == "Torso"


@pytest.mark.parametrize("ends", [("left_finger", "right_finger"), ("thumbscrew",), ("knuckle",)])
def test_five_joint_arms_whose_wrists_carry_finger_words_but_no_fingertip_stay_arms(
    ends: tuple[str, ...],
) -> None:
    # A cell of three unnamed five-joint arms, each wrist carrying fixed jaws named as
    # fingers, a thumbscrew or a knuckle: no fingertip frame ends them, so they stay arms.
    robot = RobotText("cell")
    for arm in "abc":
        wrist = robot.chain("base_link", [f"{arm}j{k}" for k in range(1, 6)])
        for end in ends:
            robot.joint(f"{arm}_{end}_fix", "fixed", wrist, f"{arm}_{end}")
    result = identify_urdf(robot.text())
    assert result.structure == "Torso"
    assert result.body is not None
    assert result.body.count("arm") == 3


def test_arms_whose_hands_mount_fingers_on_fixed_finger_bases_stay_arms() -> None:
    # An upper body: a waist, a two-joint neck and two unnamed five-joint arms ending in
    # palms, each palm's named fingers on fixed `*_finger_base` links (mounts, no tips).
    robot = RobotText("upper")
    waist = robot.chain("base_link", ["waist"])
    robot.chain(waist, ["n1", "n2"])
    for side in "lr":
        palm = robot.fixed(robot.chain(waist, [f"{side}j{k}" for k in range(1, 6)]), f"{side}_palm")
        for finger in ("index", "middle"):
            base = robot.fixed(palm, f"{side}_{finger}_finger_base")
            robot.chain(base, [f"{side}_{finger}_finger_j1", f"{side}_{finger}_finger_j2"])
    result = identify_urdf(robot.text())
    assert result.structure == "Torso"
    assert result.body is not None
    assert (result.body.count("arm"), result.body.grippers) == (2, 2)


def test_fingers_on_a_link_named_as_a_hand_make_the_arm_end_in_a_gripper() -> None:
    robot = RobotText("arm_hand")
    wrist = robot.chain("base_link", ["a1", "a2", "a3", "a4"])
    robot.fixed(wrist, "r_hand_base")
    for f in range(4):
        robot.chain("r_hand_base", [f"f{f}"])
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert result.body.limbs[0].gripper


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
    assert result.body is not None
    assert result.body.grippers == 0
    assert [len(limb.joints) for limb in result.body.limbs] == [6]


def test_the_closure_of_a_gripper_joint_holds_every_movable_joint_below_it_and_no_other() -> None:
    robot = RobotText("closure")
    wrist = robot.chain("base_link", ["a1", "a2"])
    jaw = robot.chain(wrist, ["jaw"], "prismatic")
    robot.fixed(jaw, "pad")
    robot.chain("pad", ["pad_tilt"])
    robot.chain(wrist, ["camera_pan"])
    assert gripper_closure(tree_of(robot), {"jaw"}) == {"jaw", "pad_tilt"}


def test_a_finger_of_three_gripper_joints_has_one_tip_and_tips_come_in_document_order() -> None:
    robot = RobotText("two fingers", root="palm")
    robot.chain("palm", ["b1", "b2", "b3"])
    robot.chain("palm", ["a1", "a2", "a3"])
    grippers = {"a1", "a2", "a3", "b1", "b2", "b3"}
    assert finger_tips(tree_of(robot), grippers) == ["b3", "a3"]


def _chains(robot: RobotText, link: str, count: int) -> list[Limb]:
    limbs = []
    for f in range(count):
        names = [f"{link}{f}_a", f"{link}{f}_b"]
        tip = robot.chain(link, names)
        limbs.append(Limb("other", tuple(names), link, tip))
    return limbs


def test_three_short_unnamed_chains_on_one_link_are_fingers_and_two_are_not() -> None:
    robot = RobotText("claws")
    three = _chains(robot, "base_link", 3)
    mount = robot.chain("base_link", ["mount"])  # another body, a joint away
    two = _chains(robot, mount, 2)
    tree = tree_of(robot)
    assert finger_groups(tree, three + two) == {name for limb in three for name in limb.joints}
    # On a body that rolls, the chains on its root are the base's own (a tracked vehicle's
    # flippers).
    assert finger_groups(tree, three + two, grounded=True) == set()


def upper_body(elbow: float, shoulder: float = 0.18) -> RobotText:
    """A chest turned by three hinges, carrying a neck of three hinges at one place and two
    chains ``shoulder`` metres to each side of it of a shoulder's three hinges and an elbow
    ``elbow`` metres below them, no names."""
    robot = RobotText("character", root="l0")
    chest = robot.chain("l0", ["j0", "j1", "j2"])
    robot.chain(chest, ["j3", "j4", "j5"])
    for side, y in (("a", shoulder), ("b", -shoulder)):
        link = builders.placed(robot, f"{side}0", "revolute", chest, f"{side}0_l", xyz=f"0 {y} 0.2")
        link = robot.chain(link, [f"{side}1", f"{side}2"])
        builders.placed(robot, f"{side}3", "revolute", link, f"{side}3_l", xyz=f"0 0 -{elbow}")
    return robot


def test_chains_on_one_body_one_of_which_reaches_farther_than_a_finger_are_no_fingers() -> None:
    # An animated character's neck and arms, each joint of a ball written as three hinges:
    # the arms' elbows 0.27 m from their shoulders, as no finger's last knuckle is from its
    # first.
    result = identify_urdf(upper_body(0.27).text())
    assert "finger" not in {role.role for role in result.roles}
    assert result.structure != "Hand"
    # Knuckles 4 cm apart are a hand's fingers, where the chains start within a hand's
    # breadth of each other; not 36 cm apart.
    hand = identify_urdf(upper_body(0.04, shoulder=0.04).text())
    assert "finger" in {role.role for role in hand.roles}
    assert "finger" not in {role.role for role in identify_urdf(upper_body(0.04).text()).roles}


def test_short_unnamed_chains_on_a_flying_bodys_airframe_are_its_own_and_no_fingers() -> None:
    # Four single hinges on links fixed to the root, and three short chains on a link a joint
    # away: on a body that does not fly, two groups of fingers; on one that flies the four are
    # its own (a blimp's rudders and elevators), the three still a claw's fingers.
    robot = RobotText("airship")
    airframe = []
    for i in range(4):
        base = robot.fixed("base_link", f"part{i}")
        airframe.append(Limb("other", (f"h{i}",), base, robot.chain(base, [f"h{i}"])))
    mount = robot.chain("base_link", ["mount"])
    claw = _chains(robot, mount, 3)
    tree = tree_of(robot)
    hinges = {name for limb in airframe for name in limb.joints}
    fingers = {name for limb in claw for name in limb.joints}
    assert finger_groups(tree, airframe + claw) == hinges | fingers
    assert finger_groups(tree, airframe + claw, flying=True) == fingers


def test_single_hinges_farther_apart_than_a_hand_is_broad_are_no_fingers() -> None:
    # A small aircraft with every name removed: two ailerons 0.55 m apart across its wings, an
    # elevator and a rudder 0.6 m behind; and a claw's three hinges 4 cm apart on one palm.
    def hinges(places: list[tuple[float, float, float]]) -> str:
        robot = RobotText("r")
        for i, (x, y, z) in enumerate(places):
            builders.placed(robot, f"j{i}", "revolute", robot.root, f"l{i}", xyz=f"{x} {y} {z}")
        return identify_urdf(robot.text()).structure

    assert hinges([(-0.03, 0.28, 0), (-0.03, -0.28, 0), (-0.58, 0, 0), (-0.65, 0, 0.02)]) != "Hand"
    assert hinges([(0, 0.04, 0), (0, 0, 0), (0, -0.04, 0)]) == "Hand"


def test_a_slide_beside_hinges_farther_apart_than_a_hand_is_broad_is_no_hand() -> None:
    # A cable robot drawn as a stage sliding three ways in the middle of its frame, and a cable
    # hanging on a hinge from each of its four pillars' tops, 2 m apart; then the same stage
    # among three hinges 4 cm apart (a jaw that slides beside three fingers).
    def stage_and_hinges(places: list[tuple[float, float, float]]) -> str:
        robot = RobotText("r")
        robot.chain(robot.root, ["x", "y", "z"], "prismatic")
        for i, (x, y, z) in enumerate(places):
            builders.placed(robot, f"j{i}", "revolute", robot.root, f"l{i}", xyz=f"{x} {y} {z}")
        return identify_urdf(robot.text()).structure

    assert stage_and_hinges([(1, 1, 2), (1, -1, 2), (-1, 1, 2), (-1, -1, 2)]) != "Hand"
    assert stage_and_hinges([(0, 0.04, 0), (0, 0, 0), (0, -0.04, 0)]) == "Hand"


def segmented(steps: list[list[tuple[float, float, float]]]) -> RobotText:
    """A body with one unnamed chain per entry of ``steps``, starting 0.03 m apart across it:
    a joint at each step (an offset from the joint before), its tip one step further."""
    robot = RobotText("segmented", root="body")
    for c, chain in enumerate(steps):
        link, (x, y, z) = "body", (0.0, 0.03 * (c - 1), 0.0)
        for j, step in enumerate(chain[:-1]):
            link = builders.placed(
                robot, f"j{c}_{j}", "revolute", link, f"l{c}_{j}", xyz=f"{x} {y} {z}",
                axis="0 1 0",
            )  # fmt: skip
            x, y, z = step
        robot.joint(f"tip{c}", "fixed", link, f"tip{c}_link", f'<origin xyz="{x} {y} {z}"/>')
    return robot


def test_three_unnamed_chains_of_many_short_links_are_flexure_fingers() -> None:
    # Ten joints 8 mm apart: longer than a finger's joints, no longer than a finger.
    robot = segmented([[(0.0, 0.0, 0.008)] * 11] * 3)
    result = identify_urdf(robot.text())
    assert result.structure == "Hand"
    assert result.body is not None
    assert len(result.body.fingers) == 3


def test_arms_folded_at_rest_are_as_long_as_their_links_and_no_fingers() -> None:
    # Six joints 0.1 m apart, each link folding back on the last: the tips end 7 cm from the
    # starts, as near as a finger's would.
    folded = [(0.0, 0.01, 0.1 if j % 2 == 0 else -0.1) for j in range(7)]
    assert identify_urdf(segmented([folded] * 3).text()).structure != "Hand"


@pytest.mark.parametrize("joints", [5, 10])
def test_short_chains_of_many_links_whose_tips_meet_hold_one_platform_and_are_no_fingers(
    joints: int,
) -> None:
    # Each chain steps in towards the middle: the three tips meet above the palm (a small delta),
    # with one joint more than a finger's four (no fingertip named), or many more.
    chains = [[(0.0, -0.03 * (c - 1) / joints, 0.06 / joints)] * (joints + 1) for c in range(3)]
    assert identify_urdf(segmented(chains).text()).structure != "Hand"


def test_a_chain_that_slides_or_turns_twice_at_one_point_past_its_first_is_no_flexure_finger() -> (
    None
):
    # A small Stewart platform's strut slides; a linkage's ball joint is hinges at one point.
    finger = Limb("arm", tuple(f"j0_{j}" for j in range(10)), "body", "tip0_link")
    robot = segmented([[(0.0, 0.0, 0.008)] * 11] * 3)
    assert _finger_sized(tree_of(robot), finger)
    strut = robot.text().replace('name="j0_5" type="revolute"', 'name="j0_5" type="prismatic"')
    assert not _finger_sized(JointTree(parse_urdf(strut, strict=False), load_profile()), finger)
    ball = segmented([[(0.0, 0.0, 0.008)] * 3 + [(0.0, 0.0, 0.0)] + [(0.0, 0.0, 0.008)] * 7])
    assert not _finger_sized(tree_of(ball), finger)


def test_chains_past_the_most_fingers_a_palm_holds_are_not_compared_pair_by_pair() -> None:
    robot = segmented([[(0.0, 0.0, 0.008)] * 11] * 3)
    fingers = [
        Limb("arm", tuple(f"j{c}_{j}" for j in range(10)), "body", f"tip{c}_link") for c in range(3)
    ]
    assert not _tips_meet(tree_of(robot), fingers)
    assert _tips_meet(tree_of(robot), fingers * _MOST_SIZED_FINGERS)


def test_jaws_closed_by_one_motion_are_a_gripper_whatever_their_names() -> None:
    result = identify_urdf(builders.one_motion_gripper().text())
    assert result.structure == "Gripper"
    assert result.body is not None
    assert result.body.finger_motions == 1  # one actuator: a gripper, not a hand
    assert {role.role for role in result.roles} == {"finger"}


def lever(ratios: tuple[str, str]) -> RobotText:
    """A lever (the driven joint) between two joints that follow it at ``ratios``; no name
    says gripper."""
    robot = RobotText("lever", root="base")
    builders.placed(robot, "lever", "revolute", "base", "lever_link", xyz="0.05 0 0")
    for jaw, y, ratio in (("a", "0.03", ratios[0]), ("b", "-0.03", ratios[1])):
        builders.placed(
            robot, jaw, "revolute", "base", f"{jaw}_link", xyz=f"0.05 {y} 0",
            extra=f'<mimic joint="lever" multiplier="{ratio}"/>',
        )  # fmt: skip
    return robot


def test_jaws_a_lever_between_them_works_at_a_ratio_of_their_own_are_a_gripper() -> None:
    result = identify_urdf(lever(("0.5", "-0.5")).text())  # one mirrors the other
    assert result.structure == "Gripper"
    assert result.body is not None
    assert result.body.finger_motions == 1


@pytest.mark.parametrize(
    "ratios", [("0.5", "0.5"), ("0", "0")], ids=["turning one way (gears)", "not moving"]
)
def test_followers_of_a_lever_that_do_not_close_on_each_other_are_no_jaws(
    ratios: tuple[str, str],
) -> None:
    assert identify_urdf(lever(ratios).text()).structure != "Gripper"


def test_an_srdf_group_of_a_grippers_jaws_is_no_arm_group() -> None:
    srdf = (
        '<robot name="jaws"><group name="gripper"><joint name="r1"/><joint name="r2"/>'
        '<joint name="l1"/><joint name="l2"/></group></robot>'
    )
    result = identify_urdf(builders.one_motion_gripper().text(), srdf_text=srdf)
    assert result.structure == "Gripper"
    assert "End Effector" not in {c.motion_control for c in result.motion_controls}


def test_two_jaws_side_by_side_at_the_end_of_an_arm_make_it_end_in_a_gripper() -> None:
    # A humanoid's split gripper: two grip joints on the wrist, mirrored, each driven alone.
    robot = builders.humanoid()
    for side, sign in (("l", 1), ("r", -1)):
        wrist = f"{side}_wrist_2_link"
        builders.placed(
            robot,
            f"{side}_grip",
            "revolute",
            wrist,
            f"{side}_grip_a",
            xyz=f"0.09 {0.058 * sign} 0",
            axis="0 0 -1",
        )
        builders.placed(
            robot,
            f"{side}_grip_1",
            "revolute",
            wrist,
            f"{side}_grip_b",
            xyz=f"0.09 {0.032 * sign} 0",
            axis="0 0 1",
        )
    result = identify_urdf(robot.text())
    assert result.structure == "Humanoid"
    assert result.body is not None
    assert [limb.gripper for limb in result.body.limbs if limb.kind == "arm"] == [True, True]


def servo_arm(tip_joints: int = 1) -> RobotText:
    """Four numbered hinges, then two mirrored hinges side by side on the last link, each
    carrying ``tip_joints`` more hinges of its own (a servo gripper whose fingers and fingertips
    an open linkage draws, no mimic between them)."""
    robot = RobotText("servo_arm", root="base_link")
    link = "base_link"
    for i in range(1, 5):
        link = builders.placed(robot, f"J{i}", "revolute", link, f"link{i}", xyz="0 0 0.1")
    for name, y, limits in (("J5", 0.014, "0 1.5"), ("J6", -0.014, "-1.5 0")):
        lower, upper = limits.split()
        part = robot.joint(
            name,
            "revolute",
            link,
            f"{name}_link",
            f'<origin xyz="0 {y} 0.05"/><axis xyz="1 0 0"/>'
            f'<limit lower="{lower}" upper="{upper}" effort="1" velocity="1"/>',
        )
        for k in range(tip_joints):
            part = builders.placed(robot, f"{name}_tip{k}", "revolute", part, f"{name}_t{k}")
    return robot


def plated_arm(plates: int = 2) -> RobotText:
    """Four numbered hinges, then ``plates`` plates fixed to the last link (every other one
    turned half round), each carrying one hinge about x with the same limits: a gripper whose
    jaws hinge on plates fixed to its palm, named nothing."""
    robot = RobotText("plated_arm", root="base_link")
    link = "base_link"
    for i in range(1, 5):
        link = builders.placed(robot, f"J{i}", "revolute", link, f"link{i}", xyz="0 0 0.1")
    for k in range(plates):
        plate = builders.placed(
            robot,
            f"F{k}",
            "fixed",
            link,
            f"plate{k}",
            xyz=f"0.02 {0.018 * (-1) ** k * (k // 2 + 1)} 0.08",
            rpy=f"0 0 {math.pi * (k % 2)}",
        )
        robot.joint(
            f"H{k}",
            "revolute",
            plate,
            f"piece{k}",
            '<axis xyz="1 0 0"/><limit lower="-0.03" upper="0.7" effort="3" velocity="1"/>',
        )
    return robot


def test_two_hinges_on_plates_fixed_to_an_arms_last_link_are_its_jaws() -> None:
    result = identify_urdf(plated_arm().text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.gripper for limb in result.body.limbs if limb.kind == "arm"] == [True]
    # Two such hinges on plates of two links apart are no pair of jaws.
    apart = plated_arm()
    apart.joints = [
        j.replace('"link4"/><child link="plate1"', '"link3"/><child link="plate1"')
        for j in apart.joints
    ]
    body = identify_urdf(apart.text()).body
    assert body is not None
    assert not any(limb.gripper for limb in body.limbs)


def hinges_by_plate(tree: JointTree, names: list[str]) -> dict[str, list[Joint]]:
    """The named joints of ``tree``, by the link each hangs from (as the jaw search keeps them)."""
    by_parent: dict[str, list[Joint]] = {}
    for name in names:
        joint = tree.urdf.joint(name)
        assert joint is not None
        by_parent.setdefault(joint.parent, []).append(joint)
    return by_parent


def test_one_hinge_on_each_of_two_plates_fixed_to_one_body_is_a_pair_on_that_body() -> None:
    by_parent = hinges_by_plate(tree_of(plated_arm()), ["H0", "H1"])
    _pair_on_one_body(tree_of(plated_arm()), by_parent)
    assert list(by_parent) == ["link4"]
    assert [(j.name, j.parent) for j in by_parent["link4"]] == [("H0", "link4"), ("H1", "link4")]


def test_a_hinge_on_the_body_itself_and_one_on_a_plate_are_left_where_they_hang() -> None:
    robot = plated_arm(plates=1)
    robot.joint("H_body", "revolute", "link4", "piece_body", '<axis xyz="1 0 0"/>')
    tree = tree_of(robot)
    by_parent = hinges_by_plate(tree, ["H0", "H_body"])
    _pair_on_one_body(tree, by_parent)
    assert {link: [j.name for j in joints] for link, joints in by_parent.items()} == {
        "plate0": ["H0"],
        "link4": ["H_body"],
    }


def test_a_plate_with_two_hinges_keeps_them_and_is_paired_with_no_other_plate() -> None:
    robot = plated_arm()
    robot.joint("H0b", "revolute", "plate0", "piece0b", '<axis xyz="1 0 0"/>')
    tree = tree_of(robot)
    by_parent = hinges_by_plate(tree, ["H0", "H0b", "H1"])
    _pair_on_one_body(tree, by_parent)
    assert {link: [j.name for j in joints] for link, joints in by_parent.items()} == {
        "plate0": ["H0", "H0b"],
        "plate1": ["H1"],
    }


def test_mirrored_hinges_each_carrying_a_fingertip_hinge_at_an_arms_end_are_its_jaws() -> None:
    result = identify_urdf(servo_arm().text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [limb.gripper for limb in result.body.limbs] == [True]


def test_mirrored_chains_of_three_hinges_at_an_arms_end_are_a_torsos_arms_not_jaws() -> None:
    # Three hinges each, as long as the four below them: two short arms on a trunk.
    result = identify_urdf(servo_arm(tip_joints=2).text())
    assert not [role.joint for role in result.roles if role.role == "finger"]
    assert result.structure == "Torso"


@pytest.mark.parametrize("named", [True, False])
def test_two_short_arms_travelling_alike_on_a_waist_are_no_tipped_jaws(named: bool) -> None:
    # A waist of two joints carrying two arms of a shoulder and an elbow each, limits -1..1:
    # they do not mirror each other (a travel symmetric about zero), so they are no jaws.
    robot = RobotText("torso", root="base_link")
    waist = robot.chain("base_link", ["waist_yaw", "waist_pitch"] if named else ["j1", "j2"])
    for side, y in (("l", 0.2), ("r", -0.2)):
        names = [f"{side}_shoulder", f"{side}_elbow"] if named else [f"{side}1", f"{side}2"]
        upper = builders.placed(
            robot, names[0], "revolute", waist, f"{names[0]}_link", xyz=f"0 {y} 0"
        )
        builders.placed(robot, names[1], "revolute", upper, f"{names[1]}_link", xyz="0.25 0 0")
    result = identify_urdf(robot.text())
    assert not [role.joint for role in result.roles if role.role == "finger"]


def spinning_pair(robot: RobotText, link: str) -> None:
    """Two unnamed joints that turn without limits side by side on ``link`` (a sloppy file's
    jaws, or a hub's rim halves)."""
    for name, side in (("a", "0.04"), ("b", "-0.04")):
        builders.placed(robot, name, "continuous", link, f"{name}_link", xyz=f"0.05 {side} 0")


def test_two_jaws_turning_without_limits_at_the_end_of_an_arm_make_it_end_in_a_gripper() -> None:
    robot = builders.ugv()
    spinning_pair(robot, robot.chain(robot.root, [f"j{i}" for i in range(1, 7)]))
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert [limb.gripper for limb in result.body.limbs if limb.kind == "arm"] == [True]
    # On a short chain, or on a hub that slides far enough to place the body in a
    # simulator's world (a wheel-leg's rim halves), they close on nothing.
    short = builders.ugv()
    spinning_pair(short, short.chain(short.root, ["j1", "j2"]))
    slid = RobotText("segway", root="world_base")
    travel = '<limit lower="-200" upper="200" effort="1" velocity="1"/>'
    for name, axis in (("z_slide", "0 0 1"), ("x_slide", "1 0 0")):
        slid.joint(
            name, "prismatic", slid.links[-1], f"{name}_link", f'<axis xyz="{axis}"/>{travel}'
        )
    spinning_pair(slid, slid.chain(slid.links[-1], ["hub"], "continuous"))
    for robot in (short, slid):
        assert "finger" not in {role.role for role in identify_urdf(robot.text()).roles}


def test_twin_wheels_on_a_shin_or_wheels_under_a_planners_root_joints_are_no_endless_jaws() -> None:
    # A wheel-legged quadruped whose shins each carry twin endless wheels: wheels, read before
    # any jaw. A wheeled base placed by a planner's six root joints (x, y, z and three turns):
    # the root joints are no arm, so its two wheels close on nothing.
    walker = RobotText("twin")
    for leg, y in (("fl", 0.2), ("fr", -0.2), ("rl", 0.2), ("rr", -0.2)):
        shin = walker.chain(walker.root, [f"{leg}_haa", f"{leg}_hfe", f"{leg}_kfe"])
        for wheel, dy in (("a", 0.03), ("b", 0.08)):
            side = dy if y > 0 else -dy
            builders.placed(
                walker,
                f"{leg}_{wheel}",
                "continuous",
                shin,
                f"{leg}_{wheel}_link",
                xyz=f"0 {side} -0.3",
                axis="0 1 0",
            )
    placed = RobotText("planned", root="world")
    link = builders.simulated_root(placed, "base")
    for name, across in (("a", "0.2"), ("b", "-0.2")):
        builders.placed(
            placed, name, "continuous", link, f"{name}_link", xyz=f"0 {across} -0.05", axis="0 1 0"
        )
    for robot in (walker, placed):
        result = identify_urdf(robot.text())
        assert "finger" not in {role.role for role in result.roles}
        assert "Driving" in {c.motion_control for c in result.motion_controls}


def test_hinges_whose_range_no_stop_has_behind_an_articulated_waist_are_wheels_not_jaws() -> None:
    # An articulated rover written by a simulator's export: every wheel a revolute joint of
    # +-1.8e308 rad, the rear pair on an axle that rolls behind a waist that yaws, no names.
    robot = RobotText("articulated", root="l0")
    endless = '<limit lower="-1.79769e+308" upper="1.79769e+308" effort="1" velocity="1"/>'
    for name, parent, xyz in (("j0", "l0", "0 0.25 0.18"), ("j1", "l0", "0 -0.25 0.18")):
        robot.joint(
            name,
            "revolute",
            parent,
            f"{name}_l",
            f'<origin xyz="{xyz}"/><axis xyz="0 1 0"/>{endless}',
        )
    builders.placed(robot, "j4", "revolute", "l0", "rear", xyz="-0.35 0 0.22", axis="0 0 1")
    builders.placed(robot, "j5", "revolute", "rear", "axle", xyz="-0.7 0 -0.04", axis="1 0 0")
    for name, y in (("j2", "0.25"), ("j3", "-0.25")):
        robot.joint(
            name,
            "revolute",
            "axle",
            f"{name}_l",
            f'<origin xyz="0 {y} 0"/><axis xyz="0 1 0"/>{endless}',
        )
    result = identify_urdf(robot.text())
    assert "finger" not in {role.role for role in result.roles}
    assert sorted(role.joint for role in result.roles if role.role == "wheel") == [
        "j0",
        "j1",
        "j2",
        "j3",
    ]
    assert result.structure == "UGV"


def test_jaws_apart_along_one_line_but_a_hair_across_it_are_side_by_side() -> None:
    # A CAD export places a six-joint arm's two unnamed sliding fingers 0.8 m apart across the
    # tool and 0.03 m apart along its axis (the second finger turned half a turn about x):
    # apart along one line, within a tenth of the distance; beside it by as much as a third
    # they are no jaws by that rule.
    def arm(across: float) -> RobotText:
        robot = RobotText("arm6")
        tool = builders.arm(robot, robot.root, gripper=False)
        for name, y, z, rpy in (
            ("s1", -0.4, -across / 2, "0 0 0"),
            ("s2", 0.4, across / 2, "3.1416 0 0"),
        ):
            builders.placed(
                robot, name, "prismatic", tool, f"{name}_l", xyz=f"0.53 {y} {z}", rpy=rpy
            )
        return robot

    def read(across: float) -> tuple[list[str], list[bool]]:
        body = identify_urdf(arm(across).text()).body
        assert body is not None
        found = {role.joint: role.role for role in body.roles}
        ends = [limb.gripper for limb in body.limbs if limb.kind == "arm"]
        return [found.get(name, "") for name in ("s1", "s2")], ends

    assert read(0.032) == (["finger", "finger"], [True])
    assert read(0.09)[0] == ["other", "other"]  # more than a tenth of 0.8 m across


def test_hinges_a_hair_off_one_line_on_a_head_or_a_torso_are_no_jaws() -> None:
    # Two eyelids on a pan/tilt head, and two one-joint arms on a waist, placed 2 and 30 mm
    # off one line: hinges must sit exactly side by side to be jaws (sliding fingers may not).
    robot = builders.ugv()
    head = robot.chain(robot.root, ["neck_pan", "neck_tilt"])
    builders.placed(
        robot, "lid_l", "revolute", head, "lid_l_link", xyz="0.08 0.03 0.05", axis="0 1 0"
    )
    builders.placed(
        robot, "lid_r", "revolute", head, "lid_r_link", xyz="0.08 -0.03 0.052", axis="0 1 0"
    )
    waist = robot.chain(robot.root, ["waist_yaw", "waist_pitch"])
    builders.placed(robot, "arm_l", "revolute", waist, "arm_l_link", xyz="0 0.2 0.3", axis="0 1 0")
    builders.placed(
        robot, "arm_r", "revolute", waist, "arm_r_link", xyz="0 -0.2 0.33", axis="0 1 0"
    )
    body = identify_urdf(robot.text()).body
    assert body is not None
    roles = {role.joint: role.role for role in body.roles}
    assert not {"lid_l", "lid_r", "arm_l", "arm_r"} & {
        n for n, r in roles.items() if r in ("finger", "gripper")
    }


def spread_hand(fingers: int = 4) -> RobotText:
    """A hand of unnamed joints: on each metacarpal link fixed to the palm, a spreading joint
    (``aaN``) into a knuckle link that carries a 3-joint finger and a 1-joint tendon driver."""
    robot = RobotText("anatomy", root="palm")
    for i in range(1, fingers + 1):
        meta = robot.joint(f"meta{i}", "fixed", "palm", f"meta{i}_link")
        knuckle = robot.chain(meta, [f"aa{i}"])
        robot.chain(knuckle, [f"mcp{i}", f"pip{i}", f"dip{i}"])
        robot.chain(knuckle, [f"act{i}"])
    return robot


def test_fingers_that_spread_on_a_joint_of_their_own_before_they_branch_make_a_hand() -> None:
    result = identify_urdf(spread_hand().text())
    assert result.structure == "Hand"
    roles = {role.joint: role.role for role in result.roles}
    assert {roles[f"aa{i}"] for i in range(1, 5)} == {"finger"}


def test_two_spreading_chains_on_one_palm_are_no_hand() -> None:
    assert identify_urdf(spread_hand(2).text()).structure != "Hand"


def crank_hand() -> RobotText:
    """A hand of joints and links no name says anything of (``jN``, ``lN``; a crank-driven
    design): two fingers and a thumb, each spreading on a joint of its own (``j1``, ``j6``,
    ``j12``) into a knuckle link carrying the finger's two flexions and, beside them, its
    crank and pusher; the thumb's spread sits on a link its rotation (``j11``) turns, which
    carries nothing else. Every limit zero, as its exporter wrote them (placeholders)."""
    robot = RobotText("r", root="l0")
    count = iter(range(1, 100))

    def hinge(parent: str, xyz: str, rpy: str) -> str:
        index = next(count)
        shape = f'<origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="0 0 1"/>'
        limit = '<limit lower="0" upper="0" effort="1" velocity="1"/>'
        return robot.joint(f"j{index}", "revolute", parent, f"l{index}", shape + limit)

    for parent, xyz in (("l0", "-0.022 0 0"), ("l0", "0.022 0 0"), (None, "0 0.021 0.02")):
        # The thumb's spread on its rotation.
        on = parent or hinge("l0", "0.0392 -0.031 -0.062", "1.5708 0 0")
        knuckle = hinge(on, xyz, "1.5708 -1.5708 0")
        hinge(hinge(knuckle, "0 0 0.0135", "-1.5708 -0.13963 0"), "0.05 0 0", "0 0 -0.34703")
        hinge(hinge(knuckle, "0.034 0 -0.0065", "1.5708 -1.1692 3.1416"), "-0.062 0 0", "0 0 0.45")
    return robot


def test_a_thumb_spreading_from_a_rotation_of_its_own_counts_on_the_palm() -> None:
    # Two fingers spread on the palm; the thumb spreads on a link its rotation turns toward
    # the palm, carrying that spread alone: three fingers on one palm, a hand.
    result = identify_urdf(crank_hand().text())
    assert result.structure == "Hand"
    roles = {role.joint: role.role for role in result.roles}
    assert {roles["j1"], roles["j6"], roles["j12"]} == {"finger"}


def wheel_legs(hubs: int = 6) -> RobotText:
    """A wheel-leg walker: hubs that turn all the way round, each carrying two rim halves on
    joints of their own (they open into a leg, close into a wheel)."""
    robot = RobotText("wheel_legs", root="body")
    for i in range(hubs):
        hub = robot.chain("body", [f"hub{i}"], "continuous")
        robot.chain(hub, [f"rim{i}a"], "continuous")
        robot.chain(hub, [f"rim{i}b"], "continuous")
    return robot


def test_a_hub_turning_all_the_way_round_spreads_no_finger() -> None:
    result = identify_urdf(wheel_legs().text())
    assert result.structure != "Hand"
    assert not [role for role in result.roles if role.role == "finger"]


def test_a_hand_exported_with_every_joint_continuous_still_spreads_its_fingers() -> None:
    # A CAD export writes no limits: the spreading joints turn whole as written, but each
    # carries a finger of three joints, no rim half of one.
    text = spread_hand().text().replace('type="revolute"', 'type="continuous"')
    assert identify_urdf(text).structure == "Hand"


def test_endless_joints_at_the_ends_of_limited_ones_are_wheels_on_pivots_not_fingers() -> None:
    # Four unnamed chains on one frame, each a pivot with limits carrying a joint that turns
    # endless (a rover's wheel on a rocker, drawn folded): no finger spins whole.
    robot = RobotText("r", root="frame")
    corners = (
        (0.05, 0.05, 0.1, -1),
        (0.05, 0.55, 0.2, 1),
        (0.55, 0.05, 0.1, -1),
        (0.55, 0.55, 0.2, 1),
    )
    for i, (x, y, z, turn) in enumerate(corners):
        pivot = builders.placed(
            robot, f"p{i}", "revolute", "frame", f"k{i}", xyz=f"{x} {y} {z}",
            rpy=f"{1.5708 * turn} 0 0", axis=f"0 0 {turn}",
        )  # fmt: skip
        builders.placed(
            robot, f"w{i}", "continuous", pivot, f"t{i}", xyz="0.01 0.05 0.3", axis=f"0 0 {turn}"
        )
    # And a boom with a bucket above them (two hinges).
    boom = builders.placed(
        robot, "b0", "revolute", "frame", "boom", xyz="0 -0.05 1.1", rpy="1.5708 0 0",
        axis="0 -1 0",
    )  # fmt: skip
    builders.placed(
        robot, "b1", "revolute", boom, "bucket", xyz="1.65 0.05 0.35", rpy="1.5708 0 1.5708"
    )
    result = identify_urdf(robot.text())
    assert not [role for role in result.roles if role.role == "finger"]
    assert result.structure != "Hand"


def test_a_five_finger_hand_named_by_its_bones_is_a_hand() -> None:
    # index, middle, ring, pinky and a thumb of five joints each (a display hand's): no
    # finger word but the thumb's, the bones' are (metacarpals, a phalanx's).
    robot = RobotText("one_finger", root="left_base")
    limits = '<limit lower="-1.6" upper="1.6" effort="30" velocity="1"/>'
    bones = ("metacarpals", "metacarpals_2", "proximal", "intermediate", "distal")
    joints = ("base", "metacarpals", "metacarpals_2", "proximal", "intermediate")
    for finger in ("index", "middle", "ring", "pinky", "thumb"):
        link = "left_base"
        for joint, bone in zip(joints, bones, strict=True):
            name = f"left_{finger}_{joint}_joint"
            link = robot.joint(name, "revolute", link, f"left_{finger}_{bone}", limits)
    assert identify_urdf(robot.text()).structure == "Hand"


def sliding_jaws(*, third: bool = False) -> RobotText:
    """Two unnamed prismatic joints on the root at one place, sliding opposite ways, each with
    its own drive (no mimic); ``third`` adds an unnamed hinge elsewhere on the body."""
    robot = RobotText("r")
    builders.placed(robot, "p0", "prismatic", robot.root, "a", axis="1 0 0")
    builders.placed(robot, "p1", "prismatic", robot.root, "b", rpy="0 0 3.14159", axis="-1 0 0")
    if third:
        builders.placed(robot, "h0", "revolute", robot.root, "c", xyz="0 0 0.3", axis="0 1 0")
    return robot


def cad_arm(jaw_axes: tuple[str, str], limits: tuple[float, float]) -> RobotText:
    """A five-joint arm on a world link whose last link carries two hinges placed apart along
    and across their axes, about ``jaw_axes`` over ``limits`` (a CAD export's jaws)."""
    robot = RobotText("arm", root="world")
    tip = robot.chain(robot.root, [f"joint{i}" for i in range(1, 6)])
    lower, upper = limits
    for name, axis, xyz in (
        ("6a", jaw_axes[0], "-0.005 -0.015 0.035"),
        ("6b", jaw_axes[1], "0.005 0.01 0.035"),
    ):
        robot.joint(
            f"joint{name}",
            "revolute",
            tip,
            f"link{name}",
            f'<origin xyz="{xyz}"/><axis xyz="{axis}"/>'
            f'<limit lower="{lower}" upper="{upper}" effort="1" velocity="1"/>',
        )
    return robot


def test_two_hinges_mirroring_each_other_at_the_end_of_an_arm_are_its_jaws() -> None:
    result = identify_urdf(cad_arm(("0 -1 0", "0 1 0"), (-1.3, 1.135)).text())
    assert (result.structure, result.body and result.body.grippers) == ("Manipulator", 1)
    # On a head (its pan and tilt named so), two mirrored hinges are eyelids or ears.
    head = cad_arm(("0 -1 0", "0 1 0"), (-1.3, 1.135))
    head.joints = [
        j.replace('"joint4"', '"head_pan"').replace('"joint5"', '"head_tilt"') for j in head.joints
    ]
    assert identify_urdf(head.text()).structure != "Manipulator"
    # Two hinges that turn alike, or over a travel symmetric about zero, mirror nothing.
    for axes, limits in ((("0 1 0", "0 1 0"), (-1.3, 1.135)), (("0 -1 0", "0 1 0"), (-1.0, 1.0))):
        assert identify_urdf(cad_arm(axes, limits).text()).structure != "Manipulator"


def mirrored_pair(chain: list[str], kind: str, axis: str) -> RobotText:
    """A chain of joints ``chain`` ending in two joints of ``kind`` side by side, one following
    the other mirrored (``<mimic multiplier="-1">``), about ``axis``."""
    robot = RobotText("r")
    tip = robot.chain(robot.root, chain)
    builders.placed(robot, "pair_l", kind, tip, "pair_l_link", xyz="0 0.02 0.05", axis=axis)
    builders.placed(
        robot,
        "pair_r",
        kind,
        tip,
        "pair_r_link",
        xyz="0 -0.02 0.05",
        axis=axis,
        extra='<mimic joint="pair_l" multiplier="-1"/>',
    )
    return robot


def grippers(robot: RobotText) -> int:
    return grippers_of(robot.text())


def grippers_of(text: str) -> int:
    result = identify_urdf(text)
    assert result.body is not None
    return result.body.grippers


def test_two_hinges_one_motion_closes_on_a_head_are_ears_not_jaws() -> None:
    # A pet robot's head (pan and tilt named so) with two ears, one following the other.
    assert grippers(mirrored_pair(["head_pan", "head_tilt"], "revolute", "1 0 0")) == 0
    # The same pair at the end of an arm's two joints closes a gripper.
    assert grippers(mirrored_pair(["joint1", "joint2"], "revolute", "1 0 0")) == 1


def droid_head(names: tuple[str, str]) -> RobotText:
    """Two legs and a neck of three joints (named so) ending in two hinges ``names`` that
    swing unevenly and mirror each other about the line between them (a droid's antennas)."""
    robot = builders.biped()
    tip = robot.chain(robot.root, ["neck_pitch", "head_pitch", "head_yaw"])
    for name, y, (lower, upper) in zip(
        names, ("0.03", "-0.03"), ((-1.1, 2.1), (-2.1, 1.1)), strict=True
    ):
        limit = f'<limit lower="{lower}" upper="{upper}" effort="1" velocity="1"/>'
        body = f'<origin xyz="0 {y} 0.05"/><axis xyz="0 1 0"/>{limit}'
        robot.joint(name, "revolute", tip, f"{name}_link", body)
    return robot


def test_a_heads_antennas_or_ears_named_so_are_no_jaws() -> None:
    for names in (("left_antenna", "right_antenna"), ("ear_l", "ear_r"), ("l_eyelid", "r_eyelid")):
        robot = droid_head(names)
        assert grippers(robot) == 0, names
        assert identify_urdf(robot.text()).structure == "Biped", names
    # Named for nothing, the pair could close like pliers at the end of the neck: jaws.
    assert grippers(droid_head(("side_l", "side_r"))) == 1
    # At an arm's end, a gripper's jaws are jaws whatever they are called.
    robot = RobotText("clamp_arm")
    tip = robot.chain(robot.root, ["joint_1", "joint_2", "joint_3", "joint_4"])
    for side, y in (("left", "0.03"), ("right", "-0.03")):
        limit = '<limit lower="0" upper="0.8" effort="1" velocity="1"/>'
        body = f'<origin xyz="0 {y} 0.05"/><axis xyz="1 0 0"/>{limit}'
        robot.joint(f"{side}_ear_joint", "revolute", tip, f"{side}_ear", body)
    assert grippers(robot) == 1
    assert identify_urdf(robot.text()).structure == "Manipulator"


def test_a_lone_antenna_hinge_makes_no_head() -> None:
    # A rover trimmed of its wheels, its radio antenna on a hinge: no pan/tilt unit.
    robot = RobotText("rover", root="chassis")
    robot.chain("chassis", ["antenna_hinge"])
    assert identify_urdf(robot.text()).structure == "Other"


def test_two_hinges_swinging_both_ways_on_one_axis_line_on_a_head_are_ears() -> None:
    # A head box (pan and tilt named so) with two ears, each driven alone, hinged about the
    # line between them and swinging as far either way: ears, no jaws.
    def pair_on_a_chain(
        chain: list[str], axis: str, travel: tuple[float, float] = (-1.0, 1.0)
    ) -> RobotText:
        robot = RobotText("r")
        tip = robot.chain(robot.root, chain)
        limit = f'<limit lower="{travel[0]}" upper="{travel[1]}" effort="1" velocity="1"/>'
        for side, y in (("l", "0.09"), ("r", "-0.09")):
            body = f'<origin xyz="0 {y} 0.04"/><axis xyz="{axis}"/>{limit}'
            robot.joint(f"side_{side}", "revolute", tip, f"side_{side}_link", body)
        return robot

    head = ["head_pan", "head_tilt"]
    assert grippers(pair_on_a_chain(head, "0 1 0")) == 0
    # The same pair at an arm's end (pliers' blades on one pin), curling one way, hinged across
    # the line between them, or with placeholder limits, is a gripper's jaws.
    assert grippers(pair_on_a_chain(["joint1", "joint2"], "0 1 0")) == 1
    assert grippers(pair_on_a_chain(head, "0 1 0", (0.0, 2.6))) == 1
    assert grippers(pair_on_a_chain(head, "1 0 0")) == 1
    # A CAD export whose every limit is 0/0 (placeholders) says nothing of how they swing.
    placeholders = pair_on_a_chain(head, "0 1 0", (0.0, 0.0)).text()
    assert grippers_of(placeholders.replace('lower="-1" upper="1"', 'lower="0" upper="0"')) == 1


def side_mounts(axis: str, travel: tuple[float, float] = (-0.8, 0.8)) -> RobotText:
    """A body whose only motions are two servos at its sides, each tilting a mount."""
    robot = RobotText("servo_pair", root="base")
    limit = f'<limit lower="{travel[0]}" upper="{travel[1]}" effort="1" velocity="1"/>'
    for side, y in (("left", "0.11"), ("right", "-0.11")):
        body = f'<origin xyz="0 {y} 0.12"/><axis xyz="{axis}"/>{limit}'
        robot.joint(f"servo_{side}", "revolute", "base", f"mount_{side}", body)
    return robot


def test_a_bodys_only_two_hinges_swinging_both_ways_about_the_line_between_them_are_no_jaws() -> (
    None
):
    # They turn about the line that joins them: they never close on each other (a tilt-rotor's
    # two motor mounts, a pair of ears), whatever they are.
    assert grippers(side_mounts("0 1 0")) == 0
    assert identify_urdf(side_mounts("0 1 0").text()).structure == "Other"
    # Hinged across that line, or curling one way (pliers' blades on one pin), they close.
    assert grippers(side_mounts("1 0 0")) == 1
    assert grippers(side_mounts("0 1 0", (0.0, 1.2))) == 1


def test_jaws_one_motion_closes_at_an_arms_end_stay_jaws_below_a_shoulder_pan() -> None:
    # A UR-style arm: "pan" names its shoulder far above the gripper, no head's.
    names = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint"]
    assert (
        grippers(mirrored_pair([*names, "wrist_2_joint", "wrist_3_joint"], "prismatic", "0 1 0"))
        == 1
    )


def test_two_alike_jaws_that_are_a_bodys_only_motions_are_a_gripper_on_its_own() -> None:
    result = identify_urdf(sliding_jaws().text())
    assert result.structure == "Gripper"
    assert result.body is not None
    assert any("the body's only motions" in role.evidence for role in result.body.roles)
    # Beside another motion, two joints side by side on the body are no jaws by that rule.
    assert identify_urdf(sliding_jaws(third=True).text()).structure != "Gripper"


def test_a_parallel_linkage_of_four_knuckles_closed_by_one_motion_is_a_gripper() -> None:
    robot = RobotText("r")
    builders.placed(robot, "k0", "revolute", robot.root, "k0_l", xyz="0 -0.017 0.12", axis="-1 0 0")
    for name, y, z in (("k1", -0.008, 0.14), ("k2", 0.017, 0.12), ("k3", 0.008, 0.14)):
        builders.placed(
            robot,
            name,
            "revolute",
            robot.root,
            f"{name}_l",
            xyz=f"0 {y} {z}",
            axis="1 0 0",
            extra='<mimic joint="k0"/>',
        )
    assert identify_urdf(robot.text()).structure == "Gripper"


def three_fingers_about_a_palm(*, second_motor: bool = False) -> RobotText:
    """Three unnamed fingers a third of a turn apart about the palm, each a hinge and a link
    of its linkage, all following the first hinge (one motor); ``second_motor`` drives the
    third finger on its own."""
    robot = RobotText("r")
    for i in range(3):
        follows = "" if i == 0 or (second_motor and i == 2) else '<mimic joint="m0"/>'
        turn = f"0 0 {i * 2.0944:.4f}"
        builders.placed(robot, f"m{i}", "revolute", robot.root, f"m{i}_l", rpy=turn, axis="1 0 0")
        robot.joints[-1] = robot.joints[-1].replace("</joint>", f"{follows}</joint>")
        builders.placed(
            robot,
            f"s{i}",
            "revolute",
            f"m{i}_l",
            f"s{i}_l",
            xyz="0 0 0.03",
            axis="1 0 0",
            extra=f'<mimic joint="m{i}" multiplier="-1"/>',
        )
    return robot


def test_three_fingers_one_motion_closes_about_a_palm_are_a_gripper() -> None:
    result = identify_urdf(three_fingers_about_a_palm().text())
    assert result.structure == "Gripper"
    assert result.body is not None
    assert any("the body's only motion (m0)" in role.evidence for role in result.body.roles)
    # A second motor: the body's motions are no longer one.
    other = identify_urdf(three_fingers_about_a_palm(second_motor=True).text())
    assert other.body is not None
    assert not any("the body's only motion" in role.evidence for role in other.body.roles)


def test_a_gearbox_whose_shafts_turn_along_x_y_and_z_is_no_gripper() -> None:
    robot = RobotText("gearbox")
    builders.placed(robot, "input", "revolute", robot.root, "in_l", axis="1 0 0")
    for name, axis in (("out_y", "0 1 0"), ("out_z", "0 0 1")):
        builders.placed(
            robot, name, "revolute", robot.root, f"{name}_l", axis=axis,
            extra='<mimic joint="input"/>',
        )  # fmt: skip
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert not any("the body's only motion" in role.evidence for role in result.body.roles)


def palm_with_a_thumb(*, arm_beside: bool = False) -> RobotText:
    """A forearm's wrist joint into a palm carrying a thumb (one joint to its base, two
    thumb-named joints) and four three- or four-joint chains, two of them starting with a
    carpal joint named for the wrist; ``arm_beside`` makes one of the four a six-joint chain."""
    robot = RobotText("smart_arm", root="elbow_link")
    palm = robot.chain(robot.root, ["wrist_joint"])
    robot.chain(robot.chain(palm, ["wrist_upper_joint"]), ["thumb_1_joint", "thumb_2_joint"])
    robot.chain(palm, ["wrist_lower_joint", "a_1", "a_2", "a_3"])
    robot.chain(palm, ["wrist_middle_joint", "b_1", "b_2", "b_3"])
    robot.chain(palm, ["c_1", "c_2", "c_3"])
    robot.chain(palm, [f"d_{i}" for i in range(6 if arm_beside else 3)])
    return robot


def test_chains_beside_a_thumb_are_fingers_though_a_carpal_joint_is_named_for_the_wrist() -> None:
    result = identify_urdf(palm_with_a_thumb().text())
    assert result.structure == "Hand"
    fingers = {role.joint for role in result.roles if role.role == "finger"}
    assert {"wrist_lower_joint", "a_3", "c_1", "d_2", "thumb_2_joint"} <= fingers
    # A chain longer than any finger on that link: an arm beside a short gripper, no palm.
    beside = identify_urdf(palm_with_a_thumb(arm_beside=True).text())
    assert beside.structure != "Hand"
    assert "d_5" not in {role.joint for role in beside.roles if role.role == "finger"}


def test_short_chains_each_on_a_metacarpal_fixed_to_the_palm_are_its_fingers() -> None:
    robot = RobotText("hand", root="palm")
    chains = []
    for f in range(4):
        chains += _chains(robot, robot.fixed("palm", f"metacarpal{f}"), 1)
    tree = tree_of(robot)
    assert finger_groups(tree, chains) == {name for limb in chains for name in limb.joints}


def linkage_gripper(*, free_link: bool = False) -> RobotText:
    """Two unnamed joints side by side on a base, each driving a linkage of three mimic joints
    (a parallel gripper's cranks and rods); ``free_link`` makes one rod turn on its own."""
    robot = RobotText("r")
    for side, x in (("a", 0.055), ("b", -0.055)):
        crank = builders.placed(
            robot,
            f"{side}0",
            "revolute",
            robot.root,
            f"{side}_crank",
            xyz=f"{x} 0 0.05",
            axis="0 1 0",
        )
        link = crank
        for k in range(1, 4):
            mimic = "" if free_link and side == "b" and k == 2 else f'<mimic joint="{side}0"/>'
            link = builders.placed(
                robot,
                f"{side}{k}",
                "revolute",
                link,
                f"{side}_rod{k}",
                xyz="0 0 0.07",
                axis="0 1 0",
                extra=mimic,
            )
    return robot


def test_two_jaws_each_driving_a_linkage_of_its_own_mimic_joints_are_a_gripper() -> None:
    assert identify_urdf(linkage_gripper().text()).structure == "Gripper"
    # A joint in the linkage that moves on its own: no jaw's own linkage.
    assert identify_urdf(linkage_gripper(free_link=True).text()).structure != "Gripper"


def test_two_short_arms_each_ending_in_a_gripper_are_no_thumbs_of_a_palm() -> None:
    robot = RobotText("desk_bot", root="torso")
    for side in ("l", "r"):
        tip = robot.chain(
            "torso", [f"{side}_shoulder_pitch", f"{side}_shoulder_roll", f"{side}_elbow"]
        )
        robot.chain(tip, [f"{side}_gripper"])
    robot.chain("torso", ["t1", "t2"])
    assert identify_urdf(robot.text()).structure != "Hand"


def hand_with_a_named_thumb(*, finger_joints: int = 5) -> RobotText:
    """A wrist link carrying four unnamed chains of ``finger_joints`` joints (a finger with its
    carpometacarpal joint) and, on a carpal link fixed to it, a thumb named so."""
    robot = RobotText("Hand9DOF", root="Wrist")
    for finger in ("a", "b", "c", "d"):
        robot.chain("Wrist", [f"{finger}{i}_joint" for i in range(finger_joints)])
    robot.chain(robot.fixed("Wrist", "trapezium"), ["ThumbTMC_joint", "ThumbIP_joint"])
    return robot


def test_chains_on_the_body_a_named_thumb_starts_from_are_fingers_with_their_cmc_joint() -> None:
    assert identify_urdf(hand_with_a_named_thumb().text()).structure == "Hand"
    # Six joints each: arms beside a thumb-named part, no palm.
    assert identify_urdf(hand_with_a_named_thumb(finger_joints=6).text()).structure != "Hand"


def test_gripper_joints_stacked_in_one_chain_are_an_arm_carrying_the_last() -> None:
    """A lift, a tilt and a turn named for the gripper they carry, then its jaw, on a rover:
    a gripper's jaws stand side by side, so the three below the jaw are an arm."""
    robot = builders.ugv()
    lift = robot.chain("base_link", ["gripper_lift"], "prismatic")
    robot.chain(lift, ["gripper_tilt", "gripper_turn", "gripper_claw"])
    result = identify_urdf(robot.text())
    assert result.structure == "Mobile Manipulator"
    assert result.body is not None
    assert [(limb.kind, limb.joints) for limb in result.body.limbs] == [
        ("arm", ("gripper_lift", "gripper_tilt", "gripper_turn"))
    ]
    assert result.body.fingers == ("gripper_claw",)


@pytest.mark.parametrize(
    ("names", "tip"),
    [
        (["gripper_a", "gripper_b", "gripper_c"], "gripper_c"),
        (["finger_base", "finger_proximal", "finger_middle", "finger_distal"], "finger_distal"),
    ],
    ids=["three gripper joints", "four finger joints"],
)
def test_a_finger_no_longer_than_an_arms_minimum_or_a_fingers_most_stays_a_finger(
    names: list[str], tip: str
) -> None:
    robot = builders.ugv()
    robot.chain("base_link", names)
    result = identify_urdf(robot.text())
    assert result.body is not None
    assert result.body.limbs == ()
    assert result.body.fingers == (tip,)  # one finger, counted by its tip


def test_stacked_gripper_joints_carrying_two_jaws_are_an_arm_and_with_a_follower_a_gripper() -> (
    None
):
    # A lift, a tilt and a wrist named for the gripper they carry, then two jaws side by side:
    # three joints that place the jaws, an arm's worth, are the arm (as with every name
    # removed). Ended by a claw that follows the turn's motion, they stay the gripper's.
    branched = builders.ugv()
    wrist = branched.chain("base_link", ["gripper_lift", "gripper_tilt", "gripper_wrist"])
    branched.chain(wrist, ["gripper_left_jaw"], "prismatic")
    branched.chain(wrist, ["gripper_right_jaw"], "prismatic")
    placed = identify_urdf(branched.text())
    assert placed.structure == "Mobile Manipulator"
    assert placed.body is not None
    assert [(limb.kind, limb.joints, limb.gripper) for limb in placed.body.limbs] == [
        ("arm", ("gripper_lift", "gripper_tilt", "gripper_wrist"), True)
    ]
    following = builders.ugv()
    turn = following.chain("base_link", ["gripper_lift", "gripper_tilt", "gripper_turn"])
    following.joint(
        "gripper_claw", "revolute", turn, "claw",
        '<mimic joint="gripper_turn"/><limit lower="0" upper="1" effort="1" velocity="1"/>',
    )  # fmt: skip
    result = identify_urdf(following.text())
    assert result.structure == "UGV"
    assert result.body is not None
    assert result.body.limbs == ()


def test_an_arm_whose_every_part_is_named_a_jaw_carrying_two_jaws_is_an_arm() -> None:
    """An exporter's names: six joints one upon another, every link named ``Jaw_N``, the last
    carrying two jaws side by side (each driven alone): an arm ending in a gripper."""
    robot = RobotText("exported")
    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    link = "base_link"
    for i in range(1, 7):
        link = robot.joint(f"L{i - 1}_L{i}", "revolute", link, f"Jaw_{i}_1", limit)
    robot.joint("L6_GL", "revolute", link, "Jaw_7_copy_1", limit)
    robot.joint("L6_GR", "revolute", link, "Jaw_7_copy_2", limit)
    result = identify_urdf(robot.text())
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints)) for limb in result.body.limbs] == [("arm", 6)]
    assert result.body.fingers == ("L6_GL", "L6_GR")


def hand_named_chain(robot: RobotText, side: str, joints: int) -> None:
    """A chain on the root whose first link is named ``<Side>_hand``, then unnamed links."""
    link = robot.chain(robot.root, [f"{side[0]}hj"])
    robot.links[-1] = f"{side}_hand"  # the chain's first link, as an exporter named it
    robot.joints[-1] = robot.joints[-1].replace(link, f"{side}_hand")
    link = f"{side}_hand"
    for i in range(1, joints):
        link = robot.joint(
            f"{side[0]}hj{i}", "revolute", link, f"{side[0]}h{i}",
            '<limit lower="-1" upper="1" effort="1" velocity="1"/>',
        )  # fmt: skip


def test_a_chain_named_for_its_hand_at_the_body_is_an_arm() -> None:
    # A small humanoid's exporter named each arm for its hand: the link the shoulder turns is
    # `Right_hand`, and three unnamed joints follow one under another. A hand's fingers stand
    # side by side from a palm at an arm's end; this is the arm (1805, read as a Biped).
    robot = builders.biped()
    for side in ("Right", "Left"):
        hand_named_chain(robot, side, 4)
    result = identify_urdf(robot.text())
    assert result.structure == "Humanoid"
    assert result.body is not None
    assert [(limb.kind, limb.joints[0]) for limb in result.body.limbs if limb.kind == "arm"] == [
        ("arm", "Rhj"),
        ("arm", "Lhj"),
    ]


def test_a_hand_turned_at_the_body_that_carries_fingers_side_by_side_stays_a_hand() -> None:
    # A wrist on the mount turns a palm named as a hand, which carries three fingers side by
    # side, or one short chain (a two-joint hand-named chain is no arm's worth).
    robot = RobotText("hand_on_wrist")
    palm = robot.joint("wrist", "revolute", robot.root, "right_hand",
                       '<limit lower="-1" upper="1" effort="1" velocity="1"/>')  # fmt: skip
    for finger in ("a", "b", "c"):
        robot.chain(palm, [f"{finger}_1", f"{finger}_2"])
    result = identify_urdf(robot.text())
    assert result.structure == "Hand"
    short = builders.biped()
    hand_named_chain(short, "Right", 2)
    hand_named_chain(short, "Left", 2)
    assert identify_urdf(short.text()).structure == "Biped"


def two_chains(apart: float, link: float, *, on: str = "", third: bool = False) -> RobotText:
    """Two unnamed three-joint chains on one link, their first joints ``apart`` metres from
    each other, each link of them ``link`` metres long (straight up); ``on``: that link is
    turned by a joint of this name on the root; ``third``: a third chain elsewhere."""
    robot = RobotText("r")
    palm = robot.root
    if on:
        palm = builders.placed(robot, on, "revolute", palm, "chest", xyz="0 0 0.1", axis="0 0 1")
    for side, y in (("a", apart / 2), ("b", -apart / 2)):
        link_name = builders.placed(
            robot, f"{side}0", "revolute", palm, f"{side}l0", xyz=f"0 {y} 0.04", axis="0 1 0"
        )
        for i in (1, 2):
            link_name = builders.placed(
                robot,
                f"{side}{i}",
                "revolute",
                link_name,
                f"{side}l{i}",
                xyz=f"0 0 {link}",
                axis="1 0 0",
            )
    if third:
        robot.chain(robot.root, ["c0", "c1", "c2", "c3", "c4", "c5"])
    return robot


def test_two_short_unnamed_chains_close_together_are_a_two_finger_grippers_fingers() -> None:
    # A two-finger gripper whose fingers bend on three joints each, 1.6 cm apart, about 8 cm
    # long, names saying nothing (j_1_1 .. j_2_3): no torso of two arms.
    assert identify_urdf(two_chains(apart=0.016, link=0.04).text()).structure == "Gripper"
    # Two arms a shoulder's width apart (farther than half their reach), reaching farther than
    # a finger, starting at one place (the chest's middle), or on a body a joint turns (a
    # torso; a head's antennae): arms.
    for robot in (
        two_chains(apart=0.06, link=0.04),
        two_chains(apart=0.016, link=0.3),
        two_chains(apart=0.0, link=0.04),
        two_chains(apart=0.016, link=0.04, on="waist"),
    ):
        assert identify_urdf(robot.text()).structure == "Torso"
    # Beside a third chain of the body (an arm on the same base), no gripper alone.
    beside = identify_urdf(two_chains(apart=0.016, link=0.04, third=True).text())
    assert "finger" not in {role.role for role in beside.roles}


def arm_with_fingers(finger_joints: int, *, spacing: float = 0.03, apart: float = 0.02) -> str:
    """Six unnamed hinges one above the other, 0.2 m apart (an arm), and at its end two unnamed
    chains of ``finger_joints`` hinges, ``spacing`` apart, starting ``apart`` either side."""
    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    robot = RobotText("arm")
    link = robot.root
    for index in range(6):
        axis = "0 0 1" if index in (0, 3, 5) else "0 1 0"
        place = f'<origin xyz="0 0 0.2"/><axis xyz="{axis}"/>{limit}'
        link = robot.joint(f"joint{index + 1}", "revolute", link, f"link{index + 1}", place)
    number = 7
    for side in (apart, -apart):
        finger = link
        for step in range(finger_joints):
            across = side if step == 0 else 0.0
            place = f'<origin xyz="0 {across} {spacing}"/><axis xyz="1 0 0"/>{limit}'
            finger = robot.joint(f"joint{number}", "revolute", finger, f"link{number}", place)
            number += 1
    return robot.text()


@pytest.mark.parametrize("finger_joints", [2, 3, 4])
def test_two_short_unnamed_chains_ending_an_unnamed_arm_are_its_grippers_fingers(
    finger_joints: int,
) -> None:
    result = identify_urdf(arm_with_fingers(finger_joints))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints), limb.gripper) for limb in result.body.limbs] == [
        ("arm", 6, True)
    ]
    # Chains reaching as far as arms (0.2 m and more) at the end of a chain are a torso's arms
    # on its waist, and two turning about one point each (a head's eyes) reach nowhere: no
    # fingers.
    for far in (arm_with_fingers(finger_joints, spacing=0.2), arm_with_fingers(2, spacing=0.0)):
        other = identify_urdf(far)
        assert other.body is not None
        assert not any(limb.gripper for limb in other.body.limbs)


def test_two_one_joint_jaws_ending_an_unnamed_arm_reach_as_far_as_their_mass_sits() -> None:
    # A CAD export's jaws, placed apart across the wrist's frame diagonally (not side by side
    # along one of its axes), one hinge each: no second joint measures them, their mass centres,
    # 5 cm out, say how far they reach. Drawn as bare frames, they reach nowhere: no fingers.
    bare = (
        arm_with_fingers(1)
        .replace('<origin xyz="0 0.02 0.03"/>', '<origin xyz="0.02 0.02 0.03"/>')
        .replace('<origin xyz="0 -0.02 0.03"/>', '<origin xyz="-0.02 -0.02 0.03"/>')
    )
    jaw = (
        '<link name="{}"><inertial><origin xyz="0 0 0.05"/><mass value="0.1"/>'
        '<inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial></link>'
    )
    weighed = bare
    for link in ("link7", "link8"):
        weighed = weighed.replace(f'<link name="{link}"/>', jaw.format(link))
    result = identify_urdf(weighed)
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints), limb.gripper) for limb in result.body.limbs] == [
        ("arm", 6, True)
    ]
    unweighed = identify_urdf(bare)
    assert unweighed.body is not None
    assert not any(limb.gripper for limb in unweighed.body.limbs)


def test_a_jaws_massless_tip_frame_says_nothing_of_how_far_the_jaw_reaches() -> None:
    # Fresh set 1527's servo claw: a SolidWorks export ends each jaw in a tip frame whose
    # inertial writes a mass of 0 at an origin 0.2 m off; no mass, no centre of it.
    bare = (
        arm_with_fingers(1)
        .replace('<origin xyz="0 0.02 0.03"/>', '<origin xyz="0.02 0.02 0.03"/>')
        .replace('<origin xyz="0 -0.02 0.03"/>', '<origin xyz="-0.02 -0.02 0.03"/>')
    )
    tips = "".join(
        f'<link name="tip{n}"><inertial><origin xyz="-0.2 0 0"/><mass value="0"/>'
        f'<inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>'
        f'<joint name="tip{n}_joint" type="fixed"><parent link="link{n}"/>'
        f'<child link="tip{n}"/><origin xyz="0 0 0.05"/></joint>'
        for n in (7, 8)
    )
    result = identify_urdf(bare.replace("</robot>", tips + "</robot>"))
    assert result.structure == "Manipulator"
    assert result.body is not None
    assert [(limb.kind, len(limb.joints), limb.gripper) for limb in result.body.limbs] == [
        ("arm", 6, True)
    ]


def _five_chain_hand(thumb_tip: str) -> RobotText:
    """Four unnamed four-joint fingers in a row on a palm (named for no part) and a thumb
    beside them, its last joint ``thumb_tip`` (a CAD export writes some tips endless)."""
    robot = RobotText("montage", root="base_link")
    number = 0
    starts = [(-0.04, 0.02), (-0.02, 0.03), (0.01, 0.03), (0.035, 0.03), (0.03, -0.003)]
    for finger, (x, y) in enumerate(starts):
        link = robot.root
        for step in range(4):
            number += 1
            kind = thumb_tip if finger == 4 and step == 3 else "revolute"
            xyz = f"{x} {y} 0" if step == 0 else "0 0.02 0"
            link = builders.placed(
                robot, f"joint{number}", kind, link, f"link{number}", xyz=xyz, axis="1 0 0"
            )
    return robot


@pytest.mark.parametrize("thumb_tip", ["revolute", "continuous"])
def test_a_thumb_whose_tip_joint_is_endless_is_a_finger_beside_four_others(thumb_tip: str) -> None:
    # Fresh set 1743's mechanical hand: its thumb's last joint is written continuous; beside
    # four fingers on one palm it is the hand's thumb, no wheel on a pivot.
    assert identify_urdf(_five_chain_hand(thumb_tip).text()).structure == "Hand"


def test_chains_each_ending_in_an_endless_joint_are_no_fingers_on_their_own() -> None:
    # Four hip-knee-wheel legs close together: wheels spun on pivots, not a hand.
    robot = RobotText("wheel_legs", root="body")
    for i, (x, y) in enumerate([(0.02, 0.02), (0.02, -0.02), (-0.02, 0.02), (-0.02, -0.02)]):
        hip = builders.placed(robot, f"h{i}", "revolute", "body", f"h{i}_link", xyz=f"{x} {y} 0")
        knee = builders.placed(robot, f"k{i}", "revolute", hip, f"k{i}_link", xyz="0 0 -0.02")
        builders.placed(robot, f"w{i}", "continuous", knee, f"w{i}_link", xyz="0 0 -0.02")
    assert identify_urdf(robot.text()).structure != "Hand"
