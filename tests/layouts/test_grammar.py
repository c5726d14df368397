"""The presentation grammar (solver.layouts.grammar): roles, their regions and the cuts between
them, read from a presentation file whose every problem is located (file, line, field)."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.cli import main
from solver.layouts.grammar import DEFAULT_GRAMMAR, Cut, Rect, prune
from solver.layouts.presentation import PresentationError, load_presentation

HEAD = "profile: presentation\ncomponents: {}\n"
# The shipped regions, written out: controls left, primary and secondary above status.
ROLES = """\
grammar:
  roles:
    primary: {region: {x: 20, y: 0, width: 62.5, height: 80}, components: [visual display]}
    secondary: {region: {x: 82.5, y: 0, width: 17.5, height: 80}}
    controls: {region: {x: 0, y: 0, width: 20, height: 100}, components: [Flight]}
    status: {region: {x: 20, y: 80, width: 80, height: 20}}
"""


def _faults(tmp_path: Path, text: str) -> list[tuple[int | None, str, str]]:
    path = tmp_path / "p.yaml"
    path.write_text(HEAD + text)
    with pytest.raises(PresentationError) as caught:
        load_presentation(path)
    return [(f.location.line, f.location.path, f.message) for f in caught.value.faults]


def test_the_shipped_grammar_docks_controls_left_and_gives_the_primary_view_half_the_screen() -> (
    None
):
    grammar = load_presentation().grammar
    assert grammar == DEFAULT_GRAMMAR
    assert grammar.region("controls") == Rect(0, 0, 20, 100)
    assert grammar.region("primary").area / 100 == 50.0  # percent of the screen
    assert grammar.candidates() == ("visual display", "spherical display", "point cloud")
    assert grammar.role_of("Waypoint") == "controls"
    assert grammar.order == "alphabetical"


def test_regions_are_cut_as_lichtblick_splits_them(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(HEAD + ROLES)
    assert load_presentation(path).grammar.cuts == Cut(
        "row",
        20.0,
        "controls",
        Cut("column", 80.0, Cut("row", 78.125, "primary", "secondary"), "status"),
    )


def test_a_presentation_without_a_grammar_takes_the_default(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(HEAD)
    assert load_presentation(path).grammar == DEFAULT_GRAMMAR


def test_an_unknown_role_is_a_located_error(tmp_path: Path) -> None:
    text = ROLES + "    sidebar: {region: {x: 0, y: 0, width: 1, height: 1}}\n"
    assert _faults(tmp_path, text) == [
        (
            9,
            "grammar.roles.sidebar",
            "unknown role 'sidebar'; allowed: controls, primary, secondary, status",
        )
    ]


def test_overlapping_regions_are_a_located_error(tmp_path: Path) -> None:
    text = ROLES.replace("{x: 82.5, y: 0, width: 17.5", "{x: 70, y: 0, width: 30")
    ((line, path, message),) = _faults(tmp_path, text)
    assert (line, path) == (6, "grammar.roles.secondary.region")
    assert message == "the secondary region overlaps the primary region"


def test_a_region_past_the_screen_edge_is_a_located_error(tmp_path: Path) -> None:
    text = ROLES.replace("{x: 82.5, y: 0, width: 17.5", "{x: 82.5, y: 0, width: 27.5")
    ((line, path, message),) = _faults(tmp_path, text)
    assert (line, path) == (6, "grammar.roles.secondary.region")
    assert message.startswith("the region does not fit on the screen: x + width = 110%")


def test_a_region_no_tile_of_the_smallest_size_fits_in_is_a_located_error(tmp_path: Path) -> None:
    # A control column 5% wide: 96 pixels of 1920, under the 320x180 of checks/quality.yaml;
    # every layout with a control would fail the quality check.
    text = (
        ROLES.replace("{x: 20, y: 0, width: 62.5", "{x: 5, y: 0, width: 77.5")
        .replace("{x: 0, y: 0, width: 20, height: 100}", "{x: 0, y: 0, width: 5, height: 100}")
        .replace("{x: 20, y: 80, width: 80", "{x: 5, y: 80, width: 95")
    )
    assert _faults(tmp_path, text) == [
        (
            7,
            "grammar.roles.controls.region",
            "the controls region is 96x1080 pixels at 1920x1080, smaller than the smallest "
            "tile, 320x180 (solver/layouts/checks/quality.yaml)",
        )
    ]
    # A screen that cannot be read is said once: the regions are measured at 1920x1080, where
    # the shipped ones fit, not at a made-up size where they would not.
    assert [path for _, path, _ in _faults(tmp_path, ROLES + "  screen: [1, 2]\n")] == [
        "grammar.screen",
        "grammar.screen.width",
        "grammar.screen.height",
    ]


def test_regions_that_leave_a_gap_are_a_located_error(tmp_path: Path) -> None:
    text = ROLES.replace("width: 17.5, height: 80", "width: 17.5, height: 70")
    ((line, path, message),) = _faults(tmp_path, text)
    assert (line, path) == (5, "grammar.roles")
    assert message == "the regions cover 98.25% of the screen; together they must fill it (100%)"


def test_regions_no_straight_cut_separates_are_a_located_error(tmp_path: Path) -> None:
    pinwheel = """\
grammar:
  roles:
    primary: {region: {x: 0, y: 0, width: 60, height: 40}}
    secondary: {region: {x: 60, y: 0, width: 40, height: 60}}
    controls: {region: {x: 0, y: 40, width: 40, height: 60}}
    status: {region: {x: 40, y: 60, width: 60, height: 40}}
"""
    # The centre square (40..60) is in no region: first the gap is reported.
    assert [m for _, _, m in _faults(tmp_path, pinwheel)] == [
        "the regions cover 96% of the screen; together they must fill it (100%)"
    ]


def test_a_component_given_two_roles_and_a_missing_role_are_located(tmp_path: Path) -> None:
    text = ROLES.replace("components: [Flight]", "components: [visual display]").replace(
        "    status: {region: {x: 20, y: 80, width: 80, height: 20}}\n", ""
    )
    assert _faults(tmp_path, text) == [
        (5, "grammar.roles.status", "missing role 'status'"),  # where the roles are
        (
            7,
            "grammar.roles.controls.components[0]",
            "component 'visual display' already has the role 'primary'",
        ),
    ]


def test_an_unknown_cluster_order_and_a_priority_order_without_priorities_are_located(
    tmp_path: Path,
) -> None:
    assert _faults(tmp_path, ROLES + "  clusters: {order: loudest}\n") == [
        (
            9,
            "grammar.clusters.order",
            "unknown cluster order 'loudest'; known: alphabetical, priority, data rate",
        )
    ]
    assert _faults(tmp_path, ROLES + "  clusters: {order: priority}\n") == [
        (
            9,
            "grammar.clusters.order",
            "the priority order needs a priority: list (topics or sensors, most used first)",
        )
    ]


def test_an_unused_region_gives_its_room_to_its_neighbour() -> None:
    assert prune(DEFAULT_GRAMMAR.cuts, {"primary", "controls"}) == Cut(
        "row", 20.0, "controls", "primary"
    )
    assert prune(DEFAULT_GRAMMAR.cuts, set()) is None


def test_a_bad_grammar_given_to_layouts_exits_2_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "p.yaml"
    bad.write_text(HEAD + ROLES.replace("primary: {", "main: {"))
    out = tmp_path / "out"
    assert main(["layouts", "case1", "-o", str(out), "--presentation", str(bad)]) == 2
    error = capsys.readouterr().err
    assert f"{bad}:5:" in error
    assert "unknown role 'main'" in error
    assert "Traceback" not in error
    assert not out.exists()


def test_hostile_grammar_values_are_located_faults_not_crashes(tmp_path: Path) -> None:
    text = (
        "grammar:\n"
        "  screen: {width: 99999999999, height: .nan}\n"
        "  roles:\n"
        "    primary: {region: {x: .nan, y: 0, width: .inf, height: 80}}\n"
        "    secondary: {region: [1, 2, 3, 4]}\n"
        "    controls: {region: {x: '0', y: 0, width: 20, height: 100}, components: {a: 1}}\n"
        "    status: {region: {x: 20, y: 80, width: 80, height: 20}, components: "
        + "["
        + ", ".join(f"c{n}" for n in range(20_000))
        + "]}\n"
        "  clusters: {order: [alphabetical]}\n"
    )
    found = _faults(tmp_path, text)
    assert [(line, path) for line, path, _ in found] == [
        (4, "grammar.screen.width"),
        (4, "grammar.screen.height"),
        (6, "grammar.roles.primary.region.x"),
        (7, "grammar.roles.secondary.region"),
        (8, "grammar.roles.controls.region.x"),
        (8, "grammar.roles.controls.components"),
        (10, "grammar.clusters.order"),
    ]
    assert [message for _, _, message in found][1:4] == [
        "screen height must be a whole number, got a number (nan)",
        "region x must be a percentage of the screen (0..100), got nan",
        "region must be a mapping, got a list",
    ]
