"""The operator's station (:mod:`solver.live.operator`): a switch checked before anything is
written, written on a real graph (Cyclone DDS participants on loopback, a real roscore), and
answered by a running watcher; what a stranger wrote on the graph (a forged answer, a forged
announcement, a hostile answer) neither answers a switch nor reaches the terminal unescaped.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from solver import InputError, load_rules, load_team, solve
from solver.core.rules import default_rules_path
from solver.identify.profile import Profile
from solver.live.graph import MISSING
from solver.live.operator import (
    Station,
    Switch,
    Switched,
    check_switch,
    render_switched,
    robot_name,
    switch_robot,
    switched_data,
)
from solver.live.selection import NAMESPACE
from solver.live.sources import graph_address, open_source
from solver.live.sources.ros2 import DdsGraph
from solver.live.watcher import Watcher
from solver.solving.solution import Solution
from solver.untrusted import shown
from tests.live.conftest import Recorder
from tests.live.fleet import drone_configuration, expected, put_drone
from tests.live.own_rules import write_own
from tests.live.ros2_graph import Domain, Operator
from tests.live.roscore import Roscore, TestNode, wait_until

PAPER = load_rules(default_rules_path())


def refusal(call: Callable[[], object]) -> str:
    """The one located message of the :class:`InputError` ``call`` raises."""
    with pytest.raises(InputError) as raised:
        call()
    (fault,) = raised.value.faults
    return str(fault)


# ---- checked before anything is written ------------------------------------------------------


def test_a_robot_is_named_by_its_namespace_written_any_usual_way() -> None:
    assert robot_name("uav1") == "/uav1"
    assert robot_name("/uav1/") == "/uav1"
    assert robot_name("/team/ugv_1") == "/team/ugv_1"
    assert robot_name("/") == "/"


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("/uav 1", "it has a character other than a letter, a digit, '_' or '/' at 5"),
        ("/uav1\n/ugv1", "it has a character other than a letter, a digit, '_' or '/' at 6"),
        # The name as it would be written (absolute) is what is checked, and said.
        ("../etc", "'/../etc' has a character other than a letter, a digit, '_' or '/' at 2"),
        ("//uav1", "it has '//' at character 1"),
        ("/1uav", "it has a name part starting with a digit at character 2"),
        ("", "it is empty (the robot described at the root is '/')"),
    ],
)
def test_a_robot_name_that_is_no_ros_name_is_refused_where_it_was_given(
    text: str, problem: str
) -> None:
    message = refusal(lambda: robot_name(text))
    assert (
        message
        == f"<arguments>: ROBOT: the robot {shown(text, quoted=True)} is no ROS name: {problem}"
    )


def test_a_robot_name_longer_than_a_watcher_reads_is_refused() -> None:
    assert refusal(lambda: robot_name("/" + "a" * 240)) == (
        f"<arguments>: ROBOT: the robot '/{'a' * 59}...' (cut from 241 characters) is no ROS "
        "name: it is longer than 200 characters (241)"
    )


def test_values_are_checked_against_the_rule_set_and_written_as_it_writes_them() -> None:
    switch = check_switch("uav1", {"sensor_count": "03", "motion_control": "Waypoint"}, PAPER)
    # The rule set's order, and the count as the rule set writes it.
    assert switch == Switch("/uav1", (("motion_control", "Waypoint"), ("sensor_count", "3")))
    cleared = check_switch("/uav1", {"motion_control": ""}, PAPER)
    assert (cleared.values, cleared.asked) == ((("motion_control", ""),), ())


def test_a_name_or_value_the_rule_set_lacks_is_refused_with_what_it_has() -> None:
    assert refusal(lambda: check_switch("/uav1", {"sensor": "LIDAR"}, PAPER)) == (
        "<arguments>: sensor: unknown characteristic 'sensor' (did you mean 'sensor_type'?); "
        "the rules (rules/paper.yaml) have: kinematic_type, motion_control, sensor_type, "
        "sensor_count"
    )
    assert refusal(lambda: check_switch("/uav1", {"sensor_count": "99"}, PAPER)) == (
        "<arguments>: sensor_count: '99' is not a value of sensor_count; the rules "
        "(rules/paper.yaml) have: whole numbers 1 to 50"
    )
    message = refusal(lambda: check_switch("/uav1", {"robot": "/ugv1"}, None))
    assert "/teleop_ui/active_robot names the active robot" in message


def test_without_a_rule_set_only_what_a_topic_or_parameter_can_hold_is_checked() -> None:
    # Any name and value a watcher could read passes: the watcher's rule set decides.
    switch = check_switch("/uav1", {"comm_link": "LTE 5G"}, None)
    assert switch.values == (("comm_link", "LTE 5G"),)
    assert "is no characteristic name" in refusal(
        lambda: check_switch("/uav1", {"comm link": "LTE"}, None)
    )
    assert "is no value a watcher reads" in refusal(
        lambda: check_switch("/uav1", {"comm_link": "LTE\x1b[2J"}, None)
    )
    assert "is no value a watcher reads" in refusal(
        lambda: check_switch("/uav1", {"comm_link": "x" * 201}, None)
    )


# ---- output ------------------------------------------------------------------------------------


def forged(**fields: Any) -> Switched:
    answer = {
        "robot": "/uav1\nERROR: forged",
        "configuration": 1,
        "combination": {"kinematic_type": "UAV\x1b[31m", "motion_control": "Flight"},
        "team": "Case 3",
        "notes": ["a note\nwith a line break"],
        "watcher": "/teleop_ui_watch_1",
        **fields,
    }
    return Switched("ros2://domain/7", Switch("/uav1"), 5.0, answer)


def test_the_text_escapes_what_the_graph_wrote_and_never_cuts_a_layouts_path() -> None:
    path = "/layouts/" + "deep/" * 60 + "config-001.json"
    text = render_switched(
        forged(layouts={"foxglove": {"path": path, "url": "http://127.0.0.1:8770/x\n"}})
    )
    assert text.splitlines() == [
        "/uav1 -> UI configuration 1  <- UAV\\x1b[31m, Flight",
        "  answered by /teleop_ui_watch_1 for team Case 3",
        "  note: a note\\nwith a line break",
        f"  layout foxglove  {path}",
        "                   http://127.0.0.1:8770/x\\n",
    ]


def test_the_json_holds_anything_an_answer_may_hold_as_json() -> None:
    # A ROS 1 master hands back binary data and floats JSON has no word for.
    answer = switched_data(forged(configuration=math.nan, extra=b"\x00\x01", deep=[(1, 2)]))
    decoded = json.loads(json.dumps(answer, allow_nan=False))
    assert decoded["answer"]["configuration"] == "nan"
    assert decoded["answer"]["extra"] == "binary data"
    assert decoded["answer"]["deep"] == [[1, 2]]


# ---- on a ROS 2 graph ----------------------------------------------------------------------------


@pytest.fixture
def ros2_station(domain: Domain) -> Iterator[Station]:
    station = Station(open_source(graph_address(ros2=True, domain=domain.id)))
    yield station
    station.close()


@pytest.fixture
def ros2_watcher(
    domain: Domain, solution: Solution, profile: Profile
) -> Iterator[Callable[..., Recorder]]:
    started: list[Recorder] = []

    def start(answering: Solution = solution) -> Recorder:
        source = DdsGraph(domain.id)
        started.append(Recorder(Watcher(source.name, answering, profile, source=source), answering))
        started[-1].wait_for_event("synced")
        return started[-1]

    yield start
    for recorder in started:
        recorder.stop()


def test_a_switch_on_ros2_is_answered_by_the_running_watcher_with_the_values_asked(
    domain: Domain,
    ros2_station: Station,
    ros2_watcher: Callable[..., Recorder],
    solution: Solution,
) -> None:
    domain.drone("/uav1")
    watcher = ros2_watcher()
    switched = switch_robot(ros2_station, "/uav1", {"motion_control": "Waypoint"})
    assert switched.answer is not None
    assert switched.rules == "rules/paper.yaml"  # the rule set the watcher announces
    waypoint = expected(
        solution,
        kinematic_type="UAV",
        motion_control="Waypoint",
        sensor_type="2D Camera",
        sensor_count="1",
    )
    assert (switched.answer["robot"], switched.answer["configuration"]) == ("/uav1", waypoint)
    assert switched.answer["watcher"] == watcher.watcher.caller_id
    # The station stays: a second switch from it clears the value (an empty string).
    again = switch_robot(ros2_station, "/uav1", {"motion_control": ""})
    assert again.answer is not None
    assert again.answer["configuration"] == drone_configuration(solution)


class LateDiscovery(DdsGraph):
    """A real DDS source that sees a running watcher only from its third asking on: a busy
    machine, where a watcher's announcement (a parameter) is read before its answer's writer
    is discovered."""

    asked = 0

    def running_watcher(self, node: str) -> tuple[bool, str | None]:
        self.asked += 1
        if self.asked <= 2:
            return False, None
        return super().running_watcher(node)


def test_a_switch_waits_until_the_watcher_that_announced_its_rules_is_seen_running(
    domain: Domain, ros2_watcher: Callable[..., Recorder]
) -> None:
    domain.drone("/uav1")
    ros2_watcher()
    source = LateDiscovery(domain.id)
    station = Station(source)
    try:
        switched = switch_robot(station, "/uav1", {"motion_control": "Waypoint"})
    finally:
        station.close()
    # Checked against the rule set the watcher announces, not against names alone: a value
    # misspelt would be refused (exit 2), not written.
    assert switched.rules == "rules/paper.yaml"
    assert switched.answer is not None
    assert source.asked >= 3


def test_the_station_leaves_the_domain_when_closed_and_the_watcher_keeps_the_selection(
    domain: Domain, ros2_watcher: Callable[..., Recorder], solution: Solution
) -> None:
    domain.drone("/uav1")
    watcher = ros2_watcher()
    station = Station(open_source(graph_address(ros2=True, domain=domain.id)))
    observer = DdsGraph(domain.id)
    try:
        switched = switch_robot(station, "/uav1", {"motion_control": "Waypoint"})
        assert switched.answer is not None

        def writers() -> tuple[str, ...]:
            return dict(observer.observe("/teleop_ui").publishers).get(
                "/teleop_ui/active_robot", ()
            )

        wait_until(lambda: writers() or None, 60, "the station's writer seen")
        station.close()
        wait_until(lambda: not writers() or None, 60, "the station's participant gone")
        # The watcher kept what it read: a robot that comes later makes it answer again, for
        # the same selection.
        mark = watcher.mark()
        domain.rover("/ugv1")
        watcher.wait_for_event("robot_added", "/ugv1", after=mark)
        selections = [d for d in watcher.data() if d["event"] == "selection_changed"]
        assert (selections[-1]["robot"], selections[-1]["active"]["motion_control"]) == (
            "/uav1",
            "Waypoint",
        )
    finally:
        station.close()
        observer.close()


def test_a_forged_answer_naming_the_robot_answers_no_switch(
    domain: Domain, ros2_station: Station
) -> None:
    """Any participant can write the answer topic; one no running watcher wrote is no answer,
    whatever watcher it names."""
    from cyclonedds.pub import DataWriter
    from cyclonedds.topic import Topic

    from tests.live.ros2_robot import LATCHED

    domain.drone("/uav1")
    forger = Operator(domain.id)
    try:
        topic: Any = Topic(forger.participant, "rt/teleop_ui/ui_configuration", forger.String)
        writer = DataWriter(forger.participant, topic, qos=LATCHED)
        forgery = {"robot": "/uav1", "configuration": 1, "combination": {}}
        for watcher in ("/teleop_ui_watch_1_" + "ab" * 16, "/nobody"):
            writer.write(forger.String(json.dumps({**forgery, "watcher": watcher})))
            switched = switch_robot(ros2_station, "/uav1", wait=1.0)
            assert switched.answer is None
            assert switched.there == {**forgery, "watcher": watcher}
    finally:
        forger.close()


def test_a_watcher_of_a_rule_set_teleop_ui_does_not_ship_leaves_the_names_to_it(
    domain: Domain,
    ros2_station: Station,
    ros2_watcher: Callable[..., Recorder],
    tmp_path: Path,
) -> None:
    own, _profile = write_own(tmp_path)
    domain.drone("/uav1")
    ros2_watcher(own)
    # 'autonomy' is no characteristic of the shipped rules: it is written, and answered.
    switched = switch_robot(ros2_station, "/uav1", {"autonomy": "supervised"})
    assert switched.rules is None
    assert switched.why is not None
    assert "announces the rule set 'Own live rules (test)', which is not one shipped" in (
        switched.why
    )
    assert switched.answer is not None
    assert switched.answer["combination"]["autonomy"] == "supervised"


# ---- on a ROS master -----------------------------------------------------------------------------


@pytest.fixture
def ros1_station(master: Roscore) -> Iterator[Station]:
    station = Station(open_source(graph_address(master=master.uri), push=False))
    yield station
    station.close()


def test_a_forged_announcement_tells_no_rule_set(node: TestNode, ros1_station: Station) -> None:
    put_drone(node, "/uav1")
    node.set_param(
        "/teleop_ui/watchers/nobody",
        {"watcher": "/nobody", "team": "Case 3", "rules": "Mortimer et al. 2017"},
    )
    _robots, params = ros1_station.look("/uav1", announcements=True)
    rules, why = ros1_station.announced_rules(params)
    assert rules is None
    assert why == f"no running watcher on {ros1_station.name} announces its rule set"


def counted_looks(
    station: Station,
    monkeypatch: pytest.MonkeyPatch,
    found: Callable[[Any, int], Any] = lambda observation, _count: observation,
) -> list[object]:
    """The station's observations from now on, counted (each call's arguments), with the look
    ended by the first quiet one (at most 2 s); ``found`` makes each observation from the
    graph's and how many were made."""
    from solver.live import operator

    monkeypatch.setattr(operator, "LOOK_QUIET", 0.0)
    monkeypatch.setattr(operator, "LOOK_LIMIT", 2.0)
    observed: list[object] = []
    observe = station.source.observe
    # The shared master settles first (a test before may still be taking its values back):
    # the looks counted then see only what the test does.
    wait_until(lambda: observe(NAMESPACE) == observe(NAMESPACE), 60, "a quiet master")

    def counted(*args: Any) -> Any:
        observed.append(args)
        return found(observe(*args), len(observed))

    monkeypatch.setattr(station.source, "observe", counted)
    return observed


def test_an_announced_watcher_not_yet_seen_running_is_looked_for_past_a_quiet_graph(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A quiet graph ends the look after two observations; on a graph that discovers its
    # participants late (DDS), an announcement whose watcher is not seen running keeps it
    # looking. A master tells at once: a stale announcement there costs no wait.
    put_drone(node, "/uav1")
    node.set_param(
        "/teleop_ui/watchers/late",
        {"watcher": "/late", "team": "Case 3", "rules": "Mortimer et al. 2017"},
    )
    observed = counted_looks(ros1_station, monkeypatch)
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) == 2
    observed.clear()
    monkeypatch.setattr(ros1_station, "_discovers", True)  # as a DDS graph's station
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) > 2
    # A robot not on the graph is not looked for past the quiet: it is refused at once.
    observed.clear()
    ros1_station.look("/uav9", announcements=True)
    assert len(observed) == 2
    # Without announcements asked for, the robot there ends it.
    observed.clear()
    ros1_station.look("/uav1", announcements=False)
    assert len(observed) == 1
    # With no announcement on the graph, nothing is waited for.
    node.delete_param("/teleop_ui/watchers/late")
    observed.clear()
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) == 2


def test_a_switch_with_values_to_check_looks_past_a_quiet_dds_graph_for_a_watcher(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # On DDS a watcher's participant may be discovered well after the robot's, and nothing on
    # the graph says one is coming: a switch with values to check and no rule set given keeps
    # looking for a watcher that announces one, to its limit. A master tells at once.
    put_drone(node, "/uav1")
    observed = counted_looks(ros1_station, monkeypatch)
    ros1_station.look("/uav1", announcements=True, wants_rules=True)
    assert len(observed) == 2
    observed.clear()
    monkeypatch.setattr(ros1_station, "_discovers", True)  # as a DDS graph's station
    ros1_station.look("/uav1", announcements=True, wants_rules=True)
    assert len(observed) > 2
    # With nothing to check (the robot alone), the quiet graph ends it.
    observed.clear()
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) == 2


def test_a_switch_says_its_values_were_checked_for_syntax_only_only_when_it_has_some(
    node: TestNode, ros1_station: Station
) -> None:
    # No watcher announces a rule set. A switch of the robot alone has nothing to check (the
    # rule set would only order the answer's text): no warning. One with a value, or --clear,
    # is told why its names were checked for their syntax only.
    put_drone(node, "/uav1")
    assert switch_robot(ros1_station, "/uav1", wait=0.0).why is None
    expected = f"no running watcher on {ros1_station.name} announces its rule set"
    with_value = switch_robot(ros1_station, "/uav1", {"motion_control": "Flight"}, wait=0.0)
    assert with_value.why == expected
    assert switch_robot(ros1_station, "/uav1", clear=True, wait=0.0).why == expected


def test_a_graph_still_discovering_endpoints_is_not_yet_quiet(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A participant's endpoints found one by one (DDS on a busy machine) are news: the look
    # goes on while they come, for the watcher's announcement that follows them.
    put_drone(node, "/uav1")

    def discovering(observation: Any, count: int) -> Any:
        late = tuple((f"/late_{i}", ("/late",)) for i in range(min(count, 4)))
        return dataclasses.replace(observation, publishers=observation.publishers + late)

    observed = counted_looks(ros1_station, monkeypatch, discovering)
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) == 5  # four looks each finding a new writer, then one quiet look


def test_an_announcement_whose_writer_is_found_before_its_sample_is_waited_for(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # On DDS a watcher's announcement writer is found first and its sample comes after the
    # match: until the sample is read the graph only names /teleop_ui/watchers. Without the
    # wait a busy machine's switch checked its values for syntax only and wrote a misspelt one.
    put_drone(node, "/uav1")

    def writer_found(observation: Any, count: int) -> Any:
        # The writer is found in the first five looks, and gone from the sixth on.
        names = ("/teleop_ui/watchers",) if count <= 5 else ()
        return dataclasses.replace(observation, param_names=observation.param_names + names)

    observed = counted_looks(ros1_station, monkeypatch, writer_found)
    from solver.live import operator

    # The quiet, not the limit, ends each look: a busy machine's slow looks change nothing.
    monkeypatch.setattr(operator, "LOOK_LIMIT", 60.0)
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) < 5  # a master tells at once: the quiet ends the look
    observed.clear()
    monkeypatch.setattr(ros1_station, "_discovers", True)  # as a DDS graph's station
    ros1_station.look("/uav1", announcements=True)
    assert len(observed) > 5  # looked for while the writer was there


def test_a_participant_found_before_its_endpoints_is_waited_for_even_for_a_robot_not_seen(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # DDS finds a participant, then its readers and writers: that one may be the robot asked
    # for, or the watcher whose announcement tells the rule set. Without the wait a busy
    # machine's switch checked its values for syntax only (tests/cli/test_switch.py, in CI).
    put_drone(node, "/uav1")

    def participant_found(observation: Any, count: int) -> Any:
        # A participant without its endpoints in the first five looks, complete from the sixth.
        return dataclasses.replace(observation, discovering=count <= 5)

    observed = counted_looks(ros1_station, monkeypatch, participant_found)
    from solver.live import operator

    monkeypatch.setattr(operator, "LOOK_LIMIT", 60.0)
    ros1_station.look("/uav9", announcements=True)
    assert len(observed) < 5  # a master tells at once: the quiet ends the look
    monkeypatch.setattr(ros1_station, "_discovers", True)  # as a DDS graph's station
    for robot in ("/uav9", "/uav1"):
        observed.clear()
        ros1_station.look(robot, announcements=True)
        assert len(observed) > 5, robot  # looked for while the participant was incomplete


def test_a_graph_that_changes_at_every_look_ends_the_look_at_its_limit(
    node: TestNode, ros1_station: Station, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A participant that comes and goes at every poll never lets the graph be quiet: the limit
    # ends the look all the same (it was only read on a look that found nothing new).
    put_drone(node, "/uav1")

    def flapping(observation: Any, count: int) -> Any:
        if count > 1_000:
            raise AssertionError("the look never ended")
        flap = (("/flapping", ("/flapper",)),) if count % 2 else ()
        return dataclasses.replace(observation, publishers=observation.publishers + flap)

    observed = counted_looks(ros1_station, monkeypatch, flapping)
    from solver.live import operator

    monkeypatch.setattr(operator, "LOOK_LIMIT", 0.5)
    robots, _params = ros1_station.look("/uav9", announcements=True)
    assert "/uav9" not in robots
    assert len(observed) > 2  # each look found something new


def test_a_switch_on_a_master_is_answered_and_the_parameters_hold_it(
    master: Roscore,
    node: TestNode,
    ros1_station: Station,
    solution: Solution,
    profile: Profile,
) -> None:
    put_drone(node, "/uav1")
    watcher = Recorder(Watcher(master.uri, solution, profile), solution)
    try:
        watcher.wait_for_event("synced")
        switched = switch_robot(
            ros1_station, "uav1", {"sensor_count": "1"}, rules=solve(load_team("case3")).rules
        )
        assert switched.answer is not None
        assert switched.answer["configuration"] == drone_configuration(solution)
        assert node.get_param("/teleop_ui/active_robot") == "/uav1"
        assert node.get_param("/teleop_ui/active_sensor_count") == "1"
        # A robot the master does not have: refused, nothing written.
        node.delete_param("/teleop_ui/active_robot")
        message = refusal(lambda: switch_robot(ros1_station, "/uav2", rules=solution.rules))
        assert message.startswith("<arguments>: ROBOT: no robot /uav2 on ")
        assert node.get_param("/teleop_ui/active_robot") is MISSING
    finally:
        watcher.stop()
