"""The symbolic counts of ``count --symbolic`` as text, JSON or Markdown.

The formulas themselves are made in :mod:`solver.solving.symbolic`; this module only shows them,
checked against the exact counts of the same team.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import sympy

from solver.files.output import dumps, text_table
from solver.reporting import markdown
from solver.solving.solution import Solution
from solver.solving.symbolic import Growth, agrees_with

__all__ = ["render_growth"]


def _pieces_text(expression: Any) -> str:
    """``1 for n <= 5, 2 for n <= 10`` for a Piecewise; the expression itself otherwise."""
    if isinstance(expression, sympy.Piecewise):
        return ", ".join(f"{sympy.sstr(e)} for {sympy.sstr(c)}" for e, c in expression.args)
    return str(sympy.sstr(expression))


def _sum_text(terms: Iterable[Any]) -> str:
    """A sum in the kinematic types' order (sympy would sort its terms by name)."""
    return " + ".join(sympy.sstr(term) for term in terms)


def render_growth(growth: Growth, solution: Solution, fmt: str = "text") -> str:
    """The formulas as text, JSON or Markdown, checked against the exact counts."""
    maxima = growth.at_team_maxima()
    robots_at = growth.evaluate(growth.total_robots, maxima)
    configurations_at = growth.evaluate(growth.total_configurations, maxima)
    totals = solution.totals
    agrees = agrees_with(growth, solution)
    verdict = (
        "equal to the exact count"
        if agrees
        else (
            f"DIFFERENT from the exact count {totals.valid_robots} / {totals.ui_configurations}: "
            "a bug, please report it"
        )
    )
    characteristic = growth.types[0].characteristic if growth.types else ""
    if fmt == "json":
        return dumps(
            {
                "team": growth.team.name,
                "rules": growth.team.rules.name,
                "characteristic": characteristic,
                "functions": {
                    name: {
                        "argument": "n",
                        "definition": sympy.sstr(definition),
                        "latex": sympy.latex(definition),
                    }
                    for name, _, definition in growth.functions
                },
                "by_type": [
                    {
                        "kinematic_type": t.kinematic_type,
                        "symbol": str(t.symbol),
                        "range": [t.low, t.high],
                        "team_maximum": t.at,
                        "valid_robots": sympy.sstr(t.robots),
                        "ui_configurations": sympy.sstr(t.configurations),
                    }
                    for t in growth.types
                ],
                "totals": {
                    "valid_robots": _sum_text(t.robots for t in growth.types),
                    "ui_configurations": _sum_text(t.configurations for t in growth.types),
                },
                "at_team_maxima": {
                    "maxima": {str(k): v for k, v in maxima.items()},
                    "valid_robots": robots_at,
                    "ui_configurations": configurations_at,
                    "equal_to_exact_count": agrees,
                },
            }
        )
    label = growth.team.rules.characteristic(characteristic).label if characteristic else ""
    lines = [
        f"{growth.team.name}: counts as functions of each kinematic type's maximum "
        f"{label} (n_<type>)",
        "",
    ]
    for name, _, definition in growth.functions:
        lines.append(f"{name}(n) = {_pieces_text(definition)}")
        lines.append(f"  (how many {label} components {growth.types[0].low}..n reach)")
    headers = ["kinematic type", "valid robots", "UI configurations"]
    rows = [
        [t.kinematic_type, _pieces_text(t.robots), _pieces_text(t.configurations)]
        for t in growth.types
    ]
    rows.append(
        [
            "total",
            _sum_text(t.robots for t in growth.types),
            _sum_text(t.configurations for t in growth.types),
        ]
    )
    shown = ", ".join(f"{k} = {v}" for k, v in maxima.items())
    check = (
        f"at the team's maxima ({shown}): {robots_at} valid robots, {configurations_at} "
        f"UI configurations ({verdict})"
    )
    if fmt == "markdown":
        return "\n".join([*lines, "", markdown.table(headers, rows), check]) + "\n"
    return "\n".join([*lines, "", text_table(headers, rows).rstrip("\n"), "", check]) + "\n"
