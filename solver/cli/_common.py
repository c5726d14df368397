"""Options and helpers the commands share: output format, rule and team arguments, writing."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from solver.team import Team

__all__ = ["add_engine", "add_format", "add_master_options", "add_profile", "add_rules",
           "load_team_argument", "positive", "seconds", "write"]


def add_format(parser: argparse.ArgumentParser, choices: tuple[str, ...],
               default: str = "text") -> None:
    parser.add_argument("--format", "-f", choices=choices, default=default,
                        help=f"output format (default: {default})")


def add_engine(parser: argparse.ArgumentParser, *, enumerate_only: bool = False) -> None:
    """--engine and --max-robots, for commands that count or enumerate robots."""
    if enumerate_only:
        parser.add_argument("--engine", "-e", choices=("fast", "csp"), default="fast",
                            help="fast (default): numpy enumeration; csp: python-constraint "
                                 "enumeration (the reference)")
    else:
        parser.add_argument("--engine", "-e", choices=("auto", "structure", "fast", "csp"),
                            default="auto",
                            help="structure: count without enumerating; fast: numpy "
                                 "enumeration; csp: python-constraint enumeration (the "
                                 "reference); auto (default): structure where it applies, "
                                 "else fast")
    parser.add_argument("--max-robots", type=positive, default=10**8, metavar="N",
                        help="refuse to enumerate more robots than this "
                             "(default: 100000000)")


def positive(text: str) -> int:
    """An argparse type: a whole number of at least 1 (``100000000`` or ``100_000_000``)."""
    try:
        number = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None
    if number < 1:
        raise argparse.ArgumentTypeError(f"expected a number of at least 1, got {text!r}")
    return number


def seconds(text: str) -> float:
    """An argparse type: seconds from 0.01 (below that, polls and timeouts mean nothing) to an
    hour."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected seconds, got {text!r}") from None
    if not 0.01 <= value <= 3600:
        raise argparse.ArgumentTypeError(f"expected seconds from 0.01 to 3600, got {text!r}")
    return value


def add_master_options(parser: argparse.ArgumentParser, *, required_help: str) -> None:
    """--master and --timeout, for the commands that read a ROS master."""
    parser.add_argument("--master", "-m", metavar="URL",
                        help=f"ROS master URI, e.g. http://127.0.0.1:11311 ({required_help})")
    parser.add_argument("--timeout", type=seconds, default=2.0, metavar="S",
                        help="seconds to wait for the master to accept a connection, and for "
                             "each part of its reply (default: 2)")


def add_profile(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--profile", "-p", metavar="PROFILE.yaml",
                        help="identification profile (default: the shipped "
                             "rules/identification.yaml)")


def add_rules(parser: argparse.ArgumentParser,
              help: str = "rule set to use instead of the one the team file names "
                          "(default: the team's 'rules:', else the shipped paper rules)"
              ) -> None:
    parser.add_argument("--rules", "-r", metavar="RULES.yaml", help=help)


def load_team_argument(text: str, rules: str | None) -> Team:
    """A team given on the command line: a file, or the name of a shipped team (``case3``)."""
    from solver.rules import shipped_name
    from solver.team import load_team, resolve_team_path

    path = resolve_team_path(text)
    shown = text if str(path) == text else (shipped_name(path) or str(path))
    return load_team(path, rules, display=shown)


def write(text: str) -> None:
    sys.stdout.write(text)
    sys.stdout.flush()
