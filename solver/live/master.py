"""A client for the ROS 1 master's XML-RPC API, on Python's standard library, with timeouts.

The master (``rosmaster``, started by ``roscore``) answers every call with ``[code, message,
value]``: code 1 is success, -1 a caller error (a parameter that is not set), 0 a failure on
the master. :class:`MasterClient` makes the calls the watcher needs (getPid, getSystemState,
getTopicTypes, getParamNames, getParam, setParam, deleteParam, subscribeParam,
unsubscribeParam) and the ones a test or a tool needs to play a node (registerPublisher,
registerSubscriber, lookupNode), checks the shape of every reply, and turns every way a call
can go wrong into one of two errors:

* :class:`MasterUnreachable`: no answer at all (refused, timed out, dropped): the master is
  down, restarting or on the wrong port;
* :class:`MasterError`: an answer, but not one a ROS master gives (an HTTP error, an XML-RPC
  fault, a malformed reply, code 0): the address is not a ROS master, or the master failed.

Every call has a timeout (the socket's, for connecting and for each read), so a master that
hangs is reported instead of hanging the caller. Connections are kept alive between calls
(rosmaster speaks HTTP/1.1). :meth:`MasterClient.observe` reads everything one poll needs in a
single round trip through ``system.multicall``, which rosmaster's server offers; against a
master without it, it falls back to one call per method.

Not here: what the graph means (:mod:`solver.live.discovery`), answering the master's calls to
a node (:mod:`solver.live.node`).
"""

from __future__ import annotations

import contextlib
import enum
import http.client
import ipaddress
import os
import xmlrpc.client
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Final
from urllib.parse import urlsplit
from xml.parsers.expat import ExpatError

from solver.errors import InputError, SolverError

__all__ = [
    "MISSING",
    "MasterClient",
    "MasterError",
    "MasterUnreachable",
    "Observation",
    "is_loopback",
    "master_uri",
]

SUCCESS: Final = 1
CALLER_ERROR: Final = -1


class _Missing(enum.Enum):
    """The value of a parameter that is not set (``None`` cannot travel in ROS's XML-RPC)."""

    MISSING = "MISSING"


MISSING: Final = _Missing.MISSING


class MasterError(SolverError, ConnectionError):
    """The master cannot be used: it answered, but not as a ROS master does."""


class MasterUnreachable(MasterError):
    """The master did not answer at all: refused, timed out, or the connection dropped."""


@dataclass(frozen=True, slots=True)
class Observation:
    """Everything one poll reads from the master, in one round trip.

    ``publishers`` / ``subscribers``: (topic, node names) pairs from getSystemState;
    ``topic_types``: (topic, message type) pairs from getTopicTypes (the master never forgets a
    type, so it lists topics nobody uses any more); ``params``: the parameter subtree the
    caller asked for, as (key, value) pairs, empty when it is not set.
    """

    pid: int
    publishers: tuple[tuple[str, tuple[str, ...]], ...]
    subscribers: tuple[tuple[str, tuple[str, ...]], ...]
    topic_types: tuple[tuple[str, str], ...]
    param_names: tuple[str, ...]
    params: tuple[tuple[str, Any], ...] = ()


def master_uri(text: str | None) -> str:
    """``http://host:port`` checked and normalised (trailing slash); :class:`InputError` if bad.

    ``None`` reads ``ROS_MASTER_URI``, as every ROS tool does.
    """
    given = text if text is not None else os.environ.get("ROS_MASTER_URI")
    where = "--master" if text is not None else "ROS_MASTER_URI"
    if not given:
        raise InputError.at(
            "<arguments>",
            "no ROS master given: pass --master http://HOST:PORT or set ROS_MASTER_URI",
        )
    parts = urlsplit(given.strip())
    try:
        port = parts.port
    except ValueError:
        port = None
    if (
        parts.scheme != "http"
        or not parts.hostname
        or port is None
        or parts.query
        or parts.fragment
        or parts.path not in ("", "/")
    ):
        raise InputError.at(
            "<arguments>",
            f"{where}: expected a ROS master URI like http://127.0.0.1:11311, got {given!r}",
        )
    host = f"[{parts.hostname}]" if ":" in parts.hostname else parts.hostname
    return f"http://{host}:{port}/"


def is_loopback(uri: str) -> bool:
    """Whether the master at ``uri`` is on this machine's loopback interface."""
    host = urlsplit(uri).hostname or ""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


class _TimeoutTransport(xmlrpc.client.Transport):
    """The standard transport with a socket timeout on connecting and on every read."""

    def __init__(self, timeout: float) -> None:
        super().__init__(use_builtin_types=True)
        self.timeout = timeout

    def make_connection(self, host: Any) -> http.client.HTTPConnection:
        connection = super().make_connection(host)
        connection.timeout = self.timeout
        return connection


class MasterClient:
    """Calls to one ROS master as one caller (a ROS node name such as ``/teleop_ui_watch``).

    Not thread-safe: one client per thread (the standard library's proxy is not).
    """

    def __init__(self, uri: str, *, caller_id: str = "/teleop_ui", timeout: float = 2.0) -> None:
        self.uri = uri
        self.caller_id = caller_id
        self.timeout = timeout
        self._transport = _TimeoutTransport(timeout)
        self._proxy = xmlrpc.client.ServerProxy(
            uri, transport=self._transport, use_builtin_types=True
        )
        self._multicall: bool | None = None  # unknown until the first batch

    def close(self) -> None:
        self._transport.close()

    # -- the calls -----------------------------------------------------------------------

    def get_pid(self) -> int:
        return self._pid(self._value("getPid"))

    def get_param(self, key: str) -> Any:
        """The value of ``key`` (a namespace gives a dict), or :data:`MISSING`."""
        code, _, value = self._call("getParam", key)
        return value if code == SUCCESS else MISSING

    def get_params(self, keys: Sequence[str]) -> dict[str, Any]:
        """Several parameters in one round trip: key -> value or :data:`MISSING`."""
        replies = self._batch([("getParam", key) for key in keys])
        return {
            key: value if code == SUCCESS else MISSING
            for key, (code, _, value) in zip(keys, replies, strict=True)
        }

    def set_param(self, key: str, value: Any) -> None:
        self._value("setParam", key, value)

    def delete_param(self, key: str) -> None:
        """Delete ``key``; a key that is not set is not an error (the end state is reached)."""
        self._call("deleteParam", key)

    def subscribe_param(self, caller_api: str, key: str) -> Any:
        """The value of ``key`` (or :data:`MISSING`); later changes go to ``caller_api``."""
        value = self._value("subscribeParam", caller_api, key)
        # rosmaster answers an unset parameter with an empty dict.
        return MISSING if value == {} else value

    def unsubscribe_param(self, caller_api: str, key: str) -> None:
        self._value("unsubscribeParam", caller_api, key)

    def unsubscribe_params(self, caller_api: str, keys: Iterable[str]) -> None:
        """Several unsubscriptions in one round trip."""
        for code, message, _ in self._batch(
            [("unsubscribeParam", caller_api, key) for key in keys]
        ):
            if code != SUCCESS:
                raise MasterError.at(self.uri, message, path="unsubscribeParam")

    def register_publisher(self, topic: str, message_type: str, caller_api: str) -> None:
        self._value("registerPublisher", topic, message_type, caller_api)

    def register_subscriber(self, topic: str, message_type: str, caller_api: str) -> None:
        self._value("registerSubscriber", topic, message_type, caller_api)

    def unregister_publisher(self, topic: str, caller_api: str) -> None:
        self._value("unregisterPublisher", topic, caller_api)

    def unregister_subscriber(self, topic: str, caller_api: str) -> None:
        self._value("unregisterSubscriber", topic, caller_api)

    def lookup_node(self, name: str) -> str | None:
        """The XML-RPC URI of node ``name``, or ``None`` when the master does not know it."""
        code, _, value = self._call("lookupNode", name)
        return str(value) if code == SUCCESS else None

    def observe(self, params: str | None = None) -> Observation:
        """The graph and parameter names (and the subtree ``params``) in one round trip."""
        calls: list[tuple[Any, ...]] = [
            ("getPid",),
            ("getSystemState",),
            ("getTopicTypes",),
            ("getParamNames",),
        ]
        if params is not None:
            calls.append(("getParam", params))
        replies = self._batch(calls)
        for (method, *_), (code, message, _) in zip(calls, replies, strict=True):
            if code != SUCCESS and method != "getParam":
                raise MasterError.at(self.uri, message or f"code {code}", path=method)
        pid = self._pid(replies[0][2])
        state = replies[1][2]
        if not isinstance(state, list) or len(state) != 3:
            raise self._malformed("getSystemState", "[publishers, subscribers, services]")
        subtree = replies[4][2] if params is not None and replies[4][0] == SUCCESS else {}
        return Observation(
            pid=pid,
            publishers=self._pairs_of_lists(state[0]),
            subscribers=self._pairs_of_lists(state[1]),
            topic_types=self._pairs(replies[2][2]),
            param_names=self._names(replies[3][2]),
            params=tuple(sorted(subtree.items())) if isinstance(subtree, dict) else (),
        )

    # -- plumbing ------------------------------------------------------------------------

    def _value(self, method: str, *args: Any) -> Any:
        code, message, value = self._call(method, *args)
        if code != SUCCESS:
            raise MasterError.at(self.uri, message or f"code {code}", path=method)
        return value

    def _call(self, method: str, *args: Any) -> tuple[int, str, Any]:
        with _translated(self.uri, method):
            reply = getattr(self._proxy, method)(self.caller_id, *args)
        return self._triple(method, reply)

    def _batch(self, calls: Sequence[tuple[Any, ...]]) -> list[tuple[int, str, Any]]:
        """Calls (method, *args) in one ``system.multicall``, or one by one without it."""
        if not calls:
            return []
        if self._multicall is not False:
            multicall = xmlrpc.client.MultiCall(self._proxy)
            for method, *args in calls:
                getattr(multicall, method)(self.caller_id, *args)
            try:
                with _translated(self.uri, "system.multicall"):
                    results = list(multicall().results)
            except MasterUnreachable:
                raise
            except MasterError:
                if self._multicall:
                    raise
                # The server has no system.multicall (it is not part of the ROS master API,
                # only of rosmaster's server): use plain calls from now on.
                self._multicall = False
            else:
                self._multicall = True
                return [
                    self._multicall_item(call[0], item)
                    for call, item in zip(calls, results, strict=True)
                ]
        return [self._call(method, *args) for method, *args in calls]

    def _multicall_item(self, method: str, item: Any) -> tuple[int, str, Any]:
        if isinstance(item, dict):
            raise MasterError.at(
                self.uri,
                f"XML-RPC fault {item.get('faultCode')}: {item.get('faultString')}",
                path=method,
            )
        if not isinstance(item, list) or len(item) != 1:
            raise self._malformed(method, "a one-element list from system.multicall")
        return self._triple(method, item[0])

    def _triple(self, method: str, reply: Any) -> tuple[int, str, Any]:
        if (
            not isinstance(reply, list | tuple)
            or len(reply) != 3
            or not isinstance(reply[0], int)
            or not isinstance(reply[1], str)
        ):
            raise self._malformed(method, "[code, message, value]")
        code, message, value = reply
        if code not in (SUCCESS, CALLER_ERROR):
            raise MasterError.at(self.uri, f"the master failed: {message}", path=method)
        return code, message, value

    def _malformed(self, method: str, expected: str) -> MasterError:
        return MasterError.at(
            self.uri, f"not a ROS master's reply (expected {expected})", path=method
        )

    def _pid(self, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self._malformed("getPid", "a process id")
        return value

    def _pairs_of_lists(self, value: Any) -> tuple[tuple[str, tuple[str, ...]], ...]:
        if not isinstance(value, list) or not all(
            isinstance(item, list)
            and len(item) == 2
            and isinstance(item[0], str)
            and isinstance(item[1], list)
            and all(isinstance(n, str) for n in item[1])
            for item in value
        ):
            raise self._malformed("getSystemState", "[[topic, [node, ...]], ...]")
        return tuple(sorted((item[0], tuple(sorted(item[1]))) for item in value))

    def _pairs(self, value: Any) -> tuple[tuple[str, str], ...]:
        if not isinstance(value, list) or not all(
            isinstance(item, list)
            and len(item) == 2
            and all(isinstance(part, str) for part in item)
            for item in value
        ):
            raise self._malformed("getTopicTypes", "[[topic, type], ...]")
        return tuple(sorted((item[0], item[1]) for item in value))

    def _names(self, value: Any) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(name, str) for name in value):
            raise self._malformed("getParamNames", "[name, ...]")
        return tuple(sorted(value))


@contextlib.contextmanager
def _translated(uri: str, method: str) -> Iterator[None]:
    """Turns whatever the standard library raises for one call into a master error."""
    try:
        yield
    except xmlrpc.client.Fault as error:
        raise MasterError.at(
            uri, f"XML-RPC fault {error.faultCode}: {error.faultString}", path=method
        ) from None
    except xmlrpc.client.ProtocolError as error:
        raise MasterError.at(
            uri, f"not a ROS master: HTTP {error.errcode} {error.errmsg}", path=method
        ) from None
    # No answer at all: which call it was says nothing to the user.
    except TimeoutError:
        raise MasterUnreachable.at(uri, "the ROS master did not answer in time") from None
    except (OSError, http.client.HTTPException) as error:
        reason = getattr(error, "strerror", None) or str(error) or type(error).__name__
        raise MasterUnreachable.at(uri, f"cannot reach the ROS master ({reason})") from None
    except (ExpatError, xmlrpc.client.ResponseError, ValueError, TypeError, OverflowError) as error:
        raise MasterError.at(
            uri, f"not a ROS master: unreadable XML-RPC reply ({error})", path=method
        ) from None
