"""The sensor-count arrangement as tiles, and panels arranged as a balanced split tree.

The article's g(i) clusters of a configuration are the number of tiles of its sensor panel:
1..5 sensors are shown individually, above that one tile per cluster. Not here: panel configs.
"""

from __future__ import annotations

from typing import Any

from solver.partition import Configuration
from solver.rules import RuleSet

__all__ = ["split_tree", "tiles"]


def tiles(rules: RuleSet, configuration: Configuration) -> int:
    """Tiles of the sensor panel: the most clusters the configuration's sensor counts take."""
    for position, characteristic in enumerate(rules.characteristics):
        if characteristic.kind == "integer":
            return max(1, configuration.clusters(position)[1])
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
