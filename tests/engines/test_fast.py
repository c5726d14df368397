"""The numpy engine: the same partition as the reference, block by block."""

from __future__ import annotations

import pytest

from solver import load_team, solve
from solver.core.model import robots
from solver.core.rules import parse_rules
from solver.core.team import parse_team
from solver.engines import fast as stream
from solver.engines.fast import partition as partition_stream
from solver.engines.fast import robots as robots_stream
from solver.files.yamlio import parse_document
from tests.conftest import TEAMS


def test_small_blocks_give_the_same_partition(monkeypatch: pytest.MonkeyPatch) -> None:
    team = load_team(TEAMS / "case3.yaml")
    reference = solve(team, engine="csp")
    monkeypatch.setattr(stream, "BLOCK", 4)  # many prefixes, one tiny block each
    assert solve(team, engine="fast").configurations == reference.configurations


def test_sparse_counters_give_the_same_partition(monkeypatch: pytest.MonkeyPatch) -> None:
    team = load_team(TEAMS / "case3.yaml")
    reference = solve(team, engine="csp")
    monkeypatch.setattr(stream._Counter, "DENSE", 0)
    monkeypatch.setattr(stream._Pairs, "DENSE", 0)
    assert solve(team, engine="fast").configurations == reference.configurations


def test_robots_stream_in_product_order() -> None:
    team = load_team(TEAMS / "case1.yaml")
    (uav,) = team.selections
    streamed = list(robots_stream(team.rules, uav))
    assert streamed[:3] == [
        ("UAV", "Flight", "2D Camera", 1),
        ("UAV", "Flight", "2D Camera", 2),
        ("UAV", "Flight", "2D Camera", 3),
    ]
    assert sorted(streamed) == sorted(robots(team.rules, uav.domains))


def test_partition_stream_counts_each_robot_once() -> None:
    team = load_team(TEAMS / "case3.yaml")
    for selection in team.selections:
        part = partition_stream(team.rules, selection)
        assert sum(found.robots for found in part.classes) == part.valid_robots


COUNTS = """\
characteristics:
  kinematic_type: {values: [UGV]}
  sensor_type: {values: [A, B]}
  sensor_count:
    range: {min: 1, max: 100000}
    components:
      - {name: few, min: 1, max: 50000}
      - {name: many, min: 50001, max: 100000}
constraints:
  - forbid: {sensor_type: A, sensor_count: {min: 99991}}
"""


def test_counts_the_rules_cannot_tell_apart_are_weighed_not_enumerated_one_by_one() -> None:
    rules = parse_rules(parse_document(COUNTS, "rules.yaml"))
    team = parse_team(parse_document("team: {UGV: {}}", "team.yaml"), rules)
    (selection,) = team.selections
    part = partition_stream(rules, selection)
    # 2 x 100,000 robots less A's top 10 counts; A's "many" serves 50001..99990 only.
    assert part.valid_robots == 199_990
    assert [(found.robots, found.served[2][0], found.served[2][-1]) for found in part.classes] == [
        (50_000, 1, 50_000),
        (49_990, 50_001, 99_990),
        (50_000, 1, 50_000),
        (50_000, 50_001, 100_000),
    ]
    assert [len(found.served[2]) for found in part.classes] == [50_000, 49_990, 50_000, 50_000]
    assert (
        solve(team, engine="fast").configurations == solve(team, engine="structure").configurations
    )
