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
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeAlias

import numpy as np

from solver import partition as partitioning
from solver.constraints import Value
from solver.engines import Counts
from solver.partition import Partition, PartitionClass, sort_key
from solver.rules import RuleSet
from solver.team import TypeSelection

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from solver.constraints import Condition, RuleConstraint

# Over the block: True where a robot passes (a mask), and whole-number codes or positions.
Mask: TypeAlias = "NDArray[np.bool_]"
Codes: TypeAlias = "NDArray[np.int64]"
Scalars = tuple[tuple[int, frozenset[int]], ...]  # (prefix position, allowed digits)

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


class _Plan:
    """Everything about one kinematic type that does not change from block to block."""

    def __init__(self, rules: RuleSet, selection: TypeSelection) -> None:
        self.rules = rules
        self.domains = selection.domains
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
        for characteristic, domain in zip(rules.characteristics, self.domains, strict=True):
            # The component of each selected value (-1: none), then renumbered compactly.
            first = np.array([_first(m) for m in characteristic.membership], dtype=np.int64)
            if len(domain) == len(characteristic.values):
                component = first
            else:
                where = characteristic.positions
                component = first[
                    np.fromiter((where[v] for v in domain), dtype=np.int64, count=len(domain))
                ]
            reached = np.unique(component[component >= 0])
            self.components.append(reached.tolist())
            compact = np.full(int(first.max(initial=0)) + 2, -1, dtype=np.int64)
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


def robots(rules: RuleSet, selection: TypeSelection) -> Iterator[tuple[Value, ...]]:
    """Every valid robot of one kinematic type, block by block, in product order."""
    plan = _Plan(rules, selection)
    cache: dict[tuple[int, ...], Mask | None] = {}
    domains = plan.domains
    width = len(domains)
    for prefix in plan.prefixes():
        mask = plan.mask(prefix, cache)
        if mask is None:
            continue
        head = tuple(domains[i][d] for i, d in enumerate(prefix))
        columns = [
            np.asarray(domains[i], dtype=object)[plan.digits[i][mask]]
            for i in range(plan.start, width)
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
    rules: RuleSet, selection: TypeSelection
) -> tuple[BlockLayout, Iterator[RobotBlock]]:
    """Every valid robot of one kinematic type as blocks of positions and configuration codes,
    in the order of :func:`robots`: for writers that turn millions of robots into rows with
    vector operations rather than one Python tuple per robot.

    The codes are those of each value's first component: the configuration of a robot when
    every value is in at most one component.
    """
    plan = _Plan(rules, selection)
    layout = BlockLayout(
        tuple(plan.domains),
        plan.start,
        tuple(plan.digits[i] for i in range(plan.start, len(plan.domains))),
        tuple(tuple(c) for c in plan.components),
        tuple(plan.strides),
    )
    return layout, _robot_blocks(plan)


def _robot_blocks(plan: _Plan) -> Iterator[RobotBlock]:
    masks: dict[tuple[int, ...], Mask | None] = {}
    # Per distinct mask, once: its valid rows and their distinct codes within the block.
    blocks: dict[int, tuple[Codes, Codes, Codes]] = {}
    for prefix in plan.prefixes():
        mask = plan.mask(prefix, masks)
        if mask is None:
            continue
        found = blocks.get(id(mask))
        if found is None:
            rows = np.flatnonzero(mask)
            keys, which = np.unique(
                np.where(plan.block_gap, -1, plan.block_key)[rows], return_inverse=True
            )
            found = blocks[id(mask)] = (rows, keys, which.reshape(-1))
        rows, keys, which = found
        offset = 0
        gap = False
        for position, digit in enumerate(prefix):
            code = int(plan.codes[position][digit])
            gap |= code < 0
            offset += code * plan.strides[position]
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
    _, counts, _, total, unserved = _scan(rules, selection, served_too=False)
    return Counts(selection.kinematic_type, total, counts.size(), unserved)


def partition(rules: RuleSet, selection: TypeSelection, _memo: object = None) -> Partition:
    """The configurations of one kinematic type, by vectorised enumeration of its robots.

    The memo is unused: enumeration shares nothing between kinematic types.
    """
    if not all(c.is_partition for c in rules.characteristics):
        return partitioning.partition(rules, selection.kinematic_type, robots(rules, selection))
    plan, counts, served, total, unserved = _scan(rules, selection, served_too=True)
    return _partition_from_counts(plan, counts.items(), served, total, unserved)


def _scan(
    rules: RuleSet, selection: TypeSelection, *, served_too: bool
) -> tuple[_Plan, _Counter, dict[int, _Pairs], int, int]:
    """Robots per configuration code, and (``served_too``) the values each code serves, with
    the valid and unserved robots."""
    plan = _Plan(rules, selection)
    width = len(plan.domains)
    counts = _Counter(plan.key_space)
    # served[i] holds (configuration code, value position) pairs met among valid robots. Only
    # characteristics whose components hold several selected values need it; for the others
    # the configuration names the value.
    plural = [
        i
        for i in range(width)
        if served_too
        and any(np.count_nonzero(plan.codes[i] == c) > 1 for c in range(len(plan.components[i])))
    ]
    served = {i: _Pairs(plan.key_space, len(plan.domains[i])) for i in plural}
    masks: dict[tuple[int, ...], Mask | None] = {}
    blocks: dict[int, _MaskedBlock] = {}
    total = unserved = 0
    for prefix in plan.prefixes():
        mask = plan.mask(prefix, masks)
        if mask is None:
            continue
        block = blocks.get(id(mask))
        if block is None:
            block = blocks[id(mask)] = _MaskedBlock(plan, mask, plural)
        total += block.valid
        offset = 0
        prefix_gap = False
        for position, digit in enumerate(prefix):
            code = int(plan.codes[position][digit])
            prefix_gap |= code < 0
            offset += code * plan.strides[position]
        if prefix_gap:
            unserved += block.valid
            continue
        unserved += block.valid - len(block.keys)
        # Every valid robot of the block, its configuration code and its values: a few vector
        # passes over the block per prefix.
        present = counts.add_counted(block.distinct + offset, block.counts)
        for i in plural:
            if i < plan.start:
                served[i].add(present, prefix[i])
            else:
                served[i].add_shifted(block.pairs[i], offset)
    return plan, counts, served, total, unserved


class _MaskedBlock:
    """What a mask makes of the block, the same for every prefix with that mask: the valid
    robots' configuration codes within the block, and their (code, value) pairs."""

    def __init__(self, plan: _Plan, mask: Mask, plural: list[int]) -> None:
        self.valid = int(np.count_nonzero(mask))
        keep = mask & ~plan.block_gap
        self.keys = plan.block_key[keep]
        # Counted once per mask: a prefix only shifts these codes (its cost follows the
        # configurations of the block, not its robots).
        space = plan.strides[plan.start - 1] if plan.start else plan.key_space
        if space <= _Counter.DENSE:
            every = np.bincount(self.keys, minlength=space)
            self.distinct = np.flatnonzero(every)
            self.counts = every[self.distinct]
        else:
            self.distinct, self.counts = np.unique(self.keys, return_counts=True)
        # A set of pairs: duplicates within the block say nothing more, so keep each once
        # (marked in a bit array over the block's codes x values: cheaper than sorting).
        self.pairs = {}
        for i in plural:
            if i >= plan.start:
                size = len(plan.domains[i])
                seen = np.zeros(space * size, dtype=bool)
                seen[self.keys * size + plan.digits[i][keep]] = True
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

    def items(self) -> list[tuple[int, int]]:
        if self.dense is not None:
            codes = np.flatnonzero(self.dense)
            return list(zip(codes.tolist(), self.dense[codes].tolist(), strict=True))
        return sorted(self.sparse.items())


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

    def grouped(self, codes: list[int]) -> list[Sequence[int]]:
        """For each of ``codes``: the value positions paired with it, ascending (a ``range``
        where they are a run, which is the common case for counts)."""
        if self.dense is not None:
            table = self.dense.reshape(-1, self.size)[codes]
            # First and last position per row and how many: a row is a run when they agree
            # (three passes over the table, no index per pair); other rows are listed.
            sizes = np.count_nonzero(table, axis=1)
            firsts = table.argmax(axis=1)
            lasts = self.size - 1 - table[:, ::-1].argmax(axis=1)
            runs = (lasts - firsts + 1 == sizes) & (sizes > 0)
            # The other rows' positions in one pass, split by row as Python lists.
            others = np.flatnonzero(~runs)
            rows, columns = np.nonzero(table[others])
            bounds = np.searchsorted(rows, np.arange(len(others) + 1)).tolist()
            listed = columns.tolist()
            where = dict(zip(others.tolist(), itertools.pairwise(bounds), strict=True))
            found: list[Sequence[int]] = []
            for row, (run, first, last) in enumerate(
                zip(runs.tolist(), firsts.tolist(), lasts.tolist(), strict=True)
            ):
                if run:
                    found.append(range(first, last + 1))
                else:
                    a, b = where[row]
                    found.append(listed[a:b])
            return found
        by_code: dict[int, list[int]] = {code: [] for code in codes}
        for pair in sorted(self.sparse):
            code, position = divmod(pair, self.size)
            if code in by_code:
                by_code[code].append(position)
        return [by_code[code] for code in codes]


def _partition_from_counts(
    plan: _Plan, counts: list[tuple[int, int]], served: dict[int, _Pairs], total: int, unserved: int
) -> Partition:
    rules = plan.rules
    width = len(plan.domains)
    # For a characteristic without served pairs, a component code names its selected values.
    named = [
        []
        if i in served
        else [
            _values(domain, np.flatnonzero(plan.codes[i] == c).tolist())
            for c in range(len(plan.components[i]))
        ]
        for i, domain in enumerate(plan.domains)
    ]
    codes = np.array([code for code, _ in counts], dtype=np.int64)
    positions = {i: pairs.grouped(codes.tolist()) for i, pairs in served.items()}
    sizes = np.array([len(c) for c in plan.components], dtype=np.int64)
    digit_rows = ((codes[:, None] // np.array(plan.strides, dtype=np.int64)) % sizes).tolist()
    classes = []
    components = plan.components
    domains = plan.domains
    columns = [(i, positions.get(i), named[i]) for i in range(width)]
    # Configurations share few distinct value sets (an arrangement's counts, a group's sensor
    # types): each is made once.
    made: dict[tuple[int, Sequence[int] | tuple[int, ...]], tuple[Value, ...]] = {}

    def values_at(i: int, where: Sequence[int]) -> tuple[Value, ...]:
        key = (i, where if isinstance(where, range) else tuple(where))
        found = made.get(key)
        if found is None:
            found = made[key] = _values(domains[i], where)
        return found

    for row, ((_, number), digits) in enumerate(zip(counts, digit_rows, strict=True)):
        key = tuple([components[i][d] for i, d in enumerate(digits)])
        values = tuple(
            [
                values_at(i, grouped[row]) if grouped is not None else by_code[digits[i]]
                for i, grouped, by_code in columns
            ]
        )
        classes.append(PartitionClass(key, number, values))
    classes.sort(key=lambda found: sort_key(rules, found.key))
    kinematic_type = str(plan.domains[rules.key_position][0])
    return Partition(kinematic_type, tuple(classes), total, unserved, True)
