"""Rendering solutions, assignments and reproduction tables as text, JSON, CSV and Markdown.

The JSON shapes built here (:func:`solution_data`, :func:`assignment_data`) are the project's
documented, stable contract (README, "JSON output"); the other formats are views of the same
data. Output is deterministic: values in declared order, no timestamps, identical runs give
identical bytes.

Not here: the HTML/plot reports of ``teleop-ui report``.
"""

from __future__ import annotations

import csv
import io
import json
import re
from collections.abc import Sequence
from typing import Any

from solver import markdown
from solver.assignment import Assignment
from solver.engines import describe
from solver.partition import Configuration
from solver.reproduce import Comparison, published_note
from solver.rules import Characteristic, Component, RuleSet
from solver.solution import Solution, TypeSummary

__all__ = [
    "FORMATS",
    "assignment_data",
    "configuration_data",
    "csv_cell",
    "csv_row",
    "dumps",
    "integer_runs",
    "method_text",
    "render_assignment",
    "render_comparisons",
    "render_counts",
    "render_solution",
    "solution_data",
    "solution_warnings",
    "text_table",
]

FORMATS = ("text", "json", "csv", "markdown")


def _ratio(summary: TypeSummary) -> float | None:
    ratio = summary.reduction_ratio
    return None if ratio is None else round(ratio, 4)


def _summary_data(summary: TypeSummary) -> dict[str, Any]:
    data = {
        "kinematic_type": summary.kinematic_type,
        "valid_robots": summary.valid_robots,
        "ui_configurations": summary.ui_configurations,
        "reduction_ratio": _ratio(summary),
        "unserved_robots": summary.unserved_robots,
    }
    if summary.method:
        data["method"] = summary.method
    return data


def method_text(solution: Solution) -> str:
    """How the counts were obtained, in words, per kinematic type where they differ."""
    methods = [t.method for t in solution.by_type]
    if len(set(methods)) <= 1:
        return describe(methods[0]) if methods else "nothing to count"
    return "; ".join(f"{t.kinematic_type}: {describe(t.method)}" for t in solution.by_type)


def _component_data(
    characteristic: Characteristic, component: Component, served: Sequence[Any]
) -> dict[str, Any]:
    data: dict[str, Any] = {"characteristic": characteristic.name, "component": component.name}
    if characteristic.kind == "integer":
        counts = sorted(int(v) for v in served)
        data["range"] = [counts[0], counts[-1]]
        data["clusters"] = [component.clusters(counts[0]), component.clusters(counts[-1])]
        data["counts"] = [list(run) for run in integer_runs(counts)]
    else:
        data["values"] = list(served)
    return data


def configuration_data(rules: RuleSet, configuration: Configuration) -> dict[str, Any]:
    """One configuration: number, kinematic type, components and the robots it serves."""
    return {
        "number": configuration.number,
        "kinematic_type": configuration.kinematic_type,
        "valid_robots": configuration.robots,
        "components": [
            _component_data(c, component, served)
            for c, component, served in zip(
                rules.characteristics, configuration.components, configuration.served, strict=True
            )
        ],
    }


def _default_components(rules: RuleSet) -> dict[str, list[str]]:
    return {c.name: [component.name for component in c.components] for c in rules.characteristics}


def solution_data(solution: Solution, *, configurations: bool = False) -> dict[str, Any]:
    """The JSON contract of ``teleop-ui solve --format json``."""
    rules = solution.rules
    team = solution.team
    data: dict[str, Any] = {
        "team": team.name,
        "team_file": team.file,
        "rules": rules.name,
        "rules_file": rules.file,
        "engine": solution.engine,
        "bound": solution.bound,
        "bound_factors": dict(zip(rules.names, rules.bound_factors, strict=True)),
        "by_type": [_summary_data(t) for t in solution.by_type],
        "totals": {
            k: v for k, v in _summary_data(solution.totals).items() if k != "kinematic_type"
        },
        "default_configuration": solution.default_configuration,
        "default_components": _default_components(rules),
        "listed": solution.listed,
        "proven_minimal": solution.proven_minimal,
        "published": None
        if team.published is None
        else {
            "valid_robots": team.published.valid_robots,
            "ui_configurations": team.published.ui_configurations,
            "source": team.published.source,
        },
        # What text output prints as "warning: ..." lines (solution_warnings), for programs.
        "warnings": [w.removeprefix("warning: ") for w in solution_warnings(solution)],
    }
    if configurations:
        data["configurations"] = [configuration_data(rules, c) for c in solution.configurations]
    return data


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


def dumps(data: Any) -> str:
    """JSON as the project writes it everywhere: indented, UTF-8 kept, trailing newline."""
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def text_table(
    headers: Sequence[str], rows: Sequence[Sequence[Any]], right: Sequence[bool] | None = None
) -> str:
    """A plain aligned table; ``right[i]`` right-aligns column i (numbers)."""
    cells = [
        [str(h) for h in headers],
        *[["" if v is None else str(v) for v in row] for row in rows],
    ]
    widths = [max(len(row[i]) for row in cells) for i in range(len(headers))]
    align = right or [False] * len(headers)
    lines = []
    for row in cells:
        parts = [
            cell.rjust(w) if a else cell.ljust(w)
            for cell, w, a in zip(row, widths, align, strict=True)
        ]
        lines.append("  ".join(parts).rstrip())
    return "\n".join(lines) + "\n"


# A spreadsheet reads a cell starting with one of these as a formula (OWASP "CSV injection"):
# `=HYPERLINK(...)` in a team's name would run when someone opens the summary.
_FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
_NUMBER = re.compile(r"[+-]?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?")


def csv_cell(value: Any) -> Any:
    """``value`` as a CSV cell no spreadsheet runs: text that starts like a formula gets a
    leading ``'`` (OWASP's advice); numbers, and text that is just a number, are left alone."""
    if (
        isinstance(value, str)
        and value.startswith(_FORMULA_STARTS)
        and _NUMBER.fullmatch(value) is None
    ):
        return "'" + value
    return value


def csv_row(values: Sequence[Any]) -> list[Any]:
    """:func:`csv_cell` of every value of a row."""
    return [csv_cell(value) for value in values]


def _csv(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(csv_row(headers))
    writer.writerows(csv_row(row) for row in rows)
    return buffer.getvalue()


def _summary_rows(solution: Solution) -> list[list[Any]]:
    rows = []
    for summary in (*solution.by_type, solution.totals):
        ratio = summary.reduction_ratio
        rows.append(
            [
                summary.kinematic_type,
                summary.valid_robots,
                summary.ui_configurations,
                "" if ratio is None else f"{ratio:.2f}",
            ]
        )
    return rows


def _component_text(
    characteristic: Characteristic, component: Component, served: Sequence[Any]
) -> str:
    if characteristic.kind != "integer":
        return component.name
    counts = sorted(int(v) for v in served)
    clusters = sorted({component.clusters(count) for count in counts})
    return f"{component.name} ({_runs_text(counts)}: {_runs_text(clusters)} clusters)"


def integer_runs(numbers: Sequence[int]) -> list[tuple[int, int]]:
    """Sorted whole numbers as runs of consecutive ones: [1, 2, 3, 7] -> [(1, 3), (7, 7)]."""
    found: list[tuple[int, int]] = []
    for number in numbers:
        if found and number == found[-1][1] + 1:
            found[-1] = (found[-1][0], number)
        else:
            found.append((number, number))
    return found


def _runs_text(numbers: Sequence[int]) -> str:
    return ", ".join(
        f"{low}" if low == high else f"{low}..{high}" for low, high in integer_runs(numbers)
    )


def _configuration_rows(solution: Solution) -> tuple[list[str], list[list[Any]]]:
    rules = solution.rules
    headers = ["#", *(c.label for c in rules.characteristics), "robots"]
    rows = []
    for configuration in solution.configurations:
        rows.append(
            [
                configuration.number,
                *(
                    _component_text(c, component, served)
                    for c, component, served in zip(
                        rules.characteristics,
                        configuration.components,
                        configuration.served,
                        strict=True,
                    )
                ),
                configuration.robots,
            ]
        )
    return headers, rows


_SUMMARY_HEADERS = [
    "kinematic type",
    "valid robots",
    "UI configurations",
    "robots per configuration",
]


def render_solution(solution: Solution, fmt: str = "text", *, configurations: bool = False) -> str:
    """A solution in ``fmt`` (one of :data:`FORMATS`); ``configurations`` adds the list."""
    if fmt == "json":
        return dumps(solution_data(solution, configurations=configurations))
    if fmt == "csv":
        if configurations:
            headers, rows = _configuration_rows(solution)
            return _csv(
                ["number", *solution.rules.names, "valid_robots"],
                [[row[0], *row[1:-1], row[-1]] for row in rows],
            )
        return _csv(
            ["kinematic_type", "valid_robots", "ui_configurations", "reduction_ratio"],
            _summary_rows(solution),
        )
    numbers = [False, True, True, True]
    if fmt == "markdown":
        summary = markdown.table(_SUMMARY_HEADERS, _summary_rows(solution), numbers)
        parts = [
            markdown.heading(2, solution.team.name) + "\n",
            "",
            summary,
            "",
            *(f"{markdown.escape(line)}  " for line in _footer(solution)),
        ]
        if configurations:
            headers, rows = _configuration_rows(solution)
            parts += [
                "",
                markdown.table(headers, rows, [True] + [False] * (len(headers) - 2) + [True]),
            ]
        return "\n".join(parts).rstrip("\n") + "\n"
    rules = solution.rules
    text = f"{solution.team.name}  (rules: {rules.name}, {rules.file})\n\n"
    text += text_table(_SUMMARY_HEADERS, _summary_rows(solution), numbers)
    text += "\n" + "\n".join(_footer(solution)) + "\n"
    if configurations:
        headers, rows = _configuration_rows(solution)
        text += "\n" + text_table(headers, rows, [True] + [False] * (len(headers) - 2) + [True])
    return text


def render_counts(solution: Solution, fmt: str = "text") -> str:
    """Per-type counts only (``teleop-ui count``): text, JSON or Markdown."""
    if fmt == "json":
        return dumps(
            {
                "team": solution.team.name,
                "rules": solution.rules.name,
                "rules_file": solution.rules.file,
                "bound": solution.bound,
                "by_type": [_summary_data(t) for t in solution.by_type],
                "totals": {
                    k: v for k, v in _summary_data(solution.totals).items() if k != "kinematic_type"
                },
                "default_configuration": solution.default_configuration,
            }
        )
    headers = ["kinematic type", "valid robots", "UI configurations", "how"]
    rows = [
        [t.kinematic_type, t.valid_robots, t.ui_configurations, t.method] for t in solution.by_type
    ]
    totals = solution.totals
    rows.append(["total", totals.valid_robots, totals.ui_configurations, ""])
    align = [False, True, True, False]
    if fmt == "markdown":
        return (
            markdown.heading(2, solution.team.name) + "\n\n" + markdown.table(headers, rows, align)
        )
    return (
        f"{solution.team.name}  (rules: {solution.rules.name}, {solution.rules.file})\n\n"
        + text_table(headers, rows, align)
    )


def solution_warnings(solution: Solution) -> list[str]:
    """What a reader of the counts must know: selected values the constraints exclude, robots
    left unserved, a minimum not proven. The one place for them: solve, report and batch."""
    warnings = [
        f"warning: the rules' constraints exclude what the team selects: "
        f"{removed.describe()}; such robots get the default configuration"
        for removed in solution.removed
    ]
    if solution.totals.unserved_robots:
        warnings.append(
            f"warning: {solution.totals.unserved_robots} valid robots have a value "
            "in no component and get the default configuration (run teleop-ui "
            "check)"
        )
    if not solution.proven_minimal:
        warnings.append(
            "warning: overlapping components; the configuration count is the best "
            "found, not proven minimal"
        )
    return warnings


def _footer(solution: Solution) -> list[str]:
    rules = solution.rules
    factors = " x ".join(str(n) for n in rules.bound_factors)
    lines = [
        f"bound T = {solution.bound} ({factors})",
        f"how: {method_text(solution)}",
        f"default UI configuration: {solution.default_configuration} "
        f"(every component: {sum(rules.bound_factors)})",
    ]
    lines += solution_warnings(solution)
    note = published_note(solution)
    if note is not None:
        stated, verdict, _ = note
        lines += [stated, f"  {verdict}"]
    return lines


def render_assignment(solution: Solution, assignment: Assignment, fmt: str = "text") -> str:
    """An assignment as text or JSON."""
    if fmt == "json":
        return dumps(assignment_data(solution, assignment))
    given = " ".join(f"{name}={value}" for name, value in assignment.given) or "(nothing)"
    rules = solution.rules
    configuration = assignment.configuration
    if configuration is not None:
        lines = [f"UI configuration {assignment.number} for {given}"]
        values = dict(assignment.given)
        for characteristic, component in zip(
            rules.characteristics, configuration.components, strict=True
        ):
            own = [characteristic.parse_value(values[characteristic.name])]
            lines.append(
                f"  {characteristic.label}: {_component_text(characteristic, component, own)}"
            )
        lines.append(
            f"  (serves {configuration.robots} valid robots of team {solution.team.name!r})"
        )
        return "\n".join(lines) + "\n"
    lines = [f"default UI configuration {assignment.number} for {given}"]
    lines += [f"  invalid: {reason}" for reason in assignment.reasons]
    relevant = [
        (rules.characteristic(name).label, names) for name, names in assignment.relevant if names
    ]
    if relevant:
        lines.append("  components relevant to the known values:")
        lines += [f"    {label}: {', '.join(names)}" for label, names in relevant]
    return "\n".join(lines) + "\n"


def render_comparisons(comparisons: Sequence[Comparison], fmt: str = "markdown") -> str:
    """Published beside computed figures, one row per team."""
    headers = [
        "team",
        "file",
        "published robots / configurations",
        "computed robots / configurations",
        "reproduced",
    ]
    rows = []
    for comparison in comparisons:
        totals = comparison.solution.totals
        rows.append(
            [
                comparison.solution.team.name,
                comparison.file,
                f"{comparison.published.valid_robots} / {comparison.published.ui_configurations}",
                f"{totals.valid_robots} / {totals.ui_configurations}",
                "yes" if comparison.agrees else "no",
            ]
        )
    if fmt == "json":
        return dumps(
            [
                {
                    "team": r[0],
                    "file": r[1],
                    "published": {
                        "valid_robots": c.published.valid_robots,
                        "ui_configurations": c.published.ui_configurations,
                    },
                    "computed": {
                        "valid_robots": c.solution.totals.valid_robots,
                        "ui_configurations": c.solution.totals.ui_configurations,
                    },
                    "reproduced": c.agrees,
                }
                for r, c in zip(rows, comparisons, strict=True)
            ]
        )
    if fmt == "text":
        return text_table(headers, rows)
    if fmt == "csv":
        return _csv(headers, rows)
    return markdown.table(headers, rows)
