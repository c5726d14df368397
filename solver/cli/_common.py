"""Options and helpers the commands share: output format, rule and team arguments, a robot's
description and the values given beside it, writing.

Only what two or more commands take from the command line is here; what a command does with
it is the library's (a command imports the library and this module, never another command:
tests/test_architecture.py)."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from solver.untrusted import shown

if TYPE_CHECKING:
    from pathlib import Path

    from solver import Profile, RuleSet, Solution, Team

__all__ = [
    "add_description_options",
    "add_engine",
    "add_format",
    "add_master_options",
    "add_profile",
    "add_rules",
    "add_set",
    "add_team",
    "add_time_limit",
    "given_values",
    "load_rules_and_profile",
    "load_team_argument",
    "package_path",
    "positive",
    "seconds",
    "team_path",
    "write",
    "xacro_arguments",
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


def add_ros2_options(parser: argparse.ArgumentParser, *, ros2_help: str) -> None:
    """--ros2 and --domain, for the commands that read a ROS 2 graph."""
    parser.add_argument("--ros2", action="store_true", help=ros2_help)
    parser.add_argument(
        "--domain",
        type=int,
        default=None,
        metavar="N",
        help="with --ros2: the DDS domain id (default: $ROS_DOMAIN_ID, else 0)",
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


def given_values(pairs: list[str], solution: Solution | None) -> dict[str, str]:
    """``--set NAME=VALUE`` pairs for one robot (``identify``, ``layouts --robot``), checked
    against the team's rules (they need ``--team``)."""
    if not pairs:
        return {}
    from solver import InputError
    from solver.live.given import parse_fixed

    if solution is None:
        raise InputError.at("--set", "values are given to a combination: --set needs --team")
    fixed = parse_fixed(pairs, solution.rules)
    if fixed.per_robot:
        raise InputError.at("--set", "one robot here: give NAME=VALUE, without a /ROBOT: part")
    return dict(fixed.everywhere)


def add_description_options(parser: argparse.ArgumentParser) -> None:
    """Options ``identify`` and ``fleet`` share: profile, xacro arguments, package path."""
    add_profile(parser)
    parser.add_argument(
        "--arg",
        dest="xacro_args",
        action="append",
        default=[],
        metavar="NAME:=VALUE",
        help="xacro argument (repeatable)",
    )
    parser.add_argument(
        "--trust-xacro",
        action="store_true",
        help="compile .xacro files: xacro runs Python code written in the file, "
        "so only for files you trust (run in a child process with CPU, "
        "memory and time limits; see docs/security.md)",
    )
    parser.add_argument(
        "--strict",
        action="store_true",
        help="treat the description's and SRDF's warnings (flaws read past: a "
        "missing link, a duplicate, a joint type outside the spec) as "
        "errors, exit 2",
    )
    parser.add_argument(
        "--package-path",
        action="append",
        default=[],
        metavar="DIR",
        help="folder holding ROS packages for $(find pkg) and package:// "
        "(repeatable; default: $TELEOP_UI_PACKAGE_PATH)",
    )


def xacro_arguments(pairs: list[str]) -> dict[str, str]:
    """``--arg NAME:=VALUE`` pairs, as xacro takes them; a located error for anything else."""
    from solver import InputError

    found: dict[str, str] = {}
    for pair in pairs:
        name, sep, value = pair.partition(":=")
        if not sep or not name.strip():
            raise InputError.at(
                "<arguments>", f"--arg expects NAME:=VALUE, got {shown(pair, quoted=True)}"
            )
        found[name.strip()] = value
    return found


def package_path(folders: list[str]) -> tuple[Path, ...]:
    """``--package-path`` folders (each may hold several, as ``$ROS_PACKAGE_PATH`` does), else
    ``$TELEOP_UI_PACKAGE_PATH``."""
    import os
    from pathlib import Path

    from solver.identify.xacro.packages import package_path_from_env

    given = tuple(Path(p) for text in folders for p in text.split(os.pathsep) if p)
    return given or package_path_from_env()


def load_rules_and_profile(rules: str | None, profile: str | None) -> tuple[RuleSet, Profile]:
    """``--rules`` (default: the shipped paper rules) and ``--profile`` (default: the shipped
    identification profile), read."""
    from solver import default_rules_path, load_profile, load_rules

    return load_rules(rules or default_rules_path()), load_profile(profile)


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
    from solver import InputError
    from solver.core.rules import shipped_path
    from solver.core.team import resolve_team_path

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
    from solver import load_team
    from solver.core.rules import shipped_name

    path = team_path(text)
    shown = text if str(path) == text else (shipped_name(path) or str(path))
    return load_team(path, rules, display=shown)


def write(text: str) -> None:
    sys.stdout.write(text)
    sys.stdout.flush()
