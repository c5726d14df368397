"""A Publish panel's message: whole, of its type, by Lichtblick's own rules, or none at all."""

from __future__ import annotations

import json
from typing import Any

import pytest

from solver.layouts import JointStart
from solver.layouts.checks import check_lichtblick
from solver.layouts.samples import sample_message

JOINTS = (JointStart("shoulder", 0.0), JointStart("elbow", 0.25))


def _publish_faults(datatype: str, message: Any) -> list[str]:
    """What Lichtblick's rules say of a Publish panel holding ``message``."""
    config = {
        "topicName": "/r/command",
        "datatype": datatype,
        "buttonText": "Publish",
        "buttonTooltip": "",
        "advancedView": True,
        "value": json.dumps(message),
    }
    layout = {
        "configById": {"Publish!a": config},
        "globalVariables": {},
        "playbackConfig": {"speed": 1},
        "layout": "Publish!a",
    }
    return [str(f) for f in check_lichtblick(layout, namespace="/r")]


@pytest.mark.parametrize(
    "datatype",
    [
        "geometry_msgs/Twist",
        "geometry_msgs/msg/TwistStamped",
        "geometry_msgs/PoseStamped",
        "trajectory_msgs/msg/JointTrajectory",
    ],
)
def test_every_sample_is_a_whole_message_by_lichtblicks_rules(datatype: str) -> None:
    message = sample_message(datatype, JOINTS)
    assert message is not None
    assert _publish_faults(datatype, message) == []


def test_a_velocity_sample_is_a_stop_command() -> None:
    assert sample_message("geometry_msgs/msg/Twist", None) == {
        "linear": {"x": 0.0, "y": 0.0, "z": 0.0},
        "angular": {"x": 0.0, "y": 0.0, "z": 0.0},
    }


def test_a_pose_sample_has_a_unit_quaternion() -> None:
    message = sample_message("geometry_msgs/PoseStamped", None)
    assert message is not None
    assert message["pose"]["orientation"] == {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}


def test_a_trajectory_names_every_joint_once_with_one_position_each_reached_slowly() -> None:
    message = sample_message("trajectory_msgs/JointTrajectory", JOINTS)
    assert message is not None
    assert message["joint_names"] == ["shoulder", "elbow"]
    assert message["points"][0]["positions"] == [0.0, 0.25]
    assert message["points"][0]["time_from_start"] == {"sec": 5, "nsec": 0}


@pytest.mark.parametrize("joints", [None, ()])
def test_a_trajectory_without_the_robots_joints_has_no_sample(
    joints: tuple[JointStart, ...] | None,
) -> None:
    assert sample_message("trajectory_msgs/msg/JointTrajectory", joints) is None


def test_a_type_without_a_known_message_has_no_sample() -> None:
    assert sample_message("my_msgs/msg/Launch", JOINTS) is None
