"""The prologue scan finds what a document type declares, in one pass, and stops at its bounds."""

from __future__ import annotations

import pytest

from solver.identify.readers.prologue import (
    MAX_ENTITIES,
    MAX_PROLOGUE_BYTES,
    MAX_PROLOGUE_ITEMS,
    Declaration,
    Entity,
    Stop,
    scan_prologue,
)

ROBOT = b'<robot name="r"/>'


def test_a_plain_prologue_ends_at_the_root_element() -> None:
    raw = b'\xef\xbb\xbf<?xml version="1.0"?>\n<!-- licence -->\n' + ROBOT
    prologue = scan_prologue(raw)
    assert prologue.stop is Stop.ROOT
    assert raw[prologue.offset :] == ROBOT
    assert prologue.entities == ()


def test_entities_are_named_with_their_offset_and_external_reference() -> None:
    raw = (
        b"<!DOCTYPE r [\n"
        b"  <!ELEMENT robot ANY> <!-- ] > --> <?pi ]>?>\n"
        b'  <!ENTITY a "x > y">\n'
        b'  <!ENTITY % p SYSTEM "file:///etc/passwd">\n'
        b'  <!ENTITY b PUBLIC "-//x//EN" "http://example.com/b.dtd">\n'
        b"  %p;\n"
        b"]>\n" + ROBOT
    )
    prologue = scan_prologue(raw)
    assert prologue.stop is Stop.ROOT
    assert prologue.entities == (
        Entity("a", raw.index(b"<!ENTITY a")),
        Entity("p", raw.index(b"<!ENTITY %"), "file:///etc/passwd"),
        Entity("b", raw.index(b"<!ENTITY b"), "http://example.com/b.dtd"),
    )


def test_a_document_type_without_internal_subset_declares_nothing() -> None:
    prologue = scan_prologue(b'<!DOCTYPE robot SYSTEM "a>b.dtd">' + ROBOT)
    assert (prologue.stop, prologue.entities) == (Stop.ROOT, ())


def test_the_scan_stops_after_enough_entities_to_refuse() -> None:
    raw = b"<!DOCTYPE r [" + b'<!ENTITY a "x">' * (MAX_ENTITIES * 10) + b"]>" + ROBOT
    prologue = scan_prologue(raw)
    assert prologue.stop is Stop.ENTITIES
    assert len(prologue.entities) == MAX_ENTITIES


@pytest.mark.parametrize(
    "raw",
    [
        b"<!--" + b"x" * MAX_PROLOGUE_BYTES + b"-->" + ROBOT,
        b" " * (MAX_PROLOGUE_BYTES + 1) + ROBOT,
        b'<!DOCTYPE r "' * (MAX_PROLOGUE_BYTES // 12 + 1) + ROBOT,
        b"<?a?>" * (MAX_PROLOGUE_ITEMS + 1) + ROBOT,
        b"<!DOCTYPE r [" + b"%a;" * (MAX_PROLOGUE_ITEMS + 1) + b"]>" + ROBOT,
    ],
    ids=["long-comment", "spaces", "open-literals", "many-instructions", "many-references"],
)
def test_a_prologue_past_its_bounds_is_reported_too_long(raw: bytes) -> None:
    assert scan_prologue(raw).stop is Stop.TOO_LONG


@pytest.mark.parametrize(
    ("raw", "stop"),
    [
        (b"<!-- never closed", Stop.END),
        (b'<!DOCTYPE r [<!ENTITY a "never closed', Stop.END),
        (b"<!DOCTYPE r [ garbage ]>" + ROBOT, Stop.OTHER),
        (b"<!DOCTYPE r [ ] garbage>" + ROBOT, Stop.OTHER),
        (b"text before the root" + ROBOT, Stop.OTHER),
        ("<?xml?>".encode("utf-16") + ROBOT, Stop.OTHER),
    ],
    ids=["open-comment", "open-literal", "subset-garbage", "after-subset", "text", "utf-16"],
)
def test_bytes_that_are_no_prologue_leave_the_verdict_to_the_parser(raw: bytes, stop: Stop) -> None:
    assert scan_prologue(raw).stop is stop


def test_forty_thousand_open_document_types_are_scanned_once() -> None:
    # Issue 23.2: a regular expression searching from each "<!DOCTYPE[" took minutes here. The
    # scan moves forward only: it stops at the first subset's first byte that is no declaration.
    raw = b"<!DOCTYPE[" * 40_000 + ROBOT
    prologue = scan_prologue(raw)
    assert prologue.stop is Stop.OTHER
    assert prologue.offset == len(b"<!DOCTYPE[")


def test_every_other_declaration_of_the_internal_subset_is_named_with_its_offset() -> None:
    raw = (
        b"<!DOCTYPE robot [\n"
        b'  <!ATTLIST joint type CDATA "revolute">\n'
        b"  <!ELEMENT robot ANY>\n"
        b'  <!NOTATION n SYSTEM "a>b">\n'
        b"  %p;\n"
        b"  <!-- a comment declares nothing --> <?pi nor does this?>\n"
        b"]>\n" + ROBOT
    )
    prologue = scan_prologue(raw)
    assert prologue.stop is Stop.ROOT
    assert prologue.entities == ()
    assert prologue.declarations == (
        Declaration("ATTLIST", "joint", raw.index(b"<!ATTLIST")),
        Declaration("ELEMENT", "robot", raw.index(b"<!ELEMENT")),
        Declaration("NOTATION", "n", raw.index(b"<!NOTATION")),
        Declaration("%", "p", raw.index(b"%p;")),
    )


def test_an_empty_internal_subset_declares_nothing() -> None:
    prologue = scan_prologue(b"<!DOCTYPE robot [ <!-- only a comment --> ]>" + ROBOT)
    assert (prologue.stop, prologue.entities, prologue.declarations) == (Stop.ROOT, (), ())
