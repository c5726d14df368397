"""``teleop-ui layouts TEAM -o DIR``: a Foxglove or RViz2 layout per UI configuration."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import (
    add_profile,
    add_rules,
    add_set,
    given_values,
    load_team_argument,
    write,
)
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "layouts",
        help="write one viewer layout per UI configuration, plus the default",
        description="Write a Foxglove / Lichtblick layout JSON (or an RViz2 file) for every UI "
        "configuration of a team and for the default configuration, into a folder written as "
        "one unit (an earlier run's layouts there are replaced, those no longer written "
        "removed). Topics are in the root namespace (/cmd_vel; RViz2: relative, cmd_vel) or "
        "under --namespace.",
    )
    parser.add_argument(
        "team",
        metavar="TEAM.yaml",
        nargs="?",
        help="team selection file (or a shipped team name: case1, case3, ...)",
    )
    parser.add_argument(
        "--robot",
        metavar="URDF",
        help="one robot's layout: identify the URDF, give it its configuration "
        "and write that one layout to -o FILE, topics under its name",
    )
    parser.add_argument(
        "--team", dest="robot_team", metavar="TEAM.yaml", help="the team the --robot belongs to"
    )
    parser.add_argument(
        "--topics",
        metavar="FILE",
        help="with --robot: the robot's topic list (rostopic list -v, ros2 topic list -t); "
        "panels take its real topics instead of the templates",
    )
    parser.add_argument(
        "--bag",
        metavar="BAG",
        help="with --robot: a bag (ROS 1 .bag or ROS 2 folder) the robot recorded; "
        "panels take its topics instead of the templates",
    )
    parser.add_argument(
        "--namespace",
        metavar="/NAME",
        help="the robot's ROS namespace: every topic under it (/NAME/cmd_vel); with --robot "
        "the default is /ROBOT_NAME",
    )
    add_rules(parser)
    parser.add_argument(
        "-o",
        "--output",
        metavar="DIR",
        required=True,
        help="directory for the layout files (with --robot: the file)",
    )
    # The targets' table (solver.layouts.targets) checks the name when the command runs: its
    # import would slow every start of the command line.
    parser.add_argument(
        "--format",
        metavar="TARGET",
        default="foxglove",
        help="the operator tool: foxglove (Foxglove / Lichtblick layout JSON, the default) or "
        "rviz (RViz2 .rviz files)",
    )
    parser.add_argument(
        "--presentation",
        metavar="FILE",
        help="which panel presents each UI component (default: the shipped "
        "rules/presentation.yaml)",
    )
    parser.add_argument(
        "--cluster-order",
        metavar="ORDER",
        help="how the sensors of a cluster are ordered (the article's three): alphabetical, "
        "priority (the presentation grammar's priority list) or 'data rate' (bytes per "
        "second, from --rates-bag); default: the presentation grammar's",
    )
    parser.add_argument(
        "--rates-bag",
        metavar="BAG",
        help="a bag (ROS 1 .bag or ROS 2 folder) whose messages give each topic's bytes per "
        "second, for the 'data rate' order (read streaming, message by message)",
    )
    add_profile(parser)
    add_set(parser, per_robot=False)
    parser.add_argument(
        "--preview",
        action="store_true",
        help="also write DIR/preview.html: one thumbnail of each layout's "
        "panel tree (foxglove format)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import InputError

    if args.preview and args.format != "foxglove":
        raise InputError.at("--preview", "previews are drawn from foxglove layouts only")
    if args.robot:
        if args.cluster_order or args.rates_bag:
            given = "--cluster-order" if args.cluster_order else "--rates-bag"
            raise InputError.at(given, "orders a team's layouts (not with --robot)")
        return _robot(args)
    if args.topics or args.bag or args.profile or args.set:
        given = (
            "--topics"
            if args.topics
            else "--bag"
            if args.bag
            else "--profile"
            if args.profile
            else "--set"
        )
        raise InputError.at(given, "needs --robot URDF")
    if args.team is None:
        raise InputError.at("TEAM.yaml", "a team is needed (or --robot URDF --team TEAM)")
    return _team(args)


def _team(args: argparse.Namespace) -> int:
    """A team's layouts into ``-o DIR``, and what was written, replaced and removed."""
    from solver import load_presentation, solve
    from solver.layouts.plan import check_namespace
    from solver.layouts.writer import check_layout_count, write_layout_folder

    namespace = check_namespace(args.namespace, "--namespace") if args.namespace else None
    team = load_team_argument(args.team, args.rules)
    # Counted first (by structure, in milliseconds): a team of 50,000 configurations is
    # refused before anything is solved, built or written.
    counted = solve(team, count_only=True).totals.ui_configurations
    check_layout_count(counted, args.output, extra=1 if args.preview else 0)
    solution = solve(team)
    # A user's presentation is checked against the rule set; the shipped one serves every one.
    presentation = load_presentation(
        args.presentation, solution.rules if args.presentation else None
    )
    presentation = _ordered(presentation, args)
    if args.rates_bag:
        presentation = _rates_found(presentation, solution, namespace, args.rates_bag)
    done = write_layout_folder(
        solution,
        presentation,
        args.output,
        args.format,
        namespace=namespace,
        preview=args.preview,
    )
    layouts = len(done.paths) - (1 if args.preview else 0)
    write(f"wrote {layouts} layouts to {shown(args.output, limit=SHOWN_FILE_NAME_CHARS)}\n")
    from solver.layouts.checks.quality import describe_consistency, team_consistency

    write(shown(describe_consistency(team_consistency(solution, presentation)), limit=None) + "\n")
    if args.preview:
        write(f"wrote {shown(str(done.paths[-1]), limit=SHOWN_FILE_NAME_CHARS)}\n")
    if done.replaced:
        write(f"replaced {len(done.replaced)} files of an earlier run: {_names(done.replaced)}\n")
    if done.removed:
        write(f"removed {len(done.removed)} files of an earlier run: {_names(done.removed)}\n")
    return 0


def _ordered(presentation: Any, args: argparse.Namespace) -> Any:
    """The presentation with the cluster order of ``--cluster-order`` (or its own) and the
    rates of ``--rates-bag``, checked (a located error for an order without its data)."""
    from solver.layouts.ordering import with_order

    rates = None
    if args.rates_bag:
        from solver.identify.readers.bags import read_bag_rates

        with_order(presentation, args.cluster_order, {})  # the order is checked first
        rates = read_bag_rates(args.rates_bag)
    return with_order(presentation, args.cluster_order, rates)


def _rates_found(presentation: Any, solution: Any, namespace: str | None, bag: str) -> Any:
    """The presentation ordering by data rate where the bag holds a sensor topic of the
    layouts to write (by name or last part); else alphabetically, and a warning says so."""
    from solver.layouts.design import SENSORS
    from solver.layouts.ordering import matched_rates
    from solver.layouts.plan import panel_entries, template_topic

    sensors = {
        component.name
        for characteristic in solution.rules.characteristics
        if characteristic.name == SENSORS
        for component in characteristic.components
    }
    topics = {
        template_topic(spec, namespace, tile)
        for configuration in solution.configurations
        for spec, count in panel_entries(solution, configuration, presentation)
        if spec.component in sensors
        for tile in range(count)
    }
    presentation, fault = matched_rates(presentation, topics, str(bag))
    if fault is not None:
        sys.stderr.write(f"warning: {shown(str(fault), limit=None)}\n")
    return presentation


def _names(names: tuple[str, ...], shown: int = 6) -> str:
    more = len(names) - shown
    return ", ".join(names[:shown]) + (f" and {more} more" if more > 0 else "")


def _robot(args: argparse.Namespace) -> int:
    from solver import InputError, identified_layout, load_profile, solve
    from solver.files.atomic import write_atomic
    from solver.layouts.plan import check_namespace

    if not args.robot_team:
        raise InputError.at("--robot", "--robot needs --team TEAM.yaml")
    namespace = check_namespace(args.namespace, "--namespace") if args.namespace else None
    solution = solve(load_team_argument(args.robot_team, args.rules))
    profile = load_profile(args.profile)
    done = identified_layout(
        args.robot,
        solution,
        profile=profile,
        presentation=args.presentation,
        fmt=args.format,
        namespace=namespace,
        given=given_values(args.set, solution),
        topics=args.topics,
        bag=args.bag,
        file=args.output,
    )
    for warning in done.layout.warnings:
        sys.stderr.write(f"warning: {shown(str(warning), limit=None)}\n")
    write_atomic(args.output, done.layout.text)
    write(
        f"{shown(done.identification.robot)}: configuration {done.assignment.number}; "
        f"wrote {shown(str(args.output), limit=SHOWN_FILE_NAME_CHARS)}\n"
    )
    return 0
