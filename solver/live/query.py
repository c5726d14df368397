"""One question to a running graph: which UI configuration does this robot get?

:func:`assign_from_graph` is ``teleop-ui assign --master URL [--robot NS] [NAME=VALUE...]`` (and
``--ros2``), on any :class:`~solver.live.graph.GraphSource`: it looks at the graph once (after
the source's discovery has settled), identifies the robot at ``NS`` (or the operator's active
robot, with the operator's active values, when no ``--robot`` is given), with the robot's own
values (``<ns>/teleop_ui/<characteristic>``), fills in the values given on the command line
(which win), and chooses one combination as the watcher does
(:func:`solver.live.selection.choose`). It writes nothing to the graph, and reads only the asked
robot's description. :func:`assign_from_master` is the same question to a ROS 1 master.

Unlike the watcher, which reports a robot it cannot identify and goes on, a question about one
robot that cannot be answered is an error: no such robot (with the robots there are), or a
description that does not identify (its located error).

Not here: following changes (:mod:`solver.live.watcher`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from solver.errors import InputError, did_you_mean
from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.live.discovery import discover, normalise_namespace
from solver.live.given import ACTIVE_PREFIX, robot_values, unknown_name
from solver.live.graph import MISSING, GraphSource
from solver.live.robot import identify_robot
from solver.live.selection import NAMESPACE, choose, read_request
from solver.solving.assignment import Assignment
from solver.solving.solution import Solution

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
    """The configuration of a robot on the ROS 1 master at ``master`` (see the docstring)."""
    from solver.live.sources.ros1 import MasterGraph

    source = MasterGraph(master, timeout=timeout, push=False)
    try:
        return assign_from_graph(source, solution, profile, robot=robot, given=given)
    finally:
        source.close()


def assign_from_graph(
    source: GraphSource,
    solution: Solution,
    profile: Profile,
    *,
    robot: str | None = None,
    given: Mapping[str, str] | None = None,
) -> LiveAssignment:
    """The configuration of a robot on the graph ``source`` (see the module docstring)."""
    source.settle(lambda: False)
    observation = source.observe(NAMESPACE)
    values = dict(given or {})
    notes: list[str] = []
    if robot is None:
        request = read_request(dict(observation.params), solution.rules.names)
        if request.robot is None:
            raise InputError.at(
                "<arguments>",
                f"no --robot given and no {NAMESPACE}/active_robot set on {source.name}",
            )
        namespace = request.robot
        values = {**dict(request.values), **values}  # the command line's values win
        notes += request.notes
        notes += [
            f"{NAMESPACE}/{key}: {unknown_name(key[len(ACTIVE_PREFIX) :], solution.rules)}"
            for key in request.unknown
        ]
    else:
        namespace = normalise_namespace(robot)
    found = {s.namespace: s for s in discover(observation, profile)}
    robot_source = found.get(namespace)
    if robot_source is None:
        raise _no_robot(namespace, source, found)
    source.descriptions.sync(robot_source.keys(solution.rules.names))
    description = source.descriptions.get(robot_source.description_key)
    if description is MISSING:
        raise _no_robot(namespace, source, found)
    own, warnings = robot_values(robot_source.value_keys, source.descriptions.get, solution.rules)
    notes += [f"{key}: {message}" for key, message in warnings]
    live = identify_robot(
        robot_source,
        description,
        MISSING
        if robot_source.semantic_key is None
        else source.descriptions.get(robot_source.semantic_key),
        cache=IdentificationCache(),
        solution=solution,
        profile=profile,
        given=own,
        teleop=MISSING
        if robot_source.teleop_key is None
        else source.descriptions.get(robot_source.teleop_key),
    )
    notes += [f"{where}: {message}" for where, message in live.warnings]
    if live.identification is None:
        raise InputError.at(
            source.name, f"robot {namespace} cannot be identified: {_one_line(live.error)}"
        )
    assignment, chosen = choose(live, values, solution)
    said = live.identification.disagreements
    differ = [f"declared and read differ (the declared value wins): {line}" for line in said]
    return LiveAssignment(namespace, assignment, (*notes, *differ, *chosen))


def _no_robot(namespace: str, source: GraphSource, found: Mapping[str, object]) -> InputError:
    return InputError.at(
        "<arguments>",
        f"no robot {namespace} on {source.name} (no "
        f"{namespace.rstrip('/')}/robot_description)"
        f"{did_you_mean(namespace, found)}; robots there: {', '.join(found) or 'none'}",
    )


def _one_line(error: str | None) -> str:
    # The robot's faults, one per line in the watcher, on the one line of this error.
    return "; ".join((error or "").splitlines())
