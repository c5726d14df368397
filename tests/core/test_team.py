"""Loading team selections: shapes, rule-file resolution, and every malformation located."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import pytest

from solver import InputError, RulesError, TeamError, load_rules, load_team
from tests.conftest import RULES, TEAMS

WriteFile = Callable[[str, str], Path]


def faults(path: Path) -> list[str]:
    with pytest.raises(TeamError) as caught:
        load_team(path)
    return [str(fault).removeprefix(f"{path}:") for fault in caught.value.faults]


def test_a_team_selects_values_per_kinematic_type() -> None:
    team = load_team(TEAMS / "case1.yaml")
    (uav,) = team.selections
    assert uav.kinematic_type == "UAV"
    assert uav.domains == (
        ("UAV",),
        ("Flight", "Waypoint"),
        ("2D Camera", "360 Camera", "RGB-D Camera"),
        (1, 2, 3, 4, 5),
    )
    assert team.published is not None
    assert (team.published.valid_robots, team.published.ui_configurations) == (30, 6)


def test_selections_follow_the_rule_files_kinematic_type_order() -> None:
    team = load_team(TEAMS / "case3.yaml")
    assert team.kinematic_types == ("UAV", "UGV", "Mobile Manipulator", "Humanoid")


def test_a_complement_selects_all_but_the_named_values() -> None:
    (uav,) = load_team(TEAMS / "figure8.yaml").selections
    assert "Force Sensor" not in uav.domains[2]
    assert len(uav.domains[2]) == 9


def test_an_unmentioned_characteristic_allows_its_whole_domain(write_file: WriteFile) -> None:
    team = load_team(write_file("t.yaml", "team:\n  UGV: {motion_control: Driving}\n"))
    assert len(team.selections[0].domains[3]) == 50


def test_the_shipped_paper_rules_are_used_when_a_team_names_none(write_file: WriteFile) -> None:
    team = load_team(write_file("t.yaml", "team:\n  UAV: {}\n"))
    assert team.rules.name == "Mortimer et al. 2017"


def test_a_relative_rules_path_resolves_against_the_team_files_folder(
    write_file: WriteFile, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write_file(
        "rules/mine.yaml",
        (RULES / "paper.yaml").read_text().replace("name: Mortimer et al. 2017", "name: mine"),
    )
    team_path = write_file("rules/teams/t.yaml", "rules: ../mine.yaml\nteam:\n  UAV: {}\n")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    assert load_team(os.path.relpath(team_path)).rules.name == "mine"


def test_a_shipped_rule_set_is_named_by_its_name_on_any_machine(write_file: WriteFile) -> None:
    team = load_team(write_file("anywhere/t.yaml", "rules: extended\nteam:\n  UAV: {}\n"))
    assert team.rules.name == load_rules(RULES / "extended.yaml").name
    assert team.rules.file == "rules/extended.yaml"


def test_a_file_beside_the_team_wins_over_a_shipped_name(write_file: WriteFile) -> None:
    write_file(
        "here/extended",
        (RULES / "paper.yaml").read_text().replace("name: Mortimer et al. 2017", "name: mine"),
    )
    team = load_team(write_file("here/t.yaml", "rules: extended\nteam:\n  UAV: {}\n"))
    assert team.rules.name == "mine"


def test_a_misspelled_shipped_name_lists_the_shipped_rule_sets(write_file: WriteFile) -> None:
    (message,) = faults(write_file("t.yaml", "rules: extendd\nteam:\n  UAV: {}\n"))
    assert message.endswith(
        "no such file (a shipped rule set is named by its name: "
        "extended, marine, paper-case3-hypothesis, paper)"
    )


def test_a_profile_shipped_beside_the_rule_sets_is_no_rule_set_name(
    write_file: WriteFile,
) -> None:
    (message,) = faults(write_file("t.yaml", "rules: identification\nteam:\n  UAV: {}\n"))
    assert "cannot use rules file 'identification'" in message


def test_rules_given_by_the_caller_override_the_team_file(write_file: WriteFile) -> None:
    rules = load_rules(RULES / "paper-case3-hypothesis.yaml")
    assert load_team(TEAMS / "case3.yaml", rules).rules.bound == 1080


def test_a_misspelled_sensor_type_is_located_with_a_suggestion(write_file: WriteFile) -> None:
    path = write_file(
        "t.yaml",
        """\
team:
  UAV:
    sensor_type: [2D Camera, Mic]
""",
    )
    assert faults(path) == [
        "3:30: team.UAV.sensor_type[1]: unknown sensor type 'Mic' (did you mean 'Microphone'?)"
    ]


def test_every_problem_in_a_team_file_is_reported_in_file_order(write_file: WriteFile) -> None:
    path = write_file(
        "t.yaml",
        """\
name: Broken
colour: blue
team:
  UAV:
    motion_control: [Flight, Waypont]
    sensor_count: 0
  Quadruped:
    motion_control: [Walking]
  UGV:
    sensor_count: 60
    sensor_typ: [LIDAR]
  Humanoid:
    sensor_type: []
  Torso:
    sensor_count: five
  Manipulator:
published: {valid_robots: many}
""",
    )
    assert faults(path) == [
        "2:1: colour: unknown team file field 'colour'; allowed: description, name, published, "
        "rules, team",
        "5:30: team.UAV.motion_control[1]: unknown robot motion control 'Waypont' "
        "(did you mean 'Waypoint'?)",
        "6:19: team.UAV.sensor_count: sensor_count maximum must be at least 1, got 0",
        "7:3: team.Quadruped: unknown robot kinematic type 'Quadruped'; the rules "
        "(rules/paper.yaml) have: UAV, UGV, Manipulator, Mobile Manipulator, Torso, "
        "Humanoid",
        "10:19: team.UGV.sensor_count: sensor_count maximum 60 exceeds the rule set's maximum "
        "of 50",
        "11:5: team.UGV.sensor_typ: unknown characteristic 'sensor_typ' (did you mean "
        "'sensor_type'?); allowed: motion_control, sensor_count, sensor_type",
        "13:18: team.Humanoid.sensor_type: empty selection for 'sensor_type'",
        "15:19: team.Torso.sensor_count: sensor_count values are whole numbers, got a string "
        "('five')",
        "16:15: team.Manipulator: no selections for 'Manipulator'; list its characteristics' "
        "values (or write {} to allow every value)",
        "17:12: published.ui_configurations: missing published ui_configurations",
        "17:27: published.valid_robots: published valid_robots must be a whole number, got a "
        "string ('many')",
    ]


def test_a_team_may_not_select_its_own_key(write_file: WriteFile) -> None:
    path = write_file("t.yaml", "team:\n  UAV: {kinematic_type: UGV}\n")
    assert faults(path) == [
        "2:9: team.UAV.kinematic_type: 'kinematic_type' is given by the "
        "entry itself ('UAV'); remove it"
    ]


def test_a_team_with_no_kinematic_types_is_refused(write_file: WriteFile) -> None:
    assert faults(write_file("t.yaml", "team: {}\n")) == [
        "1:7: team: the team selects no kinematic type"
    ]


def test_a_team_file_without_a_team_is_refused(write_file: WriteFile) -> None:
    assert faults(write_file("t.yaml", "name: lonely\n")) == [
        "1:1: not a team file: it has no 'team:' field"
    ]


def test_a_missing_rules_file_is_named_at_the_rules_field(write_file: WriteFile) -> None:
    path = write_file("teams/t.yaml", "rules: ../nothere.yaml\nteam:\n  UAV: {}\n")
    shown = os.path.normpath(path.parent / "../nothere.yaml")
    assert faults(path) == [
        f"1:8: rules: cannot use rules file '../nothere.yaml' (resolved to {shown}): no such file"
    ]


def test_a_broken_rules_file_reports_its_own_faults(write_file: WriteFile) -> None:
    write_file("bad.yaml", "characteristics:\n  kinematic_type:\n    values: [UAV, UAV]\n")
    with pytest.raises(RulesError, match="duplicate value 'UAV'"):
        load_team(write_file("t.yaml", "rules: bad.yaml\nteam:\n  UAV: {}\n"))


def test_a_rules_file_that_is_not_yaml_reports_its_syntax_error(write_file: WriteFile) -> None:
    write_file("bad.yaml", "characteristics: [oops\n")
    with pytest.raises(InputError, match=r"bad\.yaml:2:1: YAML syntax error"):
        load_team(write_file("t.yaml", "rules: bad.yaml\nteam:\n  UAV: {}\n"))


def test_a_value_listed_twice_is_an_error_not_a_silent_drop(write_file: WriteFile) -> None:
    path = write_file(
        "t.yaml", "team:\n  UAV: {motion_control: [Flight, Flight]}\n  UGV: {sensor_count: 3}\n"
    )
    assert faults(path) == ["2:34: team.UAV.motion_control[1]: 'Flight' is listed twice"]


def test_a_range_beyond_the_rules_is_an_error_not_a_silent_clip(write_file: WriteFile) -> None:
    path = write_file("t.yaml", "team:\n  UAV: {sensor_count: {min: 0, max: 99}}\n")
    assert faults(path) == [
        "2:29: team.UAV.sensor_count.min: sensor_count min 0 is outside the rule set's range 1..50",
        "2:37: team.UAV.sensor_count.max: sensor_count max 99 is outside the rule set's range "
        "1..50",
    ]


def test_negative_published_figures_are_errors(write_file: WriteFile) -> None:
    path = write_file(
        "t.yaml", "team:\n  UAV: {}\npublished: {valid_robots: -1, ui_configurations: 3}\n"
    )
    assert faults(path) == [
        "3:27: published.valid_robots: published valid_robots must not be negative, got -1"
    ]


def test_a_maximum_count_selects_the_counts_up_to_it_one_tuple_shared_by_types(
    write_file: Callable[[str, str], Path],
) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [A, B, C]}
  sensor_count: {range: {min: 3, max: 9}}
""",
    )
    team = load_team(
        write_file(
            "team.yaml",
            "rules: rules.yaml\nteam:\n  A: {sensor_count: 5}\n  B: {sensor_count: 5}\n"
            "  C: {sensor_count: 9}\n",
        )
    )
    a, b, c = (s.domains[1] for s in team.selections)
    assert a == (3, 4, 5)
    assert a is b  # read once for both types: reading follows the file, not the counts
    assert c == tuple(range(3, 10))
