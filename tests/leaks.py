"""A pytest plugin (``-p tests.leaks`` in pyproject.toml's ``addopts``): the run fails when a
process it started is still alive at its end, and ends it; found by the run's mark
(:mod:`tests.processes`)."""

from __future__ import annotations

import os
import signal
import time

import pytest

from tests.processes import Process, end, marked, run_mark

__all__ = ["GRACE_VARIABLE"]

# A process that is ending when the run ends gets this long to be gone before it is a leak
# (seconds; a run of pytest that leaks on purpose, in tests/test_processes.py, sets less).
GRACE_VARIABLE = "TELEOP_UI_TEST_GRACE"
GRACE = float(os.environ.get(GRACE_VARIABLE, "10"))
# multiprocessing's own service processes, started for the run's process by an in-process
# `batch` (tests.conftest.run_cli): they serve it until it exits, and then end themselves.
_SERVICES = (
    "from multiprocessing.forkserver import",
    "from multiprocessing.resource_tracker import",
)


def _leaks(mark: str) -> list[Process]:
    me = os.getpid()
    return [
        p
        for p in marked(mark, exclude=frozenset({me}))
        if not (p.parent == me and any(service in p.command for service in _SERVICES))
    ]


def pytest_configure(config: pytest.Config) -> None:
    run_mark()
    # A run started in the background of a shell without job control (`cmd &` in a script, some
    # CI runners) inherits SIGINT ignored, and so would every process the tests start: the tests
    # of what Ctrl-C does would then wait for an exit that never comes. A user's terminal
    # delivers SIGINT; the run restores Python's handler, so its children start with the default.
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    """Fail the run when a process it started is still alive (and end it)."""
    mark = run_mark()
    if not mark.startswith(f"{os.getpid()}-"):
        return  # a nested run (a test running pytest): the outer run checks
    deadline = time.monotonic() + GRACE
    left = _leaks(mark)
    while left and time.monotonic() < deadline:
        time.sleep(0.2)
        left = _leaks(mark)
    if not left:
        return
    end(left)
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    lines = [f"  {p.pid}: {p.command[:200]}" for p in left]
    message = "processes started by the tests were still alive at the end (killed now):"
    if reporter is not None:
        reporter.write_line(message, red=True, bold=True)
        for line in lines:
            reporter.write_line(line, red=True)
    session.exitstatus = pytest.ExitCode.TESTS_FAILED
