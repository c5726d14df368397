"""The message a Publish panel holds: a whole message of its type that is right for the robot.

Lichtblick's Publish panel starts with ``{}`` and its button sends whatever parses: an empty
``JointTrajectory`` (no joints, no point) that a robot's controller rejects, or worse (the
app's ROS 2 writer sent bytes a strict reader refuses, ``tools/lichtblick_check.md``). A
layout holds a whole message instead, in the shape Lichtblick's own sample builder gives
(``panels/Publish/buildSampleMessage.ts``: a time is ``{sec, nsec}``), or none where no
message can be right:

- ``geometry_msgs/Twist`` (and ``TwistStamped``): all zero, a stop command;
- ``geometry_msgs/PoseStamped``: the identity pose (``w: 1``) at the frame's origin;
- ``trajectory_msgs/JointTrajectory``: the robot's own joints, each to 0 or the limit nearest
  it, reached in :data:`TRAJECTORY_SECONDS` s; without the robot's joints, none.

Not here: the panel around the message (:mod:`solver.layouts.foxglove`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from solver.ros.joints import JointStart
from solver.ros.names import normalise_type

__all__ = ["TRAJECTORY_SECONDS", "sample_message"]

# A joint command's time to reach its point: slow, so a press is never a jerk.
TRAJECTORY_SECONDS = 5


def _time(seconds: int = 0) -> dict[str, int]:
    return {"sec": seconds, "nsec": 0}


def _header() -> dict[str, Any]:
    return {"stamp": _time(), "frame_id": ""}


def _vector() -> dict[str, float]:
    return {"x": 0.0, "y": 0.0, "z": 0.0}


def sample_message(datatype: str, joints: Sequence[JointStart] | None) -> dict[str, Any] | None:
    """A whole message of ``datatype`` worth sending, or None where none can be right."""
    kind = normalise_type(datatype)
    if kind == "geometry_msgs/Twist":
        return {"linear": _vector(), "angular": _vector()}
    if kind == "geometry_msgs/TwistStamped":
        return {"header": _header(), "twist": {"linear": _vector(), "angular": _vector()}}
    if kind == "geometry_msgs/PoseStamped":
        orientation = {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}
        return {"header": _header(), "pose": {"position": _vector(), "orientation": orientation}}
    if kind == "trajectory_msgs/JointTrajectory" and joints:
        return {
            "header": _header(),
            "joint_names": [joint.name for joint in joints],
            "points": [
                {
                    "positions": [joint.position for joint in joints],
                    "velocities": [],
                    "accelerations": [],
                    "effort": [],
                    "time_from_start": _time(TRAJECTORY_SECONDS),
                }
            ],
        }
    return None
