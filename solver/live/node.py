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

Not here: what an update means (:mod:`solver.live.descriptions`, :mod:`solver.live.watcher`).
"""

from __future__ import annotations

import os
import socket
import socketserver
import threading
from collections.abc import Callable
from typing import Any
from urllib.parse import urlsplit
from xmlrpc.server import SimpleXMLRPCRequestHandler, SimpleXMLRPCServer

from solver.errors import InputError
from solver.live.master import is_loopback

__all__ = ["NodeServer", "callback_host"]

_OK = 1


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
    daemon_threads = True
    allow_reuse_address = True


class _Quiet(SimpleXMLRPCRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        """Requests are not logged: the watcher's output is its events."""


class NodeServer:
    """An XML-RPC node API on a free port of ``host``; calls arrive on a server thread."""

    def __init__(
        self,
        host: str,
        master: str,
        on_param_update: Callable[[str, Any], None],
        on_shutdown: Callable[[str], None],
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

    def _paramUpdate(self, _caller: str, key: str, value: Any) -> list[Any]:
        self._on_param_update(key, value)
        return [_OK, "", 0]

    def _publisherUpdate(self, _caller: str, _topic: str, _publishers: list[str]) -> list[Any]:
        return [_OK, "", 0]

    def _shutdown(self, _caller: str, message: str = "") -> list[Any]:
        self._on_shutdown(message)
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
