"""Rendering solutions, assignments and reproduction tables as text, JSON, CSV and Markdown.

The JSON shapes are the project's documented, stable contract and live with their types
(:mod:`solver.core.contracts`); the formats here are views of the same data. Output is
deterministic: values in declared order, no timestamps, identical runs give identical bytes.

Not here: the HTML/plot reports of ``teleop-ui report``.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re
from collections.abc import Callable, Iterator, Sequence
from json.encoder import encode_basestring as _quoted
from typing import TYPE_CHECKING, Any

from solver.core.contracts import (
    assignment_data,
    component_data,
    configuration_data,
    counts_data,
    integer_runs,
    solution_data,
    solution_warnings,
)
from solver.engines import describe
from solver.reporting import markdown
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown, visible

if TYPE_CHECKING:
    from solver.core.assignment import Assignment
    from solver.core.partition import Configuration
    from solver.core.reproduce import Comparison
    from solver.core.ruleset import Characteristic, Component, RuleSet
    from solver.core.solution import Solution

__all__ = [
    "FORMATS",
    "csv_cell",
    "csv_row",
    "dumps",
    "json_printable",
    "method_text",
    "render_assignment",
    "render_comparisons",
    "render_counts",
    "render_solution",
    "solution_chunks",
    "text_table",
]

FORMATS = ("text", "json", "csv", "markdown")


def method_text(solution: Solution) -> str:
    """How the counts were obtained, in words, per kinematic type where they differ."""
    methods = [t.method for t in solution.by_type]
    if len(set(methods)) <= 1:
        return describe(methods[0]) if methods else "nothing to count"
    return "; ".join(f"{t.kinematic_type}: {describe(t.method)}" for t in solution.by_type)


def dumps(data: Any, *, indent: int | None = 2) -> str:
    """JSON as the project writes it everywhere: indented (``None``: one line), UTF-8 kept,
    trailing newline.

    Printable characters are kept as they are; every other one (a control, a line separator
    U+2028, a right-to-left override, a lone surrogate) is written as a JSON escape
    (``\\u202e``), so the text holds no invisible character, a terminal shows it as it is, and
    any JSON reader reads the same strings back.

    Indented by two, data of dicts with text keys, lists, text, whole and finite numbers,
    booleans and None (what the project writes) takes a small writer: the same text in a
    third of the time, as Python's encoder writes indented JSON a generator per value (its C
    encoder only writes one-line JSON). Anything else goes to ``json.dumps``.
    """
    if indent == 2:
        parts: list[str] = []
        try:
            _write_indented(data, "\n", parts)
        except (_Unusual, RecursionError):  # json.dumps says what is wrong, if anything
            pass
        else:
            return json_printable("".join(parts)) + "\n"
    return json_printable(json.dumps(data, indent=indent, ensure_ascii=False)) + "\n"


class _Unusual(Exception):
    """A value :func:`_write_indented` leaves to Python's encoder."""


def _float(value: float) -> str:
    if not math.isfinite(value):  # NaN and the infinities: as json.dumps writes them
        raise _Unusual
    return float.__repr__(value)


# The text of a value that holds no other, by its exact type (a subclass is unusual).
_SCALAR: dict[type, Callable[[Any], str]] = {
    str: _quoted,
    int: int.__repr__,
    float: _float,
    bool: lambda value: "true" if value else "false",
    type(None): lambda _: "null",
}


def _write_indented(value: Any, newline: str, parts: list[str]) -> None:
    kind = type(value)
    scalar = _SCALAR.get(kind)
    if scalar is not None:
        parts.append(scalar(value))
    elif kind is list:
        if not value:
            parts.append("[]")
            return
        inner = newline + "  "
        kinds = {type(item) for item in value}
        if kinds in ({str}, {int}):  # a configuration's served values: one join
            texts = map(_quoted if kinds == {str} else int.__repr__, value)
            parts.append("[" + inner + ("," + inner).join(texts) + newline + "]")
            return
        parts.append("[")
        for index, item in enumerate(value):
            parts.append(inner if index == 0 else "," + inner)
            _write_indented(item, inner, parts)
        parts.append(newline + "]")
    elif kind is dict:
        if not value:
            parts.append("{}")
            return
        inner = newline + "  "
        parts.append("{")
        for index, (key, item) in enumerate(value.items()):
            if type(key) is not str:
                raise _Unusual
            parts.append((inner if index == 0 else "," + inner) + _quoted(key) + ": ")
            _write_indented(item, inner, parts)
        parts.append(newline + "}")
    else:  # anything else: as json.dumps writes it
        raise _Unusual


def json_printable(text: str) -> str:
    """JSON ``text`` (from ``json.dumps(..., ensure_ascii=False)``) with every unprintable or
    invisible character (:func:`solver.untrusted.visible`) but its own line breaks written as
    a ``\\uXXXX`` escape."""
    if visible(text.replace("\n", "")):  # nearly always: one pass in C
        return text
    return "\n".join(
        line if visible(line) else "".join(map(_json_char, line)) for line in text.split("\n")
    )


def _json_char(char: str) -> str:
    if visible(char):
        return char
    code = ord(char)
    if code < 0x10000:
        return f"\\u{code:04x}"
    code -= 0x10000  # a UTF-16 surrogate pair, as JSON writes characters beyond the BMP
    return f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}"


def text_table(
    headers: Sequence[str], rows: Sequence[Sequence[Any]], right: Sequence[bool] | None = None
) -> str:
    """A plain aligned table; ``right[i]`` right-aligns column i (numbers). Every cell is one
    line, whatever the names in it hold (:func:`~solver.untrusted.shown`)."""
    cells = [
        [shown(h, limit=None) for h in headers],
        *[["" if v is None else shown(str(v), limit=None) for v in row] for row in rows],
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
# `=HYPERLINK(...)` in a team's name would run when someone opens the summary. Their fullwidth
# and other compatibility forms (U+FF1D fullwidth, U+FE66 small, U+207C superscript =) count: a
# spreadsheet (and an input method) may turn them into the ASCII sign; NFKC maps each to it.
_FORMULA_SIGNS = frozenset("=+-@")
# ... and so does a cell that starts with a line break or tab, or with spaces (which a
# spreadsheet may trim on import) before one of the signs.
_LINE_STARTS = ("\t", "\r", "\n")
_NUMBER = re.compile(r"[+-]?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?")


def csv_cell(value: Any) -> Any:
    """``value`` as a CSV cell no spreadsheet runs: text that starts like a formula (see
    above) gets a leading ``'`` (OWASP's advice); numbers, and text that is just a number,
    are left alone. Every CSV the tool writes has its cells through here."""
    if not isinstance(value, str) or not value:
        return value
    first = value[0]
    if first.isascii() and first not in _FORMULA_SIGNS and first not in " \t\r\n":
        return value  # nearly every cell: one look at its first character
    if value.startswith(_LINE_STARTS) or (
        _starts_with_a_sign(value) and _NUMBER.fullmatch(value) is None
    ):
        return "'" + value
    return value


def _starts_with_a_sign(text: str) -> bool:
    """Whether ``text``, past any leading spaces, starts with a formula sign in any form."""
    import unicodedata

    stripped = text.lstrip()
    return bool(stripped) and unicodedata.normalize("NFKC", stripped[0])[:1] in _FORMULA_SIGNS


def csv_row(values: Sequence[Any]) -> list[Any]:
    """:func:`csv_cell` of every value of a row."""
    return [csv_cell(value) for value in values]


def _csv(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    return _csv_rows([headers, *rows])


def _csv_rows(rows: Sequence[Sequence[Any]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
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
            yield _csv_rows(rows)
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
                data = component_data(characteristic, component, served)
                text = parts.components[key] = _AT_COMPONENT + _nested(data, 2)
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


def _nested(data: Any, levels: int = 0) -> str:
    """``dumps(data)`` without its newline, its lines moved to where a listed configuration
    starts and ``levels`` levels further in."""
    parts: list[str] = []
    try:
        _write_indented(data, _AT_CONFIGURATION + "  " * levels, parts)
    except (_Unusual, RecursionError):
        return dumps(data)[:-1].replace("\n", _AT_CONFIGURATION + "  " * levels)
    return json_printable("".join(parts))


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
    from solver.core.reproduce import published_note  # a shipped team's figures from the paper

    note = published_note(solution)
    if note is not None:
        stated, verdict, _ = note
        lines += [stated, f"  {verdict}"]
    return lines


def render_assignment(solution: Solution, assignment: Assignment, fmt: str = "text") -> str:
    """An assignment as text or JSON."""
    if fmt == "json":
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
