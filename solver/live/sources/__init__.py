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

A new source is one subpackage that produces those types.

Not here: identification, events, selection (the same for every source).
"""
