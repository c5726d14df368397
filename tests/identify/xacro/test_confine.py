"""The kernel fence of the trusted-xacro child: escapes past the Python-level fence still fail."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify.xacro.compiler import XacroLimits, compile_xacro
from tests.conftest import ROOT

LIMITS = XacroLimits(cpu_seconds=5, memory_bytes=512 * 2**20, wall_seconds=20.0)

# Reaches xacro's module globals (and through them `os`, `sys` and every loaded module) using
# only names xacro's expression check lets through.
ESCAPE = (
    "python.vars(python.type(python.vars(python.type(xacro.load_yaml))['__globals__']))"
    "['__get__'](python.vars(python.type(xacro.load_yaml))['__globals__'], "
    "xacro.load_yaml)"
)

PROBE = """
import json, os, socket, subprocess, sys
from solver.identify.xacro.confine import confine
allowed, outside, target = sys.argv[1:4]
tcp = socket.socket()  # made before the fence: Landlock alone must stop its connect
confined = confine([allowed, *sys.path])
def attempt(action):
    try:
        action()
    except OSError as error:
        return type(error).__name__
    return "done"
def fork():
    if os.fork() == 0:
        os._exit(0)
print(json.dumps({
    "abi": confined.landlock_abi,
    "seccomp": confined.seccomp,
    "read inside": attempt(lambda: open(os.path.join(allowed, "inside.txt")).read()),
    "read outside": attempt(lambda: open(outside).read()),
    "create inside": attempt(lambda: open(os.path.join(allowed, "new.txt"), "w").close()),
    "mknod": attempt(lambda: os.mknod(target)),
    "execute": attempt(lambda: os.execv("/bin/true", ["true"])),
    "tcp connect": attempt(lambda: tcp.connect(("127.0.0.1", 9))),
    "udp socket": attempt(lambda: socket.socket(socket.AF_INET, socket.SOCK_DGRAM)),
    "unix socket": attempt(lambda: socket.socket(socket.AF_UNIX)),
    "fork": attempt(fork),
    "process": attempt(lambda: subprocess.run(["/bin/true"], check=True)),
}))
"""


@pytest.fixture(scope="module")
def landlock() -> int:
    """The Landlock ABI this kernel offers; the tests that need it skip without it."""
    code = "from solver.identify.xacro.confine import confine; print(confine([]).landlock_abi)"
    done = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=True,
        timeout=120,
    )
    abi = int(done.stdout)
    if abi == 0:
        pytest.skip("this kernel has no Landlock")
    return abi


def probe(tmp_path: Path) -> dict[str, object]:
    allowed = tmp_path / "package"
    allowed.mkdir()
    (allowed / "inside.txt").write_text("inside")
    outside = tmp_path / "secret.txt"
    outside.write_text("secret")
    done = subprocess.run(
        [sys.executable, "-c", PROBE, str(allowed), str(outside), str(tmp_path / "MARKER")],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=True,
        timeout=120,
    )
    answer: dict[str, object] = json.loads(done.stdout)
    return answer


@pytest.mark.usefixtures("landlock")
def test_a_confined_process_reads_only_beneath_its_folders_and_writes_and_runs_nothing(
    tmp_path: Path,
) -> None:
    answer = probe(tmp_path)
    assert answer["read inside"] == "done"
    assert answer["read outside"] == "PermissionError"
    assert answer["create inside"] == "PermissionError"
    assert answer["mknod"] == "PermissionError"
    assert answer["execute"] == "PermissionError"
    assert not (tmp_path / "MARKER").exists()
    assert not (tmp_path / "package" / "new.txt").exists()


def test_a_confined_process_opens_no_socket_and_starts_no_process_where_seccomp_applies(
    tmp_path: Path,
) -> None:
    answer = probe(tmp_path)
    if not answer["seccomp"]:
        pytest.skip("no seccomp filter on this system (not Linux x86-64 or arm64)")
    assert answer["udp socket"] == "PermissionError"
    assert answer["unix socket"] == "PermissionError"
    assert answer["fork"] == "PermissionError"
    assert answer["process"] == "PermissionError"


def test_a_confined_process_connects_no_tcp_socket_on_landlock_4_and_later(
    landlock: int, tmp_path: Path
) -> None:
    if landlock < 4:
        pytest.skip("Landlock before ABI 4 does not handle TCP")
    assert probe(tmp_path)["tcp connect"] == "PermissionError"


def escaping(body: str) -> str:
    return (
        '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        f'  <xacro:property name="g" value="${{{ESCAPE}}}"/>\n  {body}\n</robot>\n'
    )


# Each reaches a file function the Python-level fence does not replace.
ESCAPES = {
    "io-open": "<link name=\"${{g['sys'].modules['_io'].open('{marker}', 'w') and 'x'}}\"/>",
    "mknod": "<link name=\"${{g['os'].mknod('{marker}') or 'x'}}\"/>",
    "lxml-write": (
        "<link name=\"${{g['sys'].modules['lxml.etree'].ElementTree(g['sys']"
        ".modules['lxml.etree'].Element('a')).write('{marker}') or 'x'}}\"/>"
    ),
}


@pytest.mark.usefixtures("landlock")
@pytest.mark.parametrize("escape", sorted(ESCAPES))
def test_a_trusted_xacro_that_escapes_the_python_fence_still_writes_no_file(
    escape: str, tmp_path: Path
) -> None:
    marker = tmp_path / "MARKER"
    path = tmp_path / "evil.xacro"
    path.write_text(escaping(ESCAPES[escape].format(marker=marker)))
    with pytest.raises(InputError, match="Permission denied") as caught:
        compile_xacro(path, limits=LIMITS)
    assert caught.value.faults[0].location.file == str(path)
    assert not marker.exists()


@pytest.mark.usefixtures("landlock")
def test_a_trusted_xacro_that_escapes_the_python_fence_still_reads_no_file_outside(
    tmp_path: Path,
) -> None:
    secret = tmp_path / "secret.xml"
    secret.write_text("<secret>hunter2</secret>")
    (tmp_path / "pkg").mkdir()
    path = tmp_path / "pkg" / "evil.xacro"
    path.write_text(
        escaping(
            "<link name=\"${g['sys'].modules['lxml.etree'].parse('" + str(secret) + "')"
            '.getroot().text}"/>'
        )
    )
    with pytest.raises(InputError, match="Permission denied") as caught:
        compile_xacro(path, limits=LIMITS)
    assert "hunter2" not in str(caught.value)


@pytest.mark.usefixtures("landlock")
def test_a_trusted_xacro_eval_that_runs_arbitrary_python_still_writes_no_file(
    tmp_path: Path,
) -> None:
    # $(eval) evaluates with Python's builtins; a property holding code gets past its lexer (no
    # ')' inside) and exec of hex-encoded code past its only check (no double underscore).
    marker = tmp_path / "MARKER"
    code = f"__import__('os').mknod({str(marker)!r})".encode().hex()
    path = tmp_path / "evil.xacro"
    path.write_text(
        escaping(
            f'<xacro:property name="c" value="exec(bytes.fromhex(\'{code}\')'
            '.decode()) or \'x\'"/>\n  <link name="$(eval ${c})"/>'
        )
    )
    with pytest.raises(InputError, match="Permission denied"):
        compile_xacro(path, limits=LIMITS)
    assert not marker.exists()
