"""The exact minimum cover behind partitions with overlapping components.

When a value belongs to several components, a robot can use several configurations, and the
fewest configurations serving every robot is a minimum hitting set: choose keys (one component
per characteristic) so that every *element* contains at least one. An element is what one class
of robots can use: per characteristic, the components its value belongs to (its *options*), and
the element is their product.

Solved in three steps, each exact:

* **Factors.** Characteristics that vary independently of each other (no rule constraint links
  them) make the family of elements a product: the elements over characteristics A and B are
  every element over A beside every element over B. The family is split into its finest such
  factors (:func:`factors`; unique, and found from the elements alone, so all engines agree).
* **A cover per factor.** Each factor's hitting set is a small integer program solved by HiGHS
  (``highspy``), a maintained MIP solver that proves its answers optimal: one binary variable per
  key, minimise their sum, one ``>= 1`` row per element.
* **Their product.** A factor whose minimum cover is as large as its largest set of pairwise
  disjoint elements (a *packing*; so for components that are runs of a line, such as sliding
  windows) multiplies: no cover of the product can be smaller than the product of the packings,
  each packed element needing its own cover of the rest. Factors without that property are
  solved jointly, as one integer program over their product.

So 80 values in each of three characteristics, each value in two sliding components, are three
programs of 40 rows instead of one of 64,000, and the configurations are the product of three
choices of 20.

>>> cover = minimum_cover([((0, 1),), ((1, 2),)])
>>> cover.chosen()
[(1,)]
>>> cover.first(((0, 1),))
(1,)

Not here: which robots go to which chosen configuration
(:func:`solver.core.partition.partition_classes`).
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass, field

from solver.deadline import Deadline
from solver.errors import Location, StructureTooComplex

__all__ = ["Cover", "Group", "Options", "factors", "minimum_cover", "product_cover"]

Key = tuple[int, ...]
# An element: per position, the components allowed there (the element is their product).
Options = tuple[tuple[int, ...], ...]
# Positions (ascending) and a family of elements over exactly those positions.
Part = tuple[tuple[int, ...], Collection[Options]]


@dataclass(frozen=True, slots=True)
class Group:
    """Positions whose chosen keys are chosen together, and those keys (partial keys over the
    positions, ascending)."""

    positions: tuple[int, ...]
    keys: tuple[Key, ...]
    _first: dict[Options, Key | None] = field(default_factory=dict, compare=False, repr=False)

    def first(self, options: Options) -> Key | None:
        """The lowest chosen partial key the ``options`` (over :attr:`positions`) allow
        (``None``: none, the options of no element)."""
        if options not in self._first:
            self._first[options] = next(
                (key for key in self.keys if all(map(tuple.__contains__, options, key))), None
            )
        return self._first[options]


@dataclass(frozen=True, slots=True)
class Cover:
    """A minimum cover: the product of its groups' chosen keys, each over its own positions."""

    width: int
    groups: tuple[Group, ...]

    @property
    def size(self) -> int:
        """How many keys the cover holds."""
        if not self.groups:
            return 0
        return math.prod(len(group.keys) for group in self.groups)

    def chosen(self) -> list[Key]:
        """Every chosen key, ascending."""
        if not self.groups:
            return []
        found = []
        for parts in itertools.product(*(group.keys for group in self.groups)):
            key = [0] * self.width
            for group, part in zip(self.groups, parts, strict=True):
                for position, component in zip(group.positions, part, strict=True):
                    key[position] = component
            found.append(tuple(key))
        return sorted(found)

    def first(self, options: Options) -> Key:
        """The lowest chosen key (lexicographically) that an element's ``options`` allow.

        The chosen keys are a product over groups and the element a product over positions,
        so the lowest key is each group's lowest part.
        """
        key = [0] * self.width
        for group in self.groups:
            part = group.first(tuple(options[p] for p in group.positions))
            if part is None:
                raise ValueError(f"{options} is not covered")
            for position, component in zip(group.positions, part, strict=True):
                key[position] = component
        return tuple(key)


def minimum_cover(elements: Iterable[Options], *, file: str = "<cover>") -> Cover:
    """The fewest keys such that every element allows at least one, proven minimal.

    Each program HiGHS solves has the ``cover-seconds`` limit as its time limit: past it, a
    :class:`~solver.errors.TimeLimitError` at ``file`` (the rule set whose components
    overlap); :class:`~solver.errors.StructureTooComplex` if HiGHS ends without a proven
    optimum for any other reason (the solver itself failed).
    """
    family = set(elements)
    width = len(next(iter(family))) if family else 0
    return product_cover(width, [(tuple(range(width)), family)], file=file)


def product_cover(width: int, parts: Sequence[Part], *, file: str = "<cover>") -> Cover:
    """:func:`minimum_cover` of the product of ``parts`` (disjoint positions, together
    ``0 .. width - 1``), without building the product: the same cover as for the product's
    elements listed one by one."""
    if any(not family for _, family in parts):
        return Cover(width, ())
    found = sorted(
        (factor for positions, family in parts for factor in factors(positions, family)),
        key=lambda factor: factor[0],
    )
    solved = [(positions, family, _cover(family, file)) for positions, family in found]
    wide = [entry for entry in solved if len(entry[2]) > 1]
    joint = (
        [] if len(wide) < 2 else [entry for entry in wide if not _packs(entry[1], entry[2], file)]
    )
    groups = [
        Group(positions, tuple(sorted(keys)))
        for positions, family, keys in solved
        if not any(positions == other[0] for other in joint)
    ]
    if joint:
        # No product of the separate covers is proven minimal here: one program over the
        # product of these factors (rare: components that overlap in a cycle, say).
        positions, family = _joined([(entry[0], entry[1]) for entry in joint])
        groups.append(Group(positions, tuple(sorted(_cover(family, file)))))
        groups.sort(key=lambda group: group.positions)
    return Cover(width, tuple(groups))


def factors(positions: tuple[int, ...], family: Collection[Options]) -> list[Part]:
    """The finest split of ``family`` (elements over ``positions``, non-empty) into a product of
    families over disjoint positions.

    Positions are added one at a time; a factor found so far stays apart from the new position
    exactly when the elements seen so far are the product of its projection and the rest's
    (prime factors of a product are unique, so the order of discovery does not matter).
    """
    width = len(positions)
    projections = [_projected(family, [i]) for i in range(width)]
    if math.prod(len(p) for p in projections) == len(family):
        return [((p,), found) for p, found in zip(positions, projections, strict=True)]
    groups: list[list[int]] = []
    for t in range(width):
        prefix = _projected(family, list(range(t + 1)))
        kept = [group for group in groups if _separable(prefix, group)]
        merged = sorted({t}.union(*(group for group in groups if group not in kept)))
        groups = [*kept, merged]
    return [
        (tuple(positions[i] for i in group), _projected(family, group)) for group in sorted(groups)
    ]


def _projected(family: Collection[Options], where: list[int]) -> set[Options]:
    return {tuple([element[i] for i in where]) for element in family}


def _separable(family: Collection[Options], group: list[int]) -> bool:
    """Whether ``family`` is the product of its projection on ``group`` and on the rest."""
    rest = [i for i in range(len(next(iter(family)))) if i not in group]
    return len(_projected(family, group)) * len(_projected(family, rest)) == len(family)


def _joined(parts: Sequence[Part]) -> Part:
    """The product of families over disjoint positions, as one family over their union."""
    positions = tuple(sorted(p for part_positions, _ in parts for p in part_positions))
    where = {p: i for i, p in enumerate(positions)}
    family = set()
    for choice in itertools.product(*(sorted(f) for _, f in parts)):
        options: list[tuple[int, ...]] = [()] * len(positions)
        for (part_positions, _), element in zip(parts, choice, strict=True):
            for p, allowed in zip(part_positions, element, strict=True):
                options[where[p]] = allowed
        family.add(tuple(options))
    return positions, family


def _reduced(family: Collection[Options]) -> list[frozenset[Key]]:
    """The elements as sets of keys, without any that contains another (it is hit whenever the
    smaller one is), smallest first, in a fixed order."""
    sets = sorted(
        {frozenset(itertools.product(*element)) for element in family},
        key=lambda s: (len(s), sorted(s)),
    )
    kept: list[frozenset[Key]] = []
    # Each kept set is filed under one of its keys; a later (no smaller) set contains a kept
    # one only if it holds that key, so only the sets filed under its own keys are compared.
    filed: dict[Key, list[frozenset[Key]]] = {}
    for candidate in sets:
        if any(other <= candidate for key in candidate for other in filed.get(key, ())):
            continue
        kept.append(candidate)
        filed.setdefault(min(candidate), []).append(candidate)
    return kept


def _runs(family: Collection[Options]) -> bool:
    """Whether every element is a run of consecutive components of one characteristic."""
    return all(
        len(element) == 1 and element[0][-1] - element[0][0] == len(element[0]) - 1
        for element in family
    )


def _stabbed(family: Collection[Options]) -> frozenset[Key]:
    """The minimum cover of runs on a line: by the run that ends first, its last component.

    Exact: the runs that took a component share none, so no cover has fewer; and as many
    disjoint runs as keys means the family packs (see :func:`_packs`).
    """
    chosen: list[int] = []
    for (run,) in sorted(family, key=lambda element: (element[0][-1], element[0][0])):
        if not chosen or chosen[-1] < run[0]:
            chosen.append(run[-1])
    return frozenset((component,) for component in chosen)


def _cover(family: Collection[Options], file: str) -> frozenset[Key]:
    """A minimum hitting set of one family, proven by HiGHS where it is not forced."""
    if _runs(family):
        return _stabbed(family)
    reduced = _reduced(family)
    forced = {next(iter(e)) for e in reduced if len(e) == 1}
    open_elements = [e for e in reduced if forced.isdisjoint(e)]
    if not open_elements:
        return frozenset(forced)
    chosen = _program(open_elements, packing=False, file=file)
    return frozenset(forced | set(chosen))


def _packs(family: Collection[Options], cover: frozenset[Key], file: str) -> bool:
    """Whether ``family`` has as many pairwise disjoint elements as ``cover`` has keys."""
    if _runs(family):
        return True
    reduced = _reduced(family)
    # Greedy first, by the highest key each element holds (exact for runs of a line).
    taken: set[Key] = set()
    packed = 0
    for element in sorted(reduced, key=lambda e: (max(e), len(e), sorted(e))):
        if taken.isdisjoint(element):
            taken.update(element)
            packed += 1
    if packed >= len(cover):
        return True
    return len(_program(reduced, packing=True, file=file)) >= len(cover)


def _program(elements: list[frozenset[Key]], *, packing: bool, file: str) -> list[Key]:
    """Solve one 0/1 program with HiGHS, proven optimal within the ``cover-seconds`` limit.

    Cover: a variable per key, the fewest keys with every element hit. Packing: a variable per
    element, the most elements with no key in two. Returns the keys chosen (cover) or one key
    of each element chosen (packing: only their number matters).
    """
    import highspy  # loaded only for rule sets with overlapping components
    import numpy as np

    keys = sorted(set().union(*elements))
    column = {key: i for i, key in enumerate(keys)}
    rows = [sorted(column[key] for key in element) for element in elements]
    if packing:  # one row per key, over the elements holding it
        by_key: list[list[int]] = [[] for _ in keys]
        for number, row in enumerate(rows):
            for i in row:
                by_key[i].append(number)
        rows, columns = by_key, len(elements)
        lower, upper = np.full(len(rows), -highspy.kHighsInf), np.ones(len(rows))
    else:
        columns = len(keys)
        lower, upper = np.ones(len(rows)), np.full(len(rows), highspy.kHighsInf)
    starts = [0, *itertools.accumulate(len(row) for row in rows)]
    deadline = Deadline.start(
        "cover-seconds", "the minimum cover of overlapping components", option=""
    )
    solver = _quiet_highs()()
    # One thread: the same input gives the same answer on every machine and run.
    solver.setOptionValue("threads", 1)
    # Set covers are NP-hard: 300 values in 100 overlapping components took HiGHS minutes.
    solver.setOptionValue("time_limit", deadline.seconds)
    model = highspy.HighsLp()
    model.num_col_ = columns
    model.num_row_ = len(rows)
    model.col_cost_ = np.full(columns, -1.0 if packing else 1.0)
    model.col_lower_ = np.zeros(columns)
    model.col_upper_ = np.ones(columns)
    model.row_lower_ = lower
    model.row_upper_ = upper
    model.a_matrix_.format_ = highspy.MatrixFormat.kRowwise
    model.a_matrix_.start_ = np.array(starts, dtype=np.int32)
    model.a_matrix_.index_ = np.array([i for row in rows for i in row], dtype=np.int32)
    model.a_matrix_.value_ = np.ones(starts[-1])
    model.integrality_ = [highspy.HighsVarType.kInteger] * columns
    solver.passModel(model)
    solver.run()
    status = solver.getModelStatus()
    if status == highspy.HighsModelStatus.kTimeLimit:
        raise deadline.error(Location(file))
    if status != highspy.HighsModelStatus.kOptimal:
        raise StructureTooComplex.at(
            "<cover>",
            "the minimum cover of overlapping components "
            "was not proven: "
            f"{solver.modelStatusToString(status)}",
        )
    values = solver.getSolution().col_value
    if packing:
        return [min(elements[i]) for i, value in enumerate(values) if value > 0.5]
    return [key for key, value in zip(keys, values, strict=True) if value > 0.5]


@functools.cache
def _quiet_highs() -> type:
    import highspy

    class Quiet(highspy.Highs):
        """HiGHS without its banner: ``Highs()`` prints one on standard output (the file
        descriptor, past ``sys.stdout``) as it sets its callbacks up, unless output is off
        first; it would land in the middle of ``--format json``."""

        def enableCallbacks(self) -> None:  # HiGHS's own name
            self.setOptionValue("output_flag", False)
            super().enableCallbacks()  # type: ignore[no-untyped-call]  # no hints in highspy

    return Quiet
