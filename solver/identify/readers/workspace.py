"""The robot's workspace: the ROS packages around its description that use it, read as text.

A description package rarely says how its robot is commanded: a bringup package launches the
teleop node, a navigation package runs Nav2 or move_base, a MoveIt configuration plans for the
arm. Those packages sit beside the description in the workspace and name it. This module finds
them and reads their launch, configuration and script files as text; nothing in them is run,
imported or parsed as code.

* The description's *package* is the nearest folder above the file (at most
  :data:`MAX_LEVELS_UP` folders up) holding a ``package.xml``; the *workspace* is the folder
  above that package, or one the caller names.
* The workspace is walked once: symbolic links are never followed, hidden folders and the
  folders builds and tests write (``build``, ``install``, ``devel``, ``log``, ``test``, ...) are
  skipped, at most :data:`MAX_DEPTH` folders deep and :data:`MAX_ENTRIES` entries. Each file
  belongs to the nearest package above it; a file in no package is nobody's.
* The *robot's packages*: the description's and, for a package named ``ROBOT_description``,
  every package named ``ROBOT_...`` (the ROS convention: ``jackal_navigation`` is the Jackal's
  though it never names ``jackal_description``); then every package that uses one of the
  robot's (names it as a word in its ``package.xml`` or its files: a bringup that finds the
  description) and every package one of the robot's uses (a bringup that includes a navigation
  package), in at most :data:`MAX_ROUNDS` rounds. Other packages of the workspace (another
  robot's, a library's source) are not the robot's, however much navigation they hold.
* Text files (launch, YAML, XML, Python, C++: :data:`TEXT_SUFFIXES`) are read through a
  descriptor that refuses links and anything but a regular file (a FIFO or a device is
  skipped, never waited on), at most :data:`MAX_FILE_BYTES` of each, :data:`MAX_FILES` files and
  :data:`MAX_TOTAL_BYTES` in all, decoded with replacement; XML comments are removed.

Past a bound the rest is not read and one located warning says so; a workspace that cannot be
read (no such folder, no permission) is no evidence, never an error: the description is read
alone. What the files mean is :mod:`solver.identify.shipped`'s.
"""

from __future__ import annotations

import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from solver.errors import Fault, Location

__all__ = [
    "MAX_DEPTH",
    "MAX_ENTRIES",
    "MAX_FILES",
    "MAX_FILE_BYTES",
    "MAX_LEVELS_UP",
    "MAX_ROUNDS",
    "MAX_TOTAL_BYTES",
    "TEXT_SUFFIXES",
    "ShippedFile",
    "Workspace",
    "description_package",
    "read_workspace",
]

# Folders above the description file searched for its package.xml (pkg/urdf/robots/x.urdf).
MAX_LEVELS_UP = 4
# Folders below the workspace walked, entries listed, files and bytes read.
MAX_DEPTH = 10
MAX_ENTRIES = 50_000
MAX_FILES = 4_000
MAX_FILE_BYTES = 256 * 1024
MAX_TOTAL_BYTES = 48 * 1024 * 1024
# Rounds of "uses or is used by" from the description's package.
MAX_ROUNDS = 3
# A package.xml is read up to this size (its name and dependencies are at the top).
MAX_MANIFEST_BYTES = 64 * 1024

TEXT_SUFFIXES = (".launch", ".xml", ".yaml", ".yml", ".py", ".cpp")
# Folders no package ships controls in: builds, installs, logs, caches and tests.
SKIPPED_FOLDERS = frozenset(
    {"build", "devel", "install", "log", "logs", "node_modules", "__pycache__", "test", "tests"}
)
_NAME = re.compile(r"<name>\s*([A-Za-z0-9_.-]{1,200})\s*</name>")
_WORD = re.compile(r"[A-Za-z0-9_]+")


@dataclass(frozen=True, slots=True)
class ShippedFile:
    """One text file of one of the robot's packages; ``path`` is relative to the workspace."""

    package: str
    path: str
    text: str


@dataclass(frozen=True, slots=True)
class Workspace:
    """The robot's packages (the description's first) and their text files."""

    root: str
    package: str
    packages: tuple[str, ...]
    files: tuple[ShippedFile, ...]
    warnings: tuple[Fault, ...] = ()


def description_package(path: str | Path) -> Path | None:
    """The folder of the ROS package holding ``path``: the nearest folder above it (at most
    :data:`MAX_LEVELS_UP` up) with a ``package.xml`` that is a regular file; else None."""
    here = Path(os.path.abspath(path)).parent
    for _ in range(MAX_LEVELS_UP):
        manifest = here / "package.xml"
        try:
            if stat.S_ISREG(os.lstat(manifest).st_mode):
                return here
        except OSError:
            pass
        if here.parent == here:
            return None
        here = here.parent
    return None


@dataclass(slots=True)
class _Package:
    folder: str
    name: str
    words: set[str]
    files: list[ShippedFile]


@dataclass(slots=True)
class _Budget:
    entries: int = 0
    files: int = 0
    total: int = 0
    stopped: str | None = None

    def stop(self, why: str) -> None:
        self.stopped = self.stopped or why


def read_workspace(package: str | Path, root: str | Path | None = None) -> Workspace | None:
    """The robot's packages in the workspace around the description's ``package`` folder
    (``root``: the workspace; default: the folder above the package). None when the package
    has no readable ``package.xml`` (no package, no evidence)."""
    folder = os.path.abspath(package)
    top = os.path.abspath(root) if root is not None else os.path.dirname(folder)
    own = _manifest_name(os.path.join(folder, "package.xml"))
    if own is None:
        return None
    budget = _Budget()
    # The description's own package first: the bounds never leave it unread.
    packages = _walk(folder, budget, top)
    if folder not in packages:
        return None
    packages.update(_walk(top, budget, top, skip=folder))
    ours = _robots_packages(packages, folder)
    files = tuple(f for name in ours for f in _by_name(packages, name).files)
    warnings: tuple[Fault, ...] = ()
    if budget.stopped is not None:
        warnings = (
            Fault(
                Location(file=top),
                f"workspace: {budget.stopped}; the rest of it is not read "
                f"(docs/identify.md, The robot's packages)",
                "too-large",
            ),
        )
    return Workspace(top, own, ours, files, warnings)


def _by_name(packages: dict[str, _Package], name: str) -> _Package:
    return next(p for p in packages.values() if p.name == name)


def _robots_packages(packages: dict[str, _Package], folder: str) -> tuple[str, ...]:
    """The description's package and the packages named for the same robot, then those that
    use one of the robot's or that one of the robot's uses, round by round (names compared as
    words)."""
    own = packages[folder]
    stem = _robot_stem(own.name)
    ours = [own]
    if stem is not None:
        ours += sorted(
            (p for p in packages.values() if p is not own and p.name.startswith(stem)),
            key=lambda p: p.folder,
        )
    for _ in range(MAX_ROUNDS):
        names = {p.name for p in ours}
        words = set().union(*(p.words for p in ours))
        added = [
            p
            for p in packages.values()
            if p not in ours and (p.name in words or not names.isdisjoint(p.words))
        ]
        if not added:
            break
        ours += sorted(added, key=lambda p: p.folder)
    return tuple(dict.fromkeys(p.name for p in ours))


def _robot_stem(name: str) -> str | None:
    """``jackal_`` for ``jackal_description``: the prefix of the packages a robot's authors
    name for it (``jackal_navigation``, ``jackal_bringup``), the ROS convention; None for a
    package not named ``ROBOT_description(s)``."""
    for suffix in ("_descriptions", "_description"):
        if name.endswith(suffix) and len(name) > len(suffix):
            return name[: -len(suffix)] + "_"
    return None


def _walk(start: str, budget: _Budget, top: str, skip: str | None = None) -> dict[str, _Package]:
    """Every package under ``start`` (by folder) with its words and text files (paths shown
    from ``top``); a package owns the folders below it (links not followed, skipped folders
    and ``skip`` left out)."""
    packages: dict[str, _Package] = {}
    stack: list[tuple[str, int, _Package | None]] = [(start, 0, None)]
    while stack and budget.stopped is None:
        folder, level, owner = stack.pop()
        if folder == skip:
            continue
        files, subfolders = _list(folder, budget)
        if "package.xml" in files:
            name = _manifest_name(os.path.join(folder, "package.xml"))
            if name is not None:
                owner = packages[folder] = _Package(folder, name, set(), [])
                owner.words.update(_WORD.findall(_read(os.path.join(folder, "package.xml"))))
        if owner is not None:
            for name in sorted(files):
                if name.endswith(TEXT_SUFFIXES) and name != "package.xml":
                    _add_file(owner, folder, name, top, budget)
        if level < MAX_DEPTH:
            stack += [(os.path.join(folder, n), level + 1, owner) for n in sorted(subfolders)[::-1]]
    return packages


def _list(folder: str, budget: _Budget) -> tuple[list[str], list[str]]:
    files: list[str] = []
    subfolders: list[str] = []
    try:
        with os.scandir(folder) as entries:
            for entry in entries:
                budget.entries += 1
                if budget.entries > MAX_ENTRIES:
                    budget.stop(f"more than {MAX_ENTRIES} entries")
                    break
                if entry.name.startswith(".") or entry.is_symlink():
                    continue
                if entry.is_dir(follow_symlinks=False):
                    if entry.name not in SKIPPED_FOLDERS:
                        subfolders.append(entry.name)
                elif entry.is_file(follow_symlinks=False):
                    files.append(entry.name)
    except OSError:
        pass
    return files, subfolders


def _add_file(owner: _Package, folder: str, name: str, top: str, budget: _Budget) -> None:
    if budget.files >= MAX_FILES:
        budget.stop(f"more than {MAX_FILES} files")
        return
    if budget.total >= MAX_TOTAL_BYTES:
        budget.stop(f"more than {MAX_TOTAL_BYTES // (1024 * 1024)} MiB of files")
        return
    path = os.path.join(folder, name)
    text = _read(path)
    budget.files += 1
    budget.total += len(text)
    if name.endswith((".launch", ".xml")):
        text = uncommented(text)
    owner.words.update(_WORD.findall(text))
    owner.files.append(ShippedFile(owner.name, os.path.relpath(path, top), text))


def _manifest_name(path: str) -> str | None:
    found = _NAME.search(_read(path, MAX_MANIFEST_BYTES))
    return found.group(1) if found else None


def _read(path: str, limit: int | None = None) -> str:
    """At most ``limit`` bytes of the regular file ``path`` as text; links, FIFOs, devices
    and unreadable files are empty (opened without following a link, never blocking)."""
    flags = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
    try:
        descriptor = os.open(path, flags)
    except OSError:
        return ""
    try:
        if not stat.S_ISREG(os.fstat(descriptor).st_mode):
            return ""
        data = os.read(descriptor, MAX_FILE_BYTES if limit is None else limit)
    except OSError:
        return ""
    finally:
        os.close(descriptor)
    return data.decode("utf-8", errors="replace")


def uncommented(text: str) -> str:
    """``text`` without XML comments, in one pass (an unclosed comment runs to the end)."""
    kept: list[str] = []
    start = 0
    while True:
        opening = text.find("<!--", start)
        if opening < 0:
            kept.append(text[start:])
            return "".join(kept)
        kept.append(text[start:opening])
        closing = text.find("-->", opening + 4)
        if closing < 0:
            return "".join(kept)
        start = closing + 3
