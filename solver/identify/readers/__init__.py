"""Readers of the files and records identification starts from, apart from what they mean.

=============  ==============================================================================
``safexml``    safe XML parsing (no entities, no network, size cap)
``prologue``   what comes before the root element, scanned once in linear time, bounded
``bags``       topics and message types recorded in ROS 1/2 bags, read in a limited child
``bag_child``  that child: resource limits, each format's index only, capped decompression
=============  ==============================================================================

Not here: what is read means (:mod:`solver.identify.urdf`, :mod:`solver.identify.classifier`,
:mod:`solver.identify.interfaces`).
"""
