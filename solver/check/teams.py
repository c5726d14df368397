"""A team selection read against its rule set: what the selection asks for that cannot be.

A team says which values robots of each kinematic type may have; the rule set's constraints
may forbid some of them for that type (or in combination with the rest of the selection).
Real robots with such values are invalid and get the default UI configuration, which the
team's author should hear about with the reason: the constraints (file and line) that exclude
them, a deletion-minimal set found with the SAT solver over the team's own domains. A
selection that leaves a type, or the whole team, without any valid robot is an error; a
selected value that no component serves (a coverage gap in the rules) is a warning too.

Not here: the rule set on its own (the other check modules); counting configurations
(``teleop-ui solve``).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import (
    TeamContext,
    blame,
    constraint_list,
    integer_runs,
    values_text,
)
from solver.check.finding import Check, Finding, Related
from solver.core.constraints import Value
from solver.core.ruleset import Characteristic
from solver.core.team import TypeSelection
from solver.errors import Location

__all__ = ["CHECKS"]


def _related(context: TeamContext, conflict: tuple[int, ...], message: str) -> tuple[Related, ...]:
    rules = context.rules
    return tuple(
        Related(rules.constraints[i].location, f"{message}: {rules.constraints[i].describe()}")
        for i in conflict
    )


def _selects(context: TeamContext, kinematic_type: str, characteristic: Characteristic) -> str:
    if context.is_open(kinematic_type, characteristic):
        return (
            f"{kinematic_type} leaves {characteristic.name} open, so it selects "
            f"{characteristic.name}"
        )
    return f"{kinematic_type} selects {characteristic.name}"


def _void_types(context: TeamContext) -> list[TypeSelection]:
    position = context.rules.key_position
    return [s for s in context.team.selections if not context.live[s.kinematic_type][position]]


def _void_team(context: TeamContext) -> Iterator[Finding]:
    selections = context.team.selections
    if selections and len(_void_types(context)) == len(selections):
        yield VOID_TEAM.finding(
            context.locate(("team",), key=True),
            "the team has no valid robot at all: every kinematic type it "
            "selects is void (see each type)",
        )


def _void_team_types(context: TeamContext) -> Iterator[Finding]:
    analysis = context.analysis
    for selection in _void_types(context):
        conflict = analysis.minimal_conflict(selection.domains)
        yield VOID_TEAM_TYPE.finding(
            context.locate(("team", selection.kinematic_type), key=True),
            f"{selection.kinematic_type}: the selection leaves no valid robot: "
            f"{blame(context.rules, conflict)} every robot it selects",
            _related(context, conflict, "in the conflict"),
        )


def _forbidden(context: TeamContext) -> Iterator[Finding]:
    analysis = context.analysis
    rules = context.rules
    void = {s.kinematic_type for s in _void_types(context)}
    for selection in context.team.selections:
        kt = selection.kinematic_type
        if kt in void:
            continue
        analysis.check_time()
        live = context.live[kt]
        for position, characteristic in enumerate(rules.characteristics):
            # A characteristic the team leaves open takes whatever the rules allow.
            if position == rules.key_position or context.is_open(kt, characteristic):
                continue
            # Live values are some of the selected ones: as many means none is dead.
            if len(live[position]) == len(selection.domains[position]):
                continue
            dead = [v for v in selection.domains[position] if v not in live[position]]
            found: dict[tuple[Location, tuple[int, ...]], list[Value]] = {}
            for values in _groups(characteristic, dead):
                conflict = analysis.minimal_conflict(
                    analysis.narrowed(selection.domains, position, values)
                )
                location = context.selection_location(kt, characteristic, values[0])
                found.setdefault((location, conflict), []).extend(values)
            for (location, conflict), chosen in found.items():
                yield FORBIDDEN.finding(
                    location,
                    f"{kt} selects {characteristic.name} {values_text(characteristic, chosen)} "
                    f"but no valid {kt} robot of this selection can have it: excluded by "
                    f"{constraint_list(rules, conflict)}; such robots get the default UI "
                    "configuration",
                    _related(context, conflict, "excludes it"),
                )


def _groups(characteristic: Characteristic, values: list[Value]) -> list[tuple[Value, ...]]:
    """Values one at a time, or runs of consecutive counts."""
    if characteristic.kind != "integer":
        return [(v,) for v in values]
    return list(integer_runs(values))


def _uncovered(context: TeamContext) -> Iterator[Finding]:
    rules = context.rules
    # The values no component serves, found once: each of 20,000 selected types walked all
    # 100,000 counts of the rule set for them. Live values are selected ones.
    unserved = [_unserved(c) for c in rules.characteristics]
    for selection in context.team.selections:
        kt = selection.kinematic_type
        context.analysis.check_time()
        live = context.live[kt]
        for position, characteristic in enumerate(rules.characteristics):
            gaps = sorted(
                (v for v in unserved[position] if v in live[position]),
                key=characteristic.positions.__getitem__,
            )
            found: dict[Location, list[Value]] = {}
            for values in _groups(characteristic, gaps):
                location = context.selection_location(kt, characteristic, values[0])
                found.setdefault(location, []).extend(values)
            for location, chosen in found.items():
                yield UNCOVERED.finding(
                    location,
                    f"{_selects(context, kt, characteristic)} "
                    f"{values_text(characteristic, chosen)}, "
                    f"which no component of the rules ({rules.file}) serves: such robots get "
                    "the default UI configuration",
                )


def _unserved(characteristic: Characteristic) -> frozenset[Value]:
    """The values of ``characteristic`` that no component serves (coverage gaps)."""
    membership = characteristic.membership
    return frozenset(v for i, v in enumerate(characteristic.values) if not membership[i])


VOID_TEAM = Check(
    "void-team",
    "error",
    "team",
    "The team has no valid robot at all: for every kinematic type it selects, the rule set's "
    "constraints exclude every combination the selection allows. Each type is also reported "
    "as `void-team-type` with its reason.",
    _void_team,
)
VOID_TEAM_TYPE = Check(
    "void-team-type",
    "error",
    "team",
    "A kinematic type of the team whose selection leaves no valid robot under the rule set's "
    "constraints, with a minimal set of constraints (file and line) that excludes everything "
    "it selects. The team gets no UI configuration for that type.",
    _void_team_types,
)
FORBIDDEN = Check(
    "team-forbidden-value",
    "warning",
    "team",
    "A team selects a value for a kinematic type that the rule set's constraints forbid for "
    "that type (given the rest of its selection): no valid robot of the team has it, so real "
    "robots with it get the default UI configuration. The message names the constraints "
    "responsible, with file and line. A characteristic the team leaves out takes whatever "
    "the rules allow and is not reported.",
    _forbidden,
)
UNCOVERED = Check(
    "team-uncovered-value",
    "warning",
    "team",
    "A team selects a value that no component of its rule set serves (a `coverage-gap` in the "
    "rules): valid robots with it have no UI configuration and get the default one.",
    _uncovered,
)

CHECKS: tuple[Check[TeamContext], ...] = (VOID_TEAM, VOID_TEAM_TYPE, FORBIDDEN, UNCOVERED)
