"""How any output of the tool is written: JSON, CSV and aligned text tables, the project's
way (deterministic, every stranger's string safe for the reader it goes to).

Generic: nothing here knows a solution, a finding or a robot; the commands and reports that
write those (:mod:`solver.reporting.render`, :mod:`solver.check.render`,
:mod:`solver.identify.render`, :mod:`solver.live.render`) write them through these.

- :func:`dumps`: JSON, indented (or on one line), UTF-8 kept, every unprintable or invisible
  character escaped (:func:`json_printable`);
- :func:`text_table`: a plain aligned table, every cell one line (:func:`solver.untrusted.shown`);
- :func:`csv_cell`, :func:`csv_row`, :func:`csv_text`: CSV whose cells no spreadsheet runs as
  formulas.
"""

from __future__ import annotations

import io
import json
import math
import re
from collections.abc import Callable, Sequence
from json.encoder import encode_basestring as _quoted
from typing import Any

from solver.untrusted import shown, visible

__all__ = [
    "csv_cell",
    "csv_row",
    "csv_text",
    "dumps",
    "json_printable",
    "nested_json",
    "text_table",
]


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


def nested_json(data: Any, newline: str) -> str:
    """``data`` as :func:`dumps` indents it, without the trailing newline, each of its line
    breaks written as ``newline`` (a line break and the indentation of where it is nested)."""
    parts: list[str] = []
    try:
        _write_indented(data, newline, parts)
    except (_Unusual, RecursionError):
        return dumps(data)[:-1].replace("\n", newline)
    return json_printable("".join(parts))


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


def csv_text(rows: Sequence[Sequence[Any]]) -> str:
    """Rows as CSV text (``\\n`` line ends), every cell through :func:`csv_cell`."""
    import csv  # here: most commands write no CSV, and start-up pays for every import

    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerows(csv_row(row) for row in rows)
    return buffer.getvalue()
