"""Graph sources: where the watcher reads a robot graph from, one subpackage per ROS family.

The watcher (:mod:`solver.live.watcher`) and ``assign`` (:mod:`solver.live.query`) are one code
path above the transport: what they need of a graph is a
:class:`~solver.live.graph.GraphSource` (an :class:`~solver.live.graph.Observation` per poll,
the description values, a place to write the answer), made of the neutral types in
:mod:`solver.live.graph`. No source imports another.

=========== ===================================================================================
``ros1``    a ROS 1 master over XML-RPC (:class:`~solver.live.sources.ros1.MasterGraph`: the
            master's API, the watcher's own node for pushes, the descriptions it follows)
``ros2``    a ROS 2 graph on DDS, read with Eclipse Cyclone DDS, no ROS 2 installed
            (:class:`~solver.live.sources.ros2.DdsGraph`; needs the ``[ros2]`` extra)
=========== ===================================================================================

Choosing a source is one lookup, here, for ``watch``, ``assign --master`` / ``--ros2``,
``demo`` and the studio alike (as rosbags' ``STORAGE_PLUGINS``): :func:`graph_address` checks
what names a graph (a master URI, a DDS domain id) into a :class:`GraphAddress`, and
:func:`open_source` opens the source of its family from :data:`SOURCES`, importing that source
alone (watching a ROS 1 master loads no DDS). A new source is one subpackage that produces the
neutral types, and one entry in :data:`SOURCES`.

Not here: identification, events, selection (the same for every source); the watcher on an
address (:func:`solver.live.watcher.open_watcher`).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from solver.errors import InputError
from solver.untrusted import shown

if TYPE_CHECKING:
    from solver.live.graph import GraphSource

__all__ = ["MAX_DOMAIN", "SOURCES", "GraphAddress", "dds_domain", "graph_address", "open_source"]

# The highest DDS domain id ROS 2 allows (its port mapping ends there).
MAX_DOMAIN = 232


@dataclass(frozen=True)
class GraphAddress:
    """Where a graph is: ``family`` (a key of :data:`SOURCES`: ``ros1``, ``ros2``) and ``where``
    (a ROS 1 master's URI, checked and normalised; a DDS domain id).

    >>> GraphAddress("ros2", 7).label, GraphAddress("ros1", "http://127.0.0.1:11311/").label
    ('ROS 2 domain 7', 'http://127.0.0.1:11311/')
    """

    family: str
    where: str | int

    @property
    def label(self) -> str:
        """The graph as a person reads it: the master's URI, or ``ROS 2 domain N``."""
        return f"ROS 2 domain {self.where}" if self.family == "ros2" else str(self.where)


def _master(address: GraphAddress, timeout: float, push: bool) -> GraphSource:
    from solver.live.sources.ros1 import MasterGraph

    return MasterGraph(str(address.where), timeout=timeout, push=push)


def _dds(address: GraphAddress, timeout: float, push: bool) -> GraphSource:
    del timeout  # a DDS domain has no calls to time
    from solver.live.sources.ros2 import DdsGraph

    # Without push (a snapshot, `assign`, an operator station) the source reads only: no
    # writer of the answer topic (DDS has no pushes to ask for).
    return DdsGraph(int(address.where), answers=push)


# The graph sources by family: each opens its source for an address (``timeout``: seconds each
# call to a master may take; ``push``: a master tells the watcher's own node what changed; on
# DDS, the source writes answers).
SOURCES: dict[str, Callable[[GraphAddress, float, bool], GraphSource]] = {
    "ros1": _master,
    "ros2": _dds,
}


def graph_address(
    *, ros2: bool = False, master: str | None = None, domain: int | None = None
) -> GraphAddress:
    """The graph named, checked: with ``ros2`` a DDS domain (:func:`dds_domain`), else a ROS 1
    master (``master``, else ``$ROS_MASTER_URI``); a located error for anything else.

    >>> graph_address(master="http://127.0.0.1:11311")
    GraphAddress(family='ros1', where='http://127.0.0.1:11311/')
    >>> graph_address(ros2=True, domain=7)
    GraphAddress(family='ros2', where=7)
    """
    if ros2:
        if master is not None:
            raise InputError.at(
                "<arguments>", "--ros2 reads a DDS domain: give --domain N, not --master"
            )
        return GraphAddress("ros2", dds_domain(domain))
    from solver.live.sources.ros1.master import master_uri

    return GraphAddress("ros1", master_uri(master))


def dds_domain(domain: int | None = None) -> int:
    """``domain``, else ``$ROS_DOMAIN_ID``, else 0: a DDS domain id, 0 to :data:`MAX_DOMAIN`;
    a located error for anything else."""
    text = str(domain) if domain is not None else os.environ.get("ROS_DOMAIN_ID", "0")
    digits = text.strip()
    # ASCII digits, a few: int() reads "٣" as 3, and fails on "²" or on 5,000 digits.
    if not (digits.isascii() and digits.isdigit() and len(digits) <= 3) or int(digits) > MAX_DOMAIN:
        raise InputError.at(
            "<arguments>",
            f"DDS domain id must be 0..{MAX_DOMAIN}, got {shown(text, quoted=True)}",
        )
    return int(text)


def open_source(address: GraphAddress, *, timeout: float = 2.0, push: bool = True) -> GraphSource:
    """The source of the graph at ``address``, opened (the caller closes it, or hands it to a
    watcher that does). ``timeout`` and ``push`` are a master's (see :data:`SOURCES`)."""
    opener = SOURCES.get(address.family)
    if opener is None:
        raise InputError.at(
            "<arguments>",
            f"no graph source {shown(address.family, quoted=True)}; "
            f"sources: {', '.join(sorted(SOURCES))}",
        )
    return opener(address, timeout, push)
