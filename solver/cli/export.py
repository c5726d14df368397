"""``teleop-ui export TEAM --format uvl``: a team's design space for feature-model tools."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_rules, load_team_argument, write


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "export",
        help="export a team's design space as a UVL feature model",
        description="Write the team's valid robots as a UVL feature model (one alternative "
        "group per characteristic) for feature-model tools such as flamapy.",
    )
    parser.add_argument(
        "team",
        metavar="TEAM.yaml",
        help="team selection file (or a shipped team name: case1, case3, ...)",
    )
    add_rules(parser)
    parser.add_argument("--format", choices=("uvl",), default="uvl", help="uvl (the default)")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import team_to_uvl

    write(team_to_uvl(load_team_argument(args.team, args.rules)))
    return 0
