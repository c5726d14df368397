"""Answers from a question's neighbourhood (:mod:`solver.core.oracle`), against brute force.

Chains of characteristics, each linked to its neighbours, are where the oracle answers from
the characteristics near the ones a question narrows. It does so from 128 characteristics on
(:data:`~solver.core.oracle.NEAR_FROM`); here from any number, so that brute force can tell.
Whatever it answers locally must be what enumerating every robot says: the live values, and
the very constraints deletion in declared order keeps for a dead value and for a redundant
constraint.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import Any

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from solver.core import oracle
from solver.core.analysis import Analysis
from solver.core.constraints import RuleConstraint, Value
from solver.core.rules import parse_rules
from solver.core.ruleset import RuleSet
from solver.files.yamlio import parse_document
from tests.check.helpers import valid_robots


@pytest.fixture(autouse=True)
def _near_everywhere(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every oracle here asks near the question first, however few its characteristics."""
    monkeypatch.setattr(oracle, "NEAR_FROM", 0)


# The fixture only sets a constant: it holds for every example.
FIXTURE_OK = [HealthCheck.function_scoped_fixture]


def _rules(data: dict[str, Any]) -> RuleSet:
    return parse_rules(parse_document(yaml.safe_dump(data, sort_keys=False), "chain.yaml"))


@st.composite
def chains(draw: st.DrawFn) -> RuleSet:
    """6 or 7 characteristics of 2 or 3 values, constraints between neighbours (sometimes
    one further, sometimes with the kinematic type)."""
    count = draw(st.integers(6, 7))
    domains = {f"c{i}": [f"v{k}" for k in range(draw(st.integers(2, 3)))] for i in range(count)}
    kinds = [f"K{i}" for i in range(draw(st.integers(1, 2)))]
    names = list(domains)

    def some(name: str) -> list[str]:
        values = kinds if name == "kind" else domains[name]
        most = len(values) - 1 or 1
        return draw(st.lists(st.sampled_from(values), min_size=1, max_size=most, unique=True))

    constraints = []
    for index in range(draw(st.integers(3, 10))):
        first = draw(st.integers(0, count - 1))
        group = [names[first], names[min(first + draw(st.integers(1, 2)), count - 1)]]
        if draw(st.integers(0, 5)) == 0:
            group.append("kind")
        group = list(dict.fromkeys(group))
        rule: dict[str, Any] = {"name": f"r{index}"}
        kind = draw(st.sampled_from(["forbid", "forbid", "require", "when"]))
        if kind == "when" and len(group) > 1:
            rule["when"] = {group[0]: some(group[0])}
            rule["require"] = {name: some(name) for name in group[1:]}
        else:
            verb = "require" if kind == "require" else "forbid"
            rule[verb] = {name: some(name) for name in group}
        constraints.append(rule)
    characteristics = {"kind": {"values": kinds}} | {n: {"values": v} for n, v in domains.items()}
    return _rules({"characteristics": characteristics, "constraints": constraints})


def _deletion(every: Sequence[RuleConstraint], conflicts: Any) -> tuple[int, ...]:
    """Deletion in declared order by brute force: drop each constraint while the rest still
    ``conflicts``."""
    kept: list[int] = []
    for index in range(len(every)):
        if not conflicts([*kept, *range(index + 1, len(every))]):
            kept.append(index)
    return tuple(kept)


def _live(rules: RuleSet, domains: Sequence[Sequence[Value]]) -> tuple[frozenset[Value], ...]:
    found = valid_robots(rules, domains)
    return tuple(frozenset(robot[i] for robot in found) for i in range(len(domains)))


@settings(max_examples=60, deadline=None, suppress_health_check=FIXTURE_OK)
@given(chains())
def test_live_values_and_the_reasons_for_dead_ones_match_brute_force(rules: RuleSet) -> None:
    analysis = Analysis(rules)
    every = rules.constraints
    for kinematic_type, live in analysis.type_live.items():
        domains = analysis.type_domains(kinematic_type)
        assert live == _live(rules, domains)
        if not live[0]:
            continue
        for position, characteristic in enumerate(rules.characteristics):
            for value in characteristic.values:
                if value in live[position]:
                    continue
                narrowed = analysis.narrowed(domains, position, [value])

                def conflicts(subset: list[int], narrowed: Any = narrowed) -> bool:
                    return not valid_robots(rules, narrowed, [every[i] for i in subset])

                assert analysis.minimal_conflict(narrowed) == _deletion(every, conflicts)


@settings(max_examples=40, deadline=None, suppress_health_check=FIXTURE_OK)
@given(chains())
def test_the_constraints_that_entail_a_redundant_one_match_brute_force(rules: RuleSet) -> None:
    analysis = Analysis(rules)
    every = rules.constraints
    robots = list(itertools.product(*analysis.full))
    if not valid_robots(rules, analysis.full):
        return

    def holds(rule: RuleConstraint, robot: tuple[Value, ...]) -> bool:
        return rule.holds(dict(zip(rules.names, robot, strict=True)))

    for index, rule in enumerate(every):
        excluded = [robot for robot in robots if not holds(rule, robot)]

        def entails(subset: list[int], excluded: Any = excluded) -> bool:
            return not any(all(holds(every[i], r) for i in subset) for r in excluded)

        others = [i for i in range(len(every)) if i != index]

        def entailed(subset: list[int], others: list[int] = others) -> bool:
            return entails([others[i] for i in subset])

        expected = None
        if entails(others):
            kept = _deletion([every[i] for i in others], entailed)
            expected = tuple(others[i] for i in kept)
        assert analysis.entailing(index) == expected


def test_a_value_dead_through_a_whole_chain_is_found_and_explained() -> None:
    """x0 = a forces a all along 40 links, and the last characteristic cannot be a: the
    neighbourhood grows past half the chain, and the whole chain answers."""
    count = 40
    characteristics = {"kind": {"values": ["K"]}} | {
        f"x{i:02d}": {"values": ["a", "b"]} for i in range(count)
    }
    constraints: list[dict[str, Any]] = [
        {"name": f"link {i}", "when": {f"x{i:02d}": "a"}, "require": {f"x{i + 1:02d}": "a"}}
        for i in range(count - 1)
    ]
    constraints.append({"name": "end", "forbid": {f"x{count - 1:02d}": "a"}})
    analysis = Analysis(_rules({"characteristics": characteristics, "constraints": constraints}))
    assert [sorted(values) for values in analysis.live_anywhere[1:]] == [["b"]] * count
    first = analysis.narrowed(analysis.full, 1, ["a"])
    assert analysis.minimal_conflict(first) == tuple(range(count))
    middle = analysis.narrowed(analysis.full, 21, ["a"])
    assert analysis.minimal_conflict(middle) == tuple(range(20, count))
