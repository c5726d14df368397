"""Exact counting from the structure of a team, without enumerating robots.

Two observations make counting independent of how many robots there are:

* **Interchangeable values.** Two values of a characteristic that belong to the same components
  and satisfy exactly the same conditions of every rule constraint can never be told apart by
  the rules. Each characteristic's selected values are grouped into such *value classes*
  (:attr:`RuleSet.value_classes`; 1..50 sensors under the article's rules: five classes, one
  per arrangement).
* **Independent characteristics.** Characteristics that no constraint links vary freely, so
  counts multiply. Characteristics linked by constraints form a *block*; only the block's class
  combinations are enumerated (a handful, whatever the domain sizes), each weighted by the
  number of robots it stands for.

For one kinematic type: valid robots = product over blocks of the block's weight; UI
configurations = product over blocks of the distinct component combinations the block reaches
(the article's closed form, a product of component counts, is the constraint-free special
case, and rules without constraints are counted as that product: :func:`count`). Team totals
are sums over kinematic types. All arithmetic is on Python integers, so 10^30 robots are
counted exactly. Kinematic types whose selections have the same structure are counted once
(:class:`Memo`).

Where the structure does not allow this (a block whose class combinations exceed
:data:`BLOCK_LIMIT`), :class:`~solver.errors.StructureTooComplex` says so and the ``auto``
policy falls back to enumeration. Overlapping components (a value in two components) take the
exact minimum cover of :mod:`solver.core.cover`, found from each block's class combinations
apart (the blocks vary independently, so the family to cover is their product); each block's
combinations then get their part of the lowest chosen configuration, and configurations are the
product of the blocks' parts as without overlaps. Only a cover that must span blocks (no product
of separate covers is minimal) partitions the joint classes
(:func:`solver.core.partition.partition_classes`).

Not here: enumerating robots (:mod:`solver.engines.fast`, :mod:`solver.engines.csp`), symbolic
formulas (:mod:`solver.solving.symbolic`).
"""

from __future__ import annotations

import bisect
import itertools
import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any, NamedTuple

from solver.core.constraints import Value
from solver.core.partition import Key, Partition, PartitionClass, RobotClass, partition_classes
from solver.core.ruleset import RuleSet
from solver.core.team import TypeSelection
from solver.engines.shared import Counts, Memo
from solver.errors import StructureTooComplex
from solver.limits import readable
from solver.untrusted import shown

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import NDArray

    from solver.core.constraints import Condition
    from solver.core.cover import Cover, Group, Pieces

__all__ = [
    "BLOCK_LIMIT",
    "Product",
    "component_use",
    "count",
    "partition",
    "product",
    "robots",
]

# Class combinations one block may have before counting falls back to enumeration.
BLOCK_LIMIT = 1_000_000
# Class combinations past which a block is evaluated as a numpy mask, not a list.
VECTOR = 4096

Members = tuple[Value, ...]


@dataclass(frozen=True, slots=True)
class _Class:
    """Selected values of one characteristic that the rules cannot tell apart."""

    index: int  # its position in RuleSet.value_classes
    members: Members
    membership: tuple[int, ...]  # the components every member belongs to


class _Block:
    """Characteristics linked by constraints, and their valid class combinations.

    Small blocks list their combinations and are tallied once, as they are made (plain
    attributes: a cached property takes a lock on every first use, and counting a team made
    over a hundred of them). Large ones (more than :data:`VECTOR` class combinations) hold
    them as a numpy mask over the product of their classes, so counting never makes a Python
    tuple per combination, and the list is made only if asked for.
    """

    def __init__(
        self,
        positions: tuple[int, ...],
        combinations: tuple[tuple[tuple[_Class, ...], int], ...] | None = None,
        grid: _Grid | None = None,
    ) -> None:
        self.positions = positions
        self._combinations = combinations
        self.grid = grid
        self._tally = None if combinations is None else _tally(combinations)

    @property
    def combinations(self) -> tuple[tuple[tuple[_Class, ...], int], ...]:
        """(one class per position, the robots it stands for), in product order."""
        if self._combinations is not None:
            return self._combinations
        return self._grid_combinations

    @staticmethod
    def partial_key(classes: tuple[_Class, ...]) -> Key | None:
        """The block's components for a combination (``None``: a class in no component)."""
        if not all(c.membership for c in classes):
            return None
        return tuple(c.membership[0] for c in classes)

    # A grid block's figures, each worked out over its mask when first asked for.
    @property
    def _grid(self) -> _Grid:
        assert self.grid is not None  # one of the two is always given
        return self.grid

    @cached_property
    def _grid_combinations(self) -> tuple[tuple[tuple[_Class, ...], int], ...]:
        return self._grid.combinations()

    @cached_property
    def _grid_weights(self) -> dict[Key, int]:
        return self._grid.partial_weights()

    @cached_property
    def _grid_configurations(self) -> int:
        return len(self._grid.keys())

    @cached_property
    def _grid_robots(self) -> tuple[int, int]:
        return self._grid.robots(served=False), self._grid.robots(served=True)

    @cached_property
    def _grid_overlaps(self) -> bool:
        return self._grid.overlaps()

    @property
    def partial_weights(self) -> dict[Key, int]:
        """Robots per partial configuration (robots with a value in no component left out)."""
        return self._grid_weights if self._tally is None else self._tally.partial_weights

    @property
    def configurations(self) -> int:
        """How many partial configurations the block reaches (values in one component each)."""
        if self._tally is None:
            return self._grid_configurations
        return len(self._tally.partial_weights)

    @property
    def robots(self) -> int:
        return self._grid_robots[0] if self._tally is None else self._tally.robots

    @property
    def served(self) -> int:
        """Robots whose every class is in some component."""
        return self._grid_robots[1] if self._tally is None else self._tally.served

    @property
    def overlaps(self) -> bool:
        """Whether a class of a valid combination is in several components."""
        return self._grid_overlaps if self._tally is None else self._tally.overlaps


class _Tally(NamedTuple):
    robots: int
    served: int  # robots whose every class is in some component
    partial_weights: dict[Key, int]  # robots per partial configuration
    overlaps: bool  # a class of a valid combination is in several components


def _tally(combinations: tuple[tuple[tuple[_Class, ...], int], ...]) -> _Tally:
    """A listed block's figures (see :class:`_Block`), in one pass over its combinations."""
    robots = served = 0
    weights: dict[Key, int] = {}
    overlaps = False
    for combination, weight in combinations:
        robots += weight
        if len(combination) == 1:  # most blocks: one characteristic
            membership = combination[0].membership
            if membership:
                overlaps = overlaps or len(membership) > 1
                own = (membership[0],)
                served += weight
                weights[own] = weights.get(own, 0) + weight
            continue
        # Plain loops: a block's combinations are few and short, and a generator per step
        # cost more than the step.
        components: list[int] | None = []
        for found in combination:
            membership = found.membership
            if len(membership) > 1:
                overlaps = True
            if not membership:
                components = None
            elif components is not None:
                components.append(membership[0])
        if components is not None:
            key = tuple(components)
            served += weight
            weights[key] = weights.get(key, 0) + weight
    return _Tally(robots, served, weights, overlaps)


class _Grid:
    """The valid class combinations of a large block as a mask over the product of its classes
    (C order: the last position varies fastest, as :func:`itertools.product`)."""

    def __init__(self, classes: Sequence[Sequence[_Class]], valid: NDArray[np.bool_]) -> None:
        import numpy as np

        self.classes = classes
        self.valid = valid  # shaped as the product
        self.shape = tuple(len(c) for c in classes)
        self._np = np

    def _axis(self, axis: int, column: Sequence[int] | Sequence[bool]) -> NDArray[Any]:
        shape = [1] * len(self.shape)
        shape[axis] = -1
        return self._np.asarray(column).reshape(shape)

    def _served(self) -> NDArray[np.bool_]:
        served = self.valid.copy()
        for axis, found in enumerate(self.classes):
            served &= self._axis(axis, [bool(c.membership) for c in found])
        return served

    def robots(self, *, served: bool) -> int:
        """The robots of the valid (and, with ``served``, served) combinations, exactly."""
        np = self._np
        mask = self._served() if served else self.valid
        # Python integers where the block's robots could overflow int64.
        bound = math.prod(sum(len(c.members) for c in found) for found in self.classes)
        kind = np.int64 if bound < 1 << 62 else object
        weights: NDArray[Any] = mask.astype(kind)
        for axis, found in enumerate(self.classes):
            weights = weights * self._axis(
                axis, np.array([len(c.members) for c in found], dtype=kind)
            )
        return int(weights.sum())

    def _codes(self) -> tuple[NDArray[np.int64], list[list[int]]]:
        """Each served combination's partial configuration as one number (mixed radix over the
        components each position reaches, compactly), and those components per position."""
        np = self._np
        served = self._served()
        reached = [
            sorted({c.membership[0] for c in found if c.membership}) for found in self.classes
        ]
        code = np.zeros(self.shape, dtype=np.int64)
        for axis, found in enumerate(self.classes):
            digit = {component: d for d, component in enumerate(reached[axis])}
            column = [digit[c.membership[0]] if c.membership else 0 for c in found]
            radix = math.prod(len(r) for r in reached[axis + 1 :])
            code = code + self._axis(axis, np.array(column, dtype=np.int64) * radix)
        return code[served], reached

    def keys(self) -> NDArray[np.int64]:
        """The partial configurations reached, ascending, one row each (component indices)."""
        np = self._np
        codes, reached = self._codes()
        # Sorted, then one of each run: numpy's unique hashes first, ten times slower here.
        codes = np.sort(codes)
        unique = codes[np.concatenate(([True], codes[1:] != codes[:-1]))] if len(codes) else codes
        columns = []
        for axis in range(len(self.shape)):
            radix = math.prod(len(r) for r in reached[axis + 1 :])
            digits = unique // radix % max(len(reached[axis]), 1)
            columns.append(np.asarray(reached[axis], dtype=np.int64)[digits])
        keys: NDArray[Any] = np.stack(columns, axis=1)
        return keys

    def partial_weights(self) -> dict[Key, int]:
        weights: dict[Key, int] = {}
        for combination, weight in self.combinations():
            key = _Block.partial_key(combination)
            if key is not None:
                weights[key] = weights.get(key, 0) + weight
        return weights

    def overlaps(self) -> bool:
        np = self._np
        for axis, found in enumerate(self.classes):
            present = self.valid.any(axis=tuple(a for a in range(len(self.shape)) if a != axis))
            plural = np.array([len(c.membership) > 1 for c in found])
            if (present & plural).any():
                return True
        return False

    def combinations(self) -> tuple[tuple[tuple[_Class, ...], int], ...]:
        np = self._np
        where = np.nonzero(self.valid)
        return tuple(
            (
                choice := tuple(found[i] for found, i in zip(self.classes, index, strict=True)),
                math.prod(len(c.members) for c in choice),
            )
            for index in zip(*(w.tolist() for w in where), strict=True)
        )


def count(rules: RuleSet, selection: TypeSelection, memo: Memo | None = None) -> Counts:
    """Valid robots and UI configurations of one kinematic type, without enumerating robots.

    ``memo``, shared across the kinematic types of a team, avoids counting twice a structure
    that several types share (their robots differ only by the type's name).
    """
    if not rules.constraints:
        free = _free_count(rules, selection, memo)
        if free is not None:
            return free
    classes = _selected_classes(rules, selection, memo)
    signature: list[object] = [_shape(found, memo) for found in classes]
    # The type itself only matters through the constraint conditions it meets (each type is
    # its own component, so which one it is never changes a count).
    kinematic_type = selection.kinematic_type
    signature[rules.key_position] = tuple(
        kinematic_type in condition.allowed
        for rule in rules.constraints
        for condition in (*rule.when, *rule.conditions)
        if condition.characteristic == rules.team_key
    )
    memo_key = tuple(signature)
    if memo is not None and memo_key in memo.counts:
        return _renamed(memo.counts[memo_key], kinematic_type)
    blocks = _blocks(rules, classes)
    if memo is not None:
        memo.blocks[kinematic_type] = blocks
    if _overlaps(blocks):
        robots = served = 1
        for block in blocks:
            robots *= block.robots
            served *= block.served
        cover = _cover(rules, blocks)
        if memo is not None:
            memo.covers[kinematic_type] = cover
        result = Counts(selection.kinematic_type, robots, cover.size, robots - served)
    else:
        robots = served = configurations = 1
        for block in blocks:
            robots *= block.robots
            served *= block.served
            configurations *= block.configurations
        result = Counts(selection.kinematic_type, robots, configurations, robots - served)
    if memo is not None:
        memo.counts[memo_key] = result
    return result


@dataclass(frozen=True)
class Product:
    """The UI configurations of one kinematic type as a product, without listing them.

    ``parts``: per block of characteristics, its places in numbering order (the team key first,
    then the others in rule order: :func:`solver.core.partition.sort_key`) and its partial
    configurations over them, ascending; every configuration joins one of each block.
    ``cover``: where values overlap, the minimum cover that gives each robot its configuration
    (its keys in numbering order too).
    """

    parts: tuple[tuple[tuple[int, ...], NDArray[np.int64]], ...]  # keys: one row each
    cover: Cover | None

    @property
    def size(self) -> int:
        """How many configurations."""
        return math.prod(len(keys) for _, keys in self.parts)


def product(rules: RuleSet, selection: TypeSelection) -> Product | None:
    """The configurations of one kinematic type as a :class:`Product` of its blocks' parts;
    ``None`` where overlapping values need a cover spanning blocks (not a product of theirs).
    :class:`~solver.errors.StructureTooComplex` where the structure does not apply."""
    import numpy as np

    blocks = _blocks(rules, _selected_classes(rules, selection))
    cover = None
    key_of: Callable[[_Block, tuple[_Class, ...]], Key | None] = _own_key
    if _overlaps(blocks):
        cover = _cover(rules, blocks)
        by_block = _cover_by_block(rules, blocks, cover)
        if by_block is None:
            return None
        key_of = by_block
    place = _numbering(rules)
    parts = []
    for block in blocks:
        order = sorted(range(len(block.positions)), key=lambda i: place[block.positions[i]])
        if block.grid is not None and cover is None:
            keys = block.grid.keys()[:, order]
            keys = keys[np.lexsort(keys.T[::-1])] if len(order) > 1 else keys
        else:
            found = {key_of(block, combination) for combination, _ in block.combinations}
            listed = sorted(tuple([key[i] for i in order]) for key in found if key is not None)
            keys = np.array(listed, dtype=np.int64).reshape(len(listed), len(order))
        parts.append((tuple(place[block.positions[i]] for i in order), keys))
    return Product(tuple(parts), cover)


def robots(rules: RuleSet, selection: TypeSelection) -> Iterator[tuple[Value, ...]]:
    """Every valid robot: counting by structure never lists robots, so the fast engine does."""
    from solver.engines.fast import robots as enumerated

    return enumerated(rules, selection)


def _renamed(counts: Counts, kinematic_type: str) -> Counts:
    return Counts(
        kinematic_type, counts.valid_robots, counts.ui_configurations, counts.unserved_robots
    )


def partition(
    rules: RuleSet, selection: TypeSelection, blocks: Sequence[_Block] | Memo | None = None
) -> Partition:
    """The configurations of one kinematic type, with robot counts and served values.

    ``blocks``: the type's blocks if already built, or a :class:`Memo` that :func:`count`
    filled for this type.
    """
    memo = None
    if isinstance(blocks, Memo):
        memo, blocks = blocks, blocks.blocks.get(selection.kinematic_type)
    if blocks is None:
        blocks = _blocks(rules, _selected_classes(rules, selection))
    if not _overlaps(blocks):
        return _partition_product(rules, selection, blocks, _own_key)
    cover = memo.covers.get(selection.kinematic_type) if memo is not None else None
    if cover is None:
        cover = _cover(rules, blocks)
    inside = _cover_by_block(rules, blocks, cover)
    if inside is not None:
        return _partition_product(rules, selection, blocks, inside)
    if math.prod(len(b.combinations) for b in blocks) > BLOCK_LIMIT:
        raise StructureTooComplex.at(
            rules.file,
            "overlapping components over too many class combinations",
            path="constraints",
        )
    return partition_classes(rules, selection.kinematic_type, _joint_classes(rules, blocks))


def component_use(
    rules: RuleSet, selection: TypeSelection
) -> dict[tuple[int, int], tuple[int, int]] | None:
    """Per (characteristic position, component): how many configurations of one kinematic type
    use the component and how many valid robots those serve, from each block's partial
    configurations without joining them (what :func:`partition` lists, tallied); ``None`` where
    overlapping values need a cover spanning blocks. A block's part of a configuration is in
    as many configurations as the other blocks' parts multiply to, and serves its robots times
    the other blocks' served robots. :class:`~solver.errors.StructureTooComplex` where the
    structure does not apply."""
    blocks = _blocks(rules, _selected_classes(rules, selection))
    key_of: Callable[[_Block, tuple[_Class, ...]], Key | None] = _own_key
    if _overlaps(blocks):
        by_block = _cover_by_block(rules, blocks, _cover(rules, blocks))
        if by_block is None:
            return None
        key_of = by_block
    per_block = [
        block.partial_weights if key_of is _own_key else _weights(block, key_of) for block in blocks
    ]
    use: dict[tuple[int, int], tuple[int, int]] = {}
    for index, (block, weights) in enumerate(zip(blocks, per_block, strict=True)):
        others = [found for n, found in enumerate(per_block) if n != index]
        configurations = math.prod(len(found) for found in others)
        served = math.prod(sum(found.values()) for found in others)
        for key, weight in weights.items():
            for position, component in zip(block.positions, key, strict=True):
                used, robots = use.get((position, component), (0, 0))
                use[position, component] = (used + configurations, robots + weight * served)
    return use


def _weights(
    block: _Block, key_of: Callable[[_Block, tuple[_Class, ...]], Key | None]
) -> dict[Key, int]:
    """Robots per partial configuration of ``block`` as ``key_of`` gives them (unserved left
    out)."""
    weights: dict[Key, int] = {}
    for combination, weight in block.combinations:
        key = key_of(block, combination)
        if key is not None:
            weights[key] = weights.get(key, 0) + weight
    return weights


def _partition_product(
    rules: RuleSet,
    selection: TypeSelection,
    blocks: Sequence[_Block],
    key_of: Callable[[_Block, tuple[_Class, ...]], Key | None],
) -> Partition:
    """Configurations as the product of each block's partial configurations, ``key_of`` giving
    the partial configuration of a block's class combination (``None``: unserved)."""
    per_block = []
    robots = served_robots = 1
    for block in blocks:
        parts = _partial_configurations(rules, block, key_of)
        robots *= block.robots
        served_robots *= sum(weight for _, weight, _ in parts)
        per_block.append(parts)
    return Partition(
        selection.kinematic_type,
        tuple([PartitionClass(*found) for found in _joined(rules, blocks, per_block)]),
        robots,
        robots - served_robots,
        True,
    )


# A configuration or a block's part of one: its key, the robots it stands for, the values served
# (per characteristic, in domain order).
_Part = tuple[Key, int, tuple[Members, ...]]


def _partial_configurations(
    rules: RuleSet, block: _Block, key_of: Callable[[_Block, tuple[_Class, ...]], Key | None]
) -> list[_Part]:
    """A block's partial configurations in key order: its combinations gathered by key, with
    their robots and the values they serve (unserved combinations left out)."""
    own = key_of is _own_key
    if own and len(block.positions) == 1:  # most blocks: one characteristic, no rule
        return _single_parts(rules, block)
    # The classes of each position that a key's combinations take (each once, first seen
    # first); their members, sorted into domain order, are the values the key serves.
    held: dict[Key, list[dict[int, Members]]] = {}
    weights = block.partial_weights if own else _weights(block, key_of)
    key: Key | None
    for combination, _ in block.combinations:
        if own and len(combination) == 1:  # most blocks: one characteristic, one component
            membership = combination[0].membership
            key = (membership[0],) if membership else None
        else:
            key = key_of(block, combination)
        if key is not None:
            taken = held.get(key)
            if taken is None:
                taken = held[key] = [{} for _ in combination]
            for classes, found in zip(taken, combination, strict=True):
                classes[found.index] = found.members
    orders = [rules.characteristics[p].positions.__getitem__ for p in block.positions]
    parts: list[_Part] = []
    for key, weight in sorted(weights.items()):
        served = []
        for classes, order in zip(held[key], orders, strict=True):
            # In domain order (a class's members are in the team's order when it lists them).
            served.append(tuple(sorted(itertools.chain(*classes.values()), key=order)))
        parts.append((key, weight, tuple(served)))
    return parts


def _single_parts(rules: RuleSet, block: _Block) -> list[_Part]:
    """:func:`_partial_configurations` of a block of one characteristic whose every value is
    in one component at most: each class goes to its component."""
    order = rules.characteristics[block.positions[0]].positions.__getitem__
    members: dict[int, list[Members]] = {}
    for (found,), _ in block.combinations:  # one class per combination, each class once
        if found.membership:
            members.setdefault(found.membership[0], []).append(found.members)
    weights = block.partial_weights
    return [
        (
            (component,),
            weights[(component,)],
            (tuple(sorted(itertools.chain(*members[component]), key=order)),),
        )
        for component in sorted(members)
    ]


def _joined(rules: RuleSet, blocks: Sequence[_Block], per_block: list[list[_Part]]) -> list[_Part]:
    """Every configuration, one partial configuration per block, in numbering order (by the
    team key's component, then the key)."""
    # Concatenate the blocks' parts, then put the characteristics back in rule order if the
    # blocks interleave them.
    width = len(rules.characteristics)
    order = [position for block in blocks for position in block.positions]
    inverse = None if order == list(range(width)) else [order.index(i) for i in range(width)]
    found_classes: list[_Part] = [((), 1, ())]
    for parts in per_block:
        found_classes = [
            (key + part_key, weight * part_weight, served + part_served)
            for key, weight, served in found_classes
            for part_key, part_weight, part_served in parts
        ]
    if inverse is not None:
        found_classes = [
            (tuple([key[j] for j in inverse]), weight, tuple([served[j] for j in inverse]))
            for key, weight, served in found_classes
        ]
    position = rules.key_position
    found_classes.sort(key=lambda item: (item[0][position], item[0]))
    return found_classes


def _own_key(_: _Block, combination: tuple[_Class, ...]) -> Key | None:
    """A combination's partial configuration where every value has one component."""
    return _Block.partial_key(combination)


def _numbering(rules: RuleSet) -> list[int]:
    """Each characteristic's place in numbering order (the team key first)."""
    key = rules.key_position
    return [0 if p == key else p + (p < key) for p in range(len(rules.characteristics))]


def _cover(rules: RuleSet, blocks: Sequence[_Block]) -> Cover:
    """The minimum cover of a kinematic type whose values overlap, from each block's class
    combinations: the same cover its robots listed one by one give
    (:func:`solver.core.partition.partition_classes`), positions in numbering order."""
    from solver.core.cover import product_cover

    place = _numbering(rules)
    parts = []
    for block in blocks:
        order = sorted(range(len(block.positions)), key=lambda i: place[block.positions[i]])
        family = {
            tuple([combination[i].membership for i in order])
            for combination, _ in block.combinations
            if all(c.membership for c in combination)
        }
        parts.append((tuple(place[block.positions[i]] for i in order), family))
    return product_cover(len(place), parts, file=rules.file)


def _cover_by_block(
    rules: RuleSet, blocks: Sequence[_Block], cover: Cover
) -> Callable[[_Block, tuple[_Class, ...]], Key | None] | None:
    """The partial configuration each class combination of a block is given (the lowest-
    numbered chosen one it can use), when every group of the cover lies inside one block;
    ``None`` when a group spans blocks (the cover is then not a product of the blocks')."""
    place = _numbering(rules)
    home = {place[p]: n for n, block in enumerate(blocks) for p in block.positions}
    groups: list[list[Group | Pieces]] = [[] for _ in blocks]
    for group in cover.groups:
        found = {home[p] for p in group.positions}
        if len(found) > 1:
            return None
        groups[found.pop()].append(group)
    # Per block and group: where the group's positions sit in the block's combinations.
    at = {
        id(group): [block.positions.index(place.index(p)) for p in group.positions]
        for block, inside in zip(blocks, groups, strict=True)
        for group in inside
    }
    number = {id(block): n for n, block in enumerate(blocks)}

    def key_of(block: _Block, combination: tuple[_Class, ...]) -> Key | None:
        if not all(c.membership for c in combination):
            return None
        key = [0] * len(combination)
        for group in groups[number[id(block)]]:
            where = at[id(group)]
            part = group.first(tuple([combination[i].membership for i in where]))
            if part is None:  # never for a valid combination: the cover hits them all
                return None
            for i, component in zip(where, part, strict=True):
                key[i] = component
        return tuple(key)

    return key_of


def _overlaps(blocks: Sequence[_Block]) -> bool:
    """Whether any value of a valid robot belongs to more than one component."""
    return any(block.overlaps for block in blocks)


def _joint_classes(rules: RuleSet, blocks: Sequence[_Block]) -> Iterator[RobotClass]:
    width = len(rules.characteristics)
    for choice in itertools.product(*(block.combinations for block in blocks)):
        values: list[Members] = [()] * width
        weight = 1
        for block, (combination, block_weight) in zip(blocks, choice, strict=True):
            weight *= block_weight
            for position, found in zip(block.positions, combination, strict=True):
                values[position] = found.members
        yield RobotClass(tuple(values), weight)


def _shape(classes: list[_Class], memo: Memo | None) -> tuple[tuple[int, int], ...]:
    """What counting sees of a characteristic's classes: which classes, how many values each."""
    if memo is not None and id(classes) in memo.shapes:
        return memo.shapes[id(classes)]  # a whole domain's (see _selected_classes)
    return tuple([(c.index, len(c.members)) for c in classes])


def _free_count(rules: RuleSet, selection: TypeSelection, memo: Memo | None) -> Counts | None:
    """The counts of a kinematic type under rules without constraints: the article's closed
    form, a product over the characteristics, which vary freely (robots: the selected values;
    served robots: those in some component; configurations: the components they reach).
    ``None`` where a selected value is in several components (the minimum cover decides)."""
    robots = served = configurations = 1
    for position, domain in enumerate(selection.domains):
        factor = _free_factor(rules, position, domain, memo)
        if factor is None:
            return None
        robots *= len(domain)
        served *= factor[0]
        configurations *= factor[1]
    return Counts(selection.kinematic_type, robots, configurations, robots - served)


# A selection of at most this many values of a characteristic is counted value by value when
# nothing links its characteristics; a longer one (a range of 100,000 counts) by its classes.
FREE_VALUES = 64


def _free_factor(
    rules: RuleSet, position: int, domain: Sequence[Value], memo: Memo | None
) -> tuple[int, int] | None:
    """Of one characteristic's selected values: how many are in some component, and how many
    components they reach; ``None`` if one is in several."""
    if len(domain) > FREE_VALUES:
        memberships = [
            (len(c.members), c.membership) for c in _classes(rules, position, domain, memo)
        ]
    else:
        characteristic = rules.characteristics[position]
        membership, where = characteristic.membership, characteristic.positions
        memberships = [(1, membership[where[value]]) for value in domain]
    served = 0
    reached = set()
    for size, components in memberships:
        if len(components) > 1:
            return None
        if components:
            served += size
            reached.add(components[0])
    return served, len(reached)


def _selected_classes(
    rules: RuleSet, selection: TypeSelection, memo: Memo | None = None
) -> list[list[_Class]]:
    """Per characteristic: the selected values, grouped into the rule set's value classes."""
    return [
        _classes(rules, position, domain, memo) for position, domain in enumerate(selection.domains)
    ]


def _classes(
    rules: RuleSet, position: int, domain: Sequence[Value], memo: Memo | None
) -> list[_Class]:
    """One characteristic's selected values grouped into its value classes (a whole domain's
    made once per team: ``memo``)."""
    whole = len(domain) == len(rules.characteristics[position].values)
    if whole and memo is not None and position in memo.whole:
        found: list[_Class] = memo.whole[position]
        return found
    classes = _cut(rules, position, domain)
    if whole and memo is not None:
        memo.whole[position] = classes
        # Its shape too, by identity: whole-domain lists live as long as the memo.
        memo.shapes[id(classes)] = tuple([(c.index, len(c.members)) for c in classes])
    return classes


def _cut(rules: RuleSet, position: int, domain: Sequence[Value]) -> list[_Class]:
    characteristic = rules.characteristics[position]
    classes = rules.value_classes[position]

    def made(index: int, members: Members) -> _Class:
        return _Class(
            index, members, characteristic.membership[characteristic.positions[members[0]]]
        )

    if len(domain) == len(characteristic.values):
        return [made(i, members) for i, members in enumerate(classes)]
    found = []
    if characteristic.kind == "integer" and int(domain[-1]) - int(domain[0]) + 1 == len(domain):
        # A range low..high (a team's "sensor_count: 13"): cut each class by bisection.
        low, high = int(domain[0]), int(domain[-1])
        for index, members in enumerate(classes):
            start = bisect.bisect_left(members, low, key=int)
            stop = bisect.bisect_right(members, high, key=int)
            if stop > start:
                found.append(made(index, members[start:stop]))
        return found
    # Any other selection: each selected value to its class, classes kept in their order.
    index_of = rules.value_class_index[position]
    grouped: dict[int, list[Value]] = {}
    for value in domain:
        grouped.setdefault(index_of[value], []).append(value)
    return [made(index, tuple(grouped[index])) for index in sorted(grouped)]


def _blocks(rules: RuleSet, classes: list[list[_Class]]) -> list[_Block]:
    """Group characteristics linked by constraints; list each group's valid class combinations."""
    groups, rules_of = _linked_groups(rules, classes)
    # A value of every characteristic; a block's are overwritten as its combinations are tried.
    values: list[Value] = [found[0].members[0] if found else "" for found in classes]
    return [
        _block(rules, classes, group, numbers, values)
        for group, numbers in zip(groups, rules_of, strict=True)
    ]


def _linked_groups(
    rules: RuleSet, classes: list[list[_Class]]
) -> tuple[list[list[int]], list[list[int]]]:
    """The characteristics' positions in groups that constraints link (each group and the
    groups in position order), and per group the numbers of the constraints over it."""
    width = len(rules.characteristics)
    if not rules.constraints:  # nothing links anything: a group per characteristic
        return [[i] for i in range(width)], [[] for _ in range(width)]
    index = {name: i for i, name in enumerate(rules.names)}
    parent = list(range(width))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    # A characteristic with a single class cannot link anything: its value never matters.
    linked = [
        [index[name] for name in rule.characteristics if len(classes[index[name]]) > 1]
        for rule in rules.constraints
    ]
    for positions in linked:
        for a, b in itertools.pairwise(positions):
            parent[find(a)] = find(b)
    members: dict[int, list[int]] = {}
    for i in range(width):
        members.setdefault(find(i), []).append(i)
    groups = sorted(members.values())
    home = {find(group[0]): n for n, group in enumerate(groups)}
    rules_of: list[list[int]] = [[] for _ in groups]
    for number, positions in enumerate(linked):
        # A rule over single-class characteristics only is a constant: attach it to the first
        # block, where it keeps every combination or none.
        rules_of[home[find(positions[0])] if positions else 0].append(number)
    return groups, rules_of


def _block(
    rules: RuleSet,
    classes: list[list[_Class]],
    group: list[int],
    numbers: list[int],
    values: list[Value],
) -> _Block:
    """One group's block: no combination when a characteristic has no class selected, its
    combinations listed when few, a grid of them past :data:`VECTOR`; refused past
    :data:`BLOCK_LIMIT`."""
    if len(group) == 1 and not numbers and len(classes[group[0]]) <= VECTOR:
        # Most blocks: one characteristic, no rule; each class is a valid combination.
        return _Block((group[0],), tuple([((c,), len(c.members)) for c in classes[group[0]]]))
    if any(not classes[i] for i in group):
        return _Block(tuple(group), ())
    size = math.prod(len(classes[i]) for i in group)
    if size > BLOCK_LIMIT:
        names = ", ".join(shown(rules.names[i]) for i in group[:6])
        if len(group) > 6:
            names += f" and {len(group) - 6} more"
        raise StructureTooComplex.at(
            rules.file,
            f"constraints link {names} into {readable(size)} class combinations "
            f"(more than {BLOCK_LIMIT})",
            path="constraints",
        )
    if size > VECTOR:
        grid = _grid(rules, [classes[i] for i in group], group, numbers, values)
        return _Block(tuple(group), grid=grid)
    return _Block(tuple(group), _listed(rules, classes, group, numbers, values))


def _listed(
    rules: RuleSet,
    classes: list[list[_Class]],
    group: list[int],
    numbers: list[int],
    values: list[Value],
) -> tuple[tuple[tuple[_Class, ...], int], ...]:
    """The valid combinations of a small block, one by one (``values``: a value of every
    characteristic, the block's overwritten as its combinations are tried)."""
    choices = itertools.product(*(classes[i] for i in group))
    if not numbers:  # no rule over the block: every combination is valid
        return tuple((choice, math.prod(len(c.members) for c in choice)) for choice in choices)
    index = {name: i for i, name in enumerate(rules.names)}
    checks = [
        (
            rules.constraints[n].predicate(),
            [index[name] for name in rules.constraints[n].characteristics],
        )
        for n in numbers
    ]
    combinations = []
    for choice in choices:
        for i, found in zip(group, choice, strict=True):
            values[i] = found.members[0]
        if all(check(*(values[i] for i in positions)) for check, positions in checks):
            combinations.append((choice, math.prod(len(c.members) for c in choice)))
    return tuple(combinations)


def _grid(
    rules: RuleSet,
    classes: list[list[_Class]],
    group: list[int],
    numbers: list[int],
    values: list[Value],
) -> _Grid:
    """The valid combinations of a large block, each rule evaluated over the whole product of
    its classes at once (a class's first value answers every condition for its class)."""
    import numpy as np

    axis_of = {position: axis for axis, position in enumerate(group)}
    shape = tuple(len(found) for found in classes)
    index = {name: i for i, name in enumerate(rules.names)}

    def holds(condition: Condition) -> NDArray[np.bool_] | bool:
        position = index[condition.characteristic]
        if position not in axis_of:  # one class outside the block: a constant
            return values[position] in condition.allowed
        axis = axis_of[position]
        column = np.array([c.members[0] in condition.allowed for c in classes[axis]])
        return column.reshape([-1 if a == axis else 1 for a in range(len(shape))])

    def together(conditions: Sequence[Condition]) -> NDArray[np.bool_] | bool:
        result: NDArray[np.bool_] | bool = True
        for condition in conditions:
            result = result & holds(condition)
        return result

    valid = np.ones(shape, dtype=bool)
    for number in numbers:
        rule = rules.constraints[number]
        if rule.kind == "forbid":
            valid &= ~np.asarray(together(rule.conditions))
        else:
            valid &= ~np.asarray(together(rule.when)) | together(rule.conditions)
    return _Grid(classes, valid)
