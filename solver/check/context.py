"""What the checks read: a rule set or a team with its analysis, and how they name things.

A check receives a :class:`RulesContext` (one rule set and its shared
:class:`~solver.core.analysis.Analysis`) or a :class:`TeamContext` (a team, the YAML document
it came from, and the analysis of the rule set it is read against). The helpers here locate
things in the files (a value in a ``values`` list, a constraint, a component's bound) and
write values and constraints the way a rule author recognises them, so that every check's
messages read alike.

Not here: the analyses or the findings' levels (the check modules).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from solver.check.finding import Related
from solver.core.analysis import Analysis
from solver.core.constraints import Value
from solver.core.ruleset import Characteristic, Component, RuleSet
from solver.core.team import Team
from solver.errors import Location
from solver.files.yamlio import Document, PathPart
from solver.untrusted import shown

__all__ = [
    "ListIndex",
    "RulesContext",
    "TeamContext",
    "blame",
    "constraint_list",
    "integer_runs",
    "item_path",
    "values_text",
]

YPath = tuple[PathPart, ...]


def values_text(characteristic: Characteristic, values: Iterable[Value]) -> str:
    """Values in domain order: ``'2D Camera', 'LIDAR'`` or, for counts, ``1, 6..9``."""
    chosen = set(values)
    ordered = [v for v in characteristic.values if v in chosen]
    if characteristic.kind != "integer":
        return ", ".join(repr(str(v)) for v in ordered)
    return ", ".join(
        str(run[0]) if len(run) == 1 else f"{run[0]}..{run[-1]}" for run in integer_runs(ordered)
    )


def integer_runs(values: Iterable[Value]) -> list[tuple[int, ...]]:
    """Consecutive runs of whole numbers, in order: ``[1, 2, 5] -> [(1, 2), (5,)]``."""
    runs: list[list[int]] = []
    for value in sorted(int(v) for v in values):
        if runs and runs[-1][-1] == value - 1:
            runs[-1].append(value)
        else:
            runs.append([value])
    return [tuple(run) for run in runs]


def _raw(document: Document | None, path: YPath) -> Any:
    value: Any = None if document is None else document.data
    for part in path:
        if isinstance(part, int):
            if not isinstance(value, list) or part >= len(value):
                return None
            value = value[part]
        else:
            if not isinstance(value, dict):
                return None
            # The loader keeps one key per name (1 and "1" are duplicates), so a key that is
            # the name itself is the one; only a key of another type (1 for "1") needs the walk
            # (which, for each of 1,000 characteristics, walked them all).
            if part in value:
                value = value[part]
            else:
                value = next((v for k, v in value.items() if str(k) == part), None)
    return value


def item_path(document: Document | None, path: YPath, value: Value) -> YPath:
    """``path`` extended by the index where the list at ``path`` names ``value`` (if it does)."""
    return ListIndex(document).path(path, value)


class ListIndex:
    """Where each name stands in the lists of one document, each list indexed once: locating
    every one of 6,000 kinematic types scanned the list 6,000 times."""

    def __init__(self, document: Document | None) -> None:
        self.document = document
        self._made: dict[YPath, dict[str, int]] = {}

    def path(self, path: YPath, value: Value) -> YPath:
        """``path`` extended by the index where the list at ``path`` names ``value``."""
        found = self._made.get(path)
        if found is None:
            found = self._made[path] = {}
            raw = _raw(self.document, path)
            if isinstance(raw, list):
                for index, item in enumerate(raw):
                    if not isinstance(item, bool):
                        found.setdefault(str(item).strip(), index)
        at = found.get(str(value))
        return path if at is None else (*path, at)


def locate(document: Document | None, file: str, path: YPath, *, key: bool = False) -> Location:
    if document is None:
        return Location(file)
    return document.location(path, key=key)


@dataclass(frozen=True)
class RulesContext:
    """One loaded rule set and the answers the semantic checks share."""

    rules: RuleSet
    analysis: Analysis

    def locate(self, path: YPath, *, key: bool = False) -> Location:
        return locate(self.rules.document, self.rules.file, path, key=key)

    def raw(self, path: YPath) -> Any:
        return _raw(self.rules.document, path)

    @cached_property
    def lists(self) -> ListIndex:
        return ListIndex(self.rules.document)

    def value_location(self, characteristic: Characteristic, value: Value) -> Location:
        """Where ``value`` is declared in its characteristic's ``values`` list."""
        path: YPath = ("characteristics", characteristic.name, "values")
        return self.locate(self.lists.path(path, value))

    def component_path(self, characteristic: Characteristic, component: Component) -> YPath:
        return ("characteristics", characteristic.name, "components", component.index)

    def component_location(
        self, characteristic: Characteristic, component: Component, *fields: str
    ) -> Location:
        """A component, or the first of ``fields`` (``min``, ``above``, ...) it declares."""
        path = self.component_path(characteristic, component)
        spec = self.raw(path)
        for name in fields:
            if isinstance(spec, dict) and name in spec:
                return self.locate((*path, name))
        return component.location or self.locate(path)

    def constraint_related(self, indices: Sequence[int], message: str) -> tuple[Related, ...]:
        rules = self.rules
        return tuple(
            Related(rules.constraints[i].location, f"{message}: {rules.constraints[i].describe()}")
            for i in indices
        )

    def constraint_list(self, indices: Sequence[int]) -> str:
        return constraint_list(self.rules, indices)


def constraint_list(rules: RuleSet, indices: Sequence[int]) -> str:
    """``'A' (rules/x.yaml:30:5) and 'B' (rules/x.yaml:34:5)``."""
    names = [
        f"{shown(rules.constraints[i].name, quoted=True)} ({rules.constraints[i].location})"
        for i in indices
    ]
    if len(names) <= 1:
        return "".join(names)
    return ", ".join(names[:-1]) + " and " + names[-1]


def blame(rules: RuleSet, indices: Sequence[int]) -> str:
    """``constraint 'A' (f:l:c) alone excludes`` / ``constraints ... together exclude``."""
    listed = constraint_list(rules, indices)
    if len(indices) == 1:
        return f"constraint {listed} alone excludes"
    return f"constraints {listed} together exclude"


@dataclass(frozen=True)
class TeamContext:
    """A team selection, the document it was read from, and its rule set's analysis."""

    team: Team
    document: Document
    analysis: Analysis

    @property
    def rules(self) -> RuleSet:
        return self.team.rules

    @cached_property
    def live(self) -> dict[str, tuple[frozenset[Value], ...]]:
        """Per selected kinematic type, the values its valid robots can have (empty: void)."""
        return {s.kinematic_type: self.analysis.live(s.domains) for s in self.team.selections}

    def locate(self, path: YPath, *, key: bool = False) -> Location:
        return locate(self.document, self.team.file, path, key=key)

    def is_open(self, kinematic_type: Value, characteristic: Characteristic) -> bool:
        """Whether the team leaves ``characteristic`` unrestricted for a type (every value)."""
        return _raw(self.document, ("team", str(kinematic_type), characteristic.name)) is None

    def selection_location(
        self, kinematic_type: Value, characteristic: Characteristic, value: Value | None = None
    ) -> Location:
        """Where the team selects ``value`` (or the characteristic, or the type) for a type."""
        type_path: YPath = ("team", str(kinematic_type))
        path: YPath = (*type_path, characteristic.name)
        if _raw(self.document, path) is None:
            return self.locate(type_path, key=True)
        if value is not None:
            path = self.lists.path(path, value)
        return self.locate(path)

    @cached_property
    def lists(self) -> ListIndex:
        return ListIndex(self.document)
