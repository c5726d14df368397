"""Redundancy is entailment: removing a redundant constraint changes no valid robot."""

from __future__ import annotations

from solver.core.model import robots
from solver.core.rules import load_rules
from solver.core.ruleset import RuleSet
from tests.check.helpers import findings, fixture


def _valid(rules: RuleSet, skip: int | None = None) -> set[tuple[object, ...]]:
    kept = [r for i, r in enumerate(rules.constraints) if i != skip]
    return set(robots(rules, [c.values for c in rules.characteristics], kept))


def test_redundant_constraint_is_reported_with_the_constraint_that_entails_it() -> None:
    [redundant] = findings("redundant-constraint.yaml", check="redundant-constraint")
    assert redundant.message == (
        "constraint 'no microphone on drones with many sensors' is redundant: 'no microphone "
        f"on drones' ({fixture('redundant-constraint.yaml')}:30:5) already excludes every "
        "robot it excludes; removing it changes no valid robot"
    )
    assert [r.location.line for r in redundant.related] == [30]


def test_removing_the_redundant_constraint_changes_no_valid_robot() -> None:
    rules = load_rules(fixture("redundant-constraint.yaml"))
    assert _valid(rules, skip=1) == _valid(rules)
    assert _valid(rules, skip=0) != _valid(rules)
    assert _valid(rules, skip=2) != _valid(rules)


def test_overlapping_constraints_are_not_redundant_when_each_excludes_something_alone() -> None:
    rules = load_rules(fixture("redundant-constraint.clean.yaml"))
    assert _valid(rules, skip=0) != _valid(rules) != _valid(rules, skip=1)
    assert findings("redundant-constraint.clean.yaml", check="redundant-constraint") == []


def test_tautology_excludes_no_robot_and_is_not_also_called_redundant() -> None:
    rules = load_rules(fixture("tautology.yaml"))
    assert _valid(rules, skip=0) == _valid(rules)
    [tautology] = findings("tautology.yaml", check="tautology")
    assert tautology.message == (
        "constraint 'lidar robots have a lidar or a camera' (when sensor_type is Lidar require "
        "sensor_type in {Camera, Lidar}) excludes no robot at all"
    )
    assert findings("tautology.yaml", check="redundant-constraint") == []
