"""The XML prologue (what comes before the root element), scanned once, in linear time.

A robot description's prologue is an XML declaration, perhaps a comment or two, and in a
hostile file a document type declaration whose internal subset declares entities, attribute
defaults or elements. Before libxml2 sees a document, :mod:`solver.identify.readers.safexml`
asks this module which entities and other declarations the prologue holds, to refuse them with
one clear, located message.

The scan is a single pass with ``bytes.find`` from a position that only moves forward, so it
costs time linear in the prologue whatever the bytes are (a regular expression searching for
the internal subset from every ``<!DOCTYPE[`` was quadratic: 40,000 of them took minutes). It
reads at most :data:`MAX_PROLOGUE_BYTES` and :data:`MAX_PROLOGUE_ITEMS` items (comments,
processing instructions, declarations); a longer prologue is reported as such (real
descriptions have a few hundred bytes and a handful of items before the root element, a
licence comment a few kilobytes) and the reader refuses it.

The scan is not a parser: where the bytes are not a prologue it knows (a second document type,
a malformed declaration, a UTF-16 document), it stops and leaves the verdict to libxml2, whose
tree is checked for entities again after parsing.

Not here: refusing what was found, parsing (:mod:`solver.identify.readers.safexml`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import Enum

__all__ = [
    "MAX_ENTITIES",
    "MAX_PROLOGUE_BYTES",
    "MAX_PROLOGUE_ITEMS",
    "Declaration",
    "Entity",
    "Prologue",
    "Stop",
    "scan_prologue",
]

# The longest prologue read. Real URDFs and SRDFs: an XML declaration and a comment of at most
# a few kilobytes; 1 MiB is far past any of them and still scanned in about a millisecond.
MAX_PROLOGUE_BYTES = 1024 * 1024
# ... and at most this many items in it (comments, processing instructions, declarations):
# three-byte items would otherwise cost a Python step each, a second per 300,000.
MAX_PROLOGUE_ITEMS = 10_000
# The scan stops at this many entity declarations: one is enough to refuse the document.
MAX_ENTITIES = 64

# Single-byte classes: each search costs time linear in the distance it moves.
_NOT_SPACE = re.compile(rb"[^ \t\r\n]")
_NAME_END = re.compile(rb"[ \t\r\n>\"']")
_MARKUP_END = re.compile(rb"[>\"']")
_DOCTYPE_PART_END = re.compile(rb"[\[>\"']")
# A processing instruction whose target is ``xml``: an XML declaration (not ``<?xml-model``).
_XML_TARGET = re.compile(rb"<\?xml[ \t\r\n]")


class Stop(Enum):
    """Why the scan ended."""

    ROOT = "root"  # at the root element's "<": the whole prologue was seen
    ENTITIES = "entities"  # MAX_ENTITIES entity declarations seen; the rest was not scanned
    END = "end"  # the bytes ended (or a construct was left open) before any root element
    OTHER = "other"  # something a prologue does not hold; libxml2 will say what
    TOO_LONG = "too long"  # no root element within MAX_PROLOGUE_BYTES or MAX_PROLOGUE_ITEMS


@dataclass(frozen=True, slots=True)
class Entity:
    """One ``<!ENTITY`` declaration of the internal subset."""

    name: str
    offset: int  # of its "<!ENTITY"
    external: str | None = None  # the SYSTEM (or PUBLIC) literal of an external entity


@dataclass(frozen=True, slots=True)
class Declaration:
    """Any other declaration of the internal subset: ``<!ATTLIST joint ...>`` is
    ``Declaration("ATTLIST", "joint", offset)``, a parameter entity reference ``%p;`` is
    ``Declaration("%", "p", offset)``."""

    kind: str
    name: str
    offset: int  # of its "<!" (or "%")


@dataclass(frozen=True, slots=True)
class Prologue:
    entities: tuple[Entity, ...]
    stop: Stop
    offset: int  # where the scan ended (the root element's "<" when stop is ROOT)
    declarations: tuple[Declaration, ...] = ()  # the subset's others, comments aside
    # Where each XML declaration of the prologue (a processing instruction whose target is
    # ``xml``, outside the document type) starts and ends: the first, and any a file wrote
    # after a comment or a second time.
    xml_declarations: tuple[tuple[int, int], ...] = ()


def scan_prologue(raw: bytes, limit: int = MAX_PROLOGUE_BYTES) -> Prologue:
    """The entities the prologue of ``raw`` declares, and where and why the scan ended."""
    return _Scanner(raw, limit).prologue()


class _Scanner:
    def __init__(self, raw: bytes, limit: int) -> None:
        self.raw = raw
        self.end = min(len(raw), limit)
        self.cut = len(raw) > limit  # running out of bytes at `end` means the limit was hit
        self.pos = 0
        self.entities: list[Entity] = []
        self.declarations: list[Declaration] = []
        self.xml_declarations: list[tuple[int, int]] = []
        self.items = 0

    def prologue(self) -> Prologue:
        raw = self.raw
        if raw.startswith(b"\xef\xbb\xbf"):
            self.pos = 3
        doctype_seen = False
        while True:
            self._skip_space()
            if self.pos >= self.end:
                return self._out_of_bytes()
            if self._crowded():
                return self._result(Stop.TOO_LONG)
            if raw.startswith(b"<?", self.pos):
                if not self._instruction():
                    return self._out_of_bytes()
            elif raw.startswith(b"<!--", self.pos):
                if not self._past(b"<!--", b"-->"):
                    return self._out_of_bytes()
            elif raw.startswith(b"<!DOCTYPE", self.pos) and not doctype_seen:
                doctype_seen = True
                stop = self._doctype()
                if stop is not None:
                    return self._result(stop)
            elif raw.startswith(b"<", self.pos) and self._name_start(self.pos + 1):
                return self._result(Stop.ROOT)
            else:
                return self._result(Stop.OTHER)

    def _instruction(self) -> bool:
        """Past one processing instruction, an XML declaration's place noted; ``False`` if open."""
        start = self.pos
        if not self._past(b"<?", b"?>"):
            return False
        if _XML_TARGET.match(self.raw, start):
            self.xml_declarations.append((start, self.pos))
        return True

    def _doctype(self) -> Stop | None:
        """Past ``<!DOCTYPE name ExternalID? [subset]? >``; a stop if the scan ends inside."""
        self.pos += len(b"<!DOCTYPE")
        while True:  # the name and external identifier, up to "[" or ">"
            found = _DOCTYPE_PART_END.search(self.raw, self.pos, self.end)
            if found is None:
                return self._stop_out_of_bytes()
            self.pos = found.start()
            mark = self.raw[self.pos : self.pos + 1]
            if mark in b">[":
                self.pos += 1
                return self._internal_subset() if mark == b"[" else None
            if not self._past_literal():
                return self._stop_out_of_bytes()

    def _internal_subset(self) -> Stop | None:
        """Past the declarations up to ``]`` and the ``>`` after it."""
        while True:
            self._skip_space()
            if self.pos >= self.end:
                return self._stop_out_of_bytes()
            if self._crowded():
                return Stop.TOO_LONG
            if self.raw.startswith(b"]", self.pos):
                self.pos += 1
                self._skip_space()
                if self.pos >= self.end:
                    return self._stop_out_of_bytes()
                if not self.raw.startswith(b">", self.pos):
                    return Stop.OTHER
                self.pos += 1
                return None
            if self.raw.startswith(b"<!ENTITY", self.pos) and len(self.entities) >= MAX_ENTITIES:
                return Stop.ENTITIES
            done = self._declaration()
            if done is None:
                return Stop.OTHER
            if not done:
                return self._stop_out_of_bytes()

    def _declaration(self) -> bool | None:
        """Past one item of the internal subset: ``None`` if it is none, ``False`` if open."""
        raw, pos = self.raw, self.pos
        if raw.startswith(b"<!--", pos):
            return self._past(b"<!--", b"-->")
        if raw.startswith(b"<?", pos):
            return self._past(b"<?", b"?>")
        if raw.startswith(b"<!ENTITY", pos):
            return self._entity()
        for kind in (b"ELEMENT", b"ATTLIST", b"NOTATION"):
            if raw.startswith(b"<!" + kind, pos):
                self.pos += len(kind) + 2
                self._declared(kind.decode(), pos)
                return self._past_markup()
        if raw.startswith(b"%", pos):  # a parameter entity reference
            end = raw.find(b";", pos + 1, self.end)
            if end >= 0:
                self.declarations.append(Declaration("%", _text(raw[pos + 1 : end]), pos))
            return self._past(b"%", b";")
        return None

    def _declared(self, kind: str, start: int) -> None:
        """Record the declaration of ``kind`` at ``start`` by the name after it."""
        self._skip_space()
        found = _NAME_END.search(self.raw, self.pos, self.end)
        end = self.end if found is None else found.start()
        self.declarations.append(Declaration(kind, _text(self.raw[self.pos : end]), start))
        self.pos = end

    def _entity(self) -> bool:
        start = self.pos
        self.pos += len(b"<!ENTITY")
        self._skip_space()
        if self.raw.startswith(b"%", self.pos):
            self.pos += 1
            self._skip_space()
        name_start = self.pos
        found = _NAME_END.search(self.raw, self.pos, self.end)
        self.pos = self.end if found is None else found.start()
        name = _text(self.raw[name_start : self.pos])
        self._skip_space()
        literals: list[bytes] = []
        keyword = b""
        for word in (b"SYSTEM", b"PUBLIC"):
            if self.raw.startswith(word, self.pos):
                keyword = word
                self.pos += len(word)
        while self.pos < self.end and len(literals) < 2:
            self._skip_space()
            if self.pos >= self.end or self.raw[self.pos] not in b"\"'":
                break
            opened = self.pos
            if not self._past_literal():
                return False
            literals.append(self.raw[opened + 1 : self.pos - 1])
        external = None
        if keyword and literals:
            literal = literals[-1] if keyword == b"PUBLIC" else literals[0]
            external = literal.decode("utf-8", errors="replace")
        self.entities.append(Entity(name, start, external))
        return self._past_markup()

    def _past_markup(self) -> bool:
        """Past the ">" that ends this declaration, skipping quoted literals."""
        while True:
            found = _MARKUP_END.search(self.raw, self.pos, self.end)
            if found is None:
                return False
            self.pos = found.start()
            if self.raw[self.pos : self.pos + 1] == b">":
                self.pos += 1
                return True
            if not self._past_literal():
                return False

    def _past_literal(self) -> bool:
        quote = self.raw[self.pos : self.pos + 1]
        close = self.raw.find(quote, self.pos + 1, self.end)
        if close < 0:
            return False
        self.pos = close + 1
        return True

    def _past(self, opener: bytes, terminator: bytes) -> bool:
        found = self.raw.find(terminator, self.pos + len(opener), self.end)
        if found < 0:
            return False
        self.pos = found + len(terminator)
        return True

    def _skip_space(self) -> None:
        found = _NOT_SPACE.search(self.raw, self.pos, self.end)
        self.pos = self.end if found is None else found.start()

    def _name_start(self, position: int) -> bool:
        if position >= len(self.raw):
            return False
        byte = self.raw[position]
        return byte >= 0x80 or byte in b"_:" or chr(byte).isalpha()

    def _crowded(self) -> bool:
        self.items += 1
        return self.items > MAX_PROLOGUE_ITEMS

    def _stop_out_of_bytes(self) -> Stop:
        return Stop.TOO_LONG if self.cut else Stop.END

    def _out_of_bytes(self) -> Prologue:
        return self._result(self._stop_out_of_bytes())

    def _result(self, stop: Stop) -> Prologue:
        return Prologue(
            tuple(self.entities),
            stop,
            min(self.pos, self.end),
            tuple(self.declarations),
            tuple(self.xml_declarations),
        )


def _text(name: bytes) -> str:
    return name.decode("utf-8", errors="replace")
