"""Where a constraint bites: the robots it excludes, as boxes of per-characteristic value sets.

A ``forbid`` rule excludes exactly the robots whose values satisfy all of its conditions: one
box, the conditions intersected per characteristic. A ``require`` rule excludes the robots for
which every ``when`` condition holds and at least one required condition fails: one box per
required condition (the ``when`` sets, intersected with the complement of that condition).
A box leaves characteristics it does not mention free (``None``).

The semantic checks use boxes to ask python-constraint small questions with *restricted
domains* instead of a second evaluator: "is there a valid robot that this rule excludes?" is
"is the model over the box, without this rule, satisfiable?". Boxes also say which constraints
can matter at all on a set of domains (:func:`touches`): a rule none of whose boxes meets the
domains holds for every robot there and can be left out of the problem.

Not here: the questions themselves (:mod:`solver.core.analysis`).
"""

from __future__ import annotations

from collections.abc import Sequence

from solver.core.constraints import Condition, RuleConstraint, Value
from solver.core.ruleset import RuleSet

__all__ = [
    "Box",
    "Domains",
    "Sparse",
    "intersect",
    "narrowed_positions",
    "regions",
    "sparse_regions",
    "touches",
]

# One entry per characteristic, in rule order: the values a box allows, or None for "any".
Box = tuple[frozenset[Value] | None, ...]
# A box as the (position, value set) pairs of the characteristics it restricts.
Sparse = tuple[tuple[int, frozenset[Value]], ...]
Domains = tuple[tuple[Value, ...], ...]


def _box(
    rules: RuleSet, conditions: Sequence[Condition], complement: Condition | None = None
) -> Sparse:
    sets: dict[int, frozenset[Value]] = {}
    positions = rules.positions

    def narrow(position: int, allowed: frozenset[Value]) -> None:
        current = sets.get(position)
        sets[position] = allowed if current is None else current & allowed

    for condition in conditions:
        narrow(positions[condition.characteristic], condition.allowed)
    if complement is not None:
        position = positions[complement.characteristic]
        values = frozenset(rules.characteristics[position].values)
        narrow(position, values - complement.allowed)
    return tuple(sorted(sets.items()))


def sparse_regions(rules: RuleSet, rule: RuleConstraint) -> tuple[Sparse, ...]:
    """The boxes whose union is exactly the set of robots ``rule`` excludes, each as the
    (position, set) pairs of the characteristics it restricts, in position order: a box about
    two of 1,000 characteristics is two pairs."""
    if rule.kind == "forbid":
        return (_box(rules, rule.conditions),)
    return tuple(_box(rules, rule.when, condition) for condition in rule.conditions)


def regions(rules: RuleSet, rule: RuleConstraint) -> tuple[Box, ...]:
    """The boxes whose union is exactly the set of robots ``rule`` excludes."""
    width = len(rules.characteristics)
    boxes = []
    for parts in sparse_regions(rules, rule):
        box: list[frozenset[Value] | None] = [None] * width
        for position, allowed in parts:
            box[position] = allowed
        boxes.append(tuple(box))
    return tuple(boxes)


def intersect(domains: Domains, box: Box) -> Domains:
    """``domains`` narrowed to ``box`` (an empty tuple where they do not meet)."""
    return tuple(
        domain if allowed is None else tuple(v for v in domain if v in allowed)
        for domain, allowed in zip(domains, box, strict=True)
    )


def touches(boxes: Sequence[Box], domains: Sequence[frozenset[Value]]) -> bool:
    """Whether some robot over ``domains`` lies in one of ``boxes`` (the rule can exclude it)."""
    return any(
        all(
            allowed is None or not allowed.isdisjoint(domain)
            for allowed, domain in zip(box, domains, strict=True)
        )
        for box in boxes
    )


def narrowed_positions(domains: Domains, wholes: Domains) -> list[int]:
    """The positions, in order, where ``domains`` leave out values of ``wholes`` (each
    characteristic's own values; a domain is part of them, so one as long is whole).

    Questions narrow one or two of up to 1,000 characteristics and pass the others as the
    characteristic's own tuple, so the domains are compared a block at a time, in C (a tuple
    is equal to itself at once), and only a block that differs is looked into.
    """
    found = []
    for start in range(0, len(wholes), _BLOCK):
        end = start + _BLOCK
        if domains[start:end] != wholes[start:end]:
            found += [
                p for p in range(start, min(end, len(wholes))) if len(domains[p]) != len(wholes[p])
            ]
    return found


_BLOCK = 64
