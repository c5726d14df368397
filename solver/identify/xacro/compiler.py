"""Compiling xacro to URDF text, only when the user trusts the file, in a limited child process.

xacro evaluates ``${...}`` expressions as Python, and that namespace can be escaped: compiling a
xacro file runs its author's code. So nothing compiles xacro unless the user asked for it
(``--trust-xacro``, ``trust_xacro=True``); a ``.urdf`` file or a ``robot_description`` is always
read as URDF, never compiled. When trusted, :func:`compile_xacro` runs
:mod:`solver.identify.xacro.child` in a fresh interpreter with an empty environment, CPU-time,
memory and no-file-write limits, kernel fences (:mod:`solver.identify.xacro.confine`: read-only
access to its packages, no sockets, no processes) and a wall-clock timeout
(:class:`XacroLimits`), and reads back at most the size cap. A hostile or exponential macro
ends with a located error.

``$(find pkg)`` resolves through the package map of :mod:`solver.identify.xacro.packages`; a
package found nowhere is a located error naming it and where it was looked for. The child may
read files only inside the description's own folder (or its package) and the packages of that
map; the environment is never read (``$(env NAME)`` is the xacro argument ``NAME`` or
refused, ``$(optenv NAME DEFAULT)`` that argument or its default). Mesh ``package://``
references are left as written: identification never opens a mesh.

Not here: reading the compiled URDF (:mod:`solver.identify.readers.urdf`); the child's fence
(:mod:`solver.identify.xacro.child`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import solver
from solver.errors import InputError
from solver.identify.limited import run_limited
from solver.identify.readers.safexml import MAX_XML_BYTES, parse_xml, read_bytes
from solver.identify.xacro.packages import PACKAGE_PATH_ENV, find_packages, own_package_root

__all__ = ["CompiledXacro", "XacroLimits", "compile_xacro"]

_MISSING = re.compile(r"Package not found: ([\w\-]+)")
# The child's answer: the URDF text (at most MAX_XML_BYTES, JSON-escaped) and its warnings.
_ANSWER_BYTES = 2 * MAX_XML_BYTES + 65536


@dataclass(frozen=True, slots=True)
class XacroLimits:
    """What one trusted xacro compilation may use; past any of them it is a located error."""

    cpu_seconds: int = 10
    memory_bytes: int = 1024 * 2**20
    wall_seconds: float = 20.0


@dataclass(frozen=True, slots=True)
class CompiledXacro:
    text: str
    warnings: tuple[str, ...] = ()


def compile_xacro(
    path: str | Path,
    *,
    args: Mapping[str, str] | None = None,
    package_path: Sequence[str | Path] = (),
    display: str | None = None,
    limits: XacroLimits = XacroLimits(),
) -> CompiledXacro:
    """Compile the xacro file ``path`` in a limited child process; :class:`InputError` if not."""
    name = display if display is not None else str(path)
    source = Path(path).resolve()
    data = read_bytes(path, display=name)
    # Refuse entity bombs and malformed XML before xacro sees them, but read what xacro reads
    # (its minidom knows no namespace URIs: a markdown link pasted as xmlns:xacro); the child
    # warns of each file's flaws as it reads it.
    parse_xml(data, name, warnings=[])
    folders = [Path(p) for p in package_path]
    for folder in folders:
        if not folder.is_dir():
            raise InputError.at(str(folder), "package path is not a folder", code="xacro")
    packages = find_packages(source, folders)
    roots = {str(own_package_root(source))} | set(packages.values())
    request = {
        "source": str(source),
        "args": dict(args or {}),
        "packages": packages,
        "roots": sorted(roots),
        "cpu_seconds": limits.cpu_seconds,
        "memory_bytes": limits.memory_bytes,
    }
    answer = _run_child(request, name, limits)
    if not answer.get("ok"):
        raise _xacro_error(name, data, answer, folders)
    text = str(answer["text"])
    warnings = tuple(str(w) for w in answer.get("warnings", ()))
    return CompiledXacro(text, warnings)


def _run_child(request: dict[str, Any], name: str, limits: XacroLimits) -> dict[str, Any]:
    root = str(Path(solver.__file__).resolve().parent.parent)
    code = (
        "import sys; sys.path[:0] = sys.argv[1:]; "
        "from solver.identify.xacro.child import main; main()"
    )
    finished = run_limited(
        ["-c", code, root, *_site_paths(name)],
        request,
        wall_seconds=limits.wall_seconds,
        answer_bytes=_ANSWER_BYTES,
        cwd=root,
    )
    if finished.stopped is not None:
        raise InputError.at(
            name,
            f"xacro did not finish within {limits.wall_seconds:g} s; stopped",
            code="xacro-limit",
        )
    if finished.oversized:
        raise InputError.at(
            name, f"xacro output is larger than {MAX_XML_BYTES} bytes; refused", code="too-large"
        )
    if finished.returncode != 0 or finished.answer is None:
        reason = {
            24: f"used more than {limits.cpu_seconds} s of CPU",
            9: f"used more than {limits.cpu_seconds} s of CPU or "
            f"{limits.memory_bytes // 2**20} MiB of memory",
        }.get(
            finished.signal or 0,
            f"ended without an answer (exit status {finished.returncode})",
        )
        raise InputError.at(name, f"xacro {reason}; stopped", code="xacro-limit")
    return finished.answer


def _site_paths(name: str) -> list[str]:
    # -S leaves site-packages out (no .pth files run); the child needs xacro, PyYAML and lxml.
    try:
        import xacro
    except ImportError:
        raise InputError.at(
            name,
            "xacro support is not installed: pip install 'teleop-ui[xacro]'",
            code="missing-extra",
        ) from None
    import lxml
    import yaml

    modules = (xacro, yaml, lxml)
    return sorted({str(Path(m.__file__ or "").resolve().parent.parent) for m in modules})


def _xacro_error(
    name: str, data: bytes, answer: Mapping[str, Any], folders: list[Path]
) -> InputError:
    message = str(answer.get("message") or "xacro failed")
    code = str(answer.get("code") or "xacro")
    missing = _MISSING.search(message)
    if missing:
        package = missing.group(1)
        needle = f"$(find {package})".encode()
        position = data.find(needle)
        if position < 0:
            position = data.find(f"package://{package}".encode())
        line = None if position < 0 else data.count(b"\n", 0, position) + 1
        where = ", ".join(str(f) for f in folders) or "(no --package-path given)"
        return InputError.at(
            name,
            f"xacro: ROS package {package!r} not found; looked in "
            f"--package-path / ${PACKAGE_PATH_ENV}: {where}; the "
            f"package.xml folders above {name}; and $ROS_PACKAGE_PATH",
            line=line,
            path=f"$(find {package})",
            code="xacro-package",
        )
    file = answer.get("file")
    line = answer.get("line")
    where = str(file) if isinstance(file, str) and file else name
    text = message if message.startswith("xacro") else f"xacro: {message}"
    return InputError.at(where, text, line=line if isinstance(line, int) else None, code=code)
