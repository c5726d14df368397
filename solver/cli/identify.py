"""``teleop-ui identify ROBOT.urdf``: what a real robot is, from its ROS metadata."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from solver.cli._common import (
    add_description_options,
    add_format,
    add_rules,
    add_set,
    given_values,
    load_rules_and_profile,
    load_team_argument,
    package_path,
    write,
    xacro_arguments,
)
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from solver import Solution, Team


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "identify",
        help="identify a robot (kinematic type, sensors, motion controls) from its "
        "URDF, SRDF, topics or bag",
        description="Read a robot's URDF (a .xacro only with --trust-xacro), and optionally "
        "its SRDF, "
        "topic lists and bags; print its structure, the rule set's kinematic type, "
        "a confidence, the evidence, its sensors and motion controls. With --team, "
        "also each characteristic combination and its UI configuration. The robot's "
        "teleoperation description (ROBOT.teleop.yaml beside the URDF, or --teleop) wins "
        "over what is read; --describe drafts one.",
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
        "--teleop",
        metavar="ROBOT.teleop.yaml",
        help="the robot's teleoperation description (its declared kinematic type, motion "
        "controls and sensors win over what is read); default: ROBOT.teleop.yaml beside the "
        "URDF when there is one",
    )
    parser.add_argument(
        "--package",
        metavar="DIR",
        help="the description's ROS package folder, when the file is not in it (an expanded "
        "URDF); default: the package holding the file. The robot's packages (this one, those "
        "that use it, those they use) are read for the controls they ship",
    )
    parser.add_argument(
        "--workspace",
        metavar="DIR",
        help="the folder the robot's packages are found in (default: the workspace's src folder "
        "above the description's package, else the folder above that package); for a "
        "description in no package, the repository it lies in (read only when named)",
    )
    parser.add_argument(
        "--no-packages",
        action="store_true",
        help="read the description alone: no package's launch, configuration or script file",
    )
    parser.add_argument(
        "--describe",
        action="store_true",
        help="print a teleoperation description drafted from what was found, the evidence as "
        "comments, instead of the report (no description is read)",
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
            teleop=None if args.describe else args.teleop,
            look_beside=not args.describe,
            package=None if args.no_packages else args.package,
            workspace=None if args.no_packages else args.workspace,
            look_around=not args.no_packages,
        )
    if args.strict and result.warnings:
        from solver import InputError

        raise InputError(result.warnings)
    if args.describe:
        from solver.identify.describe import draft_description

        write(draft_description(result))
        return 0
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
    from solver import solve

    return solve(team)
