"""Reading a URDF into an immutable robot description, checked as a tree.

:func:`parse_urdf` takes URDF *text* (from a file, a compiled xacro, or ``/robot_description``
on a ROS master) and returns a :class:`Urdf`: links, joints, Gazebo sensors and model plugins,
and the joints that have a transmission or a ``ros2_control`` interface. The whole document is
validated and every problem is reported at once, each with the file, line and element: a joint
whose parent or child link does not exist, an unknown joint type, duplicate names, a link with
two parents, cycles, several root links, an empty robot.

A :class:`Urdf` also answers the tree questions the classifier asks (root, children, subtree).

Not here: what the body is (:mod:`solver.identify.body`), what the sensors are
(:mod:`solver.identify.sensors`), xacro (:mod:`solver.identify.xacro.compiler`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, replace
from functools import cached_property
from typing import TYPE_CHECKING

from solver.errors import Fault, InputError, Location
from solver.identify.readers.safexml import line_of, parse_xml
from solver.untrusted import shown

if TYPE_CHECKING:
    from lxml import etree

__all__ = [
    "JOINT_TYPES",
    "MAX_PARTS",
    "Box",
    "Cylinder",
    "Joint",
    "Link",
    "ModelInclude",
    "PluginTag",
    "SensorTag",
    "Urdf",
    "parse_urdf",
]

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
# The most links + joints one description may have: reading is linear, so this bounds the time
# and memory one description (a robot_description is whatever a robot publishes) may cost.
# 250,000 is some 30 times the largest real robot known and still reads in seconds.
MAX_PARTS = 250_000
# Plugin parameters kept for the classifiers: short text values (joint names, topics, frames),
# from the plugin's leaf elements at any depth (a thruster list, a fin's joint), at most this many.
_MAX_PARAM_TEXT = 200
_MAX_PARAMS = 400
# A Gazebo model include's URI (``model://gps``).
_MODEL_URI = "model://"
# A revolute joint whose range spans this many radians (16 turns) has no stop: it is endless.
_ENDLESS_RANGE = 100.0
# A range narrower than this (a tenth of a millimetre, a tenth of a milliradian) leaves a joint
# no room to move: no joint of a robot's description moves so little, so limits this close are
# a lock written with a rounding (an SDF converter's +-1e-16 on a sensor's frame) or a gap left
# on purpose (a force sensor's revolute joint of 0..1e-5 rad, for a simulator to measure the
# wrench across it), as equal limits are.
_NO_ROOM = 1e-4
# The most a link may weigh (kg) and be a simulator's mass point, not a part (:func:`_mass_points`):
# a few grams, what a simulator is given for a link it must keep.
_MASS_POINT = 0.005
# How deep below a joint its mass points are looked through (:func:`_mass_points`): bounds a
# stranger's chain; deeper is read as a part.
_MASS_POINT_DEPTH = 64
# Joints that move without limits: beside them, equal limits are a lock, not placeholders.
_UNLIMITED = frozenset({"continuous", "floating", "planar"})
# Sea water's density (kg/m3): what a hydrodynamics plugin assumes when it names none.
_SEA_WATER = 1028.0
# The fewest blank joints (limits 0..0, effort 0) in a row that are an exporter's limbs, not
# locked mounts (:func:`_blank_chains`).
_BLANK_CHAIN = 3
# Distinct element names kept from the whole document (hull and buoyancy hints live there).
_MAX_TAGS = 2000
# Warnings of one kind listed per description; the rest are counted.
_MAX_WARNINGS = 20
# Loop-closing joints read from <gazebo> blocks (a walker has a few; bounds a stranger's).
MAX_CLOSURES = 256


@dataclass(frozen=True, slots=True)
class Link:
    name: str
    line: int | None = None
    # Its <buoyancy><compensation> (freefloating_gazebo, the usv plugins), or the water a
    # hydrodynamics plugin says it displaces over its mass (the UUV simulator's <volume>):
    # buoyancy force over weight; above 1 the link floats. None when nothing gives it (or not a
    # finite number).
    buoyancy: float | None = None
    # Its first <visual> when that is a cylinder, else its first <collision> when that is one:
    # what its shape says (a propeller's disc, a wheel); None for meshes, boxes, or neither.
    cylinder: Cylinder | None = None
    # False for a link a joint names that no <link> declares, read as an implicit link: the
    # link of another description this one is made to hang from (a vehicle's base_link).
    declared: bool = True
    # A declared <link/> with nothing in it: no visual, collision or inertial (a frame).
    empty: bool = False
    # It has a <visual> or a <collision>: a part one can see or touch, not a frame or a
    # simulator's mass point.
    drawn: bool = False
    # Its <inertial>'s mass and where its <origin xyz> puts the mass centre on the link; None
    # when it writes no inertial, no positive mass or no readable place (an origin left out is
    # a macro's default, not a measurement). A wheel's mass centre lies on its axle.
    mass: float | None = None
    mass_centre: tuple[float, float, float] | None = None
    # Its first <inertial>'s <inertia>, when it writes all six terms readably and positive
    # moments; None otherwise.
    inertia: Inertia | None = None
    # Its first <visual> when that is a box, else its first <collision> when that is one: a
    # plate's shape (a wing drawn as a board); None for meshes, cylinders, or neither.
    box: Box | None = None


@dataclass(frozen=True, slots=True)
class Inertia:
    """A link's inertia about its mass centre as its ``<inertial>`` writes it: the moments and
    products (``ixx``, ``ixy``, ``ixz``, ``iyy``, ``iyz``, ``izz``) in a frame turned by the
    inertial's ``<origin rpy>`` on the link."""

    terms: tuple[float, float, float, float, float, float]
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)


@dataclass(frozen=True, slots=True)
class Box:
    """A link's ``<visual>`` box: its size along its own x, y and z, and where it sits and how
    it is turned on the link."""

    size: tuple[float, float, float]
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)


@dataclass(frozen=True, slots=True)
class Cylinder:
    """A link's ``<visual>`` cylinder: its size, and where it sits and how it is turned on the
    link (its axis is the turned z axis)."""

    radius: float
    length: float
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)  # where it sits on the link


@dataclass(frozen=True, slots=True)
class Joint:
    """One joint; ``movable`` is false for fixed joints and zero-range revolute/prismatic ones."""

    name: str
    type: str
    parent: str
    child: str
    line: int | None = None
    mimic: str | None = None
    lower: float | None = None
    upper: float | None = None
    axis: tuple[float, float, float] = (1.0, 0.0, 0.0)  # URDF's default axis
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)  # where it sits on its parent link
    # How its frame is turned on its parent link (roll, pitch, yaw), so axes and places can be
    # read in one frame (solver.identify.pose).
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    # A mimic joint's ratio to the joint it follows (<mimic multiplier>): a jaw mirrors its
    # driver (1 or -1), a gear turns by its ratio.
    multiplier: float = 1.0
    # Whether the description writes an <axis> (else ``axis`` is URDF's default, x): what a
    # joint's name says is weighed against a written axis only.
    axis_written: bool = True
    # Whether equal limits are placeholders, not a lock: it is one of a pair <mimic> couples
    # (it follows another joint that is no fixed joint, or such a joint follows it), or every
    # joint with limits in the file has equal ones (:func:`_placeholders`).
    unlocked: bool = False
    # Its <limit effort>: what its actuator may exert (None when not written).
    effort: float | None = None
    # It moves nothing and exerts nothing: its limit's effort is zero, its child an empty leaf
    # (a frame with nothing in it, nothing hung from it), and nothing couples or commands it. A
    # model's bookkeeping, not a joint of the body (the Pisa/IIT LWR's joint-stiffness
    # pseudo-joints, one beside each joint). Or a limited joint that moves mass points only:
    # nothing below it is drawn or senses, and each link there weighs a few grams at most, in a
    # file that draws its body (a simulator's helper chain at an arm's end). :func:`_phantoms`,
    # :func:`_mass_points`.
    phantom: bool = False

    @property
    def movable(self) -> bool:
        if self.type == "fixed" or self.phantom:
            return False
        # RotorS and others mount sensors on revolute joints with lower == upper: fixed in effect,
        # and so are limits closer than a tenth of a millimetre or milliradian (:attr:`closed`).
        # Not an unlocked joint: nobody couples a joint that cannot move, nor locks every joint
        # of a robot, so such equal limits are placeholders (a kinematic simulator's fingers, a
        # CAD exporter's limits all zero).
        return not (self.type in ("revolute", "prismatic") and self.closed and not self.unlocked)

    @property
    def closed(self) -> bool:
        """Its limits leave it no room: equal, or closer than :data:`_NO_ROOM` (whether that
        locks it is :attr:`movable`'s question)."""
        return (
            self.lower is not None
            and self.upper is not None
            # Equal infinities are closed too (their difference is no number).
            and (self.lower == self.upper or abs(self.upper - self.lower) < _NO_ROOM)
        )

    def turns(self, at_least: float) -> bool:
        """It turns through ``at_least`` radians: continuous, or revolute with that range."""
        if self.type == "continuous":
            return True
        return (
            self.type == "revolute"
            and self.lower is not None
            and self.upper is not None
            and self.upper - self.lower >= at_least
        )

    @property
    def endless(self) -> bool:
        """It turns for ever: continuous, or revolute with a range no real stop has (PX4's
        rotors are revolute joints of +-1e16 rad)."""
        return self.turns(_ENDLESS_RANGE)

    @property
    def actuated(self) -> bool:
        """Movable and driven on its own (a mimic joint follows another joint)."""
        return self.movable and self.mimic is None


@dataclass(frozen=True, slots=True)
class PluginTag:
    """A Gazebo ``<plugin>``: inside a ``<sensor>``, or a model plugin under ``<gazebo>``."""

    name: str
    filename: str
    reference: str | None = None
    line: int | None = None
    # (tag, text) of the plugin's simple child elements: topics, frames, joint names.
    params: tuple[tuple[str, str], ...] = ()
    # Names of the elements inside the plugin that hold elements of their own (a
    # ``<thruster>`` entry of a thruster list), each once, in document order.
    groups: tuple[str, ...] = ()

    def param(self, *tags: str) -> str | None:
        """The text of the first of ``tags`` the plugin sets (case-insensitive)."""
        wanted = {t.lower() for t in tags}
        return next((text for tag, text in self.params if tag.lower() in wanted), None)

    def numbers(self, *tags: str) -> tuple[float, ...]:
        """The finite numbers the plugin sets in any of ``tags`` (case-insensitive), in order;
        a text that is no number (``${rho}``, an unexpanded argument) is left out."""
        wanted = {t.lower() for t in tags}
        found = (_float(text) for tag, text in self.params if tag.lower() in wanted)
        return tuple(value for value in found if value is not None)

    @property
    def text(self) -> str:
        """Everything that names this plugin, for pattern matching."""
        return " ".join([self.name, self.filename, *(text for _, text in self.params)])


@dataclass(frozen=True, slots=True)
class ModelInclude:
    """A Gazebo model a ``<gazebo><include>`` adds (``<uri>model://gps</uri>``): ``model`` is
    the name in its URI, ``link`` the link a ``<joint>`` beside it fixes it to (if any)."""

    model: str
    name: str
    link: str | None = None
    line: int | None = None


@dataclass(frozen=True, slots=True)
class SensorTag:
    """A URDF ``<sensor>`` or Gazebo ``<sensor type=...>`` element."""

    name: str
    type: str
    link: str | None
    line: int | None = None
    # "gazebo" (<gazebo><sensor type>), "urdf" (top-level <sensor>) or "ros2_control" (a
    # hardware interface's <sensor>, its kind told by what it reads).
    origin: str = "gazebo"
    plugins: tuple[PluginTag, ...] = ()
    horizontal_samples: int | None = None
    vertical_samples: int | None = None
    horizontal_fov: float | None = None
    camera_count: int = 0
    # A ray sensor's horizontal sweep (max_angle - min_angle, radians), its vertical one, and
    # farthest range (metres): a one-ray range finder sweeps nothing and reaches a metre or
    # two; a lidar sweeps.
    sweep: float | None = None
    vertical_sweep: float | None = None
    max_range: float | None = None
    # The topic a Gazebo ``<sensor>`` publishes on, its own ``<topic>`` element ("" when none;
    # cut as a plugin setting is).
    topic: str = ""

    @property
    def text(self) -> str:
        """Everything that names this sensor, for pattern matching."""
        return " ".join([self.name, self.link or "", *(p.text for p in self.plugins)])

    @property
    def device_text(self) -> str:
        """What names the device itself: its name, link and plugins, and the wave a range
        plugin says it casts (ROS 1's ``<radiation>ultrasound</radiation>``, ROS 2's
        ``<radiation_type>``, unless its ``<output_type>`` is a scan or a point cloud: a ray
        sensor's plugin that sweeps casts no wave it names, whatever it was copied with),
        not the topics it feeds (a plain camera whose plugin publishes ``depth/...`` topics is
        still a camera)."""
        plugins = (
            f"{p.name} {p.filename} {p.param('radiation') or ''} {_ranged_wave(p)}"
            for p in self.plugins
        )
        return " ".join([self.name, self.link or "", *plugins])


# What a ray sensor's plugin outputs when it sweeps (its ``<output_type>``): a scan or a point
# cloud.
SCAN_OUTPUT = re.compile(r"laserscan|pointcloud", re.IGNORECASE)


def _ranged_wave(plugin: PluginTag) -> str:
    """The wave a ROS 2 ray sensor's plugin names (``<radiation_type>``), unless it says it
    outputs a scan or a point cloud (``sensor_msgs/LaserScan``, ``PointCloud2``): a wave is a
    range's, and a plugin copied from a range finder's keeps it when made a lidar."""
    if SCAN_OUTPUT.search(plugin.param("output_type") or ""):
        return ""
    return plugin.param("radiation_type") or ""


@dataclass(frozen=True)
class Urdf:
    """A robot description: links, joints, sensors, plugins, checked to form one tree."""

    name: str
    file: str
    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    sensors: tuple[SensorTag, ...] = ()
    plugins: tuple[PluginTag, ...] = ()
    # Joints named by a <transmission>, a <ros2_control> block or a simulator's joint
    # controller plugin (<joint_name>): driven by a controller.
    controlled_joints: frozenset[str] = frozenset()
    root: str = ""
    # Local flaws read past (parse_urdf(strict=False)), each located.
    warnings: tuple[Fault, ...] = ()
    # (joint, command interfaces) from <ros2_control> (<command_interface name="velocity"/>),
    # <transmission> (<hardwareInterface>...VelocityJointInterface) and a simulator's joint
    # controller plugin: position, velocity, effort.
    command_interfaces: tuple[tuple[str, tuple[str, ...]], ...] = ()
    # The names of the document's elements outside sensors and plugins (lower case): a hull's
    # <metacentric_width>, a link's <buoyancy> with <windVelocity> say what the robot floats in.
    tags: frozenset[str] = frozenset()
    # Gazebo models the description includes (a GPS model, a camera model), in document order.
    models: tuple[ModelInclude, ...] = ()
    # A <gazebo> block turns gravity off (<turnGravityOff>true, <gravity>false): a body the
    # simulator holds in the air (a kinematic drone) or in water.
    gravity_off: bool = False
    # Loops a URDF cannot write, closed by SDF joints in <gazebo> blocks (<joint><parent>
    # <child>): (parent link, child link), both links of the description.
    closures: tuple[tuple[str, str], ...] = ()
    # Loops an exporter cut, its two ends named as one loop's (:func:`_cut_loops`): (A, B).
    cut_loops: tuple[tuple[str, str], ...] = ()

    @cached_property
    def _children(self) -> dict[str, tuple[Joint, ...]]:
        found: dict[str, list[Joint]] = {link.name: [] for link in self.links}
        for joint in self.joints:
            found[joint.parent].append(joint)
        return {name: tuple(joints) for name, joints in found.items()}

    @cached_property
    def _parent_joint(self) -> dict[str, Joint]:
        return {joint.child: joint for joint in self.joints}

    @cached_property
    def _joint_by_name(self) -> dict[str, Joint]:
        return {joint.name: joint for joint in self.joints}

    def children(self, link: str) -> tuple[Joint, ...]:
        """The joints whose parent is ``link``, in document order."""
        return self._children.get(link, ())

    def parent_joint(self, link: str) -> Joint | None:
        return self._parent_joint.get(link)

    def joint(self, name: str) -> Joint | None:
        return self._joint_by_name.get(name)

    def interfaces(self, joint: str) -> tuple[str, ...]:
        """The command interfaces a controller declares for ``joint`` (may be empty)."""
        return self._interfaces.get(joint, ())

    @cached_property
    def _interfaces(self) -> dict[str, tuple[str, ...]]:
        return dict(self.command_interfaces)

    def has_link(self, name: str) -> bool:
        return name in self._children

    def link(self, name: str) -> Link | None:
        return self._link_by_name.get(name)

    @cached_property
    def _link_by_name(self) -> dict[str, Link]:
        return {link.name: link for link in self.links}

    def fixed_below(self, link: str) -> Iterator[str]:
        """The links fixed below ``link`` (through joints that cannot move): the rest of the
        rigid part ``link`` begins, depth first."""
        stack = [link]
        while stack:
            for joint in self.children(stack.pop()):
                if not joint.movable:
                    yield joint.child
                    stack.append(joint.child)

    def subtree_joints(self, link: str) -> Iterator[Joint]:
        """Every joint below ``link``, depth first in document order."""
        stack = list(reversed(self.children(link)))
        while stack:
            joint = stack.pop()
            yield joint
            stack.extend(reversed(self.children(joint.child)))


def parse_urdf(text: str | bytes, file: str = "<string>", *, strict: bool = True) -> Urdf:
    """Parse URDF text into a :class:`Urdf`.

    ``strict`` (the default, a validator's reading): every problem is an error, all reported
    at once in one :class:`InputError`. ``strict=False`` reads the way the ROS tools do with
    real files: a local flaw (a joint naming a missing link, a duplicate link, a link with two
    parents, a joint type outside the spec, several roots, an XML declaration out of place)
    becomes a located warning in :attr:`Urdf.warnings` and the rest is read. Only a document
    that cannot be read at all is an error then: not XML, hostile XML, not a ``<robot>``, no
    links, no root link, or more than :data:`MAX_PARTS` links and joints.
    """
    warnings: list[Fault] | None = None if strict else []
    root = parse_xml(text, file, warnings=warnings)
    urdf = _Builder(file).build(root)
    if strict and urdf.warnings:
        raise InputError(urdf.warnings)
    return replace(urdf, warnings=(*(warnings or ()), *urdf.warnings))


class _Builder:
    def __init__(self, file: str) -> None:
        self.file = file
        self.faults: list[Fault] = []

    def fault(
        self, element: etree._Element | int | None, path: str, message: str, code: str = "urdf"
    ) -> None:
        line = element if isinstance(element, int) or element is None else line_of(element)
        self.faults.append(Fault(Location(self.file, line, None, path), message, code))

    def warnings(self) -> tuple[Fault, ...]:
        """The faults, at most :data:`_MAX_WARNINGS` of a kind (a hostile file has millions)."""
        kept: list[Fault] = []
        seen: dict[str, int] = {}
        for fault in self.faults:
            seen[fault.code] = seen.get(fault.code, 0) + 1
            if seen[fault.code] <= _MAX_WARNINGS:
                kept.append(fault)
        for code, number in seen.items():
            if number > _MAX_WARNINGS:
                kept.append(
                    Fault(
                        Location(self.file),
                        f"{number - _MAX_WARNINGS} more problem(s) of this kind not listed",
                        code,
                    )
                )
        return tuple(kept)

    def _models(self, root: etree._Element) -> tuple[ModelInclude, ...]:
        """The ``<gazebo><include>`` models (at most ``_MAX_PARAMS``; a located warning at the
        first one past it): the model name of a ``model://NAME`` URI, the include's ``<name>``
        (the model's, when empty), and the ``<parent>`` of a ``<joint>`` in the same ``<gazebo>``
        whose ``<child>`` is one of that model's links (``NAME::link``)."""
        found: list[ModelInclude] = []
        for gazebo in root.findall("gazebo"):
            parents = {
                (joint.findtext("child") or "").split("::")[0].strip(): joint.findtext("parent")
                for joint in gazebo.findall("joint")
            }
            for include in gazebo.findall("include"):
                uri = (include.findtext("uri") or "").strip()
                if not uri.startswith(_MODEL_URI):
                    continue
                if len(found) >= _MAX_PARAMS:
                    message = f"more than {_MAX_PARAMS} model includes: the rest are not read"
                    self.fault(include, "gazebo/include", message, "too-large")
                    return tuple(found)
                model = uri[len(_MODEL_URI) :].strip("/").split("/")[0][:_MAX_PARAM_TEXT]
                name = (include.findtext("name") or "").strip()[:_MAX_PARAM_TEXT] or model
                parent = parents.get(name)
                link = parent.strip() if parent else None
                found.append(ModelInclude(model, name, link, line_of(include)))
        return tuple(found)

    def build(self, root: etree._Element) -> Urdf:
        if root.tag != "robot":
            raise InputError.at(
                self.file,
                f"root element is <{root.tag}>, expected <robot> (is this a URDF?)",
                line=line_of(root),
                path=str(root.tag),
                code="urdf",
            )
        name = (root.get("name") or "").strip()
        link_elements = root.findall("link")
        joint_elements = root.findall("joint")
        if len(link_elements) + len(joint_elements) > MAX_PARTS:
            beyond = (link_elements + joint_elements)[MAX_PARTS]
            raise InputError.at(
                self.file,
                f"{len(link_elements)} links and "
                f"{len(joint_elements)} joints: more than "
                f"{MAX_PARTS} in all is refused (a cap on what one "
                "description may cost)",
                line=line_of(beyond),
                path=str(beyond.tag),
                code="too-large",
            )
        if not link_elements:
            raise InputError.at(
                self.file,
                f"robot {shown(name, quoted=True)} has no links: an empty robot cannot be "
                f"identified",
                line=line_of(root),
                path="robot",
                code="urdf-empty",
            )
        links = self._links(link_elements, _displacements(root))
        plugins = tuple(
            _plugin(p, g.get("reference"))
            for g in root.findall("gazebo")
            for p in g
            if p.tag == "plugin" or _legacy(p, "controller")
        )
        simulated = _plugin_commands(plugins)
        commands = _merged_commands(_command_interfaces(root), simulated)
        commanded = {name for name, _ in commands}
        joints = self._joints(joint_elements, links, commanded)
        tree, top = self._tree(root, links, joints)
        sensors = self._sensors(root, {j.name: j.child for j in tree})
        tree = _without_mass_points(tree, links, {s.link for s in sensors if s.link}, commanded)
        controlled = frozenset(self._controlled(root)) | {name for name, _ in simulated}
        self.faults += _uncompiled_xacro(root, self.file)  # read as URDF, never compiled: say so
        models = self._models(root)
        return Urdf(
            name or "robot",
            self.file,
            tuple(links.values()),
            tree,
            sensors,
            plugins,
            controlled,
            top,
            self.warnings(),
            commands,
            _tags(root),
            models,
            _gravity_off(root),
            _closures(root, links),
            _cut_loops(links),
        )

    def _links(
        self, elements: list[etree._Element], displaced: dict[str, float | None]
    ) -> dict[str, Link]:
        """The links; ``displaced``: the mass of water each displaces, where a plugin says
        (:func:`_displacements`; None: as much as it weighs), for those whose file gives no
        buoyancy of its own."""
        found: dict[str, Link] = {}
        for element in elements:
            name = (element.get("name") or "").strip()
            if not name:
                self.fault(element, "link", "a <link> without a name (ignored)")
            elif name in found:
                self.fault(
                    element,
                    f"link[{name}]",
                    f"duplicate link {shown(name, quoted=True)} (first at line {found[name].line})",
                )
            else:
                mass = _mass(element)
                buoyancy = _compensation(element)
                if buoyancy is None and mass is not None and name in displaced:
                    water = displaced[name]
                    buoyancy = 1.0 if water is None else water / mass
                found[name] = Link(
                    name,
                    line_of(element),
                    buoyancy,
                    _cylinder(element),
                    empty=not any(isinstance(part.tag, str) for part in element),
                    drawn=any(part.tag in ("visual", "collision") for part in element),
                    mass=mass,
                    mass_centre=_mass_centre(element),
                    inertia=_inertia(element),
                    box=_box(element),
                )
        return found

    def _joints(
        self, elements: list[etree._Element], links: dict[str, Link], commanded: set[str]
    ) -> list[Joint]:
        """The joints, those whose equal limits are placeholders unlocked: coupled by
        ``<mimic>``, all equal (:func:`_placeholders`), or ``commanded`` by a controller (a
        joint a controller moves is not fixed: a CAD exporter wrote every slide 0..0); the
        phantoms marked (:func:`_phantoms`; mass points once the sensors are known,
        :func:`_without_mass_points`)."""
        found: dict[str, Joint] = {}
        for element in elements:
            joint = self._joint(element, links)
            if joint is None:
                continue
            if joint.name in found:
                self.fault(
                    element,
                    f"joint[{joint.name}]",
                    f"duplicate joint {shown(joint.name, quoted=True)} "
                    f"(first at line "
                    f"{found[joint.name].line}; "
                    "ignored)",
                )
                continue
            found[joint.name] = joint
        coupled = _coupled(found)
        unlocked = (
            coupled | _placeholders(found) | _blank_chains(found) | (commanded & found.keys())
        )
        phantoms = _phantoms(found, links) - coupled - commanded
        changed = unlocked | phantoms
        return [
            replace(joint, unlocked=name in unlocked, phantom=name in phantoms)
            if name in changed
            else joint
            for name, joint in found.items()
        ]

    def _joint(self, element: etree._Element, links: dict[str, Link]) -> Joint | None:
        line = line_of(element)
        name = (element.get("name") or "").strip()
        path = f"joint[{name}]" if name else "joint"
        if not name:
            self.fault(element, path, "a <joint> without a name")
            name = f"<joint at line {line}>"
        kind = (element.get("type") or "").strip()
        if kind not in JOINT_TYPES:
            if kind:
                self.fault(
                    element,
                    f"{path}.type",
                    f"unknown joint type {shown(kind, quoted=True)}; URDF joint types are "
                    f"{', '.join(JOINT_TYPES)}",
                    code="urdf-joint-type",
                )
            else:
                self.fault(
                    element,
                    f"{path}.type",
                    f"missing joint type; URDF joint types are {', '.join(JOINT_TYPES)}",
                    code="urdf-joint-type",
                )
                kind = "fixed"
        # One pass over the joint's children instead of a find() per tag (big descriptions).
        parts: dict[str, etree._Element] = {}
        for child in element:
            if isinstance(child.tag, str):
                parts.setdefault(child.tag, child)
        ends: dict[str, str] = {}
        for end in ("parent", "child"):
            tag = parts.get(end)
            link = (tag.get("link") or "").strip() if tag is not None else ""
            if tag is None or not link:
                self.fault(
                    element if tag is None else tag,
                    f"{path}.{end}",
                    f"joint {shown(name, quoted=True)} has no <{end} link=...> (joint ignored)",
                )
                return None
            if link not in links:
                self.fault(
                    tag,
                    f"{path}.{end}",
                    f"joint {shown(name, quoted=True)} names {end} link "
                    f"{shown(link, quoted=True)}, which does not exist",
                    code="urdf-missing-link",
                )
                # Read as an implicit link: an attachment described alone still has a body.
                links[link] = Link(link, line_of(tag), declared=False)
            ends[end] = link
        if ends["parent"] == ends["child"]:
            self.fault(
                element,
                path,
                f"joint {shown(name, quoted=True)} connects link "
                f"{shown(ends['parent'], quoted=True)} to "
                "itself (a cycle; joint ignored)",
                code="urdf-cycle",
            )
            return None
        limit = parts.get("limit")
        mimic = parts.get("mimic")
        return Joint(
            name,
            kind,
            ends["parent"],
            ends["child"],
            line,
            None if mimic is None else (mimic.get("joint") or "").strip() or None,
            self._number(limit, "lower", path),
            self._number(limit, "upper", path),
            _vector(parts.get("axis"), (1.0, 0.0, 0.0)),
            _vector(parts.get("origin"), (0.0, 0.0, 0.0)),
            _vector(parts.get("origin"), (0.0, 0.0, 0.0), "rpy"),
            self._multiplier(mimic),
            parts.get("axis") is not None,
            effort=self._number(limit, "effort", path),
        )

    @staticmethod
    def _multiplier(mimic: etree._Element | None) -> float:
        value = None if mimic is None else _float(mimic.get("multiplier"))
        return 1.0 if value is None else value

    def _number(self, element: etree._Element | None, attribute: str, path: str) -> float | None:
        if element is None or element.get(attribute) is None:
            return None
        text = element.get(attribute, "")
        value = _float(text)
        if value is None:
            self.fault(
                element,
                f"{path}.limit.{attribute}",
                f"limit {attribute} is not a finite number: {shown(text[:40], quoted=True)}",
            )
        return value

    def _tree(
        self, root: etree._Element, links: dict[str, Link], joints: list[Joint]
    ) -> tuple[tuple[Joint, ...], str]:
        """Keep the joints that form a tree; the root link. Linear in links + joints."""
        parents: dict[str, Joint] = {}
        kept: list[Joint] = []
        for joint in joints:
            first = parents.get(joint.child)
            if first is not None:
                self.fault(
                    joint.line,
                    f"joint[{joint.name}].child",
                    f"link {shown(joint.child, quoted=True)} has two parent joints: "
                    f"{shown(first.name, quoted=True)} "
                    f"(line {first.line}) and {shown(joint.name, quoted=True)}; a URDF is a tree "
                    f"({shown(joint.name, quoted=True)} ignored)",
                    code="urdf-cycle",
                )
                continue
            parents[joint.child] = joint
            kept.append(joint)
        below: dict[str, list[str]] = {}
        for joint in kept:
            below.setdefault(joint.parent, []).append(joint.child)
        roots = [link for link in links.values() if link.name not in parents]
        if not roots:
            raise InputError.at(
                self.file,
                "every link has a parent joint: the joints form a cycle, there is no root link",
                line=line_of(root),
                path="robot",
                code="urdf-cycle",
            )
        sizes = {link.name: _reach(link.name, below) for link in roots}
        top = max(roots, key=lambda link: len(sizes[link.name]))
        reached = set().union(*sizes.values())
        cyclic = [link for link in links.values() if link.name not in reached]
        if cyclic:
            names = ", ".join(repr(link.name) for link in cyclic[:5])
            joint = parents[cyclic[0].name]
            self.fault(
                joint.line,
                f"joint[{joint.name}]",
                f"joints form a cycle through links {names}; those links are not read",
                code="urdf-cycle",
            )
        if len(roots) > 1:
            names = ", ".join(
                f"{shown(link.name, quoted=True)} (line {link.line})" for link in roots[:5]
            )
            more = f", ... ({len(roots)} in all)" if len(roots) > 5 else ""
            self.fault(
                root,
                "robot",
                f"{len(roots)} root links (links with no parent "
                f"joint): {names}{more}; a URDF has exactly one root; "
                f"read from {shown(top.name, quoted=True)}, the largest tree",
                code="urdf-roots",
            )
        return tuple(kept), top.name

    def _sensors(
        self, root: etree._Element, joint_children: dict[str, str]
    ) -> tuple[SensorTag, ...]:
        found = []
        for gazebo in root.findall("gazebo"):
            found += self._gazebo_sensors(gazebo)
        # URDF's own <sensor> element (urdfdom): <sensor name><parent link/><camera|ray/>.
        for sensor in root.findall("sensor"):
            parent = sensor.find("parent")
            link = None if parent is None else parent.get("link")
            if parent is not None and link is None and parent.get("joint"):
                # <parent joint=...>: the sensor sits on that joint's child link.
                link = joint_children.get(str(parent.get("joint")))
            kind = sensor.get("type") or next(
                (
                    child.tag
                    for child in sensor
                    if isinstance(child.tag, str) and child.tag not in ("parent", "origin")
                ),
                "",
            )
            found.append(self._sensor(sensor, link, "urdf", str(kind)))
        # SDF's way, kept by some URDFs a converter reads: a <sensor> inside its <link>. A
        # declaration of its own ("link"): the same device declared again on that link (a
        # Gazebo <sensor> referring to it) counts once.
        found += self._link_sensors(
            (((link.get("name") or "").strip() or None, link) for link in root.findall("link")),
            "link",
        )
        found += _hardware_sensors(root)
        return tuple(found)

    def _gazebo_sensors(self, gazebo: etree._Element) -> list[SensorTag]:
        """The sensors of one ``<gazebo>`` block: its own (on its ``reference`` link), and
        those of SDF links it adds to the model, alone or in a nested ``<model>`` (a GPS on a
        link of its own, as PX4's models insert)."""
        reference = gazebo.get("reference")
        found = []
        for sensor in gazebo:
            if sensor.tag == "sensor":
                found.append(self._sensor(sensor, reference, "gazebo"))
            elif _legacy(sensor, "sensor"):
                kind = _local_name(str(sensor.tag))
                found.append(self._sensor(sensor, reference, "gazebo", kind))
        return found + self._link_sensors(_sdf_links(gazebo), "gazebo")

    def _link_sensors(
        self, links: Iterable[tuple[str | None, etree._Element]], origin: str
    ) -> list[SensorTag]:
        """The ``<sensor>`` elements written inside ``links`` (name, element), each on its
        link."""
        found = []
        for name, link in links:
            found += [self._sensor(sensor, name, origin) for sensor in link.findall("sensor")]
        return found

    @staticmethod
    def _controlled(root: etree._Element) -> Iterator[str]:
        for transmission in root.findall("transmission"):
            for joint in transmission.findall("joint"):
                if joint.get("name"):
                    yield str(joint.get("name"))
        for control in root.findall("ros2_control"):
            for joint in control.findall("joint"):
                if joint.get("name"):
                    yield str(joint.get("name"))

    def _sensor(
        self, element: etree._Element, link: str | None, origin: str, kind: str | None = None
    ) -> SensorTag:
        numbers = (*element.iterfind(".//scan/*/samples"), *element.iterfind(".//horizontal_fov"))
        for node in numbers:
            if node.text is not None and node.text.strip() and _float(node.text) is None:
                self.fault(
                    node,
                    f"sensor[{element.get('name') or ''}].{node.tag}",
                    f"<{node.tag}> is not a finite number: "
                    f"{shown(node.text.strip()[:40], quoted=True)} (ignored)",
                    code="urdf-number",
                )
        return _sensor(element, link, origin, kind)


def _sensor(
    element: etree._Element, link: str | None, origin: str, kind: str | None = None
) -> SensorTag:
    samples: dict[str, int | None] = {}
    for axis in ("horizontal", "vertical"):
        node = element.find(f".//scan/{axis}/samples")
        samples[axis] = _integer(node.text if node is not None else None)
    fov = element.find(".//horizontal_fov")
    cameras = len(element.findall("camera")) + len(element.findall(".//camera[@name]"))
    low_angle, high_angle = _angles(element, "horizontal")
    low_tilt, high_tilt = _angles(element, "vertical")
    farthest = element.find(".//range/max")
    return SensorTag(
        name=(element.get("name") or "").strip(),
        type=(kind if kind is not None else element.get("type") or "").strip().lower(),
        link=link,
        line=line_of(element),
        origin=origin,
        plugins=tuple(
            _plugin(p, link)
            for p in element.iter()
            if p.tag == "plugin" or _legacy(p, "controller")
        ),
        horizontal_samples=samples["horizontal"],
        vertical_samples=samples["vertical"],
        horizontal_fov=_float(fov.text if fov is not None else None),
        camera_count=cameras,
        sweep=None if low_angle is None or high_angle is None else abs(high_angle - low_angle),
        vertical_sweep=None if low_tilt is None or high_tilt is None else abs(high_tilt - low_tilt),
        max_range=_float(farthest.text if farthest is not None else None),
        topic=(element.findtext("topic") or "").strip()[:_MAX_PARAM_TEXT],
    )


def _angles(element: etree._Element, axis: str) -> tuple[float | None, float | None]:
    """A ray sensor's ``min_angle`` and ``max_angle`` along ``axis`` (radians), None where
    not given."""
    low, high = (element.find(f".//scan/{axis}/{end}_angle") for end in ("min", "max"))
    return _float(low.text if low is not None else None), _float(
        high.text if high is not None else None
    )


def _sdf_links(gazebo: etree._Element) -> Iterator[tuple[str, etree._Element]]:
    """The SDF links a ``<gazebo>`` block adds to the model: its own ``<link>`` children and
    those of the ``<model>``s it nests (``gps0::link``, as the ``<joint>`` joining them names
    them), models within models too; nothing inside a sensor or a plugin. Each element is
    visited once: linear in the block."""
    stack: list[tuple[str, etree._Element]] = [("", gazebo)]
    while stack:
        scope, element = stack.pop()
        for child in element:
            name = (child.get("name") or "").strip() if isinstance(child.tag, str) else ""
            if child.tag == "link":
                yield f"{scope}{name}", child
            elif child.tag == "model":
                stack.append((f"{scope}{name}::", child))


def _hardware_sensors(root: etree._Element) -> list[SensorTag]:
    """The devices a ``<ros2_control>`` block reads, told by their state interfaces: a wrench
    (``force.x`` .. ``torque.z``, or a load cell's one ``force``) is a force-torque sensor,
    angular velocity or linear acceleration an IMU, a magnetic field a magnetometer, a fluid
    pressure a barometer (a depth gauge below the water), a velocity a DVL named so; a
    ``<sensor>`` whose readings say none of these (``x``, ``y``, ``z``; ``value``) is of type
    ``unknown``, told by its name as a URDF ``<sensor>`` with no type is (but never as a camera
    or a lidar by its name alone); one whose parameters name an image topic is a camera a
    simulator renders (mujoco_ros2_control's), a depth camera when they name a depth image's or
    a point cloud's topic, and a lidar when they name a scan's topic or settings
    (:func:`_rendered_kind`). A pose
    (``tcp_pose``) is computed, not read, and a block named as an estimate
    (``external_wrench_in_base``) is the controller's reckoning from the joints' torques, not a
    device of its own. A block of ``type="sensor"`` that writes its readings on joints instead
    (a balancing robot's IMU read as the wheels' roll, pitch and yaw) is one device, named by
    the block."""
    found = []
    for control in root.findall("ros2_control"):
        sensors = control.findall("sensor")
        if not sensors and (control.get("type") or "").strip() == "sensor":
            # Its readings written on joints (a joint's position or velocity is an encoder's).
            states = [
                s for joint in control.findall("joint") for s in joint.findall("state_interface")
            ]
            found.append(_device(control, states))
        found += (_device(sensor, sensor.findall("state_interface")) for sensor in sensors)
    return [device for device in found if device is not None]


def _device(element: etree._Element, states: list[etree._Element]) -> SensorTag | None:
    """The device ``element`` (a ``<sensor>``, or a sensor block) is by what its ``states``
    read, or None (see :func:`_hardware_sensors`)."""
    name = (element.get("name") or "").strip()
    readings = {(state.get("name") or "").strip().lower().split(".", 1)[0] for state in states}
    kind = _hardware_kind(name, readings) or _rendered_kind(element)
    if kind is None and element.tag == "sensor":
        kind = "unknown"  # its readings do not say (x, y, z; value): told by its name
    if kind is None or _ESTIMATE.search(name):
        return None
    frame = next(
        (
            (param.text or "").strip()
            for param in element.findall("param")
            if param.get("name") in _FRAME_PARAMS and (param.text or "").strip()
        ),
        None,
    )
    return SensorTag(name, kind, frame, line_of(element), "ros2_control")


def _rendered_kind(element: etree._Element) -> str | None:
    """A device a simulator's hardware interface renders, by the outputs and settings its
    parameters name (mujoco_ros2_control's ``<sensor>``, which reads no state interface): a
    lidar by its scan's topic (``laserscan_topic``) or two of its settings (``angle_increment``,
    ``min_angle``, ``max_angle``, ``range_min``, ``range_max``); a
    camera by its image topic, ``depth`` when it names a depth image's or a point cloud's topic
    too or alone (a fork renders the depth as a cloud: ``pointcloud_topic``); None when it names
    none of them."""
    named = {
        (param.get("name") or "").strip()
        for param in element.findall("param")
        if (param.text or "").strip()
    }
    if "laserscan_topic" in named or len(named & _SCAN_PARAMS) >= _SCAN_SETTINGS:
        return "lidar"
    if named & _DEPTH_PARAMS:
        return "depth"
    return "camera" if "image_topic" in named else None


# What a simulator's hardware interface names for a lidar it renders (mujoco_ros2_control's
# rangefinder lidar) and for a camera's depth (an image, or a cloud).
_SCAN_PARAMS = frozenset({"angle_increment", "min_angle", "max_angle", "range_min", "range_max"})
# A lidar names its scan's topic, or two of its settings (one angle may be any sensor's).
_SCAN_SETTINGS = 2
_DEPTH_PARAMS = frozenset({"depth_topic", "pointcloud_topic"})


def _hardware_kind(name: str, readings: set[str]) -> str | None:
    """The kind of device a ``<ros2_control>`` sensor is, by what it reads; a velocity over the
    ground is a DVL's only where its name says so (odometry reads one too), and an attitude
    (roll and pitch) is an IMU's."""
    if "linear_velocity" in readings and _DVL_NAME.search(name):
        return "dvl"
    if readings >= _ATTITUDE:
        return "imu"
    return next((k for k, read in _HARDWARE_READINGS if readings & read), None)


# What a ros2_control sensor's state interfaces read (the part before the first dot), by kind.
_HARDWARE_READINGS = (
    ("force_torque", frozenset({"force", "torque"})),
    ("imu", frozenset({"angular_velocity", "linear_acceleration"})),
    ("magnetometer", frozenset({"magnetic_field"})),
    ("barometer", frozenset({"fluid_pressure"})),  # a depth gauge below the water
)
_DVL_NAME = re.compile(r"dvl|doppler", re.IGNORECASE)
# An attitude a ros2_control sensor reads (its roll and pitch): an IMU's.
_ATTITUDE = frozenset({"roll", "pitch"})
_FRAME_PARAMS = frozenset({"frame_id", "sensor_frame", "frame", "frame_name"})
_ESTIMATE = re.compile(r"estimat|external_(wrench|force|torque)", re.IGNORECASE)


def _coupled(joints: dict[str, Joint]) -> set[str]:
    """The joints of pairs ``<mimic>`` couples: a joint that is not fixed following another
    that exists, is not fixed and is not itself, and that joint."""
    followers = {
        joint.name
        for joint in joints.values()
        if joint.type != "fixed"
        and joint.mimic not in (None, joint.name)
        and (leader := joints.get(joint.mimic or "")) is not None
        and leader.type != "fixed"
    }
    return followers | {joints[name].mimic or "" for name in followers}


def _phantoms(joints: dict[str, Joint], links: dict[str, Link]) -> set[str]:
    """The joints that move nothing and exert nothing (:attr:`Joint.phantom`): not fixed, a
    zero ``<limit effort>``, the child a declared link with nothing in it from which no joint
    hangs; none when no joint of the file has an effort other than zero (a file whose efforts
    are all placeholders says nothing by them). The caller leaves out those a mimic couples or
    a controller commands."""
    if not any(joint.effort for joint in joints.values()):
        return set()
    parents = {joint.parent for joint in joints.values()}
    return {
        name
        for name, joint in joints.items()
        if joint.type != "fixed"
        and joint.effort == 0
        and joint.child not in parents
        and (child := links.get(joint.child)) is not None
        and child.empty
    }


def _mass_points(joints: dict[str, Joint], links: dict[str, Link], sensing: set[str]) -> set[str]:
    """The limited joints (revolute, prismatic) that move mass points only: every link below
    them writes a mass of at most :data:`_MASS_POINT` and is neither drawn (:attr:`Link.drawn`)
    nor carries a sensor (``sensing``), in a file that draws some link. A helper a simulator
    needs (a mass for each link), not a part of the body: Velma's keep-upright chains at its
    wrists. A bare chain (no geometry in the file, or links with no mass written) says nothing
    by it; an endless joint's undrawn mass point is a rotor's or a wheel's stand-in."""
    if not any(link.drawn for link in links.values()):
        return set()
    below: dict[str, list[str]] = {}
    for joint in joints.values():
        below.setdefault(joint.parent, []).append(joint.child)
    seen: dict[str, bool] = {}

    def points(link: str, depth: int = 0) -> bool:
        if link not in seen:
            found = links.get(link)
            seen[link] = False  # a cycle (refused later) reads as drawn
            seen[link] = (
                depth < _MASS_POINT_DEPTH
                and found is not None
                and found.mass is not None
                and found.mass <= _MASS_POINT
                and not found.drawn
                and link not in sensing
                and all(points(child, depth + 1) for child in below.get(link, ()))
            )
        return seen[link]

    return {
        name
        for name, joint in joints.items()
        if joint.type in ("revolute", "prismatic") and not joint.endless and points(joint.child)
    }


def _without_mass_points(
    joints: tuple[Joint, ...], links: dict[str, Link], sensing: set[str], commanded: set[str]
) -> tuple[Joint, ...]:
    """``joints`` with those that move mass points only (:func:`_mass_points`; ``sensing``: the
    links a sensor is on) marked phantoms, but for one ``<mimic>`` couples or a controller
    ``commanded``."""
    found = {joint.name: joint for joint in joints}
    points = _mass_points(found, links, sensing) - _coupled(found) - commanded
    if not points:
        return joints
    return tuple(
        replace(joint, phantom=True) if joint.name in points else joint for joint in joints
    )


def _placeholders(joints: dict[str, Joint]) -> set[str]:
    """Every joint with limits, when all of them have equal ones, one carries another (a chain,
    not only mounts on a body) and no joint moves without limits (continuous, floating,
    planar): a CAD exporter's placeholder limits (all zero), not a robot locked whole. Sensor
    mounts written so (RotorS, the UUV simulator: each a leaf on the body) stay locked."""
    limited = {j.name: j for j in joints.values() if j.type in ("revolute", "prismatic")}
    if any(j.type in _UNLIMITED for j in joints.values()) or not all(
        j.closed for j in limited.values()
    ):
        return set()
    carried = {j.child for j in limited.values()}
    if not any(j.parent in carried for j in limited.values()):
        return set()
    return set(limited)


def _blank_chains(joints: dict[str, Joint]) -> set[str]:
    """Every blank joint (:func:`written_blank`) when :data:`_BLANK_CHAIN` of them are in a
    row, each carried by the one before (through fixed links), or when there are that many and
    every joint of the file that is not fixed is blank: nobody locks an arm joint by joint that
    way, nor every joint of a robot, so the file is an export that wrote no limits, its wheels'
    joints too. A sensor mount written so is a leaf on the body, or two (a camera and its
    gimbal) in a row, and stays locked beside joints that move."""
    blank = {name for name, joint in joints.items() if written_blank(joint)}
    if len(blank) < _BLANK_CHAIN:
        return set()
    if all(name in blank or joint.type == "fixed" for name, joint in joints.items()):
        return blank
    above = {joint.child: joint for joint in joints.values()}
    known: dict[str, str | None] = {}
    carrier: dict[str, str | None] = {}
    for name in blank:
        up = walk_up(above.get, joints[name].parent, known, _not_fixed)
        carrier[name] = up if up in blank else None
    return blank if _longest_row(carrier) >= _BLANK_CHAIN else set()


def walk_up(
    parent_joint: Callable[[str], Joint | None],
    link: str,
    known: dict[str, str | None],
    wanted: Callable[[Joint], bool],
) -> str | None:
    """The nearest joint above ``link`` that is ``wanted`` (None when none is, up to the root,
    or when the joints above close a loop: a file read before its tree is checked);
    ``parent_joint`` gives the joint a link hangs from. Every link walked is remembered in
    ``known`` (one ``known`` per ``wanted``), so many links cost one walk of the tree at most."""
    walked: list[str] = []
    seen: set[str] = set()
    found: str | None = None
    while link not in known:
        walked.append(link)
        seen.add(link)
        joint = parent_joint(link)
        if joint is None or wanted(joint):
            found = None if joint is None else joint.name
            break
        if joint.parent in seen:
            break
        link = joint.parent
    else:
        found = known[link]
    for name in walked:
        known[name] = found
    return found


def _not_fixed(joint: Joint) -> bool:
    return joint.type != "fixed"


def written_blank(joint: Joint) -> bool:
    """A revolute or prismatic joint with limits 0..0 and a zero effort: what a CAD exporter
    writes when it was given no limits."""
    return (
        joint.type in ("revolute", "prismatic")
        and joint.lower == 0
        and joint.upper == 0
        and joint.effort == 0
    )


def _longest_row(carrier: dict[str, str | None]) -> int:
    """The most joints in a row, each carried by the next in ``carrier`` (``None``: by none of
    them); every joint walked once, a loop cut where it closes."""
    depth: dict[str, int] = {}
    for name in carrier:
        path: list[str] = []
        on_path: set[str] = set()
        here: str | None = name
        while here is not None and here not in depth and here not in on_path:
            path.append(here)
            on_path.add(here)
            here = carrier[here]
        base = depth[here] if here is not None and here in depth else 0
        for level, joint_name in enumerate(reversed(path), start=base + 1):
            depth[joint_name] = level
    return max(depth.values(), default=0)


def _closures(root: etree._Element, links: dict[str, Link]) -> tuple[tuple[str, str], ...]:
    """The links SDF joints in ``<gazebo>`` blocks join (a loop the tree cannot write: a
    five-bar leg closed at its wheel), at most :data:`MAX_CLOSURES` of them."""
    found = []
    for block in root.findall("gazebo"):
        for joint in block.findall("joint"):
            parent = (joint.findtext("parent") or "").strip()
            child = (joint.findtext("child") or "").strip()
            if parent in links and child in links and parent != child:
                found.append((parent, child))
                if len(found) >= MAX_CLOSURES:
                    return tuple(found)
    return tuple(found)


def _cut_loops(links: dict[str, Link]) -> tuple[tuple[str, str], ...]:
    """Pairs of links named as the two ends of one cut loop: ``closedloop`` in the name and an
    ``A`` and a ``B`` in one place of it, the rest alike (``closedloop13_A_3D`` and
    ``closedloop13_B_3D``, ``closedloop_knee_right_A`` and ``..._B``: an exporter's frames for a
    parallel linkage's loop, to be joined in a simulator)."""
    ends: dict[str, dict[str, str]] = {}
    for name in links:
        if _LOOP_WORD.search(name) is None:
            continue
        for marker in _LOOP_END.finditer(name):
            key = f"{name[: marker.start()]}*{name[marker.end() :]}"
            ends.setdefault(key, {})[marker.group()] = name
    found = [(pair["A"], pair["B"]) for pair in ends.values() if len(pair) == 2]
    return tuple(found[:MAX_CLOSURES])


# A cut loop's frames (Gepetto's exports of closed-chain legs), and the end each one is.
_LOOP_WORD = re.compile(r"closed_?loop", re.IGNORECASE)
_LOOP_END = re.compile(r"(?<=[_0-9])[AB](?=_|$)")


# A simulator's joint controller plugin (Gazebo Sim's JointPositionController and
# JointController, Ignition's): it commands the joints its <joint_name> elements name, as a
# ros2_control block does (to a position, or a velocity).
_JOINT_CONTROLLER = re.compile(r"joint[-_]?(position[-_]?)?controller", re.IGNORECASE)


def _plugin_commands(plugins: tuple[PluginTag, ...]) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """(joint, command interface) of each joint a simulator's joint controller plugin names:
    position for a position controller, velocity for the others (effort where it says
    ``<use_force_commands>``); :func:`_merged_commands` puts one joint's together."""
    found: list[tuple[str, tuple[str, ...]]] = []
    for plugin in plugins:
        matched = _JOINT_CONTROLLER.search(plugin.filename or plugin.name)
        if matched is None:
            continue
        kind = "position" if matched.group(1) else "velocity"
        if (plugin.param("use_force_commands") or "").lower() == "true":
            kind = "effort"
        found += ((text, (kind,)) for tag, text in plugin.params if tag.lower() == "joint_name")
    return tuple(found)


def _merged_commands(
    *sources: tuple[tuple[str, tuple[str, ...]], ...],
) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """(joint, command interfaces) of every source, each joint once with all its kinds, in
    the order first given."""
    found: dict[str, list[str]] = {}
    for source in sources:
        for name, kinds in source:
            found.setdefault(name, []).extend(kinds)
    return tuple((name, tuple(dict.fromkeys(kinds))) for name, kinds in found.items())


def _command_interfaces(root: etree._Element) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """(joint, command interface) of each ``<ros2_control>`` joint's and ``<transmission>``
    joint's; :func:`_merged_commands` puts one joint's together."""
    found: list[tuple[str, tuple[str, ...]]] = []
    for control in root.findall("ros2_control"):
        for joint in control.findall("joint"):
            name = (joint.get("name") or "").strip()
            for command in joint.findall("command_interface"):
                kind = (command.get("name") or "").strip().lower()
                if name and kind:
                    found.append((name, (kind,)))
    for transmission in root.findall("transmission"):
        for joint in transmission.findall("joint"):
            name = (joint.get("name") or "").strip()
            for interface in joint.iterfind("hardwareInterface"):
                kind = _interface_kind(interface.text or "")
                if name and kind:
                    found.append((name, (kind,)))
    return tuple(found)


def _interface_kind(text: str) -> str:
    """``hardware_interface/VelocityJointInterface`` -> ``velocity``; '' when none is named."""
    word = text.strip().rsplit("/", 1)[-1].lower()
    return next((kind for kind in ("position", "velocity", "effort") if kind in word), "")


def _tags(root: etree._Element) -> frozenset[str]:
    """The element names of the description itself, not inside a ``<sensor>`` or a
    ``<plugin>`` (their words are a device's settings: a barometer's water-surface offset says
    nothing of the hull; plugins keep theirs in :attr:`PluginTag.params`), nor inside a Gazebo
    0.x ``<sensor:...>`` or ``<controller:...>``."""
    # The elements themselves are kept (not their ids): lxml makes a proxy per access, and a
    # freed proxy's id may be another element's.
    inside = {
        element
        for device in root.iter()
        if _a_device(device)
        for element in device.iterdescendants()
    }
    found: set[str] = set()
    for element in root.iter():
        if isinstance(element.tag, str) and element not in inside and len(found) < _MAX_TAGS:
            found.add(_local_name(element.tag).lower())
    return frozenset(found)


def _a_device(element: etree._Element) -> bool:
    """A sensor or a plugin element, of any Gazebo's spelling (``<sensor>``, ``<plugin>``, a
    namespaced ``<sensor>``, Gazebo 0.x's ``<sensor:ray>`` and ``<controller:...>``)."""
    tag = element.tag
    if not isinstance(tag, str):
        return False
    return (
        tag in ("sensor", "plugin")
        or (tag.startswith("{") and tag.endswith("}sensor"))
        or _legacy(element, "sensor")
        or _legacy(element, "controller")
    )


def _gravity_off(root: etree._Element) -> bool:
    """A ``<gazebo>`` block of the description turns gravity off for its links: Gazebo
    Classic's ``<turnGravityOff>true`` or ``<gravity>`` false (``0``, ``false``)."""
    for block in root.iterchildren("gazebo"):
        for element in block.iterchildren(*_GRAVITY_OFF):
            if (element.text or "").strip().lower() in _GRAVITY_OFF[element.tag]:
                return True
    return False


# The Gazebo flags that turn gravity off, and the texts that do.
_GRAVITY_OFF = {"turnGravityOff": ("1", "true"), "gravity": ("0", "false")}


def _legacy(element: etree._Element, kind: str) -> bool:
    """A Gazebo 0.x namespaced element of ``kind`` (``<sensor:ray>``, ``<controller:gazebo_ros_imu
    plugin="...">``), as URDFs written for ROS in 2010-2012 still have them: its namespace
    declared, or not (a file that never declared it, read with the element kept under its
    prefixed name: :func:`~solver.identify.readers.safexml.parse_xml`'s recovery)."""
    tag = element.tag
    if not isinstance(tag, str):
        return False
    if tag.startswith("{"):
        return tag[1:].split("}")[0].endswith(f"#{kind}")
    return tag.startswith(f"{kind}:")


def _local_name(tag: str) -> str:
    """A tag without its namespace (``{...#sensor}ray``) or undeclared prefix (``sensor:ray``)."""
    return tag.rsplit("}", 1)[-1].rsplit(":", 1)[-1]


def _uncompiled_xacro(root: etree._Element, file: str) -> list[Fault]:
    """A located warning for each outermost ``<xacro:...>`` element of a document read as URDF.

    Such a file is never compiled (a ``.urdf``, a ``robot_description``): its xacro elements,
    and whatever a macro body holds, are not part of the robot, and the user should know.
    """
    found: list[Fault] = []
    stack = [root]
    while stack:
        element = stack.pop()
        tag = element.tag
        if not isinstance(tag, str):
            continue  # comments and processing instructions
        # Declared, the prefix maps to xacro's namespace; undeclared, safexml keeps the element
        # under its prefixed name. xacro itself goes by the prefix, so does this.
        namespace, _, local = tag[1:].partition("}") if tag.startswith("{") else ("", "", tag)
        if tag.startswith("xacro:"):
            local = tag.removeprefix("xacro:")
        elif element.prefix != "xacro" and "xacro" not in namespace:
            stack.extend(reversed(list(element)))
            continue
        found.append(
            Fault(
                Location(file, line_of(element), None, f"xacro:{local}"),
                f"<xacro:{local}> ignored: this file is read as URDF and never "
                "compiled (compiling xacro runs code from the file; a .xacro file "
                "is compiled with --trust-xacro)",
                "xacro-ignored",
            )
        )
    return found


def _plugin(element: etree._Element, reference: str | None) -> PluginTag:
    params: list[tuple[str, str]] = []
    groups: dict[str, None] = {}
    for child in element.iterdescendants():
        if len(params) >= _MAX_PARAMS:
            break
        if not isinstance(child.tag, str):
            continue
        if len(child) > 0:
            if len(groups) < _MAX_PARAMS:
                groups.setdefault(child.tag[:_MAX_PARAM_TEXT])
        elif child.text and child.text.strip():
            params.append((child.tag, child.text.strip()[:_MAX_PARAM_TEXT]))
    return PluginTag(
        (element.get("name") or "").strip(),
        (element.get("filename") or element.get("plugin") or "").strip(),  # plugin=: Gazebo 0.x
        reference,
        line_of(element),
        tuple(params),
        tuple(groups),
    )


def _reach(start: str, below: dict[str, list[str]]) -> set[str]:
    seen = {start}
    stack = [start]
    while stack:
        for child in below.get(stack.pop(), ()):
            if child not in seen:
                seen.add(child)
                stack.append(child)
    return seen


def _vector(
    element: etree._Element | None, default: tuple[float, float, float], attribute: str = "xyz"
) -> tuple[float, float, float]:
    """The ``xyz`` (or ``rpy``) of an ``<axis>`` or ``<origin>``; ``default`` where absent or
    unreadable."""
    text = (element.get(attribute) or "") if element is not None else ""
    parts = [_float(t) for t in text.split()[:4]]
    if len(parts) != 3 or any(p is None for p in parts):
        return default
    x, y, z = (p or 0.0 for p in parts)
    return (x, y, z)


def _displacements(root: etree._Element) -> dict[str, float | None]:
    """The mass of water each link displaces, as a hydrodynamics plugin of the UUV simulator's
    kind lists it (a ``<link name>`` entry with its ``<volume>``, in the plugin's
    ``<fluid_density>``, 1028 kg/m3 of sea water when it gives none): its buoyancy over its
    weight is that over its mass. None for a link the entry makes neutrally buoyant (the
    plugin then sets the volume to balance the weight, whatever is written: its buoyancy is
    its weight)."""
    found: dict[str, float | None] = {}
    for plugin in root.iterfind("gazebo/plugin"):
        density = _float(plugin.findtext("fluid_density"))
        density = density if density is not None and density > 0 else _SEA_WATER
        for entry in plugin.iterfind("link"):
            if len(found) >= _MAX_PARAMS:
                return found
            name = (entry.get("name") or "").strip()
            volume = _float(entry.findtext("volume"))
            neutral = (entry.findtext("neutrally_buoyant") or "").strip().lower()
            water = volume * density if volume is not None and volume > 0 else math.nan
            if name and neutral in ("1", "true"):
                found.setdefault(name, None)
            elif name and math.isfinite(water):
                found.setdefault(name, water)
    return found


def _compensation(link: etree._Element) -> float | None:
    """A link's ``<buoyancy><compensation>`` value (its first), or None."""
    found = link.find("buoyancy/compensation")
    return None if found is None else _float(found.text)


def _cylinder(link: etree._Element) -> Cylinder | None:
    """A link's first ``<visual>`` when it is a cylinder of a readable size, else its first
    ``<collision>`` when that is one (a propeller or a wheel drawn as a mesh collides as a
    disc), or None."""
    for kind in ("visual", "collision"):
        found = _shape_cylinder(link.find(kind))
        if found is not None:
            return found
    return None


def _shape_cylinder(element: etree._Element | None) -> Cylinder | None:
    """A ``<visual>`` or ``<collision>`` when it is a cylinder of a readable size, or None."""
    shape = None if element is None else element.find("geometry/cylinder")
    if element is None or shape is None:
        return None
    radius, length = _float(shape.get("radius")), _float(shape.get("length"))
    if radius is None or length is None or radius <= 0 or length <= 0:
        return None
    origin = element.find("origin")
    zero = (0.0, 0.0, 0.0)
    return Cylinder(radius, length, _vector(origin, zero, "rpy"), _vector(origin, zero))


def _box(link: etree._Element) -> Box | None:
    """A link's first ``<visual>`` when it is a box of a readable size, else its first
    ``<collision>`` when that is one, or None."""
    for kind in ("visual", "collision"):
        element = link.find(kind)
        shape = None if element is None else element.find("geometry/box")
        if element is None or shape is None:
            continue
        parts = (shape.get("size") or "").split(None, 3)  # a fourth part: no box's size
        size = tuple(_float(part) for part in parts)
        if len(size) == 3 and all(side is not None and side > 0 for side in size):
            origin = element.find("origin")
            zero = (0.0, 0.0, 0.0)
            x, y, z = (float(side or 0.0) for side in size)
            return Box((x, y, z), _vector(origin, zero, "rpy"), _vector(origin, zero))
    return None


def _mass(link: etree._Element) -> float | None:
    """A link's first ``<inertial>``'s positive mass, or None."""
    found = link.find("inertial/mass")
    value = None if found is None else _float(found.get("value"))
    return value if value is not None and value > 0 else None


def _mass_centre(link: etree._Element) -> tuple[float, float, float] | None:
    """Where a link's first ``<inertial>`` puts its mass centre (its ``<origin xyz>``), or None
    when it writes no inertial, no positive mass (a frame a CAD export writes with a mass of 0
    and an origin anywhere: no mass, no centre of it), no such origin or one that cannot be
    read."""
    origin = link.find("inertial/origin")
    if origin is None or origin.get("xyz") is None or _mass(link) is None:
        return None
    unread = (math.nan, math.nan, math.nan)
    found = _vector(origin, unread)
    return None if found is unread else found


def _inertia(link: etree._Element) -> Inertia | None:
    """A link's first ``<inertial>``'s ``<inertia>``, or None when a term is missing or
    unreadable or a moment is not positive."""
    found = link.find("inertial/inertia")
    if found is None:
        return None
    terms = [_float(found.get(name)) for name in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")]
    xx, xy, xz, yy, yz, zz = (term if term is not None else math.nan for term in terms)
    if not all(moment > 0 for moment in (xx, yy, zz)) or any(math.isnan(t) for t in (xy, xz, yz)):
        return None
    zero = (0.0, 0.0, 0.0)
    return Inertia((xx, xy, xz, yy, yz, zz), _vector(link.find("inertial/origin"), zero, "rpy"))


def _integer(text: str | None) -> int | None:
    value = _float(text)
    return None if value is None else int(value)


def _float(text: str | None) -> float | None:
    """A finite number, or ``None``: ``inf``, ``nan`` and ``1e999`` are no measurement, and
    Python's float() would read non-ASCII digits (``٣`` as 3), which no URDF reader does."""
    if text is not None and not text.isascii():
        return None
    try:
        value = None if text is None else float(text.strip()[:64])
    except ValueError:
        return None
    return value if value is not None and math.isfinite(value) else None
