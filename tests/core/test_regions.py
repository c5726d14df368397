"""The exclusion boxes of a constraint are exactly the robots it excludes."""

from __future__ import annotations

import itertools

from hypothesis import given, settings

from solver.core.regions import regions, touches
from solver.core.ruleset import RuleSet
from tests.check.helpers import rule_sets


def _in_box(box: tuple[frozenset[object] | None, ...], robot: tuple[object, ...]) -> bool:
    return all(
        allowed is None or value in allowed for allowed, value in zip(box, robot, strict=True)
    )


@settings(max_examples=150, deadline=None)
@given(rule_sets())
def test_a_robot_is_in_a_box_exactly_when_the_constraint_excludes_it(rules: RuleSet) -> None:
    domains = [c.values for c in rules.characteristics]
    for rule in rules.constraints:
        boxes = regions(rules, rule)
        for robot in itertools.product(*domains):
            excluded = not rule.holds(dict(zip(rules.names, robot, strict=True)))
            assert any(_in_box(box, robot) for box in boxes) == excluded


@settings(max_examples=100, deadline=None)
@given(rule_sets())
def test_touches_says_whether_a_constraint_excludes_some_robot_of_the_domains(
    rules: RuleSet,
) -> None:
    domains = [c.values for c in rules.characteristics]
    for rule in rules.constraints:
        excludes_some = any(
            not rule.holds(dict(zip(rules.names, robot, strict=True)))
            for robot in itertools.product(*domains)
        )
        assert touches(regions(rules, rule), [frozenset(d) for d in domains]) == excludes_some
