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
section 4's closed form), never from the code under test.

Charts, the same way: a change answered as the page answers it, ``GET /api/solve`` then
``GET /api/charts/radar.svg`` for the same selection (the radar chart's title must give the
closed-form counts too), timed apart and together, on both teams. The peers, in the same run and
in-process on the same teams: ``solve`` plus the chart written as SVG
(:func:`solver.reporting.svg.chart_svg`), and the same chart drawn by matplotlib (what the
studio did before, and what ``report`` still does; a few changes only, it is slow). The Charts
page's other two charts (bars, component matrix; the matrix tallied by structure, no
configuration listed) are reported for new selections of both teams, beside the same chart of
the same team in-process (``solve(count_only=True)`` then :func:`~solver.reporting.svg.chart_svg`)
and the matrix of the listed configurations (``solve`` then ``chart_svg``: what the studio drew
before).

Run: ``python -m pytest benchmarks/bench_studio.py -s -p no:cacheprovider``.
"""

from __future__ import annotations

import http.client
import json
import math
import re
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
from solver.reporting.plot import figure_bytes, radar_figure
from solver.reporting.svg import chart_svg
from solver.studio.security import cookie_name
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


def case3_changes(label: str = "change") -> list[Change]:
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
        pairs = [p for p in pairs if p[0] != "name"] + [("name", f"{label} {index}")]
        changes.append(Change(urlencode(pairs), *case3_counts(removed)))
    return changes


def scaled_changes(team: Team, label: str = "change") -> list[Change]:
    scale = SCALES["1e7"]
    per_motion = scale.sensors * scale.counts - scale.forbidden
    per_motion_configurations = scale.groups * scale.arrangements
    changes = []
    for index in range(CHANGES):
        pairs = [
            ("rules", "start"),
            ("name", f"{label} {index}"),  # a name of its own: nothing from the cache
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
        # The cookie a browser keeps after opening the printed address.
        self.headers = {"cookie": f"{cookie_name(where.port or 0)}={server.token}"}

    def get(self, path: str) -> bytes:
        self.connection.request("GET", path, headers=self.headers)
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


TITLE = re.compile(rb"<title>.*: (\d+) valid robots?, (\d+) UI configurations?")


def chart_counts(svg: bytes) -> tuple[int, int]:
    """The counts a chart's title gives (``<title>Case 3: 872 valid robots, ...</title>``)."""
    found = TITLE.search(svg[:4000])
    assert found is not None, svg[:400]
    return int(found.group(1)), int(found.group(2))


def ms(latencies: list[float], share: float = 0.5) -> str:
    return f"{percentile(latencies, share) * 1000:.1f} ms"


def with_charts(
    benchmark: BenchmarkFixture,
    name: str,
    server: Server,
    changes: list[Change],
    team_for: Callable[[Change], Team],
    *,
    drawn_by_matplotlib: int,
) -> None:
    """Each change as the selection page answers it: the totals, then the radar chart."""
    client = Client(server)
    totals: list[float] = []
    charts: list[float] = []
    both: list[float] = []

    def answer(change: Change) -> None:
        start = time.perf_counter()
        data = json.loads(client.get(f"/api/solve?{change.query}"))["totals"]
        counted = time.perf_counter()
        svg = client.get(f"/api/charts/radar.svg?{change.query}")
        drawn = time.perf_counter()
        expected = (change.robots, change.configurations)
        assert (data["valid_robots"], data["ui_configurations"]) == expected, change.query
        assert chart_counts(svg) == expected, change.query
        totals.append(counted - start)
        charts.append(drawn - counted)
        both.append(drawn - start)

    try:
        answer(changes[0])  # the studio's first answer loads its modules
        for kept in (totals, charts, both):
            kept.clear()

        def answer_all() -> None:
            for change in changes[1:]:
                answer(change)

        # pytest-benchmark has no type hints
        benchmark.pedantic(answer_all, rounds=1, iterations=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    finally:
        client.close()

    # The peers: the same teams in-process, the chart written as SVG; and drawn by matplotlib.
    def in_process(change: Change) -> tuple[int, int]:
        return chart_counts(chart_svg(solve(team_for(change), count_only=True), "radar"))

    peer = timed(changes[1:], in_process)

    def by_matplotlib(change: Change) -> tuple[int, int]:
        figure = radar_figure(solve(team_for(change), count_only=True))
        assert figure_bytes(figure, "svg").startswith(b"<?xml")  # drawn, glyphs and all
        title = figure.texts[0].get_text().encode()
        return chart_counts(b"<title>" + title)

    old = timed(changes[1 : 1 + drawn_by_matplotlib], by_matplotlib)
    benchmark.extra_info.update(
        {
            "totals_median_ms": round(percentile(totals, 0.5) * 1000, 1),
            "totals_p95_ms": round(percentile(totals, 0.95) * 1000, 1),
            "chart_median_ms": round(percentile(charts, 0.5) * 1000, 1),
            "chart_p95_ms": round(percentile(charts, 0.95) * 1000, 1),
            "peer_median_ms": round(percentile(peer, 0.5) * 1000, 2),
            "matplotlib_median_ms": round(percentile(old, 0.5) * 1000, 1),
            "matplotlib_changes": len(old),
        }
    )
    report(
        benchmark,
        name,
        both,
        f" (totals then radar chart); totals median {ms(totals)}, p95 {ms(totals, 0.95)}"
        f"; chart median {ms(charts)}, p95 {ms(charts, 0.95)}"
        f"; in-process solve + chart_svg median {ms(peer)}, p95 {ms(peer, 0.95)}"
        f"; the radar by matplotlib, in-process, median {ms(old)} ({len(old)} changes)"
        f"; HTTP chart / matplotlib = {percentile(charts, 0.5) / percentile(old, 0.5):.3f}",
    )


def test_studio_answers_a_change_of_case_3_with_its_radar_chart(
    benchmark: BenchmarkFixture, server: Server
) -> None:
    rules = load_team("case3").rules
    changes = case3_changes("charted")
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, "paper"), rules) for c in changes
    }
    with_charts(
        benchmark,
        "studio: change of selection with its radar chart, Case 3",
        server,
        changes,
        lambda change: teams[change.query],
        drawn_by_matplotlib=10,
    )


def test_studio_answers_a_change_of_ten_million_robots_with_its_radar_chart(
    benchmark: BenchmarkFixture, server: Server, scaled_team: Team
) -> None:
    rules = scaled_team.rules
    changes = scaled_changes(scaled_team, "charted")
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, "start"), rules) for c in changes
    }
    with_charts(
        benchmark,
        "studio: change of selection with its radar chart, 9,990,000 robots",
        server,
        changes,
        lambda change: teams[change.query],
        drawn_by_matplotlib=3,
    )


@pytest.mark.parametrize("team_name", ["case3", "1e7"])
@pytest.mark.parametrize("kind", ["bars", "matrix"])
def test_studio_draws_the_charts_pages_other_charts_of_a_new_selection(
    benchmark: BenchmarkFixture, server: Server, scaled_team: Team, kind: str, team_name: str
) -> None:
    changes = (
        case3_changes(f"{kind} page")
        if team_name == "case3"
        else scaled_changes(scaled_team, f"{kind} page")
    )[:20]
    rules = load_team("case3").rules if team_name == "case3" else scaled_team.rules
    rules_id = "paper" if team_name == "case3" else "start"
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, rules_id), rules) for c in changes
    }
    client = Client(server)
    latencies: list[float] = []

    def draw(change: Change) -> tuple[int, int]:
        start = time.perf_counter()
        svg = client.get(f"/api/charts/{kind}.svg?{change.query}")
        latencies.append(time.perf_counter() - start)
        return chart_counts(svg)

    try:
        draw(changes[0])
        latencies.clear()
        benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
            lambda: timed(changes[1:], draw), rounds=1, iterations=1
        )
    finally:
        client.close()

    def in_process(change: Change, *, listed: bool = False) -> tuple[int, int]:
        solution = solve(teams[change.query], count_only=not listed)
        return chart_counts(chart_svg(solution, kind))

    peer = timed(changes[1:], in_process)
    note = (
        f"; in-process solve(count_only=True) + chart_svg median {ms(peer)}, p95 {ms(peer, 0.95)}"
    )
    if kind == "matrix":
        old = timed(changes[1:], lambda change: in_process(change, listed=True))
        note += (
            f"; every configuration listed (solve + chart_svg) median {ms(old)}"
            f", p95 {ms(old, 0.95)}"
        )
    ratio = percentile(latencies, 0.5) / percentile(peer, 0.5)
    benchmark.extra_info.update(
        {
            "peer_median_ms": round(percentile(peer, 0.5) * 1000, 2),
            "peer_p95_ms": round(percentile(peer, 0.95) * 1000, 2),
            "ratio_to_solve": round(ratio, 1),
        }
    )
    report(
        benchmark,
        f"studio: {kind} chart of a new selection, {team_name}",
        latencies,
        f"{note}; HTTP / in-process = {ratio:.1f}x",
    )
