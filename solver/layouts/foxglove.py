"""Foxglove / Lichtblick "classic" layout JSON, one per UI configuration, and its validation.

A layout is ``{"configById": {"Type!id": {...}}, "layout": tree, ...}`` where the tree is a
panel id or ``{direction, first, second, splitPercentage}``. Panel ids are numbered in panel
order, so the same configuration always gives the same bytes.

A layout opens in Lichtblick as it is written (issue 26, checked by
:mod:`solver.layouts.checks`): every topic a full ROS 2 name; every key a panel fills in when it
opens already there (else the app marks the layout modified at once), including a 3D panel's
whole ``publish`` block and a point cloud's colour; a title only on panels that show one; a
Publish panel holds a whole message (:mod:`solver.layouts.samples`) or is not there; one Teleop
pad per command topic; the 3D and Image panels' click-to-publish topics in the robot's
namespace (the app advertises them while the panel is open, whatever tool is chosen); a
reference grid in every 3D scene. Teleop pads publish while a button is held and send nothing
on release (no zero Twist); no panel publishes on its own.

Not here: the component -> panel mapping (:mod:`solver.layouts.presentation`, data); which
panels and topics (:mod:`solver.layouts.plan`).
"""

from __future__ import annotations

import json
from typing import Any

from solver.core.partition import Configuration
from solver.errors import Fault, Location, SolverError
from solver.layouts.plan import Panel, Plan, Robot, plan_layout
from solver.layouts.presentation import PANEL_TYPES, Presentation
from solver.layouts.samples import sample_message
from solver.layouts.tiling import split_tree
from solver.ros.names import normalise_type
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = [
    "NOTE_VARIABLE",
    "LayoutError",
    "foxglove_layout",
    "layout_filename",
    "plan_foxglove",
    "validate_foxglove",
]

# The global variable that says whom a layout is for and how to write it for another robot
# (JSON has no comments; the app lists global variables in its Variables sidebar).
NOTE_VARIABLE = "teleop_ui_layout"

# What the 3D renderer (ThreeDeeRender.tsx, IRenderer.ts) starts from and saves when a layout
# lacks it; written out so that the layout opens unmodified. Lichtblick v1.19.0's values.
_CAMERA = {
    "distance": 20,
    "perspective": True,
    "phi": 60,
    "target": [0, 0, 0],
    "targetOffset": [0, 0, 0],
    "targetOrientation": [0, 0, 0, 1],
    "thetaOffset": 45,
    "fovy": 45,
    "near": 0.5,
    "far": 5000,
}
# renderables/PublishSettings.ts DEFAULT_PUBLISH_SETTINGS: the pose estimate's deviations.
_DEVIATIONS = {
    "poseEstimateXDeviation": 0.5,
    "poseEstimateYDeviation": 0.5,
    "poseEstimateThetaDeviation": 0.26179939,
}
# The reference grid of the app's own default layout (CurrentLayoutProvider/defaultLayout.ts).
_GRID = {
    "visible": True,
    "frameLocked": True,
    "label": "Grid",
    "instanceId": "grid",
    "layerId": "foxglove.Grid",
    "size": 10,
    "divisions": 10,
    "lineWidth": 1,
    "color": "#248eff",
    "position": [0, 0, 0],
    "rotation": [0, 0, 0],
    "order": 1,
}
# A pose clicked with the 3D "publish pose" tool in a panel that is no goal panel: a topic
# nothing listens to for goals (the app's default is a navigation goal, /move_base_simple/goal).
CLICKED_POSE = "clicked_pose"
# How to write a layout for another robot (the note in every layout says so): a team's
# layouts under its namespace, or one robot's again from its description (its joints, and its
# real topics with --topics), which a team's layouts would lose.
_AGAIN = "teleop-ui layouts TEAM -o DIR --namespace /NAME"
_AGAIN_DESCRIBED = (
    "teleop-ui layouts --robot URDF --team TEAM -o FILE --namespace /NAME "
    "(--topics FILE: its own topics)"
)
# Message types whose first message makes the 3D panel pick and save a colour field.
_CLOUDS = {"sensor_msgs/PointCloud2", "sensor_msgs/LaserScan"}


class LayoutError(SolverError, ValueError):
    """A layout breaks a rule its viewer enforces."""


def layout_filename(number: int, *, default: bool = False, extension: str = "json") -> str:
    """The file name of configuration ``number``'s layout (``watch`` names it in its events)."""
    return f"config-{number:03d}{'-default' if default else ''}.{extension}"


def foxglove_layout(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    *,
    robot: Robot | None = None,
    tile_count: int | None = None,
) -> dict[str, Any]:
    """The layout of ``configuration`` (``None``: the default configuration, every component)
    for ``robot`` (default: a template in the root namespace)."""
    return plan_foxglove(
        plan_layout(solution, configuration, presentation, robot, tile_count=tile_count)
    )


def plan_foxglove(plan: Plan) -> dict[str, Any]:
    """A plan as a Lichtblick layout."""
    config_by_id: dict[str, Any] = {}
    ids: list[str] = []
    for panel in plan.panels:
        kind, config = _panel_config(panel, plan)
        panel_id = f"{kind}!p{len(ids) + 1:02d}"
        config_by_id[panel_id] = config
        ids.append(panel_id)
    return {
        "configById": config_by_id,
        "globalVariables": {NOTE_VARIABLE: _note(plan)},
        "userNodes": {},
        "playbackConfig": {"speed": 1},
        "layout": split_tree(ids) if ids else None,
    }


def _note(plan: Plan) -> str:
    which = f"teleop-ui: UI configuration {plan.number}" + (
        " (the default)" if plan.default else ""
    )
    again = _AGAIN_DESCRIBED if plan.described else _AGAIN
    return f"{which}, {plan.whom}; for a robot under /NAME: {again}"


def _titled(panel: Panel, config: dict[str, Any], *, note: str = "") -> dict[str, Any]:
    # Lichtblick reads the title from "lichtblickPanelTitle" (util/layout.ts), Foxglove Studio,
    # the project it forked, from "foxglovePanelTitle"; each ignores the other.
    title = panel.name
    if panel.spec.placeholder:
        title += " (placeholder: no panel for this component)"
    title += note
    return {"foxglovePanelTitle": title, "lichtblickPanelTitle": title, **config}


def _panel_config(panel: Panel, plan: Plan) -> tuple[str, dict[str, Any]]:
    """The panel's type and its whole config."""
    kind = panel.kind
    topic = panel.topic
    if kind in ("3D", "Image"):
        return kind, _titled(panel, _renderer(panel, plan))
    if kind == "Teleop":
        # Publishes while a button is held (at once, then every 1/publishRate s); sends nothing
        # on release: the robot must stop by itself when commands stop (docs/layouts.md).
        return kind, _titled(
            panel,
            {
                "topic": topic,
                "publishRate": 5,
                "upButton": {"field": "linear-x", "value": 0.5},
                "downButton": {"field": "linear-x", "value": -0.5},
                "leftButton": {"field": "angular-z", "value": 0.5},
                "rightButton": {"field": "angular-z", "value": -0.5},
            },
        )
    if kind == "Plot":
        # Plot paths are {value, enabled, timestampMethod} (Plot/utils/config.ts PlotConfig);
        # the other keys are Plot/constants.ts DEFAULT_PLOT_CONFIG's, which the panel saves.
        # Each series labelled: the legend names a series by its label, else its whole path,
        # and cuts it in a narrow tile (the three paths differ only in their last letter).
        paths = [
            {
                "value": f"{topic}.wrench.force.{axis}",
                "label": f"force {axis}",
                "enabled": True,
                "timestampMethod": "receiveTime",
            }
            for axis in "xyz"
        ]
        return kind, _titled(panel, {"paths": paths, **_PLOT})
    if kind == "Publish":
        return _publish(panel, plan)
    if kind == "Indicator":
        label = "no panel" if panel.spec.placeholder else "no data"
        return kind, _titled(panel, _indicator(topic, label))
    # RawMessages draws its own toolbar: it shows the topic path, never a title.
    return kind, {"topicPath": topic, **_RAW}


_PLOT = {
    "showXAxisLabels": True,
    "showYAxisLabels": True,
    "showLegend": True,
    "legendDisplay": "floating",
    "showPlotValuesInLegend": False,
    "isSynced": True,
    "xAxisVal": "timestamp",
    "sidebarDimension": 240,
}
# RawMessages/index.tsx defaultConfig.
_RAW = {
    "diffEnabled": False,
    "diffMethod": "custom",
    "diffTopicPath": "",
    "showFullMessageForDiff": False,
}


def _indicator(path: str, label: str) -> dict[str, Any]:
    # Lichtblick's IndicatorConfig: path, style, rules, fallbackColor, fallbackLabel. The label
    # never wraps: lines of at most 20 characters (checks/lichtblick.yaml label_lines).
    return {
        "path": path,
        "style": "bulb",
        "rules": [],
        "fallbackColor": "#a0a0a0",
        "fallbackLabel": label,
    }


def _renderer(panel: Panel, plan: Plan) -> dict[str, Any]:
    """A 3D or Image panel: the renderer's whole config, click tools in the namespace."""
    goal = panel.is_goal
    topics: dict[str, Any] = {}
    if panel.kind == "3D":
        topics[panel.topic] = {"visible": True, **_colour(panel)}
    return {
        "cameraState": dict(_CAMERA),
        "followMode": "follow-pose",
        "scene": {},
        "transforms": {},
        "topics": topics,
        "layers": {"grid": dict(_GRID)} if panel.kind == "3D" else {},
        "publish": {
            "type": "pose" if goal else "point",
            "poseTopic": panel.topic if goal else plan.topic(CLICKED_POSE),
            "pointTopic": plan.topic("clicked_point"),
            "poseEstimateTopic": plan.topic("initialpose"),
            **_DEVIATIONS,
        },
        "imageMode": {"imageTopic": panel.topic} if panel.kind == "Image" else {},
    }


def _colour(panel: Panel) -> dict[str, Any]:
    """The colour a point-cloud topic is drawn in, set so the app does not set it on the first
    message: a LaserScan's intensity (its only choices are intensity and range), a
    PointCloud2's height (z); intensity where the type is not known (a PointCloud2 without
    that field is coloured by x, no error)."""
    kinds = {normalise_type(t) for t in panel.types}
    if not kinds & _CLOUDS:
        return {}
    field = "z" if kinds & _CLOUDS == {"sensor_msgs/PointCloud2"} else "intensity"
    return {"colorField": field, "colorMode": "colormap", "colorMap": "turbo"}


def _publish(panel: Panel, plan: Plan) -> tuple[str, dict[str, Any]]:
    """A Publish panel holding a whole message, or, where none can be right, an Indicator
    saying why (it only listens: nothing is sent)."""
    datatype = panel.types[0] if panel.types else ""
    message = sample_message(datatype, plan.joints) if datatype else None
    if message is None:
        if normalise_type(datatype) == "trajectory_msgs/JointTrajectory":
            why = "the robot's joint names are not known"
            label = "no joint names:\nteleop-ui layouts\n--robot URDF"
        else:
            why = "no whole message of this type is known"
            label = "no message\nto send"
        return "Indicator", _titled(
            panel, _indicator(panel.topic, label), note=f" (no Publish button: {why})"
        )
    return "Publish", _titled(
        panel,
        {
            "topicName": panel.topic,
            "datatype": datatype,
            "buttonText": "Publish",
            "buttonTooltip": f"sends the message below to {panel.topic} once",
            "advancedView": True,
            "value": json.dumps(message, indent=2),
        },
    )


def validate_foxglove(layout: dict[str, Any], file: str = "<layout>") -> None:
    """Every tree id has a config, no orphan configs, unique ids, splits 0..100, known types."""
    faults: list[Fault] = []
    seen: list[str] = []

    def walk(node: Any, path: str) -> None:
        if isinstance(node, str):
            seen.append(node)
            return
        if not isinstance(node, dict):
            faults.append(Fault(Location(file, path=path), "not a panel id or split"))
            return
        split = node.get("splitPercentage", 50)
        if not isinstance(split, (int, float)) or not 0 <= split <= 100:
            faults.append(
                Fault(
                    Location(file, path=f"{path}.splitPercentage"),
                    f"split percentage must be in 0..100 (got {shown(split, quoted=True)})",
                )
            )
        if node.get("direction") not in ("row", "column"):
            faults.append(
                Fault(
                    Location(file, path=f"{path}.direction"), "direction must be 'row' or 'column'"
                )
            )
        walk(node.get("first"), f"{path}.first")
        walk(node.get("second"), f"{path}.second")

    configs = layout.get("configById", {})
    if layout.get("layout") is not None:
        walk(layout["layout"], "layout")
    for panel_id in sorted(set(seen)):
        if seen.count(panel_id) > 1:
            faults.append(
                Fault(Location(file, path="layout"), f"duplicate id {shown(panel_id, quoted=True)}")
            )
        if panel_id not in configs:
            faults.append(
                Fault(
                    Location(file, path="layout"), f"{shown(panel_id, quoted=True)} has no config"
                )
            )
    for panel_id in configs:
        if panel_id not in seen:
            faults.append(Fault(Location(file, path=f"configById.{panel_id}"), "orphan config"))
        if panel_id.partition("!")[0] not in PANEL_TYPES:
            faults.append(
                Fault(Location(file, path=f"configById.{panel_id}"), "unknown panel type")
            )
    if faults:
        raise LayoutError(faults)
