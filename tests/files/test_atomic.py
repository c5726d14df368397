"""Atomic writes replace a regular file or make a new one, and nothing else."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.files.atomic import make_folder, write_all_atomic, write_atomic


def test_a_file_is_written_and_a_regular_file_replaced(tmp_path: Path) -> None:
    target = tmp_path / "team.yaml"
    write_atomic(target, "first\n")
    write_atomic(target, "second\n")
    assert target.read_text() == "second\n"
    assert os.listdir(tmp_path) == ["team.yaml"]  # no temporary left behind


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
