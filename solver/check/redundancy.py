"""Redundant and tautological constraints: rules that change nothing.

Redundancy is entailment, strictly: a constraint is *redundant* when the other constraints
already exclude every robot it excludes, so removing it changes no valid robot. It is decided
with the SAT solver, not by comparing rule texts: for each box of robots the constraint
excludes (:mod:`solver.core.regions`), the model over that box with all the *other*
constraints must have no solution. The message names a deletion-minimal set of constraints
that entails it. A constraint is *tautological* when it excludes no robot at all, whatever the
other constraints say (``when: {sensor_type: LIDAR}`` ``require: {sensor_type: [LIDAR,
3D Scanning]}``). Of two identical constraints each is redundant given the other.

Not reported for a void rule set (there, every constraint outside the conflict is trivially
redundant; the conflict is the finding).

Not here: constraints that conflict (:mod:`solver.check.void`).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext
from solver.check.finding import Check, Finding
from solver.untrusted import shown

__all__ = ["CHECKS"]


def _redundant(context: RulesContext) -> Iterator[Finding]:
    analysis = context.analysis
    if analysis.is_void:
        return
    for index, entailing in enumerate(analysis.entailments):
        if not entailing:
            continue
        rule = context.rules.constraints[index]
        verb = "excludes" if len(entailing) == 1 else "exclude"
        yield REDUNDANT.finding(
            rule.location,
            f"constraint {shown(rule.name, quoted=True)} is redundant: "
            f"{context.constraint_list(entailing)} "
            f"already {verb} every robot it excludes; removing it changes no valid robot",
            context.constraint_related(entailing, "entails it"),
        )


def _tautologies(context: RulesContext) -> Iterator[Finding]:
    for index in range(len(context.rules.constraints)):
        if not context.analysis.exclusions(index):
            rule = context.rules.constraints[index]
            yield TAUTOLOGY.finding(
                rule.location, f"constraint {rule.describe()} excludes no robot at all"
            )


REDUNDANT = Check(
    "redundant-constraint",
    "warning",
    "rules",
    "A constraint the other constraints already entail: every robot it excludes is excluded "
    "by them too, so removing it changes no valid robot (checked with the SAT solver over "
    "the robots it excludes, with every other constraint). The message names a minimal set "
    "of constraints that entails it. Of two identical constraints, each is reported.",
    _redundant,
)
TAUTOLOGY = Check(
    "tautology",
    "warning",
    "rules",
    "A constraint that excludes no robot at all, whatever the other constraints say: its "
    "required values always hold whenever its conditions do (for example `when: {sensor_type: "
    "LIDAR}` with `require: {sensor_type: [LIDAR, 3D Scanning]}`). It is probably not what "
    "its author meant.",
    _tautologies,
)

CHECKS: tuple[Check[RulesContext], ...] = (REDUNDANT, TAUTOLOGY)
