"""What-if: the single changes to a team that save UI configurations, ranked by what they save.

The designer's question is "what is costing us UI configurations?". For the team a page
selects, every single change of one kinematic type's selection is tried:

- **drop a value** of a categorical characteristic (where more than one is selected);
- **lower a count's maximum** to just below where one of the rules' arrangements (components)
  starts, dropping that arrangement and every one above it (a maximum lowered within an
  arrangement loses robots and saves no configuration, so it is not offered).

Then the changes to the rule set (:func:`rule_changes`), each counted on the whole team under
the changed rule set (:func:`changed_rules_text`, read back as any rule file is):

- **merge two components** of one categorical characteristic into one (the configurations
  that differed only there become one): pairs within one characteristic whose components both
  serve a value the team selects, at most :data:`MAX_MERGES`;
- **remove a constraint**, at most :data:`MAX_REMOVALS` (it loses no robot: it gains some, and
  it may cost configurations; it is offered when it gains robots).

Each is counted exactly from the rules' structure (the ``structure`` engine of ``solve
--count-only``: closed form, no configuration or robot listed) on the changed type alone: a
team's counts are the sums of its types' (every configuration has its type's kinematic type as
a component), so the rest of the team is unchanged. A change the structure cannot count (it
would take listing robots) is left out, and the answer says which and why; so is a change that
leaves nothing to solve. A suggestion says how many UI configurations it saves and how many
valid robots it loses; they are ranked by configurations saved (most first), then robots lost
(fewest first), then the rules' order.

The changes are tried in the rules' order (types as the team lists them, characteristics as
the rules do, values as the selection does; then merges, characteristics and components as
the rules list them; then constraints as the file lists them), at most :data:`MAX_TRIED` of
them and within a time budget when given, looked at between changes
(:class:`~solver.deadline.Deadline`). The answer is the same on every machine up to where it
stopped: which changes were tried is a prefix of that order, and the answer says how many
of how many (``tried`` of ``total``) and why it stopped (``stopped``). One count is never cut
short; each is bounded by the structure's own limits (its block size, the ``cover-seconds``
budget of a minimum cover) and, for a changed rule set, by the rule file's own limits.

Not here: HTTP, the page (:mod:`solver.studio.pages`); the counting (:mod:`solver.engines`).
"""

from __future__ import annotations

import copy
import dataclasses
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from itertools import chain, combinations, islice

import yaml

from solver import InputError, RuleSet, Solution, SolverError, Team, solve
from solver.core.constraints import Value
from solver.core.rules import parse_rules
from solver.core.ruleset import Characteristic
from solver.core.team import TypeSelection
from solver.deadline import Deadline, seconds_text
from solver.errors import Location
from solver.files.yamlio import parse_document
from solver.studio.selection import SELECTION_FILE
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "MAX_MERGES",
    "MAX_REMOVALS",
    "MAX_TRIED",
    "LeftOut",
    "RuleChange",
    "Suggestion",
    "WhatIf",
    "changed_rules",
    "changed_rules_text",
    "rule_changes",
    "what_if",
]

# Changes tried at most for one team.
MAX_TRIED = 5000
# Changes to the rule set tried at most for one team: merges of two components (the first
# pairs in the rules' order), and removals of a constraint (the first in the file).
MAX_MERGES = 40
MAX_REMOVALS = 20


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
    # A change to the rule set: how a query names it (``RuleChange.key``) and its words.
    rules_change: str = ""
    rules_text: str = ""

    @property
    def text(self) -> str:
        if self.rules_text:
            return self.rules_text
        return _text(self.kinematic_type, self.label or self.characteristic, self.kind, self.value)


@dataclass(frozen=True)
class RuleChange:
    """One change to the rule set: two components of a characteristic merged into one
    (``merge``), or a constraint removed (``remove``). ``key`` names it in a query:
    ``merge:CHARACTERISTIC:I:J`` (the components' positions, I < J) or ``remove:I``."""

    kind: str
    key: str
    text: str
    characteristic: str = ""
    label: str = ""


@dataclass(frozen=True)
class LeftOut:
    """A change tried but not counted, and why."""

    change: str
    reason: str


@dataclass(frozen=True)
class WhatIf:
    """The suggestions for a team (those that save a configuration, and the changes to the
    rule set that gain a robot; best first); how many of the ``total`` changes were ``tried``
    (the first in the rules' order) and why the rest were not (``stopped``, empty when every
    change was tried); the changes tried but not counted."""

    suggestions: tuple[Suggestion, ...]
    tried: int
    total: int
    stopped: str = ""
    left_out: tuple[LeftOut, ...] = ()


def what_if(team: Team, *, seconds: float | None = None, base: Solution | None = None) -> WhatIf:
    """The single changes of ``team`` ranked by configurations saved, then robots lost; tried
    in the rules' order for at most ``seconds`` (``None``: no budget) and at most
    :data:`MAX_TRIED` changes."""
    deadline = None if seconds is None else Deadline.start("whatif-seconds", "what-if", seconds)
    changes = rule_changes(team)
    total = _total(team) + len(changes)
    found: list[tuple[tuple[int, int, int], Suggestion]] = []
    left_out: list[LeftOut] = []
    base = solve(team, count_only=True) if base is None else base  # the team counted
    tried = 0
    stopped = ""
    # Made one at a time as tried: a domain of 20,000 values is 20,000 changes of its own.
    trials = chain(_team_trials(team, base), (_rule_trial(team, base, c) for c in changes))
    for index, (text, count) in enumerate(trials):
        if tried >= MAX_TRIED:
            stopped = f"at most {MAX_TRIED:,} changes are tried for one team"
            break
        if deadline is not None and deadline.passed():
            stopped = f"the {seconds_text(deadline.seconds)} s what-if may take were spent"
            break
        tried += 1
        try:
            suggestion = count()
        except SolverError as error:
            left_out.append(LeftOut(text, _reason(error)))
            continue
        if suggestion is not None:
            key = (-suggestion.configurations_saved, suggestion.robots_lost, index)
            found.append((key, suggestion))
    found.sort(key=lambda pair: pair[0])
    return WhatIf(tuple(s for _, s in found), tried, total, stopped, tuple(left_out))


Trial = tuple[str, Callable[[], Suggestion | None]]


def _team_trials(team: Team, base: Solution) -> Iterator[Trial]:
    """Each change of one type's selection, and how to count it (on the changed type alone)."""
    before_of = {t.kinematic_type: t for t in base.by_type}
    for position, changed, characteristic, kind, value in _changes(team):
        selection = team.selections[position]
        text = _text(selection.kinematic_type, characteristic.label, kind, str(value))

        def count(
            position: int = position,
            changed: TypeSelection = changed,
            characteristic: Characteristic = characteristic,
            kind: str = kind,
            value: Value = value,
        ) -> Suggestion | None:
            alone = dataclasses.replace(team, selections=(changed,), published=None)
            (after,) = solve(alone, engine="structure", count_only=True).by_type
            before = before_of[changed.kinematic_type]
            saved = before.ui_configurations - after.ui_configurations
            if saved <= 0:
                return None
            whole = list(team.selections)
            whole[position] = changed
            return Suggestion(
                changed.kinematic_type,
                characteristic.name,
                kind,
                str(value),
                saved,
                before.valid_robots - after.valid_robots,
                dataclasses.replace(team, selections=tuple(whole), published=None),
                characteristic.label,
            )

        yield text, count


def _rule_trial(team: Team, base: Solution, change: RuleChange) -> Trial:
    """A change to the rule set, and how to count it: the whole team under the changed rules
    (the structure engine, counts only), offered when it saves a configuration or gains a
    robot."""

    def count() -> Suggestion | None:
        changed = dataclasses.replace(
            team, rules=changed_rules(team.rules, change.key), published=None
        )
        after = solve(changed, engine="structure", count_only=True).totals
        saved = base.totals.ui_configurations - after.ui_configurations
        lost = base.totals.valid_robots - after.valid_robots
        if saved <= 0 and lost >= 0:
            return None
        return Suggestion(
            "",
            change.characteristic,
            change.kind,
            change.key,
            saved,
            lost,
            changed,
            change.label,
            rules_change=change.key,
            rules_text=change.text,
        )

    return change.text, count


def rule_changes(team: Team) -> tuple[RuleChange, ...]:
    """The changes to ``team``'s rule set what-if tries, in its order: merges of two
    components of one categorical characteristic (both serving a value some type of the team
    selects; the first :data:`MAX_MERGES` pairs), then removals of a constraint (the first
    :data:`MAX_REMOVALS`)."""
    rules = team.rules
    merges = islice(_merges(team), MAX_MERGES)
    removals = (
        RuleChange(
            "remove",
            f"remove:{index}",
            f"remove the constraint at {_where(constraint.location)} {constraint.describe()}",
        )
        for index, constraint in enumerate(rules.constraints[:MAX_REMOVALS])
    )
    return (*merges, *removals)


def _merges(team: Team) -> Iterator[RuleChange]:
    rules = team.rules
    for place, characteristic in enumerate(rules.characteristics):
        if characteristic.name == rules.team_key or characteristic.kind != "categorical":
            continue
        selected = {v for s in team.selections for v in s.domains[place]}
        used = [
            component
            for component in characteristic.components
            if any(value in selected for value in component.values)
        ]
        for first, second in combinations(used, 2):
            yield RuleChange(
                "merge",
                f"merge:{characteristic.name}:{first.index}:{second.index}",
                f"merge {characteristic.label}: {first.name} and {second.name}",
                characteristic.name,
                characteristic.label,
            )


def _where(location: Location) -> str:
    """``rules/extended.yaml:42``: the file and line of a constraint."""
    file = shown(location.file, limit=SHOWN_FILE_NAME_CHARS)
    return f"{file}:{location.line}" if location.line is not None else file


def changed_rules(rules: RuleSet, key: str) -> RuleSet:
    """``rules`` with the change ``key`` made (:func:`changed_rules_text`, read back)."""
    text = changed_rules_text(rules, key)
    return parse_rules(parse_document(text, rules.file))


def changed_rules_text(rules: RuleSet, key: str) -> str:
    """The rule file of ``rules`` with the change ``key`` (:attr:`RuleChange.key`) made: two
    components written as one (named ``FIRST + SECOND``, the values of both, in the
    characteristic's order), or one constraint left out. Its declared ``bound`` is left out
    (it was the unchanged rules'); everything else is the file's as read (comments are not
    kept). A key that names no such change is refused (located at ``change``)."""
    data = copy.deepcopy(rules.document.data if rules.document is not None else None)
    if not isinstance(data, dict):
        raise _unknown(key)
    kind, _, rest = key.partition(":")
    if kind == "merge":
        _merge(rules, data, rest, key)
    elif kind == "remove" and rest.isdigit() and int(rest) < len(data.get("constraints") or ()):
        del data["constraints"][int(rest)]
        if not data["constraints"]:
            del data["constraints"]
    else:
        raise _unknown(key)
    data.pop("bound", None)
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True)


def _merge(rules: RuleSet, data: dict[str, object], rest: str, key: str) -> None:
    name, _, positions = rest.rpartition(":")
    name, _, first_text = name.rpartition(":")
    characteristic = next((c for c in rules.characteristics if c.name == name), None)
    if (
        characteristic is None
        or characteristic.kind != "categorical"
        or characteristic.name == rules.team_key
        or not (first_text.isdigit() and positions.isdigit())
        or not int(first_text) < int(positions) < len(characteristic.components)
    ):
        raise _unknown(key)
    first, second = int(first_text), int(positions)
    components = characteristic.components
    merged = set(components[first].values) | set(components[second].values)
    written: list[dict[str, object]] = []
    for index, component in enumerate(components):
        if index == second:
            continue
        if index == first:
            values = [v for v in characteristic.values if v in merged]
            written.append(
                {"name": f"{component.name} + {components[second].name}", "values": values}
            )
            continue
        entry: dict[str, object] = {"name": component.name, "values": list(component.values)}
        if component.description:
            entry["description"] = component.description
        written.append(entry)
    spec = data.get("characteristics")
    if not isinstance(spec, dict) or not isinstance(spec.get(name), dict):
        raise _unknown(key)
    spec[name]["components"] = written


def _unknown(key: str) -> InputError:
    return InputError.at(
        SELECTION_FILE,
        f"no change {shown(key, quoted=True)} to this rule set; what-if names the changes it "
        "offers",
        path="change",
        code="unknown-reference",
    )


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
