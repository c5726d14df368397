"""Benchmark: reading grows with the values per characteristic, no faster (issue 29, item 4).

A rule set of V sensor values in V/4 components of four, one constraint forbidding the first half of
the values for ``K0`` (a list of V/2 values), and a team whose ``K0`` lists all V values and whose
``K1`` names all V/4 components and leaves out the first quarter of the values (``not:``, V/4 of
them): every list a reader walks is as long as the domain. ``count`` (read the team and its rule
set, count) and ``check`` (read the rule set, check it) at V = 5,120, 10,240 and 20,480, in CPU
time; the claim is the growth per doubling (``tools/bench_table.py``; linear: 2).

Both were 3.4-3.7x per doubling at 10,240 values: a team's value list was checked for duplicates
against a list, and Python's cycle collector walked every object read so far each time the old
generation had grown by a quarter.

What each must say follows from how the files are built: ``K0`` keeps the V/2 values of the
second half (V/8 components), ``K1`` the 3V/4 values after the first quarter (3V/16
components); every value is its own robot. ``check`` finds the first half dead for ``K0``.

Run: ``python -m pytest benchmarks/bench_read_growth.py``.
"""

from __future__ import annotations

import itertools
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver import load_team, solve
from solver.check import check_files

SIZES = (5_120, 10_240, 20_480)
# CPU time of this process: the growth ratio should not move with the machine's other work.
pytestmark = pytest.mark.benchmark(timer=time.process_time)


def _names(prefix: str, numbers: range) -> str:
    return ", ".join(f"{prefix}{i}" for i in numbers)


def _write(folder: Path, values: int) -> Path:
    components = "".join(
        f"      - {{name: G{g}, values: [{_names('S', range(4 * g, 4 * g + 4))}]}}\n"
        for g in range(values // 4)
    )
    (folder / "rules.yaml").write_text(
        "name: many values\ncharacteristics:\n"
        "  kinematic_type:\n    values: [K0, K1]\n"
        f"  sensor:\n    values: [{_names('S', range(values))}]\n    components:\n{components}"
        "constraints:\n"
        f"  - forbid: {{kinematic_type: K0, sensor: [{_names('S', range(values // 2))}]}}\n",
        encoding="utf-8",
    )
    team = folder / "team.yaml"
    team.write_text(
        "rules: rules.yaml\nteam:\n"
        f"  K0: {{sensor: [{_names('S', range(values))}]}}\n"
        f"  K1: {{sensor: {{component: [{_names('G', range(values // 4))}], "
        f"not: [{_names('S', range(values // 4))}]}}}}\n",
        encoding="utf-8",
    )
    return team


def _count(team_file: Path) -> tuple[int, int]:
    totals = solve(load_team(team_file), count_only=True).totals
    return totals.valid_robots, totals.ui_configurations


def _edited(team_file: Path) -> Callable[[], tuple[tuple[Path], dict[str, object]]]:
    """A setup that changes the rule file's text before each round: a process keeps the rule
    sets it has read while their text is unchanged (up to 256 KB each), so without it the
    smaller sizes would time a kept rule set and the largest a read one."""
    rules = team_file.parent / "rules.yaml"
    text = rules.read_text(encoding="utf-8")
    rounds = itertools.count()

    def setup() -> tuple[tuple[Path], dict[str, object]]:
        rules.write_text(f"{text}# round {next(rounds)}\n", encoding="utf-8")
        return (team_file,), {}

    return setup


@pytest.mark.parametrize("values", SIZES, ids=[str(v) for v in SIZES])
def test_count_growth_in_values(benchmark: BenchmarkFixture, tmp_path: Path, values: int) -> None:
    team_file = _write(tmp_path, values)
    # pytest-benchmark ships no type hints.
    counted = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        _count, setup=_edited(team_file), rounds=5, iterations=1
    )
    assert counted == (values // 2 + 3 * values // 4, values // 8 + 3 * values // 16)


@pytest.mark.parametrize("values", SIZES, ids=[str(v) for v in SIZES])
def test_check_growth_in_values(benchmark: BenchmarkFixture, tmp_path: Path, values: int) -> None:
    _write(tmp_path, values)
    report = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        check_files, args=([tmp_path / "rules.yaml"],), rounds=5, iterations=1
    )
    dead = {f.location.path for f in report.findings if f.check == "dead-for-type"}
    assert dead == {"characteristics.kinematic_type.values[0]"}
