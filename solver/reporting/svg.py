"""The charts of a solved team written straight as SVG, for pages that redraw them as you click.

:func:`chart_svg` writes the chart :mod:`solver.reporting.chart` decides (the radar chart, the
bars, the component matrix) as an SVG document: the same strokes, regions, bars, cells and
texts in the same places, sizes and colours as matplotlib draws them for ``report``
(:mod:`solver.reporting.plot`), without matplotlib: no layout search, no glyph outlines, so a
chart takes milliseconds instead of a third of a second. Texts are SVG text in DejaVu Sans (the
font matplotlib draws with) or the viewer's sans-serif, so where a viewer lacks it a label may
be a little wider or narrower than in the PNG; a value label's white ground is a halo around
its letters rather than a box.

Every text is written as XML text (markup escaped; names from the user's files were escaped
for display by the chart already, :func:`~solver.untrusted.shown`), never as markup, so a
name cannot add an element, an attribute or a script. The same chart gives the same bytes.

Not here: what the charts show (:mod:`solver.reporting.chart`), matplotlib's drawing and
image files (:mod:`solver.reporting.plot`).
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from solver.reporting.chart import (
    GREY,
    REGION_ALPHA,
    BarsChart,
    Label,
    Layer,
    MatrixChart,
    RadarChart,
    Stroke,
    bars_chart,
    matrix_chart,
    radar_chart,
    text_width,
)

if TYPE_CHECKING:
    from solver.solving.solution import Solution

__all__ = [
    "CHART_KINDS",
    "ChartKind",
    "bars_svg",
    "chart_svg",
    "matrix_svg",
    "panel_radar_svg",
    "radar_svg",
]

ChartKind = Literal["radar", "bars", "matrix"]
CHART_KINDS: tuple[ChartKind, ...] = ("radar", "bars", "matrix")
FONT = "DejaVu Sans, Bitstream Vera Sans, Verdana, sans-serif"
# Where a text's first baseline sits below its top (em), and its last above its bottom:
# DejaVu Sans's ascent and descent as matplotlib lays text out; lines 1.2 em apart.
ASCENT = 0.76
DESCENT = 0.24
LINE = 1.2
# Ticks: length and gap to their labels (points), as matplotlib's defaults.
TICK = 3.5
PAD = 3.5


def _number(value: float) -> str:
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _xml(text: str) -> str:
    return html.escape(text, quote=True)


@dataclass(frozen=True)
class _Frame:
    """Data coordinates of a chart's plot -> SVG points (y down) of the whole figure."""

    width: float  # the figure, points
    height: float
    plot: tuple[float, float, float, float]  # fractions of the figure: left, bottom, width, height
    xlim: tuple[float, float]
    ylim: tuple[float, float]  # bottom, top of the plot (may run downwards)

    @property
    def left(self) -> float:
        return self.plot[0] * self.width

    @property
    def right(self) -> float:
        return (self.plot[0] + self.plot[2]) * self.width

    @property
    def top(self) -> float:
        return (1 - self.plot[1] - self.plot[3]) * self.height

    @property
    def bottom(self) -> float:
        return (1 - self.plot[1]) * self.height

    def x(self, value: float) -> float:
        low, high = self.xlim
        return self.left + (value - low) / (high - low) * (self.right - self.left)

    def y(self, value: float) -> float:
        low, high = self.ylim
        return self.bottom - (value - low) / (high - low) * (self.bottom - self.top)

    def point(self, point: tuple[float, float]) -> tuple[float, float]:
        return self.x(point[0]), self.y(point[1])


class _Canvas:
    """SVG elements of one figure, drawn in matplotlib's order: by z-order, then as added."""

    def __init__(self, width_inches: float, height_inches: float, title: str) -> None:
        self.width = width_inches * 72
        self.height = height_inches * 72
        self.title = title
        self.defs: list[str] = []
        self._parts: list[tuple[float, int, str]] = []

    def add(self, zorder: float, markup: str) -> None:
        self._parts.append((zorder, len(self._parts), markup))

    def frame(
        self,
        plot: tuple[float, float, float, float],
        xlim: tuple[float, float],
        ylim: tuple[float, float],
    ) -> _Frame:
        return _Frame(self.width, self.height, plot, xlim, ylim)

    def line(self, zorder: float, points: list[tuple[float, float]], style: str) -> None:
        self.add(zorder, f'<path d="{_segments(points)}" fill="none" {style}/>')

    def text(self, zorder: float, x: float, y: float, label: Label) -> None:
        """``label`` anchored at ``(x, y)`` points, aligned as matplotlib aligns it."""
        lines = label.text.split("\n")
        block = (len(lines) - 1) * LINE + ASCENT + DESCENT
        first = {
            "top": ASCENT,
            "center": ASCENT - block / 2,
            "bottom": ASCENT - block,
        }[label.va]
        anchor = {"left": "start", "center": "middle", "right": "end"}[label.ha]
        attributes = f'font-size="{_number(label.size)}" text-anchor="{anchor}"'
        if label.bold:
            attributes += ' font-weight="bold"'
        if label.colour != "#000000":
            attributes += f' fill="{label.colour}"'
        if label.boxed:
            attributes += (
                ' stroke="#ffffff" stroke-opacity="0.8" stroke-width="2.4"'
                ' stroke-linejoin="round" paint-order="stroke"'
            )
        where = ""
        if label.rotation:
            turn = f"translate({_number(x)} {_number(y)}) rotate({_number(-label.rotation)})"
            where = f'transform="{turn}"'
            x = y = 0.0
        spans = "".join(
            f'<tspan x="{_number(x)}" dy="{_number(first if i == 0 else LINE)}em">'
            f"{_xml(line)}</tspan>"
            for i, line in enumerate(lines)
        )
        # Spaces as written ("rules: X    bound T"): SVG would fold them into one.
        self.add(
            zorder,
            f'<text {where} y="{_number(y)}" {attributes} xml:space="preserve">{spans}</text>',
        )

    def svg(self) -> bytes:
        body = "\n".join(markup for _, _, markup in sorted(self._parts))
        defs = f"<defs>{''.join(self.defs)}</defs>\n" if self.defs else ""
        return (
            '<?xml version="1.0" encoding="utf-8" standalone="no"?>\n'
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{_number(self.width)}pt" '
            f'height="{_number(self.height)}pt" viewBox="0 0 {_number(self.width)} '
            f'{_number(self.height)}" font-family="{FONT}">\n'
            f"<title>{_xml(self.title)}</title>\n{defs}"
            f'<rect width="100%" height="100%" fill="#ffffff"/>\n{body}\n</svg>\n'
        ).encode()


def _segments(points: list[tuple[float, float]]) -> str:
    """``M x0 y0 L x1 y1`` for each pair of points: separate strokes in one path."""
    return " ".join(
        f"M{_number(a[0])} {_number(a[1])}L{_number(b[0])} {_number(b[1])}"
        for a, b in zip(points[::2], points[1::2], strict=True)
    )


def _legend_handle(x: float, y: float, colour: str) -> str:
    """A legend's mark, 2 em by 0.7 em of a 10-point text: the region's shade, the run's stroke."""
    return (
        f'<rect x="{_number(x)}" y="{_number(y - 3.5)}" width="20" height="7" fill="{colour}" '
        f'fill-opacity="0.3"/><path d="M{_number(x)} {_number(y)}h20" stroke="{colour}" '
        'stroke-width="4"/>'
    )


def draw_radar(chart: RadarChart, *, focusable: bool = False) -> bytes:
    """``chart`` as SVG (see :func:`radar_svg`); ``focusable``: each type's values on each
    spoke, and each legend entry, a group the keyboard reaches that says its text."""
    canvas = _Canvas(chart.width, chart.height, chart.title)
    frame = canvas.frame(chart.plot, chart.xlim, chart.ylim)
    for spoke in chart.spokes:
        centre = frame.point((0.0, 0.0))
        canvas.line(1, [centre, frame.point(spoke.end)], f'stroke="{GREY}" stroke-width="0.8"')
        if spoke.ticks:
            canvas.line(
                1,
                [frame.point(p) for tick in spoke.ticks for p in tick],
                f'stroke="{GREY}" stroke-width="0.7" stroke-linecap="square"',
            )
        for label in (*spoke.labels, spoke.title):
            canvas.text(5, *frame.point((label.x, label.y)), label)
    for layer in chart.layers:
        _draw_layer(canvas, frame, layer, focusable=focusable)
    _draw_legend(canvas, chart, focusable=focusable)
    if chart.titled:
        canvas.text(6, canvas.width / 2, 0.3 * 72, Label(0, 0, chart.title, 13, bold=True))
        subtitle = Label(0, 0, chart.subtitle, 9, colour="#444444")
        canvas.text(6, canvas.width / 2, 0.6 * 72, subtitle)
    return canvas.svg()


def _draw_layer(canvas: _Canvas, frame: _Frame, layer: Layer, *, focusable: bool) -> None:
    """A type's region and its runs: one element per layer, every run of the type a sub-path,
    every lone value a dot; ``focusable`` groups them by spoke, each group a stop of the
    keyboard saying its values."""
    if layer.quads:
        shape = " ".join(
            "M" + "L".join(f"{_number(x)} {_number(y)}" for x, y in map(frame.point, quad)) + "Z"
            for quad in layer.quads
        )
        canvas.add(2, f'<path d="{shape}" fill="{layer.colour}" fill-opacity="{REGION_ALPHA}"/>')
    groups = [(layer.strokes, "")]
    if focusable:
        groups = [
            (tuple(s for s in layer.strokes if s.spoke == k), note)
            for k, note in enumerate(layer.notes)
        ]
    markup = f'<g class="layer" fill="{layer.colour}" stroke="{layer.colour}">'
    markup += "".join(
        _strokes(frame, strokes, layer.width, note) for strokes, note in groups if strokes
    )
    canvas.add(3 + layer.order, markup + "</g>")


def _draw_legend(canvas: _Canvas, chart: RadarChart, *, focusable: bool) -> None:
    """One row per type, the last row lowest, the block centred under the chart;
    ``focusable``: each row a stop of the keyboard saying the type's counts."""
    size = 10 * chart.text
    widest = max((text_width(layer.legend, size) for layer in chart.layers), default=0.0)
    left = (canvas.width - (20 + 8 + widest)) / 2
    pitch = size * 1.16 + 5
    lowest = canvas.height - chart.legend_bottom * 72 - 9 - size * 1.16 / 2
    for row, layer in enumerate(chart.layers):
        y = lowest - (len(chart.layers) - 1 - row) * pitch
        if focusable:
            canvas.add(6, f"<g {_stop(layer.summary)}>")
        canvas.add(6, _legend_handle(left, y, layer.colour))
        canvas.text(6, left + 28, y, Label(0, 0, layer.legend, size, ha="left"))
        if focusable:
            canvas.add(6, "</g>")


def _stop(note: str) -> str:
    """The attributes of a group a keyboard reaches, saying ``note`` (hover: its title)."""
    return f'class="value" tabindex="0" role="img" aria-label="{_xml(note)}"'


def _strokes(frame: _Frame, strokes: tuple[Stroke, ...], width: float, note: str) -> str:
    """A type's runs (one path) and lone values (dots); with a ``note``, as a group saying it."""
    runs = [frame.point(p) for s in strokes if not s.dot for p in (s.start, s.end)]
    dots = [frame.point(s.start) for s in strokes if s.dot]
    markup = ""
    if runs:
        markup += (
            f'<path d="{_segments(runs)}" fill="none" stroke-width="{_number(width)}" '
            'stroke-linecap="round"/>'
        )
    markup += "".join(
        f'<circle cx="{_number(x)}" cy="{_number(y)}" r="{_number(width / 2)}" stroke="none"/>'
        for x, y in dots
    )
    if note:
        return f"<g {_stop(note)}><title>{_xml(note)}</title>{markup}</g>"
    return markup


def _hatch(canvas: _Canvas) -> str:
    """The pattern of matplotlib's ``//`` hatch: thin diagonal lines, 1/9 inch apart."""
    canvas.defs.append(
        '<pattern id="hatch" patternUnits="userSpaceOnUse" width="8" height="8">'
        '<path d="M-1 1L1 -1M0 8L8 0M7 9L9 7" stroke="#333333" stroke-width="0.8"/></pattern>'
    )
    return "url(#hatch)"


def draw_bars(chart: BarsChart) -> bytes:
    """``chart`` as SVG (see :func:`bars_svg`)."""
    canvas = _Canvas(chart.width, chart.height, chart.title)
    frame = canvas.frame(chart.plot, chart.xlim, (0.0, chart.ytop))
    hatch = _hatch(canvas)
    for series in chart.series:
        for position, value in enumerate(series.values):
            x0 = frame.x(position + series.offset - chart.bar_width / 2)
            x1 = frame.x(position + series.offset + chart.bar_width / 2)
            top, base = frame.y(value), frame.y(0)
            shape = (
                f'x="{_number(x0)}" y="{_number(top)}" width="{_number(x1 - x0)}" '
                f'height="{_number(base - top)}"'
            )
            markup = f'<rect {shape} fill="{series.colour}" stroke="#333333" stroke-width="0.6"/>'
            if series.hatch:
                markup += f'<rect {shape} fill="{hatch}" stroke="none"/>'
            canvas.add(1, markup)
            canvas.text(3, (x0 + x1) / 2, top - 2, Label(0, 0, str(value), 9, va="bottom"))
    axis = 'stroke="#000000" stroke-width="0.8"'
    canvas.line(2.5, [(frame.left, frame.bottom), (frame.right, frame.bottom)], axis)
    canvas.line(2.5, [(frame.left, frame.bottom), (frame.left, frame.top)], axis)
    for position, category in enumerate(chart.categories):
        x = frame.x(position)
        canvas.line(2.5, [(x, frame.bottom), (x, frame.bottom + TICK)], axis)
        canvas.text(3, x, frame.bottom + TICK + PAD, Label(0, 0, category, 9, va="top"))
    widest = 0.0
    for tick in chart.yticks:
        y = frame.y(tick)
        canvas.line(2.5, [(frame.left - TICK, y), (frame.left, y)], axis)
        canvas.text(3, frame.left - TICK - PAD, y, Label(0, 0, str(tick), 10, ha="right"))
        widest = max(widest, text_width(str(tick), 10))
    canvas.text(
        3,
        frame.left - TICK - PAD - widest - 4,
        (frame.top + frame.bottom) / 2,
        Label(0, 0, chart.ylabel, 10, va="bottom", rotation=90),
    )
    # The legend: one row between the title and the plot, centred over it.
    entries = [(s, text_width(s.name, 9)) for s in chart.series]
    total = sum(18 + 7.2 + width for _, width in entries) + 18 * (len(entries) - 1)
    x = (frame.left + frame.right - total) / 2
    y = frame.top - 1.8 - 3.6 - 9 * 1.16 / 2
    for series, width in entries:
        shape = f'x="{_number(x)}" y="{_number(y - 3.15)}" width="18" height="6.3"'
        markup = f'<rect {shape} fill="{series.colour}" stroke="#333333" stroke-width="0.6"/>'
        if series.hatch:
            markup += f'<rect {shape} fill="{hatch}" stroke="none"/>'
        canvas.add(4, markup)
        canvas.text(4, x + 25.2, y, Label(0, 0, series.name, 9, ha="left"))
        x += 18 + 7.2 + width + 18
    canvas.text(
        4, (frame.left + frame.right) / 2, frame.top - 22, Label(0, 0, chart.title, 11, va="bottom")
    )
    return canvas.svg()


def draw_matrix(chart: MatrixChart) -> bytes:
    """``chart`` as SVG (see :func:`matrix_svg`)."""
    canvas = _Canvas(chart.width, chart.height, chart.title.split("\n")[0])
    rows, columns = max(len(chart.rows), 1), max(len(chart.columns), 1)
    frame = canvas.frame(chart.plot, (-0.5, columns - 0.5), (rows - 0.5, -0.5))
    cell_width = frame.x(0.5) - frame.x(-0.5)
    cell_height = frame.y(0.5) - frame.y(-0.5)
    cells = []
    for r, row in enumerate(chart.fills):
        for k, fill in enumerate(row):
            cells.append(
                f'<rect x="{_number(frame.x(k - 0.5))}" y="{_number(frame.y(r - 0.5))}" '
                f'width="{_number(cell_width + 0.05)}" height="{_number(cell_height + 0.05)}" '
                f'fill="{fill}"/>'
            )
    if not cells:
        cells.append(
            f'<rect x="{_number(frame.left)}" y="{_number(frame.top)}" '
            f'width="{_number(frame.right - frame.left)}" '
            f'height="{_number(frame.bottom - frame.top)}" fill="#ffffff"/>'
        )
    canvas.add(0, "".join(cells))
    for label in (*chart.cells, *chart.groups):
        canvas.text(3, frame.x(label.x), frame.y(label.y), label)
    for edge in chart.edges:
        x = frame.x(edge)
        canvas.line(2, [(x, frame.top), (x, frame.bottom)], 'stroke="#333333" stroke-width="1"')
    canvas.add(
        2.5,
        f'<rect x="{_number(frame.left)}" y="{_number(frame.top)}" '
        f'width="{_number(frame.right - frame.left)}" height="{_number(frame.bottom - frame.top)}" '
        'fill="none" stroke="#000000" stroke-width="0.8"/>',
    )
    for r, name in enumerate(chart.rows):
        canvas.text(3, frame.left - PAD, frame.y(r), Label(0, 0, name, 9, ha="right"))
    for k, name in enumerate(chart.columns):
        canvas.text(
            3, frame.x(k), frame.bottom + PAD, Label(0, 0, name, 8, ha="right", rotation=60)
        )
    canvas.text(
        4, (frame.left + frame.right) / 2, frame.top - 22, Label(0, 0, chart.title, 9, va="bottom")
    )
    return canvas.svg()


def radar_svg(solution: Solution) -> bytes:
    """The team's radar chart (the article's Figure 9) as SVG."""
    return draw_radar(radar_chart(solution))


# A page's radar chart beside its totals: texts this many times ``report``'s, so that at the
# 480 points a page gives it its smallest labels (7.5 points in ``report``) are 12 pixels.
PANEL_TEXT = 1.9


def panel_radar_svg(solution: Solution) -> bytes:
    """The radar chart for a page that shows it small beside the team's totals: larger texts,
    no title (the page has the totals; the SVG's ``<title>`` still says them), the legend by
    type, and each type's values per spoke and each legend entry a group the keyboard reaches
    (``tabindex``, ``aria-label``; ``<title>`` on hover) that says its text."""
    return draw_radar(radar_chart(solution, text=PANEL_TEXT, titled=False), focusable=True)


def bars_svg(solution: Solution) -> bytes:
    """Valid robots beside UI configurations, one pair of bars per kinematic type, as SVG."""
    return draw_bars(bars_chart(solution))


def matrix_svg(solution: Solution) -> bytes:
    """The component matrix as SVG (``solution`` must list its configurations)."""
    return draw_matrix(matrix_chart(solution))


_DRAW: dict[str, Callable[[Solution], bytes]] = {
    "radar": radar_svg,
    "bars": bars_svg,
    "matrix": matrix_svg,
}


def chart_svg(solution: Solution, kind: str) -> bytes:
    """The chart ``kind`` (one of :data:`CHART_KINDS`) of ``solution`` as SVG."""
    if kind not in _DRAW:
        raise ValueError(f"kind must be in {CHART_KINDS} (got {kind!r})")
    return _DRAW[kind](solution)
