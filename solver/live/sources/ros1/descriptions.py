"""Robot description parameters, fetched once and then re-read when the master says they changed.

A robot description is the largest thing on a parameter server (tens of kilobytes to
megabytes of URDF), and the master has no version stamp to poll. So :class:`Descriptions`
fetches a description once, with ``subscribeParam``, and from then on the master calls the
watcher's node (:mod:`~solver.live.sources.ros1.node`) when it changes, which hands the key
to :meth:`push`; polls only read parameter *names*. Without a node (a one-shot snapshot)
values are read with ``getParam``, all in one round trip.

A push is a hint, never a value: the watcher's node API is an open port, and anyone who can
reach it can call ``paramUpdate`` with any value. :meth:`push` only marks the key stale; the
next :meth:`sync` (on the loop thread) reads it from the master again. A push that arrives
while a key is being read marks it stale again, so the newest value always wins.

*A push can be lost*: the master calls the node once, and a neighbour can keep the node's
slots busy when it does, or unsubscribe the watcher from the master in its name (the master
believes any caller id). So the master is not taken at its word either: every :meth:`sync`
also reads again, in one round trip, the followed values read longest ago once they are
:data:`REREAD_AFTER` seconds old, as many as fit in :data:`REREAD_BYTES` (each counted by its
last size, at least :data:`REREAD_MIN_BYTES`; at least one a sync). A value that comes back the
same is kept as it was (the watcher then identifies nothing again); one that differs replaces
it, as a push would have. So a change whose push was lost is seen within :data:`REREAD_AFTER`
seconds, or, when the followed values add up to more than :data:`REREAD_BYTES` in that time,
within one round of them at :data:`REREAD_BYTES` a poll, plus one poll: a round of 500 robots
of 50 KB takes 25 polls (5 s at the default interval), one of 500 robots of 4 KB 8 polls
(within the 2 s).

A description whose reply is larger than the transport's cap
(:data:`solver.live.sources.ros1.rpc.MAX_REPLY_BYTES`) is that robot's error (an
:class:`~solver.errors.InputError` as its value), not the master's.

Not here: which keys are descriptions (:mod:`solver.live.discovery`).
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Iterable
from typing import Any, Final

from solver.errors import InputError, SolverError
from solver.live.graph import MISSING, MasterError, MasterUnreachable
from solver.live.sources.ros1.master import MasterClient, ReplyTooLarge

__all__ = ["REREAD_AFTER", "REREAD_BYTES", "REREAD_MIN_BYTES", "Descriptions"]

# A followed value is read again when it is this old (seconds), whatever the pushes said...
REREAD_AFTER: Final = 2.0
# ... at most this many bytes a sync, each value counted by its last size, at least this.
REREAD_BYTES: Final = 1024 * 1024
REREAD_MIN_BYTES: Final = 16 * 1024


def _key(name: str) -> str:
    """Parameter keys as the watcher names them: absolute, no trailing slash."""
    return "/" + name.strip("/")


def _same(old: Any, new: Any) -> bool:
    """Whether a value read again is the one held: the same text, or the same error."""
    if isinstance(old, SolverError) and isinstance(new, SolverError):
        return old.faults == new.faults
    return type(old) is type(new) and bool(old == new)


class Descriptions:
    """The current values of a set of parameter keys (a missing one is :data:`MISSING`)."""

    def __init__(self, client: MasterClient, node_uri: str | None = None) -> None:
        self.client = client
        self.node_uri = node_uri
        self._lock = threading.Lock()
        self._values: dict[str, Any] = {}
        self._stale: set[str] = set()
        self._subscribed: set[str] = set()
        self._read_at: dict[str, float] = {}  # key -> when it was last read from the master

    def sync(self, keys: Iterable[str]) -> None:
        """Follow exactly ``keys``: read the new ones, those pushed since and those due again
        (see the module docstring), forget (and unsubscribe) the others."""
        wanted = {_key(k) for k in keys}
        now = time.monotonic()
        with self._lock:
            gone = sorted(set(self._values) - wanted)
            new = sorted(wanted - set(self._values))
            for key in gone:
                del self._values[key]
                self._read_at.pop(key, None)
            for key in new:
                self._values[key] = MISSING
                self._read_at[key] = now
            self._stale -= set(gone)
            # A new key is read below in any case: a push for it meanwhile changes nothing.
            self._stale -= set(new)
        self._reread(now)
        if self.node_uri is None:
            self._read(new)
        else:
            stale = [key for key in gone if key in self._subscribed]
            if stale:
                self.client.unsubscribe_params(self.node_uri, stale)
                self._subscribed.difference_update(stale)
            for key in new:
                self._subscribed.add(key)
                self._store(key, self._subscribed_value(self.node_uri, key))
        with self._lock:
            pushed = sorted(self._stale)
            self._stale.clear()
            for key in pushed:
                self._read_at[key] = now
        for key in pushed:
            self._store(key, self.client.get_param_bounded(key))

    def _reread(self, now: float) -> None:
        """Read again the values due (see the module docstring); keep those that came back
        the same as they were."""
        with self._lock:
            due = sorted((at, key) for key, at in self._read_at.items() if now - at >= REREAD_AFTER)
            batch: list[str] = []
            spent = 0
            for _, key in due:
                value = self._values[key]
                cost = max(len(value) if isinstance(value, str) else 0, REREAD_MIN_BYTES)
                if batch and spent + cost > REREAD_BYTES:
                    break
                batch.append(key)
                spent += cost
                self._read_at[key] = now
        for key, value in self._fetch(batch).items():
            with self._lock:
                if key in self._values and not _same(self._values[key], value):
                    self._values[key] = value

    def _read(self, keys: list[str]) -> None:
        """Read ``keys`` (new ones, without a node) and hold their values."""
        for key, value in self._fetch(keys).items():
            self._store(key, value)

    def _fetch(self, keys: list[str]) -> dict[str, Any]:
        """Values of ``keys`` in one round trip; one by one when that reply is too large, so
        that only the description past the cap is an error."""
        if not keys:
            return {}
        try:
            return self.client.get_params(keys)
        except ReplyTooLarge:
            return {key: self.client.get_param_bounded(key) for key in keys}

    def _subscribed_value(self, node_uri: str, key: str) -> Any:
        """``subscribeParam``'s value; one the master cannot send (a fault) or past the reply
        cap is that description's error, not the master's."""
        try:
            return self.client.subscribe_param(node_uri, key)
        except MasterUnreachable:
            raise
        except MasterError as error:
            return InputError.at(key, f"cannot be read from the master: {error.faults[0].message}")

    def _store(self, key: str, value: Any) -> None:
        with self._lock:
            if key in self._values:  # not forgotten meanwhile
                self._values[key] = value

    def push(self, key: str) -> bool:
        """The master (or anyone) said ``key`` changed; ``True`` when it is a followed key,
        which the next :meth:`sync` reads again."""
        name = _key(key)
        with self._lock:
            if name not in self._values:
                return False
            self._stale.add(name)
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
            self._stale.clear()
            self._read_at.clear()
        self._subscribed.clear()

    def close(self) -> None:
        """Unsubscribe from the master, if it is still there (best effort)."""
        if self.node_uri is not None and self._subscribed:
            # A master that is gone took its subscriptions with it.
            with contextlib.suppress(MasterError):
                self.client.unsubscribe_params(self.node_uri, sorted(self._subscribed))
        self.reset()
