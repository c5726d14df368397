"""The watcher's events and their JSON schema (one object per line; documented in the README).

Every event has ``seq`` (1, 2, ... within one run: a gap would mean a lost line) and ``event``,
its kind:

==================== ==============================================================
``robot_added``      a robot appeared (or is part of a (re)synchronisation); the robot
                     fields below
``robot_changed``    a robot's reported fields changed: the robot fields, and
                     ``changed``, the names of the fields that differ
``robot_removed``    its ``robot_description`` is gone: ``robot``
``selection_changed`` the operator's selection or its answer (reasons and notes
                     included) changed: ``robot``, ``active`` (every characteristic
                     of the rule set -> the value asked for, ``null`` when not set),
                     ``assignment`` (``teleop-ui assign``'s JSON, ``null`` with no
                     active robot), ``notes``; with ``watch --layouts``,
                     ``layout`` and ``layouts`` (where the answer's layouts are:
                     :func:`solver.live.selection.layouts_data`)
``warning``          something on the graph is ignored, located: ``where`` (the
                     parameter or topic), ``message`` (an ``active_*`` name or a
                     robot's value the rules know no characteristic of, a robot's
                     value that is not text)
``rival``            another watcher with a different team, rules or values answers
                     on the same graph: ``watcher``, ``team`` (theirs), ``own_team``,
                     ``policy`` (``yield`` or ``insist``: what this watcher does)
``rival_gone``       that watcher stopped: ``watcher``
``master_lost``      the master stopped answering (or restarted): ``master``, ``error``
``master_back``      it answers again; a full resynchronisation follows
``synced``           the robots below are every robot on the master: ``master``, ``robots``
==================== ==============================================================

Robot fields: ``robot`` (the namespace), ``name`` (the URDF's), ``structure``,
``kinematic_type`` (``null`` when the rule set has none for it), ``confidence``,
``sensor_count``, ``sensors``, ``motion_controls`` (identification's fields:
:func:`solver.identify.render.summary_data`), ``given`` (characteristic -> ``{"value",
"source"}``: the robot's own values and ``--set``), ``combinations`` (each ``{"combination",
"configuration", "default", "reasons"}``), ``missing`` (each ``{"characteristic", "how"}``: what
no source gives, and how to give it), ``error`` (``null``, or why the robot could not be
identified; the scalar identification fields are then ``null``, and ``sensors``,
``motion_controls`` and ``combinations`` empty lists), and ``topics`` (the robot's topics that
identification reads, each ``{"topic", "type", "direction"}`` with its full name: a renamed
camera topic is a ``robot_changed``).

A run starts with one ``robot_added`` per robot, the ``warning`` and ``rival`` events that hold,
a ``selection_changed`` if a robot is active (or a ``/teleop_ui`` parameter has a note), and
``synced``. After ``master_back`` the same
sequence follows again: the watcher starts over, so a consumer drops what it knew at
``master_lost`` and rebuilds from the events that follow.

Not here: producing events (:mod:`solver.live.watcher`), text (:mod:`solver.live.render`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from solver.live.robot import LiveRobot, robot_data
from solver.live.selection import ActiveSelection, Request, selection_data
from solver.solving.solution import Solution

__all__ = [
    "Event",
    "GraphWarning",
    "MasterBack",
    "MasterLost",
    "Rival",
    "RivalGone",
    "RobotAdded",
    "RobotChanged",
    "RobotRemoved",
    "SelectionChanged",
    "Synced",
    "event_data",
]


@dataclass(frozen=True, slots=True)
class Event:
    seq: int
    kind: ClassVar[str] = "event"


@dataclass(frozen=True, slots=True)
class RobotAdded(Event):
    robot: LiveRobot
    kind: ClassVar[str] = "robot_added"


@dataclass(frozen=True, slots=True)
class RobotChanged(Event):
    robot: LiveRobot
    changed: tuple[str, ...]
    kind: ClassVar[str] = "robot_changed"


@dataclass(frozen=True, slots=True)
class RobotRemoved(Event):
    namespace: str
    kind: ClassVar[str] = "robot_removed"


@dataclass(frozen=True, slots=True)
class SelectionChanged(Event):
    """``with_layouts``: the watcher writes layouts (the event then says where they are, or
    that there are none)."""

    request: Request
    selection: ActiveSelection | None
    with_layouts: bool = False
    kind: ClassVar[str] = "selection_changed"


@dataclass(frozen=True, slots=True)
class GraphWarning(Event):
    where: str
    message: str
    kind: ClassVar[str] = "warning"


@dataclass(frozen=True, slots=True)
class Rival(Event):
    watcher: str
    team: str | None
    own_team: str
    policy: str
    kind: ClassVar[str] = "rival"


@dataclass(frozen=True, slots=True)
class RivalGone(Event):
    watcher: str
    kind: ClassVar[str] = "rival_gone"


@dataclass(frozen=True, slots=True)
class MasterLost(Event):
    master: str
    error: str
    kind: ClassVar[str] = "master_lost"


@dataclass(frozen=True, slots=True)
class MasterBack(Event):
    master: str
    kind: ClassVar[str] = "master_back"


@dataclass(frozen=True, slots=True)
class Synced(Event):
    master: str
    robots: tuple[str, ...]
    kind: ClassVar[str] = "synced"


def event_data(event: Event, solution: Solution) -> dict[str, Any]:
    """The JSON object of one event (see the module docstring)."""
    data: dict[str, Any] = {"seq": event.seq, "event": event.kind}
    if isinstance(event, RobotAdded):
        data.update(robot_data(event.robot))
    elif isinstance(event, RobotChanged):
        data.update(robot_data(event.robot))
        data["changed"] = list(event.changed)
    elif isinstance(event, RobotRemoved):
        data["robot"] = event.namespace
    elif isinstance(event, SelectionChanged):
        data.update(
            selection_data(event.selection, event.request, solution, layouts=event.with_layouts)
        )
    elif isinstance(event, GraphWarning):
        data.update(where=event.where, message=event.message)
    elif isinstance(event, Rival):
        data.update(
            watcher=event.watcher, team=event.team, own_team=event.own_team, policy=event.policy
        )
    elif isinstance(event, RivalGone):
        data["watcher"] = event.watcher
    elif isinstance(event, MasterLost):
        data.update(master=event.master, error=event.error)
    elif isinstance(event, MasterBack):
        data["master"] = event.master
    elif isinstance(event, Synced):
        data.update(master=event.master, robots=list(event.robots))
    return data
