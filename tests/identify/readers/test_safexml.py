"""Hostile XML is refused with a located error, in bounded memory."""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import pytest

from solver.errors import Fault, InputError
from solver.identify.readers.prologue import MAX_PROLOGUE_BYTES, MAX_PROLOGUE_ITEMS
from solver.identify.readers.safexml import MAX_XML_BYTES, parse_xml, read_xml
from tests.conftest import run_cli

LAUGHS = (
    '<?xml version="1.0"?>\n<!DOCTYPE lolz [\n <!ENTITY lol "lol">\n'
    + "".join(
        f' <!ENTITY lol{i} "{("&lol" + str(i - 1) + ";") * 10}">\n' for i in range(1, 10)
    ).replace("&lol0;", "&lol;")
    + ']>\n<robot name="&lol9;"/>\n'
)
QUADRATIC = (
    '<?xml version="1.0"?>\n<!DOCTYPE r [<!ENTITY a "' + "x" * 50_000 + '">]>\n'
    '<robot name="q">' + "&a;" * 50_000 + "</robot>\n"
)
EXTERNAL = (
    '<?xml version="1.0"?>\n<!DOCTYPE r [\n<!ENTITY xxe SYSTEM "file:///etc/passwd">\n]>'
    '\n<robot name="&xxe;"/>\n'
)


@pytest.mark.parametrize(
    "text",
    [LAUGHS, QUADRATIC, EXTERNAL],
    ids=["billion-laughs", "quadratic-blowup", "external-entity"],
)
def test_entity_declarations_are_refused_with_their_line(text: str) -> None:
    with pytest.raises(InputError) as caught:
        parse_xml(text, "bomb.urdf")
    fault = caught.value.faults[0]
    assert fault.code == "xml-entity"
    assert fault.location.file == "bomb.urdf"
    assert fault.location.line is not None
    assert fault.location.line >= 2


def test_external_entity_error_names_the_reference() -> None:
    with pytest.raises(InputError, match="file:///etc/passwd"):
        parse_xml(EXTERNAL, "x.urdf")


def test_malformed_xml_error_has_line_and_column() -> None:
    with pytest.raises(InputError) as caught:
        parse_xml('<robot name="x">\n  <link name="a">\n</robot>\n', "bad.urdf")
    location = caught.value.faults[0].location
    assert (location.file, location.line) == ("bad.urdf", 3)
    assert location.column is not None


def test_a_100_mb_file_is_refused_after_reading_at_most_the_cap(tmp_path: Path) -> None:
    big = tmp_path / "big.urdf"
    with big.open("wb") as stream:
        stream.write(b'<robot name="big">')
        stream.truncate(100 * 1024 * 1024)
    tracemalloc.start()
    with pytest.raises(InputError, match="larger than"):
        read_xml(big)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 2 * MAX_XML_BYTES + 1024 * 1024


def test_an_empty_file_and_a_folder_are_refused(tmp_path: Path) -> None:
    (tmp_path / "empty.urdf").write_text("")
    with pytest.raises(InputError, match="empty file"):
        read_xml(tmp_path / "empty.urdf")
    with pytest.raises(InputError, match="directory"):
        read_xml(tmp_path)


@pytest.mark.parametrize(
    "text",
    [LAUGHS, QUADRATIC, EXTERNAL],
    ids=["billion-laughs", "quadratic-blowup", "external-entity"],
)
def test_the_cli_refuses_bombs_with_exit_2_and_no_traceback(tmp_path: Path, text: str) -> None:
    path = tmp_path / "bomb.urdf"
    path.write_text(text, encoding="utf-8")
    result = run_cli("identify", path)
    assert result.returncode == 2
    assert "bomb.urdf:" in result.stderr
    assert "entity" in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""


# Issue 23.2: a regular expression searching the prologue from every "<!DOCTYPE[" was quadratic
# (more than 60 s in `identify` for this file, and the same on a live robot_description).
OPEN_DOCTYPES = b"<!DOCTYPE[" * 40_000 + b'<robot name="r"/>'


def test_forty_thousand_open_document_types_are_malformed_xml_at_their_line() -> None:
    with pytest.raises(InputError) as caught:
        parse_xml(OPEN_DOCTYPES, "open.urdf")
    fault = caught.value.faults[0]
    assert (fault.code, fault.location.file, fault.location.line) == ("xml", "open.urdf", 1)


@pytest.mark.parametrize(
    ("raw", "line"),
    [
        (b"<!--" + b"x" * MAX_PROLOGUE_BYTES + b'-->\n<robot name="r"/>', 1),
        # The document type is the first item, so the declaration past the bound is on the
        # line of the last one allowed.
        (
            b"<!DOCTYPE r [<!ELEMENT a ANY>\n"
            + b"<!ELEMENT a ANY>\n" * MAX_PROLOGUE_ITEMS
            + b']><robot name="r"/>',
            MAX_PROLOGUE_ITEMS,
        ),
    ],
    ids=["a-1-mib-comment", "ten-thousand-declarations"],
)
def test_a_prologue_past_its_bounds_is_refused_with_its_line(raw: bytes, line: int) -> None:
    with pytest.raises(InputError, match="no root element within") as caught:
        parse_xml(raw, "long.urdf", warnings=[])
    fault = caught.value.faults[0]
    assert (fault.code, fault.location.line) == ("xml-prologue", line)


def test_entity_names_from_the_prologue_are_shown_escaped() -> None:
    raw = b'<!DOCTYPE r [<!ENTITY a\x1b[2J "x">]><robot name="r"/>'
    with pytest.raises(InputError) as caught:
        parse_xml(raw, "x.urdf")
    assert "\x1b" not in str(caught.value)
    assert "\\x1b[2J" in str(caught.value)


def test_the_cli_refuses_forty_thousand_open_document_types_with_exit_2(tmp_path: Path) -> None:
    path = tmp_path / "open.urdf"
    path.write_bytes(OPEN_DOCTYPES)
    result = run_cli("identify", path)
    assert result.returncode == 2
    assert result.stderr.startswith(f"{path}:1:")
    assert "malformed XML" in result.stderr
    assert "Traceback" not in result.stderr


# ---- declarations in a document type (issue 36.14c) -------------------------------------------
# An attribute default gives an element an attribute the file does not write, to every tool
# that applies it (xml.etree.ElementTree does; lxml with attribute_defaults) and to no other
# (minidom, lxml as read here): one file, two robots.


@pytest.mark.parametrize(
    ("declaration", "named"),
    [
        ('<!ATTLIST joint type CDATA "revolute">', "<!ATTLIST joint>"),
        ("<!ELEMENT robot ANY>", "<!ELEMENT robot>"),
        ('<!NOTATION gif SYSTEM "image/gif">', "<!NOTATION gif>"),
        ("%p;", "%p;"),
    ],
    ids=["ATTLIST", "ELEMENT", "NOTATION", "parameter entity reference"],
)
def test_a_document_type_that_declares_anything_is_refused_at_its_line(
    declaration: str, named: str
) -> None:
    text = (
        '<?xml version="1.0"?>\n<!DOCTYPE robot [\n  <!-- fine -->\n'
        f"  {declaration}\n]>\n"
        '<robot name="r"><link name="a"/><joint name="j"/></robot>\n'
    )
    lenient: list[Fault] = []
    for warnings in (None, lenient):  # strict, and lenient as the ROS tools are
        with pytest.raises(InputError) as caught:
            parse_xml(text, "r.urdf", warnings=warnings)
        fault = caught.value.faults[0]
        assert (fault.code, fault.location.line, fault.location.path) == ("xml-dtd", 4, named)
        assert fault.message.startswith(f"the document type declares {named}; declarations in")


def test_a_document_type_that_declares_nothing_is_read() -> None:
    for doctype in ("<!DOCTYPE robot>", "<!DOCTYPE robot [ ]>", '<!DOCTYPE robot SYSTEM "r.dtd">'):
        root = parse_xml(f'{doctype}\n<robot name="r"/>', "r.urdf")
        assert root.get("name") == "r"


def test_a_document_type_the_prologue_scan_cannot_read_is_refused_after_parsing() -> None:
    # UTF-16: the byte scan stops at once, and libxml2 reads the declaration.
    text = '<!DOCTYPE robot [<!ATTLIST joint type CDATA "revolute">]>\n<robot name="r"/>'
    with pytest.raises(InputError) as caught:
        parse_xml(text.encode("utf-16"), "r.urdf")
    assert caught.value.faults[0].code == "xml-dtd"


@pytest.mark.parametrize("option", ["", "--srdf"])
def test_identify_refuses_an_attribute_default_in_a_urdf_or_srdf(
    tmp_path: Path, option: str
) -> None:
    from tests.identify import builders

    attlist = '<!DOCTYPE robot [\n<!ATTLIST joint type CDATA "revolute">\n]>\n'
    urdf, srdf = tmp_path / "r.urdf", tmp_path / "r.srdf"
    urdf.write_text((attlist if not option else "") + builders.ugv().text(), encoding="utf-8")
    srdf.write_text(attlist + '<robot name="r"><group name="arm"/></robot>\n', encoding="utf-8")
    srdf_option: list[str | Path] = [option, srdf] if option else []
    result = run_cli("identify", urdf, *srdf_option)
    assert "Traceback" not in result.stderr
    if not option:
        assert result.returncode == 2, result.stdout
        assert result.stderr.startswith(f"{urdf}:2: <!ATTLIST joint>: the document type declares")
        return
    # A supporting file is refused, not read, with its located warning; the URDF is read alone.
    assert result.returncode == 0, result.stderr
    assert f"warning: {srdf}:2: <!ATTLIST joint>: the document type declares" in result.stdout
    assert "the SRDF is not read; the URDF alone is" in result.stdout
    assert "structure:      UGV" in result.stdout


def test_comments_xml_forbids_are_read_with_one_warning_and_refused_when_strict() -> None:
    text = b'<robot name="r">\n<link name="a"/>\n<!-- a -- b -->\n<!-- c --->\n</robot>\n'
    warnings: list[Fault] = []
    root = parse_xml(text, "r.urdf", warnings=warnings)
    assert [child.get("name") for child in root] == ["a"]
    assert [(w.location.line, w.code) for w in warnings] == [(3, "xml-comment")]
    assert warnings[0].message.startswith("2 comment(s) hold '--' or end in '-'")
    with pytest.raises(InputError, match=r"r.urdf:3:\d+: malformed XML: Double hyphen"):
        parse_xml(text, "r.urdf")
