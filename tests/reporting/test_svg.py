"""The charts written straight as SVG show what matplotlib draws for ``report``: the same texts,
regions, runs, bars and cells, read back from the SVG by an XML parser and from matplotlib's
artists; names from the user's files stay text, whatever they hold."""

from __future__ import annotations

import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import pytest
from matplotlib.figure import Figure
from matplotlib.patches import PathPatch, Rectangle
from matplotlib.text import Text

from solver import Solution, load_team, solve
from solver.reporting.plot import bars_figure, matrix_figure, radar_figure
from solver.reporting.svg import CHART_KINDS, chart_svg
from tests.conftest import ROOT, TEAMS

SVG = "{http://www.w3.org/2000/svg}"
TEAM_NAMES = ("case1", "case3", "search-and-rescue", "figure8")


@pytest.fixture(scope="module", params=TEAM_NAMES)
def solution(request: pytest.FixtureRequest) -> Solution:
    return solve(load_team(TEAMS / f"{request.param}.yaml"))


def _tree(svg: bytes) -> ET.Element:
    assert svg.startswith(b"<?xml")
    return ET.fromstring(svg)


def _svg_texts(svg: bytes) -> Counter[str]:
    """Every text of the SVG, its lines joined by newlines (the title element left out)."""
    return Counter(
        "\n".join("".join(span.itertext()) for span in text.iter(f"{SVG}tspan"))
        for text in _tree(svg).iter(f"{SVG}text")
    )


def _figure_texts(figure: Figure) -> Counter[str]:
    """Every non-empty text matplotlib draws for ``figure``."""
    figure.canvas.draw()  # lays out tick labels
    return Counter(t.get_text() for t in figure.findobj(Text) if t.get_text() and t.get_visible())


@pytest.mark.parametrize(
    ("kind", "draw"), [("radar", radar_figure), ("bars", bars_figure), ("matrix", matrix_figure)]
)
def test_the_svg_shows_every_text_matplotlib_draws(
    solution: Solution, kind: str, draw: Callable[[Solution], Figure]
) -> None:
    assert _svg_texts(chart_svg(solution, kind)) == _figure_texts(draw(solution))


def test_the_svg_radar_has_a_region_and_every_run_of_each_type(solution: Solution) -> None:
    figure = radar_figure(solution)
    ax = figure.axes[0]
    regions = {str(p.get_label()): p for p in ax.patches if isinstance(p, PathPatch)}
    tree = _tree(chart_svg(solution, "radar"))
    shapes = [
        p for p in tree.iter(f"{SVG}path") if p.get("fill-opacity") and p.get("d", "").count("Z")
    ]
    assert [s.get("fill") for s in shapes] == [p.get_label() and _hex(p) for p in regions.values()]
    for shape, region in zip(shapes, regions.values(), strict=True):
        assert shape.get("d", "").count("Z") == len(
            region.get_path().to_polygons(closed_only=False)
        )
    layers = list(tree.iter(f"{SVG}g"))
    for layer, name in zip(layers, regions, strict=True):
        lines = [line for line in ax.lines if line.get_label() == f"run {name}"]
        dots = [line for line in lines if line.get_marker() == "o"]
        drawn_runs = sum(p.get("d", "").count("M") for p in layer.iter(f"{SVG}path"))
        assert drawn_runs == len(lines) - len(dots)
        assert len(list(layer.iter(f"{SVG}circle"))) == len(dots)


def _hex(patch: PathPatch) -> str:
    from matplotlib.colors import to_hex

    return to_hex(patch.get_facecolor(), keep_alpha=False).upper()


def test_the_svg_bars_are_as_tall_as_matplotlibs(solution: Solution) -> None:
    ax = bars_figure(solution).axes[0]
    drawn = [b for b in ax.patches if isinstance(b, Rectangle)]
    tree = _tree(chart_svg(solution, "bars"))
    # A bar is a rectangle drawn with an outline; hatching is a second one over it.
    bars = [r for r in tree.iter(f"{SVG}rect") if r.get("stroke") == "#333333"]
    legend = 2
    assert len(bars) == len(drawn) + legend
    heights = [float(r.get("height", 0)) for r in bars[: len(drawn)]]
    tallest = max(range(len(drawn)), key=lambda i: drawn[i].get_height())
    scale = heights[tallest] / drawn[tallest].get_height()
    # One scale for every bar: heights in proportion (SVG lengths are kept to 0.01 point).
    for height, bar in zip(heights, drawn, strict=True):
        assert height == pytest.approx(bar.get_height() * scale, abs=0.02)


def test_the_svg_matrix_shades_each_cell_as_the_chart_decides(solution: Solution) -> None:
    from solver.reporting.chart import matrix_chart

    chart = matrix_chart(solution)
    fills = [r.get("fill") for r in _tree(chart_svg(solution, "matrix")).iter(f"{SVG}rect")]
    cells = [fill for row in chart.fills for fill in row]
    assert fills[1 : 1 + len(cells)] == cells  # after the white page


# What would be markup, a script or an entity if written raw, and TeX-like names.
HOSTILE = (
    "<script>alert(1)</script>",
    "a&amp;b",
    "]]><x/>",
    "\"quoted\" 'single'",
    r"$\input{/etc/passwd}$",
    "two\nlines",
    "bidi\u202eoverride",
)


@pytest.fixture
def hostile_team(write_file: Callable[[str, str], Path]) -> Path:
    import yaml

    rules = {
        "name": HOSTILE[0],
        "characteristics": {
            "kind": {"label": HOSTILE[1], "values": list(HOSTILE[2:5])},
            "control": {"label": HOSTILE[5], "values": [HOSTILE[6], "plain"]},
        },
    }
    write_file("hostile.yaml", yaml.safe_dump(rules, sort_keys=False))
    team = {"name": HOSTILE[3], "rules": "hostile.yaml", "team": {v: {} for v in HOSTILE[2:5]}}
    return write_file("team.yaml", yaml.safe_dump(team, sort_keys=False))


@pytest.mark.parametrize("kind", CHART_KINDS)
def test_names_from_the_files_stay_text_in_every_svg_chart(kind: str, hostile_team: Path) -> None:
    solution = solve(load_team(hostile_team))
    svg = chart_svg(solution, kind)
    tree = _tree(svg)
    tags = {element.tag.removeprefix(SVG) for element in tree.iter()}
    assert tags <= {
        "svg",
        "title",
        "defs",
        "pattern",
        "rect",
        "path",
        "circle",
        "g",
        "text",
        "tspan",
    }
    texts = "\n".join(_svg_texts(svg))
    # The team's name and a type's in every chart; the rule set's and a label in the radar's.
    shown = [HOSTILE[2], HOSTILE[3]]
    if kind == "radar":
        shown += [HOSTILE[0], HOSTILE[1], r"$\input{/etc/passwd}$", "two\\nlines"]
    for name in shown:
        assert name in texts
    # Shown escaped, as every chart shows them: no forged line, no hidden override.
    assert "two\nlines" not in texts
    assert "\u202e" not in svg.decode()


def test_svg_charts_are_byte_identical_from_run_to_run(tmp_path: Path) -> None:
    script = (
        "import sys\nfrom solver import load_team, solve\n"
        "from solver.reporting.svg import chart_svg\n"
        "s = solve(load_team('search-and-rescue'))\n"
        "sys.stdout.buffer.write(b''.join(chart_svg(s, k) for k in ('radar', 'bars', 'matrix')))\n"
    )
    runs = [
        subprocess.run(
            [sys.executable, "-c", script],
            cwd=ROOT,
            check=True,
            capture_output=True,
            env={**os.environ, "PYTHONHASHSEED": seed},
        ).stdout
        for seed in ("0", "1")
    ]
    assert runs[0] == runs[1]
    assert runs[0].count(b"<svg") == 3


def test_an_unknown_chart_kind_is_refused(solution: Solution) -> None:
    with pytest.raises(ValueError, match="kind must be in"):
        chart_svg(solution, "pie")


def test_the_panel_radar_has_larger_texts_and_names_every_selected_value_for_the_keyboard() -> None:
    from solver.reporting.chart import TICK_FONT
    from solver.reporting.svg import PANEL_TEXT, panel_radar_svg

    team = load_team(TEAMS / "case3.yaml")
    tree = _tree(panel_radar_svg(solve(team)))
    sizes = [float(t.get("font-size") or 0) for t in tree.iter(f"{SVG}text")]
    assert min(sizes) == TICK_FONT * PANEL_TEXT
    stops = [g.get("aria-label") or "" for g in tree.iter(f"{SVG}g") if g.get("tabindex") == "0"]
    # Per type, one stop per spoke and one for its legend entry.
    assert len(stops) == len(team.selections) * (len(team.rules.characteristics) + 1)
    for selection in team.selections:
        for characteristic, domain in zip(
            team.rules.characteristics, selection.domains, strict=True
        ):
            if characteristic.kind == "integer":
                continue
            (stop,) = [
                s
                for s in stops
                if s.startswith(f"{selection.kinematic_type}: {characteristic.label}:")
            ]
            # Every value the type selects is in its stop's text, labelled on the spoke or not.
            assert all(str(value) in stop for value in domain)
    # The chart of `report` is unchanged: no stops.
    assert b"tabindex" not in chart_svg(solve(team), "radar")


def test_names_from_the_files_stay_text_in_the_panel_radar_and_its_keyboard_names(
    hostile_team: Path,
) -> None:
    from solver.reporting.svg import panel_radar_svg

    svg = panel_radar_svg(solve(load_team(hostile_team)))
    tree = _tree(svg)
    assert {element.tag.removeprefix(SVG) for element in tree.iter()} <= {
        "svg",
        "title",
        "rect",
        "path",
        "circle",
        "g",
        "text",
        "tspan",
    }
    labels = [g.get("aria-label") or "" for g in tree.iter(f"{SVG}g") if g.get("tabindex")]
    # A type's name read back as the attribute's text, never as markup.
    assert any(label.startswith(f"{HOSTILE[2]}: ") for label in labels)
    assert not any("\n" in label or "\u202e" in label for label in labels)
    assert "\u202e" not in svg.decode()
