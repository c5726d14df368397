"""Where ``$(find pkg)`` leads: ROS packages found with no ROS install and no rospkg.

The ``package.xml`` folders above the xacro file (and their sibling packages), then the folders
given as ``package_path`` (``--package-path``, or ``TELEOP_UI_PACKAGE_PATH`` joined with
``:``), then ``ROS_PACKAGE_PATH``; the first found wins, as ROS's own lookup does. The search is
bounded (:data:`_MAX_FOLDERS` folders, :data:`_MAX_DEPTH` levels), follows no symlink and reads
each ``package.xml`` through the bounded reader. The folders found are also the only ones the
xacro child may read (:mod:`solver.identify.xacro.child`).

Not here: compiling (:mod:`solver.identify.xacro.compiler`).
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from solver.errors import InputError
from solver.identify.readers.safexml import read_bytes

__all__ = [
    "PACKAGE_PATH_ENV",
    "find_packages",
    "own_package_root",
    "package_path_from_env",
]

PACKAGE_PATH_ENV = "TELEOP_UI_PACKAGE_PATH"
_PACKAGE_NAME = re.compile(rb"<name>\s*([A-Za-z0-9_\-]+)\s*</name>")
# A package search stops after this many folders, so a package path of / ends quickly.
_MAX_FOLDERS = 20_000
_MAX_DEPTH = 6


def package_path_from_env(environ: Mapping[str, str] | None = None) -> tuple[Path, ...]:
    """The folders in ``TELEOP_UI_PACKAGE_PATH`` (``:``-separated)."""
    value = (os.environ if environ is None else environ).get(PACKAGE_PATH_ENV, "")
    return tuple(Path(p) for p in value.split(os.pathsep) if p)


def own_package_root(source: Path) -> Path:
    """The folder of the package holding ``source`` (nearest ``package.xml`` above), or its own."""
    for folder in source.parents:
        if (folder / "package.xml").is_file():
            return folder
    return source.parent


def find_packages(
    source: Path, package_path: Sequence[Path] = (), environ: Mapping[str, str] | None = None
) -> dict[str, str]:
    """Package name -> folder: above ``source`` and beside it, then ``package_path``, then
    ``ROS_PACKAGE_PATH``; the first found wins, as ROS's own lookup does."""
    env = os.environ if environ is None else environ
    found: dict[str, str] = {}
    budget = [_MAX_FOLDERS]
    for folder in source.parents:
        if (folder / "package.xml").is_file():
            _scan(folder.parent, found, budget, depth=2)  # the package and its siblings
            break
    ros = [Path(p) for p in env.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    for folder in [*package_path, *ros]:
        _scan(folder, found, budget, depth=_MAX_DEPTH)
    return found


def _scan(folder: Path, found: dict[str, str], budget: list[int], depth: int) -> None:
    if budget[0] <= 0 or depth < 0:
        return
    budget[0] -= 1
    manifest = folder / "package.xml"
    if manifest.is_file():
        try:
            head = read_bytes(manifest, limit=1024 * 1024)
        except InputError:
            return
        named = _PACKAGE_NAME.search(head)
        if named is not None:
            found.setdefault(named.group(1).decode(), str(folder.resolve()))
        return  # packages do not nest
    try:
        children = sorted(
            p
            for p in folder.iterdir()
            if p.is_dir() and not p.is_symlink() and not p.name.startswith(".")
        )
    except OSError:
        return
    for child in children:
        _scan(child, found, budget, depth - 1)
