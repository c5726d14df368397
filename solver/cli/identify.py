"""``teleop-ui identify ROBOT.urdf``: what a real robot is, from its ROS metadata."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from solver.cli._common import (
    add_format,
    add_profile,
    add_rules,
    add_set,
    load_team_argument,
    write,
)
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from pathlib import Path

    from solver.core.ruleset import RuleSet
    from solver.core.team import Team
    from solver.identify.profile import Profile
    from solver.solving.solution import Solution


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


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "identify",
        help="identify a robot (kinematic type, sensors, motion controls) from its "
        "URDF, SRDF, topics or bag",
        description="Read a robot's URDF (a .xacro only with --trust-xacro), and optionally "
        "its SRDF, "
        "topic lists and bags; print its structure, the rule set's kinematic type, "
        "a confidence, the evidence, its sensors and motion controls. With --team, "
        "also each characteristic combination and its UI configuration.",
    )
    parser.add_argument("description", metavar="ROBOT.urdf", help="URDF or xacro file")
    parser.add_argument("--srdf", metavar="ROBOT.srdf", help="MoveIt SRDF of the robot")
    parser.add_argument(
        "--topics",
        action="append",
        default=[],
        metavar="TOPICS.txt",
        help="topic list: `rostopic list -v`, `ros2 topic list -t`, or "
        "'TOPIC TYPE' lines (repeatable)",
    )
    parser.add_argument(
        "--bag",
        action="append",
        default=[],
        metavar="RUN.bag",
        help="recorded bag: ROS 1 .bag, ROS 2 folder, .db3 or .mcap (repeatable)",
    )
    parser.add_argument(
        "--team",
        "-t",
        metavar="TEAM.yaml",
        help="team selection: also give each combination its UI configuration",
    )
    add_set(parser, per_robot=False)
    add_rules(
        parser,
        "rule set whose kinematic types, sensor types and motion controls the "
        "robot is mapped to (default: the --team file's rules, else the shipped "
        "paper rules)",
    )
    parser.add_argument(
        "--explain",
        action="store_true",
        help="also print the decision path for the body: each structure rule in order, "
        "and why it held or not",
    )
    add_description_options(parser)
    add_format(parser, ("text", "json"))
    parser.set_defaults(run=run)


def xacro_arguments(pairs: list[str]) -> dict[str, str]:
    from solver.errors import InputError

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
    import os
    from pathlib import Path

    from solver.identify.xacro.packages import package_path_from_env

    given = tuple(Path(p) for text in folders for p in text.split(os.pathsep) if p)
    return given or package_path_from_env()


def load_rules_and_profile(rules: str | None, profile: str | None) -> tuple[RuleSet, Profile]:
    from solver.core.rules import default_rules_path, load_rules
    from solver.identify.profile import load_profile

    return load_rules(rules or default_rules_path()), load_profile(profile)


def run(args: argparse.Namespace) -> int:
    from solver.files.output import dumps
    from solver.identify.combinations import combinations, missing
    from solver.identify.identification import identify
    from solver.identify.render import identification_data, render_identification

    team = load_team_argument(args.team, args.rules) if args.team else None
    rules, profile = load_rules_and_profile(None if team else args.rules, args.profile)
    from solver.cli._progress import working

    # A large description, a long bag or a trusted xacro can take seconds: a spinner then.
    with working(
        f"identifying {shown(args.description, limit=SHOWN_FILE_NAME_CHARS)}", fmt=args.format
    ):
        result = identify(
            args.description,
            srdf=args.srdf,
            topic_lists=args.topics,
            bags=args.bag,
            xacro_args=xacro_arguments(args.xacro_args),
            package_path=package_path(args.package_path),
            rules=team.rules if team else rules,
            profile=profile,
            trust_xacro=args.trust_xacro,
        )
    if args.strict and result.warnings:
        from solver.errors import InputError

        raise InputError(result.warnings)
    solution = _solved(team)
    given = given_values(args.set, solution)
    found = combinations(result, solution, profile, given) if solution else ()
    lacking = missing(found, solution) if solution else ()
    if args.format == "json":
        data = identification_data(result, found, solution, explain=args.explain, missing=lacking)
        write(dumps(data))
    else:
        write(render_identification(result, found, solution, explain=args.explain, missing=lacking))
    return 0


def _solved(team: Team | None) -> Solution | None:
    """The team solved, with ``--team`` (solving is loaded for that case only)."""
    if team is None:
        return None
    from solver.solving.solution import solve

    return solve(team)


def given_values(pairs: list[str], solution: Solution | None) -> dict[str, str]:
    """``--set NAME=VALUE`` pairs, checked against the team's rules (they need ``--team``)."""
    if not pairs:
        return {}
    from solver.errors import InputError
    from solver.live.given import parse_fixed

    if solution is None:
        raise InputError.at("--set", "values are given to a combination: --set needs --team")
    fixed = parse_fixed(pairs, solution.rules)
    if fixed.per_robot:
        raise InputError.at("--set", "one robot here: give NAME=VALUE, without a /ROBOT: part")
    return dict(fixed.everywhere)
