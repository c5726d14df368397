"""What the command line writes to a terminal never carries a raw control character.

Names, messages and file names come from files and robots that strangers wrote. Printed as
they are, ``\\x1b[2J`` clears the operator's screen and other escape sequences retitle the
window, hide text or fake output; a right-to-left override reorders what a line appears to
say. :func:`main <solver.cli.main>` therefore wraps ``sys.stdout`` and ``sys.stderr`` in an
:class:`EscapingStream`: every character that is not printable, other than a newline and a
tab, is written as its Python escape (``\\x1b``, ``\\u202e``) by
:func:`solver.untrusted.shown`, so it is seen, not obeyed.

This is the last net, not the escaping itself: the stream cannot tell a newline inside a name
from the output's own line break, so every name is shown through :func:`~solver.untrusted.shown`
where the output is formatted, and a newline in a name never starts a line.

JSON output is unchanged by this (``json.dumps`` already escapes control characters); text,
CSV and Markdown written to standard output get the escapes. Files written with ``-o`` are
not terminals and keep their content (each format escapes what it must itself).

Not here: escaping for a format (CSV cells: :func:`solver.reporting.render.csv_cell`; SARIF
messages: :mod:`solver.check.render`; Markdown: :mod:`solver.reporting.markdown`).
"""

from __future__ import annotations

import re
from typing import IO, Any

from solver.untrusted import shown

__all__ = ["EscapingStream", "escape_controls", "raw_stream"]

# The output's own line breaks and tabs; everything between them is shown escaped.
_LAYOUT = re.compile("([\n\t])")


def escape_controls(text: str) -> str:
    """``text`` with every unprintable character but newline and tab written as its escape."""
    if text.isprintable():
        return text
    return "".join(
        part if part in ("\n", "\t") else shown(part, limit=None) for part in _LAYOUT.split(text)
    )


class EscapingStream:
    """A text stream that writes to ``stream`` through :func:`escape_controls`.

    Everything else (``isatty``, ``fileno``, ``buffer``, ``encoding``...) is the wrapped
    stream's, so callers cannot tell the difference except by what reaches the terminal.
    """

    def __init__(self, stream: IO[str]) -> None:
        self.raw = stream

    def write(self, text: str) -> int:
        self.raw.write(escape_controls(text))
        return len(text)

    def writelines(self, lines: Any) -> None:
        for line in lines:
            self.write(line)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.raw, name)


def raw_stream(stream: IO[str] | EscapingStream) -> IO[str]:
    """The stream below an :class:`EscapingStream`: for a progress bar that writes its own
    escape sequences (and is given only escaped text)."""
    return stream.raw if isinstance(stream, EscapingStream) else stream
