"""Plots of a solved team: the article's radar chart (its Figure 9) and a bar chart of counts.

:func:`radar_figure` draws one spoke per characteristic of the rule set, in rule order. Along a
spoke sit the characteristic's values (categorical values in declared order, whole numbers on a
linear scale from the domain's minimum to the largest count the team selects). Every kinematic
type of the team is one coloured region: between each pair of neighbouring spokes it joins
every run of its selected values on one spoke to every run on the next. A run is a set of
values that are neighbours in the domain (``1..13`` sensors; ``Speaker, Microphone``), so a
contiguous selection is a continuous shaded band, and a lone value is a point that the region
narrows to, as the article's Figure 9 shades "characteristic selections which are numerically
continuous". The legend gives each type's valid robots and UI configurations.

:func:`bars_figure` sets valid robots beside UI configurations for each kinematic type.

Every text on a chart that comes from the user's files (names of the team, rule set, kinematic
types, characteristics, values, components) is drawn as written: matplotlib's mathtext never
parses it (``$\\sqrt{x}$``, ``\\input{...}`` stay text, and cannot make drawing fail) and TeX
never runs, whatever a ``matplotlibrc`` says (:func:`literal_text`); a control or invisible
character in it is shown as its escape (:func:`~solver.untrusted.shown`).

Figures are built on matplotlib's Agg canvas without pyplot (no global figure registry, safe in
worker processes) and written by :func:`write_plot` as PNG, SVG or PDF by file extension,
atomically and byte-identical from run to run (fixed SVG hash salt, no dates in metadata).
matplotlib is imported inside the functions that draw, so importing this module is cheap.

Not here: the pages that embed the plots (:mod:`solver.reporting.report`), solving
(:mod:`solver.core.solution`).
"""

from __future__ import annotations

import bisect
import io
import math
import textwrap
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from solver.core.constraints import Value
from solver.core.rules import Characteristic
from solver.errors import InputError
from solver.extras import require
from solver.files.atomic import write_atomic
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from solver.core.solution import Solution
    from solver.core.team import Team

__all__ = [
    "PLOT_FORMATS",
    "PLOT_KINDS",
    "RadarAxis",
    "bars_figure",
    "component_matrix",
    "figure_bytes",
    "literal_text",
    "matrix_figure",
    "plot_format",
    "radar_axes",
    "radar_figure",
    "runs",
    "write_plot",
]

PlotKind = Literal["radar", "bars", "matrix"]
PLOT_FORMATS = ("png", "svg", "pdf")
PLOT_KINDS: tuple[PlotKind, ...] = ("radar", "bars", "matrix")

# A categorical spoke lists every value of the domain up to this many; past it, only the values
# some kinematic type of the team selects (more would not fit as readable labels).
MAX_SPOKE_VALUES = 12
# At most this many labels on a spoke of names (integers are thinned by spacing instead).
MAX_SPOKE_LABELS = 40
# Past this many components the component matrix has one column per characteristic.
MAX_MATRIX_COLUMNS = 60
# Where the first value of a spoke sits (radius 0 is the centre, 1 the end of a spoke): far
# enough out that the innermost labels of neighbouring spokes do not meet.
INNER_RADIUS = 0.22
# Integer tick labels closer than this (in radius) to one already placed are left out.
MIN_TICK_GAP = 0.075
# Tick marks closer than this (in radius, about 4 pixels in a PNG) would merge into a solid bar:
# a spoke whose values sit closer gets marks at its labelled values only, so a domain of
# 100,000 counts costs no more to draw than one of 10.
MIN_TICK_MARK_GAP = 0.01
# Stroke widths (points) of the first and the last type's runs along a spoke.
STROKE_WIDEST = 12.0
STROKE_NARROWEST = 5.0
# How far tick labels sit from their spoke (radius units): clear of the widest stroke.
LABEL_GAP = 0.055
# |sin| of the spoke angle from which labels are written horizontally (stacked lines clear
# each other); flatter spokes get labels written across them.
STEEP = 0.45
PNG_DPI = 150
# The Okabe-Ito palette: told apart by people with colour-blind vision and in greyscale print,
# and strokes of different width as a second cue.
COLOURS = ("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#D55E00", "#56B4E9", "#F0E442", "#000000")
TICK_FONT = 7.5
# Values wider than this many characters are wrapped onto two lines.
LABEL_WRAP = 22


@dataclass(frozen=True, slots=True)
class RadarAxis:
    """One spoke: its characteristic, direction, the values it shows and where they sit."""

    characteristic: Characteristic
    angle: float  # radians, counter-clockwise from the positive x axis
    shown: tuple[Value, ...]  # values with a position on the spoke, in domain order
    low: int = 0  # integer spokes: the counts at radius INNER_RADIUS and 1
    high: int = 0

    @property
    def complete(self) -> bool:
        """Whether every value of the domain is shown (integer spokes may stop earlier)."""
        return self.shown == self.characteristic.values

    def radius(self, value: Value) -> float:
        """Where ``value`` sits on the spoke (it must be one of :attr:`shown`)."""
        if self.characteristic.kind == "integer":
            span = self.high - self.low
            fraction = 0.5 if span == 0 else (int(value) - self.low) / span
        else:
            count = len(self.shown)
            fraction = 0.5 if count == 1 else self.shown.index(value) / (count - 1)
        return INNER_RADIUS + (1 - INNER_RADIUS) * fraction

    def point(self, value: Value, offset: float = 0.0) -> tuple[float, float]:
        """Where ``value`` is drawn, ``offset`` across the spoke (clockwise side positive)."""
        radius = self.radius(value)
        cos, sin = math.cos(self.angle), math.sin(self.angle)
        return radius * cos + offset * sin, radius * sin - offset * cos


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


def runs(characteristic: Characteristic, values: Sequence[Value]) -> list[tuple[Value, Value]]:
    """``values`` as runs of domain neighbours, each ``(first, last)``, in domain order.

    >>> from solver import load_rules, default_rules_path
    >>> count = load_rules(default_rules_path()).characteristic("sensor_count")
    >>> runs(count, [1, 2, 3, 7, 8])
    [(1, 3), (7, 8)]
    """
    positions = sorted(p for p in (characteristic.index(v) for v in values) if p is not None)
    found: list[tuple[Value, Value]] = []
    start = previous = None
    for position in positions:
        if previous is not None and position == previous + 1:
            previous = position
            continue
        if start is not None and previous is not None:
            found.append((characteristic.values[start], characteristic.values[previous]))
        start = previous = position
    if start is not None and previous is not None:
        found.append((characteristic.values[start], characteristic.values[previous]))
    return found


def radar_axes(team: Team) -> tuple[RadarAxis, ...]:
    """The spokes of the team's radar chart, one per characteristic in rule order.

    Spokes go clockwise from the upper left, half a step off the vertical, so that with four
    characteristics every spoke is a diagonal and its labels can be written horizontally.
    """
    characteristics = team.rules.characteristics
    count = len(characteristics)
    found = []
    for position, characteristic in enumerate(characteristics):
        angle = math.pi / 2 + math.pi / count - 2 * math.pi * position / count
        selected = {v for s in team.selections for v in s.domains[position]}
        if characteristic.kind == "integer":
            low = int(characteristic.values[0])
            high = max((int(v) for v in selected), default=int(characteristic.values[-1]))
            shown = tuple(v for v in characteristic.values if low <= int(v) <= high)
            found.append(RadarAxis(characteristic, angle, shown, low, high))
            continue
        shown = characteristic.values
        if len(shown) > MAX_SPOKE_VALUES:
            shown = tuple(v for v in characteristic.values if v in selected)
        found.append(RadarAxis(characteristic, angle, shown))
    return tuple(found)


def _tick_values(axis: RadarAxis, team: Team, position: int) -> list[Value]:
    """The values labelled on a spoke: all of them, or for integers the telling ones.

    Integers are taken greedily in priority order (the ends, each type's largest count, where
    arrangements end, then every value in ascending order), each kept when it is at least
    :data:`MIN_TICK_GAP` from every label kept before it.
    """
    characteristic = axis.characteristic
    if characteristic.kind != "integer":
        # Past MAX_SPOKE_LABELS a spoke labels every k-th value (and the last): thousands of
        # labels would overlap into a smear and take minutes to draw.
        step = math.ceil(len(axis.shown) / MAX_SPOKE_LABELS)
        return list(dict.fromkeys([*axis.shown[::step], *axis.shown[-1:]]))
    labels = _Labels(axis)
    for value in (
        axis.low,
        axis.high,
        *(max(int(v) for v in s.domains[position]) for s in team.selections),
        *(c.high for c in characteristic.components if c.high is not None),
    ):
        labels.offer(value)
    # The rest: a value too close to a label is skipped together with every value up to the
    # end of that label's gap, so the cost follows the number of labels, not of values.
    rest = [int(v) for v in axis.shown]
    index = 0
    while index < len(rest):
        blocker = labels.offer(rest[index])
        index = (
            index + 1
            if blocker is None
            else bisect.bisect_left(rest, blocker + MIN_TICK_GAP, lo=index + 1, key=axis.radius)
        )
    return sorted(labels.values)


class _Labels:
    """The integer labels of a spoke kept so far, with their radii in order (for bisection)."""

    def __init__(self, axis: RadarAxis) -> None:
        self.axis = axis
        self.values: list[int] = []
        self.radii: list[float] = []

    def offer(self, value: int) -> float | None:
        """Keep ``value`` if it fits; else the radius of the label it is too close to.

        Only the nearest labels on either side can be too close, so two are looked at.
        """
        if not self.axis.low <= value <= self.axis.high or value in self.values:
            return None
        radius = self.axis.radius(value)
        at = bisect.bisect_left(self.radii, radius)
        close = [r for r in self.radii[max(at - 1, 0) : at + 1] if abs(radius - r) < MIN_TICK_GAP]
        if close:
            return max(close)
        self.values.append(value)
        self.radii.insert(at, radius)
        return None


def _tick_marks(axis: RadarAxis, labelled: Sequence[Value]) -> Sequence[Value]:
    """The values that get a tick mark: every shown one, unless they are too close together."""
    shown = len(axis.shown)
    if shown < 2 or (1 - INNER_RADIUS) / (shown - 1) >= MIN_TICK_MARK_GAP:
        return axis.shown
    return labelled


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
        warnings.filterwarnings("ignore", "Tight layout not applied", UserWarning)
        yield


def _drawn_literally(draw: Callable[[Solution], Figure]) -> Callable[[Solution], Figure]:
    def drawn(solution: Solution) -> Figure:
        require("matplotlib", feature=_FEATURE)
        with literal_text():
            return draw(solution)

    drawn.__name__, drawn.__qualname__, drawn.__doc__ = (
        draw.__name__,
        draw.__qualname__,
        draw.__doc__,
    )
    return drawn


def _text(name: object) -> str:
    """A name from the user's files as a chart shows it: escaped, never cut."""
    return shown(str(name), limit=None)


def _label(value: Value) -> str:
    return textwrap.fill(_text(value), LABEL_WRAP)


def _draw_spoke(ax: Axes, axis: RadarAxis, team: Team, position: int) -> None:
    from matplotlib.collections import LineCollection

    cos, sin = math.cos(axis.angle), math.sin(axis.angle)
    ax.plot(
        [0, cos],
        [0, sin],
        color="#888888",
        linewidth=0.8,
        zorder=1,
        label=f"_spoke {axis.characteristic.name}",
    )
    labelled = _tick_values(axis, team, position)
    # Tick marks: short strokes across the spoke, one collection (one artist) per spoke.
    ax.add_collection(
        LineCollection(
            [
                (axis.point(value, -0.012), axis.point(value, 0.012))
                for value in _tick_marks(axis, labelled)
            ],
            colors="#888888",
            linewidths=0.7,
            capstyle="projecting",
            zorder=1,
            label=f"_ticks {axis.characteristic.name}",
        ),
        autolim=False,
    )
    box = {"boxstyle": "square,pad=0.1", "facecolor": "white", "alpha": 0.8, "linewidth": 0}
    for value in labelled:
        if abs(sin) >= STEEP:
            outward = 1 if cos >= 0 else -1
            x, y = axis.point(value)
            ax.text(
                x + LABEL_GAP * outward / abs(sin),
                y,
                _label(value),
                fontsize=TICK_FONT,
                ha="left" if outward > 0 else "right",
                va="center",
                zorder=5,
                label=f"tick {axis.characteristic.name}",
                bbox=box,
            )
        else:
            rotation = (math.degrees(axis.angle) + 180) % 180 - 90
            x, y = axis.point(value, LABEL_GAP)
            # Text runs along the clockwise normal (sin, -cos) or against it.
            along = math.radians(rotation)
            ahead = math.cos(along) * sin - math.sin(along) * cos > 0
            ax.text(
                x,
                y,
                _label(value),
                fontsize=TICK_FONT,
                rotation=rotation,
                rotation_mode="anchor",
                ha="left" if ahead else "right",
                va="center",
                zorder=5,
                label=f"tick {axis.characteristic.name}",
                bbox=box,
            )
    title = _text(axis.characteristic.label)
    if not axis.complete and axis.characteristic.kind != "integer":
        title += "\n(selected values)"
    if axis.characteristic.kind != "integer" and len(labelled) < len(axis.shown):
        title += f"\n({len(labelled)} of {len(axis.shown)} values labelled)"
    ax.text(
        1.09 * cos,
        1.09 * sin,
        title,
        fontsize=10.5,
        fontweight="bold",
        ha="center" if abs(sin) >= STEEP else ("left" if cos > 0 else "right"),
        va="bottom" if sin > 0 else "top",
        zorder=5,
        label=f"axis {axis.characteristic.name}",
    )


def _spans(
    axes: Sequence[RadarAxis], domains: Sequence[Sequence[Value]]
) -> list[list[tuple[Value, Value]]]:
    """Per spoke, the runs of a type's selected values that the spoke shows."""
    found = []
    for axis, domain in zip(axes, domains, strict=True):
        # A set, not the tuple: a spoke may show 100,000 counts.
        shown = set(axis.shown)
        found.append(runs(axis.characteristic, [v for v in domain if v in shown]))
    return found


def _region_vertices(
    axes: Sequence[RadarAxis],
    spans: Sequence[Sequence[tuple[Value, Value]]],
) -> list[list[tuple[float, float]]]:
    """One quadrilateral per pair of runs on neighbouring spokes, all wound the same way."""
    quads = []
    for k, axis in enumerate(axes):
        following = axes[(k + 1) % len(axes)]
        for first, last in spans[k]:
            for other_first, other_last in spans[(k + 1) % len(axes)]:
                quads.append(
                    [
                        axis.point(first),
                        axis.point(last),
                        following.point(other_last),
                        following.point(other_first),
                    ]
                )
    return quads


def _counts(robots: int, configurations: int) -> str:
    return (
        f"{robots} valid robot{'' if robots == 1 else 's'}, {configurations} UI "
        f"configuration{'' if configurations == 1 else 's'}"
    )


# What needs matplotlib, as a missing-extra message names it (solver/extras.py).
_FEATURE = "drawing plots (solve --plot, report, batch --report)"


def _new_figure(width: float, height: float) -> Figure:
    require("matplotlib", feature=_FEATURE)
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(width, height))
    FigureCanvasAgg(figure)
    return figure


@_drawn_literally
def radar_figure(solution: Solution) -> Figure:
    """The team's radar chart (the article's Figure 9) as a matplotlib figure.

    Each kinematic type is drawn in its own colour: a shaded region between neighbouring
    spokes, one :class:`~matplotlib.patches.PathPatch` labelled with the type's name (its
    quadrilaterals are sub-paths, so overlaps are filled once), and on every spoke a stroke
    labelled ``"run <type>"`` per run of selected values (a dot for a single value). Strokes
    get thinner from the first type to the last, so that where types select the same values
    every colour still shows, nested.
    """
    require("matplotlib", feature=_FEATURE)
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, PathPatch
    from matplotlib.path import Path as MplPath

    team = solution.team
    axes = radar_axes(team)
    summaries = {s.kinematic_type: s for s in solution.by_type}
    count = len(team.selections)
    # The drawing is 3 radius units wide (spokes plus labels); its height follows the spokes,
    # with room for the characteristic names beyond their tips.
    sines = [math.sin(axis.angle) for axis in axes]
    top, bottom = max(*sines, 0.0) + 0.3, min(*sines, 0.0) - 0.3
    width, title_height = 8.0, 0.75
    plot_height = width * (top - bottom) / 3.0
    legend_height = 0.35 + 0.24 * max(count, 1)
    figure = _new_figure(width, plot_height + title_height + legend_height)
    height = figure.get_figheight()
    ax = figure.add_axes((0.0, legend_height / height, 1.0, plot_height / height))
    ax.set_xlim(-1.5, 1.5)
    ax.set_ylim(bottom, top)
    ax.set_aspect("equal")
    ax.set_axis_off()
    for position, axis in enumerate(axes):
        _draw_spoke(ax, axis, team, position)

    # Each entry pairs the region's patch with the run stroke (a tuple handle, drawn overlaid).
    legend_handles: list[Any] = []
    legend_texts = []
    for index, selection in enumerate(team.selections):
        colour = COLOURS[index % len(COLOURS)]
        stroke = STROKE_WIDEST - (STROKE_WIDEST - STROKE_NARROWEST) * index / max(count - 1, 1)
        spans = _spans(axes, selection.domains)
        quads = _region_vertices(axes, spans)
        if quads:
            vertices = [point for quad in quads for point in (*quad, quad[0])]
            codes = [
                code
                for _ in quads
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
                    facecolor=colour,
                    alpha=0.15,
                    edgecolor="none",
                    zorder=2,
                    label=selection.kinematic_type,
                )
            )
        for axis, axis_runs in zip(axes, spans, strict=True):
            for first, last in axis_runs:
                (x0, y0), (x1, y1) = axis.point(first), axis.point(last)
                # A line of no length draws nothing: a single value is a dot as wide.
                ax.plot(
                    [x0, x1],
                    [y0, y1],
                    color=colour,
                    linewidth=stroke,
                    solid_capstyle="round",
                    marker="o" if first == last else "",
                    markersize=stroke,
                    markeredgewidth=0,
                    zorder=3 + index,
                    label=f"run {selection.kinematic_type}",
                )
        summary = summaries.get(selection.kinematic_type)
        text = _text(selection.kinematic_type)
        if summary is not None:
            text += f": {_counts(summary.valid_robots, summary.ui_configurations)}"
            if summary.unserved_robots:
                text += f" ({summary.unserved_robots} unserved)"
        legend_handles.append(
            (
                Patch(facecolor=colour, alpha=0.3, edgecolor="none"),
                Line2D([], [], color=colour, linewidth=4),
            )
        )
        legend_texts.append(text)
    if legend_handles:
        figure.legend(
            legend_handles,
            legend_texts,
            loc="lower center",
            bbox_to_anchor=(0.5, 0.1 / height),
            frameon=False,
            fontsize=10,
        )
    totals = solution.totals
    figure.text(
        0.5,
        1 - 0.3 / height,
        f"{_text(team.name)}: {_counts(totals.valid_robots, totals.ui_configurations)}",
        ha="center",
        va="center",
        fontsize=13,
        fontweight="bold",
    )
    figure.text(
        0.5,
        1 - 0.6 / height,
        f"rules: {_text(team.rules.name)}    bound T = {solution.bound}    "
        f"default UI configuration: {solution.default_configuration}",
        ha="center",
        va="center",
        fontsize=9,
        color="#444444",
    )
    return figure


@_drawn_literally
def bars_figure(solution: Solution) -> Figure:
    """Valid robots beside UI configurations, one pair of bars per kinematic type."""
    types = [s.kinematic_type for s in solution.by_type]
    figure = _new_figure(max(5.0, 1.5 + 1.3 * len(types)), 4.6)
    ax = figure.add_subplot()
    positions = list(range(len(types)))
    width = 0.38
    series = (
        ("valid robots", [s.valid_robots for s in solution.by_type], "#0072B2", ""),
        ("UI configurations", [s.ui_configurations for s in solution.by_type], "#E69F00", "//"),
    )
    for offset, (name, heights, colour, hatch) in zip((-width / 2, width / 2), series, strict=True):
        bars = ax.bar(
            [p + offset for p in positions],
            heights,
            width,
            label=name,
            color=colour,
            hatch=hatch,
            edgecolor="#333333",
            linewidth=0.6,
        )
        ax.bar_label(bars, padding=2, fontsize=9)
    ax.set_xticks(positions, [textwrap.fill(_text(t), 12) for t in types], fontsize=9)
    ax.set_ylabel("count")
    ax.margins(y=0.12)
    ax.spines[["top", "right"]].set_visible(False)
    ax.legend(frameon=False, fontsize=9)
    totals = solution.totals
    ax.set_title(
        f"{_text(solution.team.name)}: {_counts(totals.valid_robots, totals.ui_configurations)}",
        fontsize=11,
    )
    figure.tight_layout()
    return figure


def component_matrix(
    solution: Solution,
) -> tuple[list[str], list[tuple[str, str]], list[list[tuple[int, int]]]]:
    """Rows (kinematic types), columns (characteristic label, component) and per cell the
    (configurations, valid robots) of that type that use that component."""
    rules = solution.rules
    columns = [
        (c.label, component.name)
        for i, c in enumerate(rules.characteristics)
        if i != rules.key_position
        for component in c.components
    ]
    # A rule set with thousands of components would draw thousands of columns: past
    # MAX_MATRIX_COLUMNS, each characteristic is one column (its components taken together).
    grouped = len(columns) > MAX_MATRIX_COLUMNS
    if grouped:
        columns = [
            (c.label, f"{len(c.components)} components")
            for i, c in enumerate(rules.characteristics)
            if i != rules.key_position
        ]
    rows = [s.kinematic_type for s in solution.by_type]
    cells = [[(0, 0) for _ in columns] for _ in rows]
    row_of = {kt: r for r, kt in enumerate(rows)}
    column_of = {key: k for k, key in enumerate(columns)}
    for configuration in solution.configurations:
        r = row_of[configuration.kinematic_type]
        k = -1
        for i, (characteristic, component) in enumerate(
            zip(rules.characteristics, configuration.components, strict=True)
        ):
            if i == rules.key_position:
                continue
            k = k + 1 if grouped else column_of[(characteristic.label, component.name)]
            used, robots = cells[r][k]
            cells[r][k] = (used + 1, robots + configuration.robots)
    return rows, columns, cells


@_drawn_literally
def matrix_figure(solution: Solution) -> Figure:
    """Which UI components each kinematic type needs, at a glance: one row per type, one
    column per component (grouped by characteristic); a cell's shade is the share of the
    type's valid robots whose configuration uses the component, its text the number of
    configurations that do. Blank: the type never needs it."""
    require("matplotlib", feature=_FEATURE)
    rows, columns, cells = component_matrix(solution)
    figure = _new_figure(max(6.0, 2.2 + 0.42 * len(columns)), 1.9 + 0.42 * max(len(rows), 1))
    ax = figure.add_subplot()
    totals = {s.kinematic_type: s.valid_robots for s in solution.by_type}
    shares = [
        [robots / totals[kt] if totals[kt] else 0.0 for _, robots in row]
        for kt, row in zip(rows, cells, strict=True)
    ]
    ax.imshow(shares or [[0.0]], cmap="Blues", vmin=0.0, vmax=1.0, aspect="auto")
    for r, row in enumerate(cells):
        for k, (used, _) in enumerate(row):
            if used:
                ax.text(
                    k,
                    r,
                    str(used),
                    ha="center",
                    va="center",
                    fontsize=8,
                    color="white" if shares[r][k] > 0.6 else "#222222",
                )
    ax.set_yticks(range(len(rows)), [_text(row) for row in rows], fontsize=9)
    ax.set_xticks(
        range(len(columns)),
        [textwrap.shorten(_text(name), 18) for _, name in columns],
        rotation=60,
        ha="right",
        fontsize=8,
    )
    # A thin line between characteristics: the columns are grouped by them.
    edges = [k - 0.5 for k in range(1, len(columns)) if columns[k][0] != columns[k - 1][0]]
    for edge in edges:
        ax.axvline(edge, color="#333333", linewidth=1.0)
    # Each group's characteristic, above its columns.
    starts = [0, *(int(edge + 0.5) for edge in edges)]
    for first, last in zip(starts, [*starts[1:], len(columns)], strict=True):
        if first < last:
            ax.text(
                (first + last - 1) / 2,
                -0.7,
                _text(columns[first][0]),
                ha="center",
                va="bottom",
                fontsize=8,
                color="#444444",
            )
    ax.tick_params(length=0)
    totals_all = solution.totals
    ax.set_title(
        f"{_text(solution.team.name)}: "
        f"{_counts(totals_all.valid_robots, totals_all.ui_configurations)}\n"
        "shade: share of the type's robots whose configuration uses the component; "
        "number: configurations that do",
        fontsize=9,
        pad=22,
    )
    figure.tight_layout()
    return figure


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
