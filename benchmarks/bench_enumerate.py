"""Enumerating about 10^6 robots: the numpy engine beside python-constraint, and memory.

Targets (issue 4): fast enumeration with partitioning at least 50x the throughput of
python-constraint2's solution iterator on a team of about 10^6 robots; memory during
enumeration bounded by the number of UI configurations plus a fixed block, not the robots.
Issue 14 raises the first target to 200x (the ratio is in tools/bench_table.py's report): the
fast engine now enumerates the product of value classes (values the rules cannot tell apart),
each weighing the robots it stands for, so its cost follows classes and configurations.
"""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.conftest import Scale, Scaled
from solver import Team, load_team, solve
from solver.core.model import build_problem
from solver.engines.csp import partition as partition_csp
from solver.engines.fast import BLOCK
from solver.engines.fast import partition as partition_stream

# 10 motion controls x (100 sensor types x 1..1000 sensors - 100 forbidden) = 999,000 robots.
MILLION = Scale(
    types=1, motions=10, sensors=100, groups=10, counts=1_000, arrangements=5, forbidden=100
)


def test_enumerate_1e6_fast(benchmark: BenchmarkFixture, scaled: Scaled) -> None:
    team: Team = scaled(MILLION)
    solution = benchmark(solve, team, engine="fast")
    assert solution.totals.valid_robots == MILLION.robots == 999_000
    assert solution.totals.ui_configurations == MILLION.configurations
    assert {t.method for t in solution.by_type} == {"fast"}


def test_enumerate_1e6_csp(benchmark: BenchmarkFixture, scaled: Scaled) -> None:
    # The csp engine's own work on the same team: `solve --engine csp` refuses a type of more
    # than 100,000 robots (limit 'csp-robots', docs/security.md), so the engine is called
    # directly. One round: python-constraint takes seconds here, the point of the comparison.
    team: Team = scaled(MILLION)
    (selection,) = team.selections
    partition = benchmark.pedantic(  # type: ignore[no-untyped-call]  # untyped in pytest-benchmark
        partition_csp, args=(team.rules, selection), rounds=1, iterations=1
    )
    assert partition.valid_robots == MILLION.robots
    assert len(partition.classes) == MILLION.configurations


def test_iterate_1e6_python_constraint(benchmark: BenchmarkFixture, scaled: Scaled) -> None:
    # The bare solution iterator, no partitioning: the reference throughput of the issue.
    team: Team = scaled(MILLION)
    (selection,) = team.selections

    def iterate() -> int:
        problem = build_problem(team.rules, selection.domains)
        assert problem is not None
        return sum(1 for _ in problem.getSolutionIter())

    assert (
        benchmark.pedantic(  # type: ignore[no-untyped-call]  # untyped in pytest-benchmark
            iterate, rounds=1, iterations=1
        )
        == MILLION.robots
    )


def one_component_team(folder: Path, modes: int) -> Team:
    """Robots grow with ``modes`` while the configurations stay 10 x 5 and the block layout
    stays the same: every mode value is in one component, and modes lead the characteristics
    (the block is made of the trailing ones)."""
    rules = MILLION.rules()
    characteristics = rules["characteristics"]
    assert isinstance(characteristics, dict)
    values = [f"m{i}" for i in range(modes)]
    rules["characteristics"] = {
        "kinematic_type": characteristics["kinematic_type"],
        "mode": {"values": values, "components": [{"name": "any mode", "values": values}]},
        "motion_control": {"values": ["M0"]},
        "sensor_type": characteristics["sensor_type"],
        "sensor_count": characteristics["sensor_count"],
    }
    (folder / "rules.yaml").write_text(yaml.safe_dump(rules, sort_keys=False), encoding="utf-8")
    (folder / "team.yaml").write_text("rules: rules.yaml\nteam:\n  T0: {}\n", encoding="utf-8")
    return load_team(folder / "team.yaml")


def peak_bytes(team: Team) -> tuple[int, int]:
    (selection,) = team.selections
    tracemalloc.start()
    try:
        part = partition_stream(team.rules, selection)
        return tracemalloc.get_traced_memory()[1], part.valid_robots
    finally:
        tracemalloc.stop()


def test_enumeration_memory_does_not_grow_with_robots(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    (tmp_path / "small").mkdir()
    (tmp_path / "large").mkdir()
    small = one_component_team(tmp_path / "small", 10)
    large = one_component_team(tmp_path / "large", 100)
    small_peak, small_robots = peak_bytes(small)
    large_peak, large_robots = peak_bytes(large)
    assert (small_robots, large_robots) == (10 * 99_900, 100 * 99_900)
    # Ten times the robots, the same configurations and block: the same peak, give or take
    # the larger mode domain (a few kB).
    assert large_peak < small_peak * 1.1 + 64 * 1024
    assert large_peak < 16 * BLOCK * 8  # a few block-sized arrays, whatever the robot count
    (selection,) = large.selections
    part = benchmark.pedantic(  # type: ignore[no-untyped-call]  # untyped in pytest-benchmark
        partition_stream, args=(large.rules, selection), rounds=1, iterations=1
    )
    assert len(part.classes) == 10 * 5
