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
from solver.layouts.design import Design, Split, design
from solver.layouts.plan import Panel, Plan, Robot, plan_layout
from solver.layouts.presentation import PANEL_TYPES, Presentation
from solver.layouts.samples import sample_message
from solver.ros.names import normalise_type
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = [
    "DESIGN_VARIABLE",
    "NOTE_VARIABLE",
    "TAB_TITLE_CHARS",
    "LayoutError",
    "foxglove_layout",
    "layout_filename",
    "plan_foxglove",
    "short_title",
    "validate_foxglove",
]

# The global variable that says whom a layout is for and how to write it for another robot
# (JSON has no comments; the app lists global variables in its Variables sidebar).
NOTE_VARIABLE = "teleop_ui_layout"
# The global variable that says how the layout was designed: the grammar's regions, the
# cluster order used, and each component's tile (read by :mod:`solver.layouts.quality`).
DESIGN_VARIABLE = "teleop_ui_design"

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
    """A plan as a Lichtblick layout, laid out by its grammar (:mod:`solver.layouts.design`):
    a tile is a panel, or a Tab panel with a tab per sensor of one cluster."""
    laid = design(plan)
    config_by_id: dict[str, Any] = {}
    # Panel ids are numbered in the plan's order (the configuration's components), whatever
    # region a panel goes to: a component's id says which it is, not where.
    numbered: dict[int, str] = {}
    for panel in plan.panels:
        kind, config = _panel_config(panel, plan)
        panel_id = f"{kind}!p{len(numbered) + 1:02d}"
        config_by_id[panel_id] = config
        numbered[id(panel)] = panel_id
    leaves: list[str] = []
    for tile in laid.tiles:
        ids = [numbered[id(panel)] for panel in tile.panels]
        if not tile.grouped:
            leaves.append(ids[0])
            continue
        tab_id = f"Tab!c{len(leaves) + 1:02d}"
        tabs = [
            {"title": short_title(panel, plan), "layout": panel_id}
            for panel, panel_id in zip(tile.panels, ids, strict=True)
        ]
        config_by_id[tab_id] = {"activeTabIdx": 0, "tabs": tabs}
        leaves.append(tab_id)
    return {
        "configById": config_by_id,
        "globalVariables": {
            NOTE_VARIABLE: _note(plan),
            DESIGN_VARIABLE: _design_note(laid, leaves),
        },
        "userNodes": {},
        "playbackConfig": {"speed": 1},
        "layout": _tree(laid.tree, leaves),
    }


def _tree(node: Split | int | None, leaves: list[str]) -> Any:
    if node is None:
        return None
    if isinstance(node, int):
        return leaves[node]
    return {
        "direction": node.direction,
        "first": _tree(node.first, leaves),
        "second": _tree(node.second, leaves),
        "splitPercentage": node.percent,
    }


def _design_note(laid: Design, leaves: list[str]) -> dict[str, Any]:
    """How the layout was designed: the screen, the regions as laid out in percent (the
    grammar's that hold tiles, grown by the empty ones), the cluster order, and each tile's
    component, role and panel id (its first tile's, per component)."""
    grammar = laid.grammar
    return {
        "screen": list(grammar.screen),
        "regions": {
            role: [round(rect.x, 4), round(rect.y, 4), round(rect.width, 4), round(rect.height, 4)]
            for role, rect in laid.regions
        },
        "clusterOrder": grammar.order,
        **({"clusterOrderNote": grammar.order_note} if grammar.order_note else {}),
        "tiles": [
            {"component": component, "role": tile.role, "panel": leaf}
            for tile, leaf in zip(laid.tiles, leaves, strict=True)
            for component in tile.components
        ],
    }


def _note(plan: Plan) -> str:
    which = f"teleop-ui: UI configuration {plan.number}" + (
        " (the default)" if plan.default else ""
    )
    again = _AGAIN_DESCRIBED if plan.described else _AGAIN
    return f"{which}, {plan.whom}; for a robot under /NAME: {again}"


# A Tab panel's tab shows about 12 characters (Lichtblick v1.19.0 at 1920x1080 cut
# "visual display 1" to "visual displa"): a tab is titled with the sensor's short name.
TAB_TITLE_CHARS = 12


def short_title(panel: Panel, plan: Plan) -> str:
    """A tab's title: the first part of the panel's topic under the robot's namespace and the
    sensor's number (``camera 3`` for ``/uav1/camera/image_raw_3``, ``visual display 3``),
    at most :data:`TAB_TITLE_CHARS` characters; the panel in the tab names the whole topic."""
    topic = panel.topic
    if plan.namespace and topic.startswith(plan.namespace + "/"):
        topic = topic[len(plan.namespace) + 1 :]
    first = topic.strip("/").partition("/")[0].rpartition("_")
    # The template's sensor suffix (_2, _3) ends the last part, not the first: drop it here.
    base = first[0] if first[2].isdigit() and first[0] else "".join(first)
    number = panel.name.rpartition(" ")[2]
    text = f"{base} {number}" if number.isdigit() else base
    if len(text) <= TAB_TITLE_CHARS:
        return text
    keep = TAB_TITLE_CHARS - 1 - (len(number) + 1 if number.isdigit() else 0)
    return base[:keep] + "\u2026" + (f" {number}" if number.isdigit() else "")


def _titled(panel: Panel, config: dict[str, Any], *, note: str = "") -> dict[str, Any]:
    # Lichtblick reads the title from "lichtblickPanelTitle" (util/layout.ts), Foxglove Studio,
    # the project it forked, from "foxglovePanelTitle"; each ignores the other. The title names
    # the component and the topic, the component first (a narrow tile cuts the end).
    title = f"{panel.name} \u00b7 {panel.topic}"
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
    for panel_id in list(seen):
        if panel_id.partition("!")[0] == "Tab":
            for index, tab in enumerate(configs.get(panel_id, {}).get("tabs", [])):
                if tab.get("layout") is not None:
                    walk(tab["layout"], f"configById.{panel_id}.tabs[{index}].layout")
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
        if panel_id.partition("!")[0] not in (*PANEL_TYPES, "Tab"):
            faults.append(
                Fault(Location(file, path=f"configById.{panel_id}"), "unknown panel type")
            )
    if faults:
        raise LayoutError(faults)
