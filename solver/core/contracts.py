"""The JSON contracts of ``solve`` and ``assign``: the documented, stable shapes of a
:class:`~solver.core.solution.Solution` and an :class:`~solver.core.assignment.Assignment`.

They live with the types they describe (``Solution.to_dict()`` is :func:`solution_data`), so
every consumer (the CLI's ``--format json``, batch summaries, live events, the identification
output) speaks the same JSON. Text, CSV and Markdown views of the same data are in
:mod:`solver.reporting.render`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from solver.core.assignment import Assignment
    from solver.core.partition import Configuration
    from solver.core.ruleset import Characteristic, Component, RuleSet
    from solver.core.solution import Solution, TypeSummary

__all__ = [
    "assignment_data",
    "component_data",
    "configuration_data",
    "counts_data",
    "integer_runs",
    "solution_data",
    "solution_warnings",
    "summary_data",
]


def _ratio(summary: TypeSummary) -> float | None:
    ratio = summary.reduction_ratio
    return None if ratio is None else round(ratio, 4)


def summary_data(summary: TypeSummary) -> dict[str, Any]:
    data = {
        "kinematic_type": summary.kinematic_type,
        "valid_robots": summary.valid_robots,
        "ui_configurations": summary.ui_configurations,
        "reduction_ratio": _ratio(summary),
        "unserved_robots": summary.unserved_robots,
    }
    if summary.method:
        data["method"] = summary.method
    return data


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


def _default_components(rules: RuleSet) -> dict[str, list[str]]:
    return {c.name: [component.name for component in c.components] for c in rules.characteristics}


def solution_data(solution: Solution, *, configurations: bool = False) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui solve --format json``."""
    rules = solution.rules
    team = solution.team
    data: dict[str, Any] = {
        "team": team.name,
        "team_file": team.file,
        "rules": rules.name,
        "rules_file": rules.file,
        "engine": solution.engine,
        "bound": solution.bound,
        "bound_factors": dict(zip(rules.names, rules.bound_factors, strict=True)),
        "by_type": [summary_data(t) for t in solution.by_type],
        "totals": {k: v for k, v in summary_data(solution.totals).items() if k != "kinematic_type"},
        "default_configuration": solution.default_configuration,
        "default_components": _default_components(rules),
        "listed": solution.listed,
        "proven_minimal": solution.proven_minimal,
        "published": None
        if team.published is None
        else {
            "valid_robots": team.published.valid_robots,
            "ui_configurations": team.published.ui_configurations,
            "source": team.published.source,
        },
        # What text output prints as "warning: ..." lines (solution_warnings), for programs.
        "warnings": [w.removeprefix("warning: ") for w in solution_warnings(solution)],
    }
    if configurations:
        data["configurations"] = [configuration_data(rules, c) for c in solution.configurations]
    return data


def counts_data(solution: Solution) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui count --format json``: per-type counts only."""
    return {
        "team": solution.team.name,
        "rules": solution.rules.name,
        "rules_file": solution.rules.file,
        "bound": solution.bound,
        "by_type": [summary_data(t) for t in solution.by_type],
        "totals": {k: v for k, v in summary_data(solution.totals).items() if k != "kinematic_type"},
        "default_configuration": solution.default_configuration,
    }


def assignment_data(solution: Solution, assignment: Assignment) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui assign --format json``."""
    configuration = assignment.configuration
    return {
        "team": solution.team.name,
        "combination": dict(assignment.given),
        "configuration": assignment.number,
        "default": assignment.is_default,
        "default_configuration": solution.default_configuration,
        "kinematic_type": None if configuration is None else configuration.kinematic_type,
        "components": None
        if configuration is None
        else configuration_data(solution.rules, configuration)["components"],
        "reasons": list(assignment.reasons),
        "relevant_components": {name: list(names) for name, names in assignment.relevant},
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


def solution_warnings(solution: Solution) -> list[str]:
    """What a reader of the counts must know: selected values the constraints exclude, robots
    left unserved, a minimum not proven. The one place for them: solve, report and batch."""
    warnings = [
        f"warning: the rules' constraints exclude what the team selects: "
        f"{removed.describe()}; such robots get the default configuration"
        for removed in solution.removed
    ]
    if solution.totals.unserved_robots:
        warnings.append(
            f"warning: {solution.totals.unserved_robots} valid robots have a value "
            "in no component and get the default configuration (run teleop-ui "
            "check)"
        )
    if not solution.proven_minimal:
        warnings.append(
            "warning: overlapping components; the configuration count is the best "
            "found, not proven minimal"
        )
    return warnings
