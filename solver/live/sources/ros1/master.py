"""A client for the ROS 1 master's XML-RPC API, on Python's standard library, with timeouts.

The master (``rosmaster``, started by ``roscore``) answers every call with ``[code, message,
value]``: code 1 is success, -1 a caller error (a parameter that is not set), 0 a failure on
the master. :class:`MasterClient` makes the calls the watcher needs (getPid, getSystemState,
getTopicTypes, getParamNames, getParam, setParam, deleteParam, subscribeParam,
unsubscribeParam) and the ones a test or a tool needs to play a node (registerPublisher,
registerSubscriber, lookupNode), checks the shape of every reply, and turns every way a call
can go wrong into one of the graph's two errors (:mod:`solver.live.graph`):

* :class:`MasterUnreachable`: no answer at all (refused, timed out, dropped): the master is
  down, restarting or on the wrong port;
* :class:`MasterError`: an answer, but not one a ROS master gives (an HTTP error, an XML-RPC
  fault, a malformed reply, code 0): the address is not a ROS master, or the master failed;
  :class:`ReplyTooLarge` when the reply is past the byte cap (a caller may treat that as the
  value's fault rather than the master's).

Every call is bounded (:mod:`~solver.live.sources.ros1.rpc`): one deadline for the whole call,
however slowly the reply trickles in; a cap on the bytes of a reply (compressed or not);
values nested too deep are not built. A master that hangs, floods or nests is reported instead
of hanging or exhausting the caller. Connections are kept alive between calls (rosmaster speaks
HTTP/1.1). :meth:`MasterClient.observe` reads everything one poll needs in two round trips
through ``system.multicall``, which rosmaster's server offers (the graph, then the watched
subtree, so that a graph that did not change is the same bytes and is not parsed again); against
a master without it, it falls back to one call per method. :meth:`MasterClient.observe_params`
reads the pid and the watched subtree alone, the same way.

Not here: what the graph means (:mod:`solver.live.discovery`), answering the master's calls to
a node (:mod:`solver.live.sources.ros1.node`).
"""

from __future__ import annotations

import contextlib
import dataclasses
import http.client
import ipaddress
import os
import re
import xmlrpc.client
from collections.abc import Iterable, Iterator, Sequence
from typing import Any, Final
from urllib.parse import urlsplit
from xml.parsers.expat import ExpatError

from solver.addresses import loopback
from solver.errors import InputError
from solver.live.graph import MISSING, MasterError, MasterUnreachable, Observation
from solver.live.sources.ros1.rpc import BoundedTransport, OversizedReply
from solver.untrusted import shown

__all__ = [
    "MasterClient",
    "ReplyTooLarge",
    "is_loopback",
    "master_uri",
    "node_api",
]

SUCCESS: Final = 1
CALLER_ERROR: Final = -1


class ReplyTooLarge(MasterError):
    """The reply was longer than :data:`~solver.live.sources.ros1.rpc.MAX_REPLY_BYTES` (it was
    not read)."""


# A host name as DNS and /etc/hosts have them (an IP address literal is checked apart).
_HOST = re.compile(r"[A-Za-z0-9_](?:[A-Za-z0-9._-]{0,252})")


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
    uri = _http_uri(given.strip())
    if uri is None:
        raise InputError.at(
            "<arguments>",
            f"{where}: expected a ROS master URI like http://127.0.0.1:11311, "
            f"got {shown(given, quoted=True)}",
        )
    return uri


def node_api(text: object) -> str | None:
    """A node's XML-RPC API URI (``http://host:port/``) normalised, or ``None`` when ``text``
    is anything else (``rosrpc://...``, a malformed address, not text): what a master lists
    for a node was written by that node, a stranger."""
    return _http_uri(text.strip()) if isinstance(text, str) and len(text) <= 1000 else None


def _http_uri(text: str) -> str | None:
    try:
        parts = urlsplit(text)
        port = parts.port
    except ValueError:  # "http://[::1", a port that is no number or out of range
        return None
    host = parts.hostname
    if (
        parts.scheme != "http"
        or not host
        or port is None
        or parts.query
        or parts.fragment
        or parts.path not in ("", "/")
        or not (_is_address(host) or _HOST.fullmatch(host))
    ):
        return None
    bracketed = f"[{host}]" if ":" in host else host
    return f"http://{bracketed}:{port}/"


def _is_address(host: str) -> bool:
    try:
        ipaddress.ip_address(host)
    except ValueError:
        return False
    return True


def is_loopback(uri: str) -> bool:
    """Whether the master at ``uri`` is on this machine's loopback interface."""
    return loopback(urlsplit(uri).hostname or "")


class MasterClient:
    """Calls to one ROS master as one caller (a ROS node name such as ``/teleop_ui_watch``).

    ``timeout`` bounds each whole call (see :mod:`~solver.live.sources.ros1.rpc`). Not
    thread-safe: one client per thread (the standard library's proxy is not), except
    :meth:`cut_off`.
    """

    def __init__(self, uri: str, *, caller_id: str = "/teleop_ui", timeout: float = 2.0) -> None:
        self.uri = uri
        self.caller_id = caller_id
        self.timeout = timeout
        self._transport = BoundedTransport(timeout)
        self._proxy = xmlrpc.client.ServerProxy(
            uri,
            transport=self._transport,  # type: ignore[arg-type]  # duck-typed: request, close
            use_builtin_types=True,
        )
        self._multicall: bool | None = None  # unknown until the first batch
        self._whole = False  # whether the last batch was one multicall
        # The graph as read from the last multicall reply (see _graph).
        self._observed: Observation | None = None

    def close(self) -> None:
        self._transport.close()

    def cut_off(self, when: float | None) -> None:
        """Every call ends by ``when`` (:func:`time.monotonic`), the one under way included;
        ``None`` lifts it. Thread-safe: a stopping watcher calls it from a signal handler."""
        self._transport.cut_off(when)

    # -- the calls -----------------------------------------------------------------------

    def get_pid(self) -> int:
        return self._pid(self._value("getPid"))

    def get_param(self, key: str) -> Any:
        """The value of ``key`` (a namespace gives a dict), or :data:`MISSING`."""
        code, _, value = self._call("getParam", key)
        return value if code == SUCCESS else MISSING

    def get_params(self, keys: Sequence[str]) -> dict[str, Any]:
        """Several parameters in one round trip: key -> value or :data:`MISSING`, or an
        :class:`~solver.errors.InputError` for a value the master could not send (a fault: a
        value too deep for rosmaster to marshal). :class:`ReplyTooLarge` for the whole."""
        replies = self._batch([("getParam", key) for key in keys])
        return {key: _param_value(key, reply) for key, reply in zip(keys, replies, strict=True)}

    def get_param_bounded(self, key: str) -> Any:
        """:meth:`get_param`, with a value the master could not send or that is past the reply
        cap as an :class:`~solver.errors.InputError` (that value's fault, not the master's)."""
        try:
            return _param_value(key, self._call("getParam", key))
        except MasterUnreachable:
            raise
        except MasterError as error:
            return _param_value(key, error)

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
        for reply in self._batch([("unsubscribeParam", caller_api, key) for key in keys]):
            code, message, _ = _ok(reply)
            if code != SUCCESS:
                raise MasterError.at(self.uri, shown(message), path="unsubscribeParam")

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
        return value if code == SUCCESS and isinstance(value, str) else None

    def observe(self, params: str | None = None) -> Observation:
        """The graph and parameter names in one round trip, and the subtree ``params`` in one more.

        The graph's reply is the largest by far; apart from the subtree (the operator's switch
        changes that), it is the same bytes as long as the graph does not change, and then not
        parsed again (:mod:`~solver.live.sources.ros1.rpc`): the same tuples come back.

        A value under ``params`` that the master cannot send (a fault) or that makes the reply
        too large does not fail the poll: each child of ``params`` is then read on its own, and
        the unreadable one is an :class:`~solver.errors.InputError` in ``params``."""
        graph = self._graph()
        if not params:
            return graph
        try:
            reply: tuple[int, str, Any] | MasterError | None = self._single("getParam", params)
        except ReplyTooLarge:
            reply = None
        return dataclasses.replace(graph, params=self._subtree(params, reply, graph.param_names))

    def observe_params(self, params: str) -> tuple[int, tuple[tuple[str, Any], ...]]:
        """The master's pid and the subtree ``params`` (as :meth:`observe` gives them), in one
        round trip of two calls; a subtree the master cannot send whole (past the cap, or a
        value its marshaller fails on, which fails a multicall whole) is read child by child."""
        try:
            pid, reply = self._batch([("getPid",), ("getParam", params)])
        except MasterUnreachable:
            raise
        except MasterError:
            pid, reply = self._single("getPid"), None
        return self._pid(self._succeeded("getPid", pid)), self._subtree(params, reply)

    def _graph(self) -> Observation:
        """The pid, topics and parameter names: the same object as the last time when the
        reply is the same bytes."""
        calls: list[tuple[Any, ...]] = [
            ("getPid",),
            ("getSystemState",),
            ("getTopicTypes",),
            ("getParamNames",),
        ]
        replies = self._batch(calls)
        kept = self._observed
        if self._whole and self._transport.reused and kept is not None:
            return kept
        pid, state, types, names = (
            self._succeeded(method, reply) for (method,), reply in zip(calls, replies, strict=True)
        )
        if not isinstance(state, list) or len(state) != 3:
            raise self._malformed("getSystemState", "[publishers, subscribers, services]")
        observation = Observation(
            pid=self._pid(pid),
            publishers=self._pairs_of_lists(state[0]),
            subscribers=self._pairs_of_lists(state[1]),
            topic_types=self._pairs(types),
            param_names=self._names(names),
        )
        # Made from one reply alone: the next reply of the same bytes is this observation.
        self._observed = observation if self._whole else None
        return observation

    def _subtree(
        self,
        params: str,
        reply: tuple[int, str, Any] | MasterError | None,
        names: Sequence[str] | None = None,
    ) -> tuple[tuple[str, Any], ...]:
        """The subtree from ``getParam``'s ``reply``; child by child when the master could not
        send it whole (a fault, or ``None``: a reply past the cap)."""
        if reply is None or isinstance(reply, MasterError):
            if names is None:
                names = self._names(self._value("getParamNames"))
            return tuple(sorted(self._children(params, names).items()))
        code, _, value = reply
        return tuple(sorted(value.items())) if code == SUCCESS and isinstance(value, dict) else ()

    def _succeeded(self, method: str, reply: tuple[int, str, Any] | MasterError) -> Any:
        """The value of a call that must succeed: its error, or a master error, otherwise."""
        code, message, value = _ok(reply)
        if code != SUCCESS:
            raise MasterError.at(self.uri, shown(message) or f"code {code}", path=method)
        return value

    def _children(self, namespace: str, names: Sequence[str]) -> dict[str, Any]:
        """The children of ``namespace``, read one by one, each bounded on its own."""
        prefix = namespace.rstrip("/") + "/"
        children = sorted({n[len(prefix) :].split("/")[0] for n in names if n.startswith(prefix)})
        found = {child: self.get_param_bounded(prefix + child) for child in children}
        return {child: value for child, value in found.items() if value is not MISSING}

    # -- plumbing ------------------------------------------------------------------------

    def _value(self, method: str, *args: Any) -> Any:
        code, message, value = self._call(method, *args)
        if code != SUCCESS:
            raise MasterError.at(self.uri, shown(message) or f"code {code}", path=method)
        return value

    def _call(self, method: str, *args: Any) -> tuple[int, str, Any]:
        with _translated(self.uri, method):
            reply = getattr(self._proxy, method)(self.caller_id, *args)
        return self._triple(method, reply)

    def _batch(self, calls: Sequence[tuple[Any, ...]]) -> list[tuple[int, str, Any] | MasterError]:
        """Calls (method, *args) in one ``system.multicall``, or one by one without it. Each
        reply is ``[code, message, value]`` or the :class:`MasterError` of that call alone (a
        fault, a malformed item); a failure of the whole (no answer, a reply past the cap)
        raises."""
        self._whole = False
        if not calls:
            return []
        if self._multicall is not False:
            multicall = xmlrpc.client.MultiCall(self._proxy)
            for method, *args in calls:
                getattr(multicall, method)(self.caller_id, *args)
            try:
                with _translated(self.uri, "system.multicall"):
                    results = list(multicall().results)
            except (MasterUnreachable, ReplyTooLarge):
                raise
            except MasterError:
                if self._multicall is None:
                    # The server has no system.multicall (it is not part of the ROS master API,
                    # only of rosmaster's server): use plain calls from now on.
                    self._multicall = False
                # Else one reply could not be sent (rosmaster's marshaller fails on a value
                # nested too deep, and fails the whole multicall): these calls one by one, so
                # that the fault is that call's alone.
            else:
                self._multicall = self._whole = True
                if len(results) != len(calls):
                    raise self._malformed("system.multicall", "one reply per call")
                return [
                    self._multicall_item(call[0], item)
                    for call, item in zip(calls, results, strict=True)
                ]
        return [self._single(method, *args) for method, *args in calls]

    def _single(self, method: str, *args: Any) -> tuple[int, str, Any] | MasterError:
        try:
            return self._call(method, *args)
        except (MasterUnreachable, ReplyTooLarge):
            raise
        except MasterError as error:
            return error

    def _multicall_item(self, method: str, item: Any) -> tuple[int, str, Any] | MasterError:
        if isinstance(item, dict):
            return MasterError.at(
                self.uri,
                f"XML-RPC fault {shown(item.get('faultCode'))}: {shown(item.get('faultString'))}",
                path=method,
            )
        if not isinstance(item, list) or len(item) != 1:
            return self._malformed(method, "a one-element list from system.multicall")
        try:
            return self._triple(method, item[0])
        except MasterError as error:
            return error

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
            raise MasterError.at(self.uri, f"the master failed: {shown(message)}", path=method)
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


def _ok(reply: tuple[int, str, Any] | MasterError) -> tuple[int, str, Any]:
    if isinstance(reply, MasterError):
        raise reply
    return reply


def _param_value(key: str, reply: tuple[int, str, Any] | MasterError) -> Any:
    """A getParam reply as a value: the value, :data:`MISSING`, or an :class:`InputError`
    naming the key when the master could not send it."""
    if isinstance(reply, MasterError):
        return InputError.at(key, f"cannot be read from the master: {reply.faults[0].message}")
    code, _, value = reply
    return value if code == SUCCESS else MISSING


@contextlib.contextmanager
def _translated(uri: str, method: str) -> Iterator[None]:
    """Turns whatever the standard library raises for one call into a master error."""
    try:
        yield
    except xmlrpc.client.Fault as error:
        raise MasterError.at(
            uri,
            f"XML-RPC fault {shown(error.faultCode)}: {shown(error.faultString)}",
            path=method,
        ) from None
    except xmlrpc.client.ProtocolError as error:
        raise MasterError.at(
            uri, f"not a ROS master: HTTP {error.errcode} {shown(error.errmsg)}", path=method
        ) from None
    except OversizedReply as error:
        raise ReplyTooLarge.at(uri, f"not read: {error}", path=method) from None
    # No answer at all: which call it was says nothing to the user.
    except TimeoutError:
        raise MasterUnreachable.at(uri, "the ROS master did not answer in time") from None
    except (OSError, http.client.HTTPException) as error:
        reason = getattr(error, "strerror", None) or str(error) or type(error).__name__
        raise MasterUnreachable.at(uri, f"cannot reach the ROS master ({reason})") from None
    except (ExpatError, xmlrpc.client.ResponseError, ValueError, TypeError, OverflowError) as error:
        # ResponseError's str() is its repr: its own words are its first argument.
        reason = error.args[0] if error.args and isinstance(error.args[0], str) else str(error)
        raise MasterError.at(
            uri, f"not a ROS master: unreadable XML-RPC reply ({shown(reason)})", path=method
        ) from None
