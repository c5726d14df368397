"""``teleop-ui report TEAM -o FILE``: a page to take to a design meeting (HTML or Markdown)."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import add_rules, load_team_argument
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "report",
        help="write a report with tables, charts and every UI configuration",
        description="Solve a team and write a report: counts per kinematic type, the "
        "comparison with published figures, the radar and bar charts, the team's "
        "selections and every UI configuration with its components. The format "
        "follows the file name: .html (one self-contained page) or .md (Markdown; "
        "its PNG charts are written beside it as NAME-radar.png and "
        "NAME-bars.png).",
    )
    parser.add_argument(
        "team",
        metavar="TEAM.yaml",
        help="team selection file (or a shipped team name: case1, case3, ...)",
    )
    parser.add_argument(
        "--output",
        "-o",
        required=True,
        metavar="FILE",
        help="report file: .html/.htm or .md/.markdown",
    )
    add_rules(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import solve, write_report
    from solver.reporting.plot import check_chart_size
    from solver.reporting.report import report_format

    report_format(args.output)  # an unusable file name fails before any solving
    team = load_team_argument(args.team, args.rules)
    check_chart_size(team)  # so does a team too large to draw
    solution = solve(team)
    for path in write_report(solution, args.output):
        print(f"wrote {shown(str(path), limit=SHOWN_FILE_NAME_CHARS)}", file=sys.stderr)
    return 0
