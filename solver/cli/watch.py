"""``teleop-ui watch --master URL --team TEAM``: UI configurations live from a ROS master."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from typing import TYPE_CHECKING, Any

from solver.cli._common import (
    add_format,
    add_master_options,
    add_profile,
    add_ros2_options,
    add_set,
    add_team,
    load_team_argument,
    seconds,
    write,
)
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver import MasterError, Solution, Watcher
    from solver.live.events import Event
    from solver.live.layouts import LiveLayouts
    from solver.live.server import AnswerServer


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "watch",
        help="follow a running ROS master: robots, their UI configurations, and the "
        "operator's active selection, as events",
        description="Follow a ROS 1 master (or a ROS 2 graph, --ros2): every namespace with a "
        "robot_description is a robot, identified from its description and topics; print an "
        "event (JSON lines, or text) whenever a robot is added, changed or removed, the "
        "operator's selection (/teleop_ui/active_robot, /teleop_ui/active_<characteristic> "
        "for any characteristic of the rule set) changes, something on the graph is ignored "
        "(a warning), another watcher answers differently (a rival), or the master is lost and "
        "back. The active selection's UI configuration is written to "
        "/teleop_ui/ui_configuration.",
    )
    add_master_options(parser, required_help="default: $ROS_MASTER_URI")
    add_ros2_options(
        parser,
        ros2_help="follow a ROS 2 graph on DDS instead of a ROS 1 master (no ROS 2 "
        "needed; the [ros2] extra; Cyclone DDS is configured by "
        "$CYCLONEDDS_URI); see docs/live.md",
    )
    add_team(parser)
    add_profile(parser)
    parser.add_argument(
        "--once",
        action="store_true",
        help="print one snapshot (every robot, the selection) and exit",
    )
    parser.add_argument(
        "--interval",
        "-i",
        type=seconds,
        default=0.2,
        metavar="S",
        help="polling interval in seconds (default: 0.2)",
    )
    parser.add_argument(
        "--wait",
        action="store_true",
        help="wait for the master to come up instead of failing (exit 2); with --ros2, wait "
        "for the first robot (a DDS domain is never down)",
    )
    add_set(parser)
    rivals = parser.add_mutually_exclusive_group()
    rivals.add_argument(
        "--yield",
        dest="policy",
        action="store_const",
        const="yield",
        default="yield",
        help="leave the answer of a running rival watcher (another team, rules or values) in "
        "place, saying so in the selection's notes (the default)",
    )
    rivals.add_argument(
        "--insist",
        dest="policy",
        action="store_const",
        const="insist",
        help="write this watcher's answer over a yielding rival's (never over another "
        "insisting one's)",
    )
    add_format(parser, ("json", "text"), default="json")
    # --layouts (issues 17, 26; solver.live.layouts): each robot's layouts, named in events.
    parser.add_argument(
        "--layouts",
        metavar="DIR",
        help="write each robot's Lichtblick layouts, filled with its real topics, into "
        "DIR/NAMESPACE/ when it appears or changes, and the team layout DIR/team.json (a "
        "tab per robot and configuration, and the follower panel that switches them); the "
        "answer and each selection_changed event say where the active robot's are",
    )
    # --serve (issue 38; solver.live.server): the answer and the layouts on loopback.
    parser.add_argument(
        "--serve",
        metavar="[HOST:]PORT",
        help="with --layouts: serve the answer (/answer, and /answer/events as Server-Sent "
        "Events) and DIR's layouts (/layouts/PATH) read-only on this loopback address "
        "(HOST 127.0.0.1 by default; PORT 0: a free one, printed on stderr at start)",
    )
    parser.add_argument(
        "--viewer-origin",
        action="append",
        metavar="ORIGIN",
        help="with --serve: a web page origin that may read what is served (repeat for "
        "more; default: http://127.0.0.1:8080 and http://localhost:8080, where "
        "Lichtblick's web build is served by tools/lichtblick/serve.py)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from solver import graph_address, load_profile, open_watcher, solve
    from solver.live.given import parse_fixed

    _check_serving(args)
    team = load_team_argument(args.team, args.rules)
    profile = load_profile(args.profile)
    solution = solve(team)
    fixed = parse_fixed(args.set, solution.rules)
    address = graph_address(ros2=args.ros2, master=args.master, domain=args.domain)
    with ExitStack() as stack:
        server = _server(args, stack)
        watcher = stack.enter_context(
            open_watcher(
                address,
                solution,
                profile,
                interval=args.interval,
                timeout=args.timeout,
                push=not args.once,
                fixed=fixed,
                policy=args.policy,
                layouts=_layouts(args, solution, server),
            )
        )
        stack.enter_context(_stopped_by_sigterm(watcher))
        return _watch(watcher, args, solution, server)


def _check_serving(args: argparse.Namespace) -> None:
    """--serve needs --layouts and a watch that runs; --viewer-origin needs --serve."""
    from solver.errors import InputError

    if args.serve is not None and args.layouts is None:
        raise InputError.at("--serve", "needs --layouts DIR: the folder it serves")
    if args.serve is not None and args.once:
        raise InputError.at("--serve", "a snapshot (--once) ends at once: nothing to serve")
    if args.viewer_origin is not None and args.serve is None:
        raise InputError.at("--viewer-origin", "only with --serve: who may read what it serves")


def _server(args: argparse.Namespace, stack: ExitStack) -> AnswerServer | None:
    """The server of ``--serve``, listening (its address said on stderr), closed with the
    watch."""
    if args.serve is None:
        return None
    from solver.files.atomic import make_folder
    from solver.live.server import DEFAULT_ORIGINS, AnswerServer, serve_address, viewer_origin

    address = serve_address(args.serve)
    origins = [viewer_origin(o) for o in args.viewer_origin or DEFAULT_ORIGINS]
    make_folder(args.layouts)
    server = stack.enter_context(AnswerServer(args.layouts, address, origins))
    print(
        f"serving on {server.url} (answer: /answer, events: /answer/events, layouts: "
        f"/layouts/; viewers: {', '.join(origins)})",
        file=sys.stderr,
        flush=True,
    )
    return server


@contextmanager
def _stopped_by_sigterm(watcher: Watcher) -> Iterator[None]:
    """SIGTERM (systemd, roslaunch after SIGINT, kill) ends the watch as cleanly as Ctrl-C:
    subscriptions released, exit 0; the previous handler is back afterwards."""
    import signal  # here, not at start-up: only watching needs it

    previous = signal.signal(signal.SIGTERM, lambda *_: watcher.stop("terminated (SIGTERM)"))
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _watch(
    watcher: Watcher, args: argparse.Namespace, solution: Solution, server: AnswerServer | None
) -> int:
    from solver import MasterError

    try:
        _follow(watcher, args, solution, server)
    except MasterError:
        if not watcher.stopped:
            raise
        # stop() (SIGTERM, a shutdown call) cut the call under way off: a stop, not an error.
    if watcher.stop_reason is not None:
        print(f"watch stopped: {shown(watcher.stop_reason, limit=None)}", file=sys.stderr)
    return 0


def _follow(
    watcher: Watcher, args: argparse.Namespace, solution: Solution, server: AnswerServer | None
) -> None:
    """One loop for every graph: wait for it (``--wait``: a master to answer, or on DDS a first
    robot) or check it answers, then a snapshot (``--once``) or events until stopped; each new
    answer served first (``--serve``), then its event written."""
    from solver.live.events import SelectionChanged

    if args.wait and args.ros2:
        watcher.wait_for_robot(lambda: _waiting(f"a robot on {shown(watcher.master)}", None))
    elif args.wait:
        watcher.wait_for_master(
            lambda error: _waiting(f"the ROS master at {shown(watcher.master)}", error)
        )
    else:
        _check_answers(watcher)
    events = [] if watcher.stopped else watcher.snapshot() if args.once else watcher.events()
    for event in events:
        if server is not None and isinstance(event, SelectionChanged):
            server.publish(watcher.answer)
        write(_render(event, solution, args, watcher.layouts))


def _waiting(what: str, error: MasterError | None) -> None:
    why = "" if error is None else f" ({shown(error.faults[0].message, limit=None)})"
    print(f"waiting for {what}{why}", file=sys.stderr, flush=True)


def _check_answers(watcher: Watcher) -> None:
    """A master that does not answer is exit 2 at once (``--wait`` waits for it)."""
    from solver.live.graph import MasterUnreachable

    try:
        watcher.source.get_pid()
    except MasterUnreachable as error:
        if watcher.stopped:
            raise
        raise MasterUnreachable.at(
            watcher.master,
            f"{shown(error.faults[0].message, limit=None)}: is roscore running there? "
            "(--wait waits for it)",
        ) from None


def _layouts(
    args: argparse.Namespace, solution: Solution, server: AnswerServer | None
) -> LiveLayouts | None:
    """The robots' layouts of ``--layouts``, with their addresses when served."""
    if args.layouts is None:
        return None
    from solver.live.layouts import LiveLayouts

    if server is None:
        return LiveLayouts(args.layouts, solution)
    return LiveLayouts(
        args.layouts, solution, base_url=server.url, answer_url=f"{server.url}/answer/events"
    )


def _render(
    event: Event, solution: Solution, args: argparse.Namespace, layouts: LiveLayouts | None
) -> str:
    """The event as text or JSON, after the warnings of the layouts written for it (stderr)."""
    from solver.live.render import render_event

    for warning in layouts.take_warnings() if layouts is not None else ():
        print(f"warning: {warning}", file=sys.stderr, flush=True)
    return render_event(event, solution, args.format)
