"""Bounded XML-RPC: what a ROS master, a node or anyone on the network sends is bounded.

A ROS 1 master and the nodes it names are strangers on the network: a reply can trickle in a
byte a second, never end, expand from a small gzip body to gigabytes, or nest arrays thousands
deep. :class:`BoundedTransport` is what :class:`xmlrpc.client.ServerProxy` calls instead of the
standard transport, and every call through it:

* ends by one **deadline for the whole call** (resolving the name, connecting, sending,
  reading every byte of the reply), not per read. Blocking operations wait in slices of at
  most :data:`SLICE` seconds, so a deadline brought forward (:meth:`BoundedTransport.cut_off`,
  what a stopping watcher does on SIGTERM) takes effect within one slice;
* reads at most :data:`MAX_REPLY_BYTES` of reply: a longer ``Content-Length`` is refused before
  anything is read, a longer body when it gets there; a gzip body is decompressed to at most the
  same number of bytes; any other content encoding is refused;
* parses the reply with expat, refusing a DTD (so no entity is ever declared or expanded), and
  does not build values nested deeper than :data:`MAX_DEPTH` arrays and structs: each such
  value is :data:`TOO_DEEP` instead, so the caller reports a value of the wrong kind;
* parses a reply of at least :data:`REUSE_BYTES` only when it differs from the reply to the
  same request before: a poll of a large graph that did not change (the same bytes) is not
  parsed again, and :attr:`BoundedTransport.reused` says so (the values are the same objects
  as then: callers do not change them).

:func:`loads` is the same parser for requests (the watcher's own node API,
:mod:`~solver.live.sources.ros1.node`).

Not here: what a reply means (:mod:`solver.live.sources.ros1.master`).
"""

from __future__ import annotations

import errno
import functools
import http.client
import ipaddress
import os
import select
import socket
import threading
import time
import xmlrpc.client
import zlib
from collections.abc import Callable
from typing import Any, Final
from xml.parsers import expat

from solver.live.graph import MAX_DEPTH, TOO_DEEP

__all__ = [
    "MAX_REPLY_BYTES",
    "REUSE_BYTES",
    "SLICE",
    "BoundedTransport",
    "OversizedReply",
    "loads",
]

MAX_REPLY_BYTES: Final = 32 * 1024 * 1024
SLICE: Final = 0.1
# Replies this long are kept (the last one, with its request) to be compared with the next.
REUSE_BYTES: Final = 64 * 1024
_CHUNK = 64 * 1024
_USER_AGENT = "teleop-ui (bounded xmlrpc)"


class OversizedReply(ValueError):
    """A reply (or request) longer than the byte cap."""

    def __init__(self, limit: int) -> None:
        super().__init__(f"a reply larger than {limit} bytes")
        self.limit = limit


# -- parsing --------------------------------------------------------------------------------


class _Unmarshaller(xmlrpc.client.Unmarshaller):
    """The standard unmarshaller (iterative: no recursion), with a depth bound: arrays and
    structs nested deeper than ``max_depth`` are skipped whole and stand as :data:`TOO_DEEP`."""

    def __init__(self, max_depth: int) -> None:
        super().__init__(use_builtin_types=True)
        self._max_depth = max_depth
        self._skipping = 0  # elements open inside the value being skipped

    def start(self, tag: str, attrs: Any) -> None:
        if self._skipping:
            self._skipping += 1
            return
        if tag.rsplit(":", 1)[-1] in ("array", "struct") and len(self._marks) >= self._max_depth:
            self._skipping = 1
            return
        super().start(tag, attrs)

    def data(self, text: str) -> None:
        if not self._skipping:
            super().data(text)

    def end(self, tag: str) -> None:
        if self._skipping:
            self._skipping -= 1
            if not self._skipping:
                self.append(TOO_DEEP)
                self._value = False
            return
        super().end(tag)


def _refuse_dtd(*_: Any) -> None:
    raise xmlrpc.client.ResponseError("a DTD, which XML-RPC never holds")


def loads(data: bytes, max_depth: int = MAX_DEPTH) -> tuple[tuple[Any, ...], str | None]:
    """The values and method name (``None`` in a reply) of an XML-RPC message.

    :class:`xmlrpc.client.Fault` for a fault reply; :class:`xmlrpc.client.ResponseError` for
    anything that is not XML-RPC (a DTD included); values deeper than ``max_depth`` are
    :data:`TOO_DEEP`.
    """
    target = _Unmarshaller(max_depth)
    parser = expat.ParserCreate()
    parser.StartElementHandler = target.start
    parser.EndElementHandler = target.end
    parser.CharacterDataHandler = target.data
    parser.StartDoctypeDeclHandler = _refuse_dtd
    # As the standard ExpatParser does: no encoding, so text stays str (expat decoded it).
    target.xml(None, None)  # type: ignore[arg-type]  # no encoding, as ExpatParser does
    try:
        parser.Parse(data, True)
        return target.close(), target.getmethodname()
    except (xmlrpc.client.Fault, xmlrpc.client.ResponseError, expat.ExpatError):
        raise
    except (IndexError, KeyError, TypeError, ValueError, OverflowError) as error:
        # The standard unmarshaller trusts the element order (a struct member without a value
        # is an IndexError): any such slip is a malformed message, never a traceback.
        raise xmlrpc.client.ResponseError(f"malformed XML-RPC ({type(error).__name__})") from None


# -- the socket -----------------------------------------------------------------------------


def _wait(remaining: Callable[[], float], operation: Callable[[float], Any]) -> Any:
    """``operation(timeout)`` retried in slices until it completes or ``remaining()`` ends."""
    while True:
        left = remaining()
        if left <= 0:
            raise TimeoutError("the deadline passed")
        try:
            return operation(min(left, SLICE))
        except TimeoutError:
            continue  # one slice passed with nothing to do: look at the deadline again


class _Socket(socket.socket):
    """A socket whose reads and writes end by its owner's deadline (``remaining``).

    ``http.client`` reads through ``recv_into`` (its buffered reader) and writes through
    ``sendall``: both wait in slices. ``sendall`` is a loop of ``send``, so that a slice that
    ends mid-way never sends a byte twice.
    """

    remaining: Callable[[], float]

    def _sliced(self, call: Callable[..., Any], *args: Any) -> Any:
        def once(timeout: float) -> Any:
            self.settimeout(timeout)
            return call(*args)

        return _wait(self.remaining, once)

    def recv_into(self, buffer: Any, nbytes: int = 0, flags: int = 0) -> int:
        received: int = self._sliced(super().recv_into, buffer, nbytes, flags)
        return received

    def recv(self, bufsize: int, flags: int = 0) -> bytes:
        received: bytes = self._sliced(super().recv, bufsize, flags)
        return received

    def sendall(self, data: Any, flags: int = 0) -> None:
        view = memoryview(data).cast("B")
        while view:
            sent: int = self._sliced(super().send, view, flags)
            view = view[sent:]


def _resolve(host: str, port: int, remaining: Callable[[], float]) -> list[Any]:
    """``getaddrinfo`` by the deadline: a name is resolved on a helper thread (the resolver has
    no timeout of its own that this call could set), an address literal at once."""
    try:
        ipaddress.ip_address(host)
    except ValueError:
        pass
    else:
        return socket.getaddrinfo(host, port, 0, socket.SOCK_STREAM)
    found: list[Any] = []
    done = threading.Event()

    def resolve() -> None:
        try:
            found.append(socket.getaddrinfo(host, port, 0, socket.SOCK_STREAM))
        except OSError as error:
            found.append(error)
        done.set()

    def resolved(timeout: float) -> None:
        if not done.wait(timeout):
            raise TimeoutError

    threading.Thread(target=resolve, name=f"resolve {host}", daemon=True).start()
    _wait(remaining, resolved)
    if isinstance(found[0], OSError):
        raise found[0]
    result: list[Any] = found[0]
    return result


def _open(host: str, port: int, remaining: Callable[[], float]) -> _Socket:
    """A connected :class:`_Socket`, trying each address of ``host`` by the deadline."""
    failure: OSError | None = None
    for family, kind, proto, _, address in _resolve(host, port, remaining):
        sock = _Socket(family, kind, proto)
        sock.remaining = remaining
        try:
            sock.setblocking(False)
            code = sock.connect_ex(address)
            if code not in (0, errno.EINPROGRESS, errno.EWOULDBLOCK):
                raise OSError(code, os.strerror(code))
            _wait(remaining, functools.partial(_writable, sock))
            code = sock.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR)
            if code:
                raise OSError(code, os.strerror(code))
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            return sock
        except OSError as error:
            sock.close()
            if isinstance(error, TimeoutError):
                raise
            failure = error
    raise failure or OSError(errno.EHOSTUNREACH, f"no address for {host}")


def _writable(sock: socket.socket, timeout: float) -> None:
    """Wait for a non-blocking connect to end (``select``), or :class:`TimeoutError`."""
    _, writable, _ = select.select([], [sock], [], timeout)
    if not writable:
        raise TimeoutError


class _Connection(http.client.HTTPConnection):
    def __init__(self, host: str, remaining: Callable[[], float]) -> None:
        super().__init__(host)
        self._remaining = remaining

    def connect(self) -> None:
        self.sock = _open(self.host, self.port, self._remaining)


# -- the transport --------------------------------------------------------------------------


class BoundedTransport:
    """The transport :class:`xmlrpc.client.ServerProxy` uses (``request``, ``close``), bounded
    as the module docstring says. Keeps one connection alive between calls (rosmaster speaks
    HTTP/1.1). Not thread-safe, except :meth:`cut_off`."""

    def __init__(
        self,
        timeout: float,
        *,
        max_bytes: int = MAX_REPLY_BYTES,
        max_depth: int = MAX_DEPTH,
    ) -> None:
        self.timeout = timeout
        self.max_bytes = max_bytes
        self.max_depth = max_depth
        self._cutoff = float("inf")
        self._connection: tuple[str, _Connection] | None = None
        self._deadline = 0.0
        # The last large reply: (host and handler, request body, reply body, its values).
        self._kept: tuple[str, bytes, bytes, tuple[Any, ...]] | None = None
        self.reused = False  # whether the last call's reply was the kept one, byte for byte

    def cut_off(self, when: float | None) -> None:
        """Every call ends by ``when`` (a :func:`time.monotonic` time), the call under way
        included (within :data:`SLICE` seconds); ``None`` lifts it. Thread-safe."""
        self._cutoff = float("inf") if when is None else when

    def _remaining(self) -> float:
        return min(self._deadline, self._cutoff) - time.monotonic()

    def request(
        self,
        host: str,
        handler: str,
        request_body: bytes,
        verbose: bool = False,  # noqa: ARG002 - ServerProxy passes it; nothing is logged
    ) -> tuple[Any, ...]:
        self._deadline = time.monotonic() + self.timeout
        self.reused = False
        for attempt in (0, 1):
            reused = self._connection is not None and self._connection[0] == host
            try:
                return self._request(host, handler, request_body)
            except (
                http.client.RemoteDisconnected,
                ConnectionResetError,
                ConnectionAbortedError,
                BrokenPipeError,
            ):
                # A kept-alive connection the server closed meanwhile: once more, afresh.
                self.close()
                if attempt or not reused:
                    raise
            except BaseException:
                self.close()
                raise
        raise AssertionError("unreachable")  # pragma: no cover

    def _request(self, host: str, handler: str, body: bytes) -> tuple[Any, ...]:
        if self._connection is None or self._connection[0] != host:
            self.close()
            self._connection = (host, _Connection(host, self._remaining))
        connection = self._connection[1]
        connection.putrequest("POST", handler, skip_accept_encoding=True)
        connection.putheader("User-Agent", _USER_AGENT)
        connection.putheader("Content-Type", "text/xml")
        connection.putheader("Accept-Encoding", "gzip")
        connection.putheader("Content-Length", str(len(body)))
        connection.endheaders(body)
        response = connection.getresponse()
        if response.status != 200:
            self.close()  # the body of an error is not read: it may be anything
            raise xmlrpc.client.ProtocolError(
                host + handler, response.status, response.reason, dict(response.getheaders())
            )
        data = self._body(response)
        if response.will_close:
            self.close()
        kept, where = self._kept, host + handler
        if kept is not None and kept[0] == where and kept[1] == body and kept[2] == data:
            self.reused = True
            return kept[3]
        values, _ = loads(data, self.max_depth)
        if len(data) >= REUSE_BYTES:
            self._kept = (where, body, data, values)
        return values  # ServerProxy unwraps a single value, as from the standard transport

    def _body(self, response: http.client.HTTPResponse) -> bytes:
        declared = response.getheader("Content-Length", "")
        if declared.strip().isdigit() and int(declared) > self.max_bytes:
            raise OversizedReply(self.max_bytes)
        chunks: list[bytes] = []
        size = 0
        while chunk := response.read(min(_CHUNK, self.max_bytes + 1 - size)):
            chunks.append(chunk)
            size += len(chunk)
            if size > self.max_bytes:
                raise OversizedReply(self.max_bytes)
        data = b"".join(chunks)
        encoding = (response.getheader("Content-Encoding", "") or "identity").strip().lower()
        if encoding in ("gzip", "x-gzip"):
            return self._gunzip(data)
        if encoding != "identity":
            raise xmlrpc.client.ResponseError(f"a reply in content encoding {encoding!r:.40}")
        return data

    def _gunzip(self, data: bytes) -> bytes:
        inflater = zlib.decompressobj(16 + zlib.MAX_WBITS)
        try:
            plain = inflater.decompress(data, self.max_bytes + 1)
        except zlib.error as error:
            raise xmlrpc.client.ResponseError(f"gzip that does not inflate ({error})") from None
        if len(plain) > self.max_bytes or inflater.unconsumed_tail:
            raise OversizedReply(self.max_bytes)
        if not inflater.eof or inflater.unused_data:
            raise xmlrpc.client.ResponseError("a gzip body cut short or followed by more data")
        return plain

    def close(self) -> None:
        if self._connection is not None:
            self._connection[1].close()
            self._connection = None
