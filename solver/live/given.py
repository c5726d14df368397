"""Where a robot's characteristic values come from, beside identification, and what it lacks.

Every characteristic of the rule set can be live, not only those identification fills (the
profile's roles: motion control, sensor type, sensor count; and the kinematic type). For each,
the value used is the first of, in this order:

1. the operator's active selection, ``/teleop_ui/active_<characteristic>`` (for the active
   robot: :mod:`solver.live.selection`);
2. the robot's own, a parameter (ROS 1) or a ``std_msgs/String`` topic (ROS 2)
   ``<ns>/teleop_ui/<characteristic>`` (:attr:`~solver.live.discovery.RobotSource.value_keys`);
3. a fixed value given at start, ``--set NAME=VALUE`` for every robot or
   ``--set /ns:NAME=VALUE`` for one (:class:`FixedValues`; one robot's wins over all robots');
4. identification.

A characteristic none of them gives is *missing*: the robot's combinations get the default
configuration, and :func:`how_to_give` says how to give it.

Not here: reading the graph (:mod:`solver.live.sources`), choosing a combination
(:mod:`solver.live.selection`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from solver.core.ruleset import RuleSet
from solver.errors import InputError
from solver.live.discovery import ROBOT_VALUES, normalise_namespace
from solver.live.graph import MISSING
from solver.live.values import selection_text
from solver.solving.assignment import check_names, parse_combination
from solver.untrusted import shown

__all__ = [
    "ACTIVE_PREFIX",
    "FixedValues",
    "GivenValue",
    "how_to_give",
    "parse_fixed",
    "robot_values",
]

# /teleop_ui/active_<characteristic>: the operator's selection of a characteristic's value.
ACTIVE_PREFIX = "active_"
# Values listed in a "how to give it" hint, at most.
_LISTED = 6


@dataclass(frozen=True, slots=True)
class GivenValue:
    """A value a robot is given beside identification, and where it was read (a key on the
    graph, or ``--set``)."""

    characteristic: str
    value: str
    source: str


@dataclass(frozen=True, slots=True)
class FixedValues:
    """Values given at start: for every robot, and for one robot by namespace."""

    everywhere: tuple[tuple[str, str], ...] = ()
    per_robot: tuple[tuple[str, tuple[tuple[str, str], ...]], ...] = ()

    def for_robot(self, namespace: str) -> tuple[GivenValue, ...]:
        """The fixed values of the robot ``namespace``, in the rule set's order."""
        values = {name: GivenValue(name, value, "--set") for name, value in self.everywhere}
        for robot, pairs in self.per_robot:
            if robot == namespace:
                for name, value in pairs:
                    values[name] = GivenValue(name, value, f"--set {robot}:{name}={value}")
        return tuple(values.values())

    def __bool__(self) -> bool:
        return bool(self.everywhere or self.per_robot)


def parse_fixed(pairs: Sequence[str], rules: RuleSet, *, option: str = "--set") -> FixedValues:
    """``["comm_link=Wi-Fi", "/uav1:comm_link=LTE"]`` -> :class:`FixedValues`; an
    :class:`InputError` for a malformed pair or a name the rules do not have."""
    everywhere: list[str] = []
    per_robot: dict[str, list[str]] = {}
    for pair in pairs:
        target, separator, rest = pair.partition(":")
        if separator and target.strip().startswith("/") and "=" not in target:
            per_robot.setdefault(normalise_namespace(target), []).append(rest)
        else:
            everywhere.append(pair)
    try:
        common = parse_combination(everywhere)
        check_names(rules, common)
        robots = []
        for namespace, items in sorted(per_robot.items()):
            values = parse_combination(items)
            check_names(rules, values)
            robots.append((namespace, _ordered(values, rules)))
    except InputError as error:
        fault = error.faults[0]
        raise InputError.at(option, fault.message, path=fault.location.path) from None
    return FixedValues(_ordered(common, rules), tuple(robots))


def _ordered(values: Mapping[str, str], rules: RuleSet) -> tuple[tuple[str, str], ...]:
    return tuple((name, values[name]) for name in rules.names if name in values)


def robot_values(
    value_keys: Iterable[tuple[str, str]], read: Any, rules: RuleSet
) -> tuple[tuple[GivenValue, ...], tuple[tuple[str, str], ...]]:
    """The robot's own values (``read(key)`` gives each key's value) for the characteristics the
    rules know, and (key, message) warnings: for a name the rules do not know, and for a value
    that is not short text (:func:`~solver.live.values.selection_text`)."""
    found: list[GivenValue] = []
    warnings: list[tuple[str, str]] = []
    for name, key in value_keys:
        if name not in rules.names:
            warnings.append((key, unknown_name(name, rules)))
            continue
        value = read(key)
        if value is MISSING:
            continue
        text, note = selection_text(key, value)
        if note is not None:
            warnings.append((key, note))
        elif text is not None:
            found.append(GivenValue(name, text, key))
    return tuple(found), tuple(warnings)


def unknown_name(name: str, rules: RuleSet) -> str:
    """What a warning says of a characteristic name the rules do not have."""
    from solver.errors import did_you_mean

    return (
        f"the rule set has no characteristic {shown(name, quoted=True)}"
        f"{did_you_mean(name, rules.names)}; it has {', '.join(rules.names)}: ignored"
    )


def how_to_give(name: str, namespace: str, rules: RuleSet) -> str:
    """How a robot that lacks ``name`` is given it (see the module docstring)."""
    values = [str(value) for value in rules.characteristic(name).values]
    listed = ", ".join(shown(value) for value in values[:_LISTED])
    more = f", ... ({len(values)} in all)" if len(values) > _LISTED else ""
    own = namespace.rstrip("/") + f"/{ROBOT_VALUES}/{name}"
    return (
        f"the operator's /teleop_ui/{ACTIVE_PREFIX}{name}, the robot's {shown(own)}, "
        f"or --set {name}=VALUE when the watcher starts (values: {listed}{more})"
    )
