"""Sensors on frames the description only draws, that a driver of the robot's packages
publishes in.

A description often carries a sensor as a bare frame: ``imu_link``, ``gps_link`` or
``camera_link`` on a fixed joint, with no ``<sensor>`` element or plugin (a real robot's
description, written for its TF tree rather than a simulator). When the robot's packages run
a driver that stamps its data with that frame (``frame_id: imu_link`` in its configuration,
``<param name="frame_id" value="imu_link"/>`` in a launch file, ``header.frame_id =
"imu_link"`` in a node), the device is real and the operator's UI has its data to show.

* A frame is *named* by a package when one of its launch, configuration or script files
  (:mod:`solver.identify.readers.workspace`) gives a driver a link of the description as its
  frame id: a key ``frame_id``, ``frame``, ``frame_name`` or one a device's word begins
  (``imu_frame``, ``camera_frame_id``; not a node's ``target_frame``, where it looks a
  transform up), the value (quoted after a prefix the node joins to it too:
  ``tf::resolve(tf_prefix_, "imu_link")``, ``prefix + "/imu_link"``) naming the link whole or by
  its last ``/`` segment (and a link the
  description writes under a namespace of its own, ``rc_12345/front_lidar``, by its last
  segment, when no other link ends so: ``$(var rc)/front_lidar``); or lists several, one per
  device (a device's word before ``frame_id`` or ``frame_ids`` and a list on one line: a
  cleaning robot's ``cliff_frame_id[4] = {...}``); or gives a frame id no link has that two
  numbered links or more begin (``ultrasonic_link`` for ``ultrasonic_link_0`` ...
  ``ultrasonic_link_7``, a driver stamping each device's readings with its index), or makes
  frame names from a quoted template with one number in it (``"US%d_link"``,
  ``f"sonar{i}_link"``) that two links or more fit; or when it names
  a camera driver (``camera_name``) from which the driver builds its frames (realsense2_camera,
  orbbec_camera): the link of that name, else ``NAME_link``, else the first link whose name
  begins ``NAME_`` and reads as a camera. A file that launches a depth camera's driver
  (a node of realsense2_camera, orbbec_camera, depthai_ros_driver, the Kinects' and Astra's
  drivers, or their launch files) and names no camera names the link it gives the driver as
  its ``parent_frame`` (depthai's mount), the one its ROS 1 launch file's ``camera`` argument
  gives, else the driver's default name (``camera``, depthai's ``oak``, kinect2_bridge's
  ``kinect2``), else, when no link has that name, the description's one camera
  (:meth:`_Naming.sole_device`); the camera so named is a depth camera, whatever its frame's
  name says (a ``camera_name`` in such a file may be another driver's, and says no kind). A
  file that launches a plain camera's driver (usb_cam, cv_camera, v4l2_camera, camera_ros,
  raspicam_node, gscam), which publishes in a frame id of its own, names the description's one
  camera so too, and one that launches an IMU's driver (bno055, xsens_mti_driver,
  openzen_sensor, a WitMotion's, ...) its one IMU: weighed once every file is read
  (:meth:`_Naming.launched_drivers`), a device a file names by a frame of its own staying as
  that file says.
* The profile's ``sensors.frames`` rules tell a named link's kind by its name (``imu``,
  ``gps``, ``lidar``, ``camera``, ...); a link no rule matches (``base_link``, ``odom``) is
  no sensor.
* One device's frames are one sensor: a frame hangs from its device's body through fixed
  joints whose links read as the same kind (any camera kind, for a camera's frames:
  ``camera_color_optical_frame`` under ``camera_color_frame`` under ``camera_link``); a
  camera's frames fixed beneath its body, named or not, say which camera it is, the first rule
  among them naming it (a colour and a depth frame: an RGB-D camera). Any other kind is a device
  of its own wherever it hangs (a D435i's IMU frame, under its camera link, is an IMU); named
  frames of one body of another kind farther apart than one device's streams sit
  (:data:`~solver.identify.sensors.STREAM_REACH`: a lidar's frame and its driver's scan
  frame) are a device each (a front and a back laser hung from one ``base_scan`` link;
  :func:`_apart`).
* The description's own word wins: no device is added for a kind the description declares
  (its camera's optical frame is that camera), nor on a device that carries a sensor the
  description declares.
* Bounds: the patterns are linear in the texts; a list's first 64 items are read; each
  link's rule is found once; a device's
  body is at most three joints up (from the topmost of the named frames in its run: a
  camera's depth frame and its optical frame, both named, three and four joints below a
  gripper's camera mount, are one camera; each link is climbed from once) and its camera
  frames at most three down; at most 64 camera
  names are looked up among the links; one body's frames are told apart at eight places at
  most.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Iterable

from solver.identify.pose import Poses, Vector, distance
from solver.identify.profile import Profile, SensorRule
from solver.identify.readers.urdf import Urdf
from solver.identify.readers.workspace import Workspace
from solver.identify.sensors import STREAM_REACH, Detection
from solver.untrusted import shown

__all__ = ["SOURCE", "named_frames", "sensors_on_frames"]

# The source the detections are merged under (a view of the robot, as a topic list is).
SOURCE = "packages"
# Fixed joints climbed from a frame to its device's body (an optical frame, a stream frame),
# and walked down from a camera's body to the frames of its streams.
_DEVICE_DEPTH = 3
# Kinds of one family: a camera's streams (a colour and a depth frame) are one camera, the
# first rule among them naming it. Any other kind is a device of its own wherever it hangs
# (an IMU inside a camera is an IMU, not the camera).
_CAMERAS = frozenset(
    {"camera", "depth_camera", "stereo_camera", "wide_angle_camera", "thermal_camera"}
)
# The most places one body's named frames are told apart at (each frame is compared with each
# place): more are read as one device, a stranger's thousand frames in linear time.
_MOST_PLACES = 8
# The most camera names resolved to links (each a walk over the links, for a name no link
# has): a stranger's files may write any number.
_MAX_CAMERA_NAMES = 64
# A frame id a driver is given: `frame_id`, `frame`, `frame_name`, or one of a device's
# (`camera_frame_id`, `imu_frame`), a word of its own; not a consumer's (`target_frame`,
# `base_frame`: what a node looks a transform up in). The devices' words, shared with a list of
# frame ids (`_LISTED`).
_DEVICE_WORDS = (
    "imu|gps|gnss|navsat|laser|lidar|scan|camera|cam|sensor|depth|color|rgb|sonar|dvl|range"
)
_KEY_WORD = r"(?:(?:" + _DEVICE_WORDS + r")_)?frame(?:_?id|_?name)?"
_KEY = r"(?<![A-Za-z0-9_])" + _KEY_WORD
# A value: a link's name (which may begin with a digit: `3d_camera_link`), after an optional
# `$(arg ns)/` or `/`, up to 200 characters.
_VALUE = r"(?:\$\([^()\n]{0,80}\))?/?([A-Za-z0-9_][A-Za-z0-9_/.-]{0,199})"
# `frame_id: x`, `frame_id:=x`, `"frame_id": "x"`, `frame_id="x"`, `header.frame_id = 'x'`;
# a parameter's default after its quoted key and a comma: `declare_parameter("frame_id", "x")`,
# `rospy.get_param("~frame_id", "x")`, `LaunchConfiguration("frame_id", default="x")`; and
# roscpp's `nh.param("frame_id", frame_id_, std::string("x"))`, a variable between, only in a
# `param` call (a log line's `("frame_id", frame, "x")` gives no frame).
_QUOTED_KEY = r"""["'][~/]?""" + _KEY + r"""["'][ \t]{0,3},[ \t]{0,8}"""
# A prefix a node joins before the quoted frame id, after `=` or `:=` only (not a statement's
# colon): roscpp's `tf::resolve(tf_prefix_, "x")` or another call named to resolve or join a
# name (`os.path.join(ns, "x")`; not `putText(frame, "x")` or `lookup_transform(a, "x")`), or a
# namespace added `prefix + "/x"` (a variable, then the value in quotes).
_PREFIXED = (
    r"""(?::=|=)[ \t]{0,8}"""
    r"""(?:(?:[A-Za-z_][A-Za-z0-9_]{0,30}(?:::|\.)){0,3}(?:resolve|join)[ \t]{0,3}\([ \t]{0,3}"""
    r"""[A-Za-z_][A-Za-z0-9_.]{0,40}[ \t]{0,3},"""
    r"""|[A-Za-z_][A-Za-z0-9_.]{0,40}[ \t]{0,3}\+)[ \t]{0,8}["']"""
)
_ASSIGNED = re.compile(
    _KEY + r"""["']?[ \t]{0,3}(?:""" + _PREFIXED + r"""|(?::=|:|=)[ \t]{0,8}["']?)""" + _VALUE
    + r"|" + _QUOTED_KEY + r"""(?:default(?:_value)?[ \t]{0,3}=[ \t]{0,3})?["']""" + _VALUE
    + r"""|(?<![A-Za-z0-9_])param(?:<[A-Za-z0-9_:]{0,30}>)?\([ \t]{0,3}""" + _QUOTED_KEY
    + r"""[A-Za-z_][A-Za-z0-9_.]{0,60}[ \t]{0,3},[ \t]{0,8}(?:std::string\([ \t]{0,3})?["']"""
    + _VALUE,
    re.IGNORECASE,
)  # fmt: skip
# A list of frame ids a driver is given, one per device of a kind (a cleaning robot's driver:
# `std::string cliff_frame_id[4] = {"left_cliff_sensor_link", ...}`, `bumper_frame_ids:
# [left_bumper_link, right_bumper_link]`): a key whose word before `frame_id` or `frame_ids`
# is a device's (a node's `source_frame_ids`, `ignore_frame_ids` or `self.frame_ids` are frames
# it looks up), then a brace or bracket list on one line; its items are read as frame ids.
_LISTED = re.compile(
    r"(?<![A-Za-z0-9_])(?:[A-Za-z0-9]{1,20}_){0,3}"
    r"(?:" + _DEVICE_WORDS + r"|cliff|ir|bumper|contact|ultrasonic|tof|proximity)s?_frame_?ids?"
    r"(?:[ \t]{0,3}\[[ \t]{0,3}\d{0,4}[ \t]{0,3}\])?"
    r"[ \t]{0,3}(?::|=)[ \t]{0,8}[{\[]([^{}\[\]\n]{0,2000})[}\]]",
    re.IGNORECASE,
)
# The most items of one list read (a stranger's file may list any number).
_MOST_LISTED = 64
# A launch parameter or argument: <param name="frame_id" type="string" value="x"/>,
# <arg name="imu_frame" default="x"/>.
_PARAMETER = re.compile(
    r"""name\s{0,3}=\s{0,3}["']""" + _KEY_WORD
    + r"""["'][^<>]{0,120}?(?:value|default)\s{0,3}=\s{0,3}["']""" + _VALUE,
    re.IGNORECASE,
)  # fmt: skip
# A number in a link's name (``US3_link``, ``ultrasonic_link_7``): up to three digits between
# non-digits.
_NUMBER = re.compile(r"(?<![0-9])[0-9]{1,3}(?![0-9])")
# A frame name made from a template with one number in it, quoted: C's and Python's
# ``"US%d_link"``, ``"sonar_%02d"``, a format string's ``"sonar{}_link"`` or ``f"sonar{i}_link"``
# (the text before and after the number, up to 80 characters each).
_TEMPLATE = re.compile(
    r"""["']([A-Za-z0-9_/]{0,80})(?:%0?[0-9]?[diu]|\{[A-Za-z0-9_]{0,20}(?::0?[0-9]?d)?\})"""
    r"""([A-Za-z0-9_/]{0,80})["']"""
)
# A camera driver's name, from which it builds its frames (realsense2_camera, orbbec_camera:
# camera_name:=camera_front publishes in camera_front_link, camera_front_color_optical_frame).
_DEVICE_NAME = re.compile(
    r"""(?<![A-Za-z0-9_])camera_?name["']?[ \t]{0,3}(?::=|:|=)[ \t]{0,8}["']?""" + _VALUE
    + r"""|name\s{0,3}=\s{0,3}["']camera_?name["'][^<>]{0,120}?(?:value|default)\s{0,3}="""
    + r"""\s{0,3}["']""" + _VALUE,
    re.IGNORECASE,
)  # fmt: skip

# A depth camera's driver that builds its frames from its name, launched or included in a
# file: a node of its package (``pkg="realsense2_camera"``, ``package='orbbec_camera'``), its
# package's launch file (``$(find-pkg-share realsense2_camera)/...``, ``$(find ...)``,
# ``get_package_share_directory("...")``, ``FindPackageShare("...")``, ``ros2 launch ...``).
# A mention elsewhere (a comment, a build script) launches nothing. Each driver's default
# name for its camera, taken when the file names none.
_DEPTH_DRIVERS = {
    "realsense2_camera": "camera",
    "orbbec_camera": "camera",
    "depthai_ros_driver": "oak",
    "openni_launch": "camera",
    "openni2_launch": "camera",
    "freenect_launch": "camera",
    "astra_camera": "camera",
    "kinect2_bridge": "kinect2",
    "azure_kinect_ros_driver": "camera",
}


def _launching(drivers: Iterable[str]) -> re.Pattern[str]:
    """A file that launches one of ``drivers`` (package names): a node of its package, its
    package's launch file, ``ros2 launch``/``run``; each form captures the driver's name."""
    driver = "(" + "|".join(drivers) + ")"
    return re.compile(
        r"""(?<![A-Za-z0-9_])(?:pkg|package)\s{0,3}=\s{0,3}["']""" + driver + r"""["']"""
        + r"|\$\(find(?:-pkg-share)?[ \t]{1,3}" + driver + r"\)"
        + r"""|(?:get_package_share_directory|FindPackageShare)\(\s{0,3}["']""" + driver
        + r"""["']|(?:ros2[ \t]+launch|roslaunch|ros2[ \t]+run|rosrun)[ \t]+""" + driver
        + r"(?![A-Za-z0-9_])",
    )  # fmt: skip


_DEPTH_LAUNCH = _launching(_DEPTH_DRIVERS)
# A camera driver that publishes a plain camera's images in a frame id of its own (usb_cam's
# ``head_camera``, raspicam_node's ``raspicam``), launched in a file as a depth camera's is.
_CAMERA_LAUNCH = _launching(
    (
        "usb_cam", "cv_camera", "v4l2_camera", "camera_ros", "raspicam_node", "gscam",
        "video_stream_opencv", "gscam2", "libcamera_ros",
    )
)  # fmt: skip
# An IMU's driver, which publishes in a frame id of its own (bno055's ``bno055``), launched
# in a file as a camera's is: it names the description's one IMU.
_IMU_LAUNCH = _launching(
    (
        "bno055", "ros_imu_bno055", "imu_bno055", "witmotion_ros", "wit_ros_imu",
        "wit_ros2_imu", "openzen_sensor", "xsens_mti_driver", "xsens_driver",
        "bluespace_ai_xsens_mti_driver", "microstrain_inertial_driver", "um7", "um6",
        "phidgets_spatial", "phidgets_imu", "razor_imu_9dof", "mpu6050_driver", "ros2_mpu6050",
        "vectornav", "imu_vn_100", "adi_imu", "sbg_driver", "myahrs_driver", "lpms_ig1",
        "hipnuc_imu",
    )
)  # fmt: skip
_IMUS = frozenset({"imu"})
# A camera whose name says it is no depth camera: a depth camera's driver does not name it.
_NOT_DEPTH = re.compile(r"thermal|flir|lepton|fisheye|webcam|usb", re.IGNORECASE)
# The name a ROS 1 depth camera's launch file takes its camera's by (``rs_camera.launch``'s
# ``<arg name="camera" value="d435"/>``), read only in a file that launches such a driver.
_CAMERA_ARGUMENT = re.compile(
    r"""name\s{0,3}=\s{0,3}["']camera["'][^<>]{0,120}?(?:value|default)\s{0,3}=\s{0,3}["']"""
    + _VALUE,
)  # fmt: skip
# The link a depth camera's driver hangs its frames from (depthai's ``"parent_frame":
# "oak_mount"``), read only in a file that launches such a driver.
_PARENT_FRAME = re.compile(
    r"""(?<![A-Za-z0-9_])parent_frame["']?[ \t]{0,3}(?::=|:|=)[ \t]{0,8}["']?""" + _VALUE
    + r"""|name\s{0,3}=\s{0,3}["']parent_frame["'][^<>]{0,120}?(?:value|default)\s{0,3}="""
    + r"""\s{0,3}["']""" + _VALUE,
)  # fmt: skip


def named_frames(workspace: Workspace, urdf: Urdf, profile: Profile) -> dict[str, str]:
    """Each link of ``urdf`` a file of the robot's packages gives a driver as its frame id, or
    names as a camera driver's (:func:`_device_frame`), with how and where first (``frame id
    in PATH``, ``camera name in PATH``, ``default camera name in PATH``; the path in the
    workspace)."""
    return _named(workspace, urdf, profile)[0]


def _named(
    workspace: Workspace, urdf: Urdf, profile: Profile
) -> tuple[dict[str, str], frozenset[str]]:
    """:func:`named_frames`, and the links a depth camera's driver publishes in: those a file
    that launches one and names no camera (a ``camera_name`` there may be another driver's)
    gives it as its ``parent_frame``, names by its ROS 1 ``camera`` argument, or else by the
    driver's default name."""
    naming = _Naming(urdf, profile)
    for shipped in workspace.files:
        naming.read(shipped.text, shown(shipped.path))
    naming.launched_drivers()
    return naming.found, frozenset(naming.depth)


class _Naming:
    """The frames the files read so far name, each with how and where first; the depth
    cameras among them; the camera names resolved to links (each once, at most
    :data:`_MAX_CAMERA_NAMES`)."""

    def __init__(self, urdf: Urdf, profile: Profile) -> None:
        self.urdf = urdf
        self.profile = profile
        self.found: dict[str, str] = {}
        self.depth: set[str] = set()
        self.cameras: dict[str, str | None] = {}
        self.tails: dict[str, list[str]] | None = None
        self.numbers: dict[tuple[str, str], list[str]] | None = None
        self.tops: dict[frozenset[str], dict[str, str | None]] = {}
        self.seen_numbered: set[tuple[str, str]] = set()
        # Where a driver that names no link of the description was launched, by what it reads.
        self.launches: dict[str, list[str]] = {"camera": [], "depth": [], "imu": []}

    def link(self, value: str) -> str | None:
        """The link a frame id names (:func:`_link`), else the one link the description writes
        under a namespace of its own (``rc_12345/front_lidar``) whose last ``/`` segment is the
        frame id's (``$(var rc)/front_lidar``); None when none is, or more than one."""
        found = _link(value, self.urdf)
        if found is not None:
            return found
        if self.tails is None:  # every link's last segment, once per description
            self.tails = {}
            for link in self.urdf.links:
                if "/" in link.name:
                    self.tails.setdefault(link.name.rsplit("/", 1)[-1], []).append(link.name)
        links = self.tails.get(value.rsplit("/", 1)[-1], [])
        return links[0] if len(links) == 1 else None

    def numbered(self, before: str, after: str = "") -> list[str]:
        """The links named ``before``, a number, then ``after`` (``US3_link``), when two or
        more are: one device's frame each, a driver stamping each device's readings with its
        index. The index of every link's numbers is made once per description."""
        if self.numbers is None:
            self.numbers = {}
            for link in self.urdf.links:
                for number in _NUMBER.finditer(link.name):
                    key = (link.name[: number.start()], link.name[number.end() :])
                    self.numbers.setdefault(key, []).append(link.name)
        if (before, after) in self.seen_numbered:
            return []  # noted once already: a stranger's file may repeat it a million times
        self.seen_numbered.add((before, after))
        links = self.numbers.get((before, after), [])
        return links if len(links) > 1 else []

    def read(self, text: str, path: str) -> None:
        """What one file names: frame ids, camera names, and the drivers it launches."""
        self.frame_ids(text, path)
        named = False
        for match in _DEVICE_NAME.finditer(text):
            named = True
            self.camera(_last(match), f"camera name in {path}")
        if not named:
            self.depth_cameras(text, path)
        if _CAMERA_LAUNCH.search(text):
            self.launches["camera"].append(path)
        if _IMU_LAUNCH.search(text):
            self.launches["imu"].append(path)

    def launched_drivers(self) -> None:
        """Once every file is read: a driver launched that names no link of the description
        names its one device of the driver's kind, unless a file names that device's frames
        already. A plain camera's driver makes the one camera a camera; else a depth camera's
        driver (whose default name was no link) an RGB-D camera, unless its name says another
        kind of camera (thermal, fisheye, a webcam)."""
        # The description's devices are looked for only when a driver was launched.
        imu = self.sole_device(_IMUS) if self.launches["imu"] else None
        if imu is not None and not self.named(imu, _IMUS):
            self.note(imu, f"IMU driver launched in {self.launches['imu'][0]}")
        if not (self.launches["camera"] or self.launches["depth"]):
            return
        camera = self.sole_device(_CAMERAS)
        if camera is None or self.named(camera, _CAMERAS):
            return
        if self.launches["camera"]:
            self.note(camera, f"camera driver launched in {self.launches['camera'][0]}")
        elif self.launches["depth"] and not _NOT_DEPTH.search(camera):
            self.note(camera, f"depth camera driver launched in {self.launches['depth'][0]}")
            self.depth.add(camera)

    def named(self, device: str, kinds: frozenset[str]) -> bool:
        """A file names ``device`` or one of its frames already (a link whose topmost link of
        ``kinds`` is the device)."""
        return any(self.top(link, kinds) == device for link in self.found)

    def frame_ids(self, text: str, path: str) -> None:
        """The frame ids one file gives: a device's own, a frame id no link has that numbered
        links begin with (``ultrasonic_link`` for ``ultrasonic_link_0`` ...), frame names made
        from a template (``"US%d_link"``), and lists of them."""
        for pattern in (_ASSIGNED, _PARAMETER):
            for match in pattern.finditer(text):
                value = _value(match)
                link = self.link(value)
                self.note(link, f"frame id in {path}")
                if link is None:
                    for each in self.numbered(f"{value}_") or self.numbered(value):
                        self.note(each, f"numbered frame id in {path}")
        for match in _TEMPLATE.finditer(text):
            for each in self.numbered(match[1], match[2]):
                self.note(each, f"frame name template in {path}")
        for match in _LISTED.finditer(text):
            for item in match.group(1).split(",")[:_MOST_LISTED]:
                value = item.strip().strip("\"'").lstrip("/")
                if value:
                    self.note(self.link(value), f"frame id in {path}")

    def depth_cameras(self, text: str, path: str) -> None:
        """The depth cameras a file that launches their driver names (and names no camera):
        its ``parent_frame``, its ROS 1 ``camera`` argument, else each driver's default."""
        drivers = {m[1] or m[2] or m[3] or m[4] for m in _DEPTH_LAUNCH.finditer(text)}
        if not drivers:
            return
        for match in _PARENT_FRAME.finditer(text):
            link = self.link(_value(match))
            self.note(link, f"parent frame in {path}")
            if link is not None:
                self.depth.add(link)
        given = [_last(match) for match in _CAMERA_ARGUMENT.finditer(text)]
        for name, how in [(name, "camera name") for name in given] or [
            (_DEPTH_DRIVERS[driver], "default camera name") for driver in sorted(drivers)
        ]:
            link = self.camera(name, f"{how} in {path}")
            if link is None and how == "default camera name":
                self.launches["depth"].append(path)
            if link is not None:
                self.depth.add(link)

    def camera(self, name: str, how: str) -> str | None:
        """The link a camera driver named ``name`` publishes in (resolved once), noted."""
        if name not in self.cameras and len(self.cameras) < _MAX_CAMERA_NAMES:
            self.cameras[name] = _device_frame(name, self.urdf, self.profile)
        link = self.cameras.get(name)
        self.note(link, how)
        return link

    def sole_device(self, kinds: frozenset[str]) -> str | None:
        """The description's one device of ``kinds``: the links the frame rules read as one
        of them, each taken to the topmost of the unbroken run of such links above it
        (:meth:`top`: a camera's body with its stream frames beneath it, a pan/tilt camera's
        links with it), are all one link; None when the description draws none or several (a
        driver that names no link of them says nothing of which)."""
        found: str | None = None
        for link in self.urdf.links:
            top = self.top(link.name, kinds)
            if top is not None and top != found:
                if found is not None:
                    return None
                found = top
        return found

    def top(self, link: str, kinds: frozenset[str]) -> str | None:
        """The topmost link of the unbroken run of links read as ``kinds`` from ``link`` up
        (``link`` itself when its parent reads as none; None when ``link`` reads as none).
        Each link is walked once per kinds (memoised: a link read as none is None)."""
        tops = self.tops.setdefault(kinds, {})
        path: list[str] = []
        current = link
        while current not in tops:
            if not self.reads_as(current, kinds):
                tops[current] = None
                break
            path.append(current)
            joint = self.urdf.parent_joint(current)
            if joint is None:
                break
            current = joint.parent
        above = tops.get(current)
        found = above if above is not None else (path[-1] if path else None)
        for each in path:
            tops[each] = found
        return tops[link]

    def reads_as(self, link: str, kinds: frozenset[str]) -> bool:
        rule = _rule(link, self.profile)
        return rule is not None and self.profile.frame_rules[rule].kind in kinds

    def note(self, link: str | None, how: str) -> None:
        if link is not None and link not in self.found:
            self.found[link] = how


def _value(match: re.Match[str]) -> str:
    """The value a match gives (the group of the form that matched)."""
    return next(g for g in match.groups() if g is not None)


def _last(match: re.Match[str]) -> str:
    """The name a match gives: its value's last ``/`` segment (a namespace the launch adds)."""
    return _value(match).rsplit("/", 1)[-1]


def _link(value: str, urdf: Urdf) -> str | None:
    """The link a frame id names: the value, else its last ``/`` segment (a namespace the
    driver adds); None when the description has neither."""
    for link in (value, value.rsplit("/", 1)[-1]):
        if urdf.has_link(link):
            return link
    return None


def _device_frame(name: str, urdf: Urdf, profile: Profile) -> str | None:
    """The link a camera driver named ``name`` publishes in: ``name`` itself, ``name_link``,
    else the first link whose name begins ``name_`` that the frame rules read as a camera (its
    stream frames); None when none is."""
    for exact in (name, f"{name}_link"):
        if urdf.has_link(exact):
            return exact
    for link in urdf.links:
        if link.name.startswith(f"{name}_"):
            rule = _rule(link.name, profile)
            if rule is not None and profile.frame_rules[rule].kind in _CAMERAS:
                return link.name
    return None


def _rule(link: str, profile: Profile) -> int | None:
    """The index of the first frame rule that reads ``link``, or None."""
    rules = profile.frame_rules
    return next((i for i, rule in enumerate(rules) if rule.accepts(None, link)), None)


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
    known: dict[str, int | None] = {}

    def kind_of(link: str) -> int | None:
        if link not in known:
            known[link] = _rule(link, profile)
        return known[link]

    def family(rule: int) -> str:
        kind = rules[rule].kind
        return "camera" if kind in _CAMERAS else kind

    def body(link: str, rule: int) -> str:
        """The device's body: up through fixed joints while the parent reads as a device of
        the same family (a camera's optical frame under its camera link)."""
        for _ in range(_DEVICE_DEPTH):
            joint = urdf.parent_joint(link)
            above = None if joint is None or joint.movable else kind_of(joint.parent)
            if joint is None or above is None or family(above) != family(rule):
                break
            link = joint.parent
        return link

    def streams(device: str, rule: int) -> list[int]:
        """The camera rules of the frames fixed beneath a camera's body, a few levels down
        (each link is walked from at most that many bodies above it); none for another kind."""
        found: list[int] = []
        level = [device] if family(rule) == "camera" else []
        for _ in range(_DEVICE_DEPTH):
            level = [j.child for link in level for j in urdf.children(link) if not j.movable]
            found += [r for r in map(kind_of, level) if r is not None and family(r) == "camera"]
        return found

    def body_of(link: str) -> str:
        rule = kind_of(link)
        return link if rule is None else body(link, rule)

    bodies_declared = {body_of(d.link) for d in declared if d.link is not None}
    devices: dict[str, list[tuple[int, str, str]]] = {}  # body -> (rule, frame, how)
    frame_ids, depth = _named(workspace, urdf, profile)
    named_top = _NamedTop(urdf, kind_of, family, frame_ids)
    for link, how in frame_ids.items():
        rule = kind_of(link)
        if rule is not None:
            devices.setdefault(body(named_top(link, rule), rule), []).append((rule, link, how))
    poses: Poses | None = None

    def place(link: str) -> Vector:
        """Where ``link`` is in the root's frame (the poses computed once, when needed)."""
        nonlocal poses
        if poses is None:
            poses = Poses(urdf)
        return poses.place(link)

    found = []
    for body_link, named in devices.items():
        if body_link in bodies_declared:
            continue  # a device the description declares a sensor on
        for device, frames in _apart(body_link, named, rules, place):
            rule, link, how = min(frames)
            rule = min((rule, *streams(device, rule)))
            kind = rules[rule].kind
            if kind == "camera" and any(frame in depth for _, frame, _ in frames):
                kind = "depth_camera"  # a depth camera's driver publishes in it
            if kind in kinds_declared or device in bodies_declared:
                continue
            found.append(Detection(kind, f"{shown(link)} ({how})", SOURCE, device))
    return tuple(found)


class _NamedTop:
    """The topmost of the named frames in the run of fixed links of one device family from a
    named frame up (:meth:`__call__`)."""

    def __init__(
        self,
        urdf: Urdf,
        kind_of: Callable[[str], int | None],
        family: Callable[[int], str],
        named: Collection[str],
    ) -> None:
        self.urdf = urdf
        self.kind_of = kind_of
        self.family = family
        self.named = named
        self.tops: dict[tuple[str, str], str | None] = {}

    def __call__(self, link: str, rule: int) -> str:
        """The topmost of the named frames in the run of fixed links of ``rule``'s family from
        ``link`` up, ``link`` included: a stream's frame above its optical frame, both named,
        are one device's however deep they hang under its mount (a wrist camera's depth frame
        and its optical frame, three and four joints below the gripper's camera link). Two
        cameras' frames under one mount named like a camera stay apart: neither is above the
        other. Each link is climbed from once per family (memoised)."""
        kin = self.family(rule)
        path: list[str] = []
        current = link
        while (current, kin) not in self.tops:
            path.append(current)
            parent = self._alike_parent(current, kin)
            if parent is None or len(path) > len(self.urdf.links):
                break
            current = parent
        top = self.tops.get((current, kin))
        for each in reversed(path):
            top = top if top is not None else (each if each in self.named else None)
            self.tops[(each, kin)] = top
        return self.tops[(link, kin)] or link

    def _alike_parent(self, link: str, kin: str) -> str | None:
        """``link``'s parent when a fixed joint holds it and it reads as a device of ``kin``."""
        joint = self.urdf.parent_joint(link)
        above = None if joint is None or joint.movable else self.kind_of(joint.parent)
        return None if joint is None or above is None or self.family(above) != kin else joint.parent


def _apart(
    body: str,
    frames: list[tuple[int, str, str]],
    rules: tuple[SensorRule, ...],
    place: Callable[[str], Vector],
) -> list[tuple[str, list[tuple[int, str, str]]]]:
    """The devices the named ``frames`` under one ``body`` are: one, for a camera's streams
    (its colour and depth frames, wherever they sit); else one per place (a front and a back
    laser a driver each publishes in, hung from one ``base_scan`` link), each its own first
    frame's device: a frame, in rule-then-name order, joins the first place whose first frame
    is within :data:`STREAM_REACH` of it. More places than :data:`_MOST_PLACES` are one device,
    as before (each frame is compared with that many places at most)."""
    if len(frames) < 2 or any(rules[rule].kind in _CAMERAS for rule, _, _ in frames):
        return [(body, frames)]
    groups: list[tuple[Vector, list[tuple[int, str, str]]]] = []
    for frame in sorted(frames):
        at = place(frame[1])
        near = next((g for first, g in groups if distance(at, first) <= STREAM_REACH), None)
        if near is not None:
            near.append(frame)
        elif len(groups) == _MOST_PLACES:
            return [(body, frames)]
        else:
            groups.append((at, [frame]))
    if len(groups) == 1:
        return [(body, frames)]
    return [(group[0][1], group) for _, group in groups]
