"""ROS vocabulary shared by identification, layouts, checking and the live graph.

===============  ==================================================================
``names``        a topic with its message type and direction; message-type names
``joints``       a joint a joint command names, with its start position
``description``  a robot's teleoperation description (``ROBOT.teleop.yaml``): the
                 format and its reader, over the project's bounded YAML reader
===============  ==================================================================

This wing imports only the file readers below it (:mod:`solver.files`): reading topic lists
and bags is :mod:`solver.identify`, talking to a graph is :mod:`solver.live`.
"""
