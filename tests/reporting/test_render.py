"""Rendering solutions (solver.reporting.render): runs of counts, safe CSV cells, how counts were
made."""

from __future__ import annotations

from solver import load_team, solve
from solver.core.contracts import integer_runs
from solver.reporting.render import csv_cell, method_text
from tests.conftest import TEAMS


def test_sorted_numbers_read_as_runs_of_consecutive_ones() -> None:
    assert integer_runs([1, 2, 3, 7, 9, 10]) == [(1, 3), (7, 7), (9, 10)]
    assert integer_runs([]) == []


def test_a_cell_that_would_read_as_a_formula_is_neutralised() -> None:
    assert csv_cell("=1+2") == "'=1+2"
    assert csv_cell("Camera") == "Camera"
    assert csv_cell(3) == 3


def test_the_method_says_which_engine_counted_in_words() -> None:
    team = load_team(TEAMS / "case3.yaml")
    assert method_text(solve(team)) == "counted from the rules' structure, no robots enumerated"
    assert (
        method_text(solve(team, engine="csp"))
        == "robots enumerated with python-constraint (csp engine)"
    )
