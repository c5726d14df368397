"""A robot's UI configuration number, without listing the configurations.

Configurations are numbered by kinematic type in rule order, then by their components in
numbering order (:func:`solver.core.partition.sort_key`). A listing of robots needs the number
of each robot it writes, and the first robot should not wait for the last configuration to be
built: so the numbers come from the structure (:func:`solver.engines.structure.product`). The
configurations of one kinematic type are a product of its blocks' partial configurations, and a
key's place among them is counted from each block's sorted list (:class:`Ranks`), with memory
for the blocks, never for the configurations. Where values overlap, the cover says which
configuration a robot is given (the lowest-numbered it can use).

Where the structure does not apply (too many linked classes, or a cover spanning blocks), the
configurations of that type are partitioned by the fast engine and looked up: as before, memory
for the configurations.

Not here: writing the robots (:mod:`solver.reporting.listing`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from solver.core.constraints import Value
from solver.core.partition import Key, sort_key, unsorted
from solver.core.ruleset import RuleSet
from solver.core.team import TypeSelection
from solver.errors import StructureTooComplex

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from solver.core.cover import Group, Pieces

    Codes = NDArray[Any]

__all__ = ["Numbers", "Ranks"]


class Ranks:
    """The place of a key among the product of parts, in lexicographic order.

    ``parts``: disjoint places (ascending) and the part's keys over them (ascending); together
    they hold every place ``0 .. width - 1``. The keys of the product below a key are, place by
    place, those equal to it before that place and lower at it: per part a range of its sorted
    keys, found by bisection, and the product of the other parts' ranges.
    """

    def __init__(self, parts: Sequence[tuple[tuple[int, ...], Codes]]) -> None:
        self.parts = parts
        width = sum(len(places) for places, _ in parts)
        self.owner = [(0, 0)] * width  # place -> (part, its coordinate in the part)
        for number, (places, _) in enumerate(parts):
            for coordinate, place in enumerate(places):
                self.owner[place] = (number, coordinate)
        self.size = math.prod(len(keys) for _, keys in parts)

    def rank(self, key: Key) -> int | None:
        """How many keys of the product are below ``key`` (``None``: it is not one of them)."""
        ranges = [(0, len(keys)) for _, keys in self.parts]
        below = 0
        for place, value in enumerate(key):
            number, coordinate = self.owner[place]
            low, high = ranges[number]
            # Within the range, the keys agree before this coordinate: sorted along it.
            column = self.parts[number][1][low:high, coordinate]
            start = low + int(column.searchsorted(value, "left"))
            stop = low + int(column.searchsorted(value, "right"))
            if start > low:
                others = math.prod(h - lo for n, (lo, h) in enumerate(ranges) if n != number)
                below += (start - low) * others
            if start == stop:
                return None
            ranges[number] = (start, stop)
        return below


class Numbers:
    """The configuration numbers of one kinematic type's robots.

    ``first`` is the number of the type's first configuration (the configurations of the types
    before it, plus one).
    """

    def __init__(self, rules: RuleSet, selection: TypeSelection, first: int) -> None:
        from solver.engines import structure

        self.rules = rules
        self.first = first
        # Bounded memories of keys given and ranked (cleared past 65,536 entries).
        self._cache: dict[tuple[tuple[int, ...], ...], Key | None] = {}
        self._ranked: dict[Key, int | None] = {}
        try:
            found = structure.product(rules, selection)
        except StructureTooComplex:
            found = None
        self.product = found
        self._listed: dict[Key, int] = {}
        self._keys: list[Key] = []
        if found is not None:
            self.ranks: Ranks | None = Ranks(found.parts)
        else:
            self.ranks = None
            from solver.engines import fast

            keys = [c.key for c in fast.partition(rules, selection).classes]
            self._keys = keys
            self._listed = {key: n for n, key in enumerate(keys)}

    @property
    def size(self) -> int:
        """How many configurations the type has."""
        return self.ranks.size if self.ranks is not None else len(self._keys)

    def number(self, robot: Sequence[Value]) -> int | None:
        """The number of the configuration ``robot`` is given (``None``: a value of it is in no
        component, or the robot is not one of this type's)."""
        options = []
        for characteristic, value in zip(self.rules.characteristics, robot, strict=True):
            position = characteristic.index(value)
            if position is None or not characteristic.membership[position]:
                return None
            options.append(characteristic.membership[position])
        key = self.key(tuple(options))
        return None if key is None else self.key_number(key)

    def key(self, options: tuple[tuple[int, ...], ...]) -> Key | None:
        """The configuration (its key, in characteristic order) that a robot whose values are
        in the components ``options`` is given: the lowest-numbered one it can use."""
        if all(len(o) == 1 for o in options) and self._listed == {}:
            return tuple([o[0] for o in options])
        if options in self._cache:
            return self._cache[options]
        found: Key | None
        if self.product is not None and self.product.cover is not None:
            try:
                chosen = self.product.cover.first(sort_key(self.rules, options))
            except ValueError:  # not a valid robot of this type: no configuration
                found = None
            else:
                found = unsorted(self.rules, chosen)
        elif self.product is not None:
            found = tuple([o[0] for o in options])
        else:
            found = next((k for k in self._keys if all(map(tuple.__contains__, options, k))), None)
        if len(self._cache) > 1 << 16:
            self._cache.clear()
        self._cache[options] = found
        return found

    def key_number(self, key: Key) -> int | None:
        """The number of the configuration ``key`` (characteristic order), if it is one."""
        if self.ranks is None:
            found = self._listed.get(key)
        elif key in self._ranked:
            found = self._ranked[key]
        else:
            found = self.ranks.rank(sort_key(self.rules, key))
            if len(self._ranked) > 1 << 16:
                self._ranked.clear()
            self._ranked[key] = found
        return None if found is None else self.first + found

    def by_codes(
        self, components: Sequence[Sequence[int]], strides: Sequence[int]
    ) -> Callable[[Codes], Codes] | None:
        """Numbers for a block of configuration codes at once, codes made as
        :func:`solver.engines.fast.robot_blocks` makes them (``code // strides[i] %
        len(components[i])`` indexes ``components[i]``; no negative codes); ``None`` where the
        blocks' parts interleave in numbering order (then :meth:`key_number`, code by code).

        With parts one after the other, a key's rank is mixed radix over the parts of its part
        keys' indices, each found by a sorted search over the part's keys encoded as codes."""
        import numpy as np

        if self.ranks is None or not all(components):
            return None
        parts = self.ranks.parts
        width = len(components)
        if [place for places, _ in parts for place in places] != list(range(width)):
            return None
        position = sort_key(self.rules, tuple(range(width)))
        sizes = [len(c) for c in components]
        steps = []
        radix = 1
        for places, keys in reversed(parts):
            where = [position[place] for place in places]
            encoded = np.zeros(len(keys), dtype=np.int64)
            for column, w in enumerate(where):
                top = max(*components[w], int(keys[:, column].max(initial=0)))
                digit = np.zeros(top + 1, dtype=np.int64)
                digit[list(components[w])] = np.arange(len(components[w]))
                encoded += digit[keys[:, column]] * strides[w]
            steps.append((where, encoded, radix))
            radix *= len(keys)
        first = self.first

        def numbers(codes: Codes) -> Codes:
            total = np.full(len(codes), first, dtype=np.int64)
            for where, encoded, step in steps:
                part = np.zeros(len(codes), dtype=np.int64)
                for w in where:
                    part += (codes // strides[w] % sizes[w]) * strides[w]
                total += np.searchsorted(encoded, part) * step
            return total

        return numbers

    def serving(self) -> list[Callable[[Value], int]] | None:
        """Per characteristic, the component (its index; -1: none) that serves each value,
        where a robot's configuration is its values' serving components one by one; ``None``
        where it depends on several values together (a cover part over linked
        characteristics)."""
        characteristics = self.rules.characteristics
        if self.size == 0:  # every robot unserved (or none valid): the default for each
            return [_none] * len(characteristics)
        if self.product is None:
            if self._keys and not all(c.is_partition for c in characteristics):
                return None
            return [_first_of(c.membership, c.index) for c in characteristics]
        cover = self.product.cover
        if cover is None:
            return [_first_of(c.membership, c.index) for c in characteristics]
        if any(len(group.positions) > 1 for group in cover.groups):
            return None
        by_place = {group.positions[0]: group for group in cover.groups}
        order = sort_key(self.rules, tuple(range(len(characteristics))))
        serving: list[Callable[[Value], int]] = [_none] * len(characteristics)
        for place, position in enumerate(order):
            group = by_place[place]
            serving[position] = _chosen_of(
                characteristics[position].membership, characteristics[position].index, group
            )
        return serving


def _none(_: Value) -> int:
    return -1


def _first_of(
    membership: Sequence[tuple[int, ...]], index: Callable[[Value], int | None]
) -> Callable[[Value], int]:
    def first(value: Value) -> int:
        position = index(value)
        if position is None or not membership[position]:
            return -1
        return membership[position][0]

    return first


def _chosen_of(
    membership: Sequence[tuple[int, ...]],
    index: Callable[[Value], int | None],
    group: Group | Pieces,
) -> Callable[[Value], int]:
    def chosen(value: Value) -> int:
        position = index(value)
        if position is None or not membership[position]:
            return -1
        # A selected value no valid robot has is in no element: no robot asks for it.
        found = group.first((membership[position],))
        return -1 if found is None else found[0]

    return chosen
