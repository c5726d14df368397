"""A real robot's characteristic combinations and the UI configuration of each.

An identified robot with two motion controls and three sensor types stands for six valid robots
of the article: the operator works with one control mode and one sensor at a time. Each
combination is (kinematic type, motion control, sensor type, sensor count) with the count being
the robot's number of sensors that have a presentation, and is given its UI configuration by
:func:`solver.assign` against a solved team, or the default configuration with the reasons (a
kinematic type the rule set or team lacks, a control outside the selection, too many sensors).
The characteristics filled are the rule set's ``team_key`` (the kinematic type) and the
profile's roles (:data:`~solver.identify.profile.ROLES`: which of the rule set's characteristics
receives the motion control, the sensor type and the sensor count); ``given`` values (``--set``,
or a robot's own on a live graph) replace or complete them. Any other characteristic is left
unknown, which :func:`solver.assign` reports and :func:`missing` lists.

Not here: identification (:mod:`solver.identify.identification`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from solver.identify.profile import MOTION_CONTROL, SENSOR_COUNT, SENSOR_TYPE, Profile

if TYPE_CHECKING:
    from solver.identify.identification import Identification
    from solver.solving.assignment import Assignment
    from solver.solving.solution import Solution

__all__ = ["Combination", "combinations", "missing"]


@dataclass(frozen=True, slots=True)
class Combination:
    values: tuple[tuple[str, str], ...]
    assignment: Assignment


def combinations(
    identification: Identification,
    solution: Solution,
    profile: Profile,
    given: Mapping[str, str] | None = None,
) -> tuple[Combination, ...]:
    """One combination per motion control x sensor type (at least one, with what is known);
    ``given`` (characteristic name -> value) replaces what identification found for those
    characteristics and completes the others (a name the rules lack is an
    :class:`~solver.errors.InputError`, as in :func:`solver.assign`)."""
    from solver.solving.assignment import assign  # with a solved team only (identify --team)

    rules = solution.rules
    given = dict(given or {})
    base: dict[str, str] = {
        rules.team_key: identification.kinematic_type or identification.structure
    }
    control_name = profile.role(MOTION_CONTROL)
    type_name = profile.role(SENSOR_TYPE)
    count_name = profile.role(SENSOR_COUNT)
    if count_name in rules.names and identification.sensor_count:
        base[count_name] = str(identification.sensor_count)
    controls: list[str | None] = [c.motion_control for c in identification.motion_controls]
    types: list[str | None] = list(identification.sensor_types)
    if control_name in given:
        controls = [None]
    if type_name in given:
        types = [None]
    found = []
    for control in controls or [None]:
        for sensor_type in types or [None]:
            values = dict(base)
            if control is not None and control_name in rules.names:
                values[control_name] = control
            if sensor_type is not None and type_name in rules.names:
                values[type_name] = sensor_type
            values.update(given)
            ordered = tuple((name, values[name]) for name in rules.names if name in values)
            found.append(Combination(ordered, assign(solution, {**dict(ordered), **given})))
    return tuple(found)


def missing(found: Sequence[Combination], solution: Solution) -> tuple[str, ...]:
    """The rule set's characteristics no combination has a value for, in the rule set's order."""
    known = {name for combination in found for name, _ in combination.values}
    return tuple(name for name in solution.rules.names if name not in known)
