"""The exact minimum cover behind partitions with overlapping components.

When a value belongs to several components, a robot can use several configurations, and the
fewest configurations serving every robot is a minimum hitting set. A configuration is a *key*,
one component per characteristic (:mod:`solver.core.partition`), and a robot can use it when
each of its values is in that component. An *element* is what one class of robots can use: per
characteristic, the components its value belongs to (its *options*), and the element is their
product. Choose the fewest keys so that every element contains at least one. Below, tau(F) is
that fewest number for a family F of elements and nu(F) its *packing*: the most elements of F no
two of which share a key (always nu <= tau: each of them needs a key of its own).

Solved in steps, each exact:

* **Factors.** Characteristics that vary independently of each other (no rule constraint links
  them) make the family of elements a product: the elements over characteristics A and B are
  every element over A beside every element over B. The family is split into its finest such
  factors (:func:`factors`; unique, and found from the elements alone, so all engines agree).
* **A cover per factor.** Each factor's hitting set is a small integer program solved by HiGHS
  (``highspy``), a maintained MIP solver that proves its answers optimal: one binary variable per
  key, minimise their sum, one ``>= 1`` row per element.
* **Their product, where it is exact.** tau(F x G) is not tau(F) tau(G) in general: three values
  each in two of three components (a *ring*: {X, Z}, {X, Y}, {Y, Z}) need two components, but
  two such characteristics need three configurations, not four (the diagonal (X, X), (Y, Y),
  (Z, Z) serves all nine pairs), and three of them five, not eight. It is exact when one side
  packs: if nu(F) = tau(F), then tau(F x G) = tau(F) tau(G). *Proof*: a product of covers is a
  cover, so <=. Take nu(F) elements e_1, e_2, ... of F that share no key; a cover S must hit
  e_i x g for every g in G, so the keys of S inside e_i x (all keys of G) project onto a cover
  of G: at least tau(G) of them; the sets e_i x (keys of G) are disjoint, so |S| >=
  nu(F) tau(G). Components that are runs of a line (sliding windows) always pack. So factors
  whose covers pack multiply, and only the factors that do not (at least two, each needing more
  than one key) are covered together.
* **Apart pieces of the factors covered together.** Such a factor is often made of *pieces*:
  sets of its elements that share no key with the rest (rings of components over separate
  blocks of values, say). If F is the disjoint union of pieces F_1 and F_2 (no key in both),
  every element of F x G lies in F_1 x G or in F_2 x G, whose keys are disjoint: the keys a
  cover of F x G has among those of F_1 x G cover F_1 x G, the others F_2 x G, and the union of
  a cover of each covers F x G, so tau(F x G) = tau(F_1 x G) + tau(F_2 x G). Over several
  factors, the minimum cover is the union, over each choice of one piece per factor, of that
  choice's minimum cover. A choice is a product again,
  so the rule above applies to it: its pieces that pack multiply, and only the pieces that do not
  (at least two) are one integer program over their product. Pieces that are the same up to
  renaming their components in order (the same *shape*) have the same covers renamed, so each
  choice of shapes is solved once, and the count is a sum over choices of shapes, weighted by
  how many choices of pieces have those shapes: never a sum over every choice.

So 80 values in each of three characteristics, each value in two sliding components, are three
programs of 40 rows instead of one of 64,000, and the configurations are the product of three
choices of 20; and 640 values in rings of three over blocks of four, in three characteristics,
are a program of 27 rows for a choice of three rings, counted 160^3 times without listing them
(``benchmarks/bench_overlap.py``). A team whose factors covered together are pieces of a single
shape costs a program per shape; a team whose every piece has a shape of its own costs a
program per choice of pieces, and the budget below is its net.

Every cover, however many programs it takes, has one time budget, the ``cover-seconds`` limit
(:mod:`solver.deadline`): each program gets what is left of it as HiGHS's time limit, and the
work between programs looks at it, so a cover that cannot be proven in time is refused, located
at the rule set, never left running.

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

__all__ = ["Cover", "Group", "Options", "Pieces", "factors", "minimum_cover", "product_cover"]

Key = tuple[int, ...]
# An element: per position, the components allowed there (the element is their product).
Options = tuple[tuple[int, ...], ...]
# Positions (ascending) and a family of elements over exactly those positions.
Part = tuple[tuple[int, ...], Collection[Options]]
# A piece renamed: its elements with each position's components numbered 0, 1, ... in order.
Shape = tuple[Options, ...]
# Which factors (their indices) and shapes a joint program covered.
Programmed = tuple[tuple[int, ...], tuple[Shape, ...]]

# Steps of a loop between two looks at the deadline.
_STEPS = 4096


@dataclass(frozen=True, slots=True)
class Group:
    """Positions whose chosen keys are chosen together, and those keys (partial keys over the
    positions, ascending)."""

    positions: tuple[int, ...]
    keys: tuple[Key, ...]
    _first: dict[Options, Key | None] = field(default_factory=dict, compare=False, repr=False)

    @property
    def size(self) -> int:
        """How many keys."""
        return len(self.keys)

    def first(self, options: Options) -> Key | None:
        """The lowest chosen partial key the ``options`` (over :attr:`positions`) allow
        (``None``: none, the options of no element)."""
        if options not in self._first:
            self._first[options] = next(
                (key for key in self.keys if all(map(tuple.__contains__, options, key))), None
            )
        return self._first[options]


@dataclass(frozen=True, slots=True)
class Piece:
    """Elements of a factor that share no key with the rest of it: the components it uses at
    each position of the factor (ascending), its shape (those components numbered 0, 1, ...),
    a minimum cover of the shape, and whether it packs (see the module docstring)."""

    labels: tuple[tuple[int, ...], ...]
    shape: Shape
    cover: tuple[Key, ...]
    packs: bool

    def named(self, key: Key) -> Key:
        """A key of the shape with the piece's own components."""
        return tuple([labels[i] for labels, i in zip(self.labels, key, strict=True)])


@dataclass(frozen=True, slots=True)
class Split:
    """A factor covered with others, as its pieces: ``positions`` its own, ``where`` their
    indices in the :class:`Pieces` group's positions, ``home`` the piece of each of its keys."""

    positions: tuple[int, ...]
    where: tuple[int, ...]
    pieces: tuple[Piece, ...]
    home: dict[Key, int] = field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Pieces:
    """The factors whose covers do not multiply, covered together: the union, over each choice
    of one piece per factor, of that choice's minimum cover (see the module docstring), held
    without listing it. ``joint``: the cover of each choice of shapes that needs a program, over
    the positions of the factors whose pieces do not pack, in the shapes' own numbering, by
    those factors and shapes."""

    positions: tuple[int, ...]
    splits: tuple[Split, ...]
    size: int
    joint: dict[Programmed, tuple[Key, ...]] = field(compare=False, repr=False)
    _blocks: dict[tuple[int, ...], tuple[Key, ...]] = field(
        default_factory=dict, compare=False, repr=False
    )

    @property
    def keys(self) -> tuple[Key, ...]:
        """Every chosen key over :attr:`positions`, ascending (listed: as many as :attr:`size`)."""
        found = itertools.chain.from_iterable(
            map(self.block, itertools.product(*(range(len(s.pieces)) for s in self.splits)))
        )
        return tuple(sorted(found))

    def block(self, choice: tuple[int, ...]) -> tuple[Key, ...]:
        """The chosen keys of one choice of a piece per factor, ascending."""
        if choice in self._blocks:
            return self._blocks[choice]
        pieces = [split.pieces[i] for split, i in zip(self.splits, choice, strict=True)]
        alone = [n for n, piece in enumerate(pieces) if not piece.packs]
        together = alone if len(alone) > 1 else []
        # Units whose keys multiply: each factor taken alone, and those covered together.
        units: list[tuple[list[int], list[Key]]] = [
            (list(self.splits[n].where), [piece.named(key) for key in piece.cover])
            for n, piece in enumerate(pieces)
            if n not in together
        ]
        if together:
            where = [i for n in together for i in self.splits[n].where]
            order = sorted(range(len(where)), key=where.__getitem__)
            named = [pieces[n] for n in together]
            shapes = tuple(piece.shape for piece in named)
            found = self.joint[tuple(together), shapes]
            units.append((sorted(where), [_named_together(named, key, order) for key in found]))
        keys = []
        for parts in itertools.product(*(found for _, found in units)):
            key = [0] * len(self.positions)
            for (where, _), part in zip(units, parts, strict=True):
                for i, component in zip(where, part, strict=True):
                    key[i] = component
            keys.append(tuple(key))
        self._blocks[choice] = found = tuple(sorted(keys))
        return found

    def first(self, options: Options) -> Key | None:
        """The lowest chosen key over :attr:`positions` the ``options`` allow: one in the block
        of the element's pieces, the only block whose keys it can hold."""
        choice = []
        for split in self.splits:
            own = tuple([options[i] for i in split.where])
            piece = split.home.get(tuple([allowed[0] for allowed in own]))
            if piece is None:
                return None
            choice.append(piece)
        return next(
            (
                key
                for key in self.block(tuple(choice))
                if all(map(tuple.__contains__, options, key))
            ),
            None,
        )


def _named_together(pieces: Sequence[Piece], key: Key, order: Sequence[int]) -> Key:
    """A key of the joint program over pieces' shapes (positions ascending) in their own
    components: ``order`` gives, for each position ascending, its place in the pieces' positions
    one after the other."""
    labels = [labels for piece in pieces for labels in piece.labels]
    return tuple([labels[order[i]][component] for i, component in enumerate(key)])


@dataclass(frozen=True, slots=True)
class Cover:
    """A minimum cover: the product of its groups' chosen keys, each over its own positions."""

    width: int
    groups: tuple[Group | Pieces, ...]

    @property
    def size(self) -> int:
        """How many keys the cover holds."""
        if not self.groups:
            return 0
        return math.prod(group.size for group in self.groups)

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

    All the programs HiGHS solves for one cover share the ``cover-seconds`` limit: past it, a
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
    solver = _Solver(
        Deadline.start("cover-seconds", "the minimum cover of overlapping components", option=""),
        file,
    )
    found = sorted(
        (factor for positions, family in parts for factor in factors(positions, family)),
        key=lambda factor: factor[0],
    )
    measured = [solver.measure(family) for _, family in found]
    wide = [n for n, (size, _) in enumerate(measured) if size > 1]
    joint = [] if len(wide) < 2 else [n for n in wide if not measured[n][1].packs()]
    groups: list[Group | Pieces] = [
        Group(positions, tuple(sorted(measured[n][1].whole())))
        for n, (positions, _) in enumerate(found)
        if n not in joint
    ]
    if joint:
        # No product of the factors' covers is proven minimal here (rings, say: see the module
        # docstring): their pieces, each choice of one per factor covered apart.
        groups.append(solver.together([(found[n][0], measured[n][1]) for n in joint]))
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


@dataclass(frozen=True, slots=True)
class _Solver:
    """One cover's programs: its deadline, the rule set it is refused at, and what it solved
    once per shape (a piece's cover, whether it packs; a choice of shapes' joint cover)."""

    deadline: Deadline
    file: str
    covers: dict[Shape, tuple[Key, ...]] = field(default_factory=dict)
    packing: dict[Shape, bool] = field(default_factory=dict)

    def cover(self, family: Collection[Options]) -> frozenset[Key]:
        return _cover(family, self.deadline, self.file)

    def packs(self, family: Collection[Options], cover: Collection[Key]) -> bool:
        return _packs(family, len(cover), self.deadline, self.file)

    def look(self) -> None:
        self.deadline.check(Location(self.file))

    def measure(self, family: Collection[Options]) -> tuple[int, _Factor]:
        """A factor's fewest keys, found piece by piece (a shape once), and the factor."""
        if _runs(family):
            return len(whole := _stabbed(family)), _Factor(self, family, whole)
        parts, home = _pieces(family, self)
        if len(parts) == 1:  # the factor's own program, as when it is covered alone
            whole = self.cover(family)
            labels, shape = _shaped(parts[0])
            rank = [{c: i for i, c in enumerate(found)} for found in labels]
            cover = tuple(
                sorted(tuple([r[c] for r, c in zip(rank, key, strict=True)]) for key in whole)
            )
            self.covers.setdefault(shape, cover)
            found = [(labels, shape, cover)]
            return len(whole), _Factor(self, family, whole, found, home)
        found = []
        for elements in parts:
            labels, shape = _shaped(elements)
            if shape not in self.covers:
                self.covers[shape] = tuple(sorted(self.cover(shape)))
            found.append((labels, shape, self.covers[shape]))
        return sum(len(cover) for _, _, cover in found), _Factor(self, family, None, found, home)

    def together(self, joint: Sequence[tuple[tuple[int, ...], _Factor]]) -> Pieces:
        """The factors ``joint`` covered together, piece by piece (see :class:`Pieces`)."""
        positions = tuple(sorted(p for own, _ in joint for p in own))
        splits = tuple(
            Split(own, tuple(positions.index(p) for p in own), factor.pieces(), factor.home)
            for own, factor in joint
        )
        programs: dict[Programmed, tuple[Key, ...]] = {}
        size = 0
        for choice in itertools.product(*map(_classes, splits)):
            self.look()
            alone = [(n, shape) for n, (_, shape) in enumerate(choice) if shape is not None]
            weight = math.prod(w for w, _ in choice)
            if len(alone) > 1:
                size += weight * len(self.program(splits, alone, programs))
            elif alone:
                size += weight * len(self.covers[alone[0][1]])
            else:
                size += weight
        return Pieces(positions, splits, size, programs)

    def program(
        self,
        splits: Sequence[Split],
        alone: list[tuple[int, Shape]],
        programs: dict[Programmed, tuple[Key, ...]],
    ) -> tuple[Key, ...]:
        """The joint cover of pieces of these shapes over these factors' positions (once)."""
        which = (tuple(n for n, _ in alone), tuple(shape for _, shape in alone))
        if which not in programs:
            _, family = _joined(
                [(splits[n].positions, shape) for n, shape in alone], self.deadline, self.file
            )
            programs[which] = tuple(sorted(self.cover(family)))
        return programs[which]


class _Factor:
    """A factor measured piece by piece: its whole cover when it is kept as a group, whether it
    packs, its pieces when it is covered together with others."""

    __slots__ = ("_found", "_packs", "_whole", "family", "home", "solver")

    def __init__(
        self,
        solver: _Solver,
        family: Collection[Options],
        whole: frozenset[Key] | None,
        found: list[tuple[tuple[tuple[int, ...], ...], Shape, tuple[Key, ...]]] | None = None,
        home: dict[Key, int] | None = None,
    ) -> None:
        self.solver, self.family, self._whole = solver, family, whole
        self._found = found or []
        self.home = home or {}
        self._packs: list[bool] | None = None if found else [True]

    def whole(self) -> frozenset[Key]:
        """The factor's minimum cover, one program over all of it (as when it is alone)."""
        if self._whole is None:
            self._whole = self.solver.cover(self.family)
        return self._whole

    def packs(self) -> bool:
        """Whether the factor packs: every piece of it does (nu and tau add over pieces)."""
        return all(self._piece_packs())

    def _piece_packs(self) -> list[bool]:
        if self._packs is None:
            solver = self.solver
            if len(self._found) == 1:
                self._packs = [solver.packs(self.family, self.whole())]
            else:
                for _, shape, cover in self._found:
                    if shape not in solver.packing:
                        solver.packing[shape] = solver.packs(shape, cover)
                self._packs = [solver.packing[shape] for _, shape, _ in self._found]
        return self._packs

    def pieces(self) -> tuple[Piece, ...]:
        return tuple(
            Piece(labels, shape, cover, packs)
            for (labels, shape, cover), packs in zip(self._found, self._piece_packs(), strict=True)
        )


def _classes(split: Split) -> list[tuple[int, Shape | None]]:
    """A factor's pieces for counting: those that pack as one class weighing their keys
    together (a choice of one of them multiplies the rest by its cover), the others by shape,
    each weighing how many pieces have it."""
    found: list[tuple[int, Shape | None]] = []
    packed = sum(len(piece.cover) for piece in split.pieces if piece.packs)
    if packed:
        found.append((packed, None))
    shapes: dict[Shape, int] = {}
    for piece in split.pieces:
        if not piece.packs:
            shapes[piece.shape] = shapes.get(piece.shape, 0) + 1
    found.extend((count, shape) for shape, count in shapes.items())
    return found


def _pieces(
    family: Collection[Options], solver: _Solver
) -> tuple[list[list[Options]], dict[Key, int]]:
    """The family's pieces (elements joined by shared keys), each piece's elements, in the order
    of their lowest keys, and the piece of each key."""
    parent: dict[Key, Key] = {}

    def root(key: Key) -> Key:
        top = parent.setdefault(key, key)
        while top != parent[top]:
            parent[top] = top = parent[parent[top]]
        parent[key] = top
        return top

    for step, element in enumerate(family):
        if step % _STEPS == 0:
            solver.look()
        keys = itertools.product(*element)
        top = root(next(keys))
        for key in keys:
            other = root(key)
            if other != top:
                parent[other] = top
    grouped: dict[Key, list[Options]] = {}
    for element in family:
        grouped.setdefault(root(tuple([allowed[0] for allowed in element])), []).append(element)
    lowest = {
        top: min(tuple(map(min, element)) for element in found) for top, found in grouped.items()
    }
    order = sorted(grouped, key=lowest.__getitem__)
    number = {top: n for n, top in enumerate(order)}
    home = {key: number[root(key)] for key in list(parent)}
    return [grouped[top] for top in order], home


def _shaped(elements: Sequence[Options]) -> tuple[tuple[tuple[int, ...], ...], Shape]:
    """A piece's components at each position (ascending) and its shape: its elements with those
    components numbered 0, 1, ... in order (renaming in order keeps every order, so a program
    over the shape is the program over the piece)."""
    width = len(elements[0])
    labels = tuple(
        tuple(sorted({c for element in elements for c in element[i]})) for i in range(width)
    )
    rank = [{c: n for n, c in enumerate(found)} for found in labels]
    shape = tuple(
        sorted(
            tuple(tuple([r[c] for c in allowed]) for r, allowed in zip(rank, element, strict=True))
            for element in elements
        )
    )
    return labels, shape


def _joined(
    parts: Sequence[Part], deadline: Deadline, file: str
) -> tuple[tuple[int, ...], set[Options]]:
    """The product of families over disjoint positions, as one family over their union."""
    positions = tuple(sorted(p for part_positions, _ in parts for p in part_positions))
    where = {p: i for i, p in enumerate(positions)}
    family = set()
    choices = itertools.product(*(sorted(f) for _, f in parts))
    for step, choice in enumerate(choices):
        if step % _STEPS == 0:
            deadline.check(Location(file))
        options: list[tuple[int, ...]] = [()] * len(positions)
        for (part_positions, _), element in zip(parts, choice, strict=True):
            for p, allowed in zip(part_positions, element, strict=True):
                options[where[p]] = allowed
        family.add(tuple(options))
    return positions, family


def _reduced(family: Collection[Options], deadline: Deadline, file: str) -> list[frozenset[Key]]:
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
    for step, candidate in enumerate(sets):
        if step % _STEPS == 0:
            deadline.check(Location(file))
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


def _cover(family: Collection[Options], deadline: Deadline, file: str) -> frozenset[Key]:
    """A minimum hitting set of one family, proven by HiGHS where it is not forced."""
    if _runs(family):
        return _stabbed(family)
    reduced = _reduced(family, deadline, file)
    forced = {next(iter(e)) for e in reduced if len(e) == 1}
    open_elements = [e for e in reduced if forced.isdisjoint(e)]
    if not open_elements:
        return frozenset(forced)
    chosen = _program(open_elements, packing=False, deadline=deadline, file=file)
    return frozenset(forced | set(chosen))


def _packs(family: Collection[Options], size: int, deadline: Deadline, file: str) -> bool:
    """Whether ``family`` has as many pairwise disjoint elements as a minimum cover of ``size``
    keys."""
    if _runs(family):
        return True
    reduced = _reduced(family, deadline, file)
    # Greedy first, by the highest key each element holds (exact for runs of a line).
    taken: set[Key] = set()
    packed = 0
    for element in sorted(reduced, key=lambda e: (max(e), len(e), sorted(e))):
        if taken.isdisjoint(element):
            taken.update(element)
            packed += 1
    if packed >= size:
        return True
    return len(_program(reduced, packing=True, deadline=deadline, file=file)) >= size


def _program(
    elements: list[frozenset[Key]], *, packing: bool, deadline: Deadline, file: str
) -> list[Key]:
    """Solve one 0/1 program with HiGHS, proven optimal within what is left of the cover's
    ``cover-seconds`` budget.

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
    deadline.check(Location(file))
    solver = _quiet_highs()()
    # One thread: the same input gives the same answer on every machine and run.
    solver.setOptionValue("threads", 1)
    # Set covers are NP-hard: 300 values in 100 overlapping components took HiGHS minutes.
    solver.setOptionValue("time_limit", max(deadline.remaining(), 0.001))
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
