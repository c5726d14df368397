"""The ways of solving a kinematic type, behind one interface, looked up by name.

Every engine answers the same three questions for one kinematic type of a team (see
:class:`Engine`): how many valid robots and UI configurations (:func:`Engine.count`), which
configurations with which robots (:func:`Engine.partition`), and every valid robot in order
(:func:`Engine.robots`).

=============  ==============================================================================
``structure``  counts from the rules' structure without enumerating robots
               (:mod:`solver.engines.structure`)
``fast``       enumerates with numpy, a block of robots per vector step
               (:mod:`solver.engines.fast`)
``csp``        enumerates with python-constraint, the reference (:mod:`solver.engines.csp`)
=============  ==============================================================================

``auto`` is not an engine but a policy (:func:`choose`): the structure where it applies, fast
enumeration elsewhere. The limits every engine obeys live here too (:data:`MAX_ROBOTS`,
:data:`MAX_CONFIGURATIONS`). Adding an engine is one module with ``count``, ``partition`` and
``robots`` and one line in :data:`DESCRIPTIONS`.

Engine modules are imported on first use only: numpy and python-constraint stay out of
``import solver`` and of commands that never enumerate.

>>> NAMES
('auto', 'structure', 'fast', 'csp')
>>> lookup("fast").__name__
'solver.engines.fast'

Beside them, :mod:`solver.engines.numbering` gives a robot its configuration number from the
structure, without listing the configurations (for streaming ``robots``).

Not here: numbering configurations across a team (:mod:`solver.core.solution`); the exact
minimum cover every engine uses when components overlap (:mod:`solver.core.cover`).
"""

from __future__ import annotations

import importlib
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, cast

from solver.errors import InputError, StructureTooComplex, TooLargeError

if TYPE_CHECKING:
    from solver.core.constraints import Value
    from solver.core.partition import Partition
    from solver.core.rules import RuleSet
    from solver.core.team import Team, TypeSelection
    from solver.engines.structure import Memo

__all__ = [
    "DESCRIPTIONS",
    "ENUMERATING",
    "MAX_CONFIGURATIONS",
    "MAX_ROBOTS",
    "NAMES",
    "Counts",
    "Engine",
    "choose",
    "describe",
    "lookup",
]

# Enumerating more robots than this is refused unless the caller raises the limit.
MAX_ROBOTS = 10**8
# Listing more UI configurations than this is refused; counting them is not.
MAX_CONFIGURATIONS = 10**6

# What each engine does, in the words reports and `solve` print beside the counts.
DESCRIPTIONS = {
    "structure": "counted from the rules' structure, no robots enumerated",
    "fast": "robots enumerated with numpy (fast engine)",
    "csp": "robots enumerated with python-constraint (csp engine)",
}
# The names a caller may ask for: the policy first, then the engines.
NAMES: tuple[str, ...] = ("auto", *DESCRIPTIONS)
# The engines that produce robots one by one (`teleop-ui robots`).
ENUMERATING: tuple[str, ...] = ("fast", "csp")


@dataclass(frozen=True, slots=True)
class Counts:
    """Exact counts for one kinematic type."""

    kinematic_type: str
    valid_robots: int
    ui_configurations: int
    unserved_robots: int


class Engine(Protocol):
    """What every engine module provides (the module itself is the engine)."""

    def count(self, rules: RuleSet, selection: TypeSelection, memo: Memo, /) -> Counts:
        """Valid robots and UI configurations of one kinematic type.

        ``memo`` is shared across the kinematic types of one team; engines that cannot use it
        ignore it. :class:`~solver.errors.StructureTooComplex` when this engine cannot count
        this selection.
        """
        ...

    def partition(self, rules: RuleSet, selection: TypeSelection, memo: Memo, /) -> Partition:
        """The fewest UI configurations of one kinematic type, with the robots each serves."""
        ...

    def robots(self, rules: RuleSet, selection: TypeSelection, /) -> Iterator[tuple[Value, ...]]:
        """Every valid robot of one kinematic type, one at a time."""
        ...


def describe(name: str) -> str:
    """The words for how an engine obtained its counts (the name itself when unknown)."""
    return DESCRIPTIONS.get(name, name)


def lookup(name: str) -> Engine:
    """The engine called ``name``; an :class:`~solver.errors.InputError` for any other name."""
    if name not in DESCRIPTIONS:
        raise InputError.at(
            "<arguments>", f"unknown engine {name!r}; choose from {', '.join(DESCRIPTIONS)}"
        )
    return cast("Engine", importlib.import_module(f"solver.engines.{name}"))


def choose(
    team: Team, selection: TypeSelection, name: str, max_robots: int, memo: Memo
) -> tuple[str, Counts | None]:
    """Which engine solves ``selection`` when ``name`` is asked for, and its counts when they
    came for free (the structure counted them on the way).

    ``auto`` takes the structure where it applies and ``fast`` elsewhere. A selection larger
    than ``max_robots`` is counted by structure whatever the engine, so the refusal says how
    many robots there would really be. :class:`~solver.errors.TooLargeError` when enumerating
    would exceed ``max_robots``.
    """
    if name not in NAMES:
        raise InputError.at(
            "<arguments>", f"unknown engine {name!r}; choose from {', '.join(NAMES)}"
        )
    counts = None
    reason = ""
    if name in ("auto", "structure") or selection.size > max_robots:
        try:
            counts = lookup("structure").count(team.rules, selection, memo)
        except StructureTooComplex as error:
            if name == "structure":
                raise TooLargeError.at(
                    team.file,
                    f"{selection.kinematic_type}: cannot count by structure: {_message(error)}",
                ) from None
            reason = f" ({_message(error)})"
        else:
            if name in ("auto", "structure"):
                return "structure", counts
    robots = selection.size if counts is None else counts.valid_robots
    if robots > max_robots:
        exact = "" if counts is not None else "up to "
        raise TooLargeError.at(
            team.file,
            f"{selection.kinematic_type}: enumerating {exact}"
            f"{robots} robots is refused (more than "
            f"{max_robots}, see --max-robots){reason}; use "
            "--count-only for exact counts without enumeration",
        )
    return ("fast" if name == "auto" else name), counts


def _message(error: StructureTooComplex) -> str:
    return "; ".join(fault.message for fault in error.faults)
