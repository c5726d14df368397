"""Writing output files atomically: a temporary file in the same folder, then a rename.

An interrupted run (Ctrl-C, SIGTERM, a crash, a full disk) leaves either the old file or the
new one, never half of one, and no temporary: while temporaries exist, SIGTERM is turned into
:class:`~solver.errors.Terminated` (as SIGINT is a ``KeyboardInterrupt``) so that they are
removed before the process ends. Every command that writes files goes through
:func:`write_atomic`, or :func:`write_all_atomic` when its files belong together (a Markdown
report and its charts): then either every file is written or none is changed.

What one call writes is bounded (the ``written-bytes`` limit, :mod:`solver.limits`): content
given whole is measured before any file is created; content given as chunks (a listing
streamed as it is made) stops at the limit, its temporaries removed and no file changed.

Not here: deciding what to write or where (nor how many files: ``written-files`` is checked
by the commands that write many, :mod:`solver.layouts.writer`).
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import replace
from pathlib import Path

from solver.errors import Fault, InputError, Location, Terminated, TooLargeError
from solver.limits import limit
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = ["Content", "make_folder", "remove_temporaries", "write_all_atomic", "write_atomic"]

# How much of a target's name its temporaries and backups keep (names end at 255 bytes).
_KEPT_NAME = 100
# After that name and a dot: mkstemp's 8 random characters and ".tmp", or a pid and ".old".
_LEFT_BEHIND = re.compile(r"[a-z0-9_]{8}\.tmp|[0-9]+\.old")

# A file's content: whole, or chunks written as they come (never all in memory at once).
Content = str | bytes | Iterable[str | bytes]


def make_folder(path: str | Path) -> Path:
    """``path`` as a folder to write into, made with its parents when missing;
    :class:`InputError` when it cannot be one (a file is there, a name is too long, ...)."""
    folder = Path(path)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise InputError.at(
            _shown(path), "is not a folder: give a folder to write into", code="bad-output"
        ) from None
    except OSError as error:
        raise InputError.at(
            _shown(path), f"cannot make this folder: {error.strerror or error}", code="bad-output"
        ) from None
    return folder


def write_atomic(path: str | Path, content: Content) -> Path:
    """Write ``content`` to ``path`` atomically; :class:`InputError` if the folder is unusable,
    :class:`~solver.errors.TooLargeError` past the ``written-bytes`` limit."""
    return write_all_atomic({path: content})[0]


def write_all_atomic(files: Mapping[str | Path, Content]) -> list[Path]:
    """Write every file of ``files`` or none; the paths written, in the mapping's order.

    Every target is checked first (a folder, device, pipe or socket in the way is reported
    for all of them at once: renaming onto ``/dev/full`` as root would replace the device;
    whole contents past the ``written-bytes`` limit together are refused), then every content
    goes to a temporary file beside its target, and only then are they renamed into place. A
    rename that still fails puts back the files renamed before it.
    """
    budget = limit("written-bytes").value
    targets = [(Path(path), _encoded(content)) for path, content in files.items()]
    faults = [
        Fault(Location(_shown(target)), problem, "invalid")
        for target, _ in targets
        if (problem := _in_the_way(target))
    ]
    if faults:
        raise InputError(faults)
    whole = sum(len(data) for _, data in targets if isinstance(data, bytes))
    if whole > budget:
        _refuse(targets[0][0], whole, budget, "bytes to write")
    temporaries: list[tuple[Path, Path]] = []
    with _terminable():
        try:
            written = 0  # by the files before, against the same budget
            for target, data in targets:
                written = _temporary(target, data, written, budget, temporaries)
            _replace_all(temporaries)
        finally:
            for temporary, _ in temporaries:
                with contextlib.suppress(OSError):
                    temporary.unlink()  # gone already when renamed into place
    return [target for target, _ in targets]


def remove_temporaries(target: str | Path) -> list[Path]:
    """Remove what a write of ``target`` killed outright (SIGKILL, the kernel's memory limit)
    left beside it: its temporaries and the copy of its old content kept while renaming. Only
    regular files named as this module names them for ``target``; the paths removed."""
    path = Path(target)
    folder = path.parent if str(path.parent) else Path(".")
    prefix = f".{path.name[:_KEPT_NAME]}."
    removed = []
    try:
        names = [entry for entry in os.scandir(folder) if entry.name.startswith(prefix)]
    except OSError:
        return []
    for entry in names:
        ours = _LEFT_BEHIND.fullmatch(entry.name[len(prefix) :])
        if ours and entry.is_file(follow_symlinks=False):
            with contextlib.suppress(OSError):
                os.unlink(entry.path)
                removed.append(Path(entry.path))
    return removed


def _encoded(content: Content) -> bytes | Iterator[bytes]:
    """``content`` as bytes, or as an iterator of byte chunks when it came in chunks."""
    # backslashreplace: a file name that is not UTF-8 (its bytes arrive as surrogate escapes)
    # is written as "\udcff", readable text, instead of failing the whole write.
    if isinstance(content, str):
        return content.encode("utf-8", "backslashreplace")
    if isinstance(content, bytes):
        return content
    return (
        chunk.encode("utf-8", "backslashreplace") if isinstance(chunk, str) else chunk
        for chunk in content
    )


def _refuse(target: Path, size: int, budget: int, noun: str) -> None:
    which = replace(limit("written-bytes"), value=budget)
    raise TooLargeError(which.fault(Location(_shown(target)), size, noun=noun))


@contextlib.contextmanager
def _terminable() -> Iterator[None]:
    """While temporaries may exist: SIGTERM raises :class:`Terminated` (in the main thread,
    where Python runs signal handlers) instead of ending the process on the spot, so the
    ``finally`` above removes them. A handler someone else installed is left alone."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.getsignal(signal.SIGTERM)
    if previous is not signal.SIG_DFL:
        yield
        return

    def stop(number: int, _frame: object) -> None:
        raise Terminated(number)

    signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """SIGTERM and SIGINT held back for this thread while a step on the file system and its
    record are made together; one that came meanwhile is handled as the block ends (Python
    runs its handler at the next instruction), when the clean-up knows of the step."""
    import signal

    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def _shown(path: str | Path) -> str:
    return shown(str(path), limit=SHOWN_FILE_NAME_CHARS)


def _in_the_way(target: Path) -> str | None:
    """What is at ``target`` that a file must not replace, if anything.

    A rename replaces whatever has the name: a device (``/dev/full``, as root), or a link such
    as ``/dev/stdout`` or one planted where an output is expected. Only a regular file is
    replaced."""
    try:
        mode = os.lstat(target).st_mode
    except (OSError, ValueError):  # nothing there, or a name the write will report
        return None
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "is a folder; cannot write a file there"
    if stat.S_ISLNK(mode):
        return (
            "is a link; refused: writing would replace the link, not the file it names "
            "(give that file)"
        )
    return "is a device, a pipe or a socket, not a file; refused: writing would replace it"


def _temporary(
    target: Path,
    data: bytes | Iterator[bytes],
    written: int,
    budget: int,
    made: list[tuple[Path, Path]],
) -> int:
    """``data`` in a new temporary file in ``target``'s folder (created if needed), listed in
    ``made`` with its target as it is created; the bytes ``written`` with it.
    :class:`TooLargeError` (and no temporary) past ``budget``."""
    folder = target.parent if str(target.parent) else Path(".")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        # The temporary's name is the target's and 13 more characters: cut, so that a target
        # name near the system's limit (255 bytes) still has room for one.
        prefix = f".{target.name[:_KEPT_NAME]}."
        with _signals_held():  # listed as soon as it exists: the caller's clean-up finds it
            handle, name = tempfile.mkstemp(prefix=prefix, suffix=".tmp", dir=folder)
            temporary = Path(name)
            made.append((temporary, target))
    except OSError as error:
        raise InputError.at(
            _shown(target), f"cannot write here: {error.strerror or error}"
        ) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            for chunk in (data,) if isinstance(data, bytes) else data:
                written += len(chunk)
                if written > budget:
                    _refuse(target, written, budget, "bytes or more to write")
                stream.write(chunk)
            stream.flush()
            os.fsync(stream.fileno())
        # mkstemp makes the file private (0600); give it the mode a plain write would have.
        mode = target.stat().st_mode & 0o777 if target.exists() else 0o644
        os.chmod(temporary, mode)
    except BaseException as error:
        with contextlib.suppress(OSError):
            temporary.unlink()
        if isinstance(error, OSError):
            raise InputError.at(
                _shown(target), f"cannot write: {error.strerror or error}"
            ) from None
        raise
    return written


def _replace_all(temporaries: list[tuple[Path, Path]]) -> None:
    """Rename each temporary onto its target; on a failure, undo the renames before it."""
    done: list[tuple[Path, Path | None]] = []  # (target, a copy of its old content)
    try:
        for index, (temporary, target) in enumerate(temporaries):
            # A rename and its record are one step: a signal between them would leave a file
            # renamed that no undo knows of.
            with _signals_held():
                # Only a later failure needs the old content back; the last rename either
                # happens or not.
                backup = _backup(target) if index < len(temporaries) - 1 else None
                try:
                    os.replace(temporary, target)
                except BaseException:
                    _discard(backup)
                    raise
                done.append((target, backup))
    except BaseException as error:
        for target, backup in reversed(done):
            with contextlib.suppress(OSError):
                if backup is not None:
                    os.replace(backup, target)
                else:
                    target.unlink()
        if isinstance(error, OSError):
            raise InputError.at(
                _shown(temporaries[len(done)][1]), f"cannot write: {error.strerror or error}"
            ) from None
        raise
    finally:
        for _, backup in done:
            _discard(backup)  # gone already when put back


def _backup(target: Path) -> Path | None:
    """A hard link to (or else a copy of) ``target``'s content; ``None`` if it is no file."""
    if not os.path.isfile(target):
        return None
    backup = target.with_name(f".{target.name[:_KEPT_NAME]}.{os.getpid()}.old")
    _discard(backup)
    try:
        os.link(target, backup)
    except OSError:  # a file system without hard links
        shutil.copy2(target, backup)
    return backup


def _discard(path: Path | None) -> None:
    if path is not None:
        with contextlib.suppress(OSError):
            path.unlink()
