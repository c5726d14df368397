"""Core values and components: what the constraints force on every robot of a kinematic type.

A value is *core* for a kinematic type when every valid robot of that type has it (all other
values of its characteristic are excluded); a component is core when every such robot needs
it although several of its values remain possible. Feature-model tools call these core
features. They are information, not faults: a team need not select a core value, and a UI
designer can build the component into every configuration of that type. Each comes with a
deletion-minimal set of constraints that forces it.

Not here: values no robot can have (:mod:`solver.check.dead`). Nothing is reported for void
types or a void rule set.
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.context import RulesContext, values_text
from solver.check.finding import Check, Finding
from solver.core.constraints import Value
from solver.core.ruleset import Component
from solver.untrusted import shown

__all__ = ["CHECKS"]


def _forced(context: RulesContext, *, components: bool) -> Iterator[Finding]:
    analysis = context.analysis
    rules = context.rules
    if not rules.constraints or analysis.is_void:
        return
    key = rules.key
    component_sets = _ComponentSets()
    for kinematic_type, live in analysis.type_live.items():
        if kinematic_type in analysis.void_types:
            continue
        analysis.check_time()
        domains = analysis.type_domains(kinematic_type)
        location = context.value_location(key, kinematic_type)
        for position, characteristic in enumerate(rules.characteristics):
            if position == rules.key_position or len(characteristic.values) < 2:
                continue
            possible = live[position]
            if not components:
                if len(possible) != 1:
                    continue
                others = [v for v in characteristic.values if v not in possible]
                conflict = analysis.minimal_conflict(analysis.narrowed(domains, position, others))
                yield CORE_VALUE.finding(
                    location,
                    f"every valid {kinematic_type} robot has {characteristic.name} "
                    f"{values_text(characteristic, possible)}: forced by "
                    f"{context.constraint_list(conflict)}",
                    context.constraint_related(conflict, "forces it"),
                )
                continue
            if (
                len(possible) < 2
                or not characteristic.declared_components
                or len(characteristic.components) < 2
            ):
                continue
            for component in characteristic.components:
                # A component serving every value is needed by construction, not forced.
                if len(component.values) == len(characteristic.values) or not (
                    component_sets.holds(position, component, possible)
                ):
                    continue
                others = [v for v in characteristic.values if v not in component.values]
                conflict = analysis.minimal_conflict(analysis.narrowed(domains, position, others))
                yield CORE_COMPONENT.finding(
                    location,
                    f"every valid {kinematic_type} robot needs {characteristic.name} "
                    f"component {shown(component.name, quoted=True)} (its values "
                    f"{values_text(characteristic, possible)} remain): forced by "
                    f"{context.constraint_list(conflict)}",
                    context.constraint_related(conflict, "forces it"),
                )


class _ComponentSets:
    """Each component's values as a set, made once for all kinematic types (each of 20,000
    types made its own set of a component's 50,000 counts)."""

    def __init__(self) -> None:
        self._sets: dict[tuple[int, int], frozenset[Value]] = {}

    def holds(self, position: int, component: Component, values: frozenset[Value]) -> bool:
        """Whether every one of ``values`` is a value of ``component``."""
        if len(values) > len(component.values):
            return False
        key = (position, component.index)
        if key not in self._sets:
            self._sets[key] = frozenset(component.values)
        return values <= self._sets[key]


def _core_values(context: RulesContext) -> Iterator[Finding]:
    yield from _forced(context, components=False)


def _core_components(context: RulesContext) -> Iterator[Finding]:
    yield from _forced(context, components=True)


CORE_VALUE = Check(
    "core-value",
    "info",
    "rules",
    "A value that every valid robot of a kinematic type has, because the constraints exclude "
    "all the other values of its characteristic (for example, every UAV flies with Flight). "
    "Reported with the constraints that force it; teams need not select it.",
    _core_values,
)
CORE_COMPONENT = Check(
    "core-component",
    "info",
    "rules",
    "A UI component that every valid robot of a kinematic type needs, although more than one "
    "of its values remains possible (for example, only cameras of the visual-display group are "
    "left for a type). Every UI configuration of that type contains it.",
    _core_components,
)

CHECKS: tuple[Check[RulesContext], ...] = (CORE_VALUE, CORE_COMPONENT)
