"""Dead values and dead components: what the constraints make impossible.

A value is *dead* when no valid robot can have it: it is declared, teams may select it, and it
never appears. A component is dead when no valid robot ever needs it. Both are worth a
warning because they are usually an over-eager constraint. Per kinematic type, constraints
often remove values on purpose ("Flight only for UAVs"); those are reported at info level
(``dead-for-type``), once per type and characteristic, with the constraints responsible, so
that a rule author sees what each type can still have. Every reason is a deletion-minimal set
of constraints (:meth:`solver.core.analysis.Analysis.minimal_conflict`).

Not here: kinematic types that lose every robot (:mod:`solver.check.void`); what a team
selects (:mod:`solver.check.teams`). Nothing is reported for a void rule set.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from solver.check.context import RulesContext, integer_runs, values_text
from solver.check.finding import Check, Finding
from solver.core.constraints import Value
from solver.core.regions import Domains
from solver.core.ruleset import Characteristic
from solver.untrusted import shown

__all__ = ["CHECKS"]


def _analysable(context: RulesContext) -> bool:
    return bool(context.rules.constraints) and not context.analysis.is_void


def _others(context: RulesContext) -> Iterator[tuple[int, Characteristic]]:
    key = context.rules.key_position
    for position, characteristic in enumerate(context.rules.characteristics):
        if position != key:
            yield position, characteristic


def _excluded_by(context: RulesContext, conflict: tuple[int, ...]) -> str:
    listed = context.constraint_list(conflict)
    return f"excluded by {listed}" + (" together" if len(conflict) > 1 else "")


def _dead_values(context: RulesContext) -> Iterator[Finding]:
    if not _analysable(context):
        return
    analysis = context.analysis
    for position, characteristic in _others(context):
        live = analysis.live_anywhere[position]
        dead = [v for v in characteristic.values if v not in live]
        groups: list[tuple[Value, ...]] = (
            [(v,) for v in dead] if characteristic.kind != "integer" else list(integer_runs(dead))
        )
        for values in groups:
            conflict = analysis.minimal_conflict(analysis.narrowed(analysis.full, position, values))
            if characteristic.kind == "integer":
                location = context.locate(("characteristics", characteristic.name, "range"))
            else:
                location = context.value_location(characteristic, values[0])
            yield DEAD_VALUE.finding(
                location,
                f"{characteristic.name} {values_text(characteristic, values)} can "
                f"appear in no valid robot: {_excluded_by(context, conflict)}",
                context.constraint_related(conflict, "excludes it"),
            )


def _dead_components(context: RulesContext) -> Iterator[Finding]:
    if not _analysable(context):
        return
    for position, characteristic in _others(context):
        if not characteristic.declared_components:
            continue
        live = context.analysis.live_anywhere[position]
        for component in characteristic.components:
            if component.values and live.isdisjoint(component.values):
                yield DEAD_COMPONENT.finding(
                    context.component_location(characteristic, component),
                    f"{characteristic.name} component {shown(component.name, quoted=True)} is "
                    f"never needed: no "
                    f"valid robot has any of its values "
                    f"({values_text(characteristic, component.values)})",
                )


def _dead_for_type(context: RulesContext) -> Iterator[Finding]:
    if not _analysable(context):
        return
    analysis = context.analysis
    for kinematic_type, live in analysis.type_live.items():
        if kinematic_type in analysis.void_types:
            continue
        analysis.check_time()
        domains = analysis.type_domains(kinematic_type)
        for position, characteristic in _others(context):
            finding = _dead_for_one_type(
                context,
                kinematic_type,
                characteristic,
                position=position,
                domains=domains,
                live=live[position],
            )
            if finding is not None:
                yield finding


def _dead_for_one_type(
    context: RulesContext,
    kinematic_type: Value,
    characteristic: Characteristic,
    *,
    position: int,
    domains: Domains,
    live: frozenset[Value],
) -> Finding | None:
    """The values of ``characteristic`` other types can have and ``kinematic_type`` cannot,
    with why and the components the type so never needs; None when there are none."""
    anywhere = context.analysis.live_anywhere[position]
    # One value left is a core value, reported (with its reason) by core-value. Live values
    # are some of those live anywhere: as many means none is dead, told without a walk over
    # the values (each of 20,000 types walked all 100,000 counts).
    if len(live) == len(anywhere) or len(live) == 1:
        return None
    dead = sorted(anywhere - live, key=characteristic.positions.__getitem__)
    reasons = _reasons(context, domains, position, dead)
    blamed = sorted({i for _, conflict in reasons for i in conflict})
    return DEAD_FOR_TYPE.finding(
        context.value_location(context.rules.key, kinematic_type),
        f"no valid {kinematic_type} robot has {characteristic.name} "
        f"{values_text(characteristic, dead)}: {_why(context, characteristic, reasons)}"
        f"{_never_needed(characteristic, live, anywhere)}",
        context.constraint_related(blamed, "excludes them"),
    )


def _why(
    context: RulesContext,
    characteristic: Characteristic,
    reasons: list[tuple[list[Value], tuple[int, ...]]],
) -> str:
    """The constraints that exclude the values; each group of values with its own reason
    (never "A and B together" for two groups excluded apart)."""
    if len(reasons) == 1:
        return _excluded_by(context, reasons[0][1])
    return "; ".join(
        f"{values_text(characteristic, values)} {_excluded_by(context, conflict)}"
        for values, conflict in reasons
    )


def _never_needed(
    characteristic: Characteristic, live: frozenset[Value], anywhere: frozenset[Value]
) -> str:
    """``; so it never needs component 'x'`` for the declared components other types need
    and this one, left with ``live``, does not; empty when there are none."""
    if not characteristic.declared_components:
        return ""
    unused = [
        c.name
        for c in characteristic.components
        if c.values and not live.intersection(c.values) and anywhere.intersection(c.values)
    ]
    if not unused:
        return ""
    return f"; so it never needs component {', '.join(repr(n) for n in unused)}"


def _reasons(
    context: RulesContext, domains: Domains, position: int, dead: Sequence[Value]
) -> list[tuple[list[Value], tuple[int, ...]]]:
    """``dead`` values grouped by the minimal set of constraints that excludes each one.

    Values no constraint tells apart (one class of :meth:`Analysis.classes`) have the same
    reason, so the cost follows the classes, not the values (a range of 500 counts is a few
    classes). Groups are in the order of their first value.
    """
    analysis = context.analysis
    groups: dict[tuple[int, ...], list[Value]] = {}
    # Constraints that exclude nothing over ``domains`` cannot tell values apart there, and
    # values they cannot tell apart are all dead or all live: classes of the dead ones.
    for members in analysis.classes(dead, analysis.relevant(domains), position):
        conflict = analysis.minimal_conflict(analysis.narrowed(domains, position, members))
        groups.setdefault(conflict, []).extend(members)
    # Classes come in the order of their first values, so the groups do too.
    return [(values, conflict) for conflict, values in groups.items()]


DEAD_VALUE = Check(
    "dead-value",
    "warning",
    "rules",
    "A value of a characteristic that no valid robot of any kinematic type can have under the "
    "rule set's constraints: declared, selectable, and never used. The message names a "
    "minimal set of constraints that excludes it (consecutive counts are reported together). "
    "Kinematic types with no robot are reported as `void-type` instead.",
    _dead_values,
)
DEAD_COMPONENT = Check(
    "dead-component",
    "warning",
    "rules",
    "A UI component that no valid robot ever needs, because every value it serves is dead. It "
    "still counts in the bound T; a UI designer would design it for nothing.",
    _dead_components,
)
DEAD_FOR_TYPE = Check(
    "dead-for-type",
    "info",
    "rules",
    "Values that the constraints rule out for one kinematic type although other types can "
    "have them (for example, Flight for a UGV), with the minimal set of constraints "
    "responsible and the components that type therefore never needs. Usually intended; a "
    "team that selects such a value is warned by `team-forbidden-value`. When a single value "
    "is left, `core-value` reports it instead.",
    _dead_for_type,
)

CHECKS: tuple[Check[RulesContext], ...] = (DEAD_VALUE, DEAD_COMPONENT, DEAD_FOR_TYPE)
