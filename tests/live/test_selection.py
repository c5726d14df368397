"""The operator's selection -> one combination and its configuration, and the value written back."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.live.discovery import RobotSource
from solver.live.robot import LiveRobot, identify_robot
from solver.live.selection import (
    LayoutLink,
    Request,
    choose,
    read_request,
    select,
    selection_data,
    ui_configuration_value,
)
from solver.ros.names import Topic
from solver.solving.solution import Solution
from tests.identify.builders import RobotText
from tests.live.fleet import drone_text, expected, rover_text

CAMERA = Topic("camera/image_raw", "sensor_msgs/Image", "published")
SPHERE = Topic("omni/image_raw", "sensor_msgs/Image", "published")
GOAL = Topic("move_base/goal", "move_base_msgs/MoveBaseActionGoal", "subscribed")


def robot(
    namespace: str, text: Any, topics: tuple[Topic, ...], solution: Solution, profile: Profile
) -> LiveRobot:
    source = RobotSource(namespace, f"{namespace}/robot_description", None, topics)
    return identify_robot(
        source, text, cache=IdentificationCache(), solution=solution, profile=profile
    )


NAMES = ("kinematic_type", "motion_control", "sensor_type", "sensor_count")


def test_the_request_is_read_from_the_teleop_ui_parameters() -> None:
    assert read_request(
        {
            "active_robot": "uav1/",
            "active_motion_control": "Flight",
            "ui_configuration": {"configuration": 3},
        },
        NAMES,
    ) == Request("/uav1", (("motion_control", "Flight"),))
    assert read_request({}, NAMES) == Request()
    assert read_request({"active_robot": ""}, NAMES) == Request()
    odd = read_request({"active_robot": 7, "active_sensor_type": ["x"]}, NAMES)
    assert odd.robot is None
    assert odd.values == ()
    assert odd.notes == (
        "/teleop_ui/active_robot ignored: expected text, got a number (7)",
        "/teleop_ui/active_sensor_type ignored: expected text, got a list",
    )


def test_any_characteristic_of_the_rules_is_read_and_unknown_active_names_are_kept() -> None:
    request = read_request(
        {
            "active_robot": "/r1",
            "active_link": "LTE",
            "active_platform": "Rover",
            "active_lnk": "Wi-Fi",
            "active_motion_control": "Flight",
            "link": "not the operator's",
        },
        ("platform", "link"),
    )
    # In the rule set's order, whatever the parameters' order.
    assert request.values == (("platform", "Rover"), ("link", "LTE"))
    assert request.unknown == ("active_lnk", "active_motion_control")


def test_a_value_the_robot_has_narrows_its_combinations(
    solution: Solution, profile: Profile
) -> None:
    drone = robot("/uav1", drone_text(), (CAMERA, GOAL), solution, profile)
    assignment, notes = choose(drone, {"motion_control": "Waypoint"}, solution)
    assert dict(assignment.given) == {
        "kinematic_type": "UAV",
        "motion_control": "Waypoint",
        "sensor_type": "2D Camera",
        "sensor_count": "1",
    }
    assert assignment.number == expected(solution, **dict(assignment.given))
    assert notes == ()


def test_several_remaining_combinations_take_the_first_in_rule_order_with_a_note(
    solution: Solution, profile: Profile
) -> None:
    # Waypoint is listed after Flight in the rules; 2D Camera before 360 Camera.
    drone = robot("/uav1", drone_text(), (SPHERE, GOAL, CAMERA), solution, profile)
    assignment, notes = choose(drone, {}, solution)
    assert dict(assignment.given)["motion_control"] == "Flight"
    assert dict(assignment.given)["sensor_type"] == "2D Camera"
    assert notes == (
        "/uav1 has several motion_control values (Flight, Waypoint): using "
        "Flight; give motion_control to choose",
    )
    assignment, notes = choose(drone, {"motion_control": "Flight"}, solution)
    assert notes == (
        "/uav1 has several sensor_type values (2D Camera, 360 Camera): using "
        "2D Camera; give sensor_type to choose",
    )


def test_a_value_the_robot_lacks_is_used_as_asked_with_a_note(
    solution: Solution, profile: Profile
) -> None:
    rover = robot("/ugv1", rover_text(), (CAMERA,), solution, profile)
    assignment, notes = choose(rover, {"motion_control": "Flight"}, solution)
    assert assignment.is_default
    assert assignment.reasons == (
        "motion_control 'Flight' is not selected for UGV in team 'Case 3'",
    )
    # Its wheels turn: the rover is driven, even before a cmd_vel shows up.
    assert notes == (
        "/ugv1 does not offer motion_control 'Flight' (it has Driving); using it as asked",
    )
    trimmed = RobotText("trimmed")  # fixed wheels: a base that shows no motion control
    trimmed.fixed(trimmed.root, "left_wheel")
    trimmed.fixed(trimmed.root, "right_wheel")
    still = robot("/ugv1", trimmed.text(), (CAMERA,), solution, profile)
    _, notes = choose(still, {"motion_control": "Flight"}, solution)
    assert notes == ()  # nothing to contrast
    driven = robot(
        "/ugv1",
        rover_text(),
        (CAMERA, Topic("cmd_vel", "geometry_msgs/Twist", "subscribed")),
        solution,
        profile,
    )
    _, notes = choose(driven, {"motion_control": "Waypoint"}, solution)
    assert notes == (
        "/ugv1 does not offer motion_control 'Waypoint' (it has Driving); using it as asked",
    )


def test_an_unknown_or_broken_active_robot_gets_the_default_with_the_reason(
    solution: Solution, profile: Profile
) -> None:
    drone = robot("/uav1", drone_text(), (CAMERA,), solution, profile)
    missing = select(Request("/uav9", (("motion_control", "Flight"),)), {"/uav1": drone}, solution)
    assert missing is not None
    assert missing.assignment is not None
    assert missing.assignment.number == solution.default_configuration
    assert missing.assignment.reasons[0] == "no robot /uav9 on the master (robots: /uav1)"
    assert dict(missing.assignment.relevant)["motion_control"] == ("Flight",)
    broken = robot("/bad", "<robot", (), solution, profile)
    answer = select(Request("/bad"), {"/bad": broken}, solution)
    assert answer is not None
    assert answer.assignment is not None
    assert answer.assignment.reasons[0].startswith(
        "robot /bad could not be identified: /bad/robot_description:1:"
    )
    assert select(Request(), {"/uav1": drone}, solution) is None


def test_the_written_back_value_holds_no_null_and_matches_the_event(
    solution: Solution, profile: Profile
) -> None:
    drone = robot("/uav1", drone_text(), (CAMERA,), solution, profile)
    request = Request("/uav9")
    selection = select(request, {"/uav1": drone}, solution)
    value = ui_configuration_value(selection, solution, "/teleop_ui_watch_test")
    assert value is not None

    def nulls(item: Any) -> int:
        if isinstance(item, dict):
            return sum(nulls(v) for v in item.values())
        if isinstance(item, list):
            return sum(nulls(v) for v in item)
        return int(item is None)

    assert nulls(value) == 0
    event = selection_data(selection, request, solution)
    assert value["configuration"] == event["assignment"]["configuration"]
    assert value["robot"] == "/uav9"
    assert value["default"] is True
    assert value["watcher"] == "/teleop_ui_watch_test"
    assert ui_configuration_value(None, solution, "/teleop_ui_watch_test") is None


def test_the_written_back_value_carries_the_layouts_when_the_watcher_writes_them(
    solution: Solution, profile: Profile
) -> None:
    drone = robot("/uav1", drone_text(), (CAMERA,), solution, profile)
    selection = select(Request("/uav1"), {"/uav1": drone}, solution)
    assert selection is not None
    assert "layouts" not in (ui_configuration_value(selection, solution, "/w") or {})
    links = (
        LayoutLink("foxglove", "/d/uav1/config-001.json", "http://127.0.0.1:1/layouts/x.json"),
        LayoutLink("team", "/d/team.json", None, None),
    )
    value = ui_configuration_value(replace(selection, layouts=links), solution, "/w")
    assert value is not None
    # As every null of the answer, the team layout's missing tab is left out (ROS 1 has no null).
    assert value["layouts"] == {
        "foxglove": {"path": "/d/uav1/config-001.json", "url": "http://127.0.0.1:1/layouts/x.json"},
        "team": {"path": "/d/team.json"},
    }
    assert list(value)[-2:] == ["layouts", "watcher"]
