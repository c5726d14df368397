"""ROS names: a topic with its message type, and message types spelled the ROS 1 way.

A :class:`Topic` is what a topic list, a bag and a live graph all give; ROS 2 spells types
``package/msg/Name`` where ROS 1 spells ``package/Name``, and :func:`normalise_type` makes
them one.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Topic", "normalise_type"]


@dataclass(frozen=True, slots=True)
class Topic:
    """A topic, its message type (``pkg/Name``) and, when known, the robot's direction."""

    name: str
    type: str
    direction: str | None = None  # "published", "subscribed" or None (unknown)


def normalise_type(text: str) -> str:
    """``sensor_msgs/msg/Image`` -> ``sensor_msgs/Image``; ROS 1 names unchanged."""
    parts = text.strip().split("/")
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        return f"{parts[0]}/{parts[2]}"
    return text.strip()
