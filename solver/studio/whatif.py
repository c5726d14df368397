"""What-if: the single changes to a team that save UI configurations, ranked by what they save.

The designer's question is "what is costing us UI configurations?". For the team a page
selects, every single change of one kinematic type's selection is tried:

- **drop a value** of a categorical characteristic (where more than one is selected);
- **lower a count's maximum** to just below where one of the rules' arrangements (components)
  starts, dropping that arrangement and every one above it (a maximum lowered within an
  arrangement loses robots and saves no configuration, so it is not offered).

Each is counted exactly from the rules' structure (the ``structure`` engine of ``solve
--count-only``: closed form, no configuration or robot listed) on the changed type alone: a
team's counts are the sums of its types' (every configuration has its type's kinematic type as
a component), so the rest of the team is unchanged. A change the structure cannot count (it
would take listing robots) is left out, and the answer says which and why; so is a change that
leaves nothing to solve. A suggestion says how many UI configurations it saves and how many
valid robots it loses; they are ranked by configurations saved (most first), then robots lost
(fewest first), then the rules' order.

The changes are tried in the rules' order (types as the team lists them, characteristics as
the rules do, values as the selection does), at most :data:`MAX_TRIED` of them and within a
time budget when given, looked at between changes (:class:`~solver.deadline.Deadline`). The
answer is the same on every machine up to where it stopped: which changes were tried is a
prefix of that order, and the answer says how many of how many (``tried`` of ``total``) and
why it stopped (``stopped``). One count is never cut short; each is bounded by the
structure's own limits (its block size, the ``cover-seconds`` budget of a minimum cover).

Not here: HTTP, the page (:mod:`solver.studio.pages`); the counting (:mod:`solver.engines`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass

from solver import SolverError, Team, solve
from solver.core.constraints import Value
from solver.core.ruleset import Characteristic
from solver.core.team import TypeSelection
from solver.deadline import Deadline, seconds_text

__all__ = ["MAX_TRIED", "LeftOut", "Suggestion", "WhatIf", "what_if"]

# Changes tried at most for one team.
MAX_TRIED = 5000


@dataclass(frozen=True)
class Suggestion:
    """One single change of one type's selection, and what it does to the team's counts."""

    kinematic_type: str
    characteristic: str
    kind: str  # "drop" (a value) or "lower" (a count's maximum)
    value: str  # the value dropped, or the new maximum
    configurations_saved: int
    robots_lost: int
    team: Team  # the team with this change made
    label: str = ""  # the characteristic as the rules name it to people (its label)

    @property
    def text(self) -> str:
        return _text(self.kinematic_type, self.label or self.characteristic, self.kind, self.value)


@dataclass(frozen=True)
class LeftOut:
    """A change tried but not counted, and why."""

    change: str
    reason: str


@dataclass(frozen=True)
class WhatIf:
    """The suggestions for a team (those that save a configuration, best first); how many of
    the ``total`` changes were ``tried`` (the first in the rules' order) and why the rest were
    not (``stopped``, empty when every change was tried); the changes tried but not counted."""

    suggestions: tuple[Suggestion, ...]
    tried: int
    total: int
    stopped: str = ""
    left_out: tuple[LeftOut, ...] = ()


def what_if(team: Team, *, seconds: float | None = None) -> WhatIf:
    """The single changes of ``team`` ranked by configurations saved, then robots lost; tried
    in the rules' order for at most ``seconds`` (``None``: no budget) and at most
    :data:`MAX_TRIED` changes."""
    deadline = None if seconds is None else Deadline.start("whatif-seconds", "what-if", seconds)
    total = _total(team)
    found: list[tuple[tuple[int, int, int], Suggestion]] = []
    left_out: list[LeftOut] = []
    base = {t.kinematic_type: t for t in solve(team, count_only=True).by_type}
    tried = 0
    stopped = ""
    for index, (position, changed, characteristic, kind, value) in enumerate(_changes(team)):
        if tried >= MAX_TRIED:
            stopped = f"at most {MAX_TRIED:,} changes are tried for one team"
            break
        if deadline is not None and deadline.passed():
            stopped = f"the {seconds_text(deadline.seconds)} s what-if may take were spent"
            break
        tried += 1
        selection = team.selections[position]
        text = _text(selection.kinematic_type, characteristic.label, kind, str(value))
        alone = dataclasses.replace(team, selections=(changed,), published=None)
        try:
            (after,) = solve(alone, engine="structure", count_only=True).by_type
        except SolverError as error:
            left_out.append(LeftOut(text, _reason(error)))
            continue
        before = base[selection.kinematic_type]
        saved = before.ui_configurations - after.ui_configurations
        if saved <= 0:
            continue
        whole = list(team.selections)
        whole[position] = changed
        suggestion = Suggestion(
            selection.kinematic_type,
            characteristic.name,
            kind,
            str(value),
            saved,
            before.valid_robots - after.valid_robots,
            dataclasses.replace(team, selections=tuple(whole), published=None),
            characteristic.label,
        )
        found.append(((-saved, suggestion.robots_lost, index), suggestion))
    found.sort(key=lambda pair: pair[0])
    return WhatIf(tuple(s for _, s in found), tried, total, stopped, tuple(left_out))


def _text(kinematic_type: str, label: str, kind: str, value: str) -> str:
    """The change in the words of the rules' labels: ``Mobile Manipulator: Sensor Type
    without Force Sensor``, ``Humanoid: No. of Sensors at most 15``."""
    if kind == "drop":
        return f"{kinematic_type}: {label} without {value}"
    return f"{kinematic_type}: {label} at most {value}"


def _reason(error: SolverError) -> str:
    """Why a change was not counted: the engine's refusal (its first fault), without the type
    the change already names."""
    message = error.faults[0].message if error.faults else str(error)
    _type, _, rest = message.partition(": ")
    if rest.startswith("cannot count by structure: "):
        why = rest.removeprefix("cannot count by structure: ")
        return f"the rules' structure cannot count it ({why}), and what-if lists no robots"
    return rest or message


Change = tuple[int, TypeSelection, Characteristic, str, Value]


def _changes(team: Team) -> Iterator[Change]:
    """Every single change of one type's selection, in the rules' order."""
    for position, selection, place, characteristic in _narrowable(team):
        for kind, value, kept in _narrowed(characteristic, selection.domains[place]):
            domains = list(selection.domains)
            domains[place] = kept
            changed = dataclasses.replace(selection, domains=tuple(domains))
            yield position, changed, characteristic, kind, value


def _total(team: Team) -> int:
    """How many changes :func:`_changes` gives, none made."""
    total = 0
    for _position, selection, place, characteristic in _narrowable(team):
        domain = selection.domains[place]
        total += (
            len(domain)
            if characteristic.kind != "integer"
            else len(_maxima(characteristic, domain))
        )
    return total


def _narrowable(team: Team) -> Iterator[tuple[int, TypeSelection, int, Characteristic]]:
    """``(position, selection, place, characteristic)`` for each domain of more than one value."""
    rules = team.rules
    for position, selection in enumerate(team.selections):
        for place, characteristic in enumerate(rules.characteristics):
            if characteristic.name != rules.team_key and len(selection.domains[place]) >= 2:
                yield position, selection, place, characteristic


def _narrowed(
    characteristic: Characteristic, domain: tuple[Value, ...]
) -> Iterator[tuple[str, Value, tuple[Value, ...]]]:
    """``(kind, value, the domain kept)`` for each narrowing of ``domain``."""
    if characteristic.kind != "integer":
        for value in domain:
            yield "drop", value, tuple(v for v in domain if v != value)
        return
    for most in _maxima(characteristic, domain):
        yield "lower", most, tuple(v for v in domain if int(v) <= most)


def _maxima(characteristic: Characteristic, domain: tuple[Value, ...]) -> list[int]:
    """The maxima a count may be lowered to (highest first): one below each arrangement that
    starts above the domain's least value."""
    counts = {int(v) for v in domain}
    least = min(counts)
    maxima: set[int] = set()
    for component in characteristic.components:
        inside = [int(v) for v in component.values if int(v) in counts]
        if inside and min(inside) > least:
            maxima.add(min(inside) - 1)
    return sorted(maxima, reverse=True)
