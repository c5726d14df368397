"""The numpy engine: the same partition as the reference, block by block."""

from __future__ import annotations

import pytest

from solver import load_team, solve
from solver.engines import fast as stream
from solver.engines.fast import partition as partition_stream
from solver.engines.fast import robots as robots_stream
from solver.model import robots
from tests.conftest import TEAMS


def test_small_blocks_give_the_same_partition(monkeypatch: pytest.MonkeyPatch) -> None:
    team = load_team(TEAMS / "case3.yaml")
    reference = solve(team, engine="csp")
    monkeypatch.setattr(stream, "BLOCK", 4)  # many prefixes, one tiny block each
    assert solve(team, engine="fast").configurations == reference.configurations


def test_sparse_counters_give_the_same_partition(monkeypatch: pytest.MonkeyPatch) -> None:
    team = load_team(TEAMS / "case3.yaml")
    reference = solve(team, engine="fast")
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
