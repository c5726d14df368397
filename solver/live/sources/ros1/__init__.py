"""A ROS 1 master as a graph source, spoken over XML-RPC with Python's standard library: no ROS
Python packages needed.

=================  =====================================================================
``rpc``            bounded XML-RPC: one deadline per whole call, byte and depth caps
``master``         the master's API (:class:`MasterClient`): checked replies, errors
``node``           the watcher's own node API, where the master says what changed
``descriptions``   description parameters, fetched once, re-read when said to change
``source``         :class:`MasterGraph`: all of the above as the watcher's
                   :class:`~solver.live.graph.GraphSource`
=================  =====================================================================

Not here: what the graph means (:mod:`solver.live.discovery`), the ROS 2 source
(:mod:`solver.live.sources.ros2`).
"""

from solver.live.sources.ros1.source import MasterGraph

__all__ = ["MasterGraph"]
