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

* **Near the question first.** A question that narrows a few characteristics of many (is this
  value dead? do these constraints conflict there?) is first asked of a small instance of its
  own: the characteristics around the narrowed ones, with one valid robot over the whole
  domains (the witness) standing in for everything beyond (:meth:`Oracle._local`). Along a
  chain of 1,000 characteristics a question costs what a few links cost, not the chain; a
  question that needs more than a sixteenth of the characteristics goes to the whole instance
  (and so does every question of a rule set of fewer than :data:`NEAR_FROM`).

Every answer depends only on whether a question has a solution, never on which model the
solver finds, so output stays the same from run to run. A search is bounded: the conflicts of
all questions about one rule set count against the ``conflicts`` limit
(:mod:`solver.limits`), past which the rule set is refused as too intricate to analyse, and,
given a deadline (:mod:`solver.deadline`), every question and every few thousand conflicts of
one look at it.

Not here: which questions are asked and how answers are explained (:mod:`solver.core.analysis`).
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from solver.core.constraints import Value
from solver.core.regions import Domains, Sparse, narrowed_positions
from solver.core.ruleset import RuleSet
from solver.deadline import Deadline
from solver.errors import Fault, Location, TooLargeError
from solver.limits import limit

if TYPE_CHECKING:
    from pysat.solvers import Solver

__all__ = [
    "NEAR_FROM",
    "SHARED_FROM",
    "STEP_CONFLICTS",
    "STEP_PROPAGATIONS",
    "Budget",
    "Oracle",
    "SharedClasses",
]

# The fewest characteristics an oracle has for questions to be asked near what they narrow
# first: below, MiniSat answers from the whole instance faster than Python builds a small one.
NEAR_FROM = 128
# A search looks at its deadline after this many conflicts or propagations (each step a
# fraction of a second on the largest instances the limits let in).
STEP_CONFLICTS = 2_000
STEP_PROPAGATIONS = 20_000_000
# The fewest values of a whole domain whose live values are one set shared by every question
# that finds them (below, a set of its own costs less than the sharing).
SHARED_FROM = 64


class Budget:
    """What the solver may still spend on one rule set's questions: conflicts (the
    ``conflicts`` limit) and, given a ``deadline``, time."""

    def __init__(self, rules: RuleSet, deadline: Deadline | None = None) -> None:
        self.rules = rules
        self.remaining = limit("conflicts").value
        self.deadline = deadline
        self._location = Location(rules.file)

    def spend(self, conflicts: int) -> None:
        self.remaining -= conflicts

    def check_time(self) -> None:
        """:class:`~solver.errors.TimeLimitError`, at the rule set, once the deadline passed."""
        if self.deadline is not None:
            self.deadline.check(self._location)

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
        self._inside: dict[frozenset[Value], tuple[int, ...]] = {}

    @property
    def size(self) -> int:
        return len(self.representatives)

    def inside(self, found: frozenset[Value]) -> tuple[int, ...]:
        """The classes inside ``found`` (one of the sets the classes were made from)."""
        if found not in self._inside:
            self._inside[found] = tuple(
                k for k, value in enumerate(self.representatives) if value in found
            )
        return self._inside[found]

    def of(self, value: Value) -> int:
        found = self.class_of.get(value)
        if found is not None:
            return found
        if self.rest is None:
            raise KeyError(value)
        return self.rest


_Parts = list[tuple[int, frozenset[Value]]]  # a box as the (position, set) pairs it tests
# Each characteristic's classes under each tuple of sets its boxes test: the same for every
# oracle of a rule set, so they share them (an oracle's ``made``).
SharedClasses = dict[tuple[int, tuple[frozenset[Value], ...]], _Position]


def _kept(
    boxes: Sequence[Sequence[Sparse]],
    included: Sequence[int],
    key: int | None,
    key_value: Value | None,
) -> list[tuple[int, _Parts]]:
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
        *,
        made: SharedClasses | None = None,
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
        # A characteristic's classes under the same sets are the same for every oracle of
        # the rule set: ``made`` shares them (1,000 type oracles over 1,000 characteristics
        # made each characteristic's classes 1,000 times).
        made = {} if made is None else made
        self.positions: dict[int, _Position] = {}
        for p, by_set in sorted(sets.items()):
            key = (p, tuple(by_set))
            if key not in made:
                made[key] = _Position(rules.characteristics[p].values, key[1])
            self.positions[p] = made[key]
        self.solver: Solver = Solver(name="minisat22")
        self._count = 0
        self.x = {p: [self._new() for _ in range(at.size)] for p, at in self.positions.items()}
        for variables in self.x.values():
            self.solver.add_clause(variables)
        # Prefer marking classes: a model then witnesses as many classes as it can.
        self.solver.set_phases([v for variables in self.x.values() for v in variables])
        self._classes_in = self._classes_inside(sets)
        self.selector: dict[int, int] = {}
        self.every = self._new()  # assumed: every included constraint holds
        self._add_constraints(kept, included)
        self._switches: dict[tuple[int, frozenset[int]], int] = {}
        self._wholes = [(p, rules.characteristics[p].values) for p in self.positions]
        # For local answers: each constraint's boxes, and the constraints at each position.
        self._boxes_of: dict[int, list[_Parts]] = {}
        self._at: dict[int, list[int]] = {}
        self._index_boxes(kept)
        self._witness: dict[int, int] | None = None
        self._witness_asked = False
        self._all_wholes = tuple(c.values for c in rules.characteristics)
        self._no_empty_whole = all(self._all_wholes)
        # The most characteristics a question's neighbourhood may hold (else: every one). An
        # instance built in Python costs some ten times what MiniSat spends on as many of the
        # whole instance's characteristics: a sixteenth of them (at least 8, at most half), and
        # none below NEAR_FROM, so that a question the neighbourhood cannot answer (x0 = a
        # forcing a along the whole chain) costs little more than before.
        count = len(self.positions)
        self._limit = min(max(count // 16, 8), count // 2) if count >= NEAR_FROM else 0
        self._answered = self._missed = 0  # local questions; see _local
        self._last_changed: tuple[Domains | None, dict[int, set[int]] | None] = (None, {})
        self._whole_live: tuple[dict[int, set[int]] | None] | None = None
        self._whole_values: dict[tuple[int, frozenset[int]], frozenset[Value]] = {}
        # What the oracle weighs, clauses and all: the variables it was built with.
        self.variables = self._count

    def _classes_inside(
        self, sets: dict[int, dict[frozenset[Value], None]]
    ) -> dict[tuple[int, frozenset[Value]], tuple[int, ...]]:
        """The classes of each position inside each set a box tests there."""
        return {
            (p, found): self.positions[p].inside(found)
            for p, by_set in sets.items()
            for found in by_set
        }

    def _add_constraints(self, kept: Sequence[tuple[int, _Parts]], included: Sequence[int]) -> None:
        """A selector per included constraint (implied by ``every``), and a clause per box:
        the constraint's selector excludes the robots inside the box."""
        inside = {key: self._inside(*key) for key in self._classes_in}
        for index in included:
            self.selector[index] = selector = self._new()
            self.solver.add_clause([-self.every, selector])
        for index, parts in kept:
            self.solver.add_clause(
                [-self.selector[index], *(-inside[(p, found)] for p, found in parts)]
            )

    def _index_boxes(self, kept: Sequence[tuple[int, _Parts]]) -> None:
        for index, parts in kept:
            self._boxes_of.setdefault(index, []).append(parts)
            for p, _ in parts:
                at = self._at.setdefault(p, [])
                if not at or at[-1] != index:
                    at.append(index)

    def _inside(self, p: int, found: frozenset[Value]) -> int:
        """A variable forced true by every class of ``p`` inside ``found``."""
        y = self._new()
        for k in self._classes_in[(p, found)]:
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
        if among is None:
            local = self._local(domains, lambda index: index not in without)
        else:
            among = chosen = set(among)
            local = self._local(domains, chosen.__contains__)
        if local is not None:
            return local[0]
        return self._solve(domains, among, without)

    def core(self, domains: Domains, among: Collection[int]) -> frozenset[int] | None:
        """``None`` when some robot over ``domains`` satisfies the constraints ``among``; else
        a subset of them that already leaves none (the solver's core: which subset depends on
        how the solver found it, so use it only where any such subset gives the same result,
        as :func:`solver.core.analysis.deletion` does)."""
        local = self._local(domains, among.__contains__)
        if local is not None:
            return None if local[0] else local[1]
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
        return _run(self.solver, assumptions, self.budget)

    # -- answers from a question's neighbourhood --------------------------------------------------

    def _local(
        self, domains: Domains, member: Callable[[int], bool]
    ) -> tuple[bool, frozenset[int]] | None:
        """Whether some robot over ``domains`` satisfies the constraints ``member`` accepts,
        told from the characteristics near those ``domains`` narrow, with a core when none
        does; ``None`` when the neighbourhood grows past its limit (a sixteenth of the oracle's
        characteristics; none below :data:`NEAR_FROM`), or when that happened more often than
        not (16 more times than answers came).

        One valid robot over the whole domains (the witness) satisfies every constraint. The
        neighbourhood starts at the narrowed characteristics and grows by the constraints at
        its edge, layer by layer; the characteristics those constraints reach beyond it are
        its boundary. A robot for the neighbourhood that takes the witness's values on the
        boundary is, with the witness's values everywhere else, a valid robot: the answer is
        yes. No robot for the neighbourhood's constraints alone, the boundary left free: no
        robot at all, and the core is among them. Neither: grow and ask again (each time the
        neighbourhood has doubled, so a chain of 1,000 characteristics costs what a few
        links cost, and a question that needs everything costs little more than before).
        """
        # Where neighbourhoods keep growing past their limit, the rule set is no chain: stop.
        if not self._limit or self._missed > self._answered + 16:
            return None
        allowed = self._changed(domains)
        if allowed is None or len(allowed) > self._limit:
            return None
        witness = self._whole_witness()
        if witness is None:
            return None
        if not allowed:
            return True, frozenset()  # the witness itself
        return self._near(allowed, member, witness)

    def _near(
        self,
        allowed: dict[int, set[int]],
        member: Callable[[int], bool],
        witness: dict[int, int],
        seen: list[tuple[int, int]] | None = None,
    ) -> tuple[bool, frozenset[int]] | None:
        """:meth:`_local` for the classes ``allowed`` at the positions they name (the others
        whole); after a yes, the (position, class) pairs its robots show are added to
        ``seen``."""
        local = _Local(self, allowed)
        frontier = list(allowed)
        asked = 0
        while True:
            for p in frontier:
                for index in self._at.get(p, ()):
                    if index not in local.selectors and member(index):
                        local.add(index)
            boundary = local.fresh()
            if len(local.x) > self._limit:
                self._missed += 1
                return None
            if not boundary or len(local.x) >= 2 * asked:
                answer = local.ask(boundary, witness)
                if answer is not None:
                    self._answered += 1
                    if answer[0] and seen is not None:
                        seen += local.marked(boundary)
                    return answer
                asked = len(local.x)
            frontier = boundary

    def _whole_witness(self) -> dict[int, int] | None:
        """One class per position of a valid robot over the whole domains; ``None`` when
        there is none."""
        if not self._witness_asked:
            self._witness_asked = True
            if _run(self.solver, [self.every] if self.selector else [], self.budget):
                true = {literal for literal in self.solver.get_model() or () if literal > 0}
                self._witness = {
                    p: next(k for k, v in enumerate(xs) if v in true) for p, xs in self.x.items()
                }
        return self._witness

    def _changed(self, domains: Domains) -> dict[int, set[int]] | None:
        """The allowed classes of each position whose domain is not whole; ``None`` when a
        domain is empty. The last answer is kept: deleting towards a minimal conflict asks
        several questions over one domains."""
        if self._last_changed[0] is not domains:
            narrowed = narrowed_positions(domains, self._all_wholes)
            changed = None
            if self._no_empty_whole and all(domains[p] for p in narrowed):
                changed = {p: self._allowed(p, domains[p]) for p in narrowed if p in self.positions}
            self._last_changed = domains, changed
        return self._last_changed[1]

    def live(self, domains: Domains) -> dict[int, set[int]] | None:
        """Per position, the allowed classes some valid robot over ``domains`` has; ``None``
        when there is no valid robot. Positions with no variable (no box reads them) are
        missing: every value of their domain is live when any robot is.

        The first model shows every class it marks. Then each class not yet seen is asked
        about alone, from its neighbourhood (:meth:`_local`), while that stays small; past
        that, each question asks for a robot with any class not yet seen, at any position,
        and the first "no" says that all the rest are dead.

        Over the whole domains the answer is the same for every kinematic type the oracle
        answers for: it is found once.
        """
        if self._changed(domains) == {}:
            if self._whole_live is None:
                self._whole_live = (self._live(domains),)
            return self._whole_live[0]
        return self._live(domains)

    def _live(self, domains: Domains) -> dict[int, set[int]] | None:
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
            model = self.solver.get_model() or []
            for variable in [v for v in unseen if model[v - 1] > 0]:
                p, k = unseen.pop(variable)
                live[p].add(k)
            if first:
                first = False
                self._live_near(domains, unseen, live)
        return live

    def _live_near(
        self, domains: Domains, unseen: dict[int, tuple[int, int]], live: dict[int, set[int]]
    ) -> None:
        """Settles the classes ``unseen`` one by one from their neighbourhoods, adding the
        live ones to ``live``, until one's neighbourhood is too large."""
        allowed = self._changed(domains) or {}
        if len(allowed) >= self._limit:
            return
        witness = self._whole_witness()
        if witness is None:
            return
        seen: list[tuple[int, int]] = []
        if all(witness[p] in classes for p, classes in allowed.items()):
            seen += witness.items()  # a robot over ``domains``
        for variable, (p, k) in list(unseen.items()):
            for q, c in seen:
                if unseen.pop(self.x[q][c], None):
                    live[q].add(c)
            seen.clear()
            if variable not in unseen:
                continue
            answer = self._near({**allowed, p: {k}}, self.selector.__contains__, witness, seen)
            if answer is None:
                return
            del unseen[variable]
            if answer[0]:
                live[p].add(k)

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
        """The values of ``domain`` in ``classes`` of position ``p``; over the whole domain,
        made once per set of classes (every kinematic type this oracle answers for shares
        them: 2,000 types that one constraint about any type made read the same 100,000
        counts were 2,000 sets of them, 8 GB)."""
        whole = len(domain) == len(self.rules.characteristics[p].values)
        if not whole or len(domain) < SHARED_FROM:
            return self._values(p, classes, domain, whole=whole)
        key = (p, frozenset(classes))
        if key not in self._whole_values:
            self._whole_values[key] = self._values(p, classes, domain, whole=True)
        return self._whole_values[key]

    def _values(
        self, p: int, classes: set[int], domain: Sequence[Value], *, whole: bool
    ) -> frozenset[Value]:
        at = self.positions[p]
        if at.rest is not None and at.rest in classes:
            # The values in no box, and those of the boxes' classes: the domain less the
            # boxes' other classes (in C: a Python test per value was 40 ms per 100,000).
            left_out = [
                v for k in range(len(at.members)) if k not in classes for v in at.members[k]
            ]
            return frozenset(domain).difference(left_out)
        found = frozenset(v for k in classes for v in at.members[k])
        return found if whole else found.intersection(domain)


def _run(solver: Solver, assumptions: list[int], budget: Budget) -> bool:
    """One solve under ``assumptions``, its conflicts spent from ``budget``; the deadline is
    looked at before it and every :data:`STEP_CONFLICTS` conflicts or
    :data:`STEP_PROPAGATIONS` propagations (MiniSat stops there and goes on with what it
    learnt), so a long search ends soon after its time is spent."""
    budget.check_time()
    while True:
        before = solver.accum_stats().get("conflicts", 0)
        solver.conf_budget(max(min(budget.remaining, STEP_CONFLICTS), 1))
        solver.prop_budget(STEP_PROPAGATIONS)
        found: bool | None = solver.solve_limited(assumptions=assumptions)
        budget.spend(solver.accum_stats().get("conflicts", 0) - before)
        if found is not None:
            return found
        if budget.remaining <= 0:
            raise budget.exhausted()
        budget.check_time()


class _Local:
    """A question's neighbourhood as a SAT instance of its own: the allowed classes of the
    positions its constraints reach (narrowed ones as the question says, the others whole),
    and each constraint's boxes as clauses behind a selector, as in :class:`Oracle`. Classes a
    question leaves out get no variable."""

    def __init__(self, oracle: Oracle, allowed: dict[int, set[int]]) -> None:
        from pysat.solvers import Solver

        self.oracle = oracle
        self.allowed = allowed
        self.solver: Solver = Solver(name="minisat22")
        self._count = 0
        self.x: dict[int, dict[int, int]] = {}
        self.selectors: dict[int, int] = {}
        self._inside: dict[tuple[int, frozenset[Value]], int | None] = {}
        self._fresh: list[int] = []
        for p in allowed:
            self._position(p)
        self._fresh = []  # the narrowed positions are the neighbourhood, not its boundary

    def _new(self) -> int:
        self._count += 1
        return self._count

    def _position(self, p: int) -> dict[int, int]:
        if p not in self.x:
            classes = self.allowed.get(p)
            if classes is None:
                classes = set(range(self.oracle.positions[p].size))
            self.x[p] = {k: self._new() for k in sorted(classes)}
            self.solver.add_clause(list(self.x[p].values()))
            # Prefer marking classes, as the oracle does: a model then shows more live ones.
            self.solver.set_phases(list(self.x[p].values()))
            self._fresh.append(p)
        return self.x[p]

    def fresh(self) -> list[int]:
        """The positions added since the last call."""
        found, self._fresh = self._fresh, []
        return found

    def _literal(self, p: int, found: frozenset[Value]) -> int | None:
        """A literal forced true by every allowed class of ``p`` inside ``found``; ``None``
        when there is none (a box with that part holds no robot here)."""
        key = (p, found)
        if key not in self._inside:
            x = self._position(p)
            inside = [x[k] for k in self.oracle._classes_in[key] if k in x]
            literal = inside[0] if len(inside) == 1 else None
            if len(inside) > 1:
                literal = self._new()
                for variable in inside:
                    self.solver.add_clause([-variable, literal])
            self._inside[key] = literal
        return self._inside[key]

    def add(self, index: int) -> None:
        """Constraint ``index``: its boxes as clauses, switched on by its selector."""
        self.selectors[index] = selector = self._new()
        for parts in self.oracle._boxes_of[index]:
            literals = [self._literal(p, found) for p, found in parts]
            if None not in literals:
                self.solver.add_clause([-selector, *(-(v or 0) for v in literals)])

    def ask(
        self, boundary: Sequence[int], witness: dict[int, int]
    ) -> tuple[bool, frozenset[int]] | None:
        """Yes when a robot here takes the witness's classes on ``boundary``; no, with a
        core, when there is no robot here at all; ``None`` when neither tells."""
        selectors = list(self.selectors.values())
        budget = self.oracle.budget
        if boundary:
            fixed = [self.x[q][witness[q]] for q in boundary]
            if _run(self.solver, selectors + fixed, budget):
                return True, frozenset()
        if _run(self.solver, selectors, budget):
            return None if boundary else (True, frozenset())
        which = {selector: index for index, selector in self.selectors.items()}
        return False, frozenset(which[v] for v in self.solver.get_core() or () if v in which)

    def marked(self, boundary: Sequence[int]) -> list[tuple[int, int]]:
        """After a yes: the classes the model marks off ``boundary``, each one a valid robot's
        (with any marked class elsewhere here, and the witness beyond)."""
        model = self.solver.get_model() or []
        edge = set(boundary)
        return [
            (p, k)
            for p, x in self.x.items()
            if p not in edge
            for k, variable in x.items()
            if model[variable - 1] > 0
        ]
