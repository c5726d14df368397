"""Motion controls the robot's packages ship: what their launch, configuration and script
files run, read as text (:mod:`solver.identify.readers.workspace` finds and reads them).

The profile's ``motion.packages`` rules say which texts mean which control: a bringup that
runs Nav2 or move_base, a script that streams MAVROS position set-points or follows waypoints
(Waypoint); a teleop node (a velocity control, read by structure as topics are: Driving for a
base, Flight for a drone, Walking for a walker), and the navigation above for a body on the
ground, which the stack drives (Driving); a MoveIt ``move_group`` or servo (End Effector). A
rule may exclude structures (no navigation for an arm bolted to a table, whatever its
repository holds), or name the only ones it is read for. Each control names the file that
shows it, the first one found in the order the packages were read (the description's package
first).

The same texts tell a body's own software from its joint controllers: packages read whole
with a file that configures joint controllers naming a joint of its legs, shipping no gait (no
walking software, velocity command, teleop or joystick) beside a workspace with no package
or file named for one, command its joints one by one, and no gait is guessed for its legs; a flown
body's packages that so name its rotors (by their names after a namespace) and ship no flight
software (an attitude controller, a flight stack, a teleop) command its rotors one by one, and
no flight is guessed (:func:`joint_controllers`, with the profile's ``motion.gait`` or
``motion.flight``).

The same texts say what a body travels in when its description shows no way at all (one link
and its mesh, a few sensor frames: a drone a simulator poses, an AUV drawn for RViz), or only
a drive plugin that slides it, nothing of it on the ground (:attr:`Body.moved_by_plugin_alone`):
the profile's ``body_packages`` words (a take-off command, a flight stack; a submersible's or a
surface craft's words; a ground vehicle's or its drive's) found in the robot's packages fly it,
put it in water or on the ground, with doubt
(:func:`body_from_workspace`). Packages of two kinds of vehicle say nothing.

What the packages ship is the robot's author's word, stronger than a guess: when they were read
whole (``Workspace.complete``), the description's navigation guess is not made
(:func:`solver.identify.motion.controls_from_description`); they ship navigation or they do
not. When a bound stopped the reading, the guess stays.
"""

from __future__ import annotations

import re
import string
from collections.abc import Callable, Collection
from dataclasses import replace

from solver.errors import InputError
from solver.files.yamlio import parse_document
from solver.identify.body import Body
from solver.identify.interfaces import Control
from solver.identify.profile import (
    GROUND,
    NAVIGATION_VELOCITY,
    VELOCITY,
    PackageRule,
    Pattern,
    Profile,
    SoftwareRule,
)
from solver.identify.readers.workspace import Workspace
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "body_from_workspace",
    "controller_joints",
    "controls_from_workspace",
    "joint_controllers",
    "named_joints",
    "per_joint_controllers",
]


def controls_from_workspace(
    workspace: Workspace, profile: Profile, structure: str
) -> tuple[Control, ...]:
    """One control per rule that a file of the robot's packages matches, with the first file
    (in the order the packages were read) that one of the control's rules matches."""
    rules: dict[str, list[PackageRule]] = {}
    for rule in profile.package_controls:
        if rule.reads(structure):
            control = (
                profile.velocity_control(structure)
                if rule.control in (VELOCITY, NAVIGATION_VELOCITY)
                else rule.control
            )
            rules.setdefault(control, []).append(rule)
    found = {
        control: shown_file
        for control, listed in rules.items()
        if (shown_file := _first_found(workspace, *listed)) is not None
    }
    return tuple(Control(control, source) for control, source in found.items())


def body_from_workspace(body: Body, workspace: Workspace, profile: Profile) -> Body:
    """``body`` travelling in the medium the robot's packages name, when its description shows
    no way of travelling (:attr:`Body.travels_no_way`) or a drive plugin alone moves it
    (:attr:`Body.moved_by_plugin_alone`), and the packages name one medium only
    (a repository of drones and boats says nothing of this one); a pan/tilt head alone driven
    by a teleop node its packages ship (:func:`_driven`). The ground is read only for a body
    with no head: a pan/tilt unit in a rover's packages is the rover's sensor head, no rover.
    A ground word beside another medium's says nothing either way (a flight stack that lists
    rovers among its vehicles, a rover's packages that mention a drone). A body named for a
    rig of sensors (:attr:`Body.rig_name`: a sensor kit a vehicle carries) is not read: its
    packages' vehicle is the one that carries it."""
    if body.rig_name:
        return body
    body = _driven(body, workspace, profile)
    if not (body.travels_no_way or body.moved_by_plugin_alone):
        return body
    said = {
        medium: shown_file
        for medium, pattern in profile.body_packages
        if (medium != GROUND or not body.count("head"))
        and (shown_file := _first_found(workspace, pattern, skip=_label_map)) is not None
    }
    if len(said) != 1:
        return body
    ((medium, evidence),) = said.items()
    return replace(body, shipped_as=medium, shipped_by=evidence)


def _label_map(text: str) -> bool:
    """``text`` lists an object detector's classes (a ``boat`` among them is what the robot
    sees, none of its own): :data:`_LABEL_MAP_CLASSES` of the classes
    of COCO or Pascal VOC that no robot's software names otherwise (``teddy bear``,
    ``fire hydrant``, ``pottedplant``)."""
    found = {re.sub("[ _]", "", m.group(0).lower()) for m in _DETECTOR_CLASS.finditer(text)}
    return len(found) >= _LABEL_MAP_CLASSES


# Classes of COCO's and Pascal VOC's label maps a robot's own software has no word for, and
# how many of them make a file a label map.
_DETECTOR_CLASS = re.compile(
    r"teddy[ _]?bear|hair[ _]?drier|toothbrush|fire[ _]?hydrant|parking[ _]?meter|"
    r"potted[ _]?plant|dining[ _]?table|tv[ _]?monitor|wine[ _]?glass|baseball[ _]?(bat|glove)|"
    r"tennis[ _]?racket|sports[ _]?ball|hot[ _]?dog|aeroplane|giraffe|zebra",
    re.IGNORECASE,
)
_LABEL_MAP_CLASSES = 3


def _driven(body: Body, workspace: Workspace, profile: Profile) -> Body:
    """``body``, driven by the file of its packages that runs a teleop node (a velocity
    control rule), when it is a pan/tilt head alone: its description was trimmed to a base's
    sensor head, and it is no pan/tilt unit (:attr:`Body.head_alone`)."""
    if not body.head_alone:
        return body
    for rule in profile.package_controls:
        if rule.control == VELOCITY and (found := _first_found(workspace, rule)):
            return replace(body, driven_by=found)
    return body


def joint_controllers(
    workspace: Workspace, rule: SoftwareRule | None, joints: Collection[str]
) -> str | None:
    """The first file of the robot's packages that configures joint controllers and names one
    of the ``joints`` (a walker's legs', a flown body's rotors'), when the packages were read
    whole, none ships the body's own software (``rule``: the profile's ``motion.gait`` or
    ``motion.flight``) and no package of the workspace is named for it (one of its own, or a
    ``gait_planner`` beside them that names none of them), nor a file of its packages (the
    rule's ``named``: ``normal_walk.py``): a body whose author ships those
    joints' controllers and nothing that moves the body as a whole is commanded joint by joint,
    whatever it could do (:func:`solver.identify.motion.controls_from_description`). A ``ros_gz``
    bridge's command topic of a Gazebo Sim joint controller for one of the ``joints``
    configures one too (:func:`_commanded_in_gazebo`). None when a bound stopped the reading:
    what was not read may move it."""
    # Each joint by its name after a namespace (``firefly/rotor_0_joint``), as a controller's
    # list names it; a name no word can be is not taken as named here: this is a claim.
    words = {tail for name in joints if _WORD.fullmatch(tail := name.rsplit("/", 1)[-1])}
    if rule is None or not words or not workspace.complete:
        return None
    if (
        _first_found(workspace, rule.shipped)
        or any(
            rule.shipped.find(name) is not None
            for name in (*workspace.packages, *workspace.neighbours)
        )
        or (rule.named is not None and _a_file_named(workspace, rule.named))
    ):
        return None  # software its packages ship, or a package or file named for it
    for shipped in workspace.files:
        matched = rule.controllers.find(shipped.text)
        if matched is not None and named_joints(replace(workspace, files=(shipped,)), words):
            return _shown_file(shipped.package, shipped.path, matched)
        topic = _commanded_in_gazebo(shipped.text, words)
        if topic is not None:
            return _shown_file(shipped.package, shipped.path, topic)
    return None


def _a_file_named(workspace: Workspace, named: Pattern) -> bool:
    """A file of the packages is named for the software (``named``), its folders left out: a
    script named for a gait (``normal_walk.py``, replaying recorded joint angles) is one,
    whatever its text says."""
    return any(named.search(shipped.path.rsplit("/", 1)[-1]) for shipped in workspace.files)


def controller_joints(
    workspace: Workspace, controllers: Pattern, joints: Collection[str]
) -> str | None:
    """The first controller configuration of the robot's packages (a YAML file) that gives a
    joint controller (its ``type`` found by ``controllers``, the profile's
    ``motion.gait.controllers``) one of the ``joints`` to command, by its name after a
    namespace: in its ``joints`` list or as its ``joint``, in the controller's own block (ROS 1,
    or ROS 2 with the type under its ``ros__parameters``), or under the ``ros__parameters`` of
    the block named as the controller the controller manager is given (ROS 2; a node name by
    its last part, ``/rover/sus_ctrl``). A joint only a state broadcaster lists, or another
    controller commands, is not one. A file YAML cannot read, or longer than any controller
    configuration (:data:`_CONFIGURATION_CHARS`), says nothing; a joint written through a
    launch argument (``$(arg prefix)sus0_joint``) is no joint's name. Found in packages read in
    part too: what was read says it."""
    words = {tail for name in joints if _WORD.fullmatch(tail := name.rsplit("/", 1)[-1])}
    if not words:
        return None
    for shipped in workspace.files:
        if not shipped.path.endswith((".yaml", ".yml")) or len(shipped.text) > _CONFIGURATION_CHARS:
            continue
        if controllers.find(shipped.text) is None or not named_joints(
            replace(workspace, files=(shipped,)), words
        ):
            continue  # the cheap look first: no parse of a file that cannot hold one
        for kind, commanded in _controllers(shipped.text, shipped.path):
            matched = controllers.find(kind)
            if matched is not None and words & {j.rsplit("/", 1)[-1] for j in commanded}:
                return _shown_file(shipped.package, shipped.path, matched)
    return None


# The longest controller configuration read (characters): the sample's are 13 kB at most; a
# longer YAML file is a map or a data set, and parsing it would cost seconds for nothing.
_CONFIGURATION_CHARS = 64 * 1024


def _controllers(text: str, name: str) -> list[tuple[str, frozenset[str]]]:
    """Each controller a YAML configuration declares: its type and the joints it is given. A
    block with a ``type`` (beside it or under its ``ros__parameters``) is a controller, given
    the joints of that block; one given none there (a controller manager's list of types) is
    given those of the block named as it elsewhere in the file that has no type of its own.
    Nothing from a text YAML cannot read."""
    try:
        data = parse_document(text, name, tolerate=("duplicate-key",)).data
    except InputError:
        return []
    typed: list[tuple[str, str, frozenset[str]]] = []  # (name, type, joints of its block)
    untyped: dict[str, set[str]] = {}  # a block's name -> the joints it lists, no type beside
    stack: list[tuple[str, object]] = [("", data)]
    while stack:
        key, value = stack.pop()
        if isinstance(value, list):
            stack.extend((key, item) for item in value)
            continue
        if not isinstance(value, dict):
            continue
        own = value.get("ros__parameters")
        blocks = [value, *([own] if isinstance(own, dict) else [])]
        kind = next((b["type"] for b in blocks if isinstance(b.get("type"), str)), None)
        listed = frozenset(n for block in blocks for n in _joint_names(block))
        if kind is not None:
            typed.append((key, kind, listed))
        elif listed:
            untyped.setdefault(key, set()).update(listed)
        # Each block below, its own parameters' too (a manager's controllers), named by its key;
        # a node's name by its last part (``/rover/sus_ctrl``), as the manager names it.
        below = [(k, v) for block in blocks for k, v in block.items() if v is not own]
        stack.extend((str(k).rsplit("/", 1)[-1], v) for k, v in below)
    return [(kind, listed or frozenset(untyped.get(key, ()))) for key, kind, listed in typed]


def _joint_names(block: dict[object, object]) -> set[str]:
    """The joints a controller's block gives it: its ``joints`` list, its ``joint``."""
    found = block.get("joints")
    names = [n for n in found if isinstance(n, str)] if isinstance(found, list) else []
    one = block.get("joint")
    return {*names, *([one] if isinstance(one, str) else [])}


def per_joint_controllers(
    workspace: Workspace, rule: SoftwareRule | None, joints: Collection[str]
) -> str | None:
    """The first file of the robot's packages that configures a controller of a joint's own
    (``rule.per_joint``: ROS 1's ``effort_controllers/JointPositionController``, a command
    topic for one joint; a Dynamixel's ``joint_position_controller`` module) for one of the
    ``joints`` (a walker's legs'): the ``joint:`` (or ``joint_name:``) key nearest the
    controller's type names it. Those joints take commands one by one, whatever
    else the packages ship (a gait beside them walks the body through them). A joint group's
    or trajectory controller is what a gait writes to, and a controller of a joint's own for a
    head or a gripper says nothing of the legs: not read here. Found in packages read in part
    too: what was read says it."""
    if rule is None or rule.per_joint is None:
        return None
    # Each joint by its name after a namespace, and without a prefix a launch file adds.
    tails = {name.rsplit("/", 1)[-1] for name in joints}
    words = tails.union(*map(_prefixed, tails))
    if not words:
        return None
    for shipped in workspace.files:
        for found in rule.per_joint.compiled.finditer(shipped.text):
            if _nearest_joint(shipped.text, found.start(), found.end()) in words:
                return _shown_file(shipped.package, shipped.path, found.group(0))
    return None


def _nearest_joint(text: str, start: int, end: int) -> str | None:
    """The value of the ``joint:`` (or ``joint_name:``) key nearest a controller's type found
    at ``start:end`` (a block's joint is written just before or after its type), within a few
    lines, by its name after a namespace; None when there is none."""
    before = text[max(0, start - _BLOCK_REACH) : start]
    after = text[end : end + _BLOCK_REACH]
    keys = [(len(before) - m.end(), m.group(1)) for m in _JOINT_KEY.finditer(before)]
    keys += [(m.start(), m.group(1)) for m in _JOINT_KEY.finditer(after)]
    if not keys:
        return None
    return min(keys)[1].rsplit("/", 1)[-1]


# A controller's one joint, as ROS 1 configurations write it (``joint: FL_calf``,
# ``"joint": "FL_calf"``; a Dynamixel controller's ``joint_name: pan``), and how far around its
# type it is looked for.
_JOINT_KEY = re.compile(r"""(?<![\w])["']?joint(?:_name)?["']?\s*:\s*["']?([\w./-]+)""")
_BLOCK_REACH = 240


def _commanded_in_gazebo(text: str, joints: Collection[str]) -> str | None:
    """The first Gazebo Sim joint controller's command topic in ``text`` (a ``ros_gz`` bridge
    configuration's ``/model/h1/joint/left_knee_joint/0/cmd_pos``, or ``.../cmd_force``) whose
    joint is one of ``joints``, or None: that joint's controller is configured, as a
    ``ros2_control`` one would be. A topic naming another joint (a flipper's) says nothing of
    these."""
    for found in _GAZEBO_JOINT_COMMAND.finditer(text):
        if found.group("joint") in joints:
            return found.group(0)
    return None


# A Gazebo Sim joint position or force controller's command topic (``joint/J/0/cmd_pos``; a
# velocity controller's ``cmd_vel`` is read as a velocity command, shipped software).
_GAZEBO_JOINT_COMMAND = re.compile(
    r"(?<![\w-])joint/(?P<joint>[\w.-]+)/(?:\d+/)?cmd_(?:pos|force)\b"
)


def named_joints(workspace: Workspace, joints: Collection[str]) -> frozenset[str]:
    """The ``joints`` a file of the robot's packages names (a controller's joint list, a
    script's command): joints the packages may command. A joint is named by a word of a file
    (``elbow``, ``arm.wrist-1``, ``j7`` in ``/arm/j7.pos``), or by its name without a prefix
    a launch file adds (:func:`_prefixed`).
    Each file is split into words once and they are looked up (linear in its size, however
    many joints a description lists); a name no word can be (a space in it) is taken as
    named: nothing says it is not."""
    tails: dict[str, set[str]] = {}  # a word -> the joints it names
    for name in set(joints):
        for tail in (name, *_prefixed(name)):
            tails.setdefault(tail, set()).add(name)
    named = {name for name in joints if not _WORD.fullmatch(name)}
    for shipped in workspace.files:
        if not tails:
            break
        words = set(_WORD.findall(shipped.text))
        words.update(_PART.findall(shipped.text))
        for word in tails.keys() & words:  # iterates the smaller of the two
            named |= tails.pop(word)
    return frozenset(named)


def _prefixed(name: str) -> tuple[str, ...]:
    """What a name reads as without a prefix of one or two words a launch file adds
    (``ur_shoulder_pan`` as ``shoulder_pan``), when that still has two words: a last word alone
    (``1``, ``lift``, ``joint``) names nothing."""
    parts = name.split("_", _PREFIX_WORDS)
    return tuple(tail for at in range(1, len(parts)) if "_" in (tail := "_".join(parts[at:])))


# The most words of a prefix a launch file adds to a joint's name (``ur_``, ``left_ur_``).
_PREFIX_WORDS = 2
# A word a joint is named by as written (``arm.wrist-1``), and the words inside it (``j7``).
_WORD = re.compile(r"[\w.\-]+")
_PART = re.compile(r"\w+")


def _first_found(
    workspace: Workspace,
    *patterns: Pattern | PackageRule,
    skip: Callable[[str], bool] | None = None,
) -> str | None:
    """The first file of the robot's packages one of the ``patterns`` finds text in (a
    package rule's :meth:`~solver.identify.profile.PackageRule.find`: its ``match``, in a file
    its ``unless`` finds none in), as evidence shows it (in the order the packages were
    read), or None; a file ``skip`` says of its text (asked only of a file something was found
    in) is passed by."""
    for shipped in workspace.files:
        for pattern in patterns:
            matched = pattern.find(shipped.text)
            if matched is not None and not (skip and skip(shipped.text)):
                return _shown_file(shipped.package, shipped.path, matched)
    return None


def _shown_file(package: str, path: str, matched: str) -> str:
    """A file of the robot's packages and the text found in it, as evidence shows them, the
    punctuation and spaces a pattern's word boundary matched stripped from its ends
    (``'takeoff(`` shows as ``takeoff``; an underscore or a digit stays), and its line breaks
    and indents shown as one space (a match over two lines of a configuration)."""
    where = shown(path, limit=SHOWN_FILE_NAME_CHARS)
    word = " ".join((matched.strip(_BOUNDS) or matched).split()) or matched
    return f"package {shown(package)}: {where} ({shown(word)})"


# What a pattern's word boundary matches around the word (a quote, a slash, a space).
_BOUNDS = string.punctuation.replace("_", "") + string.whitespace
