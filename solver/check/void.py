"""Void rule sets and kinematic types, and the minimal conflicts that explain them.

A rule set is *void* when its constraints leave no valid robot at all; a kinematic type is void
when they leave no robot of that type (every team that selects it gets nothing). Either way
the author needs to know which constraints are to blame: a *minimal conflicting subset*,
found by deletion (drop one constraint, re-solve, keep it dropped while still void), so that
every constraint named is necessary and each is cited by file and line.

The questions go to a SAT solver per kinematic type (:mod:`solver.core.analysis`).

Not here: values that only some robots lose (:mod:`solver.check.dead`); teams
(:mod:`solver.check.teams`).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext, blame
from solver.check.finding import Check, Finding
from solver.core.constraints import Value
from solver.untrusted import shown

__all__ = ["CHECKS"]


def _void(context: RulesContext) -> Iterator[Finding]:
    analysis = context.analysis
    if not context.rules.constraints or not analysis.is_void:
        return
    conflict = analysis.void_conflict
    yield VOID.finding(
        context.locate(("constraints",), key=True),
        f"no valid robot at all: {blame(context.rules, conflict)} every combination",
        context.constraint_related(conflict, "in the conflict"),
    )


def _void_types(context: RulesContext) -> Iterator[Finding]:
    analysis = context.analysis
    if not context.rules.constraints or analysis.is_void:
        return
    key = context.rules.key
    for kinematic_type, conflict in analysis.type_conflicts.items():
        yield VOID_TYPE.finding(
            context.value_location(key, kinematic_type),
            f"{key.name} {shown(str(kinematic_type), quoted=True)} has no valid robot: "
            f"{blame(context.rules, conflict)} every {kinematic_type} robot",
            context.constraint_related(conflict, "in the conflict"),
        )


def _conflicts(context: RulesContext) -> Iterator[Finding]:
    analysis = context.analysis
    if not context.rules.constraints:
        return
    key = context.rules.key
    by_conflict: dict[tuple[int, ...], list[Value]] = {}
    if analysis.is_void:
        by_conflict[analysis.void_conflict] = []
    else:
        for kinematic_type, conflict in analysis.type_conflicts.items():
            by_conflict.setdefault(conflict, []).append(kinematic_type)
    for conflict, types in by_conflict.items():
        victims = (
            "no valid robot at all"
            if not types
            else f"no valid robot of {key.name} {', '.join(repr(str(t)) for t in types)}"
        )
        first = context.rules.constraints[conflict[0]]
        if len(conflict) == 1:
            text = f"constraint {shown(first.name, quoted=True)} alone leaves {victims}"
        else:
            text = (
                f"constraints {context.constraint_list(conflict)} conflict: together they "
                f"leave {victims} (a minimal conflict: each of them is needed)"
            )
        yield CONFLICT.finding(
            first.location, text, context.constraint_related(conflict[1:], "also in the conflict")
        )


VOID = Check(
    "void",
    "error",
    "rules",
    "The rule set has no valid robot at all: its constraints exclude every combination of "
    "values. The message names a minimal conflicting subset of constraints with their lines.",
    _void,
)
VOID_TYPE = Check(
    "void-type",
    "error",
    "rules",
    "A kinematic type (a value of the team key) for which the constraints leave no valid "
    "robot: every team selecting it gets no robots and no UI configurations of that type. "
    "Reported at the type's entry with the constraints that cause it; not reported when the "
    "whole rule set is void.",
    _void_types,
)
CONFLICT = Check(
    "conflict",
    "error",
    "rules",
    "A minimal conflicting subset of constraints, reported at the first of them: together they "
    "make the rule set or a kinematic type void, and without any one of them the rest of the "
    "subset leaves robots. Found by deletion (drop one constraint, re-solve with "
    "the SAT solver, keep it dropped while still void), so every constraint named is "
    "necessary; types voided by the same subset are reported together.",
    _conflicts,
)

CHECKS: tuple[Check[RulesContext], ...] = (VOID, VOID_TYPE, CONFLICT)
