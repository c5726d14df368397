"""Compiling xacro to URDF text with ``xacrodoc`` (the ``xacro`` library, no ROS install needed).

``$(find pkg)`` and ``package://`` resolve through, in order: the folders given as
``package_path`` (``--package-path``, or ``TELEOP_UI_PACKAGE_PATH`` joined with ``:``), the
``package.xml`` folders above the xacro file itself, and ``ROS_PACKAGE_PATH`` (read by rospkg).
A package found nowhere is a located error naming it and where it was looked for. Mesh
``package://`` references are left as written: identification never opens a mesh.

Relative ``<xacro:include filename="...">`` paths resolve against the including file, as the
``xacro`` command does. Every file xacro opens is first read with the size cap and checked by
:mod:`solver.identify.safexml` (xacro itself parses with the standard library), so an include
cannot smuggle in an entity bomb or a 100 MB file.

xacro keeps its state in module globals and prints warnings to stderr; compilation therefore
runs under a lock with stderr captured, and the warnings are returned to the caller.
xacro evaluates ``${...}`` expressions (with builtins removed): compile only xacro you would
run with the ``xacro`` command; identification of untrusted robots should use plain URDF.

Not here: reading the compiled URDF (:mod:`solver.identify.urdf`).
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import threading
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from solver.errors import InputError
from solver.identify.safexml import MAX_XML_BYTES, parse_xml, read_bytes

__all__ = ["PACKAGE_PATH_ENV", "CompiledXacro", "compile_xacro", "is_xacro",
           "package_path_from_env"]

PACKAGE_PATH_ENV = "TELEOP_UI_PACKAGE_PATH"
_LOCK = threading.Lock()
_MISSING = re.compile(r"Package not found: ([\w\-]+)")


@dataclass(frozen=True, slots=True)
class CompiledXacro:
    text: str
    warnings: tuple[str, ...] = ()


def package_path_from_env(environ: Mapping[str, str] | None = None) -> tuple[Path, ...]:
    """The folders in ``TELEOP_UI_PACKAGE_PATH`` (``:``-separated)."""
    value = (os.environ if environ is None else environ).get(PACKAGE_PATH_ENV, "")
    return tuple(Path(p) for p in value.split(os.pathsep) if p)


def is_xacro(path: str | Path, data: bytes) -> bool:
    """A ``.xacro`` file, or XML that declares the xacro namespace."""
    return str(path).endswith(".xacro") or b"xmlns:xacro" in data[:65536]


def compile_xacro(path: str | Path, *, args: Mapping[str, str] | None = None,
                  package_path: Sequence[str | Path] = (), display: str | None = None
                  ) -> CompiledXacro:
    """Compile the xacro file ``path`` to URDF text; :class:`InputError` on any problem."""
    name = display if display is not None else str(path)
    source = Path(path).resolve()
    data = read_bytes(path, display=name)
    parse_xml(data, name)  # refuse entity bombs and malformed XML before xacro sees them
    import xacro
    from xacrodoc import XacroDoc, packages

    folders = [Path(p) for p in package_path]
    for folder in folders:
        if not folder.is_dir():
            raise InputError.at(str(folder), "package path is not a folder", code="xacro")
    captured = io.StringIO()
    with _LOCK, _guarded_parse(xacro), contextlib.redirect_stderr(captured):
        packages.reset()
        packages.walk_up_from(source)
        if folders:
            packages.look_in([str(f) for f in folders], priority=0)
        xacro.init_stacks(str(source))
        try:
            document = XacroDoc.from_string(data.decode("utf-8"), subargs=dict(args or {}),
                                            resolve_packages=False, rootdir=source.parent)
            text = document.dom.toxml()
        except InputError:
            raise
        except Exception as error:
            # xacro wraps some errors in XacroException and lets others through (expat's
            # ExpatError, NameError from ${...}, xacrodoc's PackageNotFoundError, ...): each
            # is a problem with the user's file, reported with its message.
            raise _xacro_error(name, data, error, folders) from None
        finally:
            xacro.init_stacks(None)
    if len(text.encode("utf-8")) > MAX_XML_BYTES:
        raise InputError.at(name, f"xacro output is larger than {MAX_XML_BYTES} bytes; refused",
                            code="too-large")
    warnings = tuple(line.strip() for line in captured.getvalue().splitlines() if line.strip())
    return CompiledXacro(text, warnings)


def _xacro_error(name: str, data: bytes, error: BaseException, folders: list[Path]
                 ) -> InputError:
    message = str(error).strip() or type(error).__name__
    missing = _MISSING.search(message)
    if missing:
        package = missing.group(1)
        needle = f"$(find {package})".encode()
        position = data.find(needle)
        if position < 0:
            position = data.find(f"package://{package}".encode())
        line = None if position < 0 else data.count(b"\n", 0, position) + 1
        where = ", ".join(str(f) for f in folders) or "(no --package-path given)"
        return InputError.at(name, f"xacro: ROS package {package!r} not found; looked in "
                                   f"--package-path / ${PACKAGE_PATH_ENV}: {where}; the "
                                   f"package.xml folders above {name}; and $ROS_PACKAGE_PATH",
                             line=line, path=f"$(find {package})", code="xacro-package")
    if isinstance(error, RecursionError):
        message = "macro recursion too deep"
    return InputError.at(name, f"xacro: {message}", code="xacro")


@contextlib.contextmanager
def _guarded_parse(xacro: Any) -> Iterator[None]:
    """Every file xacro opens passes the size cap and the safe-XML check first."""
    original = xacro.parse

    def guarded(inp: Any, filename: str | None = None) -> Any:
        if inp is None and filename is not None:
            target = os.path.join(xacro.root_dir, filename)
            data = read_bytes(target, display=filename)
            parse_xml(data, filename)
            return original(data.decode("utf-8"))
        return original(inp, filename)

    xacro.parse = guarded
    try:
        yield
    finally:
        xacro.parse = original
