"""The operator's active selection: which robot, control mode and sensor, and its configuration.

The convention (documented in the README): an operator station sets

* ``/teleop_ui/active_robot``: the robot's namespace (``/uav1``; ``/`` for a robot described
  at the root),
* ``/teleop_ui/active_motion_control``: a motion control of the rule set (``Flight``),
* ``/teleop_ui/active_sensor_type`` (optional): a sensor type (``2D Camera``),

and the watcher answers in ``/teleop_ui/ui_configuration`` with the JSON contract of
``teleop-ui assign`` (number, components or the default's reasons) plus the robot's namespace
and the writing watcher's node name, so any ROS node can read the configuration with
``rosparam get``.

:func:`choose` turns a robot's combinations and the values asked for into one combination:
a value the robot has narrows its combinations to it; a value it does not have is used anyway
(the operator asked for it) with a note; where several combinations remain, the first in the
rule set's value order is taken, with a note saying which and how to choose. The same choice
serves ``teleop-ui assign --master --robot``.

Not here: reading or writing the master (:mod:`solver.live.watcher`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from solver.core.assignment import Assignment, assign, check_names
from solver.core.contracts import assignment_data
from solver.core.solution import Solution
from solver.identify.profile import Profile
from solver.live.discovery import normalise_namespace
from solver.live.graph import MISSING
from solver.live.robot import LiveRobot
from solver.live.values import selection_text
from solver.untrusted import shown

__all__ = [
    "NAMESPACE",
    "REQUEST_PARAMS",
    "RESULT_PARAM",
    "WRITER_KEY",
    "ActiveSelection",
    "Request",
    "choose",
    "read_request",
    "requested_values",
    "select",
    "selection_data",
    "ui_configuration_value",
]

NAMESPACE = "/teleop_ui"
RESULT_PARAM = f"{NAMESPACE}/ui_configuration"
# The key of RESULT_PARAM naming the watcher that wrote it (its node name).
WRITER_KEY = "watcher"
# parameter (under /teleop_ui) -> the profile role whose characteristic it sets
REQUEST_PARAMS = (
    ("active_motion_control", "motion_control"),
    ("active_sensor_type", "sensor_type"),
)


@dataclass(frozen=True, slots=True)
class Request:
    """What the operator station asked for (``None``: not set)."""

    robot: str | None = None
    motion_control: str | None = None
    sensor_type: str | None = None
    notes: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class ActiveSelection:
    """The answer to a :class:`Request`: the combination's assignment, with notes."""

    request: Request
    assignment: Assignment | None = None
    notes: tuple[str, ...] = ()


def read_request(params: Mapping[str, Any]) -> Request:
    """The request in the ``/teleop_ui`` parameters (keys relative to it); a value that is not
    short text is ignored with a note (:func:`solver.live.values.selection_text`)."""
    notes: list[str] = []
    values: dict[str, str | None] = {}
    for name in ("active_robot", *(param for param, _ in REQUEST_PARAMS)):
        value = params.get(name, MISSING)
        if value is MISSING:
            values[name] = None
            continue
        values[name], note = selection_text(f"{NAMESPACE}/{name}", value)
        if note is not None:
            notes.append(note)
    robot = values["active_robot"]
    return Request(
        None if robot is None else normalise_namespace(robot),
        values["active_motion_control"],
        values["active_sensor_type"],
        tuple(notes),
    )


def _order(solution: Solution, values: Mapping[str, str]) -> tuple[int, ...]:
    """A combination's position in the rule set's declared value order."""
    key = []
    for characteristic in solution.rules.characteristics:
        text = values.get(characteristic.name)
        value = None if text is None else characteristic.parse_value(text)
        position = None if value is None else characteristic.index(value)
        key.append(len(characteristic.values) if position is None else position)
    return tuple(key)


def choose(
    robot: LiveRobot, given: Mapping[str, str], solution: Solution
) -> tuple[Assignment, tuple[str, ...]]:
    """One combination of ``robot`` with the ``given`` values (see the module docstring).

    :class:`~solver.errors.InputError` for a characteristic name the rules do not have.
    """
    rules = solution.rules
    check_names(rules, given)
    notes: list[str] = []
    known = {tuple(c.values): c.assignment for c in robot.combinations}
    candidates = [dict(c.values) for c in robot.combinations]
    for name, value in given.items():
        matching = [c for c in candidates if c.get(name) == value]
        if matching:
            candidates = matching
            continue
        offered = list(dict.fromkeys(c[name] for c in candidates if name in c))
        if offered:
            notes.append(
                f"{shown(robot.namespace)} does not offer {name} {shown(value, quoted=True)} "
                f"(it has {_listed(offered)}); using it as asked"
            )
        candidates = [{**c, name: value} for c in candidates] or [{name: value}]
    unique = {tuple((n, c[n]) for n in rules.names if n in c): c for c in candidates}
    ordered = sorted(unique.items(), key=lambda item: _order(solution, item[1]))
    chosen_key, chosen = ordered[0]
    if len(ordered) > 1:
        for name in rules.names:
            options = list(dict.fromkeys(c.get(name) for _, c in ordered))
            if len(options) > 1:
                notes.append(
                    f"{shown(robot.namespace)} has several {name} values ({_listed(options)}): "
                    "using "
                    f"{shown(chosen.get(name))}; give {name} to choose"
                )
                break
    assignment = known.get(chosen_key)
    if assignment is None:
        assignment = assign(solution, dict(chosen_key))
    return assignment, tuple(notes)


def _listed(values: Iterable[object]) -> str:
    """Values from a robot, each shown cut short (:func:`~solver.untrusted.shown`)."""
    return ", ".join(shown(str(value)) for value in values)


def requested_values(
    request: Request, solution: Solution, profile: Profile
) -> tuple[dict[str, str], tuple[str, ...]]:
    """The characteristic values the request sets (by the profile's roles), and notes on the
    parameters the rule set has no characteristic for."""
    given: dict[str, str] = {}
    notes: list[str] = []
    for param, role in REQUEST_PARAMS:
        value = getattr(request, role)
        name = profile.role(role)
        if value is None:
            continue
        if name not in solution.rules.names:
            notes.append(
                f"{NAMESPACE}/{param} ignored: the rule set has no {shown(name, quoted=True)}"
            )
            continue
        given[name] = value
    return given, tuple(notes)


def select(
    request: Request, robots: Mapping[str, LiveRobot], solution: Solution, profile: Profile
) -> ActiveSelection | None:
    """The configuration for ``request``; ``None`` when no robot is active."""
    if request.robot is None:
        return None
    robot = robots.get(request.robot)
    given, ignored = requested_values(request, solution, profile)
    notes = [*request.notes, *ignored]
    if robot is None or robot.identification is None:
        if robot is not None:
            reason = f"robot {shown(request.robot)} could not be identified: {robot.error}"
        elif robots:
            there = ", ".join(shown(namespace) for namespace in sorted(robots))
            reason = f"no robot {shown(request.robot)} on the master (robots: {there})"
        else:
            reason = f"no robot {shown(request.robot)} on the master (it has no robots)"
        default = assign(solution, given)
        return ActiveSelection(
            request,
            Assignment(
                default.given,
                solution.default_configuration,
                None,
                (reason, *default.reasons),
                default.relevant,
            ),
            tuple(notes),
        )
    assignment, chosen_notes = choose(robot, given, solution)
    return ActiveSelection(request, assignment, tuple(notes) + chosen_notes)


def selection_data(
    selection: ActiveSelection | None, request: Request, solution: Solution
) -> dict[str, Any]:
    """The fields of a ``selection_changed`` event (see the README)."""
    return {
        "robot": request.robot,
        "motion_control": request.motion_control,
        "sensor_type": request.sensor_type,
        "assignment": None
        if selection is None or selection.assignment is None
        else assignment_data(solution, selection.assignment),
        "notes": list(request.notes if selection is None else selection.notes),
    }


def _without_none(value: Any) -> Any:
    """ROS's XML-RPC has no ``None``: absent keys stand for it."""
    if isinstance(value, dict):
        return {k: _without_none(v) for k, v in value.items() if v is not None}
    if isinstance(value, list):
        return [_without_none(v) for v in value]
    return value


def ui_configuration_value(
    selection: ActiveSelection | None, solution: Solution, writer: str
) -> dict[str, Any] | None:
    """What the watcher ``writer`` (its node name) writes to ``/teleop_ui/ui_configuration``
    (``None``: delete it)."""
    if selection is None or selection.assignment is None:
        return None
    data = {
        "robot": selection.request.robot,
        **assignment_data(solution, selection.assignment),
        "notes": list(selection.notes),
        WRITER_KEY: writer,
    }
    value: dict[str, Any] = _without_none(data)
    return value
