"""RViz2 ``.rviz`` files, one per UI configuration, and their validation.

Displays come from the message types the presentation profile lists for each component,
mapped to the ``rviz_default_plugins`` display that accepts them (as its plugin description
declares). Sensor streams subscribe best-effort; ``/robot_description`` is transient-local so a
late RViz still gets the model. RViz2 has no display for velocity commands, joint commands or
audio: such a component gets a disabled ``Marker`` display named as a placeholder, never a
silent drop.

Not here: the component -> panel mapping (:mod:`solver.layouts.presentation`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import yaml

from solver.core.partition import Configuration
from solver.core.solution import Solution
from solver.errors import Fault, Location
from solver.files.yamlio import parse_document
from solver.layouts.foxglove import LayoutError, panel_entries, template_topic
from solver.layouts.presentation import PanelSpec, Presentation
from solver.untrusted import shown

__all__ = ["REQUIRED_KEYS", "rviz_layout", "rviz_text", "validate_rviz"]

# Message type -> the rviz_default_plugins display that accepts it.
DISPLAYS = {
    "sensor_msgs/Image": "Image",
    "sensor_msgs/CompressedImage": "Image",
    "sensor_msgs/PointCloud2": "PointCloud2",
    "sensor_msgs/LaserScan": "LaserScan",
    "geometry_msgs/WrenchStamped": "Wrench",
    "geometry_msgs/PoseStamped": "Pose",
}
REQUIRED_KEYS = ("Class", "Enabled", "Name", "Value")


def _qos(topic: str, *, sensor: bool) -> dict[str, Any]:
    return {
        "Depth": 5,
        "Durability Policy": "Volatile",
        "History Policy": "Keep Last",
        "Reliability Policy": "Best Effort" if sensor else "Reliable",
        "Value": topic,
    }


def _display(spec: PanelSpec, topic: str, tile: int, count: int) -> dict[str, Any]:
    name = spec.component + (f" {tile + 1}" if count > 1 else "")
    kind = next((DISPLAYS[t] for t in spec.types if t in DISPLAYS), None)
    if kind is None:
        return {
            "Class": "rviz_default_plugins/Marker",
            "Enabled": False,
            "Name": f"{name} (placeholder: no RViz2 display for this component)",
            "Topic": _qos(topic, sensor=False),
            "Value": False,
        }
    sensor = kind in ("Image", "PointCloud2", "LaserScan", "Wrench")
    return {
        "Class": f"rviz_default_plugins/{kind}",
        "Enabled": True,
        "Name": name,
        "Topic": _qos(topic, sensor=sensor),
        "Value": True,
    }


def rviz_layout(
    solution: Solution,
    configuration: Configuration | None,
    profile: Presentation,
    *,
    robot: str = "<robot>",
    tile_count: int | None = None,
    topics: Mapping[tuple[str, int], str] | None = None,
) -> dict[str, Any]:
    """The ``.rviz`` document of ``configuration`` (``None``: the default configuration).

    ``topics`` maps (component, tile) to a robot's real topic, as for Foxglove layouts.
    """
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
                "Value": "/robot_description",
            },
            "Enabled": True,
            "Name": "RobotModel",
            "Value": True,
        },
    ]
    for spec, count in panel_entries(solution, configuration, profile, tile_count):
        displays.extend(
            _display(
                spec,
                (topics or {}).get((spec.component, tile))
                or template_topic(spec, robot, tile, count),
                tile,
                count,
            )
            for tile in range(count)
        )
    return {
        "Panels": [{"Class": "rviz_common/Displays", "Name": "Displays"}],
        "Visualization Manager": {
            "Class": "",
            "Displays": displays,
            "Enabled": True,
            "Global Options": {"Fixed Frame": "base_link", "Frame Rate": 30},
            "Name": "root",
            # The goal tool publishes only on the operator's click.
            "Tools": [
                {"Class": "rviz_default_plugins/Interact"},
                {
                    "Class": "rviz_default_plugins/SetGoal",
                    "Topic": _qos(f"{robot}/goal_pose", sensor=False),
                },
            ],
            "Value": True,
            "Views": {
                "Current": {
                    "Class": "rviz_default_plugins/Orbit",
                    "Name": "Current View",
                    "Value": "Orbit (rviz_default_plugins)",
                }
            },
        },
    }


def rviz_text(document: dict[str, Any]) -> str:
    return yaml.safe_dump(document, sort_keys=False, default_flow_style=False, width=100)


def validate_rviz(text: str, file: str = "<rviz>") -> None:
    """Loads as YAML (through the project's one YAML reader); every display has Class, Enabled,
    Name and Value."""
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
