"""A selection in the address and back: the query holds what a team file holds."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from solver import SolverError, Team, TeamError, load_team
from solver.core.rules import parse_rules
from solver.core.team import parse_team
from solver.files.yamlio import MAX_KEY_CHARS, parse_document
from solver.studio.selection import (
    SELECTION_FILE,
    Selection,
    parse_query,
    query_of,
    team_document,
    team_of,
)
from tests.conftest import TEAMS
from tests.hostile import FUZZ, HOSTILE, NAME_CHARS


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


def read_as_a_file(selection: Selection, team: Team) -> Team:
    """The team a selection's team file gives, written as YAML and read back (the studio's way
    before it gave the reader the data itself)."""
    document = parse_document(team_document(selection, team.rules), SELECTION_FILE)
    return parse_team(document, team.rules)


def outcome(read: object) -> object:
    """A team's name and selections, or the faults a refusal gives (where and what), for
    comparing two ways of reading a selection."""
    try:
        team = read()  # type: ignore[operator]
    except SolverError as error:
        return type(error), [
            (f.location.file, f.location.path, f.message, f.code) for f in error.faults
        ]
    return team.name, team.selections


# Texts a stranger may put in an address: the hostile pieces, names' characters, numbers with
# signs and spaces, values of the rules, and text past the bounds of a key.
QUERY_TEXT = st.one_of(
    st.sampled_from([piece.decode("utf-8", "replace") for piece in HOSTILE]),
    st.text(NAME_CHARS, max_size=12),
    st.sampled_from(["5", "+5", "-5", "--5", "+-5", " 7 ", "05", "1_0", "9" * 19, "\x00"]),
    st.sampled_from(["UAV", "Humanoid", "Flight", "Waypoint", "LIDAR", "2D Camera"]),
    st.sampled_from(["\x00", "a\udcff", "x" * (MAX_KEY_CHARS + 1), "y" * 10_001]),
)
FIELDS = st.sampled_from(
    ["motion_control", "sensor_type", "sensor_count", "sensor_count.min", "sensor_count.max"]
)


@FUZZ
@given(
    name=QUERY_TEXT,
    types=st.lists(QUERY_TEXT, min_size=0, max_size=3),
    values=st.lists(st.tuples(FIELDS, QUERY_TEXT), max_size=6),
)
def test_a_selection_reads_as_its_team_file_reads_whatever_the_address_holds(
    name: str, types: list[str], values: list[tuple[str, str]]
) -> None:
    rules = load_team("case3").rules
    pairs = [("name", name)] + [("type", t) for t in types]
    pairs += [(f"{t}.{field}", value) for t in types for field, value in values]
    selection = parse_query(pairs, rules, "paper")
    direct = outcome(lambda: team_of(selection, rules))
    assert direct == outcome(lambda: read_as_a_file(selection, load_team("case3")))


def test_a_count_written_with_two_signs_is_a_located_error_not_a_crash() -> None:
    rules = load_team("case1").rules
    for text in ("--5", "+-5"):
        with pytest.raises(TeamError) as caught:
            team_of(
                parse_query([("type", "UAV"), ("UAV.sensor_count.max", text)], rules, ""), rules
            )
        (fault,) = caught.value.faults
        assert (fault.location.file, fault.location.path) == (
            "<selection>",
            "team.UAV.sensor_count",
        )


def test_what_yaml_refuses_is_refused_with_the_yaml_readers_words() -> None:
    rules = load_team("case1").rules
    pairs = [("type", "UAV"), ("UAV.sensor_type", "LIDAR"), ("UAV.sensor_type", "a\x00b")]
    with pytest.raises(SolverError) as caught:
        team_of(parse_query(pairs, rules, "paper"), rules)
    (fault,) = caught.value.faults
    assert (fault.location.file, fault.location.path) == ("<selection>", "team.UAV.sensor_type[1]")
    assert fault.message == "contains a NUL character (\\0); not text"
