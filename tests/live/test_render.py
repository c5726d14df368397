"""The event schema (the README's contract) and the text form of every kind of event."""

from __future__ import annotations

import dataclasses
import json

from solver.errors import Fault, Location, SolverError
from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.live.discovery import RobotSource
from solver.live.events import (
    GraphWarning,
    MasterBack,
    MasterLost,
    Rival,
    RivalGone,
    RobotAdded,
    RobotChanged,
    RobotRemoved,
    SelectionChanged,
    Synced,
    event_data,
)
from solver.live.render import render_event, text_lines
from solver.live.robot import LiveRobot, identify_robot
from solver.live.selection import LayoutLink, Request, select
from solver.ros.names import Topic
from solver.solving.solution import Solution
from tests.live.fleet import drone_configuration, drone_text

URI = "http://127.0.0.1:11311/"
ROBOT_FIELDS = [
    "robot",
    "name",
    "structure",
    "kinematic_type",
    "confidence",
    "sensor_count",
    "sensors",
    "motion_controls",
    "given",
    "combinations",
    "missing",
    "error",
    "topics",
]
FLIGHT = (("motion_control", "Flight"),)


def drone(solution: Solution, profile: Profile) -> LiveRobot:
    source = RobotSource(
        "/uav1",
        "/uav1/robot_description",
        None,
        (Topic("camera/image_raw", "sensor_msgs/Image", "published"),),
    )
    return identify_robot(
        source, drone_text(), cache=IdentificationCache(), solution=solution, profile=profile
    )


def test_every_event_kind_has_its_documented_fields(solution: Solution, profile: Profile) -> None:
    robot = drone(solution, profile)
    request = Request("/uav1", FLIGHT)
    selection = select(request, {"/uav1": robot}, solution)
    events = [
        RobotAdded(1, robot),
        RobotChanged(2, robot, ("sensors",)),
        RobotRemoved(3, "/uav1"),
        SelectionChanged(4, request, selection),
        MasterLost(5, URI, "gone"),
        MasterBack(6, URI),
        Synced(7, URI, ("/uav1",)),
        GraphWarning(8, "/teleop_ui/active_x", "no x"),
        Rival(9, "/w2", "Other team", "Case 3", "yield"),
        RivalGone(10, "/w2"),
    ]
    fields = [list(event_data(e, solution)) for e in events]
    assert fields == [
        ["seq", "event", *ROBOT_FIELDS],
        ["seq", "event", *ROBOT_FIELDS, "changed"],
        ["seq", "event", "robot"],
        ["seq", "event", "robot", "active", "assignment", "notes"],
        ["seq", "event", "master", "error"],
        ["seq", "event", "master"],
        ["seq", "event", "master", "robots"],
        ["seq", "event", "where", "message"],
        ["seq", "event", "watcher", "team", "own_team", "policy"],
        ["seq", "event", "watcher"],
    ]
    assert [event_data(e, solution)["event"] for e in events] == [
        "robot_added",
        "robot_changed",
        "robot_removed",
        "selection_changed",
        "master_lost",
        "master_back",
        "synced",
        "warning",
        "rival",
        "rival_gone",
    ]
    # Every characteristic of the rule set, by its own name, with what was asked or null.
    assert event_data(events[3], solution)["active"] == {
        "kinematic_type": None,
        "motion_control": "Flight",
        "sensor_type": None,
        "sensor_count": None,
    }


def test_json_lines_are_one_compact_object_per_line(solution: Solution, profile: Profile) -> None:
    line = render_event(RobotAdded(1, drone(solution, profile)), solution, "json")
    assert line.endswith("}\n")
    assert line.count("\n") == 1
    data = json.loads(line)
    assert data["combinations"] == [
        {
            "combination": {
                "kinematic_type": "UAV",
                "motion_control": "Flight",
                "sensor_type": "2D Camera",
                "sensor_count": "1",
            },
            "configuration": drone_configuration(solution),
            "default": False,
            "reasons": [],
        }
    ]
    assert data["sensors"] == [
        {"kind": "camera", "sensor_type": "2D Camera", "count": 1, "source": "topics: /camera"}
    ]


def test_text_lines_for_every_kind(solution: Solution, profile: Profile) -> None:
    robot = drone(solution, profile)
    number = drone_configuration(solution)
    assert text_lines(RobotChanged(2, robot, ("sensors", "combinations"))) == [
        "robot changed   /uav1  copter: UAV (structure UAV, confidence 0.95); 1 sensor(s); "
        "motion controls Flight  [changed: sensors, combinations]",
        f"                  UI configuration {number}  <- UAV, Flight, 2D Camera, 1",
    ]
    assert text_lines(RobotRemoved(3, "/uav1")) == ["robot removed   /uav1"]
    assert text_lines(MasterLost(4, URI, "cannot reach the ROS master")) == [
        f"master lost     {URI}: cannot reach the ROS master; retrying"
    ]
    assert text_lines(MasterBack(5, URI)) == [f"master back     {URI}: resynchronising"]
    assert text_lines(Synced(6, URI, ())) == ["synced          0 robot(s): none"]
    request = Request("/uav9", FLIGHT)
    answer = select(request, {"/uav1": robot}, solution)
    assert text_lines(SelectionChanged(7, request, answer)) == [
        f"selection       /uav9 Flight -> UI configuration {solution.default_configuration} "
        "(default): no robot /uav9 on the master (robots: /uav1); no kinematic_type given; "
        "no sensor_type given; no sensor_count given  <- Flight"
    ]
    assert text_lines(SelectionChanged(8, Request(), None)) == [
        "selection       no active robot (set /teleop_ui/active_robot)"
    ]
    assert text_lines(GraphWarning(9, "/teleop_ui/active_x", "no x")) == [
        "warning         /teleop_ui/active_x: no x"
    ]
    assert text_lines(Rival(10, "/w2", "Other", "Case 3", "yield")) == [
        "rival           /w2 answers for team Other, this watcher for Case 3; this one will yield"
    ]
    assert text_lines(RivalGone(11, "/w2")) == ["rival gone      /w2"]


def test_text_events_show_names_from_the_graph_on_their_own_line(
    solution: Solution, profile: Profile
) -> None:
    # A namespace, a robot name and a requested value from the graph, each holding a line
    # break, a bidi control or a megabyte: one line per event line, escaped, cut short.
    namespace = "/uav1\nselection       FORGED\u202e"
    source = RobotSource(namespace, f"{namespace}/robot_description", None, ())
    text = drone_text().replace('name="', 'name="x\nFORGED' + "N" * 1_000_000, 1)
    robot = identify_robot(
        source, text, cache=IdentificationCache(), solution=solution, profile=profile
    )
    request = Request(namespace, (("motion_control", "Flight\nFORGED\x1b[2J"),))
    selection = select(request, {namespace: robot}, solution)
    # A robot's error is its faults, one per line: each escaped when it was made.
    faults = [Fault(Location("a\nFORGED.urdf", 1), "bad\nFORGED"), Fault(Location("b", 2), "x")]
    broken = LiveRobot(namespace, None, (), error=str(SolverError(faults)))
    events = [
        RobotAdded(1, robot),
        RobotAdded(2, broken),
        RobotRemoved(3, namespace),
        SelectionChanged(4, request, selection),
        MasterLost(5, URI + "\nFORGED", "gone\nFORGED"),
        Synced(6, URI, (namespace,)),
    ]
    rendered = "".join(render_event(event, solution, "text") for event in events)
    lines = rendered.splitlines()
    assert not any(line.lstrip().startswith("FORGED") for line in lines)
    assert not any(char in rendered for char in ("\u202e", "\x1b"))
    assert len(rendered) < 10_000
    assert "... (cut from 1,000,0" in rendered


# ---- where the answer's layouts are (watch --layouts; issue 38) -----------------------------


def test_a_selections_layouts_are_shown_whole_each_on_a_line_of_its_own(
    solution: Solution, profile: Profile
) -> None:
    robot = drone(solution, profile)
    request = Request("/uav1", FLIGHT)
    # A folder of the operator's own, longer than a stranger's string is shown and holding a
    # character a terminal would act on: whole, escaped, never cut.
    folder = "/home/me/" + "a-long-folder-name-" * 4 + "\x1b[2J"
    own = f"{folder}/uav1/config-001.json"
    links = (
        LayoutLink("foxglove", own, "http://127.0.0.1:8770/layouts/uav1/config-001.json"),
        LayoutLink("team", f"{folder}/team.json", None, None),
    )
    selected = select(request, {"/uav1": robot}, solution)
    assert selected is not None
    answer = dataclasses.replace(selected, layouts=links)
    lines = text_lines(SelectionChanged(7, request, answer, with_layouts=True))
    escaped = folder.replace("\x1b", "\\x1b")
    assert lines[-3:] == [
        f"layout          foxglove: {escaped}/uav1/config-001.json",
        "                  http://127.0.0.1:8770/layouts/uav1/config-001.json",
        f"layout          team (no tab for this answer): {escaped}/team.json",
    ]
    data = event_data(SelectionChanged(7, request, answer, with_layouts=True), solution)
    assert (data["layout"], data["layouts"]) == (
        own,
        {
            "foxglove": {"path": own, "url": "http://127.0.0.1:8770/layouts/uav1/config-001.json"},
            "team": {"path": f"{folder}/team.json", "tab": None},
        },
    )
    assert json.loads(render_event(SelectionChanged(7, request, answer, True), solution))[
        "layouts"
    ] == json.loads(json.dumps(data["layouts"]))


def test_without_layouts_events_name_none_and_with_them_say_there_are_none(
    solution: Solution, profile: Profile
) -> None:
    robot = drone(solution, profile)
    request = Request("/uav1", FLIGHT)
    answer = select(request, {"/uav1": robot}, solution)
    assert "layouts" not in event_data(SelectionChanged(1, request, answer), solution)
    none = event_data(SelectionChanged(2, Request(), None, with_layouts=True), solution)
    assert (none["layout"], none["layouts"]) == (None, None)
    assert text_lines(SelectionChanged(2, Request(), None, with_layouts=True)) == [
        "selection       no active robot (set /teleop_ui/active_robot)",
        "layout          (no layout)",
    ]


def test_a_declared_robot_says_its_description_and_each_difference_on_a_line(
    solution: Solution, profile: Profile
) -> None:
    source = RobotSource(
        "/uav1", "/uav1/robot_description", None, (), teleop_key="/uav1/teleop_description"
    )
    robot = identify_robot(
        source,
        drone_text(),
        cache=IdentificationCache(),
        solution=solution,
        profile=profile,
        teleop="teleop: 1\nmotion_controls:\n  - {control: Waypoint, action: /uav1/go}\n",
    )
    data = event_data(RobotAdded(1, robot), solution)
    assert data["declared"] == "/uav1/teleop_description"
    assert len(data["disagreements"]) == 2
    lines = text_lines(RobotAdded(1, robot))
    assert lines[1] == "                  declared: /uav1/teleop_description"
    assert [line.split(": ")[1] for line in lines[2:4]] == [
        "motion control Flight",
        "motion control Waypoint",
    ]
    assert all(
        line.startswith("                  declared and read differ: ") for line in lines[2:4]
    )
