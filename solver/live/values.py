"""Values read from a robot graph: their bounds, and how a message shows them.

Every value on a graph (a ROS 1 parameter, a ROS 2 message) was written by a stranger: the
operator's selection, the answer another watcher left, a description. Each is bounded before
it is parsed, compared or formatted:

* XML-RPC values (ROS 1): the transport's bounds (:mod:`~solver.live.sources.ros1.rpc`: bytes
  per reply, nesting depth, a deadline);
* JSON text (the ROS 2 answer topic ``/teleop_ui/ui_configuration``): at most
  :data:`MAX_JSON_CHARS` characters and :data:`MAX_DEPTH` levels of nesting, both checked by
  one linear scan before the decoder runs (:func:`bounded_json`);
* the operator's selection (``/teleop_ui/active_*``): text of at most
  :data:`MAX_SELECTION_CHARS` characters (as long as a rule set's names may be); anything else
  is ignored with a note (:func:`selection_text`).

:func:`shown_value` is what a note or an error shows of such a value: escaped, cut, and for
anything but text and numbers only its kind.

Not here: reading the values (:mod:`solver.live.sources`).
"""

from __future__ import annotations

import json
import re
from typing import Any, Final

from solver.errors import SolverError
from solver.live.graph import MAX_DEPTH, TOO_DEEP
from solver.untrusted import shown

__all__ = [
    "MAX_DEPTH",
    "MAX_JSON_CHARS",
    "MAX_SELECTION_CHARS",
    "bounded_json",
    "kind_of",
    "selection_text",
    "shown_value",
]

MAX_SELECTION_CHARS: Final = 200
MAX_JSON_CHARS: Final = 1024 * 1024
# A JSON string (skipped whole, possessively: no backtracking) or one bracket.
_JSON_TOKENS = re.compile(r'"(?:[^"\\]++|\\.)*+"|[\[{]|[\]}]')


def bounded_json(text: str) -> Any:
    """The JSON value of ``text``; :class:`ValueError` for text that is not JSON, longer than
    :data:`MAX_JSON_CHARS` or nested deeper than :data:`MAX_DEPTH` (checked before decoding)."""
    if len(text) > MAX_JSON_CHARS:
        raise ValueError(f"longer than {MAX_JSON_CHARS} characters")
    depth = 0
    for token in _JSON_TOKENS.finditer(text):
        bracket = token.group()
        if bracket in ("[", "{"):
            depth += 1
            if depth > MAX_DEPTH:
                raise ValueError(f"nested deeper than {MAX_DEPTH} levels")
        elif bracket in ("]", "}"):
            depth -= 1
    return json.loads(text)


def kind_of(value: Any) -> str:
    """What a value is, in a few words whatever its size or depth: ``a number (7)``,
    ``a list``."""
    if value is TOO_DEEP:
        return f"a value nested deeper than {MAX_DEPTH} levels"
    if isinstance(value, SolverError):  # a value its source could not read (it says why)
        return f"an unreadable value ({value.faults[0].message})"
    if isinstance(value, bool):
        return f"a boolean ({value})"
    if isinstance(value, int | float):
        return f"a number ({shown(value)})"
    if isinstance(value, str):
        return f"text ({shown(value)})"
    if isinstance(value, bytes):
        return "binary data"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a namespace of parameters"
    return type(value).__name__


def shown_value(value: Any) -> str:
    """``value`` as a message shows it: text escaped and cut to 60 characters, saying so
    (:func:`solver.untrusted.shown`), a number as written, anything else as its kind
    (:func:`kind_of`)."""
    if isinstance(value, str | int | float) and not isinstance(value, bool):
        return shown(value)
    return f"({kind_of(value)})"


def selection_text(name: str, value: Any) -> tuple[str | None, str | None]:
    """The operator's selection ``name`` as text (``None``: not set or ignored) and a note
    when it is ignored: not text, or longer than :data:`MAX_SELECTION_CHARS`."""
    if not isinstance(value, str):
        return None, f"{name} ignored: expected text, got {kind_of(value)}"
    text = value.strip()
    if len(text) > MAX_SELECTION_CHARS:
        return None, (
            f"{name} ignored: {len(text):,} characters, longer than {MAX_SELECTION_CHARS} "
            f"({shown_value(text)})"
        )
    return text or None, None
