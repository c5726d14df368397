"""``teleop-ui demo ros2``: emulated ROS 2 robots and an operator on loopback, to watch."""

from __future__ import annotations

import argparse
import os
import sys
from typing import Any

from solver.cli._common import positive, seconds
from solver.untrusted import shown


def register(subparsers: Any) -> None:
    parser: argparse.ArgumentParser = subparsers.add_parser(
        "demo",
        help="start emulated ROS 2 robots and an operator on loopback, to try watch --ros2",
        description="Start a multirotor (/uav1), a differential-drive base (/ugv1) and an "
        "arm (/arm1) as real DDS participants behaving as ROS 2 processes do on the wire "
        "(Cyclone DDS, no ROS 2 needed), and an operator station that makes each robot "
        "active in turn. Run `teleop-ui watch --ros2` in another terminal with the "
        "CYCLONEDDS_URI this prints. Ctrl-C stops it. See docs/live.md.",
    )
    parser.add_argument("graph", choices=("ros2",), help="the graph to emulate: ros2")
    parser.add_argument(
        "--domain",
        type=int,
        default=None,
        metavar="N",
        help="the DDS domain id (default: $ROS_DOMAIN_ID, else 0)",
    )
    parser.add_argument(
        "--every",
        type=seconds,
        default=3.0,
        metavar="S",
        help="seconds between the operator's switches (default: 3)",
    )
    parser.add_argument(
        "--rounds",
        type=positive,
        default=None,
        metavar="N",
        help="stop after N switches (default: run until Ctrl-C)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    import signal
    import tempfile
    import threading
    from pathlib import Path

    from solver.extras import require
    from solver.live.sources import dds_domain

    require("cyclonedds", feature="the ROS 2 demo (teleop-ui demo ros2)")
    domain = dds_domain(args.domain)
    stopped = threading.Event()
    previous = signal.signal(signal.SIGTERM, lambda *_: stopped.set())
    try:
        with tempfile.TemporaryDirectory(prefix="teleop-ui-demo-") as folder:
            _configure(Path(folder), domain)
            from solver.live.demo import run_demo

            run_demo(domain, args.every, _say, stopped, rounds=args.rounds)
    finally:
        signal.signal(signal.SIGTERM, previous)
    return 0


def _configure(folder: Any, domain: int) -> None:
    """Cyclone DDS's configuration: ``$CYCLONEDDS_URI`` as given, else loopback only."""
    from solver.live.demo import demo_team, loopback_uri

    given = os.environ.get("CYCLONEDDS_URI")
    uri = given or loopback_uri(folder)
    os.environ["CYCLONEDDS_URI"] = uri
    where = "as given" if given else "loopback only"
    team = demo_team(folder)
    _say(
        f"teleop-ui demo: Cyclone DDS configured by CYCLONEDDS_URI ({where}); in another "
        "terminal:\n"
        f"  CYCLONEDDS_URI={shown(uri, limit=None)} teleop-ui watch --ros2 --domain {domain} "
        f"--team {shown(str(team), limit=None)} --format text\n"
        "(Ctrl-C stops the demo)"
    )


def _say(text: str) -> None:
    print(text, flush=True)
    sys.stdout.flush()
