"""What a check reports: located findings at a level, and the checks that produce them.

A :class:`Finding` is a result, not an error: ``teleop-ui check`` collects findings from every
file it reads and prints them like a linter (``file:line:col: [level] message (check-id)``).
A :class:`Check` is one analysis with a stable id, a level, a one-paragraph description (the
README's and SARIF's text) and a generator that yields its findings from a context: the load
faults of a file, a rule set, or a team read against a rule set.

Not here: the analyses themselves (one module per family in this package), the order in which
they run (:mod:`solver.check.registry`) or how findings are printed (:mod:`solver.check.render`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Generic, Literal, TypeVar

from solver.errors import Location
from solver.untrusted import shown

__all__ = ["LEVELS", "Check", "Finding", "Level", "Related", "Scope"]

Level = Literal["error", "warning", "info"]
# Most severe first: the order of the summary line.
LEVELS: tuple[Level, ...] = ("error", "warning", "info")
# What a check reads: a file's load faults, a rule set, or a team against a rule set.
Scope = Literal["load", "rules", "team"]

Context = TypeVar("Context")


@dataclass(frozen=True, slots=True)
class Related:
    """A second place that explains a finding: a constraint of a conflict, a first occurrence."""

    location: Location
    message: str


@dataclass(frozen=True, slots=True)
class Finding:
    """One problem found by one check at one location."""

    location: Location
    level: Level
    check: str
    message: str
    related: tuple[Related, ...] = field(default=(), compare=False)

    @property
    def sort_key(self) -> tuple[str, int, int, str, str]:
        """Linter order: file, line, column, then check id and message for ties."""
        return (
            self.location.file,
            self.location.line or 0,
            self.location.column or 0,
            self.check,
            self.message,
        )

    @property
    def line(self) -> int:
        """1-based line; a finding without a position is shown at the top of its file."""
        return self.location.line or 1

    @property
    def column(self) -> int:
        return self.location.column or 1

    def __str__(self) -> str:
        """One line (``file:line:col: [level] message (check-id)``), whatever the names in the
        message and the file name hold (:func:`~solver.untrusted.shown`)."""
        return (
            f"{shown(self.location.file, limit=None)}:{self.line}:{self.column}: [{self.level}] "
            f"{shown(self.message, limit=None)} ({self.check})"
        )


@dataclass(frozen=True)
class Check(Generic[Context]):
    """One analysis: stable ``id``, fixed ``level``, what it reads and how it finds problems.

    ``description`` is one paragraph for rule authors; ``run`` yields findings whose level is
    this check's level (use :meth:`finding`).
    """

    id: str
    level: Level
    scope: Scope
    description: str
    run: Callable[[Context], Iterator[Finding]] = field(repr=False)

    def finding(
        self, location: Location, message: str, related: tuple[Related, ...] = ()
    ) -> Finding:
        """A finding of this check."""
        return Finding(location, self.level, self.id, message, related)

    @property
    def summary(self) -> str:
        """The description's first sentence (SARIF's short description)."""
        sentence, _, _ = self.description.partition(". ")
        return sentence.rstrip(".") + "."
