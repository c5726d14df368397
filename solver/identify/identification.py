"""Identifying one robot: structure, kinematic type, sensors and motion controls, with evidence.

Two entry points:

* :func:`identify_urdf` works on URDF *text* (and optional SRDF text and topic triples). It
  reads no files, so it serves a description fetched from ``/robot_description`` on a live
  ROS master as well as a file. It is a pure function of its inputs: :func:`content_key`
  names a result by the content it came from, and :class:`IdentificationCache` keeps results
  by that key, so a watcher that sees the same description again does no work::

      cache = IdentificationCache()
      result = cache.identify_urdf(urdf_text, topics=[TopicSource("master", triples)])

* :func:`identify` reads files: a URDF, or a xacro the caller trusts (compiled first in a limited
  child process, :mod:`solver.identify.xacro.compiler`),
  an SRDF, topic lists and bags, and the robot's teleoperation description (``ROBOT.teleop.yaml``
  beside the URDF, or one named), then calls :func:`identify_urdf`.

A teleoperation description (:mod:`solver.ros.description`) is the robot's own word: its values
win over what identification reads or guesses, each disagreement said
(:mod:`solver.identify.declared`). Like an SRDF it is a supporting file: one that cannot be read
is a located warning, and the robot is identified without it.

The rule set decides the kinematic types and sensor types results are mapped to (default: the
article's); the profile (:mod:`solver.identify.profile`) holds every pattern and threshold.

Not here: UI configurations for the result (:mod:`solver.identify.combinations`), folders of
robots (:mod:`solver.identify.fleet`), rendering (:mod:`solver.identify.render`).
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from solver.core.rules import default_rules_path, load_rules
from solver.core.ruleset import RuleSet
from solver.errors import Fault, InputError, SolverError
from solver.identify.body import Body, detect_body
from solver.identify.classifier import classify
from solver.identify.declared import Characteristics, with_declared
from solver.identify.frames import sensors_on_frames
from solver.identify.interfaces import (
    Control,
    controls_from_topics,
    merge_controls,
    sensors_from_topics,
)
from solver.identify.joints import command_joints
from solver.identify.motion import controls_from_description
from solver.identify.profile import Profile, SoftwareRule, load_profile
from solver.identify.readers.safexml import read_bytes
from solver.identify.readers.urdf import Urdf, parse_urdf
from solver.identify.roles import Role
from solver.identify.sensors import (
    Detection,
    Sensor,
    merge,
    presented_count,
    sensors_from_urdf,
    under_water,
)
from solver.identify.shipped import (
    body_from_workspace,
    controller_joints,
    controls_from_workspace,
    joint_controllers,
    named_joints,
    per_joint_controllers,
)
from solver.limits import limit
from solver.ros.description import TeleopDescription, description_beside, load_description
from solver.ros.joints import JointStart
from solver.ros.names import Topic

if TYPE_CHECKING:
    from solver.identify.readers.srdf import Srdf
    from solver.identify.readers.workspace import Workspace

__all__ = [
    "Identification",
    "IdentificationCache",
    "TopicSource",
    "content_key",
    "identify",
    "identify_urdf",
    "is_xacro",
]


@dataclass(frozen=True, slots=True)
class TopicSource:
    """Topics from one place (a topic list, a bag, a ROS master), named for the evidence."""

    name: str
    topics: tuple[Topic, ...]


@dataclass(frozen=True)
class Identification:
    """What one robot is: the JSON contract of ``teleop-ui identify`` (see the README)."""

    robot: str
    file: str
    structure: str
    kinematic_type: str | None
    confidence: float
    evidence: tuple[str, ...]
    sensors: tuple[Sensor, ...]
    motion_controls: tuple[Control, ...]
    body: Body | None = None
    notes: tuple[str, ...] = ()
    # Local flaws of the description or SRDF read past, each located (file, line, message).
    warnings: tuple[Fault, ...] = ()
    # The structure rules tried in order, each with why it held or not (``--explain``).
    decision: tuple[str, ...] = ()
    # The joints a joint command names, each with a safe start (solver.identify.joints).
    joints: tuple[JointStart, ...] = ()
    # The teleoperation description whose declared values this result holds, and where they
    # differ from what identification read (solver.identify.declared).
    declared: str | None = None
    disagreements: tuple[str, ...] = ()

    @property
    def roles(self) -> tuple[Role, ...]:
        """Every moving joint's role, with the evidence that decided it."""
        return () if self.body is None else self.body.roles

    @property
    def sensor_count(self) -> int:
        """Sensors with a presentation in the rule set (the article's No. of Sensors)."""
        return presented_count(self.sensors)

    @property
    def sensor_types(self) -> tuple[str, ...]:
        return tuple(
            dict.fromkeys(s.sensor_type for s in self.sensors if s.sensor_type is not None)
        )


def content_key(
    urdf_text: str | bytes,
    *,
    srdf_text: str | bytes | None = None,
    topics: Sequence[TopicSource] = (),
    profile: Profile | None = None,
    rules: RuleSet | None = None,
) -> str:
    """A digest naming an identification by everything it depends on."""
    digest = hashlib.sha256()
    for part in (urdf_text, srdf_text or b""):
        data = part.encode("utf-8") if isinstance(part, str) else part
        digest.update(len(data).to_bytes(8, "big") + data)
    for source in topics:
        digest.update(repr((source.name, source.topics)).encode("utf-8"))
    digest.update((profile.digest if profile is not None else "default-profile").encode())
    digest.update(repr(rules).encode("utf-8") if rules is not None else b"default-rules")
    return digest.hexdigest()


def identify_urdf(
    urdf_text: str | bytes | Urdf,
    *,
    file: str = "<string>",
    robot: str | None = None,
    srdf_text: str | bytes | None = None,
    srdf_file: str = "<srdf>",
    topics: Sequence[TopicSource] = (),
    rules: RuleSet | None = None,
    profile: Profile | None = None,
    notes: Sequence[str] = (),
    description: TeleopDescription | None = None,
    warnings: Sequence[Fault] = (),
    packages: Workspace | None = None,
) -> Identification:
    """Identify a robot from URDF text (or a description already parsed, read tolerantly);
    :class:`~solver.errors.InputError` if unusable.

    ``description``: the robot's teleoperation description, whose values win; ``warnings``:
    flaws of supporting files read before (a description that could not be read);
    ``packages``: the robot's packages, whose launch, configuration and script files show
    the controls they ship (:mod:`solver.identify.shipped`)."""
    rules = rules if rules is not None else load_rules(default_rules_path())
    profile = profile if profile is not None else load_profile()
    urdf = _parsed(urdf_text, file)
    srdf, srdf_warnings = (None, ()) if srdf_text is None else _srdf(srdf_text, srdf_file, urdf)
    found_warnings = (*urdf.warnings, *srdf_warnings, *warnings)
    body = detect_body(urdf, profile)
    if packages is not None:
        body = body_from_workspace(body, packages, profile)
    reading = classify(body, profile, rules, root=urdf.root, srdf=srdf, urdf=urdf)
    detections: list[Detection] = list(sensors_from_urdf(urdf, profile))
    if packages is not None:
        detections += sensors_on_frames(packages, urdf, profile, detections)
    # A body in water that nothing places at the surface dives: its barometer is a depth gauge.
    dives = body.marine and not body.surface_hints
    if dives:
        detections = list(under_water(detections))
    # A rig of sensors a vehicle carries: its packages' controls move the vehicle.
    shipped = (
        ()
        if packages is None or body.carried_rig
        else controls_from_workspace(packages, profile, reading.structure)
    )
    legs = _limb_joints(body, "leg")
    controls = [
        controls_from_description(
            body,
            profile,
            srdf,
            urdf=urdf,
            sensor_kinds={d.kind for d in detections},
            srdf_source=Path(srdf_file).name,
            guess_software=packages is None or not packages.complete,
            named=_named(packages, body),
            leg_controllers=_joint_controllers(packages, profile.gait, legs),
            leg_joint_controllers=_own_controllers(packages, profile.gait, legs),
            rotor_controllers=_joint_controllers(packages, profile.flight, body.rotors),
            mount_joint_controllers=_own_controllers(packages, profile.gait, _vehicle_mounts(body)),
            head_joint_controllers=_own_controllers(
                packages, profile.gait, _limb_joints(body, "head")
            ),
            vehicle_joint_controllers=_given_controllers(
                packages, profile.gait, _vehicle_joints(body)
            ),
        ),
        shipped,
    ]
    if packages is not None:
        notes = (*notes, *packages.notes)
    for source in topics:
        topical = sensors_from_topics(source.topics, profile, source.name)
        detections += under_water(topical) if dives else topical
        controls.append(
            controls_from_topics(source.topics, profile, reading.structure, source.name)
        )
    found = Characteristics(
        reading.structure,
        reading.kinematic_type,
        merge_controls(*controls),
        merge(detections, profile, rules),
    )
    evidence = reading.evidence
    if packages is not None:
        read = packages.shown_packages
        evidence = (*evidence, f"packages read for the controls they ship: {read}")
    if description is not None:
        found = with_declared(found, description, profile, rules)
        evidence = (*evidence, f"declared: {Path(description.file).name} (its values win)")
    return Identification(
        robot=robot or urdf.name,
        file=file,
        structure=found.structure,
        kinematic_type=found.kinematic_type,
        confidence=reading.confidence,
        evidence=evidence,
        sensors=found.sensors,
        motion_controls=found.motion_controls,
        body=body,
        notes=tuple(notes),
        warnings=found_warnings,
        decision=reading.path,
        joints=command_joints(urdf, body),
        declared=None if description is None else description.file,
        disagreements=found.disagreements,
    )


def _parsed(urdf: str | bytes | Urdf, file: str) -> Urdf:
    """The description, parsed tolerantly from its text unless it already is."""
    return urdf if isinstance(urdf, Urdf) else parse_urdf(urdf, file, strict=False)


def _joint_controllers(
    packages: Workspace | None, rule: SoftwareRule | None, joints: Collection[str]
) -> str | None:
    """The file of the robot's packages that configures the ``joints``' controllers (its legs',
    its rotors'), when they ship none of the body's own software (``rule``: a gait, flight
    software; :func:`~solver.identify.shipped.joint_controllers`); else None."""
    return None if packages is None else joint_controllers(packages, rule, joints)


def _own_controllers(
    packages: Workspace | None, rule: SoftwareRule | None, joints: Collection[str]
) -> str | None:
    """The file of the robot's packages that configures a controller of one of the
    ``joints``' own (:func:`~solver.identify.shipped.per_joint_controllers`); else None."""
    return None if packages is None else per_joint_controllers(packages, rule, joints)


def _given_controllers(
    packages: Workspace | None, rule: SoftwareRule | None, joints: Collection[str]
) -> str | None:
    """The controller configuration of the robot's packages that gives a joint controller one
    of the ``joints`` (:func:`~solver.identify.shipped.controller_joints`, with the ``rule``'s
    controllers); else None."""
    if packages is None or rule is None:
        return None
    return controller_joints(packages, rule.controllers, joints)


def _vehicle_joints(body: Body) -> list[str]:
    """The joints a ground vehicle moves besides its wheels' spin: its mounts' (a suspension,
    a steered axle, a wheel-leg's hip; not a joint read as steering) and its heads' (a
    sensor's pan or tilt); none on a body that is no ground vehicle."""
    if not body.mobile_base or body.flying or body.marine:
        return []
    return [*_limb_joints(body, "mount"), *_limb_joints(body, "head")]


def _limb_joints(body: Body, kind: str) -> list[str]:
    """The joints of the body's limbs of ``kind`` (legs; heads, pan/tilt units pointing a
    sensor)."""
    return [j for limb in body.limbs if limb.kind == kind for j in limb.joints]


def _vehicle_mounts(body: Body) -> list[str]:
    """The joints of the mounts that carry a flown or swimming body's rotors or thrusters (a
    tilting rotor's arm); none on the ground, where a mount carries a wheel."""
    return _limb_joints(body, "mount") if body.flying or body.marine else []


def _named(packages: Workspace | None, body: Body) -> frozenset[str] | None:
    """The arms' joints the robot's packages name, when they were read whole and an arm may be
    only drawn (:func:`~solver.identify.motion.controls_from_description`: a body that moves
    by itself, :attr:`Body.carries_itself`); else None."""
    arms = {j for limb in body.limbs if limb.kind == "arm" for j in limb.joints}
    if packages is None or not packages.complete or not arms or not body.carries_itself:
        return None
    return named_joints(packages, arms)


def _srdf(text: str | bytes, file: str, urdf: Urdf) -> tuple[Srdf | None, tuple[Fault, ...]]:
    """The SRDF and its flaws. An SRDF is supporting evidence: one that cannot be read at all
    (not XML, a comment XML rejects, hostile declarations, not a ``<robot>``) is not read, each
    of its problems a located warning, and the URDF is identified alone."""
    from solver.identify.readers.srdf import parse_srdf  # loaded when there is an SRDF

    try:
        srdf = parse_srdf(text, file, urdf, strict=False)
    except InputError as error:
        return None, tuple(
            Fault(f.location, f"{f.message} (the SRDF is not read; the URDF alone is)", f.code)
            for f in error.faults
        )
    return srdf, srdf.warnings


def is_xacro(path: str | Path) -> bool:
    """A file to compile with xacro: its name ends in ``.xacro``.

    The content is not looked at: most expanded URDFs still declare the xacro namespace
    (xacro writes it), and a ``.urdf`` is read as URDF whatever it declares.
    """
    return str(path).endswith(".xacro")


def identify(
    description: str | Path,
    *,
    srdf: str | Path | None = None,
    topic_lists: Sequence[str | Path] = (),
    bags: Sequence[str | Path] = (),
    xacro_args: Mapping[str, str] | None = None,
    package_path: Sequence[str | Path] = (),
    rules: RuleSet | None = None,
    profile: Profile | None = None,
    trust_xacro: bool = False,
    teleop: str | Path | None = None,
    look_beside: bool = True,
    package: str | Path | None = None,
    workspace: str | Path | None = None,
    look_around: bool = True,
) -> Identification:
    """Identify the robot described by a URDF or xacro file (plus SRDF, topic lists, bags).

    A ``.xacro`` file is compiled only with ``trust_xacro=True`` (compiling xacro runs code
    from the file: :mod:`solver.identify.xacro.compiler`); any other file is read as URDF.
    ``teleop`` names the robot's teleoperation description; without it, ``ROBOT.teleop.yaml``
    beside the file is read when there is one (``look_beside=False``: never).
    ``package`` names the description's ROS package folder; without it, the package holding
    the file (``look_around=False``: none). The robot's packages in ``workspace`` (default: the
    ``src`` folder above the package, else the folder above it) are read for the controls they
    ship (:mod:`solver.identify.readers.workspace`); a folder named and not used is a note.
    """
    file = str(description)
    # How many files were given is known before any is read: refuse first, read nothing.
    limit("topic-lists").check(len(topic_lists), "--topics")
    limit("bags").check(len(bags), "--bag")
    notes: tuple[str, ...] = ()
    if is_xacro(file):
        if not trust_xacro:
            raise InputError.at(
                file,
                "xacro file: compiling xacro runs Python code written in "
                "the file; pass --trust-xacro for a file you trust, or "
                "give its expanded .urdf",
                code="xacro-untrusted",
            )
        # The sandbox's parent (and the child process it starts) is loaded for this case only.
        from solver.identify.xacro.compiler import compile_xacro

        compiled = compile_xacro(description, args=xacro_args, package_path=package_path)
        text: str | bytes = compiled.text
        notes = tuple(f"xacro: {warning}" for warning in compiled.warnings)
    else:
        text = read_bytes(description)
    srdf_text = None if srdf is None else read_bytes(srdf)
    # The readers of topic lists and bags are loaded when there are some to read.
    sources = _listed_topics(topic_lists) if topic_lists else []
    if bags:
        from solver.identify.readers.bags import read_bag_topics

        sources += [TopicSource(f"bag {Path(b).name}", read_bag_topics(b)) for b in bags]
    beside = description_beside(file) if teleop is None and look_beside else None
    if beside is not None and beside.is_file():
        teleop = beside
    declared, flaws = _description(teleop)
    urdf = parse_urdf(text, file, strict=False)
    around, unused = _packages(file, package, workspace, look_around, urdf.name)
    return identify_urdf(
        urdf,
        file=file,
        srdf_text=srdf_text,
        srdf_file=str(srdf) if srdf is not None else "<srdf>",
        topics=sources,
        rules=rules,
        profile=profile,
        notes=(*notes, *unused),
        description=declared,
        warnings=flaws,
        packages=around,
    )


def _packages(
    file: str,
    package: str | Path | None,
    workspace: str | Path | None,
    look_around: bool,
    robot: str,
) -> tuple[Workspace | None, tuple[str, ...]]:
    """The packages of the ``robot`` (the name its URDF gives it) around ``file`` (or in the
    ``package`` named), and a note for a folder the caller named that is not used. A
    description in no package is read with the repository the ``workspace`` names
    (:func:`~solver.identify.readers.workspace.read_repository`), never one found around it."""
    from solver.identify.readers.workspace import (
        description_package,
        read_repository,
        read_workspace,
    )

    named = package is not None
    if package is None and look_around:
        package = description_package(file)
    if package is None:
        if workspace is None:
            return None, ()
        read = read_repository(workspace, file, robot)
        if read is None:
            return None, (f"workspace {workspace}: no folder there; none is read",)
        return read, ()
    around = read_workspace(package, workspace, robot)
    if around is None and named:
        return None, (f"package {package}: no package.xml names a package there; none is read",)
    return around, ()


def _description(
    path: str | Path | None,
) -> tuple[TeleopDescription | None, tuple[Fault, ...]]:
    """The teleoperation description at ``path``; one that cannot be read (not YAML, not a
    description, past a limit) is each of its problems as a located warning, and not used."""
    if path is None:
        return None, ()
    try:
        return load_description(path, display=str(path)), ()
    except SolverError as error:
        return None, tuple(
            Fault(f.location, f"{f.message} (the teleoperation description is not read)", f.code)
            for f in error.faults
        )


def _listed_topics(topic_lists: Sequence[str | Path]) -> list[TopicSource]:
    from solver.identify.readers.topics import read_topic_list

    sources = []
    read = 0  # topic lines of all the lists together count against one limit
    for topics_file in topic_lists:
        topics = read_topic_list(topics_file, before=read)
        read += len(topics)
        sources.append(TopicSource(Path(topics_file).name, topics))
    return sources


class IdentificationCache:
    """Identifications kept by :func:`content_key`, least recently used dropped first."""

    def __init__(self, maxsize: int = 128) -> None:
        self.maxsize = maxsize
        self._entries: OrderedDict[str, Identification] = OrderedDict()
        self.hits = 0
        self.misses = 0

    def __len__(self) -> int:
        return len(self._entries)

    def identify_urdf(
        self,
        urdf_text: str | bytes,
        *,
        srdf_text: str | bytes | None = None,
        topics: Sequence[TopicSource] = (),
        rules: RuleSet | None = None,
        profile: Profile | None = None,
        file: str = "<string>",
        robot: str | None = None,
        description: TeleopDescription | None = None,
        warnings: Sequence[Fault] = (),
    ) -> Identification:
        """:func:`identify_urdf`, answered from the cache when the content was seen before."""
        # A description is named by a digest: a key holds no stranger's megabyte.
        declared = hashlib.sha256(repr((description, tuple(warnings))).encode()).hexdigest()
        key = (
            content_key(urdf_text, srdf_text=srdf_text, topics=topics, profile=profile, rules=rules)
            + f"|{file}|{robot}|{declared}"
        )
        found = self._entries.get(key)
        if found is not None:
            self.hits += 1
            self._entries.move_to_end(key)
            return found
        self.misses += 1
        result = identify_urdf(
            urdf_text,
            file=file,
            robot=robot,
            srdf_text=srdf_text,
            topics=topics,
            rules=rules,
            profile=profile,
            description=description,
            warnings=warnings,
        )
        self._entries[key] = result
        if len(self._entries) > self.maxsize:
            self._entries.popitem(last=False)
        return result
