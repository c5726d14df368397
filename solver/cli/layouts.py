"""``teleop-ui layouts TEAM -o DIR``: a Foxglove or RViz2 layout per UI configuration."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import add_rules, load_team_argument, write


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "layouts",
        help="write one viewer layout per UI configuration, plus the default",
        description="Write a Foxglove / Lichtblick layout JSON for every UI configuration of a "
        "team and for the default configuration; topics are <robot>/... templates.",
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
    add_rules(parser)
    parser.add_argument(
        "-o", "--output", metavar="DIR", required=True, help="directory for the layout files"
    )
    parser.add_argument(
        "--format",
        choices=("foxglove", "rviz"),
        default="foxglove",
        help="foxglove: Foxglove / Lichtblick layout JSON (default); rviz: RViz2 .rviz files",
    )
    parser.add_argument(
        "--profile",
        metavar="FILE",
        help="presentation profile (default: the shipped rules/presentation.yaml)",
    )
    parser.add_argument(
        "--preview",
        action="store_true",
        help="also write DIR/preview.html: one thumbnail of each layout's "
        "panel tree (foxglove format)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver.core.solution import solve
    from solver.layouts import load_profile, write_layouts

    if args.preview and args.format != "foxglove":
        from solver.errors import InputError

        raise InputError.at("--preview", "previews are drawn from foxglove layouts only")
    if args.robot:
        return _robot(args)
    if args.topics or args.bag:
        from solver.errors import InputError

        raise InputError.at("--topics" if args.topics else "--bag", "needs --robot URDF")
    if args.team is None:
        from solver.errors import InputError

        raise InputError.at("TEAM.yaml", "a team is needed (or --robot URDF --team TEAM)")
    team = load_team_argument(args.team, args.rules)
    solution = solve(team)
    # A user's profile is checked against the rule set; the shipped one serves every rule set.
    profile = load_profile(args.profile, solution.rules if args.profile else None)
    paths = write_layouts(solution, profile, args.output, args.format)
    write(f"wrote {len(paths)} layouts to {args.output}\n")
    if args.preview:
        import json
        from pathlib import Path

        from solver.files.atomic import write_atomic
        from solver.layouts.preview import preview_html

        page = Path(args.output) / "preview.html"
        write_atomic(
            page, preview_html([(path.name, json.loads(path.read_text())) for path in paths])
        )
        write(f"wrote {page}\n")
    return 0


def _robot(args: argparse.Namespace) -> int:
    import json
    from pathlib import Path

    from solver.core.assignment import assign
    from solver.core.solution import solve
    from solver.errors import InputError
    from solver.files.atomic import write_atomic
    from solver.identify import identify_urdf
    from solver.identify.readers.safexml import read_bytes
    from solver.layouts import foxglove_layout, load_profile, validate_foxglove
    from solver.layouts.rviz import rviz_layout, rviz_text, validate_rviz

    if not args.robot_team:
        raise InputError.at("--robot", "--robot needs --team TEAM.yaml")
    solution = solve(load_team_argument(args.robot_team, args.rules))
    identification = identify_urdf(
        read_bytes(args.robot, display=args.robot), file=args.robot, rules=solution.rules
    )
    # The robot's first control mode and sensor type: the combination it starts in.
    combination: dict[str, str | int] = {"sensor_count": max(1, identification.sensor_count)}
    if identification.kinematic_type:
        combination["kinematic_type"] = identification.kinematic_type
    if identification.motion_controls:
        combination["motion_control"] = identification.motion_controls[0].motion_control
    if identification.sensor_types:
        combination["sensor_type"] = identification.sensor_types[0]
    assignment = assign(solution, combination)
    profile = load_profile(args.profile, solution.rules if args.profile else None)
    namespace = "/" + identification.robot
    # The robot's own number of sensor tiles: g(i) of its sensor count.
    tile_count = None
    if assignment.configuration is not None:
        count_position = next(
            position
            for position, c in enumerate(solution.rules.characteristics)
            if c.kind == "integer"
        )
        tile_count = assignment.configuration.components[count_position].clusters(
            int(combination["sensor_count"])
        )
    # The robot's real topics, read as `identify` reads them, in place of the templates.
    real: dict[tuple[str, int], str] = {}
    if args.topics or args.bag:
        from solver.layouts.foxglove import panel_entries
        from solver.layouts.topics import match_topics

        if args.topics:
            from solver.identify.topics import read_topic_list

            source, topics = args.topics, read_topic_list(args.topics)
        else:
            from solver.identify.readers.bags import read_bag_topics

            source, topics = args.bag, read_bag_topics(args.bag)
        entries = panel_entries(solution, assignment.configuration, profile, tile_count)
        real, warnings = match_topics(entries, topics, source)
        for warning in warnings:
            sys.stderr.write(f"warning: {warning}\n")
    if args.format == "foxglove":
        layout = foxglove_layout(
            solution,
            assignment.configuration,
            profile,
            robot=namespace,
            tile_count=tile_count,
            topics=real,
        )
        validate_foxglove(layout, args.output)
        text = json.dumps(layout, indent=2, sort_keys=True) + "\n"
    else:
        text = rviz_text(
            rviz_layout(
                solution,
                assignment.configuration,
                profile,
                robot=namespace,
                tile_count=tile_count,
                topics=real,
            )
        )
        validate_rviz(text, args.output)
    write_atomic(Path(args.output), text)
    write(f"{identification.robot}: configuration {assignment.number}; wrote {args.output}\n")
    return 0
