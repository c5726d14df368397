"""``teleop-ui switch (--ros2 [--domain N] | --master URL) ROBOT [NAME=VALUE...]``: make a robot
the active one, as an operator station does, and print the watcher's answer
(:mod:`solver.live.operator`).

Exit status: 0 answered; 1 no running watcher answered within ``--wait`` seconds (the
selection is written); 2 refused (nothing written) or the graph cannot be used.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import (
    add_format,
    add_master_options,
    add_ros2_options,
    add_rules,
    load_team_argument,
    seconds,
    write,
)


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "switch",
        help="make a robot (and values of its characteristics) the operator's active "
        "selection on a live graph, and print the watcher's answer",
        description="Write the operator's selection as an operator station does "
        "(/teleop_ui/active_robot and /teleop_ui/active_<characteristic>: ROS 1 parameters, "
        "or ROS 2 topics, reliable and transient-local), wait for the answer of a running "
        "`teleop-ui watch` naming that robot with those values, and print it with its "
        "layouts. NAME and VALUE are checked against --team / --rules, else against the rule "
        "set the graph's watchers announce. Exit status: 0 answered, 1 no answer within "
        "--wait (the selection is written), 2 refused (nothing written). See docs/live.md.",
    )
    parser.add_argument("robot", metavar="ROBOT", help="the robot's namespace, e.g. /uav1")
    parser.add_argument(
        "values",
        nargs="*",
        metavar="NAME=VALUE",
        help="values to select, e.g. motion_control=Waypoint; NAME= clears that selection",
    )
    add_ros2_options(
        parser,
        ros2_help="a ROS 2 graph on DDS (the [ros2] extra); default: the ROS 1 master",
    )
    add_master_options(parser, required_help="default: $ROS_MASTER_URI")
    parser.add_argument(
        "--team",
        "-t",
        metavar="TEAM.yaml",
        help="check NAME=VALUE against this team's rule set (a file or a shipped team name; "
        "default: the rule set the graph's watchers announce)",
    )
    add_rules(parser, help="check NAME=VALUE against this rule set (instead of the team's)")
    parser.add_argument(
        "--clear",
        action="store_true",
        help="clear every other selected value, so that the robot's own values apply "
        "(default: the other selections stay as they are)",
    )
    parser.add_argument(
        "--wait",
        type=seconds,
        default=5.0,
        metavar="S",
        help="seconds to wait for the watcher's answer (default: 5; none: exit status 1)",
    )
    parser.add_argument(
        "--look",
        type=seconds,
        metavar="S",
        help="seconds at most to look for the robot and a running watcher's rule set before "
        "writing (default: 5; the look ends once both are found; a DDS graph is discovered "
        "one participant at a time, slowly on a busy machine)",
    )
    add_format(parser, ("text", "json"))
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import graph_address, open_station, parse_combination, switch_robot
    from solver.live.operator import check_switch, render_switched, unanswered

    values = parse_combination(args.values)
    rules = _rules(args)
    check_switch(args.robot, values, rules)  # refused before the graph is opened
    address = graph_address(ros2=args.ros2, master=args.master, domain=args.domain)
    station = open_station(address, timeout=args.timeout)
    try:
        switched = switch_robot(
            station,
            args.robot,
            values,
            rules=rules,
            clear=args.clear,
            wait=args.wait,
            look=args.look,
        )
    finally:
        station.close()
    if switched.why is not None:
        _say(f"switch: NAME=VALUE checked for syntax only: {switched.why}")
    write(render_switched(switched, args.format))
    if switched.answer is None:
        _say(f"switch: {unanswered(switched)}")
        return 1
    return 0


def _rules(args: argparse.Namespace) -> Any:
    """The rule set of ``--team`` / ``--rules``, or ``None`` (the graph's watchers' then)."""
    if args.team is not None:
        return load_team_argument(args.team, args.rules).rules
    if args.rules is not None:
        from solver import load_rules

        return load_rules(args.rules)
    return None


def _say(text: str) -> None:
    print(text, file=sys.stderr, flush=True)
