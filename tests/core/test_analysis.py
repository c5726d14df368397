"""The model questions of :mod:`solver.core.analysis`, against brute force (hypothesis).

Whatever shortcuts the analysis takes (relevant constraints only, one representative per class
of interchangeable values, witnesses), its answers must equal those of enumerating every
combination and testing every constraint with ``RuleConstraint.holds``.
"""

from __future__ import annotations

import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from solver.core.analysis import Analysis
from solver.core.constraints import Value
from solver.core.rules import parse_rules
from solver.core.ruleset import RuleSet
from solver.files.yamlio import parse_document
from tests.check.helpers import rule_sets, valid_robots

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
