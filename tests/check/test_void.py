"""Void rule sets and kinematic types, explained by minimal conflicting subsets."""

from __future__ import annotations

from hypothesis import given, settings

from solver.check.context import RulesContext
from solver.check.void import VOID, VOID_TYPE
from solver.core.analysis import Analysis
from solver.core.model import is_satisfiable
from solver.core.rules import load_rules
from solver.core.ruleset import RuleSet
from tests.check.helpers import findings, fixture, rule_sets, valid_robots


def test_void_rule_set_names_only_the_constraints_that_conflict() -> None:
    [void] = findings("void.yaml", check="void")
    assert "'few only'" in void.message
    assert "'many only'" in void.message
    assert "microphone" not in void.message
    assert void.message.startswith("no valid robot at all: constraints 'few only' (")


def test_the_conflict_is_reported_at_its_first_constraint_with_the_others_related() -> None:
    [conflict] = findings("void.yaml", check="conflict")
    assert (conflict.line, conflict.column) == (30, 5)
    assert [(r.location.line, r.location.column) for r in conflict.related] == [(34, 5)]
    assert conflict.message.endswith(
        "together they leave no valid robot at all (a minimal conflict: each of them is needed)"
    )


def test_the_minimal_conflict_is_void_and_each_member_is_needed_by_the_model() -> None:
    rules = load_rules(fixture("void.yaml"))
    domains = [c.values for c in rules.characteristics]
    few, microphone, many = rules.constraints
    assert not is_satisfiable(rules, domains, [few, many])
    assert is_satisfiable(rules, domains, [few, microphone])
    assert is_satisfiable(rules, domains, [microphone, many])


def test_void_kinematic_type_is_reported_at_its_entry_with_its_conflict() -> None:
    [void] = findings("void-type.yaml", check="void-type")
    assert void.message.startswith(
        "kinematic_type 'Arm' has no valid robot: constraints 'arms are jointed' ("
    )
    assert void.message.endswith("together exclude every Arm robot")
    assert "Flight" not in void.message


def test_types_voided_by_the_same_constraints_share_one_conflict() -> None:
    [conflict] = findings("conflict.yaml", check="conflict")
    assert "no valid robot of kinematic_type 'UGV', 'Arm'" in conflict.message
    assert "microphone" not in conflict.message
    assert len(findings("conflict.yaml", check="void-type")) == 2


def test_a_void_rule_set_reports_no_void_types_nor_dead_values() -> None:
    checks = {f.check for f in findings("void.yaml")}
    assert checks == {"bound", "void", "conflict"}


@settings(max_examples=100, deadline=None)
@given(rule_sets())
def test_void_findings_are_the_types_without_any_robot_by_brute_force(rules: RuleSet) -> None:
    key = rules.key
    domains = [c.values for c in rules.characteristics]
    void = [kt for kt in key.values if not valid_robots(rules, [(kt,), *domains[1:]])]
    context = RulesContext(rules, Analysis(rules))
    whole = list(VOID.run(context))
    types = [f.location.path for f in VOID_TYPE.run(context)]
    if void and len(void) == len(key.values):
        assert (len(whole), types) == (1, [])
    else:
        assert whole == []
        assert types == [f"characteristics.kind.values[{key.values.index(kt)}]" for kt in void]
