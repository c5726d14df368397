"""The peer of issue 29, item 5: Case 3 written directly with python-constraint2 and PyYAML.

What a programmer would write without teleop-ui: read the team and the article's rule set with
PyYAML's C loader, give python-constraint2 one problem per kinematic type (its motion controls,
sensor types and 1..N sensors), and group the solutions by the UI components they need (the
kinematic type, the motion control, the sensor's presentation group, the count's arrangement:
SPEC.md section 3). No validation and no locations: the peer's only job is the figures.

    python tools/peer_case3.py [TEAM]     # prints "872 102" for rules/teams/case3.yaml

``benchmarks/bench_small.py`` times :func:`solve_case3` against ``load_team`` + ``solve``
in-process, and this script against ``teleop-ui solve case3`` as whole processes.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import yaml
from constraint import Problem

ROOT = Path(__file__).resolve().parent.parent
CASE3 = ROOT / "rules" / "teams" / "case3.yaml"


def _read(path: Path) -> Any:
    with path.open(encoding="utf-8") as stream:
        return yaml.load(stream, Loader=yaml.CSafeLoader)


def solve_case3(team_path: Path = CASE3) -> tuple[int, int]:
    """(valid robots, UI configurations) of a team over the article's rule set."""
    team = _read(team_path)
    rules = _read(team_path.parent / team["rules"])
    sensor = rules["characteristics"]["sensor_type"]
    group = {value: c["name"] for c in sensor["components"] for value in c["values"]}
    arrangements = rules["characteristics"]["sensor_count"]["components"]

    def arrangement(count: int) -> str:
        return next(a["name"] for a in arrangements if a["min"] <= count <= a["max"])

    robots = 0
    configurations: set[tuple[str, str, str, str]] = set()
    for kind, selection in team["team"].items():
        problem = Problem()
        problem.addVariable("motion_control", selection["motion_control"])
        problem.addVariable("sensor_type", selection["sensor_type"])
        problem.addVariable("sensor_count", range(1, selection["sensor_count"] + 1))
        for robot in problem.getSolutionIter():
            robots += 1
            configurations.add(
                (
                    kind,
                    robot["motion_control"],
                    group[robot["sensor_type"]],
                    arrangement(robot["sensor_count"]),
                )
            )
    return robots, len(configurations)


if __name__ == "__main__":
    found = solve_case3(Path(sys.argv[1]) if len(sys.argv) > 1 else CASE3)
    print(*found)
