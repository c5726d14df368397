"""The command line as a user runs it: outputs, formats, exit codes, bad input."""

from __future__ import annotations

import csv
import functools
import io
import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.conftest import ROOT, TEAMS, run_cli

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


def test_shipped_teams_and_the_default_rules_work_from_any_directory(tmp_path: Path) -> None:
    result = run_cli("solve", "case1", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "reproduced" in result.stdout


def test_assign_gives_the_configuration_number_and_components() -> None:
    result = run_cli(
        "assign",
        "--team",
        "rules/teams/case3.yaml",
        "kinematic_type=UAV",
        "motion_control=Flight",
        "sensor_type=2D Camera",
        "sensor_count=3",
    )
    assert result.returncode == 0
    assert result.stdout.splitlines()[:5] == [
        "UI configuration 1 for kinematic_type=UAV motion_control=Flight "
        "sensor_type=2D Camera sensor_count=3",
        "  Robot Kinematic Type: UAV",
        "  Robot Motion Control: Flight",
        "  Sensor Type: visual display",
        "  No. of Sensors: individual (3: 3 clusters)",
    ]


def test_assign_answers_an_invalid_robot_with_the_default_and_exits_0() -> None:
    result = run_cli(
        "assign",
        "--team",
        "case3",
        "-f",
        "json",
        "kinematic_type=Quadruped",
        "motion_control=Walking",
        "sensor_type=360 Camera",
        "sensor_count=4",
    )
    assert result.returncode == 0
    data = json.loads(result.stdout)
    assert (data["configuration"], data["default"]) == (103, True)
    assert data["reasons"] == ["unknown robot kinematic type 'Quadruped'"]
    assert data["relevant_components"]["sensor_type"] == ["spherical display"]


def test_python_dash_m_solver_is_the_same_command_line() -> None:
    script = subprocess.run(
        [Path(sys.executable).parent / "teleop-ui", "reproduce"],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=False,
    )
    assert script.returncode == 0
    assert script.stdout == run_cli("reproduce").stdout


# What a plain URDF's `identify` has no use for: UI configurations, layouts, the live graph,
# the xacro sandbox, the children that read bags, an SRDF's reader (start-up time, issue 29).
NOT_FOR_A_URDF = (
    "solver.solving.assignment",
    "solver.solving.solution",
    "solver.identify.fleet",
    "solver.identify.limited",
    "solver.identify.readers.srdf",
    "solver.identify.xacro.compiler",
    "solver.layouts",
    "solver.live",
)


@functools.cache
def _commands_in_a_fresh_interpreter() -> tuple[str, list[str], str, list[str]]:
    """`identify` of a URDF then `solve case3`, in one fresh interpreter: each one's status and
    the project modules it loaded."""
    script = (
        "import contextlib, io, json, sys\n"
        "from solver.cli import main\n"
        "loaded = []\n"
        "for argv in (['identify', 'examples/diff_drive_lidar.urdf'], ['solve', 'case3']):\n"
        "    before = set(sys.modules)\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        status = main(argv)\n"
        "    new = sorted(m for m in set(sys.modules) - before if m.startswith('solver'))\n"
        "    loaded.append((str(status), new))\n"
        "print(json.dumps(loaded))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, check=True
    )
    (identify_status, identify_loaded), (solve_status, solve_loaded) = json.loads(done.stdout)
    return identify_status, identify_loaded, solve_status, solve_loaded


def test_a_command_imports_its_own_module_and_no_other_command() -> None:
    _, _, status, loaded = _commands_in_a_fresh_interpreter()
    assert status == "0"
    assert "solver.cli.solve" in loaded
    assert "solver.cli.watch" not in loaded
    assert "solver.cli.identify" not in loaded
    # Nor what Case 3 does not use: HiGHS's exact cover, assigning a robot.
    assert "solver.core.cover" not in loaded
    assert "solver.solving.assignment" not in loaded


def test_the_command_table_lists_each_command_module_and_a_helper_module_is_no_command() -> None:
    from solver.cli import COMMANDS

    modules = sorted(p.stem for p in (ROOT / "solver" / "cli").glob("*.py"))
    helpers = [name for name in modules if name.startswith("_")]
    assert sorted(COMMANDS) == [name for name in modules if name not in helpers]
    assert all(module == f"solver.cli.{name}" for name, module in COMMANDS.items())


def test_help_lists_the_commands_of_the_table_in_its_order() -> None:
    from solver.cli import COMMANDS

    result = run_cli("--help")
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    # Each command starts a line of its own, indented by four spaces, with its help beside it.
    listed = [line.split()[0] for line in lines if line.startswith("    ") and line[4] != " "]
    assert listed == list(COMMANDS) == sorted(COMMANDS)


def test_identifying_a_urdf_loads_no_configurations_layouts_live_graph_nor_xacro_sandbox() -> None:
    status, loaded, _, _ = _commands_in_a_fresh_interpreter()
    assert status == "0"
    assert "solver.identify.identification" in loaded
    unneeded = [m for m in loaded if m.startswith(NOT_FOR_A_URDF)]
    assert unneeded == []


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


def test_assign_with_an_unknown_characteristic_name_exits_2() -> None:
    result = run_cli("assign", "--team", "case1", "colour=red")
    assert result.returncode == 2
    assert "unknown characteristic 'colour'" in result.stderr


def test_reproduce_compares_every_shipped_article_case() -> None:
    result = run_cli("reproduce", "-f", "json")
    rows = {row["file"]: row for row in json.loads(result.stdout)}
    assert set(rows) == {
        f"rules/teams/{p.name}"
        for p in TEAMS.glob("*.yaml")
        if "\npublished:" in p.read_text(encoding="utf-8")
    }
    assert len(rows) == 5
    assert rows["rules/teams/case3.yaml"]["computed"] == {
        "valid_robots": 872,
        "ui_configurations": 102,
    }
    assert not rows["rules/teams/case3.yaml"]["reproduced"]
    assert all(row["reproduced"] for name, row in rows.items() if name != "rules/teams/case3.yaml")


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
