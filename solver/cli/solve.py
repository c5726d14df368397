"""``teleop-ui solve TEAM``: valid robots and UI configurations of a team selection."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_engine, add_format, add_rules, load_team_argument, write

FORMATS = ("text", "json", "csv", "markdown")


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "solve",
        help="count valid robots and the UI configurations that serve them",
        description="Enumerate the valid robots of a team selection, partition them into UI "
        "configurations and number the configurations.",
    )
    parser.add_argument(
        "team",
        metavar="TEAM.yaml",
        help="team selection file (or a shipped team name: case1, case3, ...)",
    )
    add_rules(parser)
    parser.add_argument(
        "--list", "-l", action="store_true", help="list every UI configuration with its components"
    )
    add_engine(parser)
    parser.add_argument(
        "--count-only",
        action="store_true",
        help="exact counts only, at any size: no configuration list",
    )
    add_format(parser, FORMATS)
    parser.add_argument(
        "--plot",
        metavar="FILE",
        help="also draw the team's radar chart (the article's Figure 9) to FILE; "
        "the format follows the extension: .png, .svg or .pdf",
    )
    parser.add_argument(
        "--plot-kind",
        choices=("radar", "bars", "matrix"),
        default="radar",
        help="what --plot draws: the radar chart (default), valid robots "
        "beside configurations per type, or the component matrix "
        "(which components each type needs, at a glance)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import solve
    from solver.reporting.render import render_solution, solution_chunks

    if args.plot:
        from solver.reporting.plot import plot_format

        plot_format(args.plot)  # an unusable file name fails before any solving
    from solver.cli._progress import working

    team = load_team_argument(args.team, args.rules)
    if args.plot:
        from solver.reporting.plot import check_chart_size

        check_chart_size(team)  # a team too large to draw is refused before it is solved
    with working(f"solving {team.name}", fmt=args.format):
        solution = solve(
            team, engine=args.engine, count_only=args.count_only, max_robots=args.max_robots
        )
        # The warnings (constraints' exclusions) are computed once, here, under the spinner.
        _ = solution.removed
    if args.plot:
        from solver import write_plot

        write_plot(solution, args.plot, args.plot_kind)
    listed = args.list and solution.listed
    if args.format in ("json", "csv"):
        # Streamed: 450,000 configurations are 330 MB of JSON, never held whole.
        for chunk in solution_chunks(solution, args.format, configurations=listed):
            write(chunk)
    else:
        write(render_solution(solution, args.format, configurations=listed))
    return 0
