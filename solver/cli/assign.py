"""``teleop-ui assign --team TEAM NAME=VALUE...``: the UI configuration of one combination."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_format, add_rules, load_team_argument, write


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "assign", help="the UI configuration for one characteristic combination",
        description="Give one characteristic combination its UI configuration number and "
                    "components, or the default configuration with the reason it is invalid "
                    "and the components relevant to the values that are known. Exits 0 in "
                    "both cases.")
    parser.add_argument("combination", nargs="+", metavar="NAME=VALUE",
                        help="characteristic values, e.g. kinematic_type=UAV "
                             "'sensor_type=2D Camera' sensor_count=3")
    parser.add_argument("--team", "-t", required=True, metavar="TEAM.yaml",
                        help="team selection file (or a shipped team name)")
    add_rules(parser)
    add_format(parser, ("text", "json"))
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver.assign import assign, parse_combination
    from solver.formats import render_assignment
    from solver.solve import solve

    combination = parse_combination(args.combination)
    solution = solve(load_team_argument(args.team, args.rules))
    write(render_assignment(solution, assign(solution, combination), args.format))
    return 0
