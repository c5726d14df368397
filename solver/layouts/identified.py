"""A real robot's layout from its description: identify it, give it the configuration of the
combination it starts in, lay that out under its namespace (``teleop-ui layouts --robot``).

The use case whole, for the command line and any other caller: the description is identified
against the team's rules (:func:`solver.identify.identify_urdf`), its first combination (first
control mode, first sensor type, the values given beside identification) is assigned
(:mod:`solver.identify.combinations`), and :func:`solver.layouts.robot.robot_layout` draws it,
fed by the robot's real topics when a topic list or a bag gives them.

Not here: writing the file (the caller's, atomically), a whole team's layouts
(:mod:`solver.layouts.writer`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from solver.layouts.ordering import without_data
from solver.layouts.plan import check_namespace
from solver.layouts.presentation import load_presentation
from solver.layouts.robot import RobotLayout, robot_layout

if TYPE_CHECKING:
    from solver.identify.identification import Identification
    from solver.identify.profile import Profile
    from solver.ros.names import Topic
    from solver.solving.assignment import Assignment
    from solver.solving.solution import Solution

__all__ = ["IdentifiedLayout", "identified_layout"]


@dataclass(frozen=True)
class IdentifiedLayout:
    """The robot as identified, the configuration it was given, and its layout (the file's
    text and a warning per panel no real topic fitted)."""

    identification: Identification
    assignment: Assignment
    layout: RobotLayout


def identified_layout(
    description: str | Path,
    solution: Solution,
    *,
    profile: Profile | None = None,
    presentation: str | Path | None = None,
    fmt: str = "foxglove",
    namespace: str | None = None,
    given: Mapping[str, str] | None = None,
    topics: str | Path | None = None,
    bag: str | Path | None = None,
    file: str = "<layout>",
) -> IdentifiedLayout:
    """The layout of the robot whose URDF is the file ``description``, in ``solution``'s team.

    ``profile``: identification's (default: the shipped one); ``presentation``: a presentation
    file, checked against the team's rules (default: the shipped one); ``fmt``: the target
    (``foxglove``, ``rviz``); ``namespace``: the robot's, as
    :func:`~solver.layouts.plan.check_namespace` returns it (default: ``/`` and the robot's
    name, which must then make one); ``given``: values beside identification (characteristic
    name -> value); ``topics`` (a topic list file) or ``bag``: the robot's real topics, which
    panels take instead of the presentation's templates; ``file``: the name the layout is
    validated under."""
    from solver.identify import identify_urdf, load_profile
    from solver.identify.combinations import combinations
    from solver.identify.readers.safexml import read_bytes

    profile = profile if profile is not None else load_profile()
    text = read_bytes(description, display=str(description))
    identification = identify_urdf(
        text, file=str(description), rules=solution.rules, profile=profile
    )
    if namespace is None:
        namespace = check_namespace(
            "/" + identification.robot,
            str(description),
            what="; the robot's name makes its namespace: give one with --namespace /NAME",
        )
    # The robot's first control mode and sensor type: the combination it starts in.
    assignment = combinations(identification, solution, profile, given)[0].assignment
    shown = load_presentation(presentation, solution.rules if presentation else None)
    # No bag of rates here: an order that needs one is applied alphabetically, and said so.
    shown, unordered = without_data(shown, "layouts --robot")
    source, real = _real_topics(topics, bag)
    layout = robot_layout(
        solution,
        assignment,
        shown,
        fmt,
        namespace=namespace,
        topics=real,
        topics_source=source,
        joints=identification.joints,
        file=file,
    )
    if unordered is not None:
        layout = replace(layout, warnings=(unordered, *layout.warnings))
    return IdentifiedLayout(identification, assignment, layout)


def _real_topics(
    topics: str | Path | None, bag: str | Path | None
) -> tuple[str, tuple[Topic, ...] | None]:
    """The robot's real topics and where they were read, as ``identify`` reads them (``None``:
    the templates)."""
    if topics:
        from solver.identify.readers.topics import read_topic_list

        return str(topics), read_topic_list(topics)
    if bag:
        from solver.identify.readers.bags import read_bag_topics

        return str(bag), read_bag_topics(bag)
    return "", None
