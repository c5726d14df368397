"""A stranger's file given to any command, tried as an attacker would: a file that never ends,
values that were tracebacks, names, lines and files too large, YAML nested a million deep, and
files that are not regular files; each ends with a located error (exit 2), never a traceback,
a runaway read or a wait for a writer.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli.hostile import (
    FILE_READERS,
    YAML_READERS,
    assert_located_refusal,
    reader_line,
    run_main,
    team_file,
    with_paper_rules,
)
from tests.conftest import ROOT, run_cli

# ---- unbounded reads ------------------------------------------------------------------------


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_batch_refuses_a_rules_file_that_never_ends_without_reading_it(
    tmp_path: Path, device: str
) -> None:
    team_file(tmp_path, rules=device)
    result = run_cli("batch", tmp_path / "team.yaml", "-o", tmp_path / "out")
    assert result.returncode == 1, result.stderr  # the team failed; the batch itself ran
    assert "Traceback" not in result.stderr
    assert "internal error" not in result.stderr
    assert f"cannot use rules file '{device}'" in result.stderr
    assert "is a character device, not a YAML file" in result.stderr


# ---- tracebacks that were ----------------------------------------------------------------


def test_a_nul_byte_in_the_rules_path_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, rules='"a\\0b"')
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:2:8: rules:")
    # Text holds no NUL (issue 36.14b): the YAML reader refuses it before any path is made.
    assert "contains a NUL character (\\0); not text" in result.stderr


def test_a_number_of_5000_digits_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name="9" * 5000)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "number too large" in result.stderr


def test_a_hexadecimal_number_too_large_to_print_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name="0x" + "f" * 5000)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")


def test_a_surrogate_escape_in_a_name_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name='"robot \\udcff"')
    result = run_cli("report", tmp_path / "team.yaml", "-o", tmp_path / "r.html")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:")
    assert not (tmp_path / "r.html").exists()


def test_a_characteristic_without_a_name_is_a_located_error(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text("characteristics:\n  kind: {values: [A, B]}\n  '': {values: [x]}\n")
    (tmp_path / "t.yaml").write_text("rules: r.yaml\nteam:\n  A: {}\n")
    result = run_cli("solve", tmp_path / "t.yaml")
    assert_located_refusal(
        result,
        f"{rules}:3:3: characteristics.: a characteristic needs a "
        "name of visible characters, got ''",
    )
    assert run_cli("check", rules).returncode == 1  # check: the same fault, as a finding


@pytest.mark.parametrize("command", ["batch", "report-html", "report-md", "solve"])
def test_a_file_name_that_is_not_utf8_is_no_traceback(tmp_path: Path, command: str) -> None:
    with_paper_rules(tmp_path)
    team = Path(os.fsdecode(bytes(tmp_path) + b"/t\xff\x1b.yaml"))
    team_file(tmp_path, file=team.name)
    args: dict[str, list[str | Path]] = {
        "batch": ["batch", team, "-o", tmp_path / "out"],
        "report-html": ["report", team, "-o", tmp_path / "r\udcff.html"],
        "report-md": ["report", team, "-o", tmp_path / "r\udcff.md"],
        "solve": ["solve", team, "--format", "csv"],
    }
    result = subprocess.run(
        [sys.executable, "-m", "solver", *map(os.fsencode, args[command])],
        capture_output=True,
        cwd=ROOT,
        check=False,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    assert b"Traceback" not in result.stderr
    assert b"\x1b" not in result.stdout + result.stderr  # shown as the text "\x1b"


# ---- sizes: names, lines, whole files ------------------------------------------------------


def test_a_15_megabyte_team_name_is_refused_at_its_line(tmp_path: Path) -> None:
    team_file(tmp_path, name="x" * 15_000_000)
    result = run_cli("report", tmp_path / "team.yaml", "-o", tmp_path / "r.html")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "longer than 10000 characters" in result.stderr
    assert len(result.stderr) < 1000


def test_a_name_longer_than_200_characters_is_refused(tmp_path: Path) -> None:
    team_file(tmp_path, name="x" * 201)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "team name is longer than 200 characters" in result.stderr


def test_a_15_megabyte_flow_style_line_is_refused_before_it_is_built(tmp_path: Path) -> None:
    path = tmp_path / "team.yaml"
    entries = ", ".join(f"a{i}: b" for i in range(1_500_000))
    path.write_text("name: t\nteam: {" + entries[:15_000_000] + "}\n")
    result = run_cli("solve", path)
    assert_located_refusal(result, f"{path}:2:")
    assert "more than 200000 values" in result.stderr


# ---- nesting: every YAML reader -------------------------------------------------------------

# A block nest composed by libyaml ended the process with SIGSEGV; a flow nest was quadratic.
DEEP_YAML = {"block": "- " * 50_000 + "x\n", "flow": "[" * 1_000_000 + "\n"}


@pytest.mark.parametrize("reader", list(YAML_READERS))
def test_a_block_nest_50000_deep_is_refused_by_every_reader(tmp_path: Path, reader: str) -> None:
    deep = tmp_path / "deep.yaml"
    deep.write_text(DEEP_YAML["block"])
    result = run_cli(*reader_line(reader, tmp_path, deep))  # a process: a signal is the point
    assert result.returncode in (1, 2), result.stderr  # 1: batch's failed row
    assert "Traceback" not in result.stderr
    assert f"{deep}:1:131: nested more than 64 levels deep; refused" in result.stderr


@pytest.mark.parametrize("reader", list(YAML_READERS))
def test_a_flow_nest_a_million_deep_is_refused_by_every_reader(
    tmp_path: Path, reader: str, capsys: pytest.CaptureFixture[str]
) -> None:
    deep = tmp_path / "deep.yaml"
    deep.write_text(DEEP_YAML["flow"])
    assert run_main(*reader_line(reader, tmp_path, deep)) in (1, 2)
    assert f"{deep}:1:66: nested more than 64 levels deep; refused" in capsys.readouterr().err


# ---- files that are not regular files: every reader -----------------------------------------


def ends(line: list[str], stdin: int | None = None) -> subprocess.CompletedProcess[str]:
    """``line`` as a process that must end by itself (60 s: a last-resort ceiling; a refusal
    takes a fraction of a second, a hang never ends)."""
    return subprocess.run(
        [sys.executable, "-m", "solver", *line],
        stdin=subprocess.DEVNULL if stdin is None else stdin,
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=False,
        timeout=60,
    )


def refused_as_no_regular_file(reader: str, file: Path, kind: str) -> str:
    """The start of the message that refuses ``file``, of ``kind``, given to ``reader``."""
    if reader != "batch" or file == Path("/dev/stdin"):
        return f"{file}: is {kind}, not a "
    if kind == "a directory":  # batch reads the teams in a folder
        return f"{file}: folder holds no .yaml or .yml file"
    return f"{file}: not a regular file or folder"


@pytest.mark.parametrize("reader", list(FILE_READERS))
def test_a_fifo_is_refused_by_every_reader_without_waiting_for_a_writer(
    tmp_path: Path, reader: str
) -> None:
    fifo = tmp_path / "hostile"
    os.mkfifo(fifo)
    result = ends(reader_line(reader, tmp_path, fifo))  # opening it for reading waited forever
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith(refused_as_no_regular_file(reader, fifo, "a pipe (FIFO)"))


@pytest.mark.parametrize("reader", ["solve", "check", "identify", "identify --topics"])
def test_standard_input_from_a_pipe_that_never_ends_is_refused(tmp_path: Path, reader: str) -> None:
    # `sleep 30 | teleop-ui solve /dev/stdin`: the writer holds the pipe open and sends nothing.
    stdin = Path("/dev/stdin")
    read_end, write_end = os.pipe()
    try:
        result = ends(reader_line(reader, tmp_path, stdin), stdin=read_end)
    finally:
        os.close(read_end)
        os.close(write_end)
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith(refused_as_no_regular_file(reader, stdin, "a pipe (FIFO)"))


@pytest.mark.parametrize("kind", ["a directory", "a character device", "a socket"])
@pytest.mark.parametrize("reader", list(FILE_READERS))
def test_a_folder_a_device_or_a_socket_is_refused_by_every_reader(
    tmp_path: Path,
    reader: str,
    kind: str,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    special = {"a directory": tmp_path / "folder", "a character device": Path("/dev/zero")}
    if kind == "a directory":
        special[kind].mkdir()
    with socket.socket(socket.AF_UNIX) as server:
        if kind == "a socket":
            monkeypatch.chdir(tmp_path)  # a socket's path is short (108 bytes): a relative one
            server.bind("hostile")
            special[kind] = tmp_path / "hostile"
        assert run_main(*reader_line(reader, tmp_path, special[kind])) == 2
    error = capsys.readouterr().err
    assert error.startswith(refused_as_no_regular_file(reader, special[kind], kind)), error
