"""A ROS 1 master as the watcher's graph source: :class:`MasterGraph`.

It puts together the master's API (:class:`~solver.live.sources.ros1.master.MasterClient`:
bounded calls, checked replies), the watcher's own node
(:class:`~solver.live.sources.ros1.node.NodeServer`, where the master says which parameters
changed) and the description parameters it follows
(:class:`~solver.live.sources.ros1.descriptions.Descriptions`), behind the
:class:`~solver.live.graph.GraphSource` the watcher and ``assign`` use for every graph.

*Rival watchers.* The answer on the master names the watcher that wrote it (its node name).
Whether that watcher still runs is asked of its node API, as the master lists it: ``getPid``,
given :data:`PROBE_TIMEOUT` seconds; a node that answered is asked again only after
:data:`PROBE_AGAIN` seconds, so a node that answers slowly or never costs a poll at most that,
now and then. A node API that is not ``http://host:port/`` (a node that registered
``rosrpc://evil:1/``) cannot be a watcher's.

*Announcing.* :meth:`MasterGraph.announce` writes who the watcher is to the parameter
``/teleop_ui/watchers/<its node name>`` (:mod:`solver.live.rivals`), deleted again at close.

*Stopping and closing.* :meth:`MasterGraph.cut_off` ends the call under way (the watcher's
stop); :meth:`MasterGraph.close` deletes the announcement and releases the parameter
subscriptions within :data:`RELEASE_BUDGET` seconds in all, whatever the master does, and stops
the node.

Not here: the watcher's state machine (:mod:`solver.live.watcher`).
"""

from __future__ import annotations

import contextlib
import os
import re
import socket
import time
from collections.abc import Callable
from typing import Any, Final

from solver.live.graph import (
    ANNOUNCEMENTS,
    DescriptionStore,
    MasterError,
    MasterUnreachable,
    Observation,
)
from solver.live.sources.ros1.descriptions import Descriptions
from solver.live.sources.ros1.master import MasterClient, node_api
from solver.live.sources.ros1.node import NodeServer, callback_host
from solver.untrusted import shown

__all__ = ["PROBE_AGAIN", "PROBE_TIMEOUT", "RELEASE_BUDGET", "MasterGraph"]

PROBE_TIMEOUT: Final = 1.0
PROBE_AGAIN: Final = 5.0
RELEASE_BUDGET: Final = 0.5


def _node_name(port: int) -> str:
    host = re.sub(r"\W", "_", socket.gethostname()) or "host"
    return f"/teleop_ui_watch_{host}_{os.getpid()}_{port}"


class MasterGraph:
    """The ROS 1 master at ``master`` (``http://host:port/``), as a graph source.

    ``push=False`` runs without a node (no parameter subscriptions, descriptions read with
    ``getParam``): enough for one look, as ``watch --once`` and ``assign`` take.
    """

    def __init__(self, master: str, *, timeout: float = 2.0, push: bool = True) -> None:
        self.name = master
        self.timeout = timeout
        self.on_change: Callable[[], None] | None = None
        self.on_params: Callable[[], None] | None = None
        self.on_stop: Callable[[str], None] | None = None
        self._namespace: str | None = None
        self._node: NodeServer | None = None
        caller_id = f"/teleop_ui_watch_{os.getpid()}"
        if push:
            self._node = NodeServer(callback_host(master), master, self._pushed, self._shutdown)
            caller_id = _node_name(int(self._node.uri.rsplit(":", 1)[1].strip("/")))
            self._node.start()
        self.client = MasterClient(master, caller_id=caller_id, timeout=timeout)
        self._descriptions = Descriptions(self.client, self.node_uri)
        self.descriptions: DescriptionStore = self._descriptions
        self._rivals: dict[tuple[str, str], float] = {}  # (node, API) -> when it answered
        self._probe: MasterClient | None = None
        self._announced: str | None = None
        self._closed = False

    @property
    def caller_id(self) -> str:
        return self.client.caller_id

    @property
    def node_uri(self) -> str | None:
        return None if self._node is None else self._node.uri

    # -- what the watcher and assign call ------------------------------------------------

    def get_pid(self) -> int:
        return self.client.get_pid()

    def observe(self, namespace: str) -> Observation:
        return self.client.observe(namespace)

    def observe_params(self, namespace: str) -> tuple[int, tuple[tuple[str, Any], ...]]:
        return self.client.observe_params(namespace)

    def resync(self, namespace: str) -> None:
        """After a start or a master restart: the master's subscriptions are gone, and so is
        what was followed."""
        self.descriptions.reset()
        self._namespace = namespace
        if self._node is None:
            return
        try:
            self.client.subscribe_param(self._node.uri, namespace)
        except MasterUnreachable:
            raise
        except MasterError:
            # The subscription's reply (the whole subtree, unused: polls read it, key by key
            # when they must) could not be sent; at worst changes wait for the next poll.
            pass

    def settle(self, stopped: Callable[[], bool]) -> None:
        """Nothing to wait for: a master answers with the whole graph at once."""

    def set_param(self, key: str, value: Any) -> None:
        self.client.set_param(key, value)

    def delete_param(self, key: str) -> None:
        self.client.delete_param(key)

    def announce(self, value: dict[str, Any]) -> None:
        """``value`` at ``/teleop_ui/watchers/<node name>`` (deleted at :meth:`close`)."""
        namespace = self._namespace or "/teleop_ui"
        key = f"{namespace.rstrip('/')}/{ANNOUNCEMENTS}/{self.caller_id.strip('/')}"
        self.client.set_param(key, value)
        self._announced = key

    def running_watcher(self, node: str) -> tuple[bool, str | None]:
        """See the module docstring: the master's word on ``node``, then its own."""
        listed = self.client.lookup_node(node)
        if listed is None:
            return False, None  # it closed (its subscriptions are gone) or never had a node
        api = node_api(listed)
        if api is None:
            return False, f"whose node API {shown(listed)} is no XML-RPC address: not a watcher's"
        now = time.monotonic()
        answered = self._rivals.get((node, api))
        if answered is not None and now - answered < PROBE_AGAIN:
            return True, None
        if self._answers(api):
            # Several watchers may be asked in turn (an answer's writer, the announced ones):
            # each is remembered; those not asked again lately are forgotten (bounded).
            self._rivals = {k: t for k, t in self._rivals.items() if now - t < PROBE_AGAIN}
            self._rivals[(node, api)] = now
            return True, None
        self._rivals.pop((node, api), None)
        return False, None  # killed without closing: the master still lists it, nobody answers

    def _answers(self, api: str) -> bool:
        """Whether the node API ``api`` answers ``getPid`` as a node does, within
        :data:`PROBE_TIMEOUT` (and the watcher's own timeout), unless cut off."""
        self._probe = MasterClient(
            api, caller_id=self.caller_id, timeout=min(PROBE_TIMEOUT, self.timeout)
        )
        try:
            self._probe.get_pid()
        except MasterError:
            return False
        finally:
            self._probe.close()
            self._probe = None
        return True

    def cut_off(self, when: float | None) -> None:
        for client in (self.client, self._probe):
            if client is not None:
                client.cut_off(when)

    def close(self) -> None:
        """Unsubscribe (best effort, within :data:`RELEASE_BUDGET`) and stop the node."""
        if self._closed:
            return
        self._closed = True
        if self._announced is not None or self._node is not None:
            # Bounded whatever the master does: it forgets a node that is gone in any case.
            self.client.cut_off(time.monotonic() + RELEASE_BUDGET)
        if self._announced is not None:
            with contextlib.suppress(MasterError):  # gone with the master
                self.client.delete_param(self._announced)
        if self._node is not None:
            if self._namespace is not None:
                with contextlib.suppress(MasterError):  # gone with the master
                    self.client.unsubscribe_params(self._node.uri, [self._namespace])
            self.descriptions.close()
            self._node.close()
        self.client.close()

    # -- the node's calls (on its server thread) -----------------------------------------

    def _pushed(self, key: str) -> None:
        """A parameter update, from the master or anyone: a hint to read now, from the master
        (the watched namespace alone when the key is under it, else the whole graph)."""
        name = "/" + key.strip("/")
        namespace = self._namespace
        if self._descriptions.push(name):  # a root robot's own values are under /teleop_ui
            callback = self.on_change
        elif namespace is not None and (name == namespace or name.startswith(namespace + "/")):
            callback = self.on_params
        else:
            return
        if callback is not None:
            callback()

    def _shutdown(self, message: str) -> None:
        callback = self.on_stop
        if callback is not None:
            callback(shown(message))  # a stranger's words
