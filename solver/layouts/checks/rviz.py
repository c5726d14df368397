"""An RViz2 ``.rviz`` document against RViz2's own rules (``rviz2.yaml``): every problem at once.

Each problem is a :class:`~solver.errors.Fault` located at its path in the document, with a
stable ``code``:

======================  ===================================================================
``rviz-file``           the file's sections: Panels, Visualization Manager, Window Geometry
``rviz-display``        a display class RViz2 does not have, a missing or unknown property
``rviz-display-type``   a display that cannot show its topic's message type
``ros-topic-name``      a topic that is not a ROS 2 name (relative names are: RViz2 expands
                        them in its own namespace, ``rviz2 --ros-args -r __ns:=/robot1``)
``rviz-tool``           an unknown tool; a goal tool that publishes where the UI does not
``rviz-view``           an unknown view controller
``namespace``           a tool's topic or the robot description outside the robot's namespace
======================  ===================================================================

Not here: writing ``.rviz`` files (:mod:`solver.layouts.rviz`); Lichtblick (:mod:`.lichtblick`).
"""

from __future__ import annotations

from collections.abc import Collection, Iterator, Mapping
from typing import Any

from solver.errors import Fault, Location
from solver.layouts.checks.data import rviz_rules
from solver.ros.names import (
    common_namespace,
    in_namespace,
    normalise_type,
    topic_name_problem,
)
from solver.untrusted import shown

__all__ = ["check_rviz", "displays", "robot_namespace"]

_MAX_DISPLAYS = 100_000
_DESCRIPTION = "rviz_default_plugins/RobotModel"
_GOAL_TOOL = "rviz_default_plugins/SetGoal"


def check_rviz(
    document: Any,
    file: str = "<rviz>",
    *,
    namespace: str | None = None,
    topic_types: Mapping[str, Collection[str]] | None = None,
    pose_topics: Collection[str] | None = None,
) -> tuple[Fault, ...]:
    """Every way ``document`` (a loaded ``.rviz`` YAML) breaks a rule of ``rviz2.yaml``.

    ``namespace``: the robot's (default: :func:`robot_namespace`). The tools' topics and the
    robot description, when absolute, must lie in it; a relative name lies in the namespace
    RViz2 runs in (such a file is re-targeted with ``rviz2 --ros-args -r __ns:=/robot1``).
    ``topic_types``: topic -> its possible message types, where known; each display must
    accept one. ``pose_topics``: the topics of the UI configuration's pose-goal components
    (``/r/goal_pose`` for a waypoint, ``/r/ee_goal_pose`` for an end effector); a SetGoal
    tool must publish on one of them, and there is none when the configuration has none.
    None: not checked.
    """
    faults = list(_file(document, file))
    if not isinstance(document, dict) or not isinstance(
        document.get("Visualization Manager"), dict
    ):
        return tuple(faults)
    manager = document["Visualization Manager"]
    types = {
        topic: {normalise_type(t) for t in kinds} for topic, kinds in (topic_types or {}).items()
    }
    for path, display in displays(document):
        faults.extend(_display(display, path, file, types))
    faults.extend(_tools(manager.get("Tools"), file, pose_topics))
    faults.extend(_views(manager.get("Views"), file))
    if namespace is None:
        namespace = robot_namespace(document)
    if namespace is not None:
        faults.extend(_namespace(document, namespace, file))
    return tuple(faults)


def displays(document: Any) -> Iterator[tuple[str, dict[str, Any]]]:
    """(path, display) of every display, those inside display groups too, in file order."""
    manager = document.get("Visualization Manager") if isinstance(document, dict) else None
    if not isinstance(manager, dict):
        return
    stack: list[tuple[str, Any]] = [("Visualization Manager.Displays", manager.get("Displays"))]
    seen = 0
    while stack:
        path, group = stack.pop(0)
        if not isinstance(group, list):
            continue
        for index, display in enumerate(group):
            seen += 1
            if seen > _MAX_DISPLAYS or not isinstance(display, dict):
                continue
            where = f"{path}[{index}]"
            yield where, display
            if isinstance(display.get("Displays"), list):
                stack.append((f"{where}.Displays", display["Displays"]))


def robot_namespace(document: Any) -> str | None:
    """The namespace the displays' absolute topics share (``/robot1``), or None."""
    names = [
        topic
        for _, display in displays(document)
        if display.get("Class") != _DESCRIPTION
        and (topic := _topic(display.get("Topic")))
        and topic.startswith("/")
    ]
    return common_namespace(names)


def _fault(file: str, path: str, message: str, code: str) -> Fault:
    return Fault(Location(file, path=path), message, code=code)


def _topic(value: Any) -> str | None:
    """A topic property's name: ``{Value: /x, Depth: 5, ...}`` (or a bare string)."""
    if isinstance(value, dict):
        value = value.get("Value")
    return value if isinstance(value, str) else None


def _file(document: Any, file: str) -> Iterator[Fault]:
    rules = rviz_rules()["file"]
    if not isinstance(document, dict):
        yield _fault(file, "", "an .rviz file is a YAML mapping", "rviz-file")
        return
    yield from _keys(document, rules["top"], "", file, "rviz-file", required=rules["top"])
    manager = document.get("Visualization Manager")
    if isinstance(manager, dict):
        yield from _keys(manager, rules["manager"], "Visualization Manager", file, "rviz-file")
        options = manager.get("Global Options")
        if isinstance(options, dict):
            where = "Visualization Manager.Global Options"
            yield from _keys(options, rules["global_options"], where, file, "rviz-file")
    geometry = document.get("Window Geometry")
    if isinstance(geometry, dict):
        # Dock panels are saved under their own titles beside the geometry.
        required = rules["window_geometry_required"]
        for key in required:
            if key not in geometry:
                yield _fault(
                    file,
                    f"Window Geometry.{key}",
                    "missing: RViz2 reads it into a flag it never set, so the dock is shown or "
                    "hidden by chance",
                    "rviz-file",
                )


def _keys(
    mapping: dict[str, Any],
    known: Collection[str],
    path: str,
    file: str,
    code: str,
    *,
    required: Collection[str] = (),
) -> Iterator[Fault]:
    prefix = f"{path}." if path else ""
    for key in required:
        if key not in mapping:
            yield _fault(file, f"{prefix}{key}", "missing section", code)
    for key in mapping:
        if key not in known:
            yield _fault(
                file,
                f"{prefix}{shown(key)}",
                f"not a key RViz2 reads here (it reads: {', '.join(sorted(known))})",
                code,
            )


def _display(
    display: dict[str, Any], path: str, file: str, types: dict[str, set[str]]
) -> Iterator[Fault]:
    rules = rviz_rules()
    cls = display.get("Class")
    spec = rules["displays"].get(cls) if isinstance(cls, str) else None
    for key in rules["file"]["display_required"]:
        if key not in display:
            yield _fault(file, f"{path}.{key}", "missing: every display has it", "rviz-display")
    if spec is None:
        yield _fault(
            file, f"{path}.Class", f"not a display RViz2 has: {shown(cls)}", "rviz-display"
        )
        return
    if "properties" in spec:
        known = {*rules["file"]["display_keys"], *spec["properties"], "Displays"}
        for key in display:
            if key not in known:
                yield _fault(
                    file,
                    f"{path}.{shown(key)}",
                    f"not a property of {cls}: RViz2 ignores it",
                    "rviz-display",
                )
    for key in ("Topic", "Description Topic", "Update Topic"):
        if key in display:
            yield from _topic_property(display[key], f"{path}.{key}", file)
    topic = _topic(display.get("Topic"))
    if topic is not None and spec["messages"] and topic in types:
        yield from _display_type(display, topic, types[topic], path, file)


def _topic_property(value: Any, path: str, file: str) -> Iterator[Fault]:
    rules = rviz_rules()["file"]
    if isinstance(value, dict):
        yield from _keys(value, rules["topic_keys"], path, file, "rviz-display")
        for policy, allowed in rules["qos_values"].items():
            if policy in value and value[policy] not in allowed:
                yield _fault(
                    file,
                    f"{path}.{policy}",
                    f"must be one of: {', '.join(allowed)}",
                    "rviz-display",
                )
    name = _topic(value)
    if name is None:
        yield _fault(file, path, "a topic property has a Value naming the topic", "rviz-display")
    elif problem := topic_name_problem(name):
        yield _fault(file, f"{path}.Value", f"topic {problem}", "ros-topic-name")


def _display_type(
    display: dict[str, Any], topic: str, kinds: set[str], path: str, file: str
) -> Iterator[Fault]:
    cls = display["Class"]
    spec = rviz_rules()["displays"][cls]
    accepted = {normalise_type(m) for m in spec["messages"]}
    last = topic.rstrip("/").rpartition("/")[2]
    transported = spec.get("transport_suffixes", {}).get(last)
    if transported is not None:
        # image_transport: /x/image_raw/compressed is the compressed transport of /x/image_raw.
        accepted = {normalise_type(transported)}
    if kinds & accepted:
        return
    disabled = " (disabled: enabling it subscribes with the wrong type)"
    yield _fault(
        file,
        f"{path}.Class",
        f"{cls} shows {', '.join(sorted(accepted))}; the topic carries "
        f"{', '.join(sorted(kinds))}" + ("" if display.get("Enabled") else disabled),
        "rviz-display-type",
    )


def _tools(tools: Any, file: str, pose_topics: Collection[str] | None) -> Iterator[Fault]:
    rules = rviz_rules()["tools"]
    if not isinstance(tools, list):
        return
    for index, tool in enumerate(tools):
        path = f"Visualization Manager.Tools[{index}]"
        cls = tool.get("Class") if isinstance(tool, dict) else None
        spec = rules.get(cls) if isinstance(cls, str) else None
        if spec is None or not isinstance(tool, dict):
            yield _fault(file, f"{path}.Class", f"not a tool RViz2 has: {shown(cls)}", "rviz-tool")
            continue
        known = {"Class", *spec.get("properties", ())}
        for key in tool:
            if key not in known:
                yield _fault(file, f"{path}.{shown(key)}", f"not a property of {cls}", "rviz-tool")
        if "topic" not in spec:
            continue
        prop = spec["topic"]["property"]
        name = _topic(tool.get(prop))
        where = f"{path}.{prop}"
        if name is None:
            default = spec["topic"]["default"]
            yield _fault(
                file,
                where,
                f"no topic: the tool publishes on its default {default!r}, resolved in RViz's "
                "own namespace",
                "rviz-tool",
            )
            continue
        if isinstance(tool.get(prop), dict):
            yield from _topic_property(tool[prop], where, file)
        elif problem := topic_name_problem(name):
            yield _fault(file, where, f"topic {problem}", "ros-topic-name")
        if cls == _GOAL_TOOL and pose_topics is not None:
            yield from _goal(name, pose_topics, where, file)


def _goal(name: str, pose_topics: Collection[str], where: str, file: str) -> Iterator[Fault]:
    if not pose_topics:
        yield _fault(
            file,
            where,
            f"the UI configuration has no pose-goal component, yet this tool publishes goals "
            f"on {shown(name, quoted=True)}",
            "rviz-tool",
        )
    elif name not in pose_topics:
        wanted = ", ".join(shown(t, quoted=True) for t in sorted(pose_topics))
        yield _fault(
            file,
            where,
            f"publishes goals on {shown(name, quoted=True)}; the configuration's pose "
            f"component takes them on {wanted}",
            "rviz-tool",
        )


def _views(views: Any, file: str) -> Iterator[Fault]:
    known = rviz_rules()["views"]
    current = views.get("Current") if isinstance(views, dict) else None
    if isinstance(current, dict) and current.get("Class") not in known:
        yield _fault(
            file,
            "Visualization Manager.Views.Current.Class",
            f"not a view RViz2 has: {shown(current.get('Class'))}",
            "rviz-view",
        )


def _namespace(document: dict[str, Any], namespace: str, file: str) -> Iterator[Fault]:
    rules = rviz_rules()["tools"]
    manager = document["Visualization Manager"]
    tools = manager.get("Tools") if isinstance(manager.get("Tools"), list) else []
    for index, tool in enumerate(tools):
        spec = rules.get(tool.get("Class")) if isinstance(tool, dict) else None
        if not spec or "topic" not in spec:
            continue
        name = _topic(tool.get(spec["topic"]["property"])) or spec["topic"]["default"]
        if name.startswith("/") and not in_namespace(name, namespace):
            yield _fault(
                file,
                f"Visualization Manager.Tools[{index}].{spec['topic']['property']}",
                f"the tool publishes on {shown(name, quoted=True)}, outside the robot's "
                f"namespace {shown(namespace, quoted=True)}",
                "namespace",
            )
    for path, display in displays(document):
        name = _topic(display.get("Description Topic"))
        from_topic = display.get("Description Source", "Topic") == "Topic"
        if display.get("Class") != _DESCRIPTION or name is None or not from_topic:
            continue
        if not name.startswith("/"):
            continue  # expanded in RViz's own namespace
        if not in_namespace(name, namespace):
            yield _fault(
                file,
                f"{path}.Description Topic.Value",
                f"the robot description {shown(name, quoted=True)} is outside the robot's "
                f"namespace {shown(namespace, quoted=True)} (robot_state_publisher "
                "publishes it in its own)",
                "namespace",
            )
