"""Markdown that shows names as written: escaping text from rule and team files.

Names come from user files (a team called ``<script>``, a value ``*bold*``, a label ``a|b``).
Written into Markdown as they are, a viewer would run them as HTML, format them, or split a
table row at the ``|``. :func:`escape` makes text literal: ``<``, ``>`` and ``&`` become HTML
entities (every Markdown viewer shows them as the characters, and none starts a tag), the
inline markup characters get a backslash (:func:`escape`), and in running text
(:func:`paragraph`) a line that would start a heading or a list is escaped at its start too.
:func:`table` builds a table of escaped cells.

Not here: the pages themselves (:mod:`solver.reporting.report`, :mod:`solver.reporting.batch`) or
HTML (``html.escape``).
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from typing import Any
from urllib.parse import quote

from solver.untrusted import shown

__all__ = ["escape", "heading", "link_target", "paragraph", "table"]

_INLINE = str.maketrans(
    {"&": "&amp;", "<": "&lt;", ">": "&gt;", **{c: "\\" + c for c in "\\`*_[]|~"}}
)
# What starts a block at the beginning of a line: "# h", "- item", "+ item", "=" (an
# underline), "1. item" / "1) item".
_LINE_START = re.compile(r"^(?:([#+\-=])|(\d+)([.)])(?=\s|$))", re.MULTILINE)


def _line_start(match: re.Match[str]) -> str:
    marker, number, dot = match.groups()
    return f"\\{marker}" if marker else f"{number}\\{dot}"


def escape(text: object) -> str:
    """``text`` as inline Markdown that shows exactly it: within a line, or a table cell.

    A line break, control or invisible format character in it is shown as its escape
    (``\\n``, ``\\u202e``: :func:`~solver.untrusted.shown`), so the text stays on its line
    and starts no heading or list. ``None`` shows as nothing.
    """
    return "" if text is None else shown(str(text), limit=None).translate(_INLINE)


def paragraph(text: object) -> str:
    """``text`` as Markdown paragraphs that show exactly it, whatever its lines start with."""
    lines = [] if text is None else [escape(line) for line in str(text).splitlines()]
    # Indentation would make a code block, two trailing spaces a line break: both are dropped,
    # as a viewer would drop them anyway.
    return _LINE_START.sub(_line_start, "\n".join(line.strip() for line in lines))


def heading(level: int, text: object) -> str:
    """A heading of ``level`` (1-6) showing ``text`` on one line."""
    title = escape(" ".join(str(text).split()))
    if title.endswith("#"):  # a closing "#" sequence would be dropped from the heading
        title = title[:-1] + "\\#"
    return f"{'#' * level} {title}"


def link_target(name: str) -> str:
    """A relative file name usable as a link or image target (spaces, parentheses, ...).

    Percent-encoded from the name's bytes as the file system has them, so a name that is not
    UTF-8 (``\xff`` arrives as the surrogate escape ``\udcff``) still links to its file.
    """
    return quote(os.fsencode(name))


def table(
    headers: Sequence[object], rows: Sequence[Sequence[Any]], right: Sequence[bool] | None = None
) -> str:
    """A Markdown table of escaped cells; ``right`` marks right-aligned (number) columns.

    A cell's line breaks become spaces: a table row is one line.
    """
    align = right or [False] * len(headers)

    def line(cells: Sequence[Any]) -> str:
        return (
            "| "
            + " | ".join("" if c is None else escape(" ".join(str(c).splitlines())) for c in cells)
            + " |"
        )

    return (
        "\n".join(
            [
                line(headers),
                "|" + "|".join("---:" if a else "---" for a in align) + "|",
                *(line(row) for row in rows),
            ]
        )
        + "\n"
    )
