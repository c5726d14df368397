"""Atomic writes replace a regular file or make a new one, and nothing else; all files or none,
no temporary left (Ctrl-C and SIGTERM included), and no more bytes than ``written-bytes``."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path

import pytest

from solver import limits
from solver.errors import InputError, TooLargeError
from solver.files.atomic import (
    link_inside,
    make_folder,
    overwrite,
    remove_output,
    remove_temporaries,
    write_all_atomic,
    write_atomic,
)
from tests.conftest import ROOT


def test_a_file_is_written_and_a_regular_file_replaced(tmp_path: Path) -> None:
    target = tmp_path / "team.yaml"
    write_atomic(target, "first\n")
    write_atomic(target, "second\n")
    assert target.read_text() == "second\n"
    assert os.listdir(tmp_path) == ["team.yaml"]  # no temporary left behind


def test_a_rewritten_file_keeps_its_permissions_and_a_new_one_gets_0644(tmp_path: Path) -> None:
    kept, new = tmp_path / "kept.txt", tmp_path / "new.txt"
    kept.write_text("old")
    kept.chmod(0o640)
    write_all_atomic({kept: "first\n", new: b"second\n"})
    assert (kept.read_text(), new.read_text()) == ("first\n", "second\n")
    assert (kept.stat().st_mode & 0o777, new.stat().st_mode & 0o777) == (0o640, 0o644)
    assert sorted(os.listdir(tmp_path)) == ["kept.txt", "new.txt"]


def test_a_name_near_the_systems_limit_still_has_room_for_its_temporary(tmp_path: Path) -> None:
    # The temporary was named after the target and 13 more characters: past 255 bytes.
    target = tmp_path / ("r" * 250 + ".md")
    write_atomic(target, "report\n")
    assert target.read_text() == "report\n"


@pytest.mark.parametrize("kind", ["a fifo", "a link to a device", "a link to a file", "a folder"])
def test_what_is_no_regular_file_is_refused_and_left_as_it_was(tmp_path: Path, kind: str) -> None:
    target = tmp_path / "out.json"
    (tmp_path / "elsewhere").write_text("theirs\n")
    if kind == "a fifo":
        os.mkfifo(target)
    elif kind == "a folder":
        target.mkdir()
    else:
        target.symlink_to("/dev/null" if kind == "a link to a device" else tmp_path / "elsewhere")
    with pytest.raises(InputError) as caught:
        write_all_atomic({tmp_path / "fine.json": "{}", target: "{}"})
    assert str(caught.value).startswith(f"{target}: is a")
    assert target.is_fifo() or target.is_symlink() or target.is_dir()
    assert (tmp_path / "elsewhere").read_text() == "theirs\n"
    assert not (tmp_path / "fine.json").exists()  # all or nothing


def test_an_output_folder_is_made_or_refused_when_a_file_is_there(tmp_path: Path) -> None:
    assert make_folder(tmp_path / "a" / "b").is_dir()
    (tmp_path / "notes.txt").write_text("mine\n")
    with pytest.raises(InputError) as caught:
        make_folder(tmp_path / "notes.txt")
    assert str(caught.value) == (
        f"{tmp_path / 'notes.txt'}: is not a folder: give a folder to write into"
    )
    with pytest.raises(InputError, match="cannot make this folder: Not a directory"):
        make_folder(tmp_path / "notes.txt" / "inside")
    with pytest.raises(InputError, match="cannot make this folder: File name too long"):
        make_folder(tmp_path / ("x" * 300))


def _lower(monkeypatch: pytest.MonkeyPatch, name: str, value: int) -> None:
    # pylint: disable=protected-access
    monkeypatch.setitem(limits._BY_NAME, name, replace(limits.limit(name), value=value))


def test_chunks_are_written_as_the_same_file_as_the_whole_text(tmp_path: Path) -> None:
    whole, chunked = tmp_path / "whole.txt", tmp_path / "chunked.txt"
    write_atomic(whole, "ab\ncd é\n")
    chunks: list[str | bytes] = ["ab\n", "cd ", b"\xc3\xa9", "\n"]
    write_atomic(chunked, iter(chunks))
    assert chunked.read_bytes() == whole.read_bytes() == "ab\ncd é\n".encode()


def test_whole_contents_past_written_bytes_are_refused_before_any_file_is_made(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _lower(monkeypatch, "written-bytes", 10)
    write_all_atomic({tmp_path / "a": "12345", tmp_path / "b": "67890"})  # 10 bytes: accepted
    with pytest.raises(TooLargeError) as caught:
        write_all_atomic({tmp_path / "c": "12345", tmp_path / "d": "678901"})
    assert "11 bytes to write; at most 10 are accepted (limit 'written-bytes'" in str(caught.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a", "b"]


def test_chunks_past_written_bytes_stop_the_write_and_change_no_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _lower(monkeypatch, "written-bytes", 10)
    kept = tmp_path / "kept.txt"
    kept.write_text("old")
    made: list[int] = []

    def endless() -> Iterator[str]:
        while True:
            made.append(1)
            yield "1234"

    with pytest.raises(TooLargeError, match=r"14 bytes or more to write; at most 10 are"):
        write_all_atomic({tmp_path / "new.txt": "ab", kept: endless()})
    assert len(made) == 3  # the chunk past the limit is the last one asked for
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept.txt"]
    assert kept.read_text() == "old"


_SLOW_WRITER = """
import sys, time
from solver.files.atomic import write_all_atomic

def chunks(marker):
    yield "first part\\n"
    open(marker, "w").close()  # the test waits for this: a temporary exists now
    while True:
        time.sleep(0.05)
        yield "more\\n"

folder = sys.argv[1]
write_all_atomic({folder + "/a.txt": "done", folder + "/b.txt": chunks(folder + "/../marker")})
"""


@pytest.mark.parametrize(
    ("sent", "status"),
    [(signal.SIGTERM, 1), (signal.SIGINT, -signal.SIGINT)],
    ids=["SIGTERM", "SIGINT"],
)
def test_a_write_stopped_by_a_signal_leaves_no_temporary_and_no_file(
    tmp_path: Path, sent: signal.Signals, status: int
) -> None:
    folder = tmp_path / "out"
    folder.mkdir()
    marker = tmp_path / "marker"
    process = subprocess.Popen(
        [sys.executable, "-c", _SLOW_WRITER, str(folder)],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        while not marker.exists():  # the event: both temporaries exist
            assert process.poll() is None, process.stderr.read() if process.stderr else ""
            time.sleep(0.01)
        assert any(path.name.endswith(".tmp") for path in folder.iterdir())
        process.send_signal(sent)
        _, stderr = process.communicate(timeout=60)
    finally:
        process.kill()
    # The exception (Terminated, KeyboardInterrupt) unwound the write and ended the script.
    assert process.returncode == status, stderr
    assert ("Terminated" if sent == signal.SIGTERM else "KeyboardInterrupt") in stderr
    assert list(folder.iterdir()) == []


def test_what_a_write_killed_outright_left_is_removed_and_nothing_else(tmp_path: Path) -> None:
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / "b.txt").write_text("old")
    others = [".b.txt.notes", ".b.txt.tmp", "b.txt.abcdefgh.tmp", ".c.txt.abcdefgh.tmp"]
    for name in others:
        (folder / name).write_text("someone else's")
    marker = tmp_path / "marker"
    process = subprocess.Popen(
        [sys.executable, "-c", _SLOW_WRITER, str(folder)],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        while not marker.exists():  # the event: both temporaries exist
            assert process.poll() is None, process.stderr.read() if process.stderr else ""
            time.sleep(0.01)
        process.kill()  # SIGKILL: no unwinding, the temporaries stay
        process.communicate(timeout=60)
    finally:
        process.kill()
    left = sorted(path.name for path in folder.iterdir() if path.name not in others)
    assert [name[:7] for name in left] == [".a.txt.", ".b.txt.", "b.txt"]  # a temporary each
    removed = remove_temporaries(folder / "a.txt") + remove_temporaries(folder / "b.txt")
    assert len(removed) == 2
    assert sorted(path.name for path in folder.iterdir()) == sorted([*others, "b.txt"])
    assert (folder / "b.txt").read_text() == "old"


# ---- links inside an output folder (issue 36.10) ----------------------------------------------


def _planted(tmp_path: Path) -> tuple[Path, Path]:
    """An output folder ``out`` whose ``teams`` someone else replaced by a link to a folder of
    theirs, ``elsewhere`` (which holds a file of its own)."""
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (elsewhere / "x.json").write_text("theirs\n")
    (out / "teams").symlink_to(elsewhere, target_is_directory=True)
    return out, elsewhere


def test_a_folder_link_planted_inside_the_output_folder_is_not_written_through(
    tmp_path: Path,
) -> None:
    out, elsewhere = _planted(tmp_path)
    with pytest.raises(InputError) as caught:
        write_all_atomic(
            {out / "summary.csv": "a\n", out / "teams" / "x.json": "{}", out / "teams" / "y": "{}"},
            within=out,
        )
    assert str(caught.value) == (
        f"{out / 'teams'}: is a link inside the output folder; refused: a write never "
        "follows a link there (someone else may have put it there)"
    )
    assert sorted(p.name for p in elsewhere.iterdir()) == ["x.json"]
    assert (elsewhere / "x.json").read_text() == "theirs\n"
    assert sorted(p.name for p in out.iterdir()) == ["teams"]  # all or nothing


def test_a_link_deeper_down_is_refused_and_the_folders_above_it_are_made(tmp_path: Path) -> None:
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    (out / "teams").mkdir(parents=True)
    elsewhere.mkdir()
    (out / "teams" / "a").symlink_to("../../elsewhere")  # relative: the same place
    with pytest.raises(InputError, match=r"teams/a: is a link inside the output folder"):
        write_atomic(out / "teams" / "a" / "b" / "x.json", "{}", within=out)
    assert list(elsewhere.iterdir()) == []
    write_atomic(out / "teams" / "c" / "d" / "x.json", "{}", within=out)  # no link: made
    assert (out / "teams" / "c" / "d" / "x.json").read_text() == "{}"


def test_the_output_folder_itself_may_be_a_link_the_user_gave(tmp_path: Path) -> None:
    real = tmp_path / "real"
    real.mkdir()
    given = tmp_path / "given"
    given.symlink_to(real, target_is_directory=True)
    write_atomic(given / "teams" / "x.json", "{}", within=given)
    assert (real / "teams" / "x.json").read_text() == "{}"


def test_a_folder_swapped_for_a_link_while_a_file_is_written_still_gets_the_file(
    tmp_path: Path,
) -> None:
    # The folder is opened once, without following a link, and the file is made and renamed
    # in that open folder: a link put in its place halfway through the write changes nothing.
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    (out / "teams").mkdir(parents=True)
    elsewhere.mkdir()

    def chunks() -> Iterator[str]:
        yield "{"
        (out / "teams").rename(out / "kept")
        (out / "teams").symlink_to(elsewhere, target_is_directory=True)
        yield "}"

    write_atomic(out / "teams" / "x.json", chunks(), within=out)
    assert list(elsewhere.iterdir()) == []
    assert [p.name for p in (out / "kept").iterdir()] == ["x.json"]
    assert (out / "kept" / "x.json").read_text() == "{}"


def test_removing_an_output_never_goes_through_a_link_inside_the_output_folder(
    tmp_path: Path,
) -> None:
    out, elsewhere = _planted(tmp_path)
    (elsewhere / ".x.json.abcdefgh.tmp").write_text("theirs too\n")
    assert remove_output(out / "teams" / "x.json", within=out) is False
    assert remove_temporaries(out / "teams" / "x.json", within=out) == []
    assert sorted(p.name for p in elsewhere.iterdir()) == [".x.json.abcdefgh.tmp", "x.json"]
    (out / "own").mkdir()
    (out / "own" / "x.json").write_text("ours\n")
    assert remove_output(out / "own" / "x.json", within=out) is True
    assert remove_output(out / "own" / "x.json", within=out) is False  # gone already
    assert list((out / "own").iterdir()) == []


def test_a_link_on_the_way_to_an_output_is_found_without_following_it(tmp_path: Path) -> None:
    out, _ = _planted(tmp_path)
    (out / "own").mkdir()
    (out / "own" / "x.json").symlink_to(tmp_path / "elsewhere" / "x.json")
    assert link_inside(out / "teams" / "x.json", within=out) == out / "teams"
    assert link_inside(out / "own" / "x.json", within=out) == out / "own" / "x.json"
    assert link_inside(out / "own" / "y.json", within=out) is None  # nothing there yet
    assert link_inside(out / "summary.csv", within=out) is None


# ---- overwrite: a record written in place (a batch stamp) -------------------------------------


def test_overwrite_makes_a_file_and_writes_over_a_longer_one_keeping_its_permissions(
    tmp_path: Path,
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    overwrite(out / ".stamps" / "a.json", '{"a": 1}\n', within=out)
    assert (out / ".stamps" / "a.json").read_text() == '{"a": 1}\n'
    (out / ".stamps" / "a.json").chmod(0o600)
    overwrite(out / ".stamps" / "a.json", b"{}\n", within=out)
    assert (out / ".stamps" / "a.json").read_bytes() == b"{}\n"  # nothing of the longer one left
    assert (out / ".stamps" / "a.json").stat().st_mode & 0o777 == 0o600
    assert os.listdir(out / ".stamps") == ["a.json"]


@pytest.mark.parametrize("kind", ["a link to a file", "a pipe", "a folder"])
def test_overwrite_refuses_what_is_no_regular_file_and_leaves_it_as_it_was(
    tmp_path: Path, kind: str
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    target, elsewhere = out / "a.json", tmp_path / "elsewhere.json"
    elsewhere.write_text("theirs")
    if kind == "a link to a file":
        target.symlink_to(elsewhere)
    elif kind == "a pipe":
        os.mkfifo(target)  # no reader: opening it to write would wait, were it not refused
    else:
        target.mkdir()
    with pytest.raises(InputError, match=r"a\.json: is a"):
        overwrite(target, "{}", within=out)
    assert elsewhere.read_text() == "theirs"
    assert target.is_symlink() or target.is_fifo() or target.is_dir()


def test_overwrite_never_writes_through_a_folder_link_planted_inside_the_output_folder(
    tmp_path: Path,
) -> None:
    out, elsewhere = _planted(tmp_path)
    with pytest.raises(InputError, match="is a link inside the output folder; refused"):
        overwrite(out / "teams" / "x.json", "{}", within=out)
    assert [(p.name, p.read_text()) for p in elsewhere.iterdir()] == [("x.json", "theirs\n")]
