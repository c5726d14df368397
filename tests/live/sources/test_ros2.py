"""The watcher on a ROS 2 graph over real Cyclone DDS participants, loopback only.

Robots are emulated ROS 2 processes (:mod:`tests.live.ros2_robot`, written from the ROS 2
design documents and rmw sources): ``rt/`` topics with ROS 2 type names, a transient-local
``robot_description``, ``ros_discovery_info`` with node names (Humble's 24-byte and Jazzy's
16-byte gids). Expected configurations come from :func:`solver.assign` (tests.live.fleet).
"""

import json
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from solver.identify.profile import Profile
from solver.identify.readers.safexml import MAX_XML_BYTES
from solver.live.graph import Observation
from solver.live.sources.ros2 import (
    REASSERT_FIRST,
    REASSERT_LIMIT,
    DdsGraph,
    Reassertion,
    dds_type,
    ros_name,
    ros_type,
    write,
)
from solver.live.watcher import Watcher
from solver.solving.solution import Solution
from tests.live.conftest import Recorder
from tests.live.fleet import drone_configuration, drone_text, expected, rover_configuration
from tests.live.ros2_graph import Domain, Operator
from tests.live.roscore import wait_until

TIMEOUT = 60.0


@pytest.fixture
def watch_ros2(
    domain: Domain, solution: Solution, profile: Profile
) -> Iterator[Callable[..., Recorder]]:
    started: list[Recorder] = []

    def start(**options: Any) -> Recorder:
        source = DdsGraph(domain.id)
        started.append(
            Recorder(Watcher(source.name, solution, profile, source=source, **options), solution)
        )
        return started[-1]

    yield start
    for recorder in started:
        recorder.stop()


def configured(namespace: str, number: int) -> Callable[[dict[str, Any]], bool]:
    """An event reporting ``namespace`` with configuration ``number`` as its only one."""
    return lambda d: (
        d.get("robot") == namespace
        and d["event"] in ("robot_added", "robot_changed")
        and [c["configuration"] for c in d["combinations"]] == [number]
    )


def test_names_and_types_map_as_the_ros2_design_says() -> None:
    assert ros_name("rt/uav1/camera/image_raw") == ("/uav1/camera/image_raw", "rt/")
    assert ros_name("rq/uav1/set_modeRequest") == ("/uav1/set_mode", "rq/")
    assert ros_name("DCPSParticipant") is None
    assert ros_type("sensor_msgs::msg::dds_::Image_") == "sensor_msgs/msg/Image"
    assert dds_type("std_msgs/msg/String") == "std_msgs::msg::dds_::String_"


def test_robots_joining_and_leaving_are_added_and_removed(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    watch = watch_ros2()
    watch.wait_for_event("synced")
    humble = domain.drone("/uav1", gid_size=24)
    jazzy = domain.rover("/ugv1", gid_size=16)
    drone = watch.wait_for(configured("/uav1", drone_configuration(solution)), "/uav1")
    assert drone["kinematic_type"] == "UAV"
    assert drone["sensors"][0]["source"] == "topics: /camera"
    rover = watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    assert [c["motion_control"] for c in rover["motion_controls"]] == ["Driving"]
    mark = watch.mark()
    jazzy.kill()
    removed = watch.wait_for_event("robot_removed", "/ugv1", after=mark)
    assert removed["robot"] == "/ugv1"
    assert humble.process.poll() is None
    assert not any(d.get("robot") == "/uav1" for d in watch.data(mark))


def test_a_description_arriving_after_its_topics_then_adds_the_robot(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    robot = domain.robot()
    robot.node("/uav7/camera_driver", publish=[("/uav7/camera/image_raw", "sensor_msgs/msg/Image")])
    watch = watch_ros2()
    watch.wait_for_event("synced")
    mark = watch.mark()
    robot.describe("/uav7", drone_text(), domain.directory)
    added = watch.wait_for_event("robot_added", "/uav7", after=mark)
    assert added["combinations"][0]["configuration"] == drone_configuration(solution)
    assert [s["kind"] for s in added["sensors"]] == ["camera"]


def test_two_robots_with_the_same_description_are_both_reported_and_parsed_once(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    domain.drone("/uav1")
    domain.drone("/uav2", gid_size=24)
    watch = watch_ros2()
    for namespace in ("/uav1", "/uav2"):
        watch.wait_for(configured(namespace, drone_configuration(solution)), namespace)
    assert watch.watcher.cache.misses == 1


def answer_for(operator: Operator, robot: str) -> dict[str, Any]:
    """The first answer the operator reads for ``robot``."""
    found: dict[str, Any] = wait_until(
        lambda: (a := operator.answer()) and a.get("robot") == robot and a,
        TIMEOUT,
        f"the answer for {robot}",
    )
    return found


def test_switching_the_active_robot_publishes_its_configuration(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    domain.drone("/uav1")
    domain.rover("/ugv1")
    watch = watch_ros2()
    watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    watch.wait_for(configured("/uav1", drone_configuration(solution)), "/uav1")
    operator = Operator(domain.id)
    try:
        operator.activate("/ugv1")
        selected = watch.wait_for(
            lambda d: d["event"] == "selection_changed" and d["robot"] == "/ugv1",
            "selection of /ugv1",
        )
        assert selected["assignment"]["configuration"] == rover_configuration(solution)
        answer = answer_for(operator, "/ugv1")
        assert answer["configuration"] == rover_configuration(solution)
        assert answer["watcher"] == watch.watcher.caller_id
        operator.activate("/uav1")
        answer = answer_for(operator, "/uav1")
        assert answer["configuration"] == drone_configuration(solution)
    finally:
        operator.close()


def test_a_watcher_that_stops_takes_its_answer_back(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    domain.rover("/ugv1")
    watch = watch_ros2()
    watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    operator = Operator(domain.id)
    try:
        operator.activate("/ugv1")
        answer_for(operator, "/ugv1")
        watch.stop()
        # The operator's reader keeps the last answer it got: "null" says there is none now.
        wait_until(
            lambda: operator.answer() is None and operator.answers[-1] is None,
            TIMEOUT,
            "the answer taken back",
        )
    finally:
        operator.close()


def test_a_forged_answer_is_reported_and_replaced_by_the_watchers_own(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    """Issue 36 item 8: another participant's answer naming a watcher that does not exist
    stayed, with no event; now it is a warning and the watcher's answer goes out again (as on
    ROS 1). DDS cannot stop the forger; the operator station is told what to check."""
    domain.drone("/uav1")
    watch = watch_ros2()
    watch.wait_for(configured("/uav1", drone_configuration(solution)), "/uav1")
    operator = Operator(domain.id)
    forger = domain.robot()
    ghost = "/teleop_ui_watch_1_" + "ab" * 16  # a GUID no participant on the domain has
    try:
        operator.activate("/uav1")
        answer_for(operator, "/uav1")
        for forged, message in (
            (
                {"watcher": ghost, "robot": "/uav1", "configuration": 999},
                f"an answer in the name of {ghost}, which is no running watcher: replaced by "
                "this watcher's",
            ),
            ([1, 2], "not a watcher's answer (a list): replaced by this watcher's"),
        ):
            read = len(operator.answers)
            mark = watch.mark()
            forger.latch("/teleop_ui/ui_configuration", json.dumps(forged))
            warning = watch.wait_for(
                lambda d: d["event"] == "warning" and d["where"] == "/teleop_ui/ui_configuration",
                "the forged answer reported",
                after=mark,
            )
            assert warning["message"] == message
            # The watcher's own answer is written again after the forged one.
            wait_until(
                lambda read=read: (  # type: ignore[misc]  # mypy: a default in a lambda
                    operator.answer() is not None
                    and len(operator.answers) > read
                    and isinstance(newest := operator.answers[-1], dict)
                    and newest.get("watcher") == watch.watcher.caller_id
                ),
                TIMEOUT,
                "the watcher's answer again",
            )
            assert operator.answers[-1]["configuration"] == drone_configuration(solution)
        assert [d for d in watch.data() if d["event"] == "rival"] == []
    finally:
        operator.close()


def test_the_answer_goes_out_again_at_doubling_gaps_while_another_writer_of_it_stays() -> None:
    schedule = Reassertion.after_write(100.0)
    assert schedule.at(100.5, own_newest=True, others=True) == (False, schedule)
    again, schedule = schedule.at(100.0 + REASSERT_FIRST, own_newest=True, others=True)
    assert again
    assert schedule.gap == 2 * REASSERT_FIRST
    gaps = []
    for _ in range(10):
        now = schedule.due
        assert now is not None
        again, schedule = schedule.at(now, own_newest=True, others=True)
        assert again
        gaps.append(schedule.gap)
    assert gaps[-1] == REASSERT_LIMIT
    assert gaps == sorted(gaps)


def test_the_answer_is_not_written_again_once_no_one_else_writes_it_or_it_was_replaced() -> None:
    due = 100.0 + REASSERT_FIRST
    for own_newest, others in ((True, False), (False, True)):
        again, schedule = Reassertion.after_write(100.0).at(
            due, own_newest=own_newest, others=others
        )
        assert not again
        assert schedule.due is None
        assert schedule.at(1e9, own_newest=True, others=True) == (False, schedule)


def test_a_station_that_got_a_forgery_after_the_watchers_answer_gets_the_answer_again(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    """DDS orders no two writers: a station the forger's writer matched late, or one that joins
    after the forgery, can get the forged sample after the watcher's answer and keep it. While
    the forger's writer stays, the watcher writes its answer again (1 s after it replaced the
    forgery, then at doubling gaps)."""
    domain.drone("/uav1")
    watch = watch_ros2()
    watch.wait_for(configured("/uav1", drone_configuration(solution)), "/uav1")
    operator = Operator(domain.id)
    forger = domain.robot()
    late: Operator | None = None
    try:
        operator.activate("/uav1")
        answer_for(operator, "/uav1")
        mark = watch.mark()
        forger.latch("/teleop_ui/ui_configuration", json.dumps({"configuration": 999}))
        watch.wait_for(
            lambda d: d["event"] == "warning" and d["where"] == "/teleop_ui/ui_configuration",
            "the forged answer reported",
            after=mark,
        )
        mine = watch.watcher.caller_id
        operator.answer()
        read = len(operator.answers)

        def watchers_since() -> int:
            operator.answer()
            return sum(a.get("watcher") == mine for a in operator.answers[read:])

        # Written again: the answer reaches this station twice more once the forgery was
        # reported (its replacement may have come before; a sample each second or more apart).
        wait_until(lambda: watchers_since() >= 2, TIMEOUT, "the answer written again")
        # A station started now gets both kept samples, in either order, and ends with the
        # watcher's.
        late = Operator(domain.id)
        wait_until(
            lambda: (newest := late.answer()) is not None and newest.get("watcher") == mine,
            TIMEOUT,
            "the watcher's answer at a station started after the forgery",
        )
        assert late.answers[-1]["configuration"] == drone_configuration(solution)
        # The forger gone, no one else writes the answer: the schedule ends.
        forger.kill()
        source = watch.watcher.source
        assert isinstance(source, DdsGraph)
        wait_until(lambda: source.reassertion.due is None, TIMEOUT, "the schedule's end")
    finally:
        for station in (operator, late):
            if station is not None:
                station.close()


def test_a_participant_that_only_reads_is_no_writer_of_the_answer(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    """An operator station's or a snapshot's source writes no answer: the watcher's answer is
    not written again for it (only another writer's kept sample could reach a station late)."""
    domain.drone("/uav1")
    watch = watch_ros2()
    watch.wait_for(configured("/uav1", drone_configuration(solution)), "/uav1")
    operator = Operator(domain.id)
    station = DdsGraph(domain.id, answers=False)
    try:
        operator.activate("/uav1")
        answer_for(operator, "/uav1")
        station.set_param("/teleop_ui/ui_configuration", {"forged": True})  # writes nothing
        source = watch.watcher.source
        assert isinstance(source, DdsGraph)
        wait_until(lambda: source.reassertion.due is None, TIMEOUT, "the schedule's end")
        assert operator.answer() == watch.watcher.answer
    finally:
        station.close()
        operator.close()


def test_a_participant_found_before_its_readers_and_writers_is_still_being_discovered(
    domain: Domain,
) -> None:
    """A participant is found first, its endpoints after (long after, on a busy machine): a
    look that stopped in between would miss the robot or the watcher it is."""
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.pub import DataWriter
    from cyclonedds.topic import Topic

    station = DdsGraph(domain.id, answers=False)
    bare = DomainParticipant(domain.id)
    try:
        wait_until(lambda: station.observe("/teleop_ui").discovering, TIMEOUT, "the participant")
        _writer = DataWriter(bare, Topic(bare, "rt/chatter", station.string_type))  # kept
        wait_until(
            lambda: not station.observe("/teleop_ui").discovering, TIMEOUT, "its writer found"
        )
    finally:
        station.close()
        bare.__del__()  # the writer with it


class _NodeLists:
    """A participant's ``ros_discovery_info`` as the rmw writes it (16-byte gids, reliable,
    transient-local): the nodes' lists, and plain String writers to list."""

    def __init__(self, participant: Any) -> None:
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from solver.live.sources.ros2 import message_types
        from tests.live.ros2_robot import LATCHED

        self.participant = participant
        self.string, discovery = message_types()
        self.gid, self.entities, self.info = discovery[16]
        topic = Topic(participant, "ros_discovery_info", self.info)
        self.writer = DataWriter(participant, topic, qos=LATCHED)

    def string_writer(self, topic: str) -> Any:
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        return DataWriter(self.participant, Topic(self.participant, topic, self.string))

    def name(self, node: str, writers: list[bytes], *, of: Any = None) -> None:
        """List the node ``node`` with ``writers`` (their GUIDs) as the participant ``of``'s
        (this one's unless said)."""
        owner = self.gid(list((of or self.participant).guid.bytes))
        listed = [self.entities("/", node, [], [self.gid(list(w)) for w in writers])]
        write(self.writer, self.info(owner, listed))


def test_a_participant_whose_nodes_name_an_endpoint_not_found_yet_is_still_being_discovered(
    domain: Domain,
) -> None:
    """DDS announces each endpoint apart, and a node's ``ros_discovery_info`` lists every one
    it made: while one it lists is not found, the look is not done (a robot's description
    writer may come after its node's other endpoints)."""
    from cyclonedds.domain import DomainParticipant

    station = DdsGraph(domain.id, answers=False)
    node = DomainParticipant(domain.id)
    try:
        lists = _NodeLists(node)
        chatter = lists.string_writer("rt/chatter")
        not_found_yet = bytes(range(16))  # the GUID of a writer the domain has not shown
        lists.name("talker", [chatter.guid.bytes, not_found_yet])
        wait_until(
            lambda: (
                (look := station.observe("/teleop_ui")).discovering
                and "/talker" in dict(look.publishers).get("/chatter", ())
            ),
            TIMEOUT,
            "the node's list read while a writer it names is not found",
        )
        lists.name("talker", [chatter.guid.bytes])
        wait_until(
            lambda: not station.observe("/teleop_ui").discovering, TIMEOUT, "every named writer"
        )
    finally:
        station.close()
        node.__del__()


def test_the_node_lists_of_participants_found_at_once_are_all_read(domain: Domain) -> None:
    """Each participant's last node list reaches a new reader as it is matched, all at once:
    none is written over by another's before a look takes them (the topic has no key)."""
    from cyclonedds.domain import DomainParticipant

    nodes = [DomainParticipant(domain.id) for _ in range(5)]
    kept = []  # the writers, alive while the station looks
    try:
        for i, node in enumerate(nodes):
            lists = _NodeLists(node)
            writer = lists.string_writer(f"rt/topic_{i}")
            lists.name(f"node_{i}", [writer.guid.bytes])
            kept += [lists, writer]
        station = DdsGraph(domain.id, answers=False)
        try:
            wait_until(
                lambda: any(len(r.get_matched_publications()) >= 5 for r in station._discovery),
                TIMEOUT,
                "the five lists' writers matched",
            )
            wanted = {(f"/topic_{i}", (f"/node_{i}",)) for i in range(5)}
            wait_until(
                lambda: wanted <= set(station.observe("/teleop_ui").publishers),
                TIMEOUT,
                "every node's name",
            )
        finally:
            station.close()
    finally:
        for node in nodes:
            node.__del__()


def test_a_node_list_another_participant_writes_for_one_is_not_taken(domain: Domain) -> None:
    """Anyone on the domain can write ``ros_discovery_info``: a list naming another
    participant renames none of its nodes and makes no look wait for endpoints never made."""
    from cyclonedds.domain import DomainParticipant

    station = DdsGraph(domain.id, answers=False)
    node, forger = DomainParticipant(domain.id), DomainParticipant(domain.id)
    try:
        own = _NodeLists(node)
        chatter = own.string_writer("rt/chatter")
        own.name("talker", [chatter.guid.bytes])
        wait_until(
            lambda: ("/chatter", ("/talker",)) in station.observe("/teleop_ui").publishers,
            TIMEOUT,
            "the node's own list",
        )
        forged = _NodeLists(forger)
        witness = forged.string_writer("rt/witness")
        never = bytes(range(16))  # a writer the domain never shows
        forged.name("forged", [chatter.guid.bytes, never], of=node)
        # Then the forger's own list, after the forged one from the same writer: once it is
        # read, the forged one was read before it.
        forged.name("witness", [witness.guid.bytes])
        look = wait_until(
            lambda: (
                (found := station.observe("/teleop_ui")).publishers
                and ("/witness", ("/witness",)) in found.publishers
                and found
            ),
            TIMEOUT,
            "the forger's own list",
        )
        assert isinstance(look, Observation)
        assert ("/chatter", ("/talker",)) in look.publishers
        assert not look.discovering
    finally:
        station.close()
        node.__del__()
        forger.__del__()


def test_the_active_motion_control_topic_selects_as_the_ros1_parameter_does(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    domain.rover("/ugv1")
    watch = watch_ros2()
    watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    operator = Operator(domain.id)
    try:
        operator.control("Flight")  # a UGV never flies: the default configuration, and why
        operator.activate("/ugv1")
        # The two may reach the watcher apart: Flight with no robot active is answered first.
        refused = watch.wait_for(
            lambda d: (
                d["event"] == "selection_changed"
                and d["robot"] == "/ugv1"
                and d["active"]["motion_control"] == "Flight"
            ),
            "Flight for /ugv1",
        )
        assert refused["assignment"]["default"] is True
        operator.control("Driving")
        driving = watch.wait_for(
            lambda d: (
                d["event"] == "selection_changed" and d["active"]["motion_control"] == "Driving"
            ),
            "Driving for /ugv1",
        )
        assert driving["assignment"]["configuration"] == rover_configuration(solution)
        answer = wait_until(
            lambda: (a := operator.answer()) and a.get("default") is False and a,
            TIMEOUT,
            "the answer for Driving",
        )
        assert answer["robot"] == "/ugv1"
        assert answer["configuration"] == rover_configuration(solution)
    finally:
        operator.close()


def test_a_50_mb_description_is_refused_located_and_the_watcher_goes_on(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    watch = watch_ros2()
    watch.wait_for_event("synced")
    hostile = domain.robot()
    text = drone_text().replace("</robot>", "<!--" + "x" * (50 * 1024 * 1024) + "-->\n</robot>")
    hostile.describe("/big", text, domain.directory)
    big = watch.wait_for_event("robot_added", "/big")
    assert big["combinations"] == []
    assert big["error"].startswith("/big/robot_description")
    assert f"larger than {MAX_XML_BYTES} bytes" in big["error"]
    mark = watch.mark()
    domain.rover("/ugv1")
    watch.wait_for(
        configured("/ugv1", rover_configuration(solution)), "/ugv1 after /big", after=mark
    )


def test_another_watcher_on_the_same_domain_sees_the_same_robots_and_agrees(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    domain.rover("/ugv1")
    first, second = watch_ros2(), watch_ros2()
    for watch in (first, second):
        watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    operator = Operator(domain.id)
    try:
        operator.activate("/ugv1")
        for watch in (first, second):
            selected = watch.wait_for(
                lambda d: d["event"] == "selection_changed" and d["robot"] == "/ugv1",
                "selection of /ugv1",
            )
            assert selected["assignment"]["configuration"] == rover_configuration(solution)
        # Neither watcher reports the other's DDS readers as part of a robot.
        assert {d["robot"] for d in second.data() if d["event"] == "robot_added"} == {"/ugv1"}
    finally:
        operator.close()


def test_hostile_answers_and_a_10_mb_selection_end_in_notes_not_a_crash(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    """Issue 23 item 6, issue 30 item 7: `'[' * 200000` and a deeply nested object on the answer
    topic, a 10 MB active robot: bounded before decoding or echoing."""
    from cyclonedds.pub import DataWriter

    from tests.live.ros2_robot import LATCHED

    domain.rover("/ugv1")
    watch = watch_ros2()
    watch.wait_for(configured("/ugv1", rover_configuration(solution)), "/ugv1")
    operator = Operator(domain.id)
    hostile: Any = DataWriter(operator.participant, operator.answer_topic, qos=LATCHED)
    try:
        for text in ("[" * 200_000, '{"a":' * 100_000 + "1" + "}" * 100_000):
            mark = watch.mark()
            hostile.write(operator.String(text))
            operator.control(f"Driving{len(text)}")  # an event after the hostile answer is read
            asked = f"Driving{len(text)}"
            watch.wait_for(
                lambda d, asked=asked: (  # type: ignore[misc]  # mypy: a default in a lambda
                    d["event"] == "selection_changed" and d["active"]["motion_control"] == asked
                ),
                "the selection after a hostile answer",
                after=mark,
            )
        operator.activate("/" + "u" * 10_000_000)
        ignored = watch.wait_for(
            lambda d: (
                d["event"] == "selection_changed"
                and any("active_robot ignored" in note for note in d["notes"])
            ),
            "the 10 MB active robot ignored",
        )
        assert ignored["robot"] is None
        assert ignored["notes"] == [
            "/teleop_ui/active_robot ignored: 10,000,001 characters, longer than 200 "
            f"(/{'u' * 59}... (cut from 10,000,001 characters))"
        ]
        operator.control("Driving")
        operator.activate("/ugv1")
        selected = watch.wait_for(
            lambda d: d["event"] == "selection_changed" and d["robot"] == "/ugv1",
            "the selection of /ugv1 after it all",
        )
        assert selected["assignment"]["configuration"] == rover_configuration(solution)
        assert watch.error is None
    finally:
        hostile.__del__()
        operator.close()


def test_a_malformed_cyclonedds_uri_is_a_located_usage_error() -> None:
    """Issue 30 item 4: a malformed address or configuration is exit 2, never a traceback."""
    import os
    import subprocess
    import sys

    from tests.conftest import ROOT

    environment = {**os.environ, "CYCLONEDDS_URI": "<CycloneDDS><Domain"}
    result = subprocess.run(
        [sys.executable, "-m", "solver", "watch", "--ros2", "--domain", "7", "--team", "case3"],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert result.returncode == 2
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    # Cyclone DDS logs its own parser's complaint first; the last line is the tool's.
    assert result.stderr.splitlines()[-1].startswith(
        "CYCLONEDDS_URI: Cyclone DDS cannot join domain 7 with this configuration "
        "('<CycloneDDS><Domain'): "
    )


@pytest.fixture
def watch_own_ros2(domain: Domain, tmp_path: Path) -> Iterator[Callable[..., Recorder]]:
    """``watch_own_ros2(team_file, *set_pairs, policy=...)``: a watcher of the test's own rules
    (:mod:`tests.live.own_rules`) on the domain, stopped afterwards."""
    from solver.core.team import load_team
    from solver.live.given import parse_fixed
    from solver.solving.solution import solve
    from tests.live.own_rules import write_own

    _, profile = write_own(tmp_path)
    started: list[Recorder] = []

    def start(team: str = "own-team.yaml", *pairs: str, policy: str = "yield") -> Recorder:
        solution = solve(load_team(tmp_path / team))
        source = DdsGraph(domain.id)
        watcher = Watcher(
            source.name,
            solution,
            profile,
            source=source,
            fixed=parse_fixed(pairs, solution.rules),
            policy=policy,
        )
        started.append(Recorder(watcher, solution))
        return started[-1]

    yield start
    for recorder in started:
        recorder.stop()


def test_synced_comes_once_the_robots_already_on_the_domain_are_discovered(
    domain: Domain, watch_ros2: Callable[..., Recorder]
) -> None:
    """Issue 27: `synced` lists the robots that were there, not `[]` before discovery."""
    domain.drone("/uav1")
    domain.rover("/ugv1", gid_size=24)
    watch = watch_ros2()
    synced = watch.wait_for_event("synced")
    assert synced["robots"] == ["/uav1", "/ugv1"]
    before = [d["event"] for d in watch.data()][: synced["seq"]]
    assert before == ["robot_added", "robot_added", "synced"]


def test_the_operators_choice_of_a_characteristic_of_the_users_own_changes_the_answer_on_ros2(
    domain: Domain, watch_own_ros2: Callable[..., Recorder]
) -> None:
    from tests.live.own_rules import drone, rover

    domain.drone("/uav1")
    tethered = domain.rover("/ugv1")
    tethered.latch("/ugv1/teleop_ui/link", "Tether")  # the robot's own value
    watch = watch_own_ros2("own-team.yaml", "/uav1:link=LTE")  # fixed for one robot
    solution = watch.solution
    watch.wait_for_event("synced")
    robots = {d["robot"]: d for d in watch.data() if d["event"] == "robot_added"}
    assert robots["/ugv1"]["given"] == {
        "link": {"value": "Tether", "source": "/ugv1/teleop_ui/link"}
    }
    assert robots["/uav1"]["given"] == {"link": {"value": "LTE", "source": "--set /uav1:link=LTE"}}
    assert [m["characteristic"] for m in robots["/uav1"]["missing"]] == ["autonomy"]
    operator = Operator(domain.id)
    try:
        operator.select("autonomy", "teleoperated")
        operator.activate("/uav1")
        # The choice and the activation are two messages: an answer for /uav1 may come before
        # the choice reaches the watcher (on a busy machine), so wait for the one with it.
        first = wait_until(
            lambda: (
                (a := operator.answer())
                and a.get("robot") == "/uav1"
                and a.get("combination", {}).get("autonomy") == "teleoperated"
                and a
            ),
            TIMEOUT,
            "the answer for /uav1, teleoperated",
        )
        assert first["configuration"] == drone(solution, autonomy="teleoperated", link="LTE")
        operator.select("autonomy", "supervised")
        second = wait_until(
            lambda: (
                (a := operator.answer()) and a["combination"].get("autonomy") == "supervised" and a
            ),
            TIMEOUT,
            "the answer for /uav1, supervised",
        )
        assert second["configuration"] == drone(solution, autonomy="supervised", link="LTE")
        assert second["configuration"] != first["configuration"]
        operator.activate("/ugv1")
        third = answer_for(operator, "/ugv1")
        assert third["configuration"] == rover(solution, autonomy="supervised", link="Tether")
        # A name the rules do not know: a located warning, nothing else changes.
        mark = watch.mark()
        operator.select("autonmy", "teleoperated")
        warning = watch.wait_for_event("warning", after=mark)
        assert warning["where"] == "/teleop_ui/active_autonmy"
        assert warning["message"].startswith(
            "the rule set has no characteristic 'autonmy' (did you mean 'autonomy'?)"
        )
    finally:
        operator.close()


def test_two_watchers_with_different_teams_report_each_other_and_one_answer_stands(
    domain: Domain, watch_own_ros2: Callable[..., Recorder]
) -> None:
    """Issue 27: they overwrote each other's answer on every change; now each reports the
    other (both teams), the second yields, and takes over when the first is gone."""
    domain.drone("/uav1")
    operator = Operator(domain.id)
    try:
        operator.activate("/uav1")
        first = watch_own_ros2("own-team.yaml")
        wait_until(
            lambda: (a := operator.answer()) and a.get("watcher") == first.watcher.caller_id,
            TIMEOUT,
            "the first watcher's answer",
        )
        second = watch_own_ros2("other-team.yaml")
        theirs = second.wait_for_event("rival")
        assert (theirs["watcher"], theirs["team"], theirs["own_team"]) == (
            first.watcher.caller_id,
            "Own live team",
            "Other live team",
        )
        ours = first.wait_for_event("rival")
        assert (ours["watcher"], ours["team"], ours["own_team"], ours["policy"]) == (
            second.watcher.caller_id,
            "Other live team",
            "Own live team",
            "yield",
        )
        held = second.wait_for(
            lambda d: (
                d["event"] == "selection_changed"
                and any("not written" in note for note in d["notes"])
            ),
            "the second watcher yielding",
        )
        assert held["assignment"]["team"] == "Other live team"
        assert operator.answer()["watcher"] == first.watcher.caller_id
        mark = second.mark()
        first.stop()
        assert second.wait_for_event("rival_gone", after=mark)["watcher"] == (
            first.watcher.caller_id
        )
        taken = wait_until(
            lambda: (a := operator.answer()) and a.get("watcher") == second.watcher.caller_id and a,
            TIMEOUT,
            "the second watcher's answer",
        )
        assert taken["team"] == "Other live team"
    finally:
        operator.close()


# An alias bomb: nine levels of nine references, a billion strings once expanded.
BOMB = "teleop: 1\na0: &a0 [x]\n" + "".join(
    f"a{k}: &a{k} [{', '.join([f'*a{k - 1}'] * 9)}]\n" for k in range(1, 10)
)


def test_a_latched_teleoperation_description_beside_the_robot_wins_and_a_bomb_is_a_warning(
    domain: Domain, watch_ros2: Callable[..., Recorder], solution: Solution
) -> None:
    rover = domain.rover("/ugv1")  # read from its topics: Driving
    rover.latch(
        "/ugv1/teleop_description",
        "teleop: 1\nmotion_controls:\n  - {control: Waypoint, action: /ugv1/navigate_to_pose}\n",
    )
    other = domain.rover("/ugv2", gid_size=24)
    other.latch("/ugv2/teleop_description", BOMB)
    watch = watch_ros2()
    declared = expected(
        solution,
        kinematic_type="UGV",
        motion_control="Waypoint",
        sensor_type="LIDAR",
        sensor_count="1",
    )
    added = watch.wait_for(configured("/ugv1", declared), "/ugv1 as declared")
    assert [c["motion_control"] for c in added["motion_controls"]] == ["Waypoint"]
    assert added["declared"] == "/ugv1/teleop_description"
    assert [line.split(":")[0] for line in added["disagreements"]] == [
        "motion control Driving",
        "motion control Waypoint",
    ]
    guessed = watch.wait_for(configured("/ugv2", rover_configuration(solution)), "/ugv2")
    assert "declared" not in guessed
    warning = watch.wait_for(
        lambda d: d["event"] == "warning" and d["where"].startswith("/ugv2/teleop_description"),
        "the warning about /ugv2's description",
    )
    assert warning["message"].endswith("; not used: what identification read stands")
