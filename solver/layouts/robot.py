"""One robot's layout: its configuration's panels under its own namespace, fed by its real
topics where a topic list or a bag gives them (``teleop-ui layouts --robot``).

The robot's combination (kinematic type, first control mode, first sensor type, sensor count:
the one it starts in) is chosen by identification (:mod:`solver.identify.combinations`) and
assigned against the team before it comes here; this module only lays the configuration out.

Not here: a whole team's layouts (:mod:`solver.layouts.writer`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from solver.errors import Fault
from solver.layouts.plan import Robot, panel_entries
from solver.layouts.presentation import Presentation
from solver.layouts.targets import target
from solver.layouts.tiling import capped
from solver.layouts.topics import match_topics
from solver.ros.joints import JointStart
from solver.ros.names import Topic
from solver.solving.assignment import Assignment
from solver.solving.solution import Solution

__all__ = ["RobotLayout", "robot_layout"]


@dataclass(frozen=True)
class RobotLayout:
    """The validated file text, and a warning per panel no real topic fitted."""

    text: str
    warnings: tuple[Fault, ...]


def _tile_count(solution: Solution, assignment: Assignment) -> int | None:
    """The robot's own number of sensors shown: its count, capped (:mod:`.tiling`)."""
    configuration = assignment.configuration
    if configuration is None:
        return None
    given = dict(assignment.given)
    for position, characteristic in enumerate(solution.rules.characteristics):
        if characteristic.kind == "integer" and characteristic.name in given:
            size = configuration.components[position].cluster_size
            return capped(int(given[characteristic.name]), size)
    return None


def robot_layout(
    solution: Solution,
    assignment: Assignment,
    presentation: Presentation,
    fmt: str = "foxglove",
    *,
    namespace: str,
    topics: Sequence[Topic] | None = None,
    topics_source: str = "<topics>",
    joints: Sequence[JointStart] | None = None,
    file: str = "<layout>",
) -> RobotLayout:
    """The layout of ``assignment``'s configuration for the robot under ``namespace``
    (``/name``); with ``topics``, panels take the robot's real topics; ``joints`` (from its
    description) fill a joint command."""
    tile_count = _tile_count(solution, assignment)
    real: dict[tuple[str, int], Topic] = {}
    warnings: tuple[Fault, ...] = ()
    if topics is not None:
        entries = panel_entries(solution, assignment.configuration, presentation, tile_count)
        real, warnings = match_topics(entries, topics, topics_source, namespace)
    robot = Robot(namespace, real, tuple(joints) if joints else None, described=True)
    text = target(fmt).render(
        solution,
        assignment.configuration,
        presentation,
        file=file,
        robot=robot,
        tile_count=tile_count,
    )
    return RobotLayout(text, warnings)
