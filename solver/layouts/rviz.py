"""RViz2 ``.rviz`` files, one per UI configuration, and their validation.

Each panel of the plan (:mod:`solver.layouts.plan`) becomes the ``rviz_default_plugins``
display that shows its topic's message type (as the plugin description declares it): the
real topic's type when the robot's topics are known (a ``LaserScan`` gets a LaserScan
display), else the first type the presentation lists that RViz2 shows. Sensor streams
subscribe best-effort; the robot description is read transient-local in the robot's namespace
(``robot_state_publisher`` publishes it in its own), so a late RViz still gets the model. RViz2
has no display for velocity commands, joint commands or audio: such a component gets an empty,
disabled display group named as a placeholder, which subscribes to nothing (never a silent
drop). Displays follow the presentation grammar's order (:mod:`solver.layouts.design`): the
primary view first, then the secondary views, the controls and the status; each of Equation
(2)'s clusters of sensors is a display group named after it (and so is a region's overflow).
The goal tool publishes on the configuration's goal-pose topic (a waypoint's, else an end
effector's) and is left out when the configuration has none.

A template names topics relative to RViz2's own namespace (``camera/image_raw``), re-targeted
to a robot with ``rviz2 -d FILE --ros-args -r __ns:=/robot1``; the file's first lines say so.

Not here: the component -> panel mapping (:mod:`solver.layouts.presentation`).
"""

from __future__ import annotations

from typing import Any

import yaml

from solver.core.partition import Configuration
from solver.errors import Fault, Location
from solver.files.yamlio import parse_document
from solver.layouts.design import design
from solver.layouts.foxglove import LayoutError
from solver.layouts.plan import Panel, Plan, Robot, plan_layout
from solver.layouts.presentation import Presentation
from solver.ros.names import normalise_type
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = [
    "REQUIRED_KEYS",
    "plan_rviz",
    "rviz_layout",
    "rviz_note",
    "rviz_text",
    "validate_rviz",
]

# Message type -> the rviz_default_plugins display that accepts it.
DISPLAYS = {
    "sensor_msgs/Image": "Image",
    "sensor_msgs/CompressedImage": "Image",
    "sensor_msgs/PointCloud2": "PointCloud2",
    "sensor_msgs/LaserScan": "LaserScan",
    "geometry_msgs/WrenchStamped": "Wrench",
    "geometry_msgs/PoseStamped": "Pose",
}
# image_transport: RViz2's Image display shows a CompressedImage topic named .../compressed.
_TRANSPORTS = ("compressed", "compressedDepth")
_SENSORS = ("Image", "PointCloud2", "LaserScan", "Wrench")
# Every display has these (a display group saves no Value: navigation2's default view).
REQUIRED_KEYS = ("Class", "Enabled", "Name")


def _qos(topic: str, *, sensor: bool) -> dict[str, Any]:
    return {
        "Depth": 5,
        "Durability Policy": "Volatile",
        "History Policy": "Keep Last",
        "Reliability Policy": "Best Effort" if sensor else "Reliable",
        "Value": topic,
    }


def _kind(panel: Panel) -> str | None:
    """The display that shows the panel's topic, or None."""
    for datatype in panel.types:
        kind = DISPLAYS.get(normalise_type(datatype))
        if kind is None:
            continue
        last = panel.topic.rpartition("/")[2]
        compressed = normalise_type(datatype) == "sensor_msgs/CompressedImage"
        if compressed and panel.real and last not in _TRANSPORTS:
            continue  # RViz2 finds a compressed stream only under its transport's name
        return kind
    return None


def _display(panel: Panel) -> dict[str, Any]:
    kind = _kind(panel)
    if kind is None:
        # A display group subscribes to nothing: enabling it shows nothing, never a wrong type.
        # Its name says which topic the component would use.
        return {
            "Class": "rviz_common/Group",
            "Displays": [],
            "Enabled": False,
            "Name": f"{panel.name}: {panel.topic} (placeholder: no RViz2 display for this "
            "component)",
        }
    return {
        "Class": f"rviz_default_plugins/{kind}",
        "Enabled": True,
        "Name": panel.name,
        "Topic": _qos(panel.topic, sensor=kind in _SENSORS),
        "Value": True,
    }


def rviz_layout(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    *,
    robot: Robot | None = None,
    tile_count: int | None = None,
) -> dict[str, Any]:
    """The ``.rviz`` document of ``configuration`` (``None``: the default configuration) for
    ``robot`` (default: a template with relative topics)."""
    plan = plan_layout(
        solution, configuration, presentation, robot, tile_count=tile_count, relative=True
    )
    return plan_rviz(plan)


def plan_rviz(plan: Plan) -> dict[str, Any]:
    """A plan as an ``.rviz`` document."""
    displays: list[dict[str, Any]] = [
        {"Class": "rviz_default_plugins/Grid", "Enabled": True, "Name": "Grid", "Value": True},
        {
            "Class": "rviz_default_plugins/RobotModel",
            "Description Source": "Topic",
            "Description Topic": {
                "Depth": 5,
                "Durability Policy": "Transient Local",
                "History Policy": "Keep Last",
                "Reliability Policy": "Reliable",
                "Value": plan.topic("robot_description"),
            },
            "Enabled": True,
            "Name": "RobotModel",
            "Value": True,
        },
    ]
    # The grammar's order (primary view, secondary views, controls, status), as in the
    # Lichtblick layout and the preview; a cluster of sensors is a display group.
    for tile in design(plan).tiles:
        if tile.grouped:
            displays.append(
                {
                    "Class": "rviz_common/Group",
                    "Displays": [_display(panel) for panel in tile.panels],
                    "Enabled": True,
                    "Name": f"{tile.title} ({tile.role})",
                }
            )
        else:
            displays.append(_display(tile.panels[0]))
    # The goal tool publishes only on the operator's click, on the configuration's goal topic.
    tools: list[dict[str, Any]] = [{"Class": "rviz_default_plugins/Interact"}]
    goals = sorted(plan.goals, key=lambda panel: panel.spec.component != "Waypoint")
    if goals:
        tools.append(
            {"Class": "rviz_default_plugins/SetGoal", "Topic": _qos(goals[0].topic, sensor=False)}
        )
    return {
        "Panels": [{"Class": "rviz_common/Displays", "Name": "Displays"}],
        "Visualization Manager": {
            "Class": "",
            "Displays": displays,
            "Enabled": True,
            "Global Options": {"Fixed Frame": "base_link", "Frame Rate": 30},
            "Name": "root",
            "Tools": tools,
            "Value": True,
            "Views": {
                "Current": {
                    "Class": "rviz_default_plugins/Orbit",
                    "Name": "Current View",
                    "Value": "Orbit (rviz_default_plugins)",
                }
            },
        },
        # RViz2 reads both dock flags; without them it reads a flag it never set.
        "Window Geometry": {
            "Displays": {"collapsed": False},
            "Height": 800,
            "Hide Left Dock": False,
            "Hide Right Dock": True,
            "Width": 1200,
            "X": 0,
            "Y": 0,
        },
    }


def rviz_note(plan: Plan) -> str:
    """Whom the file is for and how to open it for a robot (its first lines, as comments)."""
    which = f"teleop-ui: UI configuration {plan.number}" + (
        " (the default)" if plan.default else ""
    )
    if any(not panel.topic.startswith("/") for panel in plan.panels):
        return (
            f"{which}. Topics are relative to RViz2's own namespace; for a robot under "
            "/robot1:\n  rviz2 -d FILE --ros-args -r __ns:=/robot1"
        )
    return f"{which}, {plan.whom}."


def rviz_text(document: dict[str, Any], note: str = "") -> str:
    """The ``.rviz`` text: ``note`` as comments, then the document (RViz2 drops comments when it
    saves the file again)."""
    head = "".join(f"# {line}\n" for line in note.splitlines())
    return head + yaml.safe_dump(document, sort_keys=False, default_flow_style=False, width=100)


def validate_rviz(text: str, file: str = "<rviz>") -> None:
    """Loads as YAML (through the project's one YAML reader); every display has Class, Enabled
    and Name."""
    document = parse_document(text, file).data
    faults: list[Fault] = []
    displays = (document or {}).get("Visualization Manager", {}).get("Displays")
    if not isinstance(displays, list):
        faults.append(
            Fault(Location(file, path="Visualization Manager.Displays"), "missing display list")
        )
        displays = []
    for index, display in enumerate(displays):
        faults.extend(
            Fault(
                Location(file, path=f"Visualization Manager.Displays[{index}]"),
                f"display has no {shown(key, quoted=True)}",
            )
            for key in REQUIRED_KEYS
            if key not in display
        )
    if faults:
        raise LayoutError(faults)
