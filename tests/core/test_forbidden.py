"""Values a team selects that the rules' constraints exclude: solve, report and batch say so."""

from __future__ import annotations

import csv
import json
from collections.abc import Callable
from pathlib import Path

import pytest

from solver import check_files, load_team, render_markdown, solve
from solver.core.forbidden import removed_by_constraints
from tests.conftest import RULES, run_cli

# UAVs that may walk and carry a force sensor: the extended rules forbid both for a UAV.
TEAM = f"""\
name: Drones with force
rules: {RULES / "extended.yaml"}
team:
  UAV:
    motion_control: [Flight, Walking]
    sensor_type: [2D Camera, Force Sensor]
    sensor_count: 3
  UGV:
    motion_control: [Driving]
    sensor_count: 2
"""


@pytest.fixture
def team_file(write_file: Callable[[str, str], Path]) -> Path:
    return write_file("drones.yaml", TEAM)


def test_the_values_removed_are_those_check_reports_as_forbidden(team_file: Path) -> None:
    removed = removed_by_constraints(load_team(team_file))
    assert [
        (r.kinematic_type, r.characteristic, r.values, [c.name for c in r.constraints])
        for r in removed
    ] == [
        ("UAV", "motion_control", ("Walking",), ["Walking is for legged robots"]),
        (
            "UAV",
            "sensor_type",
            ("Force Sensor",),
            ["Walking is for legged robots", "no force feedback in flight"],
        ),
    ]
    findings = [f for f in check_files([team_file]).findings if f.check == "team-forbidden-value"]
    assert [f.location.line for f in findings] == [5, 6]


def test_a_team_without_constraints_in_its_rules_has_nothing_removed() -> None:
    assert solve(load_team("case3")).removed == ()


def test_solve_warns_in_text_and_json(team_file: Path) -> None:
    text = run_cli("solve", team_file)
    assert text.returncode == 0
    warnings = [line for line in text.stdout.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 2
    assert warnings[0].startswith(
        "warning: the rules' constraints exclude what the team "
        "selects: UAV: motion_control Walking, excluded by 'Walking "
        "is for legged robots' ("
    )
    data = json.loads(run_cli("solve", team_file, "--format", "json").stdout)
    assert data["warnings"] == [w.removeprefix("warning: ") for w in warnings]
    assert json.loads(run_cli("solve", "case1", "--format", "json").stdout)["warnings"] == []


def test_the_report_lists_each_constraint_with_what_it_removes(team_file: Path) -> None:
    page = render_markdown(solve(load_team(team_file)))
    section = page.split("## Rule constraints (5)\n", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| '")]
    assert len(rows) == 5
    assert rows[1].endswith("| UAV: motion\\_control Walking; UAV: sensor\\_type Force Sensor |")
    assert rows[4].endswith("| UAV: sensor\\_type Force Sensor |")
    assert rows[0].endswith("| none |")
    assert "- warning: the rules' constraints exclude" in page


def test_batch_puts_the_warnings_in_the_summary_and_on_its_output(
    team_file: Path, tmp_path: Path
) -> None:
    result = run_cli("batch", team_file, "-o", tmp_path / "out")
    assert result.returncode == 0
    assert result.stderr.count("\n    warning: the rules' constraints exclude") == 2
    with (tmp_path / "out" / "summary.csv").open(encoding="utf-8") as stream:
        (row,) = csv.DictReader(stream)
    assert row["status"] == "ok"
    assert row["message"].count("warning: ") == 2


def test_values_the_rules_exclude_for_a_type_are_listed_each_with_its_constraint() -> None:
    from solver import load_rules
    from solver.core.forbidden import excluded_by_rules

    excluded = excluded_by_rules(load_rules(RULES / "extended.yaml"))
    uav = [
        (r.characteristic, r.values, [c.name for c in r.constraints])
        for r in excluded
        if r.kinematic_type == "UAV"
    ]
    assert uav == [
        ("motion_control", ("Walking",), ["Walking is for legged robots"]),
        ("motion_control", ("End Effector",), ["End Effector control needs an arm"]),
    ]
    ugv = {r.values[0] for r in excluded if r.kinematic_type == "UGV"}
    assert ugv == {"Flight", "Walking", "End Effector"}


def test_a_rule_set_without_constraints_excludes_nothing() -> None:
    from solver import load_rules
    from solver.core.forbidden import excluded_by_rules

    assert excluded_by_rules(load_rules(RULES / "paper.yaml")) == ()


def test_each_of_many_excluded_counts_is_listed_with_the_reason_of_its_own(
    write_file: Callable[[str, str], Path],
) -> None:
    from solver import load_rules
    from solver.core.forbidden import excluded_by_rules

    rules = write_file(
        "rules.yaml",
        "characteristics:\n  kinematic_type: {values: [A, B]}\n"
        "  sensor_count: {range: {min: 1, max: 5000}}\n"
        "constraints:\n"
        "  - {name: few for A, forbid: {kinematic_type: A, sensor_count: {min: 3}}}\n"
        "  - {name: not 4000 for A, forbid: {kinematic_type: A, sensor_count: 4000}}\n"
        "  - {name: not 2 for B, forbid: {kinematic_type: B, sensor_count: 2}}\n",
    )
    excluded = [
        (r.kinematic_type, r.values[0], [c.name for c in r.constraints])
        for r in excluded_by_rules(load_rules(rules))
    ]
    # 4000 is excluded by both: deletion in declared order drops the first (the second still
    # excludes it) and keeps the second.
    assert excluded == [
        *(("A", n, ["few for A"]) for n in range(3, 4000)),
        ("A", 4000, ["not 4000 for A"]),
        *(("A", n, ["few for A"]) for n in range(4001, 5001)),
        ("B", 2, ["not 2 for B"]),
    ]


def test_exclusions_past_their_deadline_are_refused() -> None:
    from dataclasses import replace

    from solver import load_rules
    from solver.core.forbidden import excluded_by_rules
    from solver.deadline import Deadline
    from solver.errors import TimeLimitError

    spent = replace(Deadline.start("check-seconds", "exclusions", 1), end=0.0)
    with pytest.raises(TimeLimitError, match=r"extended\.yaml: exclusions stopped after 1 s"):
        excluded_by_rules(load_rules(RULES / "extended.yaml"), deadline=spent)
