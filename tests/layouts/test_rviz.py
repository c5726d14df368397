"""RViz2 files: displays by the topic's real type, the goal tool where the UI takes goals, the
robot description and the template's re-targeting."""

from __future__ import annotations

from typing import Any

import yaml

from solver import load_team, solve
from solver.core.partition import Configuration
from solver.layouts import Robot, load_presentation, rviz_layout
from solver.layouts.plan import plan_layout
from solver.layouts.rviz import plan_rviz, rviz_note, rviz_text
from solver.ros.names import Topic
from solver.solving.solution import Solution


def _configuration(solution: Solution, *names: str) -> Configuration:
    return next(c for c in solution.configurations if set(names) <= {x.name for x in c.components})


def _goal_tools(document: dict[str, Any]) -> list[str]:
    tools = document["Visualization Manager"]["Tools"]
    return [t["Topic"]["Value"] for t in tools if t["Class"] == "rviz_default_plugins/SetGoal"]


def test_the_goal_tool_publishes_on_the_configurations_goal_topic_or_is_not_there() -> None:
    solution = solve(load_team("case3"))
    presentation = load_presentation()

    def goals(configuration: Configuration | None) -> list[str]:
        return _goal_tools(rviz_layout(solution, configuration, presentation))

    assert goals(_configuration(solution, "Waypoint")) == ["goal_pose"]
    assert goals(_configuration(solution, "End Effector")) == ["ee_goal_pose"]
    assert goals(_configuration(solution, "Driving")) == []
    # The default configuration has both: a navigation goal, as RViz2's tool means.
    assert goals(None) == ["goal_pose"]


def test_a_laser_scan_topic_gets_a_laser_scan_display() -> None:
    solution = solve(load_team("case2"))
    configuration = _configuration(solution, "Driving", "point cloud")
    robot = Robot("/dd", {("point cloud", 0): Topic("/dd/scan", "sensor_msgs/msg/LaserScan")})
    document = rviz_layout(solution, configuration, load_presentation(), robot=robot, tile_count=1)
    shown = {
        d["Topic"]["Value"]: d["Class"]
        for d in document["Visualization Manager"]["Displays"]
        if "Topic" in d
    }
    assert shown["/dd/scan"] == "rviz_default_plugins/LaserScan"


def test_the_robot_description_is_read_in_the_robots_namespace() -> None:
    solution = solve(load_team("case1"))

    def description(robot: Robot | None) -> str:
        displays = rviz_layout(solution, None, load_presentation(), robot=robot)[
            "Visualization Manager"
        ]["Displays"]
        model = next(d for d in displays if d["Class"] == "rviz_default_plugins/RobotModel")
        return str(model["Description Topic"]["Value"])

    assert description(None) == "robot_description"
    assert description(Robot("/uav1")) == "/uav1/robot_description"


def test_a_template_says_in_its_first_lines_how_to_open_it_for_a_robot() -> None:
    solution = solve(load_team("case1"))
    plan = plan_layout(solution, None, load_presentation(), relative=True)
    text = rviz_text(plan_rviz(plan), rviz_note(plan))
    assert text.startswith(
        "# teleop-ui: UI configuration 7 (the default). Topics are relative to RViz2's own "
        "namespace; for a robot under /robot1:\n"
        "#   rviz2 -d FILE --ros-args -r __ns:=/robot1\n"
        "Panels:\n"
    )
    assert yaml.safe_load(text)["Window Geometry"]["Hide Left Dock"] is False


def test_a_file_for_a_namespace_says_whom_it_is_for() -> None:
    solution = solve(load_team("case1"))
    plan = plan_layout(solution, solution.configurations[0], load_presentation(), Robot("/uav1"))
    assert rviz_note(plan) == "teleop-ui: UI configuration 1, for the robot under /uav1."
