"""Plans laid out by the grammar (solver.layouts.design): the primary view, secondary views,
controls docked left, Equation (2)'s clusters as one tile each, a region's overflow in one."""

from __future__ import annotations

from solver import load_team, solve
from solver.layouts.checks.quality import leaf_rects
from solver.layouts.design import Split, Tile, design
from solver.layouts.foxglove import foxglove_layout
from solver.layouts.grammar import Rect
from solver.layouts.plan import plan_layout
from solver.layouts.presentation import load_presentation
from solver.solving.solution import Solution


def _laid(team: str, number: int | None) -> tuple[Solution, list[Tile]]:
    solution = solve(load_team(team))
    configuration = next((c for c in solution.configurations if c.number == number), None)
    return solution, list(design(plan_layout(solution, configuration, load_presentation())).tiles)


def _roles(tiles: list[Tile]) -> list[tuple[str, str]]:
    return [(tile.role, tile.title) for tile in tiles]


def test_the_main_camera_is_the_primary_view_its_other_sensors_secondary_controls_last() -> None:
    _, tiles = _laid("case1", 1)  # UAV, Flight, visual display, 1..5 sensors
    assert _roles(tiles) == [
        ("primary", "visual display 1"),
        *(("secondary", f"visual display {n}") for n in range(2, 6)),
        ("controls", "Flight"),
    ]


def test_the_designed_geometry_docks_controls_left_and_gives_the_camera_most_of_the_screen() -> (
    None
):
    solution = solve(load_team("case1"))
    layout = foxglove_layout(solution, solution.configurations[0], load_presentation())
    rects = leaf_rects(layout["layout"], 1920, 1080)
    # By hand: controls 20% of 1920 = 384 wide; the status region is empty, so the primary
    # and secondary views take the whole height: primary 62.5% of 1920 = 1200 wide, the four
    # secondary views 1920 - 384 - 1200 = 336 wide, 1080 / 4 = 270 high each.
    assert rects["Teleop!p01"] == Rect(0, 0, 384, 1080)
    assert rects["Image!p02"] == Rect(384, 0, 1200, 1080)
    # (Split percentages are written to a hundredth: 33.33% of 810 is 269.97 pixels.)
    assert [_pixels(rects[f"Image!p0{n}"]) for n in range(3, 7)] == [
        (1584, 270 * k, 336, 270) for k in range(4)
    ]


def _pixels(rect: Rect) -> tuple[int, ...]:
    return tuple(round(value) for value in (rect.x, rect.y, rect.width, rect.height))


def test_a_robot_without_a_camera_has_its_3d_view_as_primary() -> None:
    _, tiles = _laid("case2", 11)  # UGV, Driving, point cloud
    assert tiles[0].role == "primary"
    assert tiles[0].panels[0].kind == "3D"
    assert tiles[0].component == "point cloud"


def test_a_robot_with_neither_camera_nor_3d_view_has_its_first_sensor_as_primary() -> None:
    _, tiles = _laid("case2", 9)  # UGV, Driving, audio
    assert _roles(tiles)[:2] == [("primary", "audio 1"), ("secondary", "audio 2")]


def test_sensors_past_the_individual_range_are_grouped_in_equation_2s_clusters() -> None:
    _, tiles = _laid("case2", 8)  # UGV, Driving, visual display, 6..10 sensors, clusters of 2
    assert _roles(tiles) == [
        ("primary", "visual display, cluster 1 (1, 2)"),
        ("secondary", "visual display, cluster 2 (3, 4)"),
        ("secondary", "visual display, cluster 3 (5, 6)"),
        ("secondary", "visual display, cluster 4 (7, 8)"),
        ("secondary", "visual display, cluster 5 (9, 10)"),
        ("controls", "Driving"),
    ]


def test_motion_controls_sit_together_in_the_controls_region() -> None:
    solution, tiles = _laid("case3", None)  # the default configuration: every component
    controls = [tile.title for tile in tiles if tile.role == "controls"]
    assert controls == ["Joint", "Flight, Driving, Walking", "End Effector", "Waypoint"]
    assert solution.default_configuration > 0


def test_tiles_a_region_has_no_room_for_share_its_last_place() -> None:
    solution = solve(load_team("case1"))
    # A robot with eight cameras on configuration 1 (1..5 sensors, shown one by one).
    plan = plan_layout(solution, solution.configurations[0], load_presentation(), tile_count=8)
    secondary = [tile for tile in design(plan).tiles if tile.role == "secondary"]
    # 80% of 1080 = 864 pixels hold four tiles of at least 180: three, and one for the rest.
    assert [tile.title for tile in secondary] == [
        "visual display 2",
        "visual display 3",
        "visual display 4",
        "more: visual display 5, visual display 6, visual display 7, visual display 8",
    ]


def test_the_default_configuration_keeps_every_primary_view_in_the_primary_region() -> None:
    # Each sensor is the primary view of the configurations that show it; the default shows
    # them all: one Tab panel in the primary region, a tab each, the grammar's first first.
    _, tiles = _laid("rules/teams/search-and-rescue.yaml", None)
    primary = [tile for tile in tiles if tile.role == "primary"]
    assert [tile.title for tile in primary] == [
        "visual display | spherical display | point cloud | audio | haptic | environment gauges"
    ]
    assert primary[0].grouped
    assert primary[0].component == "visual display"
    assert [tile.role for tile in tiles if tile.role == "secondary"] == []
    assert [tile.role for tile in tiles if tile.component == "teleoperated"] == ["status"]


def test_a_region_stacks_its_tiles_in_equal_shares_along_its_longer_side() -> None:
    solution = solve(load_team("case1"))
    laid = design(plan_layout(solution, solution.configurations[0], load_presentation()))
    assert laid.tree == Split(
        "row",
        20.0,
        5,
        Split(
            "row",
            78.125,
            0,
            Split("column", 25.0, 1, Split("column", 33.33, 2, Split("column", 50.0, 3, 4))),
        ),
    )
