"""The questions the semantic checks ask about a rule set, kept small so they stay fast.

Every answer comes from one notion of "valid robot" (the constraints of
:mod:`solver.core.constraints`, as boxes of :mod:`solver.core.regions`), asked of a SAT solver
(:mod:`solver.core.oracle`); what this module adds is *which* questions to ask:

* **Restricted domains.** "Can sensor type X appear for a UGV?" is the question over the UGV's
  domains with the sensor type narrowed to ``{X}``; existence, never an enumeration of robots.
* **One kinematic type at a time.** A question about one type goes to that type's oracle,
  which holds only the constraints that can exclude robots of it; types the constraints
  cannot tell apart share one.
* **Relevant constraints only.** A rule none of whose exclusion boxes meets the domains holds
  for every robot there, so explanations never name it and never try it.
* **Witnesses.** One model proves every class it marks possible, so :meth:`Analysis.live`
  needs about one question per class no model has shown yet, plus one "no" per
  characteristic.

Explanations are minimal subsets (:meth:`Analysis.minimal_conflict`): the subset that deleting
constraints in declared order keeps (drop one, re-solve, keep it dropped while the rest still
has no solution), asking only about the constraints of the solver's last core
(:func:`deletion`): a few questions for a conflict of a few constraints among thousands.

Not here: deciding what is a finding (the check modules) or enumerating robots for solving
(:mod:`solver.core.model`, :mod:`solver.solving.solution`).
"""

from __future__ import annotations

from bisect import bisect_left
from collections import OrderedDict
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from functools import cached_property

from solver.core.constraints import RuleConstraint, Value
from solver.core.model import Robot
from solver.core.oracle import Budget, Oracle, SharedClasses
from solver.core.regions import Domains, Sparse, narrowed_positions, sparse_regions
from solver.core.ruleset import RuleSet
from solver.deadline import Deadline

__all__ = ["Analysis", "Classes", "deletion"]

# A domain split into classes of interchangeable values (domain order).
Classes = tuple[tuple[Value, ...], ...]
# A type oracle's constraints, and which of their boxes hold its kinematic types.
_Signature = tuple[tuple[int, ...], tuple[bool, ...]]

# The variables of the type oracles kept at once (some 400 bytes each, with their clauses);
# past it, the oracle used least recently is dropped, and built again if a question needs it.
# Each holds the constraints about any type: 1,000 types with a constraint of their own beside
# 1,000 such constraints over 1,000 characteristics held 1,000 oracles, 2.8 GB.
VARIABLES_KEPT = 500_000


class Analysis:
    """Questions about one rule set; answers that several checks share are computed once.

    Constraints are named by their index in ``rules.constraints`` (two identical constraints
    are still two constraints). With a ``deadline`` (:mod:`solver.deadline`), every question
    looks at it first, and :meth:`check_time` lets a caller's loops do the same: past it, a
    :class:`~solver.errors.TimeLimitError` located at the rule set.
    """

    def __init__(self, rules: RuleSet, *, deadline: Deadline | None = None) -> None:
        self.rules = rules
        # Each constraint's boxes (:mod:`solver.core.regions`) as the (position, set) pairs of
        # the characteristics they restrict: a box about two of 1,000 characteristics is two.
        self._sparse = tuple(sparse_regions(rules, rule) for rule in rules.constraints)
        # The kinematic types each constraint can exclude robots of (None: any); most
        # constraints are about a few types, so this cheap pre-filter spares most box tests.
        key = rules.key_position
        self._key_sets = tuple(tuple(dict(box).get(key) for box in boxes) for boxes in self._sparse)
        self._types = tuple(_types(sets) for sets in self._key_sets)
        # The same, inverted: the constraints about each type, and those about any type, so
        # that a question about one type looks at its few constraints, not at all of them.
        self._untyped = frozenset(i for i, types in enumerate(self._types) if types is None)
        self._by_type = _inverted(self._types)
        positions = {name: i for i, name in enumerate(rules.names)}
        # For each constraint: per characteristic position, the value sets its conditions test.
        self._tested: tuple[dict[int, tuple[frozenset[Value], ...]], ...] = tuple(
            _tested_sets(rule, positions) for rule in rules.constraints
        )
        # The constraints about each characteristic, and those that exclude any robot at all.
        self._about = _about(self._sparse, len(rules.characteristics))
        self._excluding = frozenset(
            i
            for i, boxes in enumerate(self._sparse)
            if any(all(s for _, s in box) for box in boxes)
        )
        self._budget = Budget(rules, deadline)
        # One oracle for questions over several types, one per class of types otherwise (the
        # ones used last, VARIABLES_KEPT in all; a kinematic type's signature names its own).
        self._whole_oracle: Oracle | None = None
        self._oracles: OrderedDict[_Signature, Oracle] = OrderedDict()
        self._kept_variables = 0
        self._signatures: dict[Value, _Signature] = {}
        self._interned: dict[_Signature, _Signature] = {}
        self._made: SharedClasses = {}

    def check_time(self) -> None:
        """:class:`~solver.errors.TimeLimitError` once the deadline (if any) has passed."""
        self._budget.check_time()

    # -- domains -------------------------------------------------------------------------------

    @cached_property
    def full(self) -> Domains:
        """Every value of every characteristic: the rule set alone."""
        return tuple(c.values for c in self.rules.characteristics)

    def type_domains(self, kinematic_type: Value) -> Domains:
        """The rule set's domains with the team key fixed to ``kinematic_type``."""
        position = self.rules.key_position
        return tuple(
            (kinematic_type,) if i == position else domain for i, domain in enumerate(self.full)
        )

    def narrowed(self, domains: Domains, position: int, values: Iterable[Value]) -> Domains:
        """``domains`` with characteristic ``position`` narrowed to ``values``."""
        allowed = frozenset(values)
        found = list(domains)
        found[position] = tuple(v for v in domains[position] if v in allowed)
        return tuple(found)

    # -- the small questions -------------------------------------------------------------------

    def relevant(self, domains: Domains, among: Iterable[int] | None = None) -> tuple[int, ...]:
        """The constraints (of ``among``, default all) that exclude some robot over ``domains``."""
        sets = self._narrowed(domains)
        key = self.rules.key_position
        if key in sets:
            # A few types: only the constraints about them, or about any type, can.
            pool = self._untyped.union(*(self._by_type.get(t, ()) for t in sets[key]))
            chosen = frozenset(i for i in pool if _touches(self._sparse[i], sets))
        else:
            # Only the constraints about a narrowed characteristic need a look at their boxes;
            # any other one excludes some robot here exactly when it excludes any at all.
            about = frozenset().union(*(self._about[p] for p in sets))
            chosen = (self._excluding - about).union(
                i for i in about if _touches(self._sparse[i], sets)
            )
        if among is None:
            return tuple(sorted(chosen))
        return tuple(i for i in among if i in chosen)

    def _narrowed(self, domains: Domains) -> dict[int, frozenset[Value]]:
        """The domains that are not whole, as sets by position (no set of 100,000 counts is
        built for a question that leaves them all). Whole domains are mostly the
        characteristic's own tuple, passed over quickly."""
        return {p: frozenset(domains[p]) for p in narrowed_positions(domains, self.full)}

    def classes(
        self, values: Sequence[Value], constraints: Sequence[int], position: int
    ) -> Classes:
        """``values`` of the characteristic at ``position`` split into classes that
        ``constraints`` cannot tell apart, in the order of their first values.

        Only the values asked about, and only the constraints about that characteristic: a
        question per kinematic type and characteristic split all 1,000 characteristics by all
        2,000 constraints (two minutes for 1,000 types), and then a range of 100,000 counts
        for the one value that mattered.
        """
        members = frozenset(values)
        # Each value's signature lists the tested sets holding it. Walking only each set's
        # values among ``values`` (set intersection walks the smaller side) costs the size of
        # the rules, not values x conditions; a set holding all or none splits nothing.
        signature: dict[Value, list[int]] = {}
        about = self._about[position]
        distinct = dict.fromkeys(
            s for i in constraints if i in about for s in self._tested[i].get(position, ())
        )
        for k, tested in enumerate(distinct):
            hits = tested & members
            if 0 < len(hits) < len(members):
                for value in hits:
                    signature.setdefault(value, []).append(k)
        groups: dict[tuple[int, ...], list[Value]] = {}
        for value in values:
            groups.setdefault(tuple(signature.get(value, ())), []).append(value)
        return tuple(tuple(group) for group in groups.values())

    def _oracle(self, domains: Domains) -> Oracle:
        """The oracle for a question: its type's when the key is one value, else the whole
        rule set's."""
        key = self.rules.key_position
        if len(domains[key]) != 1:
            if self._whole_oracle is None:
                self._whole_oracle = Oracle(
                    self.rules,
                    self._sparse,
                    range(len(self._sparse)),
                    None,
                    self._budget,
                    made=self._made,
                )
            return self._whole_oracle
        kinematic_type = domains[key][0]
        signature = self._signatures.get(kinematic_type)
        if signature is None:
            signature = self._signatures[kinematic_type] = self._signature(kinematic_type)
        oracle = self._oracles.get(signature)
        if oracle is not None:
            self._oracles.move_to_end(signature)
            return oracle
        oracle = self._oracles[signature] = Oracle(
            self.rules, self._sparse, signature[0], kinematic_type, self._budget, made=self._made
        )
        self._kept_variables += oracle.variables
        while self._kept_variables > VARIABLES_KEPT and len(self._oracles) > 1:
            self._kept_variables -= self._oracles.popitem(last=False)[1].variables
        return oracle

    def _signature(self, kinematic_type: Value) -> tuple[tuple[int, ...], tuple[bool, ...]]:
        """What a type's oracle holds: the constraints about it (or any type), and which of
        their boxes hold it. Types of one signature are the same question and share it."""
        included = tuple(sorted(self._untyped.union(self._by_type.get(kinematic_type, ()))))
        signature = (
            included,
            tuple(_holds(found, kinematic_type) for i in included for found in self._key_sets[i]),
        )
        return self._interned.setdefault(signature, signature)

    def witness(self, domains: Domains, among: Iterable[int] | None = None) -> Robot | None:
        """A valid robot over ``domains`` under the constraints ``among`` (default: all)."""
        oracle = self._oracle(domains)
        found = oracle.model(domains, among)
        if found is None:
            return None
        robot = []
        for p, domain in enumerate(domains):
            if p not in oracle.positions:
                robot.append(domain[0])
                continue
            at = oracle.positions[p]
            marked = set(found[p])
            robot.append(next(v for v in domain if at.of(v) in marked))
        return tuple(robot)

    def satisfiable(self, domains: Domains, among: Iterable[int] | None = None) -> bool:
        """Whether some robot over ``domains`` satisfies the constraints ``among``."""
        return self._oracle(domains).satisfiable(domains, among)

    def live(self, domains: Domains) -> tuple[frozenset[Value], ...]:
        """Per characteristic, the values that appear in at least one valid robot over domains.

        All sets are empty when there is no valid robot at all.
        """
        self.check_time()
        oracle = self._oracle(domains)
        found = oracle.live(domains)
        if found is None:
            return tuple(frozenset() for _ in domains)
        return tuple(
            oracle.values(p, found[p], domain) if p in found else self._whole(p, domain)
            for p, domain in enumerate(domains)
        )

    def _whole(self, position: int, domain: Sequence[Value]) -> frozenset[Value]:
        """``domain`` as a set; the whole domain's set made once, however often it is asked."""
        if len(domain) != len(self.rules.characteristics[position].values):
            return frozenset(domain)
        return self._wholes[position]

    @cached_property
    def _wholes(self) -> tuple[frozenset[Value], ...]:
        return tuple(frozenset(c.values) for c in self.rules.characteristics)

    def minimal_conflict(
        self, domains: Domains, among: Iterable[int] | None = None
    ) -> tuple[int, ...]:
        """A minimal subset of the constraints ``among`` that leaves no robot over ``domains``.

        The subset deleting in declared order keeps (drop each constraint, re-solve, keep it
        dropped while the rest still has no solution): :func:`deletion`. ``ValueError`` if the
        constraints have a solution.
        """
        oracle = self._oracle(domains)
        relevant = self.relevant(domains, among)
        if among is not None:
            relevant = tuple(sorted(relevant))
        return deletion(relevant, lambda subset: oracle.core(domains, subset))

    def exclusions(self, index: int, domains: Domains | None = None) -> tuple[Domains, ...]:
        """The non-empty boxes of robots over ``domains`` (default all) that constraint excludes."""
        base = self.full if domains is None else domains
        boxes = (self._intersect(base, box) for box in self._sparse[index])
        return tuple(box for box in boxes if all(box))

    def _intersect(self, domains: Domains, box: Sparse) -> Domains:
        """``domains`` narrowed to ``box``: only the characteristics the box restricts, and a
        whole domain in the time of the box's own set (a box about one of 2,000 types does not
        walk the 2,000, nor one about two of 1,000 characteristics the 1,000)."""
        found = list(domains)
        for p, allowed in box:
            characteristic, domain = self.rules.characteristics[p], domains[p]
            if len(domain) == len(characteristic.values):
                found[p] = tuple(sorted(allowed, key=characteristic.positions.__getitem__))
            else:
                found[p] = tuple(v for v in domain if v in allowed)
        return tuple(found)

    def entailing(self, index: int) -> tuple[int, ...] | None:
        """A minimal set of the other constraints that already excludes all ``index`` excludes.

        ``None`` when ``index`` excludes some robot that every other constraint allows (it is
        not redundant); ``()`` when it excludes nothing at all (a tautology).
        """
        boxes = self.exclusions(index)

        def entails(subset: Collection[int]) -> frozenset[int] | None:
            """None when the constraints ``subset`` leave a robot ``index`` excludes, else a
            part of them that already leaves none in any of its boxes."""
            found: set[int] = set()
            for box in boxes:
                part = self._oracle(box).core(box, subset)
                if part is None:
                    return None
                found |= part
            return frozenset(found)

        if not boxes:
            return ()
        alone = {index}
        if any(self._oracle(box).satisfiable(box, without=alone) for box in boxes):
            return None  # the others leave some robot it excludes
        touched = set().union(*(self.relevant(box) for box in boxes)) - alone
        return deletion(sorted(touched), entails)

    # -- shared answers ------------------------------------------------------------------------

    @cached_property
    def type_live(self) -> dict[Value, tuple[frozenset[Value], ...]]:
        """For each kinematic type, the values its valid robots can have (empty: void)."""
        return {kt: self.live(self.type_domains(kt)) for kt in self.rules.key.values}

    @cached_property
    def void_types(self) -> tuple[Value, ...]:
        """Kinematic types with no valid robot under the rule set's constraints."""
        position = self.rules.key_position
        return tuple(kt for kt, live in self.type_live.items() if not live[position])

    @property
    def is_void(self) -> bool:
        """No valid robot at all."""
        return len(self.void_types) == len(self.rules.key.values)

    @cached_property
    def live_anywhere(self) -> tuple[frozenset[Value], ...]:
        """Per characteristic, the values some valid robot of some kinematic type has.

        Each distinct set is added once, and none once all values are in: 20,000 types that
        can each have all of 100,000 counts cost one set, not 20,000 unions of 100,000.
        """
        sets: list[set[Value]] = [set() for _ in self.rules.characteristics]
        added: list[set[int]] = [set() for _ in self.rules.characteristics]
        sizes = [len(c.values) for c in self.rules.characteristics]
        for live in self.type_live.values():
            self.check_time()
            for position, values in enumerate(live):
                if len(sets[position]) < sizes[position] and id(values) not in added[position]:
                    added[position].add(id(values))
                    sets[position] |= values
        return tuple(frozenset(s) for s in sets)

    @cached_property
    def entailments(self) -> tuple[tuple[int, ...] | None, ...]:
        """:meth:`entailing` for every constraint, in declared order."""
        return tuple(self.entailing(index) for index in range(len(self._sparse)))

    @cached_property
    def void_conflict(self) -> tuple[int, ...]:
        """A minimal set of constraints leaving no valid robot at all (empty: not void)."""
        return self.minimal_conflict(self.full) if self.is_void else ()

    @cached_property
    def type_conflicts(self) -> dict[Value, tuple[int, ...]]:
        """For each void kinematic type, a minimal set of constraints that voids it."""
        return {kt: self.minimal_conflict(self.type_domains(kt)) for kt in self.void_types}


def deletion(
    constraints: Sequence[int], core: Callable[[Collection[int]], Collection[int] | None]
) -> tuple[int, ...]:
    """The minimal subset of ``constraints`` (indices in increasing, declared, order) that
    deletion in declared order keeps: drop each constraint in turn, keep it dropped while the
    rest still conflicts.

    ``core(subset)`` is ``None`` when ``subset`` does not conflict, else some part of it that
    conflicts already (conflicting is monotone: a superset of a conflict conflicts). Then a
    constraint outside the last core found needs no question: the rest still holds that core.
    So the questions follow the size of the conflicts, not of ``constraints`` (a dead value
    among 1,000 chained constraints is a handful of questions), and the result is deletion's
    whichever cores the solver finds. ``ValueError`` when ``constraints`` do not conflict.
    Each subset is a view (:class:`_Rest`), so a question asked locally does not cost the
    length of ``constraints``.
    """
    known = core(_Rest(constraints, [], -1))
    if known is None:
        raise ValueError("the constraints have a solution: nothing conflicts")
    kept: list[int] = []  # decided: kept; the ones after the current one are all still in
    position = -1
    pending = _later(constraints, position, known)
    while pending:
        # The next constraint of the known core: the ones before it are dropped, since the
        # rest still holds that core.
        position = pending.pop()
        found = core(_Rest(constraints, kept, position))
        if found is None:
            kept.append(constraints[position])
        else:
            pending = _later(constraints, position, found)
    return tuple(kept)


def _later(constraints: Sequence[int], position: int, core: Collection[int]) -> list[int]:
    """Where the members of ``core`` after ``position`` stand in ``constraints``, last first."""
    found = (_after(constraints, position, index) for index in core)
    return sorted((at for at in found if at >= 0), reverse=True)


class _Rest(Collection[int]):
    """The constraints ``kept`` and those after ``position`` in ``constraints`` (increasing
    indices, so a constraint is found by bisection: no view costs their number)."""

    def __init__(self, constraints: Sequence[int], kept: list[int], position: int) -> None:
        self.constraints = constraints
        self.kept = kept
        self.position = position

    def __contains__(self, index: object) -> bool:
        if index in self.kept:
            return True
        return isinstance(index, int) and _after(self.constraints, self.position, index) >= 0

    def __iter__(self) -> Iterator[int]:
        yield from self.kept
        yield from self.constraints[self.position + 1 :]

    def __len__(self) -> int:
        return len(self.kept) + len(self.constraints) - self.position - 1


def _after(constraints: Sequence[int], position: int, index: int) -> int:
    """Where ``index`` stands in ``constraints`` (increasing) if after ``position``, else -1."""
    at = bisect_left(constraints, index, position + 1)
    return at if at < len(constraints) and constraints[at] == index else -1


def _touches(
    boxes: Sequence[Sequence[tuple[int, frozenset[Value]]]], sets: dict[int, frozenset[Value]]
) -> bool:
    """Whether some robot over the domains ``sets`` (by position; any other domain is whole)
    lies in one of ``boxes``, each given as the (position, set) pairs it restricts."""
    return any(all(_meets(allowed, sets.get(p)) for p, allowed in box) for box in boxes)


def _types(key_sets: Sequence[frozenset[Value] | None]) -> frozenset[Value] | None:
    """The kinematic types a constraint's boxes can hold, from each box's key set (None:
    any)."""
    if any(found is None for found in key_sets):
        return None
    return frozenset().union(*(found or () for found in key_sets))


def _inverted(types: Sequence[frozenset[Value] | None]) -> dict[Value, frozenset[int]]:
    """Kinematic type -> the constraints about it (not those about any type)."""
    by_type: dict[Value, set[int]] = {}
    for i, found in enumerate(types):
        for value in found or ():
            by_type.setdefault(value, set()).add(i)
    return {value: frozenset(indices) for value, indices in by_type.items()}


def _about(sparse: Sequence[Sequence[Sparse]], width: int) -> tuple[frozenset[int], ...]:
    """Per characteristic, the constraints whose boxes restrict it."""
    about: list[set[int]] = [set() for _ in range(width)]
    for i, boxes in enumerate(sparse):
        for box in boxes:
            for p, _ in box:
                about[p].add(i)
    return tuple(frozenset(found) for found in about)


def _holds(allowed: frozenset[Value] | None, value: Value) -> bool:
    return allowed is None or value in allowed


def _meets(allowed: frozenset[Value], domain: frozenset[Value] | None) -> bool:
    return bool(allowed) if domain is None else not allowed.isdisjoint(domain)


def _tested_sets(
    rule: RuleConstraint, positions: dict[str, int]
) -> dict[int, tuple[frozenset[Value], ...]]:
    tested: dict[int, list[frozenset[Value]]] = {}
    for condition in (*rule.when, *rule.conditions):
        tested.setdefault(positions[condition.characteristic], []).append(condition.allowed)
    return {position: tuple(sets) for position, sets in tested.items()}
