"""Sensors and motion controls from (topic name, message type[, direction]) triples.

The one place topic metadata is interpreted, whatever it came from: a topic list file
(:mod:`solver.identify.readers.topics`), a bag (:mod:`solver.identify.readers.bags`), or a live ROS
master (getTopicTypes / getSystemState give exactly these triples)::

    >>> from solver.identify import Topic, load_profile, sensors_from_topics
    >>> topics = [Topic("/front/scan", "sensor_msgs/LaserScan", "published")]
    >>> [d.kind for d in sensors_from_topics(topics, load_profile())]
    ['lidar']

*Sensors*: each topic's message type (and, where a rule says, its name and direction) maps to a
sensor kind through the profile's ``topics.sensors`` rules. Topics of one device count once:
the device is the topic name without trailing stream segments (``/camera/rgb/image_raw`` and
``/camera/depth/points`` are both ``/camera``), and a device showing several kinds is the kind
of the earliest rule (an RGB-D camera, not a camera and a depth camera). Topics the robot only
subscribes to are not its sensors.

*Motion controls*: the profile's ``topics.controls`` rules; ``velocity`` (Twist on cmd_vel)
becomes the structure's velocity control (Driving, Flight for UAVs, Walking for legged robots).
A command counts when the robot subscribes to it or the direction is unknown; action topics
(goal/feedback/status) count in either direction, since the server publishes half of them.

Not here: parsing files (:mod:`solver.identify.readers.topics`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from solver.identify.profile import VELOCITY, Profile
from solver.identify.sensors import Detection
from solver.ros.names import Topic
from solver.untrusted import shown

__all__ = ["Control", "controls_from_topics", "device_of", "merge_controls", "sensors_from_topics"]

_ACTION_SUFFIXES = ("goal", "feedback", "status", "result", "cancel")


@dataclass(frozen=True, slots=True)
class Control:
    """A motion control the robot offers, and what shows it: the JSON ``motion_controls``."""

    motion_control: str
    source: str


def device_of(topic: str, profile: Profile) -> str:
    """The device a topic belongs to: its name without trailing stream segments."""
    parts = [p for p in topic.split("/") if p]
    while len(parts) > 1 and parts[-1].lower() in profile.stream_segments:
        parts.pop()
    return "/" + "/".join(parts)


def sensors_from_topics(
    topics: Iterable[Topic], profile: Profile, source: str = "topics"
) -> tuple[Detection, ...]:
    """One detection per device, in order of the device's first topic."""
    best: dict[str, tuple[int, str]] = {}
    for topic in topics:
        for index, rule in enumerate(profile.topic_sensors):
            # What the robot subscribes to is someone else's data, unless a rule asks for it
            # (a speaker plays the audio it subscribes to).
            if topic.direction == "subscribed" and rule.direction != "subscribed":
                continue
            if rule.accepts(topic.type, topic.name, topic.direction):
                device = device_of(topic.name, profile)
                if device not in best or index < best[device][0]:
                    best[device] = (index, rule.kind)
                break
    return tuple(Detection(kind, device, source, device) for device, (_, kind) in best.items())


def controls_from_topics(
    topics: Iterable[Topic], profile: Profile, structure: str, source: str = "topics"
) -> tuple[Control, ...]:
    """The motion controls the topics show, one :class:`Control` per control."""
    seen: dict[str, list[str]] = {}
    for topic in topics:
        action = _is_action(topic)
        for rule in profile.topic_controls:
            if not rule.accepts(topic.type, topic.name):
                continue
            wanted = rule.direction or "subscribed"
            if topic.direction is not None and topic.direction != wanted and not action:
                continue
            control = (
                profile.velocity_control(structure) if rule.control == VELOCITY else rule.control
            )
            # Name and type cut each on its own: a Nav2 action topic and its type run past
            # the cut together.
            entry = f"{shown(topic.name)} ({shown(topic.type)})"
            if entry not in seen.setdefault(control, []):
                seen[control].append(entry)
            break
    return tuple(Control(control, f"{source}: {_first(names)}") for control, names in seen.items())


def _is_action(topic: Topic) -> bool:
    last = topic.name.rstrip("/").rsplit("/", 1)[-1]
    return (
        "/_action/" in topic.name
        or (last in _ACTION_SUFFIXES and "Action" in topic.type)
        or topic.type.endswith(("_FeedbackMessage", "GoalStatusArray"))
    )


def _first(names: list[str], limit: int = 3) -> str:
    listed = ", ".join(names[:limit])
    return listed + (f", ... ({len(names)} in all)" if len(names) > limit else "")


def merge_controls(*groups: Iterable[Control]) -> tuple[Control, ...]:
    """One :class:`Control` per motion control, sources joined, in order of first mention."""
    merged: dict[str, list[str]] = {}
    for group in groups:
        for control in group:
            sources = merged.setdefault(control.motion_control, [])
            if control.source not in sources:
                sources.append(control.source)
    return tuple(Control(name, "; ".join(sources)) for name, sources in merged.items())
