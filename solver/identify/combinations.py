"""A real robot's characteristic combinations and the UI configuration of each.

An identified robot with two motion controls and three sensor types stands for six valid robots
of the article: the operator works with one control mode and one sensor at a time. Each
combination is (kinematic type, motion control, sensor type, sensor count) with the count being
the robot's number of sensors that have a presentation, and is given its UI configuration by
:func:`solver.assign` against a solved team, or the default configuration with the reasons (a
kinematic type the rule set or team lacks, a control outside the selection, too many sensors).
The characteristics filled are the profile's roles; any other characteristic of the rule set is
left unknown, which :func:`solver.assign` reports.

Not here: identification (:mod:`solver.identify.identification`).
"""

from __future__ import annotations

from dataclasses import dataclass

from solver.core.assignment import Assignment, assign
from solver.core.solution import Solution
from solver.identify.identification import Identification
from solver.identify.profile import Profile

__all__ = ["Combination", "combinations"]


@dataclass(frozen=True, slots=True)
class Combination:
    values: tuple[tuple[str, str], ...]
    assignment: Assignment


def combinations(
    identification: Identification, solution: Solution, profile: Profile
) -> tuple[Combination, ...]:
    """One combination per motion control x sensor type (at least one, with what is known)."""
    rules = solution.rules
    base: dict[str, str] = {
        rules.team_key: identification.kinematic_type or identification.structure
    }
    control_name = profile.role("motion_control")
    type_name = profile.role("sensor_type")
    count_name = profile.role("sensor_count")
    if count_name in rules.names and identification.sensor_count:
        base[count_name] = str(identification.sensor_count)
    controls: list[str | None] = [c.motion_control for c in identification.motion_controls]
    types: list[str | None] = list(identification.sensor_types)
    found = []
    for control in controls or [None]:
        for sensor_type in types or [None]:
            values = dict(base)
            if control is not None and control_name in rules.names:
                values[control_name] = control
            if sensor_type is not None and type_name in rules.names:
                values[type_name] = sensor_type
            ordered = tuple((name, values[name]) for name in rules.names if name in values)
            found.append(Combination(ordered, assign(solution, dict(ordered))))
    return tuple(found)
