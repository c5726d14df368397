"""``teleop-ui robots``: every valid robot with its configuration, from either engine, and
its limit.
"""

from __future__ import annotations

import csv
import io
import json

from tests.conftest import run_cli


def test_robots_lists_every_valid_robot_with_its_configuration() -> None:
    result = run_cli("robots", "rules/teams/case3.yaml")
    rows = list(csv.reader(io.StringIO(result.stdout)))
    assert rows[0] == [
        "configuration",
        "kinematic_type",
        "motion_control",
        "sensor_type",
        "sensor_count",
    ]
    assert len(rows) == 1 + 872
    assert rows[1] == ["1", "UAV", "Flight", "2D Camera", "1"]
    assert {int(row[0]) for row in rows[1:]} == set(range(1, 103))


def test_robots_from_both_engines_are_the_same_set() -> None:
    fast = run_cli("robots", "case2", "-f", "jsonl").stdout.splitlines()
    reference = run_cli("robots", "case2", "-f", "jsonl", "--engine", "csp").stdout.splitlines()
    assert sorted(fast) == sorted(reference)
    assert json.loads(fast[-1])["configuration"] == 18


def test_robots_refuses_to_list_more_than_the_limit() -> None:
    result = run_cli("robots", "case3", "--max-robots", "100")
    assert result.returncode == 2
    assert result.stdout == ""
    assert (
        "listing 872 robots is refused (more than 100, see --max-robots; "
        "limit 'robots', docs/security.md)" in result.stderr
    )
