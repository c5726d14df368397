"""Equivalence predicates that are not equivalences: "can share a component" must be transitive.

Two values of a characteristic *can share a component* when some component serves both. The
article's partition into UI configurations assumes this relation is an equivalence; it is
exactly when no value is in two components that each hold a value the other lacks. When it is
not, the check gives a witness triple A ~ B (both in X), B ~ C (both in Y), but A and C share
no component, for every such pair of components X, Y. The solver then has to solve a minimum
cover, and which configuration a robot gets depends on the rest of the team.

Not here: overlaps as such (:mod:`solver.check.coverage`); nested components (X inside Y) make
no triple and are only an overlap.
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext
from solver.check.finding import Check, Finding
from solver.constraints import Value
from solver.rules import Characteristic, Component

__all__ = ["CHECKS", "witness_triple"]


def witness_triple(characteristic: Characteristic, first: Component,
                   second: Component) -> tuple[Value, Value, Value] | None:
    """A ~ B in ``first``, B ~ C in ``second``, A and C in no common component; or ``None``."""
    in_first, in_second = set(first.values), set(second.values)
    shared = [v for v in characteristic.values if v in in_first and v in in_second]
    if not shared:
        return None
    only_first = [v for v in characteristic.values if v in in_first and v not in in_second]
    only_second = [v for v in characteristic.values if v in in_second and v not in in_first]
    for a in only_first:
        components_a = set(characteristic.membership[characteristic.positions[a]])
        for c in only_second:
            if components_a.isdisjoint(characteristic.membership[characteristic.positions[c]]):
                return a, shared[0], c
    return None


def _show(characteristic: Characteristic, value: Value) -> str:
    return str(value) if characteristic.kind == "integer" else repr(str(value))


def _non_transitive(context: RulesContext) -> Iterator[Finding]:
    for characteristic in context.rules.characteristics:
        if characteristic.is_partition:
            continue
        components = characteristic.components
        for i, first in enumerate(components):
            for second in components[i + 1:]:
                triple = witness_triple(characteristic, first, second)
                if triple is None:
                    continue
                a, b, c = (_show(characteristic, v) for v in triple)
                yield NON_TRANSITIVE.finding(
                    context.component_location(characteristic, second),
                    f"'can share a component' is not transitive for {characteristic.name}: "
                    f"{a} ~ {b} (both in {first.name!r}) and {b} ~ {c} (both in "
                    f"{second.name!r}), but {a} and {c} share no component")


NON_TRANSITIVE = Check(
    "non-transitive", "warning", "rules",
    "The relation \"two values can share a UI component\" is not an equivalence: overlapping "
    "components X and Y give a witness triple A ~ B (both in X), B ~ C (both in Y) with A and "
    "C in no common component. UI configurations are then no longer equivalence classes; the "
    "solver finds a minimum cover instead and the configuration a robot gets can depend on "
    "the rest of the team.",
    _non_transitive)

CHECKS: tuple[Check[RulesContext], ...] = (NON_TRANSITIVE,)
