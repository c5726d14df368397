"""Fast enumeration of valid robots: streaming, vectorised with numpy, constant memory.

The robots of one kinematic type are the product of the selected domains. The trailing
characteristics whose product fits :data:`BLOCK` form a *block*: their value positions are laid
out once as numpy arrays. Every assignment of the leading characteristics (the *prefix*) then
examines one block of robots with a handful of vector operations: the constraint mask (each rule
pre-evaluated on the block, combined with the prefix values as scalars), the configuration code
of every robot, a ``bincount``. Only the current block is in memory: memory grows with the block
size and the number of UI configurations, never with the number of robots.

The python-constraint engine (:mod:`solver.model`) stays the reference; the property tests
check that both give identical robots and partitions.

Not here: counting without enumeration (:mod:`solver.structure`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from solver.constraints import Value
from solver.partition import Partition, partition, sort_key
from solver.rules import RuleSet
from solver.team import TypeSelection

if TYPE_CHECKING:
    from numpy.typing import NDArray

__all__ = ["BLOCK", "partition_stream", "robots_stream"]

# Robots examined per vector step. Big enough to amortise numpy's per-call cost, small enough to
# stay in cache-friendly memory (a few MB per block).
BLOCK = 1 << 18


@dataclass(frozen=True)
class _Rule:
    """A rule split into the part decided by the prefix (scalars) and by the block (vectors)."""

    kind: str
    when_prefix: tuple[tuple[int, frozenset[int]], ...]   # (prefix position, allowed digits)
    then_prefix: tuple[tuple[int, frozenset[int]], ...]
    when_block: Any   # bool array over the block, or None (no block conditions: true)
    then_block: Any


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
            reached = sorted({characteristic.membership[characteristic.positions[v]][0]
                              for v in domain if characteristic.membership[
                                  characteristic.positions[v]]})
            self.components.append(reached)
            lookup = {component: i for i, component in enumerate(reached)}
            codes.append(np.array([lookup.get(_first(characteristic.membership[
                characteristic.positions[v]]), -1) for v in domain], dtype=np.int64))
        self.codes = codes
        self.strides = [math.prod(len(c) for c in self.components[i + 1:]) for i in range(width)]
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

    def _split(self, rule: Any) -> _Rule:
        index = {name: i for i, name in enumerate(self.rules.names)}

        def part(conditions: Any) -> tuple[tuple[tuple[int, frozenset[int]], ...], Any]:
            scalars = []
            vector = None
            for condition in conditions:
                position = index[condition.characteristic]
                allowed = frozenset(i for i, v in enumerate(self.domains[position])
                                    if v in condition.allowed)
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
        return itertools.product(*(range(len(d)) for d in self.domains[:self.start]))

    def mask(self, prefix: tuple[int, ...], cache: dict[tuple[int, ...], Any]) -> Any:
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

    def _mask(self, pattern: tuple[int, ...]) -> Any:
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


def _first(members: tuple[int, ...]) -> int:
    return members[0] if members else -1


def robots_stream(rules: RuleSet, selection: TypeSelection) -> Iterator[tuple[Value, ...]]:
    """Every valid robot of one kinematic type, block by block, in product order."""
    plan = _Plan(rules, selection)
    cache: dict[tuple[int, ...], Any] = {}
    domains = plan.domains
    width = len(domains)
    for prefix in plan.prefixes():
        mask = plan.mask(prefix, cache)
        if mask is None:
            continue
        head = tuple(domains[i][d] for i, d in enumerate(prefix))
        columns = [np.asarray(domains[i], dtype=object)[plan.digits[i][mask]]
                   for i in range(plan.start, width)]
        for tail in zip(*columns, strict=True):
            yield head + tuple(tail)


def partition_stream(rules: RuleSet, selection: TypeSelection) -> Partition:
    """The configurations of one kinematic type, by vectorised enumeration of its robots."""
    if not all(c.is_partition for c in rules.characteristics):
        return partition(rules, selection.kinematic_type, robots_stream(rules, selection))
    plan = _Plan(rules, selection)
    width = len(plan.domains)
    counts = _Counter(plan.key_space)
    # served[i] holds (configuration code, value position) pairs met among valid robots. Only
    # characteristics whose components hold several selected values need it; for the others
    # the configuration names the value.
    plural = [i for i in range(width)
              if any(np.count_nonzero(plan.codes[i] == c) > 1
                     for c in range(len(plan.components[i])))]
    served = {i: _Pairs(plan.key_space, len(plan.domains[i])) for i in plural}
    cache: dict[tuple[int, ...], Any] = {}
    total = unserved = 0
    for prefix in plan.prefixes():
        mask = plan.mask(prefix, cache)
        if mask is None:
            continue
        offset = 0
        prefix_gap = False
        for position, digit in enumerate(prefix):
            code = int(plan.codes[position][digit])
            prefix_gap |= code < 0
            offset += code * plan.strides[position]
        valid = int(np.count_nonzero(mask))
        total += valid
        if prefix_gap:
            unserved += valid
            continue
        keep = mask & ~plan.block_gap
        unserved += valid - int(np.count_nonzero(keep))
        keys = plan.block_key[keep] + offset
        present = counts.add(keys)
        for i in plural:
            if i < plan.start:
                served[i].add(present, prefix[i])
            else:
                served[i].add(keys, plan.digits[i][keep])
    return _partition_from_counts(plan, counts.items(), served, total, unserved)


class _Counter:
    """Robots per configuration code: a dense array when the code space is small, else a dict."""

    DENSE = 1 << 22

    def __init__(self, space: int) -> None:
        self.dense = np.zeros(space, dtype=np.int64) if space <= self.DENSE else None
        self.sparse: dict[int, int] = {}

    def add(self, keys: Any) -> Any:
        """Count ``keys``; returns the distinct codes among them."""
        if self.dense is not None:
            block = np.bincount(keys, minlength=len(self.dense))
            self.dense += block
            return np.flatnonzero(block)
        codes, block_counts = np.unique(keys, return_counts=True)
        for code, number in zip(codes.tolist(), block_counts.tolist(), strict=True):
            self.sparse[code] = self.sparse.get(code, 0) + number
        return codes

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

    def add(self, codes: Any, positions: Any) -> None:
        pairs = codes * self.size + positions
        if self.dense is not None:
            self.dense[pairs] = True
        else:
            self.sparse.update(np.unique(pairs).tolist())

    def grouped(self, codes: list[int]) -> list[Any]:
        """For each of ``codes``: the value positions paired with it, ascending."""
        if self.dense is not None:
            table = self.dense.reshape(-1, self.size)[codes]
            rows, columns = np.nonzero(table)
            return np.split(columns, np.searchsorted(rows, np.arange(1, len(codes))))
        by_code: dict[int, list[int]] = {code: [] for code in codes}
        for pair in sorted(self.sparse):
            code, position = divmod(pair, self.size)
            if code in by_code:
                by_code[code].append(position)
        return [np.array(by_code[code], dtype=np.int64) for code in codes]


def _partition_from_counts(plan: _Plan, counts: list[tuple[int, int]],
                           served: dict[int, _Pairs], total: int, unserved: int) -> Partition:
    rules = plan.rules
    width = len(plan.domains)
    arrays = [np.asarray(domain, dtype=object) for domain in plan.domains]
    # For a characteristic without served pairs, a component code names its selected values.
    named = [[tuple(arrays[i][plan.codes[i] == c].tolist()) for c in range(len(plan.components[i]))]
             for i in range(width)]
    codes = [code for code, _ in counts]
    positions = {i: pairs.grouped(codes) for i, pairs in served.items()}
    classes = []
    for row, (code, number) in enumerate(counts):
        digits = [(code // plan.strides[i]) % len(plan.components[i]) for i in range(width)]
        key = tuple(plan.components[i][d] for i, d in enumerate(digits))
        values = tuple(tuple(arrays[i][positions[i][row]].tolist()) if i in served
                       else named[i][digits[i]] for i in range(width))
        classes.append((key, number, values))
    classes.sort(key=lambda item: sort_key(rules, item[0]))
    kinematic_type = str(plan.domains[rules.key_position][0])
    return Partition(kinematic_type, tuple(classes), total, unserved, True)
