"""Robot description parameters, fetched once and then kept current by the master's pushes.

A robot description is the largest thing on a parameter server (tens of kilobytes to
megabytes of URDF), and the master has no version stamp to poll. So :class:`Descriptions`
fetches a description once, with ``subscribeParam``, and from then on the master sends every
change to the watcher's node (:mod:`solver.live.node`), which hands it to :meth:`push`; polls
only read parameter *names*. Without a node (a one-shot snapshot) values are read with
``getParam``, all in one round trip.

The loop thread calls :meth:`sync`; the node's server thread calls :meth:`push`. A push can
arrive while ``subscribeParam`` for the same key is still on its way back with the older
value; a generation count per key keeps the newer one.

Not here: which keys are descriptions (:mod:`solver.live.discovery`).
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Iterable
from typing import Any

from solver.live.master import MISSING, MasterClient, MasterError

__all__ = ["Descriptions"]


def _key(name: str) -> str:
    """Parameter keys as the watcher names them: absolute, no trailing slash."""
    return "/" + name.strip("/")


class Descriptions:
    """The current values of a set of parameter keys (a missing one is :data:`MISSING`)."""

    def __init__(self, client: MasterClient, node_uri: str | None = None) -> None:
        self.client = client
        self.node_uri = node_uri
        self._lock = threading.Lock()
        self._values: dict[str, Any] = {}
        self._generation: dict[str, int] = {}
        self._subscribed: set[str] = set()

    def sync(self, keys: Iterable[str]) -> None:
        """Follow exactly ``keys``: read the new ones, forget (and unsubscribe) the others."""
        wanted = {_key(k) for k in keys}
        with self._lock:
            gone = sorted(set(self._values) - wanted)
            new = sorted(wanted - set(self._values))
            for key in gone:
                del self._values[key]
                self._generation.pop(key, None)
            for key in new:
                self._values[key] = MISSING
                self._generation[key] = 0
        if self.node_uri is None:
            if new:
                for key, value in self.client.get_params(new).items():
                    self._store(key, 0, value)
            return
        stale = [key for key in gone if key in self._subscribed]
        if stale:
            self.client.unsubscribe_params(self.node_uri, stale)
            self._subscribed.difference_update(stale)
        for key in new:
            self._subscribed.add(key)
            self._store(key, 0, self.client.subscribe_param(self.node_uri, key))

    def _store(self, key: str, generation: int, value: Any) -> None:
        with self._lock:
            # Unchanged generation: no push came in meanwhile, so this value is the newest.
            if self._generation.get(key) == generation:
                self._values[key] = value

    def push(self, key: str, value: Any) -> bool:
        """A value the master sent; ``True`` when it is one of the followed keys."""
        name = _key(key)
        with self._lock:
            if name not in self._values:
                return False
            # rosmaster sends an empty dict for a deleted parameter.
            self._values[name] = MISSING if value == {} else value
            self._generation[name] += 1
            return True

    def get(self, key: str) -> Any:
        with self._lock:
            return self._values.get(_key(key), MISSING)

    def keys(self) -> tuple[str, ...]:
        with self._lock:
            return tuple(sorted(self._values))

    def reset(self) -> None:
        """Forget everything: after a master restart its subscriptions are gone too."""
        with self._lock:
            self._values.clear()
            self._generation.clear()
        self._subscribed.clear()

    def close(self) -> None:
        """Unsubscribe from the master, if it is still there (best effort)."""
        if self.node_uri is not None and self._subscribed:
            # A master that is gone took its subscriptions with it.
            with contextlib.suppress(MasterError):
                self.client.unsubscribe_params(self.node_uri, sorted(self._subscribed))
        self.reset()
