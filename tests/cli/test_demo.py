"""``teleop-ui demo ros2`` as a user runs it: with no Cyclone DDS configuration of its own, it
writes a loopback one and says how to watch its robots.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from tests.conftest import ROOT
from tests.live.ros2_graph import next_domain

SHORT = ("--every", "0.01", "--rounds", "2")


def test_the_demo_without_a_configuration_writes_a_loopback_one_and_says_how_to_watch(
    tmp_path: Path,
) -> None:
    environment = {k: v for k, v in os.environ.items() if k != "CYCLONEDDS_URI"}
    domain = next_domain()
    result = subprocess.run(
        [sys.executable, "-m", "solver", "demo", "ros2", "--domain", str(domain), *SHORT],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
        start_new_session=True,
    )
    assert (result.returncode, result.stderr) == (0, "")
    lines = result.stdout.splitlines()
    assert lines[0] == (
        "teleop-ui demo: Cyclone DDS configured by CYCLONEDDS_URI (loopback only); in another "
        "terminal:"
    )
    assert lines[1].startswith("  CYCLONEDDS_URI=file:///")
    assert f"teleop-ui watch --ros2 --domain {domain} --team " in lines[1]
    assert lines[3] == f"3 emulated robots on DDS domain {domain}: /uav1, /ugv1, /arm1"
    assert lines[4:] == [
        "operator selects /uav1 Flight",
        "  no answer yet (is a watcher running? teleop-ui watch --ros2 ...)",
        "operator selects /ugv1 Driving",
        "  no answer yet (is a watcher running? teleop-ui watch --ros2 ...)",
    ]
