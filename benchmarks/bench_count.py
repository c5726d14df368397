"""Exact counting without enumeration, at scales no enumeration reaches.

Target (issue 4): a team of 10^12 valid robots counted exactly in under 10 ms.

Target (issue 42, item 5): in-process ``count`` of Case 3 within 10x the closed form it
computes. In-process ``count`` is what ``teleop-ui count`` does once the team is read:
``solve(team, count_only=True)``. The peer, :func:`closed_form`, is what a user would write
knowing the article's rule set has no constraints and no overlapping components (SPEC.md
section 3): per kinematic type, robots are the product of the numbers of selected values and
UI configurations the product of the numbers of components those values reach; the team's
figures are the sums. Both are given the same team, already read (reading is common to both
and not timed); both are timed in CPU time, alternating, in one process.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from pathlib import Path

import pytest
import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.conftest import Scale, Scaled
from solver import Team, load_team, solve

SCALES = {
    "1e5": Scale(types=1, motions=10, sensors=100, groups=10, counts=100, arrangements=5),
    "1e7": Scale(
        types=10, motions=10, sensors=100, groups=10, counts=1_000, arrangements=5, forbidden=100
    ),
    "1e9": Scale(
        types=10,
        motions=10,
        sensors=1_000,
        groups=20,
        counts=10_000,
        arrangements=8,
        forbidden=1_000,
    ),
    "1e12": Scale(
        types=100,
        motions=100,
        sensors=1_000,
        groups=20,
        counts=100_000,
        arrangements=10,
        forbidden=5_000,
    ),
}


@pytest.mark.parametrize("size", list(SCALES))
def test_count_scaled_team(benchmark: BenchmarkFixture, scaled: Scaled, size: str) -> None:
    scale = SCALES[size]
    team: Team = scaled(scale)
    solution = benchmark(solve, team, count_only=True)
    assert solution.totals.valid_robots == scale.robots
    assert solution.totals.ui_configurations == scale.configurations
    assert {t.method for t in solution.by_type} == {"structure"}


def test_count_10_to_the_30_exactly(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    # 10 kinematic types x 29 characteristics of 10 values (two components each): 10^30
    # robots, 10 x 2^29 configurations. Only Python integers hold such counts exactly.
    characteristics: dict[str, object] = {
        "kinematic_type": {"values": [f"T{i}" for i in range(10)]}
    }
    for i in range(29):
        values = [f"v{i}_{k}" for k in range(10)]
        characteristics[f"c{i}"] = {
            "values": values,
            "components": [
                {"name": "low", "values": values[:5]},
                {"name": "high", "values": values[5:]},
            ],
        }
    (tmp_path / "rules.yaml").write_text(
        yaml.safe_dump({"characteristics": characteristics}, sort_keys=False), encoding="utf-8"
    )
    (tmp_path / "team.yaml").write_text(
        yaml.safe_dump({"rules": "rules.yaml", "team": {f"T{i}": {} for i in range(10)}}),
        encoding="utf-8",
    )
    team = load_team(tmp_path / "team.yaml")
    solution = benchmark(solve, team, count_only=True)
    assert solution.totals.valid_robots == 10**30
    assert solution.totals.ui_configurations == 10 * 2**29


def closed_form(team: Team) -> tuple[int, int]:
    """(valid robots, UI configurations) of a team over a rule set without constraints whose
    every value is in one component: sums over the types of products over the
    characteristics."""
    rules = team.rules
    robots = configurations = 0
    for selection in team.selections:
        type_robots = type_configurations = 1
        for characteristic, domain in zip(rules.characteristics, selection.domains, strict=True):
            position = characteristic.positions
            reached = {characteristic.membership[position[v]][0] for v in domain}
            type_robots *= len(domain)
            type_configurations *= len(reached)
        robots += type_robots
        configurations += type_configurations
    return robots, configurations


def counted(team: Team) -> tuple[int, int]:
    """What ``teleop-ui count`` computes once the team is read."""
    totals = solve(team, count_only=True).totals
    return totals.valid_robots, totals.ui_configurations


def cpu_per_call(call: Callable[[Team], tuple[int, int]], team: Team, calls: int) -> float:
    """CPU seconds per call of ``call(team)``, over ``calls`` calls."""
    start = time.process_time()
    for _ in range(calls):
        call(team)
    return (time.process_time() - start) / calls


@pytest.mark.parametrize("name", ["case1", "case2", "case3"])
def test_the_closed_form_peer_reads_the_teams_selection(name: str) -> None:
    # The peer is general over the selection (it returns no constants): it agrees with the
    # tool on the article's three teams, and on Case 3 with the figures SPEC.md gives.
    team = load_team(name)
    assert closed_form(team) == counted(team)
    if name == "case3":
        assert closed_form(team) == (872, 102)


def test_count_of_case_3_against_its_closed_form(benchmark: BenchmarkFixture) -> None:
    team = load_team("case3")
    assert team.rules.constraints == ()
    assert all(c.is_partition for c in team.rules.characteristics)
    assert counted(team) == closed_form(team) == (872, 102)
    rounds, calls = (1, 50) if benchmark.disabled else (15, 300)
    tool: list[float] = []
    peer: list[float] = []

    def alternating() -> None:
        for index in range(rounds):
            pair = [(tool, counted), (peer, closed_form)]
            for kept, call in pair if index % 2 == 0 else pair[::-1]:
                kept.append(cpu_per_call(call, team, calls))

    benchmark.pedantic(alternating, rounds=1, iterations=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    ratio = statistics.median(tool) / statistics.median(peer)
    benchmark.extra_info.update(
        {
            "count_cpu_us": round(statistics.median(tool) * 1e6, 1),
            "closed_form_cpu_us": round(statistics.median(peer) * 1e6, 1),
            "ratio_to_closed_form": round(ratio, 2),
            # The same as peer / ours, as tools/bench_targets.py reads every target.
            "closed_form_speedup": round(1 / ratio, 3),
            "rounds": rounds,
            "calls_per_round": calls,
        }
    )
    if not benchmark.disabled:
        print(
            f"\ncount of Case 3 in-process: {statistics.median(tool) * 1e6:.1f} us CPU, closed "
            f"form {statistics.median(peer) * 1e6:.1f} us; ratio {ratio:.2f}x (target <= 10x)"
        )
