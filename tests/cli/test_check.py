"""``teleop-ui check`` as a user runs it: output, exit status 0/1/2, options."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from solver.check import FORMATS, check_ids
from solver.cli import check as cli_check
from tests.conftest import ROOT, TEAMS, run_cli

FIXTURES = "tests/fixtures/check"


def test_check_paper_rules_is_clean_and_exits_0() -> None:
    result = run_cli("check", "rules/paper.yaml")
    assert result.returncode == 0
    assert result.stdout == (
        "rules/paper.yaml:11:1: [info] T = 6 x 6 x 5 x 5 = 900 UI configurations at most "
        "(components of kinematic_type x motion_control x sensor_type x sensor_count), as "
        "declared (bound)\n"
        "1 file checked: 0 errors, 0 warnings, 1 info\n"
    )
    assert result.stderr == ""


def test_check_rules_and_teams_together_exits_0_for_the_shipped_files() -> None:
    # The shipped teams written for the article's rules (search-and-rescue is written for
    # rules/extended.yaml, marine-survey for rules/marine.yaml: each is checked against its own
    # below).
    teams = sorted(
        str(p.relative_to(ROOT))
        for p in TEAMS.glob("*.yaml")
        if p.stem not in ("search-and-rescue", "marine-survey")
    )
    result = run_cli("check", "rules/paper.yaml", *teams)
    assert result.returncode == 0
    assert result.stdout.endswith(f"{len(teams) + 1} files checked: 0 errors, 0 warnings, 1 info\n")


def test_the_extended_example_rules_and_their_team_check_without_error() -> None:
    result = run_cli("check", "rules/extended.yaml", "rules/teams/search-and-rescue.yaml")
    assert result.returncode == 0
    assert result.stdout.endswith("2 files checked: 0 errors, 0 warnings, 9 info\n")


def test_the_marine_rules_and_their_team_check_clean() -> None:
    result = run_cli("check", "--strict", "rules/marine.yaml", "rules/teams/marine-survey.yaml")
    assert result.returncode == 0
    assert result.stdout.endswith("2 files checked: 0 errors, 0 warnings, 15 info\n")
    # The infos say what the constraints exclude for each type, as the extended example's do.
    infos = result.stdout.splitlines()[:-1]
    assert all("[info]" in line for line in infos)
    assert sum("(dead-for-type)" in line for line in infos) == 14


def test_check_literal_equation_2_exits_1_with_its_four_gaps() -> None:
    result = run_cli("check", f"{FIXTURES}/literal-equation-2.yaml")
    assert result.returncode == 1
    gaps = [line for line in result.stdout.splitlines() if line.endswith("(coverage-gap)")]
    assert [line.split(" is in no component")[0].rsplit(" ", 1)[1] for line in gaps] == [
        "1",
        "6",
        "11",
        "16",
    ]


def test_warnings_exit_0_unless_strict() -> None:
    assert run_cli("check", f"{FIXTURES}/unbounded-range.yaml").returncode == 0
    assert run_cli("check", "--strict", f"{FIXTURES}/unbounded-range.yaml").returncode == 1


def test_unusable_input_exits_2_with_a_located_error_and_no_output(
    write_file: Callable[[str, str], Path],
) -> None:
    bad = write_file("bad.yaml", "characteristics:\n  kind: [a, b\n")
    result = run_cli("check", f"{FIXTURES}/base.yaml", bad, "missing.yaml")
    assert result.returncode == 2
    assert result.stdout == ""
    assert f"{bad}:3:1: YAML syntax error" in result.stderr
    assert "missing.yaml: no such file" in result.stderr
    assert "Traceback" not in result.stderr


def test_unknown_check_id_or_no_file_is_a_usage_error() -> None:
    unknown = run_cli("check", "--disable", "no-such-check", "rules/paper.yaml")
    assert unknown.returncode == 2
    assert "unknown check id(s): no-such-check" in unknown.stderr
    assert run_cli("check").returncode == 2


def test_disable_leaves_checks_out() -> None:
    result = run_cli("check", "-d", "coverage-gap,bound", f"{FIXTURES}/literal-equation-2.yaml")
    assert result.returncode == 0
    assert "(unbounded-range)" in result.stdout
    assert "(coverage-gap)" not in result.stdout


def test_list_checks_names_every_check_with_its_level() -> None:
    result = run_cli("check", "--list-checks")
    assert result.returncode == 0
    listed = [
        line.split(" [")[0] for line in result.stdout.splitlines() if not line.startswith(" ")
    ]
    assert listed == list(check_ids())


def test_json_and_sarif_outputs_are_json_with_relative_paths_as_given() -> None:
    data = json.loads(run_cli("check", "-f", "json", "rules/paper.yaml").stdout)
    assert data["summary"] == {"error": 0, "warning": 0, "info": 1}
    sarif = json.loads(run_cli("check", "-f", "sarif", "rules/paper.yaml").stdout)
    [result] = sarif["runs"][0]["results"]
    assert (
        result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == "rules/paper.yaml"
    )


def test_output_is_byte_identical_on_a_second_run() -> None:
    args = ("check", "-f", "sarif", f"{FIXTURES}/void-type.yaml", f"{FIXTURES}/conflict.yaml")
    assert run_cli(*args).stdout == run_cli(*args).stdout


def test_the_command_offers_exactly_the_formats_the_renderer_knows() -> None:
    assert cli_check.FORMATS == FORMATS


@pytest.mark.parametrize("given", ["0", "-1", "nan", "soon"])
def test_a_time_limit_that_is_not_a_positive_number_is_a_usage_error(given: str) -> None:
    result = run_cli("check", "--time-limit", given, "rules/paper.yaml")
    assert result.returncode == 2
    assert "--time-limit" in result.stderr
    assert result.stdout == ""
