"""Listening: the studio's socket, its address printed once it is bound, uvicorn serving.

The socket is bound before anything is printed, so the address printed is one that answers
(port 0 picks a free port, and the address says which). Binding anything but loopback makes a
token (printed in the address, as notebook servers do) that every request must carry.

Not here: the application (:mod:`solver.studio.app`).
"""

from __future__ import annotations

import secrets
import signal
import socket
from collections.abc import Callable
from typing import Any

import uvicorn

from solver.errors import InputError
from solver.studio.security import loopback
from solver.studio.service import Studio
from solver.untrusted import shown

__all__ = ["address", "bind", "serve"]

# Bytes of a request's head (its address and headers) at most: a selection of a thousand
# values travels in the address when pages are used without scripts.
MAX_HEAD_BYTES = 256 * 1024


def bind(host: str, port: int) -> socket.socket:
    """A listening socket on ``host:port`` (a located error when that is not possible)."""
    try:
        family, kind, proto, _, where = socket.getaddrinfo(
            host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )[0]
        sock = socket.socket(family, kind, proto)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(where)
        sock.listen(128)
    except (OSError, UnicodeError) as error:  # UnicodeError: a name no resolver can encode
        reason = error.strerror if isinstance(error, OSError) else None
        raise InputError.at(
            "--host" if port == 0 or reason is None else "--port",
            f"cannot listen on {shown(host, quoted=True)}:{port}: {reason or error}",
        ) from None
    sock.set_inheritable(True)
    return sock


def address(host: str, port: int, token: str | None) -> str:
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/" + (f"?token={token}" if token else "")


def serve(
    studio: Studio,
    sock: socket.socket,
    host: str,
    *,
    announce: Callable[[str], None],
    open_browser: bool = False,
    warn: Callable[[str], None] = lambda _message: None,
) -> None:
    """Serve ``studio`` on ``sock`` until interrupted (SIGINT, SIGTERM), then return.

    ``announce`` is given the page's address; ``warn`` a message when ``open_browser`` finds
    no browser to open it in (a machine without a display)."""
    from solver.studio.app import make_app

    port = int(sock.getsockname()[1])
    token = None if loopback(host) else secrets.token_urlsafe(24)
    url = address(host, port, token)
    app = make_app(studio, host=host, port=port, token=token)
    config = uvicorn.Config(
        app,
        log_level="warning",
        access_log=False,
        lifespan="on",
        h11_max_incomplete_event_size=MAX_HEAD_BYTES,
        timeout_graceful_shutdown=3,
        server_header=False,
    )
    server = _Server(config, studio)
    announce(url)
    if open_browser:
        import webbrowser

        if not webbrowser.open(url):
            warn("no browser could be opened here: open the address above in one")
    # uvicorn stops on SIGINT and SIGTERM, then raises the signal again for the handler that was
    # there before: ours ends the serving as Ctrl-C does, so the caller's clean-up runs.
    previous = signal.signal(signal.SIGTERM, _stopped)
    try:
        server.run(sockets=[sock])
    except (_Stopped, KeyboardInterrupt):
        pass
    finally:
        signal.signal(signal.SIGTERM, previous)


class _Server(uvicorn.Server):
    """uvicorn's server, which also ends the pages' event streams when asked to stop: they
    would otherwise hold its graceful shutdown open until the timeout."""

    def __init__(self, config: uvicorn.Config, studio: Studio) -> None:
        super().__init__(config)
        self.studio = studio

    def handle_exit(self, sig: int, frame: Any) -> None:
        if self.studio.live is not None:
            self.studio.live.stop(wait=False)
        super().handle_exit(sig, frame)


class _Stopped(Exception):
    """SIGTERM arrived: the studio stops as after Ctrl-C."""


def _stopped(*_: object) -> None:
    raise _Stopped
