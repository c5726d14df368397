"""Writing a team file: the shortest form that reads back to the same selection."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver import load_team, solve
from solver.core.team import parse_team
from solver.files.yamlio import parse_document
from solver.solving.teamfile import team_yaml
from tests.conftest import TEAMS


@pytest.mark.parametrize("path", sorted(TEAMS.glob("*.yaml")), ids=lambda p: p.stem)
def test_every_shipped_team_written_reads_back_to_the_same_selection(path: Path) -> None:
    team = load_team(path)
    text = team_yaml(team, solution=solve(team, count_only=True))
    back = parse_team(parse_document(text, "<written>"), team.rules)
    assert back.selections == team.selections
    assert back.published == team.published
    assert back.name == team.name


def test_case_1_is_written_as_a_person_would_write_it() -> None:
    team = load_team(TEAMS / "case1.yaml")
    assert team_yaml(team, solution=solve(team)) == (
        "name: Case 1\n"
        "team:\n"
        "  UAV:   # 30 valid robots, 6 UI configurations\n"
        "    motion_control: [Flight, Waypoint]\n"
        "    sensor_type: [2D Camera, 360 Camera, RGB-D Camera]\n"
        "    sensor_count: 5\n"
        "published:\n"
        "  source: Mortimer et al. 2017, Section 4 and Table 2\n"
        "  valid_robots: 30\n"
        "  ui_configurations: 6\n"
    )


def test_counts_that_do_not_start_at_the_first_are_a_range_or_a_list() -> None:
    text = "team:\n  UAV: {sensor_count: {min: 3, max: 7}}\n  UGV: {sensor_count: [2, 5, 9]}\n"
    team = parse_team(parse_document(text, "t.yaml"))
    written = team_yaml(team)
    assert "    sensor_count: {max: 7, min: 3}\n" in written
    assert "    sensor_count: [2, 5, 9]\n" in written
    assert parse_team(parse_document(written, "w.yaml")).selections == team.selections


def test_a_type_allowed_everything_is_written_as_an_empty_mapping() -> None:
    team = parse_team(parse_document("team:\n  Torso: {}\n", "t.yaml"))
    assert "  Torso: {}\n" in team_yaml(team)


def test_a_name_with_a_line_break_stays_on_its_line() -> None:
    team = parse_team(parse_document('name: "a\\nteam:\\n  UGV: {}"\nteam:\n  UAV: {}\n', "t"))
    text = team_yaml(team, header=["made\nhere"])
    back = parse_team(parse_document(text, "w.yaml"))
    assert back.name == team.name
    assert back.kinematic_types == ("UAV",)
    assert text.startswith("# made\\nhere\n")
