"""Lichtblick layouts against ``lichtblick.yaml``, and the rules against the real app's own output.

The app's exports (``data/app``, see its README) are the oracle: what the app adds to a layout
on opening is exactly what the checks call missing, and what the app writes itself breaks no
type rule.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import pytest

from solver.layouts.checks import check_lichtblick
from solver.layouts.checks.data import lichtblick_rules
from solver.layouts.checks.lichtblick import robot_namespace

APP = Path(__file__).parent / "data" / "app"
POINTS = {"/robot1/points": ["sensor_msgs/msg/PointCloud2"]}
SCAN = {"/diff_drive_lidar/scan": ["sensor_msgs/msg/LaserScan"]}
JOINTS = {
    "header": {"stamp": {"sec": 0, "nsec": 0}, "frame_id": ""},
    "joint_names": ["shoulder", "elbow"],
    "points": [
        {
            "positions": [0.0, 0.5],
            "velocities": [],
            "accelerations": [],
            "effort": [],
            "time_from_start": {"sec": 2, "nsec": 0},
        }
    ],
}


def _app(name: str, kind: str) -> dict[str, Any]:
    return json.loads((APP / f"{name}.{kind}.json").read_text(encoding="utf-8"))  # type: ignore[no-any-return]  # json gives Any


def _codes(layout: Any, **kwargs: Any) -> dict[str, list[str]]:
    found: dict[str, list[str]] = {}
    for fault in check_lichtblick(layout, **kwargs):
        found.setdefault(fault.code, []).append(fault.location.path)
    return found


def _added(before: Any, after: Any, path: str = "") -> set[str]:
    """Paths of the keys ``after`` has and ``before`` lacks."""
    if not isinstance(before, dict) or not isinstance(after, dict):
        return set()
    added: set[str] = set()
    for key, value in after.items():
        where = f"{path}.{key}" if path else key
        added |= {where} if key not in before else _added(before[key], value, where)
    return added


@pytest.mark.parametrize(
    ("name", "types"),
    [("case3-default-robot1", POINTS), ("diff_drive_lidar-scan", SCAN), ("empty-panels", {})],
)
def test_what_the_app_adds_on_opening_is_what_the_checks_call_missing(
    name: str, types: dict[str, list[str]]
) -> None:
    imported, exported = _app(name, "imported"), _app(name, "exported")
    added = _added(imported, exported)
    # The app saves a point cloud's colour field, mode and map together: one fault says so.
    added = {p for p in added if ".topics." not in p or not p.endswith((".colorMode", ".colorMap"))}
    # An Image panel with no topic picks the first image topic it sees: data, not a default.
    added -= {"configById.Image!b.imageMode.imageTopic"}
    missing = set(_codes(imported, topic_types=types).get("lichtblick-modified", []))
    assert missing == added
    assert added


@pytest.mark.parametrize("name", ["case3-default-robot1", "diff_drive_lidar-scan", "empty-panels"])
def test_what_the_app_writes_itself_is_complete_and_of_the_right_types(name: str) -> None:
    codes = _codes(_app(name, "exported"), topic_types={**POINTS, **SCAN})
    for code in (
        "lichtblick-import",
        "lichtblick-tree",
        "lichtblick-config",
        "lichtblick-modified",
    ):
        assert code not in codes, codes[code]


def _clean() -> dict[str, Any]:
    """The app's own export of a layout, with what the issue asks fixed: no problem left."""
    layout = _app("case3-default-robot1", "exported")
    configs = layout["configById"]
    grid = {**lichtblick_rules()["panels"]["3D"]["grid_layer"], "instanceId": "grid"}
    for panel_id, config in configs.items():
        if panel_id.startswith(("3D!", "Image!")):
            config["publish"].update(
                pointTopic="/robot1/clicked_point", poseEstimateTopic="/robot1/initialpose"
            )
            if config["publish"]["type"] != "pose":
                config["publish"]["poseTopic"] = "/robot1/goal_pose"
        if panel_id.startswith("3D!"):
            config["layers"] = {"grid": grid}
    configs["Publish!p01"]["value"] = json.dumps(JOINTS)
    for key in ("lichtblickPanelTitle", "foxglovePanelTitle"):
        del configs["RawMessages!p09"][key]
    configs["Teleop!p03"]["topic"] = "/robot1/drive/cmd_vel"
    configs["Teleop!p04"]["topic"] = "/robot1/walk/cmd_vel"
    for series in configs["Plot!p10"]["paths"]:
        series["label"] = "force " + series["value"][-1]
    return layout


def _with_indicator(layout: dict[str, Any], label: str) -> dict[str, Any]:
    layout["configById"]["Indicator!i"] = {
        "path": "/robot1/joint_trajectory",
        "style": "bulb",
        "rules": [],
        "fallbackColor": "#a0a0a0",
        "fallbackLabel": label,
    }
    layout["layout"] = {"direction": "row", "first": layout["layout"], "second": "Indicator!i"}
    return layout


def test_a_layout_that_keeps_every_rule_has_no_fault() -> None:
    assert check_lichtblick(_clean(), topic_types=POINTS) == ()


def test_the_robot_namespace_is_what_its_own_topics_share() -> None:
    assert robot_namespace(_clean()) == "/robot1"
    assert robot_namespace(_app("diff_drive_lidar-scan", "imported")) == "/diff_drive_lidar"


def test_a_layout_that_is_no_object_is_refused_as_the_import_refuses_it() -> None:
    assert _codes([]) == {"lichtblick-import": [""]}
    broken = {"configById": {}, "globalVariables": {}, "playbackConfig": {"speed": "fast"}}
    assert _codes(broken) == {"lichtblick-import": ["playbackConfig.speed"]}


def test_the_tree_names_ids_without_config_and_configs_never_shown() -> None:
    layout = _clean()
    layout["layout"] = {"direction": "row", "first": "3D!p05", "second": "Plot!nope"}
    codes = _codes(layout, topic_types=POINTS)
    assert "layout.second" in codes["lichtblick-tree"]
    assert "configById.Teleop!p02" in codes["lichtblick-tree"]


def test_a_deep_tree_is_checked_without_recursion() -> None:
    layout = _clean()
    node: Any = "3D!p05"
    for _ in range(5000):
        node = {"direction": "row", "first": node, "second": "3D!p05"}
    layout["layout"] = node
    assert "lichtblick-tree" in _codes(layout, topic_types=POINTS)


def test_an_unknown_panel_type_is_named() -> None:
    layout = _clean()
    layout["configById"]["Audio!x"] = {}
    layout["layout"] = {"direction": "row", "first": layout["layout"], "second": "Audio!x"}
    assert _codes(layout, topic_types=POINTS) == {"lichtblick-panel-type": ["configById.Audio!x"]}


@pytest.mark.parametrize(
    ("panel", "key", "value", "where"),
    [
        ("Teleop!p02", "upButton", {"field": "forward", "value": 1}, "upButton.field"),
        ("Teleop!p02", "speed", 3, "speed"),
        ("3D!p05", "followMode", "follow-me", "followMode"),
        (
            "Plot!p10",
            "paths",
            [{"value": "/robot1/wrench.wrench.force.x", "enabled": "yes"}],
            "paths[0].enabled",
        ),
        ("Publish!p01", "advancedView", 1, "advancedView"),
    ],
)
def test_a_key_the_panel_does_not_read_or_a_value_of_another_type_is_named(
    panel: str, key: str, value: Any, where: str
) -> None:
    layout = _clean()
    layout["configById"][panel][key] = value
    codes = _codes(layout, topic_types=POINTS)
    assert codes["lichtblick-config"] == [f"configById.{panel}.{where}"]


def test_a_teleop_that_never_publishes_is_named() -> None:
    layout = _clean()
    layout["configById"]["Teleop!p02"]["publishRate"] = 0
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-config": ["configById.Teleop!p02.publishRate"]
    }


@pytest.mark.parametrize(
    ("topic", "code"),
    [
        ("<robot>/cmd_vel", "ros-topic-name"),
        ("robot1/cmd_vel", "ros-topic-name"),
        ("/robot1//cmd_vel", "ros-topic-name"),
    ],
)
def test_a_topic_that_is_no_full_ros2_name_is_named(topic: str, code: str) -> None:
    layout = _clean()
    layout["configById"]["Teleop!p02"]["topic"] = topic
    assert "configById.Teleop!p02.topic" in _codes(layout, topic_types=POINTS)[code]


@pytest.mark.parametrize(
    ("path", "code"),
    [
        ("<robot>/wrench.wrench.force.x", "lichtblick-message-path"),
        ("/robot1/wrench.wrench.", "lichtblick-message-path"),
        ("robot1/wrench.wrench.force.x", "ros-topic-name"),
    ],
)
def test_a_path_the_grammar_refuses_or_one_without_a_full_topic_is_named(
    path: str, code: str
) -> None:
    layout = _clean()
    layout["configById"]["Plot!p10"]["paths"][0]["value"] = path
    found = _codes(layout, topic_types=POINTS)
    assert found[code] == ["configById.Plot!p10.paths[0].value"]


def test_a_plot_reference_line_is_a_number_not_a_path() -> None:
    layout = _clean()
    layout["configById"]["Plot!p10"]["paths"][0]["value"] = "0.5"
    assert check_lichtblick(layout, topic_types=POINTS) == ()


def test_a_title_on_a_panel_that_draws_its_own_toolbar_is_named() -> None:
    layout = _clean()
    layout["configById"]["RawMessages!p09"]["lichtblickPanelTitle"] = "audio (placeholder)"
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-title-hidden": ["configById.RawMessages!p09.lichtblickPanelTitle"]
    }


def test_a_partial_publish_block_leaves_the_layout_modified() -> None:
    layout = _clean()
    del layout["configById"]["3D!p05"]["publish"]["poseEstimateXDeviation"]
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-modified": ["configById.3D!p05.publish.poseEstimateXDeviation"]
    }


def test_a_point_cloud_without_its_colour_field_leaves_the_layout_modified() -> None:
    layout = _clean()
    del layout["configById"]["3D!p11"]["topics"]["/robot1/points"]["colorField"]
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-modified": ["configById.3D!p11.topics./robot1/points.colorField"]
    }


def test_a_3d_panel_without_a_grid_is_named() -> None:
    layout = _clean()
    layout["configById"]["3D!p11"]["layers"] = {}
    assert _codes(layout, topic_types=POINTS) == {"lichtblick-grid": ["configById.3D!p11.layers"]}


@pytest.mark.parametrize(
    ("value", "where"),
    [
        ("{}", "value"),
        ("[1]", "value"),
        ("not json", "value"),
        ("[" * 100_000, "value"),
        (json.dumps({**JOINTS, "joint_names": [""]}), "value:joint_names"),
        (json.dumps({**JOINTS, "points": []}), "value:points"),
        (json.dumps({**JOINTS, "joint_names": ["a"]}), "value:points[0].positions"),
        (json.dumps({k: v for k, v in JOINTS.items() if k != "header"}), "value:header"),
        (json.dumps({**JOINTS, "speed": 1}), "value:speed"),
    ],
)
def test_a_publish_panel_without_a_whole_meaningful_message_is_named(
    value: str, where: str
) -> None:
    layout = _clean()
    layout["configById"]["Publish!p01"]["value"] = value
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-publish": [f"configById.Publish!p01.{where}"]
    }


def test_series_a_narrow_legend_cuts_to_the_same_name_are_named() -> None:
    # Seen in the app: /robot1/wrench.wrench.force.x, .y and .z all read
    # "/robot1/wrench.wrench.fo" in a 285 px tile.
    layout = _clean()
    for series in layout["configById"]["Plot!p10"]["paths"]:
        del series["label"]
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-plot-legend": ["configById.Plot!p10.paths[1]", "configById.Plot!p10.paths[2]"]
    }


def test_an_indicator_label_line_a_tile_cannot_show_is_named() -> None:
    # Seen in the app: a 72-character label, never wrapped, with both ends cut.
    long = "joint commands name the robot's joints: teleop-ui layouts --robot URDF"
    assert _codes(_with_indicator(_clean(), long), topic_types=POINTS) == {
        "lichtblick-label-cut": ["configById.Indicator!i.fallbackLabel"]
    }
    short = "no joint names:\nteleop-ui layouts\n--robot URDF"
    assert check_lichtblick(_with_indicator(_clean(), short), topic_types=POINTS) == ()


def test_two_teleop_pads_on_one_topic_are_named() -> None:
    layout = _clean()
    layout["configById"]["Teleop!p04"]["topic"] = "/robot1/cmd_vel"
    assert _codes(layout, topic_types=POINTS) == {
        "lichtblick-teleop-topic": ["configById.Teleop!p04.topic"]
    }


def test_the_apps_default_click_topics_are_publishers_outside_the_namespace() -> None:
    layout = _clean()
    del layout["configById"]["3D!p11"]["publish"]
    codes = _codes(layout, namespace="/robot1", topic_types=POINTS)
    assert codes["namespace"] == [
        "configById.3D!p11.publish.poseTopic",
        "configById.3D!p11.publish.pointTopic",
        "configById.3D!p11.publish.poseEstimateTopic",
    ]
    message = next(f.message for f in check_lichtblick(layout) if f.code == "namespace")
    assert message == (
        "the panel publishes on the app's default '/move_base_simple/goal', outside the "
        "robot's namespace '/robot1'"
    )


def test_faults_show_a_strangers_key_escaped() -> None:
    layout = copy.deepcopy(_clean())
    layout["configById"]["Teleop!p02"]["\x1b[2J"] = 1
    (fault,) = check_lichtblick(layout, topic_types=POINTS)
    assert fault.location.path == "configById.Teleop!p02.\\x1b[2J"


# ---- Tab panels and this project's follower panel (issue 38) -------------------------------

FOLLOWER = "teleop-ui.follower!f"


def _tabbed(*screens: dict[str, Any], robots: tuple[str, ...] = ()) -> dict[str, Any]:
    """A layout whose Tab panel holds ``screens`` (each a layout: its configs and tree) of
    ``robots`` (by default /robot1, /robot2, ...), beside the follower, as the team layout is
    made; each screen's ids suffixed with its tab."""
    robots = robots or tuple(f"/robot{index + 1}" for index in range(len(screens)))
    configs: dict[str, Any] = {}
    tabs = []
    for index, screen in enumerate(screens):
        renamed = {key: f"{key}-{index}" for key in screen["configById"]}
        configs.update({renamed[k]: copy.deepcopy(v) for k, v in screen["configById"].items()})
        tabs.append({"title": f"tab {index}", "layout": _renamed(screen["layout"], renamed)})
    configs["Tab!t"] = {"activeTabIdx": 0, "tabs": tabs}
    configs[FOLLOWER] = {
        "answerUrl": None,
        "answerTopic": "/teleop_ui/ui_configuration",
        "tabs": [
            {"robot": robot, "configuration": index, "tab": index}
            for index, robot in enumerate(robots)
        ],
        "defaultTab": None,
    }
    return {
        "configById": configs,
        "globalVariables": {},
        "playbackConfig": {"speed": 1},
        "layout": {"direction": "row", "first": FOLLOWER, "second": "Tab!t"},
    }


def _renamed(node: Any, renamed: dict[str, str]) -> Any:
    if isinstance(node, str):
        return renamed[node]
    return {
        **node,
        "first": _renamed(node["first"], renamed),
        "second": _renamed(node["second"], renamed),
    }


def _moved(layout: dict[str, Any], old: str, new: str) -> dict[str, Any]:
    """``layout`` with every topic under ``old`` put under ``new`` (another robot's)."""
    text = json.dumps(layout).replace(f'"{old}/', f'"{new}/').replace(f'"{old}"', f'"{new}"')
    moved: dict[str, Any] = json.loads(text)
    return moved


def test_a_tab_panel_and_the_follower_beside_it_keep_every_rule() -> None:
    assert check_lichtblick(_tabbed(_clean(), _moved(_clean(), "/robot1", "/robot2"))) == ()


def test_each_tab_is_a_screen_of_its_own_robot() -> None:
    # The same robot's pads on one topic in two tabs: never on screen together, no fault.
    assert check_lichtblick(_tabbed(_clean(), _clean(), robots=("/robot1", "/robot1"))) == ()
    # Each tab's publishers in its own robot's namespace: a pad of /robot2's tab driving
    # /robot1 is outside it, though /robot1 is another tab's robot.
    second = _moved(_clean(), "/robot1", "/robot2")
    second["configById"]["Teleop!p02"]["topic"] = "/robot1/cmd_vel"
    assert _codes(_tabbed(_clean(), second)) == {"namespace": ["configById.Teleop!p02-1.topic"]}
    # Two pads on one topic in one tab still are two pads commanding one robot.
    one = _clean()
    one["configById"]["Teleop!p04"]["topic"] = "/robot1/cmd_vel"
    assert _codes(_tabbed(one, _clean(), robots=("/robot1", "/robot1"))) == {
        "lichtblick-teleop-topic": ["configById.Teleop!p04-0.topic"]
    }


def test_a_tabs_tree_is_checked_as_the_layouts_own_is() -> None:
    layout = _tabbed(_clean())
    tab = layout["configById"]["Tab!t"]["tabs"][0]
    tab["layout"] = {"direction": "row", "first": tab["layout"], "second": "Plot!nope"}
    codes = _codes(layout)
    assert codes["lichtblick-tree"] == ["configById.Tab!t.tabs[0].layout.second"]
    # A panel in no tab and no tree is never shown.
    layout = _tabbed(_clean())
    layout["configById"]["Tab!t"]["tabs"][0]["layout"] = "3D!p05-0"
    assert "configById.Teleop!p02-0" in _codes(layout)["lichtblick-tree"]


def test_a_tab_panel_inside_its_own_tab_is_named_and_not_walked_forever() -> None:
    layout = _tabbed(_clean())
    tab = layout["configById"]["Tab!t"]["tabs"][0]
    tab["layout"] = {"direction": "row", "first": tab["layout"], "second": "Tab!t"}
    (fault,) = (f for f in check_lichtblick(layout) if f.code == "lichtblick-tree")
    assert (fault.location.path, fault.message) == ("layout", "Tab!t appears twice")


@pytest.mark.parametrize(
    ("config", "code", "where"),
    [
        ({"activeTabIdx": 1, "tabs": [{"title": "a"}]}, "lichtblick-config", "activeTabIdx"),
        ({"activeTabIdx": -1, "tabs": [{"title": "a"}]}, "lichtblick-config", "activeTabIdx"),
        ({"activeTabIdx": 0.5, "tabs": [{"title": "a"}]}, "lichtblick-config", "activeTabIdx"),
        ({"activeTabIdx": 0, "tabs": [{"title": 1}]}, "lichtblick-config", "tabs[0].title"),
        (
            {"activeTabIdx": 0, "tabs": [{"title": "a", "size": 1}]},
            "lichtblick-config",
            "tabs[0].size",
        ),
        ({"tabs": [{"title": "a"}]}, "lichtblick-modified", "activeTabIdx"),
    ],
)
def test_a_tab_panel_config_the_app_would_replace_or_complete_is_named(
    config: dict[str, Any], code: str, where: str
) -> None:
    layout = {
        "configById": {"Tab!t": config},
        "globalVariables": {},
        "playbackConfig": {"speed": 1},
        "layout": "Tab!t",
    }
    assert _codes(layout) == {code: [f"configById.Tab!t.{where}"]}


def test_the_follower_needs_the_tab_panel_beside_it() -> None:
    layout = _tabbed(_clean())
    layout["layout"] = {"direction": "row", "first": FOLLOWER, "second": "3D!p05-0"}
    layout["configById"]["Tab!t"]["tabs"][0]["layout"] = "3D!p05-0"  # (others now orphans)
    assert _codes(layout)["teleop-ui-follower"] == ["layout.first"]
    alone = _tabbed(_clean())
    alone["layout"] = FOLLOWER
    assert _codes(alone)["teleop-ui-follower"] == ["layout"]


@pytest.mark.parametrize(
    ("change", "where"),
    [
        ({"tabs": [{"robot": "/robot1", "configuration": 1, "tab": 1}]}, "tabs[0].tab"),
        (
            {
                "tabs": [
                    {"robot": "/robot1", "configuration": 1, "tab": 0},
                    {"robot": "/robot1", "configuration": 1, "tab": 0},
                ]
            },
            "tabs[1]",
        ),
        ({"defaultTab": 3}, "defaultTab"),
    ],
)
def test_the_follower_maps_each_robot_configuration_to_one_tab_that_is_there(
    change: dict[str, Any], where: str
) -> None:
    layout = _tabbed(_clean())
    layout["configById"][FOLLOWER].update(change)
    assert _codes(layout) == {"teleop-ui-follower": [f"configById.{FOLLOWER}.{where}"]}


@pytest.mark.parametrize(
    ("key", "value", "code"),
    [
        ("answerUrl", 8770, "lichtblick-config"),
        ("answerTopic", "teleop_ui/ui_configuration", "ros-topic-name"),
        ("answers", [], "lichtblick-config"),
    ],
)
def test_the_followers_config_is_checked_as_a_panels_is(key: str, value: Any, code: str) -> None:
    layout = _tabbed(_clean())
    layout["configById"][FOLLOWER][key] = value
    assert _codes(layout) == {code: [f"configById.{FOLLOWER}.{key}"]}


def test_an_extension_panel_this_project_does_not_ship_is_unknown() -> None:
    layout = _tabbed(_clean())
    layout["configById"]["teleop-ui.other!x"] = layout["configById"].pop(FOLLOWER)
    layout["layout"]["first"] = "teleop-ui.other!x"
    assert _codes(layout) == {"lichtblick-panel-type": ["configById.teleop-ui.other!x"]}


def test_a_cluster_tab_is_part_of_its_robots_screen_not_a_robot_of_its_own() -> None:
    from solver import load_team, solve
    from solver.layouts import Robot, foxglove_layout, load_presentation

    solution = solve(load_team("case2"))
    # Ten cameras in clusters of 2 under /robot1: each Tab panel's tabs name only
    # /robot1/camera/... topics, and its panels' click tools publish in /robot1.
    layout = foxglove_layout(
        solution, solution.configurations[7], load_presentation(), robot=Robot("/robot1")
    )
    assert sum(key.startswith("Tab!") for key in layout["configById"]) == 5
    assert check_lichtblick(layout) == ()
    # A click tool outside the robot's namespace, inside a cluster, is still found.
    layout["configById"]["Image!p03"]["publish"]["pointTopic"] = "/clicked_point"
    (fault,) = check_lichtblick(layout)
    assert fault.code == "namespace"
    assert "outside the robot's namespace '/robot1'" in fault.message
