"""Listening: the studio's socket, its address printed once it is bound, uvicorn serving.

The socket is bound before anything is printed, so the address printed is one that answers
(port 0 picks a free port, and the address says which). Every start makes a token, printed in
the address as notebook servers do, that every request must carry (loopback included: another
account on the machine reaches 127.0.0.1 too). ``--open`` hands the browser a file of the
studio's private folder that leads on to that address, never the address itself: a command
line is readable by every account of the machine.

Not here: the application (:mod:`solver.studio.app`).
"""

from __future__ import annotations

import asyncio
import logging
import secrets
import signal
import socket
from collections.abc import Callable
from typing import Any

import uvicorn

from solver import InputError
from solver.studio.connections import BACKLOG, Fence, protocol_class
from solver.studio.security import MAX_QUERY_BYTES
from solver.studio.service import Studio
from solver.untrusted import shown

__all__ = ["CutOffAtShutdown", "address", "bind", "serve"]

# Bytes of a request's head (its address and headers) at most: the longest query the fence
# takes and room for a browser's headers.
MAX_HEAD_BYTES = MAX_QUERY_BYTES + 32 * 1024


def bind(host: str, port: int) -> socket.socket:
    """A listening socket on ``host:port`` (a located error when that is not possible)."""
    try:
        family, kind, proto, _, where = socket.getaddrinfo(
            host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )[0]
        sock = socket.socket(family, kind, proto)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(where)
        sock.listen(BACKLOG)
    except (OSError, UnicodeError) as error:  # UnicodeError: a name no resolver can encode
        reason = error.strerror if isinstance(error, OSError) else None
        raise InputError.at(
            "--host" if port == 0 or reason is None else "--port",
            f"cannot listen on {shown(host, quoted=True)}:{port}: {reason or error}",
        ) from None
    sock.set_inheritable(True)
    return sock


def address(host: str, port: int, token: str) -> str:
    """The address that opens the studio on ``host:port``, with its token."""
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/?token={token}"


def serve(
    studio: Studio,
    sock: socket.socket,
    host: str,
    *,
    announce: Callable[[str], None],
    open_browser: bool = False,
    warn: Callable[[str], None] = lambda _message: None,
) -> None:
    """Serve ``studio`` on ``sock`` until interrupted (SIGINT, SIGTERM), then remove its
    private folder and return.

    ``announce`` is given the page's address; ``warn`` a message when ``open_browser`` finds
    no browser to open it in (a machine without a display)."""
    from solver.studio.app import make_app

    port = int(sock.getsockname()[1])
    token = secrets.token_urlsafe(24)
    url = address(host, port, token)
    app = make_app(studio, host=host, port=port, token=token)
    config = uvicorn.Config(
        app,
        http=protocol_class(Fence()),
        backlog=BACKLOG,
        # Not "warning": uvicorn warns once per malformed request, so a stranger could fill
        # the console with lines of its choosing.
        log_level="error",
        access_log=False,
        lifespan="on",
        h11_max_incomplete_event_size=MAX_HEAD_BYTES,
        timeout_graceful_shutdown=3,
        server_header=False,
    )
    server = _Server(config, studio)
    logging.getLogger("uvicorn.error").addFilter(CutOffAtShutdown())
    # SIGINT and SIGTERM, however many and whenever they come, ask the server to stop and
    # nothing more: uvicorn raises each one it caught again once it has stopped, and one that
    # came while the studio cleans up would otherwise cut the clean-up short (leaving the
    # private folder behind) or end in a traceback.
    previous = {sig: signal.signal(sig, server.handle_exit) for sig in _STOPPING}
    try:
        announce(url)
        if open_browser:
            import webbrowser

            if not webbrowser.open(studio.workspace.opener(url).as_uri()):
                warn("no browser could be opened here: open the address above in one")
        server.run(sockets=[sock])
    finally:
        studio.workspace.close()
        for sig, handler in previous.items():
            signal.signal(sig, handler)


_STOPPING = (signal.SIGINT, signal.SIGTERM)


class CutOffAtShutdown(logging.Filter):
    """A request still being answered when the studio stops (a long count, past the graceful
    shutdown's seconds) is cancelled: uvicorn logs that with the cancellation's traceback. It
    is the stop the person asked for, not a fault: one line says so, no traceback."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.exc_info and isinstance(record.exc_info[1], asyncio.CancelledError):
            record.exc_info = None
            record.exc_text = None
            record.msg = "a request still being answered was cut off: the studio stopped"
            record.args = ()
        return True


class _Server(uvicorn.Server):
    """uvicorn's server, which also ends the pages' event streams when asked to stop: they
    would otherwise hold its graceful shutdown open until the timeout."""

    def __init__(self, config: uvicorn.Config, studio: Studio) -> None:
        super().__init__(config)
        self.studio = studio

    def handle_exit(self, sig: int, frame: Any) -> None:
        del sig, frame  # whichever signal: the same stop
        if self.studio.live is not None:
            self.studio.live.stop(wait=False)
        # A second Ctrl-C does not force the exit (uvicorn's way): forced, uvicorn skips the
        # application's own shutdown and ends in a traceback. The graceful one takes at most
        # ``timeout_graceful_shutdown`` seconds anyway.
        self.should_exit = True
