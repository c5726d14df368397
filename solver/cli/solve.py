"""``teleop-ui solve TEAM``: valid robots and UI configurations of a team selection."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_format, add_rules, load_team_argument, write

FORMATS = ("text", "json", "csv", "markdown")


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "solve", help="count valid robots and the UI configurations that serve them",
        description="Enumerate the valid robots of a team selection, partition them into UI "
                    "configurations and number the configurations.")
    parser.add_argument("team", metavar="TEAM.yaml",
                        help="team selection file (or a shipped team name: case1, case3, ...)")
    add_rules(parser)
    parser.add_argument("--list", "-l", action="store_true",
                        help="list every UI configuration with its components")
    add_format(parser, FORMATS)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver.formats import render_solution
    from solver.solve import solve

    team = load_team_argument(args.team, args.rules)
    write(render_solution(solve(team), args.format, configurations=args.list))
    return 0
