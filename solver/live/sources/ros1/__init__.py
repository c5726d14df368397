"""A ROS 1 master as a graph source, spoken over XML-RPC with Python's standard library: no ROS
Python packages needed.

=================  =====================================================================
``source``         :class:`MasterGraph`: the master, the watcher's node and descriptions,
                   as the watcher's :class:`~solver.live.graph.GraphSource`
=================  =====================================================================

Not here: what the graph means (:mod:`solver.live.discovery`), the ROS 2 source
(:mod:`solver.live.sources.ros2`).
"""

from solver.live.sources.ros1.source import MasterGraph

__all__ = ["MasterGraph"]
