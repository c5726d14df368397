"""Hostile XML-RPC peers the tests run themselves, on loopback: masters and nodes that trickle,
flood, compress, nest or lie.

:class:`RawServer` accepts connections and hands each to a behaviour (a function of the
connection and the server, whose ``stop`` event it watches) on a thread of its own;
:meth:`RawServer.close` stops every behaviour and closes every socket, so nothing outlives the
test. ``asked`` is set when the first request has arrived: tests wait for it (an event), never
for a time.

:class:`FakeMaster` is a behaviour that speaks HTTP/1.1 and XML-RPC (``system.multicall``
included) with answers the test chooses; an answer may splice raw XML in place of a
placeholder string (:data:`RAW`), for values the standard marshaller cannot write (thousands
of levels deep).

:class:`TricklingClients` is the other side: clients that hold a server's connections by
trickling requests into them, reconnecting whenever they are cut off (a neighbour keeping a
watcher's node API busy).
"""

from __future__ import annotations

import contextlib
import gzip
import select
import socket
import threading
import xmlrpc.client
from collections.abc import Callable
from typing import Any

Behaviour = Callable[[socket.socket, "RawServer"], None]
RAW = "@@raw xml@@"


class RawServer:
    """A TCP server on 127.0.0.1 running ``behaviour`` for every connection."""

    def __init__(self, behaviour: Behaviour) -> None:
        self.behaviour = behaviour
        self.stop = threading.Event()
        self.asked = threading.Event()
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.uri = f"http://127.0.0.1:{self.listener.getsockname()[1]}/"
        self.connections: list[socket.socket] = []
        self.threads: list[threading.Thread] = []
        self._accepting = threading.Thread(target=self._accept, daemon=True)
        self._accepting.start()

    def _accept(self) -> None:
        while not self.stop.is_set():
            try:
                connection, _ = self.listener.accept()
            except OSError:
                return  # closed
            self.connections.append(connection)
            thread = threading.Thread(target=self._serve, args=(connection,), daemon=True)
            self.threads.append(thread)
            thread.start()

    def _serve(self, connection: socket.socket) -> None:
        with contextlib.suppress(OSError):
            self.behaviour(connection, self)

    def close(self) -> None:
        self.stop.set()
        with contextlib.suppress(OSError):
            self.listener.shutdown(socket.SHUT_RDWR)  # wakes the blocked accept() (Linux)
        self.listener.close()
        for connection in self.connections:
            with contextlib.suppress(OSError):
                connection.shutdown(socket.SHUT_RDWR)
            connection.close()
        self._accepting.join(timeout=60)
        for thread in self.threads:
            thread.join(timeout=60)


def read_request(connection: socket.socket, server: RawServer) -> bytes | None:
    """One HTTP request's body (``None`` when the peer closed); sets ``server.asked``."""
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = connection.recv(65536)
        if not chunk:
            return None
        data += chunk
    head, body = data.split(b"\r\n\r\n", 1)
    length = 0
    for line in head.split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            length = int(value)
    while len(body) < length:
        chunk = connection.recv(65536)
        if not chunk:
            return None
        body += chunk
    server.asked.set()
    return body


def respond(connection: socket.socket, body: bytes, headers: str = "") -> None:
    connection.sendall(
        f"HTTP/1.1 200 OK\r\nContent-Type: text/xml\r\nContent-Length: {len(body)}\r\n"
        f"{headers}\r\n".encode()
        + body
    )


# -- behaviours -------------------------------------------------------------------------------


def trickling(connection: socket.socket, server: RawServer) -> None:
    """Reads a request, then answers one byte a second, for ever (until the test ends)."""
    if read_request(connection, server) is None:
        return
    reply = b"HTTP/1.1 200 OK\r\nContent-Type: text/xml\r\nContent-Length: 100000\r\n\r\n"
    reply += b"<methodResponse>" + b" " * 100000
    for byte in reply:
        connection.sendall(bytes([byte]))
        if server.stop.wait(1.0):
            return


def flooding(*, chunked: bool) -> Behaviour:
    """Answers with a body of 300 MB (declared), or with chunks that never end."""

    def behaviour(connection: socket.socket, server: RawServer) -> None:
        if read_request(connection, server) is None:
            return
        if chunked:
            connection.sendall(b"HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n")
            piece = b"10000\r\n" + b"x" * 0x10000 + b"\r\n"
        else:
            connection.sendall(b"HTTP/1.1 200 OK\r\nContent-Length: 300000000\r\n\r\n")
            piece = b"x" * 0x10000
        while not server.stop.is_set():
            connection.sendall(piece)

    return behaviour


def gzip_bomb(size: int) -> bytes:
    """A gzip body that inflates to an XML-RPC reply of ``size`` bytes (a long string)."""
    head = b"<?xml version='1.0'?><methodResponse><params><param><value><string>"
    tail = b"</string></value></param></params></methodResponse>"
    return gzip.compress(head + b"a" * (size - len(head) - len(tail)) + tail, compresslevel=9)


def answering(body: bytes, headers: str = "") -> Behaviour:
    """Answers every request on the connection with the same raw reply."""

    def behaviour(connection: socket.socket, server: RawServer) -> None:
        while not server.stop.is_set() and read_request(connection, server) is not None:
            respond(connection, body, headers)

    return behaviour


class FakeMaster:
    """An XML-RPC peer with chosen answers: ``answers[method](*params)`` gives the reply value
    (the caller id is the first param, as in the ROS APIs); a string :data:`RAW` in a reply is
    replaced by ``raw`` (raw XML for one value)."""

    def __init__(self, answers: dict[str, Callable[..., Any]], raw: str = "") -> None:
        self.answers = answers
        self.raw = raw
        self.calls: list[str] = []
        self.server = RawServer(self._behaviour)
        self.uri = self.server.uri

    def reply(self, method: str, params: tuple[Any, ...]) -> Any:
        self.calls.append(method)
        if method == "system.multicall":
            return [[self.reply(call["methodName"], tuple(call["params"]))] for call in params[0]]
        return self.answers[method](*params)

    def _behaviour(self, connection: socket.socket, server: RawServer) -> None:
        while not server.stop.is_set():
            body = read_request(connection, server)
            if body is None:
                return
            params, method = xmlrpc.client.loads(body)
            try:
                value = self.reply(str(method), params)
                text = xmlrpc.client.dumps((value,), methodresponse=True)
            except KeyError:
                text = xmlrpc.client.dumps(xmlrpc.client.Fault(1, f"no method {method}"))
            marker = xmlrpc.client.dumps((RAW,))
            marker = marker[marker.index("<value>") : marker.rindex("</value>") + 8]
            respond(connection, text.replace(marker, self.raw).encode())

    def close(self) -> None:
        self.server.close()


class TricklingClients:
    """``count`` clients of the XML-RPC server at ``uri``, each sending the head of a request
    and then one byte of its body every ``every`` seconds, and connecting again (after
    ``every``) whenever the server ends the connection, until :meth:`close`. ``ended`` counts
    the connections the server ended: tests wait for it (an event), never for a time."""

    def __init__(self, uri: str, count: int, every: float = 0.5) -> None:
        host, port = uri.removeprefix("http://").rstrip("/").rsplit(":", 1)
        self.address = (host, int(port))
        self.every = every
        self.stop = threading.Event()
        self.ended = 0
        self._changed = threading.Condition()
        self.threads = [threading.Thread(target=self._run, daemon=True) for _ in range(count)]
        for thread in self.threads:
            thread.start()

    def _run(self) -> None:
        while not self.stop.is_set():
            with (
                contextlib.suppress(OSError),
                socket.create_connection(self.address, timeout=60) as connection,
            ):
                connection.sendall(b"POST / HTTP/1.1\r\nContent-Length: 100000\r\n\r\n")
                self._trickle(connection)
            with self._changed:
                self.ended += 1
                self._changed.notify_all()
            self.stop.wait(self.every)

    def _trickle(self, connection: socket.socket) -> None:
        """A byte whenever the server said nothing for ``every``, until it closes."""
        while not self.stop.is_set():
            readable, _, _ = select.select([connection], [], [], self.every)
            if not readable:
                connection.sendall(b"<")
            elif connection.recv(65536) == b"":
                return

    def wait_ended(self, count: int, timeout: float = 60.0) -> None:
        """Until the server has ended ``count`` of these connections."""
        with self._changed:
            if not self._changed.wait_for(lambda: self.ended >= count, timeout):
                raise AssertionError(f"the server ended {self.ended} connections, not {count}")

    def close(self) -> None:
        self.stop.set()
        for thread in self.threads:
            thread.join(timeout=60)


def empty_graph(params: dict[str, Any] | None = None) -> dict[str, Callable[..., Any]]:
    """The answers of a master with no robots and ``params`` (absolute keys) set."""
    values = dict(params or {})

    def get_param(_caller: str, key: str) -> list[Any]:
        prefix = key.rstrip("/") + "/"
        if key in values:
            return [1, "", values[key]]
        subtree = {k[len(prefix) :]: v for k, v in values.items() if k.startswith(prefix)}
        return [1, "", subtree] if subtree else [-1, "not set", 0]

    return {
        "getPid": lambda _caller: [1, "", 4242],
        "getSystemState": lambda _caller: [1, "", [[], [], []]],
        "getTopicTypes": lambda _caller: [1, "", []],
        "getParamNames": lambda _caller: [1, "", sorted(values)],
        "getParam": get_param,
        "lookupNode": lambda _caller, _name: [-1, "unknown", ""],
    }


def post_raw(uri: str, head: str, body: bytes = b"") -> bytes:
    """The answer of the XML-RPC server at ``uri`` to ``head`` (a request line and headers)
    and ``body``, read until it is whole or the connection closes."""
    host, port = uri.removeprefix("http://").rstrip("/").rsplit(":", 1)
    with socket.create_connection((host, int(port)), timeout=60) as connection:
        connection.sendall(head.encode() + b"\r\n\r\n" + body)
        reply = b""
        while chunk := connection.recv(65536):
            reply += chunk
            if b"\r\n\r\n" in reply and b"</methodResponse>" in reply:
                break
            if reply.startswith(b"HTTP/1.") and b" 200 " not in reply.split(b"\r\n")[0]:
                break
    return reply


def deep_xml(depth: int, leaf: str = "<value>x</value>") -> str:
    """Raw XML-RPC for a list ``depth`` levels deep (the standard marshaller recurses)."""
    return "<value><array><data>" * depth + leaf + "</data></array></value>" * depth


def raw_set_param(master: str, key: str, value_xml: str, caller: str = "/hostile") -> None:
    """``setParam`` with a value written as raw XML-RPC (a real master takes what its parser
    takes: thousands of levels deep, tens of megabytes)."""
    import urllib.request

    body = (
        "<?xml version='1.0'?><methodCall><methodName>setParam</methodName><params>"
        f"<param><value>{caller}</value></param><param><value>{key}</value></param>"
        f"<param>{value_xml}</param></params></methodCall>"
    ).encode()
    request = urllib.request.Request(master, body, {"Content-Type": "text/xml"})
    with urllib.request.urlopen(request, timeout=60) as reply:
        answer: Any = xmlrpc.client.loads(reply.read())[0][0]
    if answer[0] != 1:
        raise AssertionError(f"the master refused setParam {key}")
