"""Every process the test run starts, found again: to end a group of them, and (the plugin in
:mod:`tests.leaks`) to fail the run when one outlives it. No pytest here: the fleet emulation
of ``tools/demo_fleet.py`` uses these helpers in an install without the test tools.

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
from dataclasses import dataclass
from pathlib import Path

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
