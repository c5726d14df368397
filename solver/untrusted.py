"""Showing a stranger's string in human-readable output: :func:`shown`, the one way to do it.

Names, values and file names come from files, robots and command lines that strangers wrote.
Shown as they are, a newline starts a forged line in a log, a finding or a watch event
(``ok\\nERROR: ...``); ``ESC [2J`` clears the operator's screen; a right-to-left override
(U+202E), U+061C, a soft hyphen (U+00AD) or Unicode tag characters (U+E0000-U+E007F) change
or hide what a line appears to say; a 9 MB attribute fills the terminal. :func:`shown` is what
every message, text output, finding and event uses for such a string:

- every character :meth:`str.isprintable` calls unprintable is written as its Python escape:
  C0 and C1 controls, DEL, newline, tab (``\\n``, ``\\t``, ``\\x1b``), the line and paragraph
  separators U+2028/U+2029, every format character of Unicode category Cf (bidirectional
  controls, zero-width joiners, U+061C, U+00AD, tag characters, the BOM), the spaces other
  than U+0020, surrogates, private-use and unassigned code points;
- so is every character :meth:`str.isprintable` accepts that a terminal draws as nothing
  (:data:`INVISIBLE`): the letters and marks of Unicode's ``Default_Ignorable_Code_Point``
  property (the Hangul fillers U+115F, U+1160, U+3164, U+FFA0, which are letters; the
  combining grapheme joiner; variation selectors, which can hide bytes after a letter; the
  Khmer inherent vowels and Mongolian free variation selectors) and the symbols drawn empty
  (U+2800 braille pattern blank, U+1D159 musical symbol null notehead). :func:`visible` says
  whether a text needs none of this;
- at most :data:`SHOWN_CHARS` (60) characters of it are shown; a longer value ends with a
  visible mark that says how long it was: ``xxx... (cut from 9,000,000 characters)``;
- ``quoted=True`` puts it in quotes as Python's ``repr`` does (a quote or backslash inside is
  escaped too), so where the value ends is unforgeable.

A list, mapping or other value is shown through a bounded ``repr`` (a few items, a few levels;
a 100,000-item or 3,000-deep list costs no more than a short one).

Not here: escaping for a file format (CSV cells, Markdown, HTML, UVL, SARIF: each writer
escapes what its format requires), and the terminal stream (:mod:`solver.cli._terminal` uses
:func:`shown` on everything it writes, keeping only the output's own line breaks).
"""

from __future__ import annotations

import re

__all__ = ["INVISIBLE", "SHOWN_CHARS", "SHOWN_FILE_NAME_CHARS", "shown", "visible"]

# What a message, a text output or an event shows of a stranger's value: at most this many
# characters. docs/security.md says so.
SHOWN_CHARS = 60
# A file name (given by the user or named in a file) is shown up to this many characters: a
# real path is often longer than 60.
SHOWN_FILE_NAME_CHARS = 300

# A container is shown through reprlib with at most this many items per level, this deep.
_ITEMS = 6
_LEVELS = 3

_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}

# Printable to str.isprintable, drawn as nothing. Unicode 15.1's Default_Ignorable_Code_Point
# code points that are letters (Lo) or marks (Mn): the property's others are format characters
# and unassigned ones, which isprintable refuses already. Then two symbols drawn blank. The
# spaces (U+3000, U+00A0...) and U+180E are separators or format characters: escaped already.
INVISIBLE = re.compile(
    "[\u034f"  # combining grapheme joiner
    "\u115f\u1160"  # Hangul choseong and jungseong fillers
    "\u17b4\u17b5"  # Khmer inherent vowels
    "\u180b-\u180d\u180f"  # Mongolian free variation selectors
    "\u2800"  # braille pattern blank
    "\u3164"  # Hangul filler
    "\ufe00-\ufe0f"  # variation selectors 1-16
    "\uffa0"  # halfwidth Hangul filler
    "\U0001d159"  # musical symbol null notehead
    "\U000e0100-\U000e01ef]"  # variation selectors 17-256
)


def visible(text: str) -> bool:
    """Whether every character of ``text`` is shown as itself: printable, and none drawn as
    nothing (:data:`INVISIBLE`). One pass in C for the common text.

    >>> visible("UAV"), visible("a\\u3164b"), visible("a\\nb")
    (True, False, False)
    """
    return text.isprintable() and (text.isascii() or INVISIBLE.search(text) is None)


def shown(value: object, *, limit: int | None = SHOWN_CHARS, quoted: bool = False) -> str:
    """``value`` as human-readable output may show it: every unprintable character escaped,
    cut to ``limit`` characters (``None``: not cut) with a mark that says so.

    >>> shown("ok\\nERROR: forged")
    'ok\\\\nERROR: forged'
    >>> shown("x" * 100)[-34:]
    'xxxxx... (cut from 100 characters)'
    >>> shown("it's", quoted=True)
    '"it\\'s"'
    """
    if isinstance(value, str):
        text, total, items_left_out = value, f"{len(value):,} characters", False
    else:
        text, total, items_left_out = _bounded_repr(value)
        quoted = False
    cut = limit is not None and len(text) > limit
    if cut:
        text = text[:limit]
    if quoted:
        text = repr(text)  # repr escapes exactly what isprintable() refuses, and quotes
        if not text.isascii():
            text = INVISIBLE.sub(lambda found: _escape(found.group()), text)
        if cut:
            text = f"{text[:-1]}...{text[-1]}"
    else:
        if not visible(text):
            text = "".join(char if visible(char) else _escape(char) for char in text)
        if cut:
            text += "..."
    if cut or items_left_out:
        text += f" (cut from {total})"
    return text


def _escape(char: str) -> str:
    if char in _NAMED:
        return _NAMED[char]
    code = ord(char)
    if code < 0x100:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


def _bounded_repr(value: object) -> tuple[str, str, bool]:
    """A ``repr`` of ``value`` whose cost does not grow with its size or depth; what it was;
    whether anything was left out."""
    if isinstance(value, bool) or value is None or isinstance(value, float):
        return str(value), "", False
    if isinstance(value, int):
        if value.bit_length() > 4 * SHOWN_CHARS:  # str() of a 5,000-digit number raises
            digits = int(value.bit_length() * 0.30103) + 1
            return f"a whole number of about {digits:,} digits", "", False
        text = str(value)
        return text, f"{len(text):,} characters", False
    if isinstance(value, list | tuple | set | frozenset | dict):
        import reprlib  # only containers need it; keep start-up short

        bounded = reprlib.Repr()
        bounded.maxlevel = _LEVELS
        for name in ("maxlist", "maxtuple", "maxset", "maxfrozenset", "maxdict"):
            setattr(bounded, name, _ITEMS)
        bounded.maxstring = bounded.maxother = SHOWN_CHARS
        bounded.maxlong = SHOWN_CHARS
        try:
            text = bounded.repr(value)
        except (RecursionError, ValueError):
            text = f"<{type(value).__name__}>"
        return text, f"{len(value):,} items", len(value) > _ITEMS
    text = str(value)
    return text, f"{len(text):,} characters", False
