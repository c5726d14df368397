"""The live view's feed: a :class:`~solver.live.watcher.Watcher` on its own thread, its events
kept as the JSON of ``teleop-ui watch`` and handed to every page that listens.

The feed keeps what a page needs to draw the graph at any moment (every robot by namespace as
its last ``robot_added`` / ``robot_changed`` event, the operator's selection, whether the graph
answers) and the newest events, numbered, so a page that reconnects asks for what it missed.
A graph that cannot be reached is reported and retried until the studio stops; nothing a graph
sends can stop the feed.

Not here: watching (:mod:`solver.live`; the one way a watcher is made on a graph,
:func:`solver.open_watcher`), HTTP (:mod:`solver.studio.api`).
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from solver import SolverError
from solver.live.events import event_data

if TYPE_CHECKING:
    from solver import GraphAddress, Profile, Solution, Watcher

__all__ = ["MAX_KEPT_EVENTS", "LiveFeed", "LiveState", "live_feed"]

# Events kept for pages that (re)connect; older ones are summed up by the state.
MAX_KEPT_EVENTS = 500
# Seconds between attempts when the graph cannot be reached.
RETRY_SECONDS = 1.0


@dataclass(frozen=True)
class LiveState:
    """What the live view shows now."""

    source: str
    status: str
    robots: tuple[dict[str, Any], ...]
    selection: dict[str, Any] | None
    last: int


class LiveFeed:
    """Runs watchers made by ``make_watcher`` one after another (a new one when one fails)
    until :meth:`stop`."""

    def __init__(self, source: str, solution: Solution, make_watcher: Callable[[], Watcher]):
        self.source = source
        self.solution = solution
        self._make = make_watcher
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

    @property
    def stopped(self) -> bool:
        return self._stop.is_set()

    def state(self) -> LiveState:
        with self._changed:
            return LiveState(
                self.source,
                self._status,
                tuple(self._robots[name] for name in sorted(self._robots)),
                self._selection,
                self._seq,
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
                self._record({"event": "graph_error", "error": _message(error)}, "unreachable")
                self._stop.wait(RETRY_SECONDS)
                continue
            with self._changed:
                self._watcher = watcher
            try:
                with watcher:
                    if self._stop.is_set():
                        return
                    for event in watcher.events():
                        self._record(event_data(event, self.solution))
            except SolverError as error:
                self._record({"event": "graph_error", "error": _message(error)}, "unreachable")
            except Exception as error:
                self._record(
                    {"event": "graph_error", "error": f"{type(error).__name__}: {error}"},
                    "unreachable",
                )
            self._stop.wait(RETRY_SECONDS)

    def _record(self, data: dict[str, Any], status: str | None = None) -> None:
        with self._changed:
            self._seq += 1
            # The studio's own numbering: a watcher's seq restarts when it is made again.
            event = {**data, "seq": self._seq, "watcher_seq": data.get("seq")}
            kind = data.get("event")
            if kind in ("robot_added", "robot_changed"):
                self._robots[str(data["robot"])] = data
            elif kind == "robot_removed":
                self._robots.pop(str(data["robot"]), None)
            elif kind == "selection_changed":
                self._selection = data
            elif kind in ("synced", "master_back"):
                self._status = "synced" if kind == "synced" else "back"
            elif kind == "master_lost":
                self._status = "lost"
                self._robots.clear()
            if status is not None:
                self._status = status
                self._robots.clear()
            self._events.append(event)
            self._changed.notify_all()
            self._wake()


def live_feed(
    address: GraphAddress,
    solution: Solution,
    profile: Profile,
    *,
    interval: float = 0.2,
    timeout: float = 2.0,
) -> LiveFeed:
    """The feed of the graph at ``address`` for ``solution``'s team, named as a person reads
    the address; each watcher it runs is made as ``watch`` makes its own
    (:func:`solver.open_watcher`)."""
    from solver import open_watcher

    def make() -> Watcher:
        return open_watcher(address, solution, profile, interval=interval, timeout=timeout)

    return LiveFeed(address.label, solution, make)


def _message(error: SolverError) -> str:
    return "; ".join(str(fault) for fault in error.faults)
