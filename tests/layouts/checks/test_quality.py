"""Layout quality (solver.layouts.checks.quality): figures measured on a written layout's split
tree at 1920x1080, the limits of quality.yaml, and a team's consistency."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from solver import load_team, solve
from solver.layouts.checks.data import quality_rules
from solver.layouts.checks.quality import (
    Consistency,
    consistency,
    describe_consistency,
    measure,
    quality_faults,
    team_consistency,
)
from solver.layouts.foxglove import foxglove_layout
from solver.layouts.presentation import load_presentation
from tests.conftest import ROOT

REGIONS = {"primary": [20, 0, 62.5, 80], "secondary": [82.5, 0, 17.5, 80],
           "controls": [0, 0, 20, 100], "status": [20, 80, 80, 20]}  # fmt: skip


def _layout(tree: Any, tiles: list[tuple[str, str, str]]) -> dict[str, Any]:
    note = {
        "regions": REGIONS,
        "tiles": [{"component": c, "role": r, "panel": p} for c, r, p in tiles],
    }
    return {"configById": {}, "globalVariables": {"teleop_ui_design": note}, "layout": tree}


def test_the_limits_are_the_documented_figures() -> None:
    rules = quality_rules()
    assert rules["screen"] == {"width": 1920, "height": 1080}
    assert rules["primary_share"] == 50
    assert rules["smallest_tile"] == {"width": 320, "height": 180}
    assert rules["panels_per_screen"] == 12
    assert rules["consistency"] == 100


def test_a_good_layout_is_measured_and_passes() -> None:
    tree = {"direction": "row", "first": "T!c", "second": "I!p", "splitPercentage": 20}
    found = measure(_layout(tree, [("camera", "primary", "I!p"), ("Flight", "controls", "T!c")]))
    assert (found.primary_share, found.smallest_width, found.smallest_height) == (
        80.0,
        384.0,
        1080.0,
    )
    assert found.tiles == 2
    assert dict(found.places) == {"camera": "primary", "Flight": "controls"}
    assert quality_faults(found) == ()


def test_a_small_primary_view_tiny_tiles_and_too_many_tiles_are_faults() -> None:
    # Thirteen tiles side by side, each 1920/13 = 147.7 pixels wide; the primary one of them.
    ids = [f"I!p{n:02d}" for n in range(13)]
    tree: Any = ids[-1]
    for n, panel in reversed(list(enumerate(ids[:-1]))):
        tree = {
            "direction": "row",
            "first": panel,
            "second": tree,
            "splitPercentage": 100 / (13 - n),
        }
    found = measure(_layout(tree, [("camera", "primary", ids[0])]))
    assert found.tiles == 13
    messages = [fault.message for fault in quality_faults(found, "x.json")]
    assert messages == [
        "the primary view takes 7.69% of the screen, less than 50%",
        "a tile is 147.7x1080 pixels at 1920x1080, smaller than 320x180",
        "13 tiles on one screen, more than 12",
    ]


def test_a_layout_without_a_design_note_has_no_primary_view_and_no_places() -> None:
    found = measure({"configById": {}, "globalVariables": {}, "layout": "I!p"})
    assert (found.primary_share, found.places, found.tiles) == (0.0, (), 1)


def test_consistency_counts_pairs_of_configurations_sharing_a_component() -> None:
    # a: 3 configurations, always primary: 3 pairs, 3 the same; b: 2 configurations in two
    # regions: 1 pair, moved. 3 of 4 pairs: 75%.
    found = consistency(
        [{"a": "primary", "b": "secondary"}, {"a": "primary", "b": "status"}, {"a": "primary"}]
    )
    assert found == Consistency(3, 4, ("b",))
    assert found.score == 75.0
    assert describe_consistency(found) == (
        "consistency: 75.0% (3 of 4 pairs of configurations sharing a component put it in the "
        "same region); moved: b"
    )
    assert consistency([]).score == 100.0  # nothing shared, nothing moved


def test_a_shipped_team_is_consistent_as_the_shipped_grammar_lays_it_out() -> None:
    found = team_consistency(solve(load_team("case3")), load_presentation())
    assert (found.score, found.moved) == (100.0, ())
    assert found.pairs > 1000


def test_the_default_configuration_is_counted_in_a_teams_consistency() -> None:
    # case1: six configurations, (Flight or Waypoint) x (visual display, spherical display or
    # point cloud); the default shows every component. Counted by hand: Flight and Waypoint in
    # 3 + 1 layouts each (6 pairs each), each sensor in 2 + 1 (3 pairs each): 6 + 6 + 3 * 3 =
    # 21 pairs (9 without the default), every one in the same region.
    found = team_consistency(solve(load_team("case1")), load_presentation())
    assert found == Consistency(21, 21, ())


def test_a_hand_written_layout_of_any_shape_is_measured_without_a_crash() -> None:
    # What a stranger's layout may hold where a split, a percentage or a design note belongs:
    # a list as a leaf, a string, NaN, a number past a float, a list of variables, tiles of
    # strings, regions of NaN and of 10**400. A split without a usable percentage is halved
    # (react-mosaic's 50); a leaf that is no panel id is no tile.
    split = {"direction": "row", "first": "A!a", "second": "B!b"}
    for bad in ("abc", float("nan"), 10**400, float("inf"), -5, True):
        found = measure({"layout": {**split, "splitPercentage": bad}})
        assert (found.smallest_width, found.tiles) == (960.0, 2)
    found = measure({"layout": {**split, "first": ["x"]}, "globalVariables": []})
    assert (found.smallest_width, found.tiles, found.places) == (960.0, 1, ())
    note = {"tiles": ["x", {"panel": ["A!a"], "role": "primary"}], "regions": {"p": ["a"] * 4}}
    found = measure({"layout": "A!a", "globalVariables": {"teleop_ui_design": note}})
    assert (found.primary_share, found.tiles, found.places) == (0.0, 1, ())
    regions = {"primary": [float("nan"), 0, 10**400, 100]}
    note = {"tiles": [{"panel": "A!a", "role": "primary", "component": "c"}], "regions": regions}
    found = measure({"layout": "A!a", "globalVariables": {"teleop_ui_design": note}})
    assert (found.primary_share, found.places) == (100.0, ())  # no usable region: no place


def test_a_tile_in_a_region_grown_into_an_empty_one_is_placed_in_its_own_region() -> None:
    # A robot without autonomy levels: the status strip (y 80..100%) is empty and the right
    # column takes the whole height. Its last tile, at y 810..1080 of 1080, lies mostly where
    # the status strip would be, and is still in the secondary column (as the note's regions,
    # laid out, say), not "status".
    column = {"direction": "column", "first": "A!a", "second": "B!b", "splitPercentage": 75}
    tiles = [
        {"component": "primary view", "role": "primary", "panel": "P!p"},
        {"component": "a", "role": "secondary", "panel": "A!a"},
        {"component": "b", "role": "secondary", "panel": "B!b"},
    ]
    note = {
        "regions": {"primary": [0, 0, 82.5, 100], "secondary": [82.5, 0, 17.5, 100]},
        "tiles": tiles,
    }
    layout = {
        "layout": {"direction": "row", "first": "P!p", "second": column, "splitPercentage": 82.5},
        "globalVariables": {"teleop_ui_design": note},
    }
    places = dict(measure(layout).places)
    assert places == {"primary view": "primary", "a": "secondary", "b": "secondary"}


def test_a_region_a_configuration_leaves_empty_gives_its_room_to_its_neighbour() -> None:
    # case1 has no autonomy level (no status strip) and its default configuration puts every
    # sensor in the primary region (no secondary views): the primary view takes their room.
    solution = solve(load_team("case1"))
    layout = foxglove_layout(solution, None, load_presentation())
    assert layout["globalVariables"]["teleop_ui_design"]["regions"] == {
        "controls": [0, 0, 20, 100],
        "primary": [20, 0, 80, 100],
    }


def test_a_sensor_the_grammar_puts_elsewhere_moves_and_the_score_names_it(tmp_path: Path) -> None:
    # The designer's grammar puts audio in the secondary column; a configuration whose only
    # sensor is audio still has it as its primary view: audio moves, and is named.
    path = tmp_path / "p.yaml"
    shipped = (ROOT / "rules" / "presentation.yaml").read_text()
    path.write_text(
        shipped.replace(
            "      region: {x: 82.5, y: 0, width: 17.5, height: 80}\n",
            "      region: {x: 82.5, y: 0, width: 17.5, height: 80}\n      components: [audio]\n",
        )
    )
    solution = solve(load_team("case2"))
    found = team_consistency(solution, load_presentation(path, solution.rules))
    assert found.moved == ("audio",)
    assert found.score < 100
