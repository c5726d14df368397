"""Faults found while loading a file, reported as findings under stable check ids.

The rule and team loaders already validate a whole file and give every fault a ``code``
(:class:`solver.errors.Fault`). A linter must not stop at them: references to things that do not
exist and duplicates are what a rule author most needs to hear about. So each fault becomes a
finding: ``unknown-reference``, ``duplicate-value`` and ``duplicate-key`` under their own ids,
every other structural fault (wrong type, missing or unknown field, value out of range, empty
selection) under ``schema``. A file with such faults cannot be analysed further; the semantic
checks need a rule set that loads. ``not-checked`` says so for a team whose rule set has errors.

Not here: files that cannot be read or are not YAML at all; those are unusable input and stop
the run with exit status 2 (:mod:`solver.check.runner`).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from solver.check.finding import Check, Finding
from solver.errors import Fault, Location

__all__ = ["CHECKS", "LoadContext", "check_id"]


@dataclass(frozen=True)
class LoadContext:
    """The faults found while loading one file, and (for ``not-checked``) why it was skipped."""

    faults: tuple[Fault, ...] = ()
    skipped: tuple[tuple[Location, str], ...] = ()


_OWN_IDS = {"unknown-reference", "duplicate-value", "duplicate-key"}


def check_id(fault: Fault) -> str:
    """The check id a load fault is reported under."""
    return fault.code if fault.code in _OWN_IDS else "schema"


def _unknown_reference(context: LoadContext) -> Iterator[Finding]:
    yield from _load(UNKNOWN_REFERENCE, context)


def _duplicate_value(context: LoadContext) -> Iterator[Finding]:
    yield from _load(DUPLICATE_VALUE, context)


def _duplicate_key(context: LoadContext) -> Iterator[Finding]:
    yield from _load(DUPLICATE_KEY, context)


def _schema(context: LoadContext) -> Iterator[Finding]:
    yield from _load(SCHEMA, context)


def _not_checked(context: LoadContext) -> Iterator[Finding]:
    for location, reason in context.skipped:
        yield NOT_CHECKED.finding(location, reason)


def _load(check: Check[LoadContext], context: LoadContext) -> Iterator[Finding]:
    for fault in context.faults:
        if check_id(fault) == check.id:
            text = (
                f"{fault.location.path}: {fault.message}" if fault.location.path else fault.message
            )
            yield check.finding(fault.location, text)


UNKNOWN_REFERENCE = Check(
    "unknown-reference",
    "error",
    "load",
    "A name that refers to nothing: a value, component or characteristic that the rule set "
    "does not declare (in a component's values, a constraint, a selection or the team_key), a "
    "kinematic type a team selects that its rules do not have, or a `rules:` file that does "
    "not exist. The message suggests the closest existing name. Fix the spelling or declare "
    "the missing thing.",
    _unknown_reference,
)
DUPLICATE_VALUE = Check(
    "duplicate-value",
    "error",
    "load",
    "A value listed twice: twice in a characteristic's values, twice in one component, two "
    "components with the same name, or one motion control declared twice in a teleoperation "
    "description. Duplicates usually hide a copy-paste slip; the message names the first "
    "occurrence.",
    _duplicate_value,
)
DUPLICATE_KEY = Check(
    "duplicate-key",
    "error",
    "load",
    "A YAML mapping key written twice (two characteristics, two kinematic types in a team, two "
    "`min:` in one component). Plain YAML loaders silently keep the last one; this project "
    "keeps the first and reports the second, naming the line of the first.",
    _duplicate_key,
)
SCHEMA = Check(
    "schema",
    "error",
    "load",
    "The file does not follow the rule-set, team or teleoperation-description format: a field "
    "of the wrong type, a missing or unknown field, a number out of range (such as an "
    "inverted characteristic range or a team maximum beyond the rules' range), a selection "
    "that leaves no value, or a topic that is no full ROS name. "
    "The semantic checks need a file that loads, so they do not run on a file with load "
    "errors.",
    _schema,
)
NOT_CHECKED = Check(
    "not-checked",
    "info",
    "load",
    "A team file that could not be checked because the rule set it is read against has load "
    "errors (reported at the rule set's own lines). Fix the rule set and check again.",
    _not_checked,
)

CHECKS: tuple[Check[LoadContext], ...] = (
    UNKNOWN_REFERENCE,
    DUPLICATE_VALUE,
    DUPLICATE_KEY,
    SCHEMA,
    NOT_CHECKED,
)
