"""A team's design space as a UVL feature model, for feature-model tools (flamapy, FeatureIDE).

One alternative group per characteristic, one feature per value (integer characteristics as a
one-hot group of their counts, since plain UVL has no bounded integers), and per kinematic type
a constraint allowing only its selected values. The model's configurations are exactly the
team's valid robots. Not here: rule sets that declare constraints of their own (refused with a
located error rather than exported wrongly).
"""

from __future__ import annotations

import re

from solver.constraints import Value
from solver.errors import SolverError
from solver.team import Team

__all__ = ["ExportError", "feature_name", "team_to_uvl"]


class ExportError(SolverError, ValueError):
    """A team cannot be exported faithfully to the requested format."""


def feature_name(characteristic: str, value: Value) -> str:
    """A UVL identifier for one value: ``sensor_type_2D_Camera``."""
    return re.sub(r"\W", "_", f"{characteristic}_{value}")


def team_to_uvl(team: Team) -> str:
    rules = team.rules
    if rules.constraints:
        raise ExportError.at(
            team.file,
            "UVL export does not translate the rule set's "
            f"constraints yet ({len(rules.constraints)} declared); refused "
            "rather than exporting a different design space",
            code="unsupported",
        )
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
    if constraints:  # UVL rejects an empty constraints section
        lines += ["", "constraints", *constraints]
    return "\n".join(lines) + "\n"
