"""A selection in the address and back: the query holds what a team file holds."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver import TeamError, load_team
from solver.core.rules import parse_rules
from solver.files.yamlio import parse_document
from solver.studio.selection import parse_query, query_of, team_of
from tests.conftest import TEAMS


@pytest.mark.parametrize("path", sorted(TEAMS.glob("*.yaml")), ids=lambda p: p.stem)
def test_every_shipped_team_survives_the_trip_through_an_address(path: Path) -> None:
    team = load_team(path)
    pairs = query_of(team, "paper")
    back = team_of(parse_query(pairs, team.rules, "paper"), team.rules)
    assert back.selections == team.selections
    assert back.name == team.name


def test_case_1_reads_as_a_person_would_write_its_address() -> None:
    assert query_of(load_team("case1"), "paper") == [
        ("rules", "paper"),
        ("name", "Case 1"),
        ("type", "UAV"),
        ("UAV.motion_control", "Flight"),
        ("UAV.motion_control", "Waypoint"),
        ("UAV.sensor_type", "2D Camera"),
        ("UAV.sensor_type", "360 Camera"),
        ("UAV.sensor_type", "RGB-D Camera"),
        ("UAV.sensor_count.max", "5"),
    ]


def test_a_type_without_parameters_takes_every_value_and_an_empty_one_takes_none() -> None:
    rules = load_team("case1").rules
    every = team_of(parse_query([("type", "UGV")], rules, "paper"), rules)
    assert every.selections[0].domains[1] == rules.characteristic("motion_control").values
    with pytest.raises(TeamError) as caught:
        team_of(parse_query([("type", "UGV"), ("UGV.motion_control", "")], rules, "paper"), rules)
    (fault,) = caught.value.faults
    assert (fault.location.file, fault.location.path) == ("<selection>", "team.UGV.motion_control")


def test_a_count_range_and_a_list_of_counts_read_as_in_a_team_file() -> None:
    rules = load_team("case1").rules
    pairs = [
        ("type", "UAV"),
        ("UAV.sensor_count.min", "3"),
        ("UAV.sensor_count.max", "7"),
        ("type", "UGV"),
        ("UGV.sensor_count", "2"),
        ("UGV.sensor_count", "9"),
    ]
    team = team_of(parse_query(pairs, rules, "paper"), rules)
    assert [s.domains[3] for s in team.selections] == [(3, 4, 5, 6, 7), (2, 9)]


def test_names_with_dots_and_strange_characters_are_matched_to_the_rules() -> None:
    text = (
        "characteristics:\n"
        '  kind:\n    values: [a.b, "x\\ny"]\n'
        "  sensor_count:\n    range: {min: 1, max: 4}\n"
    )
    rules = parse_rules(parse_document(text, "r.yaml"))
    pairs = [("type", "a.b"), ("a.b.sensor_count.max", "2"), ("type", "x\ny")]
    team = team_of(parse_query(pairs, rules, "mine"), rules)
    assert [(s.kinematic_type, s.domains[1]) for s in team.selections] == [
        ("a.b", (1, 2)),
        ("x\ny", (1, 2, 3, 4)),
    ]
    assert team_of(parse_query(query_of(team, "mine"), rules, "mine"), rules) == team
