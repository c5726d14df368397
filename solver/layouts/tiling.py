"""The sensor-count arrangement as tiles, and panels arranged as a balanced split tree.

The article's g(i) clusters of a configuration are the number of tiles of its sensor panel:
1..5 sensors are shown individually, above that one tile per cluster. A rule set of its own may
cluster far more finely than the article; past :data:`MAX_TILES` tiles a screen shows nothing
useful and a layout of 100,000 panels is a denial of service, so the tiles stop there. Not
here: panel configs.
"""

from __future__ import annotations

from typing import Any

from solver.core.partition import Configuration
from solver.core.ruleset import RuleSet

__all__ = ["MAX_TILES", "split_tree", "tiles"]

# The most tiles one sensor panel gets (the article's arrangements never need more than 5).
MAX_TILES = 25


def tiles(rules: RuleSet, configuration: Configuration) -> int:
    """Tiles of the sensor panel: the most clusters the configuration's sensor counts take,
    at most :data:`MAX_TILES`."""
    for position, characteristic in enumerate(rules.characteristics):
        if characteristic.kind == "integer":
            return min(max(1, configuration.clusters(position)[1]), MAX_TILES)
    return 1


def split_tree(ids: list[str], depth: int = 0) -> Any:
    """A Foxglove layout tree over ``ids``: halves split row, then column, alternating."""
    if len(ids) == 1:
        return ids[0]
    half = (len(ids) + 1) // 2
    return {
        "direction": "row" if depth % 2 == 0 else "column",
        "first": split_tree(ids[:half], depth + 1),
        "second": split_tree(ids[half:], depth + 1),
        "splitPercentage": round(100 * half / len(ids), 2),
    }
