"""Solving a team: valid robots per kinematic type, their UI configurations, the totals.

:func:`solve` enumerates the valid robots of each kinematic type in the team (python-constraint
through :mod:`solver.model`), partitions them into UI configurations (:mod:`solver.partition`)
and numbers the configurations across the team. The :class:`Solution` answers the article's
questions (valid robots, UI configurations, reduction, the bound T, the default configuration)
and looks up the configuration of any valid robot.

Not here: rendering (:mod:`solver.formats`), single-combination assignment
(:mod:`solver.assign`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

from solver.constraints import Value
from solver.model import robots
from solver.partition import Configuration, Key, partition
from solver.rules import RuleSet
from solver.team import Team

__all__ = ["Solution", "TypeSummary", "solve"]


@dataclass(frozen=True, slots=True)
class TypeSummary:
    """The counts for one kinematic type of the team."""

    kinematic_type: str
    valid_robots: int
    ui_configurations: int
    unserved_robots: int = 0

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
    engine: str = "csp"
    proven_minimal: bool = True

    @property
    def rules(self) -> RuleSet:
        return self.team.rules

    @property
    def totals(self) -> TypeSummary:
        return TypeSummary("total", sum(t.valid_robots for t in self.by_type),
                           sum(t.ui_configurations for t in self.by_type),
                           sum(t.unserved_robots for t in self.by_type))

    @property
    def default_configuration(self) -> int:
        """The number of the default UI configuration: one past the last."""
        return len(self.configurations) + 1

    @property
    def bound(self) -> int:
        return self.rules.bound

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
        return next((c for c in self.configurations
                     if all(k in o for k, o in zip(c.key, options, strict=True))), None)


def solve(team: Team, *, engine: str = "csp") -> Solution:
    """Enumerate and partition the valid robots of ``team``; number its UI configurations."""
    rules = team.rules
    summaries = []
    configurations: list[Configuration] = []
    proven = True
    for selection in team.selections:
        part = partition(rules, selection.kinematic_type, robots(rules, selection.domains))
        proven = proven and part.proven_minimal
        summaries.append(TypeSummary(selection.kinematic_type, part.valid_robots,
                                     len(part.classes), part.unserved_robots))
        for key, count, served in part.classes:
            components = tuple(c.components[i] for c, i in zip(rules.characteristics, key,
                                                                 strict=True))
            configurations.append(Configuration(len(configurations) + 1,
                                                selection.kinematic_type, key, components,
                                                count, served))
    return Solution(team, tuple(summaries), tuple(configurations), engine, proven)
