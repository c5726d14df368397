"""Kernel fences for the trusted-xacro child: read a few folders; write, run, dial, touch nothing.

The child that compiles a trusted xacro file (:mod:`solver.identify.xacro.child`) guards every
expression (:mod:`solver.identify.xacro.expressions`) and replaces ``open``, but those fences
are Python-level. The fences here are the kernel's, irrevocable for this process and anything
it could start, and hold even if the Python-level ones are escaped. The child applies them in
two steps, both before it reads the user's file:

:func:`forbid_system_calls` (seccomp, x86-64 and arm64), first thing, before xacro is imported:

* no process or thread: ``fork``, ``vfork``, ``clone``, ``clone3``, ``execve``, ``execveat``;
* no socket (``socket``, ``socketpair``: no UDP, no Unix socket with a path such as Docker's or
  X's, which Landlock does not fence) and no ``io_uring`` (it works around per-call filters);
* no change to any file's mode, owner, times or extended attributes (``chmod``, ``chown``,
  ``utime``, ``utimensat``, ``setxattr``... and their ``f``/``l``/``at`` forms: Landlock does
  not fence these), and no file created, written, truncated, renamed, linked or removed
  (``open``/``openat`` with a write, create or truncate flag, ``creat``, ``mknod``,
  ``mkdir``, ``unlink``, ``rename``, ``link``, ``symlink``, ``truncate``, ``fallocate``;
  ``openat2`` whose flags a filter cannot see): writes are fenced without Landlock too;
* nothing reached in another process: ``ptrace``, ``process_vm_readv``/``writev``, pidfd
  calls, ``kcmp``, ``move_pages``, ``migrate_pages``, ``process_madvise``; signals and
  ``prlimit`` only to itself; no ``setpriority``/scheduler/io-priority change; System V IPC
  and POSIX message queues; no ``TIOCSTI``/``TIOCLINUX`` ioctl (typing into a terminal);
* no kernel keyring (``keyctl``, ``add_key``, ``request_key``), ``syslog``, ``bpf``,
  ``perf_event_open``, ``userfaultfd``, namespaces or mounts (``unshare``, ``setns``, ``mount``
  and the new mount API, ``chroot``, ``pivot_root``), ``open_by_handle_at``;
* a system call newer than this filter (numbered 470 and up) fails with ``ENOSYS``, as on an
  older kernel; an x32 or foreign-architecture call ends the process.

Refused calls fail with ``EACCES`` (``PermissionError``), as Landlock's refusals do.

:func:`restrict_reads` (Landlock, Linux 5.13+), once xacro is loaded and before the user's file
is read: files are read and folders listed only beneath the folders given (the description's
package folders); nothing is created, written, truncated, renamed, linked, removed or executed
anywhere. From ABI 4, no TCP connect or bind; from ABI 6, no signal to a process outside the
sandbox and no abstract Unix socket.

``RLIMIT_NPROC`` 0 as well, for systems where neither applies (binding non-root users only).

The raw system calls go through :mod:`ctypes` (the standard library has no binding for them,
and a third-party one would be a dependency for five calls), imported inside the functions
here and dropped from ``sys.modules`` by :func:`forget_ctypes` once the fences are up. Only the
child imports this module.

Not here: what the child reads or compiles (:mod:`solver.identify.xacro.child`).
"""

from __future__ import annotations

import errno
import os
import platform
import resource
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["Confinement", "confine", "forbid_system_calls", "forget_ctypes", "restrict_reads"]

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

# System call -> its number on (x86-64, arm64), None where that architecture has no such call:
# arch/x86/entry/syscalls/syscall_64.tbl and include/uapi/asm-generic/unistd.h. From 424 on
# every architecture numbers new calls alike. Every call here is refused, the last group
# only for some arguments.
_CALLS: dict[str, tuple[int | None, int | None]] = {
    # processes and threads
    "fork": (57, None),
    "vfork": (58, None),
    "clone": (56, 220),
    "clone3": (435, 435),
    "execve": (59, 221),
    "execveat": (322, 281),
    # sockets and io_uring (it works around per-call filters)
    "socket": (41, 198),
    "socketpair": (53, 199),
    "io_uring_setup": (425, 425),
    "io_uring_enter": (426, 426),
    "io_uring_register": (427, 427),
    # file metadata: mode, owner, times, extended attributes (Landlock does not fence these)
    "chmod": (90, None),
    "fchmod": (91, 52),
    "fchmodat": (268, 53),
    "fchmodat2": (452, 452),
    "chown": (92, None),
    "fchown": (93, 55),
    "lchown": (94, None),
    "fchownat": (260, 54),
    "utime": (132, None),
    "utimes": (235, None),
    "futimesat": (261, None),
    "utimensat": (280, 88),
    "setxattr": (188, 5),
    "lsetxattr": (189, 6),
    "fsetxattr": (190, 7),
    "setxattrat": (463, 463),
    "removexattr": (197, 14),
    "lremovexattr": (198, 15),
    "fremovexattr": (199, 16),
    "removexattrat": (466, 466),
    "file_setattr": (469, 469),
    # files created, written, removed (Landlock fences these too, where it exists)
    "creat": (85, None),
    "mknod": (133, None),
    "mknodat": (259, 33),
    "mkdir": (83, None),
    "mkdirat": (258, 34),
    "rmdir": (84, None),
    "unlink": (87, None),
    "unlinkat": (263, 35),
    "rename": (82, None),
    "renameat": (264, 38),
    "renameat2": (316, 276),
    "link": (86, None),
    "linkat": (265, 37),
    "symlink": (88, None),
    "symlinkat": (266, 36),
    "truncate": (76, 45),
    "ftruncate": (77, 46),
    "fallocate": (285, 47),
    "openat2": (437, 437),
    "open_by_handle_at": (304, 265),
    # other processes
    "ptrace": (101, 117),
    "process_vm_readv": (310, 270),
    "process_vm_writev": (311, 271),
    "pidfd_open": (434, 434),
    "pidfd_getfd": (438, 438),
    "pidfd_send_signal": (424, 424),
    "kcmp": (312, 272),
    "move_pages": (279, 239),
    "migrate_pages": (256, 238),
    "process_madvise": (440, 440),
    "process_mrelease": (448, 448),
    "setpriority": (141, 140),
    "sched_setaffinity": (203, 122),
    "sched_setscheduler": (144, 119),
    "sched_setparam": (142, 118),
    "sched_setattr": (314, 274),
    "ioprio_set": (251, 30),
    "shmget": (29, 194),
    "shmat": (30, 196),
    "shmctl": (31, 195),
    "semget": (64, 190),
    "semop": (65, 193),
    "semctl": (66, 191),
    "semtimedop": (220, 192),
    "msgget": (68, 186),
    "msgsnd": (69, 189),
    "msgrcv": (70, 188),
    "msgctl": (71, 187),
    "mq_open": (240, 180),
    "mq_unlink": (241, 181),
    # the kernel's keyring, log, namespaces and mounts
    "keyctl": (250, 219),
    "add_key": (248, 217),
    "request_key": (249, 218),
    "syslog": (103, 116),
    "bpf": (321, 280),
    "perf_event_open": (298, 241),
    "userfaultfd": (323, 282),
    "unshare": (272, 97),
    "setns": (308, 268),
    "mount": (165, 40),
    "umount2": (166, 39),
    "mount_setattr": (442, 442),
    "move_mount": (429, 429),
    "open_tree": (428, 428),
    "fsopen": (430, 430),
    "fsconfig": (431, 431),
    "fsmount": (432, 432),
    "fspick": (433, 433),
    "chroot": (161, 51),
    "pivot_root": (155, 41),
    # refused by their arguments only (see seccomp_program)
    "open": (2, None),
    "openat": (257, 56),
    "ioctl": (16, 29),
    "kill": (62, 129),
    "tkill": (200, 130),
    "tgkill": (234, 131),
    "rt_sigqueueinfo": (129, 138),
    "rt_tgsigqueueinfo": (297, 240),
    "prlimit64": (302, 261),
}
_NEWER = 470  # the first number this filter does not know: ENOSYS from here on
_AUDIT_ARCH = {"x86_64": 0xC000003E, "aarch64": 0xC00000B7}
_COLUMN = {"x86_64": 0, "aarch64": 1}

# Calls allowed only on the process itself (a first argument of 0 or its own pid).
_OWN_PROCESS = ("kill", "tkill", "tgkill", "rt_sigqueueinfo", "rt_tgsigqueueinfo", "prlimit64")
# open(path, flags) and openat(dirfd, path, flags): refused with any of these flags.
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC
_OPEN_FLAGS_ARGUMENT = {"open": 1, "openat": 2}
_TIOCSTI, _TIOCLINUX = 0x5412, 0x541C

_RET_ALLOW = 0x7FFF0000
_RET_ERRNO = 0x00050000
_RET_KILL_PROCESS = 0x80000000
_LOAD, _JEQ, _JGE, _JSET, _RET = 0x20, 0x15, 0x35, 0x45, 0x06  # BPF_LD|W|ABS, JMP|.. |K, RET|K
_NR, _ARCH = 0, 4


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
    """Both fences at once: system calls refused, reads only beneath ``readable``."""
    seccomp = forbid_system_calls()
    return Confinement(restrict_reads(readable), seccomp)


def forbid_system_calls() -> bool:
    """Refuse the system calls listed in the module docstring from now on; ``False`` where
    this system has no seccomp filter for them (not Linux x86-64 or arm64)."""
    resource.setrlimit(resource.RLIMIT_NPROC, (0, 0))
    machine = platform.machine()
    if platform.system() != "Linux" or machine not in _AUDIT_ARCH:
        return False
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return False
    program = seccomp_program(machine, os.getpid())

    class SockFilter(ctypes.Structure):
        _fields_ = (
            ("code", ctypes.c_uint16),
            ("jt", ctypes.c_uint8),
            ("jf", ctypes.c_uint8),
            ("k", ctypes.c_uint32),
        )

    class SockFprog(ctypes.Structure):
        _fields_ = (("len", ctypes.c_ushort), ("filter", ctypes.POINTER(SockFilter)))

    filters = (SockFilter * len(program))(*[SockFilter(*step) for step in program])
    fprog = SockFprog(len(program), filters)
    return bool(libc.prctl(_PR_SET_SECCOMP, _SECCOMP_MODE_FILTER, ctypes.byref(fprog), 0, 0) == 0)


def seccomp_program(machine: str, pid: int) -> list[tuple[int, int, int, int]]:
    """The classic-BPF filter for ``machine``, as (code, jump if true, jump if false, k) steps.

    Every jump is short (the next step or the one after): a refused call is a compare and a
    return; a call refused by its arguments is a small block that loads them and returns.
    """
    column = _COLUMN[machine]
    numbers: dict[str, int] = {}
    for name, row in _CALLS.items():
        number = row[column]
        if number is not None:  # fork, open... do not exist on arm64
            numbers[name] = number
    by_arguments = {"open", "openat", "ioctl", *_OWN_PROCESS}
    deny = (_RET, 0, 0, _RET_ERRNO | errno.EACCES)
    allow = (_RET, 0, 0, _RET_ALLOW)
    program = [
        (_LOAD, 0, 0, _ARCH),
        (_JEQ, 1, 0, _AUDIT_ARCH[machine]),
        (_RET, 0, 0, _RET_KILL_PROCESS),  # a foreign architecture: its numbers mean other calls
        (_LOAD, 0, 0, _NR),
        (_JGE, 0, 1, _NEWER),  # x32 calls (0x40000000 and up) included
        (_RET, 0, 0, _RET_ERRNO | errno.ENOSYS),
    ]
    for name, number in numbers.items():
        if name not in by_arguments:
            program += [(_JEQ, 0, 1, number), deny]
    for name, argument in _OPEN_FLAGS_ARGUMENT.items():
        if name in numbers:
            block = [(_LOAD, 0, 0, _argument(argument)), (_JSET, 0, 1, _WRITE_FLAGS), deny, allow]
            program += [(_LOAD, 0, 0, _NR), (_JEQ, 0, len(block), numbers[name]), *block]
    for name in _OWN_PROCESS:
        block = [(_LOAD, 0, 0, _argument(0)), (_JEQ, 2, 0, 0), (_JEQ, 1, 0, pid), deny, allow]
        program += [(_LOAD, 0, 0, _NR), (_JEQ, 0, len(block), numbers[name]), *block]
    block = [
        (_LOAD, 0, 0, _argument(1)),
        (_JEQ, 1, 0, _TIOCSTI),
        (_JEQ, 0, 1, _TIOCLINUX),
        deny,
        allow,
    ]
    program += [(_LOAD, 0, 0, _NR), (_JEQ, 0, len(block), numbers["ioctl"]), *block, allow]
    return program


def _argument(index: int) -> int:
    """Offset of the low 32 bits of system call argument ``index`` in ``seccomp_data``."""
    return 16 + 8 * index if sys.byteorder == "little" else 20 + 8 * index


def restrict_reads(readable: Sequence[str | Path]) -> int:
    """Allow only reading beneath ``readable`` from now on; the Landlock ABI, 0 if none."""
    if platform.system() != "Linux":
        return 0
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return 0
    return _landlock(libc, readable)


def _landlock(libc: Any, readable: Sequence[str | Path]) -> int:
    import ctypes

    class RulesetAttr(ctypes.Structure):
        _fields_ = (
            ("handled_access_fs", ctypes.c_uint64),
            ("handled_access_net", ctypes.c_uint64),
            ("scoped", ctypes.c_uint64),
        )

    class PathBeneathAttr(ctypes.Structure):
        _pack_ = 1  # the kernel's struct is packed: 12 bytes
        _fields_ = (("allowed_access", ctypes.c_uint64), ("parent_fd", ctypes.c_int32))

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
    attr = RulesetAttr(
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
                rule = PathBeneathAttr(rights, fd)
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


def forget_ctypes() -> None:
    """Drop ctypes from ``sys.modules``: an ``import ctypes`` after this fails.

    The fences are up; nothing in the child needs a foreign function again, and a module that
    is not in ``sys.modules`` cannot be handed out by ``__import__``.
    """
    for name in [n for n in sys.modules if n in ("ctypes", "_ctypes") or n.startswith("ctypes.")]:
        sys.modules[name] = None  # type: ignore[assignment]  # None blocks the import


def _existing(paths: Sequence[str | Path]) -> list[Path]:
    found: dict[str, Path] = {}
    for item in paths:
        try:
            resolved = Path(item).resolve(strict=True)
        except OSError:
            continue  # a folder that does not exist grants nothing
        found.setdefault(str(resolved), resolved)
    return list(found.values())
