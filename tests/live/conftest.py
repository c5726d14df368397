"""Fixtures for the live tests: a real roscore, a node to register with, and running watchers.

* ``shared_roscore`` (one per test module) and ``master`` (per test: that roscore, emptied of
  every registration and parameter the test made, afterwards). Tests that kill the master
  start their own with ``own_roscore``.
* ``node``: a :class:`~tests.live.roscore.TestNode` on the master.
* ``domain``: a DDS domain of the test's own, on loopback (:class:`~tests.live.ros2_graph.Domain`),
  for the ROS 2 tests; the robots started on it are ended afterwards.
* ``start_watcher``: a :class:`~solver.live.watcher.Watcher` running in a thread, its events
  recorded; :meth:`Recorder.wait_for` polls for an event with a generous timeout (never a
  duration assertion: the machine may be loaded).

If ``roscore`` is missing the tests fail, they do not skip: ``tools/test.sh`` installs
Debian's ``ros-core``.
"""

from __future__ import annotations

import http.server
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from solver.core.team import load_team
from solver.identify.profile import Profile, load_profile
from solver.live.events import Event, event_data
from solver.live.watcher import Watcher
from solver.solving.solution import Solution, solve
from tests.conftest import TEAMS
from tests.live.ros2_graph import Domain, write_config
from tests.live.roscore import Roscore, TestNode, roscore_available

EVENT_TIMEOUT = 60.0  # seconds to wait for an expected event before failing


def _require_roscore() -> None:
    if not roscore_available():
        pytest.fail(
            "roscore is not installed: install Debian's ros-core "
            "(tools/test.sh does); the live tests need a real ROS master"
        )


@pytest.fixture(scope="module")
def shared_roscore(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Roscore]:
    _require_roscore()
    core = Roscore(tmp_path_factory.mktemp("ros"))
    core.start()
    yield core
    core.kill()


@pytest.fixture
def master(shared_roscore: Roscore) -> Iterator[Roscore]:
    yield shared_roscore
    cleaner = TestNode(shared_roscore.uri)
    cleaner.clear()
    cleaner.close()


@pytest.fixture
def own_roscore(tmp_path: Path) -> Iterator[Roscore]:
    """A roscore of this test's own, which it may kill and restart."""
    _require_roscore()
    core = Roscore(tmp_path / "ros")
    (tmp_path / "ros").mkdir()
    core.start()
    yield core
    core.kill()


@pytest.fixture
def node(master: Roscore) -> Iterator[TestNode]:
    test_node = TestNode(master.uri)
    yield test_node
    test_node.clear()
    test_node.close()


class _NotFound(http.server.BaseHTTPRequestHandler):
    def do_POST(self) -> None:
        self.send_response(404)
        self.send_header("Content-Length", "0")
        self.end_headers()

    def log_message(self, format: str, *args: Any) -> None:
        """Quiet: the tests read what the client reports."""


@pytest.fixture
def web_server() -> Iterator[str]:
    """The URI of a web server that is not a ROS master (it answers every call with 404)."""
    server = http.server.HTTPServer(("127.0.0.1", 0), _NotFound)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}/"
    server.shutdown()
    server.server_close()


@pytest.fixture
def domain(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Domain]:
    """A DDS domain of this test's own on loopback; the robots started on it end with the test."""
    monkeypatch.setenv("CYCLONEDDS_URI", write_config(tmp_path))
    monkeypatch.setenv("ROS_DOMAIN_ID", "999")  # never used: every test names its domain
    import os

    found = Domain(tmp_path, dict(os.environ))
    yield found
    for robot in found.robots:
        robot.kill()


@pytest.fixture(scope="session")
def solution() -> Solution:
    return solve(load_team(TEAMS / "case3.yaml"))


@pytest.fixture(scope="session")
def profile() -> Profile:
    return load_profile()


class Recorder:
    """Runs ``watcher.events()`` on a thread and keeps every event."""

    def __init__(self, watcher: Watcher, solution: Solution) -> None:
        self.watcher = watcher
        self.solution = solution
        self.events: list[Event] = []
        self.error: BaseException | None = None
        self._changed = threading.Condition()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        try:
            for event in self.watcher.events():
                with self._changed:
                    self.events.append(event)
                    self._changed.notify_all()
        except BaseException as error:  # kept for the test to see, then re-raised there
            self.error = error
        with self._changed:
            self._changed.notify_all()

    def data(self, start: int = 0) -> list[dict[str, Any]]:
        with self._changed:
            return [event_data(e, self.solution) for e in self.events[start:]]

    def mark(self) -> int:
        """The number of events so far: pass it as ``after`` to wait only for newer ones."""
        with self._changed:
            return len(self.events)

    def wait_for(
        self,
        predicate: Callable[[dict[str, Any]], bool],
        what: str,
        *,
        after: int = 0,
        timeout: float = EVENT_TIMEOUT,
    ) -> dict[str, Any]:
        """The first event from index ``after`` on whose JSON data satisfies ``predicate``."""
        checked = after
        with self._changed:
            while True:
                while checked < len(self.events):
                    data = event_data(self.events[checked], self.solution)
                    checked += 1
                    if predicate(data):
                        return data
                if self.error is not None:
                    raise AssertionError(f"the watcher failed: {self.error!r}")
                if not self.thread.is_alive():
                    raise AssertionError(f"the watcher ended before {what}")
                if not self._changed.wait(timeout):
                    seen = [event_data(e, self.solution)["event"] for e in self.events]
                    raise AssertionError(f"no {what} within {timeout:.0f} s; events: {seen}")

    def wait_for_event(
        self, kind: str, robot: str | None = None, *, after: int = 0
    ) -> dict[str, Any]:
        return self.wait_for(
            lambda d: d["event"] == kind and (robot is None or d.get("robot") == robot),
            f"{kind} {robot or ''}".strip(),
            after=after,
        )

    def stop(self) -> None:
        self.watcher.stop("test over")
        self.thread.join(timeout=EVENT_TIMEOUT)
        self.watcher.close()


@pytest.fixture
def start_watcher(solution: Solution, profile: Profile) -> Iterator[Callable[..., Recorder]]:
    """``start_watcher(uri, **options)``: a running watcher, stopped and closed afterwards."""
    started: list[Recorder] = []

    def start(uri: str, **options: Any) -> Recorder:
        recorder = Recorder(Watcher(uri, solution, profile, **options), solution)
        started.append(recorder)
        return recorder

    yield start
    for recorder in started:
        recorder.stop()
