"""The presentation grammar: which role each component plays, the region each role goes to,
and how sensor clusters are ordered, as data (``grammar:`` in ``rules/presentation.yaml``).

Four roles (:data:`ROLES`): the *primary* view (the first component of its ``components`` a
configuration shows: the main camera, else the 3D view), *secondary* views (the primary
component's other clusters, other sensors), *controls* (motion controls, docked together)
and *status*. Each role has a region, a rectangle in percent of the screen; the regions
together fill the screen without overlapping and can be cut into Lichtblick's splits (a
straight cut across the whole rectangle each time: :class:`Cut`). The cuts are found once,
when the grammar is read; a configuration without a role's components gives that region's
room to its neighbour in the cut (:func:`prune`).

Every problem is reported at once, located (file:line:col): an unknown role or key, a region
outside the screen or smaller than the smallest tile, two regions that overlap, regions that
leave a gap, regions no cuts can separate, a component given two roles, an unknown cluster order.

Not here: laying a plan out (:mod:`solver.layouts.design`); component -> panel
(:mod:`solver.layouts.presentation`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from solver.files.reader import Reader
from solver.files.yamlio import PathPart
from solver.layouts.checks.data import quality_rules
from solver.untrusted import shown

__all__ = [
    "DEFAULT_GRAMMAR",
    "ORDERS",
    "ROLES",
    "Cut",
    "Grammar",
    "Rect",
    "prune",
    "read_grammar",
]

ROLES = ("primary", "secondary", "controls", "status")
# The article's three organisations of clusters (Section 3, after Equation (2)).
ORDERS = ("alphabetical", "priority", "data rate")
_RECT_KEYS = ("x", "y", "width", "height")
_ROLE_KEYS = ("region", "components")
_KEYS = ("screen", "roles", "clusters")
_CLUSTER_KEYS = ("order", "priority")
# Percentages are compared to a hundredth of a percent (a pixel of 1920 is 0.05%).
_EPSILON = 0.01


@dataclass(frozen=True, slots=True)
class Rect:
    """A rectangle in percent of the screen (or in pixels, once scaled)."""

    x: float
    y: float
    width: float
    height: float

    @property
    def area(self) -> float:
        return self.width * self.height

    def overlaps(self, other: Rect) -> bool:
        return (
            min(self.x + self.width, other.x + other.width) - max(self.x, other.x) > _EPSILON
            and min(self.y + self.height, other.y + other.height) - max(self.y, other.y) > _EPSILON
        )

    def holds(self, x: float, y: float) -> bool:
        return self.x <= x <= self.x + self.width and self.y <= y <= self.y + self.height


@dataclass(frozen=True, slots=True)
class Cut:
    """A split: ``first`` left of (``row``) or above (``column``) ``second``, ``percent`` of
    the parent to ``first``. A leaf is a role's name."""

    direction: str
    percent: float
    first: Cut | str
    second: Cut | str


@dataclass(frozen=True, slots=True)
class Grammar:
    """Roles, their regions and components, the cuts between regions, the cluster order."""

    screen: tuple[int, int]  # the operator's screen the figures are for, in pixels
    regions: tuple[tuple[str, Rect], ...]  # role -> region, in ROLES order
    components: tuple[tuple[str, tuple[str, ...]], ...]  # role -> its components, in order
    cuts: Cut | str
    order: str = "alphabetical"  # how the sensors of a cluster are ordered
    priority: tuple[str, ...] = ()  # most commonly used first (order: priority)
    rates: tuple[tuple[str, float], ...] = ()  # topic -> bytes per second (order: data rate)
    order_line: int | None = field(default=None, compare=False)  # where the file says order
    # Why the order applied is not the one the file asked for (its data was not there).
    order_note: str = ""

    def region(self, role: str) -> Rect:
        return dict(self.regions)[role]

    def role_of(self, component: str) -> str | None:
        """The role the grammar gives ``component`` (None: not named)."""
        for role, names in self.components:
            if component in names:
                return role
        return None

    def candidates(self) -> tuple[str, ...]:
        """The primary role's components, the first a configuration shows winning."""
        return dict(self.components).get("primary", ())


# The grammar of a presentation file without one (and of the shipped file, which spells it
# out): controls docked left, the primary view centre, secondary views in a right column.
DEFAULT_GRAMMAR = Grammar(
    screen=(1920, 1080),
    regions=(
        ("primary", Rect(20, 0, 62.5, 80)),
        ("secondary", Rect(82.5, 0, 17.5, 80)),
        ("controls", Rect(0, 0, 20, 100)),
        ("status", Rect(20, 80, 80, 20)),
    ),
    components=(
        ("primary", ("visual display", "spherical display", "point cloud")),
        ("secondary", ()),
        ("controls", ("Flight", "Driving", "Walking", "Joint", "End Effector", "Waypoint")),
        ("status", ("teleoperated", "shared", "supervisory")),
    ),
    cuts=Cut(
        "row",
        20.0,
        "controls",
        Cut("column", 80.0, Cut("row", 78.125, "primary", "secondary"), "status"),
    ),
)


def read_grammar(reader: Reader) -> Grammar:
    """The ``grammar:`` of a presentation (its faults recorded in ``reader``); the default
    grammar when there is none. A role may name components a rule set lacks: one grammar
    serves every rule set (the shipped one names the extended rule set's autonomy levels)."""
    if reader.get(("grammar",)) is None:
        return DEFAULT_GRAMMAR
    top = reader.mapping(("grammar",), "grammar")
    reader.unknown_keys(("grammar",), top, _KEYS, "grammar field")
    screen = _screen(reader)
    roles = reader.mapping(("grammar", "roles"), "grammar roles")
    reader.unknown_keys(("grammar", "roles"), roles, ROLES, "role")
    regions: list[tuple[str, Rect]] = []
    components: list[tuple[str, tuple[str, ...]]] = []
    seen: dict[str, str] = {}
    for role in ROLES:
        if role not in roles:
            reader.missing(("grammar", "roles", role), f"role {role!r}")
            continue
        path: tuple[PathPart, ...] = ("grammar", "roles", role)
        reader.unknown_keys(path, reader.mapping(path, f"role {role!r}"), _ROLE_KEYS, "field")
        rect = _rect(reader, (*path, "region"))
        if rect is not None:
            regions.append((role, rect))
        names = _components(reader, (*path, "components"), role, seen)
        components.append((role, names))
    _sizes(reader, screen, regions)
    order, priority = _clusters(reader)
    cuts: Cut | str = "primary"
    if len(regions) == len(ROLES):
        cuts = _fit(reader, regions)
    line = reader.document.location(("grammar", "clusters", "order")).line
    return Grammar(
        screen, tuple(regions), tuple(components), cuts, order, priority, order_line=line
    )


def _screen(reader: Reader) -> tuple[int, int]:
    path: tuple[PathPart, ...] = ("grammar", "screen")
    if reader.get(path) is None:
        return DEFAULT_GRAMMAR.screen
    reader.unknown_keys(path, reader.mapping(path, "screen"), ("width", "height"), "field")
    sizes = []
    for key, default in zip(("width", "height"), DEFAULT_GRAMMAR.screen, strict=True):
        value = reader.integer((*path, key), f"screen {key}")
        if value is not None and not 100 <= value <= 100_000:
            reader.fault((*path, key), f"screen {key} must be 100..100000 pixels, got {value}")
            value = None
        # A screen that cannot be read is said once; the regions are measured at the default.
        sizes.append(value or default)
    return sizes[0], sizes[1]


def _rect(reader: Reader, path: tuple[PathPart, ...]) -> Rect | None:
    value = reader.mapping(path, "region")
    if not isinstance(reader.get(path), dict):
        return None  # missing, or no mapping: said once
    reader.unknown_keys(path, value, _RECT_KEYS, "region field")
    numbers: list[float] = []
    for key in _RECT_KEYS:
        item = value.get(key)
        if isinstance(item, bool) or not isinstance(item, int | float) or not 0 <= item <= 100:
            reader.fault(
                (*path, key),
                f"region {key} must be a percentage of the screen (0..100), "
                f"got {shown(item, quoted=True)}",
                code="wrong-type",
            )
            return None
        numbers.append(float(item))
    rect = Rect(*numbers)
    if rect.width <= 0 or rect.height <= 0:
        reader.fault(path, "a region needs a width and a height above 0")
        return None
    if rect.x + rect.width > 100 + _EPSILON or rect.y + rect.height > 100 + _EPSILON:
        reader.fault(
            path,
            f"the region does not fit on the screen: x + width = {rect.x + rect.width:g}%, "
            f"y + height = {rect.y + rect.height:g}% (at most 100%)",
        )
        return None
    return rect


def _sizes(reader: Reader, screen: tuple[int, int], regions: list[tuple[str, Rect]]) -> None:
    """A fault for each region a tile of the smallest size (``checks/quality.yaml``) does not
    fit in, at the grammar's screen: every layout it laid out would fail the quality check."""
    smallest = quality_rules()["smallest_tile"]
    for role, rect in regions:
        width, height = rect.width * screen[0] / 100, rect.height * screen[1] / 100
        if width < smallest["width"] - _EPSILON or height < smallest["height"] - _EPSILON:
            reader.fault(
                ("grammar", "roles", role, "region"),
                f"the {role} region is {width:g}x{height:g} pixels at {screen[0]}x{screen[1]}, "
                f"smaller than the smallest tile, {smallest['width']}x{smallest['height']} "
                "(solver/layouts/checks/quality.yaml)",
            )


def _components(
    reader: Reader,
    path: tuple[PathPart, ...],
    role: str,
    seen: dict[str, str],
) -> tuple[str, ...]:
    if reader.get(path) is None:
        return ()
    names: list[str] = []
    for item_path, name in reader.names(path, f"the {role} role's components"):
        if name in seen:
            reader.fault(
                item_path,
                f"component {shown(name, quoted=True)} already has the role {seen[name]!r}",
                code="duplicate",
            )
            continue
        seen[name] = role
        names.append(name)
    return tuple(names)


def _clusters(reader: Reader) -> tuple[str, tuple[str, ...]]:
    path: tuple[PathPart, ...] = ("grammar", "clusters")
    if reader.get(path) is None:
        return "alphabetical", ()
    reader.unknown_keys(path, reader.mapping(path, "clusters"), _CLUSTER_KEYS, "field")
    order = reader.string((*path, "order"), "cluster order", required=False, default="")
    order = order or "alphabetical"
    if order not in ORDERS:
        reader.fault(
            (*path, "order"),
            f"unknown cluster order {shown(order, quoted=True)}; known: " + ", ".join(ORDERS),
            code="unknown-reference",
        )
    priority: tuple[str, ...] = ()
    if reader.get((*path, "priority")) is not None:
        priority = tuple(name for _, name in reader.names((*path, "priority"), "priority"))
    if order == "priority" and not priority:
        reader.fault(
            (*path, "order"),
            "the priority order needs a priority: list (topics or sensors, most used first)",
            code="missing-field",
        )
    return order, priority


def _fit(reader: Reader, regions: list[tuple[str, Rect]]) -> Cut | str:
    """The cuts that separate the regions; faults where they overlap, leave a gap or cannot
    be separated by straight cuts."""
    path: tuple[PathPart, ...] = ("grammar", "roles")
    for index, (role, rect) in enumerate(regions):
        for other, other_rect in regions[index + 1 :]:
            if rect.overlaps(other_rect):
                reader.fault(
                    (*path, other, "region"), f"the {other} region overlaps the {role} region"
                )
                return "primary"
    covered = sum(rect.area for _, rect in regions) / 100
    if abs(covered - 100) > _EPSILON:
        reader.fault(
            path,
            f"the regions cover {covered:g}% of the screen; together they must fill it (100%)",
        )
        return "primary"
    cuts = _cut(regions, Rect(0, 0, 100, 100))
    if cuts is None:
        reader.fault(path, "the regions cannot be separated by straight cuts across the screen")
        return "primary"
    return cuts


def _cut(regions: list[tuple[str, Rect]], box: Rect) -> Cut | str | None:
    """A guillotine cut of ``box`` holding exactly ``regions`` (None: there is none)."""
    if len(regions) == 1:
        return regions[0][0]
    for direction in ("row", "column"):
        for _, rect in regions:
            at = rect.x if direction == "row" else rect.y
            start, size = (box.x, box.width) if direction == "row" else (box.y, box.height)
            if at - start <= _EPSILON:
                continue
            first = [item for item in regions if _end(item[1], direction) <= at + _EPSILON]
            second = [item for item in regions if _start(item[1], direction) >= at - _EPSILON]
            if len(first) + len(second) != len(regions):
                continue
            one, two = _halves(box, direction, at)
            a, b = _cut(first, one), _cut(second, two)
            if a is not None and b is not None:
                return Cut(direction, round(100 * (at - start) / size, 4), a, b)
    return None


def _start(rect: Rect, direction: str) -> float:
    return rect.x if direction == "row" else rect.y


def _end(rect: Rect, direction: str) -> float:
    return rect.x + rect.width if direction == "row" else rect.y + rect.height


def _halves(box: Rect, direction: str, at: float) -> tuple[Rect, Rect]:
    if direction == "row":
        return (
            Rect(box.x, box.y, at - box.x, box.height),
            Rect(at, box.y, box.x + box.width - at, box.height),
        )
    return (
        Rect(box.x, box.y, box.width, at - box.y),
        Rect(box.x, at, box.width, box.y + box.height - at),
    )


def prune(cuts: Cut | str, used: set[str]) -> Cut | str | None:
    """The cuts with only the ``used`` roles: an unused region's room goes to its neighbour."""
    if isinstance(cuts, str):
        return cuts if cuts in used else None
    first, second = prune(cuts.first, used), prune(cuts.second, used)
    if first is None:
        return second
    if second is None:
        return first
    return Cut(cuts.direction, cuts.percent, first, second)
