"""Rendering solutions, assignments and reproduction tables as text, JSON, CSV and Markdown.

The JSON shapes are the project's documented, stable contract and live with their types
(:mod:`solver.solving.contracts`); the formats here are views of the same data. Output is
deterministic: values in declared order, no timestamps, identical runs give identical bytes.

Not here: the HTML/plot reports of ``teleop-ui report``.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from json.encoder import encode_basestring as _quoted
from typing import TYPE_CHECKING, Any

from solver.engines import describe
from solver.files.output import csv_text, dumps, json_printable, nested_json, text_table
from solver.reporting import markdown
from solver.solving.contracts import component_data, configuration_data, integer_runs
from solver.solving.solution import counts_data, solution_data, solution_warnings
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from solver.core.partition import Configuration
    from solver.core.ruleset import Characteristic, Component, RuleSet
    from solver.solving.assignment import Assignment
    from solver.solving.reproduce import Comparison
    from solver.solving.solution import Solution

__all__ = [
    "FORMATS",
    "method_text",
    "render_assignment",
    "render_comparisons",
    "render_counts",
    "render_solution",
    "solution_chunks",
]

FORMATS = ("text", "json", "csv", "markdown")


def method_text(solution: Solution) -> str:
    """How the counts were obtained, in words, per kinematic type where they differ."""
    methods = [t.method for t in solution.by_type]
    if len(set(methods)) <= 1:
        return describe(methods[0]) if methods else "nothing to count"
    return "; ".join(f"{t.kinematic_type}: {describe(t.method)}" for t in solution.by_type)


def _csv(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    return csv_text([headers, *rows])


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


def _runs_text(numbers: Sequence[int]) -> str:
    return ", ".join(
        f"{low}" if low == high else f"{low}..{high}" for low, high in integer_runs(numbers)
    )


def _configuration_rows(
    solution: Solution, configurations: Sequence[Configuration] | None = None
) -> tuple[list[str], list[list[Any]]]:
    rules = solution.rules
    headers = ["#", *(c.label for c in rules.characteristics), "robots"]
    rows = []
    for configuration in solution.configurations if configurations is None else configurations:
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
    if fmt in ("json", "csv"):
        return "".join(solution_chunks(solution, fmt, configurations=configurations))
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
    text = _title(solution) + "\n\n"
    text += text_table(_SUMMARY_HEADERS, _summary_rows(solution), numbers)
    text += "\n" + "\n".join(shown(line, limit=None) for line in _footer(solution)) + "\n"
    if configurations:
        headers, rows = _configuration_rows(solution)
        text += "\n" + text_table(headers, rows, [True] + [False] * (len(headers) - 2) + [True])
    return text


# Configurations per chunk of a streamed listing: few writes, little memory.
_CHUNK = 500


def solution_chunks(
    solution: Solution, fmt: str = "json", *, configurations: bool = False
) -> Iterator[str]:
    """:func:`render_solution` as JSON or CSV, in chunks of a few hundred configurations: the
    same text, never all in memory (450,000 configurations are 330 MB of JSON)."""
    if fmt == "csv":
        if not configurations:
            yield _csv(
                ["kinematic_type", "valid_robots", "ui_configurations", "reduction_ratio"],
                _summary_rows(solution),
            )
            return
        yield _csv(["number", *solution.rules.names, "valid_robots"], [])
        for start in range(0, len(solution.configurations), _CHUNK):
            _, rows = _configuration_rows(solution, solution.configurations[start : start + _CHUNK])
            yield csv_text(rows)
        return
    if fmt != "json":
        raise ValueError(f"fmt must be json or csv (got {fmt!r})")
    head = dumps(solution_data(solution))
    if not configurations:
        yield head
        return
    # The configurations are the last field: the head without its closing brace, then each
    # configuration as json.dumps(indent=2) writes it two levels down.
    listed = solution.configurations
    yield head[: -len("\n}\n")] + ',\n  "configurations": ' + ("[" if listed else "[]")
    rules = solution.rules
    parts = _Parts()  # for the whole listing
    for start in range(0, len(listed), _CHUNK):
        yield ("," if start else "") + _configurations_text(
            rules, listed[start : start + _CHUNK], parts
        )
    yield ("\n  ]" if listed else "") + "\n}\n"


_AT_CONFIGURATION = "\n    "  # a listed configuration's place: two levels down
_AT_COMPONENT = "\n        "  # its components' places: two levels further down


class _Parts:
    """What the configurations of one listing share, each written once: the JSON text of a
    component's part (by characteristic, component and values served) and of a kinematic
    type's name, both already passed through :func:`json_printable`."""

    def __init__(self) -> None:
        # By characteristic, component and the identity of the values served: the tuples of
        # values are shared by the configurations that share a block's part, and live as long
        # as the solution that the listing is written from.
        self.components: dict[tuple[int, int, int], str] = {}
        self.names: dict[str, str] = {}


def _configurations_text(
    rules: RuleSet, configurations: Sequence[Configuration], parts: _Parts
) -> str:
    """The text ``dumps`` gives each configuration's :func:`configuration_data` inside the
    listing (each on a new line, four spaces in, joined by commas). Most configurations share
    most of their components (a kinematic type's own, a motion control's), so a configuration
    is a few lookups in ``parts`` and one format."""
    texts = []
    characteristics = rules.characteristics
    for configuration in configurations:
        number, kinematic_type, robots = (
            configuration.number,
            configuration.kinematic_type,
            configuration.robots,
        )
        if not (type(number) is type(robots) is int and type(kinematic_type) is str):
            texts.append(_AT_CONFIGURATION + _nested(configuration_data(rules, configuration)))
            continue
        pieces = []
        for position, (characteristic, component, served) in enumerate(
            zip(characteristics, configuration.components, configuration.served, strict=True)
        ):
            key = (position, configuration.key[position], id(served))
            text = parts.components.get(key)
            if text is None:
                text = parts.components[key] = _AT_COMPONENT + _component_json(
                    characteristic, component, served
                )
            pieces.append(text)
        name = parts.names.get(kinematic_type)
        if name is None:
            name = parts.names[kinematic_type] = json_printable(_quoted(kinematic_type))
        components = "[" + ",".join(pieces) + "\n      ]" if pieces else "[]"
        texts.append(
            f'{_AT_CONFIGURATION}{{\n      "number": {int.__repr__(number)},\n'
            f'      "kinematic_type": {name},\n'
            f'      "valid_robots": {int.__repr__(robots)},\n'
            f'      "components": {components}\n    }}'
        )
    return ",".join(texts)


# A listed component's lines: its fields two levels below the configuration's, its lists'
# items one more.
_AT_FIELD = _AT_COMPONENT + "  "
_AT_ITEM = _AT_FIELD + "  "


def _component_json(characteristic: Characteristic, component: Component, served: Any) -> str:
    """``_nested(component_data(...), 2)`` for a listed component, written directly in the
    shape :func:`~solver.solving.contracts.component_data` gives it: its parts are 40% of a
    listing (Case 3's 38 parts: 0.15 ms). Anything of another shape than text names and whole
    numbers (a value that is neither, a count written as a float) goes the generic way; the
    bytes are the same (``tests/reporting/test_render.py`` compares both)."""
    text = _usual_component(characteristic, component, served)
    if text is None:
        return _nested(component_data(characteristic, component, served), 2)
    return json_printable(text)


def _usual_component(
    characteristic: Characteristic, component: Component, served: Any
) -> str | None:
    """A listed component's JSON text when its names are text and its values all text or all
    whole numbers; ``None`` for any other shape."""
    name, own = characteristic.name, component.name
    if type(name) is not str or type(own) is not str or not served:
        return None
    head = f'{{{_AT_FIELD}"characteristic": {_quoted(name)},{_AT_FIELD}"component": {_quoted(own)},'
    kinds = {type(v) for v in served}
    if characteristic.kind == "integer":
        counts = sorted(served) if kinds == {int} else []
        clusters = (component.clusters(counts[0]), component.clusters(counts[-1])) if counts else ()
        if not clusters or not all(type(n) is int for n in clusters):
            return None
        runs = ("," + _AT_ITEM).join(_pair(*run, _AT_ITEM + "  ") for run in integer_runs(counts))
        return (
            f'{head}{_AT_FIELD}"range": {_pair(counts[0], counts[-1], _AT_ITEM)},'
            f'{_AT_FIELD}"clusters": {_pair(*clusters, _AT_ITEM)},'
            f'{_AT_FIELD}"counts": [{_AT_ITEM}{runs}{_AT_FIELD}]{_AT_COMPONENT}}}'
        )
    if kinds not in ({str}, {int}):
        return None
    items = ("," + _AT_ITEM).join(map(_quoted if kinds == {str} else int.__repr__, served))
    return f'{head}{_AT_FIELD}"values": [{_AT_ITEM}{items}{_AT_FIELD}]{_AT_COMPONENT}}}'


def _pair(first: int, second: int, at: str) -> str:
    """Two whole numbers as an indented JSON list whose items sit at ``at``."""
    close = at[:-2]
    return f"[{at}{int.__repr__(first)},{at}{int.__repr__(second)}{close}]"


def _nested(data: Any, levels: int = 0) -> str:
    """``dumps(data)`` without its newline, its lines moved to where a listed configuration
    starts and ``levels`` levels further in."""
    return nested_json(data, _AT_CONFIGURATION + "  " * levels)


def render_counts(solution: Solution, fmt: str = "text") -> str:
    """Per-type counts only (``teleop-ui count``): text, JSON or Markdown."""
    if fmt == "json":
        return dumps(counts_data(solution))
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
    return _title(solution) + "\n\n" + text_table(headers, rows, align)


def _title(solution: Solution) -> str:
    """The first line of a text view: the team, its rule set and its file, each escaped."""
    rules = solution.rules
    return (
        f"{shown(solution.team.name, limit=None)}  (rules: {shown(rules.name, limit=None)}, "
        f"{shown(rules.file, limit=SHOWN_FILE_NAME_CHARS)})"
    )


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
    from solver.solving.reproduce import published_note  # a shipped team's figures from the paper

    note = published_note(solution)
    if note is not None:
        stated, verdict, _ = note
        lines += [stated, f"  {verdict}"]
    return lines


def render_assignment(solution: Solution, assignment: Assignment, fmt: str = "text") -> str:
    """An assignment as text or JSON."""
    if fmt == "json":
        from solver.solving.assignment import assignment_data  # solve does not load assign

        return dumps(assignment_data(solution, assignment))
    # The values were given on a command line or read from a robot: each is shown cut short.
    given = (
        " ".join(f"{shown(name)}={shown(value)}" for name, value in assignment.given) or "(nothing)"
    )
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
                f"  {shown(characteristic.label, limit=None)}: "
                f"{shown(_component_text(characteristic, component, own), limit=None)}"
            )
        lines.append(
            f"  (serves {configuration.robots} valid robots of team "
            f"{shown(solution.team.name, limit=None, quoted=True)})"
        )
        return "\n".join(lines) + "\n"
    lines = [f"default UI configuration {assignment.number} for {given}"]
    lines += [f"  invalid: {shown(reason, limit=None)}" for reason in assignment.reasons]
    relevant = [
        (rules.characteristic(name).label, names) for name, names in assignment.relevant if names
    ]
    if relevant:
        lines.append("  components relevant to the known values:")
        lines += [
            f"    {shown(label, limit=None)}: {shown(', '.join(names), limit=None)}"
            for label, names in relevant
        ]
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
