"""The charts of a solved team drawn by matplotlib: ``solve --plot``, ``report``, ``batch``.

:func:`radar_figure` (the article's Figure 9), :func:`bars_figure` and :func:`matrix_figure`
draw the charts :mod:`solver.reporting.chart` decides (every stroke, region, bar, cell and
text, and where), as matplotlib figures; :mod:`solver.reporting.svg` writes the same charts as
SVG without matplotlib, for the studio. The artists keep the names tests and tools find them
by: each kinematic type's region is a :class:`~matplotlib.patches.PathPatch` labelled with the
type, each run of selected values a line labelled ``"run <type>"``, value labels ``"tick
<characteristic>"``, spoke titles ``"axis <characteristic>"``.

Every text on a chart that comes from the user's files (names of the team, rule set, kinematic
types, characteristics, values, components) is drawn as written: matplotlib's mathtext never
parses it (``$\\sqrt{x}$``, ``\\input{...}`` stay text, and cannot make drawing fail) and TeX
never runs, whatever a ``matplotlibrc`` says (:func:`literal_text`); a control or invisible
character in it is shown as its escape (:func:`~solver.untrusted.shown`).

Figures are built on matplotlib's Agg canvas without pyplot (no global figure registry, safe in
worker processes) and written by :func:`write_plot` as PNG, SVG or PDF by file extension,
atomically and byte-identical from run to run (fixed SVG hash salt, no dates in metadata).
matplotlib is imported inside the functions that draw, so importing this module is cheap.

Not here: what the charts show (:mod:`solver.reporting.chart`), the pages that embed them
(:mod:`solver.reporting.report`), solving (:mod:`solver.solving.solution`).
"""

from __future__ import annotations

import io
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from solver.errors import InputError
from solver.extras import require
from solver.files.atomic import write_atomic
from solver.reporting.chart import (
    GREY,
    REGION_ALPHA,
    BarsChart,
    Label,
    Layer,
    MatrixChart,
    RadarChart,
    bars_chart,
    check_chart_size,
    matrix_chart,
    radar_chart,
)
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from solver.solving.solution import Solution

__all__ = [
    "PLOT_FORMATS",
    "PLOT_KINDS",
    "bars_figure",
    "check_chart_size",
    "figure_bytes",
    "literal_text",
    "matrix_figure",
    "plot_format",
    "radar_figure",
    "write_plot",
]

PlotKind = Literal["radar", "bars", "matrix"]
PLOT_FORMATS = ("png", "svg", "pdf")
PLOT_KINDS: tuple[PlotKind, ...] = ("radar", "bars", "matrix")
PNG_DPI = 150


def plot_format(path: str | Path) -> str:
    """The image format a file name asks for (``png``, ``svg``, ``pdf``); else InputError."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in PLOT_FORMATS:
        given = shown(f".{suffix}", quoted=True) if suffix else "no extension"
        raise InputError.at(
            shown(str(path), limit=SHOWN_FILE_NAME_CHARS),
            f"cannot tell the plot format from {given}; name the file .{', .'.join(PLOT_FORMATS)}",
            code="unknown-format",
        )
    return suffix


# While a chart is built and rendered: no text is parsed as mathtext or set by TeX.
_LITERAL_TEXT: dict[Any, Any] = {"text.parse_math": False, "text.usetex": False}


@contextmanager
def literal_text() -> Iterator[None]:
    """Within this block, matplotlib draws every text as written (see the module docstring).

    Both building a figure and rendering it need it: a text takes its ``parse_math`` and
    ``usetex`` when it is made, and tick labels are made when the figure is drawn. What a
    stranger's name can make matplotlib say about itself (a glyph no font has, labels too
    long for the margins) is not printed as a Python warning: the chart is drawn regardless.
    """
    import warnings

    import matplotlib

    with matplotlib.rc_context(_LITERAL_TEXT), warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Glyph .* missing from", UserWarning)
        yield


def _drawn_literally(draw: Callable[[Solution], Figure]) -> Callable[[Solution], Figure]:
    def drawn(solution: Solution) -> Figure:
        require_matplotlib()
        with literal_text():
            return draw(solution)

    drawn.__name__, drawn.__qualname__, drawn.__doc__ = (
        draw.__name__,
        draw.__qualname__,
        draw.__doc__,
    )
    return drawn


# What needs matplotlib, as a missing-extra message names it (solver/extras.py).
_FEATURE = "drawing plots (solve --plot, report, batch --report)"


def require_matplotlib() -> None:
    """:class:`~solver.errors.MissingExtraError` (the ``plots`` extra) when matplotlib, which
    every chart and report needs, is not installed."""
    require("matplotlib", feature=_FEATURE)


def _new_figure(width: float, height: float) -> Figure:
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(width, height))
    FigureCanvasAgg(figure)
    return figure


# A value label's ground: white, a little see-through, as tight as the text.
_BOX = {"boxstyle": "square,pad=0.1", "facecolor": "white", "alpha": 0.8, "linewidth": 0}


def _text(ax: Axes, label: Label, zorder: float) -> None:
    options: dict[str, Any] = {}
    if label.rotation is not None:
        options.update(rotation=label.rotation, rotation_mode="anchor")
    if label.bold:
        options["fontweight"] = "bold"
    if label.colour != "#000000":
        options["color"] = label.colour
    if label.boxed:
        options["bbox"] = _BOX
    if label.name:
        options["label"] = label.name
    ax.text(
        label.x,
        label.y,
        label.text,
        fontsize=label.size,
        ha=label.ha,
        va=label.va,
        zorder=zorder,
        **options,
    )


def _draw_layer(ax: Axes, layer: Layer) -> None:
    from matplotlib.path import Path as MplPath

    if layer.quads:
        from matplotlib.patches import PathPatch

        vertices = [point for quad in layer.quads for point in (*quad, quad[0])]
        codes = [
            code
            for _ in layer.quads
            for code in (
                MplPath.MOVETO,
                MplPath.LINETO,
                MplPath.LINETO,
                MplPath.LINETO,
                MplPath.CLOSEPOLY,
            )
        ]
        ax.add_patch(
            PathPatch(
                MplPath(vertices, codes),
                facecolor=layer.colour,
                alpha=REGION_ALPHA,
                edgecolor="none",
                zorder=2,
                label=layer.name,
            )
        )
    for stroke in layer.strokes:
        (x0, y0), (x1, y1) = stroke.start, stroke.end
        # A line of no length draws nothing: a single value is a dot as wide.
        ax.plot(
            [x0, x1],
            [y0, y1],
            color=layer.colour,
            linewidth=layer.width,
            solid_capstyle="round",
            marker="o" if stroke.dot else "",
            markersize=layer.width,
            markeredgewidth=0,
            zorder=3 + layer.order,
            label=f"run {layer.name}",
        )


def draw_radar(chart: RadarChart) -> Figure:
    """``chart`` as a matplotlib figure (see :func:`radar_figure`)."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    figure = _new_figure(chart.width, chart.height)
    ax = figure.add_axes(chart.plot)
    ax.set_xlim(*chart.xlim)
    ax.set_ylim(*chart.ylim)
    ax.set_aspect("equal")
    ax.set_axis_off()
    for spoke in chart.spokes:
        ax.plot(
            [0, spoke.end[0]],
            [0, spoke.end[1]],
            color=GREY,
            linewidth=0.8,
            zorder=1,
            label=f"_spoke {spoke.name}",
        )
        # Tick marks: short strokes across the spoke, one collection (one artist) per spoke.
        ax.add_collection(
            LineCollection(
                list(spoke.ticks),
                colors=GREY,
                linewidths=0.7,
                capstyle="projecting",
                zorder=1,
                label=f"_ticks {spoke.name}",
            ),
            autolim=False,
        )
        for label in (*spoke.labels, spoke.title):
            _text(ax, label, 5)
    for layer in chart.layers:
        _draw_layer(ax, layer)
    if chart.layers:
        # Each entry pairs the region's colour with the run stroke (a tuple handle, drawn
        # overlaid; matplotlib's hints know no tuple handles).
        handles: list[Any] = [
            (
                Patch(facecolor=layer.colour, alpha=0.3, edgecolor="none"),
                Line2D([], [], color=layer.colour, linewidth=4),
            )
            for layer in chart.layers
        ]
        figure.legend(
            handles,
            [layer.legend for layer in chart.layers],
            loc="lower center",
            bbox_to_anchor=(0.5, chart.legend_bottom / chart.height),
            frameon=False,
            fontsize=10,
        )
    figure.text(
        0.5,
        1 - 0.3 / chart.height,
        chart.title,
        ha="center",
        va="center",
        fontsize=13,
        fontweight="bold",
    )
    figure.text(
        0.5,
        1 - 0.6 / chart.height,
        chart.subtitle,
        ha="center",
        va="center",
        fontsize=9,
        color="#444444",
    )
    return figure


@_drawn_literally
def radar_figure(solution: Solution) -> Figure:
    """The team's radar chart (the article's Figure 9, :func:`~solver.reporting.chart.
    radar_chart`) as a matplotlib figure.

    Each kinematic type is drawn in its own colour: a shaded region between neighbouring
    spokes, one :class:`~matplotlib.patches.PathPatch` labelled with the type's name (its
    quadrilaterals are sub-paths, so overlaps are filled once), and on every spoke a stroke
    labelled ``"run <type>"`` per run of selected values (a dot for a single value). Strokes
    get thinner from the first type to the last, so that where types select the same values
    every colour still shows, nested.
    """
    return draw_radar(radar_chart(solution))


def draw_bars(chart: BarsChart) -> Figure:
    """``chart`` as a matplotlib figure (see :func:`bars_figure`)."""
    figure = _new_figure(chart.width, chart.height)
    ax = figure.add_axes(chart.plot)
    positions = list(range(len(chart.categories)))
    for series in chart.series:
        bars = ax.bar(
            [p + series.offset for p in positions],
            series.values,
            chart.bar_width,
            label=series.name,
            color=series.colour,
            hatch=series.hatch,
            edgecolor="#333333",
            linewidth=0.6,
        )
        ax.bar_label(bars, labels=[str(v) for v in series.values], padding=2, fontsize=9)
    ax.set_xticks(positions, list(chart.categories), fontsize=9)
    ax.set_xlim(*chart.xlim)
    ax.set_ylim(0, chart.ytop)
    ax.set_yticks(list(chart.yticks), [str(t) for t in chart.yticks])
    ax.set_ylabel(chart.ylabel)
    ax.spines[["top", "right"]].set_visible(False)
    ax.legend(
        loc="lower center",
        bbox_to_anchor=(0.5, 1.0),
        ncols=len(chart.series),
        frameon=False,
        fontsize=9,
        borderaxespad=0.2,
    )
    ax.set_title(chart.title, fontsize=11, pad=22)
    return figure


@_drawn_literally
def bars_figure(solution: Solution) -> Figure:
    """Valid robots beside UI configurations, one pair of bars per kinematic type."""
    return draw_bars(bars_chart(solution))


def draw_matrix(chart: MatrixChart) -> Figure:
    """``chart`` as a matplotlib figure (see :func:`matrix_figure`)."""
    from matplotlib.colors import to_rgb

    figure = _new_figure(chart.width, chart.height)
    ax = figure.add_axes(chart.plot)
    shades = [[to_rgb(fill) for fill in row] for row in chart.fills]
    ax.imshow(shades if shades and shades[0] else [[(1.0, 1.0, 1.0)]], aspect="auto")
    for label in chart.cells:
        _text(ax, label, 3)
    ax.set_yticks(range(len(chart.rows)), list(chart.rows), fontsize=9)
    ax.set_xticks(
        range(len(chart.columns)), list(chart.columns), rotation=60, ha="right", fontsize=8
    )
    for edge in chart.edges:
        ax.axvline(edge, color="#333333", linewidth=1.0)
    for label in chart.groups:
        _text(ax, label, 3)
    ax.tick_params(length=0)
    ax.set_title(chart.title, fontsize=9, pad=22)
    return figure


@_drawn_literally
def matrix_figure(solution: Solution) -> Figure:
    """Which UI components each kinematic type needs, at a glance (:func:`~solver.reporting.
    chart.matrix_chart`): one row per type, one column per component (grouped by
    characteristic); a cell's shade is the share of the type's valid robots whose configuration
    uses the component, its text the number of configurations that do. Blank: the type never
    needs it."""
    require_matplotlib()
    return draw_matrix(matrix_chart(solution))


def figure_bytes(figure: Figure, fmt: str) -> bytes:
    """``figure`` rendered as ``fmt`` (one of :data:`PLOT_FORMATS`), the same bytes every run."""
    import matplotlib

    if fmt not in PLOT_FORMATS:
        raise ValueError(f"fmt must be in {PLOT_FORMATS} (got {fmt!r})")
    # Dates and random ids are what would make two renderings differ.
    metadata: dict[str, Any] = {"svg": {"Date": None}, "pdf": {"CreationDate": None}, "png": {}}[
        fmt
    ]
    buffer = io.BytesIO()
    with (
        literal_text(),
        matplotlib.rc_context(
            {"svg.hashsalt": "teleop-ui", "svg.fonttype": "path", "pdf.fonttype": 42}
        ),
    ):
        figure.savefig(buffer, format=fmt, dpi=PNG_DPI, metadata=metadata, facecolor="white")
    return buffer.getvalue()


def write_plot(solution: Solution, path: str | Path, kind: PlotKind = "radar") -> Path:
    """Draw ``kind`` for ``solution`` and write it to ``path`` (format by extension)."""
    fmt = plot_format(path)
    draw = {"radar": radar_figure, "bars": bars_figure, "matrix": matrix_figure}[kind]
    figure = draw(solution)
    return write_atomic(path, figure_bytes(figure, fmt))
