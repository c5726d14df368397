"""``teleop-ui check FILE...``: lint rule sets, and team files against their rules."""

from __future__ import annotations

import argparse
import textwrap
from typing import Any

from solver.cli._common import add_time_limit, write

FORMATS = ("text", "parsable", "json", "sarif")


def _ids(text: str) -> list[str]:
    return [part.strip() for part in text.split(",") if part.strip()]


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "check",
        help="find faults in rule sets and team files, like a linter",
        description="Check rule set and team files: coverage of the components (gaps, "
        "overlaps, ranges), unknown references and duplicates, void and dead "
        "values, core values, redundant constraints, minimal conflicts, the bound "
        "T, and teams against their rules. Prints file:line:col: [level] message "
        "(check-id). Team files are checked against --rules, else against the "
        "one rule set among the files, else against their own 'rules:'. "
        "Exit status: 0 clean, 1 findings at error level (or warning level with "
        "--strict), 2 unusable input, or a rule set whose checks take longer than "
        "--time-limit or too intricate a SAT search.",
    )
    parser.add_argument(
        "files",
        nargs="*",
        metavar="FILE.yaml",
        help="rule set and team files (told apart by content)",
    )
    parser.add_argument(
        "--rules",
        "-r",
        metavar="RULES.yaml",
        help="rule set to check every team file against (checked as well)",
    )
    parser.add_argument(
        "--format", "-f", choices=FORMATS, default="text", help="output format (default: text)"
    )
    parser.add_argument("--strict", action="store_true", help="exit 1 on warnings too")
    parser.add_argument(
        "--disable",
        "-d",
        action="append",
        default=[],
        metavar="ID[,ID]",
        type=_ids,
        help="leave out these checks (repeatable)",
    )
    add_time_limit(parser, "check-seconds", "checking")
    parser.add_argument(
        "--list-checks",
        action="store_true",
        help="list every check with its level and description, and exit",
    )
    parser.set_defaults(run=run, parser=parser)


def run(args: argparse.Namespace) -> int:
    from solver import check_files
    from solver.check import ALL_CHECKS, check_ids, render

    if args.list_checks:
        write(
            "".join(
                f"{check.id} [{check.level}]\n"
                + textwrap.fill(
                    check.description, 96, initial_indent="    ", subsequent_indent="    "
                )
                + "\n"
                for check in ALL_CHECKS
            )
        )
        return 0
    disabled = [check_id for group in args.disable for check_id in group]
    unknown = [check_id for check_id in disabled if check_id not in check_ids()]
    if unknown or not args.files:
        message = (
            f"unknown check id(s): {', '.join(unknown)} (see --list-checks)"
            if unknown
            else "give at least one rule set or team file"
        )
        args.parser.error(message)
    from solver.cli._progress import working

    with working(f"checking {len(args.files)} file(s)", fmt=args.format):
        report = check_files(
            args.files, rules=args.rules, disable=disabled, time_limit=args.time_limit
        )
    write(render(report, args.format))
    return report.exit_status(strict=args.strict)
