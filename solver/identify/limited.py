"""Running a piece of the package in a fresh, limited interpreter: one JSON request in, one out.

Two readers hand a stranger's file to code that cannot bound itself: xacro runs the file's
Python (:mod:`solver.identify.xacro`), and the bag library's time, memory and temporary space
grow with what a bag declares (:mod:`solver.identify.readers.bags`). Each runs in a child
process started here: ``python -I -S -B`` (no user site, no ``.pth`` files, no bytecode written)
with an empty environment apart from what the caller passes, in a session of its own, fed one
JSON request on stdin. The child lowers its own resource limits; this side

* reads at most ``answer_bytes`` of its answer, and stops the child as soon as it writes more
  (left writing into a full pipe, it would wait there until the wall-clock limit);
* stops it (its whole process group, ``SIGKILL``) after ``wall_seconds`` of wall-clock time, or
  as soon as ``watch`` names a reason (polled every 50 ms: a temporary folder grown too big);
* stops it as well when the caller is interrupted while waiting (``KeyboardInterrupt``,
  ``SystemExit``), so no child outlives the command.

What the answer means, and the message for each way a child ends, is the caller's.

Not here: the limits and fences inside each child (:mod:`solver.identify.xacro.child`,
:mod:`solver.identify.readers.bag_child`).
"""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import IO, Any

__all__ = ["Finished", "run_limited"]

_POLL_SECONDS = 0.05


@dataclass(frozen=True, slots=True)
class Finished:
    """How a limited child ended."""

    answer: dict[str, Any] | None  # the JSON object it wrote, if it wrote one this side read
    returncode: int  # negative: the signal that ended it
    stopped: str | None = None  # why this side stopped it: "time", or what `watch` said
    oversized: bool = False  # it wrote more than `answer_bytes`

    @property
    def signal(self) -> int | None:
        return -self.returncode if self.returncode < 0 else None


def run_limited(
    arguments: Sequence[str],
    request: Mapping[str, Any],
    *,
    wall_seconds: float,
    answer_bytes: int,
    env: Mapping[str, str] | None = None,
    cwd: str | None = None,
    watch: Callable[[], str | None] | None = None,
) -> Finished:
    """Run ``python -I -S -B *arguments`` with ``request`` on stdin (see the module docstring)."""
    process = subprocess.Popen(
        [sys.executable, "-I", "-S", "-B", *arguments],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env={"PATH": os.defpath, "LANG": "C.UTF-8", **(env or {})},
        cwd=cwd,
        start_new_session=True,
    )
    output: list[bytes] = []
    reader = threading.Thread(
        target=_read_bounded,
        args=(process.stdout, output, answer_bytes + 1, lambda: _signal_group(process)),
        daemon=True,
    )
    reader.start()
    stopped = None
    try:
        if process.stdin is not None:  # always: Popen was given stdin=PIPE
            with process.stdin:
                process.stdin.write(json.dumps(request).encode("utf-8"))
    except BrokenPipeError:
        pass  # it ended before reading its request: its exit status says why
    try:
        stopped = _wait(process, wall_seconds, watch)
    finally:
        if process.returncode is None:  # interrupted while waiting
            _kill(process)
    reader.join(timeout=wall_seconds)
    raw = b"".join(output)
    if len(raw) > answer_bytes:
        return Finished(None, process.returncode, stopped, oversized=True)
    answer = None
    if raw and stopped is None:
        try:
            loaded = json.loads(raw)
        except ValueError:
            loaded = None
        answer = loaded if isinstance(loaded, dict) else None
    return Finished(answer, process.returncode, stopped)


def _wait(
    process: subprocess.Popen[bytes],
    wall_seconds: float,
    watch: Callable[[], str | None] | None,
) -> str | None:
    """Wait for the child; the reason it was stopped, if this side stopped it."""
    if watch is None:
        try:
            process.wait(timeout=wall_seconds)
        except subprocess.TimeoutExpired:
            _kill(process)
            return "time"
        return None
    deadline = time.monotonic() + wall_seconds
    while True:
        try:
            process.wait(timeout=_POLL_SECONDS)
        except subprocess.TimeoutExpired:
            pass
        else:
            return None
        reason = watch()
        if reason is None and time.monotonic() >= deadline:
            reason = "time"
        if reason is not None:
            _kill(process)
            return reason


def _read_bounded(
    stream: IO[bytes] | None, output: list[bytes], limit: int, over: Callable[[], None]
) -> None:
    """Read up to ``limit`` bytes into ``output``; ``over()`` once the limit is reached."""
    if stream is None:
        return
    size = 0
    while size < limit:
        chunk = stream.read(min(1 << 20, limit - size))
        if not chunk:
            return
        output.append(chunk)
        size += len(chunk)
    over()


def _signal_group(process: subprocess.Popen[bytes]) -> None:
    """SIGKILL the child's process group (the waiting side reaps it)."""
    with contextlib.suppress(OSError):  # ended already
        os.killpg(process.pid, 9)


def _kill(process: subprocess.Popen[bytes]) -> None:
    try:
        os.killpg(process.pid, 9)
    except OSError:
        process.kill()
    process.wait()
