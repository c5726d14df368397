"""What the checks read and how they name things (solver.check.context): values written as a rule
author recognises them, and every value, component, constraint and selection located where
the files declare it (lines and columns counted by hand in tests.handcounted)."""

from __future__ import annotations

from dataclasses import replace

from solver.check.context import (
    RulesContext,
    TeamContext,
    blame,
    constraint_list,
    integer_runs,
    item_path,
    values_text,
)
from solver.core.analysis import Analysis
from solver.core.constraints import Condition, RuleConstraint
from solver.errors import Location
from solver.files.yamlio import parse_document
from tests.handcounted import SMALL_TEAM, rules_of, team_of


def context() -> RulesContext:
    rules = rules_of()
    return RulesContext(rules, Analysis(rules))


def test_counts_are_written_as_runs_and_names_quoted_in_domain_order() -> None:
    rules = rules_of()
    assert values_text(rules.characteristic("sensor_count"), [6, 1, 2, 4]) == "1..2, 4, 6"
    assert values_text(rules.characteristic("sensor_type"), ["microphone", "camera"]) == (
        "'camera', 'microphone'"
    )
    assert integer_runs([5, 1, 2]) == [(1, 2), (5,)]


def test_a_value_is_located_in_its_characteristics_list_of_values() -> None:
    found = context()
    lidar = found.value_location(found.rules.characteristic("sensor_type"), "lidar")
    assert str(lidar) == "rules.yaml:6:22"  # "    values: [camera, lidar, ..."
    document = found.rules.document
    path = ("characteristics", "sensor_type", "values")
    assert item_path(document, path, "microphone") == (*path, 2)
    assert item_path(document, path, "sonar") == path  # not listed: the list itself


def test_a_component_is_located_at_the_field_asked_for_or_at_itself() -> None:
    found = context()
    counts = found.rules.characteristic("sensor_count")
    many = counts.component("many")
    assert many is not None
    # "      - {name: many, min: 3, max: 6, cluster_size: 2}": the 2 is at column 52.
    assert str(found.component_location(counts, many, "cluster_size")) == "rules.yaml:14:52"
    assert found.component_location(counts, many, "above").line == 14  # no such field
    assert found.raw(found.component_path(counts, many)) == {
        "name": "many",
        "min": 3,
        "max": 6,
        "cluster_size": 2,
    }


def test_constraints_are_named_with_their_places_one_or_several() -> None:
    rules = rules_of()
    assert constraint_list(rules, [0]) == "'no microphone on a UAV' (rules.yaml:16:5)"
    assert blame(rules, [0]) == (
        "constraint 'no microphone on a UAV' (rules.yaml:16:5) alone excludes"
    )
    uav = Condition("kinematic_type", frozenset({"UAV"}), "is UAV")
    second = RuleConstraint("UAVs only", "require", (), (uav,), Location("rules.yaml", 20, 5))
    third = RuleConstraint("a\nb", "require", (), (uav,), Location("rules.yaml", 24, 5))
    three = replace(rules, constraints=(*rules.constraints, second, third))
    assert blame(three, [0, 1, 2]) == (
        "constraints 'no microphone on a UAV' (rules.yaml:16:5), 'UAVs only' (rules.yaml:20:5)"
        " and 'a\\nb' (rules.yaml:24:5) together exclude"
    )


def test_a_teams_selection_is_located_at_the_value_or_at_its_kinematic_type() -> None:
    team = team_of()
    document = parse_document(SMALL_TEAM, "team.yaml")
    found = TeamContext(team, document, Analysis(team.rules))
    counts, sensors = (
        team.rules.characteristic("sensor_count"),
        team.rules.characteristic("sensor_type"),
    )
    assert str(found.selection_location("UGV", counts, 5)) == "team.yaml:3:30"
    assert not found.is_open("UGV", counts)
    assert found.is_open("UAV", sensors)  # UAV: {} selects every sensor type
    assert str(found.selection_location("UAV", sensors, "lidar")) == "team.yaml:4:3"
    assert found.live["UAV"][1] == frozenset({"camera", "lidar"})  # no microphone on a UAV
