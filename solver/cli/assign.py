"""``teleop-ui assign --team TEAM NAME=VALUE...``: the UI configuration of one combination.

With ``--master URL [--robot NS]`` the values come from a robot on a running ROS master
(:mod:`solver.live.query`).
"""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import (
    add_format,
    add_master_options,
    add_profile,
    add_ros2_options,
    add_team,
    load_team_argument,
    write,
)


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "assign",
        help="the UI configuration for one characteristic combination",
        description="Give one characteristic combination its UI configuration number and "
        "components, or the default configuration with the reason it is invalid "
        "and the components relevant to the values that are known. Exits 0 in "
        "both cases.",
    )
    parser.add_argument(
        "combination",
        nargs="*",
        metavar="NAME=VALUE",
        help="characteristic values, e.g. kinematic_type=UAV "
        "'sensor_type=2D Camera' sensor_count=3 (with --master: values "
        "that replace or complete what the robot's metadata gives)",
    )
    add_team(parser)
    add_format(parser, ("text", "json"))
    # Live mode (solver.live.query): the robot's values come from a running ROS master.
    add_master_options(parser, required_help="read the robot's values from this master")
    parser.add_argument(
        "--robot",
        metavar="NS",
        help="with --master: the robot's namespace, e.g. /uav1 (default: "
        "/teleop_ui/active_robot); required with --ros2",
    )
    add_ros2_options(
        parser,
        ros2_help="read the robot from a ROS 2 graph on DDS instead (the [ros2] "
        "extra; see docs/live.md)",
    )
    add_profile(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import InputError, assign, parse_combination, solve
    from solver.reporting.render import render_assignment

    combination = parse_combination(args.combination)
    if args.ros2 or args.master is not None:
        return run_live(args, combination)
    for option in ("robot", "profile"):
        if getattr(args, option) is not None:
            raise InputError.at("<arguments>", f"--{option} needs --master URL")
    if not combination:
        raise InputError.at("<arguments>", "give at least one NAME=VALUE (or --master URL)")
    solution = solve(load_team_argument(args.team, args.rules))
    write(render_assignment(solution, assign(solution, combination), args.format))
    return 0


def run_live(args: argparse.Namespace, combination: dict[str, str]) -> int:
    """``assign --master`` and ``assign --ros2``: one question, one path for every graph."""
    from solver import (
        InputError,
        assign_from_graph,
        graph_address,
        load_profile,
        open_source,
        solve,
    )
    from solver.live.render import render_live_assignment

    address = graph_address(ros2=args.ros2, master=args.master, domain=args.domain)
    if args.ros2 and args.robot is None:
        raise InputError.at(
            "<arguments>",
            "--ros2 needs --robot NS (the active robot is a "
            "topic on ROS 2: `watch --ros2` answers it)",
        )
    solution = solve(load_team_argument(args.team, args.rules))
    source = open_source(address, timeout=args.timeout, push=False)
    try:
        live = assign_from_graph(
            source, solution, load_profile(args.profile), robot=args.robot, given=combination
        )
    finally:
        source.close()
    write(render_live_assignment(live, solution, args.format))
    return 0
