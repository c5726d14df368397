"""A plan laid out by the presentation grammar: tiles, their roles, and the splits between them.

Every target draws a :class:`Design`, so a Lichtblick layout, an RViz2 file and the HTML
preview of one configuration agree (the same tiles, in the same regions, in the same order):

- a *tile* is one panel, or one of Equation (2)'s clusters of sensors (a Tab panel in
  Lichtblick, a display group in RViz2);
- the *primary* view is the first tile of the first component the grammar's primary role
  names that the plan shows (the main camera, else the point cloud's 3D view); where the plan
  shows none of them, the first sensor tile (of the ``sensor_type`` characteristic); the
  primary component's other clusters and every other sensor are *secondary*; a component the
  grammar gives a role keeps it; one it does not name is a *control* if it is a motion control
  (of ``motion_control``) or sends to the robot (:func:`solver.layouts.plan.is_command`),
  else secondary;
- the regions are cut as the grammar cuts them, a region without tiles giving its room to
  its neighbour (:func:`solver.layouts.grammar.prune`); the tiles of one region are stacked
  in equal shares along its longer side (at the grammar's screen size), as many as fit at
  the smallest tile ``checks/quality.yaml`` allows; the rest share the last place as the
  tabs of one Tab panel (an *overflow* tile, ``more: ...``).

A component's region depends on its role only, never on what else a configuration shows, so
a component shared by two configurations sits in the same region in both (measured by
:mod:`solver.layouts.checks.quality`). The one plan that shows several primary views at once
(the default configuration: every component, each sensor the primary view of the
configurations that show it) puts them all in the primary region, the first tile of each a tab
of one Tab panel, the grammar's first first: no component changes region when an operator
switches to it.

Not here: which panels (:mod:`solver.layouts.plan`); the grammar's file
(:mod:`solver.layouts.grammar`).
"""

from __future__ import annotations

from dataclasses import dataclass

from solver.layouts.checks.data import quality_rules
from solver.layouts.grammar import Cut, Grammar, Rect, prune
from solver.layouts.plan import Panel, Plan, is_command

__all__ = ["Design", "Split", "Tile", "design"]


@dataclass(frozen=True, slots=True)
class Tile:
    """One place on the screen: a panel, one of Equation (2)'s clusters of sensors, or the
    tiles a region has no room for (``overflow``), each a tab of one Tab panel."""

    role: str
    panels: tuple[Panel, ...]
    overflow: bool = False
    # The first tiles of several components that each own this region in a configuration of
    # their own (the default configuration's primary views), each a tab of one Tab panel.
    together: bool = False

    @property
    def component(self) -> str:
        return self.panels[0].spec.component

    @property
    def components(self) -> tuple[str, ...]:
        """The components it shows, in order (several for an overflow tile)."""
        return tuple(dict.fromkeys(panel.spec.component for panel in self.panels))

    @property
    def cluster(self) -> int:
        return 0 if self.overflow or self.together else self.panels[0].cluster

    @property
    def grouped(self) -> bool:
        """Several panels in one tile (a Tab panel, a display group)."""
        return self.overflow or self.together or bool(self.cluster)

    @property
    def title(self) -> str:
        """``visual display 3`` for a panel; ``visual display, cluster 2 (3, 4)`` for a cluster;
        ``more: audio, haptic`` for an overflow tile; ``visual display | point cloud`` for
        primary views together."""
        if self.together:
            return " | ".join(panel.name for panel in self.panels)
        if self.overflow:
            return "more: " + ", ".join(panel.name for panel in self.panels)
        if not self.cluster:
            return self.panels[0].name
        numbers = ", ".join(panel.name.rpartition(" ")[2] for panel in self.panels)
        return f"{self.component}, cluster {self.cluster} ({numbers})"


@dataclass(frozen=True, slots=True)
class Split:
    """``first`` left of (``row``) or above (``column``) ``second``; ``percent`` to ``first``.
    A leaf is the index of a tile in :attr:`Design.tiles`."""

    direction: str
    percent: float
    first: Split | int
    second: Split | int


@dataclass(frozen=True, slots=True)
class Design:
    """The tiles in region order (primary, secondary, controls, status) and their splits."""

    tiles: tuple[Tile, ...]
    tree: Split | int | None
    grammar: Grammar
    # The regions as laid out, in percent of the screen: the grammar's regions that hold
    # tiles, each grown by the room of the empty regions pruned into it.
    regions: tuple[tuple[str, Rect], ...] = ()


def design(plan: Plan) -> Design:
    """The plan laid out by its grammar (see the module docstring)."""
    grammar = plan.grammar
    tiles = _roles(_tiles(plan.panels), grammar)
    ordered = tuple(
        tile
        for role in _ORDER
        for tile in _fitted([t for t in tiles if t.role == role], _room(grammar, role))
    )
    regions: dict[str, list[int]] = {}
    for index, tile in enumerate(ordered):
        regions.setdefault(tile.role, []).append(index)
    cuts = prune(grammar.cuts, set(regions))
    tree = None if cuts is None else _tree(cuts, regions, grammar)
    laid = () if cuts is None else tuple(_laid(cuts, Rect(0, 0, 100, 100)))
    return Design(ordered, tree, grammar, laid)


def _laid(cuts: Cut | str, box: Rect) -> list[tuple[str, Rect]]:
    """Each region of ``cuts`` and the rectangle it takes of ``box``, cut as the tree cuts."""
    if isinstance(cuts, str):
        return [(cuts, box)]
    share = cuts.percent / 100
    if cuts.direction == "row":
        first = Rect(box.x, box.y, box.width * share, box.height)
        second = Rect(box.x + first.width, box.y, box.width - first.width, box.height)
    else:
        first = Rect(box.x, box.y, box.width, box.height * share)
        second = Rect(box.x, box.y + first.height, box.width, box.height - first.height)
    return [*_laid(cuts.first, first), *_laid(cuts.second, second)]


_ORDER = ("primary", "secondary", "controls", "status")
# The characteristics whose components are sensors and motion controls (the article's names,
# as every shipped rule set spells them).
SENSORS = "sensor_type"
MOTIONS = "motion_control"


def _room(grammar: Grammar, role: str) -> int:
    """How many tiles of the smallest size (``checks/quality.yaml``) the role's region holds
    stacked along its longer side, at the grammar's screen (at least one)."""
    smallest = quality_rules()["smallest_tile"]
    rect = grammar.region(role)
    width = rect.width * grammar.screen[0] / 100
    height = rect.height * grammar.screen[1] / 100
    if width >= height:
        return max(1, int(width // smallest["width"]))
    return max(1, int(height // smallest["height"]))


def _fitted(tiles: list[Tile], room: int) -> list[Tile]:
    """The tiles of one region; past its room, the last place is one overflow tile."""
    if len(tiles) <= room:
        return tiles
    kept, rest = tiles[: room - 1], tiles[room - 1 :]
    panels = tuple(panel for tile in rest for panel in tile.panels)
    return [*kept, Tile(rest[0].role, panels, overflow=True)]


def _tiles(panels: tuple[Panel, ...]) -> list[tuple[Panel, ...]]:
    """The panels as tiles: a cluster's sensors together, every other panel alone."""
    tiles: list[tuple[Panel, ...]] = []
    for panel in panels:
        last = tiles[-1][0] if tiles else None
        same = last is not None and last.spec.component == panel.spec.component
        if panel.cluster and same and last is not None and last.cluster == panel.cluster:
            tiles[-1] = (*tiles[-1], panel)
        else:
            tiles.append((panel,))
    return tiles


def _roles(tiles: list[tuple[Panel, ...]], grammar: Grammar) -> list[Tile]:
    primary = _primary(tiles, grammar)
    views = _views(tiles, grammar) if primary is not None else []
    made: list[Tile] = []
    for index, panels in enumerate(tiles):
        if index == primary and len(views) > 1:
            together = tuple(panel for view in views for panel in tiles[view])
            made.append(Tile("primary", together, together=True))
            continue
        if index == primary:
            made.append(Tile("primary", panels))
            continue
        if index in views:
            continue  # a tab of the primary views' Tab panel
        role = grammar.role_of(panels[0].spec.component) or _unnamed(panels[0])
        made.append(Tile("secondary" if role == "primary" else role, panels))
    return made


def _primary(tiles: list[tuple[Panel, ...]], grammar: Grammar) -> int | None:
    """The primary tile's index: the first candidate the plan shows, else the first sensor."""
    components = [panels[0].spec.component for panels in tiles]
    for candidate in grammar.candidates():
        if candidate in components:
            return components.index(candidate)
    for index, panels in enumerate(tiles):
        if panels[0].characteristic == SENSORS:
            return index
    return None


def _views(tiles: list[tuple[Panel, ...]], grammar: Grammar) -> list[int]:
    """The first tile of each component that is the primary view of a configuration showing
    it alone (one of the grammar's primary list, or a sensor the grammar gives no other
    role), the grammar's first first: several of them (the default configuration) share the
    primary region as tabs, so that none moves from the centre. (A sensor the grammar puts
    elsewhere stays there, and moves when it is a configuration's only sensor: the
    consistency score names it.)"""
    rank = {name: index for index, name in enumerate(grammar.candidates())}
    first: dict[str, int] = {}
    for index, panels in enumerate(tiles):
        component = panels[0].spec.component
        sensor = panels[0].characteristic == SENSORS and grammar.role_of(component) is None
        if component in rank or sensor:
            first.setdefault(component, index)
    return sorted(
        first.values(), key=lambda i: (rank.get(tiles[i][0].spec.component, len(rank)), i)
    )


def _unnamed(panel: Panel) -> str:
    """The role of a component the grammar does not name: a motion control, or a panel that
    sends to the robot, is a control; anything else a secondary view."""
    return "controls" if panel.characteristic == MOTIONS or is_command(panel.spec) else "secondary"


def _tree(cuts: Cut | str, regions: dict[str, list[int]], grammar: Grammar) -> Split | int:
    if isinstance(cuts, str):
        rect = grammar.region(cuts)
        wide = rect.width * grammar.screen[0] >= rect.height * grammar.screen[1]
        return _stack(regions[cuts], "row" if wide else "column")
    return Split(
        cuts.direction,
        cuts.percent,
        _tree(cuts.first, regions, grammar),
        _tree(cuts.second, regions, grammar),
    )


def _stack(indices: list[int], direction: str) -> Split | int:
    """Tiles side by side (row) or one above the other (column), in equal shares."""
    if len(indices) == 1:
        return indices[0]
    return Split(
        direction, round(100 / len(indices), 2), indices[0], _stack(indices[1:], direction)
    )
