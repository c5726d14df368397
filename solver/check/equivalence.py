"""Equivalence predicates that are not equivalences: "can share a component" must be transitive.

Two values of a characteristic *can share a component* when some component serves both. The
article's partition into UI configurations assumes this relation is an equivalence; it is
exactly when no value is in two components that each hold a value the other lacks. When it is
not, the check gives a witness triple A ~ B (both in X), B ~ C (both in Y), but A and C share
no component, for every such pair of components X, Y. The solver then has to solve a minimum
cover, and which configuration a robot gets depends on the rest of the team.

Not here: overlaps as such (:mod:`solver.check.coverage`); nested components (X inside Y) make
no triple and are only an overlap.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Iterator
from dataclasses import dataclass

from solver.check.context import RulesContext
from solver.check.finding import Check, Finding
from solver.core.constraints import Value
from solver.core.ruleset import Characteristic, Component
from solver.untrusted import shown

__all__ = ["CHECKS", "witness_triple"]

Triple = tuple[Value, Value, Value]


def witness_triple(
    characteristic: Characteristic, first: Component, second: Component
) -> Triple | None:
    """A ~ B in ``first``, B ~ C in ``second``, A and C in no common component; or ``None``.

    A is the first value in domain order (only in ``first``) that has such a C, C the first
    such value (only in ``second``), B the first value both share.
    """
    return _overlaps(characteristic).witness(first.index, second.index)


def _overlaps(characteristic: Characteristic) -> _Intervals | _Atoms:
    if characteristic.kind == "integer":
        return _Intervals.of(characteristic)
    return _Atoms.of(characteristic)


@dataclass(frozen=True)
class _Intervals:
    """Arrangements (integer components) as runs of domain positions, answered by a sweep.

    An arrangement is a run ``[first, last]`` of positions, so a value ``a`` and a larger
    value ``c`` share a component exactly when some run starting at or before ``a`` reaches
    ``c``: ``reach[a] >= c``, where ``reach`` is the running maximum of the runs' ends. That
    makes a witness a constant-time question, and overlapping pairs come from one sweep over
    the runs sorted by start, so 1,000 arrangements over 10,000 counts cost what their
    overlaps cost, not components x components x values.
    """

    characteristic: Characteristic
    runs: dict[int, tuple[int, int]]  # component index -> (first, last) position
    reach: tuple[int, ...]  # per position: the furthest last position of a run starting by it

    @classmethod
    def of(cls, characteristic: Characteristic) -> _Intervals:
        positions = characteristic.positions
        runs = {
            c.index: (positions[c.values[0]], positions[c.values[-1]])
            for c in characteristic.components
            if c.values
        }
        ends = [-1] * len(characteristic.values)
        for first, last in runs.values():
            ends[first] = max(ends[first], last)
        return cls(characteristic, runs, tuple(itertools.accumulate(ends, max)))

    def pairs(self) -> list[tuple[int, int]]:
        """Every pair of overlapping runs ``(i, j)``, ``i < j``, in order."""
        found = []
        active: list[tuple[int, int]] = []  # (last position, index), a heap
        for index, (first, last) in sorted(self.runs.items(), key=lambda item: item[1][0]):
            while active and active[0][0] < first:
                heapq.heappop(active)
            found += [(min(index, other), max(index, other)) for _, other in active]
            heapq.heappush(active, (last, index))
        return sorted(found)

    def witness(self, i: int, j: int) -> Triple | None:
        if i not in self.runs or j not in self.runs:
            return None
        (first_x, last_x), (first_y, last_y) = self.runs[i], self.runs[j]
        if max(first_x, first_y) > min(last_x, last_y):
            return None  # no value in both
        values, reach = self.characteristic.values, self.reach
        shared = values[max(first_x, first_y)]
        if first_x < first_y and last_x < last_y:
            # X to the left: A in [first_x, first_y), C in (last_x, last_y]; the first A
            # reaches least, and C is the first value beyond its reach.
            if reach[first_x] < last_y:
                return values[first_x], shared, values[max(last_x, reach[first_x]) + 1]
        elif first_y < first_x and last_y < last_x and reach[first_y] < last_x:
            # X to the right: C in [first_y, first_x), A in (last_y, last_x]; the first C
            # reaches least, and A is the first value beyond its reach.
            return values[max(last_y, reach[first_y]) + 1], shared, values[first_y]
        return None  # one run inside the other, or every A meets every C in a third run


@dataclass(frozen=True)
class _Atoms:
    """Categorical components through their values' membership sets.

    Values with the same membership (an *atom*) behave alike in a witness, so a pair of
    components is decided on its atoms, and only pairs that some value's membership joins
    (the overlapping ones) are looked at.
    """

    characteristic: Characteristic
    first_shared: dict[tuple[int, int], int]  # overlapping pair -> first position in both
    atoms: dict[int, tuple[tuple[int, frozenset[int]], ...]]  # component -> (first position,
    # membership) of its atoms

    @classmethod
    def of(cls, characteristic: Characteristic) -> _Atoms:
        first_shared: dict[tuple[int, int], int] = {}
        first_of: dict[frozenset[int], int] = {}
        for position, holders in enumerate(characteristic.membership):
            for pair in itertools.combinations(sorted(holders), 2):
                first_shared.setdefault(pair, position)
            first_of.setdefault(frozenset(holders), position)
        atoms: dict[int, list[tuple[int, frozenset[int]]]] = {}
        for membership, position in sorted(first_of.items(), key=lambda item: item[1]):
            for index in membership:
                atoms.setdefault(index, []).append((position, membership))
        return cls(
            characteristic, first_shared, {index: tuple(found) for index, found in atoms.items()}
        )

    def pairs(self) -> list[tuple[int, int]]:
        return sorted(self.first_shared)

    def witness(self, i: int, j: int) -> Triple | None:
        shared = self.first_shared.get((min(i, j), max(i, j)))
        if shared is None:
            return None
        only_x = [atom for atom in self.atoms[i] if j not in atom[1]]
        only_y = [atom for atom in self.atoms[j] if i not in atom[1]]
        values = self.characteristic.values
        for position, membership in only_x:  # in domain order of their first values
            partners = [p for p, other in only_y if membership.isdisjoint(other)]
            if partners:
                return values[position], values[shared], values[min(partners)]
        return None


def _show(characteristic: Characteristic, value: Value) -> str:
    return str(value) if characteristic.kind == "integer" else repr(str(value))


def _non_transitive(context: RulesContext) -> Iterator[Finding]:
    for characteristic in context.rules.characteristics:
        if characteristic.is_partition:
            continue
        components = characteristic.components
        overlaps = _overlaps(characteristic)
        for i, j in overlaps.pairs():  # pairs sharing no value have no triple
            triple = overlaps.witness(i, j)
            if triple is None:
                continue
            first, second = components[i], components[j]
            a, b, c = (_show(characteristic, v) for v in triple)
            yield NON_TRANSITIVE.finding(
                context.component_location(characteristic, second),
                f"'can share a component' is not transitive for {characteristic.name}: "
                f"{a} ~ {b} (both in {shown(first.name, quoted=True)}) and {b} ~ {c} (both in "
                f"{shown(second.name, quoted=True)}), but {a} and {c} share no component",
            )


NON_TRANSITIVE = Check(
    "non-transitive",
    "warning",
    "rules",
    'The relation "two values can share a UI component" is not an equivalence: overlapping '
    "components X and Y give a witness triple A ~ B (both in X), B ~ C (both in Y) with A and "
    "C in no common component. UI configurations are then no longer equivalence classes; the "
    "solver finds a minimum cover instead and the configuration a robot gets can depend on "
    "the rest of the team.",
    _non_transitive,
)

CHECKS: tuple[Check[RulesContext], ...] = (NON_TRANSITIVE,)
