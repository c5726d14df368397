"""Assigning a UI configuration to one characteristic combination, or the default one.

This is the run-time question of the article: the operator is working with a robot in one
control mode, looking at one sensor; which UI configuration does it get? A valid combination
gets its configuration's number and components. Anything else (a value the rules do not know, a
kinematic type not in the team, a value outside the team's selection, more sensors than the
maximum, a broken rule constraint, a value in no component) gets the default configuration
(number k+1), the reasons, and the components that are relevant to the values that are known.

Not here: finding the combination from ROS metadata (the identification modules do that).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from solver.core.constraints import Value
from solver.core.model import violated_constraints
from solver.core.partition import Configuration
from solver.core.ruleset import Characteristic, RuleSet
from solver.errors import InputError, did_you_mean
from solver.files.reader import MAX_NAME_CHARS
from solver.solving.contracts import configuration_data
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = ["Assignment", "assign", "assignment_data", "check_names", "parse_combination"]


@dataclass(frozen=True, slots=True)
class Assignment:
    """The UI configuration given to one combination, and why when it is the default."""

    given: tuple[tuple[str, str], ...]
    number: int
    configuration: Configuration | None
    reasons: tuple[str, ...] = ()
    # characteristic name -> names of the components its known value needs.
    relevant: tuple[tuple[str, tuple[str, ...]], ...] = ()

    @property
    def is_default(self) -> bool:
        return self.configuration is None

    def __repr__(self) -> str:  # short, for notebooks: the fields are one attribute away
        given = " ".join(f"{name}={value}" for name, value in self.given)
        if self.configuration is None:
            return f"<Assignment default {self.number} for {given}: {'; '.join(self.reasons)}>"
        return f"<Assignment {self.number} for {given}>"


# Whole numbers of a rule set are at most this many bits (solver.files.yamlio refuses more).
_MAX_INT_BITS = 63


def parse_combination(pairs: list[str] | tuple[str, ...]) -> dict[str, str]:
    """``["kinematic_type=UAV", "sensor_count=3"]`` -> a mapping; :class:`InputError` if bad."""
    combination: dict[str, str] = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise InputError.at(
                "<arguments>", f"expected NAME=VALUE, got {shown(pair, quoted=True)}"
            )
        if name.strip() in combination:
            raise InputError.at("<arguments>", f"{shown(name.strip(), quoted=True)} is given twice")
        if len(value.strip()) > MAX_NAME_CHARS:
            # No value of a rule set is longer (names are at most this long, whole numbers 63
            # bits); int() of a 5,000-digit one would raise.
            raise InputError.at(
                "<arguments>",
                f"a value of {len(value.strip()):,} characters; no characteristic value is "
                f"longer than {MAX_NAME_CHARS}",
                path=name.strip(),
            )
        if any(char.isdecimal() and not char.isascii() for char in value):
            # int() reads '٣' as 3; a command line value is written in ASCII digits or refused.
            raise InputError.at(
                "<arguments>",
                f"{shown(value.strip(), quoted=True)} has non-ASCII digits; write numbers as 0-9",
                path=name.strip(),
            )
        combination[name.strip()] = value.strip()
    return combination


def check_names(rules: RuleSet, names: Iterable[str]) -> None:
    """:class:`InputError` for the first name that is not a characteristic of ``rules``: a
    characteristic name is a usage mistake, unlike a value the rules do not allow."""
    for name in names:
        if name not in rules.names:
            raise InputError.at(
                "<arguments>",
                f"unknown characteristic {shown(name, quoted=True)}"
                f"{did_you_mean(name, rules.names)}; the rules "
                f"({rules.file}) have: {', '.join(rules.names)}",
            )


def assign(
    solution: Solution, combination: Mapping[str, str | int] | None = None, /, **by_name: str | int
) -> Assignment:
    """The configuration for ``combination`` (characteristic name -> value) in ``solution``.

    The values may be given as a mapping, as keywords (``assign(solution, kinematic_type="UAV",
    sensor_count=3)``) or both (keywords win). Characteristic *names* must exist
    (:class:`InputError` otherwise: that is a usage mistake); unknown or disallowed *values*
    are a normal outcome, answered with the default.
    """
    combination = {**(combination or {}), **by_name}
    rules = solution.rules
    check_names(rules, combination)
    for name, given_value in combination.items():
        if isinstance(given_value, int) and given_value.bit_length() > _MAX_INT_BITS:
            # str() of a number of more than 4,300 digits raises; none is a value anyway.
            raise InputError.at(
                "<arguments>", "a whole number too large to be a value (63 bits)", path=name
            )
    given = tuple(
        (c.name, str(combination[c.name])) for c in rules.characteristics if c.name in combination
    )
    reasons: list[str] = []
    values: dict[str, Value] = {}
    for characteristic in rules.characteristics:
        if characteristic.name not in combination:
            reasons.append(f"no {characteristic.name} given")
            continue
        text = str(combination[characteristic.name])
        value = characteristic.parse_value(text)
        if value is None:
            reasons.append(_unknown(characteristic, text))
        else:
            values[characteristic.name] = value
    relevant = tuple(
        (name, tuple(c.name for c in rules.characteristic(name).components_of(v)))
        for name, v in values.items()
    )
    if not reasons:
        robot = tuple(values[name] for name in rules.names)
        reasons = _team_reasons(solution, values) or [
            f"breaks rule {rule.describe()} at {rule.location}"
            for rule in violated_constraints(rules, robot)
        ]
        if not reasons:
            configuration = solution.configuration_for(robot)
            if configuration is not None:
                return Assignment(given, configuration.number, configuration, (), relevant)
            reasons = [
                f"{name} {value} is in no component of the rules (a gap)"
                for name, value in values.items()
                if not rules.characteristic(name).components_of(value)
            ]
    return Assignment(given, solution.default_configuration, None, tuple(reasons), relevant)


def _unknown(characteristic: Characteristic, text: str) -> str:
    if characteristic.kind == "integer":
        low, high = characteristic.values[0], characteristic.values[-1]
        given = shown(text, quoted=True)
        return f"{characteristic.name} {given} is not a whole number in {low}..{high}"
    hint = did_you_mean(text, [str(v) for v in characteristic.values])
    return f"unknown {characteristic.label.lower()} {shown(text, quoted=True)}{hint}"


def _team_reasons(solution: Solution, values: dict[str, Value]) -> list[str]:
    rules = solution.rules
    team = solution.team
    kinematic_type = str(values[rules.team_key])
    selection = team.selection(kinematic_type)
    if selection is None:
        return [
            f"{rules.key.label.lower()} {shown(kinematic_type, quoted=True)} is not in team "
            f"{shown(team.name, quoted=True)} "
            f"(it has {', '.join(team.kinematic_types)})"
        ]
    reasons = []
    for characteristic, domain in zip(rules.characteristics, selection.domains, strict=True):
        value = values[characteristic.name]
        if value in domain:
            continue
        if (
            characteristic.kind == "integer"
            and isinstance(value, int)
            and value > max(int(v) for v in domain)
        ):
            reasons.append(
                f"{value} is more than the {kinematic_type} maximum of "
                f"{max(int(v) for v in domain)} for {characteristic.name}"
            )
        else:
            reasons.append(
                f"{characteristic.name} {shown(value, quoted=True)} is not selected for "
                f"{kinematic_type} in team {shown(team.name, quoted=True)}"
            )
    return reasons


def assignment_data(solution: Solution, assignment: Assignment) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui assign --format json``."""
    configuration = assignment.configuration
    return {
        "team": solution.team.name,
        "combination": dict(assignment.given),
        "configuration": assignment.number,
        "default": assignment.is_default,
        "default_configuration": solution.default_configuration,
        "kinematic_type": None if configuration is None else configuration.kinematic_type,
        "components": None
        if configuration is None
        else configuration_data(solution.rules, configuration)["components"],
        "reasons": list(assignment.reasons),
        "relevant_components": {name: list(names) for name, names in assignment.relevant},
    }
