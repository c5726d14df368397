"""The joint tree the body's steps read: joints in document order, parts named by the
profile's patterns, plugins by what they are, and the links with motion below them."""

from __future__ import annotations

from solver.identify import load_profile
from solver.identify.readers.urdf import parse_urdf
from solver.identify.tree import JointTree
from tests.identify import builders
from tests.identify.builders import RobotText


def tree_of(robot: RobotText) -> JointTree:
    return JointTree(parse_urdf(robot.text(), strict=False), load_profile())


def test_joints_are_ordered_as_the_document_lists_them() -> None:
    robot = RobotText("order")
    robot.chain("base_link", ["b", "a", "c"])
    tree = tree_of(robot)
    assert sorted(["c", "a", "b"], key=tree.order) == ["b", "a", "c"]
    assert tree.order("not a joint") == 0


def test_links_with_a_movable_joint_below_them_are_known_and_leaves_are_not() -> None:
    robot = RobotText("arm")
    robot.fixed("base_link", "mount")
    robot.chain("mount", ["shoulder", "elbow"])
    robot.fixed("base_link", "camera")
    assert tree_of(robot).moving_below == {"base_link", "mount", "shoulder_link"}


def test_a_part_is_named_by_the_joint_or_by_its_child_link() -> None:
    robot = RobotText("names")
    robot.joint("left_wheel_joint", "continuous", "base_link", "l")
    robot.joint("j2", "continuous", "base_link", "rear_wheel")
    robot.joint("j3", "continuous", "base_link", "box")
    tree = tree_of(robot)
    joints = {joint.name: joint for joint in tree.urdf.joints}
    assert tree.matches("wheel", joints["left_wheel_joint"])
    assert tree.matches("wheel", joints["j2"])
    assert not tree.matches("wheel", joints["j3"])


def test_plugins_of_a_part_are_labelled_by_file_each_once() -> None:
    robot = builders.ugv()
    for name in ("front", "rear"):
        robot.add(builders.model_plugin(name, "libgazebo_ros_diff_drive.so"))
    tree = tree_of(robot)
    assert tree.labels("drive") == ("libgazebo_ros_diff_drive.so",)
    assert tree.labels("flight") == ()
