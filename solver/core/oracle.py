"""Is there a valid robot over these domains? A SAT solver answers, in time that follows the
rules, not the robots.

The questions of :mod:`solver.core.analysis` are all of one kind: does some robot over
restricted domains satisfy a set of constraints. Enumerating (python-constraint) made ``check``
exponential in constraints chained across characteristics and quadratic in unconstrained ones;
here the rule set becomes clauses once and every question is one call of an incremental SAT
solver (MiniSat 2.2 through PySAT) under assumptions:

* **Classes, not values.** At each characteristic the constraints' boxes
  (:mod:`solver.core.regions`) cut the values into classes the boxes cannot tell apart; a
  variable ``x`` per class says "the robot's value may be in this class". Values in no box are
  one class. 100 sensor types under 200 constraints are a few dozen variables.
* **A box is a clause.** A robot in box ``(S1, S2, ...)`` is excluded: for each characteristic
  a variable ``y`` is forced true by every class inside its ``S`` (``x -> y``), and the box's
  clause ``not s or not y1 or not y2 ...`` says that not all of them hold while the
  constraint's selector ``s`` is assumed. Choosing constraints is choosing selectors.
* **At least one class per characteristic, not exactly one.** A model may mark several classes
  of a characteristic; every robot taking one marked class per characteristic is valid, since
  marking more only makes more ``y`` true. So a model witnesses every marked class at once,
  and a domain restriction is "at least one of these classes" (a clause switched on by an
  assumption), never a list of every class left out.
* **One type at a time.** With the team key fixed to one value, only the constraints that can
  exclude robots of that value are clauses, and the key is no variable at all: asking about one
  type of 20,000 costs what that type's constraints cost.

Every answer depends only on whether a question has a solution, never on which model the
solver finds, so output stays the same from run to run. A search is bounded: the conflicts of
all questions about one rule set count against the ``conflicts`` limit
(:mod:`solver.limits`), past which the rule set is refused as too intricate to analyse.

Not here: which questions are asked and how answers are explained (:mod:`solver.core.analysis`).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from solver.core.constraints import Value
from solver.core.regions import Domains
from solver.core.ruleset import RuleSet
from solver.errors import Fault, Location, TooLargeError
from solver.limits import limit

if TYPE_CHECKING:
    from pysat.solvers import Solver

__all__ = ["Budget", "Oracle", "Sparse"]

# A box as the (position, value set) pairs of the characteristics it restricts.
Sparse = tuple[tuple[int, frozenset[Value]], ...]


class Budget:
    """The conflicts the solver may still spend on one rule set's questions."""

    def __init__(self, rules: RuleSet) -> None:
        self.rules = rules
        self.remaining = limit("conflicts").value

    def spend(self, conflicts: int) -> None:
        self.remaining -= conflicts

    def exhausted(self) -> TooLargeError:
        """The refusal, at the first constraint (no one constraint is to blame)."""
        which = limit("conflicts")
        constraints = self.rules.constraints
        first = constraints[0].location if constraints else Location(self.rules.file)
        return TooLargeError(
            Fault(
                replace(first, path="constraints"),
                "the constraints are too intricate to analyse: "
                + which.message(which.value + 1, noun="conflicts or more of the SAT search"),
                "too-large",
            )
        )


class _Position:
    """One characteristic's classes: the values no box at it can tell apart."""

    def __init__(self, values: Sequence[Value], sets: Sequence[frozenset[Value]]) -> None:
        signature: dict[Value, list[int]] = {}
        for number, found in enumerate(sets):
            for value in found:
                signature.setdefault(value, []).append(number)
        groups: dict[tuple[int, ...], list[Value]] = {}
        for value, numbers in signature.items():
            groups.setdefault(tuple(numbers), []).append(value)
        self.members: list[list[Value]] = list(groups.values())
        self.class_of: dict[Value, int] = {
            value: index for index, group in enumerate(self.members) for value in group
        }
        # Values in no box: one more class, stood for by the first of them. Scanning stops at
        # the first value outside every box, so it costs the boxes' size, not the domain's.
        self.rest: int | None = None
        self.representatives = [group[0] for group in self.members]
        if len(signature) < len(values):
            outside = next(v for v in values if v not in signature)
            self.rest = len(self.members)
            self.representatives.append(outside)

    @property
    def size(self) -> int:
        return len(self.representatives)

    def of(self, value: Value) -> int:
        found = self.class_of.get(value)
        if found is not None:
            return found
        if self.rest is None:
            raise KeyError(value)
        return self.rest


def _kept(
    boxes: Sequence[Sequence[Sparse]],
    included: Sequence[int],
    key: int | None,
    key_value: Value | None,
) -> list[tuple[int, list[tuple[int, frozenset[Value]]]]]:
    """The boxes of ``included`` that can hold a robot with ``key_value`` at ``key`` (when
    fixed), without the key; an empty box excludes nothing and is left out."""
    kept = []
    for index in included:
        for box in boxes[index]:
            if any(p == key and key_value not in found for p, found in box):
                continue
            parts = [(p, found) for p, found in box if p != key]
            if all(found for _, found in parts):
                kept.append((index, parts))
    return kept


class Oracle:
    """The constraints ``included`` of a rule set as clauses, with the team key fixed to
    ``key_value`` (``None``: the key is free like any characteristic).

    ``boxes[i]`` are constraint ``i``'s boxes, each as the (position, set) pairs it restricts
    (a box about two of 1,000 characteristics is two pairs). With the key fixed, the oracle
    answers for every kinematic type that lies in exactly the same boxes' key sets as
    ``key_value`` (the caller's domains name the type; the oracle does not look at it).
    """

    def __init__(
        self,
        rules: RuleSet,
        boxes: Sequence[Sequence[Sparse]],
        included: Sequence[int],
        key_value: Value | None,
        budget: Budget,
    ) -> None:
        from pysat.solvers import Solver

        self.rules = rules
        self.budget = budget
        self.key = None if key_value is None else rules.key_position
        kept = _kept(boxes, included, self.key, key_value)
        sets: dict[int, dict[frozenset[Value], None]] = {}
        for _, parts in kept:
            for p, found in parts:
                sets.setdefault(p, {})[found] = None
        self.positions = {
            p: _Position(rules.characteristics[p].values, list(found))
            for p, found in sorted(sets.items())
        }
        self.solver: Solver = Solver(name="minisat22")
        self._count = 0
        self.x = {p: [self._new() for _ in range(at.size)] for p, at in self.positions.items()}
        for variables in self.x.values():
            self.solver.add_clause(variables)
        # Prefer marking classes: a model then witnesses as many classes as it can.
        self.solver.set_phases([v for variables in self.x.values() for v in variables])
        inside = {
            (p, found): self._inside(p, found) for p, by_set in sets.items() for found in by_set
        }
        self.selector: dict[int, int] = {}
        self.every = self._new()  # assumed: every included constraint holds
        for index in included:
            self.selector[index] = selector = self._new()
            self.solver.add_clause([-self.every, selector])
        for index, parts in kept:
            self.solver.add_clause(
                [-self.selector[index], *(-inside[(p, found)] for p, found in parts)]
            )
        self._switches: dict[tuple[int, frozenset[int]], int] = {}
        self._wholes = [(p, rules.characteristics[p].values) for p in self.positions]

    def _inside(self, p: int, found: frozenset[Value]) -> int:
        """A variable forced true by every class of ``p`` inside ``found``."""
        y = self._new()
        for k, representative in enumerate(self.positions[p].representatives):
            if representative in found:
                self.solver.add_clause([-self.x[p][k], y])
        return y

    def _new(self) -> int:
        self._count += 1
        return self._count

    # -- questions ------------------------------------------------------------------------------

    def satisfiable(
        self, domains: Domains, among: Iterable[int] | None = None, without: Collection[int] = ()
    ) -> bool:
        """Whether some robot over ``domains`` satisfies the constraints ``among`` (default:
        every included one but those ``without``; the others exclude nothing here)."""
        return self._solve(domains, among, without)

    def core(self, domains: Domains, among: Iterable[int]) -> frozenset[int] | None:
        """``None`` when some robot over ``domains`` satisfies the constraints ``among``; else
        a subset of them that already leaves none (the solver's core: which subset depends on
        how the solver found it, so use it only where any such subset gives the same result,
        as :func:`solver.core.analysis.deletion` does)."""
        chosen = [i for i in among if i in self.selector]
        if self._solve(domains, chosen):
            return None
        which = {self.selector[i]: i for i in chosen}
        return frozenset(which[lit] for lit in self.solver.get_core() or () if lit in which)

    def model(
        self,
        domains: Domains,
        among: Iterable[int] | None = None,
        extra: Sequence[int] = (),
    ) -> dict[int, list[int]] | None:
        """The classes a model marks at each position (each choice of one marked, allowed
        class per position is a valid robot), or ``None`` when there is no valid robot."""
        if not self._solve(domains, among, (), extra):
            return None
        true = {literal for literal in self.solver.get_model() or () if literal > 0}
        return {p: [k for k, v in enumerate(xs) if v in true] for p, xs in self.x.items()}

    def _solve(
        self,
        domains: Domains,
        among: Iterable[int] | None,
        without: Collection[int] = (),
        extra: Sequence[int] = (),
    ) -> bool:
        assumptions = self._restrict(domains)
        if assumptions is None:
            return False
        if among is not None:
            assumptions += [self.selector[i] for i in among if i in self.selector]
        elif without:
            assumptions += [s for i, s in self.selector.items() if i not in without]
        elif self.selector:  # a variable no clause mentions is unknown to the solver
            assumptions.append(self.every)
        assumptions += extra
        solver = self.solver
        before = solver.accum_stats().get("conflicts", 0)
        solver.conf_budget(max(self.budget.remaining, 1))
        found: bool | None = solver.solve_limited(assumptions=assumptions)
        self.budget.spend(solver.accum_stats().get("conflicts", 0) - before)
        if found is None:
            raise self.budget.exhausted()
        return found

    def live(self, domains: Domains) -> dict[int, set[int]] | None:
        """Per position, the allowed classes some valid robot over ``domains`` has; ``None``
        when there is no valid robot. Positions with no variable (no box reads them) are
        missing: every value of their domain is live when any robot is.

        Each question asks for a robot with any class not yet seen, at any position: a model
        shows every class it marks, and the first "no" says that all the rest are dead.
        """
        unseen = {
            self.x[p][k]: (p, k) for p in self.positions for k in self._allowed(p, domains[p])
        }
        live: dict[int, set[int]] = {p: set() for p in self.positions}
        first = True
        while first or unseen:
            extra = []
            if not first:
                extra = [self._new()]
                self.solver.add_clause([-extra[0], *unseen])
            # The solver saves the phase of each variable as it goes: ask again for every class
            # not yet seen to be marked, so one model shows as many of them as it can.
            self.solver.set_phases(list(unseen))
            found = self._solve(domains, None, (), extra)
            if extra:
                self.solver.add_clause([-extra[0]])  # this question is answered: retire it
            if not found:
                if first:
                    return None
                break
            first = False
            model = self.solver.get_model() or []
            for variable in [v for v in unseen if model[v - 1] > 0]:
                p, k = unseen.pop(variable)
                live[p].add(k)
        return live

    # -- domains as assumptions -----------------------------------------------------------------

    def _allowed(self, p: int, domain: Sequence[Value]) -> set[int]:
        at = self.positions[p]
        if len(domain) == len(self.rules.characteristics[p].values):
            return set(range(at.size))
        return {at.of(value) for value in domain}

    def _restrict(self, domains: Domains) -> list[int] | None:
        """Assumptions that keep each position to its domain; ``None`` when a domain rules
        out every robot."""
        if not all(domains):
            return None
        assumptions = []
        for p, whole in self._wholes:
            domain = domains[p]
            # Whole domains are the characteristic's own tuple (Analysis passes them on).
            if domain is not whole and len(domain) != len(whole):
                assumptions.append(self._switch(p, frozenset(self._allowed(p, domain))))
        return assumptions

    def _switch(self, p: int, classes: frozenset[int]) -> int:
        """A literal that, assumed, asks for one of ``classes`` at ``p``."""
        if len(classes) == 1:
            return self.x[p][next(iter(classes))]
        key = (p, classes)
        if key not in self._switches:
            self._switches[key] = switch = self._new()
            self.solver.add_clause([-switch, *(self.x[p][k] for k in sorted(classes))])
        return self._switches[key]

    def values(self, p: int, classes: set[int], domain: Sequence[Value]) -> frozenset[Value]:
        """The values of ``domain`` in ``classes`` of position ``p``."""
        at = self.positions[p]
        whole = len(domain) == len(self.rules.characteristics[p].values)
        if at.rest is not None and at.rest in classes:
            if len(classes) == at.size and whole:
                return frozenset(domain)
            return frozenset(v for v in domain if at.of(v) in classes)
        found = frozenset(v for k in classes for v in at.members[k])
        return found if whole else found.intersection(domain)
