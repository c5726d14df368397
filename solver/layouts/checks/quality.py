"""Layout quality for an operator (issue 39), measured on the layouts as written: the primary
view's share of the screen, the smallest tile, the tiles on one screen, and a team's
consistency (a component shown by two configurations in the same region of the screen in
both). The limits are data, ``quality.yaml`` beside this module.

A Lichtblick layout is measured from its split tree laid on the screen of ``quality.yaml``
(each split divides its rectangle by its percentage, as the app does); which tile is which
component, and the grammar's regions, come from the layout's design note
(:data:`solver.layouts.foxglove.DESIGN_VARIABLE`). A tile's *region* is the region, as laid
out (a region a configuration leaves empty grown into its neighbour), it overlaps most; a
component's place is its first tile's region. A layout without a design note
(written before issue 39, or by hand) has no primary view and no places: it is measured for
its tiles only.

Not here: laying a layout out (:mod:`solver.layouts.design`); the viewers' own rules
(:mod:`solver.layouts.checks.lichtblick`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from solver.errors import Fault, Location
from solver.layouts.checks.data import quality_rules
from solver.layouts.design import Design, Split, design
from solver.layouts.foxglove import DESIGN_VARIABLE
from solver.layouts.grammar import Rect
from solver.layouts.plan import plan_layout
from solver.layouts.presentation import Presentation
from solver.solving.solution import Solution

__all__ = [
    "Consistency",
    "Quality",
    "consistency",
    "describe_consistency",
    "design_places",
    "leaf_rects",
    "measure",
    "quality_faults",
    "team_consistency",
]


@dataclass(frozen=True, slots=True)
class Quality:
    """One layout's figures at the screen of ``quality.yaml``."""

    primary_share: float  # percent of the screen the primary view takes (0: none found)
    smallest_width: float  # pixels: the narrowest tile's width
    smallest_height: float  # pixels: the shortest tile's height
    tiles: int  # tiles on the screen (a Tab panel is one)
    places: tuple[tuple[str, str], ...]  # component -> its region, in tile order


@dataclass(frozen=True, slots=True)
class Consistency:
    """A team's consistency: of every pair of configurations showing one component, how many
    put it in the same region (``same`` of ``pairs``), and the components that move."""

    same: int
    pairs: int
    moved: tuple[str, ...]

    @property
    def score(self) -> float:
        """Percent of the pairs in the same place (100 when nothing is shared)."""
        return 100.0 if self.pairs == 0 else 100.0 * self.same / self.pairs


def leaf_rects(tree: Any, width: float, height: float) -> dict[Any, Rect]:
    """Each leaf of a split tree (``{direction, first, second, splitPercentage}``) and its
    rectangle on a screen of ``width`` x ``height``."""
    found: dict[Any, Rect] = {}
    stack = [] if tree is None else [(tree, Rect(0, 0, width, height))]
    while stack:
        node, box = stack.pop()
        if isinstance(node, str | int):
            found[node] = box
            continue
        if not isinstance(node, dict):
            continue  # no panel id and no split (a hand-written layout): no tile
        share = _share(node.get("splitPercentage")) / 100
        if node.get("direction") == "row":
            first = Rect(box.x, box.y, box.width * share, box.height)
            second = Rect(box.x + first.width, box.y, box.width - first.width, box.height)
        else:
            first = Rect(box.x, box.y, box.width, box.height * share)
            second = Rect(box.x, box.y + first.height, box.width, box.height - first.height)
        stack.extend(((node.get("second"), second), (node.get("first"), first)))
    return found


def _share(value: Any) -> float:
    """A split's percentage as react-mosaic takes it: 50 where it is missing, and where a
    hand-written layout gives no percentage (a string, NaN, a number past 0..100)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return 50.0
    if isinstance(value, int):
        return float(value) if 0 <= value <= 100 else 50.0
    return value if 0 <= value <= 100 else 50.0  # NaN fails both comparisons


def measure(layout: Mapping[str, Any]) -> Quality:
    """The figures of a Lichtblick layout (parsed JSON) at the quality screen."""
    screen = quality_rules()["screen"]
    width, height = float(screen["width"]), float(screen["height"])
    rects = leaf_rects(layout.get("layout"), width, height)
    variables = layout.get("globalVariables")
    note = variables.get(DESIGN_VARIABLE) if isinstance(variables, dict) else None
    listed = note.get("tiles") if isinstance(note, dict) else None
    tiles = [t for t in listed if isinstance(t, dict)] if isinstance(listed, list) else []
    regions = _regions(note, width, height)
    primary = next((t.get("panel") for t in tiles if t.get("role") == "primary"), None)
    share = 0.0
    if isinstance(primary, str) and primary in rects:
        share = 100 * rects[primary].area / (width * height)
    places: dict[str, str] = {}
    for tile in tiles:
        panel = tile.get("panel")
        rect = rects.get(panel) if isinstance(panel, str) else None
        if rect is not None and regions:
            places.setdefault(str(tile.get("component")), _region(rect, regions))
    return Quality(
        round(share, 2),
        round(min((r.width for r in rects.values()), default=0.0), 1),
        round(min((r.height for r in rects.values()), default=0.0), 1),
        len(rects),
        tuple(places.items()),
    )


def quality_faults(quality: Quality, file: str = "<layout>") -> tuple[Fault, ...]:
    """Every limit of ``quality.yaml`` the figures break, located at the layout."""
    rules = quality_rules()
    smallest = rules["smallest_tile"]
    where = Location(file, path="layout")
    faults: list[Fault] = []
    if quality.primary_share < rules["primary_share"]:
        faults.append(
            Fault(
                where,
                f"the primary view takes {quality.primary_share:g}% of the screen, "
                f"less than {rules['primary_share']}%",
                "quality-primary",
            )
        )
    if quality.smallest_width < smallest["width"] or quality.smallest_height < smallest["height"]:
        faults.append(
            Fault(
                where,
                f"a tile is {quality.smallest_width:g}x{quality.smallest_height:g} pixels at "
                f"{rules['screen']['width']}x{rules['screen']['height']}, smaller than "
                f"{smallest['width']}x{smallest['height']}",
                "quality-tile",
            )
        )
    if quality.tiles > rules["panels_per_screen"]:
        faults.append(
            Fault(
                where,
                f"{quality.tiles} tiles on one screen, more than {rules['panels_per_screen']}",
                "quality-panels",
            )
        )
    return tuple(faults)


def design_places(laid: Design) -> dict[str, str]:
    """Component -> region of a design, measured as :func:`measure` measures a layout."""
    width, height = (float(side) for side in laid.grammar.screen)
    rects = leaf_rects(_as_tree(laid.tree), width, height)
    regions = [
        (
            role,
            Rect(
                r.x * width / 100,
                r.y * height / 100,
                r.width * width / 100,
                r.height * height / 100,
            ),
        )
        for role, r in laid.regions
    ]
    places: dict[str, str] = {}
    for index, tile in enumerate(laid.tiles):
        for component in tile.components:
            places.setdefault(component, _region(rects[index], regions))
    return places


def consistency(places: Iterable[Mapping[str, str]]) -> Consistency:
    """The consistency of configurations' places (component -> region, one mapping each)."""
    seen: dict[str, dict[str, int]] = {}
    for mapping in places:
        for component, region in mapping.items():
            counts = seen.setdefault(component, {})
            counts[region] = counts.get(region, 0) + 1
    same = pairs = 0
    moved: list[str] = []
    for component, counts in seen.items():
        total = sum(counts.values())
        pairs += total * (total - 1) // 2
        same += sum(n * (n - 1) // 2 for n in counts.values())
        if len(counts) > 1:
            moved.append(component)
    return Consistency(same, pairs, tuple(sorted(moved)))


def team_consistency(solution: Solution, presentation: Presentation) -> Consistency:
    """The consistency of a team's UI configurations as ``presentation`` lays them out, the
    default configuration (every component at once, given to every robot the team does not
    know) counted with them: operators switch to it too."""
    return consistency(
        design_places(design(plan_layout(solution, configuration, presentation)))
        for configuration in (*solution.configurations, None)
    )


def describe_consistency(found: Consistency) -> str:
    """One line for ``teleop-ui layouts``: the score, what it counts, and what moves."""
    text = (
        f"consistency: {found.score:.1f}% ({found.same} of {found.pairs} pairs of configurations "
        "sharing a component put it in the same region)"
    )
    if found.moved:
        text += "; moved: " + ", ".join(found.moved)
    return text


def _as_tree(node: Split | int | None) -> Any:
    """The split tree as a layout writes it, each leaf the tile's number."""
    if node is None or isinstance(node, int):
        return node
    return {
        "direction": node.direction,
        "first": _as_tree(node.first),
        "second": _as_tree(node.second),
        "splitPercentage": node.percent,
    }


def _regions(note: Any, width: float, height: float) -> list[tuple[str, Rect]]:
    regions = note.get("regions") if isinstance(note, dict) else None
    if not isinstance(regions, dict):
        return []
    found = []
    for role, box in regions.items():
        if isinstance(box, list) and len(box) == 4 and all(_percent(v) for v in box):
            x, y, w, h = (float(v) for v in box)
            found.append(
                (
                    str(role),
                    Rect(x * width / 100, y * height / 100, w * width / 100, h * height / 100),
                )
            )
    return found


def _percent(value: Any) -> bool:
    """A number of 0..100 (not a bool, NaN or one past a float)."""
    return not isinstance(value, bool) and isinstance(value, int | float) and 0 <= value <= 100


def _region(rect: Rect, regions: list[tuple[str, Rect]]) -> str:
    """The region ``rect`` overlaps most (the first on a tie)."""
    best, most = "", -1.0
    for role, region in regions:
        across = min(rect.x + rect.width, region.x + region.width) - max(rect.x, region.x)
        down = min(rect.y + rect.height, region.y + region.height) - max(rect.y, region.y)
        overlap = max(0.0, across) * max(0.0, down)
        if overlap > most:
            best, most = role, overlap
    return best
