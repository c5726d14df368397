"""A robot's real topics in its layout's panels, in place of the profile's templates.

Each panel takes a topic whose message type is one the profile lists for its component and
whose direction fits: a command panel (Teleop, Publish, a 3D panel publishing goal poses) takes
a topic the robot subscribes to, a sensor panel one it publishes (a topic of unknown direction
fits both). Among fitting topics, one named like the template's last part comes first
(``/x/front/points`` for ``<robot>/points``), then name order; each topic serves one tile. A
panel left without a topic keeps its template and gets a warning located at the topic source.

Not here: reading topics (:mod:`solver.identify.topics`, :mod:`solver.identify.readers.bags`).
"""

from __future__ import annotations

from collections.abc import Sequence

from solver.errors import Fault, Location
from solver.layouts.presentation import PanelSpec
from solver.ros.names import Topic, normalise_type

__all__ = ["is_command", "match_topics"]


def is_command(spec: PanelSpec) -> bool:
    """Does the panel send to the robot (rather than show what the robot sends)?"""
    return spec.panel in ("Teleop", "Publish") or "geometry_msgs/PoseStamped" in spec.types


def match_topics(
    entries: Sequence[tuple[PanelSpec, int]], topics: Sequence[Topic], source: str
) -> tuple[dict[tuple[str, int], str], tuple[Fault, ...]]:
    """(component, tile) -> real topic for each panel a topic fits; a warning per panel left."""
    chosen: dict[tuple[str, int], str] = {}
    warnings: list[Fault] = []
    used: set[str] = set()
    for spec, count in entries:
        wanted = "subscribed" if is_command(spec) else "published"
        types = {normalise_type(t) for t in spec.types}
        stem = spec.topic.rstrip("/").rpartition("/")[2]
        fitting = sorted(
            (
                topic
                for topic in topics
                if normalise_type(topic.type) in types
                and topic.direction in (None, wanted)
                and topic.name not in used
            ),
            # A name ending like the template first, then name order: deterministic.
            key=lambda topic: (not topic.name.rstrip("/").endswith("/" + stem), topic.name),
        )
        for tile in range(count):
            if tile < len(fitting):
                chosen[(spec.component, tile)] = fitting[tile].name
                used.add(fitting[tile].name)
                continue
            name = spec.component + (f" {tile + 1}" if count > 1 else "")
            accepted = ", ".join(sorted(types)) or "no message type"
            warnings.append(
                Fault(
                    Location(source, path=name),
                    f"the robot has no {wanted} topic of type {accepted} for this "
                    f"{spec.panel} panel; it keeps the template {spec.topic}",
                    code="no-topic",
                )
            )
    return chosen, tuple(warnings)
