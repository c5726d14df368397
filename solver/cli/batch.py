"""``teleop-ui batch PATTERN... -o DIR``: solve many teams, with progress and a summary.

Progress goes to stderr: a rich progress bar when stderr is a terminal, one plain line per
team otherwise (logs, CI). The summary table goes to stdout and, with the per-team outputs, to
the output folder. Exit status: 0 every team solved (or skipped), 1 at least one team failed
(each is reported with its error), 2 the batch could not run at all (a pattern that matches
nothing, an unusable output folder or rule file).
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections.abc import Iterator
from typing import IO, TYPE_CHECKING, Any

from solver.cli._common import positive, write
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from solver.reporting.batch import Outcome


def _default_jobs() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on every platform
        return os.cpu_count() or 1


def _jobs(text: str) -> int:
    """An argparse type: ``--jobs``, at most the ``batch-jobs`` limit (a worker each)."""
    from solver.limits import limit

    number = positive(text)
    if limit("batch-jobs").exceeded(number):
        raise argparse.ArgumentTypeError(limit("batch-jobs").message(number))
    return number


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "batch",
        help="solve many team files at once: progress, summary, per-team JSON",
        description="Solve every team file named by the patterns (files, shipped team names "
        "such as case3, folders searched recursively, or globs such as "
        "'teams/**/*.yaml'; quote them) in parallel. Writes DIR/teams/<name>.json "
        "per team (the JSON of 'solve --format json --list'), DIR/summary.csv and "
        "DIR/summary.md. A rerun skips teams whose "
        "team file, rule file and options are unchanged (content hashes kept in "
        "DIR/.stamps/). Exit 0 all solved, 1 some team failed, 2 nothing could run.",
    )
    parser.add_argument(
        "patterns",
        nargs="+",
        metavar="PATTERN",
        help="team file, shipped team name, folder or glob pattern",
    )
    parser.add_argument(
        "--output",
        "-o",
        required=True,
        metavar="DIR",
        help="folder for the per-team outputs and the summary",
    )
    parser.add_argument(
        "--jobs",
        "-j",
        type=_jobs,
        default=min(_default_jobs(), 64),
        metavar="N",
        help="worker processes, at most 64 (default: the CPUs available, here "
        f"{min(_default_jobs(), 64)})",
    )
    parser.add_argument(
        "--force",
        action="store_true",
        help="solve every team again, even those that are up to date",
    )
    parser.add_argument(
        "--report",
        choices=("html", "markdown"),
        help="also write a report per team (DIR/teams/<name>.html or .md)",
    )
    parser.add_argument(
        "--rules",
        "-r",
        metavar="RULES.yaml",
        help="rule set for every team instead of each team's own 'rules:'",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver.files.atomic import make_folder
    from solver.files.output import text_table
    from solver.reporting.batch import find_teams, make_jobs, run_batch, write_summary

    if args.rules is not None:
        from solver import load_rules

        load_rules(args.rules)  # a bad override would fail every team: say so once
    teams = find_teams(args.patterns)
    # Planned first: a refusal (a report without matplotlib) leaves no folder behind.
    jobs = make_jobs(teams, args.output, rules=args.rules, report=args.report, force=args.force)
    out = make_folder(args.output)
    show = _progress_bar if sys.stderr.isatty() else _progress_lines
    outcomes = list(show(run_batch(jobs, args.jobs), len(jobs), sys.stderr))
    rows, written = write_summary(outcomes, jobs, out)
    write(
        text_table(
            ["file", "status", "team", "rules", "valid robots", "UI configurations"],
            [
                [r.file, r.status, r.team, r.rules, r.valid_robots, r.ui_configurations]
                for r in rows
            ],
            [False, False, False, False, True, True],
        )
    )
    actions = [o.action for o in outcomes]
    counts = ", ".join(
        f"{actions.count(a)} {a}"
        for a in ("solved", "up to date", "failed", "skipped")
        if a in actions
    )
    print(
        f"{len(jobs)} team files: {counts}; "
        f"summary: {', '.join(shown(str(p), limit=None) for p in written)}",
        file=sys.stderr,
    )
    return 1 if any(o.failed for o in outcomes) else 0


def _describe(outcome: Outcome) -> str:
    """The lines that report a team: its file, then its warnings or its error's faults, each
    escaped (a name holding a newline starts no line of its own)."""
    row = outcome.row
    file = shown(row.file, limit=SHOWN_FILE_NAME_CHARS)
    if outcome.action in ("solved", "up to date"):
        text = f"{file}: {row.valid_robots} valid robots, {row.ui_configurations} UI configurations"
        text += f" ({outcome.seconds:.2f} s)" if outcome.action == "solved" else ""
        # A solved team's warnings (the summary's message column): one line each.
        warnings = re.split(r"; (?=warning: )", row.message) if row.message else []
        return "\n".join([text, *(f"    {shown(warning, limit=None)}" for warning in warnings)])
    if outcome.action == "skipped":
        return f"{file}: {shown(row.message, limit=None)}"
    lines = row.message.splitlines()
    return file + "\n" + "\n".join(f"    {shown(line, limit=None)}" for line in lines)


def _progress_lines(outcomes: Iterator[Outcome], total: int, stream: IO[str]) -> Iterator[Outcome]:
    """One line per finished team, for logs and pipes."""
    width = len(str(total))
    for done, outcome in enumerate(outcomes, 1):
        action = "FAILED" if outcome.failed else outcome.action
        print(
            f"[{done:>{width}}/{total}] {action:<10} {_describe(outcome)}", file=stream, flush=True
        )
        yield outcome


def _progress_bar(outcomes: Iterator[Outcome], total: int, stream: IO[str]) -> Iterator[Outcome]:
    """A rich progress bar; failures are printed above it as they happen."""
    from rich.console import Console
    from rich.markup import escape
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from solver.cli._terminal import escape_controls, raw_stream

    # The bar's own escape sequences go to the terminal as they are; every name and message
    # in it is escaped first (they come from team files).
    console = Console(file=raw_stream(stream))
    colours: dict[str, str] = {
        "solved": "green",
        "up to date": "cyan",
        "failed": "bold red",
        "skipped": "yellow",
    }
    with Progress(
        TextColumn("[bold]solving teams"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        TextColumn("{task.description}"),
        console=console,
        transient=False,
    ) as progress:
        task = progress.add_task("", total=total)
        for outcome in outcomes:
            if outcome.action in ("failed", "skipped"):
                label = "FAILED" if outcome.failed else outcome.action
                progress.console.print(
                    f"[{colours[outcome.action]}]{label}[/] "
                    f"{escape(escape_controls(_describe(outcome)))}",
                    highlight=False,
                    soft_wrap=True,
                )
            description = shown(outcome.job.shown, limit=SHOWN_FILE_NAME_CHARS)
            progress.update(task, advance=1, description=escape(description))
            yield outcome
