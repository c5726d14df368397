"""Our layouts use only keys the real viewers read, checked against keys of their real files.

The key sets below are written from public source and example files (named at each set). They
are the viewers' own names: a key we write that is not among them would be ignored silently by
the viewer, so the panel would open unconfigured.
"""

from __future__ import annotations

from typing import Any

import yaml

from solver import load_team, solve
from solver.layouts import JointStart, Presentation, Robot, foxglove_layout, load_presentation
from solver.layouts.presentation import PanelSpec
from solver.layouts.rviz import rviz_layout, rviz_text

# Lichtblick-Suite/lichtblick packages/suite-base/src/providers/CurrentLayoutProvider/
# defaultLayout.ts: the top-level keys of a layout and of a split node of its tree.
LAYOUT_KEYS = {"configById", "globalVariables", "userNodes", "playbackConfig", "layout"}
SPLIT_KEYS = {"first", "second", "direction", "splitPercentage"}
# Lichtblick-Suite/lichtblick packages/suite-base/src/util/layout.ts (PANEL_TITLE_CONFIG_KEY,
# "lichtblickPanelTitle"); Foxglove Studio's is "foxglovePanelTitle".
TITLE_KEYS = {"lichtblickPanelTitle", "foxglovePanelTitle"}
# Per panel type, the config keys its source declares:
PANEL_KEYS: dict[str, set[str]] = {
    # packages/suite-base/src/types/layouts.ts, type TabPanelConfig (the default
    # configuration's primary views are the tabs of one Tab panel).
    "Tab": {"activeTabIdx", "tabs"},
    # packages/suite-base/src/panels/Teleop/TeleopPanel.tsx, type Config.
    "Teleop": {"topic", "publishRate", "upButton", "downButton", "leftButton", "rightButton"},
    # packages/suite-base/src/panels/ThreeDeeRender/IRenderer.ts, type RendererConfig (the
    # Image panel is the same renderer in image mode).
    "3D": {
        "cameraState",
        "followTf",
        "followMode",
        "scene",
        "publish",
        "transforms",
        "topics",
        "layers",
        "imageMode",
    },
    "Image": {
        "cameraState",
        "followTf",
        "followMode",
        "scene",
        "publish",
        "transforms",
        "topics",
        "layers",
        "imageMode",
    },
    # packages/suite-base/src/panels/Publish/types.ts, type PublishConfig.
    "Publish": {
        "topicName",
        "datatype",
        "buttonText",
        "buttonTooltip",
        "buttonColor",
        "advancedView",
        "value",
    },
    # packages/suite-base/src/panels/Indicator/types.ts, type IndicatorConfig.
    "Indicator": {"fallbackColor", "fallbackLabel", "path", "rules", "style"},
    # packages/suite-base/src/panels/RawMessages/types.ts, type RawMessagesPanelConfig.
    "RawMessages": {
        "diffEnabled",
        "diffMethod",
        "diffTopicPath",
        "expansion",
        "showFullMessageForDiff",
        "topicPath",
        "fontSize",
    },
    # packages/suite-base/src/panels/Plot/utils/config.ts, type PlotConfig.
    "Plot": {
        "paths",
        "minXValue",
        "maxXValue",
        "minYValue",
        "maxYValue",
        "showLegend",
        "legendDisplay",
        "showPlotValuesInLegend",
        "showXAxisLabels",
        "showYAxisLabels",
        "isSynced",
        "xAxisVal",
        "xAxisPath",
        "followingViewWidth",
        "sidebarDimension",
    },
}
# Teleop buttons {field, value}, field one of TeleopPanel.tsx's geometryMsgOptions.
BUTTON_KEYS = {"field", "value"}
TWIST_FIELDS = {"linear-x", "linear-y", "linear-z", "angular-x", "angular-y", "angular-z"}
# IRenderer.ts: ImageModeConfig keys, the publish settings' keys, a topic's BaseSettings.
IMAGE_MODE_KEYS = {
    "imageTopic",
    "calibrationTopic",
    "annotations",
    "synchronize",
    "rotation",
    "flipHorizontal",
    "flipVertical",
    "minValue",
    "maxValue",
    "cameraSelection",
}
PUBLISH_KEYS = {
    "type",
    "poseTopic",
    "pointTopic",
    "poseEstimateTopic",
    "poseEstimateXDeviation",
    "poseEstimateYDeviation",
    "poseEstimateThetaDeviation",
}
# Plot paths: {value, enabled, timestampMethod} (PlotPath in the Plot panel's types.ts).
PLOT_PATH_KEYS = {"value", "enabled", "timestampMethod", "color", "label", "showLine", "lineSize"}


def _every_panel_profile() -> Presentation:
    # One component per panel type, so each type's config is generated and checked.
    base = load_presentation()
    swap = {
        "audio": PanelSpec("audio", "Indicator", "<robot>/a", ()),
        "spherical display": PanelSpec("spherical display", "RawMessages", "<robot>/s", ()),
    }
    panels = [swap.get(spec.component, spec) for spec in base.panels]
    return Presentation("<test>", tuple(panels))


def _leaves_and_splits(node: Any, splits: list[dict[str, Any]]) -> None:
    if isinstance(node, dict):
        splits.append(node)
        _leaves_and_splits(node["first"], splits)
        _leaves_and_splits(node["second"], splits)


def test_foxglove_layouts_use_only_keys_the_lichtblick_sources_declare() -> None:
    solution = solve(load_team("case3"))
    # A robot whose joints are known: its joint command is a Publish panel.
    robot = Robot("/robot1", joints=(JointStart("shoulder", 0.0),))
    layout = foxglove_layout(solution, None, _every_panel_profile(), robot=robot)
    assert set(layout) == LAYOUT_KEYS
    splits: list[dict[str, Any]] = []
    _leaves_and_splits(layout["layout"], splits)
    assert splits
    assert all(set(split) == SPLIT_KEYS for split in splits)
    seen: set[str] = set()
    for panel_id, config in layout["configById"].items():
        kind = panel_id.partition("!")[0]
        seen.add(kind)
        assert set(config) - TITLE_KEYS <= PANEL_KEYS[kind], panel_id
        if kind == "Teleop":
            for button in ("upButton", "downButton", "leftButton", "rightButton"):
                assert set(config[button]) == BUTTON_KEYS
                assert config[button]["field"] in TWIST_FIELDS
        if kind == "Image":
            assert set(config["imageMode"]) <= IMAGE_MODE_KEYS
        if "publish" in config:
            assert set(config["publish"]) <= PUBLISH_KEYS
            assert config["publish"]["type"] in ("pose", "point", "pose_estimate")
        if kind == "Plot":
            assert all(set(path) <= PLOT_PATH_KEYS for path in config["paths"])
    assert seen == set(PANEL_KEYS)


# ros-navigation/navigation2 nav2_bringup/rviz/nav2_default_view.rviz: the keys its displays
# and tools use (names only), by class.
RVIZ_TOP_KEYS = {
    "Class",
    "Displays",
    "Enabled",
    "Global Options",
    "Name",
    "Tools",
    "Value",
    "Views",
}
RVIZ_DISPLAY_KEYS = {
    "rviz_default_plugins/Grid": {"Class", "Enabled", "Name", "Value", "Alpha", "Cell Size"},
    "rviz_default_plugins/RobotModel": {
        "Class",
        "Enabled",
        "Name",
        "Value",
        "Description Source",
        "Description Topic",
        "Description File",
    },
    "rviz_default_plugins/Image": {"Class", "Enabled", "Name", "Topic", "Value", "Max Value"},
    "rviz_default_plugins/PointCloud2": {"Class", "Enabled", "Name", "Topic", "Value", "Style"},
    "rviz_default_plugins/LaserScan": {"Class", "Enabled", "Name", "Topic", "Value", "Style"},
    "rviz_default_plugins/MarkerArray": {"Class", "Enabled", "Name", "Topic", "Value"},
    "rviz_common/Group": {"Class", "Displays", "Enabled", "Name"},
}
RVIZ_TOPIC_KEYS = {
    "Depth",
    "Durability Policy",
    "Filter size",
    "History Policy",
    "Reliability Policy",
    "Value",
}
RVIZ_POLICY_VALUES = {"Volatile", "Transient Local", "Keep Last", "Reliable", "Best Effort"}
RVIZ_TOOL_KEYS = {"Class", "Topic", "Single click", "Covariance x", "Covariance y"}
RVIZ_VIEW_KEYS = {"Class", "Name", "Value", "Target Frame", "Near Clip Distance"}
RVIZ_GLOBAL_KEYS = {"Background Color", "Fixed Frame", "Frame Rate"}
RVIZ_FILE_KEYS = {"Panels", "Visualization Manager", "Window Geometry"}
# Its Window Geometry: the window, the two dock flags, and each dock panel under its title.
RVIZ_WINDOW_KEYS = {
    "Displays",
    "Height",
    "Hide Left Dock",
    "Hide Right Dock",
    "QMainWindow State",
    "Width",
    "X",
    "Y",
}


def test_rviz_files_use_only_keys_a_real_rviz2_file_uses() -> None:
    solution = solve(load_team("case3"))
    document = yaml.safe_load(rviz_text(rviz_layout(solution, None, load_presentation())))
    assert set(document) == RVIZ_FILE_KEYS
    assert set(document["Window Geometry"]) <= RVIZ_WINDOW_KEYS
    manager = document["Visualization Manager"]
    assert set(manager) <= RVIZ_TOP_KEYS
    assert set(manager["Global Options"]) <= RVIZ_GLOBAL_KEYS
    assert set(manager["Views"]["Current"]) <= RVIZ_VIEW_KEYS
    for tool in manager["Tools"]:
        assert set(tool) <= RVIZ_TOOL_KEYS
    classes = set()
    # A display group (the default configuration's primary views) holds displays of its own.
    grouped = [d for group in manager["Displays"] for d in group.get("Displays", [])]
    for display in [*manager["Displays"], *grouped]:
        cls = display["Class"]
        classes.add(cls)
        # Display classes the example does not use (Wrench, Pose, Marker placeholders) share
        # the common keys of every topic display.
        allowed = RVIZ_DISPLAY_KEYS.get(cls, RVIZ_DISPLAY_KEYS["rviz_default_plugins/MarkerArray"])
        assert set(display) <= allowed, cls
        for key in ("Topic", "Description Topic"):
            if key in display:
                assert set(display[key]) <= RVIZ_TOPIC_KEYS
                assert {display[key][k] for k in display[key] if "Policy" in k} <= (
                    RVIZ_POLICY_VALUES
                )
    assert {"rviz_default_plugins/RobotModel", "rviz_default_plugins/Image"} <= classes
    robot_model = next(
        d for d in manager["Displays"] if d["Class"] == "rviz_default_plugins/RobotModel"
    )
    assert robot_model["Description Source"] == "Topic"
    assert robot_model["Description Topic"]["Durability Policy"] == "Transient Local"
