"""Put a small demo fleet on a running ROS master, to try ``teleop-ui watch`` without robots.

Usage::

    roscore -p 11311 &
    python tools/demo_fleet.py --master http://127.0.0.1:11311

Three robots appear, as their nodes would register them at start-up: ``/uav1`` (a quadrotor
publishing a camera), ``/ugv1`` (a wheeled rover subscribing to ``cmd_vel`` and publishing a
laser scan) and ``/broken`` (a malformed description). Their topics are registered through the
master API by one small node (an XML-RPC server on loopback) that stays up until Ctrl-C, then
unregisters them and deletes the descriptions. The descriptions are the ones the tests use
(``tests/identify/builders.py``); run it from the repository's root.
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from solver.errors import SolverError
from solver.live.sources.ros1.master import master_uri
from tests.live.fleet import put_drone, put_rover
from tests.live.roscore import TestNode

BROKEN = '<robot name="broken">\n  <link name="base_link">\n</robot>\n'


def _interrupt(*_: object) -> None:
    """SIGTERM ends the demo as Ctrl-C does, cleaning up."""
    raise KeyboardInterrupt


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--master", "-m", help="ROS master URI (default: $ROS_MASTER_URI)")
    args = parser.parse_args()
    try:
        uri = master_uri(args.master)
        node = TestNode(uri)
        put_drone(node, "/uav1")
        put_rover(node, "/ugv1")
        node.set_param("/broken/robot_description", BROKEN)
    except SolverError as error:
        print(error, file=sys.stderr)
        return 2
    print(f"demo fleet on {uri}: /uav1, /ugv1, /broken (Ctrl-C removes it)", flush=True)
    signal.signal(signal.SIGTERM, _interrupt)
    with contextlib.suppress(KeyboardInterrupt):
        while True:
            time.sleep(3600)
    with contextlib.suppress(SolverError):  # the master may be gone already
        node.unregister_all()
        for robot in ("/uav1", "/ugv1", "/broken"):
            node.delete_param(f"{robot}/robot_description")
    node.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
