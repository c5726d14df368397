"""Teams against their rule set: forbidden selections, void teams, uncovered values."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from solver.check import check_files
from tests.check.helpers import findings, fixture
from tests.conftest import TEAMS


def test_forbidden_selection_names_the_constraint_and_its_file_and_line() -> None:
    microphone, flight = findings("team-forbidden-value.team.yaml", check="team-forbidden-value")
    rules = fixture("constrained.yaml")
    assert microphone.message == (
        "UAV selects sensor_type 'Mic' but no valid UAV robot of this selection can have it: "
        f"excluded by 'no microphone on drones' ({rules}:36:5); such robots get the default "
        "UI configuration"
    )
    assert flight.message.startswith("UGV selects motion_control 'Flight' but")
    assert f"'Flight only for UAVs' ({rules}:30:5)" in flight.message


def test_a_characteristic_left_open_takes_what_the_rules_allow_without_warning(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file("open.yaml", f"rules: {fixture('constrained.yaml')}\nteam:\n  UAV: {{}}\n")
    assert check_files([team]).findings == ()


def test_an_open_characteristic_with_a_count_in_no_arrangement_is_reported_at_the_type(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file(
        "open.yaml", f"rules: {fixture('literal-equation-2.yaml')}\nteam:\n  UAV: {{}}\n"
    )
    messages = [(f.line, f.message) for f in check_files([team]).findings]
    assert [(line, text.split(", which")[0]) for line, text in messages] == [
        (3, "UAV leaves sensor_count open, so it selects sensor_count 1, 6, 11, 16")
    ]


def test_a_selection_that_leaves_a_type_no_robot_is_an_error_with_its_reason() -> None:
    [void] = findings("void-team-type.team.yaml", check="void-team-type")
    assert void.message == (
        "UGV: the selection leaves no valid robot: constraint 'Flight only for UAVs' "
        f"({fixture('constrained.yaml')}:30:5) alone excludes every robot it selects"
    )
    assert findings("void-team-type.team.yaml", check="void-team") == []


def test_a_team_whose_every_type_is_void_is_void() -> None:
    checks = [f.check for f in findings("void-team.team.yaml")]
    assert checks == ["void-team", "void-team-type"]


def test_a_selected_count_in_no_arrangement_gets_the_default_configuration() -> None:
    [uncovered] = findings("team-uncovered-value.team.yaml", check="team-uncovered-value")
    assert uncovered.message.startswith(
        "UAV selects sensor_count 1, which no component of the rules ("
    )


def test_the_shipped_teams_are_clean_against_their_rules() -> None:
    report = check_files(sorted(TEAMS.glob("*.yaml")))
    assert report.findings == ()
