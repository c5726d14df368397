"""The team layout: a follower panel beside a Tab panel, a tab per (robot, configuration), each
tab that robot's layout, and the whole passing the viewer's rules with each tab a screen."""

from __future__ import annotations

import json
from typing import Any

import pytest

from solver.core.team import load_team
from solver.layouts import LayoutError, Robot, foxglove_layout, load_presentation
from solver.layouts.checks import check_lichtblick
from solver.layouts.team import (
    FOLLOWER_ID,
    TABS_ID,
    TeamTab,
    tab_title,
    team_layout,
)
from solver.solving.assignment import assign
from solver.solving.solution import Solution, solve
from tests.conftest import TEAMS

ANSWERS = "/teleop_ui/ui_configuration"


@pytest.fixture(scope="module")
def solution() -> Solution:
    return solve(load_team(TEAMS / "case3.yaml"))


def _robot(solution: Solution, namespace: str, **values: str) -> TeamTab:
    """A robot's tab: its layout of the configuration ``assign`` gives ``values``."""
    assignment = assign(solution, values)
    layout = foxglove_layout(
        solution,
        assignment.configuration,
        load_presentation(),
        robot=Robot(namespace, described=True),
    )
    title = tab_title(namespace, assignment.number, list(values.values()), default=False)
    return TeamTab(namespace, assignment.number, title, layout)


@pytest.fixture(scope="module")
def tabs(solution: Solution) -> list[TeamTab]:
    drone = {"kinematic_type": "UAV", "sensor_type": "2D Camera", "sensor_count": "1"}
    rover = {"kinematic_type": "UGV", "sensor_type": "LIDAR", "sensor_count": "1"}
    return [
        _robot(solution, "/uav1", **drone, motion_control="Flight"),
        _robot(solution, "/ugv1", **rover, motion_control="Driving"),
        _robot(solution, "/ugv1", **rover, motion_control="Waypoint"),
    ]


def _leaves(node: Any) -> list[str]:
    if isinstance(node, str):
        return [node]
    return [*_leaves(node["first"]), *_leaves(node["second"])]


def test_the_follower_sits_beside_a_tab_panel_holding_each_robots_configuration(
    solution: Solution, tabs: list[TeamTab]
) -> None:
    layout = team_layout(tabs, answer_topic=ANSWERS, answer_url="http://127.0.0.1:8770/x")
    assert layout["layout"] == {
        "direction": "row",
        "first": "teleop-ui.follower!follower",
        "second": "Tab!robots",
        "splitPercentage": 15,
    }
    assert layout["configById"][FOLLOWER_ID] == {
        "answerUrl": "http://127.0.0.1:8770/x",
        "answerTopic": ANSWERS,
        "tabs": [
            {"robot": tab.robot, "configuration": tab.configuration, "tab": index}
            for index, tab in enumerate(tabs)
        ],
        "defaultTab": None,
    }
    shown = layout["configById"][TABS_ID]
    assert shown["activeTabIdx"] == 0
    assert [tab["title"] for tab in shown["tabs"]] == [tab.title for tab in tabs]
    # Each tab holds its robot's panels, configs unchanged, ids renamed to be unique.
    for index, (tab, entry) in enumerate(zip(tabs, shown["tabs"], strict=True)):
        ids = _leaves(entry["layout"])
        assert all(f"!t{index + 1}-" in panel for panel in ids)
        own = tab.layout["configById"]
        assert [layout["configById"][panel] for panel in ids] == [
            own[p] for p in _leaves(tab.layout["layout"])
        ]


def test_the_team_layout_keeps_every_rule_of_the_viewer_each_tab_a_screen(
    tabs: list[TeamTab],
) -> None:
    layout = team_layout(tabs, answer_topic=ANSWERS)
    # Each tab's publishers lie in its own robot's namespace (each tab checked as a screen:
    # tests/layouts/checks/test_lichtblick.py).
    assert check_lichtblick(json.loads(json.dumps(layout)), "team.json") == ()


def test_a_team_without_robots_has_one_tab_that_says_so() -> None:
    layout = team_layout([], answer_topic=ANSWERS)
    (tab,) = layout["configById"][TABS_ID]["tabs"]
    assert tab == {"title": "no robot yet: import this layout again once robots are on the graph"}
    assert layout["configById"][FOLLOWER_ID]["tabs"] == []
    assert check_lichtblick(layout, "team.json") == ()


def test_two_tabs_for_one_robots_configuration_are_refused(tabs: list[TeamTab]) -> None:
    with pytest.raises(LayoutError) as refused:
        team_layout([tabs[0], tabs[0]], answer_topic=ANSWERS, file="team.json")
    (fault,) = refused.value.faults
    assert fault.location.path == f"configById.{FOLLOWER_ID}.tabs"
    assert "two tabs" in fault.message


def test_a_tab_title_names_the_robot_the_configuration_and_its_values() -> None:
    assert tab_title("/uav1", 3, ["UAV", "Flight"], default=False) == "/uav1: 3 (UAV, Flight)"
    assert tab_title("/ugv1", 103, ["UGV", "Flight"], default=True) == (
        "/ugv1: 103 (default) (UGV, Flight)"
    )


def test_a_robots_sensor_clusters_stay_tab_panels_inside_its_tab(solution: Solution) -> None:
    # A UGV of 6..10 cameras: its layout (a template: the most its configuration serves, 10)
    # groups them in clusters of 2, Tab panels inside its tab.
    rover = {"kinematic_type": "UGV", "sensor_type": "2D Camera", "sensor_count": "8"}
    tab = _robot(solution, "/ugv2", **rover, motion_control="Driving")
    layout = team_layout([tab], answer_topic=ANSWERS)
    configs = layout["configById"]
    clusters = sorted(key for key in configs if key.startswith("Tab!t1-"))
    assert clusters == [f"Tab!t1-c0{n}" for n in range(1, 6)]
    # Each cluster's tabs name the renamed panels, which are in configById.
    inside = [tab["layout"] for key in clusters for tab in configs[key]["tabs"]]
    assert inside == [f"Image!t1-p{n:02d}" for n in range(2, 12)]  # p01: the Driving pad
    assert all(panel in configs for panel in inside)
    assert check_lichtblick(json.loads(json.dumps(layout))) == ()
