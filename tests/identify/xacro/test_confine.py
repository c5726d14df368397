"""The kernel fences of the trusted-xacro child hold by themselves, as if the guards were escaped.

Each probe is a real process that raises the fences of :mod:`solver.identify.xacro.confine` and
then does, with the full Python at hand, what an escaped expression would: every attempt must
fail, no marker file may appear, and the file outside the allowed folder must be unchanged.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from solver.identify.xacro.confine import seccomp_program
from tests.conftest import ROOT

PROBE = r"""
import ctypes, errno, json, os, resource, socket, subprocess, sys, threading
from solver.identify.xacro.confine import (
    _CALLS, _COLUMN, confine, forbid_system_calls, restrict_reads,
)
mode, allowed, outside, marker = sys.argv[1:5]
library = os.path.join(os.path.dirname(os.__file__), "os.py")
tcp = socket.socket()  # made before the fences: Landlock alone must stop its connect
libc = ctypes.CDLL(None, use_errno=True)
if mode == "both":
    confined = confine([allowed])
    answer = {"abi": confined.landlock_abi, "seccomp": confined.seccomp}
elif mode == "seccomp":
    answer = {"abi": 0, "seccomp": forbid_system_calls()}
else:
    answer = {"abi": restrict_reads([allowed]), "seccomp": False}


def attempt(action):
    try:
        action()
    except Exception as error:
        return type(error).__name__
    return "done"


def fork():
    if os.fork() == 0:
        os._exit(0)
    os.wait()


def raw(number):
    ctypes.set_errno(0)
    result = libc.syscall(ctypes.c_long(number), 0, 0, 0, 0, 0, 0)
    return errno.errorcode.get(ctypes.get_errno(), str(result)) if result == -1 else "done"


column = _COLUMN.get(os.uname().machine)
answer.update({
    "read inside": attempt(lambda: open(os.path.join(allowed, "inside.txt")).read()),
    "read outside": attempt(lambda: open(outside).read()),
    "read the standard library": attempt(lambda: open(library).read()),
    "list outside": attempt(lambda: os.listdir(os.path.dirname(outside))),
    "create inside": attempt(lambda: open(os.path.join(allowed, "new.txt"), "w").close()),
    "append outside": attempt(lambda: open(outside, "a").write("x")),
    "truncate outside": attempt(lambda: os.truncate(outside, 0)),
    "mknod": attempt(lambda: os.mknod(marker)),
    "mkdir": attempt(lambda: os.mkdir(marker)),
    "symlink": attempt(lambda: os.symlink(outside, marker)),
    "link": attempt(lambda: os.link(outside, marker)),
    "rename": attempt(lambda: os.rename(outside, marker)),
    "unlink": attempt(lambda: os.unlink(outside)),
    "chmod": attempt(lambda: os.chmod(outside, 0o777)),
    "utime": attempt(lambda: os.utime(outside, (0, 0))),
    "lchown": attempt(lambda: os.lchown(outside, os.getuid(), os.getgid())),
    "setxattr": attempt(lambda: os.setxattr(outside, "user.teleop", b"x")),
    "execute": attempt(lambda: os.execv("/bin/true", ["true"])),
    "fork": attempt(fork),
    "process": attempt(lambda: subprocess.run(["/bin/true"], check=True)),
    "thread": attempt(lambda: threading.Thread(target=print).start()),
    "tcp connect": attempt(lambda: tcp.connect(("127.0.0.1", 9))),
    "udp socket": attempt(lambda: socket.socket(socket.AF_INET, socket.SOCK_DGRAM)),
    "unix socket": attempt(lambda: socket.socket(socket.AF_UNIX)),
    "signal the parent": attempt(lambda: os.kill(os.getppid(), 0)),
    "limits of the parent": attempt(
        lambda: resource.prlimit(os.getppid(), resource.RLIMIT_NOFILE)
    ),
    "own limits": attempt(lambda: resource.getrlimit(resource.RLIMIT_NOFILE)),
    "newer call": raw(500),
})
# Every call refused outright, made raw with zero arguments: the filter answers before the
# kernel looks at them (process-starting calls are left to the attempts above).
starting = {"fork", "vfork", "clone", "clone3"}
by_arguments = {"open", "openat", "ioctl", "kill", "tkill", "tgkill", "rt_sigqueueinfo",
                "rt_tgsigqueueinfo", "prlimit64"}
if answer["seccomp"] and column is not None:
    answer["raw"] = {
        name: raw(row[column])
        for name, row in _CALLS.items()
        if row[column] is not None and name not in starting | by_arguments
    }
print(json.dumps(answer))
"""


def probe(tmp_path: Path, mode: str) -> dict[str, object]:
    allowed = tmp_path / "package"
    allowed.mkdir()
    (allowed / "inside.txt").write_text("inside")
    outside = tmp_path / "secret.txt"
    outside.write_text("secret")
    os.chmod(outside, 0o640)
    os.utime(outside, (1_000_000_000, 1_000_000_000))
    done = subprocess.run(
        [sys.executable, "-c", PROBE, mode, str(allowed), str(outside), str(tmp_path / "MARKER")],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=True,
        timeout=120,
    )
    answer: dict[str, object] = json.loads(done.stdout)
    assert not (tmp_path / "MARKER").exists()
    assert not (allowed / "new.txt").exists()
    assert outside.read_text() == "secret"
    if answer["seccomp"]:  # Landlock alone does not fence a file's mode, owner or times
        status = outside.stat()
        assert (status.st_mode & 0o777, status.st_mtime) == (0o640, 1_000_000_000)
    return answer


def skip_without(answer: dict[str, object], fence: str) -> None:
    if fence == "landlock" and not answer["abi"]:
        pytest.skip("this kernel has no Landlock")
    if fence == "seccomp" and not answer["seccomp"]:
        pytest.skip("no seccomp filter on this system (not Linux x86-64 or arm64)")


WRITES = (
    *("create inside", "append outside", "truncate outside", "mknod", "mkdir", "symlink"),
    *("link", "rename", "unlink"),
)
METADATA = ("chmod", "utime", "lchown", "setxattr")
PROCESSES = ("execute", "fork", "process", "thread")
OTHERS = ("signal the parent", "limits of the parent")


def test_both_fences_read_only_beneath_the_package_and_write_touch_run_nothing(
    tmp_path: Path,
) -> None:
    answer = probe(tmp_path, "both")
    skip_without(answer, "landlock")
    skip_without(answer, "seccomp")
    assert answer["read inside"] == "done"
    assert answer["own limits"] == "done"
    # The interpreter's own library is outside too: only the package folders are readable.
    for attempt in ("read outside", "read the standard library", "list outside"):
        assert answer[attempt] == "PermissionError", attempt
    for attempt in (*WRITES, *METADATA, *OTHERS, "execute", "fork", "process"):
        assert answer[attempt] == "PermissionError", attempt
    assert answer["thread"] == "RuntimeError"  # "can't start new thread": clone refused
    assert answer["udp socket"] == answer["unix socket"] == "PermissionError"


def test_seccomp_alone_refuses_writes_metadata_processes_and_other_processes(
    tmp_path: Path,
) -> None:
    # A kernel without Landlock still refuses every write and every change to a file's
    # metadata (Landlock never fenced chmod, utime, chown or extended attributes).
    answer = probe(tmp_path, "seccomp")
    skip_without(answer, "seccomp")
    assert answer["read inside"] == answer["own limits"] == "done"
    for attempt in (*WRITES, *METADATA, *OTHERS, "execute", "fork", "process"):
        assert answer[attempt] == "PermissionError", attempt
    assert answer["thread"] == "RuntimeError"
    assert answer["udp socket"] == answer["unix socket"] == "PermissionError"


def test_seccomp_refuses_every_listed_call_and_calls_newer_than_itself(tmp_path: Path) -> None:
    answer = probe(tmp_path, "seccomp")
    skip_without(answer, "seccomp")
    raw = answer["raw"]
    assert isinstance(raw, dict)
    assert raw
    assert {name: code for name, code in raw.items() if code != "EACCES"} == {}
    assert answer["newer call"] == "ENOSYS"


def test_landlock_alone_reads_only_beneath_the_package_and_connects_no_tcp(
    tmp_path: Path,
) -> None:
    answer = probe(tmp_path, "landlock")
    skip_without(answer, "landlock")
    assert answer["read inside"] == "done"
    for attempt in ("read outside", "read the standard library", "create inside", "mknod"):
        assert answer[attempt] == "PermissionError", attempt
    if isinstance(answer["abi"], int) and answer["abi"] >= 4:
        assert answer["tcp connect"] == "PermissionError"


@pytest.mark.parametrize("machine", ["x86_64", "aarch64"])
def test_every_jump_of_the_filter_lands_inside_it(machine: str) -> None:
    # Classic BPF jumps forward only, by at most 255; a jump past the end is refused by the
    # kernel. The program for the machine this test does not run on is checked here.
    program = seccomp_program(machine, 4242)
    jumps = [(at, step) for at, step in enumerate(program) if step[0] in (0x15, 0x35, 0x45)]
    assert jumps
    for at, (_, true, false, _) in jumps:
        assert at + 1 + max(true, false) < len(program)
    assert program[-1] == (0x06, 0, 0, 0x7FFF0000)  # what is not refused is allowed
    assert len(program) < 4096
