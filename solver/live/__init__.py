"""Live UI assignment from a running ROS graph (``teleop-ui watch``, ``assign --master``):
a ROS 1 master (:mod:`solver.live.sources.ros1`), or a ROS 2 graph on DDS (``--ros2``,
:mod:`solver.live.sources.ros2`).

Robots connected to a teleoperation system get their UI configuration from their ROS
metadata, and switching robots or control modes switches the configuration at once. The
master's XML-RPC API is spoken with Python's standard library: no ROS Python packages needed.

Modules, one concept each:

=====================  ==========================================================
``graph``              the neutral types every source hands over: Observation,
                       MISSING, the GraphSource protocol, the graph's errors
``sources``            graph sources, none importing another: ``ros1`` (a master
                       over XML-RPC: ``rpc``, ``master``, ``node``, ``descriptions``,
                       ``source``), ``ros2`` (DDS, Cyclone DDS); the one lookup of a
                       source by its address (``graph_address``, ``open_source``)
``values``             bounds on values from a graph (JSON, selection), echoes
``discovery``          robots (``robot_description`` namespaces), their topics and
                       their own values' keys (``<ns>/teleop_ui/<characteristic>``)
``given``              where a characteristic's value comes from beside
                       identification (the robot's own, ``--set``), what is missing
``robot``              one robot identified, with its combinations' configurations
``selection``          ``/teleop_ui/active_*`` -> one configuration, written back
``events``             the event kinds and their JSON schema
``rivals``             other watchers on the graph: announcements, ``rival`` events,
                       who writes the answer (``--yield`` / ``--insist``)
``watcher``            the state machine on any source: polls, loss, backoff, resync;
                       ``open_watcher``, one on the graph at an address
``query``              one question on any source: ``assign --master`` / ``--ros2``
``render``             events as JSON lines or text; ``assign --master`` output
``layouts``            the robots' layouts and the team layout written as they come
                       (``watch --layouts``), and where an answer's are
``server``             the answer and the layouts served on loopback, read-only
                       (``watch --serve``)
``operator``           the operator's side: a switch checked, written, and its answer
                       awaited (``teleop-ui switch``, the studio's Live view)
``demo``               an emulated ROS 2 fleet and operator (``teleop-ui demo ros2``)
=====================  ==========================================================

Identification is :mod:`solver.identify`'s (cached by content); configurations are
:func:`solver.assign`'s.
"""

from solver.live.events import (
    Event,
    MasterBack,
    MasterLost,
    RobotAdded,
    RobotChanged,
    RobotRemoved,
    SelectionChanged,
    Synced,
    event_data,
)
from solver.live.graph import MISSING, MasterError, MasterUnreachable, Observation
from solver.live.query import LiveAssignment, assign_from_master
from solver.live.render import json_line, render_event, render_live_assignment
from solver.live.robot import LiveRobot, identify_robot
from solver.live.selection import ActiveSelection, Request
from solver.live.sources.ros1.master import MasterClient, master_uri
from solver.live.watcher import Watcher

__all__ = [
    "MISSING",
    "ActiveSelection",
    "Event",
    "LiveAssignment",
    "LiveRobot",
    "MasterBack",
    "MasterClient",
    "MasterError",
    "MasterLost",
    "MasterUnreachable",
    "Observation",
    "Request",
    "RobotAdded",
    "RobotChanged",
    "RobotRemoved",
    "SelectionChanged",
    "Synced",
    "Watcher",
    "assign_from_master",
    "event_data",
    "identify_robot",
    "json_line",
    "master_uri",
    "render_event",
    "render_live_assignment",
]
