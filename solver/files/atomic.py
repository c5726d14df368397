"""Writing output files atomically: a temporary file in the same folder, then a rename.

An interrupted run (Ctrl-C, SIGTERM, a crash, a full disk) leaves either the old file or the
new one, never half of one, and no temporary: while temporaries exist, SIGTERM is turned into
:class:`~solver.errors.Terminated` (as SIGINT is a ``KeyboardInterrupt``) so that they are
removed before the process ends. Every command that writes files goes through
:func:`write_atomic`, or :func:`write_all_atomic` when its files belong together (a Markdown
report and its charts): then either every file is written or none is changed. The one
exception, :func:`overwrite`, writes a record whose loss is harmless (a ``batch`` stamp) in
place, with the same refusals of links.

**Links inside an output folder.** A folder someone else can write into may hold a link
planted where a subfolder is expected (``OUT/teams -> /home/you``). Given ``within``, the
output folder the user named, every folder between it and a target is made or entered with
``O_NOFOLLOW``, and the temporary is made, renamed and removed relative to that open folder:
no write, rename or removal goes through a link there (:func:`link_inside` answers the same
question for a caller that reads what it wrote before). The output folder itself is taken as
the user gave it, links and all.

What one call writes is bounded (the ``written-bytes`` limit, :mod:`solver.limits`): content
given whole is measured before any file is created; content given as chunks (a listing
streamed as it is made) stops at the limit, its temporaries removed and no file changed.

Not here: deciding what to write or where (nor how many files: ``written-files`` is checked
by the commands that write many, :mod:`solver.layouts.writer` and :mod:`solver.live.layouts`).
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import secrets
import shutil
import stat
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, replace
from pathlib import Path

from solver.errors import Fault, InputError, Location, Terminated, TooLargeError
from solver.limits import limit
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "Content",
    "link_inside",
    "make_folder",
    "overwrite",
    "remove_output",
    "remove_temporaries",
    "write_all_atomic",
    "write_atomic",
]

# How much of a target's name its temporaries and backups keep (names end at 255 bytes).
_KEPT_NAME = 100
# After that name and a dot: 8 random characters (as mkstemp's) and ".tmp", or a pid and ".old".
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


def write_atomic(path: str | Path, content: Content, *, within: str | Path | None = None) -> Path:
    """Write ``content`` to ``path`` atomically; :class:`InputError` if the folder is unusable,
    :class:`~solver.errors.TooLargeError` past the ``written-bytes`` limit. ``within``: see
    :func:`write_all_atomic`."""
    return write_all_atomic({path: content}, within=within)[0]


def write_all_atomic(
    files: Mapping[str | Path, Content], *, within: str | Path | None = None
) -> list[Path]:
    """Write every file of ``files`` or none; the paths written, in the mapping's order.

    Every target is checked first (a folder, device, pipe or socket in the way is reported
    for all of them at once: renaming onto ``/dev/full`` as root would replace the device;
    whole contents past the ``written-bytes`` limit together are refused), then every content
    goes to a temporary file beside its target, and only then are they renamed into place. A
    rename that still fails puts back the files renamed before it.

    ``within``: the output folder the user named (``batch -o DIR``), which holds every
    target. It is taken as given, through any link in its own path; every folder between it
    and a target is made or entered without following a link, and a link there (someone else
    may have put it there) is refused, naming it. Each folder is opened once, for the checks
    and the writes, and the files are made and renamed in the open folder, so a link put in
    its place meanwhile changes nothing.

    Each temporary is flushed to the disk (``fsync``) before it is renamed, so that after a
    power cut the name holds either the old content or the whole new one (without it a
    journaling file system may keep the rename and lose the data: an empty file).
    """
    budget = limit("written-bytes").value
    root = None if within is None else Path(within)
    targets = [(Path(path), _encoded(content)) for path, content in files.items()]
    folders: dict[Path, int] = {}
    temporaries: list[_Temporary] = []
    try:
        modes = _check_targets([target for target, _ in targets], root, folders)
        whole = sum(len(data) for _, data in targets if isinstance(data, bytes))
        if whole > budget:
            _refuse(targets[0][0], whole, budget, "bytes to write")
        with _terminable():
            try:
                written = 0  # by the files before, against the same budget
                for target, data in targets:
                    written = _temporary(
                        _folder(target, root, folders),
                        target,
                        data,
                        _Writing(written, budget, modes.get(target, 0o644)),
                        made=temporaries,
                    )
                _replace_all(temporaries)
                temporaries.clear()  # each renamed into place: nothing left to remove
            finally:
                for temporary in temporaries:
                    with contextlib.suppress(OSError):  # gone already when put back
                        os.unlink(temporary.name, dir_fd=temporary.folder)
    finally:
        for descriptor in folders.values():
            os.close(descriptor)
    return [target for target, _ in targets]


def _check_targets(
    targets: list[Path], root: Path | None, folders: dict[Path, int]
) -> dict[Path, int]:
    """Refuse (:class:`InputError`, every fault at once) what is in the way of ``targets``;
    the permissions of those that exist (a rewritten file keeps them). The folders opened
    for the checks are left in ``folders`` for the writes."""
    faults: dict[Fault, None] = {}  # in order, each once (two files below one planted link)
    modes: dict[Path, int] = {}
    for target in targets:
        fault = _in_the_way(target, root, folders, modes)
        if fault is not None:
            faults[fault] = None
    if faults:
        raise InputError(list(faults))
    return modes


def overwrite(path: str | Path, content: str | bytes, *, within: str | Path) -> Path:
    """Write ``content`` over the regular file ``path`` in place (made when missing), below the
    output folder ``within`` and never through a link inside it (as :func:`write_all_atomic`);
    :class:`InputError` if something else is there or the folder is unusable.

    Not atomic and not flushed to the disk: a reader, a crash or a kill may meet the file empty
    (new), cut, or the new bytes followed by the tail of longer old ones (they are written
    over the old bytes, then the file is cut to their length). Only for a record whose partial
    or lost content is harmless: a ``batch`` stamp (:mod:`solver.reporting.batch`), a JSON
    object, which cut before its closing brace, or followed by another's tail, is no JSON. It
    costs no new file and no rename, which an atomic write of a few hundred bytes is mostly made
    of."""
    target = Path(path)
    data = content.encode("utf-8", "backslashreplace") if isinstance(content, str) else content
    budget = limit("written-bytes").value
    if len(data) > budget:
        _refuse(target, len(data), budget, "bytes to write")
    folders: dict[Path, int] = {}
    try:
        folder = _folder(target, Path(within), folders)
        fault = _in_the_way(target, Path(within), folders, {})
        if fault is not None:
            raise InputError([fault])
        try:
            handle = os.open(target.name, _IN_PLACE, 0o644, dir_fd=folder)
        except OSError as error:
            raise InputError.at(
                _shown(target), f"cannot write: {error.strerror or error}"
            ) from None
        try:
            problem = _obstacle(os.fstat(handle).st_mode)  # swapped since the check above
            if problem is not None:
                raise InputError.at(_shown(target), problem, code="invalid")
            # Written over the old bytes, then cut to length: truncating to nothing first
            # makes ext4 flush the file when it is closed (its auto_da_alloc), which costs
            # more than the write.
            view, offset = memoryview(data), 0
            while offset < len(data):
                offset += os.pwrite(handle, view[offset:], offset)
            os.ftruncate(handle, len(data))
        except OSError as error:
            raise InputError.at(
                _shown(target), f"cannot write: {error.strerror or error}"
            ) from None
        finally:
            os.close(handle)
    finally:
        for descriptor in folders.values():
            os.close(descriptor)
    return target


def remove_temporaries(target: str | Path, *, within: str | Path | None = None) -> list[Path]:
    """Remove what a write of ``target`` killed outright (SIGKILL, the kernel's memory limit)
    left beside it: its temporaries and the copy of its old content kept while renaming. Only
    regular files named as this module names them for ``target``, never through a link
    inside ``within`` (see :func:`write_all_atomic`); the paths removed."""
    path = Path(target)
    folder = _parent(path)
    prefix = f".{path.name[:_KEPT_NAME]}."
    removed = []
    descriptor = _open_quietly(folder, within)
    if descriptor is None:
        return []
    try:
        with os.scandir(descriptor) as entries:
            names = [entry for entry in entries if entry.name.startswith(prefix)]
        for entry in names:
            ours = _LEFT_BEHIND.fullmatch(entry.name[len(prefix) :])
            if ours and entry.is_file(follow_symlinks=False):
                with contextlib.suppress(OSError):
                    os.unlink(entry.name, dir_fd=descriptor)
                    removed.append(folder / entry.name)
    except OSError:
        return removed
    finally:
        os.close(descriptor)
    return removed


def remove_output(path: str | Path, *, within: str | Path) -> bool:
    """Remove the regular file ``path`` below the output folder ``within``, never through a
    link inside it (see :func:`write_all_atomic`); whether a file was removed."""
    target = Path(path)
    descriptor = _open_quietly(_parent(target), within)
    if descriptor is None:
        return False
    try:
        mode = os.stat(target.name, dir_fd=descriptor, follow_symlinks=False).st_mode
        if not stat.S_ISREG(mode):
            return False
        os.unlink(target.name, dir_fd=descriptor)
    except OSError:
        return False
    finally:
        os.close(descriptor)
    return True


def link_inside(path: str | Path, *, within: str | Path) -> Path | None:
    """The first symbolic link between the output folder ``within`` and ``path`` (``path``
    itself included), or ``None``: for a caller that reads what it wrote there before."""
    here = Path(within)
    for part in _parts_below(Path(path), here):
        here = here / part
        try:
            if stat.S_ISLNK(os.lstat(here).st_mode):
                return here
        except OSError:
            return None
    return None


# ---- folders opened without following a link ------------------------------------------------

# A folder opened for the calls relative to it; O_NOFOLLOW for the folders below ``within``.
_FOLDER_FLAGS = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | getattr(os, "O_CLOEXEC", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_LINK_INSIDE = (
    "is a link inside the output folder; refused: a write never follows a link there "
    "(someone else may have put it there)"
)


class _LinkInside(Exception):
    """A folder below ``within`` is a symbolic link (:attr:`path`)."""

    def __init__(self, path: Path) -> None:
        super().__init__(str(path))
        self.path = path


def _parent(path: Path) -> Path:
    return path.parent if str(path.parent) else Path(".")


def _parts_below(path: Path, within: Path) -> tuple[str, ...]:
    """The parts of ``path`` below ``within`` (a folder the caller says holds it)."""
    parts = path.relative_to(within).parts
    if ".." in parts:
        raise ValueError(f"{path} is not inside {within}")
    return parts


def _open_folder(folder: Path, within: Path | None, *, make: bool) -> int | None:
    """A descriptor of ``folder`` (the caller closes it), made with its parents when ``make``;
    ``None`` when it does not exist (and is not made). Below ``within`` each folder is made
    or opened without following a link: :class:`_LinkInside` names one found there. Other
    problems are :class:`OSError`."""
    top, below = (folder, ()) if within is None else (within, _parts_below(folder, within))
    try:
        descriptor = os.open(top, _FOLDER_FLAGS)
    except FileNotFoundError:
        if not make:
            return None
        top.mkdir(parents=True, exist_ok=True)
        descriptor = os.open(top, _FOLDER_FLAGS)
    for index, part in enumerate(below):
        try:
            inner = _enter(part, descriptor, make=make)
        except OSError as error:
            linked = _is_link(part, descriptor)
            os.close(descriptor)
            if linked:
                raise _LinkInside(top.joinpath(*below[: index + 1])) from None
            if isinstance(error, FileNotFoundError) and not make:
                return None
            raise
        os.close(descriptor)
        descriptor = inner
    return descriptor


def _enter(name: str, folder: int, *, make: bool) -> int:
    """The folder ``name`` in the open ``folder``, opened without following a link; made first
    when missing and ``make`` (opened first: a folder is made once and entered many times)."""
    try:
        return os.open(name, _FOLDER_FLAGS | _NOFOLLOW, dir_fd=folder)
    except FileNotFoundError:
        if not make:
            raise
    with contextlib.suppress(FileExistsError):
        os.mkdir(name, dir_fd=folder)
    return os.open(name, _FOLDER_FLAGS | _NOFOLLOW, dir_fd=folder)


def _is_link(name: str, folder: int) -> bool:
    try:
        return stat.S_ISLNK(os.stat(name, dir_fd=folder, follow_symlinks=False).st_mode)
    except OSError:
        return False


def _open_quietly(folder: Path, within: str | Path | None) -> int | None:
    """``folder`` opened as :func:`_open_folder` opens it, never made; ``None`` when it is
    missing, unusable or behind a link."""
    try:
        return _open_folder(folder, None if within is None else Path(within), make=False)
    except (_LinkInside, OSError):
        return None


def _folder(target: Path, within: Path | None, opened: dict[Path, int]) -> int:
    """The open folder ``target`` is written in, made if needed (once per folder)."""
    folder = _parent(target)
    if folder not in opened:
        try:
            descriptor = _open_folder(folder, within, make=True)
        except _LinkInside as link:
            raise InputError.at(_shown(link.path), _LINK_INSIDE, code="bad-output") from None
        except OSError as error:
            raise InputError.at(
                _shown(target), f"cannot write here: {error.strerror or error}"
            ) from None
        assert descriptor is not None  # made
        opened[folder] = descriptor
    return opened[folder]


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


def _in_the_way(
    target: Path, within: Path | None, folders: dict[Path, int], modes: dict[Path, int]
) -> Fault | None:
    """What is at ``target`` that a file must not replace, if anything, or a link on the way
    to it below ``within``. Its folder, when it exists, is opened into ``folders`` (for the
    write that follows) and the permissions of a regular file there go into ``modes``.

    A rename replaces whatever has the name: a device (``/dev/full``, as root), or a link such
    as ``/dev/stdout`` or one planted where an output is expected. Only a regular file is
    replaced."""
    parent = _parent(target)
    folder = folders.get(parent)
    if folder is None:
        try:
            folder = _open_folder(parent, within, make=False)
        except _LinkInside as link:
            return Fault(Location(_shown(link.path)), _LINK_INSIDE, "bad-output")
        except (OSError, ValueError):  # a folder the write will report
            return None
        if folder is None:
            return None
        folders[parent] = folder
    try:
        mode = os.stat(target.name, dir_fd=folder, follow_symlinks=False).st_mode
    except (OSError, ValueError):  # nothing there, or a name the write will report
        return None
    problem = _obstacle(mode)
    if problem is None:
        modes[target] = stat.S_IMODE(mode)
        return None
    return Fault(Location(_shown(target)), problem, "invalid")


def _obstacle(mode: int) -> str | None:
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


@dataclass(frozen=True, slots=True)
class _Temporary:
    """A temporary file: its open folder, its name there, and the target it will replace."""

    folder: int
    name: str
    target: Path


_ATTEMPTS = 100
# Opened in place: never through a link, never waiting on a pipe, never a terminal's owner.
_IN_PLACE = (
    os.O_WRONLY | os.O_CREAT | _NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY | getattr(os, "O_CLOEXEC", 0)
)
_NEW_FILE = os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW | getattr(os, "O_CLOEXEC", 0)


def _create(folder: int, target: Path, made: list[_Temporary]) -> int:
    """A new temporary for ``target`` in ``folder``, private (0600) and listed in ``made`` as
    soon as it exists; its descriptor."""
    # The temporary's name is the target's and 13 more characters: cut, so that a target
    # name near the system's limit (255 bytes) still has room for one.
    prefix = f".{target.name[:_KEPT_NAME]}."
    for _ in range(_ATTEMPTS):
        name = prefix + secrets.token_hex(4) + ".tmp"  # 8 characters of _LEFT_BEHIND's
        with _signals_held():  # listed as soon as it exists: the caller's clean-up finds it
            try:
                handle = os.open(name, _NEW_FILE, 0o600, dir_fd=folder)
            except FileExistsError:
                continue
            made.append(_Temporary(folder, name, target))
        return handle
    raise FileExistsError(errno.EEXIST, "no free name for a temporary file")


@dataclass(frozen=True, slots=True)
class _Writing:
    """How one temporary is written: the bytes ``written`` before it against the ``budget``,
    and the permissions it gets."""

    written: int
    budget: int
    mode: int


def _temporary(
    folder: int,
    target: Path,
    data: bytes | Iterator[bytes],
    how: _Writing,
    *,
    made: list[_Temporary],
) -> int:
    """``data`` in a new temporary file in ``target``'s open ``folder``, listed in ``made``
    with its target as it is created; the bytes written with it and those before.
    :class:`TooLargeError` (and no temporary) past the budget."""
    try:
        handle = _create(folder, target, made)
    except OSError as error:
        raise InputError.at(
            _shown(target), f"cannot write here: {error.strerror or error}"
        ) from None
    temporary = made[-1]
    written = how.written
    try:
        with os.fdopen(handle, "wb") as stream:
            for chunk in (data,) if isinstance(data, bytes) else data:
                written += len(chunk)
                if written > how.budget:
                    _refuse(target, written, how.budget, "bytes or more to write")
                stream.write(chunk)
            stream.flush()
            # The temporary is private (0600); give it the mode a plain write would have.
            os.fchmod(stream.fileno(), how.mode)
            os.fsync(stream.fileno())
    except BaseException as error:
        with contextlib.suppress(OSError):
            os.unlink(temporary.name, dir_fd=folder)
        if isinstance(error, OSError):
            raise InputError.at(
                _shown(target), f"cannot write: {error.strerror or error}"
            ) from None
        raise
    return written


def _replace_all(temporaries: list[_Temporary]) -> None:
    """Rename each temporary onto its target; on a failure, undo the renames before it."""
    done: list[tuple[_Temporary, str | None]] = []  # (renamed, a copy of its old content)
    try:
        for index, temporary in enumerate(temporaries):
            folder, name = temporary.folder, temporary.target.name
            # A rename and its record are one step: a signal between them would leave a file
            # renamed that no undo knows of.
            with _signals_held():
                # Only a later failure needs the old content back; the last rename either
                # happens or not.
                backup = _backup(folder, name) if index < len(temporaries) - 1 else None
                try:
                    os.replace(temporary.name, name, src_dir_fd=folder, dst_dir_fd=folder)
                except BaseException:
                    _discard(folder, backup)
                    raise
                done.append((temporary, backup))
    except BaseException as error:
        for temporary, backup in reversed(done):
            folder, name = temporary.folder, temporary.target.name
            with contextlib.suppress(OSError):
                if backup is not None:
                    os.replace(backup, name, src_dir_fd=folder, dst_dir_fd=folder)
                else:
                    os.unlink(name, dir_fd=folder)
        if isinstance(error, OSError):
            raise InputError.at(
                _shown(temporaries[len(done)].target), f"cannot write: {error.strerror or error}"
            ) from None
        raise
    finally:
        for temporary, backup in done:
            _discard(temporary.folder, backup)  # gone already when put back


def _backup(folder: int, name: str) -> str | None:
    """A hard link to (or else a copy of) the file ``name`` in ``folder``, by a name of its
    own there; ``None`` if it is no regular file."""
    try:
        mode = os.stat(name, dir_fd=folder, follow_symlinks=False).st_mode
    except OSError:
        return None
    if not stat.S_ISREG(mode):
        return None
    backup = f".{name[:_KEPT_NAME]}.{os.getpid()}.old"
    _discard(folder, backup)
    try:
        os.link(name, backup, src_dir_fd=folder, dst_dir_fd=folder)
    except OSError:  # a file system without hard links
        _copy(folder, name, backup, stat.S_IMODE(mode))
    return backup


def _copy(folder: int, name: str, copy: str, mode: int) -> None:
    source = os.open(name, os.O_RDONLY | _NOFOLLOW | getattr(os, "O_CLOEXEC", 0), dir_fd=folder)
    with (
        os.fdopen(source, "rb") as reading,
        os.fdopen(os.open(copy, _NEW_FILE, mode, dir_fd=folder), "wb") as writing,
    ):
        shutil.copyfileobj(reading, writing)


def _discard(folder: int, name: str | None) -> None:
    if name is not None:
        with contextlib.suppress(OSError):
            os.unlink(name, dir_fd=folder)
