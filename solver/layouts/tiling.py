"""The sensor-count arrangement: how many sensors a layout shows, and in clusters of how many.

The article's Equation (2): up to five sensors are shown individually, more are grouped into
g(i) = ceil(i / cluster_size) clusters, so that up to fifty sensors never take more than five
components on the screen. A layout shows each sensor (its own topic) and groups them into
those clusters (a Tab panel in Lichtblick, a display group in RViz2:
:mod:`solver.layouts.design`). A rule set of its own may cluster far more finely than the
article; past :data:`MAX_TILES` clusters, or :data:`MAX_TABS` sensors in one cluster, a screen
shows nothing useful and a layout of 100,000 panels is a denial of service, so they stop there.
Not here: where the clusters go (:mod:`solver.layouts.design`).
"""

from __future__ import annotations

from solver.core.partition import Configuration
from solver.core.ruleset import RuleSet

__all__ = ["MAX_TABS", "MAX_TILES", "capped", "cluster_size", "tiles"]

# The most clusters one sensor component gets (the article's arrangements never need more than 5).
MAX_TILES = 25
# The most sensors one cluster shows (the article's largest cluster holds 10).
MAX_TABS = 25


def cluster_size(rules: RuleSet, configuration: Configuration | None) -> int:
    """How many sensors one cluster of ``configuration`` holds (1: shown individually)."""
    if configuration is None:
        return 1
    for position, characteristic in enumerate(rules.characteristics):
        if characteristic.kind == "integer":
            return max(1, configuration.components[position].cluster_size)
    return 1


def capped(count: int, size: int) -> int:
    """``count`` sensors in clusters of ``size``, at most :data:`MAX_TILES` clusters of at
    most :data:`MAX_TABS` sensors."""
    return max(1, min(count, MAX_TILES * min(size, MAX_TABS)))


def tiles(rules: RuleSet, configuration: Configuration) -> int:
    """Sensors the configuration's layout shows: the most its robots have, capped."""
    for position, characteristic in enumerate(rules.characteristics):
        if characteristic.kind == "integer":
            most = max((int(value) for value in configuration.served[position]), default=1)
            return capped(most, cluster_size(rules, configuration))
    return 1
