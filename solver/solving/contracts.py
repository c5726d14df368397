"""The JSON of the parts solutions and assignments are made of: a configuration and its
components (the counts a count characteristic serves as runs).

The documented, stable shapes of a whole :class:`~solver.solving.solution.Solution` and an
:class:`~solver.solving.assignment.Assignment` live with those types
(:func:`~solver.solving.solution.solution_data` is ``Solution.to_dict()``,
:func:`~solver.solving.assignment.assignment_data`), built from these, so every consumer (the
CLI's ``--format json``, batch summaries, live events, the identification output) speaks the
same JSON. Text, CSV and Markdown views of the same data are in
:mod:`solver.reporting.render`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from solver.core.partition import Configuration
    from solver.core.ruleset import Characteristic, Component, RuleSet

__all__ = ["component_data", "configuration_data", "default_components", "integer_runs"]


def component_data(
    characteristic: Characteristic, component: Component, served: Sequence[Any]
) -> dict[str, Any]:
    """One component of a configuration: its characteristic, its name, the values served."""
    data: dict[str, Any] = {"characteristic": characteristic.name, "component": component.name}
    if characteristic.kind == "integer":
        counts = sorted(int(v) for v in served)
        data["range"] = [counts[0], counts[-1]]
        data["clusters"] = [component.clusters(counts[0]), component.clusters(counts[-1])]
        data["counts"] = [list(run) for run in integer_runs(counts)]
    else:
        data["values"] = list(served)
    return data


def configuration_data(rules: RuleSet, configuration: Configuration) -> dict[str, Any]:
    """One configuration: number, kinematic type, components and the robots it serves."""
    return {
        "number": configuration.number,
        "kinematic_type": configuration.kinematic_type,
        "valid_robots": configuration.robots,
        "components": [
            component_data(c, component, served)
            for c, component, served in zip(
                rules.characteristics, configuration.components, configuration.served, strict=True
            )
        ],
    }


def integer_runs(numbers: Sequence[int]) -> list[tuple[int, int]]:
    """Sorted whole numbers as runs of consecutive ones: [1, 2, 3, 7] -> [(1, 3), (7, 7)]."""
    found: list[tuple[int, int]] = []
    for number in numbers:
        if found and number == found[-1][1] + 1:
            found[-1] = (found[-1][0], number)
        else:
            found.append((number, number))
    return found


def default_components(rules: RuleSet) -> dict[str, list[str]]:
    """The default configuration's components: every component of every characteristic."""
    return {c.name: [component.name for component in c.components] for c in rules.characteristics}
