"""The questions the semantic checks ask the constraint model, kept small so they stay fast.

Every answer here comes from python-constraint through :func:`solver.core.model.build_problem`
(the one notion of "valid robot"); what this module adds is *which* questions to ask:

* **Restricted domains.** "Can sensor type X appear for a UGV?" is the model over the UGV's
  domains with the sensor type narrowed to ``{X}``; existence is ``getSolution()``, never an
  enumeration of every robot.
* **Relevant constraints only.** A rule none of whose exclusion boxes
  (:mod:`solver.core.regions`) meets the domains holds for every robot there, so it is left
  out of that problem. Fixing the kinematic type usually leaves a handful of a rule set's
  constraints.
* **Interchangeable values.** Two values of a characteristic that every remaining condition
  treats alike (each condition allows both or neither) can be swapped in any valid robot, so
  one representative per class answers for all of them (Freuder's interchangeability). With
  the kinematic type fixed, a hundred sensor types usually fall into a few classes.
* **Witnesses.** One solution proves every value in it possible, so :meth:`Analysis.live`
  asks for robots using values not yet seen and needs about as many questions as the largest
  number of classes of one characteristic, plus one "no" per characteristic.

Explanations are deletion-based minimal subsets (:meth:`Analysis.minimal_conflict`): drop one
constraint, re-solve, keep it dropped if the question still has no solution.

Not here: deciding what is a finding (the check modules) or enumerating robots for solving
(:mod:`solver.core.model`, :mod:`solver.core.solution`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import cached_property

from solver.core.constraints import RuleConstraint, Value
from solver.core.model import Robot, build_problem
from solver.core.regions import Box, Domains, intersect, regions, touches
from solver.core.rules import RuleSet

__all__ = ["Analysis", "Classes"]

# Per characteristic, its domain split into classes of interchangeable values (domain order).
Classes = tuple[tuple[tuple[Value, ...], ...], ...]


class Analysis:
    """Questions about one rule set; answers that several checks share are computed once.

    Constraints are named by their index in ``rules.constraints`` (two identical constraints
    are still two constraints).
    """

    def __init__(self, rules: RuleSet) -> None:
        self.rules = rules
        self.boxes: tuple[tuple[Box, ...], ...] = tuple(
            regions(rules, rule) for rule in rules.constraints
        )
        # The kinematic types each constraint can exclude robots of (None: any); most
        # constraints are about a few types, so this cheap pre-filter spares most box tests.
        key = rules.key_position
        self._types: tuple[frozenset[Value] | None, ...] = tuple(
            None
            if any(box[key] is None for box in boxes)
            else frozenset().union(*(box[key] or () for box in boxes))
            for boxes in self.boxes
        )
        # The same, inverted: the constraints about each type, and those about any type, so
        # that a question about one type looks at its few constraints, not at all of them.
        self._untyped = frozenset(i for i, types in enumerate(self._types) if types is None)
        by_type: dict[Value, set[int]] = {}
        for i, types in enumerate(self._types):
            for value in types or ():
                by_type.setdefault(value, set()).add(i)
        self._by_type = {value: frozenset(indices) for value, indices in by_type.items()}
        positions = {name: i for i, name in enumerate(rules.names)}
        # For each constraint: per characteristic position, the value sets its conditions test.
        self._tested: tuple[dict[int, tuple[frozenset[Value], ...]], ...] = tuple(
            _tested_sets(rule, positions) for rule in rules.constraints
        )

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
        return tuple(
            tuple(v for v in domain if v in allowed) if i == position else domain
            for i, domain in enumerate(domains)
        )

    # -- the small questions -------------------------------------------------------------------

    def relevant(self, domains: Domains, among: Iterable[int] | None = None) -> tuple[int, ...]:
        """The constraints (of ``among``, default all) that exclude some robot over ``domains``."""
        sets = [frozenset(domain) for domain in domains]
        types = sets[self.rules.key_position]
        if len(types) == len(self.rules.key.values):  # every type: no pre-filter
            indices: Iterable[int] = range(len(self.boxes)) if among is None else among
        else:
            candidates = self._untyped.union(*(self._by_type.get(t, ()) for t in types))
            indices = sorted(candidates) if among is None else [i for i in among if i in candidates]
        return tuple(i for i in indices if touches(self.boxes[i], sets))

    def classes(self, domains: Domains, constraints: Sequence[int]) -> Classes:
        """Each domain split into values that ``constraints`` cannot tell apart."""
        result = []
        for position, domain in enumerate(domains):
            members = frozenset(domain)
            # Each value's signature lists the tested sets holding it. Walking only each set's
            # values in the domain (set intersection walks the smaller side) costs the size of
            # the rules, not domain x conditions; a set holding all or none splits nothing.
            signature: dict[Value, list[int]] = {}
            distinct = dict.fromkeys(
                s for i in constraints for s in self._tested[i].get(position, ())
            )
            for k, tested in enumerate(distinct):
                hits = tested & members
                if 0 < len(hits) < len(members):
                    for value in hits:
                        signature.setdefault(value, []).append(k)
            groups: dict[tuple[int, ...], list[Value]] = {}
            for value in domain:
                groups.setdefault(tuple(signature.get(value, ())), []).append(value)
            result.append(tuple(tuple(group) for group in groups.values()))
        return tuple(result)

    def _solve(self, domains: Domains, constraints: Sequence[int]) -> Robot | None:
        """One valid robot over ``domains`` (tried last value first) or ``None``."""
        sets = [frozenset(domain) for domain in domains]
        active = [self.rules.constraints[i] for i in constraints if touches(self.boxes[i], sets)]
        problem = build_problem(self.rules, domains, active)
        if problem is None:
            return None
        solution = problem.getSolution()
        if solution is None:
            return None
        return tuple(solution[name] for name in self.rules.names)

    def witness(self, domains: Domains, among: Iterable[int] | None = None) -> Robot | None:
        """A valid robot over ``domains`` under the constraints ``among`` (default: all)."""
        relevant = self.relevant(domains, among)
        representatives = tuple(
            tuple(group[0] for group in groups) for groups in self.classes(domains, relevant)
        )
        return self._solve(representatives, relevant)

    def satisfiable(self, domains: Domains, among: Iterable[int] | None = None) -> bool:
        """Whether some robot over ``domains`` satisfies the constraints ``among``."""
        return self.witness(domains, among) is not None

    def live(self, domains: Domains) -> tuple[frozenset[Value], ...]:
        """Per characteristic, the values that appear in at least one valid robot over domains.

        All sets are empty when there is no valid robot at all.
        """
        relevant = self.relevant(domains)
        classes = self.classes(domains, relevant)
        count = len(classes)
        if any(not groups for groups in classes):
            return tuple(frozenset() for _ in classes)
        class_of = [{v: k for k, group in enumerate(groups) for v in group} for groups in classes]
        unknown = [set(range(len(groups))) for groups in classes]
        live: list[set[int]] = [set() for _ in classes]
        dead: list[set[int]] = [set() for _ in classes]

        def representatives(position: int, only_unknown: bool) -> tuple[Value, ...]:
            groups = classes[position]
            seen = [k for k in range(len(groups)) if k in live[position]]
            fresh = sorted(unknown[position])
            # python-constraint tries a domain's last value first: put unseen classes last so
            # one solution witnesses as many new classes as possible.
            chosen = fresh if only_unknown else seen + fresh
            return tuple(groups[k][0] for k in chosen)

        for position in range(count):
            while unknown[position]:
                query = tuple(representatives(p, p == position) for p in range(count))
                robot = self._solve(query, relevant)
                if robot is None:
                    dead[position] |= unknown[position]
                    unknown[position].clear()
                    break
                for p, value in enumerate(robot):
                    k = class_of[p][value]
                    live[p].add(k)
                    unknown[p].discard(k)
            if not live[position]:  # no valid robot at all
                return tuple(frozenset() for _ in classes)
        return tuple(frozenset(v for k in live[p] for v in classes[p][k]) for p in range(count))

    def minimal_conflict(
        self, domains: Domains, among: Iterable[int] | None = None
    ) -> tuple[int, ...]:
        """A minimal subset of the constraints ``among`` that leaves no robot over ``domains``.

        Deletion-based: drop each constraint in declared order, re-solve, and keep it dropped
        while the rest still has no solution. ``ValueError`` if the constraints have a solution.
        """
        kept = list(self.relevant(domains, among))
        if self.satisfiable(domains, kept):
            raise ValueError("the constraints have a solution: nothing conflicts")
        for index in list(kept):
            trial = [i for i in kept if i != index]
            if not self.satisfiable(domains, trial):
                kept = trial
        return tuple(kept)

    def exclusions(self, index: int, domains: Domains | None = None) -> tuple[Domains, ...]:
        """The non-empty boxes of robots over ``domains`` (default all) that constraint excludes."""
        base = self.full if domains is None else domains
        boxes = (intersect(base, box) for box in self.boxes[index])
        return tuple(box for box in boxes if all(box))

    def entailing(self, index: int) -> tuple[int, ...] | None:
        """A minimal set of the other constraints that already excludes all ``index`` excludes.

        ``None`` when ``index`` excludes some robot that every other constraint allows (it is
        not redundant); ``()`` when it excludes nothing at all (a tautology).
        """
        boxes = self.exclusions(index)
        others = [i for i in range(len(self.boxes)) if i != index]

        def entails(subset: Sequence[int]) -> bool:
            return not any(self.satisfiable(box, subset) for box in boxes)

        if not boxes:
            return ()
        if not entails(others):
            return None
        touched = set().union(*(self.relevant(box, others) for box in boxes))
        kept = [i for i in others if i in touched]
        for other in list(kept):
            trial = [i for i in kept if i != other]
            if entails(trial):
                kept = trial
        return tuple(kept)

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
        """Per characteristic, the values some valid robot of some kinematic type has."""
        sets: list[set[Value]] = [set() for _ in self.rules.characteristics]
        for live in self.type_live.values():
            for position, values in enumerate(live):
                sets[position] |= values
        return tuple(frozenset(s) for s in sets)

    @cached_property
    def entailments(self) -> tuple[tuple[int, ...] | None, ...]:
        """:meth:`entailing` for every constraint, in declared order."""
        return tuple(self.entailing(index) for index in range(len(self.boxes)))

    @cached_property
    def void_conflict(self) -> tuple[int, ...]:
        """A minimal set of constraints leaving no valid robot at all (empty: not void)."""
        return self.minimal_conflict(self.full) if self.is_void else ()

    @cached_property
    def type_conflicts(self) -> dict[Value, tuple[int, ...]]:
        """For each void kinematic type, a minimal set of constraints that voids it."""
        return {kt: self.minimal_conflict(self.type_domains(kt)) for kt in self.void_types}


def _tested_sets(
    rule: RuleConstraint, positions: dict[str, int]
) -> dict[int, tuple[frozenset[Value], ...]]:
    tested: dict[int, list[frozenset[Value]]] = {}
    for condition in (*rule.when, *rule.conditions):
        tested.setdefault(positions[condition.characteristic], []).append(condition.allowed)
    return {position: tuple(sets) for position, sets in tested.items()}
