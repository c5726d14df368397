"""The live view's feed: a :class:`~solver.live.watcher.Watcher` on its own thread, its events
kept as the JSON of ``teleop-ui watch`` and handed to every page that listens; and the
operator's switches made from the page.

The feed keeps what a page needs to draw the graph at any moment (every robot by namespace as
its last ``robot_added`` / ``robot_changed`` event, the operator's selection, whether the graph
answers, the team and rule set it answers for, the last answer's layouts for each robot) and
the newest events, numbered, so a page that reconnects asks for what it missed. Each event
carries ``summary``, a sentence an operator reads (:func:`summary`: who switched, to what,
which configuration, why the default), every value from the graph escaped. A graph that
cannot be reached is reported and retried until the studio stops; nothing a graph sends can
stop the feed.

*Switching* (:meth:`LiveFeed.switch`): the page's click writes the operator's selection on the
feed's graph through the same library function as ``teleop-ui switch``
(:func:`solver.live.operator.switch_robot`, checked against the feed's own rule set), from a
station the feed keeps open while it runs (on ROS 2 its writers hold the selection for a
watcher that comes later), and records a ``switch`` event with the answer.

*Layouts*: with ``layouts`` (``studio --layouts DIR``) the feed's watcher writes each robot's
layouts (:class:`~solver.live.layouts.LiveLayouts`) and its answers name them; the feed keeps
the layouts of the last answer naming each robot. :meth:`LiveFeed.layout` makes a robot's
layout of a configuration in memory (as the watcher writes it: its real topics and joints),
for the page's download link and preview; no file named by the graph is read.

Not here: watching (:mod:`solver.live`; the one way a watcher is made on a graph,
:func:`solver.open_watcher`), HTTP (:mod:`solver.studio.api`).
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from solver import InputError, SolverError
from solver.live.events import (
    Event,
    RobotAdded,
    RobotChanged,
    RobotRemoved,
    SelectionChanged,
    event_data,
)
from solver.untrusted import shown

if TYPE_CHECKING:
    from pathlib import Path

    from solver import GraphAddress, Profile, Solution, Switched, Watcher
    from solver.live.operator import Station
    from solver.live.robot import LiveRobot

__all__ = ["MAX_KEPT_EVENTS", "LiveFeed", "LiveState", "live_feed", "summary"]

# Events kept for pages that (re)connect; older ones are summed up by the state.
MAX_KEPT_EVENTS = 500
# Seconds between attempts when the graph cannot be reached.
RETRY_SECONDS = 1.0
# Layouts made for the page (download, preview) kept, at most.
MAX_KEPT_LAYOUTS = 32
# Robots whose last answer's layouts are kept, at most (the oldest dropped first).
MAX_KEPT_ANSWERS = 256


@dataclass(frozen=True)
class LiveState:
    """What the live view shows now: the graph, the team and rule set the feed answers for,
    the robots, the selection, and for each robot the last answer naming it (``robot`` ->
    ``{"configuration", "watcher", "layouts"}``)."""

    source: str
    status: str
    robots: tuple[dict[str, Any], ...]
    selection: dict[str, Any] | None
    last: int
    team: str = ""
    rules: str = ""
    rules_file: str = ""
    answers: dict[str, dict[str, Any]] = field(default_factory=dict)


class LiveFeed:
    """Runs watchers made by ``make_watcher`` one after another (a new one when one fails)
    until :meth:`stop`."""

    def __init__(
        self,
        source: str,
        solution: Solution,
        make_watcher: Callable[[], Watcher],
        *,
        address: GraphAddress | None = None,
        timeout: float = 2.0,
    ):
        self.source = source
        self.solution = solution
        self.address = address
        self.timeout = timeout
        self._make = make_watcher
        # The operator's station on the graph (opened at the first switch), and what it needs.
        self._station: Station | None = None
        self._station_lock = threading.Lock()
        self._live_robots: dict[str, LiveRobot] = {}
        self._active_assignment: Any = None
        self._answers: dict[str, dict[str, Any]] = {}
        self._layouts: dict[tuple[str, int, int], str | None] = {}
        self._changed = threading.Condition()
        self._events: deque[dict[str, Any]] = deque(maxlen=MAX_KEPT_EVENTS)
        self._robots: dict[str, dict[str, Any]] = {}
        self._selection: dict[str, Any] | None = None
        self._status = "connecting"
        self._seq = 0
        self._stop = threading.Event()
        self._watcher: Watcher | None = None
        # Pages waiting for events on the server's event loop (no thread each).
        self._waiters: set[tuple[asyncio.AbstractEventLoop, asyncio.Event]] = set()
        self._thread = threading.Thread(target=self._run, name="studio-live", daemon=True)

    def start(self) -> None:
        self._thread.start()

    def stop(self, *, wait: bool = True) -> None:
        """Stop watching; the event streams of pages end at once. ``wait``: until the watcher's
        thread has ended (a signal handler does not wait)."""
        self._stop.set()
        with self._changed:
            watcher = self._watcher
            self._changed.notify_all()
            self._wake()
        if watcher is not None:
            watcher.stop("the studio stops")
        if wait and self._thread.is_alive():
            self._thread.join(timeout=10)
        if wait:
            self._close_station()

    def _close_station(self) -> None:
        """Leave the graph as an operator station (a switch under way ends first, within its
        wait)."""
        with self._station_lock:
            station, self._station = self._station, None
        if station is not None:
            acquired = station.busy.acquire(timeout=10)
            try:
                station.close()
            finally:
                if acquired:
                    station.busy.release()

    @property
    def stopped(self) -> bool:
        return self._stop.is_set()

    def state(self) -> LiveState:
        rules = self.solution.rules
        with self._changed:
            return LiveState(
                self.source,
                self._status,
                tuple(self._robots[name] for name in sorted(self._robots)),
                self._selection,
                self._seq,
                team=self.solution.team.name,
                rules=rules.name,
                rules_file=rules.file,
                answers=dict(self._answers),
            )

    def events_after(self, seq: int, timeout: float) -> list[dict[str, Any]]:
        """Events numbered above ``seq``, waiting up to ``timeout`` seconds for one."""
        with self._changed:
            self._changed.wait_for(lambda: self._seq > seq or self._stop.is_set(), timeout)
            return [event for event in self._events if event["seq"] > seq]

    async def next_events(self, seq: int, timeout: float) -> list[dict[str, Any]]:
        """:meth:`events_after` for a coroutine: it waits on the event loop, holding no
        thread, so any number of pages may wait at once."""
        woken = asyncio.Event()
        waiter = (asyncio.get_running_loop(), woken)
        with self._changed:
            if self._seq <= seq and not self._stop.is_set():
                self._waiters.add(waiter)
        try:
            if waiter in self._waiters:
                await asyncio.wait_for(woken.wait(), timeout)
        except TimeoutError:
            pass
        finally:
            with self._changed:
                self._waiters.discard(waiter)
        with self._changed:
            return [event for event in self._events if event["seq"] > seq]

    def _wake(self) -> None:
        """Wake every waiting page (with ``_changed`` held)."""
        for loop, woken in self._waiters:
            with contextlib.suppress(RuntimeError):  # its loop is closed: the server stopped
                loop.call_soon_threadsafe(woken.set)

    def _run(self) -> None:
        while not self._stop.is_set():
            try:
                watcher = self._make()
            except SolverError as error:
                self._record(
                    {"event": "graph_error", "error": _message(error)}, status="unreachable"
                )
                self._stop.wait(RETRY_SECONDS)
                continue
            with self._changed:
                self._watcher = watcher
            try:
                with watcher:
                    if self._stop.is_set():
                        return
                    for event in watcher.events():
                        self._record(event_data(event, self.solution), event)
            except SolverError as error:
                self._record(
                    {"event": "graph_error", "error": _message(error)}, status="unreachable"
                )
            except Exception as error:
                self._record(
                    {"event": "graph_error", "error": f"{type(error).__name__}: {error}"},
                    status="unreachable",
                )
            self._stop.wait(RETRY_SECONDS)

    def _record(
        self, data: dict[str, Any], source: Event | None = None, status: str | None = None
    ) -> None:
        with self._changed:
            self._seq += 1
            # The studio's own numbering: a watcher's seq restarts when it is made again.
            event = {
                **data,
                "seq": self._seq,
                "watcher_seq": data.get("seq"),
                "summary": summary(data),
            }
            kind = data.get("event")
            if kind in ("robot_added", "robot_changed"):
                self._robots[str(data["robot"])] = event
            elif kind == "robot_removed":
                self._robots.pop(str(data["robot"]), None)
            elif kind == "selection_changed":
                self._selection = data
                self._keep_answer(data.get("robot"), data.get("assignment"), data.get("layouts"))
            elif kind in ("synced", "master_back"):
                self._status = "synced" if kind == "synced" else "back"
            elif kind == "master_lost":
                self._status = "lost"
                self._robots.clear()
                self._live_robots.clear()
            if status is not None:
                self._status = status
                self._robots.clear()
                self._live_robots.clear()
            self._keep_robot(source)
            self._events.append(event)
            self._changed.notify_all()
            self._wake()

    def _keep_robot(self, event: Event | None) -> None:
        """The watcher's own robot (what a layout is made of), with ``_changed`` held."""
        if isinstance(event, RobotAdded | RobotChanged):
            self._live_robots[event.robot.namespace] = event.robot
        elif isinstance(event, RobotRemoved):
            self._live_robots.pop(event.namespace, None)
        elif isinstance(event, SelectionChanged):
            selection = event.selection
            self._active_assignment = None if selection is None else selection.assignment

    def _keep_answer(self, robot: Any, assignment: Any, layouts: Any) -> None:
        """An answer naming ``robot`` that carries layouts: kept for its row (bounded)."""
        if not isinstance(robot, str) or not isinstance(layouts, dict) or not layouts:
            return
        configuration = assignment.get("configuration") if isinstance(assignment, dict) else None
        watcher = assignment.get("watcher") if isinstance(assignment, dict) else None
        self._answers.pop(robot, None)
        self._answers[robot] = {
            "configuration": configuration,
            "watcher": watcher,
            "layouts": _layout_links(layouts),
        }
        while len(self._answers) > MAX_KEPT_ANSWERS:
            del self._answers[next(iter(self._answers))]

    # -- the operator's switch -----------------------------------------------------------

    def switch(
        self,
        robot: str,
        values: dict[str, str] | None = None,
        *,
        clear: bool | None = None,
        wait: float | None = None,
    ) -> Switched:
        """Make ``robot`` the active one on the feed's graph with ``values`` (NAME -> VALUE),
        checked against the feed's rule set, and wait for the answer (at most ``wait``
        seconds, :data:`~solver.live.operator.DEFAULT_WAIT` by default). ``clear`` (by
        default: when no value is given, or another robot was active) clears the other
        selected values first, so the robot's own apply. A located error for a switch
        refused (nothing written)."""
        from solver.live.operator import DEFAULT_WAIT, robot_name, switch_robot, switched_data

        if self.address is None:
            raise InputError.at("<live>", "this live view follows no graph it can write to")
        namespace = robot_name(robot)
        if clear is None:
            with self._changed:
                active = self._selection.get("robot") if self._selection else None
            clear = not values or active != namespace
        switched = switch_robot(
            self._open_station(),
            robot,
            values or {},
            rules=self.solution.rules,
            clear=clear,
            wait=DEFAULT_WAIT if wait is None else wait,
        )
        data = {"event": "switch", "by": "this studio", **switched_data(switched)}
        with self._changed:
            if switched.answer is not None:
                self._keep_answer(
                    switched.switch.robot, switched.answer, switched.answer.get("layouts")
                )
        self._record(data)
        return switched

    def _open_station(self) -> Station:
        from solver.live.operator import open_station

        assert self.address is not None  # checked by the caller
        with self._station_lock:
            if self._stop.is_set():
                raise InputError.at("<live>", "the studio stops: no switch now")
            if self._station is None:
                self._station = open_station(self.address, timeout=self.timeout)
            return self._station

    # -- layouts -------------------------------------------------------------------------

    def layout(self, robot: str, configuration: int) -> str | None:
        """The Lichtblick layout of ``robot`` (a namespace on the graph) in UI configuration
        ``configuration`` as the watcher writes it, made now (``None``: no such robot, or it
        cannot be identified, or its namespace is no ROS 2 name, or it has no such
        configuration)."""
        with self._changed:
            live = self._live_robots.get(robot)
            active = self._active_assignment
            active_robot = self._selection.get("robot") if self._selection else None
        if live is None or live.identification is None:
            return None
        key = (robot, configuration, id(live))
        with self._changed:
            if key in self._layouts:
                return self._layouts[key]
        assignment = next(
            (c.assignment for c in live.combinations if c.assignment.number == configuration),
            None,
        )
        if assignment is None and active is not None and active_robot == robot:
            assignment = active if active.number == configuration else None
        text = None if assignment is None else _robot_layout(self.solution, live, assignment)
        with self._changed:
            self._layouts[key] = text
            while len(self._layouts) > MAX_KEPT_LAYOUTS:
                del self._layouts[next(iter(self._layouts))]
        return text


def live_feed(
    address: GraphAddress,
    solution: Solution,
    profile: Profile,
    *,
    interval: float = 0.2,
    timeout: float = 2.0,
    layouts: str | Path | None = None,
) -> LiveFeed:
    """The feed of the graph at ``address`` for ``solution``'s team, named as a person reads
    the address; each watcher it runs is made as ``watch`` makes its own
    (:func:`solver.open_watcher`), writing the robots' layouts into the folder ``layouts``
    when given (as ``watch --layouts`` does)."""
    from solver import open_watcher

    def make() -> Watcher:
        written = None
        if layouts is not None:
            from solver.live.layouts import LiveLayouts

            written = LiveLayouts(layouts, solution)
        return open_watcher(
            address, solution, profile, interval=interval, timeout=timeout, layouts=written
        )

    return LiveFeed(address.label, solution, make, address=address, timeout=timeout)


def _robot_layout(solution: Solution, robot: LiveRobot, assignment: Any) -> str | None:
    """``robot``'s layout of ``assignment``'s configuration, as the watcher writes it; ``None``
    when its namespace is no ROS 2 name."""
    from solver.layouts.foxglove import layout_filename
    from solver.layouts.plan import check_namespace
    from solver.layouts.presentation import load_presentation
    from solver.layouts.robot import robot_layout

    assert robot.identification is not None  # checked by the caller
    try:
        namespace = check_namespace(robot.namespace, robot.namespace)
    except SolverError:
        return None
    return robot_layout(
        solution,
        assignment,
        load_presentation(),
        namespace=namespace,
        topics=robot.graph_topics(),
        topics_source=f"{robot.namespace} topics",
        joints=robot.identification.joints,
        file=layout_filename(assignment.number, default=assignment.is_default),
    ).text


def _layout_links(layouts: dict[str, Any]) -> list[dict[str, Any]]:
    """An answer's ``layouts`` as the page shows them: each target's path, its address when it
    is a web address (``http``/``https``; anything else is no link), the team layout's tab."""
    links = []
    for target, entry in list(layouts.items())[:8]:
        if not isinstance(entry, dict):
            continue
        path, url, tab = entry.get("path"), entry.get("url"), entry.get("tab")
        links.append(
            {
                "target": shown(str(target)),
                "path": shown(path, limit=None) if isinstance(path, str) else None,
                "url": url
                if isinstance(url, str) and url.startswith(("http://", "https://"))
                else None,
                "tab": tab if isinstance(tab, int) and not isinstance(tab, bool) else None,
            }
        )
    return links


def _message(error: SolverError) -> str:
    return "; ".join(str(fault) for fault in error.faults)


# -- what an operator reads of each event ---------------------------------------------------------


def _dict(value: Any) -> dict[str, Any]:
    return value if isinstance(value, dict) else {}


def _text(value: Any) -> str:
    return shown(value) if isinstance(value, str | int | float) else "?"


def _asked(robot: Any, values: dict[str, Any]) -> str:
    chosen = [f"{_text(name)} {_text(value)}" for name, value in values.items() if value]
    return _text(robot) + (f" ({', '.join(chosen)})" if chosen else "")


def _configuration(assignment: Any) -> str:
    """``UI configuration 20 (UGV, Waypoint, LIDAR, 1)``, or the default and why."""
    if not isinstance(assignment, dict):
        return "no configuration"
    combination = assignment.get("combination")
    values = (
        ", ".join(_text(v) for v in combination.values()) if isinstance(combination, dict) else ""
    )
    number = _text(assignment.get("configuration"))
    if assignment.get("default") is True:
        reasons = assignment.get("reasons")
        why = (
            "; ".join(shown(str(r), limit=None) for r in reasons)
            if isinstance(reasons, list)
            else ""
        )
        why = why or "the team has no other"
        return f"the default UI configuration {number} ({values}), because {why}"
    return f"UI configuration {number} ({values})"


def _robot_summary(data: dict[str, Any]) -> str:
    robot = _text(data.get("robot"))
    if data.get("error"):
        first = str(data["error"]).splitlines()[0] if str(data["error"]) else ""
        return f"{robot} cannot be identified: {shown(first, limit=None)}"
    controls = ", ".join(_text(c.get("motion_control")) for c in data.get("motion_controls") or [])
    numbers = ", ".join(
        _text(c.get("configuration")) + (" (default)" if c.get("default") else "")
        for c in data.get("combinations") or []
    )
    return (
        f"{robot} is a {_text(data.get('kinematic_type') or data.get('structure'))} "
        f"({_text(data.get('name'))}); motion controls {controls or 'none found'}; "
        f"UI configuration {numbers or 'none'}"
    )


def _selection_summary(data: dict[str, Any]) -> str:
    if data.get("robot") is None:
        return "No robot is active (/teleop_ui/active_robot is not set)"
    active = _dict(data.get("active"))
    text = (
        f"The active robot is {_asked(data.get('robot'), active)}: "
        f"{_configuration(data.get('assignment'))}"
    )
    notes = [shown(str(n), limit=None) for n in data.get("notes") or []]
    return text + "".join(f"; note: {note}" for note in notes)


def _switch_summary(data: dict[str, Any]) -> str:
    selection = _dict(data.get("selection"))
    asked = _asked(data.get("robot"), selection)
    answer = data.get("answer")
    if not isinstance(answer, dict):
        return f"This studio switched to {asked}; no watcher answered in time"
    return (
        f"This studio switched to {asked}; the watcher {_text(answer.get('watcher'))} answered "
        f"with {_configuration(answer)}"
    )


_SUMMARIES: dict[str, Callable[[dict[str, Any]], str]] = {
    "robot_added": lambda d: "Robot joined: " + _robot_summary(d),
    "robot_changed": lambda d: (
        f"Robot changed ({', '.join(_text(c) for c in d.get('changed') or [])}): "
        + _robot_summary(d)
    ),
    "robot_removed": lambda d: f"Robot left: {_text(d.get('robot'))}",
    "selection_changed": _selection_summary,
    "switch": _switch_summary,
    "warning": lambda d: (
        f"Warning, {_text(d.get('where'))}: {shown(str(d.get('message')), limit=None)}"
    ),
    "rival": lambda d: (
        f"Another watcher, {_text(d.get('watcher'))}, answers for team {_text(d.get('team'))} "
        f"(this one for {_text(d.get('own_team'))}); this one will {_text(d.get('policy'))}"
    ),
    "rival_gone": lambda d: f"The other watcher {_text(d.get('watcher'))} stopped",
    "master_lost": lambda d: (
        f"Lost the graph {_text(d.get('master'))}: {shown(str(d.get('error')), limit=None)}; "
        "trying again"
    ),
    "master_back": lambda d: f"The graph {_text(d.get('master'))} answers again: reading it anew",
    "synced": lambda d: (
        f"Read the whole graph: {len(d.get('robots') or [])} robot(s)"
        + "".join(f" {_text(r)}" for r in (d.get("robots") or [])[:20])
    ),
    "graph_error": lambda d: (
        f"The graph cannot be read: {shown(str(d.get('error')), limit=None)}; trying again"
    ),
}


def summary(data: dict[str, Any]) -> str:
    """One event as a sentence an operator reads (every value from the graph escaped)."""
    describe = _SUMMARIES.get(str(data.get("event")))
    return describe(data) if describe is not None else _text(data.get("event"))
