"""A check run that stopped before it finished, said as a finding for callers that asked.

``check`` bounds its work twice: the SAT search's conflicts on one rule set (the
``conflicts`` limit) and the whole run's time (``check-seconds``, :mod:`solver.deadline`).
Past either, the command line refuses the rule set (exit status 2) and prints no finding.
A caller that must answer in time whatever the rules hold (the studio checks the selection
on every page, with a budget of a few seconds) asks :func:`solver.check.check_files` for
``partial=True`` instead: the report then holds the findings found until the stop and an
``unfinished`` finding that says where and why it stopped, so findings may be missing.

Not here: where the run stops (:mod:`solver.check.runner`), the budgets themselves
(:mod:`solver.limits`).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.finding import Check, Finding
from solver.errors import TooLargeError

__all__ = ["CHECKS", "UNFINISHED", "stopped"]


def _none(_: object) -> Iterator[Finding]:
    """Nothing to look for: the runner reports the stop itself (:func:`stopped`)."""
    yield from ()


def stopped(error: TooLargeError) -> Finding:
    """The ``unfinished`` finding for a run stopped by ``error`` (its first fault's place)."""
    fault = error.faults[0]
    return UNFINISHED.finding(
        fault.location,
        f"{fault.message}: the checks did not finish, so findings may be missing",
    )


UNFINISHED = Check(
    "unfinished",
    "warning",
    "rules",
    "The checks of a rule set stopped before they finished: the run's time budget was spent "
    "(limit `check-seconds`) or the SAT search reached the `conflicts` limit. Only callers "
    "that ask for a partial report (the studio, `check_files(..., partial=True)`) see it, "
    "with the findings found until then; the command line refuses such a rule set instead "
    "(exit status 2).",
    _none,
)

CHECKS: tuple[Check[object], ...] = (UNFINISHED,)
