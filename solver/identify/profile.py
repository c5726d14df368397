"""The identification profile: every pattern, threshold and mapping identification uses, as data.

``rules/identification.yaml`` (shipped; ``--profile`` for your own) says how body parts are
recognised (name patterns on joints and links, Gazebo plugin patterns, limb thresholds), which
structure a body has (ordered rules over part counts, with a confidence), which rule-set
kinematic type each structure maps to, how ``<sensor>`` elements, sensor plugins and topic
message types map to sensor kinds, which sensor type each kind is in the rule set, and which
messages and description features mean which motion control. :func:`load_profile` validates the
whole file and reports every problem at once, located (``file:line:col: path: message``), as a
:class:`ProfileError`.

Not here: applying the profile (:mod:`solver.identify.body`, :mod:`~solver.identify.classifier`,
:mod:`~solver.identify.sensors`, :mod:`~solver.identify.interfaces`,
:mod:`~solver.identify.motion`).
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from solver.core.rules import shipped_path
from solver.errors import Location, SolverError, did_you_mean
from solver.files.filekind import PROFILE_SECTIONS
from solver.files.reader import Reader, type_name
from solver.files.yamlio import Document, PathPart, load_document
from solver.identify.compose import compose
from solver.untrusted import shown

__all__ = [
    "CONTROL_SOURCES",
    "DIRECTIONS",
    "FEATURES",
    "GROUND",
    "MOTION_CONTROL",
    "PARTS",
    "PLUGIN_PARTS",
    "ROLES",
    "ROLE_SOURCES",
    "SENSOR_COUNT",
    "SENSOR_TYPE",
    "VEHICLE_MEDIA",
    "ControlRule",
    "FeatureCondition",
    "NavigationRule",
    "PackageRule",
    "Pattern",
    "Profile",
    "ProfileError",
    "SensorRule",
    "SoftwareRule",
    "StructureRule",
    "default_profile_path",
    "load_profile",
    "parse_profile",
]

# What the code measures on a body (the domain); which of them matter is the profile's business.
PARTS = (
    "wheel",
    "rotor",
    "track",
    "gripper",
    "leg",
    "head",
    "arm",
    "thruster",
    "fin",
    "wing",
    "caster",
    "tool",
)
# drive/track/flight/thruster/lift: plugins that move the robot (a joint they name takes their
# role); marine: plugins of a body in water; surface: hints of a hull floating at the surface
# (plugins and element names such as <metacentric_width>); underwater: what a body below the
# surface has (plugins and sensors: hydrodynamics, buoyancy, a DVL, a pressure sensor); space:
# plugins of a craft thrusters fly in air or space (a reaction wheel, air thrusters); spring:
# plugins that hold a joint on a spring (a joint they name yields: passive, no limb's); force:
# plugins that push a link with a commanded force (in water, a thruster's link); grasp: plugins
# that hold what a gripper closes on (the links they name as its fingers: gripper joints).
PLUGIN_PARTS = (
    "drive",
    "track",
    "flight",
    "thruster",
    "lift",
    "marine",
    "surface",
    "underwater",
    "space",
    "spring",
    "mover",
    "force",
    "grasp",
)
FEATURES = (
    "wheels",
    "tracks",
    "rotors",
    "arms",
    "tools",
    "legs",
    "serial_legs",
    "heads",
    "fingers",
    "grippers",
    "drive_plugins",
    "flight_plugins",
    "mobile_base",
    "flying",
    "floating_base",
    "weak_base",
    "weak_flight",
    "weak_water",
    "thrusters",
    "fins",
    "casters",
    "finger_motions",
    "marine",
    "surface",
    "underwater",
    "serpentine",
    "head_alone",
)
# tools: arms, and a flying body's rigid tool (a link the `tool` pattern names, on fixed joints)
# or a gripper named for one (one for either or both; a mirrored pair of hinges read as jaws,
# a drone's landing gear, is none).
# serial_legs: legs of three movable joints or more (half of a five-bar leg drawn open is none).
# thrusters / fins / casters: joints (or plugin-named links) in those roles; finger_motions: the
# finger joints that move on their own (not mimic); marine: a body in water (thrusters, marine
# plugins); surface: floating at the surface (a hull's buoyancy hints, a surface plugin);
# underwater: what a body below the surface has (a buoyancy or hydrodynamics plugin, a thruster
# plugin, a DVL or pressure sensor), where thruster names alone put it in water.
# weak_base: the mobile base is known only from fixed wheels, planar root joints or an SRDF
# planar virtual joint (a trimmed or simulated model), not from driven wheels or a plugin.
# weak_flight: flying is known only from fixed rotor-named links on a body with no movable
# joint at all (a trimmed multirotor model), not from rotor joints or a flight plugin.
# weak_water: the body is in water by the robot's name, its packages' words or its thrusters
# alone (nothing else says how it travels, or where in the water).
# serpentine: the body is one long chain of equal modules whose axes alternate, with no base
# that holds it (a snake robot).
# head_alone: the body is pan/tilt heads only, with no vehicle, mobile or floating base, arm,
# leg, gripper or finger, and no teleop node of its packages driving it (a camera's pan/tilt on
# a fixed base).
BOOLEAN_FEATURES = (
    "mobile_base",
    "flying",
    "floating_base",
    "weak_base",
    "weak_flight",
    "weak_water",
    "marine",
    "surface",
    "underwater",
    "serpentine",
    "head_alone",
)
DIRECTIONS = ("published", "subscribed")
# Description sources read from what joints do, not from a declared controller or plan.
ROLE_SOURCES = (
    "wheels",
    "steered_wheels",
    "planar_base",
    "undrawn_wheels",
    "thrusters",
    "arm",
    "arm_gripper",
    "gripper_alone",
    "head_alone",
    "legs",
    "sprawled_legs",
)
CONTROL_SOURCES = (
    "drive_plugin",
    "controlled_wheels",
    "controlled_rudders",
    "flight",
    "controlled_joints",
    "controlled_fingers",
    "srdf_group",
    "srdf_walker_group",
    "srdf_end_effector",
    "leg_controllers",
    "leg_joint_controllers",
    "mount_joint_controllers",
    "head_joint_controllers",
    "vehicle_joint_controllers",
    "rotor_controllers",
    *ROLE_SOURCES,
)
LIMB_KEYS = (
    "arm_min_joints",
    "leg_min_joints",
    "head_max_joints",
    "hand_min_fingers",
    "finger_max_joints",
    "min_rotors",
    "spine_min_joints",
)
# Thresholds a profile written before they existed may leave out.
LIMB_DEFAULTS = {"finger_max_joints": 4, "min_rotors": 2, "spine_min_joints": 6}
VELOCITY = "velocity"
# A package rule's control that is the structure's velocity control too, commanded by the
# navigation stack the packages ship rather than by a person: a teleop node drives a sensor
# head trimmed from its base (solver/identify/shipped.py), navigation does not.
NAVIGATION_VELOCITY = "navigation velocity"

# The sections only a profile has are the ones that tell a profile from a rule set.
_TOP_KEYS = {"name", "description", "characteristics", *PROFILE_SECTIONS}
# The roles identification fills, each naming one of the rule set's characteristics (the
# profile's ``characteristics:``); the kinematic type is always the rule set's team_key.
MOTION_CONTROL = "motion_control"
SENSOR_TYPE = "sensor_type"
SENSOR_COUNT = "sensor_count"
ROLES = (MOTION_CONTROL, SENSOR_TYPE, SENSOR_COUNT)
_STRUCTURE_KEYS = {"name", "when", "expect", "kinematic_types", "confidence", "description"}
# Degrees in a full turn: a field of view written wider says nothing (degrees where radians
# belong).
_FULL_TURN = 360
_ELEMENT_KEYS = {"kind", "types", "match", "max_rays", "max_range", "wider_than"}
_PLUGIN_RULE_KEYS = {"kind", "match"}
_TOPIC_SENSOR_KEYS = {"kind", "types", "match", "direction"}
_TOPIC_CONTROL_KEYS = {"control", "types", "match", "direction"}
_PACKAGE_KEYS = {"control", "match", "not_for", "only_for", "unless"}
# What the robot's packages may say a body travels in (``body_packages``).
GROUND = "ground"
VEHICLE_MEDIA = ("flight", "underwater", "surface", GROUND)
_LIDAR_KEYS = {"single_plane", "multi_plane"}

YPath = tuple[PathPart, ...]


class ProfileError(SolverError, ValueError):
    """An identification profile file is malformed."""


@dataclass(frozen=True, slots=True)
class Pattern:
    """A case-insensitive regular expression from the profile, and where it was written.

    Patterns come from user files and are matched against names from robot descriptions, so
    they run on RE2 (:func:`_compiled`): linear time in the text, whatever the pattern.
    """

    text: str
    location: Location | None = field(default=None, compare=False)
    # Compiled once (a big description asks a pattern hundreds of thousands of times).
    compiled: Any = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.compiled is None:
            object.__setattr__(self, "compiled", _compiled(self.text))

    def search(self, text: str) -> bool:
        return self.compiled.search(text) is not None

    def find(self, text: str) -> str | None:
        """The first text this pattern matches in ``text`` (its group named ``shown``, when it
        names one and that took part: a pattern that reads on past the word it reports), or
        None."""
        found = self.compiled.search(text)
        if found is None:
            return None
        shown = found.group("shown") if "shown" in self.compiled.groupindex else None
        return str(found.group(0) if shown is None else shown)


class PartMatcher:
    """Which of several patterns a name matches, in one RE2 pass per name (remembered).

    Classifying a 20,000-link description asks each joint and link name against every body
    part's pattern; one RE2 set match per name keeps that linear and cheap.
    """

    def __init__(self, patterns: tuple[tuple[str, Pattern], ...]) -> None:
        import re2  # type: ignore[import-untyped]  # google-re2 ships no type hints

        options = re2.Options()
        options.case_sensitive = False
        options.log_errors = False
        self._parts = [part for part, _ in patterns]
        self._set = re2.Set.SearchSet(options)
        for _, pattern in patterns:
            self._set.Add(pattern.text)  # compiled alone already: cannot fail here
        self._set.Compile()
        self._seen: dict[str, frozenset[str]] = {}

    def __call__(self, name: str) -> frozenset[str]:
        found = self._seen.get(name)
        if found is None:
            hits = self._set.Match(name) if self._parts else None
            found = frozenset(self._parts[i] for i in hits or ())
            self._seen[name] = found
        return found


class PatternError(ValueError):
    """A pattern RE2 cannot run (a syntax error, or lookaround / backreferences)."""


def _compiled(text: str) -> Any:
    """``text`` compiled by RE2, case-insensitive; :class:`PatternError` if it cannot be.

    RE2 has no backtracking: a pattern like ``^(a+)+$`` that takes Python's ``re`` seconds
    on a 29-character name takes microseconds. The price: no lookaround, no backreferences.
    """
    import re2

    options = re2.Options()
    options.case_sensitive = False
    options.log_errors = False  # the error is raised and reported with its location instead
    try:
        return re2.compile(text, options)
    except re2.error as error:
        detail = (
            error.args[0].decode("utf-8", "replace")
            if error.args and isinstance(error.args[0], bytes)
            else str(error)
        )
        raise PatternError(detail) from None


@dataclass(frozen=True, slots=True)
class FeatureCondition:
    """``low <= features[feature] <= high`` (booleans as 0/1)."""

    feature: str
    low: int | None
    high: int | None

    def holds(self, features: Mapping[str, int]) -> bool:
        value = features.get(self.feature, 0)
        return (self.low is None or value >= self.low) and (self.high is None or value <= self.high)

    def describe(self) -> str:
        if self.feature in BOOLEAN_FEATURES:
            return self.feature if self.low == 1 else f"no {self.feature.replace('_', ' ')}"
        if self.low == self.high:
            return f"{self.feature} = {self.low}"
        if self.high is None:
            return f"{self.feature} >= {self.low}"
        if self.low is None:
            return f"{self.feature} <= {self.high}"
        return f"{self.low} <= {self.feature} <= {self.high}"


@dataclass(frozen=True, slots=True)
class StructureRule:
    name: str
    when: tuple[FeatureCondition, ...]
    expect: tuple[FeatureCondition, ...]
    kinematic_types: tuple[str, ...]
    confidence: float
    location: Location | None = field(default=None, compare=False)

    def matches(self, features: Mapping[str, int]) -> bool:
        return all(condition.holds(features) for condition in self.when)


@dataclass(frozen=True, slots=True)
class SensorRule:
    """Sensor elements, plugins or topics of these types (and matching ``match``) -> ``kind``."""

    kind: str
    types: frozenset[str] = frozenset()
    match: Pattern | None = None
    direction: str | None = None
    location: Location | None = field(default=None, compare=False)
    # Ray sensors only: at most this many rays (horizontal x vertical samples). A range finder
    # casts one; a lidar sweeps hundreds.
    max_rays: int | None = None
    # Sensors whose horizontal field of view is wider than this many degrees (a panoramic
    # camera sees more than a half-turn; a fisheye lens less): one that says none, or more
    # than a full turn (degrees written where radians belong), is not.
    wider_than: int | None = None
    # Ray sensors only: reaching no farther than this many metres (a proximity ranger's
    # metre; a lidar sees tens): one that says no range, or one of zero or less, is not.
    max_range: int | None = None

    def accepts(
        self,
        kind_or_type: str | None,
        text: str,
        direction: str | None = None,
        *,
        rays: int | None = None,
        fov: float | None = None,
        reach: float | None = None,
    ) -> bool:
        """This rule takes a sensor of ``kind_or_type`` whose names are ``text`` (a topic's
        ``direction``; a ray sensor's ``rays`` and farthest ``reach`` in metres; its horizontal
        field of view ``fov`` in radians, when it says one)."""
        if self.types and kind_or_type not in self.types:
            return False
        if self.max_rays is not None and (rays is None or rays > self.max_rays):
            return False
        if self.max_range is not None and (reach is None or not 0 < reach <= self.max_range):
            return False  # a range of zero or less, which no simulator casts, says nothing
        if self.wider_than is not None and not (
            fov is not None and self.wider_than < math.degrees(fov) <= _FULL_TURN
        ):
            return False
        if self.direction is not None and direction is not None and direction != self.direction:
            return False
        if self.direction is not None and direction is None and self.match is None:
            return False  # a direction-only rule needs the direction to be known
        return self.match is None or self.match.search(text)


@dataclass(frozen=True, slots=True)
class ControlRule:
    control: str
    types: frozenset[str]
    match: Pattern | None = None
    direction: str | None = None
    location: Location | None = field(default=None, compare=False)

    def accepts(self, message_type: str, topic: str) -> bool:
        return message_type in self.types and (self.match is None or self.match.search(topic))


@dataclass(frozen=True, slots=True)
class SensorTypeMapping:
    """A sensor kind's sensor type; lidar may split by scan planes."""

    kind: str
    sensor_type: str | None = None
    single_plane: str | None = None
    multi_plane: str | None = None

    def sensor_type_for(self, vertical_samples: int | None) -> str | None:
        if self.sensor_type is not None:
            return self.sensor_type
        if vertical_samples is not None and vertical_samples > 1:
            return self.multi_plane
        return self.single_plane


@dataclass(frozen=True, slots=True)
class NavigationRule:
    """A control a description can show only as a guess (Waypoint): a body moved by one of
    ``needs``' description sources (wheels, thrusters, flight) or controls (every source of
    it) that carries one of the sensor kinds it lists."""

    control: str
    needs: tuple[tuple[str, tuple[str, ...]], ...]


@dataclass(frozen=True, slots=True)
class SoftwareRule:
    """What tells a body's own software from its joint controllers in the texts of its
    packages (:func:`solver.identify.shipped.joint_controllers`): ``shipped``, the software
    (a walker's gait, a flown body's flight controller, a velocity command, a teleop);
    ``controllers``, joint controllers configured; ``per_joint`` (optional), a controller of
    a joint's own (ROS 1's ``JointPositionController``: a command topic for that joint),
    which takes commands for the joint whatever software ships beside it; ``named``
    (optional), the software as a file's name says it (``normal_walk.py``), in words no
    abbreviation of another thing can be."""

    shipped: Pattern
    controllers: Pattern
    per_joint: Pattern | None = None
    named: Pattern | None = None


@dataclass(frozen=True, slots=True)
class PackageRule:
    """What a text of the robot's packages shows (:mod:`solver.identify.shipped`): ``match``
    found in a launch, configuration or script file means ``control`` (``velocity``, or
    ``navigation velocity`` for a navigation stack's commands: the structure's velocity
    control), except for a structure in ``not_for`` (or, when ``only_for`` lists any, one
    not in it: a structure a profile adds is then left out too) and in a file
    ``unless`` finds text in (a MoveIt script's waypoints are its arm's Cartesian path)."""

    control: str
    match: Pattern
    not_for: frozenset[str] = frozenset()
    location: Location | None = field(default=None, compare=False)
    unless: Pattern | None = None
    only_for: frozenset[str] = frozenset()

    def reads(self, structure: str) -> bool:
        """The rule is read for ``structure``: not in ``not_for``, and in ``only_for`` when
        that lists any."""
        return structure not in self.not_for and (not self.only_for or structure in self.only_for)

    def find(self, text: str) -> str | None:
        """The first text ``match`` finds in ``text``, or None (also when ``unless`` finds
        any: the file is not read for the rule)."""
        found = self.match.find(text)
        if found is None or (self.unless is not None and self.unless.search(text)):
            return None
        return found


@dataclass(frozen=True)
class Profile:
    """A loaded identification profile (see the module docstring and the shipped file)."""

    name: str
    file: str
    roles: tuple[tuple[str, str], ...]
    patterns: tuple[tuple[str, Pattern], ...]
    plugins: tuple[tuple[str, Pattern], ...]
    limbs: tuple[tuple[str, int], ...]
    doubt_factor: float
    structures: tuple[StructureRule, ...]
    element_rules: tuple[SensorRule, ...]
    plugin_rules: tuple[SensorRule, ...]
    ground_truth: Pattern | None
    sensor_types: tuple[SensorTypeMapping, ...]
    stream_segments: frozenset[str]
    topic_sensors: tuple[SensorRule, ...]
    topic_controls: tuple[ControlRule, ...]
    velocity_default: str
    velocity_by_structure: tuple[tuple[str, str], ...]
    description_controls: tuple[tuple[str, tuple[str, ...]], ...]
    digest: str = ""
    navigation: NavigationRule | None = None
    # Simulator systems (Gazebo Sim's ``gz::sim::systems::Imu``, ``...::Sensors``): they run
    # the <sensor> elements, they are none themselves (``sensors.systems``).
    simulator_systems: Pattern | None = None
    # Launch, configuration and script texts of the robot's packages -> motion controls.
    package_controls: tuple[PackageRule, ...] = ()
    # The same texts -> the medium a body travels in, when its description shows no way.
    body_packages: tuple[tuple[str, Pattern], ...] = ()
    # A link the robot's packages publish in (a frame id), by its name -> a sensor kind
    # (``sensors.frames``, :mod:`solver.identify.frames`).
    frame_rules: tuple[SensorRule, ...] = ()
    # A walker's gait, or its legs' joint controllers, in the same texts (``motion.gait``).
    gait: SoftwareRule | None = None
    # A flown body's flight software, or its rotors' joint controllers (``motion.flight``).
    flight: SoftwareRule | None = None

    def role(self, name: str) -> str:
        """The rule-set characteristic filling role ``name`` (motion_control, ...)."""
        return dict(self.roles)[name]

    def pattern(self, part: str) -> Pattern | None:
        return dict(self.patterns).get(part)

    def plugin_pattern(self, part: str) -> Pattern | None:
        return dict(self.plugins).get(part)

    def limb(self, key: str) -> int:
        return dict(self.limbs)[key]

    def sensor_type_mapping(self, kind: str) -> SensorTypeMapping | None:
        return next((m for m in self.sensor_types if m.kind == kind), None)

    def velocity_control(self, structure: str) -> str:
        return dict(self.velocity_by_structure).get(structure, self.velocity_default)

    def description_control(self, source: str) -> tuple[str, ...]:
        return dict(self.description_controls).get(source, ())

    @property
    def structure_names(self) -> tuple[str, ...]:
        return tuple(rule.name for rule in self.structures)


def default_profile_path() -> Path:
    """The shipped profile, ``rules/identification.yaml``."""
    return shipped_path("identification.yaml")


def load_profile(path: str | Path | None = None, *, display: str | None = None) -> Profile:
    """Read a profile (default: the shipped one); :class:`ProfileError` lists every problem.

    A profile that ``extends`` another (``extends: shipped``) is read on top of it
    (:mod:`solver.identify.compose`)."""
    document = load_document(default_profile_path() if path is None else path, display=display)
    return parse_profile(document)


def parse_profile(document: Document) -> Profile:
    """The profile in ``document`` (on top of the one it ``extends``, if it does)."""
    document = compose(document, shipped=default_profile_path())
    reader = Reader(document)
    # A file that is no mapping may be anything (/etc/passwd is one plain scalar): quote none of it.
    found = reader.top("identification profile")
    if found is None:
        raise ProfileError(reader.faults)
    top = found
    if "characteristics" not in top:
        # The file may be anything (/etc/shadow parses as a mapping): quote none of its keys.
        reader.fault(
            (),
            "not an identification profile: it has no 'characteristics:' field "
            "(nor 'extends:' naming a profile that has one)",
            code="missing-field",
        )
        raise ProfileError(reader.faults)
    reader.unknown_keys((), top, _TOP_KEYS, "profile field")
    name = reader.string(
        ("name",), "profile name", required=False, default=Path(document.file).stem
    )
    roles = _roles(reader)
    patterns = _patterns(reader, ("patterns",), PARTS, "part")
    plugins = _patterns(reader, ("plugins",), PLUGIN_PARTS, "plugin part")
    limbs = _limbs(reader)
    doubt = _fraction(reader, ("doubt_factor",), "doubt_factor")
    structures = _structures(reader)
    names = {rule.name for rule in structures}
    elements = _sensor_rules(reader, ("sensors", "elements"), _ELEMENT_KEYS, types=True)
    plugin_rules = _sensor_rules(reader, ("sensors", "plugins"), _PLUGIN_RULE_KEYS, types=False)
    frame_rules = (
        _sensor_rules(reader, ("sensors", "frames"), _PLUGIN_RULE_KEYS, types=False)
        if reader.get(("sensors", "frames")) is not None
        else ()
    )
    reader.unknown_keys(
        ("sensors",),
        reader.mapping(("sensors",), "sensors"),
        {"elements", "plugins", "frames", "ground_truth", "systems"},
        "sensors field",
    )
    ground_truth = _pattern(reader, ("sensors", "ground_truth"), required=False)
    systems = _pattern(reader, ("sensors", "systems"), required=False)
    sensor_types = _sensor_types(reader)
    topics = reader.mapping(("topics",), "topics")
    reader.unknown_keys(
        ("topics",), topics, {"stream_segments", "sensors", "controls"}, "topics field"
    )
    segments = frozenset(
        text.lower() for _, text in reader.names(("topics", "stream_segments"), "stream segments")
    )
    topic_sensors = _sensor_rules(
        reader, ("topics", "sensors"), _TOPIC_SENSOR_KEYS, types=True, messages=True
    )
    topic_controls = _control_rules(reader)
    velocity_default, by_structure, description = _motion(reader, names)
    navigation = _navigation(reader, description)
    package_controls = _package_rules(reader, names)
    gait = _software(reader, "gait")
    flight = _software(reader, "flight")
    body_packages = (
        _patterns(reader, ("body_packages",), VEHICLE_MEDIA, "medium")
        if reader.get(("body_packages",)) is not None
        else ()
    )
    if reader.faults:
        raise ProfileError(reader.faults)
    text = repr(document.data).encode("utf-8")
    return Profile(
        name,
        document.file,
        roles,
        patterns,
        plugins,
        limbs,
        doubt or 0.8,
        structures,
        elements,
        plugin_rules,
        ground_truth,
        sensor_types,
        segments,
        topic_sensors,
        topic_controls,
        velocity_default,
        by_structure,
        description,
        hashlib.sha256(text).hexdigest(),
        navigation,
        systems,
        package_controls,
        body_packages,
        frame_rules,
        gait,
        flight,
    )


def _roles(reader: Reader) -> tuple[tuple[str, str], ...]:
    spec = reader.mapping(("characteristics",), "characteristics (role -> rule-set name)")
    reader.unknown_keys(("characteristics",), spec, ROLES, "role")
    return tuple(
        (role, reader.string(("characteristics", role), f"characteristic for {role}"))
        for role in ROLES
    )


def _pattern(reader: Reader, path: YPath, *, required: bool = True) -> Pattern | None:
    # A pattern is no name: the 200-character name limit does not apply (the YAML reader's
    # 10,000-character bound on any value does).
    text = reader.string(path, "pattern", required=required, limit=None)
    if not text:
        return None
    try:
        compiled = _compiled(text)
    except PatternError as error:
        reader.fault(
            path,
            f"invalid regular expression {shown(text[:80], quoted=True)}: {error} (patterns run "
            "on RE2, which has no backtracking: no lookaround or "
            "backreferences)",
            code="pattern",
        )
        return None
    return Pattern(text, reader.document.location(path), compiled)


def _patterns(
    reader: Reader, path: YPath, parts: tuple[str, ...], what: str
) -> tuple[tuple[str, Pattern], ...]:
    spec = reader.mapping(path, f"{path[-1]} (a mapping of {what} -> pattern)")
    reader.unknown_keys(path, spec, parts, what)
    found = []
    for part in parts:
        if part in spec:
            pattern = _pattern(reader, (*path, part))
            if pattern is not None:
                found.append((part, pattern))
    return tuple(found)


def _positive(reader: Reader, path: YPath, what: str) -> int | None:
    value = reader.integer(path, what)
    if value is not None and value < 1:
        reader.fault(path, f"{what} must be at least 1, got {value}", code="out-of-range")
        return None
    return value


def _limbs(reader: Reader) -> tuple[tuple[str, int], ...]:
    spec = reader.mapping(("limbs",), "limbs")
    reader.unknown_keys(("limbs",), spec, LIMB_KEYS, "limb threshold")
    found = []
    for key in LIMB_KEYS:
        if key in LIMB_DEFAULTS and (not isinstance(spec, dict) or key not in spec):
            found.append((key, LIMB_DEFAULTS[key]))
            continue
        value = _positive(reader, ("limbs", key), key)
        if value is not None:
            found.append((key, value))
    return tuple(found)


def _fraction(reader: Reader, path: YPath, what: str, *, required: bool = True) -> float | None:
    value = reader.get(path)
    if value is None:
        if required:
            reader.missing(path, what)
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not 0 < value <= 1:
        reader.fault(
            path, f"{what} must be a number in (0, 1], got {type_name(value)}", code="out-of-range"
        )
        return None
    return float(value)


def _conditions(reader: Reader, path: YPath) -> tuple[FeatureCondition, ...]:
    raw = reader.get(path)
    if raw is None:
        return ()
    spec = reader.mapping(path, "conditions (feature -> value)")
    found = []
    for feature, value in spec.items():
        item = (*path, feature)
        if feature not in FEATURES:
            reader.fault(
                item,
                f"unknown feature {shown(feature, quoted=True)}{did_you_mean(feature, FEATURES)}; "
                f"features: {', '.join(FEATURES)}",
                key=True,
                code="unknown-reference",
            )
            continue
        if isinstance(value, bool):
            found.append(FeatureCondition(feature, int(value), int(value)))
        elif isinstance(value, int):
            found.append(FeatureCondition(feature, value, value))
        elif isinstance(value, dict):
            bounds = reader.mapping(item, "bounds")
            reader.unknown_keys(item, bounds, {"min", "max"}, "bound")
            low = reader.integer((*item, "min"), "min", required=False)
            high = reader.integer((*item, "max"), "max", required=False)
            if low is None and high is None:
                reader.fault(item, "give min and/or max", code="missing-field")
            found.append(FeatureCondition(feature, low, high))
        else:
            reader.fault(
                item,
                f"a condition is a number, true/false or {{min, max}}, got {type_name(value)}",
                code="wrong-type",
            )
    return tuple(found)


def _structures(reader: Reader) -> tuple[StructureRule, ...]:
    raw = reader.get(("structures",))
    if not isinstance(raw, list) or not raw:
        reader.fault(
            ("structures",),
            f"structures must be a non-empty list, got {type_name(raw)}",
            code="wrong-type",
        )
        return ()
    found: list[StructureRule] = []
    for index in range(len(raw)):
        path: YPath = ("structures", index)
        spec = reader.mapping(path, "structure")
        if not spec:
            continue
        reader.unknown_keys(path, spec, _STRUCTURE_KEYS, "structure field")
        name = reader.string((*path, "name"), "structure name")
        if name and any(rule.name == name for rule in found):
            reader.fault(
                (*path, "name"),
                f"duplicate structure {shown(name, quoted=True)}",
                code="duplicate-value",
            )
        if "when" not in spec:
            reader.missing((*path, "when"), "when (write {} to match every body)")
        kinds = (
            [text for _, text in reader.names((*path, "kinematic_types"), "kinematic types")]
            if spec.get("kinematic_types") not in (None, [])
            else []
        )
        if "kinematic_types" not in spec:
            reader.missing((*path, "kinematic_types"), "kinematic_types (may be [])")
        confidence = _fraction(reader, (*path, "confidence"), "confidence")
        found.append(
            StructureRule(
                name,
                _conditions(reader, (*path, "when")),
                _conditions(reader, (*path, "expect")),
                tuple(kinds),
                confidence or 0.5,
                reader.document.location(path),
            )
        )
    return tuple(found)


def _types(reader: Reader, path: YPath) -> frozenset[str]:
    return frozenset(_message_type(text) for _, text in reader.names(path, "types"))


def _message_type(text: str) -> str:
    """ROS 2 spelling (``pkg/msg/Name``) -> ROS 1 spelling (``pkg/Name``); the profile's too."""
    parts = text.strip().split("/")
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        return f"{parts[0]}/{parts[2]}"
    return text.strip()


def _list(reader: Reader, path: YPath) -> list[Any]:
    raw = reader.get(path)
    if not isinstance(raw, list):
        reader.fault(path, f"must be a list, got {type_name(raw)}", code="wrong-type")
        return []
    return raw


def _rules(
    reader: Reader, path: YPath, what: str, keys: set[str]
) -> Iterator[tuple[YPath, dict[str, Any]]]:
    """Each rule of the list at ``path`` (a mapping; others are located faults) with its path,
    its fields checked against ``keys``."""
    for index in range(len(_list(reader, path))):
        item: YPath = (*path, index)
        spec = reader.mapping(item, what)
        if spec:
            reader.unknown_keys(item, spec, keys, f"{what} field")
            yield item, spec


def _sensor_rules(
    reader: Reader, path: YPath, keys: set[str], *, types: bool, messages: bool = False
) -> tuple[SensorRule, ...]:
    found = []
    for item, spec in _rules(reader, path, "sensor rule", keys):
        kind = reader.string((*item, "kind"), "sensor kind")
        match = _pattern(reader, (*item, "match"), required=not types)
        allowed: frozenset[str] = frozenset()
        if types:
            written = _types(reader, (*item, "types"))
            # Gazebo sensor types are case-insensitive words; message types keep their case.
            allowed = written if messages else frozenset(t.lower() for t in written)
        direction = _direction(reader, item, spec)
        rays = reader.integer((*item, "max_rays"), "most rays", required=False)
        if rays is not None and rays < 1:
            reader.fault((*item, "max_rays"), f"max_rays must be 1 or more, got {rays}")
            rays = None
        wider = reader.integer((*item, "wider_than"), "degrees", required=False)
        if wider is not None and not 0 <= wider < _FULL_TURN:
            reader.fault((*item, "wider_than"), f"wider_than must be 0 to 359 degrees, got {wider}")
            wider = None
        reach = reader.integer((*item, "max_range"), "metres", required=False)
        if reach is not None and reach < 1:
            reader.fault((*item, "max_range"), f"max_range must be 1 metre or more, got {reach}")
            reach = None
        location = reader.document.location(item)
        found.append(SensorRule(kind, allowed, match, direction, location, rays, wider, reach))
    return tuple(found)


def _direction(reader: Reader, item: YPath, spec: dict[str, Any]) -> str | None:
    if "direction" not in spec:
        return None
    direction = reader.string((*item, "direction"), "direction")
    if direction not in DIRECTIONS:
        reader.fault(
            (*item, "direction"),
            f"direction must be one of {', '.join(DIRECTIONS)}, got "
            f"{shown(direction, quoted=True)}",
            code="out-of-range",
        )
        return None
    return direction


def _control_rules(reader: Reader) -> tuple[ControlRule, ...]:
    path: YPath = ("topics", "controls")
    found = []
    for item, spec in _rules(reader, path, "control rule", _TOPIC_CONTROL_KEYS):
        control = reader.string((*item, "control"), "motion control")
        found.append(
            ControlRule(
                control,
                _types(reader, (*item, "types")),
                _pattern(reader, (*item, "match"), required=False),
                _direction(reader, item, spec),
                reader.document.location(item),
            )
        )
    return tuple(found)


def _sensor_types(reader: Reader) -> tuple[SensorTypeMapping, ...]:
    spec = reader.mapping(("sensor_types",), "sensor_types (kind -> sensor type)")
    found = []
    for kind, value in spec.items():
        path: YPath = ("sensor_types", kind)
        if isinstance(value, dict):
            planes = reader.mapping(path, "plane mapping")
            reader.unknown_keys(path, planes, _LIDAR_KEYS, "plane mapping field")
            found.append(
                SensorTypeMapping(
                    kind,
                    None,
                    reader.string((*path, "single_plane"), "single_plane"),
                    reader.string((*path, "multi_plane"), "multi_plane"),
                )
            )
        elif value is None:
            found.append(SensorTypeMapping(kind))
        else:
            found.append(SensorTypeMapping(kind, reader.string(path, "sensor type")))
    return tuple(found)


def _motion(
    reader: Reader, structures: set[str]
) -> tuple[str, tuple[tuple[str, str], ...], tuple[tuple[str, tuple[str, ...]], ...]]:
    spec = reader.mapping(("motion",), "motion")
    reader.unknown_keys(
        ("motion",),
        spec,
        {"velocity", "description", "navigation", "packages", "gait", "flight"},
        "motion field",
    )
    velocity = reader.mapping(("motion", "velocity"), "velocity")
    reader.unknown_keys(
        ("motion", "velocity"), velocity, {"default", "by_structure"}, "velocity field"
    )
    default = reader.string(("motion", "velocity", "default"), "default velocity control")
    by_path: YPath = ("motion", "velocity", "by_structure")
    by_structure = reader.mapping(by_path, "by_structure", required=False)
    pairs = []
    for structure in by_structure:
        if not _known_structure(reader, (*by_path, structure), structure, structures, key=True):
            continue
        pairs.append((structure, reader.string((*by_path, structure), "motion control")))
    description = reader.mapping(("motion", "description"), "description controls")
    reader.unknown_keys(
        ("motion", "description"), description, CONTROL_SOURCES, "description source"
    )
    sources = []
    for source in CONTROL_SOURCES:
        if source in description:
            names = reader.names(("motion", "description", source), "motion controls")
            sources.append((source, tuple(text for _, text in names)))
    return default, tuple(pairs), tuple(sources)


def _known_structure(
    reader: Reader, path: YPath, structure: str, structures: set[str], *, key: bool = False
) -> bool:
    """``structure`` is one of the profile's; else a located fault (``key``: at the key)."""
    if structure in structures:
        return True
    reader.fault(
        path,
        f"unknown structure {shown(structure, quoted=True)}{did_you_mean(structure, structures)}",
        key=key,
        code="unknown-reference",
    )
    return False


def _package_rules(reader: Reader, structures: set[str]) -> tuple[PackageRule, ...]:
    """``motion.packages`` (optional): what a text of the robot's packages shows."""
    path: YPath = ("motion", "packages")
    if reader.get(path) is None:
        return ()
    found = []
    for item, spec in _rules(reader, path, "package rule", _PACKAGE_KEYS):
        control = reader.string((*item, "control"), "motion control")
        match = _pattern(reader, (*item, "match"))
        unless = _pattern(reader, (*item, "unless"), required=False)
        not_for, only_for = (
            _listed_structures(reader, (*item, key), structures) if key in spec else frozenset()
            for key in ("not_for", "only_for")
        )
        if control and match is not None:
            found.append(
                PackageRule(
                    control, match, not_for, reader.document.location(item), unless, only_for
                )
            )
    return tuple(found)


def _listed_structures(reader: Reader, path: YPath, structures: set[str]) -> frozenset[str]:
    """A list of the profile's structures at ``path``; an unknown one is a located fault."""
    listed = reader.names(path, "structures")
    for where, structure in listed:
        _known_structure(reader, where, structure, structures)
    return frozenset(structure for _, structure in listed)


def _software(reader: Reader, key: str) -> SoftwareRule | None:
    """``motion.gait`` or ``motion.flight`` (optional): the body's software shipped, joint
    controllers configured."""
    path: YPath = ("motion", key)
    spec = reader.mapping(path, key, required=False)
    if not spec:
        return None
    reader.unknown_keys(
        path, spec, {"shipped", "controllers", "per_joint", "named"}, f"{key} field"
    )
    shipped = _pattern(reader, (*path, "shipped"))
    controllers = _pattern(reader, (*path, "controllers"))
    if shipped is None or controllers is None:
        return None
    per_joint = _pattern(reader, (*path, "per_joint"), required=False)
    named = _pattern(reader, (*path, "named"), required=False)
    return SoftwareRule(shipped, controllers, per_joint, named)


def _navigation(
    reader: Reader, description: tuple[tuple[str, tuple[str, ...]], ...]
) -> NavigationRule | None:
    """``motion.navigation`` (optional): the control, and per description source (or control)
    that moves the body the sensor kinds its navigation needs."""
    path: YPath = ("motion", "navigation")
    spec = reader.mapping(path, "navigation", required=False)
    if not spec:
        return None
    reader.unknown_keys(path, spec, {"control", "needs"}, "navigation field")
    control = reader.string((*path, "control"), "motion control")
    needs = reader.mapping((*path, "needs"), "needs")
    movers = {*CONTROL_SOURCES, *(name for _, names in description for name in names)}
    reader.unknown_keys((*path, "needs"), needs, movers, "navigation source")
    found = []
    for moving in needs:
        kinds = reader.names((*path, "needs", moving), "sensor kinds")
        found.append((moving, tuple(text for _, text in kinds)))
    return NavigationRule(control, tuple(found))
