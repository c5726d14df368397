"""Every process the test run starts, found again: to end a group of them, and to fail the run
when one outlives it. A pytest plugin (``-p tests.processes`` in pyproject.toml's ``addopts``).

The suite's ``conftest`` puts a mark in its own environment at start-up
(``TELEOP_UI_TEST_RUN=<pid>-<random>``). Every process a test starts inherits it, and so do the
processes *those* start (``roscore`` starts ``rosmaster`` and ``rosout`` in sessions of their
own, a watcher starts DDS threads, xacro runs in a child), even once they are orphaned and
reparented to init: the mark is read back from ``/proc/<pid>/environ``, which is what a process
was started with. Linux only, as the live tests are.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import signal
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

__all__ = ["MARK", "Process", "end", "marked", "run_mark"]

MARK = "TELEOP_UI_TEST_RUN"


def run_mark() -> str:
    """This run's mark, set in the environment on first use (and inherited from then on)."""
    return os.environ.setdefault(MARK, f"{os.getpid()}-{secrets.token_hex(4)}")


@dataclass(frozen=True)
class Process:
    pid: int
    command: str
    parent: int


def _parent(pid: str) -> int:
    try:
        stat = Path("/proc", pid, "stat").read_text()
    except OSError:
        return 0
    # The command name (2nd field) is parenthesised and may hold spaces.
    return int(stat.rsplit(")", 1)[1].split()[1])


def _environment(pid: str) -> bytes:
    try:
        return Path("/proc", pid, "environ").read_bytes()
    except OSError:  # gone meanwhile, or not ours to read
        return b""


def _command(pid: str) -> str:
    try:
        raw = Path("/proc", pid, "cmdline").read_bytes()
    except OSError:
        return "?"
    return raw.replace(b"\0", b" ").decode("utf-8", "replace").strip()


def marked(
    mark: str, *, variable: str = MARK, exclude: frozenset[int] = frozenset()
) -> list[Process]:
    """The live processes started with ``variable=mark`` in their environment (zombies, which
    have no environment left, are not counted: they have ended)."""
    needle = f"{variable}={mark}".encode()
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit() or int(entry.name) in exclude:
            continue
        if needle in _environment(entry.name).split(b"\0"):
            found.append(Process(int(entry.name), _command(entry.name), _parent(entry.name)))
    return sorted(found, key=lambda p: p.pid)


def end(processes: list[Process]) -> None:
    """SIGKILL each process's group (never the test run's own) and the process itself."""
    own = os.getpgrp()
    for process in processes:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            group = os.getpgid(process.pid)
            if group != own:
                os.killpg(group, signal.SIGKILL)
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.kill(process.pid, signal.SIGKILL)


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
