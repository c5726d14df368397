"""``teleop-ui count FILE``: exact counts (and, with --symbolic, formulas) for a team or rules."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from solver.cli._common import (
    add_engine,
    add_format,
    add_rules,
    add_time_limit,
    load_team_argument,
    team_path,
    write,
)

if TYPE_CHECKING:
    from solver import Team


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "count",
        help="exact counts at any size; --symbolic: formulas of the maxima",
        description="Count valid robots and UI configurations per kinematic type without "
        "listing them. FILE is a team file, or a rule set (then every value of "
        "every kinematic type is selected: the whole design space). --symbolic "
        "gives the counts as formulas of each type's maximum count (sympy).",
    )
    parser.add_argument("file", metavar="FILE.yaml", help="team file or rule set file")
    add_rules(parser)
    parser.add_argument(
        "--symbolic",
        "-s",
        action="store_true",
        help="counts as closed-form expressions of each type's maximum",
    )
    add_engine(parser)
    add_time_limit(parser, "symbolic-seconds", "building the formulas of --symbolic")
    add_format(parser, ("text", "json", "markdown"))
    parser.set_defaults(run=run)


def load(text: str, rules: str | None) -> Team:
    """A team file, or a rule set file standing for its whole design space."""
    from solver import InputError, full_team
    from solver.core.rules import parse_rules
    from solver.files.filekind import file_kind
    from solver.files.yamlio import load_document

    path = team_path(text)
    document = load_document(path, display=text)
    if file_kind(document) == "rules":
        if rules is not None:
            raise InputError.at(text, "is a rule set: --rules applies to team files only")
        return full_team(parse_rules(document))
    return load_team_argument(text, rules)


def run(args: argparse.Namespace) -> int:
    from solver import solve
    from solver.cli._progress import working
    from solver.reporting.render import render_counts

    team = load(args.file, args.rules)
    with working(f"counting {team.name}", fmt=args.format):
        solution = solve(team, engine=args.engine, count_only=True, max_robots=args.max_robots)
    if not args.symbolic:
        write(render_counts(solution, args.format))
        return 0
    from solver import formulas
    from solver.reporting.growth import render_growth
    from solver.solving.symbolic import agrees_with

    growth = formulas(team, time_limit=args.time_limit)
    write(render_growth(growth, solution, args.format))
    # The output says so too; a formula that disagrees with the exact counter is a bug.
    return 0 if agrees_with(growth, solution) else 1
