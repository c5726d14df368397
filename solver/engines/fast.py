"""Fast enumeration of valid robots: streaming, vectorised with numpy, constant memory.

The robots of one kinematic type are the product of the selected domains. The trailing
characteristics whose product fits :data:`BLOCK` form a *block*: their value positions are laid
out once as numpy arrays. Every assignment of the leading characteristics (the *prefix*) then
examines one block of robots with a handful of vector operations: the constraint mask (each rule
pre-evaluated on the block, combined with the prefix values as scalars), the configuration code
of every robot, a ``bincount``. Only the current block is in memory: memory grows with the block
size and the number of UI configurations, never with the number of robots.

The python-constraint engine (:mod:`solver.engines.csp`) stays the reference; the property
tests check that both give identical robots and partitions.

Not here: counting without enumeration (:mod:`solver.engines.structure`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeAlias

import numpy as np

from solver.core import partition as partitioning
from solver.core.constraints import Value
from solver.core.partition import Partition, PartitionClass
from solver.core.ruleset import Characteristic, RuleSet
from solver.core.team import TypeSelection
from solver.engines.shared import Counts

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from solver.core.constraints import Condition, RuleConstraint

# Over the block: True where a robot passes (a mask), and whole-number codes or positions.
Mask: TypeAlias = "NDArray[np.bool_]"
Codes: TypeAlias = "NDArray[np.int64]"
Scalars = tuple[tuple[int, frozenset[int]], ...]  # (prefix position, allowed digits)
# Per characteristic, per selected value: how many values it stands for (a class, _classes).
_Weights = tuple[tuple[int, ...], ...]

__all__ = ["BLOCK", "BlockLayout", "RobotBlock", "count", "partition", "robot_blocks", "robots"]

# Robots examined per vector step. Big enough to amortise numpy's per-call cost, small enough to
# stay in cache-friendly memory (a few MB per block).
BLOCK = 1 << 18


@dataclass(frozen=True)
class _Rule:
    """A rule split into the part decided by the prefix (scalars) and by the block (vectors)."""

    kind: str
    when_prefix: Scalars
    then_prefix: Scalars
    when_block: Mask | None  # None: no block conditions (true)
    then_block: Mask | None


class _TypeTables:
    """Everything about one kinematic type that does not change from block to block."""

    def __init__(
        self,
        rules: RuleSet,
        selection: TypeSelection,
        weights: _Weights | None = None,
        serving: Sequence[Callable[[Value], int]] | None = None,
    ) -> None:
        self.rules = rules
        self.domains = selection.domains
        # Robots each selected value stands for (a class of values, :func:`_classes`); None: 1.
        self.weights = weights
        sizes = [len(d) for d in self.domains]
        width = len(sizes)
        start = width
        product = 1
        while start > 0 and (product * sizes[start - 1] <= BLOCK or start == width):
            start -= 1
            product *= sizes[start]
        self.start = start
        self.block_size = product
        # Block layout: the last characteristic varies fastest.
        self.digits: dict[int, NDArray[np.int64]] = {}
        repeat = 1
        for position in range(width - 1, start - 1, -1):
            size = sizes[position]
            pattern = np.repeat(np.arange(size, dtype=np.int64), repeat)
            self.digits[position] = np.tile(pattern, product // (size * repeat))
            repeat *= size
        # Compact configuration codes: only the components this selection reaches.
        self.components: list[list[int]] = []
        codes = []
        if serving is None:
            serving = [_first_component(c) for c in rules.characteristics]
        for characteristic, which, domain in zip(
            rules.characteristics, serving, self.domains, strict=True
        ):
            # The component of each selected value (-1: none), then renumbered compactly.
            component = np.fromiter(map(which, domain), dtype=np.int64, count=len(domain))
            reached = np.unique(component[component >= 0])
            self.components.append(reached.tolist())
            compact = np.full(len(characteristic.components) + 1, -1, dtype=np.int64)
            compact[reached] = np.arange(len(reached))
            codes.append(compact[component])  # component -1 reads the last cell: -1
        self.codes = codes
        self.strides = [math.prod(len(c) for c in self.components[i + 1 :]) for i in range(width)]
        self.key_space = math.prod(len(c) for c in self.components)
        block_key = np.zeros(product, dtype=np.int64)
        block_gap = np.zeros(product, dtype=bool)
        for position in range(start, width):
            code = codes[position][self.digits[position]]
            block_gap |= code < 0
            block_key += code * self.strides[position]
        self.block_key = block_key
        self.block_gap = block_gap
        # The robots each block row stands for (None: one each).
        self.block_weight: Codes | None = None
        if weights is not None and any(max(w) > 1 for w in weights[start:]):
            block_weight = np.ones(product, dtype=np.int64)
            for position in range(start, width):
                block_weight *= np.array(weights[position], dtype=np.int64)[self.digits[position]]
            self.block_weight = block_weight
        self.rules_split = [self._split(rule) for rule in rules.constraints]

    def _split(self, rule: RuleConstraint) -> _Rule:
        index = {name: i for i, name in enumerate(self.rules.names)}

        def part(conditions: Sequence[Condition]) -> tuple[Scalars, Mask | None]:
            scalars = []
            vector: Mask | None = None
            for condition in conditions:
                position = index[condition.characteristic]
                allowed = frozenset(
                    i for i, v in enumerate(self.domains[position]) if v in condition.allowed
                )
                if position < self.start:
                    scalars.append((position, allowed))
                else:
                    table = np.zeros(len(self.domains[position]), dtype=bool)
                    table[list(allowed)] = True
                    hits = table[self.digits[position]]
                    vector = hits if vector is None else vector & hits
            return tuple(scalars), vector

        if rule.kind == "forbid":
            when_prefix, when_block = part(rule.conditions)
            return _Rule("forbid", when_prefix, (), when_block, None)
        when_prefix, when_block = part(rule.when)
        then_prefix, then_block = part(rule.conditions)
        return _Rule("require", when_prefix, then_prefix, when_block, then_block)

    def head(self, prefix: tuple[int, ...]) -> tuple[int, bool, int]:
        """What ``prefix`` adds to every robot of the block: its part of the configuration
        code, whether one of its values is in no component (a gap), and the robots it stands
        for (value classes weigh more than one)."""
        offset, gap, weight = 0, False, 1
        for position, digit in enumerate(prefix):
            code = int(self.codes[position][digit])
            gap |= code < 0
            offset += code * self.strides[position]
            if self.weights is not None:
                weight *= self.weights[position][digit]
        return offset, gap, weight

    def prefixes(self) -> Iterator[tuple[int, ...]]:
        return itertools.product(*(range(len(d)) for d in self.domains[: self.start]))

    def mask(
        self, prefix: tuple[int, ...], cache: dict[tuple[int, ...], Mask | None]
    ) -> Mask | None:
        """Valid robots of the block under ``prefix`` (``True`` where valid), or None: none."""
        pattern = []
        for rule in self.rules_split:
            when = all(prefix[p] in allowed for p, allowed in rule.when_prefix)
            then = all(prefix[p] in allowed for p, allowed in rule.then_prefix)
            pattern.append(2 * when + then)
        key = tuple(pattern)
        if key not in cache:
            cache[key] = self._mask(key)
        return cache[key]

    def _mask(self, pattern: tuple[int, ...]) -> Mask | None:
        mask = np.ones(self.block_size, dtype=bool)
        for rule, state in zip(self.rules_split, pattern, strict=True):
            when, then = state >> 1, state & 1
            if not when:
                continue  # the prefix already fails the rule's condition: it holds everywhere
            if rule.kind == "forbid":
                if rule.when_block is None:
                    return None
                mask &= ~rule.when_block
                continue
            fails_when = None if rule.when_block is None else ~rule.when_block
            if not then:
                if fails_when is None:
                    return None
                mask &= fails_when
            elif rule.then_block is not None:
                mask &= rule.then_block if fails_when is None else (fails_when | rule.then_block)
        return mask


def _values(domain: tuple[Value, ...], positions: Sequence[int]) -> tuple[Value, ...]:
    """The values at ``positions`` (ascending) of ``domain``; a slice when they are a run."""
    if isinstance(positions, range):
        return domain[positions.start : positions.stop]
    if positions and positions[-1] - positions[0] + 1 == len(positions):
        return domain[positions[0] : positions[-1] + 1]
    return tuple([domain[j] for j in positions])


def _first(members: tuple[int, ...]) -> int:
    return members[0] if members else -1


def _first_component(characteristic: Characteristic) -> Callable[[Value], int]:
    """Value -> the index of its first component (-1: none, or not a value of this)."""
    membership, index = characteristic.membership, characteristic.index

    def first(value: Value) -> int:
        position = index(value)
        return -1 if position is None else _first(membership[position])

    return first


def robots(rules: RuleSet, selection: TypeSelection) -> Iterator[tuple[Value, ...]]:
    """Every valid robot of one kinematic type, block by block, in product order."""
    tables = _TypeTables(rules, selection)
    cache: dict[tuple[int, ...], Mask | None] = {}
    domains = tables.domains
    width = len(domains)
    for prefix in tables.prefixes():
        mask = tables.mask(prefix, cache)
        if mask is None:
            continue
        head = tuple(domains[i][d] for i, d in enumerate(prefix))
        columns = [
            np.asarray(domains[i], dtype=object)[tables.digits[i][mask]]
            for i in range(tables.start, width)
        ]
        for tail in zip(*columns, strict=True):
            yield head + tuple(tail)


@dataclass(frozen=True)
class RobotBlock:
    """The valid robots of one block under one prefix, as value positions and codes.

    ``head`` holds the value positions of the leading characteristics (the same for every robot
    of the block); ``rows`` indexes the block layout of :class:`BlockLayout` (which robots of
    the block are valid); valid robot ``k`` has configuration code ``codes[which[k]]``
    (components numbered as :attr:`BlockLayout.components` says; -1 where a value is in no
    component). ``codes`` are distinct and few: writers turn each into text once per block.
    """

    head: tuple[int, ...]
    rows: Codes
    codes: Codes
    which: Codes


@dataclass(frozen=True)
class BlockLayout:
    """How :func:`robot_blocks` lays out one kinematic type: the selected domains, where the
    block starts, each block characteristic's value position per block row, and how a code
    reads as components (``code // strides[i] % len(components[i])`` indexes
    ``components[i]``)."""

    domains: tuple[tuple[Value, ...], ...]
    start: int
    digits: tuple[Codes, ...]
    components: tuple[tuple[int, ...], ...]
    strides: tuple[int, ...]


def robot_blocks(
    rules: RuleSet,
    selection: TypeSelection,
    serving: Sequence[Callable[[Value], int]] | None = None,
) -> tuple[BlockLayout, Iterator[RobotBlock]]:
    """Every valid robot of one kinematic type as blocks of positions and configuration codes,
    in the order of :func:`robots`: for writers that turn millions of robots into rows with
    vector operations rather than one Python tuple per robot.

    The codes are made of the component that serves each value: ``serving[i]`` maps a value
    of characteristic ``i`` to its component's index (-1: none); by default its first
    component, the configuration of a robot when every value is in at most one component.
    """
    tables = _TypeTables(rules, selection, serving=serving)
    layout = BlockLayout(
        tuple(tables.domains),
        tables.start,
        tuple(tables.digits[i] for i in range(tables.start, len(tables.domains))),
        tuple(tuple(c) for c in tables.components),
        tuple(tables.strides),
    )
    return layout, _robot_blocks(tables)


def _robot_blocks(tables: _TypeTables) -> Iterator[RobotBlock]:
    masks: dict[tuple[int, ...], Mask | None] = {}
    # Per distinct mask, once: its valid rows and their distinct codes within the block.
    blocks: dict[int, tuple[Codes, Codes, Codes]] = {}
    for prefix in tables.prefixes():
        mask = tables.mask(prefix, masks)
        if mask is None:
            continue
        found = blocks.get(id(mask))
        if found is None:
            rows = np.flatnonzero(mask)
            keys, which = np.unique(
                np.where(tables.block_gap, -1, tables.block_key)[rows], return_inverse=True
            )
            found = blocks[id(mask)] = (rows, keys, which.reshape(-1))
        rows, keys, which = found
        offset, gap, _ = tables.head(prefix)
        if gap:
            codes = np.full(len(keys), -1, dtype=np.int64)
        elif offset:
            codes = np.where(keys < 0, -1, keys + offset)
        else:
            codes = keys
        yield RobotBlock(prefix, rows, codes, which)


def count(rules: RuleSet, selection: TypeSelection, _memo: object = None) -> Counts:
    """Valid robots and UI configurations of one kinematic type, by enumerating them.

    Only the configuration codes are counted: which values each configuration serves, and the
    configurations as values, are never built (they cost more than the enumeration itself when
    there are millions of configurations).
    """
    if not all(c.is_partition for c in rules.characteristics):
        part = partition(rules, selection)
        return Counts(
            selection.kinematic_type, part.valid_robots, len(part.classes), part.unserved_robots
        )
    scanned = _scan(rules, _classes(rules, selection), served_too=False)
    return Counts(selection.kinematic_type, scanned.total, scanned.counts.size(), scanned.unserved)


def partition(rules: RuleSet, selection: TypeSelection, _memo: object = None) -> Partition:
    """The configurations of one kinematic type, by vectorised enumeration of its robots.

    The memo is unused: enumeration shares nothing between kinematic types.
    """
    if not all(c.is_partition for c in rules.characteristics):
        return partitioning.partition(rules, selection.kinematic_type, robots(rules, selection))
    classes = _classes(rules, selection)
    return _partition_from_counts(_scan(rules, classes, served_too=True), classes)


@dataclass(frozen=True)
class _Classes:
    """A selection whose values are grouped into classes the rules cannot tell apart (the same
    components, the same answer to every condition: :attr:`RuleSet.value_classes`), each class
    standing in the enumeration as its first value. Counting and partitioning enumerate these
    representatives, each weighing as many robots as its class has values: 1,000 counts in
    five arrangements and one constraint are six representatives, not 1,000 values."""

    original: TypeSelection
    selection: TypeSelection  # the representatives, in domain order of their first value
    # members[i][k]: positions in the original domain i of the values representative k stands for
    members: tuple[tuple[tuple[int, ...], ...], ...]

    @property
    def weights(self) -> _Weights | None:
        """Values per representative; None where every class is one value (nothing grouped)."""
        if all(len(m) == len(d) for m, d in zip(self.members, self.original.domains, strict=True)):
            return None
        return tuple(tuple(len(group) for group in groups) for groups in self.members)


# Weighted sums stay exact in the float64 that numpy's weighted bincount adds in.
_EXACT = 1 << 53


def _classes(rules: RuleSet, selection: TypeSelection) -> _Classes:
    """``selection`` grouped into value classes; ungrouped when its robots could exceed what
    weighted counting adds exactly (enumerating that many robots would not end anyway)."""
    if selection.size >= _EXACT:
        single = tuple(tuple((j,) for j in range(len(d))) for d in selection.domains)
        return _Classes(selection, selection, single)
    domains: list[tuple[Value, ...]] = []
    members: list[tuple[tuple[int, ...], ...]] = []
    for index, domain in zip(rules.value_class_index, selection.domains, strict=True):
        if len(domain) == 1:
            domains.append(domain)
            members.append(((0,),))
            continue
        ids = np.fromiter(map(index.__getitem__, domain), dtype=np.int64, count=len(domain))
        _, firsts, inverse = np.unique(ids, return_index=True, return_inverse=True)
        if len(firsts) == len(domain):
            domains.append(domain)
            members.append(tuple((j,) for j in range(len(domain))))
            continue
        order = np.argsort(firsts, kind="stable")  # classes in domain order of their first value
        rank = np.empty(len(order), dtype=np.int64)
        rank[order] = np.arange(len(order))
        by_class = rank[inverse.reshape(-1)]
        positions = np.argsort(by_class, kind="stable")
        bounds = np.searchsorted(by_class[positions], np.arange(len(order) + 1)).tolist()
        listed = positions.tolist()
        members.append(tuple(tuple(listed[x:y]) for x, y in itertools.pairwise(bounds)))
        domains.append(tuple(domain[j] for j in firsts[order].tolist()))
    grouped = TypeSelection(selection.kinematic_type, tuple(domains), selection.location)
    return _Classes(selection, grouped, tuple(members))


def _scan(rules: RuleSet, classes: _Classes, *, served_too: bool) -> _Scanned:
    """Robots per configuration code, and (``served_too``) the representatives each code
    serves, with the valid and unserved robots."""
    tables = _TypeTables(rules, classes.selection, classes.weights)
    width = len(tables.domains)
    counts = _Counter(tables.key_space)
    # served[i] holds (configuration code, value position) pairs met among valid robots. Only
    # characteristics whose components hold several selected values need it; for the others
    # the configuration names the value.
    plural = [
        i
        for i in range(width)
        if served_too
        and any(
            np.count_nonzero(tables.codes[i] == c) > 1 for c in range(len(tables.components[i]))
        )
    ]
    served = {i: _Pairs(tables.key_space, len(tables.domains[i])) for i in plural}
    masks: dict[tuple[int, ...], Mask | None] = {}
    blocks: dict[int, _MaskedBlock] = {}
    total = unserved = 0
    for prefix in tables.prefixes():
        mask = tables.mask(prefix, masks)
        if mask is None:
            continue
        block = blocks.get(id(mask))
        if block is None:
            block = blocks[id(mask)] = _MaskedBlock(tables, mask, plural)
        offset, prefix_gap, weight = tables.head(prefix)
        total += block.valid * weight
        if prefix_gap:
            unserved += block.valid * weight
            continue
        unserved += (block.valid - block.kept) * weight
        # Every valid robot of the block, its configuration code and its values: a few vector
        # passes over the block per prefix.
        present = counts.add_counted(
            block.distinct + offset, block.counts * weight if weight > 1 else block.counts
        )
        for i in plural:
            if i < tables.start:
                served[i].add(present, prefix[i])
            else:
                served[i].add_shifted(block.pairs[i], offset)
    return _Scanned(tables, counts, served, total, unserved)


@dataclass(frozen=True)
class _Scanned:
    """What :func:`_scan` found: robots per configuration code, the (code, representative)
    pairs served per characteristic that needs them, and the valid and unserved robots."""

    tables: _TypeTables
    counts: _Counter
    served: dict[int, _Pairs]
    total: int
    unserved: int


class _MaskedBlock:
    """What a mask makes of the block, the same for every prefix with that mask: the valid
    robots' configuration codes within the block, and their (code, value) pairs."""

    def __init__(self, tables: _TypeTables, mask: Mask, plural: list[int]) -> None:
        keep = mask & ~tables.block_gap
        self.keys = tables.block_key[keep]
        # Counted once per mask: a prefix only shifts these codes (its cost follows the
        # configurations of the block, not its robots).
        space = tables.strides[tables.start - 1] if tables.start else tables.key_space
        # Rows may stand for several robots (value classes); weighted sums are whole numbers
        # below 2**53 (see _classes), so numpy's float64 adds them exactly.
        weight = tables.block_weight
        kept = None if weight is None else weight[keep]
        self.valid = int(np.count_nonzero(mask) if weight is None else weight[mask].sum())
        self.kept = len(self.keys) if kept is None else int(kept.sum())
        if space <= _Counter.DENSE:
            every = np.bincount(self.keys, weights=kept, minlength=space).astype(np.int64)
            self.distinct = np.flatnonzero(every)
            self.counts = every[self.distinct]
        else:
            self.distinct, where = np.unique(self.keys, return_inverse=True)
            self.counts = np.bincount(where.reshape(-1), weights=kept).astype(np.int64)
        # A set of pairs: duplicates within the block say nothing more, so keep each once
        # (marked in a bit array over the block's codes x values: cheaper than sorting).
        self.pairs = {}
        for i in plural:
            if i >= tables.start:
                size = len(tables.domains[i])
                seen = np.zeros(space * size, dtype=bool)
                seen[self.keys * size + tables.digits[i][keep]] = True
                self.pairs[i] = np.flatnonzero(seen)


class _Counter:
    """Robots per configuration code: a dense array when the code space is small, else a dict."""

    DENSE = 1 << 22

    def __init__(self, space: int) -> None:
        self.dense = np.zeros(space, dtype=np.int64) if space <= self.DENSE else None
        self.sparse: dict[int, int] = {}

    def add_counted(self, codes: Codes, counts: Codes) -> Codes:
        """Count ``counts[k]`` robots of each of the distinct ``codes``; returns ``codes``."""
        if self.dense is not None:
            self.dense[codes] += counts
            return codes
        for code, number in zip(codes.tolist(), counts.tolist(), strict=True):
            self.sparse[code] = self.sparse.get(code, 0) + number
        return codes

    def size(self) -> int:
        """How many distinct codes were counted."""
        if self.dense is not None:
            return int(np.count_nonzero(self.dense))
        return len(self.sparse)

    def found(self) -> tuple[Codes, list[int]]:
        """The codes counted, ascending, and the robots of each."""
        if self.dense is not None:
            codes = np.flatnonzero(self.dense)
            return codes, self.dense[codes].tolist()
        ordered = sorted(self.sparse.items())
        return np.array([c for c, _ in ordered], dtype=np.int64), [n for _, n in ordered]


class _Pairs:
    """A set of (configuration code, value position) pairs: a bit array when small enough."""

    DENSE = 1 << 25

    def __init__(self, space: int, size: int) -> None:
        self.size = size
        self.dense = np.zeros(space * size, dtype=bool) if space * size <= self.DENSE else None
        self.sparse: set[int] = set()

    def add(self, codes: Codes, positions: Codes | int) -> None:
        self._mark(codes * self.size + positions)

    def add_shifted(self, pairs: Codes, offset: int) -> None:
        """Pairs already coded within the block, for configuration codes ``offset`` higher."""
        self._mark(pairs + offset * self.size)

    def _mark(self, pairs: Codes) -> None:
        if self.dense is not None:
            self.dense[pairs] = True
        else:
            self.sparse.update(np.unique(pairs).tolist())

    def distinct(self, codes: Codes) -> tuple[list[list[int]], list[int]]:
        """The distinct sets of value positions paired with ``codes`` (each ascending), and
        for each code which of them it has: configurations share few sets (an arrangement's
        counts, a group's sensor types), so each is turned into values once."""
        if self.dense is not None:
            table = self.dense.reshape(-1, self.size)[codes]
            # Each row as one opaque item of bytes (a bit per value), so numpy finds the
            # distinct rows as it would distinct numbers.
            packed = np.ascontiguousarray(np.packbits(table, axis=1))
            items = packed.view(np.dtype((np.void, packed.shape[1]))).reshape(-1)
            _, firsts, which = np.unique(items, return_index=True, return_inverse=True)
            sets = [np.flatnonzero(table[row]).tolist() for row in firsts.tolist()]
            return sets, which.reshape(-1).tolist()
        by_code: dict[int, list[int]] = {code: [] for code in codes.tolist()}
        for pair in sorted(self.sparse):
            code, position = divmod(pair, self.size)
            if code in by_code:
                by_code[code].append(position)
        listed: dict[tuple[int, ...], int] = {}
        which_set = [listed.setdefault(tuple(found), len(listed)) for found in by_code.values()]
        return [list(found) for found in listed], which_set


def _partition_from_counts(scanned: _Scanned, value_classes: _Classes) -> Partition:
    tables, served = scanned.tables, scanned.served
    codes, numbers = scanned.counts.found()
    rules = tables.rules
    width = len(tables.domains)
    original = value_classes.original.domains
    members = value_classes.members

    def expand(i: int, where: Sequence[int]) -> tuple[Value, ...]:
        """The selected values the representatives at ``where`` stand for, in domain order."""
        if len(members[i]) == len(original[i]):  # nothing grouped: a representative is a value
            return _values(original[i], where)
        return _values(
            original[i], sorted(itertools.chain.from_iterable(members[i][k] for k in where))
        )

    # For a characteristic without served pairs, a component code names its selected values.
    named = [
        []
        if i in served
        else [
            expand(i, np.flatnonzero(tables.codes[i] == c).tolist())
            for c in range(len(tables.components[i]))
        ]
        for i in range(width)
    ]
    sizes = np.array([len(c) for c in tables.components], dtype=np.int64)
    digits = (codes[:, None] // np.array(tables.strides, dtype=np.int64)) % sizes
    # Column by column (a characteristic at a time), then zipped into one row per
    # configuration: few Python steps per configuration.
    key_columns = []
    value_columns = []
    for i in range(width):
        column = digits[:, i]
        key_columns.append(np.array(tables.components[i], dtype=np.int64)[column].tolist())
        if i in served:
            sets, which = served[i].distinct(codes)
            made = [expand(i, found) for found in sets]
            value_columns.append(list(map(made.__getitem__, which)))
        else:
            value_columns.append(list(map(named[i].__getitem__, column.tolist())))
    # Codes ascend, and a code orders configurations as their keys do (components numbered in
    # order, the first characteristic the most significant); the kinematic type is the same
    # throughout, so this is already numbering order (:func:`sort_key`).
    classes = [
        PartitionClass(key, number, values)
        for key, number, values in zip(
            zip(*key_columns, strict=True), numbers, zip(*value_columns, strict=True), strict=True
        )
    ]
    kinematic_type = str(tables.domains[rules.key_position][0])
    return Partition(kinematic_type, tuple(classes), scanned.total, scanned.unserved, True)
