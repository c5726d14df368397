"""The Python API page runs as written, and the API reads like the JSON contract."""

from __future__ import annotations

import doctest
import os
from pathlib import Path

import pytest

import solver
from solver import assign, load_team, solve
from solver.solving.solution import solution_data
from tests.conftest import ROOT


def test_every_example_on_the_python_api_page_prints_what_it_shows(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # From a folder without the repository's files: shipped names must work anywhere.
    monkeypatch.chdir(tmp_path)
    result = doctest.testfile(
        str(ROOT / "docs" / "python-api.md"),
        module_relative=False,
        optionflags=doctest.ELLIPSIS,
        verbose=False,
    )
    assert result.attempted >= 20
    assert result.failed == 0


def test_to_dict_is_the_json_contract_of_solve_with_its_list() -> None:
    solution = solve(load_team("case1"))
    assert solution.to_dict() == solution_data(solution, configurations=True)
    counted = solve(load_team("case1"), count_only=True)
    assert "configurations" not in counted.to_dict()


def test_records_have_one_row_per_configuration_with_a_column_per_characteristic() -> None:
    solution = solve(load_team("case2"))
    rows = solution.records()
    assert len(rows) == solution.totals.ui_configurations
    assert list(rows[0]) == [
        "number",
        "kinematic_type",
        "kinematic_type_component",
        "motion_control",
        "sensor_type",
        "sensor_count",
        "valid_robots",
    ]
    assert sum(row["valid_robots"] for row in rows) == solution.totals.valid_robots
    assert [row["kinematic_type"] for row in solution.records("types")] == [
        t.kinematic_type for t in solution.by_type
    ]


def test_assign_by_keywords_equals_assign_by_mapping() -> None:
    solution = solve(load_team("case3"))
    values: dict[str, str | int] = {
        "kinematic_type": "UGV",
        "motion_control": "Driving",
        "sensor_type": "LIDAR",
        "sensor_count": 4,
    }
    by_keywords = assign(solution, **values)
    assert by_keywords == assign(solution, values)
    assert by_keywords == assign(solution, {"kinematic_type": "UAV"}, **values)
    assert not by_keywords.is_default


def test_configurations_use_the_json_name_for_their_robots() -> None:
    solution = solve(load_team("case1"))
    assert [c.valid_robots for c in solution.configurations] == [
        c["valid_robots"] for c in solution.to_dict()["configurations"]
    ]


def test_help_of_the_package_names_a_function_for_every_command() -> None:
    from solver.cli import build_parser

    parser = build_parser()
    # argparse has no public way to list subcommands; its _actions is stable since 2.7.
    commands = next(action for action in parser._actions if action.dest == "command").choices
    text = solver.__doc__ or ""
    assert commands, "the parser has commands"
    assert [
        name for name in commands if f"``{name}" not in text and f"``teleop-ui {name}" not in text
    ] == []


def test_reprs_are_one_short_line() -> None:
    solution = solve(load_team("case3"))
    for value in (
        solution,
        solution.team,
        solution.rules,
        solution.configurations[0],
        assign(solution, kinematic_type="UAV"),
    ):
        assert "\n" not in repr(value)
        assert len(repr(value)) < 200
    assert os.linesep not in repr(solution)
