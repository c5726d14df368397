"""``teleop-ui studio [TEAM_OR_RULES]``: the design studio, a page in the browser."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from solver.cli._common import add_master_options, add_ros2_options


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "studio",
        help="the design studio: select a team in the browser and see its UI "
        "configurations as you click",
        description="Start the design studio, a local web server, and print its address. In "
        "the page: tick the values each kinematic type may have (the article's Figure 8) and "
        "see valid robots and UI configurations change; browse and compare configurations, "
        "look up a robot, see the charts and the linter's findings, identify uploaded robot "
        "descriptions, export the team, its report, layouts and UVL model; with --ros2 or "
        "--master, watch the robots on a live graph. Every page has a JSON API "
        "(GET /openapi.json). The page works offline: it loads nothing from elsewhere.",
    )
    parser.add_argument(
        "start",
        nargs="?",
        metavar="TEAM_OR_RULES",
        help="a team file (or a shipped team name: case3, ...) or a rule set to start with "
        "(default: the article's rule set, no type selected)",
    )
    parser.add_argument(
        "--port", type=int, default=8765, metavar="N", help="port (default: 8765; 0: any free)"
    )
    parser.add_argument(
        "--host",
        default="127.0.0.1",
        metavar="H",
        help="address to listen on (default: 127.0.0.1, this machine only); any other needs "
        "the token printed at start",
    )
    parser.add_argument("--open", action="store_true", help="open the page in a browser")
    parser.add_argument(
        "--fleet",
        action="append",
        default=[],
        metavar="DIR",
        help="a folder of robot descriptions the Fleet page may identify (repeatable)",
    )
    parser.add_argument(
        "--designs",
        metavar="DIR",
        help="a folder of designs (team files) the Designs page saves into, lists, reopens, "
        "compares and deletes",
    )
    add_ros2_options(parser, ros2_help="the Live page follows a ROS 2 graph on DDS")
    add_master_options(parser, required_help="the Live page follows this ROS 1 master")
    parser.add_argument(
        "--profile",
        "-p",
        metavar="PROFILE.yaml",
        help="identification profile for Fleet and Live (default: the shipped one)",
    )
    parser.add_argument(
        "--layouts",
        metavar="DIR",
        help="with --ros2/--master: write each live robot's Lichtblick layouts into DIR, as "
        "watch --layouts does; the Live view shows where the answer's are",
    )
    parser.add_argument(
        "--interval",
        type=positive_seconds,
        default=0.2,
        metavar="S",
        help="with --ros2/--master: polling interval in seconds (default: 0.2)",
    )
    parser.set_defaults(run=run)


def positive_seconds(text: str) -> float:
    from solver.cli._common import seconds

    return seconds(text)


def run(args: argparse.Namespace) -> int:
    import os

    from solver import InputError
    from solver.extras import require
    from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

    for module in ("starlette", "uvicorn", "jinja2"):
        require(module, feature="the studio (teleop-ui studio)")
    if not 0 <= args.port <= 65535:
        raise InputError.at("--port", f"a port is 0..65535, got {args.port}")
    if args.ros2 and args.master:
        raise InputError.at("--master", "give --ros2 or --master URL, not both")
    if args.layouts is not None and not (args.ros2 or args.master):
        raise InputError.at("--layouts", "the live robots' layouts need --ros2 or --master URL")
    for folder in args.fleet:
        if not os.path.isdir(folder):  # never raises, where Path.is_dir does on a long name
            raise InputError.at(
                shown(folder, limit=SHOWN_FILE_NAME_CHARS),
                "--fleet needs a folder of robot descriptions",
            )
    from solver.studio.server import bind, serve

    studio = _studio(args)
    try:
        sock = bind(args.host, args.port)
        try:
            serve(studio, sock, args.host, announce=_announce, open_browser=args.open, warn=_warn)
        finally:
            sock.close()
    finally:
        studio.workspace.close()
    return 0


def _announce(url: str) -> None:
    print(f"teleop-ui studio: {url}  (Ctrl-C stops it)", flush=True)


def _warn(message: str) -> None:
    print(f"teleop-ui studio: warning: {message}", file=sys.stderr, flush=True)


def _studio(args: argparse.Namespace) -> Any:
    from pathlib import Path

    from solver import load_profile
    from solver.studio.service import Studio
    from solver.studio.workspace import Workspace

    start = None
    shown = None
    if args.start:
        from solver.cli._common import team_path
        from solver.core.rules import shipped_name

        start = team_path(args.start)
        shown = args.start if str(start) == args.start else (shipped_name(start) or str(start))
    profile = load_profile(args.profile) if args.profile else None
    designs = None
    if args.designs is not None:
        from solver.studio.designs import Designs

        designs = Designs(Path(args.designs))
    workspace = Workspace(start=start, start_display=shown, folders=[Path(f) for f in args.fleet])
    live = _live(args, workspace, profile) if args.ros2 or args.master else None
    return Studio(workspace, live, profile, designs)


def _live(args: argparse.Namespace, workspace: Any, chosen: Any) -> Any:
    """The live feed: a watcher on the graph named (:func:`solver.graph_address`) for the team
    given at start (every type of its rule set when a rule set, or nothing, was given)."""
    from solver import full_team, graph_address, load_profile, solve
    from solver.studio.live import live_feed

    team = workspace.start_team or full_team(workspace.source(None).rules)
    solution = solve(team)
    profile = chosen if chosen is not None else load_profile()
    address = graph_address(ros2=args.ros2, master=args.master, domain=args.domain)
    return live_feed(
        address,
        solution,
        profile,
        interval=args.interval,
        timeout=args.timeout,
        layouts=args.layouts,
    )
