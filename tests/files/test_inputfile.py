"""The bounded reader: regular files only, at most the limit, every failure located.

A FIFO and standard input from a pipe are tried, as processes with a ceiling, by every command
in tests/cli/test_hostile_files.py: here a regression would hang the test run itself.
"""

from __future__ import annotations

import os
import socket
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.files.inputfile import read_bounded, read_text, sha256_bounded


def test_a_regular_file_is_read_whole(tmp_path: Path) -> None:
    path = tmp_path / "team.yaml"
    path.write_bytes(b"name: t\n")
    assert read_bounded(path, limit=8) == b"name: t\n"


def test_a_link_to_a_regular_file_is_read(tmp_path: Path) -> None:
    (tmp_path / "real.yaml").write_text("name: t\n")
    (tmp_path / "link.yaml").symlink_to(tmp_path / "real.yaml")
    assert read_text(tmp_path / "link.yaml", limit=100) == "name: t\n"


def test_a_file_one_byte_past_the_limit_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "big.yaml"
    path.write_bytes(b"x" * 9)
    with pytest.raises(InputError, match="file is larger than 8 bytes; refused"):
        read_bounded(path, limit=8)


def test_a_file_longer_than_its_size_says_is_read_whole_and_still_bounded() -> None:
    # /proc files are regular files of size 0 (as a file growing while read would be).
    status = Path("/proc/self/status")
    assert read_bounded(status, limit=1 << 20).startswith(b"Name:")
    with pytest.raises(InputError, match="file is larger than 16 bytes; refused"):
        read_bounded(status, limit=16)


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom", "/dev/null"])
def test_a_device_is_refused_without_being_read(device: str) -> None:
    with pytest.raises(InputError) as caught:
        read_bounded(device, limit=16, what="rule set")
    assert str(caught.value) == (
        f"{device}: is a character device, not a rule set: only regular files are read"
    )


def test_a_socket_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # a socket's path is at most 108 bytes: bind a relative one
    with socket.socket(socket.AF_UNIX) as server:
        server.bind("listening")
        with pytest.raises(InputError, match="listening: is a socket, not a file"):
            read_bounded("listening", limit=16)


def test_a_folder_is_refused(tmp_path: Path) -> None:
    with pytest.raises(InputError) as caught:
        read_bounded(tmp_path, display="robots/", limit=16, what="topic list")
    assert str(caught.value) == "robots/: is a directory, not a topic list"


def test_a_link_to_a_device_is_refused_as_the_device(tmp_path: Path) -> None:
    (tmp_path / "rules.yaml").symlink_to("/dev/zero")
    with pytest.raises(InputError, match=r"rules\.yaml: is a character device"):
        read_bounded(tmp_path / "rules.yaml", limit=16)


def test_missing_unreadable_and_badly_named_files_are_located(tmp_path: Path) -> None:
    with pytest.raises(InputError, match=r"absent\.yaml: no such file"):
        read_bounded(tmp_path / "absent.yaml", limit=16)
    with pytest.raises(InputError, match="not a usable file name"):
        read_bounded("a\0b", limit=16)
    with pytest.raises(InputError, match="cannot read: File name too long"):
        read_bounded(tmp_path / ("x" * 300), limit=16)
    if os.geteuid() != 0:  # root reads everything
        secret = tmp_path / "secret.yaml"
        secret.write_text("x")
        secret.chmod(0)
        with pytest.raises(InputError, match="permission denied"):
            read_bounded(secret, limit=16)


def test_a_hash_of_something_unreadable_is_none() -> None:
    assert sha256_bounded("/dev/zero", limit=16) is None
