"""The fault-collecting reader: every problem of a document, located, and validation goes on."""

from __future__ import annotations

from solver.files.reader import Reader, type_name
from solver.files.yamlio import parse_document


def reader_of(text: str) -> Reader:
    return Reader(parse_document(text, "doc.yaml"))


def test_a_wrong_type_is_a_located_fault_and_reading_continues() -> None:
    reader = reader_of("name: [a, b]\ncount: seven\nteam: {UAV: 1}\n")
    assert reader.string(("name",), "a name") == ""
    assert reader.integer(("count",), "a count") is None
    assert reader.mapping(("team",), "the team") == {"UAV": 1}
    assert [str(fault) for fault in reader.faults] == [
        "doc.yaml:1:7: name: a name must be a string, got a list",
        "doc.yaml:2:8: count: a count must be a whole number, got a string ('seven')",
    ]


def test_a_missing_required_field_is_reported_and_an_optional_one_is_not() -> None:
    reader = reader_of("other: 1\n")
    assert reader.string(("name",), "a name", required=False, default="x") == "x"
    assert reader.mapping(("team",), "the team") == {}
    assert [fault.message for fault in reader.faults] == ["missing the team"]
    assert [fault.code for fault in reader.faults] == ["missing-field"]


def test_a_file_that_is_no_mapping_is_named_without_quoting_it() -> None:
    reader = reader_of("- root:x:0:0\n")
    assert reader.top("rule set", needs="characteristics") is None
    assert [fault.message for fault in reader.faults] == [
        "not a rule set: expected a mapping of fields at the top level, got a list"
    ]


def test_names_longer_than_the_limit_are_refused() -> None:
    reader = reader_of(f"name: {'x' * 201}\n")
    assert reader.string(("name",), "a name") == ""
    assert [fault.code for fault in reader.faults] == ["too-large"]


def test_a_string_of_the_wrong_type_is_quoted_escaped_and_cut_short() -> None:
    assert type_name("a\x1bb") == "a string ('a\\x1bb')"
    assert type_name("y" * 100) == "a string ('" + "y" * 60 + "...' (cut from 100 characters))"
    assert type_name(True) == "a boolean (true)"
    assert type_name(None) == "nothing (null)"
