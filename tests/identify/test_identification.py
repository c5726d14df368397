"""Identification from text, its cache, and UI configurations for a team."""

from __future__ import annotations

from solver.core.team import load_team
from solver.identify import (
    IdentificationCache,
    Topic,
    TopicSource,
    combinations,
    content_key,
    identification_data,
    identify_urdf,
    load_profile,
)
from solver.solving.solution import solve
from tests.conftest import TEAMS
from tests.identify import builders

LASER = builders.gazebo_sensor("laser", "ray", "laser")
CAMERA = builders.gazebo_sensor("cam", "camera", "cam")


def rover_text() -> str:
    robot = builders.ugv()
    robot.add(LASER)
    robot.add(CAMERA)
    robot.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    return robot.text()


def test_the_cache_answers_the_same_content_without_identifying_again() -> None:
    cache = IdentificationCache(maxsize=2)
    first = cache.identify_urdf(rover_text())
    again = cache.identify_urdf(rover_text().encode("utf-8"))
    assert again is first
    assert (cache.hits, cache.misses) == (1, 1)
    cache.identify_urdf(builders.quadrotor().text())
    cache.identify_urdf(builders.manipulator().text())
    assert len(cache) == 2


def test_the_content_key_changes_with_every_input() -> None:
    text = rover_text()
    topics = [TopicSource("master", (Topic("/cmd_vel", "geometry_msgs/Twist"),))]
    keys = {
        content_key(text),
        content_key(text + " "),
        content_key(text, srdf_text="<robot/>"),
        content_key(text, topics=topics),
        content_key(text, profile=load_profile()),
    }
    assert len(keys) == 5


def test_topics_confirm_the_waypoint_a_description_can_only_guess() -> None:
    topics = [
        TopicSource(
            "live",
            (
                Topic("/move_base/goal", "move_base_msgs/MoveBaseActionGoal"),
                Topic("/scan", "sensor_msgs/LaserScan", "published"),
            ),
        )
    ]
    result = identify_urdf(rover_text(), topics=topics)
    assert [(c.motion_control, c.source) for c in result.motion_controls] == [
        ("Driving", "urdf: drive plugin libgazebo_ros_diff_drive.so"),
        (
            "Waypoint",
            "urdf: likely, not declared: Driving and a lidar sensor, what navigation needs; "
            "live: /move_base/goal (move_base_msgs/MoveBaseActionGoal)",
        ),
    ]
    lidar = result.sensors[0]
    assert (lidar.kind, lidar.count, lidar.source) == ("lidar", 1, "urdf: laser; live: /scan")


def test_a_ugv_gets_a_ui_configuration_per_control_and_sensor_type() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    result = identify_urdf(rover_text())
    found = combinations(result, solution, load_profile())
    # Driven by its plugin; Waypoint guessed from the drive and the lidar.
    assert [dict(c.values) for c in found] == [
        {
            "kinematic_type": "UGV",
            "motion_control": control,
            "sensor_type": sensor,
            "sensor_count": "2",
        }
        for control in ("Driving", "Waypoint")
        for sensor in ("LIDAR", "2D Camera")
    ]
    numbers = [c.assignment.number for c in found]
    assert all(not c.assignment.is_default for c in found)
    assert len(set(numbers)) == 4  # each control and each sensor type presented differently


def test_a_quadruped_gets_the_default_configuration_with_the_reason() -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))
    robot = builders.quadruped()
    robot.add(CAMERA)
    found = combinations(identify_urdf(robot.text()), solution, load_profile())
    assignment = found[0].assignment
    assert assignment.is_default
    assert assignment.number == solution.default_configuration
    assert any("unknown robot kinematic type 'Quadruped'" in r for r in assignment.reasons)


def test_the_json_contract_has_exactly_the_documented_keys() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    result = identify_urdf(rover_text(), file="rover.urdf")
    data = identification_data(result, combinations(result, solution, load_profile()), solution)
    assert list(data) == [
        "robot",
        "file",
        "structure",
        "kinematic_type",
        "confidence",
        "evidence",
        "roles",
        "sensors",
        "motion_controls",
        "combinations",
    ]
    assert list(data["roles"][0]) == ["joint", "role", "evidence"]
    assert list(data["sensors"][0]) == ["kind", "sensor_type", "count", "source"]
    assert list(data["motion_controls"][0]) == ["motion_control", "source"]
    assert (
        data["combinations"][0]["configuration"]
        == combinations(result, solution, load_profile())[0].assignment.number
    )
