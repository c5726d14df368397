"""Layout thumbnails in the HTML report: one per configuration, capped, seen in Chromium."""

from __future__ import annotations

from pathlib import Path

from solver import load_team, solve
from solver.cli import main
from solver.layouts.foxglove import foxglove_layout
from solver.layouts.presentation import load_presentation
from solver.layouts.preview import COLOURS
from solver.layouts.tiling import MAX_TILES, tiles
from solver.reporting.report import MAX_THUMBNAILS, render_html
from tests.layouts.chromium import painted_colours


def _rgb(colour: str) -> tuple[int, int, int]:
    return (int(colour[1:3], 16), int(colour[3:5], 16), int(colour[5:7], 16))


def test_report_has_one_thumbnail_per_configuration_and_the_default() -> None:
    page = render_html(solve(load_team("case1")))
    section = page.split('<h2 id="layouts">', 1)[1]
    assert section.count('<figure class="layout"><svg') == 7
    assert "<figcaption>configuration 6 (config-006.json)</figcaption>" in section
    assert "default configuration (config-007-default.json)" in section
    assert "Showing 7 of 7." in section
    # Seven thumbnails are not folded away.
    assert "<details>" not in section


def test_report_thumbnails_are_capped_and_folded_for_many_configurations() -> None:
    page = render_html(solve(load_team("case3")))
    section = page.split('<h2 id="layouts">', 1)[1]
    assert section.count('<figure class="layout">') == MAX_THUMBNAILS == 60
    assert "Showing 60 of 103 (at most 60;" in section
    assert "<summary>show 60 layout thumbnails</summary>" in section


def test_report_thumbnails_screenshot_in_headless_chromium_is_not_blank(tmp_path: Path) -> None:
    report = tmp_path / "case1.html"
    assert main(["report", "case1", "-o", str(report)]) == 0
    # Only the thumbnails section: the charts above it have colours of their own.
    text = report.read_text()
    head, _, rest = text.partition('<h2 id="layouts">')
    body_start = head.index("<body>") + len("<body>")
    page = tmp_path / "thumbnails.html"
    page.write_text(head[:body_start] + '<h2 id="layouts">' + rest)
    painted = painted_colours(page, tmp_path, (1100, 900))
    # case1 is flight control over visual displays: Teleop and Image panels, painted.
    assert _rgb(COLOURS["Teleop"]) in painted
    assert _rgb(COLOURS["Image"]) in painted


def test_a_layout_of_100000_sensor_clusters_is_capped_at_max_tiles(tmp_path: Path) -> None:
    (tmp_path / "rules.yaml").write_text(
        "name: big\nteam_key: kind\ncharacteristics:\n"
        "  kind:\n    values: [K]\n  control:\n    values: [C]\n"
        "  sensor_type:\n    values: [S]\n"
        "  count:\n    range: {min: 1, max: 100000}\n    components:\n"
        "      - {name: one by one, min: 1, max: 100000, cluster_size: 1}\n"
    )
    (tmp_path / "team.yaml").write_text(
        "name: big team\nrules: rules.yaml\nteam:\n"
        "  K:\n    control: [C]\n    sensor_type: [S]\n    count: 100000\n"
    )
    solution = solve(load_team(tmp_path / "team.yaml"))
    (configuration,) = solution.configurations
    assert configuration.clusters(3)[1] == 100000  # what the rule set asks for
    assert tiles(solution.rules, configuration) == MAX_TILES
    layout = foxglove_layout(solution, configuration, load_presentation())
    # The control panel and a panel per sensor shown (those the secondary region has no room
    # for share one Tab panel: solver.layouts.design).
    panels = [key for key in layout["configById"] if not key.startswith("Tab!")]
    assert len(panels) == MAX_TILES + 1
    section = render_html(solution).split('id="layouts"', 1)[1]
    assert "not drawn" not in section
    assert section.count("<svg") == 2  # the configuration and the default one
