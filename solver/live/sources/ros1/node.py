"""The watcher as a ROS node: the XML-RPC server the master calls back (the ROS "slave" API).

A ROS master tells a node that a parameter changed by calling the node's ``paramUpdate``
(after ``subscribeParam``; this is how roscpp and rospy keep cached parameters current). The
watcher subscribes to every robot's description and to ``/teleop_ui``, so a description set in
place or an operator's switch reaches it at once, without fetching large descriptions on every
poll. :class:`NodeServer` answers the calls a master or a ROS tool makes: ``paramUpdate``,
``publisherUpdate``, ``shutdown`` (a master sends it when another node registers the same
name: the watcher stops cleanly), ``getPid``, ``getMasterUri``, ``getBusInfo``,
``getBusStats``, ``getPublications``, ``getSubscriptions``. A node holding only parameter
subscriptions is not in ``getSystemState``, so ``rosnode list`` and ``rosnode kill`` do not
see it.

The server listens where the master can reach it, chosen as ROS does (:func:`callback_host`):
the loopback address for a master on this machine, else ``ROS_IP`` or ``ROS_HOSTNAME``, else
the local address of the route to the master.

*What it trusts.* ROS 1 has no authentication: anyone who can reach this port can call it, with
any caller id. So nothing a call carries is believed: ``paramUpdate`` passes on only the *key*
(the watcher reads the value from the master again, :mod:`~solver.live.sources.ros1.descriptions`),
and its value is never used; ``shutdown`` stops the watcher, as it stops every ROS 1 node
(``rosnode kill`` sends it), which changes no answer the watcher gives. Requests are bounded as
replies are (:mod:`~solver.live.sources.ros1.rpc`): at most
:data:`~solver.live.sources.ros1.rpc.MAX_REPLY_BYTES` of body, none in a content encoding (ROS
clients send plain XML: a gzip body is not inflated), no DTD, values nested deeper
than :data:`~solver.live.graph.MAX_DEPTH` not built; a connection that stalls is dropped after
:data:`REQUEST_TIMEOUT` seconds per read, and one that trickles in (a byte now and then, each
read within that) is cut off :data:`REQUEST_DEADLINE` seconds after it was accepted, unless it
has been read whole by then (parsing a request of the largest size allowed, nested deep, takes
about a second, more on a busy machine: that parse does not lose the answer to a request read
in time). An answer is written by a deadline of its own, as long from when it is ready, and it
is short: nothing a caller sends is echoed back longer than a line.

*Slots.* At most :data:`MAX_CONNECTIONS` requests are served at once. When they are all taken,
a new connection is not turned away: the oldest request still being *read* is cut off to make
room for it (a request read whole is answered at once: every call here is a few lines). A
neighbour that opens connections and trickles into them holds no slot against a newcomer, so
the master's ``paramUpdate``, sent whole in one go, is served however many connections trickle;
only a flood of more than :data:`MAX_CONNECTIONS` new connections within the moment it takes to
read that request can still cut it off, and a push lost so is healed by the descriptions'
re-reading (:mod:`~solver.live.sources.ros1.descriptions`). Cut-off requests whose threads have
not ended yet count too: past twice :data:`MAX_CONNECTIONS` threads, new connections are closed
unanswered.

Not here: what an update means (:mod:`~solver.live.sources.ros1.descriptions`,
:mod:`solver.live.watcher`).
"""

from __future__ import annotations

import contextlib
import os
import socket
import socketserver
import threading
import xmlrpc.client
from collections.abc import Callable
from typing import Any, Final
from urllib.parse import urlsplit
from xmlrpc.server import SimpleXMLRPCRequestHandler, SimpleXMLRPCServer

from solver.errors import InputError
from solver.live.sources.ros1.master import is_loopback
from solver.live.sources.ros1.rpc import MAX_REPLY_BYTES, loads
from solver.untrusted import shown

__all__ = [
    "MAX_CONNECTIONS",
    "REQUEST_DEADLINE",
    "REQUEST_TIMEOUT",
    "NodeServer",
    "callback_host",
]

_OK = 1
REQUEST_TIMEOUT: Final = 1.0
REQUEST_DEADLINE: Final = 2.0
MAX_CONNECTIONS: Final = 16


def callback_host(master: str) -> str:
    """The address this node advertises to the master at ``master`` (see the module doc)."""
    if is_loopback(master):
        return "127.0.0.1"
    for variable in ("ROS_IP", "ROS_HOSTNAME"):
        value = os.environ.get(variable, "").strip()
        if value:
            return value
    parts = urlsplit(master)
    # A UDP "connection" sends nothing; it only asks the kernel which local address routes
    # to the master.
    family = socket.AF_INET6 if ":" in (parts.hostname or "") else socket.AF_INET
    with socket.socket(family, socket.SOCK_DGRAM) as probe:
        try:
            probe.connect((parts.hostname or "", parts.port or 11311))
            return str(probe.getsockname()[0])
        except OSError:
            return socket.gethostname()


class _Server(socketserver.ThreadingMixIn, SimpleXMLRPCServer):
    """A thread per request, :data:`MAX_CONNECTIONS` slots (see the module docstring: the
    oldest request still being read gives its slot to a newcomer); requests parsed by the
    bounded parser (:func:`solver.live.sources.ros1.rpc.loads`)."""

    daemon_threads = True
    allow_reuse_address = True
    # Connections the kernel holds before they are accepted: a burst does not refuse the master.
    request_queue_size = 4 * MAX_CONNECTIONS
    deadline = REQUEST_DEADLINE

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._lock = threading.Lock()
        self._running = 0  # request threads not ended yet, cut-off ones included
        self._reading: dict[socket.socket, None] = {}  # not read whole yet, oldest first
        self._current = threading.local()  # the request this thread serves

    def process_request(self, request: Any, client_address: Any) -> None:
        if not self._admit(request):
            self.shutdown_request(request)  # too many threads still ending: try again
            return
        try:
            super().process_request(request, client_address)
        except BaseException:
            self._ended(request)
            raise

    def _admit(self, request: socket.socket) -> bool:
        """Take a slot for ``request``, cutting off the oldest request still being read when
        every slot is taken; ``False`` when there is none to cut off."""
        with self._lock:
            if self._running >= MAX_CONNECTIONS:
                if not self._reading or self._running >= 2 * MAX_CONNECTIONS:
                    return False
                oldest = next(iter(self._reading))
                del self._reading[oldest]
                _cut(oldest)  # its read ends at once, and its thread with it
            self._running += 1
            self._reading[request] = None
            return True

    def _ended(self, request: socket.socket) -> None:
        with self._lock:
            self._running -= 1
            self._reading.pop(request, None)

    def process_request_thread(self, request: Any, client_address: Any) -> None:
        # The request arrives by the deadline, however slowly it comes: its socket is shut down
        # then, which ends the read under way; its answer is written by a deadline of its own.
        self._current.request = request
        self._current.deadline = None
        try:
            self._current.deadline = self._cut_after(request)
            super().process_request_thread(request, client_address)
        finally:
            if self._current.deadline is not None:
                self._current.deadline.cancel()
            self._ended(request)

    def _cut_after(self, request: socket.socket) -> threading.Timer:
        """A timer that shuts ``request``'s socket down :attr:`deadline` seconds from now."""
        timer = threading.Timer(self.deadline, _cut, (request,))
        timer.daemon = True
        timer.start()
        return timer

    def read_whole(self) -> None:
        """The request this thread serves was read whole: no longer one to cut off for a
        newcomer, and its arrival's deadline is over (parsing the largest request allowed,
        nested deep, takes about a second, longer on a busy machine)."""
        request: socket.socket | None = getattr(self._current, "request", None)
        if request is None:
            return
        with self._lock:
            self._reading.pop(request, None)
        if self._current.deadline is not None:
            self._current.deadline.cancel()

    def handle_error(self, request: Any, client_address: Any) -> None:
        """A request that failed (cut off, or its caller gone) ends quietly: the watcher's
        output is its events, and the caller's mistake is no one else's."""

    def _marshaled_dispatch(
        self,
        data: Any,
        dispatch_method: Any = None,  # noqa: ARG002 - the standard signature
        path: Any = None,  # noqa: ARG002
    ) -> Any:  # bytes (typeshed says str)
        """The standard dispatch, with the bounded parser instead of ``xmlrpc.client.loads``;
        the answer is written by a deadline of its own (a caller that reads it slowly is cut
        off, as one that sends slowly is)."""
        try:
            params, method = loads(data)
            if method is None:
                raise xmlrpc.client.ResponseError("not a method call")
            response = self._dispatch(method, params)
            encoded = xmlrpc.client.dumps((response,), methodresponse=True, allow_none=False)
        except Exception as error:  # a caller's mistake is its answer, never the server's end
            # A fault the caller sent (a methodResponse) too: no call here raises one, and its
            # text is the caller's, cut as every echo is.
            message = f"{type(error).__name__}: {error}"[:200]
            encoded = xmlrpc.client.dumps(xmlrpc.client.Fault(1, message))
        request: socket.socket | None = getattr(self._current, "request", None)
        if request is not None:
            if self._current.deadline is not None:
                self._current.deadline.cancel()
            self._current.deadline = self._cut_after(request)
        return encoded.encode("utf-8", "xmlcharrefreplace")


def _cut(request: socket.socket) -> None:
    with contextlib.suppress(OSError):  # already closed: the request ended in time
        request.shutdown(socket.SHUT_RDWR)


class _Quiet(SimpleXMLRPCRequestHandler):
    """The standard handler, bounded: a read that stalls ends the request, and a body longer
    than the cap, or in a content encoding, is refused unread."""

    timeout = REQUEST_TIMEOUT

    def decode_request_content(self, data: bytes) -> bytes | None:
        """The body, read whole (the standard handler calls this right after reading it; an
        encoded body was refused unread)."""
        if isinstance(self.server, _Server):
            self.server.read_whole()
        return data

    def do_POST(self) -> None:
        length = self.headers.get("content-length", "")
        encoding = self.headers.get("content-encoding", "identity").strip().lower()
        if not length.strip().isdigit() or int(length) > MAX_REPLY_BYTES:
            self._refuse(413 if length.strip().isdigit() else 411)
        elif encoding != "identity":
            # ROS clients send plain XML; the standard handler would inflate a gzip body and
            # echo any other encoding's name back in its error, however long.
            self._refuse(415)
        else:
            super().do_POST()

    def _refuse(self, status: int) -> None:
        """An empty answer of ``status``, the body unread, the connection closed."""
        self.send_response(status)
        self.send_header("Content-Length", "0")
        self.send_header("Connection", "close")
        self.end_headers()
        self.close_connection = True

    def log_message(self, format: str, *args: Any) -> None:
        """Requests are not logged: the watcher's output is its events."""


class NodeServer:
    """An XML-RPC node API on a free port of ``host``; calls arrive on a server thread."""

    def __init__(
        self,
        host: str,
        master: str,
        on_param_update: Callable[[str], None],
        on_shutdown: Callable[[str], None],
        *,
        deadline: float = REQUEST_DEADLINE,
    ) -> None:
        self.master = master
        self._on_param_update = on_param_update
        self._on_shutdown = on_shutdown
        try:
            self._server = _Server(
                (host, 0),
                requestHandler=_Quiet,
                logRequests=False,
                allow_none=False,
                use_builtin_types=True,
            )
        except OSError as error:
            raise InputError.at(
                "<network>",
                f"cannot listen for the ROS master's calls on "
                f"{host!r} ({error.strerror or error}); set "
                f"ROS_IP to an address of this machine",
            ) from None
        self._server.deadline = deadline
        address = self._server.server_address
        shown = f"[{host}]" if ":" in host else host
        self.uri = f"http://{shown}:{address[1]}/"
        for name in (
            "paramUpdate",
            "publisherUpdate",
            "shutdown",
            "getPid",
            "getMasterUri",
            "getBusInfo",
            "getBusStats",
            "getPublications",
            "getSubscriptions",
            "requestTopic",
        ):
            self._server.register_function(getattr(self, f"_{name}"), name)
        self._thread = threading.Thread(
            target=self._server.serve_forever,
            kwargs={"poll_interval": 0.1},
            name=f"teleop-ui node {self.uri}",
            daemon=True,
        )

    def start(self) -> None:
        self._thread.start()

    def close(self) -> None:
        if self._thread.is_alive():
            self._server.shutdown()
            self._thread.join()
        self._server.server_close()

    # -- the node API (every answer is [code, message, value]) ---------------------------

    def _paramUpdate(self, _caller: Any, key: Any, _value: Any) -> list[Any]:
        # A hint only (see the module docstring): the value is read from the master again.
        if isinstance(key, str):
            self._on_param_update(key)
        return [_OK, "", 0]

    def _publisherUpdate(self, _caller: str, _topic: str, _publishers: list[str]) -> list[Any]:
        return [_OK, "", 0]

    def _shutdown(self, _caller: Any, message: Any = "") -> list[Any]:
        self._on_shutdown(message if isinstance(message, str) else "")
        return [_OK, "shutting down", 0]

    def _getPid(self, _caller: str) -> list[Any]:
        return [_OK, "", os.getpid()]

    def _getMasterUri(self, _caller: str) -> list[Any]:
        return [_OK, "", self.master]

    def _getBusInfo(self, _caller: str) -> list[Any]:
        return [_OK, "", []]

    def _getBusStats(self, _caller: str) -> list[Any]:
        return [_OK, "", [[], [], []]]

    def _getPublications(self, _caller: str) -> list[Any]:
        return [_OK, "", []]

    def _getSubscriptions(self, _caller: str) -> list[Any]:
        return [_OK, "", []]

    def _requestTopic(self, _caller: str, topic: str, _protocols: list[Any]) -> list[Any]:
        return [-1, f"the teleop-ui watcher publishes no topic (asked for {shown(topic)})", 0]
