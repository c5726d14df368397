"""Readers of the files and records identification starts from, apart from what they mean.

=============  ==============================================================================
``safexml``    safe XML parsing (no entities, no network, size cap)
``prologue``   what comes before the root element, scanned once in linear time, bounded
``urdf``       URDF text -> checked tree of links, joints, sensors, plugins
``srdf``       MoveIt SRDF: groups, chains, end effectors, virtual joints
``topics``     topic list files (``rostopic``/``ros2 topic`` output) -> topics with types
``bags``       topics and message types recorded in ROS 1/2 bags, read in a limited child
``bag_child``  that child: resource limits, each format's index only, capped decompression
=============  ==============================================================================

Not here: what is read means (:mod:`solver.identify.roles`, :mod:`solver.identify.body`,
:mod:`solver.identify.classifier`, :mod:`solver.identify.interfaces`).
"""
