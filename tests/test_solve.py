"""Solving the article's teams under the shipped rule set."""

from __future__ import annotations

import pytest

from solver import load_team, solve
from tests.conftest import TEAMS


@pytest.mark.parametrize(("team", "robots", "configurations"), [
    ("figure8", 90, 8), ("case1", 30, 6), ("case2", 110, 18)])
def test_solve_reproduces_the_published_figures_of(team: str, robots: int,
                                                    configurations: int) -> None:
    solution = solve(load_team(TEAMS / f"{team}.yaml"))
    assert (solution.totals.valid_robots, solution.totals.ui_configurations) == \
        (robots, configurations)
