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
:data:`~solver.live.sources.ros1.rpc.MAX_REPLY_BYTES` of body, no DTD, values nested deeper
than :data:`~solver.live.graph.MAX_DEPTH` not built; a connection that stalls is dropped after
:data:`REQUEST_TIMEOUT` seconds per read, one that trickles in (a byte now and then, each read
within that) is cut off :data:`REQUEST_DEADLINE` seconds after it was accepted, and at most
:data:`MAX_CONNECTIONS` requests are served at once (more are closed unanswered).

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

__all__ = [
    "MAX_CONNECTIONS",
    "REQUEST_DEADLINE",
    "REQUEST_TIMEOUT",
    "NodeServer",
    "callback_host",
]

_OK = 1
REQUEST_TIMEOUT: Final = 5.0
REQUEST_DEADLINE: Final = 10.0
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
    """A thread per request, at most :data:`MAX_CONNECTIONS` at once; requests parsed by the
    bounded parser (:func:`solver.live.sources.ros1.rpc.loads`)."""

    daemon_threads = True
    allow_reuse_address = True
    deadline = REQUEST_DEADLINE

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._slots = threading.BoundedSemaphore(MAX_CONNECTIONS)

    def process_request(self, request: Any, client_address: Any) -> None:
        if not self._slots.acquire(blocking=False):
            self.shutdown_request(request)  # busy: the caller may try again
            return
        try:
            super().process_request(request, client_address)
        except BaseException:
            self._slots.release()
            raise

    def process_request_thread(self, request: Any, client_address: Any) -> None:
        # The whole request ends by the deadline, however slowly it comes: its socket is shut
        # down then, which ends the read under way.
        timer = threading.Timer(self.deadline, _cut, (request,))
        timer.daemon = True
        timer.start()
        try:
            super().process_request_thread(request, client_address)
        finally:
            timer.cancel()
            self._slots.release()

    def _marshaled_dispatch(
        self,
        data: Any,
        dispatch_method: Any = None,  # noqa: ARG002 - the standard signature
        path: Any = None,  # noqa: ARG002
    ) -> Any:  # bytes (typeshed says str)
        """The standard dispatch, with the bounded parser instead of ``xmlrpc.client.loads``."""
        try:
            params, method = loads(data)
            if method is None:
                raise xmlrpc.client.ResponseError("not a method call")
            response = self._dispatch(method, params)
            encoded = xmlrpc.client.dumps((response,), methodresponse=True, allow_none=False)
        except xmlrpc.client.Fault as fault:
            encoded = xmlrpc.client.dumps(fault, allow_none=False)
        except Exception as error:  # a caller's mistake is its answer, never the server's end
            message = f"{type(error).__name__}: {error}"[:200]
            encoded = xmlrpc.client.dumps(xmlrpc.client.Fault(1, message))
        return encoded.encode("utf-8", "xmlcharrefreplace")


def _cut(request: socket.socket) -> None:
    with contextlib.suppress(OSError):  # already closed: the request ended in time
        request.shutdown(socket.SHUT_RDWR)


class _Quiet(SimpleXMLRPCRequestHandler):
    """The standard handler, bounded: a read that stalls ends the request, and a body longer
    than the cap is refused unread."""

    timeout = REQUEST_TIMEOUT

    def do_POST(self) -> None:
        length = self.headers.get("content-length", "")
        if not length.strip().isdigit() or int(length) > MAX_REPLY_BYTES:
            self.send_response(413 if length.strip().isdigit() else 411)
            self.send_header("Content-Length", "0")
            self.send_header("Connection", "close")
            self.end_headers()
            self.close_connection = True
            return
        super().do_POST()

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
        return [-1, f"the teleop-ui watcher publishes no topic (asked for {topic})", 0]
