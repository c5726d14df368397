"""Events as JSON lines (``--format json``) or as text for a person (``--format text``).

JSON: one compact object per line, keys in the documented order, UTF-8 kept, so a consumer
reads the stream line by line (``jq -c``, a ROS node, a UI). Text: a line per event, with the
robot's combinations and UI configuration numbers indented beneath it. Everything the graph
gave (namespaces, robot names, values, messages) is shown through
:func:`~solver.untrusted.shown`: escaped, so no name starts a forged line, and cut short.
Paths and addresses of the layouts the watcher wrote (``watch --layouts``) are the tool's own,
which an operator copies: shown escaped and whole, never cut, each on a line of its own.

:func:`render_live_assignment` is the output of ``teleop-ui assign --master``: ``assign``'s
own text or JSON, with the robot's namespace and the notes on how the combination was chosen.

Not here: the schema itself (:mod:`solver.live.events`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from solver.files.output import dumps
from solver.live.events import (
    Event,
    GraphWarning,
    MasterBack,
    MasterLost,
    Rival,
    RivalGone,
    RobotAdded,
    RobotChanged,
    RobotRemoved,
    SelectionChanged,
    Synced,
    event_data,
)
from solver.live.query import LiveAssignment
from solver.live.robot import LiveRobot
from solver.reporting.render import render_assignment
from solver.solving.assignment import Assignment, assignment_data
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = ["json_line", "render_event", "render_live_assignment", "text_lines"]

_WIDTH = 16  # the label column of the text format


def json_line(event: Event, solution: Solution) -> str:
    return dumps(event_data(event, solution), indent=None)


def render_event(event: Event, solution: Solution, fmt: str = "json") -> str:
    """One event in ``fmt`` (``json`` or ``text``), ending in a newline."""
    if fmt == "json":
        return json_line(event, solution)
    return "".join(line + "\n" for line in text_lines(event))


def _values(given: Any) -> str:
    return ", ".join(shown(value) for _, value in given) or "(nothing known)"


def _configuration(assignment: Assignment) -> str:
    if assignment.is_default:
        reasons = shown("; ".join(assignment.reasons), limit=None)
        return f"{assignment.number} (default): {reasons}"
    return str(assignment.number)


def _robot_lines(label: str, robot: LiveRobot, changed: tuple[str, ...] = ()) -> list[str]:
    head = f"{label:<{_WIDTH}}{shown(robot.namespace)}"
    found = robot.identification
    if found is None:
        return [
            f"{head}  cannot be identified:",
            *(
                " " * (_WIDTH + 2) + shown(line, limit=None)
                for line in (robot.error or "").splitlines()
            ),
        ]
    kinematic = shown(found.kinematic_type or "no kinematic type in the rule set")
    controls = ", ".join(shown(c.motion_control) for c in found.motion_controls) or "none found"
    head += (
        f"  {shown(found.robot)}: {kinematic} (structure {shown(found.structure)}, confidence "
        f"{found.confidence:.2f}); {found.sensor_count} sensor(s); motion controls "
        f"{controls}"
    )
    if changed:
        head += f"  [changed: {shown(', '.join(changed), limit=None)}]"
    indent = " " * (_WIDTH + 2)
    declared = [] if found.declared is None else [f"{indent}declared: {shown(found.declared)}"]
    return [
        head,
        *declared,
        *(
            f"{indent}declared and read differ: {shown(line, limit=None)}"
            for line in found.disagreements
        ),
        *(
            f"{indent}given: {value.characteristic} {shown(value.value)} ({shown(value.source)})"
            for value in robot.given
        ),
        *(
            f"{indent}UI configuration {_configuration(c.assignment)}  <- {_values(c.values)}"
            for c in robot.combinations
        ),
        *(f"{indent}missing {name}: give it with {how}" for name, how in robot.missing),
    ]


def _label(label: str, text: str) -> list[str]:
    return [f"{label:<{_WIDTH}}{text}"]


def _layout_lines(event: SelectionChanged) -> list[str]:
    """Where the answer's layouts are: a ``layout`` line per target, its address beneath it;
    paths and addresses whole (escaped, never cut)."""
    if not event.with_layouts:
        return []
    links = () if event.selection is None else event.selection.layouts or ()
    if not links:
        return _label("layout", "(no layout)")
    lines: list[str] = []
    for link in links:
        tab = ""
        if link.target == "team":
            tab = " (no tab for this answer)" if link.tab is None else f" (tab {link.tab})"
        lines += _label("layout", f"{link.target}{tab}: {shown(link.path, limit=None)}")
        if link.url is not None:
            lines.append(" " * (_WIDTH + 2) + shown(link.url, limit=None))
    return lines


def _selection_lines(event: SelectionChanged) -> list[str]:
    request = event.request
    if event.selection is None or event.selection.assignment is None:
        return [
            *_label("selection", "no active robot (set /teleop_ui/active_robot)"),
            *(f"  note: {shown(n, limit=None)}" for n in request.notes),
            *_layout_lines(event),
        ]
    assignment = event.selection.assignment
    asked = " ".join(
        shown(v) for v in (request.robot, *(value for _, value in request.values)) if v is not None
    )
    return [
        *_label(
            "selection",
            f"{asked} -> UI configuration {_configuration(assignment)}  "
            f"<- {_values(assignment.given)}",
        ),
        *(
            " " * (_WIDTH + 2) + f"note: {shown(note, limit=None)}"
            for note in event.selection.notes
        ),
        *_layout_lines(event),
    ]


def _rival_lines(event: Rival) -> list[str]:
    team = shown(event.team) if event.team is not None else "(no team said)"
    return _label(
        "rival",
        f"{shown(event.watcher)} answers for team {team}, this watcher for "
        f"{shown(event.own_team)}; this one will {event.policy}",
    )


# The text of each event kind, one function each.
_TEXT: dict[type[Event], Callable[[Any], list[str]]] = {
    RobotAdded: lambda e: _robot_lines("robot added", e.robot),
    RobotChanged: lambda e: _robot_lines("robot changed", e.robot, e.changed),
    RobotRemoved: lambda e: _label("robot removed", shown(e.namespace)),
    SelectionChanged: _selection_lines,
    GraphWarning: lambda e: _label("warning", f"{shown(e.where)}: {shown(e.message, limit=None)}"),
    Rival: _rival_lines,
    RivalGone: lambda e: _label("rival gone", shown(e.watcher)),
    MasterLost: lambda e: _label(
        "master lost", f"{shown(e.master)}: {shown(e.error, limit=None)}; retrying"
    ),
    MasterBack: lambda e: _label("master back", f"{shown(e.master)}: resynchronising"),
    Synced: lambda e: _label(
        "synced",
        f"{len(e.robots)} robot(s): {', '.join(shown(n) for n in e.robots) or 'none'}",
    ),
}


def text_lines(event: Event) -> list[str]:
    """The text form of one event (no ``seq``: it is for the JSON stream)."""
    render = _TEXT.get(type(event))
    return render(event) if render is not None else [event.kind]


def render_live_assignment(live: LiveAssignment, solution: Solution, fmt: str = "text") -> str:
    """``teleop-ui assign``'s output for a robot on a master: its JSON plus ``robot``, ``notes``."""
    if fmt == "json":
        data = {
            "robot": live.robot,
            **assignment_data(solution, live.assignment),
            "notes": list(live.notes),
        }
        return dumps(data)
    text = f"robot {shown(live.robot)}\n" + render_assignment(solution, live.assignment, "text")
    return text + "".join(f"  note: {shown(note, limit=None)}\n" for note in live.notes)
