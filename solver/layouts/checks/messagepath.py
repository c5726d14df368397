"""Lichtblick's message-path grammar: ``/some/topic.field[0]{id==3}.value.@derivative``.

A recursive-descent parser that accepts exactly what Lichtblick's nearley grammar accepts
(``packages/message-path/src/grammar.ne`` at lichtblick-suite/lichtblick v1.19.0, commit
717b20cf41efc251b280c9959622bf0d5d3fea2a; unchanged in develop 66adecb99ca4 of August 2026)
and builds the same parts. The tests compare it with the real grammar compiled by nearleyc
on every path of Lichtblick's own ``parseMessagePath.test.ts`` and on thousands of generated
ones (``tests/layouts/checks/data/message_paths.json``). The grammar::

    main        -> topicName messagePath? modifier?
    topicName   -> slashID+ | id slashID* | quotedString
    slashID     -> "/" id?
    id          -> [a-zA-Z0-9_-]+
    quotedString-> '"' ( [^"\\\\] | '\\\\\\\\' | '\\\\"' )* '"'
    messagePath -> ( "." name slice? filter? | filter )* "."?
    name        -> id | quotedString
    slice       -> "[" sliceVal "]" | "[" sliceVal? ":" sliceVal? "]"
    sliceVal    -> integer | variable
    filter      -> "{" simplePath? "}" | "{" simplePath? operator value "}"
    simplePath  -> id ("." id)*
    operator    -> "==" | "!=" | ">=" | "<=" | ">" | "<"
    value       -> integer | string | "true" | "false" | variable
    integer     -> "-"? [0-9]+
    string      -> "'" [^']* "'" | '"' [^"]* '"'       (no escapes)
    variable    -> "$" id?
    modifier    -> ".@" id?

What the grammar accepts is not all the app shows as working: it parses ``robot1/points``
(no leading ``/``) although no ROS 2 topic has that name, and it accepts a trailing ``.``,
an empty ``{}`` filter or a bare ``$`` so that autocomplete can run, which the app then marks
as invalid; :attr:`MessagePath.incomplete` says so. Not here: whether the topic exists or
whether it is a valid ROS name (:func:`solver.ros.names.full_topic_name_problem`).
"""

from __future__ import annotations

from dataclasses import dataclass

from solver.errors import Fault, InputError, Location
from solver.untrusted import shown

__all__ = ["Filter", "MessagePath", "MessagePathError", "Name", "Slice", "parse_message_path"]

_ID_CHARS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-")
_OPERATORS = ("==", "!=", ">=", "<=", ">", "<")  # longest first, as the grammar's choice
# A variable in a slice or a filter value: ``$name`` (the name may be empty while typing).
Variable = tuple[str]
SliceValue = int | float | Variable  # float: only ``inf``, the open end of ``[1:]``
FilterValue = int | str | bool | Variable


class MessagePathError(InputError):
    """The text is not a message path; ``position`` is the 0-based index where parsing failed."""

    def __init__(self, message: str, position: int) -> None:
        super().__init__(
            Fault(
                Location("<message path>", 1, position + 1),
                f"{message} (at character {position + 1})",
                "message-path",
            )
        )
        self.position = position


@dataclass(frozen=True, slots=True)
class Name:
    """A field name (``.pose``; ``name`` is empty for a trailing ``.``)."""

    name: str


@dataclass(frozen=True, slots=True)
class Slice:
    """``[3]`` (start == end), ``[1:3]``, ``[:]`` (0 to ``inf``) or with ``$variables``."""

    start: SliceValue
    end: SliceValue


@dataclass(frozen=True, slots=True)
class Filter:
    """``{a.b==3}``; ``operator`` and ``value`` are None in a half-written ``{a.b}``."""

    path: tuple[str, ...]
    operator: str | None
    value: FilterValue | None


Part = Name | Slice | Filter


@dataclass(frozen=True, slots=True)
class MessagePath:
    """A parsed path: the topic, the parts after it, and a ``.@modifier`` (None if absent)."""

    topic: str
    parts: tuple[Part, ...]
    modifier: str | None

    @property
    def incomplete(self) -> bool:
        """Parses, but only as a path being typed: the app marks it invalid."""
        for part in self.parts:
            if isinstance(part, Name) and not part.name:
                return True
            if isinstance(part, Filter) and (not part.path or part.operator is None):
                return True
            values: tuple[object, ...] = ()
            if isinstance(part, Slice):
                values = (part.start, part.end)
            elif isinstance(part, Filter):
                values = (part.value,)
            # A bare ``$`` (a variable not named yet).
            if any(value == ("",) for value in values):
                return True
        return False


def parse_message_path(text: str) -> MessagePath:
    """The parts of ``text``, or :class:`MessagePathError` where Lichtblick's grammar fails."""
    return _Parser(text).main()


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.at = 0

    # -- helpers ---------------------------------------------------------------------------
    def peek(self, offset: int = 0) -> str:
        index = self.at + offset
        return self.text[index] if index < len(self.text) else ""

    def fail(self, message: str) -> MessagePathError:
        found = self.peek()
        got = f"unexpected {shown(found, quoted=True)}" if found else "unexpected end"
        return MessagePathError(f"{got}: {message}", self.at)

    def expect(self, literal: str) -> None:
        if not self.text.startswith(literal, self.at):
            raise self.fail(f"expected {literal!r}")
        self.at += len(literal)

    def id(self) -> str:
        start = self.at
        while self.peek() and self.peek() in _ID_CHARS:
            self.at += 1
        return self.text[start : self.at]

    # -- rules -----------------------------------------------------------------------------
    def main(self) -> MessagePath:
        topic = self.topic()
        parts = self.message_path()
        modifier = None
        if self.text.startswith(".@", self.at):
            self.at += 2
            modifier = self.id()
        if self.at != len(self.text):
            raise self.fail("expected '.', '{', '.@' or the end of the path")
        return MessagePath(topic, tuple(parts), modifier)

    def topic(self) -> str:
        if self.peek() == '"':
            return self.quoted()
        start = self.at
        if self.peek() != "/" and not self.id():
            raise self.fail("a topic starts with '/', a letter, a digit, '_', '-' or '\"'")
        while self.peek() == "/":
            self.at += 1
            self.id()
        return self.text[start : self.at]

    def quoted(self) -> str:
        self.expect('"')
        chars: list[str] = []
        while True:
            char = self.peek()
            if char == "":
                raise self.fail("an unclosed quoted name (missing '\"')")
            if char == '"':
                self.at += 1
                return "".join(chars)
            if char == "\\":
                following = self.peek(1)
                if following not in ('"', "\\"):
                    raise self.fail('in a quoted name only \\\\ and \\" are escapes')
                chars.append(following)
                self.at += 2
                continue
            chars.append(char)
            self.at += 1

    def message_path(self) -> list[Part]:
        parts: list[Part] = []
        while True:
            char, following = self.peek(), self.peek(1)
            if char == "{":
                parts.append(self.filter())
            elif char == "." and (following == '"' or following in _ID_CHARS) and following:
                self.at += 1
                parts.append(Name(self.quoted() if following == '"' else self.id()))
                if self.peek() == "[":
                    parts.append(self.slice())
                if self.peek() == "{":
                    parts.append(self.filter())
            elif char == "." and (following == "" or self.text.startswith(".@", self.at + 1)):
                # A trailing dot, kept so that autocomplete shows: an empty name.
                self.at += 1
                parts.append(Name(""))
                return parts
            elif char == "." and following != "@":
                self.at += 1
                raise self.fail("a field name after '.'")
            else:
                return parts

    def slice(self) -> Slice:
        self.expect("[")
        start = self.slice_value(optional=True)
        if self.peek() == ":":
            self.at += 1
            end = self.slice_value(optional=True)
            self.expect("]")
            return Slice(0 if start is None else start, float("inf") if end is None else end)
        if start is None:
            raise self.fail("an index, a range or a $variable in '[ ]'")
        self.expect("]")
        return Slice(start, start)

    def slice_value(self, *, optional: bool) -> SliceValue | None:
        if self.peek() == "$":
            self.at += 1
            return (self.id(),)
        if self.peek() == "-" or _is_digit(self.peek()):
            return self.integer()
        if optional:
            return None
        raise self.fail("an integer or a $variable")

    def integer(self) -> int:
        start = self.at
        if self.peek() == "-":
            self.at += 1
        digits = self.at
        while _is_digit(self.peek()):
            self.at += 1
        if self.at == digits:
            raise self.fail("digits")
        return int(self.text[start : self.at])

    def filter(self) -> Filter:
        self.expect("{")
        path: list[str] = []
        first = self.id()
        if first:
            path.append(first)
            while self.peek() == "." and self.peek(1) in _ID_CHARS and self.peek(1):
                self.at += 1
                path.append(self.id())
        if self.peek() == "}":
            self.at += 1
            return Filter(tuple(path), None, None)
        operator = next((op for op in _OPERATORS if self.text.startswith(op, self.at)), None)
        if operator is None:
            raise self.fail("a comparison (==, !=, >=, <=, >, <) or '}'")
        self.at += len(operator)
        value = self.value()
        self.expect("}")
        return Filter(tuple(path), operator, value)

    def value(self) -> FilterValue:
        char = self.peek()
        if char in ("'", '"'):
            self.at += 1
            end = self.text.find(char, self.at)
            if end < 0:
                raise self.fail(f"an unclosed string (missing {char!r})")
            text = self.text[self.at : end]
            self.at = end + 1
            return text
        if char == "$":
            self.at += 1
            return (self.id(),)
        if char == "-" or _is_digit(char):
            return self.integer()
        for word, meaning in (("true", True), ("false", False)):
            if self.text.startswith(word, self.at):
                self.at += len(word)
                return meaning
        raise self.fail("an integer, a 'string', true, false or a $variable")


def _is_digit(char: str) -> bool:
    return len(char) == 1 and "0" <= char <= "9"
