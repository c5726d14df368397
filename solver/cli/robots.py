"""``teleop-ui robots TEAM``: every valid robot with its UI configuration number, streamed."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_engine, add_rules, load_team_argument


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "robots",
        help="list every valid robot with its UI configuration number",
        description="Stream every valid robot combination of a team, one per line, with the "
        "number of the UI configuration it is given (the lookup table an operator "
        "station needs). Robots are enumerated, not counted: the --max-robots "
        "guard applies.",
    )
    parser.add_argument(
        "team", metavar="TEAM.yaml", help="team selection file (or a shipped team name)"
    )
    add_rules(parser)
    add_engine(parser, enumerate_only=True)
    parser.add_argument(
        "--format",
        "-f",
        choices=("csv", "jsonl"),
        default="csv",
        help="csv (default) or JSON lines",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    import sys

    from solver import solve
    from solver.cli._progress import working
    from solver.cli._terminal import escape_controls, made_safe
    from solver.reporting.listing import write_robots

    team = load_team_argument(args.team, args.rules)
    # A spinner only while the robots go to a file: on the terminal they are the progress.
    fmt = "json" if sys.stdout.isatty() else args.format
    with working(f"listing the robots of {team.name}", fmt=fmt):
        # The counts give each kinematic type its first configuration number and the default
        # one; numbers within a type come from the structure as its robots are written, so the
        # first robot does not wait for the last configuration.
        solution = solve(team, count_only=True, max_robots=args.max_robots)
        # The rule set's text is escaped for the terminal once per value, and the rows go
        # below the escaping stream: escaping every byte written took 42% of a long listing.
        write_robots(
            solution,
            made_safe(sys.stdout),
            fmt=args.format,
            engine=args.engine,
            max_robots=args.max_robots,
            escape=escape_controls,
        )
    return 0
