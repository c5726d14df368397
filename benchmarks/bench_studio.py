"""Latency of the design studio: a change of selection answered over HTTP, beside ``solve``.

A real studio (``teleop-ui studio TEAM --port 0``, its own process, loopback) is asked what
its page asks on every click: ``GET /api/solve?<selection>`` (the counts of
``solve --count-only --format json``), one persistent connection as a browser keeps. Each
change removes one motion control from one kinematic type or puts it back, under a team name
of its own, so no answer comes from the studio's cache (undo does, and is faster). Two teams:

* the article's Case 3 (872 robots, 102 configurations; issue 25's target: 100 ms);
* a generated team of 9,990,000 robots (10 types x 10 motion controls x 100 sensor types in
  10 groups x 1..1,000 sensors in 5 arrangements, one constraint removing 100 robots per type
  and motion control; target 100 ms too).

The peer, in the same run: ``solve(team, count_only=True)`` in-process on the same teams, as
many times. The ratio (API p50 / solve p50) is what one answer over HTTP costs beyond the
library: parsing the address, reading the selection as a team file, solving, JSON, HTTP.

Every answer is checked against counts computed here from how the team was built (SPEC.md
section 4's closed form), never from the code under test. A third measure, reported only:
the radar chart of a new selection (matplotlib, the code of ``report``), which is drawn after
the counts and is not part of the 100 ms.

Run: ``python -m pytest benchmarks/bench_studio.py -s -p no:cacheprovider``.
"""

from __future__ import annotations

import http.client
import json
import math
import statistics
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from urllib.parse import parse_qsl, urlencode, urlsplit

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.bench_count import SCALES
from benchmarks.latency import report
from solver import Team, load_team, solve
from solver.studio.selection import parse_query, query_of, team_of
from tests.studio.conftest import Server, stop, studio_process

CHANGES = 60

# The article's sensor groups and arrangements (SPEC.md section 3), for the closed form.
GROUPS = {
    "2D Camera": 1, "3D Camera": 1, "360 Camera": 2, "Speaker": 3, "Microphone": 3,
    "Force Sensor": 4, "2D Scanning": 5, "3D Scanning": 5, "LIDAR": 5, "RGB-D Camera": 5,
}  # fmt: skip
ARRANGEMENT_STARTS = (1, 6, 11, 16, 26)
CASE_3 = {  # motion controls, sensor types, maximum sensors (SPEC.md section 5)
    "UAV": (["Flight", "Waypoint"], ["2D Camera", "360 Camera", "RGB-D Camera"], 5),
    "UGV": (["Driving", "Waypoint"], ["2D Camera", "LIDAR", "Speaker", "Microphone"], 10),
    "Mobile Manipulator": (
        ["Joint", "Driving", "End Effector", "Waypoint"],
        ["2D Camera", "RGB-D Camera", "LIDAR", "Speaker", "Microphone", "Force Sensor"],
        13,
    ),
    "Humanoid": (
        ["Joint", "Walking", "Waypoint"],
        ["2D Camera", "3D Camera", "LIDAR", "RGB-D Camera", "Speaker", "Microphone"],
        25,
    ),
}


def case3_counts(removed: tuple[str, str] | None) -> tuple[int, int]:
    """Case 3's robots and configurations with one (type, motion control) removed."""
    robots = configurations = 0
    for kinematic_type, (motions, sensors, most) in CASE_3.items():
        kept = [m for m in motions if (kinematic_type, m) != removed]
        arrangements = sum(1 for start in ARRANGEMENT_STARTS if start <= most)
        robots += len(kept) * len(sensors) * most
        configurations += len(kept) * len({GROUPS[s] for s in sensors}) * arrangements
    return robots, configurations


@dataclass(frozen=True)
class Change:
    query: str
    robots: int
    configurations: int


def case3_changes() -> list[Change]:
    team = load_team("case3")
    base = query_of(team, "paper")
    removals = [(t, m) for t, (motions, _, _) in CASE_3.items() for m in motions]
    changes = []
    for index in range(CHANGES):
        removed = removals[(index // 2) % len(removals)] if index % 2 == 0 else None
        pairs = [
            p for p in base if removed is None or p != (f"{removed[0]}.motion_control", removed[1])
        ]
        # A name of its own: no change is answered from the studio's cache.
        pairs = [p for p in pairs if p[0] != "name"] + [("name", f"change {index}")]
        changes.append(Change(urlencode(pairs), *case3_counts(removed)))
    return changes


def scaled_changes(team: Team) -> list[Change]:
    scale = SCALES["1e7"]
    per_motion = scale.sensors * scale.counts - scale.forbidden
    per_motion_configurations = scale.groups * scale.arrangements
    changes = []
    for index in range(CHANGES):
        pairs = [
            ("rules", "start"),
            ("name", f"change {index}"),  # a name of its own: nothing from the cache
            *(("type", f"T{t}") for t in range(scale.types)),
        ]
        robots, configurations = scale.robots, scale.configurations
        if index % 2 == 0:
            # Type T_k keeps every motion control but one.
            kind, dropped = (index // 2) % scale.types, (index // 2) % scale.motions
            pairs += [
                (f"T{kind}.motion_control", f"M{m}") for m in range(scale.motions) if m != dropped
            ]
            robots -= per_motion
            configurations -= per_motion_configurations
        changes.append(Change(urlencode(pairs), robots, configurations))
    return changes


class Client:
    """One keep-alive connection to the studio, as a browser's page keeps."""

    def __init__(self, server: Server) -> None:
        where = urlsplit(server.url)
        self.connection = http.client.HTTPConnection(where.hostname or "", where.port, timeout=300)

    def get(self, path: str) -> bytes:
        self.connection.request("GET", path)
        response = self.connection.getresponse()
        body = response.read()
        assert response.status == 200, body[:500]
        return body

    def close(self) -> None:
        self.connection.close()


@pytest.fixture(scope="module")
def scaled_team(tmp_path_factory: pytest.TempPathFactory) -> Team:
    return SCALES["1e7"].team(tmp_path_factory.mktemp("studio-scale"))


@pytest.fixture(scope="module")
def server(scaled_team: Team, tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    started = studio_process(scaled_team.file, tmp_path=tmp_path_factory.mktemp("studio"))
    yield started
    stop(started.process)


def timed(changes: list[Change], ask: Callable[[Change], tuple[int, int]]) -> list[float]:
    latencies = []
    for change in changes:
        start = time.perf_counter()
        counts = ask(change)
        latencies.append(time.perf_counter() - start)
        assert counts == (change.robots, change.configurations), change.query
    return latencies


def percentile(latencies: list[float], share: float) -> float:
    ordered = sorted(latencies)
    return ordered[min(len(ordered) - 1, math.ceil(share * len(ordered)) - 1)]


def compare(
    benchmark: BenchmarkFixture,
    name: str,
    server: Server,
    changes: list[Change],
    team_for: Callable[[Change], Team],
) -> None:
    client = Client(server)

    def over_http(change: Change) -> tuple[int, int]:
        totals = json.loads(client.get(f"/api/solve?{change.query}"))["totals"]
        return totals["valid_robots"], totals["ui_configurations"]

    def in_process(change: Change) -> tuple[int, int]:
        totals = solve(team_for(change), count_only=True).totals
        return totals.valid_robots, totals.ui_configurations

    try:
        over_http(changes[0])  # the studio's first answer loads its modules
        api: list[float] = []
        benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
            lambda: api.extend(timed(changes, over_http)), rounds=1, iterations=1
        )
    finally:
        client.close()
    peer = timed(changes, in_process)
    ratio = statistics.median(api) / statistics.median(peer)
    benchmark.extra_info.update(
        {
            "peer_median_ms": round(statistics.median(peer) * 1000, 3),
            "peer_p95_ms": round(percentile(peer, 0.95) * 1000, 3),
            "ratio_to_solve": round(ratio, 1),
        }
    )
    report(
        benchmark,
        name,
        api,
        f"; in-process solve(count_only=True) median "
        f"{statistics.median(peer) * 1000:.2f} ms, p95 {percentile(peer, 0.95) * 1000:.2f} ms"
        f"; API / solve = {ratio:.1f}x",
    )


def test_studio_answers_a_change_of_case_3(benchmark: BenchmarkFixture, server: Server) -> None:
    rules = load_team("case3").rules
    changes = case3_changes()
    # Teams are read before the peer is timed: it times solve alone.
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, "paper"), rules) for c in changes
    }
    compare(
        benchmark,
        "studio: change of selection, Case 3",
        server,
        changes,
        lambda change: teams[change.query],
    )


def test_studio_answers_a_change_of_ten_million_robots(
    benchmark: BenchmarkFixture, server: Server, scaled_team: Team
) -> None:
    rules = scaled_team.rules
    changes = scaled_changes(scaled_team)
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, "start"), rules) for c in changes
    }
    compare(
        benchmark,
        "studio: change of selection, 9,990,000 robots",
        server,
        changes,
        lambda change: teams[change.query],
    )


def test_studio_draws_the_radar_chart_of_a_new_selection(
    benchmark: BenchmarkFixture, server: Server
) -> None:
    client = Client(server)
    base = [p for p in query_of(load_team("case3"), "paper") if p[0] != "UAV.sensor_count.max"]
    latencies: list[float] = []

    def draw_all() -> None:
        for most in range(1, 11):  # ten selections never drawn before
            start = time.perf_counter()
            body = client.get(
                f"/api/charts/radar.svg?{urlencode([*base, ('UAV.sensor_count.max', str(most))])}"
            )
            latencies.append(time.perf_counter() - start)
            assert body.startswith(b"<?xml")
            assert b"<svg" in body[:2000]

    try:
        benchmark.pedantic(draw_all, rounds=1, iterations=1)  # type: ignore[no-untyped-call]
    finally:
        client.close()
    report(benchmark, "studio: radar chart of a new selection, Case 3 (matplotlib)", latencies)
