"""The operator's active selection: which robot, and any characteristic's value; its configuration.

The convention (docs/live.md): an operator station sets

* ``/teleop_ui/active_robot``: the robot's namespace (``/uav1``; ``/`` for a robot described
  at the root),
* ``/teleop_ui/active_<characteristic>`` for any characteristic of the rule set it wants to
  choose (``/teleop_ui/active_motion_control: Flight`` under the article's rules,
  ``/teleop_ui/active_comm_link: LTE`` under a rule set with a ``comm_link``),

and the watcher answers in ``/teleop_ui/ui_configuration`` with the JSON contract of
``teleop-ui assign`` (number, components or the default's reasons) plus the robot's namespace
and the writing watcher's node name, so any ROS node can read the configuration with
``rosparam get``; a watcher that writes layouts (``watch --layouts``) adds ``layouts``, where
the answer's layouts are (:class:`LayoutLink`: each target's file, its address when served,
the team layout's tab). An ``active_*`` name the rules do not know is kept in
:attr:`Request.unknown` (the watcher warns of it).

:func:`choose` turns a robot's combinations and the values asked for into one combination:
a value the robot has narrows its combinations to it; a value it does not have is used anyway
(the operator asked for it) with a note; where several combinations remain, the first in the
rule set's value order is taken, with a note saying which and how to choose. The same choice
serves ``teleop-ui assign --master --robot``.

Not here: reading or writing the master (:mod:`solver.live.watcher`), the robot's own and fixed
values (:mod:`solver.live.given`).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from solver.live.discovery import normalise_namespace
from solver.live.given import ACTIVE_PREFIX
from solver.live.graph import MISSING
from solver.live.robot import LiveRobot
from solver.live.values import selection_text
from solver.solving.assignment import Assignment, assign, assignment_data, check_names
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = [
    "ACTIVE_ROBOT",
    "NAMESPACE",
    "RESULT_PARAM",
    "WRITER_KEY",
    "ActiveSelection",
    "LayoutLink",
    "Request",
    "choose",
    "layouts_data",
    "read_request",
    "select",
    "selection_data",
    "ui_configuration_value",
]

NAMESPACE = "/teleop_ui"
RESULT_PARAM = f"{NAMESPACE}/ui_configuration"
ACTIVE_ROBOT = f"{ACTIVE_PREFIX}robot"
# The key of RESULT_PARAM naming the watcher that wrote it (its node name).
WRITER_KEY = "watcher"


@dataclass(frozen=True, slots=True)
class Request:
    """What the operator station asked for: the robot (``None``: not set), the values of
    characteristics (name, value) in the rule set's order, notes on values ignored, and the
    ``active_*`` parameter names the rules know no characteristic of."""

    robot: str | None = None
    values: tuple[tuple[str, str], ...] = ()
    notes: tuple[str, ...] = ()
    unknown: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class LayoutLink:
    """Where one layout of an answer is: its ``target`` (``foxglove``: the active robot's
    layout of the configuration; ``team``: the team layout), the file's absolute ``path``, its
    ``url`` where the watcher serves it, and for the team layout the ``tab`` of the answer's
    (robot, configuration) (``None``: the team layout has none)."""

    target: str
    path: str
    url: str | None = None
    tab: int | None = None


@dataclass(frozen=True, slots=True)
class ActiveSelection:
    """The answer to a :class:`Request`: the combination's assignment, with notes, and where
    its layouts are (``None``: the watcher writes none)."""

    request: Request
    assignment: Assignment | None = None
    notes: tuple[str, ...] = ()
    layouts: tuple[LayoutLink, ...] | None = None


def read_request(params: Mapping[str, Any], names: Collection[str]) -> Request:
    """The request in the ``/teleop_ui`` parameters (keys relative to it), for a rule set whose
    characteristics are ``names`` (in order); a value that is not short text is ignored with a
    note (:func:`solver.live.values.selection_text`)."""
    notes: list[str] = []
    asked: dict[str, str] = {}
    robot: str | None = None
    keys = [ACTIVE_ROBOT, *(f"{ACTIVE_PREFIX}{name}" for name in names)]
    for key in keys:
        value = params.get(key, MISSING)
        if value is MISSING:
            continue
        text, note = selection_text(f"{NAMESPACE}/{key}", value)
        if note is not None:
            notes.append(note)
        if text is None:
            continue
        if key == ACTIVE_ROBOT:
            robot = normalise_namespace(text)
        else:
            asked[key[len(ACTIVE_PREFIX) :]] = text
    known = set(keys)
    unknown = sorted(
        str(key) for key in params if str(key).startswith(ACTIVE_PREFIX) and key not in known
    )
    values = tuple((name, asked[name]) for name in names if name in asked)
    return Request(robot, values, tuple(notes), tuple(unknown))


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
    candidates, notes = _narrowed(robot, given)
    unique = {tuple((n, c[n]) for n in rules.names if n in c): c for c in candidates}
    ordered = sorted(unique.items(), key=lambda item: _order(solution, item[1]))
    chosen_key = ordered[0][0]
    several = _several(robot.namespace, [c for _, c in ordered], rules.names)
    known = {tuple(c.values): c.assignment for c in robot.combinations}
    assignment = known.get(chosen_key)
    if assignment is None:
        assignment = assign(solution, dict(chosen_key))
    return assignment, (*notes, *several)


def _narrowed(robot: LiveRobot, given: Mapping[str, str]) -> tuple[list[dict[str, str]], list[str]]:
    """The robot's combinations with the ``given`` values: those that have a value, else all
    of them with it put in (noted when the robot has others)."""
    notes: list[str] = []
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
    return candidates, notes


def _several(
    namespace: str, ordered: list[dict[str, str]], names: Iterable[str]
) -> tuple[str, ...]:
    """A note on the first characteristic with several values left, the first one taken."""
    for name in names:
        options = list(dict.fromkeys(c.get(name) for c in ordered))
        if len(options) > 1:
            return (
                f"{shown(namespace)} has several {name} values ({_listed(options)}): using "
                f"{shown(ordered[0].get(name))}; give {name} to choose",
            )
    return ()


def _listed(values: Iterable[object]) -> str:
    """Values from a robot, each shown cut short (:func:`~solver.untrusted.shown`)."""
    return ", ".join(shown(str(value)) for value in values)


def select(
    request: Request, robots: Mapping[str, LiveRobot], solution: Solution
) -> ActiveSelection | None:
    """The configuration for ``request``; ``None`` when no robot is active."""
    if request.robot is None:
        return None
    robot = robots.get(request.robot)
    given = dict(request.values)
    notes = list(request.notes)
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
    chosen = dict(assignment.given)
    lacking = [
        f"{shown(robot.namespace)} has no {name}: give it with {how}"
        for name, how in robot.missing
        if name not in chosen
    ]
    return ActiveSelection(request, assignment, (*notes, *chosen_notes, *lacking))


def selection_data(
    selection: ActiveSelection | None,
    request: Request,
    solution: Solution,
    *,
    layouts: bool = False,
) -> dict[str, Any]:
    """The fields of a ``selection_changed`` event (see docs/live.md): ``active`` has every
    characteristic of the rule set, with the value asked for or ``None``. ``layouts``: the
    watcher writes layouts, and the event says where the answer's are (``layout``, the active
    robot's, as before ``layouts`` came; ``layouts``, :func:`layouts_data`, ``None`` with no
    active robot)."""
    asked = dict(request.values)
    data = {
        "robot": request.robot,
        "active": {name: asked.get(name) for name in solution.rules.names},
        "assignment": None
        if selection is None or selection.assignment is None
        else assignment_data(solution, selection.assignment),
        "notes": list(request.notes if selection is None else selection.notes),
    }
    if layouts:
        links = None if selection is None else selection.layouts
        own = [link.path for link in links or () if link.target == "foxglove"]
        data["layout"] = own[0] if own else None
        data["layouts"] = None if links is None else layouts_data(links)
    return data


def layouts_data(links: tuple[LayoutLink, ...]) -> dict[str, Any]:
    """``{"foxglove": {"path", "url"}, "team": {"path", "url", "tab"}}``: ``url`` only where
    served; ``tab`` for the team layout (``None``: it has no tab for the answer)."""
    data: dict[str, Any] = {}
    for link in links:
        entry: dict[str, Any] = {"path": link.path}
        if link.url is not None:
            entry["url"] = link.url
        if link.target == "team":
            entry["tab"] = link.tab
        data[link.target] = entry
    return data


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
        **({} if selection.layouts is None else {"layouts": layouts_data(selection.layouts)}),
        WRITER_KEY: writer,
    }
    value: dict[str, Any] = _without_none(data)
    return value
