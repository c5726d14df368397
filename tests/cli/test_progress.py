"""Progress (:mod:`solver.cli._progress`): a spinner on a terminal for long work only, never on a
pipe or in JSON."""

from __future__ import annotations

import io
import threading

from rich.console import Console

from solver.cli._progress import wanted, working
from tests.conftest import run_cli


def _terminal() -> tuple[Console, io.StringIO]:
    buffer = io.StringIO()
    return Console(file=buffer, force_terminal=True, width=60), buffer


def test_long_work_shows_what_is_being_done_on_a_terminal() -> None:
    console, buffer = _terminal()
    never = threading.Event()
    with working("solving Big team", delay=0.0, console=console):
        # The spinner starts on a timer thread: wait for it (a condition, not a duration).
        for _ in range(3000):
            if "solving Big team" in buffer.getvalue():
                break
            never.wait(timeout=0.01)
    assert "solving Big team" in buffer.getvalue()


def test_work_that_ends_before_the_delay_shows_nothing() -> None:
    console, buffer = _terminal()
    with working("solving Small team", delay=3600.0, console=console):
        pass
    assert buffer.getvalue() == ""


def test_no_spinner_on_a_pipe_or_for_json() -> None:
    class Tty(io.StringIO):
        def isatty(self) -> bool:
            return True

    assert wanted("text", Tty())
    assert not wanted("json", Tty())
    assert not wanted("sarif", Tty())
    assert not wanted("text", io.StringIO())


def test_commands_on_a_pipe_write_nothing_but_their_output() -> None:
    for command in (
        ("solve", "case3"),
        ("count", "case3"),
        ("check", "rules/paper.yaml"),
        ("identify", "examples/quadrotor.urdf"),
    ):
        result = run_cli(*command)
        assert result.returncode == 0
        assert result.stderr == ""
