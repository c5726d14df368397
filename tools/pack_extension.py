"""Pack the follower extension (viewer/lichtblick/) into the .foxe file an operator installs in
Lichtblick: the same build gives the same bytes.

usage: python tools/pack_extension.py [OUT.foxe] [--source DIR]

Build it first (``tools/test.sh`` does): ``cd viewer/lichtblick && npm ci && npm run build``.
The default OUT is ``viewer/lichtblick/teleop-ui-follower.foxe``, the file in the repository.

A .foxe is a zip that Lichtblick's web app keeps in its IndexedDB and reads with JSZip
(v1.19.0, ``packages/suite-base/src/services/IdbExtensionLoader.ts``): ``package.json``
(required: ``name``, and a ``publisher`` or a ``@scope/`` name), ``dist/extension.js`` (the
fixed path the app loads; the desktop app loads ``main``, which must name the same file) and
``README.md`` (optional; the app shows it). The extension's panels are named
``<displayName>.<panel>`` in a layout (the ``local`` namespace's qualified name is the
``displayName``), so ``displayName`` must be a name a layout's panel id can carry: no ``!``
(``Type!id``), no space, no ``.``.

The zip holds those three files only, in name order, each stored (not compressed: the bytes
then depend on no zlib version) with the zip format's earliest date, 1980-01-01 00:00, and the
permissions 0644: two packs of one build are byte-identical, whenever and wherever they are
made. It is written atomically (a temporary file renamed into place): an operator never
installs half a file. A source that breaks a rule is refused with the file and field named,
exit status 2, nothing written.
"""

from __future__ import annotations

import argparse
import io
import json
import os
import re
import sys
import tempfile
import zipfile
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "viewer" / "lichtblick"
FOXE_NAME = "teleop-ui-follower.foxe"
# IdbExtensionLoader.ts ALLOWED_FILES, without CHANGELOG.md (the extension has none).
EXTENSION = "dist/extension.js"
FILES = ("package.json", "README.md", EXTENSION)
# The zip format's earliest date: no build time in the file.
DATE = (1980, 1, 1, 0, 0, 0)
MODE = 0o100644  # a regular file, rw-r--r--
# Larger than the extension will ever be: a runaway build is refused, not packed.
MAX_FILE_BYTES = 4 * 1024 * 1024
SCOPED = re.compile(r"^@([^/]+)/(.+)")  # IdbExtensionLoader.ts parsePackageName


class PackError(Exception):
    """A source the app would refuse, or none to pack: its file and what is wrong."""


def _read(source: Path, name: str) -> bytes:
    path = source / name
    if not path.is_file():
        hint = " (build it: cd viewer/lichtblick && npm ci && npm run build)"
        raise PackError(f"{path}: missing{hint if name == EXTENSION else ''}")
    data = path.read_bytes()
    if len(data) > MAX_FILE_BYTES:
        raise PackError(f"{path}: {len(data):,} bytes, more than {MAX_FILE_BYTES:,}")
    return data


def _text(info: dict[str, Any], key: str) -> str:
    value = info.get(key)
    return value if isinstance(value, str) else ""


def check_package(info: Any, where: Path) -> None:
    """Refuses a package.json the app would refuse, or whose panels no layout could name."""
    if not isinstance(info, dict):
        raise PackError(f"{where}: not a JSON object")
    name = _text(info, "name")
    if not name:
        raise PackError(f"{where}: name: missing (Lichtblick: 'Invalid extension: missing name')")
    scoped = SCOPED.match(name)
    publisher = info.get("publisher")  # `info.publisher ?? parsedPublisher`
    if publisher is None and scoped is not None:
        publisher = scoped.group(1)
    if not isinstance(publisher, str) or not publisher:
        raise PackError(
            f"{where}: publisher: missing, and the name has no @scope/ "
            "(Lichtblick: 'Invalid extension: missing publisher')"
        )
    display = _text(info, "displayName")
    if not display or re.search(r"[!.\s]", display):
        raise PackError(
            f"{where}: displayName: {display!r} cannot name a panel in a layout "
            "(<displayName>.<panel>!<id>: no '!', '.' or space, not empty)"
        )
    if info.get("main") not in (EXTENSION, f"./{EXTENSION}"):
        raise PackError(f"{where}: main: must be ./{EXTENSION}, the file the web app loads")


def foxe_bytes(source: Path) -> bytes:
    """The .foxe of ``source`` (see the module docstring)."""
    files = {name: _read(source, name) for name in FILES}
    try:
        info = json.loads(files["package.json"])
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise PackError(f"{source / 'package.json'}: not JSON: {error}") from None
    check_package(info, source / "package.json")
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_STORED) as archive:
        for name in sorted(files):
            entry = zipfile.ZipInfo(name, date_time=DATE)
            entry.create_system = 3  # Unix, so that the permissions below are read as such
            entry.external_attr = MODE << 16
            entry.compress_type = zipfile.ZIP_STORED
            archive.writestr(entry, files[name])
    return out.getvalue()


def write_foxe(source: Path, out: Path) -> int:
    """Writes the .foxe of ``source`` to ``out`` atomically; its size in bytes."""
    data = foxe_bytes(source)
    out.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=".", suffix=".foxe", dir=out.parent)
    try:
        with os.fdopen(handle, "wb") as file:
            file.write(data)
        os.chmod(temporary, 0o644)
        os.replace(temporary, out)
    except BaseException:
        os.unlink(temporary)
        raise
    return len(data)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("out", nargs="?", type=Path, help=f"default: viewer/lichtblick/{FOXE_NAME}")
    parser.add_argument("--source", type=Path, default=SOURCE, help="the extension's folder")
    args = parser.parse_args(argv)
    out = args.out if args.out is not None else args.source / FOXE_NAME
    try:
        size = write_foxe(args.source, out)
    except PackError as error:
        print(f"pack_extension: {error}", file=sys.stderr)
        return 2
    print(f"wrote {out} ({size:,} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
