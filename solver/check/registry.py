"""Every check, in the order the documentation lists them, looked up by id.

The registry is a constant built from each check module's ``CHECKS`` tuple (no registration
side effects, no mutable state): load faults first, then coverage and equivalence of the
components, then the semantic analyses of the constraints, the bound, the checks of teams
against their rule set, and finally ``unfinished``, which the runner reports itself.

Not here: running the checks over files (:mod:`solver.check.runner`).
"""

from __future__ import annotations

from typing import Any

from solver.check import (
    bound,
    coverage,
    dead,
    equivalence,
    forced,
    load,
    redundancy,
    teams,
    unfinished,
    void,
)
from solver.check.context import RulesContext, TeamContext
from solver.check.finding import Check
from solver.check.load import LoadContext

__all__ = [
    "ALL_CHECKS",
    "LOAD_CHECKS",
    "RULE_CHECKS",
    "RUN_CHECKS",
    "TEAM_CHECKS",
    "check_ids",
    "get",
]

LOAD_CHECKS: tuple[Check[LoadContext], ...] = load.CHECKS
RULE_CHECKS: tuple[Check[RulesContext], ...] = (
    *coverage.CHECKS,
    *equivalence.CHECKS,
    *void.CHECKS,
    *dead.CHECKS,
    *forced.CHECKS,
    *redundancy.CHECKS,
    *bound.CHECKS,
)
TEAM_CHECKS: tuple[Check[TeamContext], ...] = teams.CHECKS
# Reported by the runner itself, for a run that stopped (partial reports only).
RUN_CHECKS: tuple[Check[object], ...] = unfinished.CHECKS
ALL_CHECKS: tuple[Check[Any], ...] = (*LOAD_CHECKS, *RULE_CHECKS, *TEAM_CHECKS, *RUN_CHECKS)

_BY_ID: dict[str, Check[Any]] = {check.id: check for check in ALL_CHECKS}
if len(_BY_ID) != len(ALL_CHECKS):  # a programming error, caught by the first import in tests
    raise RuntimeError("two checks share an id")


def check_ids() -> tuple[str, ...]:
    """Every check id, in documentation order."""
    return tuple(check.id for check in ALL_CHECKS)


def get(check_id: str) -> Check[Any]:
    """The check called ``check_id``; :class:`KeyError` if there is none."""
    return _BY_ID[check_id]
