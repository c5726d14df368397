"""Foxglove / Lichtblick "classic" layout JSON, one per UI configuration, and its validation.

A layout is ``{"configById": {"Type!id": {...}}, "layout": tree, ...}`` where the tree is a
panel id or ``{direction, first, second, splitPercentage}``. Panel ids are numbered in panel
order, so the same configuration always gives the same bytes. Teleop panels publish only while
a button is held (the viewer stops on release); no panel publishes on its own.

Not here: the component -> panel mapping (:mod:`solver.layouts.presentation`, data).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from solver.core.partition import Configuration
from solver.core.solution import Solution
from solver.errors import Fault, Location, SolverError
from solver.layouts.presentation import PANEL_TYPES, PanelSpec, Presentation
from solver.layouts.tiling import split_tree, tiles
from solver.untrusted import shown

__all__ = [
    "LayoutError",
    "foxglove_layout",
    "layout_filename",
    "panel_entries",
    "template_topic",
    "validate_foxglove",
]


class LayoutError(SolverError, ValueError):
    """A layout breaks a rule its viewer enforces."""


def layout_filename(number: int, *, default: bool = False, extension: str = "json") -> str:
    """The file name of configuration ``number``'s layout (``watch`` names it in its events)."""
    return f"config-{number:03d}{'-default' if default else ''}.{extension}"


def panel_entries(
    solution: Solution,
    configuration: Configuration | None,
    profile: Presentation,
    tile_count: int | None = None,
) -> list[tuple[PanelSpec, int]]:
    """Each panel spec of ``configuration`` and its number of tiles, in panel order.

    ``None`` is the default configuration: every component, one tile each.
    """
    rules = solution.rules
    entries: list[tuple[PanelSpec, int]] = []
    if configuration is None:
        for characteristic in rules.characteristics[1:]:
            if characteristic.kind == "integer":
                continue
            entries.extend(
                (profile.spec(component.name), 1) for component in characteristic.components
            )
        return entries
    # One robot shows its own g(i) tiles; a template, the most its configuration needs.
    count = tile_count if tile_count is not None else tiles(rules, configuration)
    # Position 0 is the kinematic type (the layout's subject, not a panel); the integer
    # characteristic is the tiling of the sensor panel, not a panel of its own.
    sensor_position = next(
        (position for position, c in enumerate(rules.characteristics) if c.name == "sensor_type"),
        -1,
    )
    for position, component in enumerate(configuration.components):
        characteristic = rules.characteristics[position]
        if position == 0 or characteristic.kind == "integer":
            continue
        entries.append((profile.spec(component.name), count if position == sensor_position else 1))
    return entries


def template_topic(spec: PanelSpec, robot: str, tile: int, count: int) -> str:
    """The profile's topic under ``robot``; tiles after the first get ``_2``, ``_3``, ..."""
    return spec.topic.replace("<robot>", robot) + (f"_{tile + 1}" if count > 1 else "")


def foxglove_layout(
    solution: Solution,
    configuration: Configuration | None,
    profile: Presentation,
    *,
    robot: str = "<robot>",
    tile_count: int | None = None,
    topics: Mapping[tuple[str, int], str] | None = None,
) -> dict[str, Any]:
    """The layout of ``configuration`` (``None``: the default configuration, every component).

    ``topics`` maps (component, tile) to a robot's real topic; a panel not in it keeps the
    profile's template (see :func:`solver.layouts.topics.match_topics`).
    """
    config_by_id: dict[str, Any] = {}
    ids: list[str] = []
    for spec, count in panel_entries(solution, configuration, profile, tile_count):
        for tile in range(count):
            panel_id = f"{spec.panel}!p{len(ids) + 1:02d}"
            suffix = f" {tile + 1}" if count > 1 else ""
            topic = (topics or {}).get((spec.component, tile)) or template_topic(
                spec, robot, tile, count
            )
            config_by_id[panel_id] = _panel_config(spec, topic, suffix)
            ids.append(panel_id)
    return {
        "configById": config_by_id,
        "globalVariables": {},
        "userNodes": {},
        "playbackConfig": {"speed": 1},
        "layout": split_tree(ids) if ids else None,
    }


def _panel_config(spec: PanelSpec, topic: str, suffix: str) -> dict[str, Any]:
    title = spec.component + suffix
    if spec.placeholder:
        title += " (placeholder: no panel for this component)"
    # Foxglove Studio reads the panel title from "foxglovePanelTitle", Lichtblick (its fork)
    # from "lichtblickPanelTitle" (packages/suite-base/src/util/layout.ts); each ignores the other.
    config: dict[str, Any] = {"foxglovePanelTitle": title, "lichtblickPanelTitle": title}
    if spec.panel == "Image":
        config["imageMode"] = {"imageTopic": topic}
    elif spec.panel == "3D":
        config["topics"] = {topic: {"visible": True}}
        if "PoseStamped" in " ".join(spec.types):
            config["publish"] = {"type": "pose", "poseTopic": topic}
    elif spec.panel == "Teleop":
        # Publishes only while a button is held; releasing it stops publishing.
        config.update(
            {
                "topic": topic,
                "publishRate": 5,
                "upButton": {"field": "linear-x", "value": 0.5},
                "downButton": {"field": "linear-x", "value": -0.5},
                "leftButton": {"field": "angular-z", "value": 0.5},
                "rightButton": {"field": "angular-z", "value": -0.5},
            }
        )
    elif spec.panel == "Plot":
        # Plot paths are {value, enabled, timestampMethod} (Lichtblick/webviz PlotConfig).
        config["paths"] = [
            {
                "value": f"{topic}.wrench.force.{axis}",
                "enabled": True,
                "timestampMethod": "receiveTime",
            }
            for axis in "xyz"
        ]
    elif spec.panel == "Publish":
        # A message goes out only when the operator presses the button.
        config.update(
            {
                "topicName": topic,
                "datatype": spec.types[0] if spec.types else "",
                "buttonText": "Publish",
                "advancedView": True,
            }
        )
    elif spec.panel == "Indicator":
        # Lichtblick's IndicatorConfig: path, style, rules, fallbackColor, fallbackLabel.
        config.update(
            {
                "path": topic,
                "style": "bulb",
                "rules": [],
                "fallbackColor": "#a0a0a0",
                "fallbackLabel": "no data",
            }
        )
    else:
        config["topicPath"] = topic
    return config


def validate_foxglove(layout: dict[str, Any], file: str = "<layout>") -> None:
    """Every tree id has a config, no orphan configs, unique ids, splits 0..100, known types."""
    faults: list[Fault] = []
    seen: list[str] = []

    def walk(node: Any, path: str) -> None:
        if isinstance(node, str):
            seen.append(node)
            return
        if not isinstance(node, dict):
            faults.append(Fault(Location(file, path=path), "not a panel id or split"))
            return
        split = node.get("splitPercentage", 50)
        if not isinstance(split, (int, float)) or not 0 <= split <= 100:
            faults.append(
                Fault(
                    Location(file, path=f"{path}.splitPercentage"),
                    f"split percentage must be in 0..100 (got {shown(split, quoted=True)})",
                )
            )
        if node.get("direction") not in ("row", "column"):
            faults.append(
                Fault(
                    Location(file, path=f"{path}.direction"), "direction must be 'row' or 'column'"
                )
            )
        walk(node.get("first"), f"{path}.first")
        walk(node.get("second"), f"{path}.second")

    configs = layout.get("configById", {})
    if layout.get("layout") is not None:
        walk(layout["layout"], "layout")
    for panel_id in sorted(set(seen)):
        if seen.count(panel_id) > 1:
            faults.append(
                Fault(Location(file, path="layout"), f"duplicate id {shown(panel_id, quoted=True)}")
            )
        if panel_id not in configs:
            faults.append(
                Fault(
                    Location(file, path="layout"), f"{shown(panel_id, quoted=True)} has no config"
                )
            )
    for panel_id in configs:
        if panel_id not in seen:
            faults.append(Fault(Location(file, path=f"configById.{panel_id}"), "orphan config"))
        if panel_id.partition("!")[0] not in PANEL_TYPES:
            faults.append(
                Fault(Location(file, path=f"configById.{panel_id}"), "unknown panel type")
            )
    if faults:
        raise LayoutError(faults)
