"""A teleoperation description drafted from what identification found (``identify --describe``).

A robot's makers write its teleoperation description (:mod:`solver.ros.description`) once;
:func:`draft_description` gives them a start: the structure, motion controls and sensors
identification found, each above the evidence that found it as a YAML comment, so a person can
check every line against the URDF before shipping the file beside it. A motion control's topic
or action is the one the robot's topics showed where they were given, else the usual one
(:data:`~solver.ros.description.USUAL_CARRIERS`), said so in a comment: a draft names what a
ROS 2 graph usually offers until the robot's own names are written in.

The draft is a valid description as it stands: ``teleop-ui check`` reads it without a finding,
and ``identify`` reading it back gives the same kinematic type, motion controls and sensors
(tests check the round trip). Every string from the robot's files is written as a quoted YAML
scalar with every character outside printable ASCII escaped, and every comment through
:func:`~solver.untrusted.shown`: nothing in a stranger's URDF starts a line of its own in the
draft.

Not here: reading a description (:mod:`solver.ros.description`), what its values mean for a
robot (:mod:`solver.identify.declared`).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

from solver.files.reader import MAX_NAME_CHARS
from solver.ros.description import FORMAT_KEY, SUFFIX, USUAL_CARRIERS, VERSION
from solver.ros.names import full_topic_name_problem
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.identify.identification import Identification

__all__ = ["draft_description"]

# A topic a source names: "topics.txt: /cmd_vel (geometry_msgs/Twist)".
_SOURCE_TOPIC = re.compile(r": (/[A-Za-z0-9_/]+) \(([A-Za-z0-9_/]+)\)")
# The usual carrier of a control the table does not know: a topic named after it.
_FALLBACK_TYPE = "std_msgs/msg/String"


def draft_description(result: Identification) -> str:
    """The YAML text of a teleoperation description for ``result`` (see the module docstring)."""
    name = Path(result.file).name
    lines = [
        f"# Teleoperation description of {_comment(result.robot)}, drafted by",
        f"# `teleop-ui identify --describe` from {_comment(name)}. Check each value against the",
        "# robot, write its own topics and actions where the draft names the usual ones, and",
        f"# ship it beside the URDF as ROBOT{SUFFIX}; `teleop-ui check` validates it.",
        f"{FORMAT_KEY}: {VERSION}",
    ]
    if len(result.robot) <= MAX_NAME_CHARS:
        lines.append(f"robot: {_scalar(result.robot)}")
    lines += _kinematic(result)
    lines += _controls(result)
    lines += _sensors(result)
    return "\n".join(lines) + "\n"


def _kinematic(result: Identification) -> list[str]:
    lines = [f"# structure {_comment(result.structure)} (confidence {result.confidence:.2f}):"]
    lines += [f"#   {_comment(line)}" for line in result.evidence[:8]]
    lines.append(f"kinematic_type: {_scalar(result.structure)}")
    if result.kinematic_type is not None and result.kinematic_type != result.structure:
        lines.append(f"# under the rule set read, {_comment(result.kinematic_type)}")
    return lines


def _controls(result: Identification) -> list[str]:
    if not result.motion_controls:
        return ["# no motion control was found: declare the robot's own under motion_controls:"]
    lines = ["motion_controls:"]
    for control in result.motion_controls:
        carrier, topic, kind, seen = _carrier(control.motion_control, control.source)
        lines.append(f"  # {_comment(control.source)}")
        if not seen:
            lines.append("  # the usual name on a ROS 2 graph: write the robot's own")
        lines += [
            f"  - control: {_scalar(control.motion_control)}",
            f"    {carrier}: {_scalar(topic)}",
            f"    type: {_scalar(kind)}",
        ]
    return lines


def _carrier(control: str, source: str) -> tuple[str, str, str, bool]:
    """(topic/action, name, type, whether the robot's own topics showed it)."""
    for match in _SOURCE_TOPIC.finditer(source):
        topic, kind = match.group(1), match.group(2)
        if full_topic_name_problem(topic) is None and len(topic) <= MAX_NAME_CHARS:
            return "topic", topic, kind, True
    usual = USUAL_CARRIERS.get(control)
    if usual is not None:
        return (*usual, False)
    slug = re.sub(r"[^a-z0-9]+", "_", control.lower()).strip("_") or "command"
    return "topic", f"/{slug}", _FALLBACK_TYPE, False


def _sensors(result: Identification) -> list[str]:
    if not result.sensors:
        return ["# no sensor was found: declare the robot's own under sensors:"]
    lines = ["sensors:"]
    for sensor in result.sensors:
        presented = sensor.sensor_type or "no presentation in the rule set read"
        lines += [
            f"  # {_comment(sensor.source)} ({_comment(presented)})",
            f"  - kind: {_scalar(sensor.kind)}",
            f"    count: {sensor.count}",
        ]
    return lines


def _scalar(text: str) -> str:
    """A double-quoted YAML scalar: every character outside printable ASCII escaped (``\\u``
    up to U+FFFF, ``\\U`` beyond: YAML's escapes, no surrogate pairs)."""
    out = []
    for char in text:
        code = ord(char)
        if char in '\\"':
            out.append("\\" + char)
        elif 0x20 <= code < 0x7F:
            out.append(char)
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    return '"' + "".join(out) + '"'


def _comment(text: str) -> str:
    """A stranger's text inside a comment: escaped (no line break ends the comment)."""
    return shown(text, limit=None)
