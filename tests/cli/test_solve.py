"""``teleop-ui solve`` as a user runs it: the table, its formats and the list of
configurations, bad team files, the enumeration limit, and the charts it plots.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Callable
from pathlib import Path

import pytest

from solver import load_team, solve
from solver.reporting.plot import figure_bytes, matrix_figure
from tests.conftest import run_cli

WriteFile = Callable[[str, str], Path]


def test_solve_prints_the_per_type_table_and_the_bound() -> None:
    result = run_cli("solve", "rules/teams/case3.yaml")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "Case 3  (rules: Mortimer et al. 2017, rules/paper.yaml)"
    assert lines[3].split() == ["UAV", "30", "6", "5.00"]
    assert lines[7].split() == ["total", "872", "102", "8.55"]
    assert "bound T = 900 (6 x 6 x 5 x 5)" in lines
    assert "how: counted from the rules' structure, no robots enumerated" in lines
    assert lines[-2:] == [
        "published: 820 valid robots / 99 UI configurations (Mortimer et al. "
        "2017, Section 4 and Table 2)",
        "  NOT reproduced: these rules give 872 / 102",
    ]


def test_solve_json_follows_the_documented_contract() -> None:
    result = run_cli("solve", "rules/teams/case2.yaml", "--format", "json", "--list")
    data = json.loads(result.stdout)
    assert {
        "team",
        "rules",
        "bound",
        "by_type",
        "totals",
        "default_configuration",
        "configurations",
    } <= set(data)
    assert data["team"] == "Case 2"
    assert data["bound"] == 900
    assert data["by_type"][1] == {
        "kinematic_type": "UGV",
        "valid_robots": 80,
        "ui_configurations": 12,
        "reduction_ratio": 6.6667,
        "unserved_robots": 0,
        "method": "structure",
    }
    assert data["totals"]["valid_robots"] == 110
    assert data["default_configuration"] == 19
    first = data["configurations"][0]
    assert first["number"] == 1
    assert first["components"][3] == {
        "characteristic": "sensor_count",
        "component": "individual",
        "range": [1, 5],
        "clusters": [1, 5],
        "counts": [[1, 5]],
    }


def test_solve_lists_every_configuration_with_its_components() -> None:
    result = run_cli("solve", "rules/teams/case1.yaml", "--rules", "rules/paper.yaml", "--list")
    table = result.stdout.split("\n\n")[-1].splitlines()
    assert table[0].split()[:3] == ["#", "Robot", "Kinematic"]
    assert len(table) == 1 + 6
    assert table[1].split() == [
        "1",
        "UAV",
        "Flight",
        "visual",
        "display",
        "individual",
        "(1..5:",
        "1..5",
        "clusters)",
        "5",
    ]


def test_solve_csv_and_markdown_carry_the_same_counts() -> None:
    rows = list(csv.reader(io.StringIO(run_cli("solve", "case2", "-f", "csv").stdout)))
    assert rows[0] == ["kinematic_type", "valid_robots", "ui_configurations", "reduction_ratio"]
    assert rows[-1][:3] == ["total", "110", "18"]
    markdown = run_cli("solve", "case2", "-f", "markdown").stdout
    assert "| total | 110 | 18 | 6.11 |" in markdown


def test_output_is_identical_across_runs() -> None:
    first = run_cli("solve", "case3", "--list", "-f", "json").stdout
    assert first == run_cli("solve", "case3", "--list", "-f", "json").stdout


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("team: [unclosed\n", "t.yaml:2:1: YAML syntax error"),
        ("team:\n  UAV: {}\n  UAV: {}\n", "t.yaml:3:3: team.UAV: duplicate key 'UAV'"),
        ("team:\n  Quadruped: {}\n", "t.yaml:2:3: team.Quadruped: unknown robot kinematic type"),
        ("team:\n  UAV: {sensor_count: -1}\n", "maximum must be at least 1, got -1"),
        ("rules: none.yaml\nteam:\n  UAV: {}\n", "t.yaml:1:8: rules: cannot use rules file"),
        ("just words", "not a team file: expected a mapping of fields at the top level"),
        ("team: !!python/object/apply:os.system [ls]\n", "unsupported YAML tag"),
    ],
)
def test_bad_team_files_exit_2_with_a_located_message_and_no_traceback(
    write_file: WriteFile, content: str, message: str
) -> None:
    path = write_file("t.yaml", content)
    result = run_cli("solve", path)
    assert result.returncode == 2
    assert message in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""


def test_a_missing_team_file_exits_2() -> None:
    result = run_cli("solve", "rules/teams/case9.yaml")
    assert (result.returncode, result.stderr) == (2, "rules/teams/case9.yaml: no such file\n")


def test_counts_with_holes_are_shown_as_runs(write_file: WriteFile) -> None:
    path = write_file(
        "t.yaml",
        "team:\n  UAV: {motion_control: Flight, sensor_type: LIDAR, sensor_count: [2, 5, 9]}\n",
    )
    table = run_cli("solve", path, "--list").stdout.splitlines()[-2:]
    assert table[0].split()[-7:] == ["individual", "(2,", "5:", "2,", "5", "clusters)", "2"]
    data = json.loads(run_cli("solve", path, "--list", "-f", "json").stdout)
    count = data["configurations"][0]["components"][3]
    assert (count["range"], count["counts"]) == ([2, 5], [[2, 2], [5, 5]])


def test_solve_refuses_to_enumerate_more_than_the_limit_and_suggests_count_only() -> None:
    result = run_cli("solve", "case3", "--engine", "fast", "--max-robots", "100")
    assert result.returncode == 2
    assert "enumerating 312 robots is refused" in result.stderr
    assert "use --count-only" in result.stderr
    counted = run_cli("solve", "case3", "--count-only", "--max-robots", "100")
    assert counted.returncode == 0
    assert "872" in counted.stdout


def test_solve_plot_option_draws_the_radar_chart_beside_the_table(tmp_path: Path) -> None:
    result = run_cli("solve", "case1", "--plot", tmp_path / "case1.svg")
    assert result.returncode == 0, result.stderr
    assert "UAV" in result.stdout
    assert (tmp_path / "case1.svg").read_bytes().startswith(b"<?xml")


def test_solve_plot_with_an_unknown_extension_exits_2_without_traceback(tmp_path: Path) -> None:
    result = run_cli("solve", "case1", "--plot", tmp_path / "case1.gif")
    assert result.returncode == 2
    assert "case1.gif: cannot tell the plot format from '.gif'" in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""
    assert list(tmp_path.iterdir()) == []


def test_solve_can_plot_the_component_matrix(tmp_path: Path) -> None:
    result = run_cli("solve", "case3", "--plot", tmp_path / "m.svg", "--plot-kind", "matrix")
    assert result.returncode == 0
    svg = (tmp_path / "m.svg").read_bytes()
    assert svg.startswith(b"<?xml")
    assert svg == figure_bytes(matrix_figure(solve(load_team("case3"))), "svg")
