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
structure, without listing the configurations (for streaming ``robots``), and
:mod:`solver.engines.shared` holds what they share (:class:`Counts`, the team's :class:`Memo`).

Not here: numbering configurations across a team (:mod:`solver.solving.solution`); the exact
minimum cover every engine uses when components overlap (:mod:`solver.core.cover`).
"""

from __future__ import annotations

import importlib
from collections.abc import Iterator
from dataclasses import replace
from functools import cached_property
from typing import TYPE_CHECKING, Protocol, cast

from solver.engines.shared import Counts, Memo
from solver.errors import Fault, InputError, Location, StructureTooComplex, TooLargeError
from solver.limits import Limit, limit, readable

if TYPE_CHECKING:
    from solver.core.constraints import Value
    from solver.core.partition import Partition
    from solver.core.ruleset import RuleSet
    from solver.core.team import Team, TypeSelection

__all__ = [
    "DESCRIPTIONS",
    "ENUMERATING",
    "MAX_CONFIGURATIONS",
    "MAX_ROBOTS",
    "NAMES",
    "Counts",
    "Engine",
    "Memo",
    "check_listing",
    "choose",
    "describe",
    "lookup",
]

# Enumerating more robots than this is refused unless the caller raises the limit.
MAX_ROBOTS = limit("robots").value
# Listing more UI configurations than this is refused; counting them is not.
MAX_CONFIGURATIONS = limit("configurations").value

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


# Engines whose module has been imported whole, by name.
_LOADED: dict[str, Engine] = {}


def lookup(name: str) -> Engine:
    """The engine called ``name``; an :class:`~solver.errors.InputError` for any other name."""
    if name not in DESCRIPTIONS:
        raise InputError.at(
            "<arguments>", f"unknown engine {name!r}; choose from {', '.join(DESCRIPTIONS)}"
        )
    # Loaded once: the import machinery costs microseconds per call even for a loaded module.
    # Kept only once its import has finished: ``sys.modules`` holds a module while it is still
    # being executed, and a second thread (the studio solves in a thread pool) would get it
    # half made; ``import_module`` waits for the thread importing it.
    engine = _LOADED.get(name)
    if engine is None:
        engine = _LOADED[name] = cast("Engine", importlib.import_module(f"solver.engines.{name}"))
    return engine


def choose(
    team: Team,
    selection: TypeSelection,
    name: str,
    max_robots: int,
    memo: Memo,
) -> tuple[str, Counts | None]:
    """Which engine solves ``selection`` when ``name`` is asked for, and its counts when they
    came for free (the structure counted them on the way).

    ``auto`` takes the structure where it applies and ``fast`` elsewhere. Before any engine
    enumerates, its limits are checked (``max_robots``; the csp engine's ``csp-robots``, the
    fast engine's ``fast-rows``): a selection whose cheap upper bounds exceed one is counted
    by structure first, so the refusal says how many there would really be.
    :class:`~solver.errors.TooLargeError` when a limit would be exceeded.
    """
    if name not in NAMES:
        raise InputError.at(
            "<arguments>", f"unknown engine {name!r}; choose from {', '.join(NAMES)}"
        )
    counts = None
    reason = ""
    bounds = _Bounds(team.rules, selection)
    # The structure counts first when asked to, or when enumerating would pass a limit (the
    # bounds are worked out only then: counting by structure needs none of them).
    if name in ("auto", "structure") or _over(selection, name, max_robots, bounds):
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
    exact = "" if counts is not None else "up to "
    if robots > max_robots:
        raise TooLargeError(
            Fault(
                selection.location or Location(team.file),
                f"{selection.kinematic_type}: enumerating {exact}"
                f"{readable(robots)} robots is refused (more than "
                f"{max_robots}, see --max-robots; limit 'robots', docs/security.md){reason}; use "
                "--count-only for exact counts without enumeration",
                "too-large",
            )
        )
    chosen = "fast" if name == "auto" else name
    if chosen == "csp":
        _refuse(team, selection, limit("csp-robots"), robots, bound=counts is None, reason=reason)
    if chosen == "fast":
        # The fast engine enumerates value classes (robots where components overlap).
        _refuse(team, selection, limit("fast-rows"), bounds.rows, bound=False, reason=reason)
    return chosen, counts


def _over(selection: TypeSelection, name: str, max_robots: int, bounds: _Bounds) -> bool:
    """Whether enumerating ``selection`` with engine ``name`` could pass one of its limits."""
    return (
        selection.size > max_robots
        or (name == "csp" and limit("csp-robots").exceeded(selection.size))
        or (name == "fast" and limit("fast-rows").exceeded(bounds.rows))
    )


def check_listing(
    team: Team, chosen: list[tuple[str, Counts | None]], memo: Memo, max_configurations: int
) -> None:
    """Refuse, before any is built, to list more than ``max_configurations`` UI configurations
    for the whole team (``chosen``: what :func:`choose` gave each of its kinematic types).

    Types without exact counts are bounded by the components their values reach; only when
    the bounds add up to too many are they counted (by structure where that applies).
    """
    found: list[tuple[int, bool]] = []  # (configurations, exact) per type
    for selection, (_, counts) in zip(team.selections, chosen, strict=True):
        if counts is not None:
            found.append((counts.ui_configurations, True))
        else:
            found.append((_Bounds(team.rules, selection).configurations, False))
    if sum(n for n, _ in found) > max_configurations:
        for index, (selection, (method, _)) in enumerate(zip(team.selections, chosen, strict=True)):
            if not found[index][1]:
                try:
                    counted = lookup("structure").count(team.rules, selection, memo)
                except StructureTooComplex:
                    # Counting by enumeration builds no configuration; its limits held.
                    counted = lookup(method).count(team.rules, selection, memo)
                found[index] = (counted.ui_configurations, True)
    total = sum(n for n, _ in found)
    which = replace(limit("configurations"), value=max_configurations)
    if which.exceeded(total):
        raise TooLargeError(
            Fault(
                team.location or Location(team.file),
                f"{team.name}: {which.message(total)}; use --count-only for exact counts "
                "without listing",
                "too-large",
            )
        )


def _refuse(
    team: Team, selection: TypeSelection, which: Limit, size: int, *, bound: bool, reason: str
) -> None:
    """A located :class:`~solver.errors.TooLargeError` when ``size`` is over ``which``."""
    if which.exceeded(size):
        location = selection.location or Location(team.file)
        message = which.message(size, bound=bound)
        raise TooLargeError(
            Fault(
                location,
                f"{selection.kinematic_type}: {message}{reason}; to count without "
                "enumerating, use --engine auto with --count-only",
                "too-large",
            )
        )


class _Bounds:
    """Upper bounds of what enumerating a selection costs, from its domains alone."""

    def __init__(self, rules: RuleSet, selection: TypeSelection) -> None:
        self.rules = rules
        self.selection = selection

    @cached_property
    def rows(self) -> int:
        """Rows the fast engine would enumerate: value classes where every value is in one
        component, else robots."""
        rules = self.rules
        if not all(c.is_partition for c in rules.characteristics):
            return self.selection.size
        total = 1
        for position, domain in enumerate(self.selection.domains):
            if len(domain) == len(rules.characteristics[position].values):
                total *= len(rules.value_classes[position])
            elif len(domain) > 1:
                index = rules.value_class_index[position]
                total *= len({index[value] for value in domain})
        return total

    @cached_property
    def configurations(self) -> int:
        """At most the product of the numbers of components the selected values reach."""
        total = 1
        for characteristic, domain in zip(
            self.rules.characteristics, self.selection.domains, strict=True
        ):
            if len(domain) == len(characteristic.values):
                total *= len(characteristic.components)
                continue
            membership, positions = characteristic.membership, characteristic.index
            reached: set[int] = set()
            for value in domain:
                position = positions(value)
                if position is not None:
                    reached.update(membership[position])
            total *= len(reached)
        return total


def _message(error: StructureTooComplex) -> str:
    return "; ".join(fault.message for fault in error.faults)
