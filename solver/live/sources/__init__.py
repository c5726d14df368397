"""Graph sources: where the watcher reads a robot graph from, one subpackage per ROS family.

The watcher (:mod:`solver.live.watcher`) is one code path above the transport. What it needs of
a graph is an :class:`~solver.live.master.Observation` per poll (topics with their types,
publishing and subscribing node names, the names of robot descriptions, the operator's
selection and the answer present), the description values (:class:`DescriptionStore`), and a
place to write the answer. Two sources provide it:

=========== ===================================================================================
``ros1``    a ROS 1 master over XML-RPC (:class:`~solver.live.master.MasterClient` and
            :class:`~solver.live.descriptions.Descriptions`, with the watcher's own node for
            pushes)
``ros2``    a ROS 2 graph on DDS, read with Eclipse Cyclone DDS, no ROS 2 installed
            (:class:`~solver.live.sources.ros2.DdsGraph`; needs the ``[ros2]`` extra)
=========== ===================================================================================

Not here: identification, events, selection (the same for every source).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, Protocol

from solver.live.master import Observation

__all__ = ["DescriptionStore", "GraphSource"]


class DescriptionStore(Protocol):
    """The current values of the description keys the watcher follows."""

    def sync(self, keys: Iterable[str]) -> None: ...

    def get(self, key: str) -> Any: ...

    def keys(self) -> tuple[str, ...]: ...

    def reset(self) -> None: ...

    def close(self) -> None: ...


class GraphSource(Protocol):
    """A robot graph the watcher can follow instead of a ROS 1 master (see the docstring).

    ``name`` is what events report as ``master``; ``on_change`` is set by the watcher and
    called (from any thread) when something arrived, so that the watcher polls at once.
    """

    name: str
    caller_id: str
    timeout: float
    descriptions: DescriptionStore
    on_change: Callable[[], None] | None

    def get_pid(self) -> int: ...

    def observe(self, namespace: str) -> Observation: ...

    def set_param(self, key: str, value: Any) -> None: ...

    def delete_param(self, key: str) -> None: ...

    def lookup_node(self, name: str) -> str | None: ...

    def close(self) -> None: ...
