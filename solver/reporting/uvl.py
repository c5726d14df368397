"""A team's design space as a UVL feature model, for feature-model tools (flamapy, FeatureIDE).

One alternative group per characteristic, one feature per value (integer characteristics as a
one-hot group of their counts, since plain UVL has no bounded integers), and per kinematic type
a constraint allowing only its selected values. The model's configurations are exactly the
team's valid robots. The rule set's own constraints become UVL constraints over the exported
values (a condition no exported value meets is false, one every value meets is dropped).
"""

from __future__ import annotations

import re

from solver.core.constraints import Condition, RuleConstraint, Value
from solver.core.team import Team
from solver.errors import SolverError

__all__ = ["ExportError", "feature_name", "team_to_uvl"]


class ExportError(SolverError, ValueError):
    """A team cannot be exported faithfully to the requested format."""


def feature_name(characteristic: str, value: Value) -> str:
    """A UVL identifier for one value: ``sensor_type_2D_Camera``."""
    return re.sub(r"\W", "_", f"{characteristic}_{value}")


def team_to_uvl(team: Team) -> str:
    rules = team.rules
    characteristics = rules.characteristics
    lines = ["namespace Team", "", "features", "    Team {abstract}", "        mandatory"]
    domains: list[list[Value]] = []
    for position, characteristic in enumerate(characteristics):
        # Every value any selected type may take (integers: 1..the largest maximum).
        values: list[Value] = []
        for selection in team.selections:
            values.extend(v for v in selection.domains[position] if v not in values)
        if characteristic.kind == "integer":
            values = sorted(values, key=int)
        else:
            order = list(characteristic.values)
            values = sorted(values, key=lambda v: order.index(v) if v in order else len(order))
        domains.append(values)
        lines += [f"            {characteristic.name} {{abstract}}", "                alternative"]
        lines += [f"                    {feature_name(characteristic.name, v)}" for v in values]
    constraints: list[str] = []
    kinematic = characteristics[0].name
    for selection in team.selections:
        head = feature_name(kinematic, selection.kinematic_type)
        for position in range(1, len(characteristics)):
            allowed = selection.domains[position]
            if len(allowed) == len(domains[position]):
                continue
            name = characteristics[position].name
            options = " | ".join(feature_name(name, v) for v in allowed)
            constraints.append(f"    {head} => ({options})")
    # The rule set's own constraints, over the exported domains.
    positions = {c.name: position for position, c in enumerate(characteristics)}
    constraints += (
        text
        for constraint in rules.constraints
        if (text := _constraint(constraint, positions, domains)) is not None
    )
    if constraints:  # UVL rejects an empty constraints section
        lines += ["", "constraints", *constraints]
    return "\n".join(lines) + "\n"


# The root feature is mandatory, so "!Team" is false: a rule no exported robot can satisfy.
_FALSE = "!Team"


def _condition(
    condition: Condition, positions: dict[str, int], domains: list[list[Value]]
) -> bool | str:
    """A condition as a disjunction of features; ``True``/``False`` when it is decided."""
    domain = domains[positions[condition.characteristic]]
    allowed = [v for v in domain if v in condition.allowed]
    if not allowed:
        return False
    if len(allowed) == len(domain):
        return True
    return "(" + " | ".join(feature_name(condition.characteristic, v) for v in allowed) + ")"


def _conjunction(
    conditions: tuple[Condition, ...], positions: dict[str, int], domains: list[list[Value]]
) -> bool | str:
    parts: list[str] = []
    for condition in conditions:
        part = _condition(condition, positions, domains)
        if part is False:
            return False
        if part is not True:
            parts.append(str(part))
    return " & ".join(parts) if parts else True


def _constraint(
    constraint: RuleConstraint, positions: dict[str, int], domains: list[list[Value]]
) -> str | None:
    """One declared constraint as a UVL constraint line; ``None`` when it always holds."""
    then = _conjunction(constraint.conditions, positions, domains)
    if constraint.kind == "forbid":
        if then is False:
            return None
        return f"    {_FALSE}" if then is True else f"    !({then})"
    when = _conjunction(constraint.when, positions, domains)
    if when is False or then is True:
        return None
    if when is True:
        return f"    {_FALSE}" if then is False else f"    {then}"
    if then is False:
        return f"    !({when})"
    return f"    {_grouped(when)} => {_grouped(then)}"


def _grouped(conjunction: str) -> str:
    # One condition is already parenthesised; a conjunction of several gets its own pair.
    return f"({conjunction})" if " & " in conjunction else conjunction
