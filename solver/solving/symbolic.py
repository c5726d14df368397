"""Counts as formulas of each kinematic type's maximum sensor count (sympy).

For a team shape (the categorical selections fixed), how do valid robots and UI configurations
grow as robots of a type gain sensors? With ``n`` the maximum of a type's integer
characteristic (robots have ``low..n`` sensors):

* when no rule constraint mentions that characteristic, every count adds the same robots, so
  ``valid robots = R * (n - low + 1)`` and ``UI configurations = C * A(n)``, where ``A(n)``,
  the number of the characteristic's components (arrangements) that ``low..n`` reaches, is a
  piecewise function read off the rule set's component ranges;
* otherwise the domain ``low..max`` splits into runs of counts the rules cannot tell apart, and
  both counts are piecewise in ``n`` with one piece per run (linear robots, constant
  configurations), each piece's coefficients taken from the exact counter.

sympy is for the formulas people read; the numbers come from :mod:`solver.engines.structure` (plain
integers), and the formulas are checked against it at every ``n`` in the tests. sympy takes a
while to import, so only this module imports it, and only ``teleop-ui count --symbolic`` imports
this module.

A formula has a piece per run of counts, up to 100,000 of them: pieces are built as they are
(``n <= end``, ends ascending) without sympy's simplification of each condition, and a
formula is evaluated at the numbers given, each arrangement function by bisection over its
ends; both were quadratic in the pieces (5,000 components: 44 s). The formulas of a team
have a time budget (limit ``symbolic-seconds``, :mod:`solver.deadline`), looked at between
counts.

Not here: exact integer counting (:mod:`solver.engines.structure`).
"""

from __future__ import annotations

import re
from bisect import bisect_left
from dataclasses import dataclass, replace
from typing import Any

import sympy

from solver.core.ruleset import Characteristic, RuleSet
from solver.core.team import Team, TypeSelection
from solver.deadline import Deadline
from solver.engines.structure import count
from solver.errors import InputError, Location
from solver.solving.solution import Solution

__all__ = [
    "Growth",
    "TypeFormula",
    "agrees_with",
    "formulas",
    "symbol_name",
]


@dataclass(frozen=True)
class TypeFormula:
    """The counts of one kinematic type as functions of its maximum ``symbol``."""

    kinematic_type: str
    characteristic: str
    symbol: Any  # sympy.Symbol
    low: int
    high: int  # the largest maximum the rules allow
    at: int  # the team's own maximum
    robots: Any  # sympy expression in symbol
    configurations: Any  # sympy expression in symbol (may use the function A)


@dataclass(frozen=True)
class Growth:
    """Formulas for a whole team, and the arrangement functions they use."""

    team: Team
    types: tuple[TypeFormula, ...]
    # Name -> (symbol, Piecewise) of the arrangement-count functions used above.
    functions: tuple[tuple[str, Any, Any], ...]

    @property
    def total_robots(self) -> Any:
        return sympy.Add(*(t.robots for t in self.types))

    @property
    def total_configurations(self) -> Any:
        return sympy.Add(*(t.configurations for t in self.types))

    def evaluate(self, expression: Any, values: dict[Any, int]) -> int:
        """An expression at given maxima, arrangement functions expanded: an exact integer.

        The numbers go in first, so each arrangement function is asked at a number
        (:func:`_at`), not rewritten for a symbol piece by piece."""
        expanded = expression.subs(values)
        for _, function, definition in self.functions:
            expanded = expanded.replace(function, lambda x, d=definition: _at(d, x))
        return int(expanded)

    def at_team_maxima(self) -> dict[Any, int]:
        return {t.symbol: t.at for t in self.types}


def symbol_name(kinematic_type: str, characteristic: str, several: bool) -> str:
    """``n_Mobile_Manipulator`` (or ``n_UAV_sensor_count`` when a type has several)."""
    base = re.sub(r"\W+", "_", kinematic_type).strip("_") or "type"
    return f"n_{base}_{characteristic}" if several else f"n_{base}"


def formulas(team: Team, *, time_limit: float | None = None) -> Growth:
    """Symbolic counts for every kinematic type of ``team``; :class:`InputError` if the team's
    shape has no single growing count (no integer characteristic, or a selection with holes).

    ``time_limit``: seconds the formulas may take (default: the ``symbolic-seconds`` limit);
    past it, :class:`~solver.errors.TimeLimitError` at the team file."""
    deadline = _Clock(Deadline.start("symbolic-seconds", "count --symbolic", time_limit), team)
    rules = team.rules
    integers = [c for c in rules.characteristics if c.kind == "integer"]
    if len(integers) != 1:
        raise InputError.at(
            rules.file,
            f"symbolic counts need exactly one whole-number "
            f"characteristic to grow (the rules have "
            f"{len(integers)})",
        )
    characteristic = integers[0]
    position = rules.names.index(characteristic.name)
    functions: dict[str, tuple[str, Any, Any]] = {}
    types = []
    used: set[str] = set()
    for selection in team.selections:
        deadline.check()
        domain = [int(v) for v in selection.domains[position]]
        low, at = domain[0], domain[-1]
        if domain != list(range(low, at + 1)):
            raise InputError.at(
                team.file,
                f"{selection.kinematic_type}: symbolic counts need "
                f"{characteristic.name} to be a range low..max",
            )
        high = int(characteristic.values[-1])
        name = symbol_name(selection.kinematic_type, characteristic.name, False)
        while name in used:  # "Mobile Manipulator" and "Mobile-Manipulator" read alike
            name += "_"
        used.add(name)
        # Only `integer`: counts may be 0 or negative in a rule set's range.
        symbol = sympy.Symbol(name, integer=True)
        independent = all(c.is_partition for c in rules.characteristics) and not any(
            characteristic.name in rule.characteristics for rule in rules.constraints
        )
        if not independent:
            robots, configurations = _piecewise(
                rules, selection, position, (low, high), symbol, deadline=deadline
            )
        else:
            robots, configurations = _factored(rules, selection, position, symbol, functions)
        types.append(
            TypeFormula(
                selection.kinematic_type,
                characteristic.name,
                symbol,
                low,
                high,
                at,
                robots,
                configurations,
            )
        )
    return Growth(team, tuple(types), tuple(functions.values()))


class _Clock:
    """A deadline, and the team file its refusal names."""

    def __init__(self, deadline: Deadline, team: Team) -> None:
        self.deadline = deadline
        self.location = Location(team.file)

    def check(self) -> None:
        self.deadline.check(self.location)


def _restricted(selection: TypeSelection, position: int, values: range) -> TypeSelection:
    domains = list(selection.domains)
    domains[position] = tuple(values)
    return replace(selection, domains=tuple(domains))


def _factored(
    rules: RuleSet,
    selection: TypeSelection,
    position: int,
    symbol: Any,
    functions: dict[str, tuple[str, Any, Any]],
) -> tuple[Any, Any]:
    """Counts when the count characteristic is independent: R * (n - low + 1), C * A(n)."""
    characteristic = rules.characteristics[position]
    low = int(selection.domains[position][0])
    single = count(rules, _restricted(selection, position, range(low, low + 1)))
    served = characteristic.components_of(low)
    per_count_robots = single.valid_robots
    # Configurations per component of the count, the same for every component reached.
    per_component = (
        single.ui_configurations
        if served
        else _first_served_configurations(rules, selection, position, low, characteristic)
    )
    name = f"A_{characteristic.name}" if low == 1 else f"A_{characteristic.name}_from_{low}"
    if name not in functions:
        argument = sympy.Symbol("n", integer=True)
        functions[name] = (
            name,
            sympy.Function(name),
            _arrangements_reached(characteristic, low, argument),
        )
    function = functions[name][1]
    return (per_count_robots * (symbol - low + 1), per_component * function(symbol))


def _first_served_configurations(
    rules: RuleSet,
    selection: TypeSelection,
    position: int,
    low: int,
    characteristic: Characteristic,
) -> int:
    for value in characteristic.values:
        if int(value) >= low and characteristic.components_of(value):
            one = count(rules, _restricted(selection, position, range(int(value), int(value) + 1)))
            return one.ui_configurations
    return 0


def _arrangements_reached(characteristic: Characteristic, low: int, n: Any) -> Any:
    """A(n): how many components the counts low..n reach, as a Piecewise in n."""
    pieces = []
    reached: set[int] = set()
    for value in (int(v) for v in characteristic.values if int(v) >= low):
        reached.update(c.index for c in characteristic.components_of(value))
        pieces.append((sympy.Integer(len(reached)), value))
    return _piecewise_of(pieces, n)


def _piecewise(
    rules: RuleSet,
    selection: TypeSelection,
    position: int,
    bounds: tuple[int, int],
    symbol: Any,
    *,
    deadline: _Clock,
) -> tuple[Any, Any]:
    """Counts when constraints read the count: one piece per run of indistinguishable counts."""
    low, high = bounds
    # The value class of each count: counts in one class are indistinguishable to the rules.
    signature = {
        value: number
        for number, members in enumerate(rules.value_classes[position])
        for value in members
    }

    robot_pieces = []
    configuration_pieces = []
    start = low
    while start <= high:
        deadline.check()
        end = start
        while end + 1 <= high and signature[end + 1] == signature[start]:
            end += 1
        before = count(rules, _restricted(selection, position, range(low, start + 1)))
        each = count(rules, _restricted(selection, position, range(start, start + 1)))
        robot_pieces.append(
            (sympy.expand(before.valid_robots + each.valid_robots * (symbol - start)), end)
        )
        configuration_pieces.append((sympy.Integer(before.ui_configurations), end))
        start = end + 1
    return _piecewise_of(robot_pieces, symbol), _piecewise_of(configuration_pieces, symbol)


def _piecewise_of(pieces: list[tuple[Any, int]], symbol: Any) -> Any:
    """Piecewise((expression, symbol <= end), ...), neighbours with equal expressions merged.

    Built as it is: the ends ascend and no two neighbours are equal, so there is nothing for
    sympy to simplify, and asking it to (each condition against the symbol's assumptions,
    each piece against the ones before) took seconds for 5,000 pieces."""
    merged: list[tuple[Any, int]] = []
    for expression, end in pieces:
        if merged and merged[-1][0] == expression:
            merged[-1] = (expression, end)
        else:
            merged.append((expression, end))
    return sympy.Piecewise(
        *((expression, sympy.Le(symbol, end, evaluate=False)) for expression, end in merged),
        evaluate=False,
    )


def _at(definition: Any, value: Any) -> Any:
    """An arrangement function (a Piecewise of :func:`_piecewise_of`, in its argument ``n``)
    at ``value``: the piece whose end is the first at or past it, found by bisection; NaN
    past the last end, as the Piecewise itself says. A symbolic ``value`` is substituted."""
    argument = definition.args[0][1].lhs
    if not value.is_Integer:
        return definition.subs(argument, value)
    ends = [int(condition.rhs) for _, condition in definition.args]
    index = bisect_left(ends, int(value))
    if index == len(ends):
        return sympy.nan
    return definition.args[index][0].subs(argument, value)


def agrees_with(growth: Growth, solution: Solution) -> bool:
    """Whether the formulas at the team's maxima give the exact counts of ``solution``."""
    maxima = growth.at_team_maxima()
    totals = solution.totals
    return (
        growth.evaluate(growth.total_robots, maxima),
        growth.evaluate(growth.total_configurations, maxima),
    ) == (totals.valid_robots, totals.ui_configurations)
