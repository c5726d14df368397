"""Safe YAML loading that remembers where every value came from.

PyYAML's loaders lose positions and silently keep the last of two duplicate keys. Here a file is
*composed* into nodes (no Python objects are constructed from tags, so ``!!python/object`` and
friends are refused), then walked into plain ``dict``/``list``/scalar data while recording the
line and column of every key and value under its path. Duplicate keys, recursive or exploding
aliases, unsupported tags, oversized files and non-UTF-8 bytes are all reported as located faults.

Before anything is composed, :func:`prescan` reads the document's parsing events once and refuses
one nested deeper than :data:`MAX_DEPTH` (block indentation and flow brackets alike) or with more
events than :data:`MAX_EVENTS`: libyaml's composer recurses once per level (50,000 levels of
``- - - ...`` ended the process with SIGSEGV) and its scanner costs time in proportion to the
flow depth on every token (``[`` repeated 40,000 times took 8 s). The pre-scan stops at the
first event past a bound, so its work is linear in the input whatever the input is. Every YAML
text the project reads (rule sets, teams, identification and presentation profiles, and text
from a live graph through :func:`prescan` itself) goes through it.

Not here: what the data means. :mod:`solver.core.rules` and :mod:`solver.core.team` read the data
and use :meth:`Document.location` to say where a problem is.
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from solver.collector import collector_paused
from solver.errors import Fault, InputError, Location
from solver.files.inputfile import decode_text, read_bounded, read_text, sha256_hex

__all__ = [
    "MAX_FILE_BYTES",
    "MAX_KEY_CHARS",
    "MAX_TEXT_CHARS",
    "Document",
    "PathPart",
    "declares_kind",
    "format_path",
    "load_document",
    "load_hashed",
    "parse_document",
    "prescan",
]

PathPart = str | int
YamlPath = tuple[PathPart, ...]

MAX_FILE_BYTES = 16 * 1024 * 1024
# A document with more values than this, counting every alias expansion, is refused: this is
# what stops "billion laughs" style alias bombs from exhausting memory.
MAX_NODES = 200_000
# Nesting deeper than this is refused (rule and team files nest a handful of levels), by the
# pre-scan before composing and again, counting alias expansions, while building values.
MAX_DEPTH = 64
# A mapping key is a name (a characteristic, a kinematic type, a field): at most this long.
MAX_KEY_CHARS = 200
# Any text value (a description is the longest there is) is at most this long: a 15 MB name
# would otherwise travel through solving, charts and reports.
MAX_TEXT_CHARS = 10_000
# Parsing events read before composing: a document that needs more than this many (a 15 MB
# flow-style line of a million entries) is refused before any node is built. Every value is
# one event (two for a collection), so this is never reached below MAX_NODES values.
MAX_EVENTS = 2 * MAX_NODES + 16
# libyaml when PyYAML has it (ten to fifty times faster on big inputs; same nodes, same marks).
_LOADER: Any = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

_STR_TAG = "tag:yaml.org,2002:str"
_INT_TAG = "tag:yaml.org,2002:int"
_PLAIN_TAGS = {
    _STR_TAG,
    _INT_TAG,
    "tag:yaml.org,2002:float",
    "tag:yaml.org,2002:bool",
    "tag:yaml.org,2002:null",
}
_TIMESTAMP_TAG = "tag:yaml.org,2002:timestamp"
_MAP_TAG = "tag:yaml.org,2002:map"
_SEQ_TAG = "tag:yaml.org,2002:seq"


def format_path(path: Sequence[PathPart]) -> str:
    """``("team", "UAV", "sensor_type", 1)`` -> ``team.UAV.sensor_type[1]``."""
    text = ""
    for part in path:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += f".{part}" if text else str(part)
    return text


@dataclass(frozen=True)
class Document:
    """Plain data loaded from one YAML file, with the position of every key and value."""

    file: str
    data: Any
    value_marks: dict[YamlPath, tuple[int, int]] = field(default_factory=dict, repr=False)
    key_marks: dict[YamlPath, tuple[int, int]] = field(default_factory=dict, repr=False)
    # Faults the caller chose to tolerate (``tolerate=`` of :func:`load_document`), e.g. the
    # duplicate keys that ``teleop-ui check`` reports as findings; the first value was kept.
    tolerated: tuple[Fault, ...] = field(default=(), repr=False)

    def location(self, path: Sequence[PathPart] = (), *, key: bool = False) -> Location:
        """Where the value at ``path`` is (or its key, with ``key=True``).

        A path that was never recorded (a missing key, say) is located at its nearest recorded
        ancestor, which is where a user would add it.
        """
        path = tuple(path)
        line: int | None
        column: int | None
        if key and path in self.key_marks:
            line, column = self.key_marks[path]
        else:
            probe = path
            while probe and probe not in self.value_marks:
                probe = probe[:-1]
            line, column = self.value_marks.get(probe, (None, None))
        return Location(self.file, line, column, format_path(path))

    def fault(self, path: Sequence[PathPart], message: str, *, key: bool = False) -> Fault:
        """A fault located at ``path`` in this document."""
        return Fault(self.location(path, key=key), message)


def load_document(
    path: str | Path, *, display: str | None = None, tolerate: Collection[str] = ()
) -> Document:
    """Read and compose one YAML file; :class:`InputError` with a location on any problem.

    Faults whose ``code`` is in ``tolerate`` (only ``duplicate-key`` makes sense: the first
    value is kept) do not raise; they are kept in :attr:`Document.tolerated`.
    """
    name = display if display is not None else str(path)
    text = read_text(path, display=name, limit=MAX_FILE_BYTES, what=_WHAT)
    return parse_document(text, name, tolerate=tolerate)


def load_hashed(path: str | Path, *, display: str | None = None) -> tuple[Document, str]:
    """:func:`load_document` and the SHA-256 of the bytes it read (what ``batch`` records of
    a team file: exactly the text it solved, read once)."""
    name = display if display is not None else str(path)
    raw = read_bounded(path, display=name, limit=MAX_FILE_BYTES, what=_WHAT)
    text = decode_text(raw, path, display=name, what=_WHAT)
    return parse_document(text, name), sha256_hex(raw)


_WHAT = "YAML file"  # what a file that cannot be read was meant to be, as messages say


def parse_document(
    text: str, name: str = "<string>", *, tolerate: Collection[str] = ()
) -> Document:
    """Compose YAML text into a :class:`Document`; :class:`InputError` on any problem.

    ``tolerate``: fault codes kept in :attr:`Document.tolerated` instead of raised.
    """
    # A short text is composed first and pre-scanned only when composing or building its
    # values meets a problem, so that the pre-scan's refusal still comes first: the same
    # document or the same error, without parsing a plain file twice (see _SHORT_TEXT).
    scanned = len(text) > _SHORT_TEXT
    if scanned:
        prescan(text, name)
    syntax: InputError | None = None
    walker = _Walker(name)
    with collector_paused():
        try:
            node = yaml.compose(text, Loader=_LOADER)
        except yaml.YAMLError as error:
            syntax = _syntax_error(name, error)
        else:
            try:
                data = walker.convert(node, ()) if node is not None else None
            except _TooLarge:
                data = None
    if not scanned and (syntax is not None or walker.faults):
        prescan(text, name)
    if syntax is not None:
        raise syntax
    # A file that reads as no kind of file may be anyone's (a secret given by mistake): its
    # faults name only their lines, quoting none of its text, keys or tags.
    faults = walker.faults if not walker.faults or declares_kind(data) else walker.bare
    if any(fault.code not in tolerate for fault in faults):
        raise InputError(faults)
    return Document(name, data, walker.value_marks, walker.key_marks, tuple(faults))


# The fields that make a file one kind or another (:mod:`solver.files.filekind`): a file with
# none of them at its top level is none of the kinds, and nothing of it is quoted
# (docs/security.md, "No echoes").
_KIND_FIELDS = frozenset({"team", "rules", "characteristics", "extends", "components"})


def declares_kind(data: object) -> bool:
    """Whether ``data`` (a document's, even one with faults) is a mapping with a field that
    makes it a kind of file: ``team:``, ``rules:``, ``characteristics:``, ``extends:``, a
    presentation's ``components:`` or ``profile: presentation``. Only such a file may be quoted
    in a message."""
    if not isinstance(data, dict):
        return False
    return data.get("profile") == "presentation" or any(str(key) in _KIND_FIELDS for key in data)


# Texts up to this many characters are composed before their pre-scan (parse_document). Such a
# text nests at most this many levels, so nothing the pre-scan guards against can happen to it:
# libyaml's composer recursed once per level and crashed at 50,000; its scanner's cost grows
# with the square of the flow depth (a few milliseconds here, and libyaml >= 0.2.5 stops at
# 1,000 levels anyway); building values stops at MAX_DEPTH and MAX_NODES by itself.
_SHORT_TEXT = 4096


def prescan(text: str, name: str = "<string>") -> None:
    """Refuse, before anything is composed, YAML text nested deeper than :data:`MAX_DEPTH` or
    with more parsing events than :data:`MAX_EVENTS`; :class:`InputError` at the first event
    past the bound (its line and column).

    One pass over libyaml's events, which come from a state machine with explicit stacks (no
    recursion), and stops at that first event: the work before it is at most ``MAX_EVENTS``
    events, each costing the scanner time in proportion to at most ``MAX_DEPTH`` open flow
    collections (plus the 1,024 characters libyaml looks ahead for a key). A syntax error
    met first is an :class:`InputError` at its line and column.
    """
    if "\x00" in text:
        raise InputError.at(name, "contains NUL bytes; is this a YAML file?")
    try:
        _count_events(text, name)
    except yaml.YAMLError as error:
        if getattr(error, "problem", None) != _LIBYAML_NEST_CAP:
            raise _syntax_error(name, error) from None
        # libyaml >= 0.2.5 (PyYAML 6.0.4 wheels) caps open collections at 1,000 in its
        # scanner, which looks ahead past the 65th before handing out its event: the text
        # before the cap holds the level too deep, and is read again to say where it opens.
        mark = getattr(error, "problem_mark", None)
        with contextlib.suppress(yaml.YAMLError):
            _count_events(_before(text, mark), name)
        raise _refusal(name, mark, _TOO_DEEP) from None


_TOO_DEEP = f"nested more than {MAX_DEPTH} levels deep; refused"
_LIBYAML_NEST_CAP = "exceeded maximum nesting depth"


def _count_events(text: str, name: str) -> None:
    """Walk libyaml's events, refusing at the first one past :data:`MAX_DEPTH` open
    collections or :data:`MAX_EVENTS` events; libyaml's own errors pass through."""
    open_collections = 0
    for count, event in enumerate(yaml.parse(text, Loader=_LOADER)):
        if isinstance(event, yaml.CollectionEndEvent):
            open_collections -= 1
            continue
        if isinstance(event, yaml.NodeEvent) and open_collections > MAX_DEPTH:
            raise _refusal(name, event.start_mark, _TOO_DEEP)
        if count > MAX_EVENTS:
            raise _refusal(name, event.start_mark, f"more than {MAX_NODES} values; refused")
        if isinstance(event, yaml.CollectionStartEvent):
            open_collections += 1


def _before(text: str, mark: Any) -> str:
    """The text before a mark (its line and column, which count characters)."""
    if mark is None:
        return ""
    lines = text.split("\n", mark.line)[: mark.line + 1]
    lines[-1] = lines[-1][: mark.column]
    return "\n".join(lines)


def _syntax_error(name: str, error: yaml.YAMLError) -> InputError:
    if not isinstance(error, yaml.MarkedYAMLError):
        return InputError.at(name, f"YAML error: {_short(str(error), 120)}")
    mark = error.problem_mark or error.context_mark
    problem = _short(error.problem or error.context or "invalid YAML", 120)
    if mark is None:
        return InputError.at(name, f"YAML syntax error: {problem}")
    return InputError.at(
        name,
        f"YAML syntax error: {problem}",
        line=mark.line + 1,
        column=mark.column + 1,
        code="yaml",
    )


def _refusal(name: str, mark: Any, message: str) -> InputError:
    return InputError.at(
        name,
        message,
        line=None if mark is None else mark.line + 1,
        column=None if mark is None else mark.column + 1,
        code="too-large",
    )


class _TooLarge(Exception):
    """Stops the walk at once: finishing it is exactly the work an alias bomb (or a needlessly
    deep nest) asks for."""


class _Walker:
    """Turns composed nodes into plain data, collecting faults instead of stopping at the first."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.faults: list[Fault] = []
        # The same faults located by line and column only, quoting nothing of the text.
        self.bare: list[Fault] = []
        self.value_marks: dict[YamlPath, tuple[int, int]] = {}
        self.key_marks: dict[YamlPath, tuple[int, int]] = {}
        self.nodes = 0
        self.active: set[int] = set()
        self._constructor: yaml.SafeLoader | None = None

    @property
    def constructor(self) -> yaml.SafeLoader:
        """PyYAML's safe constructor, for the scalars :meth:`_scalar` does not read itself."""
        if self._constructor is None:
            self._constructor = yaml.SafeLoader("")
        return self._constructor

    def fault(
        self,
        node: yaml.Node,
        path: YamlPath,
        message: str,
        code: str = "yaml",
        *,
        bare: str | None = None,
    ) -> None:
        """A fault at ``node``; ``bare``: the message without what it quotes of the file."""
        mark = node.start_mark
        line, column = mark.line + 1, mark.column + 1
        self.faults.append(
            Fault(Location(self.name, line, column, format_path(path)), message, code)
        )
        self.bare.append(Fault(Location(self.name, line, column), bare or message, code))

    def convert(self, node: yaml.Node, path: YamlPath) -> Any:
        self.nodes += 1
        if self.nodes > MAX_NODES:
            self.fault(
                node,
                path,
                f"document expands to more than {MAX_NODES} values (an alias bomb?); refused",
                "too-large",
            )
            raise _TooLarge
        if len(path) > MAX_DEPTH:
            self.fault(
                node,
                path[:MAX_DEPTH],
                f"nested more than {MAX_DEPTH} levels deep; refused",
                "too-large",
            )
            raise _TooLarge
        self.value_marks.setdefault(path, (node.start_mark.line + 1, node.start_mark.column + 1))
        if id(node) in self.active:
            self.fault(node, path, "recursive alias: a value refers to itself")
            return None
        self.active.add(id(node))
        try:
            if isinstance(node, yaml.MappingNode):
                return self._mapping(node, path)
            if isinstance(node, yaml.SequenceNode):
                return self._sequence(node, path)
            return self._scalar(node, path)
        finally:
            self.active.discard(id(node))

    def _mapping(self, node: yaml.MappingNode, path: YamlPath) -> dict[Any, Any] | None:
        if node.tag != _MAP_TAG:
            self._unsupported(node, path, "")
            return None
        result: dict[Any, Any] = {}
        first_seen: dict[Any, int] = {}
        for key_node, value_node in node.value:
            if key_node.tag == "tag:yaml.org,2002:merge":
                self.fault(
                    key_node, path, "YAML merge keys ('<<') are not supported; write the keys out"
                )
                continue
            if not isinstance(key_node, yaml.ScalarNode):
                self.fault(key_node, path, "mapping keys must be plain scalars")
                continue
            key = self._scalar(key_node, path)
            if key is None and key_node.tag != "tag:yaml.org,2002:null":
                continue
            if len(str(key_node.value)) > MAX_KEY_CHARS:
                self.fault(
                    key_node,
                    path,
                    f"a key longer than {MAX_KEY_CHARS} characters; names are at most that long",
                    "too-large",
                )
                continue
            try:
                hash(key)
            except TypeError:
                self.fault(key_node, path, "mapping keys must be plain scalars")
                continue
            child = (*path, str(key))
            # Keys are names: 1 and "1", true and "True" name the same thing.
            if str(key) in first_seen:
                first = first_seen[str(key)]
                self.fault(
                    key_node,
                    child,
                    f"duplicate key {key!r} (first at line {first})",
                    "duplicate-key",
                    bare=f"a key written twice (first at line {first})",
                )
                continue
            first_seen[str(key)] = key_node.start_mark.line + 1
            self.key_marks[child] = (key_node.start_mark.line + 1, key_node.start_mark.column + 1)
            result[key] = self.convert(value_node, child)
        return result

    def _sequence(self, node: yaml.SequenceNode, path: YamlPath) -> list[Any] | None:
        if node.tag != _SEQ_TAG:
            self._unsupported(node, path, "")
            return None
        return [self.convert(item, (*path, index)) for index, item in enumerate(node.value)]

    def _scalar(self, node: yaml.Node, path: YamlPath) -> Any:
        if node.tag == _TIMESTAMP_TAG:
            return str(node.value)
        if node.tag not in _PLAIN_TAGS:
            self._unsupported(node, path, _PLAIN_ONLY)
            return None
        text = str(node.value)
        if len(text) > MAX_TEXT_CHARS:
            self.fault(
                node, path, f"a value longer than {MAX_TEXT_CHARS} characters; refused", "too-large"
            )
            return None
        if "\x00" in text:
            # Written as an escape ("\0", "\x00"): a NUL byte itself is refused before.
            self.fault(node, path, "contains a NUL character (\\0); not text")
            return None
        if not text.isascii() and _SURROGATE.search(text):
            # A "\udcff" escape: no file, terminal or UTF-8 output can hold it.
            self.fault(
                node, path, "contains an unpaired surrogate escape (\\ud800-\\udfff); not text"
            )
            return None
        if node.tag == _STR_TAG:
            return text  # what PyYAML's constructor gives a string: the scalar's text
        if (
            node.tag == _INT_TAG
            and len(text) <= _PLAIN_DIGITS
            and text.isascii()
            and text.isdigit()
            and text[0] != "0"
        ):
            # Plain decimal digits (no sign, underscore, base prefix, leading zero or
            # sexagesimal colon, which PyYAML reads its own way below): the same int.
            return int(text)
        try:
            value = self.constructor.construct_object(node)
        except yaml.YAMLError as error:
            self.fault(
                node, path, f"cannot read value: {_short(str(error))}", bare="cannot read value"
            )
            return None
        except (ValueError, OverflowError):
            # int() of more than 4,300 digits (Python's int-to-string limit).
            self.fault(node, path, "a number too large to use; refused", "too-large")
            return None
        if (
            isinstance(value, int)
            and not isinstance(value, bool)
            and value.bit_length() > _MAX_INT_BITS
        ):
            # 0x... with thousands of digits is no error to int(), but printing it would be.
            self.fault(node, path, "a number too large to use; refused", "too-large")
            return None
        return value

    def _unsupported(self, node: yaml.Node, path: YamlPath, more: str) -> None:
        self.fault(
            node,
            path,
            f"unsupported YAML tag '{_short(node.tag, 40)}'{more}",
            bare=f"unsupported YAML tag{more}",
        )


_PLAIN_ONLY = "; only plain strings, numbers, booleans, lists and mappings are allowed"
# Whole numbers beyond 2**63 mean nothing in a rule or team file.
_MAX_INT_BITS = 63
# Decimal digits that always fit in _MAX_INT_BITS (2**63 has 19 digits).
_PLAIN_DIGITS = 18
# An unpaired surrogate ("\udcff" written as an escape): no file or terminal can hold it.
_SURROGATE = re.compile("[\ud800-\udfff]")


def _short(text: str, limit: int = 80) -> str:
    """``text`` escaped and cut to ``limit`` characters, for quoting input in a message."""
    escaped = text.encode("unicode_escape", "backslashreplace").decode("ascii")
    return escaped if len(escaped) <= limit else escaped[: limit - 3] + "..."
