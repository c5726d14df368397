"""Sensors and clusters (solver.layouts.tiling): a layout shows each sensor of the most its
configuration serves, grouped into Equation (2)'s clusters of the arrangement's size, capped.
(At most MAX_TILES individual sensors for 100,000: tests/reporting/test_report_thumbnails.py.)"""

from __future__ import annotations

from solver import solve
from solver.layouts.tiling import MAX_TABS, MAX_TILES, capped, cluster_size, tiles
from tests.handcounted import OVERLAPPING_RULES, team_of


def test_a_layout_shows_each_sensor_of_the_most_its_configuration_serves() -> None:
    solution = solve(team_of())
    few, *_, many = solution.configurations
    assert tiles(solution.rules, few) == 2  # "few": 1 or 2 sensors, one by one
    assert tiles(solution.rules, many) == 6  # "many": up to 6 sensors, in clusters of 2


def test_the_cluster_size_is_the_arrangements() -> None:
    solution = solve(team_of())
    few, *_, many = solution.configurations
    assert cluster_size(solution.rules, few) == 1
    assert cluster_size(solution.rules, many) == 2
    assert cluster_size(solution.rules, None) == 1  # the default configuration: one tile each


def test_rules_without_a_count_show_one_tile() -> None:
    solution = solve(team_of("team: {UGV: {}}", OVERLAPPING_RULES))
    assert {tiles(solution.rules, c) for c in solution.configurations} == {1}


def test_sensors_stop_at_max_tiles_clusters_of_at_most_max_tabs() -> None:
    assert capped(100_000, 1) == MAX_TILES == 25
    assert capped(100_000, 10) == MAX_TILES * 10
    assert capped(100_000, 1000) == MAX_TILES * MAX_TABS
    assert capped(50, 10) == 50  # the article's largest arrangement is whole
    assert capped(0, 1) == 1
