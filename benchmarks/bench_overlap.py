"""Benchmark: overlapping components, each value in two, as values per characteristic double.

Three characteristics of N values each, with components that are windows of four values
sliding by two (w_s holds values 2s .. 2s + 3), so every value but the first two and the last
two is in two components. From the construction alone: N^3 valid robots; a characteristic's
fewest windows serving all its values are the N / 4 disjoint ones (no window holds values
four apart, so values 0, 4, 8, ... need one each), and three characteristics need
(N / 4)^3 configurations: no cover of the product is smaller than the product of those
packings.

Counting (``solve(count_only=True)``, what ``teleop-ui count`` does) should grow by at most
2.5x per doubling of N: the three characteristics vary independently, so their covers are found
apart and multiplied, and the 64,000 or 512,000 robot classes are never listed. Solving lists
the configurations, which grow 8x per doubling: its ratio is reported beside that. It was 6.7 s
at 40 values and 141 s at 80 (x21), half of it a quadratic filter before a single program over
every class.

Run: ``python -m pytest benchmarks/bench_overlap.py``.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from solver import Team, load_team, solve

CHARACTERISTICS = 3


def rules(values: int) -> dict[str, object]:
    characteristics: dict[str, object] = {"kinematic_type": {"values": ["T0"]}}
    for c in range(CHARACTERISTICS):
        names = [f"c{c}v{i}" for i in range(values)]
        characteristics[f"c{c}"] = {
            "values": names,
            "components": [
                {"name": f"c{c}w{s}", "values": names[2 * s : 2 * s + 4]}
                for s in range(values // 2 - 1)
            ],
        }
    return {"name": f"windows over {values}", "characteristics": characteristics}


def team(folder: Path, values: int) -> Team:
    (folder / "rules.yaml").write_text(
        yaml.safe_dump(rules(values), sort_keys=False), encoding="utf-8"
    )
    (folder / "team.yaml").write_text("rules: rules.yaml\nteam:\n  T0: {}\n", encoding="utf-8")
    return load_team(folder / "team.yaml")


@pytest.fixture(scope="module")
def teams(tmp_path_factory: pytest.TempPathFactory) -> dict[int, Team]:
    made = {n: team(tmp_path_factory.mktemp(f"windows{n}"), n) for n in (20, 40, 80, 160)}
    solve(made[20])  # HiGHS and numpy imported once, outside the timings
    return made


@pytest.mark.parametrize("values", [20, 40, 80, 160])
def test_count_overlapping_windows(
    benchmark: BenchmarkFixture, teams: dict[int, Team], values: int
) -> None:
    solution = benchmark(solve, teams[values], count_only=True)
    assert solution.totals.valid_robots == values**CHARACTERISTICS
    assert solution.totals.ui_configurations == (values // 4) ** CHARACTERISTICS
    assert solution.totals.unserved_robots == 0


@pytest.mark.parametrize("values", [20, 40, 80])
def test_solve_overlapping_windows(
    benchmark: BenchmarkFixture, teams: dict[int, Team], values: int
) -> None:
    solution = benchmark(solve, teams[values])
    assert len(solution.configurations) == (values // 4) ** CHARACTERISTICS
    assert sum(c.robots for c in solution.configurations) == values**CHARACTERISTICS
    assert solution.proven_minimal
