"""Parsing untrusted XML (URDF, SRDF, xacro) safely, with located errors.

Robot descriptions come from anywhere: a download, a ROS master, a colleague's folder. They are
parsed with lxml set up so that nothing in a file can reach outside it or blow up in memory:
entity substitution, DTD loading and network access are off, libxml2's "huge tree" mode is off
(it caps depth and text node size), and files are read with a size cap before parsing, so a
100 MB file or ``/dev/zero`` is refused after reading at most :data:`MAX_XML_BYTES` + 1 bytes.
A document type declaration that declares entities (the shape of "billion laughs", quadratic
blowup and external-entity attacks) is refused outright: URDF and SRDF never need one.

Every problem is an :class:`~solver.errors.InputError` naming the file and, where libxml2 knows
it, the line and column.

Not here: what the elements mean (:mod:`solver.identify.urdf`, :mod:`solver.identify.srdf`).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

from solver.errors import InputError
from solver.inputfile import read_bounded

if TYPE_CHECKING:
    from lxml import etree

__all__ = ["MAX_XML_BYTES", "line_of", "parse_xml", "read_bytes", "read_xml"]

# The largest description read. Real URDFs are kilobytes (the largest of 31 public robots
# measured is 91 KB); generated ones with inline data stay well under this.
MAX_XML_BYTES = 16 * 1024 * 1024


def read_bytes(path: str | Path, *, display: str | None = None,
               limit: int = MAX_XML_BYTES) -> bytes:
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


def parse_xml(data: bytes | str, name: str = "<string>") -> etree._Element:
    """Safely parse XML text or bytes into its root element (see the module docstring)."""
    from lxml import etree

    raw = data.encode("utf-8") if isinstance(data, str) else data
    if len(raw) > MAX_XML_BYTES:
        raise InputError.at(name, f"document is larger than {MAX_XML_BYTES} bytes; refused",
                            code="too-large")
    if not raw.strip():
        raise InputError.at(name, "empty file: expected an XML document", code="xml")
    _refuse_declared_entities(raw, name)
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                             dtd_validation=False, huge_tree=False, remove_comments=True,
                             remove_pis=True)
    try:
        root = etree.fromstring(raw, parser)
    except etree.XMLSyntaxError as error:
        line, column = error.position if error.position else (None, None)
        message = str(error.msg or error).split(f", line {line}")[0]
        raise InputError.at(name, f"malformed XML: {message}", line=line or None,
                            column=column or None, code="xml") from None
    except ValueError as error:  # lxml refuses, e.g., str input carrying an encoding declaration
        raise InputError.at(name, f"malformed XML: {error}", code="xml") from None
    _refuse_entities(root, raw, name)
    return root


_DOCTYPE_SUBSET = re.compile(rb"<!DOCTYPE[^\[>]*\[(.*?)\]\s*>", re.DOTALL)
_ENTITY = re.compile(rb"<!ENTITY\s+(%\s+)?([^\s>]+)(?:\s+(SYSTEM|PUBLIC)\s+([\"'][^\"']*[\"']))?")


def _refuse_declared_entities(raw: bytes, name: str) -> None:
    """Refuse entity declarations before libxml2 sees them, naming the first one.

    libxml2 would refuse most bombs itself, but with messages about loops or amplification;
    checking the internal subset first gives one clear message for every variant.
    """
    subset = _DOCTYPE_SUBSET.search(raw[:1024 * 1024])
    if subset is None:
        return
    entities = list(_ENTITY.finditer(subset.group(1)))
    if not entities:
        return
    first = entities[0]
    line = raw.count(b"\n", 0, subset.start(1) + first.start()) + 1
    external = next((e for e in entities if e.group(3)), None)
    if external is not None:
        what = (f"external entity {external.group(2).decode(errors='replace')!r} "
                f"({external.group(4).decode(errors='replace').strip(chr(34) + chr(39))})")
    else:
        names = ", ".join(repr(e.group(2).decode(errors="replace")) for e in entities[:3])
        what = f"{len(entities)} entity declaration(s) ({names})"
    raise InputError.at(name, f"the document type declares {what}; entity declarations are "
                              "refused (entity expansion and external references are never "
                              "needed in a robot description)", line=line,
                        path=f"<!ENTITY {first.group(2).decode(errors='replace')}>",
                        code="xml-entity")


def _refuse_entities(root: etree._Element, raw: bytes, name: str) -> None:
    """Refuse a DOCTYPE that declares entities, and any entity reference left in the tree."""
    from lxml import etree

    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None:
        entities = list(dtd.iterentities())  # type: ignore[attr-defined]  # not in lxml-stubs
        if entities:
            first = entities[0]
            external = [e.name for e in entities if e.system_url]
            kind = (f"external entity {external[0]!r} ({_system_url(entities, external[0])})"
                    if external else f"{len(entities)} entity declaration(s) "
                                     f"({', '.join(repr(e.name) for e in entities[:3])})")
            raise InputError.at(name, f"the document type declares {kind}; entity "
                                      "declarations are refused (entity expansion and "
                                      "external references are never needed in a robot "
                                      "description)", line=_line_of(raw, b"<!ENTITY"),
                                path=f"<!ENTITY {first.name}>", code="xml-entity")
    for node in root.iter(etree.Entity):
        raise InputError.at(name, f"entity reference {node.text!r} refused (entities are not "
                                  "expanded)", line=line_of(node), code="xml-entity")


def _system_url(entities: list[etree._DTDEntityDecl], wanted: str) -> str:
    return next((str(e.system_url) for e in entities if e.name == wanted), "")


def _line_of(raw: bytes, needle: bytes) -> int | None:
    position = raw.find(needle)
    return None if position < 0 else raw.count(b"\n", 0, position) + 1
