"""Connections a stalled client holds never starve a prompt one: a head must arrive in time,
the studio holds a bounded number of connections (making room by closing the one that has
waited longest for a head), and live event streams hold no thread and are bounded too.

Each attack is run for real against a studio process: slow heads trickled in over a thousand
sockets under a desktop's descriptor limit, streams held open on a live ROS 2 domain. Nothing
here times an answer; the benchmark (benchmarks/bench_studio_attack.py) does.
"""

from __future__ import annotations

import contextlib
import os
import resource
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import urlsplit

import pytest
from playwright.sync_api import Page, expect

from solver.studio.api import MAX_STREAMS
from solver.studio.connections import HEAD_SECONDS, MAX_CONNECTIONS
from tests.conftest import ROOT
from tests.live.ros2_graph import next_domain, write_config
from tests.live.roscore import wait_until
from tests.studio.conftest import Server, StartStudio, stop

# A desktop's limit on open descriptors (Debian's and Ubuntu's default soft limit).
DESKTOP_DESCRIPTORS = 1024


def desktop_limit() -> None:
    """In the studio's process before it starts: a desktop's descriptor limit."""
    _, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    resource.setrlimit(resource.RLIMIT_NOFILE, (DESKTOP_DESCRIPTORS, hard))


@contextlib.contextmanager
def descriptors(needed: int) -> Iterator[None]:
    """This test process may hold ``needed`` descriptors more than it does."""
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    wanted = min(hard, max(soft, needed + 256))
    resource.setrlimit(resource.RLIMIT_NOFILE, (wanted, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))


def stalled(server: Server, count: int) -> list[socket.socket]:
    """``count`` connections that each sent the start of a request's head, and no more."""
    where = urlsplit(server.url)
    opened = []
    for _ in range(count):
        connection = socket.create_connection((where.hostname, where.port), timeout=120)
        connection.sendall(b"GET /api/count?type=UAV HTTP/1.1\r\nHost: 127.0.0.1\r\n")
        opened.append(connection)
    return opened


def closed_by_server(connection: socket.socket) -> bool:
    connection.setblocking(False)
    try:
        return connection.recv(1) == b""
    except BlockingIOError:
        return False
    except ConnectionResetError:
        return True


def test_a_thousand_stalled_heads_under_a_desktops_descriptor_limit_do_not_stop_answers(
    start_studio: StartStudio,
) -> None:
    count = DESKTOP_DESCRIPTORS + 76
    assert count > MAX_CONNECTIONS
    with descriptors(count):
        server = start_studio(preexec_fn=desktop_limit)
        attackers = stalled(server, count)
        try:
            # Answered, though more stalled connections were made than the studio may hold.
            assert server.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
            # Room was made by closing the longest waiting: at most MAX_CONNECTIONS stay open.
            wait_until(
                lambda: sum(not closed_by_server(c) for c in attackers) <= MAX_CONNECTIONS,
                timeout=120,
                what="the studio to close the connections it has no room for",
            )
            assert closed_by_server(attackers[0])
        finally:
            for connection in attackers:
                connection.close()
    assert server.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
    errors = server.stderr.read_text(encoding="utf-8")
    assert "Traceback" not in errors
    assert "Too many open files" not in errors


def test_an_attacker_reopening_a_thousand_slow_heads_does_not_exhaust_descriptors(
    start_studio: StartStudio,
) -> None:
    # benchmarks.attack's slow heads: 1,100 connections trickled a byte a second, each one the
    # studio closes opened again at once. The event loop accepts a burst of connections before
    # the fence sees them; bursts past the descriptors left ended in a traceback per accept
    # and a second of deafness each.
    server = start_studio(preexec_fn=desktop_limit)
    attacker = subprocess.Popen(
        [sys.executable, "-m", "benchmarks.attack", "slow-heads", server.url],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        assert attacker.stdout is not None
        assert attacker.stdout.readline().strip() == "ready"
        for _ in range(20):
            assert server.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
    finally:
        stop(attacker)
    errors = server.stderr.read_text(encoding="utf-8")
    assert "Too many open files" not in errors
    assert "Traceback" not in errors


def test_a_head_trickled_in_is_cut_off_while_others_are_answered(studio: Server) -> None:
    (slow,) = stalled(studio, 1)
    started = time.monotonic()

    def cut_off() -> bool:
        # One byte of header now and then keeps the connection busy, never complete.
        with contextlib.suppress(OSError):
            slow.sendall(b"x")
        assert studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
        return closed_by_server(slow)

    try:
        wait_until(cut_off, timeout=HEAD_SECONDS + 120, what="the slow head to be cut off")
    finally:
        slow.close()
    # Not before its time: the head had HEAD_SECONDS to arrive.
    assert time.monotonic() - started >= HEAD_SECONDS


def test_a_kept_alive_connection_answers_request_after_request(studio: Server) -> None:
    import http.client

    where = urlsplit(studio.url)
    connection = http.client.HTTPConnection(where.hostname or "", where.port, timeout=120)
    try:
        for _ in range(5):
            connection.request(
                "GET", "/api/count?type=UAV", headers={"authorization": f"Bearer {studio.token}"}
            )
            response = connection.getresponse()
            assert response.status == 200
            response.read()
    finally:
        connection.close()


@pytest.fixture
def live_studio(start_studio: StartStudio, tmp_path: Path) -> Server:
    """A studio following a ROS 2 domain of its own (no robot on it: streams wait)."""
    environment = {**os.environ, "CYCLONEDDS_URI": write_config(tmp_path)}
    return start_studio("case3", "--ros2", "--domain", str(next_domain()), env=environment)


def test_live_streams_are_bounded_and_hold_no_thread(live_studio: Server) -> None:
    where = urlsplit(live_studio.url)
    request = (
        f"GET /api/live/events HTTP/1.1\r\nHost: 127.0.0.1:{where.port}\r\n"
        f"Authorization: Bearer {live_studio.token}\r\n\r\n"
    ).encode()

    def open_stream() -> tuple[socket.socket, bytes]:
        connection = socket.create_connection((where.hostname, where.port), timeout=120)
        connection.sendall(request)
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = connection.recv(4096)
            if not chunk:
                break
            head += chunk
        return connection, head

    def threads() -> int:
        status = Path(f"/proc/{live_studio.process.pid}/status").read_text(encoding="utf-8")
        return int(next(line for line in status.splitlines() if line.startswith("Threads:"))[8:])

    assert live_studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
    before = threads()
    streams = []
    try:
        for _ in range(MAX_STREAMS):
            connection, head = open_stream()
            streams.append(connection)
            assert head.startswith(b"HTTP/1.1 200"), head[:200]
        assert live_studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0
        # Each stream waits on the event loop: no thread of the server's pool each (it has
        # 40; 45 streams waiting on threads made every other request wait).
        assert threads() - before < MAX_STREAMS // 2
        assert live_studio.json("/api/live")["source"].startswith("ROS 2 domain")
        extra, answer = open_stream()
        while b"open already" not in answer and (chunk := extra.recv(4096)):
            answer += chunk
        extra.close()
        assert answer.startswith(b"HTTP/1.1 503"), answer[:200]
        assert b"live event streams are open already" in answer
        streams.pop().close()

        def one_more() -> bool:
            connection, head = open_stream()
            streams.append(connection)
            return head.startswith(b"HTTP/1.1 200")

        wait_until(one_more, timeout=120, what="a stream in the place of the one closed")
    finally:
        for connection in streams:
            connection.close()


def test_a_live_view_refused_for_want_of_room_says_so_in_the_page(
    live_studio: Server, page: Page
) -> None:
    where = urlsplit(live_studio.url)
    request = (
        f"GET /api/live/events HTTP/1.1\r\nHost: 127.0.0.1:{where.port}\r\n"
        f"Authorization: Bearer {live_studio.token}\r\n\r\n"
    ).encode()
    streams = []
    try:
        for _ in range(MAX_STREAMS):
            connection = socket.create_connection((where.hostname, where.port), timeout=120)
            connection.sendall(request)
            assert connection.recv(4096).startswith(b"HTTP/1.1 200")
            streams.append(connection)
        page.goto(live_studio.at("live"))
        expect(page.locator("#event-log")).to_contain_text("Live events stopped")
    finally:
        for connection in streams:
            connection.close()
