"""The charts of a solved team as plain data: what each chart shows, and where.

One chart, two drawings. :func:`radar_chart` (the article's Figure 9), :func:`bars_chart` and
:func:`matrix_chart` decide everything a chart shows (every stroke, region, bar, cell and text,
its place, size and colour, the figure's size and margins) from a :class:`Solution`, without
drawing. :mod:`solver.reporting.plot` draws them with matplotlib (``solve --plot``, ``report``,
``batch --report``: PNG, SVG, PDF); :mod:`solver.reporting.svg` writes them straight as SVG
(the studio, which redraws a chart on every click and cannot wait for matplotlib's layout and
glyph outlines). Both read the same model, so both show the same chart.

The radar chart has one spoke per characteristic of the rule set, in rule order. Along a spoke
sit the characteristic's values (categorical values in declared order, whole numbers on a
linear scale from the domain's minimum to the largest count the team selects). Every kinematic
type of the team is one coloured layer: between each pair of neighbouring spokes its region
joins every run of its selected values on one spoke to every run on the next. A run is a set of
values that are neighbours in the domain (``1..13`` sensors; ``Speaker, Microphone``), so a
contiguous selection is a continuous shaded band, and a lone value is a point that the region
narrows to, as the article's Figure 9 shades "characteristic selections which are numerically
continuous". The legend gives each type's valid robots and UI configurations.

The bar chart sets valid robots beside UI configurations for each kinematic type; the component
matrix shows which UI components each type's configurations use.

Every text that comes from the user's files is held as a chart shows it: unprintable characters
escaped (:func:`~solver.untrusted.shown`), never cut; the drawings draw it as written.

Not here: drawing (:mod:`solver.reporting.plot`, :mod:`solver.reporting.svg`), solving
(:mod:`solver.solving.solution`).
"""

from __future__ import annotations

import bisect
import math
import textwrap
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from solver.core.constraints import Value
from solver.core.ruleset import Characteristic, Run
from solver.errors import Location
from solver.limits import Limit, limit
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.core.partition import Key
    from solver.core.team import Team, TypeSelection
    from solver.solving.solution import Solution

__all__ = [
    "BarsChart",
    "Label",
    "Layer",
    "MatrixChart",
    "RadarAxis",
    "RadarChart",
    "Spoke",
    "Stroke",
    "bars_chart",
    "check_chart_size",
    "component_matrix",
    "matrix_chart",
    "radar_axes",
    "radar_chart",
    "runs",
    "text_width",
]

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
# The Okabe-Ito palette: told apart by people with colour-blind vision and in greyscale print,
# and strokes of different width as a second cue.
COLOURS = ("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#D55E00", "#56B4E9", "#F0E442", "#000000")
TICK_FONT = 7.5
# Values wider than this many characters are wrapped onto two lines.
LABEL_WRAP = 22
# Spoke titles wider than this are wrapped, where texts are drawn larger (a page's panel).
TITLE_WRAP = 16
# The grey of spokes, tick marks and secondary text.
GREY = "#888888"
# A region's fill is this opaque (neighbouring types' regions show through one another).
REGION_ALPHA = 0.15
# ColorBrewer's "Blues" (matplotlib's colour map of that name): a matrix cell's shade.
BLUES = (
    "#f7fbff", "#deebf7", "#c6dbef", "#9ecae1", "#6baed6", "#4292c6", "#2171b5", "#08519c",
    "#08306b",
)  # fmt: skip
# A cell darker than this share gets white text.
DARK_SHARE = 0.6

# Advance widths of DejaVu Sans (matplotlib's default font, the one the charts name first),
# printable ASCII from the space, in 1/2048 em; other characters count as wide as "M" is not,
# a little over half an em. Only margins and the placing of a legend are estimated from them.
_WIDTHS = (
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716,
    1087, 2048, 1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767,
    1532, 1612, 1235, 1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690,
    799, 1716, 1024, 1024, 1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186,
    569, 1995, 1298, 1253, 1300, 1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075,
    1303, 690, 1303, 1716,
)  # fmt: skip
_OTHER_WIDTH = 1300
_BOLD_WIDER = 1.1

Point = tuple[float, float]
HAlign = Literal["left", "center", "right"]
VAlign = Literal["top", "center", "bottom"]


def text_width(text: str, size: float, *, bold: bool = False) -> float:
    """About how wide ``text`` is at ``size`` points, in points (its widest line)."""
    widest = max(
        sum(_WIDTHS[ord(c) - 32] if " " <= c <= "~" else _OTHER_WIDTH for c in line)
        for line in text.split("\n")
    )
    return widest / 2048 * size * (_BOLD_WIDER if bold else 1.0)


@dataclass(frozen=True, slots=True)
class Label:
    """A text on a chart, anchored at ``(x, y)`` as matplotlib anchors text.

    ``rotation`` (degrees, counter-clockwise) turns it about its anchor; ``None`` is upright.
    ``boxed`` puts it on a see-through white ground; ``name`` is the drawn artist's label
    (tests and tools find texts by it).
    """

    x: float
    y: float
    text: str
    size: float
    ha: HAlign = "center"
    va: VAlign = "center"
    rotation: float | None = None
    bold: bool = False
    colour: str = "#000000"
    boxed: bool = False
    name: str = ""


# ---- the radar chart ----------------------------------------------------------------------


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

    def point(self, value: Value, offset: float = 0.0) -> Point:
        """Where ``value`` is drawn, ``offset`` across the spoke (clockwise side positive)."""
        radius = self.radius(value)
        cos, sin = math.cos(self.angle), math.sin(self.angle)
        return radius * cos + offset * sin, radius * sin - offset * cos


@dataclass(frozen=True, slots=True)
class Spoke:
    """A spoke as drawn: from the centre to ``end``, its tick marks, value labels and title."""

    name: str  # the characteristic's name
    end: Point
    ticks: tuple[tuple[Point, Point], ...]
    labels: tuple[Label, ...]
    title: Label


@dataclass(frozen=True, slots=True)
class Stroke:
    """A run of selected values along a spoke, from ``start`` to ``end`` (a dot when one)."""

    start: Point
    end: Point
    dot: bool
    spoke: int = 0  # which spoke it runs along


@dataclass(frozen=True, slots=True)
class Layer:
    """One kinematic type of the radar chart: its region, its runs and its legend entry.

    The region is one shape of quadrilaterals, all wound the same way, so overlaps are filled
    once. Strokes get thinner from the first type to the last (``width``, points) and later
    types are drawn over earlier ones, so where types select the same values every colour shows.
    """

    name: str  # the kinematic type, as written in the team
    colour: str
    width: float
    order: int  # drawn over every layer of a lower order
    quads: tuple[tuple[Point, Point, Point, Point], ...]
    strokes: tuple[Stroke, ...]
    legend: str
    # The type's counts (the legend's text when it shows them), and per spoke the values it
    # selects there, as text: what a page shows on hover and focus.
    summary: str = ""
    notes: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class RadarChart:
    """The radar chart: a figure of ``width`` x ``height`` inches whose plot (``plot``: left,
    bottom, width, height as fractions of the figure) shows radius units ``xlim`` x ``ylim`` at
    one scale; the title and subtitle above it, the legend below (its lowest row
    ``legend_bottom`` inches from the bottom, rows ``legend_pitch`` inches apart)."""

    width: float
    height: float
    plot: tuple[float, float, float, float]
    xlim: tuple[float, float]
    ylim: tuple[float, float]
    spokes: tuple[Spoke, ...]
    layers: tuple[Layer, ...]
    title: str
    subtitle: str
    legend_bottom: float = 0.1
    legend_pitch: float = 0.24
    # Texts this many times their size in ``report`` (a chart shown small, on a page); a
    # chart with ``titled`` off leaves its title and subtitle out (the page says them).
    text: float = 1.0
    titled: bool = True


def runs(characteristic: Characteristic, values: Sequence[Value]) -> list[tuple[Value, Value]]:
    """``values`` as runs of domain neighbours, each ``(first, last)``, in domain order.

    >>> from solver import load_rules, default_rules_path
    >>> count = load_rules(default_rules_path()).characteristic("sensor_count")
    >>> runs(count, [1, 2, 3, 7, 8])
    [(1, 3), (7, 8)]
    """
    domain = characteristic.values
    if isinstance(domain, Run) and domain:
        # Counts: a count's position is its distance from the first (a spoke may hold 100,000).
        low, high = domain[0], domain[-1]
        positions = sorted({v - low for v in values if type(v) is int and low <= v <= high})
    else:
        positions = sorted({p for p in map(characteristic.index, values) if p is not None})
    if positions and positions[-1] - positions[0] == len(positions) - 1:
        return [(domain[positions[0]], domain[positions[-1]])]  # one run, the common case
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


def _highest(characteristic: Characteristic, domain: Sequence[Value]) -> int:
    """The largest count of a selected domain (in domain order: a run's is its last)."""
    if isinstance(characteristic.values, Run) and domain and type(domain[-1]) is int:
        return domain[-1]
    return max(int(v) for v in domain)


def _tick_values(axis: RadarAxis, team: Team, position: int, text: float = 1.0) -> list[Value]:
    """The values labelled on a spoke: all of them, or for integers the telling ones.

    Integers are taken greedily in priority order (the ends, each type's largest count, where
    arrangements end, then every value in ascending order), each kept when it is at least
    :data:`MIN_TICK_GAP` (times ``text``, the texts' scale) from every label kept before it.
    """
    characteristic = axis.characteristic
    if characteristic.kind != "integer":
        # Past MAX_SPOKE_LABELS a spoke labels every k-th value (and the last): thousands of
        # labels would overlap into a smear and take minutes to draw.
        step = math.ceil(len(axis.shown) / MAX_SPOKE_LABELS)
        if text != 1.0 and len(axis.shown) > 1:
            # Larger texts: as many values apart as a label's line needs across the spoke.
            sine = abs(math.sin(axis.angle))
            line = TICK_FONT * text * 1.2 / _UNIT / (sine if sine >= STEEP else 1.0)
            step = max(step, math.ceil(line / ((1 - INNER_RADIUS) / (len(axis.shown) - 1))))
        return list(dict.fromkeys([*axis.shown[::step], *axis.shown[-1:]]))
    gap = MIN_TICK_GAP * text
    labels = _Labels(axis, gap)
    for value in (
        axis.low,
        axis.high,
        *(_highest(characteristic, s.domains[position]) for s in team.selections),
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
            else bisect.bisect_left(rest, blocker + gap, lo=index + 1, key=axis.radius)
        )
    return sorted(labels.values)


class _Labels:
    """The integer labels of a spoke kept so far, with their radii in order (for bisection)."""

    def __init__(self, axis: RadarAxis, gap: float = MIN_TICK_GAP) -> None:
        self.axis = axis
        self.gap = gap
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
        close = [r for r in self.radii[max(at - 1, 0) : at + 1] if abs(radius - r) < self.gap]
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


def chart_text(name: object) -> str:
    """A name from the user's files as a chart shows it: escaped, never cut."""
    return shown(str(name), limit=None)


def _label(value: Value) -> str:
    return textwrap.fill(chart_text(value), LABEL_WRAP)


def counts_text(robots: int, configurations: int) -> str:
    """``872 valid robots, 102 UI configurations`` (a one in the singular)."""
    return (
        f"{robots} valid robot{'' if robots == 1 else 's'}, {configurations} UI "
        f"configuration{'' if configurations == 1 else 's'}"
    )


def _value_label(axis: RadarAxis, value: Value, size: float = TICK_FONT) -> Label:
    """A value's label beside its spoke: written across a steep spoke, along a flat one."""
    cos, sin = math.cos(axis.angle), math.sin(axis.angle)
    name = f"tick {axis.characteristic.name}"
    if abs(sin) >= STEEP:
        outward = 1 if cos >= 0 else -1
        x, y = axis.point(value)
        return Label(
            x + LABEL_GAP * outward / abs(sin),
            y,
            _label(value),
            size,
            ha="left" if outward > 0 else "right",
            boxed=True,
            name=name,
        )
    rotation = (math.degrees(axis.angle) + 180) % 180 - 90
    x, y = axis.point(value, LABEL_GAP)
    # Text runs along the clockwise normal (sin, -cos) or against it.
    along = math.radians(rotation)
    ahead = math.cos(along) * sin - math.sin(along) * cos > 0
    return Label(
        x,
        y,
        _label(value),
        size,
        ha="left" if ahead else "right",
        rotation=rotation,
        boxed=True,
        name=name,
    )


def _spoke(axis: RadarAxis, team: Team, position: int, text: float = 1.0) -> Spoke:
    cos, sin = math.cos(axis.angle), math.sin(axis.angle)
    labelled = _tick_values(axis, team, position, text)
    characteristic = axis.characteristic
    title = chart_text(characteristic.label)
    if text != 1.0:
        # Larger texts: a long name on two lines, clear of its neighbours' (six spokes).
        title = textwrap.fill(title, TITLE_WRAP)
    if not axis.complete and characteristic.kind != "integer":
        title += "\n(selected values)"
    if characteristic.kind != "integer" and len(labelled) < len(axis.shown):
        title += f"\n({len(labelled)} of {len(axis.shown)} values labelled)"
    return Spoke(
        characteristic.name,
        (cos, sin),
        tuple(
            (axis.point(value, -0.012), axis.point(value, 0.012))
            for value in _tick_marks(axis, labelled)
        ),
        tuple(_value_label(axis, value, TICK_FONT * text) for value in labelled),
        Label(
            1.09 * cos,
            1.09 * sin,
            title,
            10.5 * text,
            ha="center" if abs(sin) >= STEEP else ("left" if cos > 0 else "right"),
            va="bottom" if sin > 0 else "top",
            bold=True,
            name=f"axis {characteristic.name}",
        ),
    )


def _spans(
    axes: Sequence[RadarAxis],
    domains: Sequence[Sequence[Value]],
    known: dict[tuple[int, tuple[Value, ...]], list[tuple[Value, Value]]],
) -> list[list[tuple[Value, Value]]]:
    """Per spoke, the runs of a type's selected values that the spoke shows (``known``: the
    runs of domains met before, by spoke: types often select the same values)."""
    found = []
    for k, (axis, domain) in enumerate(zip(axes, domains, strict=True)):
        key = (k, tuple(domain))
        if key not in known:
            # A set, not the tuple: a spoke may show 100,000 counts.
            shown_values = set(axis.shown)
            known[key] = runs(axis.characteristic, [v for v in domain if v in shown_values])
        found.append(known[key])
    return found


def _region_quads(
    axes: Sequence[RadarAxis],
    spans: Sequence[Sequence[tuple[Value, Value]]],
) -> tuple[tuple[Point, Point, Point, Point], ...]:
    """One quadrilateral per pair of runs on neighbouring spokes, all wound the same way."""
    quads = []
    for k, axis in enumerate(axes):
        following = axes[(k + 1) % len(axes)]
        for first, last in spans[k]:
            for other_first, other_last in spans[(k + 1) % len(axes)]:
                quads.append(
                    (
                        axis.point(first),
                        axis.point(last),
                        following.point(other_last),
                        following.point(other_first),
                    )
                )
    return tuple(quads)


def _layers(
    solution: Solution, axes: Sequence[RadarAxis], *, counted: bool = True
) -> tuple[Layer, ...]:
    """Each type's layer; its legend without the counts unless ``counted`` (its ``summary``
    has them either way)."""
    team = solution.team
    summaries = {s.kinematic_type: s for s in solution.by_type}
    count = len(team.selections)
    layers = []
    known: dict[tuple[int, tuple[Value, ...]], list[tuple[Value, Value]]] = {}
    for index, selection in enumerate(team.selections):
        spans = _spans(axes, selection.domains, known)
        legend = chart_text(selection.kinematic_type)
        summary = summaries.get(selection.kinematic_type)
        counts = legend
        if summary is not None:
            counts += f": {counts_text(summary.valid_robots, summary.ui_configurations)}"
            if summary.unserved_robots:
                counts += f" ({summary.unserved_robots} unserved)"
        layers.append(
            Layer(
                selection.kinematic_type,
                COLOURS[index % len(COLOURS)],
                STROKE_WIDEST - (STROKE_WIDEST - STROKE_NARROWEST) * index / max(count - 1, 1),
                index,
                _region_quads(axes, spans),
                tuple(
                    Stroke(axis.point(first), axis.point(last), first == last, k)
                    for k, (axis, axis_runs) in enumerate(zip(axes, spans, strict=True))
                    for first, last in axis_runs
                ),
                counts if counted else legend,
                counts,
                tuple(
                    _note(legend, axis, axis_runs)
                    for axis, axis_runs in zip(axes, spans, strict=True)
                ),
            )
        )
    return tuple(layers)


# Values a note names before it counts the rest.
NOTE_VALUES = 12


def _note(kinematic_type: str, axis: RadarAxis, spans: Sequence[tuple[Value, Value]]) -> str:
    """``UAV: Robot Motion Control: Flight, Waypoint`` (runs of counts as ``1..25``)."""
    characteristic = axis.characteristic
    if characteristic.kind == "integer":
        parts = [_label(a) if a == b else f"{a}..{b}" for a, b in spans]
    else:
        parts = []
        for first, last in spans:
            start, end = axis.shown.index(first), axis.shown.index(last)
            parts += [chart_text(v) for v in axis.shown[start : end + 1]]
    more = len(parts) - NOTE_VALUES
    text = ", ".join(parts[:NOTE_VALUES]) + (f" and {more} more" if more > 0 else "")
    return f"{kinematic_type}: {chart_text(characteristic.label)}: {text or 'none shown'}"


# Points per radius unit: the drawing is 8 inches for 3 units.
_UNIT = 8.0 * 72 / 3


def _reach(title: Label) -> float:
    """How far from the centre a spoke's title reaches across (radius units), with a margin."""
    if title.ha == "center":
        return abs(title.x) + text_width(title.text, title.size, bold=title.bold) / 2 / _UNIT
    return abs(title.x) + text_width(title.text, title.size, bold=title.bold) / _UNIT + 0.03


def check_chart_size(team: Team) -> None:
    """Refuse, before anything is solved or drawn, a team too large for a chart: more kinematic
    types than the ``chart-types`` limit (5,000 types made a figure wider than matplotlib
    draws, after 30 s of work), located at the first type past it; more characteristics than
    ``chart-characteristics`` (each is a spoke of the radar); or a type of more robots than
    ``chart-robots`` (a bar's height is a float)."""
    rules = team.rules
    spokes = limit("chart-characteristics")
    if spokes.exceeded(len(rules.characteristics)):  # at the first characteristic past it
        at = rules.characteristics[spokes.value].location or Location(rules.file)
        spokes.check(
            len(rules.characteristics), at.file, line=at.line, column=at.column, path=at.path
        )
    types = limit("chart-types")
    if types.exceeded(len(team.selections)):
        _refuse(team, team.selections[types.value], types, len(team.selections))
    robots = limit("chart-robots")
    for selection in team.selections:
        if robots.exceeded(selection.size):
            _refuse(team, selection, robots, selection.size)


def _refuse(team: Team, selection: TypeSelection, which: Limit, size: int) -> None:
    at = selection.location
    if at is None:
        which.check(size, team.file, path="team")
    else:
        which.check(size, at.file, line=at.line, column=at.column, path=at.path)


def radar_chart(solution: Solution, *, text: float = 1.0, titled: bool = True) -> RadarChart:
    """The team's radar chart (the article's Figure 9): its texts ``text`` times their size
    in ``report`` (more values then apart on a spoke between labels), and with ``titled`` off
    no title nor counts in the legend (a page that shows them beside it)."""
    check_chart_size(solution.team)
    team = solution.team
    axes = radar_axes(team)
    # The drawing is 3 radius units wide (spokes plus labels); its height follows the spokes,
    # with room for the characteristic names beyond their tips.
    sines = [math.sin(axis.angle) for axis in axes]
    top, bottom = max(*sines, 0.0) + 0.3, min(*sines, 0.0) - 0.3
    spokes = tuple(_spoke(axis, team, position, text) for position, axis in enumerate(axes))
    # 8 inches for 3 units, wider where a flat spoke's title would reach past the edge.
    half = max(1.5, *(_reach(spoke.title) for spoke in spokes))
    width, title_height = 8.0 * half / 1.5, 0.75 if titled else 0.1
    plot_height = width * (top - bottom) / (2 * half)
    pitch = 0.24 * text
    legend_height = 0.35 + pitch * max(len(team.selections), 1)
    height = plot_height + title_height + legend_height
    totals = solution.totals
    return RadarChart(
        width,
        height,
        (0.0, legend_height / height, 1.0, plot_height / height),
        (-half, half),
        (bottom, top),
        spokes,
        _layers(solution, axes, counted=titled),
        f"{chart_text(team.name)}: {counts_text(totals.valid_robots, totals.ui_configurations)}",
        f"rules: {chart_text(team.rules.name)}    bound T = {solution.bound}    "
        f"default UI configuration: {solution.default_configuration}",
        legend_pitch=pitch,
        text=text,
        titled=titled,
    )


# ---- the bar chart ------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Series:
    """One kind of bar: a value per kinematic type, drawn ``offset`` from the type's place."""

    name: str
    values: tuple[int, ...]
    colour: str
    hatch: str
    offset: float


@dataclass(frozen=True, slots=True)
class BarsChart:
    """Valid robots beside UI configurations: a figure of ``width`` x ``height`` inches whose
    plot (``plot``, fractions of the figure) shows types ``0..n-1`` across ``xlim`` and counts
    ``0..ytop`` up, ticked at ``yticks``; the legend in a row between the title and the plot."""

    width: float
    height: float
    plot: tuple[float, float, float, float]
    title: str
    categories: tuple[str, ...]  # each type's name, wrapped as the chart shows it
    series: tuple[Series, ...]
    bar_width: float
    xlim: tuple[float, float]
    ytop: float
    yticks: tuple[int, ...]
    ylabel: str = "count"


def nice_ticks(highest: int, most: int = 6) -> tuple[int, ...]:
    """Whole-number ticks from 0 past ``highest``: steps of 1, 2 or 5 times a power of ten,
    at most ``most`` of them below ``highest``.

    >>> nice_ticks(450)
    (0, 100, 200, 300, 400, 500)
    >>> nice_ticks(3)
    (0, 1, 2, 3)
    """
    step = 1
    while highest / step > most - 1:
        for factor in (2, 2.5, 2):  # 1 -> 2 -> 5 -> 10 -> 20 ...
            step = int(step * factor)
            if highest / step <= most - 1:
                break
    last = -(-highest // step) * step
    return tuple(range(0, last + 1, step))


def bars_chart(solution: Solution) -> BarsChart:
    """Valid robots beside UI configurations, one pair of bars per kinematic type."""
    check_chart_size(solution.team)
    summaries = solution.by_type
    categories = tuple(textwrap.fill(chart_text(s.kinematic_type), 12) for s in summaries)
    width, height = max(5.0, 1.5 + 1.3 * len(categories)), 4.6
    highest = max([1, *(s.valid_robots for s in summaries)])
    ytop = highest * 1.12
    yticks = tuple(t for t in nice_ticks(highest) if t <= ytop)
    # Margins: the tick labels and the axis name on the left, the wrapped names below, the
    # title and the legend above (points converted to fractions of the figure).
    left = (text_width(str(yticks[-1]), 10) + 10 + 10 + 14) / 72
    lines = max((c.count("\n") + 1 for c in categories), default=1)
    bottom = (9 * 1.2 * lines + 12) / 72
    top = 0.75
    bar_width = 0.38
    totals = solution.totals
    return BarsChart(
        width,
        height,
        (left / width, bottom / height, 1 - (left + 0.2) / width, 1 - (bottom + top) / height),
        f"{chart_text(solution.team.name)}: "
        f"{counts_text(totals.valid_robots, totals.ui_configurations)}",
        categories,
        (
            Series(
                "valid robots",
                tuple(s.valid_robots for s in summaries),
                "#0072B2",
                "",
                -bar_width / 2,
            ),
            Series(
                "UI configurations",
                tuple(s.ui_configurations for s in summaries),
                "#E69F00",
                "//",
                bar_width / 2,
            ),
        ),
        bar_width,
        (-0.6, len(categories) - 0.4),
        ytop,
        yticks,
    )


# ---- the component matrix -----------------------------------------------------------------


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
    column_of = {key: k for k, key in enumerate(columns)}
    # A characteristic's column when grouped: its place among the characteristics shown.
    group_of = {
        i: k
        for k, i in enumerate(
            i for i in range(len(rules.characteristics)) if i != rules.key_position
        )
    }
    for r, use in enumerate(_component_use(solution)):
        for (position, index), (used, robots) in sorted(use.items()):
            if position == rules.key_position:
                continue
            characteristic = rules.characteristics[position]
            k = (
                group_of[position]
                if grouped
                else column_of[(characteristic.label, characteristic.components[index].name)]
            )
            before = cells[r][k]
            cells[r][k] = (before[0] + used, before[1] + robots)
    return rows, columns, cells


Use = dict[tuple[int, int], tuple[int, int]]


def _component_use(solution: Solution) -> list[Use]:
    """Per kinematic type: per (characteristic position, component index), the configurations
    that use the component and the robots they serve. A listed solution's configurations are
    tallied; otherwise each type is tallied by structure where it applies
    (:func:`solver.engines.structure.component_use`: no configuration is listed), else from its
    partition."""
    from solver import engines
    from solver.engines import structure

    rules = solution.rules
    keys: dict[str, list[tuple[Key, int]]] = {s.kinematic_type: [] for s in solution.by_type}
    for configuration in solution.configurations:
        keys[configuration.kinematic_type].append((configuration.key, configuration.robots))
    found = []
    for summary, selection in zip(solution.by_type, solution.team.selections, strict=True):
        use: Use | None = None
        if not solution.listed:
            if summary.method == "structure":
                use = structure.component_use(rules, selection)
            if use is None:
                part = engines.lookup(summary.method).partition(rules, selection, engines.Memo())
                keys[summary.kinematic_type] = [(c.key, c.robots) for c in part.classes]
        if use is None:
            use = {}
            for key, robots in keys[summary.kinematic_type]:
                for position, component in enumerate(key):
                    used, served = use.get((position, component), (0, 0))
                    use[position, component] = (used + 1, served + robots)
        found.append(use)
    return found


@dataclass(frozen=True, slots=True)
class MatrixChart:
    """The component matrix: a figure of ``width`` x ``height`` inches whose plot (``plot``,
    fractions of the figure) holds a cell per row (kinematic type) and column (component);
    ``fills`` the shade of each cell (the share of the type's robots whose configuration uses
    the component), ``cells`` the labels on them. ``edges`` are the column boundaries between
    characteristics, ``groups`` the characteristics' names above their columns."""

    width: float
    height: float
    plot: tuple[float, float, float, float]
    title: str
    rows: tuple[str, ...]
    columns: tuple[str, ...]
    fills: tuple[tuple[str, ...], ...]
    cells: tuple[Label, ...]
    edges: tuple[float, ...]
    groups: tuple[Label, ...]


def blues(share: float) -> str:
    """The shade of ``share`` (0..1) in ColorBrewer's Blues, as ``#rrggbb``."""
    share = min(max(share, 0.0), 1.0)
    position = share * (len(BLUES) - 1)
    below = min(int(position), len(BLUES) - 2)
    fraction = position - below
    low, high = BLUES[below], BLUES[below + 1]
    channels = (
        round(int(low[i : i + 2], 16) * (1 - fraction) + int(high[i : i + 2], 16) * fraction)
        for i in (1, 3, 5)
    )
    return "#" + "".join(f"{c:02x}" for c in channels)


def matrix_chart(solution: Solution) -> MatrixChart:
    """Which UI components each kinematic type needs, at a glance: one row per type, one
    column per component (grouped by characteristic); a cell's shade is the share of the
    type's valid robots whose configuration uses the component, its text the number of
    configurations that do. Blank: the type never needs it."""
    check_chart_size(solution.team)
    rows, columns, cells = component_matrix(solution)
    totals = {s.kinematic_type: s.valid_robots for s in solution.by_type}
    shares = [
        [robots / totals[kt] if totals[kt] else 0.0 for _, robots in row]
        for kt, row in zip(rows, cells, strict=True)
    ]
    labels = tuple(
        Label(
            k,
            r,
            str(used),
            8,
            colour="#ffffff" if shares[r][k] > DARK_SHARE else "#222222",
        )
        for r, row in enumerate(cells)
        for k, (used, _) in enumerate(row)
        if used
    )
    # A thin line between characteristics: the columns are grouped by them.
    edges = tuple(k - 0.5 for k in range(1, len(columns)) if columns[k][0] != columns[k - 1][0])
    starts = [0, *(int(edge + 0.5) for edge in edges)]
    groups = tuple(
        Label(
            (first + last - 1) / 2,
            -0.7,
            chart_text(columns[first][0]),
            8,
            va="bottom",
            colour="#444444",
        )
        for first, last in zip(starts, [*starts[1:], len(columns)], strict=True)
        if first < last
    )
    names = tuple(textwrap.shorten(chart_text(name), 18) for _, name in columns)
    row_names = tuple(chart_text(row) for row in rows)
    width = max(6.0, 2.2 + 0.42 * len(columns))
    height = 1.9 + 0.42 * max(len(rows), 1)
    # Margins in points: the row names on the left (and the first column's name, written at 60
    # degrees, reaching left of its column), the slanted names below, the group names and the
    # two-line title above.
    slanted = max((text_width(n, 8) for n in names), default=0.0)
    column_width = (width * 72) / max(len(columns), 1)
    left = max(max((text_width(n, 9) for n in row_names), default=0.0) + 14, 0.5 * slanted) + 8
    bottom = slanted * math.sin(math.radians(60)) + 8 * 0.5 + 14
    top = 9 * 1.2 * 2 + 22 + 10
    right = 12.0
    plot_width = max(width * 72 - left - right, column_width)
    plot_height = max(height * 72 - top - bottom, 20.0)
    height = max(height, (top + bottom + plot_height) / 72)
    width = max(width, (left + right + plot_width) / 72)
    totals_all = solution.totals
    return MatrixChart(
        width,
        height,
        (
            left / 72 / width,
            bottom / 72 / height,
            plot_width / 72 / width,
            plot_height / 72 / height,
        ),
        f"{chart_text(solution.team.name)}: "
        f"{counts_text(totals_all.valid_robots, totals_all.ui_configurations)}\n"
        "shade: share of the type's robots whose configuration uses the component; "
        "number: configurations that do",
        row_names,
        names,
        tuple(tuple(blues(share) for share in row) for row in shares),
        labels,
        edges,
        groups,
    )
