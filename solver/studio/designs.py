"""Designs kept as files: the folder ``teleop-ui studio --designs DIR`` names, and what is in it.

A design is a team file (the format the command line reads), ``NAME.yaml`` in that folder. Its
rule set is named so that it solves on another machine: nothing for the article's rules, a
shipped set by its name (``rules: extended``), the rule set given at start by its path relative
to the folder. The folder is the user's, but what lies in it may not be: every name in it is a
stranger's, and so is every file's content.

- **Names.** A design's name is at most 100 letters, digits, spaces, ``.``, ``_`` or ``-``,
  not starting with a dot or a space; its file is ``NAME.yaml``. A name the studio would not
  make (a line break, a path, a control character) is listed as a refusal, escaped; it is
  never opened.
- **Nothing but the folder.** The folder is opened once per request and every file in it
  through that open folder (``dir_fd``) with ``O_NOFOLLOW``: no link is followed, whether the
  design itself or a folder's name; a design must be a regular file of at most the bounded
  readers' 16 MB, read through the open descriptor. Saving is :func:`solver.files.atomic.
  write_atomic` (a temporary beside it, renamed; never through a link); deleting removes only
  a regular file, never through a link.
- **Its rule set.** A design's ``rules:`` line must name what the studio may read: a shipped
  rule set by its name (not by where it is installed), or the rule set given at start (by its
  path from the folder, as the OS resolves the folder). Anything else (``/etc/passwd``,
  ``../other.yaml``) is a located refusal at that line, and that path is not opened.
- **Bounded.** At most :data:`MAX_DESIGNS` entries of the folder are listed (the first by
  name; more are said to be left out).

Not here: HTTP and the pages (:mod:`solver.studio.pages`), the answers
(:mod:`solver.studio.service`).
"""

from __future__ import annotations

import errno
import os
import re
import stat
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from solver.errors import InputError
from solver.files.atomic import remove_output, write_atomic
from solver.files.yamlio import MAX_FILE_BYTES, Document, parse_document
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "DESIGNS_FILE",
    "MAX_DESIGNS",
    "Designs",
    "Entry",
    "design_name",
]

# Folder entries listed at most (the first by name).
MAX_DESIGNS = 1000
# How a message names the design folder (never its path: the page is the user's).
DESIGNS_FILE = "<designs>"
SUFFIX = ".yaml"
_NAME = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9 ._-]{0,99}")
_FOLDER_FLAGS = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | getattr(os, "O_CLOEXEC", 0)
_FILE_FLAGS = (
    os.O_RDONLY
    | getattr(os, "O_NOFOLLOW", 0)
    | getattr(os, "O_NONBLOCK", 0)
    | getattr(os, "O_CLOEXEC", 0)
)


def design_name(text: str) -> str:
    """``text`` as a design's name, or a located :class:`InputError` saying what a name may
    hold."""
    name = text.removesuffix(SUFFIX)
    if _NAME.fullmatch(name) is None or name != name.rstrip():
        raise InputError.at(
            DESIGNS_FILE,
            f"{shown(text, quoted=True)} is no design name: at most 100 letters, digits, "
            "spaces, '.', '_' or '-', not starting with a dot or a space",
            path="name",
            code="invalid",
        )
    return name


@dataclass(frozen=True)
class Entry:
    """One entry of the design folder: a design's name, or a refusal (``problem``) with the
    entry's name escaped."""

    name: str
    problem: str = ""


class Designs:
    """The design folder given at start (``--designs DIR``)."""

    def __init__(self, folder: Path) -> None:
        if not os.path.isdir(folder):
            raise InputError.at(
                shown(str(folder), limit=SHOWN_FILE_NAME_CHARS),
                "--designs needs a folder (make it first)",
            )
        self.folder = folder

    @contextmanager
    def _opened(self) -> Iterator[int]:
        try:
            descriptor = os.open(self.folder, _FOLDER_FLAGS)
        except OSError as error:
            raise InputError.at(
                DESIGNS_FILE, f"the design folder cannot be opened: {error.strerror}"
            ) from None
        try:
            yield descriptor
        finally:
            os.close(descriptor)

    def entries(self) -> tuple[list[Entry], int]:
        """The folder's ``.yaml`` entries by name (at most :data:`MAX_DESIGNS`), each a design
        or a refusal, and how many more were left out."""
        with self._opened() as folder:
            names = sorted(n for n in os.listdir(folder) if n.endswith(SUFFIX))
            found = []
            for name in names[:MAX_DESIGNS]:
                found.append(_entry(folder, name))
        return found, max(0, len(names) - MAX_DESIGNS)

    def read(self, name: str) -> Document:
        """Design ``name`` as a YAML document (located errors: no such design, a link, not a
        regular file, too large, not YAML)."""
        name = design_name(name)
        file = name + SUFFIX
        with self._opened() as folder:
            text = _read(folder, file)
        return parse_document(text, file)

    def save(self, name: str, text: str) -> str:
        """Write design ``name`` (replacing one of that name); its file name."""
        name = design_name(name)
        write_atomic(self.folder / (name + SUFFIX), text, within=self.folder)
        return name + SUFFIX

    def delete(self, name: str) -> None:
        """Remove design ``name`` (a regular file only, never through a link)."""
        name = design_name(name)
        if not remove_output(self.folder / (name + SUFFIX), within=self.folder):
            raise InputError.at(
                name + SUFFIX, "no such design (or not a regular file: not removed)"
            )


def _entry(folder: int, name: str) -> Entry:
    try:
        design = design_name(name)
    except InputError:
        return Entry(shown(name), "not a name the studio gives a design; not opened")
    try:
        mode = os.stat(name, dir_fd=folder, follow_symlinks=False).st_mode
    except OSError as error:
        return Entry(design, f"cannot be read: {error.strerror}")
    if stat.S_ISLNK(mode):
        return Entry(design, "a link; a design is never read through a link")
    if not stat.S_ISREG(mode):
        return Entry(design, "not a regular file")
    return Entry(design)


def _read(folder: int, file: str) -> str:
    try:
        descriptor = os.open(file, _FILE_FLAGS, dir_fd=folder)
    except OSError as error:
        reasons = {
            errno.ELOOP: "a link; a design is never read through a link",  # O_NOFOLLOW
            errno.ENOENT: "no such file in the design folder",
        }
        reason = reasons.get(error.errno or 0, error.strerror or "cannot be opened")
        raise InputError.at(file, f"no design: {reason}") from None
    try:
        details = os.fstat(descriptor)
        if not stat.S_ISREG(details.st_mode):
            raise InputError.at(file, "no design: not a regular file")
        chunks: list[bytes] = []
        size = 0
        while size <= MAX_FILE_BYTES:
            chunk = os.read(descriptor, min(1 << 20, MAX_FILE_BYTES + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    finally:
        os.close(descriptor)
    if size > MAX_FILE_BYTES:
        raise InputError.at(
            file, f"no design: larger than {MAX_FILE_BYTES} bytes", code="too-large"
        )
    try:
        return b"".join(chunks).decode("utf-8")
    except UnicodeDecodeError as error:
        raise InputError.at(file, f"no design: not UTF-8 text (byte {error.start})") from None
