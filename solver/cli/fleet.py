"""``teleop-ui fleet ROBOTS/ -o team.yaml``: identify a folder of robots, write their team."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import (
    add_description_options,
    add_format,
    add_rules,
    load_rules_and_profile,
    package_path,
    write,
    xacro_arguments,
)
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "fleet",
        help="identify every robot in a folder and build their team selection",
        description="Identify every NAME.urdf / NAME.urdf.xacro / NAME.xacro in a folder "
        "(with NAME.srdf, NAME.topics[.txt] and NAME.bag beside it when present), "
        "print a table (or the JSON list), and with -o write a team selection "
        "that `teleop-ui solve` accepts. Robots that cannot be identified are "
        "listed with the reason; the others still go through.",
    )
    parser.add_argument("folder", metavar="ROBOTS/", help="folder of robot descriptions")
    parser.add_argument("--output", "-o", metavar="TEAM.yaml", help="write the team selection here")
    parser.add_argument("--name", help="team name (default: 'fleet FOLDER')")
    add_rules(
        parser,
        "rule set the robots are mapped to and the written team names (default: the "
        "shipped paper rules)",
    )
    add_description_options(parser)
    add_format(parser, ("text", "json"))
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from solver import default_rules_path, identify_fleet
    from solver.files.atomic import write_atomic
    from solver.files.output import dumps, text_table
    from solver.identify.fleet import rules_reference, team_text
    from solver.identify.render import identification_data

    rules, profile = load_rules_and_profile(args.rules, args.profile)
    with _progress() as progress:
        fleet = identify_fleet(
            args.folder,
            rules=rules,
            profile=profile,
            package_path=package_path(args.package_path),
            xacro_args=xacro_arguments(args.xacro_args),
            progress=progress,
            trust_xacro=args.trust_xacro,
            strict=args.strict,
        )
    team = None
    if args.output:
        reference = None
        if args.rules and Path(args.rules).resolve() != default_rules_path().resolve():
            reference = rules_reference(args.rules, args.output)
        name = args.name or f"fleet {Path(args.folder).name}"
        team = team_text(fleet, rules, profile, name=name, rules_reference=reference)
    if args.format == "json":
        write(dumps([identification_data(i) for i in fleet.identified]))
    else:
        rows = [
            [
                e.name,
                e.identification.structure,
                e.identification.kinematic_type or "-",
                f"{e.identification.confidence:.2f}",
                e.identification.sensor_count,
                ", ".join(c.motion_control for c in e.identification.motion_controls) or "-",
            ]
            for e in fleet.entries
            if e.identification is not None
        ]
        write(
            text_table(
                [
                    "robot",
                    "structure",
                    "kinematic type",
                    "confidence",
                    "sensors",
                    "motion controls",
                ],
                rows,
                [False, False, False, True, True, False],
            )
        )
        for entry in fleet.failed:
            write(f"not identified: {_failure(entry.name, entry.error)}\n")
        for found in fleet.identified:
            for warning in found.warnings:
                write(f"warning: {warning}\n")
    if team is not None:
        write_atomic(args.output, team)
        print(f"wrote {shown(args.output, limit=SHOWN_FILE_NAME_CHARS)}", file=sys.stderr)
    elif fleet.failed and args.format == "json":
        for entry in fleet.failed:
            print(f"not identified: {_failure(entry.name, entry.error)}", file=sys.stderr)
    return 0


def _failure(name: str, error: object) -> str:
    """A file that could not be identified and why, on one line: a file name or a fault may
    hold a newline."""
    faults = "; ".join(str(error).splitlines())
    return f"{shown(name, limit=SHOWN_FILE_NAME_CHARS)}: {shown(faults, limit=None)}"


class _progress:
    """A rich progress bar on a terminal, plain lines on stderr otherwise."""

    def __enter__(self) -> Any:
        if not sys.stderr.isatty():
            return self._plain
        from rich.console import Console
        from rich.progress import Progress

        from solver.cli._terminal import raw_stream

        # rich writes its own escape sequences: give it the terminal itself (the names it shows
        # are escaped in _rich).
        self._bar = Progress(transient=True, console=Console(file=raw_stream(sys.stderr)))
        self._bar.start()
        self._task: Any = None
        return self._rich

    def __exit__(self, *exc: object) -> None:
        if hasattr(self, "_bar"):
            self._bar.stop()

    @staticmethod
    def _plain(done: int, total: int, name: str) -> None:
        if name:
            name = shown(name, limit=SHOWN_FILE_NAME_CHARS)
            print(f"[{done + 1}/{total}] {name}", file=sys.stderr, flush=True)

    def _rich(self, done: int, total: int, name: str) -> None:
        from rich.markup import escape

        if self._task is None:
            self._task = self._bar.add_task("identifying", total=total)
        self._bar.update(
            self._task,
            completed=done,
            description=f"identifying {escape(shown(name, limit=SHOWN_FILE_NAME_CHARS))}"
            if name
            else "done",
        )
