"""The ``teleop-ui`` command line: a thin layer over the library.

Each command lives in its own module here, named in :data:`COMMANDS` (the one list of
commands: a module that is not named there is no command), and exposes
``register(subparsers)``; the module's ``run(args)`` parses nothing itself, calls the library
(its public API, :mod:`solver`, where that has the thing), writes the result and returns the
exit status. A command imports the library and the shared options (``_common``, ``_progress``,
``_terminal``), never another command (tests/test_architecture.py). :func:`main` is the
one place that turns a :class:`~solver.errors.SolverError` into a message on stderr and exit
status 2. Heavy imports happen inside ``run`` so that start-up stays fast.

:func:`main` is also the one place that handles output streams that fail, for every command:
standard output closed (``>&-``) or full (``> /dev/full``) ends the command with exit status 2
and one line on standard error (when that can still be written); a pipe its reader closed
early (``| head -1``) ends it quietly with status 0, as well-behaved tools do. No traceback,
and nothing more is attempted on the failed stream (it is pointed at ``/dev/null``, so the
interpreter's own last flush at exit does not fail again).
"""

from __future__ import annotations

import argparse
import gc
import importlib
import os
import sys
from collections.abc import Sequence
from typing import Any, NoReturn

from solver import SolverError
from solver.cli._terminal import EscapingStream, OutputFailed
from solver.errors import Terminated

__all__ = ["COMMANDS", "build_parser", "console", "main"]

# Every command and its module, in the order ``teleop-ui --help`` lists them. A module is
# imported only when its command runs (or for the whole --help), so start-up stays short.
COMMANDS: dict[str, str] = {
    "assign": "solver.cli.assign",
    "batch": "solver.cli.batch",
    "check": "solver.cli.check",
    "count": "solver.cli.count",
    "demo": "solver.cli.demo",
    "export": "solver.cli.export",
    "fleet": "solver.cli.fleet",
    "identify": "solver.cli.identify",
    "layouts": "solver.cli.layouts",
    "report": "solver.cli.report",
    "reproduce": "solver.cli.reproduce",
    "robots": "solver.cli.robots",
    "solve": "solver.cli.solve",
    "studio": "solver.cli.studio",
    "switch": "solver.cli.switch",
    "watch": "solver.cli.watch",
}


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command, or of ``command`` alone when it names one (what a run
    needs: the other commands' modules are not imported, which keeps start-up short)."""
    parser = _Parser(
        prog="teleop-ui",
        description="Design teleoperation UI configurations for heterogeneous robot teams: "
        "robot characteristics, relationship rules, team selections.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {_version()}")
    subparsers = parser.add_subparsers(
        dest="command", metavar="COMMAND", required=True, parser_class=_Parser
    )
    for name in [command] if command in COMMANDS else COMMANDS:
        importlib.import_module(COMMANDS[name]).register(subparsers)
    return parser


class _Formatter(argparse.HelpFormatter):
    """argparse's help formatter, told the terminal's width: left to itself it imports
    ``shutil`` (and with it zlib, bz2 and lzma) to ask, a millisecond of every command's
    start-up. The width is found as ``shutil.get_terminal_size`` finds it."""

    def __init__(
        self,
        prog: str,
        indent_increment: int = 2,
        max_help_position: int = 24,
        width: int | None = None,
    ) -> None:
        if width is None:
            width = _columns() - 2
        super().__init__(prog, indent_increment, max_help_position, width)


class _Parser(argparse.ArgumentParser):
    """An argument parser whose help is laid out by :class:`_Formatter`."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)


def _columns() -> int:
    """The terminal's width in columns: ``$COLUMNS``, else standard output's terminal, else 80."""
    try:
        columns = int(os.environ.get("COLUMNS", ""))
    except ValueError:
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):  # no standard output, or no terminal
            columns = 0
    return columns if columns > 0 else 80


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (0 ok, 1 findings, 2 unusable input)."""
    arguments = sys.argv[1:] if argv is None else list(argv)
    # numpy starts an OpenBLAS thread per core on import, which spin while it loads (about
    # 50 ms of CPU on two cores); no command multiplies matrices. A user's own setting stands.
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    parser = build_parser(arguments[0] if arguments else None)
    args = parser.parse_args(arguments)
    # Names and messages come from files strangers wrote: no raw escape sequence reaches the
    # terminal (see solver/cli/_terminal.py).
    stdout, stderr = sys.stdout, sys.stderr
    _hold_closed_descriptors()
    # An EscapingStream is a TextIO in all but name (it delegates everything but write).
    sys.stdout = EscapingStream(stdout, "standard output")
    sys.stderr = EscapingStream(stderr, "standard error")
    try:
        status: int = args.run(args)
        sys.stdout.flush()  # a full disk shows here, not in the interpreter's flush at exit
    except SolverError as error:
        _say(error)
        return 2
    except KeyboardInterrupt:
        _say("interrupted")
        return 130
    except OutputFailed as failed:
        failing = stdout if failed.name == "standard output" else stderr
        _to_null(failing)
        if failed.reader_gone:
            return 0  # the reader went away (| head): nothing more to say
        if failing is not stderr:
            _say(f"teleop-ui: {failed}")
        return 2
    except Terminated:
        print("terminated", file=sys.stderr)
        return 143
    except BrokenPipeError:
        # A progress bar on the terminal itself (a rich console) lost its reader.
        _to_null(stdout)
        _to_null(stderr)
        return 0
    finally:
        sys.stdout, sys.stderr = stdout, stderr
    return status


def console() -> NoReturn:
    """The ``teleop-ui`` program (and ``python -m solver``): :func:`main`, then exit.

    Before the exit, the objects still alive are moved to the cycle collector's permanent
    generation (``gc.freeze``). The interpreter's shutdown would otherwise walk all of them
    looking for cycles, about 5 ms of a 65 ms ``solve`` (measured: docs/benchmarks.md),
    though a finished command leaves none worth finding: standard output is flushed by
    :func:`main` and every file a command writes is closed when it is written. Objects are
    still freed at shutdown by their reference counts, as before. Not in :func:`main`, which
    tests and programs call in their own process: freezing is for a process about to end.
    """
    status = main()
    gc.freeze()
    sys.exit(status)


def _hold_closed_descriptors() -> None:
    """Give a closed descriptor 0, 1 or 2 (``>&-``) to /dev/null: the next file opened would
    take its number, and a child process would then write its output into that file."""
    for descriptor in (0, 1, 2):
        try:
            os.fstat(descriptor)
        except OSError:
            # The lowest free number is the closed one (lower ones are open, or held here).
            os.open(os.devnull, os.O_RDWR)


def _say(message: object) -> None:
    """``message`` on one line of standard error, if standard error can still be written."""
    try:
        print(message, file=sys.stderr, flush=True)
    except (OutputFailed, OSError):
        _to_null(sys.stderr)


def _to_null(stream: Any) -> None:
    """Point a failed stream's descriptor at /dev/null, so that the interpreter's last flush
    at exit (of what is still buffered) fails no more; a stream without one is left alone."""
    try:
        descriptor = stream.fileno()
    except (AttributeError, OSError, ValueError):
        return
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(null, descriptor)
    finally:
        os.close(null)


def _version() -> str:
    from solver import __version__

    return __version__
