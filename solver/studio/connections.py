"""How many connections the studio holds, and how long a request's head may take to arrive.

uvicorn waits for a request's head as long as a client trickles it in, and accepts connections
until the process runs out of descriptors (then it stops answering anyone, and logs a
traceback per refused accept). :class:`Fence` bounds both, for uvicorn's own HTTP/1.1 protocol
(:class:`FencedProtocol`, made for one fence by :func:`protocol_class`):

* a head (the request line and headers) must be complete within ``head_seconds`` of the
  connection's start, or of the end of the previous answer on a kept-alive connection, else
  the connection is closed;
* at most ``most`` connections are open; one more closes the connection that has waited
  longest for a head (a stalled client, or a browser's idle kept-alive connection, which it
  opens again at once), or, when every connection is busy with a request, the new one.

So a client that stalls never holds a place a prompt one needs. Event streams count as busy
connections; how many may be open is bounded where they are served
(:mod:`solver.studio.api`).

Not here: what a request may carry (:mod:`solver.studio.security`).
"""

from __future__ import annotations

import asyncio
from collections import OrderedDict
from typing import Any

from uvicorn.protocols.http.h11_impl import H11Protocol

__all__ = [
    "BACKLOG",
    "HEAD_SECONDS",
    "MAX_CONNECTIONS",
    "Fence",
    "FencedProtocol",
    "protocol_class",
]

# Connections open at once, at most: well under a desktop's 1,024 descriptors.
MAX_CONNECTIONS = 256
# Connections the kernel holds for the studio to accept, at most; the event loop accepts as
# many in one go before the fence sees any, so this bounds the descriptors of a burst too
# (uvicorn's 2,048 took a desktop's 1,024 at once).
BACKLOG = 64
# Seconds a request's head may take to arrive in full.
HEAD_SECONDS = 10.0


class Fence:
    """The open connections of one server: which wait for a head, and since when."""

    def __init__(self, most: int = MAX_CONNECTIONS, head_seconds: float = HEAD_SECONDS) -> None:
        self.most = most
        self.head_seconds = head_seconds
        self.busy: set[FencedProtocol] = set()
        # Waiting for a head, oldest first, with the timer that closes each.
        self.waiting: OrderedDict[FencedProtocol, asyncio.TimerHandle] = OrderedDict()

    @property
    def open(self) -> int:
        return len(self.busy) + len(self.waiting)

    def opened(self, connection: FencedProtocol) -> None:
        """A new connection: room is made for it, or it is closed."""
        if self.open >= self.most:
            if self.waiting:
                oldest = next(iter(self.waiting))
                self.closed(oldest)
                oldest.transport.close()
            else:
                connection.transport.close()
                return
        self.wait(connection)

    def wait(self, connection: FencedProtocol) -> None:
        """``connection`` waits for a request's head from now on."""
        self.busy.discard(connection)
        previous = self.waiting.pop(connection, None)
        if previous is not None:
            previous.cancel()
        self.waiting[connection] = connection.loop.call_later(
            self.head_seconds, connection.head_too_slow
        )

    def working(self, connection: FencedProtocol) -> None:
        """A request's head has arrived on ``connection``."""
        timer = self.waiting.pop(connection, None)
        if timer is not None:
            timer.cancel()
        self.busy.add(connection)

    def closed(self, connection: FencedProtocol) -> None:
        timer = self.waiting.pop(connection, None)
        if timer is not None:
            timer.cancel()
        self.busy.discard(connection)


class FencedProtocol(H11Protocol):
    """uvicorn's HTTP/1.1 protocol, telling its :class:`Fence` when a connection opens, when a
    request's head has arrived, when an answer is complete and when it closes."""

    fence: Fence

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]  # a TCP transport
        super().connection_made(transport)
        self.fence.opened(self)

    def data_received(self, data: bytes) -> None:
        before = self.cycle
        super().data_received(data)
        if self.cycle is not before and not self.transport.is_closing():
            self.fence.working(self)

    def on_response_complete(self) -> None:
        super().on_response_complete()
        # Kept alive: the next head is waited for afresh (unless a pipelined one already came).
        idle = self.cycle is not None and self.cycle.response_complete
        if idle and not self.transport.is_closing():
            self.fence.wait(self)

    def connection_lost(self, exc: Exception | None) -> None:
        self.fence.closed(self)
        super().connection_lost(exc)

    def head_too_slow(self) -> None:
        self.fence.closed(self)
        if not self.transport.is_closing():
            self.transport.close()


def protocol_class(fence: Fence) -> Any:
    """A :class:`FencedProtocol` class for uvicorn's ``http=`` setting, bound to ``fence``."""
    return type("StudioProtocol", (FencedProtocol,), {"fence": fence})
