"""Foxglove / Lichtblick layouts: one per configuration, valid, tiled, deterministic."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from solver import load_team, solve
from solver.layouts import (
    JointStart,
    LayoutError,
    Robot,
    foxglove_layout,
    layout_filename,
    load_presentation,
    validate_foxglove,
    write_layouts,
)
from solver.layouts.foxglove import TAB_TITLE_CHARS, short_title
from solver.layouts.plan import plan_layout


def test_layouts_writes_one_file_per_configuration_plus_the_default(tmp_path: Path) -> None:
    solution = solve(load_team("case1"))
    paths = write_layouts(solution, load_presentation(), tmp_path)
    assert [path.name for path in paths] == [
        "config-001.json",
        "config-002.json",
        "config-003.json",
        "config-004.json",
        "config-005.json",
        "config-006.json",
        "config-007-default.json",
    ]
    for path in paths:
        validate_foxglove(json.loads(path.read_text()), path.name)


def test_layouts_are_the_same_bytes_on_every_run(tmp_path: Path) -> None:
    solution = solve(load_team("case3"))
    first = write_layouts(solution, load_presentation(), tmp_path / "a")
    second = write_layouts(solution, load_presentation(), tmp_path / "b")
    assert [p.read_bytes() for p in first] == [p.read_bytes() for p in second]


def test_sensor_clusters_become_tab_panels_of_a_panel_per_sensor() -> None:
    solution = solve(load_team("case2"))
    # A UGV with 6..10 sensors in clusters of 2 shows its 10 sensors in ceil(10/2) = 5
    # clusters (Equation (2)): 5 Tab panels of 2 tabs each, one 3D panel per sensor.
    configuration = next(
        c
        for c in solution.configurations
        if c.kinematic_type == "UGV"
        and c.components[3].name != "individual"
        and c.components[2].name == "point cloud"
    )
    layout = foxglove_layout(solution, configuration, load_presentation())
    configs = layout["configById"]
    assert sum(1 for key in configs if key.startswith("3D!")) == 10
    tabs = [configs[key]["tabs"] for key in sorted(configs) if key.startswith("Tab!")]
    # A tab is titled with the sensor's short name (its topic's first part, its number);
    # the panel in it names the component and the whole topic.
    assert [[tab["title"] for tab in cluster] for cluster in tabs] == [
        ["points 1", "points 2"],
        ["points 3", "points 4"],
        ["points 5", "points 6"],
        ["points 7", "points 8"],
        ["points 9", "points 10"],
    ]
    first = configs[tabs[0][0]["layout"]]
    assert first["lichtblickPanelTitle"] == "point cloud 1 \u00b7 /points"
    topics = [configs[tab["layout"]]["topics"] for cluster in tabs for tab in cluster]
    assert list(topics[0]) == ["/points"]
    assert list(topics[9]) == ["/points_10"]


def test_a_template_names_full_topics_in_the_root_namespace() -> None:
    solution = solve(load_team("case1"))
    layout = foxglove_layout(solution, solution.configurations[0], load_presentation())
    teleop = layout["configById"]["Teleop!p01"]
    assert teleop["topic"] == "/cmd_vel"
    assert teleop["foxglovePanelTitle"] == "Flight \u00b7 /cmd_vel"
    assert layout["globalVariables"]["teleop_ui_layout"] == (
        "teleop-ui: UI configuration 1, topics in the root namespace (/cmd_vel); for a robot "
        "under /NAME: teleop-ui layouts TEAM -o DIR --namespace /NAME"
    )


def test_a_layout_for_a_namespace_puts_every_topic_and_click_tool_under_it() -> None:
    solution = solve(load_team("case1"))
    layout = foxglove_layout(
        solution, solution.configurations[0], load_presentation(), robot=Robot("/uav1")
    )
    configs = layout["configById"]
    assert configs["Teleop!p01"]["topic"] == "/uav1/cmd_vel"
    assert configs["Image!p02"]["imageMode"]["imageTopic"] == "/uav1/camera/image_raw"
    assert configs["Image!p02"]["publish"] == {
        "type": "point",
        "poseTopic": "/uav1/clicked_pose",
        "pointTopic": "/uav1/clicked_point",
        "poseEstimateTopic": "/uav1/initialpose",
        "poseEstimateXDeviation": 0.5,
        "poseEstimateYDeviation": 0.5,
        "poseEstimateThetaDeviation": 0.26179939,
    }


def test_three_velocity_components_on_one_topic_share_one_teleop_pad() -> None:
    solution = solve(load_team("case3"))
    layout = foxglove_layout(solution, None, load_presentation())
    pads = [c for key, c in layout["configById"].items() if key.startswith("Teleop!")]
    assert [(pad["topic"], pad["foxglovePanelTitle"]) for pad in pads] == [
        ("/cmd_vel", "Flight, Driving, Walking \u00b7 /cmd_vel")
    ]


def test_audio_gets_a_placeholder_panel_showing_its_topic_not_a_silent_drop() -> None:
    solution = solve(load_team("case2"))
    audio = next(c for c in solution.configurations if c.components[2].name == "audio")
    layout = foxglove_layout(solution, audio, load_presentation())
    raw = [c for key, c in layout["configById"].items() if key.startswith("RawMessages!")]
    # A Raw Messages panel shows its topic path where a title would be: it gets no title.
    # Five microphones, one tile each; tiles after the first are named _2, _3, ...
    assert [(c["topicPath"], "foxglovePanelTitle" in c) for c in raw] == [
        ("/audio", False),
        ("/audio_2", False),
        ("/audio_3", False),
        ("/audio_4", False),
        ("/audio_5", False),
    ]


def test_a_joint_command_without_the_robots_joints_is_no_publish_button() -> None:
    solution = solve(load_team("case3"))
    layout = foxglove_layout(solution, None, load_presentation())
    assert not any(key.startswith("Publish!") for key in layout["configById"])
    joint = layout["configById"]["Indicator!p01"]
    assert joint["path"] == "/joint_trajectory"
    assert joint["foxglovePanelTitle"] == (
        "Joint \u00b7 /joint_trajectory (no Publish button: the robot's joint names are not known)"
    )


def test_a_joint_command_holds_a_whole_trajectory_of_the_robots_joints() -> None:
    solution = solve(load_team("case3"))
    joints = (JointStart("shoulder", 0.0), JointStart("gripper", 0.01))
    layout = foxglove_layout(
        solution, None, load_presentation(), robot=Robot("/arm", joints=joints)
    )
    publish = layout["configById"]["Publish!p01"]
    assert publish["topicName"] == "/arm/joint_trajectory"
    assert json.loads(publish["value"]) == {
        "header": {"stamp": {"sec": 0, "nsec": 0}, "frame_id": ""},
        "joint_names": ["shoulder", "gripper"],
        "points": [
            {
                "positions": [0.0, 0.01],
                "velocities": [],
                "accelerations": [],
                "effort": [],
                "time_from_start": {"sec": 5, "nsec": 0},
            }
        ],
    }


def test_validation_reports_orphan_configs_and_bad_splits() -> None:
    layout = {
        "configById": {"Image!a": {}, "Image!b": {}, "Nope!c": {}},
        "layout": {
            "direction": "row",
            "first": "Image!a",
            "second": "Nope!c",
            "splitPercentage": 140,
        },
    }
    with pytest.raises(LayoutError) as caught:
        validate_foxglove(layout, "x.json")
    message = str(caught.value)
    assert "orphan config" in message
    assert "0..100" in message
    assert "unknown panel type" in message


def test_layout_filename_marks_the_default_configuration() -> None:
    assert layout_filename(7, default=True) == "config-007-default.json"


def test_rviz_layouts_load_as_yaml_with_every_display_key(tmp_path: Path) -> None:
    import yaml

    from solver.layouts.rviz import REQUIRED_KEYS

    paths = write_layouts(solve(load_team("case2")), load_presentation(), tmp_path, "rviz")
    assert paths[-1].name == "config-019-default.rviz"
    for path in paths:
        displays = yaml.safe_load(path.read_text())["Visualization Manager"]["Displays"]
        assert all(key in display for display in displays for key in REQUIRED_KEYS)


def test_rviz_robot_description_is_transient_local_and_sensors_best_effort() -> None:
    from solver.layouts import rviz_layout

    solution = solve(load_team("case1"))
    displays = rviz_layout(solution, solution.configurations[0], load_presentation())[
        "Visualization Manager"
    ]["Displays"]
    model = next(d for d in displays if d["Name"] == "RobotModel")
    assert model["Description Topic"]["Durability Policy"] == "Transient Local"
    image = next(d for d in displays if d["Class"] == "rviz_default_plugins/Image")
    assert image["Topic"]["Reliability Policy"] == "Best Effort"


def test_rviz_gives_velocity_control_a_placeholder_that_subscribes_to_nothing() -> None:
    from solver.layouts import rviz_layout

    solution = solve(load_team("case1"))
    displays = rviz_layout(solution, solution.configurations[0], load_presentation())[
        "Visualization Manager"
    ]["Displays"]
    flight = next(d for d in displays if d["Name"].startswith("Flight"))
    assert flight == {
        "Class": "rviz_common/Group",
        "Displays": [],
        "Enabled": False,
        "Name": "Flight: cmd_vel (placeholder: no RViz2 display for this component)",
    }


def test_a_component_the_presentation_omits_is_a_panel_whose_title_says_it_is_a_placeholder() -> (
    None
):
    # search-and-rescue's autonomy levels and environment gauges: as Raw Messages panels the
    # app showed only "/robot1/teleoperated", in red (no robot has such a topic).
    solution = solve(load_team("search-and-rescue"))
    configs = foxglove_layout(solution, None, load_presentation())["configById"]
    shown = {
        config["lichtblickPanelTitle"]: (config["path"], config["fallbackLabel"])
        for key, config in configs.items()
        if key.startswith("Indicator!") and "placeholder" in config["lichtblickPanelTitle"]
    }
    assert shown == {
        f"{name} \u00b7 /{topic} (placeholder: no panel for this component)": (
            f"/{topic}",
            "no panel",
        )
        for name, topic in [
            ("environment gauges", "environment_gauges"),
            ("teleoperated", "teleoperated"),
            ("shared", "shared"),
            ("supervisory", "supervisory"),
        ]
    }


def test_plot_series_are_labelled_so_a_narrow_legend_tells_them_apart() -> None:
    solution = solve(load_team("case3"))
    plot = foxglove_layout(solution, None, load_presentation())["configById"]["Plot!p08"]
    assert [(s["label"], s["value"]) for s in plot["paths"]] == [
        ("force x", "/wrench.wrench.force.x"),
        ("force y", "/wrench.wrench.force.y"),
        ("force z", "/wrench.wrench.force.z"),
    ]


def test_titles_name_the_component_and_the_topic_and_tabs_the_sensors_short_name() -> None:
    solution = solve(load_team("case2"))
    configuration = solution.configurations[7]  # UGV, Driving, 6..10 cameras, clusters of 2
    layout = foxglove_layout(solution, configuration, load_presentation(), robot=Robot("/uav1"))
    configs = layout["configById"]
    assert configs["Image!p02"]["lichtblickPanelTitle"] == (
        "visual display 1 \u00b7 /uav1/camera/image_raw"
    )
    assert configs["Image!p02"]["foxglovePanelTitle"] == (
        "visual display 1 \u00b7 /uav1/camera/image_raw"
    )
    assert [tab["title"] for tab in configs["Tab!c05"]["tabs"]] == ["camera 9", "camera 10"]


def test_a_tab_title_longer_than_a_tab_shows_is_cut_before_its_number() -> None:
    solution = solve(load_team("case2"))
    plan = plan_layout(solution, solution.configurations[7], load_presentation(), Robot("/uav1"))
    panel = replace(plan.panels[1], name="visual display 3", topic="/uav1/forward_stereo_left_3")
    assert short_title(panel, plan) == "forward_s\u2026 3"
    assert len(short_title(panel, plan)) == TAB_TITLE_CHARS
