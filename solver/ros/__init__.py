"""ROS vocabulary shared by identification, layouts and the live graph, with no I/O.

==========  ==================================================================
``names``   a topic with its message type and direction; message-type names
``joints``  a joint a joint command names, with its start position
==========  ==================================================================

This wing imports nothing of the project: reading topic lists and bags is
:mod:`solver.identify`, talking to a graph is :mod:`solver.live`.
"""
