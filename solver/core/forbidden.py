"""What a rule set's constraints remove from a team: selected values no valid robot can have.

A team selects values per kinematic type; a constraint of its rule set may forbid some of them for
that type (``no force feedback in flight``). The robots with such a value are not valid and get the
default UI configuration. ``solve``, ``report`` and ``batch`` say so (through
:func:`solver.solving.solution.solution_warnings`) and the report lists the constraints with what
they removed; ``teleop-ui check`` gives the same finding, located in the team file
(``team-forbidden-value``). The analysis is :class:`solver.core.analysis.Analysis`, shared with the
checker, so both always agree.

A characteristic a team leaves open (every value selected) is not reported: it takes whatever
the rules allow. A type left with no valid robot at all is reported as a whole.

Not here: the located finding for a team file (:mod:`solver.check.teams`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from solver.core.constraints import RuleConstraint, Value
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.core.analysis import Analysis
    from solver.core.regions import Domains
    from solver.core.ruleset import RuleSet
    from solver.core.team import Team
    from solver.deadline import Deadline

__all__ = ["Removed", "excluded_by_rules", "removed_by_constraints"]


@dataclass(frozen=True, slots=True)
class Removed:
    """Values one kinematic type selects that its rule set's constraints exclude.

    ``characteristic`` is empty when the whole type has no valid robot (``values`` is then
    empty too). ``constraints``: a minimal set that excludes them, in declared order.
    """

    kinematic_type: str
    characteristic: str
    values: tuple[Value, ...]
    constraints: tuple[RuleConstraint, ...]

    def describe(self) -> str:
        """``UAV: sensor_type Force Sensor, excluded by 'no force ...' (rules/x.yaml:70:5)``."""
        cited = " and ".join(
            f"{shown(c.name, quoted=True)} ({c.location})" for c in self.constraints
        )
        if not self.characteristic:
            return f"{self.kinematic_type}: no valid robot at all, excluded by {cited}"
        listed = ", ".join(str(value) for value in self.values)
        return f"{self.kinematic_type}: {self.characteristic} {listed}, excluded by {cited}"


def removed_by_constraints(team: Team, *, deadline: Deadline | None = None) -> tuple[Removed, ...]:
    """Per kinematic type and characteristic, the selected values the constraints exclude.

    ``deadline``: past it, :class:`~solver.errors.TimeLimitError` (the questions are those of
    ``check``, as long on an intricate rule set)."""
    rules = team.rules
    if not rules.constraints:
        return ()
    from solver.core.analysis import Analysis

    analysis = Analysis(rules, deadline=deadline)
    found: list[Removed] = []
    for selection in team.selections:
        kt = selection.kinematic_type
        live = analysis.live(selection.domains)
        if not live[rules.key_position]:
            conflict = analysis.minimal_conflict(selection.domains)
            found.append(Removed(kt, "", (), tuple(rules.constraints[i] for i in conflict)))
            continue
        for position, characteristic in enumerate(rules.characteristics):
            domain = selection.domains[position]
            # Left open (every value), or as many live values as selected (none removed).
            if position == rules.key_position or len(domain) in (
                len(characteristic.values),
                len(live[position]),
            ):
                continue
            dead = tuple(value for value in domain if value not in live[position])
            if not dead:
                continue
            # One minimal set for all of them: the values are shown together, and the
            # checker's finding gives each group its own set when they differ.
            conflict = analysis.minimal_conflict(
                analysis.narrowed(selection.domains, position, dead)
            )
            found.append(
                Removed(
                    kt, characteristic.name, dead, tuple(rules.constraints[i] for i in conflict)
                )
            )
    return tuple(found)


def excluded_by_rules(rules: RuleSet, *, deadline: Deadline | None = None) -> tuple[Removed, ...]:
    """Per kinematic type, each value the constraints exclude whatever a team selects, with a
    minimal set of constraints that excludes it: no valid robot of that type can have it (a
    selection tool shows it disabled, with the reason). A type with no valid robot at all is
    one entry with an empty ``characteristic``. ``deadline``: past it,
    :class:`~solver.errors.TimeLimitError` (:func:`removed_by_constraints`)."""
    if not rules.constraints:
        return ()
    from solver.core.analysis import Analysis

    analysis = Analysis(rules, deadline=deadline)
    found: list[Removed] = []
    for kinematic_type in rules.key.values:
        domains = analysis.type_domains(kinematic_type)
        live = analysis.live(domains)
        if not live[rules.key_position]:
            conflict = analysis.minimal_conflict(domains)
            found.append(
                Removed(str(kinematic_type), "", (), tuple(rules.constraints[i] for i in conflict))
            )
            continue
        for position, characteristic in enumerate(rules.characteristics):
            # Live values are the type's own: as many means none is excluded.
            if position == rules.key_position or len(live[position]) == len(domains[position]):
                continue
            # One entry per value: each shows its own reason beside its control.
            for value, conflict in _reasons(analysis, domains, position, live[position]):
                found.append(
                    Removed(
                        str(kinematic_type),
                        characteristic.name,
                        (value,),
                        tuple(rules.constraints[i] for i in conflict),
                    )
                )
    return tuple(found)


def _reasons(
    analysis: Analysis, domains: Domains, position: int, live: frozenset[Value]
) -> list[tuple[Value, tuple[int, ...]]]:
    """Each value of ``domains[position]`` not ``live``, in domain order, with a minimal set of
    constraints that excludes it. Values the constraints cannot tell apart share their reason,
    found once (a question per value of 50,000 excluded counts narrowed 100,000 each time)."""
    characteristic = analysis.rules.characteristics[position]
    dead = sorted(
        frozenset(domains[position]).difference(live), key=characteristic.positions.__getitem__
    )
    reason: dict[Value, tuple[int, ...]] = {}
    for members in analysis.classes(dead, analysis.relevant(domains), position):
        analysis.check_time()
        conflict = analysis.minimal_conflict(analysis.narrowed(domains, position, members))
        reason.update(dict.fromkeys(members, conflict))
    return [(value, reason[value]) for value in dead]
