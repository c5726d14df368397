"""Latency of ``teleop-ui watch --ros2`` on real Cyclone DDS participants, loopback only.

Ten and a hundred emulated ROS 2 robots (half quadrotors, half rovers, in ten processes of their
own, see :mod:`tests.live.ros2_robot`: one robot each, or ten) are on a DDS domain of their own;
a watcher (DdsGraph source, default polling interval 0.2 s) runs in a thread. Timed, on each:

* ``switch``: at a human pace (an untimed pause before each), the operator participant writes
  ``/teleop_ui/active_robot`` (round-robin over the ten) -> the operator's reader receives
  ``/teleop_ui/ui_configuration`` naming that robot (end to end: DDS both ways, the watcher
  woken by the sample; issue 16's target: median <= 50 ms);
* ``description``: a new robot's transient-local ``robot_description`` is written -> the
  watcher's ``robot_added`` for it (discovery of the new writer, the sample, identification).

* ``echo`` (the peer): the same operator writes a String on a topic of its own and a bare DDS
  participant in another process answers it from a data-available listener, with the same
  QoS: DDS both ways and nothing else, on the same domain as the robots, in the same run.
  ``tools/bench_table.py`` reports ``switch / echo`` for each size (issue 29's target: at most
  3x with 100 robots). The watcher runs in the operator's process here, where Cyclone DDS
  delivers without a network hop, so the ratio is a rough measure: how many bare round trips
  between processes one answer of the watcher costs.

The same again with layouts (``, layouts`` fleets: ``watch --layouts DIR --serve 127.0.0.1:0``,
the team layout on; issue 38's target: the answer with its layouts within 2x the echo): each
robot's layouts and ``DIR/team.json`` are written as the robots are identified (untimed), and
each ``switch`` asserts the answer's layouts too (the robot's file of the configuration
``solver.assign`` gives, its address, the team layout's tab of that robot and configuration).
And, on those fleets only, ``served``: the operator's switch -> the answer on the watcher's
event stream (``GET /answer/events``, what the viewer's follower reads on either graph).

Each round asserts what it timed (robot, configuration number); the median and 95th percentile
are printed and kept in the benchmark's extra info. Run:
``python -m pytest benchmarks/bench_ros2.py -s -p no:cacheprovider``.
"""

import itertools
import json
import os
import queue
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.latency import report
from solver.core.team import load_team
from solver.identify.profile import load_profile
from solver.live.events import SelectionChanged, event_data
from solver.live.layouts import LiveLayouts
from solver.live.server import AnswerServer
from solver.live.sources.ros2 import DdsGraph
from solver.live.watcher import Watcher
from solver.solving.solution import Solution, solve
from tests.conftest import TEAMS
from tests.live.fleet import drone_configuration, drone_text, rover_configuration, rover_text
from tests.live.ros2_graph import EmulatedRobot, Operator, next_domain, write_config

SWITCHES = 40
DESCRIPTIONS = 10
PROCESSES = 10  # each holds ROBOTS / PROCESSES robots
ROBOTS = (10, 100)
# Each fleet: its number of robots, and whether the watcher writes and serves layouts.
FLEETS = [(robots, layouts) for layouts in (False, True) for robots in ROBOTS]
# Untimed, before each switch: an operator switches robots at a human pace. Back-to-back
# switches are answered at most every 10 ms (the watcher's gap between polls, which keeps
# bursts of changes from becoming bursts of polls), so without a pause that gap is measured.
PAUSE = 0.05


def pause() -> None:
    time.sleep(PAUSE)


class Fleet:
    def __init__(self, directory: Path, robots: int, layouts: bool = False) -> None:
        os.environ["CYCLONEDDS_URI"] = write_config(directory)
        self.domain = next_domain()
        self.solution: Solution = solve(load_team(TEAMS / "case3.yaml"))
        self.robots: list[EmulatedRobot] = []
        self.names: list[str] = []
        for index in range(PROCESSES):
            process = EmulatedRobot(self.domain, dict(os.environ), 24 if index % 2 else 16)
            for number in range(index, robots, PROCESSES):
                self.names.append(self._put(process, number, robots, directory))
            self.robots.append(process)
        source = DdsGraph(self.domain)
        # With layouts: as `watch --layouts DIR --serve 127.0.0.1:0` runs.
        self.layouts = directory / "layouts" if layouts else None
        self.server: AnswerServer | None = None
        written: LiveLayouts | None = None
        if self.layouts is not None:
            self.server = AnswerServer(self.layouts)
            self.server.start()
            url = self.server.url
            written = LiveLayouts(
                self.layouts, self.solution, base_url=url, answer_url=f"{url}/answer/events"
            )
        self.watcher = Watcher(
            source.name, self.solution, load_profile(), source=source, layouts=written
        )
        self.events: queue.Queue[tuple[float, dict[str, Any]]] = queue.Queue()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()
        self.operator = Operator(self.domain)
        # The robots switched to, round-robin across the tests: two switches in a row never
        # name the same robot (the same robot again would change no answer).
        self.order = itertools.cycle(self.names)
        ready: set[str] = set()
        deadline = time.monotonic() + 60
        while ready != set(self.names) and time.monotonic() < deadline:
            _, data = self.events.get(timeout=60)
            if data.get("combinations"):
                ready.add(data["robot"])
        assert ready == set(self.names), f"robots identified: {sorted(ready)}"

    @staticmethod
    def _put(process: EmulatedRobot, number: int, robots: int, directory: Path) -> str:
        """Robot ``number``: a quadrotor in the first half, a rover in the second."""
        if number < robots // 2:
            name = f"/uav{number}"
            process.node(
                f"{name}/camera_driver",
                publish=[(f"{name}/camera/image_raw", "sensor_msgs/msg/Image")],
            )
            process.describe(name, drone_text(), directory)
        else:
            name = f"/ugv{number}"
            process.node(
                f"{name}/base_driver",
                subscribe=[(f"{name}/cmd_vel", "geometry_msgs/msg/Twist")],
                publish=[(f"{name}/scan", "sensor_msgs/msg/LaserScan")],
            )
            process.describe(name, rover_text(), directory)
        return name

    def _run(self) -> None:
        for event in self.watcher.events():
            if self.server is not None and isinstance(event, SelectionChanged):
                self.server.publish(self.watcher.answer)  # as `watch --serve` does, first
            self.events.put((time.perf_counter(), event_data(event, self.solution)))

    def until_event(self, robot: str, kind: str) -> tuple[float, dict[str, Any]]:
        while True:
            at, data = self.events.get(timeout=60)
            if data["event"] == kind and data.get("robot") == robot:
                return at, data

    def expected(self, robot: str) -> int:
        return (
            drone_configuration(self.solution)
            if robot.startswith("/uav")
            else rover_configuration(self.solution)
        )

    def team_titles(self) -> list[str]:
        """The team layout's tab titles as written now (its robots do not change while the
        operator switches)."""
        assert self.layouts is not None
        team = json.loads((self.layouts / "team.json").read_text(encoding="utf-8"))
        return [tab["title"] for tab in team["configById"]["Tab!robots"]["tabs"]]

    def check_layouts(self, robot: str, answer: dict[str, Any], titles: list[str]) -> None:
        """The answer's layouts: the robot's file of the configuration ``solver.assign`` gives
        (there, and served at the address named), and the team layout's tab of that pair."""
        assert self.layouts is not None
        assert self.server is not None
        number = self.expected(robot)
        own = answer["layouts"]["foxglove"]
        name = f"{robot.strip('/')}/config-{number:03d}.json"
        assert own == {"path": str(self.layouts / name), "url": f"{self.server.url}/layouts/{name}"}
        assert Path(own["path"]).is_file()
        team = answer["layouts"]["team"]
        assert team["path"] == str(self.layouts / "team.json")
        assert titles[team["tab"]].startswith(f"{robot}: {number} (")

    def close(self) -> None:
        self.watcher.stop("benchmark over")
        self.thread.join(timeout=30)
        self.watcher.close()
        if self.server is not None:
            self.server.close()
        self.operator.close()
        for robot in self.robots:
            robot.kill()


@pytest.fixture(
    scope="module",
    params=FLEETS,
    ids=[f"{n} robots" + (", layouts" if layouts else "") for n, layouts in FLEETS],
)
def fleet(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Fleet]:
    robots, layouts = request.param
    running = Fleet(tmp_path_factory.mktemp("dds"), robots, layouts)
    yield running
    running.close()


def _which(fleet: Fleet) -> str:
    return f"{len(fleet.names)} robots" + (", layouts" if fleet.layouts is not None else "")


def test_active_robot_message_to_published_configuration(
    benchmark: BenchmarkFixture, fleet: Fleet
) -> None:
    latencies: list[float] = []
    titles = fleet.team_titles() if fleet.layouts is not None else []

    def switch() -> None:
        robot = next(fleet.order)
        start = time.perf_counter()
        fleet.operator.activate(robot)
        while True:
            answer = fleet.operator.answer()
            if answer is not None and answer.get("robot") == robot:
                break
            time.sleep(0.0005)
        latencies.append(time.perf_counter() - start)
        assert answer["configuration"] == fleet.expected(robot)
        if fleet.layouts is not None:
            fleet.check_layouts(robot, answer, titles)
        else:
            assert "layouts" not in answer

    benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        switch, setup=pause, rounds=SWITCHES
    )
    report(benchmark, f"active robot -> published configuration ({_which(fleet)})", latencies)


class Stream:
    """The watcher's event stream as the viewer's follower reads it (``GET /answer/events``)."""

    def __init__(self, server: AnswerServer) -> None:
        self.socket = socket.create_connection(("127.0.0.1", server.port), timeout=60)
        self.socket.sendall(
            f"GET /answer/events HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\n"
            "Origin: http://127.0.0.1:8080\r\n\r\n".encode()
        )
        self.reader = self.socket.makefile("rb")
        assert self.reader.readline().startswith(b"HTTP/1.1 200")
        while self.reader.readline() != b"\r\n":
            pass

    def next(self) -> Any:
        """The next answer (keep-alive comments skipped; at most a minute)."""
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            line = self.reader.readline()
            assert line, "the stream ended"
            if line.startswith(b"data: "):
                return json.loads(line[len(b"data: ") :])
        raise AssertionError("no answer on the stream within a minute")

    def close(self) -> None:
        self.reader.close()
        self.socket.close()


SERVING = [(robots, layouts) for robots, layouts in FLEETS if layouts]


# The watcher serves its answer (``--serve``) in the fleets that write layouts only; the fleet
# fixture is shared with the tests above (same parameters, same module-scoped fleet).
@pytest.mark.parametrize(
    "fleet", SERVING, indirect=True, ids=[f"{n} robots, layouts" for n, _ in SERVING]
)
def test_active_robot_message_to_served_event(benchmark: BenchmarkFixture, fleet: Fleet) -> None:
    assert fleet.server is not None
    stream = Stream(fleet.server)
    latencies: list[float] = []
    titles = fleet.team_titles()
    try:
        stream.next()  # the current answer, sent first

        def switch() -> None:
            robot = next(fleet.order)
            start = time.perf_counter()
            fleet.operator.activate(robot)
            while (answer := stream.next()) is None or answer.get("robot") != robot:
                pass
            latencies.append(time.perf_counter() - start)
            assert answer["configuration"] == fleet.expected(robot)
            fleet.check_layouts(robot, answer, titles)

        benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
            switch, setup=pause, rounds=SWITCHES
        )
    finally:
        stream.close()
    report(benchmark, f"active robot -> served event stream ({_which(fleet)})", latencies)


def test_new_robots_description_to_its_first_event(
    benchmark: BenchmarkFixture, fleet: Fleet
) -> None:
    from cyclonedds.pub import DataWriter
    from cyclonedds.topic import Topic

    from tests.live.ros2_robot import LATCHED

    latencies: list[float] = []
    counter = itertools.count()
    writers: list[Any] = []

    def describe() -> None:
        name = f"/new{next(counter)}"
        participant = fleet.operator.participant
        writer: Any = DataWriter(
            participant,
            Topic(participant, f"rt{name}/robot_description", fleet.operator.String),
            qos=LATCHED,
        )
        writers.append(writer)
        start = time.perf_counter()
        writer.write(fleet.operator.String(drone_text()))
        at, data = fleet.until_event(name, "robot_added")
        latencies.append(at - start)
        # Only its description (no camera topic yet): identified as a UAV, without sensors.
        assert (data["kinematic_type"], data["error"], data["sensors"]) == ("UAV", None, [])

    benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        describe, rounds=DESCRIPTIONS
    )
    report(benchmark, f"new robot's description -> robot_added ({_which(fleet)})", latencies)


class Echo:
    """The peer: a process of its own on the domain (as the robots are) that answers each
    String on ``/bench/ping`` with the same String on ``/bench/pong``, from a data-available
    listener, with the watcher's QoS."""

    def __init__(self, fleet: Fleet) -> None:
        from cyclonedds.pub import DataWriter
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        from tests.live.ros2_robot import LATCHED

        self.process = EmulatedRobot(fleet.domain, dict(os.environ))
        self.process.send(echo="/bench/ping", to="/bench/pong")
        operator = fleet.operator.participant
        self.string = fleet.operator.String
        self.ping: Any = DataWriter(
            operator, Topic(operator, "rt/bench/ping", self.string), qos=LATCHED
        )
        self.pong: Any = DataReader(
            operator, Topic(operator, "rt/bench/pong", self.string), qos=LATCHED
        )

    def round_trip(self, text: str) -> list[str]:
        """Ping with ``text``; the answers read until one is ``text``."""
        self.ping.write(self.string(text))
        answers: list[str] = []
        while text not in answers:
            answers += [s.data for s in self.pong.take(N=64) if hasattr(s, "data")]
            if text not in answers:
                time.sleep(0.0005)  # the operator polls its answer the same way in ``switch``
        return answers

    def close(self) -> None:
        self.ping.__del__()
        self.pong.__del__()
        self.process.kill()


def test_bare_dds_echo_round_trip_peer(benchmark: BenchmarkFixture, fleet: Fleet) -> None:
    echo = Echo(fleet)
    counter = itertools.count()
    latencies: list[float] = []
    try:
        echo.round_trip("warm-up")  # discovery between the two participants, untimed

        def round_trip() -> None:
            text = f"ping {next(counter)}"
            start = time.perf_counter()
            answers = echo.round_trip(text)
            latencies.append(time.perf_counter() - start)
            assert answers == [text]  # the echo, once, and nothing stale before it

        benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
            round_trip, setup=pause, rounds=SWITCHES
        )
    finally:
        echo.close()
    report(
        benchmark, f"bare DDS echo round trip, another process (peer; {_which(fleet)})", latencies
    )
