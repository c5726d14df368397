"""Exact counting without enumeration, at scales no enumeration reaches.

Target (issue 4): a team of 10^12 valid robots counted exactly in under 10 ms.
"""

from __future__ import annotations

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
