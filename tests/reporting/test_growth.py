"""The symbolic counts shown (solver.reporting.growth): each kinematic type's counts as formulas
of its maximum, as text, Markdown or JSON, checked against the exact count. Case 2's UAV has
2 controls x 3 sensor types (6 robots a count), its UGV 2 x 4 (8); the counts' arrangements
start at 1, 6, 11, 16 and 26 sensors (rules/paper.yaml)."""

from __future__ import annotations

import json

from solver import load_team, solve
from solver.reporting.growth import render_growth
from solver.solving.symbolic import formulas
from tests.conftest import TEAMS


def test_the_rendered_formulas_say_they_equal_the_exact_count() -> None:
    team = load_team(TEAMS / "case3.yaml")
    text = render_growth(formulas(team), solve(team, count_only=True))
    assert text.splitlines()[-1].endswith(
        "872 valid robots, 102 UI configurations (equal to the exact count)"
    )


def test_text_shows_each_types_formulas_and_the_arrangement_function() -> None:
    team = load_team(TEAMS / "case2.yaml")
    lines = render_growth(formulas(team), solve(team, count_only=True)).splitlines()
    assert lines[2] == (
        "A_sensor_count(n) = 1 for n <= 5, 2 for n <= 10, 3 for n <= 15, 4 for n <= 25, "
        "5 for n <= 50"
    )
    assert [line.split()[:2] for line in lines if line.startswith(("UAV", "UGV"))] == [
        ["UAV", "6*n_UAV"],
        ["UGV", "8*n_UGV"],
    ]
    assert lines[-1] == (
        "at the team's maxima (n_UAV = 5, n_UGV = 10): 110 valid robots, 18 UI configurations "
        "(equal to the exact count)"
    )


def test_markdown_shows_the_formulas_as_a_table_with_its_markup_escaped() -> None:
    team = load_team(TEAMS / "case2.yaml")
    text = render_growth(formulas(team), solve(team, count_only=True), "markdown")
    assert "| kinematic type | valid robots | UI configurations |" in text
    assert "| UGV | 8\\*n\\_UGV | 6\\*A\\_sensor\\_count(n\\_UGV) |" in text


def test_json_gives_each_types_formulas_and_the_check_at_the_teams_maxima() -> None:
    team = load_team(TEAMS / "case2.yaml")
    data = json.loads(render_growth(formulas(team), solve(team, count_only=True), "json"))
    assert [(t["kinematic_type"], t["symbol"], t["valid_robots"]) for t in data["by_type"]] == [
        ("UAV", "n_UAV", "6*n_UAV"),
        ("UGV", "n_UGV", "8*n_UGV"),
    ]
    assert data["functions"]["A_sensor_count"]["argument"] == "n"
    assert data["at_team_maxima"] == {
        "maxima": {"n_UAV": 5, "n_UGV": 10},
        "valid_robots": 110,
        "ui_configurations": 18,
        "equal_to_exact_count": True,
    }
