"""Parsing untrusted XML (URDF, SRDF, xacro) safely, with located errors.

Robot descriptions come from anywhere: a download, a ROS master, a colleague's folder. They are
parsed with lxml set up so that nothing in a file can reach outside it or blow up in memory:
entity substitution, DTD loading and network access are off, libxml2's "huge tree" mode is off
(it caps depth and text node size), and files are read with a size cap before parsing, so a
100 MB file or ``/dev/zero`` is refused after reading at most :data:`MAX_XML_BYTES` + 1 bytes.
A document type declaration that declares entities (the shape of "billion laughs", quadratic
blowup and external-entity attacks) is refused outright: URDF and SRDF never need one. So is
one that declares anything else (``<!ATTLIST joint type CDATA "revolute">``, an element, a
notation, a parameter entity reference): an attribute default gives an element an attribute
the file does not write, to every tool that applies defaults (Python's ElementTree does) and
to none that does not (this reader, xacro's minidom), so one file would be two robots. A document
type that declares nothing (``<!DOCTYPE robot>``, an external one, which is never loaded) is
read.

Every problem is an :class:`~solver.errors.InputError` naming the file and, where libxml2 knows
it, the line and column.

Not here: what the elements mean (:mod:`solver.identify.readers.urdf`,
:mod:`solver.identify.readers.srdf`).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

from solver.errors import Fault, InputError, Location
from solver.extras import require
from solver.files.inputfile import read_bounded
from solver.identify.readers.prologue import (
    MAX_PROLOGUE_BYTES,
    MAX_PROLOGUE_ITEMS,
    Prologue,
    Stop,
    scan_prologue,
)
from solver.untrusted import shown

if TYPE_CHECKING:
    from lxml import etree

__all__ = ["MAX_XML_BYTES", "line_of", "parse_xml", "read_bytes", "read_xml"]

# The largest description read. Real URDFs are kilobytes (the largest of 31 public robots
# measured is 91 KB); generated ones with inline data stay well under this.
MAX_XML_BYTES = 16 * 1024 * 1024


def read_bytes(
    path: str | Path, *, display: str | None = None, limit: int = MAX_XML_BYTES
) -> bytes:
    """The bytes of ``path``, refusing more than ``limit`` without reading them all."""
    return read_bounded(path, display=display, limit=limit)


def line_of(element: etree._Element | None) -> int | None:
    """The source line of ``element`` (lxml-stubs types ``sourceline`` loosely)."""
    line: object = None if element is None else element.sourceline
    return line if isinstance(line, int) else None


def read_xml(path: str | Path, *, display: str | None = None) -> etree._Element:
    """Read and safely parse the XML file ``path``; its root element."""
    name = display if display is not None else str(path)
    return parse_xml(read_bytes(path, display=name), name)


def parse_xml(
    data: bytes | str, name: str = "<string>", *, warnings: list[Fault] | None = None
) -> etree._Element:
    """Safely parse XML text or bytes into its root element (see the module docstring).

    With a ``warnings`` list the parse is lenient the way the ROS tools are with real files:
    blank lines before the XML declaration, a declaration after a comment or a second one, an
    XML version other than 1.0, trailing NUL bytes, comments XML forbids (``--`` inside),
    undeclared namespace prefixes (``<xacro:include>`` in an expanded URDF) and elements in a
    default namespace (Drake's) are read, and each is appended to ``warnings`` as a located
    :class:`~solver.errors.Fault`. Without it, each is an error. Hostile XML (entity
    declarations) is refused either way.
    """
    require("lxml", feature="reading URDF, SRDF and xacro files (identify, fleet, watch)")
    from lxml import etree

    raw = data.encode("utf-8") if isinstance(data, str) else data
    if len(raw) > MAX_XML_BYTES:
        raise InputError.at(
            name, f"document is larger than {MAX_XML_BYTES} bytes; refused", code="too-large"
        )
    if not raw.strip(b" \t\r\n\x00"):
        raise InputError.at(name, "empty file: expected an XML document", code="xml")
    prologue = _refuse_declarations(raw, name)
    if warnings is not None:
        raw = _mend(raw, name, warnings, prologue)
    try:
        root = etree.fromstring(raw, _parser())
    except etree.XMLSyntaxError as error:
        mended = None if warnings is None else _namespace_recovery(raw, name, warnings)
        if mended is None:
            line, column = error.position if error.position else (None, None)
            message = str(error.msg or error).split(f", line {line}")[0]
            raise InputError.at(
                name,
                f"malformed XML: {message}",
                line=line or None,
                column=column or None,
                code="xml",
            ) from None
        root = mended
    except ValueError as error:  # lxml refuses, e.g., str input carrying an encoding declaration
        raise InputError.at(name, f"malformed XML: {error}", code="xml") from None
    _refuse_entities(root, raw, name, prologue)
    if warnings is not None:
        _drop_default_namespace(root, name, warnings)
    return root


def _drop_default_namespace(root: etree._Element, name: str, warnings: list[Fault]) -> None:
    """Elements written without a prefix in the root's default namespace (``<robot
    xmlns="http://drake.mit.edu">``, Drake's URDF) renamed by their local names, as ROS's
    parsers (TinyXML2, which knows no namespaces) read them, with one warning. Prefixed
    elements (``xacro:``) keep their names, whatever namespace their prefix is bound to."""
    from lxml import etree

    namespace = root.nsmap.get(None)
    if namespace is None or etree.QName(root).namespace != namespace:
        return
    _warn(
        warnings,
        name,
        line_of(root),
        f"the document's elements are in the namespace {shown(namespace, quoted=True)}; "
        "read by their local names, as ROS's parsers read them",
        "xml-namespace",
    )
    prefix = f"{{{namespace}}}"
    for element in root.iter(prefix + "*"):
        if element.prefix is None:
            element.tag = element.tag[len(prefix) :]


_DECLARATION = re.compile(rb"<\?xml\s[^>]*?\?>")
_BOM = b"\xef\xbb\xbf"
_VERSION = re.compile(rb"""version\s*=\s*(["'])([^"']*)\1""")


def _warn(warnings: list[Fault], name: str, line: int | None, message: str, code: str) -> None:
    warnings.append(Fault(Location(name, line), message, code))


def _mend(raw: bytes, name: str, warnings: list[Fault], prologue: Prologue) -> bytes:
    """Repair the flaws real descriptions have outside their elements, keeping line numbers."""
    stripped = raw.rstrip(b" \t\r\n\x00")
    if b"\x00" in raw[len(stripped) :]:
        _warn(
            warnings,
            name,
            raw.count(b"\n", 0, raw.index(b"\x00", len(stripped))) + 1,
            "NUL byte(s) after the end of the document ignored",
            "xml-trailing-nul",
        )
        raw = stripped + b"\n"
    raw = _declaration_first(raw, name, warnings, prologue)
    declaration = _DECLARATION.match(raw)
    if declaration is not None:
        version = _VERSION.search(declaration.group(0))
        if version is not None and version.group(2) != b"1.0":
            given = version.group(2).decode("ascii", errors="replace")
            _warn(
                warnings,
                name,
                1,
                f"XML version {shown(given, quoted=True)} declared; read as XML 1.0",
                "xml-version",
            )
            text = declaration.group(0)
            fixed = text[: version.start(2)] + b"1.0" + text[version.end(2) :]
            raw = fixed + raw[declaration.end() :]
    return _mend_comments(raw, name, warnings)


def _declaration_first(raw: bytes, name: str, warnings: list[Fault], prologue: Prologue) -> bytes:
    """XML declarations the prologue scan found out of place (one after blank lines or under a
    licence banner, a second one a generator wrote after its own banner), which XML forbids
    and ROS's URDF parser (TinyXML2) reads: the first moved to the start when none is there,
    the others blanked; every line keeps its number; one warning. Only the prologue's own
    processing instructions are touched (:attr:`Prologue.xml_declarations`), never text
    inside a comment, another instruction or the document type."""
    spans = prologue.xml_declarations
    if not spans:
        return raw
    lead = len(_BOM) if raw.startswith(_BOM) else 0  # a declaration may follow a byte order mark
    in_place = _DECLARATION.match(raw, lead) is not None  # at the start, or moved there
    misplaced = spans[1:] if in_place else spans
    if not misplaced:
        return raw
    first = misplaced[0][0]
    if in_place:
        why = f"{len(misplaced)} more XML declaration(s) after the first"
    else:
        why = (
            f"the XML declaration is not at the start of the document ({_before(raw[lead:first])})"
        )
    _warn(warnings, name, raw.count(b"\n", 0, first) + 1, f"{why}; read anyway", "xml-declaration")
    pieces = [raw[:lead], b"" if in_place else _one_line(raw[first : misplaced[0][1]])]
    position = lead
    for start, end in misplaced:
        pieces += [raw[position:start], bytes(c if c in b"\r\n" else 0x20 for c in raw[start:end])]
        position = end
    return b"".join(pieces) + raw[position:]


def _before(text: bytes) -> str:
    """What comes before a declaration out of place, in words."""
    if not text.strip(b" \t\r\n"):
        return "blank lines before it"
    return "a comment before it" if b"<!--" in text else "something before it"


def _one_line(text: bytes) -> bytes:
    return text.replace(b"\r", b" ").replace(b"\n", b" ")


def _mend_comments(raw: bytes, name: str, warnings: list[Fault]) -> bytes:
    """Comments holding ``--`` or ending in ``-`` (``<!-- a -- b -->``, ``<!-- x --->``), which
    XML forbids and ROS's own URDF parser (TinyXML2) reads: read as the comments they are, the
    offending hyphens blanked (same length: every line keeps its number), one warning at the
    first. One pass over the document."""
    pieces: list[bytes] = []
    start = first = 0
    mended = 0
    while True:
        opening = raw.find(b"<!--", start)
        closing = -1 if opening < 0 else raw.find(b"-->", opening + 4)
        if closing < 0:
            break
        body = raw[opening + 4 : closing]
        if b"--" in body or body.endswith(b"-"):
            fixed = body.replace(b"--", b"- ")
            fixed = fixed[:-1] + b" " if fixed.endswith(b"-") else fixed
            pieces += [raw[start : opening + 4], fixed]
            start = closing
            first = first or raw.count(b"\n", 0, opening) + 1
            mended += 1
        else:
            pieces.append(raw[start : closing + 3])
            start = closing + 3
    if not mended:
        return raw
    _warn(
        warnings,
        name,
        first,
        f"{mended} comment(s) hold '--' or end in '-', which XML forbids (ROS's URDF parser "
        "reads them); read as comments",
        "xml-comment",
    )
    return b"".join(pieces) + raw[start:]


def _namespace_recovery(raw: bytes, name: str, warnings: list[Fault]) -> etree._Element | None:
    """Parse again when namespace errors are libxml2's only complaint; ``None`` otherwise.

    An expanded URDF that still holds a ``<xacro:...>`` element without the xacro namespace
    declared is well formed apart from the prefix: the element is kept under its prefixed name.
    """
    from lxml import etree

    parser = _parser(recover=True)
    try:
        root = etree.fromstring(raw, parser)
    except etree.XMLSyntaxError:
        return None
    errors = list(parser.error_log)
    if root is None or not errors or any(e.domain_name != "NAMESPACE" for e in errors):
        return None
    for error in errors:
        _warn(
            warnings,
            name,
            error.line or None,
            f"{error.message.strip()}; element kept under its prefixed name",
            "xml-namespace",
        )
    return root


def _refuse_declarations(raw: bytes, name: str) -> Prologue:
    """Refuse entity and other declarations before libxml2 sees them, naming the first one;
    the prologue scanned.

    libxml2 would refuse most bombs itself, but with messages about loops or amplification;
    scanning the prologue first (:mod:`solver.identify.readers.prologue`, linear and bounded)
    gives one clear message for every variant, and refuses a prologue past its length bound.
    """
    prologue = scan_prologue(raw)
    if prologue.entities:
        _refuse_entity_declarations(prologue, raw, name)
    if prologue.stop is Stop.TOO_LONG:
        raise InputError.at(
            name,
            "no root element within the first "
            f"{MAX_PROLOGUE_BYTES} bytes or {MAX_PROLOGUE_ITEMS:,} items (XML declaration, "
            "comments, processing instructions, document type declarations); refused",
            line=raw.count(b"\n", 0, prologue.offset) + 1,
            code="xml-prologue",
        )
    if prologue.declarations:
        first = prologue.declarations[0]
        named = (
            f"%{shown(first.name)};"
            if first.kind == "%"
            else f"<!{first.kind} {shown(first.name)}>"
        )
        raise _declared(name, named, line=raw.count(b"\n", 0, first.offset) + 1)
    return prologue


def _declared(name: str, named: str, *, line: int | None) -> InputError:
    return InputError.at(
        name,
        f"the document type declares {named}; declarations in a document type are refused "
        "(an attribute default would give elements attributes the file does not write, to "
        "some tools and not to others; a robot description needs none)",
        line=line,
        path=named,
        code="xml-dtd",
    )


def _refuse_entity_declarations(prologue: Prologue, raw: bytes, name: str) -> None:
    entities = prologue.entities
    first = entities[0]
    line = raw.count(b"\n", 0, first.offset) + 1
    external = next((e for e in entities if e.external is not None), None)
    if external is not None:
        reference = shown(external.external or "")
        what = f"external entity {shown(external.name, quoted=True)} ({reference})"
    else:
        names = ", ".join(shown(e.name, quoted=True) for e in entities[:3])
        more = " or more" if prologue.stop is Stop.ENTITIES else ""
        what = f"{len(entities)}{more} entity declaration(s) ({names})"
    raise InputError.at(
        name,
        f"the document type declares {what}; entity declarations are "
        "refused (entity expansion and external references are never "
        "needed in a robot description)",
        line=line,
        path=f"<!ENTITY {shown(first.name)}>",
        code="xml-entity",
    )


def _refuse_entities(root: etree._Element, raw: bytes, name: str, prologue: Prologue) -> None:
    """Refuse a DOCTYPE that declares entities, one the prologue scan could not read through
    (a UTF-16 document, say: its declarations were not seen), and any entity reference left
    in the tree."""
    from lxml import etree

    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None and prologue.stop is not Stop.ROOT:
        raise InputError.at(
            name,
            "a document type the prologue scan could not read (is the file UTF-8?); refused: "
            "what it declares cannot be checked, and a robot description needs none",
            line=_line_of(raw, b"<!DOCTYPE"),
            code="xml-dtd",
        )
    if dtd is not None:
        entities = list(dtd.iterentities())  # type: ignore[attr-defined]  # not in lxml-stubs
        if entities:
            first = entities[0]
            external = [e.name for e in entities if e.system_url]
            kind = (
                f"external entity {external[0]!r} ({_system_url(entities, external[0])})"
                if external
                else f"{len(entities)} entity declaration(s) "
                f"({', '.join(repr(e.name) for e in entities[:3])})"
            )
            raise InputError.at(
                name,
                f"the document type declares {kind}; entity "
                "declarations are refused (entity expansion and "
                "external references are never needed in a robot "
                "description)",
                line=_line_of(raw, b"<!ENTITY"),
                path=f"<!ENTITY {first.name}>",
                code="xml-entity",
            )
    for node in root.iter(etree.Entity):
        raise InputError.at(
            name,
            f"entity reference {node.text!r} refused (entities are not expanded)",
            line=line_of(node),
            code="xml-entity",
        )


def _system_url(entities: list[etree._DTDEntityDecl], wanted: str) -> str:
    return next((str(e.system_url) for e in entities if e.name == wanted), "")


def _line_of(raw: bytes, needle: bytes) -> int | None:
    position = raw.find(needle)
    return None if position < 0 else raw.count(b"\n", 0, position) + 1


def _parser(*, recover: bool = False) -> etree.XMLParser:
    """lxml's parser with everything that reaches outside the document off: no entities, no
    DTD, no network, no huge trees; comments and processing instructions dropped."""
    from lxml import etree

    return etree.XMLParser(
        resolve_entities=False,
        no_network=True,
        load_dtd=False,
        dtd_validation=False,
        huge_tree=False,
        remove_comments=True,
        remove_pis=True,
        recover=recover,
    )
