"""What every graph source hands the watcher: the neutral types of a robot graph, ROS 1 or ROS 2.

The watcher (:mod:`solver.live.watcher`), discovery, identification, selection and the one
question of ``assign`` work on these, never on a transport; each graph source
(:mod:`solver.live.sources`) produces them from its own wire and imports nothing of another
source (as rosbags keeps what both bag formats share in ``interfaces``):

* :class:`Observation`: one poll of the graph (topics with their types, publishing and
  subscribing nodes, the names of parameters, the operator's selection and the answer);
* :data:`MISSING`: a value that is not set (``None`` cannot travel in ROS 1's XML-RPC);
  :data:`TOO_DEEP`: a value nested deeper than :data:`MAX_DEPTH` levels, which was not built;
* :class:`GraphSource` and :class:`DescriptionStore`: what the watcher asks of a source;
* :class:`MasterError` and :class:`MasterUnreachable`: the graph cannot be read (for ROS 1, its
  master answered wrongly or not at all). The names are ROS 1's, kept for the public API.

Not here: any transport (:mod:`solver.live.sources`), what the graph means
(:mod:`solver.live.discovery`).
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any, Final, Protocol

from solver.errors import SolverError

__all__ = [
    "ANNOUNCEMENTS",
    "MAX_DEPTH",
    "MISSING",
    "TOO_DEEP",
    "DescriptionStore",
    "GraphSource",
    "MasterError",
    "MasterUnreachable",
    "Observation",
]

# Values from a graph are built at most this many arrays, structs or JSON levels deep.
MAX_DEPTH: Final = 64
# Watchers announce themselves under /teleop_ui/<this> (solver.live.rivals).
ANNOUNCEMENTS: Final = "watchers"


class _Missing(enum.Enum):
    """The value of a parameter that is not set (``None`` cannot travel in ROS's XML-RPC)."""

    MISSING = "MISSING"


MISSING: Final = _Missing.MISSING


class _TooDeep(enum.Enum):
    """A value nested deeper than :data:`MAX_DEPTH`: it was not built."""

    TOO_DEEP = "TOO_DEEP"


TOO_DEEP: Final = _TooDeep.TOO_DEEP


class MasterError(SolverError, ConnectionError):
    """The graph cannot be used: for ROS 1, its master answered, but not as a ROS master does."""


class MasterUnreachable(MasterError):
    """The graph did not answer at all: refused, timed out, or the connection dropped."""


@dataclass(frozen=True, slots=True)
class Observation:
    """Everything one poll reads from the graph, in one round trip.

    ``publishers`` / ``subscribers``: (topic, node names) pairs (ROS 1's getSystemState);
    ``topic_types``: (topic, message type) pairs (a ROS 1 master never forgets a type, so it
    lists topics nobody uses any more); ``params``: the parameter subtree the caller asked for,
    as (key, value) pairs, empty when it is not set; ``discovering``: a participant is found
    whose readers and writers are not yet, or not all those its nodes name (DDS discovers a
    participant before its endpoints, long before on a busy machine, and each endpoint apart;
    a ROS master answers at once, so never there).
    """

    pid: int
    publishers: tuple[tuple[str, tuple[str, ...]], ...]
    subscribers: tuple[tuple[str, tuple[str, ...]], ...]
    topic_types: tuple[tuple[str, str], ...]
    param_names: tuple[str, ...]
    params: tuple[tuple[str, Any], ...] = ()
    discovering: bool = False


class DescriptionStore(Protocol):
    """The current values of the description keys the watcher follows (a value is text,
    :data:`MISSING`, or a :class:`~solver.errors.SolverError` saying why it cannot be read)."""

    def sync(self, keys: Iterable[str]) -> None: ...

    def get(self, key: str) -> Any: ...

    def keys(self) -> tuple[str, ...]: ...

    def reset(self) -> None: ...

    def close(self) -> None: ...


class GraphSource(Protocol):
    """A robot graph the watcher follows and ``assign`` asks (see the module docstring).

    ``name`` is what events report as ``master``; ``caller_id`` the watcher's node name there;
    ``node_uri`` the watcher's own node API, where the source has one. The watcher sets
    ``on_change`` (called from any thread when something of the graph arrived, so that it polls
    at once), ``on_params`` (called when only parameters under the watched namespace changed:
    the operator's selection, an answer, an announcement; the watcher then reads those alone,
    with :meth:`observe_params`, not the whole graph) and ``on_stop`` (called when the graph
    asks the watcher to stop, with its words).
    """

    name: str
    timeout: float
    descriptions: DescriptionStore
    on_change: Callable[[], None] | None
    on_params: Callable[[], None] | None
    on_stop: Callable[[str], None] | None

    @property
    def caller_id(self) -> str: ...

    @property
    def node_uri(self) -> str | None: ...

    def get_pid(self) -> int:
        """The graph's process id, new when it restarted; :class:`MasterError` if unreadable."""
        ...

    def observe(self, namespace: str) -> Observation:
        """The graph now, with the parameters under ``namespace``."""
        ...

    def observe_params(self, namespace: str) -> tuple[int, tuple[tuple[str, Any], ...]]:
        """The graph's process id and the parameters under ``namespace`` (as
        :attr:`Observation.params`), without the rest of the graph: what a change of the
        operator's selection needs, cheap whatever the number of robots."""
        ...

    def resync(self, namespace: str) -> None:
        """Forget the descriptions followed so far, and follow ``namespace`` (again)."""
        ...

    def settle(self, stopped: Callable[[], bool]) -> None:
        """Wait until a one-shot look sees the graph whole (discovery), or ``stopped()``."""
        ...

    def set_param(self, key: str, value: Any) -> None: ...

    def delete_param(self, key: str) -> None: ...

    def announce(self, value: dict[str, Any]) -> None:
        """Say who the watcher is, under ``/teleop_ui/watchers`` (:mod:`solver.live.rivals`):
        the observation's ``watchers`` param then holds it by its key; withdrawn at
        :meth:`close`."""
        ...

    def running_watcher(self, node: str) -> tuple[bool, str | None]:
        """Whether the watcher ``node``, which wrote the answer there, still runs; and, when
        the source can tell that ``node`` is no watcher at all, why (``whose node API ...``)."""
        ...

    def cut_off(self, when: float | None) -> None:
        """End the call under way, and every later one, by ``when`` (:func:`time.monotonic`;
        ``None`` lifts it). Thread-safe."""
        ...

    def close(self) -> None: ...
