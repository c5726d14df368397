"""Solving a team: valid robots per kinematic type, their UI configurations, the totals.

:func:`solve` asks an engine (:mod:`solver.engines`) for the counts or the partition of each
kinematic type in the team into UI configurations, and numbers the configurations across the team.
The :class:`Solution` answers the article's questions (valid robots, UI configurations, reduction,
the bound T, the default configuration) and looks up the configuration of any valid robot.

The JSON contract of ``solve`` and ``count`` lives here too (:func:`solution_data`, which is
``Solution.to_dict()``; :func:`counts_data`), made of the parts in
:mod:`solver.solving.contracts`.

Not here: how robots are counted or enumerated (:mod:`solver.engines`), rendering
(:mod:`solver.reporting.render`), single-combination assignment
(:mod:`solver.solving.assignment`).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any, Literal

from solver import engines
from solver.collector import collector_paused
from solver.core.constraints import Value
from solver.core.forbidden import Removed, removed_by_constraints
from solver.core.partition import Configuration, Key, Partition
from solver.core.ruleset import RuleSet
from solver.core.team import Team
from solver.engines import MAX_CONFIGURATIONS, MAX_ROBOTS, Memo
from solver.errors import TooLargeError
from solver.solving.contracts import configuration_data, default_components

__all__ = [
    "MAX_CONFIGURATIONS",
    "MAX_ROBOTS",
    "Solution",
    "TooLargeError",
    "TypeSummary",
    "counts_data",
    "solution_data",
    "solution_warnings",
    "solve",
    "summary_data",
]


@dataclass(frozen=True, slots=True)
class TypeSummary:
    """The counts for one kinematic type of the team."""

    kinematic_type: str
    valid_robots: int
    ui_configurations: int
    unserved_robots: int = 0
    # The engine that obtained the counts (see solver.engines.NAMES); empty for totals.
    method: str = ""

    @property
    def reduction_ratio(self) -> float | None:
        """Valid robots per UI configuration (``None`` when there are no configurations)."""
        if not self.ui_configurations:
            return None
        return self.valid_robots / self.ui_configurations


@dataclass(frozen=True)
class Solution:
    """Everything a team selection produces under its rule set."""

    team: Team
    by_type: tuple[TypeSummary, ...]
    configurations: tuple[Configuration, ...]
    engine: str = "auto"
    proven_minimal: bool = True
    # False when solved with count_only: the counts are exact, the list was not built.
    listed: bool = True

    @property
    def rules(self) -> RuleSet:
        return self.team.rules

    @property
    def totals(self) -> TypeSummary:
        return TypeSummary(
            "total",
            sum(t.valid_robots for t in self.by_type),
            sum(t.ui_configurations for t in self.by_type),
            sum(t.unserved_robots for t in self.by_type),
        )

    @property
    def default_configuration(self) -> int:
        """The number of the default UI configuration: one past the last."""
        return self.totals.ui_configurations + 1

    @property
    def bound(self) -> int:
        return self.rules.bound

    def __repr__(self) -> str:
        totals = self.totals
        return (
            f"<Solution {self.team.name!r}: {totals.valid_robots} valid robots, "
            f"{totals.ui_configurations} UI configurations>"
        )

    def to_dict(self) -> dict[str, Any]:
        """The JSON contract of ``teleop-ui solve --format json --list`` (docs/formats.md)."""
        return solution_data(self, configurations=self.listed)

    def records(
        self, table: Literal["configurations", "types"] = "configurations"
    ) -> list[dict[str, Any]]:
        """One flat dict per configuration (or per kinematic type), for a table:
        ``pandas.DataFrame(solution.records())``. Keys as in :meth:`to_dict`; a configuration's
        components are one column per characteristic, named after it (``<name>_component``
        where that name is taken: the team key ``kinematic_type`` names its component so)."""
        data = self.to_dict()
        if table == "types":
            return [dict(row) for row in data["by_type"]]
        taken = {"number", "kinematic_type", "valid_robots"}
        columns = [f"{name}_component" if name in taken else name for name in self.rules.names]
        return [
            {
                "number": c["number"],
                "kinematic_type": c["kinematic_type"],
                **{
                    column: part["component"]
                    for column, part in zip(columns, c["components"], strict=True)
                },
                "valid_robots": c["valid_robots"],
            }
            for c in data.get("configurations", [])
        ]

    @cached_property
    def removed(self) -> tuple[Removed, ...]:
        """Selected values the rule set's constraints exclude (:mod:`solver.core.forbidden`)."""
        return removed_by_constraints(self.team)

    @cached_property
    def _by_key(self) -> dict[Key, Configuration]:
        return {c.key: c for c in self.configurations}

    def configuration_for(self, robot: Sequence[Value]) -> Configuration | None:
        """The configuration a valid robot is given (``None``: unserved, or not in the team).

        With overlapping components several configurations could serve the robot; it is given
        the lowest-numbered one, exactly as the partition assigned it.
        """
        options = []
        for characteristic, value in zip(self.rules.characteristics, robot, strict=True):
            position = characteristic.index(value)
            if position is None:
                return None
            options.append(characteristic.membership[position])
        if all(len(o) == 1 for o in options):
            return self._by_key.get(tuple(o[0] for o in options))
        return next(
            (
                c
                for c in self.configurations
                if all(k in o for k, o in zip(c.key, options, strict=True))
            ),
            None,
        )


@collector_paused()  # listing many configurations: see solver/collector.py
def solve(
    team: Team,
    *,
    engine: str = "auto",
    count_only: bool = False,
    max_robots: int = MAX_ROBOTS,
    max_configurations: int = MAX_CONFIGURATIONS,
) -> Solution:
    """Count, or enumerate and partition, the valid robots of ``team``.

    ``engine``: one of :data:`solver.engines.NAMES`; ``auto`` (default) uses the structure
    where it applies and fast enumeration elsewhere (:func:`solver.engines.choose`). Enumerating
    more than ``max_robots`` robots, or listing more than ``max_configurations`` configurations,
    is refused with a :class:`TooLargeError` that says how many there would be.
    ``count_only`` computes the per-type counts without the configuration list.
    """
    rules = team.rules
    summaries = []
    configurations: list[Configuration] = []
    proven = True
    memo = Memo()
    chosen = [
        engines.choose(team, selection, engine, max_robots, memo) for selection in team.selections
    ]
    if not count_only:
        engines.check_listing(team, chosen, memo, max_configurations)
    for selection, (method, free) in zip(team.selections, chosen, strict=True):
        if count_only:
            counts = free or engines.lookup(method).count(rules, selection, memo)
            summaries.append(
                TypeSummary(
                    selection.kinematic_type,
                    counts.valid_robots,
                    counts.ui_configurations,
                    counts.unserved_robots,
                    method,
                )
            )
            continue
        part = engines.lookup(method).partition(rules, selection, memo)
        proven = proven and part.proven_minimal
        summaries.append(
            TypeSummary(
                selection.kinematic_type,
                part.valid_robots,
                len(part.classes),
                part.unserved_robots,
                method,
            )
        )
        configurations.extend(
            _numbered(rules, selection.kinematic_type, part, len(configurations) + 1)
        )
    return Solution(
        team, tuple(summaries), tuple(configurations), engine, proven, listed=not count_only
    )


def _numbered(
    rules: RuleSet, kinematic_type: str, part: Partition, first: int
) -> list[Configuration]:
    """The configurations of one partition, numbered from ``first``, with their components."""
    if not part.classes:
        return []
    # The components the configurations use, looked up once each (a characteristic's
    # components may be made on demand: a range of counts without declared components),
    # then a characteristic at a time: few Python steps per configuration.
    columns = []
    for characteristic, column in zip(
        rules.characteristics, zip(*(found.key for found in part.classes), strict=True), strict=True
    ):
        used = {k: characteristic.components[k] for k in set(column)}
        columns.append(map(used.__getitem__, column))
    return [
        Configuration(number, kinematic_type, found.key, components, found.robots, found.served)
        for number, found, components in zip(
            itertools.count(first), part.classes, zip(*columns, strict=True), strict=False
        )
    ]


# -- the JSON contract of solve and count (docs/formats.md) ------------------------------


def _ratio(summary: TypeSummary) -> float | None:
    ratio = summary.reduction_ratio
    return None if ratio is None else round(ratio, 4)


def summary_data(summary: TypeSummary) -> dict[str, Any]:
    data = {
        "kinematic_type": summary.kinematic_type,
        "valid_robots": summary.valid_robots,
        "ui_configurations": summary.ui_configurations,
        "reduction_ratio": _ratio(summary),
        "unserved_robots": summary.unserved_robots,
    }
    if summary.method:
        data["method"] = summary.method
    return data


def solution_data(solution: Solution, *, configurations: bool = False) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui solve --format json``."""
    rules = solution.rules
    team = solution.team
    data: dict[str, Any] = {
        "team": team.name,
        "team_file": team.file,
        "rules": rules.name,
        "rules_file": rules.file,
        "engine": solution.engine,
        "bound": solution.bound,
        "bound_factors": dict(zip(rules.names, rules.bound_factors, strict=True)),
        "by_type": [summary_data(t) for t in solution.by_type],
        "totals": {k: v for k, v in summary_data(solution.totals).items() if k != "kinematic_type"},
        "default_configuration": solution.default_configuration,
        "default_components": default_components(rules),
        "listed": solution.listed,
        "proven_minimal": solution.proven_minimal,
        "published": None
        if team.published is None
        else {
            "valid_robots": team.published.valid_robots,
            "ui_configurations": team.published.ui_configurations,
            "source": team.published.source,
        },
        # What text output prints as "warning: ..." lines (solution_warnings), for programs.
        "warnings": [w.removeprefix("warning: ") for w in solution_warnings(solution)],
    }
    if configurations:
        data["configurations"] = [configuration_data(rules, c) for c in solution.configurations]
    return data


def counts_data(solution: Solution) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui count --format json``: per-type counts only."""
    return {
        "team": solution.team.name,
        "rules": solution.rules.name,
        "rules_file": solution.rules.file,
        "bound": solution.bound,
        "by_type": [summary_data(t) for t in solution.by_type],
        "totals": {k: v for k, v in summary_data(solution.totals).items() if k != "kinematic_type"},
        "default_configuration": solution.default_configuration,
    }


def solution_warnings(solution: Solution) -> list[str]:
    """What a reader of the counts must know: selected values the constraints exclude, robots
    left unserved, a minimum not proven. The one place for them: solve, report and batch."""
    warnings = [
        f"warning: the rules' constraints exclude what the team selects: "
        f"{removed.describe()}; such robots get the default configuration"
        for removed in solution.removed
    ]
    if solution.totals.unserved_robots:
        warnings.append(
            f"warning: {solution.totals.unserved_robots} valid robots have a value "
            "in no component and get the default configuration (run teleop-ui "
            "check)"
        )
    if not solution.proven_minimal:
        warnings.append(
            "warning: overlapping components; the configuration count is the best "
            "found, not proven minimal"
        )
    return warnings
