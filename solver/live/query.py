"""One question to a running master: which UI configuration does this robot get?

:func:`assign_from_master` is ``teleop-ui assign --master URL [--robot NS] [NAME=VALUE...]``:
it reads the master once, identifies the robot at ``NS`` (or the operator's active robot, with
the active motion control and sensor type, when no ``--robot`` is given), fills in the values
given on the command line, and chooses one combination as the watcher does
(:func:`solver.live.selection.choose`). It writes nothing to the master.

Unlike the watcher, which reports a robot it cannot identify and goes on, a question about one
robot that cannot be answered is an error: no such robot (with the robots there are), or a
description that does not identify (its located error).

Not here: following changes (:mod:`solver.live.watcher`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from solver.core.assignment import Assignment
from solver.core.solution import Solution
from solver.errors import InputError, did_you_mean
from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.live.discovery import discover, normalise_namespace
from solver.live.master import MISSING, MasterClient
from solver.live.robot import identify_robot
from solver.live.selection import NAMESPACE, choose, read_request, requested_values

if TYPE_CHECKING:
    from solver.live.sources.ros2 import DdsGraph

__all__ = ["LiveAssignment", "assign_from_graph", "assign_from_master"]


@dataclass(frozen=True, slots=True)
class LiveAssignment:
    """The answer: the robot asked about, its combination's assignment, and notes."""

    robot: str
    assignment: Assignment
    notes: tuple[str, ...] = ()


def assign_from_master(
    master: str,
    solution: Solution,
    profile: Profile,
    *,
    robot: str | None = None,
    given: Mapping[str, str] | None = None,
    timeout: float = 2.0,
) -> LiveAssignment:
    """The configuration of a robot on the master (see the module docstring)."""
    client = MasterClient(master, caller_id="/teleop_ui_assign", timeout=timeout)
    try:
        observation = client.observe(NAMESPACE)
        values = dict(given or {})
        notes: list[str] = []
        if robot is None:
            request = read_request(dict(observation.params))
            if request.robot is None:
                raise InputError.at(
                    "<arguments>",
                    f"no --robot given and no {NAMESPACE}/active_robot set on {master}",
                )
            namespace = request.robot
            asked, ignored = requested_values(request, solution, profile)
            values = {**asked, **values}  # the command line's values win
            notes += [*request.notes, *ignored]
        else:
            namespace = normalise_namespace(robot)
        sources = {s.namespace: s for s in discover(observation, profile)}
        source = sources.get(namespace)
        found = (
            {}
            if source is None
            else client.get_params(
                [source.description_key, *([source.semantic_key] if source.semantic_key else [])]
            )
        )
        if source is None or found[source.description_key] is MISSING:
            there = ", ".join(sources) or "none"
            raise InputError.at(
                "<arguments>",
                f"no robot {namespace} on {master} (no "
                f"{namespace.rstrip('/')}/robot_description)"
                f"{did_you_mean(namespace, sources)}; robots "
                f"there: {there}",
            )
    finally:
        client.close()
    live = identify_robot(
        source,
        found[source.description_key],
        found.get(source.semantic_key or "", MISSING),
        cache=IdentificationCache(),
        solution=solution,
        profile=profile,
    )
    if live.identification is None:
        raise InputError.at(
            master, f"robot {namespace} cannot be identified: {_one_line(live.error)}"
        )
    assignment, chosen = choose(live, values, solution)
    return LiveAssignment(namespace, assignment, (*notes, *chosen))


def assign_from_graph(
    source: DdsGraph,
    solution: Solution,
    profile: Profile,
    *,
    robot: str,
    given: Mapping[str, str] | None = None,
) -> LiveAssignment:
    """:func:`assign_from_master` on a ROS 2 graph: the robot ``robot`` as the watcher sees it
    once discovery is quiet (``--robot`` is required: the active robot is a topic there)."""
    from solver.live.watcher import Watcher

    namespace = normalise_namespace(robot)
    source.settle()
    with Watcher(source.name, solution, profile, source=source) as watcher:
        watcher.snapshot()
        robots = watcher.robots()
    live = robots.get(namespace)
    if live is None:
        there = ", ".join(robots) or "none"
        raise InputError.at(
            "<arguments>",
            f"no robot {namespace} on {source.name} (no "
            f"{namespace.rstrip('/')}/robot_description)"
            f"{did_you_mean(namespace, robots)}; robots there: "
            f"{there}",
        )
    if live.identification is None:
        raise InputError.at(
            source.name, f"robot {namespace} cannot be identified: {_one_line(live.error)}"
        )
    assignment, chosen = choose(live, dict(given or {}), solution)
    return LiveAssignment(namespace, assignment, tuple(chosen))


def _one_line(error: str | None) -> str:
    # The robot's faults, one per line in the watcher, on the one line of this error.
    return "; ".join((error or "").splitlines())
