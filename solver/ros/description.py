"""A robot's declared teleoperation description: the file a robot package ships beside its URDF.

Identification reads what a robot *is* from its URDF and guesses what it is *driven by*; the
robot's makers know both. A teleoperation description says it in a small YAML file
(``ROBOT.teleop.yaml`` beside ``ROBOT.urdf``; docs/identify.md, "A declared teleoperation
description"; its JSON Schema is docs/schema/teleop.schema.json)::

    teleop: 1                        # the format and its version: what makes the file one
    robot: turtlebot3_burger         # the robot it describes (its URDF's robot name)
    kinematic_type: UGV              # the body's structure, as identification names it
    kinematic_types:                 # optional: the type under a rule set of other names
      Field rules (example): Rover
    motion_controls:
      - {control: Driving, topic: /cmd_vel, type: geometry_msgs/msg/Twist}
      - {control: Waypoint, action: /navigate_to_pose, type: nav2_msgs/action/NavigateToPose}
    sensors:
      - {kind: lidar, topic: /scan, type: sensor_msgs/msg/LaserScan}
      - {kind: camera, count: 2, topics: [/left/image_raw, /right/image_raw]}

:func:`parse_description` reads a loaded YAML document (:mod:`solver.files.yamlio`: bounded,
safe, located) into a frozen :class:`TeleopDescription`, or raises one
:class:`DescriptionError` naming every problem at its line: a missing or unknown field, a value
of the wrong type, a topic that is no full ROS name, a message type of no ``pkg/Name`` shape,
two entries for one control, more entries than the ``description-entries`` limit. Nothing in
the file runs or is looked up: names are data.

A robot on a live graph may carry its description as text (a parameter or topic
``<ns>/teleop_description`` beside ``robot_description``): :func:`parse_description_text` reads
it, at most ``description-bytes`` characters.

Not here: what the declared values mean for a robot (``solver.identify.declared``), drafting
one (``identify --describe``), checking one (``teleop-ui check``), reading one from a live
graph (``solver.live.robot``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from solver.errors import InputError, Location
from solver.files.reader import Reader, type_name
from solver.files.yamlio import Document, load_document, parse_document
from solver.limits import limit
from solver.ros.names import full_topic_name_problem
from solver.untrusted import shown

__all__ = [
    "FORMAT_KEY",
    "SUFFIX",
    "USUAL_CARRIERS",
    "VERSION",
    "DeclaredControl",
    "DeclaredSensor",
    "DescriptionError",
    "TeleopDescription",
    "description_beside",
    "load_description",
    "parse_description",
    "parse_description_text",
]

# The top-level key that makes a file a teleoperation description, and the version read.
FORMAT_KEY = "teleop"
VERSION = 1
# What carries a motion control on the graph: one of these, each a full ROS name.
CARRIERS = ("topic", "action", "service")
_TOP = {FORMAT_KEY, "robot", "kinematic_type", "kinematic_types", "motion_controls", "sensors"}
_CONTROL = {"control", *CARRIERS, "type"}
_SENSOR = {"kind", "count", "topic", "topics", "type"}
# ROS 1 (pkg/Name) and ROS 2 (pkg/msg/Name, pkg/action/Name, pkg/srv/Name) interface types.
_TYPE = re.compile(r"[A-Za-z][A-Za-z0-9_]*(/(msg|srv|action))?/[A-Za-z][A-Za-z0-9_]*")
# A sensor device count: the rule sets' No. of Sensors goes to 50; a robot may declare more.
_MOST_SENSORS = 1_000
# The suffix a description beside ROBOT.urdf (or ROBOT.urdf.xacro) takes: ROBOT.teleop.yaml.
SUFFIX = ".teleop.yaml"
# What usually carries each of the article's motion controls on a ROS 2 graph (the interfaces
# ros2_control, Nav2 and MoveIt offer): a draft names these until the robot's own are written.
USUAL_CARRIERS: dict[str, tuple[str, str, str]] = {
    "Driving": ("topic", "/cmd_vel", "geometry_msgs/msg/Twist"),
    "Flight": ("topic", "/cmd_vel", "geometry_msgs/msg/Twist"),
    "Walking": ("topic", "/cmd_vel", "geometry_msgs/msg/Twist"),
    "Waypoint": ("action", "/navigate_to_pose", "nav2_msgs/action/NavigateToPose"),
    "Joint": (
        "action",
        "/joint_trajectory_controller/follow_joint_trajectory",
        "control_msgs/action/FollowJointTrajectory",
    ),
    "End Effector": ("action", "/move_action", "moveit_msgs/action/MoveGroup"),
}


class DescriptionError(InputError):
    """A teleoperation description that cannot be read; every problem located."""


@dataclass(frozen=True, slots=True)
class DeclaredControl:
    """One motion control and what carries it: a topic, an action or a service."""

    control: str
    carrier: str  # topic, action or service
    name: str
    type: str | None = None
    location: Location | None = None


@dataclass(frozen=True, slots=True)
class DeclaredSensor:
    """Sensors of one kind (``lidar``, ``camera``, ...): how many, and their topics."""

    kind: str
    count: int
    topics: tuple[str, ...] = ()
    type: str | None = None
    location: Location | None = None


@dataclass(frozen=True)
class TeleopDescription:
    """A read teleoperation description (see the module docstring)."""

    file: str
    robot: str | None = None
    kinematic_type: str | None = None
    # (rule set name, kinematic type) for rule sets whose types are named otherwise.
    kinematic_types: tuple[tuple[str, str], ...] = ()
    motion_controls: tuple[DeclaredControl, ...] = ()
    sensors: tuple[DeclaredSensor, ...] = ()
    # Where each declared value is written, for the evidence (``file:line``).
    kinematic_type_location: Location | None = None

    def kinematic_type_for(self, rules_name: str) -> str | None:
        """The type declared under the rule set named ``rules_name``, if any."""
        return dict(self.kinematic_types).get(rules_name)

    def where(self, location: Location | None) -> str:
        """``robot.teleop.yaml:4``: a declared value's place, for evidence lines."""
        if location is None or location.line is None:
            return Path(self.file).name
        return f"{Path(self.file).name}:{location.line}"


def description_beside(robot_file: str | Path) -> Path:
    """Where a robot's description is looked for: ``ROBOT.teleop.yaml`` beside
    ``ROBOT.urdf``, ``ROBOT.urdf.xacro`` or ``ROBOT.xacro``."""
    path = Path(robot_file)
    name = path.name
    for ending in (".urdf.xacro", ".xacro", ".urdf"):
        if name.endswith(ending):
            name = name[: -len(ending)]
            break
    else:
        name = path.stem
    return path.with_name(name + SUFFIX)


def load_description(path: str | Path, *, display: str | None = None) -> TeleopDescription:
    """Read the description at ``path`` (bounded, safe YAML); :class:`InputError` if not."""
    return parse_description(load_document(path, display=display))


def parse_description_text(text: str, file: str) -> TeleopDescription:
    """The description in ``text`` from a live graph (a ``<ns>/teleop_description`` parameter
    or topic, named ``file``): at most ``description-bytes`` characters, refused before it is
    parsed (:class:`~solver.errors.TooLargeError`); then as :func:`parse_description`."""
    limit("description-bytes").check(len(text), file, noun="characters")
    return parse_description(parse_document(text, file))


def parse_description(document: Document) -> TeleopDescription:
    """The description in ``document``; :class:`DescriptionError` naming every problem."""
    reader = Reader(document)
    top = reader.top("teleoperation description", needs=FORMAT_KEY)
    if top is None:
        raise DescriptionError(reader.faults)
    reader.unknown_keys((), top, _TOP, "field")
    _version(reader)
    robot = reader.string(("robot",), "robot name", required=False) or None
    kinematic = reader.string(("kinematic_type",), "kinematic type", required=False) or None
    per_rules = _kinematic_types(reader)
    entries = _count(reader, "motion_controls") + _count(reader, "sensors")
    reader.within(limit("description-entries"), entries, (), noun="controls and sensors")
    controls = _controls(reader)
    sensors = _sensors(reader)
    if reader.faults:
        raise DescriptionError(reader.faults)
    return TeleopDescription(
        document.file,
        robot,
        kinematic,
        per_rules,
        controls,
        sensors,
        document.location(("kinematic_type",)) if kinematic else None,
    )


def _version(reader: Reader) -> None:
    version = reader.integer((FORMAT_KEY,), "format version")
    if version is not None and version != VERSION:
        reader.fault(
            (FORMAT_KEY,),
            f"format version {version} is not read; this reader reads version {VERSION}",
            code="out-of-range",
        )


def _kinematic_types(reader: Reader) -> tuple[tuple[str, str], ...]:
    spec = reader.mapping(("kinematic_types",), "kinematic types by rule set", required=False)
    found = []
    for name in spec:
        value = reader.string(("kinematic_types", name), "kinematic type")
        if value:
            found.append((name, value))
    return tuple(found)


def _count(reader: Reader, key: str) -> int:
    value = reader.get((key,))
    return len(value) if isinstance(value, list) else 0


def _items(reader: Reader, key: str, what: str) -> list[tuple[int, dict[str, object]]]:
    """The entries of the list ``key`` that are mappings, each with its index."""
    value = reader.get((key,))
    if value is None:
        return []
    if not isinstance(value, list):
        reader.fault(
            (key,), f"{key} must be a list of entries, got {type_name(value)}", code="wrong-type"
        )
        return []
    found = []
    for index in range(len(value)):
        spec = reader.mapping((key, index), what)
        if spec:
            found.append((index, spec))
    return found


def _controls(reader: Reader) -> tuple[DeclaredControl, ...]:
    found: list[DeclaredControl] = []
    seen: dict[str, int] = {}
    for index, spec in _items(reader, "motion_controls", "a motion control"):
        path = ("motion_controls", index)
        reader.unknown_keys(path, spec, _CONTROL, "motion control field")
        control = reader.string((*path, "control"), "motion control")
        carriers = [key for key in CARRIERS if key in spec]
        if len(carriers) != 1:
            reader.fault(
                path,
                "a motion control names exactly one of topic, action or service "
                f"(what carries it), got {len(carriers)}",
                code="missing-field" if not carriers else "invalid",
            )
            continue
        carrier = carriers[0]
        name = _ros_name(reader, (*path, carrier), carrier)
        kind = _type(reader, (*path, "type"))
        if control in seen:
            reader.fault(
                (*path, "control"),
                f"motion control {shown(control, quoted=True)} is declared twice (first at "
                f"entry {seen[control]})",
                code="duplicate-value",
            )
            continue
        seen[control] = index
        if control and name:
            found.append(
                DeclaredControl(control, carrier, name, kind, reader.document.location(path))
            )
    return tuple(found)


def _sensors(reader: Reader) -> tuple[DeclaredSensor, ...]:
    found: list[DeclaredSensor] = []
    for index, spec in _items(reader, "sensors", "a sensor"):
        path = ("sensors", index)
        reader.unknown_keys(path, spec, _SENSOR, "sensor field")
        kind = reader.string((*path, "kind"), "sensor kind")
        topics = _topics(reader, path, spec)
        count = reader.integer((*path, "count"), "sensor count", required=False)
        if count is None:
            count = max(len(topics), 1)
        elif not 1 <= count <= _MOST_SENSORS:
            reader.fault(
                (*path, "count"),
                f"sensor count must be 1 to {_MOST_SENSORS}, got {count}",
                code="out-of-range",
            )
            continue
        kind_type = _type(reader, (*path, "type"))
        if kind:
            found.append(
                DeclaredSensor(kind, count, topics, kind_type, reader.document.location(path))
            )
    return tuple(found)


def _topics(reader: Reader, path: tuple[str, int], spec: dict[str, object]) -> tuple[str, ...]:
    if "topic" in spec and "topics" in spec:
        reader.fault(path, "a sensor names topic or topics, not both", code="invalid")
        return ()
    if "topic" in spec:
        name = _ros_name(reader, (*path, "topic"), "topic")
        return (name,) if name else ()
    if "topics" not in spec:
        return ()
    names = []
    for item_path, text in reader.names((*path, "topics"), "topics"):
        problem = full_topic_name_problem(text)
        if problem is not None:
            reader.fault(item_path, f"topic {problem}", code="invalid")
        else:
            names.append(text)
    return tuple(names)


def _ros_name(reader: Reader, path: tuple[str | int, ...], what: str) -> str:
    text = reader.string(path, f"{what} name")
    if not text:
        return ""
    problem = full_topic_name_problem(text)
    if problem is not None:
        reader.fault(path, f"{what} name {problem}", code="invalid")
        return ""
    return text


def _type(reader: Reader, path: tuple[str | int, ...]) -> str | None:
    text = reader.string(path, "type", required=False)
    if not text:
        return None
    if _TYPE.fullmatch(text) is None:
        reader.fault(
            path,
            "type must be a ROS interface type: pkg/Name or pkg/msg|srv|action/Name",
            code="invalid",
        )
        return None
    return text
