"""The ``teleop-ui`` command line: a thin layer over the library.

Each command lives in its own module here (found automatically: every module whose name does
not start with an underscore) and exposes ``register(subparsers)``; the module's
``run(args)`` parses nothing itself, calls the library, writes the result and returns the exit
status. :func:`main` is the one place that turns a :class:`~solver.errors.SolverError` into a
message on stderr and exit status 2. Heavy imports happen inside ``run`` so that start-up
stays fast.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence
from pathlib import Path

from solver.cli._terminal import EscapingStream
from solver.errors import SolverError

__all__ = ["main"]


def command_modules() -> list[str]:
    """The command modules, in name order (the order ``teleop-ui --help`` lists them)."""
    package = Path(__file__).parent
    return sorted(path.stem for path in package.glob("*.py") if not path.stem.startswith("_"))


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command, or of ``command`` alone when it names one (what a run
    needs: the other commands' modules are not imported, which keeps start-up short)."""
    parser = argparse.ArgumentParser(
        prog="teleop-ui",
        description="Design teleoperation UI configurations for heterogeneous robot teams: "
        "robot characteristics, relationship rules, team selections.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {_version()}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    names = command_modules()
    for name in [command] if command in names else names:
        importlib.import_module(f"solver.cli.{name}").register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (0 ok, 1 findings, 2 unusable input)."""
    arguments = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(arguments[0] if arguments else None)
    args = parser.parse_args(arguments)
    # Names and messages come from files strangers wrote: no raw escape sequence reaches the
    # terminal (see solver/cli/_terminal.py).
    stdout, stderr = sys.stdout, sys.stderr
    # An EscapingStream is a TextIO in all but name (it delegates everything but write).
    sys.stdout = EscapingStream(stdout)
    sys.stderr = EscapingStream(stderr)
    try:
        status: int = args.run(args)
    except SolverError as error:
        print(error, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # The reader went away (| head); nothing more to say.
        stderr.close()
        return 0
    finally:
        sys.stdout, sys.stderr = stdout, stderr
    return status


def _version() -> str:
    from solver import __version__

    return __version__
