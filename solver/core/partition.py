"""Partitioning valid robots into UI configurations, and numbering the configurations.

A UI configuration is one component per characteristic. A robot can use a configuration when
each of its values belongs to that configuration's component. When every value belongs to
exactly one component (the relation "needs the same component" is an equivalence, as in the
article), each robot has exactly one configuration and the classes are unique.

When a value belongs to several components (overlapping presentation groups or arrangements),
"can share a component" is no longer transitive and choosing the fewest configurations is a
minimum hitting-set problem: pick configurations so that every robot can use at least one. It
is solved exactly, proven optimal, by :func:`solver.core.cover.minimum_cover`; each robot
then goes to the lowest-numbered chosen configuration it can use. A value in no component (a
gap) leaves its robots *unserved*: they get the default configuration.

Configurations are numbered 1..k by kinematic type in rule-file order, then by the component
order of the other characteristics in characteristic order; the default configuration is k+1.

Not here: producing the robots (:mod:`solver.engines`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeVar

from solver.core.constraints import Value
from solver.core.ruleset import Component, RuleSet

if TYPE_CHECKING:
    from solver.core.cover import Options

__all__ = [
    "Configuration",
    "Partition",
    "PartitionClass",
    "RobotClass",
    "partition",
    "partition_classes",
    "sort_key",
    "unsorted",
]

Key = tuple[int, ...]
T = TypeVar("T")


@dataclass(frozen=True, slots=True)
class Configuration:
    """One UI configuration: its number, its components and the robots it serves."""

    number: int
    kinematic_type: str
    key: Key
    components: tuple[Component, ...]
    robots: int
    # served[i]: the values of characteristic i among the robots this configuration serves.
    served: tuple[tuple[Value, ...], ...]

    @property
    def valid_robots(self) -> int:
        """The valid robots it serves (the JSON contract's name for ``robots``)."""
        return self.robots

    def __repr__(self) -> str:  # short, for notebooks: the fields are one attribute away
        components = " / ".join(component.name for component in self.components)
        return (
            f"<Configuration {self.number} ({self.kinematic_type}): {components}; "
            f"{self.robots} valid robots>"
        )

    def clusters(self, position: int) -> tuple[int, int]:
        """The fewest and most clusters the served counts of characteristic ``position`` take."""
        component = self.components[position]
        counts = [int(v) for v in self.served[position]]
        return component.clusters(min(counts)), component.clusters(max(counts))


@dataclass(frozen=True, slots=True)
class RobotClass:
    """Robots the rules cannot tell apart: for each characteristic the values they take (all in
    the same components), and how many robots the class stands for."""

    values: tuple[tuple[Value, ...], ...]
    robots: int


@dataclass(frozen=True, slots=True)
class PartitionClass:
    """One configuration of a partition, before numbering: its component per characteristic
    (``key``), the robots it serves, and per characteristic the values among them."""

    key: Key
    robots: int
    served: tuple[tuple[Value, ...], ...]


@dataclass(frozen=True, slots=True)
class Partition:
    """The configurations of one kinematic type, before numbering across the team."""

    kinematic_type: str
    # In numbering order (:func:`sort_key`).
    classes: tuple[PartitionClass, ...]
    valid_robots: int
    unserved_robots: int
    proven_minimal: bool


def sort_key(rules: RuleSet, key: tuple[T, ...]) -> tuple[T, ...]:
    """Numbering order: kinematic type first, then the other characteristics in order."""
    position = rules.key_position
    return (key[position], *key[:position], *key[position + 1 :])


def unsorted(rules: RuleSet, key: tuple[T, ...]) -> tuple[T, ...]:
    """The key in characteristic order again, from numbering order (:func:`sort_key`)."""
    position = rules.key_position
    return (*key[1 : position + 1], key[0], *key[position + 1 :])


def partition(rules: RuleSet, kinematic_type: str, robots: Iterable[Sequence[Value]]) -> Partition:
    """Partition the valid robots of one kinematic type into the fewest configurations."""
    if all(c.is_partition for c in rules.characteristics):
        return _partition_equivalence(rules, kinematic_type, robots)
    singletons = (RobotClass(tuple((value,) for value in robot), 1) for robot in robots)
    return partition_classes(rules, kinematic_type, singletons)


def partition_classes(
    rules: RuleSet, kinematic_type: str, classes: Iterable[RobotClass]
) -> Partition:
    """Partition weighted classes of robots (see :class:`RobotClass`) into configurations.

    All values a class lists for one characteristic must belong to the same components, so
    every robot of the class has the same candidate configurations. Used by the structural
    counter, which never lists robots one by one.
    """
    characteristics = rules.characteristics
    width = len(characteristics)
    # Robot classes by their options: per characteristic, the components their values are in.
    by_options: dict[Options, list[tuple[tuple[tuple[Value, ...], ...], int]]] = {}
    unserved = total = 0
    for robot_class in classes:
        values, weight = robot_class.values, robot_class.robots
        total += weight
        options = tuple(
            [
                c.membership[c.positions[members[0]]]
                for c, members in zip(characteristics, values, strict=True)
            ]
        )
        if not all(options):
            unserved += weight
            continue
        by_options.setdefault(options, []).append((values, weight))
    if all(len(o) == 1 for options in by_options for o in options):
        order = sorted({tuple(o[0] for o in options) for options in by_options})
        assigned = {options: tuple(o[0] for o in options) for options in by_options}
    else:
        # Imported here: HiGHS loads only for rule sets with overlapping components.
        from solver.core.cover import minimum_cover

        # Positions in numbering order, so that "lowest" below is the lowest number.
        cover = minimum_cover((sort_key(rules, options) for options in by_options), file=rules.file)
        order = [unsorted(rules, key) for key in cover.chosen()]
        # Each robot goes to the lowest-numbered chosen configuration it can use.
        assigned = {
            options: unsorted(rules, cover.first(sort_key(rules, options)))
            for options in by_options
        }
    order.sort(key=lambda key: sort_key(rules, key))
    counts = dict.fromkeys(order, 0)
    served: dict[Key, list[set[Value]]] = {key: [set() for _ in range(width)] for key in order}
    for options, members in by_options.items():
        key = assigned[options]
        for values, weight in members:
            counts[key] += weight
            for i in range(width):
                served[key][i].update(values[i])
    classes_out = tuple(
        PartitionClass(key, counts[key], _ordered(rules, served[key])) for key in order
    )
    return Partition(kinematic_type, classes_out, total, unserved, True)


def _partition_equivalence(
    rules: RuleSet, kinematic_type: str, robots: Iterable[Sequence[Value]]
) -> Partition:
    characteristics = rules.characteristics
    width = len(characteristics)
    lookup = [
        {value: c.membership[i][0] for i, value in enumerate(c.values) if c.membership[i]}
        for c in characteristics
    ]
    counts: dict[Key, int] = {}
    served: dict[Key, list[set[Value]]] = {}
    unserved = total = 0
    for robot in robots:
        total += 1
        try:
            key = tuple(lookup[i][robot[i]] for i in range(width))
        except KeyError:  # a value in no component: a gap in the rules
            unserved += 1
            continue
        if key in counts:
            counts[key] += 1
        else:
            counts[key] = 1
            served[key] = [set() for _ in range(width)]
        sets = served[key]
        for i in range(width):
            sets[i].add(robot[i])
    order = sorted(counts, key=lambda key: sort_key(rules, key))
    classes = tuple(PartitionClass(key, counts[key], _ordered(rules, served[key])) for key in order)
    return Partition(kinematic_type, classes, total, unserved, True)


def _ordered(rules: RuleSet, sets: list[set[Value]]) -> tuple[tuple[Value, ...], ...]:
    """Each set in domain order, in the time of its own values (a pass over the whole domain
    per configuration made listing 20,000 configurations of 5,000 counts take seconds)."""
    return tuple(
        tuple(sorted(values, key=c.positions.__getitem__))
        for c, values in zip(rules.characteristics, sets, strict=True)
    )
