"""Tiles and panel trees (solver.layouts.tiling): a sensor panel has a tile per cluster of the
most sensors its configuration serves, and panels split in balanced halves, rows then columns.
(At most MAX_TILES tiles for 100,000 clusters: tests/reporting/test_report_thumbnails.py.)"""

from __future__ import annotations

from solver import solve
from solver.layouts.tiling import split_tree, tiles
from tests.handcounted import OVERLAPPING_RULES, team_of


def test_a_sensor_panel_has_a_tile_per_cluster_of_the_most_sensors_served() -> None:
    solution = solve(team_of())
    few, *_, many = solution.configurations
    assert tiles(solution.rules, few) == 2  # "few": 1 or 2 sensors, one by one
    assert tiles(solution.rules, many) == 3  # "many": up to 6 sensors in clusters of 2


def test_rules_without_a_count_show_one_tile() -> None:
    solution = solve(team_of("team: {UGV: {}}", OVERLAPPING_RULES))
    assert {tiles(solution.rules, c) for c in solution.configurations} == {1}


def test_one_panel_is_the_tree_itself() -> None:
    assert split_tree(["a"]) == "a"


def test_panels_split_in_halves_a_row_first_then_columns() -> None:
    assert split_tree(["a", "b", "c"]) == {
        "direction": "row",
        "first": {"direction": "column", "first": "a", "second": "b", "splitPercentage": 50.0},
        "second": "c",
        "splitPercentage": 66.67,
    }
