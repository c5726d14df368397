"""Solving the article's cases: every engine in-process, and the whole command as a process.

Targets (issue 4): Case 3 solved in-process, enumeration and partition, under 1 ms;
``teleop-ui solve rules/teams/case3.yaml`` as a whole process under 0.3 s.
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver import Solution, load_team, solve
from tests.conftest import ROOT, TEAMS

# SPEC.md sections 4-5: what the article's stated rules give for each case.
EXPECTED = {"figure8": (90, 8), "case1": (30, 6), "case2": (110, 18), "case3": (872, 102)}


def totals(solution: Solution) -> tuple[int, int]:
    return solution.totals.valid_robots, solution.totals.ui_configurations


@pytest.mark.parametrize("case", sorted(EXPECTED))
def test_solve_article_case(benchmark: BenchmarkFixture, case: str) -> None:
    team = load_team(TEAMS / f"{case}.yaml")
    solution = benchmark(solve, team)
    assert totals(solution) == EXPECTED[case]


@pytest.mark.parametrize("engine", ["structure", "fast", "csp"])
def test_solve_case3_in_process(benchmark: BenchmarkFixture, engine: str) -> None:
    team = load_team(TEAMS / "case3.yaml")
    solution = benchmark(solve, team, engine=engine)
    assert totals(solution) == EXPECTED["case3"]
    assert len(solution.configurations) == 102


def test_solve_case3_whole_process(benchmark: BenchmarkFixture) -> None:
    # As a user runs it after `pip install .`: bytecode is cached (pip compiles it), so let
    # Python write and use it even where the environment turns that off.
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    command = [sys.executable, "-m", "solver", "solve", "rules/teams/case3.yaml"]
    subprocess.run(command, cwd=ROOT, env=environment, check=True, capture_output=True)

    def run() -> str:
        return subprocess.run(
            command, cwd=ROOT, env=environment, check=True, capture_output=True, text=True
        ).stdout

    output = benchmark(run)
    assert "total                        872                102" in output
