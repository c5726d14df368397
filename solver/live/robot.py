"""One robot on a ROS master: identified from its description and topics, with its combinations.

:func:`identify_robot` hands a robot's ``robot_description`` text (and SRDF, and topic triples
from :mod:`solver.live.discovery`) to :meth:`IdentificationCache.identify_urdf`, then gives
every characteristic combination its UI configuration with
:func:`solver.identify.combinations.combinations`, with the values the robot is given beside
identification (its own ``<ns>/teleop_ui/<characteristic>``, ``--set``:
:mod:`solver.live.given`); a characteristic nothing gives is listed as missing, with how to give
it. Identification is cached by content: a
description seen before (the same robot after a master restart, or a second robot of the same
model) is not parsed again. The cache is asked with a file name that does not depend on the
namespace (``robot_description``) for that reason; errors are then re-located to the robot's
own parameter (``/uav1/robot_description:3:5: ...``).

A robot may declare what it is and what drives it: its teleoperation description, the YAML
text of a ``ROBOT.teleop.yaml`` in ``<ns>/teleop_description``
(:mod:`solver.live.discovery`). Its declared values win over what identification read or
guessed, and where the two differ each difference is in the robot's event
(``disagreements``), as ``identify`` says them. The description is a supporting input: one
that cannot be read (not text, not YAML, not a description, past ``description-bytes`` or
``description-entries``) is a located warning (:attr:`LiveRobot.warnings`, which the watcher
reports as ``warning`` events and ``assign`` as notes), and what identification read stands.

A description that cannot be identified (not text, malformed XML, a broken tree, larger than
the reader's cap, or anything the readers did not expect to raise) gives a :class:`LiveRobot`
with the error and no combinations: the robot is still reported, and the others are not
affected. This is the per-robot boundary: nothing one robot publishes may end a
watcher serving the others.

Not here: finding the robots (:mod:`solver.live.discovery`), events (:mod:`solver.live.events`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from solver.errors import Fault, SolverError
from solver.identify.combinations import Combination, combinations, missing
from solver.identify.identification import Identification, IdentificationCache, TopicSource
from solver.identify.profile import Profile
from solver.identify.render import summary_data
from solver.live.discovery import RobotSource
from solver.live.given import GivenValue, how_to_give
from solver.live.graph import MISSING
from solver.ros.description import TeleopDescription, parse_description_text
from solver.ros.names import Topic
from solver.solving.solution import Solution

__all__ = ["LiveRobot", "identify_robot", "robot_data", "unexpected_error"]

_FILE = "robot_description"
_SRDF_FILE = "<srdf>"  # what IdentificationCache names an SRDF
_SOURCE = "topics"


@dataclass(frozen=True, slots=True)
class LiveRobot:
    """A robot as the watcher reports it: identified, or the error that prevented it; its
    topics as discovery found them (names relative to the namespace, with their direction); the
    values it was given beside identification, and the characteristics it lacks with how to
    give each."""

    namespace: str
    identification: Identification | None
    combinations: tuple[Combination, ...] = ()
    error: str | None = None
    topics: tuple[Topic, ...] = ()
    given: tuple[GivenValue, ...] = ()
    missing: tuple[tuple[str, str], ...] = ()
    # (where, message) of each problem of a teleoperation description that was not used.
    warnings: tuple[tuple[str, str], ...] = ()

    def graph_topics(self) -> tuple[Topic, ...]:
        """The robot's topics with their full names on the graph (``/uav1/camera/image_raw``)."""
        prefix = self.namespace.rstrip("/")
        return tuple(
            Topic(f"{prefix}/{topic.name}", topic.type, topic.direction) for topic in self.topics
        )


def _text(value: Any, key: str, what: str = "URDF") -> str | bytes:
    if isinstance(value, str | bytes):
        return value
    if isinstance(value, SolverError):
        raise value  # a source that could not read the value says why (solver.live.sources)
    kind = "a namespace of parameters" if isinstance(value, dict) else type(value).__name__
    raise _NotText(f"{key}: expected {what} text, got {kind}")


class _NotText(ValueError):
    pass


def _relocated(error: SolverError, description: str, semantic: str | None) -> str:
    lines = []
    for fault in error.faults:
        file = fault.location.file
        if file == _FILE:
            file = description
        elif file == _SRDF_FILE and semantic is not None:
            file = semantic
        lines.append(
            str(dataclasses.replace(fault, location=dataclasses.replace(fault.location, file=file)))
        )
    return "\n".join(lines)


def declared_description(
    key: str | None, value: Any
) -> tuple[TeleopDescription | None, tuple[tuple[str, str], ...]]:
    """The teleoperation description in ``value`` (the text of the parameter or topic
    ``key``), or ``None`` and each of its problems as (where, message): a warning, never the
    robot's error."""
    if key is None or value is MISSING:
        return None, ()
    if isinstance(value, SolverError):  # a source that could not read the value says why
        return None, _unused(value.faults)
    if not isinstance(value, str):
        kind = "a namespace of parameters" if isinstance(value, dict) else type(value).__name__
        return None, (
            (key, f"expected a teleoperation description (YAML text), got {kind}{_UNUSED}"),
        )
    try:
        return parse_description_text(value, key), ()
    except SolverError as error:
        return None, _unused(error.faults)
    except Exception as error:  # the per-robot boundary, as for its URDF
        return None, ((key, unexpected_error(key, error) + _UNUSED),)


_UNUSED = "; not used: what identification read stands"


def _unused(faults: tuple[Fault, ...]) -> tuple[tuple[str, str], ...]:
    """Each fault as (where, message): the file and line, then the field and the problem."""
    return tuple(
        (
            str(f.location),
            (f"{f.location.path}: " if f.location.path else "") + f.message + _UNUSED,
        )
        for f in faults
    )


def identify_robot(
    source: RobotSource,
    description: Any,
    semantic: Any = MISSING,
    *,
    cache: IdentificationCache,
    solution: Solution,
    profile: Profile,
    given: tuple[GivenValue, ...] = (),
    teleop: Any = MISSING,
) -> LiveRobot:
    """The robot ``source`` describes, from its parameter values (``robot_description``,
    ``robot_description_semantic``, ``teleop_description`` or :data:`MISSING`), topics and
    ``given`` values (names the rules have; the later of two for one name wins); never raises
    for input."""
    namespace = source.namespace
    declared, flaws = declared_description(source.teleop_key, teleop)
    try:
        text = _text(description, source.description_key)
        srdf = (
            None
            if source.semantic_key is None or semantic is MISSING
            else _text(semantic, source.semantic_key, "SRDF")
        )
        identification = cache.identify_urdf(
            text,
            srdf_text=srdf,
            topics=[TopicSource(_SOURCE, source.topics)] if source.topics else (),
            rules=solution.rules,
            profile=profile,
            file=_FILE,
            description=declared,
        )
        values = {value.characteristic: value.value for value in given}
        found = combinations(identification, solution, profile, values)
    except _NotText as error:
        return LiveRobot(namespace, None, (), str(error), source.topics)
    except SolverError as error:
        located = _relocated(error, source.description_key, source.semantic_key)
        return LiveRobot(namespace, None, (), located, source.topics)
    except Exception as error:  # the per-robot boundary
        # A robot_description is whatever a robot on the network publishes: one that gets
        # past the readers' own checks (an overflow, a recursion, a reader bug) must still
        # not stop the watcher. The robot is reported with what went wrong, the others go on.
        unexpected = unexpected_error(source.description_key, error)
        return LiveRobot(namespace, None, (), unexpected, source.topics)
    lacking = tuple(
        (name, how_to_give(name, namespace, solution.rules)) for name in missing(found, solution)
    )
    kept = tuple({value.characteristic: value for value in given}.values())
    return LiveRobot(
        namespace,
        identification,
        found,
        topics=source.topics,
        given=kept,
        missing=lacking,
        warnings=flaws,
    )


def unexpected_error(key: str, error: BaseException) -> str:
    """The located message of an exception the identification did not expect to raise."""
    text = str(error).splitlines()[0][:200] if str(error) else ""
    return f"{key}: cannot identify ({type(error).__name__}{': ' + text if text else ''})"


def robot_data(robot: LiveRobot) -> dict[str, Any]:
    """The robot fields of a ``robot_added`` / ``robot_changed`` event (see docs/live.md):
    ``declared`` and ``disagreements`` only for a robot whose teleoperation description was
    read."""
    found = robot.identification
    declared = (
        {"declared": found.declared, "disagreements": list(found.disagreements)}
        if found is not None and found.declared is not None
        else {}
    )
    return {
        "robot": robot.namespace,
        **summary_data(robot.identification),
        **declared,
        "given": {
            value.characteristic: {"value": value.value, "source": value.source}
            for value in robot.given
        },
        "combinations": [
            {
                "combination": dict(c.values),
                "configuration": c.assignment.number,
                "default": c.assignment.is_default,
                "reasons": list(c.assignment.reasons),
            }
            for c in robot.combinations
        ],
        "missing": [{"characteristic": name, "how": how} for name, how in robot.missing],
        "error": robot.error,
        "topics": [
            {"topic": topic.name, "type": topic.type, "direction": topic.direction}
            for topic in robot.graph_topics()
        ],
    }
