"""Sensors on frames the description only draws, that a driver of the robot's packages
publishes in.

A description often carries a sensor as a bare frame: ``imu_link``, ``gps_link`` or
``camera_link`` on a fixed joint, with no ``<sensor>`` element or plugin (a real robot's
description, written for its TF tree rather than a simulator). When the robot's packages run
a driver that stamps its data with that frame (``frame_id: imu_link`` in its configuration,
``<param name="frame_id" value="imu_link"/>`` in a launch file, ``header.frame_id =
"imu_link"`` in a node), the device is real and the operator's UI has its data to show.

* A frame is *named* by a package when one of its launch, configuration or script files
  (:mod:`solver.identify.readers.workspace`) assigns a frame id (``frame_id``, ``frame``,
  ``frame_name``, ``camera_frame_id``, ...) whose value, its last ``/`` segment, is a link of
  the description; or names a camera driver (``camera_name``) from which the driver builds its
  frames (realsense2_camera, orbbec_camera): the link of that name, else ``NAME_link``, else
  the first link whose name begins ``NAME_``.
* The profile's ``sensors.frames`` rules tell a named link's kind by its name (``imu``,
  ``gps``, ``lidar``, ``camera``, ...); a link no rule matches (``base_link``, ``odom``) is
  no sensor.
* One device's frames are one sensor: a frame hangs from its device's body through fixed
  joints whose links the rules match too (``camera_color_optical_frame`` under
  ``camera_color_frame`` under ``camera_link``); the device's frames, named or fixed beneath its
  body, say what it is, the first rule among them naming it (a colour and a depth frame of one
  camera: an RGB-D camera).
* The description's own word wins: no device is added for a kind the description declares
  (its camera's optical frame is that camera), nor on a device that carries a sensor the
  description declares.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from solver.identify.profile import Profile
from solver.identify.readers.urdf import Urdf
from solver.identify.readers.workspace import Workspace
from solver.identify.sensors import Detection
from solver.untrusted import shown

__all__ = ["SOURCE", "named_frames", "sensors_on_frames"]

# The source the detections are merged under (a view of the robot, as a topic list is).
SOURCE = "packages"
# Fixed joints climbed from a frame to its device's body (an optical frame, a stream frame).
_DEVICE_DEPTH = 3
# A frame id assigned a value: `frame_id: x`, `frame_id:=x`, `"frame_id": "x"`,
# `frame_id="x"`, `header.frame_id = 'x'`, `("frame_id", "x")`, `camera_frame_id: x`.
_ASSIGNED = re.compile(
    r"""frame(?:_?id|_?name)?["'\s]{0,3}(?::=|:|=|,)[ \t]{0,8}["']?/?"""
    r"""([A-Za-z_][A-Za-z0-9_/]{0,199})""",
    re.IGNORECASE,
)
# A launch parameter: <param name="frame_id" value="x"/> (or imu_frame, camera_frame_id).
_PARAMETER = re.compile(
    r"""name\s{0,3}=\s{0,3}["'][A-Za-z0-9_]{0,60}frame(?:_?id|_?name)?["']\s{1,8}"""
    r"""value\s{0,3}=\s{0,3}["']/?([A-Za-z_][A-Za-z0-9_/]{0,199})""",
    re.IGNORECASE,
)


# A camera driver's name, from which it builds its frames (realsense2_camera, orbbec_camera:
# camera_name:=camera_front publishes in camera_front_link, camera_front_color_optical_frame).
_DEVICE_NAME = re.compile(
    r"""camera_?name["'\s]{0,3}(?::=|:|=|,)[ \t]{0,8}["']?/?([A-Za-z_][A-Za-z0-9_/]{0,199})"""
    r"""|name\s{0,3}=\s{0,3}["']camera_?name["']\s{1,8}(?:value|default)\s{0,3}=\s{0,3}["']/?"""
    r"""([A-Za-z_][A-Za-z0-9_/]{0,199})""",
    re.IGNORECASE,
)


def named_frames(workspace: Workspace, urdf: Urdf) -> dict[str, str]:
    """Each link of ``urdf`` a file of the robot's packages assigns as a frame id, or names as
    a camera driver's frames (:func:`_device_frame`), with the first such file (its path in
    the workspace)."""
    found: dict[str, str] = {}
    for shipped in workspace.files:
        for pattern in (_ASSIGNED, _PARAMETER):
            for match in pattern.finditer(shipped.text):
                link = match.group(1).rsplit("/", 1)[-1]
                if link not in found and urdf.has_link(link):
                    found[link] = shipped.path
        for match in _DEVICE_NAME.finditer(shipped.text):
            link = _device_frame((match.group(1) or match.group(2)).rsplit("/", 1)[-1], urdf)
            if link is not None and link not in found:
                found[link] = shipped.path
    return found


def _device_frame(name: str, urdf: Urdf) -> str | None:
    """The link a camera driver named ``name`` publishes in: ``name`` itself, ``name_link``,
    else the first link whose name begins ``name_`` (its stream frames); None when none is."""
    for link in (name, f"{name}_link"):
        if urdf.has_link(link):
            return link
    return next((link.name for link in urdf.links if link.name.startswith(f"{name}_")), None)


def sensors_on_frames(
    workspace: Workspace, urdf: Urdf, profile: Profile, declared: Iterable[Detection]
) -> tuple[Detection, ...]:
    """One detection per device the robot's packages publish in a frame of (see the module
    docstring), for kinds and devices ``declared`` (the description's detections) lacks."""
    rules = profile.frame_rules
    if not rules:
        return ()
    declared = tuple(declared)
    kinds_declared = {d.kind for d in declared}

    def kind_of(link: str) -> int | None:
        return next((i for i, rule in enumerate(rules) if rule.accepts(None, link)), None)

    def body(link: str) -> str:
        for _ in range(_DEVICE_DEPTH):
            joint = urdf.parent_joint(link)
            if joint is None or joint.movable or kind_of(joint.parent) is None:
                break
            link = joint.parent
        return link

    bodies_declared = {body(d.link) for d in declared if d.link is not None}
    devices: dict[str, list[tuple[int, str, str]]] = {}  # body -> (rule, frame, file)
    for link, path in named_frames(workspace, urdf).items():
        rule = kind_of(link)
        if rule is not None:
            devices.setdefault(body(link), []).append((rule, link, path))
    found = []
    for device, frames in devices.items():
        rule, link, path = min(frames)
        # The device's own frames, named or not, say what it is (a depth stream's frame).
        streams = (kind_of(part) for part in urdf.fixed_below(device))
        rule = min((rule, *(r for r in streams if r is not None)))
        kind = rules[rule].kind
        if kind in kinds_declared or kind == "unknown" or device in bodies_declared:
            continue
        name = f"{shown(link)} (frame id in {shown(path)})"
        found.append(Detection(kind, name, SOURCE, device))
    return tuple(found)
