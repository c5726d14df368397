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

The peer over HTTP (issue 42, item 5: a change within 2x of it): a handwritten Starlette app
(:func:`peer_app`, a few lines) whose handler reads the same query into a team with the public
types (:class:`~solver.Team`, :class:`~solver.TypeSelection`), calls the same library function
the studio calls for that answer (``solve(team, count_only=True)``) and answers its JSON
(``Solution.to_dict()``, what the studio answers too), in a process of its own served by uvicorn
as the studio is (:func:`serve_peer`). Every change is asked of both, alternately, by the same
kind of client; the studio's and the peer's CPU time (their processes', from the kernel's
accounting) per change and their latency medians are reported with their ratios.

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
The peer alone: ``python -m benchmarks.bench_studio TEAM.yaml`` (prints its address).
"""

from __future__ import annotations

import functools
import http.client
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import parse_qsl, urlencode, urlsplit

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.bench_count import SCALES
from benchmarks.latency import report
from solver import RuleSet, Team, TypeSelection, load_team, solve
from solver.reporting.plot import figure_bytes, radar_figure
from solver.reporting.svg import chart_svg
from solver.studio.security import cookie_name
from solver.studio.selection import parse_query, query_of, team_of
from tests.conftest import ROOT
from tests.studio.conftest import Server, stop, studio_process

if TYPE_CHECKING:
    from starlette.applications import Starlette
    from starlette.requests import Request
    from starlette.responses import Response

CHANGES = 60
# Rounds of CHANGES new selections each, for the comparison with the peer over HTTP: the
# processes' CPU time is counted in clock ticks (10 ms), so a round alone is too short.
PEER_ROUNDS = 5

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


@dataclass(frozen=True)
class Peer:
    """The handwritten peer's process (:func:`serve_peer`) and its address."""

    url: str
    process: subprocess.Popen[str]


class Client:
    """One keep-alive connection to the studio (or the peer), as a browser's page keeps."""

    def __init__(self, server: Server | Peer) -> None:
        where = urlsplit(server.url)
        self.connection = http.client.HTTPConnection(where.hostname or "", where.port, timeout=300)
        # The cookie a browser keeps after opening the printed address (the peer asks none).
        self.headers = (
            {"cookie": f"{cookie_name(where.port or 0)}={server.token}"}
            if isinstance(server, Server)
            else {}
        )

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


def peer_app(rules: dict[str, RuleSet]) -> Starlette:
    """The peer: what a user would write to answer ``GET /api/solve?<selection>`` with the
    library (``rules``: the rule sets by the ids the query names, read once)."""
    from starlette.applications import Starlette
    from starlette.responses import JSONResponse
    from starlette.routing import Route

    def answer(request: Request) -> Response:
        query = request.query_params
        chosen: dict[str, list[str]] = {}
        for key, value in query.multi_items():
            chosen.setdefault(key, []).append(value)
        ruleset = rules[query["rules"]]
        selections = []
        for kinematic_type in chosen.get("type", []):
            domains: list[tuple[str | int, ...]] = []
            for characteristic in ruleset.characteristics:
                key = f"{kinematic_type}.{characteristic.name}"
                if characteristic.name == ruleset.team_key:
                    domains.append((kinematic_type,))
                elif key in chosen:
                    wanted = set(chosen[key])
                    domains.append(tuple(v for v in characteristic.values if str(v) in wanted))
                elif f"{key}.max" in chosen:
                    most = int(chosen[f"{key}.max"][0])
                    domains.append(tuple(v for v in characteristic.values if int(v) <= most))
                else:
                    domains.append(characteristic.values)
            selections.append(TypeSelection(kinematic_type, tuple(domains)))
        team = Team(query.get("name", "team"), "<query>", ruleset, tuple(selections))
        return JSONResponse(solve(team, count_only=True).to_dict())

    return Starlette(routes=[Route("/api/solve", answer)])


def serve_peer(team_file: str) -> None:
    """The peer in a process of its own, served by uvicorn (HTTP/1.1 by h11, as the studio
    is), its address printed once its socket listens: the rule sets of Case 3 (``paper``) and
    of ``team_file`` (``start``, as the studio names the rules it was started with)."""
    import uvicorn

    from solver.studio.server import bind

    rules = {"paper": load_team("case3").rules, "start": load_team(team_file).rules}
    sock = bind("127.0.0.1", 0)  # as the studio binds its socket (a TCP one: no Nagle delay)
    print(f"http://127.0.0.1:{sock.getsockname()[1]}/", flush=True)
    config = uvicorn.Config(
        peer_app(rules), http="h11", log_level="error", access_log=False, lifespan="off"
    )
    uvicorn.Server(config).run(sockets=[sock])


@pytest.fixture(scope="module")
def peer(scaled_team: Team) -> Iterator[Peer]:
    process = subprocess.Popen(
        [sys.executable, "-m", "benchmarks.bench_studio", scaled_team.file],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    assert process.stdout is not None
    url = process.stdout.readline().strip()
    try:
        assert url.startswith("http://"), "the peer did not start"
        yield Peer(url, process)
    finally:
        stop(process)


def cpu_seconds(process: subprocess.Popen[str]) -> float:
    """A process's CPU time so far (user and system, every thread), from the kernel."""
    fields = Path(f"/proc/{process.pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


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
    *,
    peer: Peer | None = None,
) -> None:
    """The studio's answers to ``changes`` over HTTP, then ``solve`` in-process on the same
    teams; with ``peer``, each change is also asked of the peer, alternately (which of the two
    is asked first changes with every change), and both processes' CPU time is counted."""
    clients = [Client(server)] + ([Client(peer)] if peer is not None else [])
    answered: list[list[float]] = [[] for _ in clients]  # latencies, per client
    cpu: list[float] = []  # CPU seconds per change, per process

    def over_http(change: Change, client: Client) -> tuple[int, int]:
        totals = json.loads(client.get(f"/api/solve?{change.query}"))["totals"]
        return totals["valid_robots"], totals["ui_configurations"]

    def in_process(change: Change) -> tuple[int, int]:
        totals = solve(team_for(change), count_only=True).totals
        return totals.valid_robots, totals.ui_configurations

    def measured() -> None:
        processes = [server.process] + ([peer.process] if peer is not None else [])
        started = [cpu_seconds(p) for p in processes]
        order = list(range(len(clients)))
        for change in changes:
            for n in order:
                answered[n] += timed([change], functools.partial(over_http, client=clients[n]))
            order.reverse()
        ended = [cpu_seconds(p) for p in processes]
        cpu.extend((end - start) / len(changes) for start, end in zip(started, ended, strict=True))

    try:
        for client in clients:
            over_http(changes[0], client)  # the first answer loads the server's modules
        benchmark.pedantic(measured, rounds=1, iterations=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    finally:
        for client in clients:
            client.close()
    api = answered[0]
    local = timed(changes, in_process)
    ratio = statistics.median(api) / statistics.median(local)
    benchmark.extra_info.update(
        {
            "peer_median_ms": round(statistics.median(local) * 1000, 3),
            "peer_p95_ms": round(percentile(local, 0.95) * 1000, 3),
            "ratio_to_solve": round(ratio, 1),
            "studio_cpu_ms": round(cpu[0] * 1000, 3),
        }
    )
    note = ""
    if peer is not None:
        by_peer = answered[1]
        over = statistics.median(api) / statistics.median(by_peer)
        # The kernel counts CPU time in ticks (10 ms): an untimed run's few changes may get none.
        cpu_ratio = cpu[0] / cpu[1] if cpu[0] and cpu[1] else math.nan
        benchmark.extra_info.update(
            {
                "http_peer_median_ms": round(statistics.median(by_peer) * 1000, 3),
                "http_peer_p95_ms": round(percentile(by_peer, 0.95) * 1000, 3),
                "ratio_to_http_peer": round(over, 2),
                "http_peer_cpu_ms": round(cpu[1] * 1000, 3),
                "cpu_ratio_to_http_peer": round(cpu_ratio, 2),
                # Peer / ours in CPU time, as tools/bench_targets.py reads every target.
                "starlette_over_studio": round(1 / cpu_ratio, 3),
            }
        )
        note = (
            f"; the Starlette peer over HTTP median {statistics.median(by_peer) * 1000:.2f} ms"
            f" (studio / peer = {over:.2f}x); CPU per change: studio {cpu[0] * 1000:.2f} ms,"
            f" peer {cpu[1] * 1000:.2f} ms ({cpu_ratio:.2f}x)"
        )
    report(
        benchmark,
        name,
        api,
        f"; in-process solve(count_only=True) median "
        f"{statistics.median(local) * 1000:.2f} ms, p95 {percentile(local, 0.95) * 1000:.2f} ms"
        f"; API / solve = {ratio:.1f}x{note}",
    )


def rounds(make: Callable[[str], list[Change]], benchmark: BenchmarkFixture) -> list[Change]:
    """:data:`PEER_ROUNDS` lists of new selections (one when not timed)."""
    count = 1 if benchmark.disabled else PEER_ROUNDS
    return [change for n in range(count) for change in make(f"change {n}")]


def test_studio_answers_a_change_of_case_3(
    benchmark: BenchmarkFixture, server: Server, peer: Peer
) -> None:
    rules = load_team("case3").rules
    changes = rounds(case3_changes, benchmark)
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
        peer=peer,
    )


def test_studio_answers_a_change_of_ten_million_robots(
    benchmark: BenchmarkFixture, server: Server, scaled_team: Team, peer: Peer
) -> None:
    rules = scaled_team.rules
    changes = rounds(lambda label: scaled_changes(scaled_team, label), benchmark)
    teams = {
        c.query: team_of(parse_query(parse_qsl(c.query), rules, "start"), rules) for c in changes
    }
    compare(
        benchmark,
        "studio: change of selection, 9,990,000 robots",
        server,
        changes,
        lambda change: teams[change.query],
        peer=peer,
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


if __name__ == "__main__":
    serve_peer(sys.argv[1])
