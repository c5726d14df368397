"""Kernel fences for the trusted-xacro child: read a few folders, write, run and dial nothing.

The child that compiles a trusted xacro file (:mod:`solver.identify.xacro.child`) replaces
``open`` and the process functions of ``os`` before xacro runs, but that fence is Python-level:
an expression that escapes xacro's namespace reaches ``_io.open``, ``os.mknod`` or lxml's C
file writer, none of which go through it. :func:`confine` moves the fence into the kernel,
irrevocably, for this process and anything it starts:

* **Landlock** (Linux 5.13+, no privileges needed): files are read and folders listed only
  beneath the folders given (the description's packages and the interpreter's own library
  folders); nothing is created, written, truncated, renamed, linked or removed anywhere, and
  nothing executed. From ABI 4, no TCP connect or bind; from ABI 6, no signal to a process
  outside the sandbox and no abstract Unix socket.
* **seccomp** (x86-64 and arm64): ``socket`` fails, so neither UDP nor a Unix socket with a
  path (a Docker or X server socket: Landlock does not fence those) can be reached;
  ``io_uring_setup`` fails (io_uring works around per-call filters); ``fork``, ``vfork``,
  ``clone`` and ``clone3`` fail, so no process or thread starts, root included.
* ``RLIMIT_NPROC`` 0, for kernels where neither applies (binding non-root users only).

What none of this covers (CPU and memory: ``setrlimit`` in :mod:`solver.identify.xacro.child`)
is listed in docs/security.md. The raw system calls go through :mod:`ctypes`: the standard
library has no binding for them, and a third-party one would be a dependency for five calls.
Only the child imports this module.

Not here: what the child reads or compiles (:mod:`solver.identify.xacro.child`).
"""

from __future__ import annotations

import ctypes
import errno
import os
import platform
import resource
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

__all__ = ["Confinement", "confine"]

# The Landlock system calls have the same numbers on every Linux architecture (asm-generic).
_CREATE_RULESET, _ADD_RULE, _RESTRICT_SELF = 444, 445, 446
_CREATE_RULESET_VERSION = 1
_RULE_PATH_BENEATH = 1
_PR_SET_NO_NEW_PRIVS = 38
_PR_SET_SECCOMP = 22
_SECCOMP_MODE_FILTER = 2

_READ_FILE = 1 << 2
_READ_DIR = 1 << 3
# Every file-system right the kernel knows at each ABI: all are "handled" (denied unless a rule
# grants them), so a right that a newer kernel adds is denied too.
_FS_RIGHTS = {
    1: (1 << 13) - 1,
    2: (1 << 14) - 1,
    3: (1 << 15) - 1,
    4: (1 << 15) - 1,
    5: (1 << 16) - 1,
}
_NET_TCP = (1 << 0) | (1 << 1)  # bind and connect
_SCOPES = (1 << 0) | (1 << 1)  # abstract Unix sockets and signals

# seccomp: audit architecture, then the system calls refused (socket, io_uring_setup, clone,
# clone3, and fork/vfork where they exist). x86-64 numbers at or above 0x40000000 are x32 calls.
_DENIED = {
    "x86_64": (0xC000003E, (41, 425, 56, 435, 57, 58)),
    "aarch64": (0xC00000B7, (198, 425, 220, 435)),
}
_X32 = 0x40000000
_RET_ALLOW = 0x7FFF0000
_RET_ERRNO = 0x00050000
_RET_KILL_PROCESS = 0x80000000


@dataclass(frozen=True, slots=True)
class Confinement:
    """Which kernel fences hold: the Landlock ABI (0: none) and whether seccomp is on."""

    landlock_abi: int
    seccomp: bool

    @property
    def missing(self) -> tuple[str, ...]:
        """The fences this kernel did not give, named for a warning."""
        return (
            *(() if self.landlock_abi else ("Landlock",)),
            *(() if self.seccomp else ("seccomp",)),
        )


def confine(readable: Sequence[str | Path]) -> Confinement:
    """Allow only reading beneath ``readable`` from now on, and no sockets or processes."""
    resource.setrlimit(resource.RLIMIT_NPROC, (0, 0))
    if platform.system() != "Linux":
        return Confinement(0, seccomp=False)
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return Confinement(0, seccomp=False)
    abi = _landlock(libc, readable)
    return Confinement(abi, _seccomp(libc))


class _RulesetAttr(ctypes.Structure):
    _fields_: ClassVar = [
        ("handled_access_fs", ctypes.c_uint64),
        ("handled_access_net", ctypes.c_uint64),
        ("scoped", ctypes.c_uint64),
    ]


class _PathBeneathAttr(ctypes.Structure):
    _pack_ = 1  # the kernel's struct is packed: 12 bytes
    _fields_: ClassVar = [("allowed_access", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]


class _SockFilter(ctypes.Structure):
    _fields_: ClassVar = [
        ("code", ctypes.c_uint16),
        ("jt", ctypes.c_uint8),
        ("jf", ctypes.c_uint8),
        ("k", ctypes.c_uint32),
    ]


class _SockFprog(ctypes.Structure):
    _fields_: ClassVar = [("len", ctypes.c_ushort), ("filter", ctypes.POINTER(_SockFilter))]


def _landlock(libc: Any, readable: Sequence[str | Path]) -> int:
    syscall = libc.syscall
    syscall.restype = ctypes.c_long
    abi = int(
        syscall(
            ctypes.c_long(_CREATE_RULESET),
            None,
            ctypes.c_size_t(0),
            ctypes.c_uint32(_CREATE_RULESET_VERSION),
        )
    )
    if abi <= 0:
        return 0
    attr = _RulesetAttr(
        _FS_RIGHTS.get(abi, _FS_RIGHTS[5]), _NET_TCP if abi >= 4 else 0, _SCOPES if abi >= 6 else 0
    )
    # An older kernel takes the shorter struct it knows (the fields it does not know are absent).
    size = 8 if abi < 4 else 16 if abi < 6 else 24
    ruleset = int(
        syscall(
            ctypes.c_long(_CREATE_RULESET),
            ctypes.byref(attr),
            ctypes.c_size_t(size),
            ctypes.c_uint32(0),
        )
    )
    if ruleset < 0:
        return 0
    try:
        for folder in _existing(readable):
            rights = _READ_FILE | _READ_DIR if folder.is_dir() else _READ_FILE
            fd = os.open(folder, os.O_PATH | os.O_CLOEXEC)
            try:
                rule = _PathBeneathAttr(rights, fd)
                if (
                    syscall(
                        ctypes.c_long(_ADD_RULE),
                        ctypes.c_int(ruleset),
                        ctypes.c_int(_RULE_PATH_BENEATH),
                        ctypes.byref(rule),
                        ctypes.c_uint32(0),
                    )
                    != 0
                ):
                    raise OSError(ctypes.get_errno(), f"landlock_add_rule {folder}")
            finally:
                os.close(fd)
        if syscall(ctypes.c_long(_RESTRICT_SELF), ctypes.c_int(ruleset), ctypes.c_uint32(0)):
            raise OSError(ctypes.get_errno(), "landlock_restrict_self")
    finally:
        os.close(ruleset)
    return abi


def _seccomp(libc: Any) -> bool:
    denied = _DENIED.get(platform.machine())
    if denied is None:
        return False
    arch, calls = denied
    load, jeq, jge, ret = 0x20, 0x15, 0x35, 0x06  # BPF_LD|W|ABS, JMP|JEQ|K, JMP|JGE|K, RET|K
    # 0: arch; 1: a foreign architecture is killed (its numbers mean other calls);
    # 2: number; 3: x32 refused; 4..: each denied call jumps to the last instruction.
    program = [
        (load, 0, 0, 4),
        (jeq, 1, 0, arch),
        (ret, 0, 0, _RET_KILL_PROCESS),
        (load, 0, 0, 0),
        (jge, len(calls) + 1, 0, _X32),
    ]
    program += [(jeq, len(calls) - i, 0, call) for i, call in enumerate(calls)]
    program += [(ret, 0, 0, _RET_ALLOW), (ret, 0, 0, _RET_ERRNO | errno.EACCES)]
    filters = (_SockFilter * len(program))(*[_SockFilter(*step) for step in program])
    fprog = _SockFprog(len(program), filters)
    return bool(libc.prctl(_PR_SET_SECCOMP, _SECCOMP_MODE_FILTER, ctypes.byref(fprog), 0, 0) == 0)


def _existing(paths: Sequence[str | Path]) -> list[Path]:
    found: dict[str, Path] = {}
    for item in paths:
        try:
            resolved = Path(item).resolve(strict=True)
        except OSError:
            continue  # a sys.path entry that does not exist (a missing zip) grants nothing
        found.setdefault(str(resolved), resolved)
    return list(found.values())
