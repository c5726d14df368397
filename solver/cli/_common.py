"""Options and helpers the commands share: output format, rule and team arguments, writing."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from solver.team import Team

__all__ = ["add_engine", "add_format", "add_rules", "load_team_argument", "write"]


def add_format(parser: argparse.ArgumentParser, choices: tuple[str, ...],
               default: str = "text") -> None:
    parser.add_argument("--format", "-f", choices=choices, default=default,
                        help=f"output format (default: {default})")


def add_engine(parser: argparse.ArgumentParser) -> None:
    """--engine and --max-robots, for commands that count or enumerate robots."""
    parser.add_argument("--engine", "-e", choices=("auto", "structure", "fast", "csp"),
                        default="auto",
                        help="structure: count without enumerating; fast: numpy enumeration; "
                             "csp: python-constraint enumeration (the reference); auto "
                             "(default): structure where it applies, else fast")
    parser.add_argument("--max-robots", type=_positive, default=10**8, metavar="N",
                        help="refuse to enumerate more robots than this (default: 10^8)")


def _positive(text: str) -> int:
    try:
        number = int(float(text)) if "e" in text.lower() else int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None
    if number < 1:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}")
    return number


def add_rules(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--rules", "-r", metavar="RULES.yaml",
                        help="rule set to use instead of the one the team file names "
                             "(default: the team's 'rules:', else the shipped paper rules)")


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
