"""Which robots a ROS master holds, and which topics are each robot's, with their direction.

*Robots.* Every namespace holding a ``robot_description`` parameter is one robot, named by the
namespace (``/uav1``); the root namespace's ``/robot_description`` is the robot ``/`` of a
single-robot system. ``robot_description_semantic`` beside it (MoveIt's SRDF) is read too, and
so is ``teleop_description`` (the robot's teleoperation description, the YAML text of a
``ROBOT.teleop.yaml``: :mod:`solver.ros.description`).

*Topics.* A topic belongs to the robot with the deepest namespace that contains it; the root
robot, if there is one, takes every topic no other robot claims. Names are given to
identification *relative to the namespace* (``camera/image_raw``), so that the robot's own name
never matches a topic pattern and identical robots under different namespaces share one cached
identification.

*Direction*, as the robot's nodes see it: a topic is ``published`` when a publisher is
registered for it and ``subscribed`` when a subscriber is. When nodes under the robot's
namespace are among them, only those nodes count (a teleop node at the root publishing
``/uav1/cmd_vel`` does not make the drone a publisher of it); when none is (one simulator node
serving every robot), both sides count and the topic is given once per direction.
Identification then reads sensors from what is published and commands from what is subscribed.

*The robot's own values.* A parameter (ROS 1) or a ``std_msgs/String`` topic (ROS 2)
``<ns>/teleop_ui/<characteristic>`` gives the robot ``<ns>`` a value of that characteristic
(``/uav1/teleop_ui/comm_link: LTE``); :attr:`RobotSource.value_keys` lists every such name found,
known to the rules or not (the watcher says which it does not know). Under the root robot's
``/teleop_ui`` the operator's names (``active_*``) and the watchers' (``ui_configuration``,
``watchers``) are not the robot's.

*Relevance.* Topics whose message type no rule of the identification profile reads (``tf``,
``rosout``, diagnostics) are left out before identification: their coming and going changes
nothing, and leaving them out keeps the cached identification valid.

Not here: reading a graph (:mod:`solver.live.sources`), identifying (:mod:`solver.live.robot`).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable
from dataclasses import dataclass

from solver.identify.profile import Profile
from solver.live.graph import Observation
from solver.ros.names import Topic, normalise_type

__all__ = [
    "DESCRIPTION",
    "ROBOT_VALUES",
    "SEMANTIC",
    "TELEOP",
    "RobotSource",
    "description_key",
    "discover",
    "normalise_namespace",
    "robot_namespaces",
    "robot_topics",
]

DESCRIPTION = "robot_description"
SEMANTIC = "robot_description_semantic"
TELEOP = "teleop_description"
# A robot's own values are under <ns>/teleop_ui/<characteristic>.
ROBOT_VALUES = "teleop_ui"
# Names under /teleop_ui that are the operator's or the watchers', not the root robot's.
_NOT_VALUES = ("active_", "ui_configuration", "watchers")
_ANY_TYPE = "*"


@dataclass(frozen=True, slots=True)
class RobotSource:
    """What the master holds about one robot: its namespace, parameter keys and topics, its
    own values' keys (characteristic name, key), sorted by name, and the key of its
    teleoperation description when it has one."""

    namespace: str
    description_key: str
    semantic_key: str | None
    topics: tuple[Topic, ...]
    value_keys: tuple[tuple[str, str], ...] = ()
    teleop_key: str | None = None

    def keys(self, characteristics: Collection[str]) -> list[str]:
        """The keys to read of this robot: its description, SRDF and teleoperation
        description when it has them, and its own values of ``characteristics``."""
        found = [self.description_key]
        found += [key for key in (self.semantic_key, self.teleop_key) if key is not None]
        found += [key for name, key in self.value_keys if name in characteristics]
        return found


def normalise_namespace(text: str) -> str:
    """``uav1``, ``/uav1/`` -> ``/uav1``; ``""`` or ``/`` -> ``/`` (the root namespace)."""
    parts = [part for part in text.strip().split("/") if part]
    return "/" + "/".join(parts)


def description_key(namespace: str, name: str = DESCRIPTION) -> str:
    return namespace.rstrip("/") + "/" + name


def robot_namespaces(param_names: Iterable[str]) -> tuple[str, ...]:
    """Namespaces holding a ``robot_description`` parameter, sorted."""
    found = set()
    for name in param_names:
        parts = [part for part in name.split("/") if part]
        if parts and parts[-1] == DESCRIPTION:
            found.add("/" + "/".join(parts[:-1]))
    return tuple(sorted(found))


def _owner(name: str, namespaces: frozenset[str]) -> str | None:
    """The deepest namespace strictly containing ``name``, the root one last; one set lookup
    per level of ``name``, so a poll costs O(topics + nodes), not O(topics x robots)."""
    parts = [part for part in name.split("/") if part]
    for depth in range(len(parts) - 1, 0, -1):
        candidate = "/" + "/".join(parts[:depth])
        if candidate in namespaces:
            return candidate
    return "/" if "/" in namespaces else None


def _relative(name: str, namespace: str) -> str:
    return name[len(namespace) :].lstrip("/") if namespace != "/" else name.lstrip("/")


def _relevant(message_type: str, profile: Profile) -> bool:
    return any(
        not rule.types or message_type in rule.types for rule in profile.topic_sensors
    ) or any(message_type in rule.types for rule in profile.topic_controls)


def robot_topics(
    namespaces: Iterable[str], observation: Observation, profile: Profile
) -> dict[str, tuple[Topic, ...]]:
    """The topics of each robot in ``namespaces`` (see the module docstring), each sorted.

    Every topic and node name is placed once, so the cost grows with the size of the graph,
    not with the number of robots times the number of topics.
    """
    known = frozenset(namespaces)
    types = dict(observation.topic_types)
    sides = {"published": dict(observation.publishers), "subscribed": dict(observation.subscribers)}
    owners: dict[str, str | None] = {}

    def owner(name: str) -> str | None:
        if name not in owners:
            owners[name] = _owner(name, known)
        return owners[name]

    relevant: dict[str, bool] = {}
    found: dict[str, list[Topic]] = {namespace: [] for namespace in sorted(known)}
    for name in sorted(set(sides["published"]) | set(sides["subscribed"])):
        namespace = owner(name)
        if namespace is None:
            continue
        message_type = normalise_type(types.get(name, _ANY_TYPE))
        if message_type == _ANY_TYPE:
            continue
        if message_type not in relevant:
            relevant[message_type] = _relevant(message_type, profile)
        if not relevant[message_type]:
            continue
        own = {
            side: [node for node in nodes.get(name, ()) if owner(node) == namespace]
            for side, nodes in sides.items()
        }
        counted = (
            own
            if any(own.values())
            else {side: list(nodes.get(name, ())) for side, nodes in sides.items()}
        )
        relative = _relative(name, namespace)
        found[namespace] += [
            Topic(relative, message_type, side)
            for side in ("published", "subscribed")
            if counted[side]
        ]
    return {namespace: tuple(topics) for namespace, topics in found.items()}


def robot_value_keys(
    namespaces: Iterable[str], param_names: Iterable[str]
) -> dict[str, tuple[tuple[str, str], ...]]:
    """Each robot's own values: (characteristic name, key) for every ``<ns>/teleop_ui/<name>``
    (a name with children is one value: the watcher says it is not text)."""
    known = frozenset(namespaces)
    found: dict[str, dict[str, str]] = {namespace: {} for namespace in known}
    for name in param_names:
        parts = [part for part in name.split("/") if part]
        for depth in range(len(parts) - 1):
            if parts[depth] != ROBOT_VALUES:
                continue
            namespace = "/" + "/".join(parts[:depth])
            value = parts[depth + 1]
            if namespace not in known or (namespace == "/" and value.startswith(_NOT_VALUES)):
                continue
            found[namespace].setdefault(
                value, description_key(namespace, f"{ROBOT_VALUES}/{value}")
            )
    return {namespace: tuple(sorted(keys.items())) for namespace, keys in found.items()}


def discover(observation: Observation, profile: Profile) -> tuple[RobotSource, ...]:
    """Every robot on the master, in namespace order."""
    namespaces = robot_namespaces(observation.param_names)
    names = set(observation.param_names)
    topics = robot_topics(namespaces, observation, profile)
    values = robot_value_keys(namespaces, observation.param_names)
    return tuple(
        RobotSource(
            namespace,
            description_key(namespace),
            description_key(namespace, SEMANTIC)
            if description_key(namespace, SEMANTIC) in names
            else None,
            topics[namespace],
            values[namespace],
            description_key(namespace, TELEOP)
            if description_key(namespace, TELEOP) in names
            else None,
        )
        for namespace in namespaces
    )
