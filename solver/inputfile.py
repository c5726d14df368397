"""Reading input files with a size limit, and every failure as a located error.

Every file a command reads (rule sets, teams, profiles, URDF, topic lists) goes through here:
at most ``limit`` bytes are read, whatever ``stat()`` says (it says 0 for pipes and
``/dev/zero``), and a missing, unreadable, oversized, binary or non-UTF-8 file is an
:class:`~solver.errors.InputError` naming it.

Not here: parsing what was read (:mod:`solver.yamlio`, :mod:`solver.identify.safexml`).
"""

from __future__ import annotations

from pathlib import Path

from solver.errors import InputError

__all__ = ["read_bounded", "read_text"]


def read_bounded(path: str | Path, *, display: str | None = None, limit: int,
                 what: str = "file") -> bytes:
    """The bytes of ``path``, refusing more than ``limit`` without reading them all."""
    name = display if display is not None else str(path)
    file = Path(path)
    try:
        if file.is_dir():
            raise InputError.at(name, f"is a directory, not a {what}")
        with file.open("rb") as stream:
            data = stream.read(limit + 1)  # one byte past the limit says "too large"
    except FileNotFoundError:
        raise InputError.at(name, "no such file") from None
    except PermissionError:
        raise InputError.at(name, "permission denied") from None
    except OSError as error:
        raise InputError.at(name, f"cannot read: {error.strerror or error}") from None
    if len(data) > limit:
        raise InputError.at(name, f"file is larger than {limit} bytes; refused",
                            code="too-large")
    return data


def read_text(path: str | Path, *, display: str | None = None, limit: int,
              what: str = "file") -> str:
    """:func:`read_bounded`, decoded as UTF-8 (a byte-order mark is dropped)."""
    name = display if display is not None else str(path)
    raw = read_bounded(path, display=name, limit=limit, what=what)
    if b"\x00" in raw:
        raise InputError.at(name, f"contains NUL bytes: a binary file, not a {what}")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise InputError.at(name, f"not UTF-8 text (invalid byte at offset {error.start}); "
                                  f"is this a {what}?") from None
