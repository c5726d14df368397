"""The watcher: a state machine that follows a robot graph and yields events as things change.

It works on any :class:`~solver.live.graph.GraphSource` (:mod:`solver.live.sources`): a ROS 1
master (the default, :class:`~solver.live.sources.ros1.MasterGraph`) or a ROS 2 graph on DDS;
what follows is the same for both, in the ROS 1 words the events use.

States and transitions::

    start --(master answers)--> synchronised --(poll: something changed)--> events
      |                             |
      | (no answer: error,          +--(a call fails, or the master's pid changed)--> lost
      |  or --wait retries)         |                                                  |
      v                             +<--(an answer: master_back, full resync)----------+

*Synchronising* (at start and after ``master_back``) forgets everything, waits until the
source has seen the graph whole (:meth:`GraphSource.settle`: nothing on a ROS 1 master, the
discovery window on DDS), reads it afresh and reports every robot as ``robot_added``, the
warnings and rivals, the selection, then ``synced``: a consumer never has to merge an old view
with a new one, and no robot is reported twice or missed.

*Polling*: every ``interval`` seconds one round trip (:meth:`GraphSource.observe`) reads the
master's pid, the topic graph, the parameter names and ``/teleop_ui``. Descriptions are not
read by polls: the source follows them (on ROS 1 the watcher's node subscribes to each one and
to ``/teleop_ui``) and wakes the loop when one changed, so a new description is reported well
within one interval. A change under ``/teleop_ui`` alone (the operator's switch, an answer, an
announcement) is answered from ``/teleop_ui`` alone (:meth:`GraphSource.observe_params`: the
pid and that subtree), with the robots as the last poll left them: its cost does not grow with
the graph, and the next poll of the whole graph comes at its usual time. A robot is identified
again only when its description or its relevant topics changed (identification is cached by
content besides); an event is emitted only when what it reports changed.

*Values*: each robot's combinations take the values it is given beside identification (its own
``<ns>/teleop_ui/<characteristic>``, ``--set``), and the operator's ``/teleop_ui/active_*``
choose among them (:mod:`solver.live.given`, :mod:`solver.live.selection`). A name the rules
know no characteristic of, or a robot's value that is not text, is a located ``warning`` event
(once while it lasts; at most :data:`MAX_WARNINGS` a poll).

*Write-back*: a watcher that follows the graph (:meth:`Watcher.events`; a :meth:`snapshot`
alone writes nothing) writes the answer to the active selection to
``/teleop_ui/ui_configuration`` (deleted with no active robot) whenever what is on the master
differs from it, with the watcher's node name under ``watcher``. Two watchers on one master
with different teams or rules would overwrite each other's answer on every push; so every
watcher announces itself and reports the others as ``rival`` events
(:mod:`solver.live.rivals`), and a yielding watcher (the default) does not overwrite an answer
written by another watcher that is still running (the source says so:
:meth:`GraphSource.running_watcher`): it leaves that answer there and says so in the
selection's notes. An insisting one (``policy="insist"``) writes over a yielding rival's
answer, never over an insisting one's. Once that watcher is gone, the parameter is taken over
at the next poll. A writer the source can tell is no watcher (on ROS 1, a node API that is not
``http://host:port/``) is overwritten, with a note. Any other answer no running watcher wrote
(anyone can write one: a forgery naming a watcher that does not exist, a killed watcher's,
something that is no answer at all) is overwritten with a ``warning`` event saying what was
replaced (once while it lasts). Watchers with the same team agree, and leave each other's
equal answers alone.

*Layouts* (``layouts``, :class:`~solver.live.layouts.LiveLayouts`: ``watch --layouts DIR``):
the robots' layouts and the team layout are written as robots are read (before the answer
that names them), and the answer and its ``selection_changed`` event carry where the active
robot's are (``layouts``); the answer as this watcher makes it is :attr:`Watcher.answer`
(what ``watch --serve`` serves).

*Lost*: any failed call, or a new pid (the master restarted between two polls), gives
``master_lost``; the watcher retries after one interval, doubling up to ``max_backoff``, and
when the master answers gives ``master_back`` and synchronises again.

*Stopping* (:meth:`Watcher.stop`: SIGTERM, a ``shutdown`` call, Ctrl-C's handler) cuts off the
call under way within :data:`_STOP_GRACE` seconds, however the master behaves; closing takes the
watcher's answer back when it is still its own (within :data:`_WITHDRAW_BUDGET`: left there, it
would name a node that no longer runs), then the source releases what it holds (on ROS 1,
within half a second).

Nothing here prints: events are yielded to the caller (the CLI writes them).

Not here: the event schema (:mod:`solver.live.events`), rendering (:mod:`solver.live.render`),
any transport (:mod:`solver.live.sources`).
"""

from __future__ import annotations

import dataclasses
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from types import TracebackType
from typing import TYPE_CHECKING, Any

from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.live.discovery import RobotSource, discover
from solver.live.events import (
    Event,
    GraphWarning,
    MasterBack,
    MasterLost,
    RobotAdded,
    RobotChanged,
    RobotRemoved,
    SelectionChanged,
    Synced,
)
from solver.live.given import ACTIVE_PREFIX, FixedValues, GivenValue, robot_values, unknown_name
from solver.live.graph import (
    MISSING,
    DescriptionStore,
    GraphSource,
    MasterError,
    MasterUnreachable,
    Observation,
)
from solver.live.rivals import INSIST, YIELD, Rivals, fingerprint
from solver.live.robot import LiveRobot, identify_robot, robot_data, unexpected_error
from solver.live.selection import (
    NAMESPACE,
    RESULT_PARAM,
    WRITER_KEY,
    ActiveSelection,
    Request,
    read_request,
    select,
    selection_data,
    ui_configuration_value,
)
from solver.live.values import MAX_SELECTION_CHARS, kind_of, shown_value
from solver.ros.names import Topic
from solver.solving.solution import Solution
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.live.layouts import LiveLayouts
    from solver.live.sources import GraphAddress

__all__ = ["MAX_WARNINGS", "Watcher", "open_watcher"]

# Warning events a poll reports at most (a graph may hold any number of unknown names).
MAX_WARNINGS = 20

# Pushes can come in bursts (a launch file setting many parameters); reads triggered by them
# are at least this far apart.
_MIN_GAP = 0.01
# After stop(), the call under way ends within this.
_STOP_GRACE = 0.2
# A stopping watcher's answer taken back (read, then deleted) within this, whatever the graph.
_WITHDRAW_BUDGET = 0.5
_RESULT_KEY = RESULT_PARAM.rsplit("/", 1)[1]


class _Restarted(MasterError):
    """The master answers with another process id: it restarted between two polls."""


@dataclass(frozen=True, slots=True)
class _Tracked:
    inputs: tuple[Any, Any, Any, tuple[Topic, ...], tuple[GivenValue, ...]]
    robot: LiveRobot
    data: dict[str, Any]


class Watcher:
    """Follows the graph ``source`` (by default the ROS 1 master at ``master``) for
    ``solution``'s team (see the module docstring).

    Use it as a context manager, so that what the source holds (on ROS 1 its node and
    parameter subscriptions) is released::

        with Watcher(uri, solve(team), load_profile()) as watcher:
            for event in watcher.events():
                ...

    ``timeout`` and ``push`` are the ROS 1 master's (``push=False`` runs without a node, no
    parameter subscriptions: enough for :meth:`snapshot`, which reads everything once); a
    ``source`` given brings its own. ``fixed``: values given at start (``--set``);
    ``policy``: ``yield`` or ``insist`` towards rival watchers (:mod:`solver.live.rivals`);
    ``layouts``: the robots' layouts, written as they are read and named in the answer.
    """

    def __init__(
        self,
        master: str,
        solution: Solution,
        profile: Profile,
        *,
        interval: float = 0.2,
        timeout: float = 2.0,
        push: bool = True,
        max_backoff: float = 2.0,
        cache: IdentificationCache | None = None,
        source: GraphSource | None = None,
        fixed: FixedValues | None = None,
        policy: str = YIELD,
        layouts: LiveLayouts | None = None,
    ) -> None:
        if source is None:
            # The default source: a ROS 1 master (imported here: watching ROS 2 needs none).
            from solver.live.sources.ros1 import MasterGraph

            source = MasterGraph(master, timeout=timeout, push=push)
        self.source: GraphSource = source
        self.master = source.name
        self.solution = solution
        self.profile = profile
        self.interval = interval
        self.max_backoff = max(max_backoff, interval)
        self.cache = cache if cache is not None else IdentificationCache()
        self.stop_reason: str | None = None
        self._stop = threading.Event()
        self._wake = threading.Event()
        self._due = threading.Lock()  # guards _graph_due, set from the source's threads
        self._graph_due = False
        self._closed = False
        source.on_change = self.wake
        source.on_params = self.wake_params
        source.on_stop = self.stop
        self.fixed = fixed if fixed is not None else FixedValues()
        self.rivals = Rivals(
            source.caller_id,
            solution,
            fingerprint(solution, profile, self.fixed),
            policy,
            source.running_watcher,
        )
        self._warned: tuple[tuple[str, str], ...] = ()
        self._robot_warnings: list[tuple[str, str]] = []  # the robots' own, at the last poll
        # The last observation and the robots found in it (a graph that did not change).
        self._discovered: tuple[Observation, tuple[RobotSource, ...]] | None = None
        # Only a watcher that follows the graph announces itself and writes its answer: a
        # snapshot (:meth:`snapshot` alone, ``watch --once``) is a look, no rival, and leaves
        # the graph as it found it.
        self._announcing = False
        self._robots: dict[str, _Tracked] = {}
        self.layouts = layouts
        self._no_selection = selection_data(None, Request(), solution, layouts=layouts is not None)
        self._selection = self._no_selection
        self._answer_value: dict[str, Any] | None = None
        self._pid: int | None = None
        self._seq = 0
        self._last_poll = 0.0  # the last read of the whole graph
        self._last_read = 0.0  # the last read of anything

    # -- life cycle ----------------------------------------------------------------------

    @property
    def caller_id(self) -> str:
        """The watcher's node name on the graph."""
        return self.source.caller_id

    @property
    def node_uri(self) -> str | None:
        """The watcher's own node API, where the source has one (ROS 1)."""
        return self.source.node_uri

    @property
    def descriptions(self) -> DescriptionStore:
        return self.source.descriptions

    def __enter__(self) -> Watcher:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    def stop(self, reason: str = "") -> None:
        """Make :meth:`events` return, cutting off the call under way (thread-safe; SIGTERM and
        the graph's ``shutdown`` call it)."""
        self.stop_reason = reason or "stopped"
        self._stop.set()
        self._wake.set()
        self.source.cut_off(time.monotonic() + _STOP_GRACE)

    def wake(self) -> None:
        """Poll the whole graph now instead of at the next tick (thread-safe)."""
        with self._due:
            self._graph_due = True
        self._wake.set()

    def wake_params(self) -> None:
        """Read the watched parameters now (only they changed; thread-safe)."""
        self._wake.set()

    @property
    def stopped(self) -> bool:
        return self._stop.is_set()

    def close(self) -> None:
        """Take this watcher's answer back, release what the source holds (best effort,
        bounded) and close it; idempotent."""
        self._stop.set()
        if self._closed:
            return
        self._closed = True
        if self._announcing:
            self._withdraw_answer()
        self.source.close()

    def _withdraw_answer(self) -> None:
        """Delete the answer if it is still this watcher's: left there, it would name a node
        that no longer runs, and an operator station reading it would show a stale
        configuration. Another watcher still running writes its own at its next poll."""
        self.source.cut_off(time.monotonic() + _WITHDRAW_BUDGET)
        try:
            _, params = self.source.observe_params(NAMESPACE)
            present = dict(params).get(_RESULT_KEY)
            if isinstance(present, dict) and present.get(WRITER_KEY) == self.caller_id:
                self.source.delete_param(RESULT_PARAM)
        except MasterError:
            pass  # the graph is gone or too slow: nothing more to do on the way out

    def wait_for_master(self, on_waiting: Callable[[MasterError], None] | None = None) -> bool:
        """Retry until the master answers (``True``) or :meth:`stop` (``False``).

        Only a master that does not answer is waited for: an answer that is not a ROS
        master's (another server on that port) raises :class:`MasterError` at once.
        """
        delay = self.interval
        told = False
        while not self.stopped:
            try:
                self.source.get_pid()
            except MasterUnreachable as error:
                if not told and on_waiting is not None:
                    on_waiting(error)
                told = True
                self._stop.wait(delay)
                delay = min(delay * 2, self.max_backoff)
            else:
                return True
        return False

    def wait_for_robot(self, on_waiting: Callable[[], None] | None = None) -> bool:
        """Watch until a robot's description is there (``True``) or :meth:`stop` (``False``):
        on a DDS domain, which is never "down", ``--wait`` waits for the first robot."""
        told = False
        while not self.stopped:
            sources = discover(self._observe(), self.profile)
            self.descriptions.sync([s.description_key for s in sources])
            if any(self.descriptions.get(s.description_key) is not MISSING for s in sources):
                return True
            if not told and on_waiting is not None:
                on_waiting()
            told = True
            if self._wake.wait(self.interval):
                self._wake.clear()
        return False

    # -- events --------------------------------------------------------------------------

    @property
    def answer(self) -> dict[str, Any] | None:
        """This watcher's answer to the selection as last read (what it writes, or would
        write: a rival's may stand on the graph), ``None`` with no active robot."""
        return self._answer_value

    def robots(self) -> dict[str, LiveRobot]:
        """The robots as last read (after :meth:`snapshot` or an event), by namespace."""
        return {namespace: tracked.robot for namespace, tracked in sorted(self._robots.items())}

    def snapshot(self) -> list[Event]:
        """One full synchronisation: ``robot_added`` per robot, the selection, ``synced``.

        Alone (before :meth:`events`, which starts with one), it only reads the graph: no
        announcement and no answer written.

        :class:`~solver.live.graph.MasterError` when the graph cannot be read.
        """
        return self._numbered(self._resync())

    def events(self) -> Iterator[Event]:
        """Events until :meth:`stop`; the first synchronisation raises if the master is down."""
        self._announcing = True
        yield from self.snapshot()
        lost: str | None = None
        delay = self.interval
        while not self.stopped:
            try:
                if lost is not None:
                    batch = [MasterBack(0, self.master), *self._resync()]
                    lost = None
                else:
                    whole = self._pause_until_next_poll()
                    if self.stopped:
                        break
                    batch = self._poll() if whole else self._poll_params()
            except MasterError as error:
                if self.stopped:
                    break  # the call was cut off by stop(): nothing was lost
                if lost is None:
                    # The event names the master already; the error says what went wrong.
                    lost = "; ".join(fault.message for fault in error.faults)
                    yield from self._numbered([MasterLost(0, self.master, lost)])
                    # A restart is already over: synchronise at once.
                    delay = 0.0 if isinstance(error, _Restarted) else self.interval
                else:
                    delay = min(max(delay, self.interval) * 2, self.max_backoff)
                self._stop.wait(delay)
                continue
            yield from self._numbered(batch)
            delay = self.interval

    def _numbered(self, batch: list[Event]) -> list[Event]:
        # Events are built unnumbered: a batch cut short by a failed call is dropped whole,
        # and the numbers stay without gaps.
        numbered = []
        for event in batch:
            self._seq += 1
            numbered.append(dataclasses.replace(event, seq=self._seq))
        return numbered

    def _pause_until_next_poll(self) -> bool:
        """Wait for the next read: ``True`` for the whole graph (the interval passed, or the
        source said the graph changed), ``False`` for the watched parameters alone."""
        deadline = self._last_poll + self.interval
        while not self.stopped:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return True
            if self._wake.wait(remaining):
                self._wake.clear()
                gap = self._last_read + _MIN_GAP - time.monotonic()
                if gap > 0:
                    self._stop.wait(gap)
                with self._due:
                    return self._graph_due
        return True

    # -- reading the master ----------------------------------------------------------------

    def _observe(self) -> Observation:
        with self._due:
            # What was pushed until now, this read sees.
            self._graph_due = False
            self._wake.clear()
        self._last_poll = self._last_read = time.monotonic()
        return self.source.observe(NAMESPACE)

    def _resync(self) -> list[Event]:
        self._robots = {}
        self._selection = self._no_selection
        self._warned = ()
        self._robot_warnings = []
        self.rivals.reset()
        self.source.resync(NAMESPACE)
        self.source.settle(lambda: self.stopped)
        observation = self._observe()
        self._pid = observation.pid
        batch = self._update(observation)
        return [*batch, Synced(0, self.master, tuple(sorted(self._robots)))]

    def _poll(self) -> list[Event]:
        observation = self._observe()
        self._same_master(observation.pid)
        return self._update(observation)

    def _poll_params(self) -> list[Event]:
        """The watched parameters alone changed: the answer from them, with the robots as the
        last poll of the whole graph left them."""
        self._last_read = time.monotonic()
        pid, params = self.source.observe_params(NAMESPACE)
        self._same_master(pid)
        return self._answer(dict(params))

    def _same_master(self, pid: int) -> None:
        if pid != self._pid:
            raise _Restarted.at(
                self.master,
                f"the master restarted (process {self._pid}, now {pid})",
                path="getPid",
            )

    def _update(self, observation: Observation) -> list[Event]:
        rules = self.solution.rules
        graph = dataclasses.replace(observation, params=())  # what discovery reads
        if self._discovered is None or self._discovered[0] != graph:
            self._discovered = (graph, discover(graph, self.profile))
        sources = self._discovered[1]
        self.descriptions.sync([key for s in sources for key in s.keys(rules.names)])
        robots: dict[str, _Tracked] = {}
        changes: list[Event] = []
        warnings: list[tuple[str, str]] = []
        for source in sources:
            description, semantic, teleop = self._values(source)
            if description is MISSING:
                continue  # deleted since the names were read: the next poll removes it
            own, noted = robot_values(source.value_keys, self.descriptions.get, rules)
            warnings += noted
            given = (*self.fixed.for_robot(source.namespace), *own)
            inputs = (description, semantic, teleop, source.topics, given)
            old = self._robots.get(source.namespace)
            if old is not None and old.inputs == inputs:
                robots[source.namespace] = old
                warnings += old.robot.warnings
                continue
            robot, data = self._identify(source, (description, semantic, teleop), given)
            warnings += robot.warnings
            robots[source.namespace] = _Tracked(inputs, robot, data)
            if old is None:
                changes.append(RobotAdded(0, robot))
            elif data != old.data:
                changes.append(
                    RobotChanged(0, robot, tuple(k for k in data if data[k] != old.data.get(k)))
                )
        removed: list[Event] = [
            RobotRemoved(0, namespace) for namespace in sorted(set(self._robots) - set(robots))
        ]
        self._robots = robots
        self._robot_warnings = warnings
        self._write_layouts(changes)  # before the answer that names them
        return [*removed, *changes, *self._answer(dict(observation.params))]

    def _values(self, source: RobotSource) -> tuple[Any, Any, Any]:
        """A robot's description, SRDF and teleoperation description as held now (each
        :data:`MISSING` when it has none)."""

        def held(key: str | None) -> Any:
            return MISSING if key is None else self.descriptions.get(key)

        return held(source.description_key), held(source.semantic_key), held(source.teleop_key)

    def _write_layouts(self, changes: list[Event]) -> None:
        """The robots' layouts (``layouts``), those of the robots in ``changes`` again."""
        if self.layouts is None:
            return
        changed = [e.robot.namespace for e in changes if isinstance(e, RobotAdded | RobotChanged)]
        self.layouts.sync({ns: t.robot for ns, t in self._robots.items()}, changed)

    def _answer(self, params: dict[str, Any]) -> list[Event]:
        """Warnings, rivals and the selection from the watched parameters ``params``."""
        rules = self.solution.rules
        request = read_request(params, rules.names)
        warnings = self._robot_warnings + [
            (f"{NAMESPACE}/{key}", unknown_name(key[len(ACTIVE_PREFIX) :], rules))
            for key in request.unknown
        ]
        if self._announcing and self.rivals.needs_announcing(params):
            self.source.announce(self.rivals.announcement)
        rivals = self.rivals.update(params)  # before the write-back, which asks who insists
        selected, replaced = self._select(params, request)
        return [*self._warnings(warnings + replaced), *rivals, *selected]

    def _warnings(self, found: list[tuple[str, str]]) -> list[Event]:
        """A ``warning`` event for each of ``found`` not reported at the last poll (at most
        :data:`MAX_WARNINGS`)."""
        # A name from the graph is shown cut short past what any name of a rule set may be.
        bounded = [(w if len(w) <= MAX_SELECTION_CHARS else shown(w), m) for w, m in found]
        current = tuple(dict.fromkeys(bounded))[:MAX_WARNINGS]
        new = [
            GraphWarning(0, where, message)
            for where, message in current
            if (where, message) not in self._warned
        ]
        self._warned = current
        return list(new)

    def _identify(
        self,
        source: RobotSource,
        values: tuple[Any, Any, Any],
        given: tuple[GivenValue, ...],
    ) -> tuple[LiveRobot, dict[str, Any]]:
        """One robot and its event fields, from its description, SRDF and teleoperation
        description (``values``); whatever goes wrong stays that robot's error."""
        description, semantic, teleop = values
        try:
            robot = identify_robot(
                source,
                description,
                semantic,
                cache=self.cache,
                solution=self.solution,
                profile=self.profile,
                given=given,
                teleop=teleop,
            )
            return robot, robot_data(robot)
        except Exception as error:  # the per-robot boundary
            # identify_robot already turns input errors into the robot's; this is the last
            # line: a robot on the network must never end the watcher serving the others.
            error_text = unexpected_error(source.description_key, error)
            robot = LiveRobot(source.namespace, None, (), error_text, source.topics)
            return robot, robot_data(robot)

    def _select(
        self, params: dict[str, Any], request: Request
    ) -> tuple[list[Event], list[tuple[str, str]]]:
        """The ``selection_changed`` event, if the answer changed, and the warning for an
        answer of no running watcher's that was replaced."""
        selection = select(request, {ns: t.robot for ns, t in self._robots.items()}, self.solution)
        if self.layouts is not None and selection is not None:
            selection = dataclasses.replace(selection, layouts=self.layouts.links(selection))
        wanted = ui_configuration_value(selection, self.solution, self.caller_id)
        self._answer_value = wanted
        note, replaced = (
            self._write_back(params.get(_RESULT_KEY, MISSING), wanted, selection)
            if self._announcing
            else (None, None)
        )
        if note is not None and selection is not None:
            selection = dataclasses.replace(selection, notes=(*selection.notes, note))
        warnings = [(RESULT_PARAM, replaced)] if replaced is not None else []
        with_layouts = self.layouts is not None
        data = selection_data(selection, request, self.solution, layouts=with_layouts)
        if data == self._selection:
            return [], warnings
        self._selection = data
        return [SelectionChanged(0, request, selection, with_layouts)], warnings

    def _write_back(
        self, present: Any, wanted: dict[str, Any] | None, selection: ActiveSelection | None
    ) -> tuple[str | None, str | None]:
        """Write (or delete) the answer unless a running rival's stays (see the module
        docstring); a note saying what was not written, or overwritten, and a warning when
        what was replaced came from no running watcher (:func:`_replaced`)."""
        rival, note = self._rival(present, wanted)
        if rival is not None and selection is not None:
            number = shown_value(present.get("configuration", "?"))
            if self.rivals.policy != INSIST or self.rivals.insists(rival):
                both = (
                    " (both insist: the first to answer keeps it)"
                    if self.rivals.policy == INSIST
                    else ""
                )
                return (
                    f"{RESULT_PARAM} not written: the watcher {shown_value(rival)} answers there "
                    f"with configuration {number}{both}; run one watcher per graph, give every "
                    f"watcher the same team and rules, or start this one with --insist"
                ), None
            # Insisting on a yielding rival: written over (the rival event said so).
            self._write(present, wanted)
            return note, None
        written = self._write(present, wanted)
        return note, (self._replaced(present, wanted) if written and note is None else None)

    def _write(self, present: Any, wanted: dict[str, Any] | None) -> bool:
        """Make the answer on the graph ``wanted`` (``None``: deleted); whether it wrote."""
        if wanted is None and present is not MISSING:
            self.source.delete_param(RESULT_PARAM)
            return True
        if wanted is not None and _answer(present) != _answer(wanted):
            self.source.set_param(RESULT_PARAM, wanted)
            return True
        return False

    def _rival(self, present: Any, wanted: dict[str, Any] | None) -> tuple[str | None, str | None]:
        """The node name of another watcher, still running, whose different answer is on the
        graph (``None`` when the parameter is free to write: see the module docstring), and a
        note on a writer that cannot be a watcher."""
        if wanted is None or not isinstance(present, dict):
            return None, None
        writer = present.get(WRITER_KEY)
        if (
            not isinstance(writer, str)
            or writer == self.caller_id
            or _answer(present) == _answer(wanted)
        ):
            return None, None
        running, doubt = self.source.running_watcher(writer)
        if doubt is not None:
            note = f"{RESULT_PARAM} was written by {shown_value(writer)}, {doubt}; overwritten"
            return None, note
        return (writer if running else None), None

    def _replaced(self, present: Any, wanted: dict[str, Any] | None) -> str | None:
        """What a ``warning`` says of the answer ``present`` this watcher just replaced, when
        no running watcher wrote it (a forgery, a killed watcher's, anything but an answer);
        ``None`` for its own, or a running rival's taken away with the active robot."""
        writer = present.get(WRITER_KEY) if isinstance(present, dict) else None
        if present is MISSING or writer == self.caller_id:
            return None  # nothing was there (a deletion is no answer), or its own
        done = "replaced by this watcher's" if wanted is not None else "deleted (no active robot)"
        if not isinstance(writer, str):
            return f"not a watcher's answer ({kind_of(present)}): {done}"
        # With an answer of its own to write, _rival already found the writer not running.
        if wanted is None and self.source.running_watcher(writer) == (True, None):
            return None
        named = shown_value(writer)
        return f"an answer in the name of {named}, which is no running watcher: {done}"


def open_watcher(
    address: GraphAddress,
    solution: Solution,
    profile: Profile,
    *,
    interval: float = 0.2,
    timeout: float = 2.0,
    push: bool = True,
    fixed: FixedValues | None = None,
    policy: str = YIELD,
    layouts: LiveLayouts | None = None,
) -> Watcher:
    """A :class:`Watcher` on the graph at ``address`` (:func:`solver.live.sources.graph_address`),
    its source opened by the one lookup of sources (:func:`solver.live.sources.open_source`;
    ``timeout`` and ``push`` are a master's) and closed with the watcher: what ``watch`` and
    the studio's live view follow (``layouts``: see :class:`Watcher`)."""
    # Here, not at module level: the watcher's machinery imports no source.
    from solver.live.sources import open_source

    source = open_source(address, timeout=timeout, push=push)
    try:
        return Watcher(
            source.name,
            solution,
            profile,
            interval=interval,
            source=source,
            fixed=fixed,
            policy=policy,
            layouts=layouts,
        )
    except BaseException:
        source.close()
        raise


def _answer(value: Any) -> Any:
    """A ``ui_configuration`` value without its writer: what two watchers can agree on."""
    if isinstance(value, dict):
        return {key: item for key, item in value.items() if key != WRITER_KEY}
    return value
