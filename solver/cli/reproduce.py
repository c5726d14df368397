"""``teleop-ui reproduce [TEAM...]``: published figures beside what the rules give."""

from __future__ import annotations

import argparse
from typing import Any

from solver.cli._common import add_format, write


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "reproduce",
        help="compare published figures with the computed ones",
        description="Solve team files that carry published figures ('published:') and show "
        "both side by side. Without arguments: the article's shipped cases.",
    )
    parser.add_argument(
        "teams",
        nargs="*",
        metavar="TEAM.yaml",
        help="team files with published figures (default: the shipped ones)",
    )
    add_format(parser, ("markdown", "text", "json", "csv"), default="markdown")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import compare
    from solver.reporting.render import render_comparisons

    write(render_comparisons(compare(args.teams or None), args.format))
    return 0
