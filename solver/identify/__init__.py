"""Identifying real robots from their ROS metadata (the article's future work, Section 6).

A URDF (or xacro), optionally an SRDF, topic lists and bags go in; out comes the robot's body
*structure* (UAV, Humanoid, Quadruped, Hand, ...), the rule set's *kinematic type* for it (or
none), a confidence, the evidence, its *sensors* mapped to the rule set's sensor types, and its
*motion controls*. Every pattern, threshold and mapping is data: ``rules/identification.yaml``.

Modules, one concept each:

=======================  ========================================================
``readers``              what identification reads, apart from what it means: safe XML
                         and its prologue, URDF and SRDF trees, topic lists, bags
``limited``              a fresh, limited interpreter for a reader (bags, trusted xacro)
``xacro``                the xacro sandbox, a security boundary: trusted xacro -> URDF
                         text in a confined child process (``compiler``, ``packages``,
                         ``child``, ``confine``)
``profile``              the identification profile (patterns, rules, mappings)
``compose``              a profile that ``extends`` another (``extends: shipped``)
``body``                 the parts a description shows, found by the next modules
``tree``                 the joint tree as the steps of ``body`` read it
``pose``                 every link's place and joint's axis at rest, in the root's frame
``couplings``            mimic groups: one actuator each, read where it acts; jaws
``actuation``            what each joint does alone: wheels, rotors, thrusters, grippers
``placement``            where the body is: a floating or planar base
``limbs``                chains of the other joints: legs, arms, heads, mounts, trunk
``hands``                fingers and grippers, by name and by place
``vehicle``              how the body travels: ground, air, water; trimmed models
``classifier``           structure + kinematic type + confidence from the parts
``sensors``              sensors from URDF, merged, mapped to sensor types
``interfaces``           sensors and motion controls from topic triples
``motion``               motion controls the description itself shows
``declared``             a robot's teleoperation description: declared values win
``describe``             a teleoperation description drafted from an identification
``joints``               the joints a joint command names, with safe start positions
``identification``       :func:`identify` / :func:`identify_urdf`, the cache
``combinations``         characteristic combinations -> UI configurations
``fleet``                a folder of robots -> a team selection
``render``               JSON contract and text report
=======================  ========================================================

For a live ROS master (``teleop-ui watch``): :func:`identify_urdf` takes URDF *text* and
:class:`IdentificationCache` keeps results by content; :func:`sensors_from_topics` and
:func:`controls_from_topics` take (topic, type, direction) :class:`Topic` triples.

Heavy libraries (lxml, xacro, rosbags) are imported inside the functions that use them.
"""

# Loaded lazily (PEP 562): a command imports the modules it uses, not the whole wing (reading
# one URDF needs neither UI configurations nor a fleet's team).
from __future__ import annotations

from typing import TYPE_CHECKING, Any

# Bound here, not lazily: the function shares its module's name, and importing the module
# (``from solver.identify.combinations import ...``) would otherwise bind the name to the module.
from solver.identify.combinations import Combination, combinations
from solver.lazy import load as _load
from solver.lazy import names as _names

if TYPE_CHECKING:
    from solver.identify.fleet import Fleet, FleetEntry, identify_fleet, team_text
    from solver.identify.identification import (
        Identification,
        IdentificationCache,
        TopicSource,
        content_key,
        identify,
        identify_urdf,
    )
    from solver.identify.interfaces import Control, controls_from_topics, sensors_from_topics
    from solver.identify.profile import Profile, ProfileError, default_profile_path, load_profile
    from solver.identify.readers.topics import parse_topic_list, read_topic_list
    from solver.identify.render import identification_data, render_identification
    from solver.identify.sensors import Detection, Sensor
    from solver.ros.names import Topic

_EXPORTS = {
    "Control": "solver.identify.interfaces",
    "Detection": "solver.identify.sensors",
    "Fleet": "solver.identify.fleet",
    "FleetEntry": "solver.identify.fleet",
    "Identification": "solver.identify.identification",
    "IdentificationCache": "solver.identify.identification",
    "Profile": "solver.identify.profile",
    "ProfileError": "solver.identify.profile",
    "Sensor": "solver.identify.sensors",
    "Topic": "solver.ros.names",
    "TopicSource": "solver.identify.identification",
    "content_key": "solver.identify.identification",
    "controls_from_topics": "solver.identify.interfaces",
    "default_profile_path": "solver.identify.profile",
    "identification_data": "solver.identify.render",
    "identify": "solver.identify.identification",
    "identify_fleet": "solver.identify.fleet",
    "identify_urdf": "solver.identify.identification",
    "load_profile": "solver.identify.profile",
    "parse_topic_list": "solver.identify.readers.topics",
    "read_topic_list": "solver.identify.readers.topics",
    "render_identification": "solver.identify.render",
    "sensors_from_topics": "solver.identify.interfaces",
    "team_text": "solver.identify.fleet",
}

__all__ = [
    "Combination",
    "Control",
    "Detection",
    "Fleet",
    "FleetEntry",
    "Identification",
    "IdentificationCache",
    "Profile",
    "ProfileError",
    "Sensor",
    "Topic",
    "TopicSource",
    "combinations",
    "content_key",
    "controls_from_topics",
    "default_profile_path",
    "identification_data",
    "identify",
    "identify_fleet",
    "identify_urdf",
    "load_profile",
    "parse_topic_list",
    "read_topic_list",
    "render_identification",
    "sensors_from_topics",
    "team_text",
]


def __getattr__(name: str) -> Any:
    return _load(globals(), _EXPORTS, name)


def __dir__() -> list[str]:
    return _names(globals(), _EXPORTS)
