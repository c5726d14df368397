"""A team's design space as a UVL feature model, for feature-model tools (flamapy, FeatureIDE).

One alternative group per characteristic, one feature per value (integer characteristics as a
one-hot group of their counts, since plain UVL has no bounded integers), and per kinematic type
a constraint allowing only its selected values. The model's configurations are exactly the
team's valid robots. The rule set's own constraints become UVL constraints over the exported
values (a condition no exported value meets is false, one every value meets is dropped).

Names come from the user's rule set, so none is written raw: a feature is named with a plain
UVL identifier (``sensor_type_2D_Camera``) where that identifier is free, is no UVL keyword and
fits UVL's strict identifiers (ASCII letters, digits, ``_``); otherwise with a quoted name that
holds the exact text, where the four characters a quoted UVL name cannot hold (``"``, ``.``,
carriage return, newline), the ``%`` and every unprintable character are percent-encoded.
Two values never share a feature (a name already taken gets a ``_2``, ``_3``... suffix), so a
name such as ``a {abstract}`` or ``x\nconstraints`` adds no feature, attribute or constraint.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from solver.core.constraints import Condition, RuleConstraint, Value
from solver.core.team import Team
from solver.errors import SolverError

__all__ = ["ExportError", "FeatureNames", "feature_name", "team_to_uvl"]


class ExportError(SolverError, ValueError):
    """A team cannot be exported faithfully to the requested format."""


# UVL's strict identifiers (ID_STRICT, without the few non-ASCII letters it also allows), and
# the words its lexer reads as keywords before identifiers.
_STRICT = re.compile(r"[A-Za-z][A-Za-z0-9_]*", re.ASCII)
_KEYWORDS = frozenset(
    {
        *("include", "features", "imports", "namespace", "as", "constraint", "constraints"),
        *("cardinality", "String", "Boolean", "Integer", "Real", "len", "sum", "avg", "floor"),
        *("ceil", "Type", "Arithmetic", "or", "alternative", "optional", "mandatory"),
        *("true", "false"),
    }
)
# In a quoted UVL name (ID_NOT_STRICT: '"' ~[\r\n".]+ '"') these cannot stand; % is the escape.
_UNQUOTABLE = frozenset('".\r\n%')


def feature_name(characteristic: str, value: Value) -> str:
    """The readable UVL name of one value, ``sensor_type_2D_Camera``: what
    :class:`FeatureNames` writes when it is free and a strict UVL identifier."""
    return re.sub(r"\W", "_", f"{characteristic}_{value}")


def _quoted(text: str) -> str:
    encoded = "".join(
        f"%{ord(char):02X}" if char in _UNQUOTABLE or not char.isprintable() else char
        for char in text
    )
    return encoded or "%"


class FeatureNames:
    """Distinct, safe UVL names for a model's features (see the module docstring)."""

    def __init__(self) -> None:
        # Names as UVL reads them (a quoted name without its quotes): one feature each.
        self._taken = {"Team"}

    def name(self, text: str, readable: str | None = None) -> str:
        """The UVL name of the feature for ``text`` (written as ``readable`` when that is a
        free strict identifier)."""
        candidate = readable if readable is not None else text
        strict = _STRICT.fullmatch(candidate) is not None and candidate not in _KEYWORDS
        base = candidate if strict else _quoted(text)
        name, number = base, 2
        while name in self._taken:
            name, number = f"{base}_{number}", number + 1
        self._taken.add(name)
        return name if strict else f'"{name}"'


def team_to_uvl(team: Team) -> str:
    rules = team.rules
    characteristics = rules.characteristics
    names = FeatureNames()
    lines = ["namespace Team", "", "features", "    Team {abstract}", "        mandatory"]
    model = _Model({c.name: position for position, c in enumerate(characteristics)}, [], {})
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
        model.domains.append(values)
        group = names.name(characteristic.name)
        lines += [f"            {group} {{abstract}}", "                alternative"]
        for value in values:
            exact = f"{characteristic.name}_{value}"
            model.features[position, value] = names.name(
                exact, feature_name(characteristic.name, value)
            )
            lines.append(f"                    {model.features[position, value]}")
    constraints: list[str] = []
    for selection in team.selections:
        head = model.features[0, selection.kinematic_type]
        for position in range(1, len(characteristics)):
            allowed = selection.domains[position]
            if len(allowed) == len(model.domains[position]):
                continue
            options = " | ".join(model.features[position, v] for v in allowed)
            constraints.append(f"    {head} => ({options})")
    # The rule set's own constraints, over the exported domains.
    constraints += (
        text
        for constraint in rules.constraints
        if (text := _constraint(constraint, model)) is not None
    )
    if constraints:  # UVL rejects an empty constraints section
        lines += ["", "constraints", *constraints]
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class _Model:
    """What the constraints are written over: each characteristic's position, its exported
    values, and the UVL name of each (position, value)."""

    positions: dict[str, int]
    domains: list[list[Value]]
    features: dict[tuple[int, Value], str]


# The root feature is mandatory, so "!Team" is false: a rule no exported robot can satisfy.
_FALSE = "!Team"


def _condition(condition: Condition, model: _Model) -> bool | str:
    """A condition as a disjunction of features; ``True``/``False`` when it is decided."""
    position = model.positions[condition.characteristic]
    domain = model.domains[position]
    allowed = [v for v in domain if v in condition.allowed]
    if not allowed:
        return False
    if len(allowed) == len(domain):
        return True
    return "(" + " | ".join(model.features[position, v] for v in allowed) + ")"


def _conjunction(conditions: tuple[Condition, ...], model: _Model) -> bool | str:
    parts: list[str] = []
    for condition in conditions:
        part = _condition(condition, model)
        if part is False:
            return False
        if part is not True:
            parts.append(str(part))
    return " & ".join(parts) if parts else True


def _constraint(constraint: RuleConstraint, model: _Model) -> str | None:
    """One declared constraint as a UVL constraint line; ``None`` when it always holds."""
    then = _conjunction(constraint.conditions, model)
    if constraint.kind == "forbid":
        if then is False:
            return None
        return f"    {_FALSE}" if then is True else f"    !({then})"
    when = _conjunction(constraint.when, model)
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
