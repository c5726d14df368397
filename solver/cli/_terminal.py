"""What the command line writes to a terminal never carries a raw control character.

Names, messages and file names come from files and robots that strangers wrote. Printed as
they are, ``\\x1b[2J`` clears the operator's screen and other escape sequences retitle the
window, hide text or fake output; a right-to-left override reorders what a line appears to
say. :func:`main <solver.cli.main>` therefore wraps ``sys.stdout`` and ``sys.stderr`` in an
:class:`EscapingStream`: every character that is not printable, other than a newline and a
tab, and every one drawn as nothing (a Hangul filler, ``\\u3164``), is written as its Python
escape (``\\x1b``, ``\\u202e``) by :func:`solver.untrusted.shown`, so it is seen, not obeyed.

This is the last net, not the escaping itself: the stream cannot tell a newline inside a name
from the output's own line break, so every name is shown through :func:`~solver.untrusted.shown`
where the output is formatted, and a newline in a name never starts a line.

JSON output is unchanged by this (``json.dumps`` already escapes control characters); text,
CSV and Markdown written to standard output get the escapes. Files written with ``-o`` are
not terminals and keep their content (each format escapes what it must itself).

Not here: escaping for a format (CSV cells: :func:`solver.files.output.csv_cell`; SARIF
messages: :mod:`solver.check.render`; Markdown: :mod:`solver.reporting.markdown`).
"""

from __future__ import annotations

import errno
import os
import re
from collections.abc import Callable
from typing import IO, Any, TextIO, cast

from solver.untrusted import shown, visible

__all__ = [
    "ClosedStream",
    "EscapingStream",
    "OutputFailed",
    "escape_controls",
    "made_safe",
    "raw_stream",
]

# The output's own line breaks and tabs; everything between them is shown escaped.
_LAYOUT = re.compile("([\n\t])")


def escape_controls(text: str) -> str:
    """``text`` with every unprintable or invisible character but newline and tab written as
    its escape (:func:`solver.untrusted.visible`)."""
    if visible(text) or visible(text.replace("\n", "").replace("\t", "")):
        return text  # the common case, at C speed: a listing of a million lines
    return "".join(
        part if part in ("\n", "\t") else shown(part, limit=None) for part in _LAYOUT.split(text)
    )


class OutputFailed(Exception):
    """Standard output or standard error cannot be written: closed (``>&-``), full
    (``> /dev/full``) or a pipe whose reader has gone (``| head -1``).

    Deliberately neither an ``OSError`` nor a :class:`~solver.errors.SolverError`: a command
    that handles those around its own files does not take it for one of them, and it reaches
    :func:`solver.cli.main`, which ends the command (see there).
    """

    def __init__(self, name: str, error: OSError) -> None:
        super().__init__(f"cannot write to {name}: {error.strerror or error}")
        self.name = name
        self.error = error

    @property
    def reader_gone(self) -> bool:
        """The reader of a pipe closed it early (``| head -1``): nothing is wrong."""
        return isinstance(self.error, BrokenPipeError)


class ClosedStream:
    """What ``sys.stdout`` is when the process started with it closed (``>&-``): Python gives
    ``None``. Writing to it fails as writing to a closed descriptor does; nothing else does."""

    encoding = "utf-8"
    closed = True

    def write(self, text: str) -> int:  # noqa: ARG002 (nothing is written)
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))

    def flush(self) -> None:
        return None

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))


class EscapingStream:
    """A text stream that writes to ``stream`` through :func:`escape_controls`.

    Everything else (``isatty``, ``fileno``, ``buffer``, ``encoding``...) is the wrapped
    stream's, so callers cannot tell the difference except by what reaches the terminal. A
    write or flush that fails raises :class:`OutputFailed` naming the stream (``name``).
    """

    def __init__(
        self,
        stream: IO[str] | None,
        name: str = "the output",
        *,
        escape: Callable[[str], str] | None = escape_controls,
    ) -> None:
        self.raw: Any = ClosedStream() if stream is None else stream
        self.name = name
        self.escape = escape

    def write(self, text: str) -> int:
        try:
            self.raw.write(text if self.escape is None else self.escape(text))
        except OSError as error:
            raise OutputFailed(self.name, error) from None
        return len(text)

    def flush(self) -> None:
        try:
            self.raw.flush()
        except OSError as error:
            raise OutputFailed(self.name, error) from None

    def writelines(self, lines: Any) -> None:
        for line in lines:
            self.write(line)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.raw, name)


def made_safe(stream: TextIO | EscapingStream) -> TextIO:
    """The stream below an :class:`EscapingStream`, its failures still
    :class:`OutputFailed`: for text made safe where it was read (a listing's values, each
    escaped once by :func:`escape_controls`), which escaping every byte again would only slow."""
    if isinstance(stream, EscapingStream):
        # An EscapingStream is a TextIO in all but name (it delegates everything but write).
        return cast("TextIO", EscapingStream(stream.raw, stream.name, escape=None))
    return stream


def raw_stream(stream: IO[str] | EscapingStream) -> IO[str]:
    """The stream below an :class:`EscapingStream`: for a progress bar that writes its own
    escape sequences (and is given only escaped text)."""
    return stream.raw if isinstance(stream, EscapingStream) else stream
