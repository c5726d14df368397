"""Reading input files with a size limit, and every failure as a located error.

Every file a command reads (rule sets, teams, profiles, URDF, SRDF, topic lists) goes through
here: only a regular file is read, and at most ``limit`` bytes of it; a missing, unreadable,
oversized, binary or non-UTF-8 file, and anything that is not a regular file, is an
:class:`~solver.errors.InputError` naming it.

Not a regular file: a directory, a named pipe (and so ``/dev/stdin`` or ``<(...)`` when they are
pipes), a terminal or other character device (``/dev/zero``, ``/dev/tty``), a block device, a
socket. Opening a pipe waits for a writer and reading it waits for data, with no end a size
limit can bring; opening a device can do things of its own. The kind is looked at before
opening, and again on what was opened (the name may lead elsewhere by then), which is opened
without waiting (``O_NONBLOCK``).

Not here: parsing what was read (:mod:`solver.files.yamlio`,
:mod:`solver.identify.readers.safexml`).
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from solver.errors import InputError
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = ["decode_text", "read_bounded", "read_text", "sha256_bounded", "sha256_hex"]


def _shown_name(path: str | Path, display: str | None) -> str:
    # A file name comes from the user or from a file (``rules: ...``): shown escaped and cut.
    return shown(display if display is not None else str(path), limit=SHOWN_FILE_NAME_CHARS)


def sha256_bounded(path: str | Path, *, limit: int) -> str | None:
    """The SHA-256 of ``path`` read through :func:`read_bounded`; ``None`` when it cannot be
    read or is larger than ``limit`` (an up-to-date check then says "not up to date" and the
    solve that follows reports the located error)."""
    try:
        return sha256_hex(read_bounded(path, limit=limit))
    except InputError:
        return None


def sha256_hex(data: bytes) -> str:
    """The SHA-256 of ``data``, in hexadecimal."""
    import hashlib  # only `batch` digests files; loading OpenSSL costs every start 5 ms

    return hashlib.sha256(data).hexdigest()


def read_bounded(
    path: str | Path, *, display: str | None = None, limit: int, what: str = "file"
) -> bytes:
    """The bytes of ``path``, refusing more than ``limit`` without reading them all."""
    name = _shown_name(path, display)
    try:
        _refuse_unless_regular(os.stat(path).st_mode, name, what)
        # Not waiting on open: a pipe put in the file's place meanwhile is refused below.
        flags = os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC
        with open(os.open(path, flags), "rb") as stream:
            status = os.fstat(stream.fileno())
            _refuse_unless_regular(status.st_mode, name, what)
            # One byte past the limit says "too large". Asked for its size and a byte more
            # (not the limit: a buffer of 16 MB for each small file), then for the rest if
            # the file grew meanwhile.
            data = stream.read(min(status.st_size, limit) + 1)
            if status.st_size < len(data) <= limit:
                data += stream.read(limit + 1 - len(data))
    except FileNotFoundError:
        raise InputError.at(name, "no such file") from None
    except PermissionError:
        raise InputError.at(name, "permission denied") from None
    except OSError as error:
        raise InputError.at(name, f"cannot read: {error.strerror or error}") from None
    except InputError:
        raise
    except ValueError:
        # os.stat refuses a NUL byte in the name ("embedded null byte"); no file has one.
        raise InputError.at(
            name, "not a usable file name (it contains a NUL byte)", code="bad-name"
        ) from None
    if len(data) > limit:
        raise InputError.at(name, f"file is larger than {limit} bytes; refused", code="too-large")
    return data


# What is not a regular file, as a message names it.
_SPECIAL = (
    (stat.S_ISFIFO, "a pipe (FIFO)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def _refuse_unless_regular(mode: int, name: str, what: str) -> None:
    if stat.S_ISREG(mode):
        return
    if stat.S_ISDIR(mode):
        raise InputError.at(name, f"is a directory, not a {what}")
    kind = next((kind for test, kind in _SPECIAL if test(mode)), "a special file")
    raise InputError.at(
        name, f"is {kind}, not a {what}: only regular files are read", code="not-a-file"
    )


def read_text(
    path: str | Path, *, display: str | None = None, limit: int, what: str = "file"
) -> str:
    """:func:`read_bounded`, decoded as UTF-8 (a byte-order mark is dropped)."""
    raw = read_bounded(path, display=display, limit=limit, what=what)
    return decode_text(raw, path, display=display, what=what)


def decode_text(
    raw: bytes, path: str | Path, *, display: str | None = None, what: str = "file"
) -> str:
    """The bytes :func:`read_bounded` read from ``path`` as :func:`read_text` gives them, or
    its :class:`InputError` (for a caller that also needs the bytes: to hash what it reads)."""
    name = _shown_name(path, display)
    if b"\x00" in raw:
        raise InputError.at(name, f"contains NUL bytes: a binary file, not a {what}")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise InputError.at(
            name, f"not UTF-8 text (invalid byte at offset {error.start}); is this a {what}?"
        ) from None
