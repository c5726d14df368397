"""The layout preview, looked at the way a person does: rendered by headless Chromium."""

from __future__ import annotations

from pathlib import Path

from solver import load_team, solve
from solver.layouts import foxglove_layout, load_presentation
from solver.layouts.preview import preview_html, preview_svg
from tests.layouts.chromium import painted_colours


def test_preview_draws_one_labelled_rectangle_per_panel() -> None:
    solution = solve(load_team("case1"))
    layout = foxglove_layout(solution, solution.configurations[0], load_presentation())
    svg = preview_svg(layout)
    assert svg.count("<rect") == len(layout["configById"])
    assert "Teleop: Flight" in svg


def test_preview_page_screenshot_in_headless_chromium_is_not_blank(tmp_path: Path) -> None:
    solution = solve(load_team("case1"))
    profile = load_presentation()
    page = tmp_path / "preview.html"
    page.write_text(
        preview_html(
            [
                (f"configuration {c.number}", foxglove_layout(solution, c, profile))
                for c in solution.configurations
            ]
        )
    )
    painted = painted_colours(page, tmp_path, (1100, 700))
    # A blank page is one colour; the thumbnails paint several panel colours over white.
    assert len(painted) >= 3
    assert (85, 168, 104) in painted  # the Image panels' green
