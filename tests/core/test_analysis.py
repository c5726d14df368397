"""The model questions of :mod:`solver.core.analysis`, against brute force (hypothesis).

Whatever shortcuts the analysis takes (relevant constraints only, one representative per class
of interchangeable values, witnesses), its answers must equal those of enumerating every
combination and testing every constraint with ``RuleConstraint.holds``.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from solver.core import analysis as analysis_module
from solver.core.analysis import Analysis
from solver.core.constraints import Value
from solver.core.rules import parse_rules
from solver.core.ruleset import RuleSet
from solver.deadline import Deadline
from solver.errors import TimeLimitError
from solver.files.yamlio import parse_document
from tests.check.helpers import pigeonhole_rules, rule_sets, valid_robots

Domains = tuple[tuple[Value, ...], ...]


@st.composite
def restricted(draw: st.DrawFn) -> tuple[RuleSet, Domains]:
    """A random rule set and random non-empty sub-domains of its characteristics."""
    rules = draw(rule_sets())
    domains = []
    for characteristic in rules.characteristics:
        kept = draw(st.sets(st.sampled_from(characteristic.values), min_size=1))
        domains.append(tuple(v for v in characteristic.values if v in kept))
    return rules, tuple(domains)


def _live_by_brute_force(rules: RuleSet, domains: Domains) -> tuple[frozenset[Value], ...]:
    found = valid_robots(rules, domains)
    return tuple(frozenset(robot[i] for robot in found) for i in range(len(domains)))


@settings(max_examples=120, deadline=None)
@given(restricted())
def test_live_values_are_the_values_of_the_valid_robots(case: tuple[RuleSet, Domains]) -> None:
    rules, domains = case
    assert Analysis(rules).live(domains) == _live_by_brute_force(rules, domains)


@settings(max_examples=100, deadline=None)
@given(rule_sets())
def test_live_values_per_kinematic_type_match_brute_force(rules: RuleSet) -> None:
    analysis = Analysis(rules)
    for kinematic_type, live in analysis.type_live.items():
        assert live == _live_by_brute_force(rules, analysis.type_domains(kinematic_type))


@settings(max_examples=100, deadline=None)
@given(restricted())
def test_a_witness_is_a_valid_robot_and_exists_exactly_when_one_does(
    case: tuple[RuleSet, Domains],
) -> None:
    rules, domains = case
    robot = Analysis(rules).witness(domains)
    expected = valid_robots(rules, domains)
    if robot is None:
        assert expected == []
    else:
        assert robot in expected


@settings(max_examples=120, deadline=None)
@given(restricted())
def test_minimal_conflict_is_void_and_each_of_its_constraints_is_needed(
    case: tuple[RuleSet, Domains],
) -> None:
    rules, domains = case
    if valid_robots(rules, domains):
        return
    conflict = Analysis(rules).minimal_conflict(domains)
    chosen = [rules.constraints[i] for i in conflict]
    assert conflict
    assert valid_robots(rules, domains, chosen) == []
    for left_out in range(len(chosen)):
        rest = chosen[:left_out] + chosen[left_out + 1 :]
        assert valid_robots(rules, domains, rest) != []


@settings(max_examples=120, deadline=None)
@given(rule_sets(max_constraints=4))
def test_redundancy_is_entailment(rules: RuleSet) -> None:
    """Redundant exactly when removing the constraint changes no valid robot; the entailing
    set excludes everything the constraint excludes, and each of its members is needed."""
    analysis = Analysis(rules)
    domains = analysis.full
    every = list(rules.constraints)
    for index, rule in enumerate(every):
        without = every[:index] + every[index + 1 :]
        unchanged = valid_robots(rules, domains, without) == valid_robots(rules, domains)
        excludes_nothing = valid_robots(rules, domains, [rule]) == valid_robots(rules, domains, [])
        entailing = analysis.entailing(index)
        assert (entailing is not None) == unchanged
        assert (entailing == ()) == excludes_nothing
        if not entailing:
            continue
        chosen = [every[i] for i in entailing]
        assert index not in entailing
        assert all(
            rule.holds(dict(zip(rules.names, robot, strict=True)))
            for robot in valid_robots(rules, domains, chosen)
        )
        for left_out in range(len(chosen)):
            rest = chosen[:left_out] + chosen[left_out + 1 :]
            assert not all(
                rule.holds(dict(zip(rules.names, robot, strict=True)))
                for robot in valid_robots(rules, domains, rest)
            )


def test_two_identical_constraints_are_each_redundant_given_the_other() -> None:
    rule = {"name": "no lidar drones", "forbid": {"kind": "UAV", "sensor": "Lidar"}}
    data = {
        "characteristics": {
            "kind": {"values": ["UAV", "UGV"]},
            "sensor": {"values": ["Camera", "Lidar"]},
        },
        "constraints": [rule, dict(rule, name="no lidar drones, again")],
    }
    rules = parse_rules(parse_document(yaml.safe_dump(data), "twice.yaml"))
    analysis = Analysis(rules)
    assert analysis.entailing(0) == (1,)
    assert analysis.entailing(1) == (0,)


def _one_constraint_per_type(types: int) -> RuleSet:
    """Each type with a constraint of its own (so an oracle of its own) beside two about any
    type; a third of the types lose a sensor, and K0 every one."""
    data = {
        "characteristics": {
            "kind": {"values": [f"K{i}" for i in range(types)]},
            "sensor": {"values": ["a", "b", "c"]},
            "count": {"range": {"min": 1, "max": 4}},
        },
        "constraints": [
            {"forbid": {"sensor": "a", "count": 1}},
            {"when": {"sensor": "b"}, "require": {"count": {"min": 2}}},
            *({"forbid": {"kind": f"K{i}", "sensor": "abc"[i % 3]}} for i in range(types)),
            {"forbid": {"kind": "K0", "count": {"min": 2}}},
        ],
    }
    return parse_rules(parse_document(yaml.safe_dump(data, sort_keys=False), "types.yaml"))


def test_type_oracles_dropped_to_bound_memory_give_the_same_answers(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    rules = _one_constraint_per_type(12)
    kept = Analysis(rules)
    expected = {kt: kept.live(kept.type_domains(kt)) for kt in rules.key.values}
    # One oracle at a time: every question about another type drops the one before.
    monkeypatch.setattr(analysis_module, "VARIABLES_KEPT", 1)
    dropped = Analysis(rules)
    for _ in range(2):  # the second time, each oracle is built again
        for kinematic_type in rules.key.values:
            domains = dropped.type_domains(kinematic_type)
            assert dropped.live(domains) == expected[kinematic_type]
            assert expected[kinematic_type] == _live_by_brute_force(rules, domains)
    assert len(dropped._oracles) == 1
    k0 = dropped.type_domains("K0")
    assert dropped.minimal_conflict(dropped.narrowed(k0, 2, (2, 3, 4))) == (14,)


def test_a_long_sat_search_stops_at_its_deadline_not_at_its_conflicts(
    write_file: Callable[[str, str], Path],
) -> None:
    # 16 pigeons, 15 holes: no robot, and MiniSat spends the whole conflicts limit (seconds)
    # before it can tell. It looks at the deadline every STEP_CONFLICTS conflicts.
    text = pigeonhole_rules(16, 15)
    path = write_file("pigeonhole.yaml", text)
    rules = parse_rules(parse_document(text, str(path)))
    analysis = Analysis(rules, deadline=Deadline.start("check-seconds", "check", 0.2))
    with pytest.raises(TimeLimitError) as caught:
        analysis.live(analysis.full)
    assert str(caught.value) == (
        f"{path}: check stopped after 0.2 s (limit 'check-seconds', docs/security.md; "
        "--time-limit sets it)"
    )
    assert analysis._budget.remaining > 0  # the conflicts limit was not reached
