"""``watch --layouts DIR`` names the active configuration's layout file, on a real roscore."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver import load_team, solve
from tests.conftest import run_cli
from tests.live.fleet import put_rover, rover_configuration
from tests.live.roscore import Roscore, TestNode, roscore_available


def test_watch_selection_event_names_the_layout_of_the_active_robot(tmp_path: Path) -> None:
    if not roscore_available():
        pytest.fail("roscore is not installed: install Debian's ros-core (tools/test.sh does)")
    (tmp_path / "ros").mkdir()
    core = Roscore(tmp_path / "ros")
    core.start()
    try:
        node = TestNode(core.uri)
        put_rover(node, "/ugv1")
        node.set_param("/teleop_ui/active_robot", "/ugv1")
        result = run_cli(
            "watch", "--master", core.uri, "--team", "case3", "--once", "--layouts", "layouts"
        )
        node.close()
    finally:
        core.kill()
    assert result.returncode == 0, result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    selection = next(e for e in events if e["event"] == "selection_changed")
    number = rover_configuration(solve(load_team("case3")))
    assert selection["layout"] == f"layouts/config-{number:03d}.json"
    assert all("layout" not in e for e in events if e["event"] != "selection_changed")
