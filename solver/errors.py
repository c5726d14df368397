"""The project's one exception root and the located faults its errors carry.

Every error a user can cause (a malformed rule file, an unknown robot value, an unreadable URDF)
is a :class:`SolverError`. It carries one or more :class:`Fault` records, each naming the file,
line, column and the path inside the document (``team.UAV.sensor_type[1]``), so a whole file is
validated and every problem in it is reported at once. The CLI catches :class:`SolverError` at
its boundary, prints the faults and exits with status 2; nothing below the CLI prints or exits.

Not here: the findings of ``teleop-ui check`` (they are results, not errors).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Self

from solver.untrusted import shown

__all__ = [
    "Fault",
    "InputError",
    "Location",
    "MissingExtraError",
    "RulesError",
    "SolverError",
    "StructureTooComplex",
    "TeamError",
    "Terminated",
    "TimeLimitError",
    "TooLargeError",
    "did_you_mean",
]


@dataclass(frozen=True, slots=True)
class Location:
    """Where something is: a file, a 1-based line and column, and a path inside the document."""

    file: str
    line: int | None = None
    column: int | None = None
    path: str = ""

    def __str__(self) -> str:
        text = shown(self.file, limit=None)  # a file name may hold a newline
        if self.line is not None:
            text += f":{self.line}"
            if self.column is not None:
                text += f":{self.column}"
        return text


@dataclass(frozen=True, slots=True)
class Fault:
    """One problem at one location: ``rules/x.yaml:14:5: team.UAV.sensor_type[1]: message``.

    ``code`` names the kind of problem (``unknown-reference``, ``duplicate-key``, ...) so that
    tools such as ``teleop-ui check`` can report it under a stable id.
    """

    location: Location
    message: str
    code: str = "invalid"

    def __str__(self) -> str:
        """One line, whatever the names inside hold (:func:`~solver.untrusted.shown`)."""
        prefix = f"{self.location}: "
        if self.location.path:
            prefix += f"{shown(self.location.path, limit=None)}: "
        return prefix + shown(self.message, limit=None)


class SolverError(Exception):
    """Root of every error the project raises on purpose; carries the faults that caused it.

    Faults are kept sorted by file and position, so a file's problems read top to bottom.
    """

    def __init__(self, faults: Fault | Sequence[Fault]) -> None:
        found = (faults,) if isinstance(faults, Fault) else tuple(faults)
        self.faults: tuple[Fault, ...] = tuple(sorted(found, key=_position))
        if not self.faults:
            raise ValueError("a SolverError needs at least one fault")
        super().__init__("\n".join(str(fault) for fault in self.faults))

    @classmethod
    def at(
        cls,
        file: str,
        message: str,
        *,
        line: int | None = None,
        column: int | None = None,
        path: str = "",
        code: str = "invalid",
    ) -> Self:
        """An error with a single fault, built in one call."""
        return cls(Fault(Location(file, line, column, path), message, code))


class InputError(SolverError, ValueError):
    """A file or argument cannot be used at all: missing, unreadable, not the expected format."""


class RulesError(SolverError, ValueError):
    """A rule set file is malformed or inconsistent with itself."""


class TeamError(SolverError, ValueError):
    """A team selection file is malformed or does not fit its rule set."""


class TooLargeError(SolverError, ValueError):
    """Enumerating or listing would take more than the configured limit allows."""


class TimeLimitError(TooLargeError):
    """A call spent its time budget before it finished (:mod:`solver.deadline`): the input is
    within every size limit, but the work it asks for took longer than the limit allows."""


class StructureTooComplex(TooLargeError):
    """The team's constraints do not decompose into blocks small enough to count by structure.

    The ``auto`` engine catches it and enumerates instead; ``count --symbolic`` and the
    ``structure`` engine report it like any other refusal (status 2, with the reason).
    """


class Terminated(BaseException):
    """SIGTERM arrived while files were being written: like ``KeyboardInterrupt`` for SIGINT,
    it unwinds the stack so that temporaries are removed, then the command ends (status 143).
    Not a :class:`SolverError`: nothing was wrong with the input."""


class MissingExtraError(SolverError, ImportError):
    """A feature needs an optional dependency that is not installed (:mod:`solver.extras`)."""


def _position(fault: Fault) -> tuple[str, int, int]:
    location = fault.location
    return (location.file, location.line or 0, location.column or 0)


# A word longer than this is no misspelling of a name (names are at most 200 characters);
# suggestions are looked for among at most this many names.
_MAX_SUGGESTED = 200


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """`` (did you mean 'X'?)`` for the closest choice, or an empty string when none is close."""
    import difflib  # only a misspelling needs it: spare every start its import

    if len(word) > _MAX_SUGGESTED:
        return ""  # no name is that long; difflib's time grows with the product of lengths
    options = list(choices)
    if len(options) > _MAX_SUGGESTED:
        return ""  # a hint is not worth a pass over 100,000 names for each misspelling
    matches = difflib.get_close_matches(word, options, n=1, cutoff=0.6)
    if not matches:
        # Abbreviations ("Mic" for "Microphone") and case slips are too short for difflib.
        lowered = word.lower()
        matches = [o for o in options if o.lower() == lowered] or (
            [o for o in options if o.lower().startswith(lowered)] if len(word) >= 2 else []
        )
    return f" (did you mean {shown(matches[0], quoted=True)}?)" if matches else ""
