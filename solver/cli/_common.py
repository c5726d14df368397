"""Options and helpers the commands share: output format, rule and team arguments, writing."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from solver.untrusted import shown

if TYPE_CHECKING:
    from pathlib import Path

    from solver.core.team import Team

__all__ = [
    "add_engine",
    "add_format",
    "add_master_options",
    "add_profile",
    "add_rules",
    "add_set",
    "load_team_argument",
    "positive",
    "seconds",
    "team_path",
    "write",
]


def add_format(
    parser: argparse.ArgumentParser, choices: tuple[str, ...], default: str = "text"
) -> None:
    parser.add_argument(
        "--format",
        "-f",
        choices=choices,
        default=default,
        help=f"output format (default: {default})",
    )


def add_engine(parser: argparse.ArgumentParser, *, enumerate_only: bool = False) -> None:
    """--engine and --max-robots, for commands that count or enumerate robots."""
    from solver.engines import DESCRIPTIONS, ENUMERATING, MAX_ROBOTS, NAMES

    if enumerate_only:
        parser.add_argument(
            "--engine",
            "-e",
            choices=ENUMERATING,
            default=ENUMERATING[0],
            help="; ".join(f"{name}: {DESCRIPTIONS[name]}" for name in ENUMERATING)
            + f" (default: {ENUMERATING[0]})",
        )
    else:
        parser.add_argument(
            "--engine",
            "-e",
            choices=NAMES,
            default=NAMES[0],
            help="; ".join(f"{name}: {DESCRIPTIONS[name]}" for name in NAMES[1:])
            + f"; {NAMES[0]} (default): the structure where it applies, "
            "else fast enumeration",
        )
    parser.add_argument(
        "--max-robots",
        type=positive,
        default=MAX_ROBOTS,
        metavar="N",
        help=f"refuse to enumerate more robots than this (default: {MAX_ROBOTS})",
    )


def positive(text: str) -> int:
    """An argparse type: a whole number of at least 1 (``100000000`` or ``100_000_000``), in
    ASCII digits (``int`` reads ``٣`` as 3) and at most 18 of them (``int`` of 4,300 raises)."""
    from solver.untrusted import shown

    digits = text.strip().lstrip("+").replace("_", "")
    if digits.isdecimal() and (not digits.isascii() or len(digits) > 18):
        raise argparse.ArgumentTypeError(
            f"expected a whole number of at most 18 digits 0-9, got {shown(text, quoted=True)}"
        )
    try:
        number = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected a whole number, got {shown(text, quoted=True)}"
        ) from None
    if number < 1:
        raise argparse.ArgumentTypeError(
            f"expected a number of at least 1, got {shown(text, quoted=True)}"
        )
    return number


def seconds(text: str) -> float:
    """An argparse type: seconds from 0.01 (below that, polls and timeouts mean nothing) to an
    hour."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected seconds, got {shown(text, quoted=True)}"
        ) from None
    if not 0.01 <= value <= 3600:
        raise argparse.ArgumentTypeError(
            f"expected seconds from 0.01 to 3600, got {shown(text, quoted=True)}"
        )
    return value


def add_time_limit(parser: argparse.ArgumentParser, name: str, what: str) -> None:
    """--time-limit S: the time budget of limit ``name`` (docs/security.md) for ``what``."""
    from solver.limits import limit

    parser.add_argument(
        "--time-limit",
        type=seconds,
        default=None,
        metavar="S",
        help=f"stop {what} after S seconds, with exit status 2 (default: "
        f"{limit(name).value}; limit '{name}', docs/security.md)",
    )


def add_master_options(parser: argparse.ArgumentParser, *, required_help: str) -> None:
    """--master and --timeout, for the commands that read a ROS master."""
    parser.add_argument(
        "--master",
        "-m",
        metavar="URL",
        help=f"ROS master URI, e.g. http://127.0.0.1:11311 ({required_help})",
    )
    parser.add_argument(
        "--timeout",
        type=seconds,
        default=2.0,
        metavar="S",
        help="seconds each call to the master may take in all: connecting, sending "
        "and reading the whole reply (default: 2)",
    )


def add_profile(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--profile",
        "-p",
        metavar="PROFILE.yaml",
        help="identification profile (default: the shipped rules/identification.yaml)",
    )


def add_set(parser: argparse.ArgumentParser, *, per_robot: bool = True) -> None:
    """``--set NAME=VALUE`` (repeatable): a characteristic's value given at start."""
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="[/ROBOT:]NAME=VALUE" if per_robot else "NAME=VALUE",
        help="a value of a characteristic of the rule set identification does not give, or "
        "replaces (e.g. --set comm_link=Wi-Fi"
        + (", or --set /uav1:comm_link=LTE for one robot" if per_robot else "")
        + "; repeatable)",
    )


def add_rules(
    parser: argparse.ArgumentParser,
    help: str = "rule set to use instead of the one the team file names "
    "(default: the team's 'rules:', else the shipped paper rules)",
) -> None:
    parser.add_argument("--rules", "-r", metavar="RULES.yaml", help=help)


def add_team(parser: argparse.ArgumentParser) -> None:
    """The required team file (``--team``/``-t``) and the ``--rules`` that may replace its own."""
    parser.add_argument(
        "--team",
        "-t",
        required=True,
        metavar="TEAM.yaml",
        help="team selection file (or a shipped team name)",
    )
    add_rules(parser)


def team_path(text: str) -> Path:
    """The file of a team argument: as given, or a shipped team's (``case3``); a bare word that
    is neither raises an :class:`InputError` listing the shipped teams."""
    from solver.core.rules import shipped_path
    from solver.core.team import resolve_team_path
    from solver.errors import InputError

    path = resolve_team_path(text)
    if not os.path.exists(path) and not path.suffix and path.name == text:
        # A bare word is a shipped team's name or a typo of one: say which names exist.
        names = sorted(team.stem for team in shipped_path("teams").glob("*.yaml"))
        raise InputError.at(
            text,
            f"no such file, and no shipped team of that name; shipped teams: {', '.join(names)}",
        )
    return path


def load_team_argument(text: str, rules: str | None) -> Team:
    """A team given on the command line: a file, or the name of a shipped team (``case3``)."""
    from solver.core.rules import shipped_name
    from solver.core.team import load_team

    path = team_path(text)
    shown = text if str(path) == text else (shipped_name(path) or str(path))
    return load_team(path, rules, display=shown)


def write(text: str) -> None:
    sys.stdout.write(text)
    sys.stdout.flush()
