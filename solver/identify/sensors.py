"""Sensors: found in a URDF or in topics, merged, and mapped to the rule set's sensor types.

A *detection* is one physical sensor seen by one source: a Gazebo ``<sensor type=...>`` or URDF
``<sensor>`` element, a Gazebo model plugin that simulates a sensor without an element (hector's
IMU, GPS, barometer; RotorS' IMU and odometry), a Gazebo model the description includes
(``<gazebo><include><uri>model://gps</uri>``, read by its model name with the plugin rules),
or a device in a topic list or bag
(:mod:`solver.identify.interfaces`). The profile's rules give each its *kind* (``lidar``,
``depth_camera``, ``sonar``, ...); a ray sensor plugin written outside any ``<sensor>``, which
says nothing of its rays, is told by its names and topics (:func:`_ray_plugin_kind`). Plugins
that publish simulation ground truth are skipped, a plugin that feeds an element already
counted (same kind, same link) or repeats one a ``<sensor>`` runs is the same sensor, and
depth streams on sibling frames of one camera link are one RGB-D camera (and cameras on frames
named for the camera's body, fixed beneath it facing its way, its streams), and a depth stream
on a stereo camera's frame is the pair's. :func:`under_water`
reads a barometer on a body below the water as the depth gauge it is there.

:func:`merge` turns detections into one :class:`Sensor` per kind and sensor type. Sources are
views of the same robot, so a kind's count is the largest any one source reports (a URDF lidar
and a ``/scan`` topic are one lidar). Each kind's sensor type comes from the profile's
``sensor_types`` and must exist in the rule set; a kind with no presentation (IMU, GPS, sonar)
is listed with ``sensor_type`` ``None`` and does not count toward the number of sensors.

Not here: reading topic lists (:mod:`solver.identify.readers.topics`).
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Container, Iterable, Sequence
from dataclasses import dataclass

from solver.core.ruleset import RuleSet
from solver.identify.limbs import moved_by
from solver.identify.pose import CELLS_AROUND, Poses, Vector, distance, grid_cell, same_way
from solver.identify.profile import SENSOR_TYPE, Profile
from solver.identify.readers.urdf import SCAN_OUTPUT, Joint, PluginTag, SensorTag, Urdf
from solver.untrusted import shown

__all__ = [
    "STREAM_REACH",
    "Detection",
    "Sensor",
    "element_kind",
    "merge",
    "plugin_kind",
    "presented_count",
    "sensor_type_of",
    "sensors_from_urdf",
    "under_water",
]

# Sensor elements a DVL's beams are written as (a range ray each).
_BEAM_TYPES = ("ray", "gpu_ray", "sonar")
_LINK_PARAMS = ("linkName", "bodyName", "frameName", "frameId", "frame_name", "link_name")
_LINK_TAGS = frozenset(tag.lower() for tag in _LINK_PARAMS)
_JOINT_PARAMS = ("jointName", "joint_name", "joint")
# How many joints that do not move may separate one device's frames (a sensor link, its
# optical frame, a beam).
_DEVICE_DEPTH = 2
# Kinds whose one device is declared as parts on one link: an IMU's accelerometer and
# gyrometer, an RGB-D camera's colour and depth streams (each read as a depth camera).
_COMPOSED = ("imu", "depth_camera")
# Kinds a ros2_control sensor cannot be told by its name: its state interfaces carry numbers,
# no image or scan (a `camera_pose` reads a pose); a camera a simulator's hardware renders says
# so by the image topics its parameters name (readers/urdf.py).
_IMAGING = frozenset(
    {"camera", "depth_camera", "stereo_camera", "wide_angle_camera", "thermal_camera", "lidar"}
)
# The parts of an IMU a description may declare one by one (iDynTree's URDF ``<sensor
# type="accelerometer">``): parts of one type with names of their own on one link are as many
# devices (a skin's accelerometers), an accelerometer and a gyroscope on it one device's.
_IMU_PARTS = frozenset({"accelerometer", "gyroscope", "gyro"})
# How far apart two frames on one link may sit and still be one device's streams (metres).
STREAM_REACH = 0.1
# Two devices of one kind cannot share a place: frames fixed to one body closer than this
# (metres) and facing one way hold one device declared twice (two lidar macros included at one
# mount, 7 mm apart; a RealSense's colour and depth streams, 15 mm). A lidar or a camera is
# centimetres across; a stereo pair's eyes are further apart than this, and so is a row of
# line sensors (19 mm).
TWIN_REACH = 0.015
# Gazebo Sim's cameras that draw the simulator's own labels (boxes round each model, a colour
# per label; each under its two names): ground truth for training, no device, wherever it is.
_ANNOTATIONS = frozenset(
    {"boundingbox_camera", "boundingbox", "segmentation_camera", "segmentation"}
)
# How many kept frames of one grid cell a frame is compared with: a ring of cameras at one
# point is a few; a stranger's thousands cost no more than this each.
_CELL = 8
# How far a place may be off by the rounding of the turns that put it there (metres): a
# RealSense's streams 15 mm apart stay within reach however its mount is turned.
_ROUNDING = 1e-6
# Two fields of view further apart than this share of the wider are two lenses: two devices.
_LENS = 0.1
# The kinds whose devices look out from their frame, each a body of its own.
_VIEWING = frozenset(
    {
        "lidar",
        "camera",
        "depth_camera",
        "stereo_camera",
        "wide_angle_camera",
        "thermal_camera",
        "sonar",
        "ir_range",
        "radar",
    }
)
# A depth stream named for an RGB-D camera, a device of its own (not a stereo pair's depth).
_RGBD_DEVICE = re.compile(r"xtion|kinect|realsense|primesense|orbbec|(^|[_/-])astra", re.IGNORECASE)
# A link that is a camera's own body (its streams' frames are fixed to it), by its name.
_CAMERA_BODY = re.compile(r"camera|realsense|kinect|openni|xtion", re.IGNORECASE)
# A side of a stereo pair in a sensor name: l, r, left or right between separators.
_SIDE = re.compile(r"(^|[_/-])(l|r|left|right)([_/-]|$)", re.IGNORECASE)
# A side last in a sensor name: one device's two channels (``nav_cam/left``, ``nav_cam/right``),
# not two devices named for their sides (``left_eye_camera``).
_LAST_SIDE = re.compile(r"[_/-](l|r|left|right)$", re.IGNORECASE)
# A link named for a camera (``camera_link``, ``link_nav_cam``, ``bb2_cam``; not ``camshaft``).
_CAMERA_LINK = re.compile(r"cam(era)?([^a-z]|$)|realsense|kinect|openni|xtion", re.IGNORECASE)
# A camera named for a ZED, Stereolabs' stereo camera (``zed2_left_camera_sensor``), as the
# profile's frames read them.
_ZED_NAME = re.compile(r"(^|[_/-])zed", re.IGNORECASE)
# A stereo pair in a camera's topic: ``stereo`` as a word (``/stereo/left/image_raw``,
# stereo_image_proc's layout; ``/front_stereo/left``, ``/stereo_camera/right``), not
# ``stereographic``.
_STEREO_TOPIC = re.compile(r"(^|[^a-z])stereo([^a-z]|$)", re.IGNORECASE)
# The streams a stereo camera's eye gives: images, and depth where the simulation computes it
# on one eye's frame.
_EYES = frozenset({"camera", "depth_camera"})
# The widest baseline of a stereo camera (metres): two frames farther apart are two cameras.
_BASELINE = 0.3
# A horizontal fan of rays narrower than this (radians, twenty degrees) points one way: a range
# finder's beam or cone, one distance. A lidar sweeps wider: every labelled ray sensor of the
# development rows this narrow is a range finder, a sonar or a DVL's beam (docs/identify.md).
_POINT_SWEEP = math.radians(20.0)
# The element types of a sensor that casts rays (Gazebo's and Gazebo Sim's spellings).
_RANGING = frozenset({"ray", "gpu_ray", "lidar", "gpu_lidar", "sonar"})
# A Gazebo plugin that casts rays (gazebo_ros_ray_sensor, a GPU ray sensor).
_RAY_PLUGIN = re.compile(r"(^|[^a-z])(gpu_?)?ray([^a-z]|$)", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class Detection:
    """One sensor seen by one source."""

    kind: str
    name: str
    source: str
    link: str | None = None
    vertical_samples: int | None = None
    # Where a camera's images go (:func:`_image_topic`), "" when the description does not say.
    topic: str = ""
    # The horizontal field of view its element declares (radians), None when it says none.
    fov: float | None = None


@dataclass(frozen=True, slots=True)
class Sensor:
    """All sensors of one kind (and sensor type): the JSON ``sensors`` entries."""

    kind: str
    sensor_type: str | None
    count: int
    source: str


def sensors_from_urdf(urdf: Urdf, profile: Profile, source: str = "urdf") -> tuple[Detection, ...]:
    """The sensors a URDF declares, one per physical device, in document order.

    One device declared twice (a Gazebo ``<sensor>`` and a URDF ``<sensor>``, a plugin feeding
    an element or written again outside it, a model plugin publishing on the topic an element
    of its kind publishes on, two parts of one IMU on one link) counts once; so
    does a device whose beams hang from its own link on joints that do not move (a DVL plugin
    and its four range rays), and a colour and a depth stream on one link are one RGB-D
    camera. Distinct devices count apart even when they share a name (one force sensor per
    joint), and sensors declared alike with names of their own on one link (three cameras on a
    head frame) are as many. A
    ``<ros2_control>`` sensor (told by what it reads, else by its name) counts when no element
    or plugin declares a device of its kind, and not when neither tells its kind.
    """
    found, beams, parts = _element_detections(urdf, profile, source)
    found += _plugin_detections(urdf, profile, source, found)
    for model in urdf.models:
        included = _model_kind(model.model, profile)
        if included is not None:
            found.append((Detection(included, model.name, source, model.link), "model"))
    return tuple(_devices(_hardware_kept(found), urdf, beams, _imu_devices(found, parts)))


def _plugin_detections(
    urdf: Urdf, profile: Profile, source: str, found: list[tuple[Detection, str]]
) -> list[tuple[Detection, str]]:
    """One detection per model plugin that simulates a sensor and is not one of the elements
    in ``found`` declared again: a plugin a ``<sensor>`` runs, written again outside it (the
    same name, file and settings), or one publishing on the topic a plugin of a ``<sensor>`` of
    its kind publishes on (:func:`_topic`; an IMU plugin on the body beside the IMU sensor,
    one stream)."""
    inside = {_same_plugin(p) for tag in urdf.sensors for p in tag.plugins}
    streams = {
        (element_kind(tag, profile), topic)
        for tag in urdf.sensors
        for p in tag.plugins
        if (topic := _topic(p)) is not None
    }
    # The links elements of each kind sit on (where a plugin of that kind may report).
    elements: dict[str, set[str | None]] = {}
    for detection, _ in found:
        elements.setdefault(detection.kind, set()).add(detection.link)
    plugins: list[tuple[Detection, str]] = []
    for plugin in urdf.plugins:
        simulated = plugin_kind(plugin, profile)
        if simulated is None or _same_plugin(plugin) in inside:
            continue
        link = _plugin_link(plugin, elements.get(simulated, frozenset()))
        joint = urdf.joint(plugin.param(*_JOINT_PARAMS) or "")
        if link is None and joint is not None:
            link = joint.child  # a sensor on a joint measures at the joint's child link
        name = plugin.name or plugin.filename
        if simulated == "unknown" and _RAY_PLUGIN.search(plugin.filename or plugin.name):
            simulated = _ray_plugin_kind(plugin, profile)
        if (simulated, _topic(plugin)) in streams:
            continue
        if simulated == "unknown":
            name = f"{name} ({plugin.filename or plugin.name})"
        plugins.append((Detection(simulated, name, source, link), "plugin"))
    return plugins


def _topic(plugin: PluginTag) -> str | None:
    """The topic ``plugin`` publishes on (``topicName``, ``topic``) under the namespace it
    names (``robotNamespace``, ``namespace``), without leading slashes; None when it names no
    topic. A ``<sensor>``'s own ``<topic>`` element is not read."""
    topic = (plugin.param("topicName", "topic") or "").strip().lstrip("/")
    return _namespaced(plugin, topic) if topic else None


def _namespaced(plugin: PluginTag, name: str) -> str:
    """``name`` under the namespace ``plugin`` names (``robotNamespace``, ``namespace``)."""
    space = (plugin.param("robotNamespace", "namespace") or "").strip().strip("/")
    return f"{space}/{name}" if space else name


def _image_topic(tag: SensorTag) -> str:
    """Where a ``<sensor>``'s images go: its own ``<topic>``, else the camera name one of its
    plugins publishes under (``cameraName``, ``camera_name``), in the namespace it names; ""
    when neither is written."""
    if tag.topic:
        return tag.topic
    for plugin in tag.plugins:
        camera = (plugin.param("cameraName", "camera_name") or "").strip().strip("/")
        if camera:
            return _namespaced(plugin, camera)
    return ""


def _same_plugin(plugin: PluginTag) -> tuple[str, str, tuple[tuple[str, str], ...]]:
    """What makes two plugin declarations one: name, file name and settings."""
    return (plugin.name, plugin.filename, plugin.params)


def _element_detections(
    urdf: Urdf, profile: Profile, source: str
) -> tuple[list[tuple[Detection, str]], set[int], dict[int, str]]:
    """One detection per sensor element, with where it was declared; the ids of those that
    are a DVL's beams (range rays its name marks), parts of a device rather than devices; and
    the part of an IMU each element declared as one is (:data:`_IMU_PARTS`), by id."""
    found: list[tuple[Detection, str]] = []
    beams: set[int] = set()
    parts: dict[int, str] = {}
    urdf_links = {t.name: t.link for t in urdf.sensors if t.origin == "urdf" and t.link}
    for tag in urdf.sensors:
        if _publishes_truth(tag, profile):
            continue
        kind = element_kind(tag, profile)
        if tag.origin == "ros2_control" and tag.type == "unknown" and kind in _IMAGING:
            kind = "unknown"  # told by a name it cannot be: dropped with the other unknown ones
        link = tag.link
        if link is not None and not urdf.has_link(link):
            if link in urdf_links:
                link = urdf_links[link]  # a Gazebo <sensor> referring to a URDF <sensor> by name
            elif (joint := urdf.joint(link)) is not None:
                link = joint.child  # a Gazebo <sensor> on a joint (a force/torque sensor)
        detection = Detection(
            kind,
            tag.name or tag.type,
            source,
            link,
            tag.vertical_samples,
            _image_topic(tag),
            tag.horizontal_fov,
        )
        if kind == "dvl" and tag.type in _BEAM_TYPES:
            beams.add(id(detection))
        part = (tag.type or "").lower()
        if kind == "imu" and part in _IMU_PARTS:
            parts[id(detection)] = part
        found.append((detection, tag.origin))
    return found, beams, parts


def _publishes_truth(tag: SensorTag, profile: Profile) -> bool:
    """Whether a ``<sensor>`` gives simulation ground truth, no device: every plugin it runs
    publishes it (a noise-free twin of a ranger on the ranger's link, named and published as
    ``gt_lidar``), its own name says so (``front_laser_truth``, the twin of an Ouster an SDF
    export kept without its plugins), or it is one of Gazebo Sim's label cameras
    (:data:`_ANNOTATIONS`)."""
    if (tag.type or "").lower() in _ANNOTATIONS or _ground_truth(tag.name, profile):
        return True
    return bool(tag.plugins) and all(_ground_truth(plugin.text, profile) for plugin in tag.plugins)


def _ground_truth(text: str, profile: Profile) -> bool:
    """Whether ``text`` (what names a plugin or a model) is of one publishing simulation ground
    truth, by the profile's ``sensors.ground_truth``."""
    truth = profile.ground_truth
    return truth is not None and bool(truth.search(text))


def _imu_devices(found: list[tuple[Detection, str]], parts: dict[int, str]) -> dict[str, set[str]]:
    """Per link where an IMU is declared as its parts, the names of its devices: the parts of
    the type declared most there, each with a name of its own (51 skin accelerometers on 11
    links are 51 devices; an accelerometer and a gyroscope beside it, one)."""
    named: dict[str, dict[str, set[str]]] = {}
    for detection, _ in found:
        part = parts.get(id(detection))
        if part is not None and detection.link is not None:
            named.setdefault(detection.link, {}).setdefault(part, set()).add(detection.name)
    return {link: max(kinds.values(), key=len) for link, kinds in named.items()}


def _hardware_kept(found: list[tuple[Detection, str]]) -> list[tuple[Detection, str]]:
    """``found`` without the ros2_control sensors of kinds something else declares (such a
    block reads a device declared elsewhere: a Gazebo IMU it names again), nor those whose
    readings and name both say nothing of their kind (``unknown``)."""
    declared = {detection.kind for detection, origin in found if origin != "ros2_control"}
    declared.add("unknown")  # a ros2_control sensor neither its readings nor its name tell
    return [
        (d, origin) for d, origin in found if origin != "ros2_control" or d.kind not in declared
    ]


def under_water(detections: Iterable[Detection]) -> tuple[Detection, ...]:
    """The sensors of a body below the water: a barometer there reads the water's pressure,
    which is its depth (a depth gauge, kind ``pressure``, as the labelled sets count it); so
    does a range finder its author names for depth (``depth_sensor``, a Bar30's link): a
    simulator fakes the gauge with a ray, the device is the gauge."""
    return tuple(
        Detection("pressure", d.name, d.source, d.link, d.vertical_samples)
        if d.kind == "barometer" or (d.kind == "ir_range" and _named_for_depth(d))
        else d
        for d in detections
    )


def _named_for_depth(detection: Detection) -> bool:
    """The device's own name or its link says a depth gauge (not a file a frame was found in:
    a frame's detection names its file after the link, ``imu_link (frame id in ...)``)."""
    name = detection.name.split(" (", 1)[0]
    return any(_DEPTH_GAUGE.search(text) for text in (name, detection.link or ""))


# A depth gauge by its name, a word of its own: `depth`, `depth_sensor`, `depth_gauge_link`
# (not `depth_camera_link`, `depth_sounder`, `max_depth_range`), or Blue Robotics' Bar30 and
# Bar02 pressure sensors.
_DEPTH_GAUGE = re.compile(
    r"(^|[^a-z])depth(_?(sensor|gauge|link|frame))*([^a-z_]|$)|(^|[^a-z])bar_?(30|02)([^0-9]|$)",
    re.IGNORECASE,
)


def _plugin_link(plugin: PluginTag, declared: Container[str | None]) -> str | None:
    """The link a sensor plugin outside any ``<sensor>`` reports on: of the links it names (its
    body, its frame), one where an element of its kind sits (``declared``), the device declared
    twice (an IMU's element on ``imu_link``, its plugin's ``<bodyName>`` the chassis and
    ``<frameName>`` ``imu_link``); else the first it names, else its ``<gazebo reference>``."""
    named = [text for tag, text in plugin.params if tag.lower() in _LINK_TAGS]
    return next((link for link in named if link in declared), None) or (
        named[0] if named else plugin.reference
    )


def _model_kind(model: str, profile: Profile) -> str | None:
    """The sensor a Gazebo model include adds (``model://gps``), read by its model name with
    the rules for plugins that simulate a sensor: a kind they name, not just ``sensor``."""
    if _ground_truth(model, profile):
        return None
    kind = next((rule.kind for rule in profile.plugin_rules if rule.accepts(None, model)), None)
    return None if kind == "unknown" else kind


def _devices(
    found: list[tuple[Detection, str]],
    urdf: Urdf,
    beams: set[int],
    imus: dict[str, set[str]],
) -> list[Detection]:
    """One detection per physical device (see :func:`sensors_from_urdf`); linear in their
    number (an index by kind and link, a few links up each). On a link where an IMU is
    declared as its parts, ``imus`` names its devices: one detection each, whatever declared it
    (a Gazebo twin of the same name), and nothing else of that kind there."""
    origins: dict[tuple[str, str], set[str]] = {}
    for detection, origin in found:
        if detection.link is not None:
            origins.setdefault((detection.kind, detection.link), set()).add(origin)
    kept: list[Detection] = []
    # Per kind and link: the names and the origins kept so far (what :func:`_same` compares a
    # new declaration with, by sets: many sensors on one link stay linear).
    seen: dict[tuple[str, str], tuple[set[str], set[str]]] = {}
    counted: set[tuple[str, str]] = set()  # the IMUs of ``imus`` kept, by link and name
    for detection, origin in found:
        link = detection.link
        if link is None:
            kept.append(detection)
            continue
        # A part of a device declared above it elsewhere (a DVL plugin's range beams, a
        # sensor's optical frame); two elements of one kind (a shin and a foot contact) stay.
        if any(origins.get((detection.kind, up), {origin}) - {origin} for up in _above(link, urdf)):
            continue
        if detection.kind == "imu" and link in imus:
            if detection.name in imus[link] and (link, detection.name) not in counted:
                counted.add((link, detection.name))
                kept.append(detection)
            continue
        names, places = seen.setdefault((detection.kind, link), (set(), set()))
        if _same(detection, origin, names, places):
            continue
        names.add(detection.name)
        places.add(origin)
        kept.append(detection)
    kept = _twins(kept, urdf)
    depth = {d.link for d in kept if d.kind == "depth_camera"}
    # A colour camera on the link of a depth camera is the RGB-D camera's colour stream.
    kept = [d for d in kept if not (d.kind == "camera" and d.link in depth)]
    cameras = _stereo_pairs(_rgbd_frames(_dvl_beams(kept, urdf, beams), urdf), urdf)
    return _stereo_depth(cameras, urdf)


def _twins(found: list[Detection], urdf: Urdf) -> list[Detection]:
    """One device declared on two frames: two detections of one kind that looks out
    (:data:`_VIEWING`), on two frames fixed to one body within :data:`TWIN_REACH` of each
    other and facing the same way (their x and z axes within about 11 degrees), are one
    device; the first stays. On one frame the names tell (:func:`_same`); frames apart, or
    turned apart (a ring of cameras at one point), hold as many devices, and so do frames at
    their body's origin (a description that places no frame, or places its sensors by their
    own ``<pose>``, says nothing of where they are). Linear in their number: each frame is
    compared with at most :data:`_CELL` kept frames of the grid cells of :data:`TWIN_REACH`
    around its place, each frame's place and axes worked out once."""
    if sum(1 for d in found if d.kind in _VIEWING and d.link is not None) < 2:
        return found
    poses = Poses(urdf)
    known: dict[str, str | None] = {}
    cells: dict[tuple[str, str | None, int, int, int], list[_Frame]] = {}
    kept: list[Detection] = []
    for detection in found:
        frame = _placed_on_body(detection, urdf, poses, known)
        if frame is None:
            kept.append(detection)
            continue
        x, y, z = frame.cell
        near = itertools.islice(
            (
                other
                for dx, dy, dz in CELLS_AROUND
                for other in cells.get((detection.kind, frame.body, x + dx, y + dy, z + dz), [])
            ),
            _CELL,
        )
        if any(other.link != frame.link and _twin_frames(frame, other) for other in near):
            continue
        cells.setdefault((detection.kind, frame.body, x, y, z), []).append(frame)
        kept.append(detection)
    return kept


@dataclass(frozen=True, slots=True)
class _Frame:
    """A looking-out sensor's frame: its link, the body it is fixed to (the nearest movable
    joint above it, None for the root's), its place, the grid cell of :data:`TWIN_REACH` it
    stands in, and where its x and z axes point."""

    link: str
    body: str | None
    place: Vector
    cell: tuple[int, int, int]
    facing: Vector
    up: Vector
    fov: float | None


def _placed_on_body(
    detection: Detection, urdf: Urdf, poses: Poses, known: dict[str, str | None]
) -> _Frame | None:
    """A looking-out detection's frame (:class:`_Frame`); None for another kind, a frame the
    file lacks, a place too far out, or a frame at its body's origin (no place said)."""
    link = detection.link
    if detection.kind not in _VIEWING or link is None or not urdf.has_link(link):
        return None
    place = poses.place(link)
    cell = grid_cell(place, TWIN_REACH)
    if cell is None:
        return None
    body = moved_by(urdf, link, known)
    moved = urdf.joint(body) if body is not None else None
    if distance(place, poses.place(moved.child if moved else urdf.root)) <= 1e-9:
        return None
    facing, up = poses.facing(link), poses.turned(link, _NO_TURN, _Z)
    return _Frame(link, body, place, cell, facing, up, detection.fov)


def _twin_frames(one: _Frame, other: _Frame) -> bool:
    """Two frames within :data:`TWIN_REACH` of each other whose x and z axes point one way,
    of sensors seeing as wide (a narrow and a wide lens at one mount are two cameras)."""
    return (
        distance(one.place, other.place) <= TWIN_REACH + _ROUNDING
        and same_way(one.facing, other.facing)
        and same_way(one.up, other.up)
        and not _other_lens(one.fov, other.fov)
    )


def _other_lens(one: float | None, other: float | None) -> bool:
    """Two fields of view both declared and more than :data:`_LENS` apart (a share of the
    wider)."""
    return one is not None and other is not None and abs(one - other) > _LENS * max(one, other)


def _dvl_beams(found: list[Detection], urdf: Urdf, beams: set[int]) -> list[Detection]:
    """A DVL's beams (range rays named for it, each on a frame of its own) are parts of the DVL
    on their rigid body, however its plugin names the hull; with no DVL declared there, the
    beams are one DVL. Two DVLs declared as such stay two."""
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it

    def body(detection: Detection) -> str | None:
        return None if detection.link is None else moved_by(urdf, detection.link, known)

    devices = {body(d) for d in found if d.kind == "dvl" and id(d) not in beams}
    kept: list[Detection] = []
    for detection in found:
        if id(detection) in beams:
            carrier = body(detection)
            if carrier in devices:
                continue
            devices.add(carrier)  # the first beam stands for a DVL drawn as its beams alone
        kept.append(detection)
    return kept


def _rgbd_frames(found: list[Detection], urdf: Urdf) -> list[Detection]:
    """An RGB-D camera declared as streams on sibling frames (a colour frame and a depth frame
    fixed to one camera link, not to the body's root, within :data:`STREAM_REACH` of each
    other and facing the same way), each read as a depth camera (the colour stream by its
    device's name, ``kinect``), is one device: the first stays. Two depth cameras on one mount
    further apart or facing apart (a front and a rear camera on ``base_link``) are two. Plain
    cameras beside a depth camera stay cameras (a head's two cameras and its depth sensor),
    unless the link they share is the camera's own body (:func:`_stream_of`) or they hang from
    a camera's body as the depth stream's frame does, or from the body that carries it
    (:meth:`_DepthFrames.holds_stream`)."""
    mounts: dict[int, Joint] = {}
    for detection in found:
        if detection.kind == "depth_camera" and detection.link is not None:
            joint = urdf.parent_joint(detection.link)
            if joint is not None and not joint.movable and joint.parent != urdf.root:
                mounts[id(detection)] = joint
    owners: dict[str, list[tuple[Detection, Joint]]] = {}
    owner_of: dict[int, Detection] = {}
    for detection in found:
        joint = mounts.get(id(detection))
        if joint is not None:
            here = owners.setdefault(joint.parent, [])
            near = next((d for d, j in here if _one_device(j, joint)), None)
            if near is None:
                here.append((detection, joint))
            owner_of[id(detection)] = near or detection
    beside = _DepthFrames(found, urdf)
    kept = []
    for detection in found:
        owner = owner_of.get(id(detection))
        own = owner is None or owner is detection or owner.link == detection.link
        if own and not _stream_of(detection, owners, urdf) and not beside.holds_stream(detection):
            kept.append(detection)
    return kept


class _DepthFrames:
    """The depth streams' frames by the camera's body each hangs from (a link named for a
    camera, the frame named for it up to its camera word, :data:`_DEVICE_DEPTH` fixed joints
    down at most, their offsets adding up to :data:`STREAM_REACH` at most), found once; every
    link's place and turn computed once, when a camera is first compared with one."""

    def __init__(self, found: list[Detection], urdf: Urdf) -> None:
        self.urdf = urdf
        self._by_body: dict[str, set[str]] = {}
        self._poses: Poses | None = None
        self._frames: dict[str, tuple[Vector, Vector, Vector]] = {}
        # The camera words of depth streams on frames the file does not draw (a RealSense
        # macro's ``camera_depth_frame`` left out): their place cannot be compared, only named.
        self._undrawn: set[str] = set()
        for detection in found:
            if detection.kind == "depth_camera" and detection.link is not None:
                for body in _bodies_above(detection.link, urdf, with_itself=True):
                    self._by_body.setdefault(body, set()).add(detection.link)
                if not urdf.has_link(detection.link) and (word := _camera_word(detection.link)):
                    self._undrawn.add(word)

    def holds_stream(self, detection: Detection) -> bool:
        """A plain camera on a frame that hangs from a camera's body as a depth stream's frame
        does, or from the body that carries the depth stream itself, within
        :data:`STREAM_REACH` of it and turned as it is (their x and z axes one way, every joint
        at rest), is that RGB-D camera's colour or infrared stream: an RGB-D macro's colour and
        depth optical frames, each turned the optical way under the camera's link; a RealSense
        macro's colour and infrared frames beneath the ``camera_link`` its depth sensor is on.
        A camera turned another way (a rear camera on the same bracket), further off, or on a
        frame not named for the body (a thermal camera bolted to it) is one of its own; a turn
        its sensor's own ``<pose>`` gives is not read. Streams on frames the file does not draw
        are one camera's where their names begin with one camera word (``camera_color_frame``
        beside the depth stream's ``camera_depth_frame``: a RealSense macro whose frames were
        left out)."""
        if detection.kind != "camera" or detection.link is None:
            return False
        if not self.urdf.has_link(detection.link):
            return _camera_word(detection.link) in self._undrawn
        return any(
            self._alike(detection.link, depth)
            for body in _bodies_above(detection.link, self.urdf)
            for depth in self._by_body.get(body, ())
        )

    def _alike(self, one: str, other: str) -> bool:
        (place, x, z), (theirs, their_x, their_z) = self._frame(one), self._frame(other)
        near = distance(place, theirs) <= STREAM_REACH
        return near and same_way(x, their_x) and same_way(z, their_z)

    def _frame(self, link: str) -> tuple[Vector, Vector, Vector]:
        """The link's place and its x and z axes, in the root's frame."""
        if link not in self._frames:
            if self._poses is None:
                self._poses = Poses(self.urdf)
            poses = self._poses
            turned = [poses.turned(link, _NO_TURN, axis) for axis in (_X, _Z)]
            self._frames[link] = (poses.place(link), turned[0], turned[1])
        return self._frames[link]


def _camera_word(frame: str) -> str:
    """``frame`` up to the end of its first camera word (``camera`` of ``camera_color_frame``,
    ``head_realsense`` of ``head_realsense_depth_frame``), when a stream's word follows it
    (:data:`_STREAM_WORD`: a colour, infrared or depth frame; not ``camera_rear_frame`` or a
    second device's ``camera2_color_frame``); empty otherwise."""
    named = _CAMERA_BODY.search(frame)
    if named is None or _STREAM_WORD.match(frame, named.end()) is None:
        return ""
    return frame[: named.end()]


# What names an RGB-D camera's stream right after its camera word (``_color``, ``_infra1``,
# ``_depth``, ``_aligned_depth_to_color``).
_STREAM_WORD = re.compile(r"_(colou?r|rgb|infra|ir|depth|aligned)", re.IGNORECASE)


def _bodies_above(link: str, urdf: Urdf, *, with_itself: bool = False) -> list[str]:
    """The links named for a camera's body that ``link`` hangs from (itself too, with
    ``with_itself``) through :data:`_DEVICE_DEPTH` fixed joints at most, their offsets adding
    up to :data:`STREAM_REACH` at most, ``link`` named for each (up to its camera word)."""
    found = [link] if with_itself else []
    reach = 0.0
    here = link
    for _ in range(_DEVICE_DEPTH):
        joint = urdf.parent_joint(here)
        if joint is None or joint.movable:
            break
        reach += math.hypot(*joint.origin)
        if reach > STREAM_REACH:
            break
        here = joint.parent
        found.append(here)
    return [
        body
        for body in found
        if (named := _CAMERA_BODY.search(body)) is not None and link.startswith(body[: named.end()])
    ]


_NO_TURN = (0.0, 0.0, 0.0)
_X = (1.0, 0.0, 0.0)
_Z = (0.0, 0.0, 1.0)


def _one_device(first: Joint, second: Joint) -> bool:
    """Two frames fixed to one link are one device's streams: they sit within
    :data:`STREAM_REACH` of each other and face the same way (a Kinect's colour and depth
    frames, 2.5 cm apart)."""
    close = math.dist(first.origin, second.origin) <= STREAM_REACH
    return close and all(abs(a - b) <= 1e-6 for a, b in zip(first.rpy, second.rpy, strict=True))


def _stream_of(
    detection: Detection, owners: dict[str, list[tuple[Detection, Joint]]], urdf: Urdf
) -> bool:
    """A plain camera on a frame fixed to the body of an RGB-D camera (a link named a camera,
    whose depth stream hangs from it too, near it and facing its way: :func:`_one_device`) is
    one of that camera's streams: its colour or infrared image. On any other mount (a head) it
    is a camera of its own."""
    if detection.kind != "camera" or detection.link is None:
        return False
    joint = urdf.parent_joint(detection.link)
    if joint is None or joint.movable or joint.parent not in owners:
        return False
    if _CAMERA_BODY.search(joint.parent) is None:
        return False
    return any(_one_device(theirs, joint) for _, theirs in owners[joint.parent])


def _stereo_pairs(found: list[Detection], urdf: Urdf) -> list[Detection]:
    """Two cameras that are one stereo camera, where the first of them was: named stereo, with
    names that differ only by a side (``wide_stereo_l_...`` and ``wide_stereo_r_...``); with
    topics that differ only by a side beside a ``stereo`` word (``/stereo/left/image_raw``
    and ``/stereo/right/image_raw``: :func:`_image_topic`), or names for a ZED that differ only
    by a side (``zed2_left_camera_sensor``, ``zed2_right_...``; two ZEDs of one macro, named
    alike, pair by their frames), or with one name on two frames that differ only by a side
    (``duo3d_left_link`` and ``duo3d_right_link``), on one rigid body a stereo baseline apart
    and facing one way (:func:`_side_by_side`); or on
    one frame named for a camera, not the root, named for one device and then a side
    (``nav_cam/left`` and ``nav_cam/right``, a stereo head's two channels; ``left_eye_camera``
    and ``right_eye_camera`` are two eyes: :func:`_stereo_head`). One of the two may be a
    depth stream (a simulated eye that also gives the pair's depth, as a ZED's left one does;
    two depth cameras are two), and any other camera or depth stream on an eye's own frame is
    one of the pair's (a raw and a rectified image of one eye)."""
    pairs: dict[tuple[str, str, str], list[Detection]] = {}  # (by what, name, frame)
    for detection in found:
        key = _pair_key(detection, urdf) if detection.kind in _EYES else None
        if key is not None:
            pairs.setdefault(key, []).append(detection)
    # Topics or ZED names that pair no two cameras (two rigs of one macro, each on its own
    # frames, publish or are named alike): those cameras pair as their frames say.
    for key in [
        key for key, group in pairs.items() if key[0] in ("topic", "zed") and len(group) != 2
    ]:
        for detection in pairs.pop(key):
            fallback = _pair_key(detection, urdf, by_topic=False)
            if fallback is not None:
                pairs.setdefault(fallback, []).append(detection)
    poses: list[Poses] = []  # computed once, when two frames are compared
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    merged: dict[int, list[Detection]] = {}
    for key, pair in pairs.items():
        if len(pair) != 2 or all(d.kind == "depth_camera" for d in pair):
            continue
        if key[0] in ("frame", "topic", "zed"):
            poses = poses or [Poses(urdf)]
            if not _side_by_side(pair[0], pair[1], poses[0], known):
                continue
        merged.update({id(d): pair for d in pair})
    return _paired(found, merged)


def _paired(found: list[Detection], merged: dict[int, list[Detection]]) -> list[Detection]:
    """``found`` with each pair of ``merged`` (by its detections' ids) one stereo camera, where
    its first was, and the other streams on an eye's own frame dropped (a pair on one frame, a
    head's, shares it with other cameras)."""
    eyes = {
        d.link
        for pair in merged.values()
        if pair[0].link != pair[1].link
        for d in pair
        if d.link is not None
    }
    kept = []
    for detection in found:
        both = merged.get(id(detection))
        if both is None:
            if detection.kind not in _EYES or detection.link not in eyes:
                kept.append(detection)
        elif detection is both[0]:
            kept.append(
                Detection("stereo_camera", _pair_name(*both), detection.source, detection.link)
            )
    return kept


def _pair_key(
    detection: Detection, urdf: Urdf, *, by_topic: bool = True
) -> tuple[str, str, str] | None:
    """What a camera and the other side of its stereo pair share (by what, name, frame), as
    :func:`_stereo_pairs` tells them (``by_topic``: a stereo topic or a ZED's name naming a side
    counts; else a ZED pairs by its frames); None for a camera no pair can hold."""
    if "stereo" in detection.name.lower():
        return ("name", _unsided(detection.name), "")
    topic = detection.topic
    if by_topic and _STEREO_TOPIC.search(topic) and _SIDE.search(topic):
        return ("topic", _unsided(topic), "")
    if _ZED_NAME.search(detection.name) and _SIDE.search(detection.name):
        if by_topic:
            return ("zed", _unsided(detection.name), "")
        if detection.link is not None and _SIDE.search(detection.link):
            return ("frame", _unsided(detection.name), _unsided(detection.link))
    if detection.link is not None and _SIDE.search(detection.link):
        return ("frame", detection.name, _unsided(detection.link))
    if _stereo_head(detection, urdf):
        return ("sides", _unsided(detection.name), detection.link or "")
    return None


def _stereo_head(detection: Detection, urdf: Urdf) -> bool:
    """A camera named for one device and then a side (``nav_cam/left``) on a link named for a
    camera (``link_nav_cam``), not the root: a stereo head's channel. Cameras a description
    puts all on its body or root (each with a pose of its own, facing any way) say nothing."""
    link = detection.link
    if link is None or link == urdf.root or not _LAST_SIDE.search(detection.name):
        return False
    return bool(_CAMERA_LINK.search(link))


def _unsided(name: str) -> str:
    return _SIDE.sub(r"\1*\3", name)


def _side_by_side(
    one: Detection, other: Detection, poses: Poses, known: dict[str, str | None]
) -> bool:
    """Two camera frames (not one) of the description on one rigid body (no joint moves one
    without the other), at most :data:`_BASELINE` apart, their x axes one way. ``known`` is
    :func:`moved_by`'s memo."""
    urdf = poses.urdf
    first, second = one.link, other.link
    if first is None or second is None or first == second:
        return False
    if not (urdf.has_link(first) and urdf.has_link(second)):
        return False
    if moved_by(urdf, first, known) != moved_by(urdf, second, known):
        return False
    apart = distance(poses.place(first), poses.place(second))
    return 0 < apart <= _BASELINE and same_way(poses.facing(first), poses.facing(second))


def _stereo_depth(found: list[Detection], urdf: Urdf) -> list[Detection]:
    """A depth stream on the frame of a stereo camera, or on a frame fixed to it within
    :data:`STREAM_REACH` and facing its way (either above the other), is the depth the pair
    computes: one stereo camera, unless it is named for an RGB-D camera of its own
    (:data:`_RGBD_DEVICE`: an ASUS Xtion on a head beside its stereo pair). Linear: a set of the
    stereo cameras' links, one joint up and the joints down from each depth stream's link."""
    stereo = {d.link for d in found if d.kind == "stereo_camera" and d.link is not None}
    if not stereo:
        return found
    return [
        d
        for d in found
        if not (
            d.kind == "depth_camera"
            and _RGBD_DEVICE.search(d.name) is None
            and _beside_stereo(d, stereo, urdf)
        )
    ]


def _beside_stereo(detection: Detection, stereo: set[str], urdf: Urdf) -> bool:
    link = detection.link
    if link is None:
        return False
    if link in stereo:
        return True
    up = urdf.parent_joint(link)
    joints = [j for j in urdf.children(link) if j.child in stereo]
    if up is not None and up.parent in stereo:
        joints.append(up)
    return any(not j.movable and _near(j) for j in joints)


def _near(joint: Joint) -> bool:
    """A fixed frame within :data:`STREAM_REACH` of its parent, not turned from it."""
    close = math.dist(joint.origin, (0.0, 0.0, 0.0)) <= STREAM_REACH
    return close and all(abs(a) <= 1e-6 for a in joint.rpy)


def _pair_name(first: Detection, second: Detection) -> str:
    """``wide_stereo_l+r_stereo_camera_sensor``: the first name with both sides."""
    for one, other in zip(_SIDE.finditer(first.name), _SIDE.finditer(second.name), strict=False):
        if one.group(2) != other.group(2):
            sides = f"{one.group(2)}+{other.group(2)}"
            return first.name[: one.start(2)] + sides + first.name[one.end(2) :]
    return first.name


def _same(detection: Detection, origin: str, names: set[str], origins: set[str]) -> bool:
    """A declaration is a device already kept on its link (``names`` and ``origins`` of those
    of its kind there) when one came from another place (a Gazebo and a URDF element) or
    shares its name, or when both are parts of one IMU (a gyrometer and an accelerometer);
    sensors declared alike with names of their own are distinct."""
    if not origins:
        return False
    return bool(origins - {origin}) or detection.name in names or detection.kind in _COMPOSED


def _above(link: str, urdf: Urdf) -> list[str]:
    """The links above ``link`` through joints that do not move, a few steps, not the root."""
    found = []
    joint = urdf.parent_joint(link)
    for _ in range(_DEVICE_DEPTH):
        if joint is None or joint.movable or joint.parent == urdf.root:
            break
        found.append(joint.parent)
        joint = urdf.parent_joint(joint.parent)
    return found


def element_kind(tag: SensorTag, profile: Profile) -> str:
    """The kind of device a sensor element is, by the profile's element rules: first those
    that read names, on what names the device itself; then, for a ray sensor, on what it
    publishes too (a one-ray Gazebo Sim ``gpu_lidar`` publishing on ``.../sonar``); then those
    that read its rays, reach or field of view; then names anywhere (a plugin's settings)."""
    kind = tag.type or "unknown"  # a URDF <sensor> with no kind element: told by its name
    # Gazebo Sim's `custom` sensor is a plugin's own device (RGL's GPU lidar): told by its
    # names as one with no kind element is; a kind they do not tell stays `custom`.
    asked = "unknown" if kind == "custom" else kind
    rays = _rays(tag)
    fov = tag.horizontal_fov
    reach = tag.max_range
    named = [rule for rule in profile.element_rules if rule.match is not None]
    for rule in named:
        if rule.accepts(asked, tag.device_text, rays=rays, fov=fov, reach=reach):
            return rule.kind
    if asked in _RANGING:  # where a ranging device publishes says it, before its rays do
        published = " ".join([tag.topic, *(_topic(plugin) or "" for plugin in tag.plugins)])
        for rule in named:
            if rule.accepts(asked, published, rays=rays, fov=fov, reach=reach):
                return rule.kind
    for rule in profile.element_rules:
        if rule.match is None and rule.accepts(asked, "", rays=rays, fov=fov, reach=reach):
            return rule.kind
    for rule in profile.element_rules:  # topic names last
        if rule.match is not None and rule.accepts(
            asked, tag.text, rays=rays, fov=fov, reach=reach
        ):
            return rule.kind
    return kind


def _ray_plugin_kind(plugin: PluginTag, profile: Profile) -> str:
    """The device a ray sensor plugin written outside any ``<sensor>`` simulates (Gazebo's
    ``libgazebo_ros_ray_sensor.so`` straight under ``<gazebo>``; it says how many rays it casts
    nowhere): told by its names and topics as a ray ``<sensor>`` is (a DVL, a sonar, an
    infrared ranger), a range finder when it publishes a range (its output type, or a topic or
    remapping named so, as the profile's rule for a ``<sensor>`` of no type reads), else a
    lidar (its default output, a point cloud; a scan it says it publishes)."""
    text = plugin.text
    for rule in profile.element_rules:
        if rule.match is not None and rule.accepts("ray", text):
            return rule.kind
    if SCAN_OUTPUT.search(plugin.param("output_type") or ""):
        return "lidar"
    ranges = (rule for rule in profile.element_rules if rule.kind == "ir_range")
    return "ir_range" if any(rule.accepts("unknown", text) for rule in ranges) else "lidar"


def _rays(tag: SensorTag) -> int | None:
    """How many rays a ray sensor casts (horizontal x vertical samples; a missing axis casts
    one; a horizontal fan sweeping less than :data:`_POINT_SWEEP` points one way, a range
    finder's beam or cone, one ray across: a single-beam laser's two samples 0.02 degrees
    apart, a narrow ranger's three over 3.6 degrees measure one distance; so does a grid
    narrower than that both ways, a laser altimeter's 5 x 5 rays over 1.7 degrees); None
    when it says no samples at all, or none a simulator would cast (``0``, which Gazebo refuses:
    a count left at zero says nothing of the device)."""
    axes = [n for n in (tag.horizontal_samples, tag.vertical_samples) if n is not None]
    if not axes or any(n < 1 for n in axes):
        return None
    along_one_line = tag.sweep is not None and tag.sweep < _POINT_SWEEP
    horizontal = 1 if along_one_line else tag.horizontal_samples or 1
    # A narrow cone both ways (a rangefinder drawn as a grid of rays a degree across) measures
    # one distance too; a narrow vertical fan under a wide sweep is a lidar's few layers.
    in_one_cone = (
        along_one_line and tag.vertical_sweep is not None and tag.vertical_sweep < _POINT_SWEEP
    )
    vertical = 1 if in_one_cone else tag.vertical_samples or 1
    return horizontal * vertical


def plugin_kind(plugin: PluginTag, profile: Profile) -> str | None:
    """The sensor kind a Gazebo plugin simulates by the profile's plugin rules; None for ground
    truth, a simulator system or a plugin of no sensor."""
    if _ground_truth(plugin.text, profile):
        return None
    systems = profile.simulator_systems
    if systems is not None and systems.search(f"{plugin.name} {plugin.filename}"):
        return None  # a simulator system runs the <sensor> elements; it is none itself
    target = plugin.filename or plugin.name
    return next((rule.kind for rule in profile.plugin_rules if rule.accepts(None, target)), None)


def sensor_type_of(
    kind: str, profile: Profile, rules: RuleSet, vertical_samples: int | None = None
) -> str | None:
    """The rule set's sensor type for a sensor ``kind`` (None: no presentation in it)."""
    mapping = profile.sensor_type_mapping(kind)
    sensor_type = None if mapping is None else mapping.sensor_type_for(vertical_samples)
    if sensor_type is not None and sensor_type not in _rule_values(
        rules, profile.role(SENSOR_TYPE)
    ):
        return None
    return sensor_type


def merge(detections: Iterable[Detection], profile: Profile, rules: RuleSet) -> tuple[Sensor, ...]:
    """One :class:`Sensor` per (kind, sensor type), in order of first detection."""
    groups: dict[tuple[str, str | None], dict[str, list[Detection]]] = {}
    for detection in detections:
        sensor_type = sensor_type_of(detection.kind, profile, rules, detection.vertical_samples)
        groups.setdefault((detection.kind, sensor_type), {}).setdefault(
            detection.source, []
        ).append(detection)
    found = []
    for (kind, sensor_type), by_source in groups.items():
        count = max(len(items) for items in by_source.values())
        source = "; ".join(f"{name}: {_names(items)}" for name, items in by_source.items())
        found.append(Sensor(kind, sensor_type, count, source))
    return tuple(found)


def presented_count(sensors: Sequence[Sensor]) -> int:
    """How many sensors have a presentation in the rule set (the article's No. of Sensors)."""
    return sum(sensor.count for sensor in sensors if sensor.sensor_type is not None)


def _rule_values(rules: RuleSet, name: str) -> frozenset[str]:
    if name not in rules.names:
        return frozenset()
    return frozenset(str(v) for v in rules.characteristic(name).values)


def _names(items: Sequence[Detection], limit: int = 4) -> str:
    names = list(dict.fromkeys(d.name for d in items))
    listed = ", ".join(shown(name) for name in names[:limit])
    return listed + (f", ... ({len(names)} in all)" if len(names) > limit else "")
