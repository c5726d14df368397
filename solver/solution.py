"""Solving a team: valid robots per kinematic type, their UI configurations, the totals.

:func:`solve` enumerates the valid robots of each kinematic type in the team (python-constraint
through :mod:`solver.model`), partitions them into UI configurations (:mod:`solver.partition`)
and numbers the configurations across the team. The :class:`Solution` answers the article's
questions (valid robots, UI configurations, reduction, the bound T, the default configuration)
and looks up the configuration of any valid robot.

Not here: rendering (:mod:`solver.formats`), single-combination assignment
(:mod:`solver.assignment`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

from solver.constraints import Value
from solver.errors import InputError, SolverError
from solver.partition import Configuration, Key, Partition, partition
from solver.rules import RuleSet
from solver.structure import Counts, Memo, StructureTooComplex, count, partition_structure
from solver.team import Team, TypeSelection

__all__ = ["ENGINES", "MAX_CONFIGURATIONS", "MAX_ROBOTS", "Solution", "TooLargeError",
           "TypeSummary", "solve"]

ENGINES = ("auto", "structure", "fast", "csp")
# Enumerating more robots than this is refused unless the caller raises the limit.
MAX_ROBOTS = 10**8
# Listing more UI configurations than this is refused; counting them is not.
MAX_CONFIGURATIONS = 10**6


class TooLargeError(SolverError, ValueError):
    """Enumerating or listing would take more than the configured limit allows."""


@dataclass(frozen=True, slots=True)
class TypeSummary:
    """The counts for one kinematic type of the team."""

    kinematic_type: str
    valid_robots: int
    ui_configurations: int
    unserved_robots: int = 0
    # How the counts were obtained: "structure" (no robots enumerated), "fast" (numpy
    # enumeration) or "csp" (python-constraint enumeration); empty for totals.
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
        return TypeSummary("total", sum(t.valid_robots for t in self.by_type),
                           sum(t.ui_configurations for t in self.by_type),
                           sum(t.unserved_robots for t in self.by_type))

    @property
    def default_configuration(self) -> int:
        """The number of the default UI configuration: one past the last."""
        return self.totals.ui_configurations + 1

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


def solve(team: Team, *, engine: str = "auto", count_only: bool = False,
          max_robots: int = MAX_ROBOTS, max_configurations: int = MAX_CONFIGURATIONS
          ) -> Solution:
    """Count, or enumerate and partition, the valid robots of ``team``.

    ``engine``: ``structure`` counts from the structure without enumerating robots
    (:mod:`solver.structure`); ``fast`` enumerates with numpy (:mod:`solver.stream`); ``csp``
    enumerates with python-constraint, the reference (:mod:`solver.model`); ``auto`` (default)
    uses the structure where it applies and fast enumeration elsewhere. Enumerating more than
    ``max_robots`` robots, or listing more than ``max_configurations`` configurations, is
    refused with a :class:`TooLargeError` that says how many there would be.
    ``count_only`` computes the per-type counts without the configuration list.
    """
    if engine not in ENGINES:
        raise InputError.at("<arguments>", f"unknown engine {engine!r}; choose from "
                                           f"{', '.join(ENGINES)}")
    rules = team.rules
    summaries = []
    configurations: list[Configuration] = []
    proven = True
    memo = Memo()
    for selection in team.selections:
        method, counts = _plan(team, selection, engine, max_robots, memo)
        if count_only and counts is not None:
            summaries.append(TypeSummary(selection.kinematic_type, counts.valid_robots,
                                         counts.ui_configurations, counts.unserved_robots,
                                         method))
            continue
        if counts is not None and counts.ui_configurations > max_configurations:
            raise TooLargeError.at(team.file, f"{selection.kinematic_type}: listing "
                                              f"{counts.ui_configurations} UI configurations "
                                              f"is refused (more than {max_configurations}); "
                                              "use --count-only for the counts")
        part = _partition(rules, selection, method, memo)
        proven = proven and part.proven_minimal
        summaries.append(TypeSummary(selection.kinematic_type, part.valid_robots,
                                     len(part.classes), part.unserved_robots, method))
        if count_only:
            continue
        every = [c.components for c in rules.characteristics]
        for key, robots_served, served in part.classes:
            components = tuple([every[i][k] for i, k in enumerate(key)])
            configurations.append(Configuration(len(configurations) + 1,
                                                selection.kinematic_type, key, components,
                                                robots_served, served))
    return Solution(team, tuple(summaries), tuple(configurations), engine, proven,
                    listed=not count_only)


def _plan(team: Team, selection: TypeSelection, engine: str, max_robots: int, memo: Memo
          ) -> tuple[str, Counts | None]:
    """Which method solves this kinematic type, and its counts when they come for free."""
    counts = None
    reason = ""
    if engine in ("auto", "structure") or selection.size > max_robots:
        try:
            counts = count(team.rules, selection, memo)
        except StructureTooComplex as error:
            if engine == "structure":
                raise TooLargeError.at(team.file, f"{selection.kinematic_type}: cannot count "
                                                  f"by structure: {error}") from None
            reason = f" ({error})"
        else:
            if engine in ("auto", "structure"):
                return "structure", counts
    robots = selection.size if counts is None else counts.valid_robots
    if robots > max_robots:
        exact = "" if counts is not None else "up to "
        raise TooLargeError.at(team.file, f"{selection.kinematic_type}: enumerating {exact}"
                                          f"{robots} robots is refused (more than "
                                          f"{max_robots}, see --max-robots){reason}; use "
                                          "--count-only for exact counts without enumeration")
    return ("csp" if engine == "csp" else "fast"), counts


def _partition(rules: RuleSet, selection: TypeSelection, method: str, memo: Memo
               ) -> Partition:
    if method == "structure":
        return partition_structure(rules, selection, memo)
    if method == "fast":
        from solver.stream import partition_stream

        return partition_stream(rules, selection)
    from solver.model import robots

    return partition(rules, selection.kinematic_type, robots(rules, selection.domains))
