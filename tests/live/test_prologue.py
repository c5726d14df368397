"""Issue 23.2 on a live graph: a description whose prologue was quadratic to scan.

``watch --once`` reads every ``robot_description`` through the same XML reader as
``identify``; 40,000 open ``<!DOCTYPE[`` took minutes there, and hung the watcher. Now the
robot is reported with a located error at once and the good robot beside it is identified.
"""

from __future__ import annotations

import json

from solver.solving.solution import Solution
from tests.conftest import run_cli
from tests.live.fleet import put_rover, rover_configuration
from tests.live.roscore import Roscore, TestNode


def test_watch_once_reports_forty_thousand_open_document_types_and_goes_on(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    node.set_param("/open/robot_description", "<!DOCTYPE[" * 40_000 + '<robot name="r"/>')
    put_rover(node, "/ugv1")
    result = run_cli(
        "watch", "--master", master.uri, "--team", "case3", "--once", "--format", "json"
    )
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    robots = {e["robot"]: e for e in events if e["event"] == "robot_added"}
    assert robots["/open"]["combinations"] == []
    assert robots["/open"]["error"].startswith("/open/robot_description:1:")
    assert "malformed XML" in robots["/open"]["error"]
    assert robots["/ugv1"]["combinations"][0]["configuration"] == rover_configuration(solution)
