"""A spinner on a terminal for work that turns out to be long, and nothing anywhere else.

``solve``, ``count``, ``robots``, ``check`` and ``identify`` usually answer at once; a large
team, rule set or description can take seconds. :func:`working` shows a rich spinner with what
is being done on stderr, but only when stderr is a terminal, the output is not JSON (programs
read it), and the work is still running after ``delay`` seconds (a quick answer never
flickers). On a pipe, in a log or
in JSON mode nothing is written. Batch runs and fleets have their own bars (``cli/batch.py``,
``cli/fleet.py``).
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import IO, Any

from solver.cli._terminal import raw_stream
from solver.untrusted import shown

__all__ = ["DELAY", "working"]

# Seconds of silence before the spinner appears.
DELAY = 1.0


def wanted(fmt: str = "text", stream: IO[str] | None = None) -> bool:
    """Whether a spinner may be shown: a terminal on stderr and no machine-read output."""
    target = sys.stderr if stream is None else stream
    return fmt not in ("json", "jsonl", "sarif") and target.isatty()


@contextmanager
def working(
    what: str, *, fmt: str = "text", delay: float = DELAY, console: Any = None
) -> Iterator[None]:
    """Show ``what`` with a spinner while the block runs, past ``delay`` seconds (see module).

    ``console``: a rich Console to draw on (default: stderr's, when :func:`wanted`).
    """
    if console is None:
        if not wanted(fmt):
            yield
            return
        from rich.console import Console

        console = Console(file=raw_stream(sys.stderr), stderr=True)
    import threading  # here, not at start-up: only a spinner on a terminal needs it

    from rich.markup import escape

    # rich writes to the terminal itself: what it shows is escaped here (team and file names).
    status = console.status(escape(shown(what, limit=None)), spinner="dots")
    lock = threading.Lock()
    state = {"started": False, "done": False}

    def start() -> None:
        with lock:
            if not state["done"]:
                status.start()
                state["started"] = True

    timer = threading.Timer(delay, start)
    timer.daemon = True
    timer.start()
    try:
        yield
    finally:
        with lock:
            state["done"] = True
            timer.cancel()
            if state["started"]:
                status.stop()
