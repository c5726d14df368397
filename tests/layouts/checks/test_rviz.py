"""RViz2 documents against ``rviz2.yaml`` (read from RViz2's sources): one broken rule at a time."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from solver.layouts.checks import check_rviz
from solver.layouts.checks.rviz import robot_namespace

QOS = {
    "Depth": 5,
    "Durability Policy": "Volatile",
    "History Policy": "Keep Last",
    "Reliability Policy": "Reliable",
}
TYPES = {
    "/robot1/scan": ["sensor_msgs/msg/LaserScan"],
    "/robot1/camera/image_raw/compressed": ["sensor_msgs/msg/CompressedImage"],
    "/robot1/cmd_vel": ["geometry_msgs/msg/Twist"],
}


def _display(cls: str, name: str, topic: str | None = None, **more: object) -> dict[str, Any]:
    display: dict[str, Any] = {"Class": f"rviz_default_plugins/{cls}", "Enabled": True}
    display.update(Name=name, Value=True, **more)
    if topic is not None:
        display["Topic"] = {**QOS, "Value": topic}
    return display


def _clean() -> dict[str, Any]:
    """A file as RViz2 saves one (its sections and keys), for robot /robot1."""
    return {
        "Panels": [{"Class": "rviz_common/Displays", "Name": "Displays"}],
        "Visualization Manager": {
            "Class": "",
            "Displays": [
                _display("Grid", "Grid", None, **{"Cell Size": 1, "Plane": "XY"}),
                _display(
                    "RobotModel",
                    "RobotModel",
                    None,
                    **{
                        "Description Source": "Topic",
                        "Description Topic": {
                            **QOS,
                            "Durability Policy": "Transient Local",
                            "Value": "/robot1/robot_description",
                        },
                    },
                ),
                _display("LaserScan", "scan", "/robot1/scan", **{"Size (m)": 0.05}),
                _display("Image", "camera", "/robot1/camera/image_raw/compressed"),
            ],
            "Enabled": True,
            "Global Options": {"Fixed Frame": "base_link", "Frame Rate": 30},
            "Name": "root",
            "Tools": [
                {"Class": "rviz_default_plugins/Interact"},
                {
                    "Class": "rviz_default_plugins/SetGoal",
                    "Topic": {**QOS, "Value": "/robot1/goal_pose"},
                },
            ],
            "Value": True,
            "Views": {"Current": {"Class": "rviz_default_plugins/Orbit", "Name": "Current View"}},
        },
        "Window Geometry": {
            "Height": 800,
            "Width": 1200,
            "Hide Left Dock": False,
            "Hide Right Dock": True,
        },
    }


def _codes(document: Any, **kwargs: Any) -> dict[str, list[str]]:
    found: dict[str, list[str]] = {}
    for fault in check_rviz(
        document, topic_types=TYPES, pose_topics=["/robot1/goal_pose"], **kwargs
    ):
        found.setdefault(fault.code, []).append(fault.location.path)
    return found


def test_a_file_that_keeps_every_rule_has_no_fault() -> None:
    assert _codes(_clean()) == {}
    assert robot_namespace(_clean()) == "/robot1"


def test_a_file_without_window_geometry_is_named() -> None:
    document = _clean()
    del document["Window Geometry"]
    assert _codes(document) == {"rviz-file": ["Window Geometry"]}


def test_window_geometry_without_the_dock_flags_is_named() -> None:
    document = _clean()
    del document["Window Geometry"]["Hide Left Dock"]
    assert _codes(document) == {"rviz-file": ["Window Geometry.Hide Left Dock"]}


def test_a_display_class_rviz2_lacks_is_named() -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"].append(_display("Audio", "audio", "/robot1/a"))
    assert _codes(document) == {"rviz-display": ["Visualization Manager.Displays[4].Class"]}


def test_a_property_the_display_lacks_is_named() -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"][2]["Colour"] = "red"
    assert _codes(document) == {"rviz-display": ["Visualization Manager.Displays[2].Colour"]}


def test_a_laser_scan_shown_as_a_point_cloud_is_named() -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"][2]["Class"] = "rviz_default_plugins/PointCloud2"
    assert _codes(document) == {"rviz-display-type": ["Visualization Manager.Displays[2].Class"]}


def test_a_disabled_placeholder_on_another_type_is_named_too() -> None:
    document = _clean()
    placeholder = _display("Marker", "cmd_vel (placeholder)", "/robot1/cmd_vel")
    placeholder.update(Enabled=False, Value=False)
    document["Visualization Manager"]["Displays"].append(placeholder)
    (fault,) = check_rviz(document, topic_types=TYPES)
    assert fault.code == "rviz-display-type"
    assert fault.message.endswith("(disabled: enabling it subscribes with the wrong type)")


def test_a_compressed_image_needs_its_transport_in_the_topic_name() -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"][3]["Topic"]["Value"] = "/robot1/camera/jpeg"
    types = {**TYPES, "/robot1/camera/jpeg": ["sensor_msgs/msg/CompressedImage"]}
    codes = {f.code for f in check_rviz(document, topic_types=types)}
    assert codes == {"rviz-display-type"}


@pytest.mark.parametrize("topic", ["<robot>/scan", "/robot1//scan", "/robot1/9scan"])
def test_a_topic_that_is_no_ros_name_is_named(topic: str) -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"][2]["Topic"]["Value"] = topic
    found = _codes(document)
    assert found["ros-topic-name"] == ["Visualization Manager.Displays[2].Topic.Value"]


def test_relative_names_are_ros_names_rviz2_expands_in_its_own_namespace() -> None:
    document = _clean()
    manager = document["Visualization Manager"]
    manager["Displays"][1]["Description Topic"]["Value"] = "robot_description"
    manager["Displays"][2]["Topic"]["Value"] = "scan"
    manager["Displays"][3]["Topic"]["Value"] = "camera/image_raw/compressed"
    manager["Tools"][1]["Topic"]["Value"] = "goal_pose"
    assert check_rviz(document) == ()
    assert robot_namespace(document) is None


def test_an_unknown_qos_value_is_named() -> None:
    document = _clean()
    document["Visualization Manager"]["Displays"][2]["Topic"]["Reliability Policy"] = "Sometimes"
    found = _codes(document)
    assert found == {"rviz-display": ["Visualization Manager.Displays[2].Topic.Reliability Policy"]}


def test_a_goal_tool_on_another_topic_than_the_pose_component_is_named() -> None:
    document = _clean()
    found = {
        f.code: f.message
        for f in check_rviz(document, topic_types=TYPES, pose_topics=["/robot1/ee_goal_pose"])
    }
    assert found == {
        "rviz-tool": "publishes goals on '/robot1/goal_pose'; the configuration's pose "
        "component takes them on '/robot1/ee_goal_pose'"
    }


def test_a_goal_tool_where_the_configuration_has_no_pose_component_is_named() -> None:
    faults = check_rviz(_clean(), topic_types=TYPES, pose_topics=[])
    assert [f.code for f in faults] == ["rviz-tool"]


def test_an_unknown_tool_and_view_are_named() -> None:
    document = _clean()
    document["Visualization Manager"]["Tools"].append({"Class": "nav2_rviz_plugins/GoalTool"})
    document["Visualization Manager"]["Views"]["Current"]["Class"] = "rviz_default_plugins/Top"
    assert _codes(document) == {
        "rviz-tool": ["Visualization Manager.Tools[2].Class"],
        "rviz-view": ["Visualization Manager.Views.Current.Class"],
    }


def test_an_absolute_description_and_tool_outside_the_namespace_are_named() -> None:
    document = copy.deepcopy(_clean())
    manager = document["Visualization Manager"]
    manager["Displays"][1]["Description Topic"]["Value"] = "/robot_description"
    manager["Tools"].append(
        {"Class": "rviz_default_plugins/PublishPoint", "Topic": {**QOS, "Value": "/clicked_point"}}
    )
    assert _codes(document) == {
        "namespace": [
            "Visualization Manager.Tools[2].Topic",
            "Visualization Manager.Displays[1].Description Topic.Value",
        ]
    }


def test_displays_inside_a_group_are_checked() -> None:
    document = _clean()
    group = {
        "Class": "rviz_common/Group",
        "Enabled": True,
        "Name": "sensors",
        "Displays": [_display("PointCloud2", "scan", "/robot1/scan")],
    }
    document["Visualization Manager"]["Displays"].append(group)
    found = _codes(document)
    assert found == {"rviz-display-type": ["Visualization Manager.Displays[4].Displays[0].Class"]}
