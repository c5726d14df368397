"""``teleop-ui count``: a rule set's whole design space, how it counted, and its formulas."""

from __future__ import annotations

import json

from tests.conftest import run_cli


def test_count_on_a_rule_set_counts_its_whole_design_space() -> None:
    data = json.loads(run_cli("count", "rules/paper.yaml", "-f", "json").stdout)
    assert data["totals"]["valid_robots"] == 6 * 6 * 10 * 50
    assert data["totals"]["ui_configurations"] == 900
    assert data["team"] == "every value of Mortimer et al. 2017"


def test_count_says_how_it_counted() -> None:
    lines = run_cli("count", "case1", "--engine", "csp").stdout.splitlines()
    assert lines[3].split() == ["UAV", "30", "6", "csp"]


def test_count_symbolic_json_from_the_command_line() -> None:
    data = json.loads(run_cli("count", "case2", "--symbolic", "-f", "json").stdout)
    assert data["by_type"][1]["valid_robots"] == "8*n_UGV"
    assert (
        data["totals"]["ui_configurations"] == "6*A_sensor_count(n_UAV) + 6*A_sensor_count(n_UGV)"
    )
    assert data["at_team_maxima"] == {
        "maxima": {"n_UAV": 5, "n_UGV": 10},
        "valid_robots": 110,
        "ui_configurations": 18,
        "equal_to_exact_count": True,
    }
