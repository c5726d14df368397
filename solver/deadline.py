"""How long a solver call may take: a deadline its loops look at, and the refusal past it.

Sizes bound most work before it starts (:mod:`solver.limits`), but not all of it: the questions
``check`` asks of a SAT solver, the formulas of ``count --symbolic`` and the minimum cover of
overlapping components (an integer program) can take minutes on inputs within every size
limit. Each such call has a time budget, a limit of the same table (``check-seconds``,
``symbolic-seconds``, ``cover-seconds``), and a :class:`Deadline` made when the call starts.
Its loops look at the deadline between steps (each SAT question, each kinematic type, each
formula piece), and each step is short, so a call ends soon after its budget is spent with a
located :class:`~solver.errors.TimeLimitError`::

    rules.yaml: check stopped after 30 s (limit 'check-seconds', docs/security.md;
    --time-limit sets it)

Wall-clock time, as the person waiting for the answer counts it: the studio gives a page's
check a few seconds. Whether a call finishes near its budget depends on the machine; what it
answers when it finishes does not.

Not here: the size limits (:mod:`solver.limits`), or where each call looks at its deadline
(:mod:`solver.core.oracle`, :mod:`solver.check.runner`, :mod:`solver.solving.symbolic`).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

from solver.errors import Fault, InputError, Location, TimeLimitError
from solver.limits import limit

__all__ = ["Deadline", "seconds_text"]


@dataclass(frozen=True, slots=True)
class Deadline:
    """A call's time budget: ``seconds`` from when it started, under the limit ``name``;
    ``what`` names the call in the refusal (``check``, ``count --symbolic``), ``option`` the
    command-line option that sets the budget (empty: none does)."""

    name: str
    what: str
    seconds: float
    end: float  # time.monotonic() when the budget is spent
    option: str = "--time-limit"

    @classmethod
    def start(
        cls, name: str, what: str, seconds: float | None = None, *, option: str = "--time-limit"
    ) -> Deadline:
        """A deadline from now: ``seconds``, or the limit's own value when ``None``.
        :class:`~solver.errors.InputError` for a budget that is not a positive number."""
        budget = float(limit(name).value if seconds is None else seconds)
        if not (budget > 0 and math.isfinite(budget)):
            raise InputError.at(
                "<arguments>", f"a time limit is a positive number of seconds, not {seconds!r}"
            )
        return cls(name, what, budget, time.monotonic() + budget, option)

    def remaining(self) -> float:
        """Seconds left (0 when spent)."""
        return max(0.0, self.end - time.monotonic())

    def passed(self) -> bool:
        return time.monotonic() >= self.end

    def check(self, location: Location) -> None:
        """Raise :meth:`error` at ``location`` when the budget is spent."""
        if time.monotonic() >= self.end:
            raise self.error(location)

    def error(self, location: Location) -> TimeLimitError:
        """``rules.yaml: check stopped after 30 s (limit 'check-seconds', ...)``."""
        sets = f"; {self.option} sets it" if self.option else ""
        return TimeLimitError(
            Fault(
                location,
                f"{self.what} stopped after {seconds_text(self.seconds)} s (limit "
                f"'{self.name}', docs/security.md{sets})",
                "too-slow",
            )
        )


def seconds_text(seconds: float) -> str:
    """``30``, ``0.5``, ``2.25``: a budget as a person wrote it."""
    return f"{seconds:g}"
