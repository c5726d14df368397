"""A robot's real topics in its layout's panels, in place of the profile's templates.

Each panel takes a topic whose message type is one the profile lists for its component and
whose direction fits: a command panel (Teleop, Publish, a 3D panel publishing goal poses) takes
a topic the robot subscribes to, a sensor panel one it publishes (a topic of unknown direction
fits both). Among fitting topics, one named like the template's last part comes first
(``/x/front/points`` for ``<robot>/points``), then name order; each topic serves one tile. A
panel left without a topic keeps the presentation's topic under the robot's namespace and gets
a warning located at the topic source.

Not here: reading topics (:mod:`solver.identify.readers.topics`,
:mod:`solver.identify.readers.bags`).
"""

from __future__ import annotations

from collections.abc import Sequence

from solver.errors import Fault, Location
from solver.layouts.plan import COMMAND_PANELS, is_command, template_topic
from solver.layouts.presentation import PanelSpec
from solver.ros.names import Topic, normalise_type

__all__ = ["match_topics"]


def match_topics(
    entries: Sequence[tuple[PanelSpec, int]],
    topics: Sequence[Topic],
    source: str,
    namespace: str | None = None,
) -> tuple[dict[tuple[str, int], Topic], tuple[Fault, ...]]:
    """(component, tile) -> real topic for each panel a topic fits; a warning per panel left
    (naming the topic it keeps: the presentation's, under ``namespace``).

    Command panels of one kind with one template (Flight, Driving and Walking pads on
    ``<robot>/cmd_vel``) take the same topic: they become one panel (:mod:`.plan`).
    """
    chosen: dict[tuple[str, int], Topic] = {}
    shared: dict[tuple[str, str, int], Topic | None] = {}
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
            key = (spec.panel, spec.topic, tile)
            if spec.panel in COMMAND_PANELS and key in shared:
                earlier = shared[key]
                if earlier is not None:
                    chosen[(spec.component, tile)] = earlier
                continue  # the panel it joins was warned about already
            found = fitting[tile] if tile < len(fitting) else None
            shared[key] = found
            if found is not None:
                chosen[(spec.component, tile)] = found
                used.add(found.name)
                continue
            name = spec.component + (f" {tile + 1}" if count > 1 else "")
            accepted = ", ".join(sorted(types)) or "no message type"
            kept = template_topic(spec, namespace, tile)
            warnings.append(
                Fault(
                    Location(source, path=name),
                    f"the robot has no {wanted} topic of type {accepted} for this "
                    f"{spec.panel} panel; it keeps the presentation's topic {kept}",
                    code="no-topic",
                )
            )
    return chosen, tuple(warnings)
