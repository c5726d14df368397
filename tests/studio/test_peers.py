"""Who is at the other end of a connection: the kernel's word, for the studio's own account and
for another account of the machine (a real process of another user id, which needs root to
start: CI runs as root), and the studio refusing that account even when it holds the token."""

from __future__ import annotations

import os
import socket
import subprocess
from collections.abc import Iterator
from urllib.parse import urlsplit

import pytest

from solver.studio.peers import account_of, same_account
from tests.studio.conftest import Server

# An account that is not ours (Debian's "nobody"), and an interpreter it may run.
OTHER = 65534
SYSTEM_PYTHON = "/usr/bin/python3"


@pytest.fixture
def listening() -> Iterator[socket.socket]:
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()
        yield server


def as_other_account(code: str) -> subprocess.Popen[str]:
    if os.getuid() != 0:
        pytest.skip("starting a process of another account needs root (CI runs as root)")
    return subprocess.Popen(
        [SYSTEM_PYTHON, "-I", "-c", code], user=OTHER, cwd="/", stdout=subprocess.PIPE, text=True
    )


def test_the_kernel_names_this_account_for_its_own_connection(
    listening: socket.socket,
) -> None:
    with socket.create_connection(listening.getsockname()):
        accepted, client = listening.accept()
        with accepted:
            assert account_of(client, accepted.getsockname()) == os.getuid()
            assert same_account(client, accepted.getsockname())


def test_a_connection_that_is_not_there_is_nobodys(listening: socket.socket) -> None:
    port = listening.getsockname()[1]
    assert account_of(("127.0.0.1", 1), ("127.0.0.1", port)) is None
    # Not known to be another account's: the token alone decides.
    assert same_account(("127.0.0.1", 1), ("127.0.0.1", port))
    assert account_of(("127.0.0.1", 1), ("::1", port)) is None
    assert account_of(("not an address", 1), ("127.0.0.1", port)) is None


def test_the_kernel_names_another_account_for_its_connection(listening: socket.socket) -> None:
    where = listening.getsockname()
    client = as_other_account(
        f"import socket; s = socket.create_connection({where!r}); print('on', flush=True); "
        "s.recv(1)"
    )
    try:
        assert client.stdout is not None
        assert client.stdout.readline().strip() == "on"
        accepted, address = listening.accept()
        with accepted:
            assert account_of(address, accepted.getsockname()) == OTHER
            assert not same_account(address, accepted.getsockname())
    finally:
        client.kill()
        client.wait(timeout=60)


def test_another_account_is_refused_even_with_the_token(studio: Server) -> None:
    where = urlsplit(studio.url)
    head = (
        f"GET /api/count?type=UAV HTTP/1.1\r\nHost: 127.0.0.1:{where.port}\r\n"
        f"Authorization: Bearer {studio.token}\r\nConnection: close\r\n\r\n"
    )
    client = as_other_account(
        "import socket, sys\n"
        f"s = socket.create_connection(({where.hostname!r}, {where.port}))\n"
        f"s.sendall({head!r}.encode())\n"
        "answer = b''\n"
        "while chunk := s.recv(65536):\n"
        "    answer += chunk\n"
        "print(answer.decode('latin-1'))\n"
    )
    output, _ = client.communicate(timeout=120)
    assert output.startswith("HTTP/1.1 403"), output[:200]
    assert "serves the account that started it only" in output
    # The same request from this account is served.
    assert studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
