"""The constraint model: characteristics as python-constraint variables, rules as constraints.

One :class:`constraint.Problem` per question: its variables are the rule set's characteristics,
its domains the values a team selection (or the whole rule set) allows, and every declared
:class:`~solver.core.constraints.RuleConstraint` becomes a ``FunctionConstraint`` over the
characteristics it reads. Rule text is never handed to python-constraint's string parser,
which evaluates Python.

Solving, checking and explaining all go through here, so there is one notion of "valid robot".

Not here: partitioning robots into UI configurations (:mod:`solver.core.partition`).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from typing import TYPE_CHECKING

from solver.core.constraints import RuleConstraint, Value
from solver.core.ruleset import RuleSet

if TYPE_CHECKING:
    from constraint import Problem

__all__ = ["Robot", "build_problem", "is_satisfiable", "robots", "violated_constraints"]

# A robot is one value per characteristic, in the rule set's characteristic order.
Robot = tuple[Value, ...]


def build_problem(
    rules: RuleSet,
    domains: Sequence[Sequence[Value]],
    constraints: Iterable[RuleConstraint] | None = None,
) -> Problem | None:
    """The problem over ``domains`` (one per characteristic) with ``constraints``.

    ``constraints`` defaults to every constraint of the rule set; pass a subset to ask what
    happens without some (redundancy, explanations). ``None`` when a domain is empty: such a
    problem has no solutions and python-constraint refuses empty domains.
    """
    # Imported here: the structural counter and the command line do not need the solver.
    from constraint import FunctionConstraint, Problem

    if any(len(domain) == 0 for domain in domains):
        return None
    problem = Problem()
    for characteristic, domain in zip(rules.characteristics, domains, strict=True):
        problem.addVariable(characteristic.name, list(domain))
    for rule in rules.constraints if constraints is None else constraints:
        problem.addConstraint(FunctionConstraint(rule.predicate()), list(rule.characteristics))
    return problem


def robots(
    rules: RuleSet,
    domains: Sequence[Sequence[Value]],
    constraints: Iterable[RuleConstraint] | None = None,
) -> Iterator[Robot]:
    """Every valid robot over ``domains``, streamed from python-constraint's solution iterator."""
    problem = build_problem(rules, domains, constraints)
    if problem is None:
        return
    names = rules.names
    for solution in problem.getSolutionIter():
        yield tuple(solution[name] for name in names)


def is_satisfiable(
    rules: RuleSet,
    domains: Sequence[Sequence[Value]],
    constraints: Iterable[RuleConstraint] | None = None,
) -> bool:
    """Whether at least one robot over ``domains`` satisfies ``constraints``."""
    problem = build_problem(rules, domains, constraints)
    return problem is not None and problem.getSolution() is not None


def violated_constraints(rules: RuleSet, robot: Robot) -> tuple[RuleConstraint, ...]:
    """The rule set's constraints that ``robot`` breaks, in declared order."""
    values = dict(zip(rules.names, robot, strict=True))
    return tuple(rule for rule in rules.constraints if not rule.holds(values))
