"""The watcher's answer and layouts served on loopback, read-only (``watch --layouts DIR
--serve [HOST:]PORT``), for the operator's viewer (issue 38).

=========================  =================================================================
``GET /answer``            the watcher's answer (its JSON, ``layouts`` included, or ``null``)
``GET /answer/events``     Server-Sent Events: one ``data:`` line per answer, the current one
                           first, a ``: keep-alive`` comment every 15 s
``GET /layouts/<path>``    a layout below ``DIR``: ``.json`` (``application/json``) and
                           ``.rviz`` (``text/plain``) files only
=========================  =================================================================

Every answer is ``Cache-Control: no-store`` and ``Connection: close`` (one request per
connection). ``HEAD`` answers the same heads without a body; any other method is 405.

**Who may ask.** No token: what is served is what every participant of the graph can read
(the answer is on ``/teleop_ui/ui_configuration``; the layouts name its topics), and nothing
can be changed. So the fences keep it to this machine and to the viewer's page:

* it listens on a loopback address only (127.0.0.0/8, ``::1``, ``localhost``): another host
  cannot reach it; every account of this machine can (loopback is shared), as it can read
  the graph;
* ``Host`` must name this server (``127.0.0.1:PORT``, ``localhost:PORT``, ``[::1]:PORT``), else
  421: a web page of another site whose name resolves to 127.0.0.1 (DNS rebinding) reads
  nothing;
* a request with an ``Origin`` (a page's ``fetch`` or ``EventSource``) is answered only for
  the viewer's origins (``--viewer-origin``; by default ``http://127.0.0.1:8080`` and
  ``http://localhost:8080``, where ``tools/lichtblick/serve.py`` serves Lichtblick's web
  build), with ``Access-Control-Allow-Origin`` naming that origin (never ``*``); any other
  origin gets 403 and holds no stream; so does another site's page that loads it without
  one (``Sec-Fetch-Site`` ``cross-site`` or ``same-site``: an ``<img>``, a ``<script>``),
  but for a navigation (a person following a link sees the JSON; the page learns nothing);
* files: below ``DIR`` only, each folder entered and the file opened without following a
  link (``O_NOFOLLOW``, relative to the open folder), a regular file of at most
  :data:`MAX_FILE_BYTES`, no name that is ``.``, ``..`` or hidden (temporaries of the atomic
  writes start with a dot), no other kind of file than the watcher writes.

**Bounded** as the studio's server is (:mod:`solver.studio.connections`; its code is
uvicorn's protocol, which this server does not use, so the idea is repeated here, not the
code): at most :data:`MAX_CONNECTIONS` connections, the one that has waited longest for a
head closed to make room (a newcomer is refused when every connection is busy); a head of at
most :data:`MAX_HEAD_BYTES` bytes and :data:`MAX_HEADERS` lines, complete within
:data:`HEAD_SECONDS`; at most :data:`MAX_STREAMS` event streams (503 past them); an answer
taken by the client within :data:`RESPONSE_SECONDS`, and on a stream each event within
:data:`SEND_SECONDS` (a client that stops reading is dropped, and never holds back the
others: each stream sends the newest answer when it can, not a queue of them).

**Why a server of its own, on asyncio.** The ``ros`` and ``ros2`` extras must not need the
``studio`` extra (Starlette, uvicorn), and what is served is three read-only routes. The
standard library's ``http.server`` holds a thread per connection, which long-lived event
streams would fill, and bounds no head's total time (its timeout is per read: a client that
trickles a byte every few seconds keeps it forever). One asyncio loop on a thread of its own
holds streams as coroutines, bounds each head by a deadline, and is woken by the watcher's
thread with :meth:`AnswerServer.publish` (``call_soon_threadsafe``). The request line and
headers are all it parses; bodies are never read (the connection closes after the answer).

Not here: what the answer holds (:mod:`solver.live.selection`), the layouts
(:mod:`solver.live.layouts`).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import stat
import threading
from collections import OrderedDict
from collections.abc import Collection
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType
from typing import Any
from urllib.parse import unquote, urlsplit

from solver.addresses import loopback
from solver.errors import InputError
from solver.untrusted import shown

__all__ = [
    "DEFAULT_ORIGINS",
    "HEAD_SECONDS",
    "MAX_CONNECTIONS",
    "MAX_FILE_BYTES",
    "MAX_HEADERS",
    "MAX_HEAD_BYTES",
    "MAX_STREAMS",
    "RESPONSE_SECONDS",
    "SEND_SECONDS",
    "AnswerServer",
    "ServeAddress",
    "serve_address",
    "viewer_origin",
]

# Connections open at once, at most, and waiting to be accepted.
MAX_CONNECTIONS = 64
BACKLOG = 16
# A request's head: its bytes and lines at most, and the seconds it may take to arrive whole.
MAX_HEAD_BYTES = 8 * 1024
MAX_HEADERS = 64
HEAD_SECONDS = 10.0
# Event streams open at once, at most.
MAX_STREAMS = 16
# A layout served: at most this large (the watcher's are far smaller; a team layout of a
# thousand robots' screens is a few MB).
MAX_FILE_BYTES = 32 * 1024 * 1024
# An answer (head and body) taken by the client within this; on a stream, each event.
RESPONSE_SECONDS = 60.0
SEND_SECONDS = 30.0
# A comment on an idle stream this often: proxies keep it open, and a gone client is found.
KEEPALIVE_SECONDS = 15.0
# Where tools/lichtblick/serve.py serves Lichtblick's web build.
DEFAULT_ORIGINS = ("http://127.0.0.1:8080", "http://localhost:8080")
# The kinds of file the watcher writes, and what they are served as.
_CONTENT_TYPES = {
    ".json": "application/json; charset=utf-8",
    ".rviz": "text/plain; charset=utf-8",
}
_CHUNK = 64 * 1024
_MAX_PARTS = 64
_REASONS = {
    200: "OK",
    400: "Bad Request",
    403: "Forbidden",
    404: "Not Found",
    405: "Method Not Allowed",
    413: "Content Too Large",
    421: "Misdirected Request",
    431: "Request Header Fields Too Large",
    503: "Service Unavailable",
}
_FOLDER = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | getattr(os, "O_CLOEXEC", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_FILE = os.O_RDONLY | _NOFOLLOW | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)


@dataclass(frozen=True, slots=True)
class ServeAddress:
    """Where to listen: a loopback address (``localhost`` is 127.0.0.1) and a port (0: a
    free one)."""

    host: str = "127.0.0.1"
    port: int = 0


def serve_address(text: str) -> ServeAddress:
    """``[HOST:]PORT`` (``8770``, ``127.0.0.1:8770``, ``[::1]:0``) as ``--serve`` takes it;
    a located :class:`~solver.errors.InputError` for anything else, or a host that is not
    this machine's."""
    host, _, port = text.rpartition(":")
    host = host or "127.0.0.1"
    if host.startswith("[") and host.endswith("]"):
        host = host[1:-1]
    if not port.isascii() or not port.isdigit() or len(port) > 5 or int(port) > 65535:
        raise InputError.at(
            "--serve",
            f"expected [HOST:]PORT with a port from 0 to 65535 (0: a free one), got "
            f"{shown(text, quoted=True)}",
        )
    if not loopback(host):
        raise InputError.at(
            "--serve",
            f"{shown(host, quoted=True)} is not a loopback address: the server has no token "
            "and serves this machine only (127.0.0.1, ::1 or localhost)",
        )
    return ServeAddress("127.0.0.1" if host == "localhost" else host, int(port))


def viewer_origin(text: str) -> str:
    """A viewer's origin as ``--viewer-origin`` takes it (``http://127.0.0.1:8080``:
    scheme, host and port, nothing else), in the form a browser sends it."""
    try:
        parts = urlsplit(text)
        port = parts.port
    except ValueError:
        parts, port = None, None
    if (
        parts is None
        or parts.scheme not in ("http", "https")
        or not parts.hostname
        or parts.path not in ("", "/")
        or parts.query
        or parts.fragment
        or parts.username is not None
        or not text.isascii()
    ):
        raise InputError.at(
            "--viewer-origin",
            f"expected an origin such as http://127.0.0.1:8080 (scheme, host and port only), "
            f"got {shown(text, quoted=True)}",
        )
    host = f"[{parts.hostname}]" if ":" in parts.hostname else parts.hostname
    return f"{parts.scheme}://{host}" + (f":{port}" if port is not None else "")


class _Refused(Exception):
    """A request answered with an error status and a short text saying why."""

    def __init__(self, status: int, why: str) -> None:
        super().__init__(why)
        self.status = status
        self.why = why


@dataclass(frozen=True, slots=True)
class _Request:
    method: str
    path: str
    headers: dict[str, str]


class AnswerServer:
    """The server (see the module docstring): :meth:`start` listens (a located
    :class:`~solver.errors.InputError` when it cannot), :meth:`publish` gives it each new
    answer from any thread, :meth:`close` ends it and every connection. A context manager."""

    def __init__(
        self,
        directory: str | Path,
        address: ServeAddress = ServeAddress(),
        origins: Collection[str] = DEFAULT_ORIGINS,
    ) -> None:
        self.directory = Path(directory).absolute()
        self.address = address
        self.origins = frozenset(origins)
        self.port = address.port
        self._loop = asyncio.new_event_loop()
        self._thread: threading.Thread | None = None
        self._answer = b"null"
        self._version = 0
        self._changed = asyncio.Event()
        self._open: set[asyncio.StreamWriter] = set()
        self._waiting: OrderedDict[asyncio.StreamWriter, None] = OrderedDict()
        self._streams = 0
        self._hosts: frozenset[str] = frozenset()

    @property
    def url(self) -> str:
        """``http://127.0.0.1:PORT`` (the port listened on, once started)."""
        host = self.address.host
        return f"http://{'[' + host + ']' if ':' in host else host}:{self.port}"

    def __enter__(self) -> AnswerServer:
        self.start()
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    def start(self) -> None:
        started = threading.Event()
        failed: list[BaseException] = []
        self._thread = threading.Thread(
            target=self._run, args=(started, failed), name="teleop-ui-serve", daemon=True
        )
        self._thread.start()
        started.wait()
        if failed:
            self._thread.join()
            raise failed[0]

    def publish(self, answer: Any) -> None:
        """The watcher's new answer (thread-safe): ``/answer`` and every stream get it."""
        line = json.dumps(answer, ensure_ascii=True, separators=(",", ":")).encode("ascii")
        with contextlib.suppress(RuntimeError):  # closed meanwhile
            self._loop.call_soon_threadsafe(self._set_answer, line)

    def close(self) -> None:
        """Stop listening and close every connection (idempotent)."""
        thread = self._thread
        if thread is None:
            if not self._loop.is_closed() and not self._loop.is_running():
                self._loop.close()  # never started
            return
        self._thread = None
        with contextlib.suppress(RuntimeError):
            self._loop.call_soon_threadsafe(self._loop.stop)
        thread.join(timeout=10)

    # -- the loop's thread ---------------------------------------------------------------

    def _run(self, started: threading.Event, failed: list[BaseException]) -> None:
        loop = self._loop
        asyncio.set_event_loop(loop)
        try:
            server = loop.run_until_complete(self._listen())
        except OSError as error:
            failed.append(
                InputError.at(
                    "--serve",
                    f"cannot listen on {self.address.host}:{self.address.port}: "
                    f"{os.strerror(error.errno) if error.errno else error}",
                )
            )
            loop.close()
            started.set()
            return
        loop.set_exception_handler(_quiet)
        started.set()
        try:
            loop.run_forever()
        finally:
            loop.run_until_complete(self._shut(server))
            loop.close()

    async def _shut(self, server: asyncio.Server) -> None:
        """Stop listening, close every connection and let each end (a second at most)."""
        server.close()
        for writer in list(self._open):
            writer.close()
        tasks = asyncio.all_tasks() - {asyncio.current_task()}
        if tasks:
            _, late = await asyncio.wait(tasks, timeout=1.0)
            for task in late:
                task.cancel()
            await asyncio.gather(*late, return_exceptions=True)

    async def _listen(self) -> asyncio.Server:
        server = await asyncio.start_server(
            self._connection,
            self.address.host,
            self.address.port,
            backlog=BACKLOG,
            limit=MAX_HEAD_BYTES,
        )
        self.port = server.sockets[0].getsockname()[1]
        names = {f"{name}:{self.port}" for name in ("127.0.0.1", "localhost", "[::1]")}
        host = self.address.host
        names.add(f"[{host}]:{self.port}" if ":" in host else f"{host}:{self.port}")
        if self.port == 80:
            names |= {name.rpartition(":")[0] for name in names}
        self._hosts = frozenset(names)
        return server

    def _set_answer(self, line: bytes) -> None:
        self._answer = line
        self._version += 1
        self._changed.set()
        self._changed = asyncio.Event()

    async def _connection(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        if not self._admit(writer):
            writer.close()
            return
        try:
            head = await self._head(reader, writer)
            if head is not None:
                await self._respond(head, reader, writer)
        except (ConnectionError, TimeoutError, asyncio.IncompleteReadError):
            pass  # the client went, or was too slow: nothing to answer
        finally:
            self._waiting.pop(writer, None)
            self._open.discard(writer)
            writer.close()

    def _admit(self, writer: asyncio.StreamWriter) -> bool:
        """Room for a new connection: the one that has waited longest for a head is closed to
        make it; when every connection is busy, the newcomer is refused."""
        if len(self._open) >= MAX_CONNECTIONS:
            if not self._waiting:
                return False
            oldest, _ = self._waiting.popitem(last=False)
            self._open.discard(oldest)
            oldest.close()
        self._open.add(writer)
        self._waiting[writer] = None
        return True

    async def _head(
        self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter
    ) -> _Request | None:
        """The request's head, whole within :data:`HEAD_SECONDS`; ``None`` when it does not
        come (or the connection was closed to make room)."""
        try:
            raw = await asyncio.wait_for(reader.readuntil(b"\r\n\r\n"), HEAD_SECONDS)
        except (TimeoutError, asyncio.IncompleteReadError, asyncio.LimitOverrunError):
            return None
        finally:
            self._waiting.pop(writer, None)
        try:
            return _parse_head(raw)
        except _Refused as refused:
            await self._send(writer, refused.status, refused.why.encode(), {}, True)
            return None

    async def _respond(
        self, request: _Request, reader: asyncio.StreamReader, writer: asyncio.StreamWriter
    ) -> None:
        cors = self._cors(request)
        body_too = request.method != "HEAD"
        try:
            self._check(request)
            if request.path == "/answer":
                headers = {"Content-Type": "application/json", **cors}
                await self._send(writer, 200, self._answer, headers, body_too)
            elif request.path == "/answer/events":
                await self._stream(reader, writer, cors, body_too)
            elif request.path.startswith("/layouts/"):
                await asyncio.wait_for(
                    self._file(request.path[len("/layouts/") :], writer, cors, body_too),
                    RESPONSE_SECONDS,
                )
            else:
                raise _Refused(404, "not found: /answer, /answer/events, /layouts/<path>")
        except _Refused as refused:
            await self._send(writer, refused.status, refused.why.encode(), cors, body_too)

    def _check(self, request: _Request) -> None:
        if request.method not in ("GET", "HEAD"):
            raise _Refused(405, "read-only: GET and HEAD only")
        if request.headers.get("host", "") not in self._hosts:
            raise _Refused(421, f"this server answers to 127.0.0.1:{self.port} only")
        origin = request.headers.get("origin")
        if origin is not None and origin not in self.origins:
            raise _Refused(
                403, "this origin may not read the answer (teleop-ui watch --viewer-origin)"
            )
        # Another site's page loading it without CORS (an <img> or <script>, which send no
        # Origin): it could not read it, but it would hold a stream; a navigation is the
        # person's own.
        site = request.headers.get("sec-fetch-site")
        navigation = request.headers.get("sec-fetch-mode") == "navigate"
        if site in ("cross-site", "same-site") and origin is None and not navigation:
            raise _Refused(403, "another site's page may not load this")

    def _cors(self, request: _Request) -> dict[str, str]:
        origin = request.headers.get("origin")
        if origin is None or origin not in self.origins:
            return {}
        return {"Access-Control-Allow-Origin": origin}

    async def _send(
        self,
        writer: asyncio.StreamWriter,
        status: int,
        body: bytes,
        headers: dict[str, str],
        body_too: bool,
    ) -> None:
        if status != 200:
            headers = {**headers, "Content-Type": "text/plain; charset=utf-8"}
            body += b"\n"
        writer.write(_head_bytes(status, {**headers, "Content-Length": str(len(body))}))
        if body_too:
            writer.write(body)
        await asyncio.wait_for(writer.drain(), RESPONSE_SECONDS)

    async def _stream(
        self,
        reader: asyncio.StreamReader,
        writer: asyncio.StreamWriter,
        cors: dict[str, str],
        body_too: bool,
    ) -> None:
        if self._streams >= MAX_STREAMS:
            raise _Refused(503, f"at most {MAX_STREAMS} event streams at once")
        headers = {"Content-Type": "text/event-stream", "X-Accel-Buffering": "no", **cors}
        writer.write(_head_bytes(200, headers))
        if not body_too:
            await asyncio.wait_for(writer.drain(), SEND_SECONDS)
            return
        self._streams += 1
        gone = asyncio.ensure_future(reader.read(1))  # the client closing (or sending more)
        try:
            sent = -1
            while not gone.done():
                if sent != self._version:
                    sent = self._version
                    writer.write(b"data: " + self._answer + b"\n\n")
                else:
                    changed = asyncio.ensure_future(self._changed.wait())
                    await asyncio.wait(
                        (gone, changed),
                        timeout=KEEPALIVE_SECONDS,
                        return_when=asyncio.FIRST_COMPLETED,
                    )
                    changed.cancel()
                    if sent == self._version and not gone.done():
                        writer.write(b": keep-alive\n\n")
                await asyncio.wait_for(writer.drain(), SEND_SECONDS)
        finally:
            self._streams -= 1
            gone.cancel()

    async def _file(
        self, encoded: str, writer: asyncio.StreamWriter, cors: dict[str, str], body_too: bool
    ) -> None:
        parts = _layout_parts(encoded)
        handle = _open_below(self.directory, parts)
        try:
            size = os.fstat(handle).st_size
            kind = _CONTENT_TYPES[Path(parts[-1]).suffix]
            headers = {"Content-Type": kind, "Content-Length": str(size), **cors}
            writer.write(_head_bytes(200, headers))
            left = size if body_too else 0
            while left > 0:
                chunk = os.read(handle, min(_CHUNK, left))
                if not chunk:
                    break  # cut short meanwhile: the client sees fewer bytes than announced
                left -= len(chunk)
                writer.write(chunk)
                await writer.drain()
            await writer.drain()
        finally:
            os.close(handle)


def _parse_head(raw: bytes) -> _Request:
    """The request line and headers (names in lower case); :class:`_Refused` for what is
    not a plain HTTP/1 head."""
    lines = raw[:-4].decode("latin-1").split("\r\n")
    if len(lines) - 1 > MAX_HEADERS:
        raise _Refused(431, f"at most {MAX_HEADERS} header lines")
    words = lines[0].split(" ")
    if len(words) != 3 or not words[2].startswith("HTTP/1.") or not words[1].startswith("/"):
        raise _Refused(400, "not an HTTP/1 request line")
    headers: dict[str, str] = {}
    for line in lines[1:]:
        name, colon, value = line.partition(":")
        name = name.lower()
        if not colon or not name or name != name.strip() or name in headers:
            raise _Refused(400, "a malformed or repeated header")
        headers[name] = value.strip(" \t")
    path = words[1].partition("?")[0]
    return _Request(words[0], path, headers)


def _layout_parts(encoded: str) -> list[str]:
    """The names below ``DIR`` an address names (percent-decoded); :class:`_Refused` for
    ``.``, ``..``, a hidden or empty name, a kind of file the watcher does not write."""
    try:
        path = unquote(encoded, errors="strict")
    except UnicodeDecodeError:
        raise _Refused(400, "not a layout's address: not UTF-8") from None
    parts = path.split("/")
    if (
        len(parts) > _MAX_PARTS
        or any(not part or part.startswith(".") or "\\" in part or "\0" in part for part in parts)
        or any(len(part.encode("utf-8", "surrogateescape")) > 255 for part in parts)
    ):
        raise _Refused(403, "not served: a name that is empty, '.', '..' or hidden")
    if Path(parts[-1]).suffix not in _CONTENT_TYPES:
        raise _Refused(404, "not served: only the layouts the watcher writes (.json, .rviz)")
    return parts


def _open_below(directory: Path, parts: list[str]) -> int:
    """The regular file ``parts`` below ``directory``, opened without following a link (each
    folder entered relative to the one before, ``O_NOFOLLOW``); its descriptor."""
    try:
        folder = os.open(directory, _FOLDER)
    except OSError:
        raise _Refused(404, "not found") from None
    try:
        for part in parts[:-1]:
            inner = os.open(part, _FOLDER | _NOFOLLOW, dir_fd=folder)
            os.close(folder)
            folder = inner
        handle = os.open(parts[-1], _FILE, dir_fd=folder)
    except FileNotFoundError:
        raise _Refused(404, "not found") from None
    except OSError:
        raise _Refused(403, "not served: a link or not a file (links are not followed)") from None
    finally:
        os.close(folder)
    mode, size = os.fstat(handle).st_mode, os.fstat(handle).st_size
    if not stat.S_ISREG(mode) or size > MAX_FILE_BYTES:
        os.close(handle)
        if not stat.S_ISREG(mode):
            raise _Refused(403, "not served: not a regular file")
        raise _Refused(413, f"not served: larger than {MAX_FILE_BYTES} bytes")
    return handle


def _head_bytes(status: int, headers: dict[str, str]) -> bytes:
    lines = [f"HTTP/1.1 {status} {_REASONS[status]}"]
    every = {
        "Cache-Control": "no-store",
        "X-Content-Type-Options": "nosniff",
        "Connection": "close",
        "Vary": "Origin",
        **headers,
    }
    lines += [f"{name}: {value}" for name, value in every.items()]
    return ("\r\n".join(lines) + "\r\n\r\n").encode("latin-1")


def _quiet(loop: asyncio.AbstractEventLoop, context: dict[str, Any]) -> None:
    """The loop's errors that are a client's doing (a connection reset, a stream cut off as
    the server stops) are no one's business; anything else is reported as asyncio does."""
    if isinstance(
        context.get("exception"), ConnectionError | TimeoutError | asyncio.CancelledError
    ):
        return
    loop.default_exception_handler(context)
