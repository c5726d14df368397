"""Limbs: the chains the actuated joints form once the single-joint roles are taken out.

The actuated joints that play no single-joint role (:mod:`solver.identify.actuation`) form a
contracted tree (fixed joints squeezed out). Maximal unbranched paths in it are *chains*: a
chain that ends in a leaf is a *limb*, one that ends where the tree branches is *trunk* (a
waist, a torso lift). :func:`find_limbs` finds them.

Each limb is a *leg*, *head* or *arm* by which pattern most of its joints and links match,
within the profile's thresholds; an unnamed chain of at least ``arm_min_joints`` joints, or one
ending in a gripper, is an arm; on a flying body any chain of two joints or more is, and so is
one of two joints or more that turns on a link named as an arm's base or mount
(``manipulator_base_link``: a course's two-joint arm on a mobile base). A limb
carrying wheels, rotors or thrusters (Pepper's hip/knee over its wheeled base, a tilt-rotor
unit, a boat's steered engine) is a *mount*, not a limb, except legs that each end in a wheel,
three or more of them (a wheel-legged robot walks on them). Anything else (a flipper, a 2-joint
pan unit without a name) is *other*, unless it carries a camera or a range sensor: a short
unnamed chain pointing one is a *head* (a pan/tilt unit), but the only limb of a robot that
calls itself an arm is that arm, the camera at its tip (:func:`camera_arm`).

Where names say nothing, the chains' places and shapes still speak:

* two equal long chains on a humanoid's pelvis below named arms are its legs
  (:func:`legs_at_the_pelvis`);
* four or more alike short chains on one link, on both its sides, each ending below where it
  starts, are legs: a walker's, whatever their number (:func:`legs_by_place`; fingers point
  away from their palm, legs down to the ground), when the link is the trunk's (at most three
  joints turning above it, a waist's or a simulator's floating base's: a hand's fingers hanging
  from an arm's wrist are no legs); longer unnamed chains, two hanging straight down from the
  bottom of a free body, are a biped's legs, and four or more so hanging, their feet level,
  a walker's (:func:`legs_by_reach`);
* a chain built as the legs beside it (joint for joint: type, axis, span of limits, length of
  link), its tip level with their feet, is one of them, whatever its words say but an arm's
  (a hexapod's middle pair named ``shoulder``, ``elbow``, ``knee``; :func:`legs_alike`);
* two leg chains whose first joints turn about one line, side by side on one side of the
  body, are the two motors of one leg closed by a linkage (a five-bar leg, the loop a URDF
  cannot write): one leg (:func:`five_bars`), when the graph shows the loop: their ends meet
  (closer than their motors sit), or a mimic joint of one follows a joint of the other; or
  when both hinge in one plane from one hip: at one point, or side by side on one side of
  the hinge that turns their link (a hip's abduction carrying the leg's two motors on one
  axle; a waist carries its two hips on either side). Two
  legs that hang from different points of the base and end as far apart as they start (a
  front and a rear hip turning about one line along the body) are two legs. A leg chain and a
  shorter one beside it, both hanging from one hinge that carries no other leg, side by side
  on one side of it within a five-bar's gap, about one axis, are one leg and its linkage's
  bar drawn open (a hip's yaw carrying the thigh and the knee's bar); a rocker's front and
  rear legs are built alike and far apart, and stay two;
* three or six alike chains, the body's only limbs, starting on a level circle a third of a
  turn apart, are one parallel manipulator (:func:`parallel_robot`: a delta, a Stewart
  platform), and so are three chains named as legs on a root bolted to the world beside other
  limbs (a delta whose platform moves on slides of its own); two chains an SDF joint of a
  ``<gazebo>`` block closes onto each other are one linkage (:func:`closed_loops`: a
  wheel-legged robot's five-bar leg drawn open); two arm chains of hinges about parallel axes
  whose ends meet are one five-bar arm (:func:`closed_arms`); a short chain ending in a foot,
  below trunk joints named as a leg's that branch only into other short chains, is the end of
  one leg, the branches its linkage (:func:`legs_through_linkages`);
* a short unnamed chain with a slide in it, beside a leg on the hip the body turns, is that
  leg's linear actuator drawn open, no arm (:func:`drives_beside_legs`);
* one long chain of equal modules whose axes alternate, on a body that has nothing else, is a
  *spine*: a snake robot, no arm (:func:`spine`); a module may hold one joint or two (a yaw
  and a pitch joint close together), and the chain may carry single leaf joints on its
  modules and nothing else (passive side wheels): it is still a spine, and they are passive
  (:func:`wheeled_spine`); on a robot that calls itself a snake, any one chain of two turning
  joints or more is (:data:`_SNAKE_NAME`);
* on a robot that calls itself a pendulum rig (a control course's plant: a cart-pole, a Furuta
  pendulum, an acrobot), its one short chain (three joints at most, none named as an arm's or
  a leg's) is the plant's links, swung by their actuators: *other*, no arm
  (:func:`pendulum`, :data:`_PENDULUM_NAME`); on a robot that calls itself a pan/tilt unit,
  its one short chain of hinges read as no limb's is the unit's *head*, its payload named
  nowhere (:func:`named_pan_tilt`, :data:`_PAN_TILT_NAME`);
* a short chain from the root that carries a whole hand and nothing else is that hand's *wrist*
  (a hand hung from its forearm), no arm (:func:`wrist`);
* trunk joints that carry a gripper chain too short to be an arm, every link on the way from
  the root holding at most one other joint and that joint nothing (a Cartesian gantry's X and
  Y carriages, a camera's mount beside its Z slide), are that arm's first joints
  (:func:`find_limbs`).

Not here: fingers and hands (:mod:`solver.identify.hands`), the body they make
(:mod:`solver.identify.body`).
"""

from __future__ import annotations

import math
import re
from collections import Counter, deque
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, replace
from itertools import combinations, islice, pairwise
from typing import NamedTuple

from solver.identify.pose import (
    CELLS_AROUND,
    Vector,
    centroid,
    cosine,
    cross,
    distance,
    dot,
    grid_cell,
    minus,
    parallel,
    perpendicular,
    spread,
)
from solver.identify.readers.urdf import Joint, Urdf, walk_up, written_blank
from solver.identify.roles import Role
from solver.identify.tree import JointTree
from solver.untrusted import shown

__all__ = [
    "CORNER",
    "LIMB_KINDS",
    "Limb",
    "arms_beside_legs",
    "bolted_chain",
    "camera_arm",
    "chain_ends",
    "closed_loops",
    "find_limbs",
    "five_bars",
    "flippers",
    "gripping_leg",
    "joint_span",
    "joint_words",
    "joints_above",
    "legs_alike",
    "legs_at_the_pelvis",
    "legs_by_place",
    "legs_by_reach",
    "lone_leg",
    "named_pan_tilt",
    "named_wheeled_snake",
    "open_linkages",
    "pendulum",
    "planar_arm",
    "small_pan_tilt",
    "sort_limbs",
    "spine",
    "sprawling",
    "tips_meet",
    "wheeled_spine",
    "wrist",
]

# A spherical (ball) joint is outside the URDF spec but real files have it: a shoulder, a hip.
_LIMB_JOINTS = ("revolute", "continuous", "prismatic", "spherical")
# Hands side by side on their wrists, at most (a pair on fixed forearms).
_HANDS = 2
_TURNING = ("revolute", "continuous")
# A wrist turns a hand about up to three axes, its joints named so.
_WRIST_JOINTS = 3
_WRIST = re.compile("wrist", re.IGNORECASE)
# A camera's frame by its name (camera_link, cam_1, gimbal_camera).
_CAMERA = re.compile(r"camera|(^|[_/])cam([_/\d]|$)", re.IGNORECASE)
# The most camera frames a pan/tilt unit carries fixed below its last link (an RGB-D camera's
# link, its colour and depth frames and their optical frames; a stereo pair's).
_MOST_CAMERA_FRAMES = 8
LIMB_KINDS = ("leg", "arm", "head")
# A chain with this many joints named an arm's is an arm though it turns a camera.
_NAMED_ARM_JOINTS = 2
# An unnamed pair of chains on the root this long, beside named arms higher up, are legs.
_LEG_BY_PLACE_JOINTS = 5
# Legs that each end in a wheel are legs (a wheel-legged robot) when there are this many.
_WHEEL_LEGS = 3
# On a flying body, a chain this long hanging from it is an arm (an aerial manipulator's arm).
_FLYING_ARM_JOINTS = 2
# Roles a single joint plays that make it part of the base, not of a limb.
_MOUNTED = ("wheel", "steering", "caster", "rotor", "thruster")
# Legs by place: at least this many alike chains of this many joints on one link.
_WALKER_LEGS = 4
# ... on the trunk: the most joints that turn above the link they hang from (a waist, or a
# simulator's floating base's roll, pitch and yaw); past more, an arm's, they are fingers.
_TRUNK_TURNS = 3
# How far from a mirror image across the body a pair of hips may be (a share of the width).
_MIRRORED = 0.25
_LEG_JOINTS = (2, 4)
# ... and up to this many joints in groups of six or more (:data:`_WHOLE_TURN_LEGS`): a
# hexapod's five-joint legs; four long chains on one link may be a multi-arm cell's arms.
_MOST_LEG_JOINTS = 6
# Six or more such chains that lie flat at rest, each reaching out from the body by this share
# of its reach, are a walker's legs too (a hexapod drawn with its legs stretched out).
_LEG_SPREAD = 0.5
# Four or more such chains are legs too when they reach every way: their directions' mean (each
# of length one) is shorter than this (a hand's fingers drawn flat reach one way, near 1).
_EVERY_WAY = 0.5
# ... each chain counted as reaching along x or y where it goes this share of its length that way.
_ALONG = 0.3
# Chains named as arms are legs so sprawled when there are this many (a torso holds fewer).
_SPRAWLED_ARMS = 5
# One-joint chains turning whole (a wheel-leg walker's, RHex-like) on one body: legs when this
# many, about parallel axes, on both sides and at this many places along the body.
_WHOLE_TURN_LEGS = 6
_WHOLE_TURN_ROWS = 3
_FULL_TURN = 2 * math.pi - 1e-6
# A leg ends below where it starts by at least this share of its reach (fingers do not).
_LEG_DROP = 0.25
# A walker's feet at rest are level: their heights differ by at most this share of the
# shortest drop from hip to foot (a hand's fingers end at their own lengths).
_FEET_LEVEL = 0.25
# Places closer than this (metres) across the body are on neither side of its middle.
_SAME_PLACE = 1e-6
# Three chains or more whose tips stand closer together than this share of how far apart they
# start meet at one platform: a parallel robot's arms (every labelled walker's feet stand at
# least 0.8 as far apart as its hips; a delta's tips, 0.13).
_MEETING = 0.5
_MEETING_LEGS = 3
_MOST_MEETING_LEGS = 8  # parallel robots have three to six arms
# A biped's leg, known by place alone, hangs nearly straight down in the zero pose.
_LEG_STRAIGHT = 0.8
_BIPED_LEGS = 2
# The most joints a waist puts between a biped's pelvis and its torso.
_WAIST = 3
# The most unnamed chains above a biped's hips among which its two arms are looked for (two
# arms, a neck, a tail, a sensor mount); with more, none is chosen.
_MOST_ABOVE_THE_HIPS = 6
# The two motors of a five-bar leg sit this close (metres), on one line; legs are paired only
# on a body of at most this many leg chains (pairing compares each with each).
_FIVE_BAR_GAP = 0.15
# The two chains of a five-bar leg close their loop where they end: their ends are closer than
# half their motors' gap, or than this (metres) when the motors sit at one point.
_LOOP_CLOSED = 0.01
# Joints looked at below each motor for a mimic partner (a leg has a few; bounds a stranger's).
_MOST_LOOP_JOINTS = 256
_MOST_FIVE_BAR_LEGS = 64
# A snake's modules are alike: every spacing within this share of the middle one.
_MODULE_SPREAD = 0.1
# Two joints of one module this close (metres) sit at one point (a universal joint).
_AT_ONE_POINT = 1e-6
# A snake that moves in a plane (every axis parallel) has at least this many modules; an arm
# has at most seven joints.
_PLANAR_SPINE_JOINTS = 8
# The fewest wheels a body rolls on of its own (:func:`raised_legs`), and the most legs whose
# chains are walked for wheels (a stranger's thousands are not).
_BODY_WHEELS = 3
_MOST_RAISED_LEGS = 16
# A body's corner in a name (``front_left``, ``rear_right``, ``left_back``): a leg's name on a
# walker, a panel's or a bumper's on a rover, as often a wheel's. Its words are the leg
# pattern's (rules/identification.yaml, ``leg``).
CORNER = r"(?:(?:left|right)_?(?:front|rear|hind|back)|(?:front|rear|hind|back)_?(?:left|right))"
_CORNER = re.compile(CORNER, re.IGNORECASE)
# A robot that calls itself a snake, read as a word (``snake``, ``robosnake``, ``snakebot``,
# ``sea_snake``, ``Snake Robot``): its one chain of turning joints, nothing else, is a spine
# however short or unevenly drawn (a bare chain with no axes or geometry, a two-joint student
# model). Not when its name also says a manipulator (``snake_arm``, ``snake2_arm``,
# ``snake_tool``, ``serpent_7dof``, a snake-like continuum robot or endoscope), named for its
# shape, nor a snake's eyes.
_SNAKE_NAME = re.compile(
    r"(^|[_/\d\s-]|robo|sea)(snake|serpent)(bot|robot)?s?([_/\d\s-]|$)", re.IGNORECASE
)
_MANIPULATOR_NAME = re.compile(
    r"arm|manip|tool|gripper|grabber|hand|dof|continuum|endoscop|catheter|surgical|like|eye",
    re.IGNORECASE,
)
# A snake's modules may be labelled ``arm_1`` .. by a CAD exporter; these words name an arm's
# or a leg's joints, which a snake has none of.
_LIMB_JOINT_WORDS = re.compile(
    r"shoulder|elbow|wrist|forearm|upper_?arm|hip|knee|ankle|thigh|shin|foot", re.IGNORECASE
)
_NAMED_SPINE_JOINTS = 2
# A robot that calls itself an arm, read as a word of its name, camelCase split (``simple_arm``,
# ``SimpleArm``, ``camera_manipulator``; not ``xarm``'s product name, nor ``armadillo``).
_ARM_NAME = re.compile(r"(^|[^a-z])(arm|manipulator)s?([^a-z]|$)", re.IGNORECASE)
# A robot that calls itself something that walks: its hanging chains are legs whatever else
# its name says (``biped_with_arms``).
_LEGGED_NAME = re.compile(r"leg|biped|humanoid|walk|ped($|[^a-z])|dog", re.IGNORECASE)
# A robot that calls itself a pendulum rig, a control course's plant (``cart_pole``,
# ``furuta_pendulum``, ``acrobot``, ``pendubot``, ``double_pendulum_2dof``): not an arm that
# balances one (``pendulum_arm``: :data:`_ARM_NAME`).
_PENDULUM_NAME = re.compile(r"pendul|cart[_\s-]?pole|acrobot|pendubot|furuta", re.IGNORECASE)
# A robot that calls itself a pan/tilt unit (``pan_tilt``, ``PanTilt``, ``ptu_d46``): its one
# short chain of hinges is the unit's pan and tilt.
_PAN_TILT_NAME = re.compile(r"pan[_\s-]?tilt|(^|[^a-z])ptu([^a-z]|$)", re.IGNORECASE)
# The most joints a pendulum rig's chain has (a triple pendulum); an arm balancing a pole
# (a UR5's six joints and the pole's) is longer.
_PENDULUM_JOINTS = 3
# A linear actuator drawn open beside a leg: at most this many joints (two pivots, a rod).
_DRIVE_JOINTS = 3
# One-hinge chains named as legs are legs when the body has this many (a toy walker's four, a
# RHex's six; eight one-hinge "legs" are no walker's read here).
_ONE_JOINT_LEGS = (4, 6)
# A leg that holds something up without walking: it folds, deploys, levels or props (a table's,
# a lander's, an outrigger, a drone's landing gear, a flipper).
_SUPPORT = re.compile(
    r"fold|deploy|landing|outrigger|stabili[sz]|support|jack|level|flipper|gear", re.IGNORECASE
)
# A thing on legs that does not walk, by its name as a word (camelCase split): furniture, a
# lander, a crane, a stand (not ``standard``).
_STANDS = re.compile(
    r"(^|[^a-z])(table|bench|bed|desk|chair|stand|cart|crane|lander)s?([^a-z]|$)", re.IGNORECASE
)
# A leg called so as a word (``leg_fr_joint``, ``FrontLeg``, ``legs_2``), camelCase split.
_LEG_WORD = re.compile(r"(^|[^a-z])legs?([^a-z]|$)|(?-i:Legs?)(?![a-z])", re.IGNORECASE)
# A spine carries at least this many single leaf joints to be read with side wheels.
_SIDE_WHEELS = 2
# Joints (or the links they move) with arm or leg names that make a chain a named limb.
_LIMB_NAMES = 2


@dataclass(frozen=True, slots=True)
class Limb:
    """A terminal chain of actuated joints, proximal to distal."""

    kind: str  # leg, arm, head, mount, other; spine (a snake's body), wrist (a hand's)
    joints: tuple[str, ...]
    base: str
    tip: str
    gripper: bool = False
    named: bool = False  # some joint or link of the chain names a leg, arm or head
    why: str = ""  # the evidence that decided its kind

    def describe(self) -> str:
        first, last = shown(self.joints[0]), shown(self.joints[-1])
        span = first if len(self.joints) == 1 else f"{first} .. {last}"
        chain = f"{shown(self.base)} -> {shown(self.tip)}"
        text = f"{self.kind}: {len(self.joints)}-joint chain {chain} ({span})"
        return text + (", ends in a gripper" if self.gripper else "")


def find_limbs(
    tree: JointTree, special: set[str], grippers: set[str], roles: dict[str, Role], flying: bool
) -> tuple[list[Limb], list[str], set[str]]:
    """Limbs and trunk joints of the contracted tree of actuated, non-special joints, and the
    anchors that hold a gripper (one per hand)."""
    children, carries, hosts = _contracted(tree, special, grippers, roles)
    limbs: list[Limb] = []
    trunk: list[str] = []
    starts = deque(children.get("", []))
    while starts:
        first = starts.popleft()
        chain = [first]
        while len(children.get(chain[-1].name, [])) == 1:
            chain.append(children[chain[-1].name][0])
        branches = children.get(chain[-1].name, [])
        starts.extend(branches)
        if branches and not (
            _tool_leaves(tree, chain, branches, (children, carries))
            or _hand_leaves(tree, chain, branches, (children, carries))
        ):
            trunk.extend(j.name for j in chain)
            continue
        limbs.append(_classify(tree, chain, chain[0].parent, _marks(chain, carries), flying))
    limbs, trunk = _carried_grippers(tree, limbs, trunk, (children, carries), flying)
    wheel_legs = sum(1 for limb in limbs if limb.kind == "wheel_leg")
    limbs = [
        replace(limb, kind="leg" if wheel_legs >= _WHEEL_LEGS else "mount")
        if limb.kind == "wheel_leg"
        else limb
        for limb in limbs
    ]
    return sort_limbs(tree, _short_pair(tree, limbs)), trunk, hosts


def _tool_leaves(
    tree: JointTree,
    chain: list[Joint],
    branches: list[Joint],
    contracted: tuple[dict[str, list[Joint]], dict[str, set[str]]],
) -> bool:
    """The chain is an arm's and its branches the parts of the tool at its end, no trunk: it
    is long enough to be an arm, more of its joints are named as an arm's than as anything
    else's, and it branches only into single joints that carry nothing (a suction tool's two
    sliding pipes, which no rule reads as jaws). A trunk branches into limbs (a torso into
    arms, a body into legs); two one-joint leaves are none, but a chain not named as an arm
    may be a body's (a neck carrying a head's two antennas). A chain named as no limb's at
    all, ending in exactly two slides, is an arm's with its jaws, each slide bare or carrying
    a finger of the gripper and nothing else (a jaw that slides, then closes its tip): a
    trunk's leaves turn (a head's antennas, ears), a gripper's two jaws slide."""
    children, carries = contracted
    if len(chain) < tree.profile.limb("arm_min_joints") or len(branches) < 2:
        return False  # (one joint below would have continued the chain)
    if any(children.get(joint.name) for joint in branches):
        return False
    scores = _name_scores(tree, chain)
    if not any(scores.values()):
        return (
            len(branches) == _JAWS
            and all(joint.type == "prismatic" for joint in branches)
            and all(_bare_or_one_finger(tree, joint, carries) for joint in branches)
        )
    if any(carries.get(joint.name) for joint in branches):
        return False
    return scores["arm"] > 0 and scores["arm"] == max(scores.values())


def _bare_or_one_finger(tree: JointTree, jaw: Joint, carries: dict[str, set[str]]) -> bool:
    """``jaw`` carries nothing, or one finger of the gripper and nothing else: a slide that
    closes a hinged tip, not a gripper of its own (two jaws) on a slide."""
    kinds = carries.get(jaw.name, set())
    if not kinds:
        return True
    moving = list(islice((j for j in tree.urdf.subtree_joints(jaw.child) if j.movable), 2))
    return kinds == {"gripper"} and len(moving) == 1


# A parallel gripper's jaws: two slides.
_JAWS = 2
# A hand at an unnamed arm's end has at least this many fingers (two are a gripper's jaws, or
# a head's antennas: :func:`_tool_leaves`)...
_HAND_FINGERS = 3
# ...and the arm at least this many joints (the sets' arms carrying hands have six or seven; a
# humanoid's waist or a test rig carrying legs has three).
_HAND_ARM_JOINTS = 5
# Every link of a hand's fingers lies this close (metres) to where the arm ends (a hand's
# length; the sets' hands and three-finger grippers reach under 0.25 m)...
_HAND_REACH = 0.3
# ...and the arm reaches at least this many times as far as the hand does.
_ARM_TO_HAND = 2.0


def _hand_leaves(
    tree: JointTree,
    chain: list[Joint],
    branches: list[Joint],
    contracted: tuple[dict[str, list[Joint]], dict[str, set[str]]],
) -> bool:
    """The chain is an unnamed arm's and its branches the fingers of a hand at its end: it has
    an arm's joints (:data:`_HAND_ARM_JOINTS`: a humanoid's waist, a test rig's have fewer), no
    name says what it or any branch is, and it branches into fingers, three or more, or two
    that bend (two joints or more each), each no longer than a finger, carrying nothing
    (:func:`_tool_leaves`) and branching no further, whose links all lie within a hand's reach
    (:data:`_HAND_REACH`) of the link the chain ends on, while the chain reaches, along its
    links (an arm may be folded at rest), at least twice as far as the farthest of them
    (:data:`_ARM_TO_HAND`, and at least as far as the hand's reach): a three-finger hand on a
    six-joint arm, its fingers' first joints coupled to one actuator; a servo arm's two
    two-joint fingers. Branches named as limbs are a trunk's (a torso's arms and head, a rig's
    legs)."""
    children, carries = contracted
    if len(chain) < _HAND_ARM_JOINTS or len(branches) < _JAWS:
        return False
    if any(_name_scores(tree, chain).values()):
        return False
    longest = tree.profile.limb("finger_max_joints")
    palm = tree.poses.place(chain[-1].child)
    farthest = 0.0
    bending = True
    for first in branches:
        finger = [first]
        while len(below := children.get(finger[-1].name, [])) == 1:
            finger.append(below[0])
        if (
            children.get(finger[-1].name)
            or len(finger) > longest
            or any(carries.get(joint.name) for joint in finger)
            or any(_name_scores(tree, finger).values())
        ):
            return False
        bending = bending and len(finger) > 1
        farthest = max(
            farthest, *(distance(tree.poses.place(joint.child), palm) for joint in finger)
        )
    if len(branches) < _HAND_FINGERS and not bending:
        return False
    places = [tree.poses.place(chain[0].parent), *(tree.poses.place(j.child) for j in chain)]
    reach = sum(distance(one, other) for one, other in pairwise(places))
    return farthest <= _HAND_REACH and reach >= _ARM_TO_HAND * max(farthest, _HAND_REACH / 2)


# A humanoid's two pairs of limbs: one pair found, the other sought among one-joint chains.
_PAIRED = {"leg": "arm", "arm": "leg"}


def _short_pair(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """``limbs`` with a pair of one-joint chains named as legs (``hips_to_left_leg``) or arms
    (``base_to_right_shoulder``), one on each side of the body, read as that pair when the
    body has exactly the other pair (two arms, two legs) and no more one-joint chains so named:
    a toy humanoid's one-hinge legs, a biped's one-hinge shoulders. Alone such a chain is too
    short to be a limb (a leg needs two joints, an arm three)."""
    for kind, other in _PAIRED.items():
        if sum(1 for limb in limbs if limb.kind == other) != 2 or any(
            limb.kind == kind for limb in limbs
        ):
            continue
        short = [
            index
            for index, limb in enumerate(limbs)
            if limb.kind == "other"
            and len(limb.joints) == 1
            and kind in tree.parts_of(limb.joints[0]) | tree.parts_of(limb.tip)
        ]
        if len(short) != 2 or not _opposite(tree, [limbs[i] for i in short]):
            continue
        why = f"one of a pair of one-joint chains named as {kind}s, beside two {other}s"
        return [
            replace(limb, kind=kind, named=True, why=why) if index in short else limb
            for index, limb in enumerate(limbs)
        ]
    return limbs


def _opposite(tree: JointTree, pair: list[Limb]) -> bool:
    """The two chains are on either side of the body: their names say left and right (a model
    drawn in its CAD's axes), or their tips lie across its y axis as it rests."""
    sides = [
        {m.group(0).lower() for m in _SIDE.finditer(f"{limb.joints[0]} {limb.tip}")}
        for limb in pair
    ]
    if sides[0] ^ sides[1] == {"left", "right"} and not sides[0] & sides[1]:
        return True
    first, second = (tree.poses.place(limb.tip)[1] for limb in pair)
    return first * second < 0


_SIDE = re.compile(r"left|right", re.IGNORECASE)


def _carried_grippers(
    tree: JointTree,
    limbs: list[Limb],
    trunk: list[str],
    contracted: tuple[dict[str, list[Joint]], dict[str, set[str]]],
    flying: bool,
) -> tuple[list[Limb], list[str]]:
    """A chain ending in a gripper too short to be an arm (kind *other*), on trunk joints from
    the root where every link on the way holds at most one other joint, and that joint carries
    nothing and has nothing below it (a camera's or a light's mount on a gantry's carriage; it
    stays a limb of its own, a head or other): those trunk joints carry the gripper, one arm
    with it (a Cartesian gantry's X and Y carriages above its Z slide), when the joined chain
    reads as an arm. Another chain on the root, a second side joint on one link (a palm's
    fingers), a side joint carrying a wheel, rotor or gripper, or one with joints below it (an
    arm, a leg, a head of two joints) leaves the trunk a trunk."""
    children, carries = contracted
    above = {joint.name: anchor for anchor, below in children.items() for joint in below}
    joints = {joint.name: joint for below in children.values() for joint in below}
    for index, limb in enumerate(limbs):
        if not limb.gripper or limb.kind != "other":
            continue
        chain = [joints[name] for name in limb.joints]
        carriage = _carriage(chain[0].name, above, joints, children, carries)
        if not carriage:
            continue
        joined = [*carriage, *chain]
        arm = _classify(tree, joined, joined[0].parent, _marks(joined, carries), flying)
        if arm.kind != "arm":
            continue
        kept = {j.name for j in carriage}
        return [*limbs[:index], arm, *limbs[index + 1 :]], [n for n in trunk if n not in kept]
    return limbs, trunk


def _carriage(
    first: str,
    above: dict[str, str],
    joints: dict[str, Joint],
    children: dict[str, list[Joint]],
    carries: dict[str, set[str]],
) -> list[Joint]:
    """The trunk joints above ``first``, from the root down, when each link on the way holds
    besides the way on at most one joint carrying nothing with nothing below it, and the root
    nothing besides; else none."""
    path: list[Joint] = []
    here = first
    while (anchor := above.get(here, "")) != "":
        siblings = [j for j in children.get(anchor, []) if j.name != here]
        if len(siblings) > 1 or any(children.get(j.name) or carries.get(j.name) for j in siblings):
            return []
        path.append(joints[anchor])
        here = anchor
    siblings = [j for j in children.get("", []) if j.name != here]
    return path[::-1] if path and not siblings else []


def _marks(chain: list[Joint], carries: dict[str, set[str]]) -> set[str]:
    """What a chain's joints carry (wheels, rotors, a gripper, ...)."""
    return set().union(*(carries.get(j.name, set()) for j in chain))


def legs_at_the_pelvis(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two unnamed long chains on the root, below a body whose arms hang higher: legs.

    A humanoid's legs hang from its pelvis (the root) and its arms from the torso above the
    waist; when the joint names say nothing (``LHY``, ``LKP``), that is where they are. Only a
    pair of equal chains of at least five joints counts, and only beside two or more arms that
    are named or end in a gripper and do not hang from the root.
    """
    root = tree.urdf.root
    pelvis = [
        limb
        for limb in limbs
        if limb.kind == "arm"
        and not limb.named
        and not limb.gripper
        and limb.base == root
        and len(limb.joints) >= _LEG_BY_PLACE_JOINTS
    ]
    arms = [
        limb
        for limb in limbs
        if limb.kind == "arm" and (limb.named or limb.gripper) and limb.base != root
    ]
    if len(pelvis) != 2 or len(pelvis[0].joints) != len(pelvis[1].joints) or len(arms) < 2:
        return limbs
    why = "one of two equal unnamed chains on the root, below named arms (legs by place)"
    legs = [replace(limb, kind="leg", why=why) for limb in pelvis]
    return sort_limbs(tree, [limb for limb in limbs if limb not in pelvis] + legs)


def legs_by_reach(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two unnamed chains that hang straight down from the bottom of a free body: its legs.

    When no name says which chains are legs (``j0`` .. ``j17``), a biped's still show where
    they are in the zero pose: a mirrored pair of equal chains (two joints or more, no gripper;
    mirrored across the root's origin, or side by side about a plane off it, :func:`_side_by_side`)
    that each end below where they start by most of their reach (``_LEG_STRAIGHT``), whose tips
    are the body's lowest and below its root by half their reach (or within half their reach
    of it, a root drawn at the feet, below a pair of arms or with no other limb: a lower body
    exported from the floor up), and that start no higher than any other chain (arms hang
    from shoulders above the hips). Not on a body bolted to
    the world (a torso's arms may hang down too), nor when legs were found otherwise. Four
    chains or more like the pair, hanging as straight, their feet level with its own
    (:func:`_level_with`), are a walker's legs, every one of them: a quadruped's legs too long
    for :func:`legs_by_place` (six joints, ``joint11`` .. ``joint16``) are no biped's two
    beside two arms. A pair alone (no walker's four) on a robot whose name calls it an arm and
    nothing that walks (``two_arm``, :data:`_LEGGED_NAME`) is a dual-arm robot's arms hanging
    at rest.
    """
    if any(limb.kind == "leg" for limb in limbs) or (_world_root(tree) and not _walks(tree)):
        return limbs
    placed: dict[int, tuple[Place, Place]] = {}
    for limb in limbs:
        first = tree.urdf.joint(limb.joints[0])
        if first is not None:
            placed[id(limb)] = (tree.poses.place(first.child), tree.poses.place(limb.tip))
    candidates = _leg_candidates(tree, limbs, placed)
    pair = _hanging_pair(tree, limbs, candidates, placed)
    if pair is None:
        return limbs
    level = _level_with(candidates, placed, pair)
    if len(level) >= _WALKER_LEGS:  # a quadruped's, a hexapod's: every one of them a leg
        why = "one of equal unnamed chains hanging straight down, their feet level (legs by reach)"
        legs = {id(limb) for limb in level}
    elif _named_arm(tree.urdf.name) and not _LEGGED_NAME.search(tree.urdf.name):
        return limbs
    else:
        why = "one of two equal unnamed chains hanging straight down from the bottom of the body"
        legs = {id(limb) for limb in pair}
    return sort_limbs(
        tree,
        [replace(limb, kind="leg", why=why) if id(limb) in legs else limb for limb in limbs],
    )


def legs_alike(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Chains built as the body's legs are, standing with them: legs too.

    A walker's legs are alike, and the words of a middle pair (``shoulder_middle_left``,
    ``elbow_middle_left``, ``knee_middle_left``) may name an arm's joints as often as a leg's.
    A chain of no gripper, read as an arm or as nothing, named no arm or manipulator as a word
    (:data:`_ARM_NAME`), on a rigid body two legs or more hang from, built as one of those legs
    joint for joint (:func:`_build`: type, axis up to its sign, span of limits, length of each
    link), whose tip is level with their feet (within :data:`_FEET_LEVEL` of the shortest leg's
    reach, hip to foot), is one of them: an arm a legged robot carries is built as an arm, and
    held above its feet. Legs that hang (each ending below its hip by :data:`_LEG_DROP` of its
    reach) take only a chain that hangs too; legs drawn spread flat, four or more of them, only
    a chain that starts among their hips (a hexapod's middle pair), so that a humanoid drawn
    lying down, arms and legs reaching one way, keeps its arms."""
    known: dict[str, str | None] = {}
    hung = Counter(moved_by(tree.urdf, limb.base, known) for limb in limbs if limb.kind == "leg")
    bodies = {body for body, count in hung.items() if count >= _BIPED_LEGS}
    legs = [
        limb
        for limb in limbs
        if limb.kind == "leg" and moved_by(tree.urdf, limb.base, known) in bodies
    ]
    stance = _stance(tree, legs)
    if stance is None:
        return limbs

    def alike(limb: Limb) -> bool:
        if limb.kind not in ("arm", "other") or limb.gripper or _names_an_arm(tree, limb):
            return False
        return (
            moved_by(tree.urdf, limb.base, known) in bodies
            and _build(tree, limb) in stance.builds
            and _stands_with(tree, limb, stance)
        )

    why = "a chain built as the legs beside it are, its tip level with their feet (a leg)"
    found = [replace(limb, kind="leg", why=why) if alike(limb) else limb for limb in limbs]
    return sort_limbs(tree, found) if found != limbs else limbs


@dataclass(frozen=True)
class _Stance:
    """How a body's legs stand: the lowest foot's height, the shortest leg's reach, whether
    every leg hangs, where the hips are, and how each leg is built (:func:`_build`)."""

    feet: float
    reach: float
    hanging: bool
    hips: tuple[Place, ...]
    builds: frozenset[_Built]


def _stance(tree: JointTree, legs: list[Limb]) -> _Stance | None:
    """The legs' stance, or None when there are none, a first joint is missing, the legs are
    drawn with no length, or two legs or three reach sideways (a body drawn lying down)."""
    placed = chain_ends(tree, legs) if legs else None
    if placed is None:
        return None
    reach = min(distance(start, end) for start, end in placed)
    hanging = all(start[2] - end[2] >= _LEG_DROP * distance(start, end) for start, end in placed)
    if reach == 0 or (not hanging and len(legs) < _WALKER_LEGS):
        return None
    return _Stance(
        feet=min(end[2] for _, end in placed),
        reach=reach,
        hanging=hanging,
        hips=tuple(start for start, _ in placed),
        builds=frozenset(built for limb in legs if (built := _build(tree, limb)) is not None),
    )


def _stands_with(tree: JointTree, limb: Limb, stance: _Stance) -> bool:
    """``limb``'s tip is level with the legs' feet, and it hangs as they do, or (legs spread
    flat) starts among their hips."""
    ends = chain_ends(tree, [limb])
    if ends is None:
        return False
    start, end = ends[0]
    if abs(end[2] - stance.feet) > _FEET_LEVEL * stance.reach:
        return False
    if stance.hanging:
        return start[2] - end[2] >= _LEG_DROP * distance(start, end)
    return all(
        min(hip[axis] for hip in stance.hips) - _SAME_PLACE
        <= start[axis]
        <= max(hip[axis] for hip in stance.hips) + _SAME_PLACE
        for axis in (0, 1)
    )


def _names_an_arm(tree: JointTree, limb: Limb) -> bool:
    """A joint of the chain, or the link it moves, names an arm or a manipulator as a word."""
    return any(_ARM_NAME.search(words) for words in joint_words(tree, limb))


def joint_words(tree: JointTree, limb: Limb) -> list[str]:
    """Each joint of the chain with the link it moves (``"elbow_joint forearm_link"``), as the
    words its name and its part's say; a joint the description lacks, by its name alone."""
    return [
        name if (joint := tree.urdf.joint(name)) is None else f"{name} {joint.child}"
        for name in limb.joints
    ]


_Built = tuple[tuple[str, tuple[float, ...], float, float], ...]


def _build(tree: JointTree, limb: Limb) -> _Built | None:
    """A chain's joints as built: each one's type, axis (its sign turned so that its first
    component not zero is positive), span of limits and the length of the link it moves (to
    the next joint, the last one's to the tip), rounded to a thousandth so that a mirrored
    twin's floating-point noise reads the same; None when a joint is missing."""
    joints = _joints_of(tree, limb)
    if len(joints) != len(limb.joints):
        return None
    places = [tree.poses.place(joint.child) for joint in joints]
    places.append(tree.poses.place(limb.tip))
    built = []
    for joint, (here, there) in zip(joints, pairwise(places), strict=True):
        span = (joint.upper or 0.0) - (joint.lower or 0.0)
        first = next((value for value in joint.axis if abs(value) > _SAME_PLACE), 1.0)
        axis = tuple(round(value if first > 0 else -value, 3) + 0.0 for value in joint.axis)
        built.append((joint.type, axis, round(span, 3), round(distance(here, there), 3)))
    return tuple(built)


def arms_beside_legs(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two unnamed chains above a biped's legs, mirrored across its trunk: its arms.

    A small humanoid's arms may be two joints each, too short for an arm by count; on a body
    that stands on two legs, a mirrored pair of equal chains (two joints or more, nothing named)
    starting higher than the hips, on the rigid body the legs hang from, is the pair of arms (a
    head sits on the middle line, a tail behind). Not when arms were found otherwise.
    """
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if len(legs) != _BIPED_LEGS or any(limb.kind == "arm" for limb in limbs):
        return limbs
    candidates = _above_the_hips(tree, limbs, legs)
    if len(candidates) > _MOST_ABOVE_THE_HIPS:
        return limbs  # no biped's upper body: too many chains to choose a pair from
    starts = {id(limb): _start(tree, limb) for limb in candidates}
    pairs = [
        (one, other)
        for index, one in enumerate(candidates)
        for other in candidates[index + 1 :]
        if len(one.joints) == len(other.joints)
        and _mirrored_either_way(starts[id(one)], starts[id(other)])
    ]
    if len(pairs) != 1:
        return limbs  # none, or no one pair to choose
    why = "one of two mirrored unnamed chains above a biped's legs (its arms)"
    arms = {id(limb) for limb in pairs[0]}
    return sort_limbs(
        tree,
        [replace(limb, kind="arm", why=why) if id(limb) in arms else limb for limb in limbs],
    )


def drives_beside_legs(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Short unnamed arms with a slide in them that start where one leg starts, on a link the
    body turns (a leg's hip), on a body of three legs or more: that leg's drive, no arm. A leg
    moved by linear actuators, its closed loops opened by a CAD export, shows each actuator's
    pivots and rod as a chain beside the leg on its hip; an arm is carried by the body (where
    several legs start, however it moves), not by one leg's hip."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if len(legs) <= _BIPED_LEGS:
        return limbs
    known: dict[str, str | None] = {}
    starts = Counter(limb.base for limb in legs)
    hips = {
        base
        for base, count in starts.items()
        if count == 1 and moved_by(tree.urdf, base, known) is not None
    }
    why = "a chain beside a leg on the hip it starts from (that leg's drive, its loop opened)"
    return [
        replace(limb, kind="other", why=why) if _drive_beside(tree, limb, hips) else limb
        for limb in limbs
    ]


def _drive_beside(tree: JointTree, limb: Limb, hips: set[str]) -> bool:
    """An unnamed arm of at most :data:`_DRIVE_JOINTS` joints, one of them a slide (a linear
    actuator's pivots and rod), with no gripper, on one leg's hip."""
    if limb.kind != "arm" or limb.named or limb.gripper or limb.base not in hips:
        return False
    if len(limb.joints) > _DRIVE_JOINTS:
        return False
    kinds = [joint.type for joint in _joints_of(tree, limb)]
    return "prismatic" in kinds


def _above_the_hips(tree: JointTree, limbs: list[Limb], legs: list[Limb]) -> list[Limb]:
    """Unnamed chains of two joints or more and of no kind yet, on the rigid body ``legs``
    hang from, starting higher than the hips."""
    known: dict[str, str | None] = {}
    trunk = {moved_by(tree.urdf, limb.base, known) for limb in legs}
    hips = max(_start(tree, limb)[2] for limb in legs)
    return [
        limb
        for limb in limbs
        if limb.kind == "other"
        and not limb.named
        and len(limb.joints) >= _LEG_JOINTS[0]
        and moved_by(tree.urdf, limb.base, known) in trunk
        and _start(tree, limb)[2] > hips
    ]


def _start(tree: JointTree, limb: Limb) -> Place:
    """Where a limb's first joint turns, in the body's frame at rest."""
    first = tree.urdf.joint(limb.joints[0])
    return tree.poses.place(first.child if first is not None else limb.base)


def _mirrored(a: Place, b: Place) -> bool:
    """One on each side of the body, as far out, at one height and one place along it."""
    across = abs(a[1] - b[1])
    return (
        _across_from(a, b)
        and abs(a[0] - b[0]) <= _MIRRORED * across
        and abs(a[2] - b[2]) <= _MIRRORED * across
    )


def _mirrored_either_way(a: Place, b: Place) -> bool:
    """:func:`_mirrored` across y, or across x in a file drawn facing y."""
    return _mirrored(a, b) or _mirrored(_facing_y(a), _facing_y(b))


def _facing_y(place: Place) -> Place:
    """``place`` with x and y swapped: a body drawn facing y, read as one drawn facing x."""
    return (place[1], place[0], place[2])


def _a_pair_alone(a: Place, b: Place, others: list[Place]) -> bool:
    """``a`` and ``b`` side by side (:func:`_side_by_side`) with none of ``others`` in line with
    them: two hips, not two of a row of fingers or tool heads."""
    return _side_by_side(a, b) and not any(_side_by_side(a, c) for c in others)


def _side_by_side(a: Place, b: Place) -> bool:
    """Apart across the body (y), at one height and one place along it (x): mirror images about
    the plane halfway between them, wherever the body's frame is."""
    across = abs(a[1] - b[1])
    return across > 0 and max(abs(a[0] - b[0]), abs(a[2] - b[2])) <= _MIRRORED * across


def _across_from(a: Place, b: Place) -> bool:
    """One on each side of the body (across y), as far out."""
    return a[1] * b[1] < 0 and abs(a[1] + b[1]) <= _MIRRORED * abs(a[1] - b[1])


def _hanging_pair(
    tree: JointTree,
    limbs: list[Limb],
    candidates: list[Limb],
    placed: dict[int, tuple[Place, Place]],
) -> tuple[Limb, Limb] | None:
    """The two ``candidates`` (:func:`_leg_candidates`) whose tips are lowest, when they are a
    biped's legs (``legs_by_reach``)."""
    if len(candidates) < _BIPED_LEGS:
        return None
    lowest = sorted(candidates, key=lambda limb: placed[id(limb)][1][2])
    one, other = lowest[0], lowest[1]
    if len(one.joints) != len(other.joints):
        return None
    feet = _feet(tree, (one, other), placed)
    if feet is None:
        return None
    below_the_root, at_the_root = feet
    (a, a_tip), (b, b_tip) = placed[id(one)], placed[id(other)]
    hips = max(a[2], b[2])
    if distance(a, b) < _AT_ONE_POINT:
        a, b = a_tip, b_tip  # both hips' first joints at the pelvis's middle: the feet tell
    # Side by side across the body (y), or across x in a file drawn facing y; or at one height
    # and one place along it, apart across it, about a plane off the root's origin (a CAD
    # export whose body frame is not on the robot's middle).
    others = [placed[id(limb)][0] for limb in candidates if limb not in (one, other)]
    if not (
        _across_from(a, b)
        or _across_from(_facing_y(a), _facing_y(b))
        or _a_pair_alone(a, b, others)
        or _a_pair_alone(_facing_y(a), _facing_y(b), [_facing_y(c) for c in others])
    ):
        return None
    if not _trunk_above(tree, limbs, (one, other), placed, hips):
        return None
    # Feet below the root's frame, or at it (a root drawn at the feet) below a pair of arms, or
    # with no other limb at all (a lower body drawn from the floor up).
    alone = all(limb in (one, other) for limb in limbs) and not _on_a_waist(tree, one)
    if not below_the_root and not (
        at_the_root and (alone or _pair_above(tree, limbs, (one, other), placed, hips))
    ):
        return None
    return one, other


def _on_a_waist(tree: JointTree, limb: Limb) -> bool:
    """``limb`` hangs from a body that one hinge about the vertical turns on the root's rigid
    body, nothing else movable between (a waist on a pedestal, a turntable): two arms hanging
    at rest from its shoulders down to the pedestal, no lower body drawn from the floor up,
    whose legs hang from the root's own body (or from a simulator's floating base)."""
    name = moved_by(tree.urdf, limb.base, {})
    joint = tree.urdf.joint(name) if name is not None else None
    if joint is None or joint.type not in _TURNING or not _on_the_root(tree, joint.parent):
        return False
    return parallel(tree.poses.axis(joint), _UP)


def _feet(
    tree: JointTree, pair: tuple[Limb, Limb], placed: dict[int, tuple[Place, Place]]
) -> tuple[bool, bool] | None:
    """Where the tips of ``pair`` are against the root's frame: whether both are below it by
    half their reach, and whether both are within half their reach of it (a root drawn at the
    feet). None when one of them does not hang nearly straight down (``_LEG_STRAIGHT``). A
    walker bolted to the world (read only when its name says it walks) is measured from the
    body its legs hang from, set up in the air, not from the world's origin on the floor."""
    bolted = _world_root(tree)
    body = pair[0].base if bolted else _free_body(tree)
    root = tree.poses.place(body)[2]
    below_the_root = at_the_root = True
    for limb in pair:
        start, end = placed[id(limb)]
        if bolted and start[2] > root + _SAME_PLACE:
            return None  # hips hang from the bottom of their body, shoulders from above it
        reach = distance(start, end)
        if reach == 0 or start[2] - end[2] < _LEG_STRAIGHT * reach:
            return None
        below_the_root = below_the_root and root - end[2] >= reach / 2
        at_the_root = at_the_root and abs(root - end[2]) <= reach / 2
    return below_the_root, at_the_root


def _level_with(
    candidates: list[Limb], placed: dict[int, tuple[Place, Place]], pair: tuple[Limb, Limb]
) -> list[Limb]:
    """The ``candidates`` like ``pair`` (a biped's legs by reach), the pair included: of as many
    joints, each hanging nearly straight down, their tips as low as the pair's (within
    :data:`_FEET_LEVEL` of the shortest drop). Four or more are a walker's legs, not a biped's
    two beside two arms hanging as low (arms hang from shoulders, their hands above the feet)."""
    drops = []
    level = []
    for limb in candidates:
        start, end = placed[id(limb)]
        reach = distance(start, end)
        if len(limb.joints) != len(pair[0].joints) or reach == 0:
            continue
        if start[2] - end[2] >= _LEG_STRAIGHT * reach:
            level.append(limb)
            drops.append(start[2] - end[2])
    if not level:
        return []
    lowest = min(placed[id(limb)][1][2] for limb in pair)
    tolerance = _FEET_LEVEL * min(drops)
    return [limb for limb in level if placed[id(limb)][1][2] - lowest <= tolerance]


def _leg_candidates(
    tree: JointTree, limbs: list[Limb], placed: dict[int, tuple[Place, Place]]
) -> list[Limb]:
    """Unnamed chains of two joints or more, no gripper's, placed, on the trunk
    (:func:`_on_the_trunk`: past an arm's joints, hanging fingers are a hand's, as
    :func:`legs_by_place` reads them), not every joint of them turning without end (a
    caster's swivel and its wheel turn for ever; a leg's hip and knee stop), unless there are
    as many as a humanoid's leg has and nothing spins on the body itself (a model that writes
    every joint continuous, with no limit, as a kid-size humanoid's of 2013 does, still hangs
    its legs so; a wheeled base's arms drawn so hang at rest beside its wheels)."""
    turns: dict[str, int] = {}
    endless_legs = not _spins_on_the_body(tree)
    return [
        limb
        for limb in limbs
        if limb.kind in ("arm", "other")
        and not limb.named
        and not limb.gripper
        and len(limb.joints) >= _LEG_JOINTS[0]
        and id(limb) in placed
        and _on_the_trunk(tree, limb.base, turns)
        and (
            (endless_legs and len(limb.joints) >= _ENDLESS_LEG_JOINTS)
            or not _spins_all_through(tree, limb)
        )
    ]


def _spins_on_the_body(tree: JointTree) -> bool:
    """An endless joint carrying nothing that moves turns on the root's rigid body (a wheel, a
    rotor)."""
    known: dict[str, str | None] = {}
    movable = [joint for joint in tree.urdf.joints if joint.movable]
    above = {joint.name: moved_by(tree.urdf, joint.parent, known) for joint in movable}
    carrying = set(above.values())
    return any(
        joint.endless and joint.name not in carrying and above[joint.name] is None
        for joint in movable
    )


# A chain of endless joints is a leg only when as long as a humanoid's leg (hip, knee, ankle);
# shorter, it may be a caster's swivel and wheel, or an arm hanging at rest on a wheeled base.
_ENDLESS_LEG_JOINTS = 5


def _spins_all_through(tree: JointTree, limb: Limb) -> bool:
    """Every joint of the chain turns without end (continuous, or a range no stop has), but
    continuous joints whose written limits are less than a whole turn apart: their author
    meant stops (a Unity import writes every hinge of a humanoid continuous, +-90 degrees)."""
    return all(
        (joint := tree.urdf.joint(name)) is not None and joint.endless and not _stops_written(joint)
        for name in limb.joints
    )


def _stops_written(joint: Joint) -> bool:
    """Limits written on the joint, less than a whole turn apart (and more than nothing)."""
    lower, upper = joint.lower, joint.upper
    return lower is not None and upper is not None and 0 < upper - lower < _WRITTEN_STOPS


# Written limits this far apart (radians) or more are a whole turn's (a wheel's +-pi).
_WRITTEN_STOPS = 1.5 * math.pi


def _pair_above(
    tree: JointTree,
    limbs: list[Limb],
    pair: tuple[Limb, Limb],
    placed: dict[int, tuple[Place, Place]],
    hips: float,
) -> bool:
    """Two other equal chains of two joints or more, arms (named, or ending in grippers) or
    unnamed ones, no head's, on the trunk (the body and a waist above it, as
    :func:`_trunk_above` reads it), start mirrored across it higher than ``hips``: a pair of
    arms above a pair of legs (a head's two ears turn on one joint each, a camera's pan and
    tilt are a head; a few chains only are compared, pair by pair). Mirrored across the root's
    frame, or, chains of three joints or more (an arm's shoulder and elbow, no antenna's or
    eye's two hinges), across the plane the legs' hips are mirrored about (a CAD export whose
    body frame is not on the robot's middle)."""
    depth: dict[str, int] = {}
    above = [
        limb
        for limb in limbs
        if limb not in pair
        and (limb.kind == "arm" or (limb.kind == "other" and not limb.named))
        and len(limb.joints) >= _LEG_JOINTS[0]
        and id(limb) in placed
        and placed[id(limb)][0][2] > hips
        and _joints_above(tree, limb.base, depth) <= _WAIST
    ]
    if len(above) > _MOST_ABOVE_THE_HIPS:
        return False
    (a, _), (b, _) = placed[id(pair[0])], placed[id(pair[1])]
    middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, 0.0)
    origins = ((0.0, 0.0, 0.0), middle)
    return any(
        len(one.joints) == len(other.joints)
        and any(
            _mirrored_either_way(minus(placed[id(one)][0], at), minus(placed[id(other)][0], at))
            for at in origins[: 2 if len(one.joints) >= _ARM_ABOVE_JOINTS else 1]
        )
        for index, one in enumerate(above)
        for other in above[index + 1 :]
    )


# Chains this long at least are arms above legs when mirrored about the hips' plane off the
# root's frame (two hinges may be a head's antennae or eyes).
_ARM_ABOVE_JOINTS = 3


def _trunk_above(
    tree: JointTree,
    limbs: list[Limb],
    pair: tuple[Limb, Limb],
    placed: dict[int, tuple[Place, Place]],
    hips: float,
) -> bool:
    """Every other chain on the trunk (the body and a waist above it) starts no lower than
    ``hips``; a hand's fingers, past an arm's joints, may hang lower."""
    depth: dict[str, int] = {}
    return not any(
        placed[id(limb)][0][2] < hips
        for limb in limbs
        if limb not in pair
        and id(limb) in placed
        and _joints_above(tree, limb.base, depth) <= _WAIST
    )


def _joints_above(
    tree: JointTree,
    link: str,
    known: dict[str, int],
    counted: Callable[[Joint], bool] = lambda joint: joint.movable,
) -> int:
    """How many ``counted`` joints (movable ones, by default) lie between the root and
    ``link``; every link walked is remembered in ``known`` (one ``known`` per ``counted``), so
    many links cost one walk of the tree at most."""
    walked: list[tuple[str, int]] = []
    current: str | None = link
    while current is not None and current not in known:
        joint = tree.urdf.parent_joint(current)
        walked.append((current, int(joint is not None and counted(joint))))
        current = None if joint is None else joint.parent
    count = 0 if current is None else known[current]
    for name, step in reversed(walked):
        count += step
        known[name] = count
    return count


def _on_the_trunk(tree: JointTree, link: str, turns: dict[str, int]) -> bool:
    """At most :data:`_TRUNK_TURNS` joints turn above ``link`` (a waist's, or a simulator's
    floating base's roll, pitch and yaw): legs may hang from it; past an arm's joints, chains
    are a hand's fingers. ``turns``: the walk's memory, one per reading."""
    return _joints_above(tree, link, turns, _turning) <= _TRUNK_TURNS


def _turning(joint: Joint) -> bool:
    """A joint that turns (a hip, a shoulder, a wrist); not a slide nor a floating or planar
    base a simulator's description writes as joints above the body."""
    return joint.movable and joint.type in _TURNING


def legs_by_place(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Alike unnamed chains on one link, four or more (of two to four joints; six or more of
    five or six joints, a hexapod's long legs), on both its sides or at the corners
    around their own middle, each ending below where it starts, the feet level: legs (a
    hexapod's, a quadruped's whose joints carry no leg names), when the link is the trunk's: at
    most :data:`_TRUNK_TURNS` joints turn above it (slides do not count; a simulator's floating
    base turns three); past an arm's joints they are a hand's fingers. The same holds for every
    way below (legs spread flat, at the corners, one-joint legs that turn whole)."""
    if _rolls(tree):
        return limbs  # chains on a body tracks or a drive plugin move are flippers, road wheels
    legs: dict[int, str] = {}
    turns: dict[str, int] = {}
    wheeled = _wheeled(tree)
    for base, kind, group in _chains_by_carrier(tree, limbs):
        if not _alike_enough(group) or not _on_the_trunk(tree, base, turns):
            continue  # a hand's fingers past an arm's joints: legs hang from the trunk
        if kind == "named":
            why = _sprawled_arms_why(tree, base, group, wheeled=wheeled)
        else:
            why = _legs_why(tree, base, group, wheeled=wheeled)
        if why:
            legs.update((id(limb), why) for limb in group)
    if not legs:
        return limbs
    return sort_limbs(
        tree,
        [
            replace(limb, kind="leg", why=legs[id(limb)]) if id(limb) in legs else limb
            for limb in limbs
        ],
    )


def _chains_by_carrier(tree: JointTree, limbs: list[Limb]) -> list[tuple[str, str, list[Limb]]]:
    """The chains that could be legs, grouped by the body carrying them and by their kind:
    unnamed chains (``chain``), one-joint chains that turn whole (``whole``, a wheel-leg
    walker's: a spinning leaf beside a hexapod's legs is no leg of it), and chains named as
    arms with no gripper (``named``). Chains on links fixed to one body hang from that body (a
    hip bracket each)."""
    by_base: dict[tuple[str, str], list[Limb]] = {}
    known: dict[str, str | None] = {}
    for limb in limbs:
        long_enough = _LEG_JOINTS[0] <= len(limb.joints) <= _MOST_LEG_JOINTS
        if limb.kind in ("arm", "other") and not limb.gripper and long_enough:
            kind = "named" if limb.named and not _elbows_only(tree, limb) else "chain"
            by_base.setdefault((_carrier(tree, limb.base, known), kind), []).append(limb)
        elif limb.kind == "other" and len(limb.joints) == 1 and _turns_whole(tree, limb):
            by_base.setdefault((_carrier(tree, limb.base, known), "whole"), []).append(limb)
    return [(base, kind, group) for (base, kind), group in by_base.items()]


def _elbows_only(tree: JointTree, limb: Limb) -> bool:
    """The chain is named as an arm's only by an elbow (``elbow_fl_1``): a bending joint a
    four-legged animal's foreleg has too, so its place tells (:func:`legs_by_place`) as an
    unnamed chain's does; an arm's, a shoulder's or a wrist's name says arm."""
    names = [name for joint in _joints_of(tree, limb) for name in (joint.name, joint.child)]
    return any(_ELBOW.search(name) for name in names) and not any(
        "arm" in tree.parts_of(_ELBOW.sub("", name)) for name in names
    )


# An elbow in a part's name.
_ELBOW = re.compile("elbow", re.IGNORECASE)


def _alike_enough(group: list[Limb]) -> bool:
    """Enough chains of one length to be a walker's legs: four or more, six or more when each
    has five or six joints (a hexapod's long legs; four such chains are arms)."""
    lengths = {len(limb.joints) for limb in group}
    if len(group) < _WALKER_LEGS or len(lengths) != 1:
        return False
    return max(lengths) <= _LEG_JOINTS[1] or len(group) >= _WHOLE_TURN_LEGS


def _legs_why(tree: JointTree, base: str, group: list[Limb], *, wheeled: bool) -> str:
    """Why alike chains around ``base`` are legs, or "" when they are not; ``wheeled``: the
    body has wheels of its own (:func:`_at_corners`; four chains reaching every way on it are
    a rover's flippers or rockers, no legs)."""
    if len(group[0].joints) == 1:
        if len(group) >= _WHOLE_TURN_LEGS and _around(tree, base, group) and _parallel(tree, group):
            return (
                "one of six or more one-joint chains turning whole about parallel axes around one"
                " body (a wheel-leg walker's legs)"
            )
        return ""
    if _stands(tree, base, group):
        return (
            "one of alike chains around one link, each ending below where it starts (legs by place)"
        )
    if len(group) >= _WHOLE_TURN_LEGS and _spreads(tree, base, group):
        return (
            "one of six or more alike chains around one link, each reaching out flat from it"
            " (a walker's legs at rest, by place)"
        )
    if len(group) >= _WHOLE_TURN_LEGS and _spreads_from_hips(tree, group):
        return (
            "one of six or more alike chains starting on one plane around their middle, each"
            " reaching out from it and not up from that plane (a walker's legs, its body drawn"
            " tilted or away from its link's origin in the file: legs by place)"
        )
    if _at_corners(tree, base, group, wheeled=wheeled):
        return (
            "one of alike chains starting in mirrored pairs at the corners of one link (a"
            " walker's hips, its legs folded at rest: legs by place)"
        )
    if not wheeled and _spreads(tree, base, group) and _every_way(tree, group):
        return (
            "one of alike chains around one link, each reaching out flat from it, every way"
            " (a walker's legs sprawled at rest, by place)"
        )
    if not wheeled and _named_corners(group):
        return (
            "one of alike chains named for the four corners of one body (FL, FR, RL, RR: a"
            " walker's legs, whichever way the file stands it up)"
        )
    return ""


def _named_corners(group: list[Limb]) -> bool:
    """Each chain names one corner of a body the same way in its joints and links, as a
    walker's legs are short-named (``L1_FL1``, ``LF_HFE``, ``rr_knee``: front or rear, left or
    right, either first), and together they name all four. A hand's fingers share one side's
    letters (``rh_``) and name no corners."""
    corners = set()
    for limb in group:
        found = {
            _corner(token) for name in (*limb.joints, limb.tip) for token in _TOKEN.findall(name)
        }
        found.discard(None)
        if len(found) != 1:
            return False
        corners |= found
    return len(corners) == _CORNERS


def _corner(token: str) -> tuple[str, str] | None:
    """The corner a two-letter token names (front or rear, then left or right), or None."""
    token = token.lower()
    if len(token) != _CORNER_LETTERS:
        return None
    first, second = token[0], token[1]
    if first in "fbhr" and second in "lr":
        return ("front" if first == "f" else "rear", second)
    if first in "lr" and second in "fbh":
        return ("front" if second == "f" else "rear", first)
    return None


# A name's short words, between separators or digits (``L1_FL1``: ``L``, ``FL``).
_TOKEN = re.compile(r"[A-Za-z]+")
_CORNER_LETTERS = 2
_CORNERS = 4


def _sprawled_arms_why(tree: JointTree, base: str, group: list[Limb], *, wheeled: bool) -> str:
    """Why alike chains named as arms are legs, or "": :data:`_SPRAWLED_ARMS` or more with no
    gripper, on a body with no wheels, each reaching out flat from the link they hang from,
    every way (a walker whose makers named its legs' parts shoulders and arms; no body holds
    so many arms sprawled so)."""
    if len(group) < _SPRAWLED_ARMS or wheeled:
        return ""
    if not (_spreads(tree, base, group) and _every_way(tree, group)):
        return ""
    return (
        f"one of {len(group)} alike chains named as arms around one link, each reaching out flat"
        " from it, every way (a walker's legs sprawled at rest, named as arms: by place)"
    )


def _rolls(tree: JointTree) -> bool:
    """Tracks or a drive plugin move the body."""
    return bool(tree.labels("drive")) or _tracked(tree)


def _tracked(tree: JointTree) -> bool:
    """Tracks move the body: a track plugin, or track-named joints."""
    return bool(tree.labels("track")) or any(
        tree.tread(joint) for joint in tree.urdf.joints if joint.movable
    )


def flippers(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """On a body tracks move, chains read as legs (by a corner's name: ``front_left_flipper``)
    are its flippers: they tilt track segments, nothing walks."""
    if not any(limb.kind == "leg" for limb in limbs) or not _tracked(tree):
        return limbs
    why = "a flipper: a chain on a body that tracks move"
    return [replace(limb, kind="other", why=why) if limb.kind == "leg" else limb for limb in limbs]


def raised_legs(tree: JointTree, limbs: list[Limb], roles: Mapping[str, Role]) -> list[Limb]:
    """On a body that rolls on wheels of its own (three or more, each a joint that turns its
    wheel and carries nothing that moves, none carried by a chain read as a leg), chains read
    as legs by a corner's name alone (``panel_back_right``: no leg's word, hip, knee, foot ...,
    on any of their joints and links) whose tips stand higher than every wheel's axle as drawn
    reach no ground: a rover's solar panels or a mast, not legs. A wheel-legged robot's legs
    carry its wheels; a walker rolls on none; legs named as legs stay legs however drawn (a
    humanoid standing on a cart); a leg-named chain ending in a gripper is an arm
    (:func:`gripping_leg`)."""
    legs = [
        limb
        for limb in limbs
        if limb.kind == "leg" and not limb.gripper and _named_by_corner_only(tree, limb)
    ]
    wheels = [
        j
        for j in tree.urdf.joints
        if j.name in roles and roles[j.name].role == "wheel" and j.child not in tree.moving_below
    ]
    if not legs or len(wheels) < _BODY_WHEELS or len(legs) > _MOST_RAISED_LEGS:
        return limbs
    carried = set().union(*(_below(tree, first) for first in _first_joints(tree, legs)))
    if any(wheel.name in carried for wheel in wheels):
        return limbs
    axles = max(tree.poses.place(wheel.child)[2] for wheel in wheels)
    why = "a chain named as a leg above the axles of the wheels the body rolls on (no leg)"
    return [
        replace(limb, kind="other", why=why)
        if limb in legs and tree.poses.place(limb.tip)[2] > axles
        else limb
        for limb in limbs
    ]


def _first_joints(tree: JointTree, limbs: list[Limb]) -> Iterator[Joint]:
    """Each of ``limbs``' first joints (those the description has)."""
    for limb in limbs:
        first = tree.urdf.joint(limb.joints[0])
        if first is not None:
            yield first


def _named_by_corner_only(tree: JointTree, limb: Limb) -> bool:
    """No joint or link of ``limb`` reads as a leg's once the body's corners are taken out of
    its name (``front_left_hip`` still says hip; ``panel_back_right`` says nothing)."""
    for name in limb.joints:
        joint = tree.urdf.joint(name)
        for text in (name, joint.child if joint is not None else ""):
            if "leg" in tree.parts_of(_CORNER.sub("_", text)):
                return False
    return True


def meeting_tips(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Three chains read as legs or more whose tips meet (across the ground, a fraction of how
    far apart they start): a parallel robot (a delta, its arms named as legs, all holding one
    platform), one manipulator, not legs: a walker's feet stand at least as far apart as its
    hips. Its longest chain is the arm, the others are its linkage."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if not _MEETING_LEGS <= len(legs) <= _MOST_MEETING_LEGS or _coxae(tree, legs):
        return limbs  # a stranger's thousands of chains are not compared pair by pair
    starts = [_start(tree, limb) for limb in legs]
    tips = [tree.poses.place(limb.tip) for limb in legs]
    if not tips_meet(starts, tips, _flat):
        return limbs
    # One manipulator: its longest chain is the arm, the others its parallel linkage.
    arm = max(legs, key=lambda limb: len(limb.joints))
    why = "a parallel robot: chains whose tips meet, holding one platform (a delta)"
    return [
        replace(limb, kind="arm" if limb is arm else "other", why=why)
        if limb.kind == "leg"
        else limb
        for limb in limbs
    ]


def sprawling(tree: JointTree, limbs: list[Limb]) -> bool:
    """The legs of ``limbs``, three or more, each a walker's with a coxa (:func:`_coxae`): a
    body slung between sprawled legs, as an insect's or a spider's is (a hexapod, a "spider"
    quadruped), not a mammal's legs under it (a hip rolling the leg out first) nor a biped's,
    whose hip yaw turns a leg standing under it."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    return len(legs) >= _SPRAWLING_LEGS and _coxae(tree, legs)


# Legs a sprawled body is slung between, at least (two legs stand under a biped).
_SPRAWLING_LEGS = 3


def _coxae(tree: JointTree, legs: list[Limb]) -> bool:
    """Every leg is a walker's: its first joint turns about the vertical as the body rests (a
    hip swinging the leg fore and aft, a hexapod's coxa), a later one about a level axis (the
    leg's lift), and none slides. Its feet may be tucked together under the body as drawn (a
    morphing robot's ball); a parallel robot's motors turn its arms up and down about level
    axes, a planar one's all turn about the vertical, and a Stewart platform's legs slide."""
    return all(_coxa(tree, limb) for limb in legs)


def _coxa(tree: JointTree, leg: Limb) -> bool:
    joints = [tree.urdf.joint(name) for name in leg.joints]
    if any(joint is None or joint.type not in _TURNING for joint in joints):
        return False
    axes = [abs(tree.poses.axis(joint)[2]) for joint in joints if joint is not None]
    return axes[0] >= _COXA and any(z < 1 - _COXA for z in axes[1:])


# How upright (the z part of the unit axis at rest) a walker's hip yaw turns; a lift's axis
# is level within the rest.
_COXA = 0.9


def tips_meet(
    starts: list[Place], tips: list[Place], measure: Callable[[Place, Place], float]
) -> bool:
    """The tips lie closer together, by ``measure`` (across the ground, or in space), than
    :data:`_MEETING` of how far apart the chains start: one platform's linkage. Pair by pair:
    callers bound how many chains they compare."""
    apart = max(measure(a, b) for a in starts for b in starts)
    return apart > 0 and max(measure(a, b) for a in tips for b in tips) < _MEETING * apart


def parallel_robot(tree: JointTree, limbs: list[Limb], *, flying: bool = False) -> list[Limb]:
    """Three or six alike chains, all the body's limbs (or all but one chain of slides that
    places the platform: :func:`_beside_a_slid_platform`), none a leg or ending in a gripper, on
    one rigid body, starting on a circle whose third of a turn maps their starts onto each
    other: a parallel robot (a delta's three arms, a Stewart platform's six), one manipulator
    whose platform the description cannot hold. Its longest chain is the arm, the others its
    linkage (as :func:`meeting_tips` reads chains named as legs whose tips meet). Chains named
    as legs count when they are struts on a body bolted to the world (:func:`_struts`): a
    walker is not bolted down, and does not walk on linear actuators. Three chains named as
    legs on the root bolted to the world are a delta's arms beside other limbs too
    (:func:`_bolted_legs`: the platform a simulator moves on a chain of its own). On a body
    that flies, single joints on the airframe (its root and the links fixed to it) are its own,
    no mechanism (:func:`_on_the_airframe`: six propellers' mounts, written alike)."""
    bolted = _bolted_legs(tree, limbs)
    group = bolted or _beside_a_slid_platform(tree, limbs) or limbs
    struts = bool(bolted) or _struts(tree, group)
    if len(group) not in _PARALLEL_CHAINS or not _alike_chains(tree, group, legs=struts):
        return limbs
    if flying and _on_the_airframe(tree, group):
        return limbs
    starts = [_start(tree, limb) for limb in group]
    if not _third_turn_symmetric(starts):
        return limbs
    chains = {id(limb) for limb in group}
    # The platform a chain of its own moves is the arm (the delta's reach); else its longest.
    moved = any(limb.kind == "arm" and id(limb) not in chains for limb in limbs)
    arm = None if moved else max(group, key=lambda limb: len(limb.joints))
    why = (
        f"a parallel mechanism: {len(group)} alike chains on a circle, a third of a turn "
        "apart (a delta, a Stewart platform, a three-jaw claw)"
    )
    return [
        replace(limb, kind="arm" if limb is arm else "other", why=why)
        if id(limb) in chains
        else limb
        for limb in limbs
    ]


def _beside_a_slid_platform(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """All but one of ``limbs``, three or six of one sequence of joint types, when the other is
    a chain of two slides or more alone, each along its own line (no two parallel): a parallel
    robot's arms beside the platform its author places on slides of its own (x, y and z
    prismatic joints standing in for the loops the description cannot close). That chain is
    then its reach (:func:`parallel_robot`); one slide alone is a lift, no platform."""
    if len(limbs) - 1 not in _PARALLEL_CHAINS:
        return []
    kinds = [_joint_types(tree, limb) for limb in limbs]
    slid = [i for i, types in enumerate(kinds) if set(types) == {"prismatic"}]
    if len(slid) != 1 or not _slides_apart(tree, limbs[slid[0]]):
        return []
    odd = slid[0]
    arms = limbs[:odd] + limbs[odd + 1 :]
    return arms if len(set(kinds[:odd] + kinds[odd + 1 :])) == 1 else []


def _slides_apart(tree: JointTree, limb: Limb) -> bool:
    """Two slides or more in ``limb``, no two along parallel lines as the body rests."""
    joints = _joints_of(tree, limb)
    axes = [tree.poses.axis(joint) for joint in joints]
    return len(axes) >= _PLATFORM_SLIDES and not any(
        parallel(one, other) for one, other in combinations(axes, 2)
    )


# A platform placed on slides of its own moves along two lines at least (x and y, or x, y, z).
_PLATFORM_SLIDES = 2


def _on_the_airframe(tree: JointTree, group: list[Limb]) -> bool:
    """Every chain of ``group`` is one joint starting on the root's rigid body."""
    known: dict[str, str | None] = {}
    return all(
        len(limb.joints) == 1 and moved_by(tree.urdf, limb.base, known) is None for limb in group
    )


def _bolted_legs(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Exactly three chains read as legs (by their names or where they hang), each starting on
    the root of a description bolted to the world (its root is ``world``, no moving joint
    between): a delta's three arms, which its makers call legs, whatever other chains the model
    adds (a platform moved on a chain of its own). No walker stands on three legs bolted to the
    world."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    bolted = len(legs) == _DELTA_LEGS and all(limb.base in tree.bolted for limb in legs)
    return legs if bolted else []


# A parallel robot's chains: a delta's three, a Stewart platform's six.
_PARALLEL_CHAINS = (3, 6)
# A delta's arms, named as legs.
_DELTA_LEGS = 3
# Starts this close (a share of the circle's radius) are one place.
_ON_CIRCLE = 0.1


def _struts(tree: JointTree, limbs: list[Limb]) -> bool:
    """Every chain slides (a prismatic joint: a linear actuator's strut), rises from where it
    starts (to the platform it holds up; a walker's feet hang below its hips), and starts on a
    body bolted to the world (its root is ``world``, no moving joint between): a Stewart
    platform's legs, not a walker's on a floating base hung from ``world``."""
    return _world_root(tree) and all(
        _on_the_root(tree, limb.base)
        and tree.poses.place(limb.tip)[2] > _start(tree, limb)[2]
        and "prismatic" in _joint_types(tree, limb)
        for limb in limbs
    )


def _alike_chains(tree: JointTree, limbs: list[Limb], *, legs: bool = False) -> bool:
    """Chains of one sequence of joint types (one of them may go on: the joint that turns
    the platform), none ending in a gripper nor a leg (but with ``legs``), all on one rigid
    body (the same nearest moving joint above their bases)."""
    known: dict[str, str | None] = {}
    first = limbs[0]
    kinds = [_joint_types(tree, limb) for limb in limbs]
    shortest = min(len(k) for k in kinds)
    if sum(len(k) > shortest for k in kinds) > 1:
        return False
    kinds_taken = ("arm", "other", "leg") if legs else ("arm", "other")
    return all(
        limb.kind in kinds_taken
        and not limb.gripper
        and kinds[i][:shortest] == kinds[0][:shortest]
        and moved_by(tree.urdf, limb.base, known) == moved_by(tree.urdf, first.base, known)
        for i, limb in enumerate(limbs)
    )


def _joint_types(tree: JointTree, limb: Limb) -> tuple[str, ...]:
    return tuple(j.type if (j := tree.urdf.joint(n)) is not None else "" for n in limb.joints)


def _third_turn_symmetric(starts: list[Place]) -> bool:
    """``starts`` lie on a level circle (one height, one radius from their middle) and a third
    of a turn about its middle maps each onto another."""
    cx = sum(p[0] for p in starts) / len(starts)
    cy = sum(p[1] for p in starts) / len(starts)
    radii = [math.hypot(p[0] - cx, p[1] - cy) for p in starts]
    if not all(math.isfinite(r) for r in (cx, cy, *radii)):
        return False  # a stranger's 1e308s overflow: no circle is read
    radius = max(radii)
    heights = [p[2] for p in starts]
    # Each test is written so that a NaN (a stranger's overflowing numbers) fails it.
    if not (radius >= _SAME_PLACE and min(radii) >= (1 - _ON_CIRCLE) * radius):
        return False
    if not max(heights) - min(heights) <= _ON_CIRCLE * radius:
        return False
    turn = 2 * math.pi / 3
    cos, sin = math.cos(turn), math.sin(turn)
    for x, y, _ in starts:
        rx = cx + cos * (x - cx) - sin * (y - cy)
        ry = cy + sin * (x - cx) + cos * (y - cy)
        if not min(math.hypot(rx - p[0], ry - p[1]) for p in starts) <= _ON_CIRCLE * radius:
            return False
    return True


def _at_corners(tree: JointTree, base: str, group: list[Limb], *, wheeled: bool) -> bool:
    """The chains start at the corners of ``base``: in pairs mirrored across it (left and right
    at one place along it), spread front to back at least as far as a pair is from the middle.
    A walker's hips are so, however its legs are folded in the zero pose; a hand's fingers
    start side by side along one edge of the palm. The middle is the link's origin or, where a
    CAD export put that origin at a corner of the chains' starts or beyond them (inside their
    box along neither x nor y), the middle of the starts; not on a body with wheels of its own
    (``wheeled``: a tracked base's flippers)."""
    placed = chain_ends(tree, group)
    if placed is None:
        return False
    starts = [start for start, _ in placed]
    origin = tree.poses.place(base)
    middles = [(origin[0], origin[1])]
    low = [min(s[i] for s in starts) + _SAME_PLACE for i in (0, 1)]
    high = [max(s[i] for s in starts) - _SAME_PLACE for i in (0, 1)]
    if not wheeled and not any(low[i] < origin[i] < high[i] for i in (0, 1)):
        middles.append(_middle(starts))
    return any(
        _corners_either_way([(s[0] - middle[0], s[1] - middle[1]) for s in starts])
        for middle in middles
    )


def _wheeled(tree: JointTree) -> bool:
    """A movable joint of the body is named as a wheel's."""
    return any(tree.matches("wheel", joint) for joint in tree.urdf.joints if joint.movable)


def _middle(starts: list[Place]) -> tuple[float, float]:
    """The middle of the box around ``starts`` across the ground (x and y)."""
    xs, ys = [start[0] for start in starts], [start[1] for start in starts]
    return ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)


def _corners_either_way(corners: list[tuple[float, float]], *, standing: bool = False) -> bool:
    """``corners`` (from the body's middle) are a walker's hips facing x (:func:`_corners`);
    only when no pairing across x's line is found, facing y (a body drawn with its length
    along y): a square of four chains paired one way is not tried the other way, unless the
    chains stand (``standing``: feet level below the hips), when a body longer along y than
    its hips are apart across x is tried facing y too."""
    if len(corners) > _MOST_FIVE_BAR_LEGS:
        return False  # no walker has so many: a stranger's file is not compared pair by pair
    paired = _corners(corners)
    if paired is not None and (paired or not standing):
        return paired
    swapped = _corners([(y, x) for x, y in corners])
    return bool(swapped)


def _corners(starts: list[tuple[float, float]]) -> bool | None:
    """``starts`` (x along the body, y across it, from its middle): ``None`` when they do not
    come in pairs mirrored across the middle, else whether they spread front to back at least
    as far as a pair is from the middle."""
    across = max((abs(y) for _, y in starts), default=0.0)
    tolerance = _MIRRORED * across
    if across <= 0:
        return None
    for x, y in starts:
        if abs(y) <= tolerance or not any(
            abs(x2 - x) <= tolerance and abs(y2 + y) <= tolerance for x2, y2 in starts
        ):
            return None
    along = [x for x, _ in starts]
    return max(along) - min(along) >= across


def _turns_whole(tree: JointTree, limb: Limb) -> bool:
    """The limb's one joint turns all the way round (continuous, or a range of a full turn)."""
    joint = tree.urdf.joint(limb.joints[0])
    return joint is not None and joint.mimic is None and joint.turns(_FULL_TURN)


def _parallel(tree: JointTree, group: list[Limb]) -> bool:
    """The chains' first joints turn about parallel axes."""
    axes = []
    for limb in group:
        joint = tree.urdf.joint(limb.joints[0])
        if joint is None:
            return False
        axes.append(tree.poses.axis(joint))
    return all(parallel(axes[0], axis) for axis in axes[1:])


def _around(tree: JointTree, base: str, group: list[Limb]) -> bool:
    """The chains start on both sides of ``base`` and at three places or more along it."""
    centre, placed = tree.poses.place(base), chain_ends(tree, group)
    if placed is None or not _both_sides(centre, placed):
        return False
    along = {round(start[0] - centre[0], 2) for start, _ in placed}
    return len(along) >= _WHOLE_TURN_ROWS


def _spreads(tree: JointTree, base: str, group: list[Limb]) -> bool:
    """Each chain, on both sides of ``base``, ends farther out from it across the ground than
    it starts, by most of its reach, and not above it by more than a leg's drop share."""
    centre, placed = tree.poses.place(base), chain_ends(tree, group)
    if placed is None:
        return False
    for start, end in placed:
        reach = distance(start, end)
        out = _flat(end, centre) - _flat(start, centre)
        if reach == 0 or out < _LEG_SPREAD * reach or end[2] - start[2] > _LEG_DROP * reach:
            return False
    return _both_sides(centre, placed)


def _every_way(tree: JointTree, group: list[Limb]) -> bool:
    """The chains reach every way from where they start: their directions at rest (first
    joint to tip, each of length one) cancel, their mean shorter than :data:`_EVERY_WAY`, and
    they reach both ways along x and both ways along y (each counted along an axis where it
    goes at least :data:`_ALONG` of its length). A walker's legs sprawl around its body; a
    hand's fingers, drawn flat, reach one way; a torso's arms held out, left and right."""
    placed = chain_ends(tree, group)
    if placed is None:
        return False
    units = []
    for start, end in placed:
        unit = _unit_or_none(minus(end, start))
        if unit is None:
            return False
        units.append(unit)
    ways = {
        (axis, unit[axis] > 0) for unit in units for axis in (0, 1) if abs(unit[axis]) >= _ALONG
    }
    return math.hypot(*centroid(units)) < _EVERY_WAY and len(ways) == 4


def _unit_or_none(vector: Place) -> Place | None:
    """``vector`` of length one, or None when it has no length (or a stranger's overflows)."""
    length = math.hypot(*vector)
    if not (math.isfinite(length) and length > _SAME_PLACE):
        return None
    return (vector[0] / length, vector[1] / length, vector[2] / length)


def _spreads_from_hips(tree: JointTree, group: list[Limb]) -> bool:
    """:func:`_spreads` on a body the file draws tilted or away from its link's origin (a CAD
    export's, the origin at a corner of the body): "up" read from the plane the chains start on
    (a walker's hips, around their middle), the file's z or tilted from it but not standing on
    edge, taken on its side where z rises. Each chain ends farther out from the hips' middle
    along that plane than it starts, by most of its reach, and not up from the plane by more
    than a leg's drop share. Hips along one line (a hand's fingers in a row) are on no plane."""
    placed = chain_ends(tree, group)
    if placed is None or len(placed) > _MOST_FIVE_BAR_LEGS:
        return False  # a stranger's thousands of chains are not paired hip by hip
    middle = centroid([start for start, _ in placed])
    # Read at the hips' own scale (a stranger's 1e100s neither overflow nor pass unread).
    radius = max(math.hypot(*minus(start, middle)) for start, _ in placed)
    if not (math.isfinite(radius) and radius >= _SAME_PLACE):
        return False
    scaled = [
        (_scaled(start, middle, radius), _scaled(end, middle, radius)) for start, end in placed
    ]
    normal = _plane([start for start, _ in scaled])
    if normal is None or perpendicular(normal, _UP):
        return False  # on edge (no side is "up")
    if parallel(normal, _UP):
        normal = _UP  # level: the file's z is "up"
    if normal[2] < 0:
        normal = (-normal[0], -normal[1], -normal[2])
    for start, end in scaled:
        reach = distance(start, end)
        out = _along_plane(end, normal) - _along_plane(start, normal)
        rise = dot(minus(end, start), normal)
        # Each test is written so that a NaN or an overflow fails it.
        if not (
            math.isfinite(reach)
            and reach > 0
            and out >= _LEG_SPREAD * reach
            and rise <= _LEG_DROP * reach
        ):
            return False
    return True


# The file's "up".
_UP = (0.0, 0.0, 1.0)
# Hips on a plane: none off it by more than this share of their radius, and not along one line
# (the widest pair of them spans at least this share of the radius squared).
_OFF_THE_PLANE = 0.1
_ALONG_A_LINE = 0.25


def _scaled(place: Place, middle: Place, radius: float) -> Place:
    offset = minus(place, middle)
    return (offset[0] / radius, offset[1] / radius, offset[2] / radius)


def _plane(offsets: list[Place]) -> Place | None:
    """The unit normal of the plane ``offsets`` (from their middle, the farthest at 1) lie on:
    spread both ways along it, none off it by more than :data:`_OFF_THE_PLANE`; else ``None``."""
    widest = max(
        (cross(one, other) for index, one in enumerate(offsets) for other in offsets[index + 1 :]),
        key=lambda normal: math.hypot(*normal),
    )
    size = math.hypot(*widest)
    if not (math.isfinite(size) and size >= _ALONG_A_LINE):
        return None  # the places lie along one line: no plane is theirs
    normal = (widest[0] / size, widest[1] / size, widest[2] / size)
    if not all(abs(dot(offset, normal)) <= _OFF_THE_PLANE for offset in offsets):
        return None
    return normal


def _along_plane(offset: Place, normal: Place) -> float:
    """How far ``offset`` (from the hips' middle) reaches along the plane of ``normal``."""
    across = dot(offset, normal)
    return math.hypot(*minus(offset, (normal[0] * across, normal[1] * across, normal[2] * across)))


def _stands(tree: JointTree, base: str, group: list[Limb]) -> bool:
    """Each chain ends below where it starts, the feet level with one another (a walker stands
    on the ground; a hand's fingers, hanging down, end at their own lengths), the chains
    starting on both sides of ``base``, or (a CAD export may put the body's origin at a corner
    of it, every hip on one side) at the corners around their own middle, facing x or y."""
    placed = chain_ends(tree, group)
    if placed is None:
        return False
    for start, end in placed:
        reach = distance(start, end)
        if reach == 0 or start[2] - end[2] < _LEG_DROP * reach:
            return False
    feet = spread([end[2] for _, end in placed])
    if feet > _FEET_LEVEL * min(start[2] - end[2] for start, end in placed):
        return False
    if _both_sides(tree.poses.place(base), placed):
        return True
    middle = _middle([start for start, _ in placed])
    corners = [(start[0] - middle[0], start[1] - middle[1]) for start, _ in placed]
    # Facing x, or facing y (a CAD export's rows of hips along y): standing, either way.
    return _corners_either_way(corners, standing=True)


Place = tuple[float, float, float]


def chain_ends(tree: JointTree, group: list[Limb]) -> list[tuple[Place, Place]] | None:
    """Where each chain starts (its first joint's child) and ends (its tip); ``None`` when a
    first joint is missing."""
    placed = []
    for limb in group:
        first = tree.urdf.joint(limb.joints[0])
        if first is None:
            return None
        placed.append((tree.poses.place(first.child), tree.poses.place(limb.tip)))
    return placed


def _both_sides(centre: Place, placed: list[tuple[Place, Place]]) -> bool:
    """Some chains start left of ``centre`` and some right of it (across y)."""
    sides = {
        start[1] - centre[1] > 0 for start, _ in placed if abs(start[1] - centre[1]) > _SAME_PLACE
    }
    return sides == {True, False}


def _flat(one: Place, other: Place) -> float:
    """Distance across the ground (x and y only)."""
    return math.hypot(one[0] - other[0], one[1] - other[1])


def five_bars(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Pairs of leg chains that are one five-bar leg (see the module docstring), merged; then
    pairs of the legs left that hang from one hip's hinge (:func:`_one_hinge`), merged."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if len(legs) > _MOST_FIVE_BAR_LEGS:
        return limbs  # no walker has so many: a stranger's file is not paired leg by leg
    several_hips = _hip_points(tree, legs) > 1
    limbs = _merge_legs(
        tree, limbs, lambda one, other: _one_leg(tree, one, other, several_hips=several_hips)
    )
    if not several_hips:
        return limbs
    hinges = _hinges(tree, [limb for limb in limbs if limb.kind == "leg"])
    return _merge_legs(tree, limbs, lambda one, other: _one_hinge(tree, one, other, hinges))


def _merge_legs(
    tree: JointTree, limbs: list[Limb], why_one: Callable[[Limb, Limb], str]
) -> list[Limb]:
    """Each leg chain merged with the first later one ``why_one`` gives a reason for, each
    chain in one merge at most."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    merged: dict[int, Limb] = {}
    used: set[int] = set()
    for index, one in enumerate(legs):
        if id(one) in used:
            continue
        for other in legs[index + 1 :]:
            why = "" if id(other) in used else why_one(one, other)
            if why:
                merged[id(one)] = replace(one, joints=one.joints + other.joints, why=why)
                used.update((id(one), id(other)))
                break
    if not merged:
        return limbs
    kept = [
        merged.get(id(limb), limb) for limb in limbs if id(limb) not in used or id(limb) in merged
    ]
    return sort_limbs(tree, kept)


def closed_loops(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two chains a loop-closing joint of a ``<gazebo>`` block joins (an SDF joint from a link
    below one to a link below the other: the loop a URDF cannot write) are one linkage, read as
    the one that carries something (a wheel's mount, an arm, before a leg): a wheel-legged
    robot's passive rear link closed onto the front one at its wheel is no leg of its own."""
    if not tree.urdf.closures:
        return limbs
    owner = {name: index for index, limb in enumerate(limbs) for name in limb.joints}
    known: dict[str, str | None] = {}
    into: dict[int, int] = {}
    for parent, child in tree.urdf.closures:
        ends = [_limb_below(tree, link, owner, known) for link in (parent, child)]
        if None in ends or ends[0] == ends[1]:
            continue
        one, other = sorted(
            (i for i in ends if i is not None),
            key=lambda i: _KEPT.index(limbs[i].kind) if limbs[i].kind in _KEPT else len(_KEPT),
        )
        # A chain is closed onto one other, or keeps others closed onto it, never both: a
        # chain of closures never drops the chain in its middle.
        if other not in into and one not in into and other not in into.values():
            into[other] = one
    return _merged(limbs, into, "closed by a loop joint with {}'s chain")


def drive_rods(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """A chain with no gripper whose joints after its first are all free (hinges written blank,
    0..0 with no effort, or mimic followers) and whose end stands within :data:`_LOOP_CLOSED`
    of a link another limb moves is that limb's drive rod, the loop a URDF cannot close: merged
    into it (a dexterous hand's wrist tilted by two rods on slides, each drawn as its slide and
    the free hinges of its ball joints, ending at the wrist's pins). Linear: each end is
    compared with the first links (:data:`_CELL_LINKS`) of the cells of
    :data:`_LOOP_CLOSED` around it."""
    if not 2 <= len(limbs) <= _MOST_FIVE_BAR_LEGS:
        return limbs
    movable = [joint for joint in tree.urdf.joints if joint.movable]
    if all(written_blank(joint) for joint in movable):
        return limbs  # an export that wrote no limits: its free joints say nothing
    rods = [i for i, limb in enumerate(limbs) if _a_rod(tree, limb)]
    if not rods:
        return limbs
    rod_set = set(rods)
    owner = {name: index for index, limb in enumerate(limbs) for name in limb.joints}
    cells = _links_by_cell(tree)
    known: dict[str, str | None] = {}
    into: dict[int, int] = {}
    for i in rods:
        tip = tree.poses.place(limbs[i].tip)
        for link in _links_near(tree, cells, tip):
            held = _limb_below(tree, link, owner, known)
            if held is not None and held not in rod_set:  # a rod drives no rod
                into[i] = held
                break
    return _merged(limbs, into, "driven by a rod closed onto it ({}'s chain)")


def _merged(limbs: list[Limb], into: dict[int, int], reason: str) -> list[Limb]:
    """``limbs`` with each of ``into``'s keys merged into the limb it maps to (no key is a
    value), its joints after the kept limb's; ``reason`` says why, its ``{}`` the merged
    chain's first joint."""
    if not into:
        return limbs
    merged = {kept: limbs[kept] for kept in into.values()}
    for closed, kept in into.items():
        limb = merged[kept]
        why = f"{limb.why}; {reason.format(shown(limbs[closed].joints[0]))}"
        merged[kept] = replace(limb, joints=limb.joints + limbs[closed].joints, why=why)
    return [merged.get(i, limb) for i, limb in enumerate(limbs) if i not in into]


def _a_rod(tree: JointTree, limb: Limb) -> bool:
    """``limb`` is no leg and carries no gripper; its first joint is driven (neither written
    blank nor a mimic follower: the rod's motor or slide) and every joint after it is free (a
    rod's ball joints, drawn as hinges); and it reaches out, its end farther than
    :data:`_LOOP_CLOSED` from where it starts (chains drawn at one point close no loop)."""
    if limb.kind == "leg" or limb.gripper or len(limb.joints) < _ROD_JOINTS:
        return False
    joints = [tree.urdf.joint(name) for name in limb.joints]
    first, rest = joints[0], joints[1:]
    if first is None or written_blank(first) or first.mimic:
        return False
    if not all(j is not None and (written_blank(j) or j.mimic) for j in rest):
        return False
    start = tree.poses.place(first.parent)
    return distance(start, tree.poses.place(limb.tip)) > _LOOP_CLOSED


# A rod is its drive and at least one free joint.
_ROD_JOINTS = 2


# A cell's links a rod's end is compared with (a stranger's crowd of links at one point costs
# no more).
_CELL_LINKS = 8


def _links_by_cell(tree: JointTree) -> dict[tuple[int, int, int], list[str]]:
    """Every link with a place, by the cell of :data:`_LOOP_CLOSED` it stands in."""
    cells: dict[tuple[int, int, int], list[str]] = {}
    for link in tree.urdf.links:
        cell = grid_cell(tree.poses.place(link.name), _LOOP_CLOSED)
        if cell is not None:
            cells.setdefault(cell, []).append(link.name)
    return cells


def _links_near(
    tree: JointTree, cells: dict[tuple[int, int, int], list[str]], place: Vector
) -> list[str]:
    """The links of the cells around ``place`` (at most :data:`_CELL_LINKS` of each) within
    :data:`_LOOP_CLOSED` of it."""
    cell = grid_cell(place, _LOOP_CLOSED)
    if cell is None:
        return []
    x, y, z = cell
    return [
        link
        for dx, dy, dz in CELLS_AROUND
        for link in cells.get((x + dx, y + dy, z + dz), [])[:_CELL_LINKS]
        if distance(tree.poses.place(link), place) <= _LOOP_CLOSED
    ]


def legs_through_linkages(
    tree: JointTree, limbs: list[Limb], trunk: list[str]
) -> tuple[list[Limb], list[str]]:
    """A short chain ending in a foot, below trunk joints that branch only into other short
    chains (a leg's linkage drawn open: a rod, a servo's horn), is the end of one leg: the
    trunk joints from the body down to it and the chain are that leg, the short branches its
    linkage (``other``). Only when the trunk joints carry a leg's name, nothing above them
    is a limb's but the body, and the branch holds no other foot, arm or leg."""
    if len(limbs) > _MOST_FIVE_BAR_LEGS:
        return limbs, trunk  # a stranger's thousands of chains are not walked one by one
    free = set(trunk)
    owner = {name: i for i, limb in enumerate(limbs) for name in limb.joints}
    legs: dict[int, Limb] = {}
    linkage: set[int] = set()
    for i, limb in enumerate(limbs):
        if limb.kind not in ("other", "leg") or not _FOOT.search(limb.tip):
            continue
        found = _leg_through(tree, limbs, i, owner, free)
        if found is not None:
            legs[i], branches, used = found
            linkage |= branches
            free -= used
    if not legs:
        return limbs, trunk
    kept = [
        legs.get(i, replace(limb, kind="other", why="a leg's linkage") if i in linkage else limb)
        for i, limb in enumerate(limbs)
    ]
    return sort_limbs(tree, kept), [name for name in trunk if name in free]


def _leg_through(
    tree: JointTree, limbs: list[Limb], i: int, owner: dict[str, int], trunk: set[str]
) -> tuple[Limb, set[int], set[str]] | None:
    """Limb ``i`` (a foot's chain) with the ``trunk`` joints above it as one leg, the limbs
    branching off them (its linkage), and the trunk joints it takes; None when they are not
    (see :func:`legs_through_linkages`)."""
    limb = limbs[i]
    path = _trunk_to_the_body(tree, limb, trunk)
    if not path or not any(tree.matches("leg", joint) for joint in path):
        return None
    below = _below(tree, path[0])
    if len(below) > _MOST_LOOP_JOINTS:
        return None  # more than the walk reads: what it does not see is not taken as absent
    branches = {owner[name] for name in below if name in owner} - {i}
    if any(
        limbs[b].kind != "other"
        or _FOOT.search(limbs[b].tip)
        or len(limbs[b].joints) > _LINKAGE_JOINTS
        for b in branches
    ):
        return None
    on_path = {j.name for j in path}
    chains = {name for b in (*branches, i) for name in limbs[b].joints}
    moving = {name for name in below if (j := tree.urdf.joint(name)) is not None and j.movable}
    # Every moving joint below is the leg's or a linkage chain's: no other trunk joint (a rod
    # carrying two chains), nor one of no limb (a sole's frame is fixed, and is passed by).
    if moving - chains - on_path:
        return None
    joints = tuple(j.name for j in path) + limb.joints
    why = f"a leg through its linkage ({len(branches)} short chain(s) beside it), to {limb.tip}"
    leg = replace(limb, kind="leg", joints=joints, base=path[0].parent, why=why)
    return leg, branches, on_path


def _trunk_to_the_body(tree: JointTree, limb: Limb, trunk: set[str]) -> list[Joint]:
    """The trunk joints above ``limb``'s first, top-down, up to a joint on the body (nothing
    above it moves); empty when a joint above them moves and is no trunk joint."""
    path: list[Joint] = []
    joint = tree.urdf.parent_joint(limb.base)
    for _ in range(_MOST_LOOP_JOINTS):  # every joint walked, fixed ones too
        if joint is None:
            return path[::-1]
        if joint.movable:
            if joint.name not in trunk:
                return []
            path.append(joint)
        joint = tree.urdf.parent_joint(joint.parent)
    return []


# A leg's linkage drawn open: chains of at most this many joints beside it (a rod, a horn).
_LINKAGE_JOINTS = 2


def closed_arms(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two arm chains that start apart on one body and end at one place (closer than
    :data:`_ARM_CLOSED` of the gap between their starts) are one arm closed by a linkage (a
    five-bar arm written as two open chains, the loop a URDF cannot close): merged, as
    :func:`five_bars` merges a leg's, when both turn in one plane (every joint of both a hinge
    about parallel axes: a five-bar linkage is planar; a dual-arm robot's hands may meet in the
    zero pose, but its arms are not planar)."""
    arms = [limb for limb in limbs if limb.kind == "arm"]
    if not 2 <= len(arms) <= _MOST_FIVE_BAR_LEGS:
        return limbs  # a stranger's thousands of chains are not paired one by one
    known: dict[str, str | None] = {}
    # Each arm read once: the body it hangs from, where it starts and ends, its hinges' axis.
    planar = {id(arm): found for arm in arms if (found := _planar_arm(tree, arm, known))}
    merged: dict[int, Limb] = {}
    used: set[int] = set()
    why = "two chains of one five-bar arm (they start apart on one body, their ends meet)"
    for index, one in enumerate(arms):
        for other in arms[index + 1 :]:
            a, b = planar.get(id(one)), planar.get(id(other))
            if {id(one), id(other)} & used or a is None or b is None or not _meet(a, b):
                continue
            merged[id(one)] = replace(one, joints=one.joints + other.joints, why=why)
            used.update((id(one), id(other)))
    if not merged:
        return limbs
    kept = [
        merged.get(id(limb), limb) for limb in limbs if id(limb) not in used or id(limb) in merged
    ]
    return sort_limbs(tree, kept)


def open_linkages(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """An arm and an unnamed chain beside it on one body, the chain planar (every joint a
    hinge about parallel axes, :func:`_planar_arm`) about the arm's first axis, starting apart
    from the arm's first joint but within :data:`_LINKAGE_GAP` of it and less than
    :data:`_LINKAGE_PLANE` off the plane it turns in, shorter than the arm and ending in a bare
    link: the arm's parallelogram (a desktop arm's, that keeps its tool level) written as an
    open chain, the loop a URDF cannot close. Merged into the arm, as :func:`closed_arms`
    merges a five-bar's; two arms of a torso start apart, across the body."""
    arms = [limb for limb in limbs if limb.kind == "arm"]
    if not 2 <= len(arms) <= _MOST_FIVE_BAR_LEGS:
        return limbs  # a stranger's thousands of chains are not paired one by one
    into = _open_sides(tree, arms)
    if not into:
        return limbs
    why = "an arm and its parallelogram, written as an open chain beside it (one arm)"
    grown: dict[int, list[str]] = {id(arm): [] for arm in into.values()}
    for limb in limbs:
        if id(limb) in into:
            grown[id(into[id(limb)])] += limb.joints
    return [
        replace(limb, joints=limb.joints + tuple(grown[id(limb)]), why=why)
        if id(limb) in grown
        else limb
        for limb in limbs
        if id(limb) not in into
    ]


def _open_sides(tree: JointTree, arms: list[Limb]) -> dict[int, Limb]:
    """Each open side's id, and the arm it is part of (:func:`open_linkages`): the longest arm
    first, whatever the order of the file, takes the chains beside it; an arm that took one is
    no other's side, and a side is one arm's."""
    known: dict[str, str | None] = {}
    planar = {id(arm): found for arm in arms if (found := _planar_arm(tree, arm, known))}
    into: dict[int, Limb] = {}
    taking: set[int] = set()
    ranked = sorted(arms, key=lambda limb: (-len(limb.joints), limb.joints))
    for arm in ranked:
        if id(arm) in into:
            continue
        for side in ranked:
            found = planar.get(id(side))
            free = side is not arm and id(side) not in into and id(side) not in taking
            if free and found is not None and _open_side(tree, arm, side, found, known):
                into[id(side)] = arm
                taking.add(id(arm))
    return into


def _carries(tree: JointTree, limb: Limb) -> bool:
    """A link hangs below the chain's last joint's (a frame, a tool): it ends in no bare link."""
    last = tree.urdf.joint(limb.joints[-1])
    return last is None or bool(tree.urdf.children(last.child))


def _open_side(
    tree: JointTree, arm: Limb, side: Limb, planar: _Planar, known: dict[str, str | None]
) -> bool:
    """``side`` (a planar chain, ``planar`` read of it), unnamed, shorter than ``arm`` and
    ending in a bare link, hangs from the body ``arm`` hangs from, turns about an axis parallel
    to the arm's first hinge's and starts apart from that hinge but within
    :data:`_LINKAGE_GAP` of it, less than :data:`_LINKAGE_PLANE` off the plane it turns in."""
    first = tree.urdf.joint(arm.joints[0])
    if (
        side.named
        or len(side.joints) >= len(arm.joints)
        or _carries(tree, side)
        or first is None
        or first.type not in _TURNING
    ):
        return False
    axis = tree.poses.axis(first)
    start = _start(tree, arm)
    return (
        moved_by(tree.urdf, arm.base, known) == planar.body
        and parallel(axis, planar.axis)
        and 0 < distance(start, planar.start) < _LINKAGE_GAP
        and abs(dot(minus(planar.start, start), axis)) < _LINKAGE_PLANE
    )


# How near an arm's first joint a parallelogram's open side starts (metres, the distance
# between them), and how far off the plane the arm's first hinge turns in.
_LINKAGE_GAP = 0.1
_LINKAGE_PLANE = 0.03


class _Planar(NamedTuple):
    """An arm read once for :func:`closed_arms`."""

    body: str | None  # the joint that moves the link it hangs from (None: the root's body)
    start: Vector
    tip: Vector
    axis: Vector  # its hinges' one axis


def _planar_arm(tree: JointTree, arm: Limb, known: dict[str, str | None]) -> _Planar | None:
    """The body an arm hangs from, where it starts and ends and its hinges' one axis; None when
    a joint slides or turns about another axis."""
    joints = [tree.urdf.joint(name) for name in arm.joints]
    hinges = [j for j in joints if j is not None and j.type in _TURNING]
    if not hinges or len(hinges) != len(joints):
        return None
    axis = tree.poses.axis(hinges[0])
    if not all(parallel(axis, tree.poses.axis(j)) for j in hinges[1:]):
        return None
    body = moved_by(tree.urdf, arm.base, known)
    return _Planar(body, _start(tree, arm), tree.poses.place(arm.tip), axis)


def _meet(one: _Planar, other: _Planar) -> bool:
    """Two planar arms on one body, about parallel axes, ending closer than
    :data:`_ARM_CLOSED` of the gap between where they start."""
    gap = distance(one.start, other.start)
    return (
        one.body == other.body
        and parallel(one.axis, other.axis)
        and gap > 0
        and distance(one.tip, other.tip) < _ARM_CLOSED * gap
    )


# Two arm chains' ends this close (a share of their starts' gap) are one place: one loop.
_ARM_CLOSED = 0.1


# Which of two chains a loop closes keeps its kind: the one that carries something.
_KEPT = ("mount", "arm", "head", "leg")


def _limb_below(
    tree: JointTree, link: str, owner: dict[str, int], known: dict[str, str | None]
) -> int | None:
    """The limb (its index in ``owner``) whose joints move ``link``: the nearest joint above it
    that is a limb's, through joints of no limb (a wheel below a leg's last link)."""
    for _ in range(_MOST_LOOP_JOINTS):
        joint = moved_by(tree.urdf, link, known)
        if joint is None:
            return None
        if joint in owner:
            return owner[joint]
        found = tree.urdf.joint(joint)
        if found is None:
            return None
        link = found.parent
    return None


def _hip_points(tree: JointTree, legs: list[Limb]) -> int:
    """How many places the leg chains start at (their first joints' places, told apart at
    :data:`_AT_ONE_POINT`)."""
    places: list[Vector] = []
    for leg in legs:
        first = tree.urdf.joint(leg.joints[0])
        at = tree.poses.place(first.child) if first is not None else None
        if at is not None and all(distance(at, place) >= _AT_ONE_POINT for place in places):
            places.append(at)
    return len(places)


def _one_leg(tree: JointTree, one: Limb, other: Limb, *, several_hips: bool) -> str:
    """Why two leg chains are one leg (a five-bar or a parallel linkage), or "". Chains from
    one hip point are one leg's motors only where legs start at ``several_hips`` points: a
    planar walker's model hangs both its legs from one point."""
    if _coaxial(tree, one, other) and _closed(tree, one, other):
        return (
            "two motors of one five-bar leg (their first joints turn about one line, "
            "their chains close a loop)"
        )
    if several_hips and _one_hip(tree, one, other):
        return (
            "two motors of one four-bar leg (their first joints turn about one axis at one "
            "point, both chains in one plane)"
        )
    if _one_axle(tree, one, other):
        return (
            "two motors of one five-bar leg (side by side on one axle that a hip's hinge "
            "carries, both chains in one plane)"
        )
    if (
        _beside(tree, one, other, on_line=False)
        and _ends_meet(tree, one, other)
        and not _coxae(tree, [one, other])  # two hips' yaws, their feet tucked together
    ):
        return (
            "two chains of one parallel-linkage leg (their first joints turn about "
            "parallel axes side by side, their ends meet)"
        )
    return ""


def _one_hip(tree: JointTree, one: Limb, other: Limb) -> bool:
    """The first joints of two chains sit at one point, every joint of both is a hinge about
    one axis, and the two are not drawn over each other (:func:`_one_plane`): two motors at
    one hip driving one leg's linkage (a four-bar leg whose loop the file leaves open). A
    model drawn in a side view puts a left and a right leg at one point, joint over joint."""
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None:
        return False
    if distance(tree.poses.place(first.child), tree.poses.place(second.child)) >= _AT_ONE_POINT:
        return False
    return _one_plane(tree, one, other)


def _one_axle(tree: JointTree, one: Limb, other: Limb) -> bool:
    """The first joints of two chains sit side by side on one line (:func:`_coaxial`) on one
    link, both on one side along that line of the hinge that turns the link (the nearest
    movable joint above it), and the chains lie in one plane (:func:`_one_plane`): a hip's
    abduction carrying one leg's two motors on one axle (a five-bar leg whose loop the file
    leaves open). A waist turning a pelvis carries two hips on either side of it, and a
    hexapod's row of legs on one line hangs from its body, each leg its own hip."""
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None or first.parent != second.parent:
        return False
    above = moved_by(tree.urdf, first.parent, {})
    hip = None if above is None else tree.urdf.joint(above)
    if hip is None or hip.type not in _TURNING:
        return False
    if not _coaxial(tree, one, other):
        return False
    pivot, axle = tree.poses.place(hip.child), tree.poses.axis(first)
    sides = [dot(minus(tree.poses.place(j.child), pivot), axle) for j in (first, second)]
    return sides[0] * sides[1] > 0 and _one_plane(tree, one, other)


class _Hinges(NamedTuple):
    """The movable joints above each leg chain's first joint (nearest first, and as a set),
    and how many leg chains hang below each movable joint."""

    above: dict[str, tuple[str, ...]]
    sets: dict[str, frozenset[str]]
    legs_under: Counter[str]


def _hinges(tree: JointTree, legs: list[Limb]) -> _Hinges:
    """The :class:`_Hinges` of ``legs``, from one walk up the tree (:func:`moved_by`)."""
    above: dict[str, tuple[str, ...]] = {}
    known: dict[str, str | None] = {}
    for leg in legs:
        found: list[str] = []
        joint = tree.urdf.joint(leg.joints[0])
        while joint is not None and (name := moved_by(tree.urdf, joint.parent, known)):
            found.append(name)
            joint = tree.urdf.joint(name)
        above[leg.joints[0]] = tuple(found)
    sets = {name: frozenset(names) for name, names in above.items()}
    return _Hinges(above, sets, Counter(name for names in above.values() for name in names))


def _one_hinge(tree: JointTree, one: Limb, other: Limb, hinges: _Hinges) -> str:
    """Why two leg chains are one leg and its linkage's bar, or "": both hang from one hinge
    that carries no other leg chain (the nearest movable joint above both), they are unlike
    (one has more joints than the other: two legs of one robot are built alike, a bar is
    shorter than its leg), their first joints are no further apart than a five-bar's motors
    (:data:`_FIVE_BAR_GAP`), side by side on one side of the hinge (:func:`_one_side`), and
    both hinge about one axis (:func:`_one_plane`): a hip's yaw carrying its leg's thigh and
    the bar of the leg's linkage, which the file leaves open. A waist carries two legs on
    either side of it, a spine's joint its two front legs, a rocker a front and a rear leg,
    alike and far apart."""
    if len(one.joints) == len(other.joints):
        return ""
    hinge = _shared_hinge(tree, one, other, hinges)
    if hinge is None or hinges.legs_under[hinge] != 2:
        return ""
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None:
        return ""
    gap = distance(tree.poses.place(first.child), tree.poses.place(second.child))
    if not gap <= _FIVE_BAR_GAP or not _one_side(tree, hinge, first, second):  # NaN fails too
        return ""
    if not _one_plane(tree, one, other):
        return ""
    return (
        f"a leg and its linkage's bar drawn open (both hang from {shown(hinge)}, which carries "
        "no other leg, side by side on one side of it, about one axis)"
    )


def _shared_hinge(tree: JointTree, one: Limb, other: Limb, hinges: _Hinges) -> str | None:
    """The nearest movable joint above the first joints of both chains, when it is a hinge."""
    shared = hinges.sets.get(other.joints[0], frozenset())
    for name in hinges.above.get(one.joints[0], ()):
        if name in shared:
            joint = tree.urdf.joint(name)
            return name if joint is not None and joint.type in _TURNING else None
    return None


def _one_side(tree: JointTree, hinge: str, first: Joint, second: Joint) -> bool:
    """Two chains' first joints, ``first`` and ``second``, sit on one side of ``hinge``, across
    y (not a centimetre or more to either side of it), and lie beside each other more than
    along ``first``'s axis: a hip's thigh and bar side by side in the leg's plane, where a waist
    or a spine's joint carries its two legs on either side of it, apart along their axes."""
    joint = tree.urdf.joint(hinge)
    if joint is None:
        return False
    centre = tree.poses.place(joint.child)
    a, b = tree.poses.place(first.child), tree.poses.place(second.child)
    across = (a[1] - centre[1], b[1] - centre[1])
    if across[0] * across[1] < 0 and min(abs(y) for y in across) >= _LOOP_CLOSED:
        return False
    apart = minus(b, a)
    along = abs(dot(apart, tree.poses.axis(first)))
    return along < math.sqrt(max(dot(apart, apart) - along * along, 0.0))


def _one_plane(tree: JointTree, one: Limb, other: Limb) -> bool:
    """Every joint of both chains is a hinge about one axis, and the two are not drawn over
    each other (:func:`_drawn_over`)."""
    joints = [tree.urdf.joint(name) for name in (*one.joints, *other.joints)]
    return (
        all(joint is not None for joint in joints)
        and _planar(tree, [joint for joint in joints if joint is not None])
        and not _drawn_over(tree, one, other)
    )


def _drawn_over(tree: JointTree, one: Limb, other: Limb) -> bool:
    """Two chains of as many joints, each joint at the place of the other's: one limb drawn
    over another (a left and a right leg in a side view), no linkage."""
    if len(one.joints) != len(other.joints):
        return False
    return all(
        a is not None
        and b is not None
        and distance(tree.poses.place(a.child), tree.poses.place(b.child)) < _LOOP_CLOSED
        for a, b in zip(
            (tree.urdf.joint(name) for name in one.joints),
            (tree.urdf.joint(name) for name in other.joints),
            strict=True,
        )
    )


def _coaxial(tree: JointTree, one: Limb, other: Limb) -> bool:
    """The first joints of two chains turn about one line, close together, on one side of the
    body (a humanoid's two hips share a line too, but on both sides of it)."""
    return _beside(tree, one, other, on_line=True)


def _beside(tree: JointTree, one: Limb, other: Limb, *, on_line: bool) -> bool:
    """The first joints of two chains turn about parallel axes, close together, on one side of
    the body; with ``on_line``, about one line."""
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None or first.type == "prismatic":
        return False
    poses = tree.poses
    a, b = poses.place(first.child), poses.place(second.child)
    axis = poses.axis(first)
    gap = distance(a, b)
    if not parallel(axis, poses.axis(second)) or gap > _FIVE_BAR_GAP:
        return False
    line = minus(b, a)
    centre = poses.place(tree.urdf.root)
    same_side = (a[1] - centre[1]) * (b[1] - centre[1]) > 0
    return same_side and (not on_line or gap < 1e-6 or parallel(line, axis))


def _ends_meet(tree: JointTree, one: Limb, other: Limb) -> bool:
    """The two chains end at one place (closer than half the gap between their first joints):
    a closed chain, written as two open ones."""
    poses = tree.poses
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None:
        return False
    gap = distance(poses.place(first.child), poses.place(second.child))
    return distance(poses.place(one.tip), poses.place(other.tip)) < max(gap / 2, _LOOP_CLOSED)


def _closed(tree: JointTree, one: Limb, other: Limb) -> bool:
    """The two chains close a loop, as a five-bar leg's do: their ends meet (closer than half
    the gap between their first joints), or a mimic joint below one follows a joint below the
    other (a closed chain written as mimic partners)."""
    first, second = tree.urdf.joint(one.joints[0]), tree.urdf.joint(other.joints[0])
    if first is None or second is None:
        return False
    if _ends_meet(tree, one, other):
        return True
    if not tree.couplings.driver_of:
        return False
    below_one, below_other = _below(tree, first), _below(tree, second)
    driver = tree.couplings.driver
    return any(driver(name) in below_other for name in below_one) or any(
        driver(name) in below_one for name in below_other
    )


def _below(tree: JointTree, joint: Joint) -> set[str]:
    """The joint and the joints below it (at most ``_MOST_LOOP_JOINTS`` of them)."""
    below = islice(tree.urdf.subtree_joints(joint.child), _MOST_LOOP_JOINTS)
    return {joint.name, *(j.name for j in below)}


def spine(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """The body's one limb as a *spine* when it is a snake's: a long chain of turning joints
    (no slide) with no arm or leg names and no gripper, of equal modules (:func:`_modules`:
    every spacing between joints alike, or every other one, a module's two joints maybe at one
    point), each joint's axis square to the last's and none along the chain (:func:`_bends`),
    on a body that has nothing else (no wheels, rotors, legs or other chains) and that no plugin
    moves but one that slides it (:func:`_slid_at_most`); on a robot
    named a snake (:data:`_SNAKE_NAME`), any such chain of two turning joints or more (of
    equal modules as long as a snake when a plugin slides the body: :func:`_named_snake`).
    Two chains from one link, and nothing else, are read as one through it (the file's root
    is a module inside the snake, not its end): a spine when that one chain is."""
    if len(limbs) == _THROUGH_ONE_LINK:
        return _spine_through(tree, limbs)
    if len(limbs) != 1:
        return limbs
    limb = limbs[0]
    joints = _joints_of(tree, limb)
    snake = _named_snake(tree, joints)
    least = _NAMED_SPINE_JOINTS if snake else tree.profile.limb("spine_min_joints")
    if limb.kind not in ("arm", "other") or limb.gripper or len(limb.joints) < least:
        return limbs
    # A snake may have a head; arm or leg names say it is something else (on a robot named a
    # snake, the words of an arm's or a leg's joints: its modules may be labelled ``arm_1``).
    # Its modules turn: a chain with a slide in it is an arm on a rail or a lift.
    named = _limb_joint_words(joints) if snake else _named_limb(tree, joints)
    if named or not all(j.type in _TURNING for j in joints):
        return limbs
    # A snake carries no tool: a chain whose tip is an arm's tool frame is an arm's.
    if not snake and _tool_frame_at(tree, joints[-1]):
        return limbs
    if snake:
        why: str | None = (
            f"a chain of {len(joints)} turning joints, nothing else, on a robot named a snake"
            f" ({shown(tree.urdf.name)})"
        )
    else:
        why = _spine_shape(tree, joints)
    return limbs if why is None else [replace(limb, kind="spine", why=why)]


def _tool_frame_at(tree: JointTree, last: Joint) -> str:
    """The first link fixed below ``last`` (or its own child) named as an arm's tool frame
    (:data:`_TOOL_FRAME`: ``tool0``, ``flange``, ``tcp``, ``ee_link``, ``end_effector``), where
    an arm's controllers aim it; empty when there is none."""
    return next((name for name in _rigid_end(tree, last) if _TOOL_FRAME.search(name)), "")


# An arm's tool frame, by the names industrial and MoveIt descriptions give it.
_TOOL_FRAME = re.compile(
    r"(^|[_/])(tool0|tool_?frame|tool_?link|flange|tcp|ee_?link|eef|end_?effector)([_/\d]|$)",
    re.IGNORECASE,
)


def _spine_shape(tree: JointTree, joints: list[Joint]) -> str | None:
    """Why an unnamed chain of ``joints`` is a snake's spine by its shape (:func:`spine`):
    equal modules that bend, on a body no plugin moves but one that slides it, whose axes
    alternate, or, in a chain longer than any arm, are all parallel; None when it is not."""
    if not _modules(tree, joints) or not _bends(tree, joints) or not _slid_at_most(tree):
        return None
    if _alternating(tree, joints):
        return (
            f"a chain of {len(joints)} equal modules whose axes alternate, nothing else (a spine)"
        )
    if len(joints) >= _PLANAR_SPINE_JOINTS and _planar(tree, joints):
        return (
            f"a chain of {len(joints)} equal modules turning about parallel axes, nothing else"
            " (a planar snake's spine)"
        )
    return None


def _spine_through(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Two chains from one link read as one through it (:func:`spine`): the spine, when that
    one chain is a snake's; else the two as they were."""
    first, second = limbs
    if first.base != second.base or first.kind not in ("arm", "other") or first.gripper:
        return limbs
    joints = first.joints[::-1] + second.joints
    through = Limb(second.kind, joints, first.tip, second.tip, gripper=second.gripper)
    found = spine(tree, [through])
    return found if found[0].kind == "spine" else limbs


# Chains from one link read as one snake through it (:func:`spine`): the two ways out of it.
_THROUGH_ONE_LINK = 2


def pendulum(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """The body's one arm as a pendulum rig's links (*other*) when the robot's name says one
    (:data:`_PENDULUM_NAME`) and no arm (:func:`_named_arm`), and the chain is short
    (:data:`_PENDULUM_JOINTS`) with no arm's or leg's joint words (:func:`_limb_joint_words`):
    a control course's plant, its joints swung by their actuators to balance it, carrying no
    tool. Asked only of a body with nothing else (no wheels, a robot balancing on them, and
    no gripper: both are roles)."""
    sole = _sole_limb_named(tree, limbs, _PENDULUM_NAME)
    if sole is None:
        return limbs
    limb, joints = sole
    if limb.kind != "arm" or len(joints) > _PENDULUM_JOINTS or _limb_joint_words(joints):
        return limbs
    why = f"a pendulum rig's links, on a robot named one ({shown(tree.urdf.name)})"
    return [replace(limb, kind="other", why=why)]


def named_pan_tilt(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """The body's one limb, a short chain of turning joints read as no limb's (*other*: a
    servo bracket drawn too large for :func:`small_pan_tilt`, a link an exporter named
    ``lower_arm``), as a head when the robot's name says a pan/tilt unit
    (:data:`_PAN_TILT_NAME`) and no arm (:func:`_named_arm`): the unit's pan and tilt, its
    payload named nowhere. Asked only of a body with nothing else (no wheels, no gripper:
    both are roles)."""
    sole = _sole_limb_named(tree, limbs, _PAN_TILT_NAME)
    if sole is None:
        return limbs
    limb, joints = sole
    if (
        limb.kind != "other"
        or len(joints) > tree.profile.limb("head_max_joints")
        or not all(_hinge(joint, endless=True) for joint in joints)
    ):
        return limbs
    why = f"a short chain of hinges, on a robot named a pan/tilt unit ({shown(tree.urdf.name)})"
    return [replace(limb, kind="head", why=why)]


def _sole_limb_named(
    tree: JointTree, limbs: list[Limb], named: re.Pattern[str]
) -> tuple[Limb, list[Joint]] | None:
    """The body's one limb and its joints, when the robot's name matches ``named`` and says
    no arm (:func:`_named_arm`); else None."""
    name = tree.urdf.name
    if len(limbs) != 1 or not named.search(name) or _named_arm(name):
        return None
    joints = [j for j in (tree.urdf.joint(n) for n in limbs[0].joints) if j is not None]
    return limbs[0], joints


def camera_arm(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """The body's one limb, a short unnamed chain read as a pan/tilt head (it turns a camera
    or a range sensor), as an arm when the robot's name says one (:func:`_named_arm`): the
    camera rides the arm's tip (a course's two-joint ``simple_arm``). Asked only of a body
    with nothing else (no wheels, no other limb: a mobile base's or an arm's pan/tilt camera
    stays a head)."""
    if len(limbs) != 1 or limbs[0].kind != "head" or limbs[0].named:
        return limbs
    name = tree.urdf.name
    if not _named_arm(name):
        return limbs
    why = f"a short chain turning a camera, on a robot named an arm ({shown(name)})"
    return [replace(limbs[0], kind="arm", why=why)]


def _joints_of(tree: JointTree, limb: Limb) -> list[Joint]:
    """The joints of ``limb`` the file has, in the limb's order."""
    return [joint for name in limb.joints if (joint := tree.urdf.joint(name)) is not None]


def _named_as_arm(tree: JointTree, limb: Limb) -> bool:
    """More of the limb's joints (with their links) are named as an arm's than as any other
    limb's, and some are."""
    joints = _joints_of(tree, limb)
    scores = _name_scores(tree, joints)
    return scores["arm"] > 0 and scores["arm"] == max(scores.values())


def _named_arm(name: str) -> bool:
    """The robot's name says an arm or a manipulator as a word (:data:`_ARM_NAME`), a
    camelCase name split into its words first (``SimpleArm``)."""
    return bool(_ARM_NAME.search(_CAMEL.sub("_", name)))


# Where a camelCase name's next word starts (``Simple|Arm``).
_CAMEL = re.compile(r"(?<=[a-z0-9])(?=[A-Z])")


def _named_snake(tree: JointTree, joints: list[Joint]) -> bool:
    """The robot's name says a snake and no manipulator (:data:`_SNAKE_NAME`), and no plugin
    drives, tracks or flies its body (a base a plugin moves carries an arm, however named); but
    a plugin that only slides the body (a planar move, nothing of it on the ground) under a
    chain of ``joints`` of a snake's length (``spine_min_joints``) and of equal modules
    (:func:`_modules`) moves a snake the simulator cannot crawl (its modules' sine is the
    robot's, the slide the simulator's)."""
    name = tree.urdf.name
    if not _SNAKE_NAME.search(name) or _MANIPULATOR_NAME.search(name):
        return False
    long = len(joints) >= tree.profile.limb("spine_min_joints") and _modules(tree, joints)
    return _slid_at_most(tree, long=long)


def _slid_at_most(tree: JointTree, *, long: bool = True) -> bool:
    """No plugin tracks or flies the body, and none drives it but one that only slides it (a
    planar move: the simulator's, under a ``long`` snake's modules); a body a wheel drive moves
    is a base, whatever chain rides it."""
    if tree.labels("track") or tree.labels("flight"):
        return False
    return set(tree.labels("drive")) <= (set(tree.labels("mover")) if long else set())


def _limb_joint_words(joints: list[Joint]) -> bool:
    """An arm's or a leg's joint words on at least two of the chain's joints or the links
    they move (``shoulder``, ``elbow``, ``knee``; not a module's label ``arm_1``)."""
    named = [j for j in joints if _LIMB_JOINT_WORDS.search(f"{j.name} {j.child}")]
    return len(named) >= _LIMB_NAMES


def wheeled_spine(
    tree: JointTree, limbs: list[Limb], trunk: list[str]
) -> tuple[list[Limb], list[str], list[str]]:
    """A snake whose modules carry passive side wheels: the trunk is one unbranched path from
    the root of at least ``spine_min_joints`` joints (no arm or leg names, equal modules that
    bend, axes alternating) and every limb is a single unnamed leaf joint on one of its links.
    Returns the limbs (the spine alone), the trunk (none) and the side joints; else what it
    was given."""
    unchanged: tuple[list[Limb], list[str], list[str]] = (limbs, trunk, [])
    joints = [j for j in (tree.urdf.joint(name) for name in trunk) if j is not None]
    if (
        len(joints) != len(trunk)
        or len(joints) < tree.profile.limb("spine_min_joints")
        or len(limbs) < _SIDE_WHEELS
        or not _one_path(tree, joints)
        or _named_limb(tree, joints)
    ):
        return unchanged
    links = {tree.urdf.root, *(joint.child for joint in joints)}
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    if not all(
        limb.kind == "other" and len(limb.joints) == 1 and _carrier(tree, limb.base, known) in links
        for limb in limbs
    ):
        return unchanged
    if not _modules(tree, joints) or not _bends(tree, joints):
        return unchanged
    if _alternating(tree, joints):
        why = (
            f"a chain of {len(joints)} joints in equal modules whose axes alternate, carrying only "
            f"{len(limbs)} single leaf joint(s) (a spine with passive side wheels)"
        )
    elif _planar(tree, joints) and _pads(tree, limbs):
        why = (
            f"a chain of {len(joints)} joints in equal modules turning about parallel axes, "
            f"carrying only {len(limbs)} sliding leaf joint(s) (a spine that anchors on pads)"
        )
    else:
        return unchanged
    spine_limb = Limb("spine", tuple(trunk), joints[0].parent, joints[-1].child, why=why)
    return [spine_limb], [], [limb.joints[0] for limb in limbs]


def named_wheeled_snake(
    tree: JointTree, limbs: list[Limb], wheels: list[str]
) -> tuple[list[Limb], list[str]]:
    """A robot named a snake (:func:`_named_snake`) whose one chain of turning joints, as long
    as a snake (``spine_min_joints``) in equal modules, runs link after link from the root, and
    whose ``wheels`` each turn on a link of that chain: a snake on passive wheels (as Hirose's
    Active Cord Mechanism glides; its hinges may all turn about the vertical; the wheels as
    :func:`_wheel_per_module` says), its chain the spine, no base's mount. Returns the limbs
    (the spine alone) and the wheels it carries; else what it was given and none."""
    unchanged: tuple[list[Limb], list[str]] = (limbs, [])
    if len(limbs) != 1 or not wheels or limbs[0].gripper:
        return unchanged
    limb = limbs[0]
    joints = _joints_of(tree, limb)
    if (
        len(joints) != len(limb.joints)
        or len(joints) < tree.profile.limb("spine_min_joints")
        or not all(joint.type in _TURNING for joint in joints)
        or not _one_path(tree, joints)
        or not _named_snake(tree, joints)
        or not _modules(tree, joints)
        or _limb_joint_words(joints)
    ):
        return unchanged
    if not _wheel_per_module(tree, joints, wheels):
        return unchanged
    why = (
        f"a chain of {len(joints)} turning joints in equal modules on {len(wheels)} wheel(s),"
        f" on a robot named a snake ({shown(tree.urdf.name)}): a spine on passive wheels"
    )
    return [replace(limb, kind="spine", why=why)], list(wheels)


def _wheel_per_module(tree: JointTree, joints: list[Joint], wheels: list[str]) -> bool:
    """Every wheel turns on the root or a link of the chain of ``joints``, no controller
    drives any (a snake's wheels glide; a base's are driven), half the chain's modules carry
    one at least, and the root no more than a module does (a base under a long arm carries
    them all; a snake's head module one, as the others)."""
    if any(name in tree.urdf.controlled_joints for name in wheels):
        return False
    known: dict[str, str | None] = {}
    on: dict[str, int] = {}
    for name in wheels:
        joint = tree.urdf.joint(name)
        if joint is None:
            return False
        carrier = _carrier(tree, joint.parent, known)
        on[carrier] = on.get(carrier, 0) + 1
    modules = [joint.child for joint in joints]
    if not set(on) <= {tree.urdf.root, *modules}:
        return False
    carried = [on[link] for link in modules if link in on]
    return 2 * len(carried) >= len(modules) and on.get(tree.urdf.root, 0) <= max(carried)


def _pads(tree: JointTree, limbs: list[Limb]) -> bool:
    """Every side joint slides (a pad pressed down and lifted: a snake moving in a plane, as a
    concertina, anchors its modules so)."""
    side = [tree.urdf.joint(limb.joints[0]) for limb in limbs]
    return all(joint is not None and joint.type == "prismatic" for joint in side)


def _one_path(tree: JointTree, joints: list[Joint]) -> bool:
    """Each joint is the next movable joint below the one before, from the root (or a link
    fixed to it)."""
    if not _on_the_root(tree, joints[0].parent):
        return False
    known: dict[str, str | None] = {}
    return all(
        _carrier(tree, joint.parent, known) == before.child for before, joint in pairwise(joints)
    )


def _carrier(tree: JointTree, link: str, known: dict[str, str | None]) -> str:
    """The link a movable joint ends in that carries ``link`` (through fixed joints); the root
    when none does. ``known`` is :func:`moved_by`'s memo, shared by the calls of one reading."""
    name = moved_by(tree.urdf, link, known)
    joint = None if name is None else tree.urdf.joint(name)
    return tree.urdf.root if joint is None else joint.child


def moved_by(urdf: Urdf, link: str, known: dict[str, str | None]) -> str | None:
    """The nearest movable joint above ``link`` (None at the root, or when only fixed joints
    lead up to it); every link walked is remembered in ``known``, so many links cost one walk
    of the tree at most."""
    return nearest_above(urdf, link, known, lambda joint: joint.movable)


def joints_above(tree: JointTree, names: Iterable[str]) -> set[str]:
    """The joints above any of ``names`` (their ancestors in the tree): one walk up from each,
    stopping where an earlier walk passed, so linear in the joints however deep the tree."""
    seen: set[str] = set()
    for name in names:
        joint = tree.urdf.joint(name)
        above = tree.urdf.parent_joint(joint.parent) if joint is not None else None
        while above is not None and above.name not in seen:
            seen.add(above.name)
            above = tree.urdf.parent_joint(above.parent)
    return seen


def nearest_above(
    urdf: Urdf, link: str, known: dict[str, str | None], wanted: Callable[[Joint], bool]
) -> str | None:
    """The nearest joint above ``link`` that is ``wanted`` (None when none is, up to the root);
    every link walked is remembered in ``known`` (one ``known`` per ``wanted``), so many links
    cost one walk of the tree at most (:func:`~solver.identify.readers.urdf.walk_up`)."""
    return walk_up(urdf.parent_joint, link, known, wanted)


def _named_limb(tree: JointTree, joints: list[Joint]) -> bool:
    """Arm or leg names on at least two of the chain's joints (or the links they move): an arm
    names its parts (upper arm, forearm); one word on one module is a label, not a limb."""
    named = [
        j
        for j in joints
        if any(part in tree.parts_of(j.name) | tree.parts_of(j.child) for part in ("arm", "leg"))
    ]
    return len(named) >= _LIMB_NAMES


def _alternating(tree: JointTree, joints: list[Joint]) -> bool:
    axes = [tree.poses.axis(joint) for joint in joints]
    return all(perpendicular(one, other) for one, other in pairwise(axes))


def _planar(tree: JointTree, joints: list[Joint]) -> bool:
    axes = [tree.poses.axis(joint) for joint in joints]
    return all(joint.type in _TURNING for joint in joints) and all(
        parallel(axes[0], axis) for axis in axes[1:]
    )


def _modules(tree: JointTree, joints: list[Joint]) -> bool:
    """The joints come in equal modules of one joint, or of two (a yaw and a pitch joint): the
    spacings between them, every one or every other one, are alike. A module's two joints may
    sit at one point (a universal joint): every other spacing is then none."""
    places = [tree.poses.place(joint.child) for joint in joints]
    spacings = [distance(a, b) for a, b in pairwise(places)]
    if _alike(spacings):
        return True
    odd, even = spacings[0::2], spacings[1::2]
    return any(
        _alike(one) and (_alike(other) or _none(other)) for one, other in ((odd, even), (even, odd))
    )


def _bends(tree: JointTree, joints: list[Joint]) -> bool:
    """No joint turns about the line the chain runs along from it, a module ahead (two joints
    on: a two-joint module's partner may sit beside it): a snake's modules bend (yaw and
    pitch); an arm's roll joints turn about its own links."""
    places = [tree.poses.place(joint.child) for joint in joints]
    for at, joint in enumerate(joints[:-2]):
        here, ahead = places[at], places[at + 2]
        run = minus(ahead, here)
        if distance(ahead, here) > _AT_ONE_POINT and parallel(tree.poses.axis(joint), run):
            return False
    return True


def _none(spacings: list[float]) -> bool:
    return all(s <= _AT_ONE_POINT for s in spacings)


def _alike(spacings: list[float]) -> bool:
    ordered = sorted(spacings)
    if not ordered:
        return False
    middle = ordered[len(ordered) // 2]
    return middle > 0 and all(abs(s - middle) <= _MODULE_SPREAD * middle for s in ordered)


def wrist(tree: JointTree, limbs: list[Limb], tips: list[str]) -> list[Limb]:
    """A short chain from the root ending in a whole hand (``tips``: the fingers' last joints,
    at least the profile's ``hand_min_fingers``), the body's only limb: the hand's wrist, not
    an arm. Short is fewer joints than an arm's, or up to three joints all named as a wrist's
    (a pitch, a yaw and a pitch under the palm). Two such chains side by side (a pair of hands
    on fixed forearms) are wrists too when each carries a whole hand of its own and neither
    is named but as a wrist (short arms named ``shoulder`` or ``elbow`` are a torso's). A
    chain whose axes pass farther apart than the hand reaches is no wrist
    (:func:`_turns_in_place`)."""
    minimum = tree.profile.limb("hand_min_fingers")
    if len(limbs) == 1:
        if (
            len(tips) < minimum
            or not _wrist(tree, limbs[0])
            or not _turns_in_place(tree, limbs[0], tips)
        ):
            return limbs
    elif len(limbs) == _HANDS:
        if not all(
            _wrist(tree, limb)
            and _named_as_a_wrist(tree, limb)
            and _fingers_below(tree, limb.tip, tips) >= minimum
            and _turns_in_place(tree, limb, tips)
            for limb in limbs
        ):
            return limbs
    else:
        return limbs
    why = f"joint(s) from the root carrying a hand ({len(tips)} fingers on {len(limbs)} hand(s))"
    return [
        replace(limb, kind="wrist", why=f"{len(_on_the_path(tree, limb))} {why}") for limb in limbs
    ]


def _wrist(tree: JointTree, limb: Limb) -> bool:
    """``limb`` is a short arm from the root ending in a gripper (:func:`wrist`); the rods
    that drive it (:func:`drive_rods`), off the path to its tip, are not counted."""
    path = _on_the_path(tree, limb)
    short = len(path) < tree.profile.limb("arm_min_joints") or (
        len(path) <= _WRIST_JOINTS and all(_WRIST.search(name) for name in path)
    )
    return limb.kind == "arm" and limb.gripper and _on_the_root(tree, limb.base) and short


def _on_the_path(tree: JointTree, limb: Limb) -> list[str]:
    """``limb``'s joints on the way from its base to its tip, in its order."""
    last = tree.urdf.parent_joint(limb.tip)
    if last is None:
        return []
    above = joints_above(tree, [last.name]) | {last.name}
    return [name for name in limb.joints if name in above]


def _turns_in_place(tree: JointTree, limb: Limb, tips: list[str]) -> bool:
    """Every two turning joints of ``limb`` turn about axes that pass no farther apart (at
    rest) than the hand reaches from the chain's end to its fingers' last links: a wrist turns
    the hand where it is (a pitch and a yaw under the palm); two upright axes an arm's length
    apart (a SCARA's shoulder and elbow) carry it across a table. A hinge about no axis (a file's
    ``0 0 0``) turns nothing and is not compared."""
    base = tree.poses.place(limb.tip)
    fingers = (tree.urdf.joint(name) for name in tips)
    reach = max(
        (distance(base, tree.poses.place(f.child)) for f in fingers if f is not None), default=0
    )
    path = _on_the_path(tree, limb)  # the rods that drive it turn it from elsewhere
    turning = _about_an_axis(tree, [j for name in path if (j := tree.urdf.joint(name))])
    return all(
        _axes_apart(tree, one, other) <= reach + _SAME_PLACE
        for one, other in combinations(turning, 2)
    )


def _about_an_axis(tree: JointTree, joints: list[Joint]) -> list[Joint]:
    """The ``joints`` that turn about an axis (a hinge about a file's ``0 0 0`` turns nothing):
    those whose axes :func:`_axes_apart` compares."""
    return [
        joint
        for joint in joints
        if joint.type in _TURNING and math.hypot(*tree.poses.axis(joint)) > _SAME_PLACE
    ]


def _axes_apart(tree: JointTree, one: Joint, other: Joint) -> float:
    """How far apart the axes of two turning joints pass, as the body rests (both axes of some
    length: :func:`_turns_in_place`)."""
    along, across = tree.poses.axis(one), tree.poses.axis(other)
    gap = minus(tree.poses.place(other.child), tree.poses.place(one.child))
    normal = cross(along, across)
    if parallel(along, across) or math.hypot(*normal) <= _SAME_PLACE:
        return math.hypot(*cross(gap, along)) / math.hypot(*along)
    return abs(dot(gap, normal)) / math.hypot(*normal)


def _named_as_a_wrist(tree: JointTree, limb: Limb) -> bool:
    """No name but a wrist's: the chain is unnamed, or each joint or the link it moves is
    named as a wrist (``rh_WRJ2`` turning ``rh_wrist``)."""
    if not limb.named:
        return True
    return all(
        _WRIST.search(name)
        or ((moved := tree.urdf.joint(name)) is not None and bool(_WRIST.search(moved.child)))
        for name in limb.joints
    )


def _fingers_below(tree: JointTree, link: str, tips: list[str]) -> int:
    """How many of the finger ``tips`` hang below ``link`` (one walk down from it)."""
    fingers = set(tips)
    return sum(1 for joint in tree.urdf.subtree_joints(link) if joint.name in fingers)


def lone_leg(tree: JointTree, limbs: list[Limb], moves: bool) -> list[Limb]:
    """A leg that is the body's only limb, hanging from the root on a body that does not move
    as a whole (no wheels, rotors or thrusters), holds nothing up: it is an arm that carries
    leg names (one leg of a walker, set up on a bench to reach)."""
    if moves or len(limbs) != 1 or limbs[0].kind != "leg":
        return limbs
    limb = limbs[0]
    if not _on_the_root(tree, limb.base):
        return limbs
    why = f"the body's only limb, a leg-named chain of {len(limb.joints)} joint(s) on its root"
    return [replace(limb, kind="arm", why=why)]


def gripping_leg(limbs: list[Limb]) -> list[Limb]:
    """The body's only leg, named as a leg and ending in a gripper, is an arm: one leg walks
    nowhere, and a leg that grips holds nothing up (a rover's arm whose joints are numbered as
    a leg's segments, ``leg1_2_joint``). Two or more legs stay legs (a climber grips with its
    feet)."""
    legs = [limb for limb in limbs if limb.kind == "leg"]
    if len(legs) != 1 or not legs[0].gripper or not legs[0].named:
        return limbs
    why = f"the body's only leg-named chain, of {len(legs[0].joints)} joint(s), ending in a gripper"
    return [replace(limb, kind="arm", why=why) if limb is legs[0] else limb for limb in limbs]


def small_pan_tilt(tree: JointTree, limbs: list[Limb], moves: bool) -> list[Limb]:
    """The only limb of a body that does not move, an unnamed chain of two hinges, one about
    an upright axis and the other square to it: a pan/tilt unit whose payload the file names
    no sensor of. Tilt then pan only with the second hinge within :data:`_PAN_TILT_SPAN` of
    the first (a servo bracket's two motors sit a few centimetres apart); pan then tilt at any
    span with the pan on the base (a yoke turning about the vertical, tilting what it holds: a
    two-link arm's shoulder and elbow turn about parallel axes, and a third joint or a
    gripper makes an arm of it, a third locked by its limits between them too (a modular
    arm's middle module locked in its file); measured: every such body of the development part is
    labelled a pan/tilt unit, spans 7 to 34 cm)."""
    found = None if moves else _two_hinges_alone(tree, limbs, endless=True)
    if found is None:
        return limbs
    limb, first, second = found
    if not _square_turns(tree, first, second):
        return limbs
    if _locked_between(tree, first, second):
        why = (
            "the body's only limb, an unnamed chain of two hinges with a third between them "
            "locked by its limits (an arm, one joint locked in this file)"
        )
        return [replace(limb, kind="arm", why=why)]
    if joint_span(tree, limb) <= _PAN_TILT_SPAN:
        apart = "a few centimetres apart"
    elif _pan_then_tilt(tree, first, second) and _on_the_root(tree, limb.base):
        apart = "the upright one on the base"
    else:
        return limbs
    why = (
        "the body's only limb, an unnamed chain of two hinges about an upright axis and one "
        f"square to it, {apart} (a pan/tilt unit)"
    )
    return [replace(limb, kind="head", why=why)]


def _locked_between(tree: JointTree, first: Joint, second: Joint) -> bool:
    """A hinge locked by its limits (equal ones, :attr:`Joint.closed`) lies between ``first``
    and ``second``: a third joint of an arm, locked in this file (a modular arm's middle
    module); a pan/tilt yoke has none between its two (a mast's slide locked there lifts it)."""
    here = second.parent
    while here != first.child:
        joint = tree.urdf.parent_joint(here)
        if joint is None:
            return False
        if joint.type == "revolute" and joint.closed:
            return True
        here = joint.parent
    return False


def _two_hinges_alone(
    tree: JointTree, limbs: list[Limb], *, endless: bool
) -> tuple[Limb, Joint, Joint] | None:
    """The body's only limb and its two joints, when it is an unnamed chain of no limb's kind
    of two hinges (limited ones, or also endless ones with ``endless``); else None."""
    if len(limbs) != 1 or limbs[0].kind != "other" or limbs[0].named:
        return None
    hinges = [tree.urdf.joint(name) for name in limbs[0].joints]
    turning = [joint for joint in hinges if joint is not None and _hinge(joint, endless=endless)]
    if len(hinges) != 2 or len(turning) != 2:
        return None
    return limbs[0], turning[0], turning[1]


def _hinge(joint: Joint, *, endless: bool) -> bool:
    """``joint`` turns within limits, or for ever too with ``endless``."""
    if joint.type == "continuous" or joint.endless:
        return endless
    return joint.type == "revolute"


# How far (metres) a pan/tilt unit's second hinge is from its first, at most.
_PAN_TILT_SPAN = 0.06


def _square_turns(tree: JointTree, first: Joint, second: Joint) -> bool:
    """Pan then tilt, or tilt then pan (:func:`_pan_then_tilt`)."""
    return _pan_then_tilt(tree, first, second) or _pan_then_tilt(tree, second, first)


def bolted_chain(tree: JointTree, limbs: list[Limb], moves: bool) -> list[Limb]:
    """A short chain, unnamed or named as an arm's (too short for its names to make it one:
    ``arm_link`` on a turret), the body's only limb, hanging from a root fixed to ``world`` (or
    every joint of it driven by a controller, or on a robot whose name says an arm or a
    manipulator and nothing that walks) on a body that does not move: the base is bolted
    down and the chain is what it is there for. It is an arm (of two joints or more), whether
    it carries a sensor at its tip (read as a pan/tilt unit only for that) or nothing the names
    tell (a two-link teaching arm)."""
    if moves or len(limbs) != 1 or limbs[0].kind not in ("head", "other"):
        return limbs
    limb = limbs[0]
    if limb.named and not _named_as_arm(tree, limb):
        return limbs  # its names made it what it is
    # Bolted down: the root fixed to the world, or every joint of the chain commanded by a
    # controller (a transmission or ros2_control) on a body that does not move itself.
    driven = all(name in tree.urdf.controlled_joints for name in limb.joints)
    if len(limb.joints) < 2 or not _on_the_root(tree, limb.base):
        return limbs
    robot = tree.urdf.name
    named = _named_arm(robot) and not _LEGGED_NAME.search(robot)
    bolted = _world_root(tree) or driven
    if not (bolted or named):
        return limbs
    pan, tilt = (tree.urdf.joint(name) for name in limb.joints[:2])
    if (
        limb.kind == "head"
        and pan is not None
        and tilt is not None
        and _square_turns(tree, pan, tilt)
    ):
        return limbs  # a pan/tilt unit bolted down is still a head
    named_only = None if bolted else robot
    return [replace(limb, kind="arm", why=_bolted_why(limb, named_only))]


def _bolted_why(limb: Limb, robot: str | None) -> str:
    """Why :func:`bolted_chain` reads ``limb`` as an arm: its root fixed to the world (or every
    joint driven), or, ``robot`` given, only the robot's name."""
    if limb.kind == "head":
        what = "carrying a sensor"
    else:
        what = "named as an arm's" if limb.named else "of no limb's name"
    root = "fixed to the world" if robot is None else f"of a robot named {shown(robot)}"
    return (
        f"the body's only limb, a chain of {len(limb.joints)} joints on a root {root}"
        f" (a short arm {what})"
    )


def planar_arm(tree: JointTree, limbs: list[Limb], moves: bool) -> list[Limb]:
    """The only limb of a body that moves as a whole (``moves``: it rolls, flies or swims), or
    its only two, one on each side of it (:func:`_opposite`), each an unnamed chain (carrying
    no sensor, or it would be a head) of two limited hinges about parallel level axes as the
    body rests, the second at least :data:`_PLANAR_REACH` from the first: a two-link arm
    swinging in a vertical plane, what the base carries to lift or push (a delivery robot's
    pair of them; a tracked body's pair are its flippers). A pan/tilt unit turns about square
    axes, a flipper's track or a wheel turns for ever, a suspension carries wheels (a mount)."""
    if not moves or len(limbs) not in (1, 2) or not all(_two_link(tree, limb) for limb in limbs):
        return limbs
    if len(limbs) == 1:
        why = (
            "the body's only limb, an unnamed chain of two hinges about parallel level axes "
            "(a two-link arm swinging in a vertical plane) on a body that moves"
        )
    elif _opposite(tree, limbs) and not _tracked(tree):
        why = (
            "one of the body's only two limbs, one on each side of it, each an unnamed chain of "
            "two hinges about parallel level axes (two-link arms) on a body that moves"
        )
    else:
        return limbs
    return [replace(limb, kind="arm", why=why) for limb in limbs]


def _two_link(tree: JointTree, limb: Limb) -> bool:
    """``limb`` is an unnamed chain of no limb's kind of two limited hinges about parallel
    level axes, the second at least :data:`_PLANAR_REACH` from the first."""
    found = _two_hinges_alone(tree, [limb], endless=False)
    if found is None:
        return False
    _, first, second = found
    axis = tree.poses.axis(first)
    return (
        abs(axis[2]) <= _LEVEL_AXIS
        and parallel(axis, tree.poses.axis(second))
        and joint_span(tree, limb) >= _PLANAR_REACH
    )


# How far (metres) a two-link arm's second hinge is from its first, at least (a wrist's two
# hinges on one servo bracket sit closer).
_PLANAR_REACH = 0.1
# How level an axis is: the most its upright part may be (the sine of its tilt).
_LEVEL_AXIS = 0.1


def joint_span(tree: JointTree, limb: Limb) -> float:
    """How far a chain's last joint is from its first, at rest (metres): a finger's knuckles
    span a few centimetres, an arm's shoulder and elbow more."""
    first, last = tree.urdf.joint(limb.joints[0]), tree.urdf.joint(limb.joints[-1])
    if first is None or last is None:
        return 0.0
    return distance(tree.poses.place(first.child), tree.poses.place(last.child))


def _walks(tree: JointTree) -> bool:
    """The robot's name calls it something that walks, as a word (:data:`_WALKER_WORD`, its
    camelCase and acronyms split: ``UXALeg``; not ``college``, ``legacy`` nor ``watchdog``), and
    no arm nor an upper body (:data:`_UPPER_BODY`: ``humanoid_upper``)."""
    name = _CAMEL.sub("_", _ACRONYM.sub("_", tree.urdf.name))
    return bool(_WALKER_WORD.search(name)) and not _named_arm(name) and not _UPPER_BODY.search(name)


# A walker's name as a word (``uxa_leg``, ``biped_rig``, ``robot_dog``, ``legged_test``).
_WALKER_WORD = re.compile(
    r"(^|[^a-z])(legs?|legged|biped|humanoid|walker|walking|quadruped|hexapod|dog)([^a-z]|$)",
    re.IGNORECASE,
)
# An upper body's name: its arms may hang down when it is bolted to the world.
_UPPER_BODY = re.compile(r"upper|torso|bust|chest|arms|dual|twin", re.IGNORECASE)
# Where an acronym ends and a capitalised word starts (``UXA|Leg``).
_ACRONYM = re.compile(r"(?<=[A-Z])(?=[A-Z][a-z])")


def _world_root(tree: JointTree) -> bool:
    """The description's root link is ``world``, the robot bolted to the ground by it: not hung
    from it on a ``floating`` joint (a simulator's free body, as good as no world). A world
    holding anything on another joint (the robot fixed to it beside a free ball) bolts."""
    root = tree.urdf.root
    children = tree.urdf.children(root)
    return root.lower() == "world" and not (
        children and all(joint.type == "floating" for joint in children)
    )


def _free_body(tree: JointTree) -> str:
    """The body's root: the description's root link, or the one link it carries, on a
    ``floating`` joint (a simulator's ``world`` holding the free body it spawns, and nothing
    else)."""
    root = tree.urdf.root
    children = tree.urdf.children(root)
    if len(children) == 1 and children[0].type == "floating":
        return children[0].child
    return root


def _on_the_root(tree: JointTree, link: str) -> bool:
    """``link`` is the root, or fixed to it (a forearm fixed to ``world``)."""
    joint = tree.urdf.parent_joint(link)
    while joint is not None and not joint.movable:
        joint = tree.urdf.parent_joint(joint.parent)
    return joint is None


def sort_limbs(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """Legs, arms, heads, then the rest; each kind in the document order of its first joint."""
    return sorted(
        limbs,
        key=lambda limb: (
            LIMB_KINDS.index(limb.kind) if limb.kind in LIMB_KINDS else len(LIMB_KINDS),
            tree.order(limb.joints[0]),
        ),
    )


def _contracted(
    tree: JointTree, special: set[str], grippers: set[str], roles: dict[str, Role]
) -> tuple[dict[str, list[Joint]], dict[str, set[str]], set[str]]:
    """The limb joints below each anchor ("" = root), what each anchor carries (wheel, rotor,
    thruster, gripper, ...) and the anchors that hold a gripper."""
    children: dict[str, list[Joint]] = {}
    carries: dict[str, set[str]] = {}
    hosts: set[str] = set()
    stack: list[tuple[str, str]] = [(tree.urdf.root, "")]
    while stack:
        link, anchor = stack.pop()
        for joint in reversed(tree.urdf.children(link)):
            below = anchor
            if joint.name in special:
                role = roles.get(joint.name)
                kind = "gripper" if joint.name in grippers else role.role if role else "base"
                carries.setdefault(anchor, set()).add(kind)
                if kind == "gripper":
                    hosts.add(anchor)
                    continue  # the gripper's own subtree is not a limb
            elif tree.drives(joint) and joint.type in _LIMB_JOINTS:
                children.setdefault(anchor, []).append(joint)
                below = joint.name
            stack.append((joint.child, below))
    for joints in children.values():
        joints.sort(key=lambda j: tree.order(j.name))
    return children, carries, hosts


def _classify(
    tree: JointTree, chain: list[Joint], base: str, marks: set[str], flying: bool
) -> Limb:
    """The limb one chain is, from what it carries, its names and its length."""
    names = tuple(j.name for j in chain)
    tip = _tip(tree, chain[-1])
    gripper = "gripper" in marks
    mounted = sorted(marks & set(_MOUNTED))
    scores = _name_scores(tree, chain)
    if _tip_matches(tree, "leg", chain[-1]):
        scores["leg"] += 1
    named = any(scores.values())
    length = _freedom(chain)
    if (
        not gripper
        and length <= tree.profile.limb("head_max_joints")
        and _turns(chain)
        and not _an_arm_by_name(tree, chain, scores, flying=flying)
        and (cameras := _cameras_turned(tree, chain[-1], named=named))
    ):
        # A camera's own frame turned by the chain's last joint: a gimbal, whatever the chain
        # is named (a drone's gimbal arms); an arm's camera hangs fixed below its wrist.
        why = f"its last joint turns a camera's frame ({cameras}): a gimbal or pan/tilt unit"
        return Limb("head", names, base, tip, gripper, named, why)
    kind, why = _named_kind(tree, scores, length, gripper)
    kind, why = _ends_in_a_foot(tree, kind, why, tip, length=length, gripper=gripper)
    tail_length = length <= tree.profile.limb("head_max_joints")
    if kind is None and not named and not gripper and tail_length and _TAIL.search(tip):
        # A tail (a walker's, balancing it; a head's few joints at most) moves as an arm
        # does, but carries nothing.
        kind, why = "head", f"an unnamed chain ending in a tail ({tip}): an appendage, no arm"
    if mounted:
        if mounted == ["wheel"] and kind == "leg":
            return Limb("wheel_leg", names, base, tip, gripper, named, f"{why}, on a wheel")
        return Limb("mount", names, base, tip, gripper, named, f"carries {', '.join(mounted)}")
    if kind is not None:
        return Limb(kind, names, base, tip, gripper, named, why)
    kind, why = _unnamed_kind(tree, chain, length, gripper=gripper, named=named, flying=flying)
    return Limb(kind, names, base, tip, gripper, named, why)


def _freedom(chain: list[Joint]) -> int:
    """The chain's degrees of freedom, not its joints: a ball-joint shoulder moves like three
    hinges."""
    return sum(3 if joint.type == "spherical" else 1 for joint in chain)


def _an_arm_by_name(
    tree: JointTree, chain: list[Joint], scores: dict[str, int], *, flying: bool
) -> bool:
    """A chain whose joints themselves, two or more, are named an arm's and none of whose
    parts a head's (``scores``: :func:`_name_scores`), on a body that does not fly: an arm
    pointing a camera at its tip (a patrol robot's ``arm_joint_01`` ..), not a gimbal (a
    drone's gimbal arms are a head whatever their names) nor a pan/tilt unit whose links only
    an exporter named (``joint_7`` moving ``arm_2``)."""
    if flying or scores["head"]:
        return False
    return sum(1 for j in chain if "arm" in tree.parts_of(j.name)) >= _NAMED_ARM_JOINTS


def _name_scores(tree: JointTree, chain: list[Joint]) -> dict[str, int]:
    """How many of the chain's joints (each with its child link) are named as each limb's."""
    named_parts = [tree.parts_of(j.name) | tree.parts_of(j.child) for j in chain]
    return {kind: sum(1 for parts in named_parts if kind in parts) for kind in LIMB_KINDS}


def _cameras_turned(tree: JointTree, last: Joint, *, named: bool) -> str:
    """The camera frame ``last`` turns: its own link named for a camera; or, in a chain its
    names call a limb (an unnamed one pointing a sensor is a head already), the links fixed
    below it when all are cameras' and nothing else hangs there (a pan/tilt's tilt link
    carrying ``camera_1`` and ``camera_2``; an arm's wrist carries a tool or a flange too);
    empty when it turns none."""
    if _CAMERA.search(last.child):
        return last.child
    if not named or last.child in tree.moving_below:
        return ""
    below = list(islice(tree.urdf.fixed_below(last.child), _MOST_CAMERA_FRAMES + 1))
    if not below or len(below) > _MOST_CAMERA_FRAMES or not all(_CAMERA.search(b) for b in below):
        return ""
    return ", ".join(below)


def _unnamed_kind(
    tree: JointTree, chain: list[Joint], length: int, *, gripper: bool, named: bool, flying: bool
) -> tuple[str, str]:
    """The kind of a chain the names do not decide, by its shape and what it carries."""
    if (
        not named
        and not gripper
        and length <= tree.profile.limb("head_max_joints")
        and _turns(chain)
        and points_a_sensor(tree, chain[-1])
        and not _shoulder_and_elbow(tree, chain)
    ):
        return "head", (
            f"a chain of {length} joint(s) carrying a camera or a range sensor (a pan/tilt unit)"
        )
    if len(chain) == 1 and chain[0].type == "spherical" and not gripper and _wheeled(tree):
        # Three turns in one ball on a wheeled body, no joint after it: a ball caster, a
        # rolling robot's shell (elsewhere an unnamed ball may be a shoulder).
        return "other", "a lone ball joint on a wheeled body (a ball caster or a shell)"
    why = _arm_why(tree, chain, length, gripper=gripper, named=named, flying=flying)
    return ("arm", why) if why else ("other", "no name or shape of a limb")


def _arm_why(
    tree: JointTree, chain: list[Joint], length: int, *, gripper: bool, named: bool, flying: bool
) -> str:
    """Why a chain the names do not decide is an arm, or "": long enough for one, or ending in
    a gripper; short, unnamed, hanging from a flying body or turning on a link named as an
    arm's base (:func:`_on_an_arm_base`)."""
    if length >= tree.profile.limb("arm_min_joints") or (gripper and length >= 2):
        return "ends in a gripper" if gripper else f"an unnamed chain of {length} joints"
    if flying and length >= _FLYING_ARM_JOINTS and not named:
        return f"a chain of {length} joints hanging from a flying body"
    if not named and length >= 2 and _on_an_arm_base(chain[0]):
        return f"a chain of {length} joints on a link named as an arm's base"
    return ""


def holding_tools(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """A chain of two joints or more that no other reading made a limb (still ``other``, once
    legs, heads and pan/tilt units are found), whose last link holds a tool on fixed joints
    (:func:`_rigid_tool_at`), is an arm: a car's lift and wrist roll holding a gripper whose
    jaws the file draws fixed, a waiter robot's lift and swing holding its tray's end effector.
    Read last, so a humanoid's arm holding a tool is found with its other arm, and a pan/tilt
    unit whose tip frame is an ``end_effector`` stays a head."""
    return [_holding_a_tool(tree, limb) if limb.kind == "other" else limb for limb in limbs]


def swinging_booms(tree: JointTree, limbs: list[Limb]) -> list[Limb]:
    """A chain of a slide along a turn's axis and that turn that no other reading made a limb
    (still ``other``), whose last link is a boom (:func:`_boom_reach`: long, reaching out from
    the axis, carrying no sensor), is an arm: a lift raising a boom that swings round the
    column it rides (a cylindrical arm on a tracked base, its links named in no language the
    profile reads). A tray, a turntable or a jacking plate is flat and holds its mass on or
    near the axis, a mast is long along the axis, and a pan head carries a sensor: none is an
    arm. Read after :func:`holding_tools`."""
    return [_swinging_a_boom(tree, limb) if limb.kind == "other" else limb for limb in limbs]


def _swinging_a_boom(tree: JointTree, limb: Limb) -> Limb:
    """``limb`` made an arm when it is a slide and a turn swinging a boom."""
    joints = _joints_of(tree, limb)
    reach = _boom_reach(tree, joints)
    if reach is None:
        return limb
    names = ", ".join(shown(joint.name) for joint in joints)
    why = f"a lift and a swing about its axis ({names}) carrying a boom {reach:.2f} m out"
    return replace(limb, kind="arm", why=why)


def _boom_reach(tree: JointTree, chain: list[Joint]) -> float | None:
    """How far out from the turn's axis the chain's last link's mass centre sits, when the
    chain is one slide along one turn's axis and that turn (either first) and its last link is
    a boom: its mass at least :data:`_BOOM_REACH` out, its inertia long (:meth:`long_axis`)
    along the line out from the axis, and no sensor on it (:func:`_carries_a_sensor`); None
    otherwise (or when the link's inertial says no place or no inertia)."""
    slides = [joint for joint in chain if joint.type == "prismatic"]
    turns = [joint for joint in chain if joint.type in _TURNING]
    if len(chain) != 2 or len(slides) != 1 or len(turns) != 1:
        return None
    axis = tree.poses.axis(turns[0])
    link = chain[-1].child
    if not parallel(tree.poses.axis(slides[0]), axis) or _carries_a_sensor(tree, chain[-1]):
        return None
    centre, long = tree.poses.mass_centre(link), tree.poses.long_axis(link)
    if centre is None or long is None:
        return None
    offset = minus(centre, tree.poses.place(turns[0].child))
    out = cross(axis, cross(offset, axis))  # the offset's part square to the (unit) axis
    reach = math.hypot(*out)
    if reach < _BOOM_REACH or cosine(long, out) < _ALONG_THE_BOOM:
        return None
    return reach


def _carries_a_sensor(tree: JointTree, last: Joint) -> bool:
    """``last`` moves a sensor: one declared on its link or below it (:func:`points_a_sensor`),
    or its link or one fixed below it named as a camera's or a sensor's frame
    (:func:`_names_a_sensor_frame`: a ``zed2`` or ``velodyne`` frame on a mast's head)."""
    return points_a_sensor(tree, last) or any(
        _CAMERA.search(name) or _names_a_sensor_frame(tree, name) for name in _rigid_end(tree, last)
    )


def _rigid_end(tree: JointTree, last: Joint) -> list[str]:
    """``last``'s link and the links fixed below it, :data:`_MOST_TOOL_LINKS` of those at most:
    the part the chain's last joint moves, where a tool, a sensor or a tool frame sits."""
    return [last.child, *islice(tree.urdf.fixed_below(last.child), _MOST_TOOL_LINKS)]


def _names_a_sensor_frame(tree: JointTree, name: str) -> bool:
    """A rule of the profile's sensor frames (``frame_rules``) reads ``name`` as a sensor's."""
    return any(rule.accepts(None, name) for rule in tree.profile.frame_rules)


def one_joint_legs(tree: JointTree, limbs: list[Limb], moves: bool) -> list[Limb]:
    """Chains of one hinge each, called legs (:func:`_a_one_joint_leg`), that no other reading
    made a limb (still ``other``), four or six of them (:data:`_ONE_JOINT_LEGS`) on one rigid
    body, alike, turning about parallel level axes, at the body's corners: a toy walker's legs,
    each swinging round whole or back and forth on one servo. A leg needs two joints by its
    name alone (``leg_min_joints``), and one-joint chains are legs by place only when six or
    more turn whole (:func:`legs_by_place`: a RHex's). Not on a body that rolls or flies
    (``moves``), that any joint's name says rolls or flies (a wheel, a rotor or a track, fixed
    ones too: a trimmed model's), whose name says it flies or stands (a drone's landing legs, a
    table's), that carries an arm (a crane's outriggers) or that is bolted to the world (a test
    stand); nor legs named as supports that fold or deploy (:data:`_SUPPORT`)."""
    if moves or _world_root(tree) or any(limb.kind == "arm" for limb in limbs):
        return limbs
    named = [limb for limb in limbs if _a_one_joint_leg(tree, limb)]
    group = [limb for limb in named if limb.base == named[0].base] if named else []
    if (
        len(group) not in _ONE_JOINT_LEGS
        or _rolls_or_flies_by_name(tree)
        or not _alike_chains(tree, group)
        or not _parallel(tree, group)
        or parallel(tree.poses.axis(_joints_of(tree, group[0])[0]), _UP)
        or not _at_corners(tree, group[0].base, group, wheeled=False)
    ):
        return limbs
    names = ", ".join(shown(limb.joints[0]) for limb in group)
    why = f"one of {len(group)} one-hinge chains named as legs at the body's corners ({names})"
    return [replace(limb, kind="leg", why=why) if limb in group else limb for limb in limbs]


def _a_one_joint_leg(tree: JointTree, limb: Limb) -> bool:
    """``limb`` is still ``other``, one hinge, no gripper, its joint or the link it turns
    called a leg as a word (:data:`_LEG_WORD`: not only a corner, a hip or a foot) and not a
    support that folds, deploys or holds (:data:`_SUPPORT`), and its names call it a leg more
    than any other limb."""
    joints = _joints_of(tree, limb)
    if limb.kind != "other" or limb.gripper or len(joints) != 1 or joints[0].type not in _TURNING:
        return False
    names = (joints[0].name, joints[0].child)
    if not any(_LEG_WORD.search(name) for name in names) or any(
        _SUPPORT.search(name) for name in names
    ):
        return False
    scores = _name_scores(tree, joints)
    return all(scores["leg"] > count for kind, count in scores.items() if kind != "leg")


def _rolls_or_flies_by_name(tree: JointTree) -> bool:
    """A joint of the description, fixed ones too, or the link it holds, is named as a wheel's,
    a rotor's or a track's, or the robot's name says it flies (the profile's flight words) or
    stands on its legs without walking (:data:`_STANDS`: furniture, a lander)."""
    flight = tree.profile.plugin_pattern("flight")
    name = tree.urdf.name
    if (flight is not None and flight.search(name)) or _STANDS.search(_CAMEL.sub("_", name)):
        return True
    return any(
        tree.matches(part, joint)
        for joint in tree.urdf.joints
        for part in ("wheel", "rotor", "track")
    )


# How far out from its turn's axis a boom's mass sits, at the least: a tray's, a turntable's or
# a jacking plate's sits on the axis or near it, a boom's along its length.
_BOOM_REACH = 0.1
# How nearly a boom's long axis points out from the turn's axis (the cosine of the angle
# between them: a boom raised or lowered by a quarter of a right angle, or less).
_ALONG_THE_BOOM = 0.9


def _holding_a_tool(tree: JointTree, limb: Limb) -> Limb:
    """``limb`` made an arm when it has two degrees of freedom or more and holds a tool."""
    joints = _joints_of(tree, limb)
    length = _freedom(joints)
    tool = _rigid_tool_at(tree, joints) if length >= 2 else ""
    if not tool:
        return limb
    why = f"a chain of {length} joints holding a tool fixed to its last link ({tool})"
    return replace(limb, kind="arm", why=why)


def _rigid_tool_at(tree: JointTree, chain: list[Joint]) -> str:
    """The first link fixed below the chain's last joint that :func:`names_a_tool` and that
    has something in it (a gripper's body, a claw, a suction cup, an end effector); empty when
    there is none. Only a grasping tool's name (the profile's gripper words) counts on a chain
    that points a camera or a sensor (:func:`_carries_a_sensor`: a mast's head) or turns as a
    pan/tilt unit does (two hinges about square axes): an ``end_effector`` or ``eef`` there is
    the frame a controller aims, no tool."""
    last = chain[-1]
    below = list(islice(tree.urdf.fixed_below(last.child), _MOST_TOOL_LINKS))
    tools = [name for name in below if names_a_tool(tree, name) and _solid(tree, name)]
    if not tools:
        return ""
    aims = _pan_tilt_turns(tree, chain) or _carries_a_sensor(tree, last)
    return next((name for name in tools if not aims or "gripper" in tree.parts_of(name)), "")


def _pan_tilt_turns(tree: JointTree, chain: list[Joint]) -> bool:
    """The chain is two hinges about square axes (:func:`_square_turns`): a pan/tilt unit's."""
    return (
        len(chain) == 2
        and all(joint.type in _TURNING for joint in chain)
        and _square_turns(tree, chain[0], chain[1])
    )


# The most links fixed below a chain's tip read for a tool (a gripper's body and its jaws).
_MOST_TOOL_LINKS = 16


def _solid(tree: JointTree, name: str) -> bool:
    """``name`` is a link with something in it (a shape or a mass), not a bare frame."""
    link = tree.urdf.link(name)
    return link is not None and not link.empty


def names_a_tool(tree: JointTree, name: str) -> bool:
    """The profile's ``tool`` pattern names the link (a gripper, a claw, a suction cup, an end
    effector), and it is neither a mount's (``gripper_camera_mount``) nor a frame the sensor
    frame rules read (``end_effector_cam``): no tool itself."""
    return (
        "tool" in tree.parts_of(name)
        and not _TOOL_MOUNT.search(name)
        and not _names_a_sensor_frame(tree, name)
    )


# A link that holds a tool or a sensor, named so: no tool itself.
_TOOL_MOUNT = re.compile(r"mount|holder|bracket", re.IGNORECASE)


def _on_an_arm_base(first: Joint) -> bool:
    """The chain's first joint turns on a link named as an arm's base or mount (``arm_base``,
    ``manipulator_base_link``, ``ArmMount``: an arm or a manipulator as a word,
    :func:`_named_arm`, and a base or a mount): what it carries is that arm, however short."""
    return _named_arm(first.parent) and bool(_BASE_WORD.search(first.parent))


# A base or a mount in a link's name.
_BASE_WORD = re.compile(r"base|mount", re.IGNORECASE)


def _shoulder_and_elbow(tree: JointTree, chain: list[Joint]) -> bool:
    """Two joints of the chain turn about parallel axes apart from each other, as an arm's
    shoulder and elbow do: the chain carries what it holds across space (a camera an arm moves
    round an object), where a pan/tilt unit turns it where it is, about axes that cross or
    are one (a pan, then a tilt square to it). A hinge about no axis is not compared."""
    turning = _about_an_axis(tree, chain)
    return any(
        parallel(tree.poses.axis(one), tree.poses.axis(other))
        and _axes_apart(tree, one, other) > _SAME_AXIS_GAP
        for one, other in combinations(turning, 2)
    )


# How far apart two parallel axes may pass and still be one (a file's rounding).
_SAME_AXIS_GAP = 1e-3


def _turns(chain: list[Joint]) -> bool:
    """The chain's last joint turns: a pan/tilt unit points the sensor it carries (on a lift
    or not); a chain that ends in a slide carries it up and down (a forklift's carriage, on a
    mast that tilts or not)."""
    return chain[-1].type != "prismatic"


def _pan_then_tilt(tree: JointTree, pan: Joint, tilt: Joint) -> bool:
    """A vertical axis, then one square to it: how a pan/tilt unit turns."""
    axis = tree.poses.axis(pan)
    return abs(axis[2]) >= _VERTICAL and perpendicular(axis, tree.poses.axis(tilt))


# How vertical a pan axis is (the cosine of its angle to the vertical).
_VERTICAL = 0.99


def points_a_sensor(tree: JointTree, joint: Joint) -> bool:
    """A camera, lidar or range sensor sits on the joint's child link or below it."""
    links = tree.sensor_links
    if not links:
        return False
    return joint.child in links or any(
        j.child in links for j in tree.urdf.subtree_joints(joint.child)
    )


def _named_kind(
    tree: JointTree, scores: dict[str, int], length: int, gripper: bool
) -> tuple[str | None, str]:
    """The limb kind the names say, within the profile's thresholds, and why."""
    ranked = sorted(LIMB_KINDS, key=lambda k: -scores[k])  # stable: leg, arm, head on ties
    for kind in ranked:
        if scores[kind] == 0:
            break
        why = f"{scores[kind]} {kind} name(s) on its joints and links"
        # Leg names win over a gripper at the end: a leg may end in a gripper.
        if kind == "leg" and length >= tree.profile.limb("leg_min_joints"):
            return "leg", why
        if kind == "head" and length <= tree.profile.limb("head_max_joints") and not gripper:
            return "head", why
        # Two joints both named as an arm's (arm_1_joint, arm_2_joint) are a short arm.
        if kind == "arm" and (
            length >= tree.profile.limb("arm_min_joints") or gripper or scores[kind] >= _LIMB_NAMES
        ):
            return "arm", why
    return None, ""


def _tip(tree: JointTree, joint: Joint) -> str:
    """The last link of a limb: follow fixed joints down while the path is unbranched."""
    link = joint.child
    while True:
        below = [j for j in tree.urdf.children(link) if not j.movable]
        if len(tree.urdf.children(link)) != 1 or len(below) != 1:
            return link
        link = below[0].child


def _ends_in_a_foot(
    tree: JointTree, kind: str | None, why: str, tip: str, *, length: int, gripper: bool
) -> tuple[str | None, str]:
    """A chain the names make an arm, at least a leg's length, with no gripper, whose tip is
    named as a foot: a leg built of modules named as an arm's (base, shoulder, elbow), as a
    modular walker's are; an arm never ends in a foot. Else ``kind`` and ``why`` as they were."""
    if (
        kind == "arm"
        and not gripper
        and length >= tree.profile.limb("leg_min_joints")
        and _FOOT.search(tip)
    ):
        return "leg", f"{why}, but it ends in a foot ({tip})"
    return kind, why


# A foot's name at a limb's tip (``leg1__FOOT``, ``rf_foot``, ``toe_link``, ``sole``, a
# camel-cased ``RightToe``).
_FOOT = re.compile(
    r"foot|feet|(^|[_/])(soles?|toes?)([_/\d]|$)|(?-i:(?<=[a-z])(Soles?|Toes?)(?=[A-Z_/\d]|$))",
    re.IGNORECASE,
)


# A tail's name at a limb's tip (``tail_end``, ``tail_tip``).
_TAIL = re.compile(r"(^|[_/])tails?([_/\d]|$)", re.IGNORECASE)


def _tip_matches(tree: JointTree, part: str, joint: Joint) -> bool:
    """A link held by a fixed joint somewhere below ``joint`` is named as ``part`` (a foot),
    and not as a wheel or a caster: a corner's words in a caster's name
    (``front_right_caster_link`` on a bogie's shaft) say where it rolls, not that it is a
    leg's."""
    return any(
        not below.movable and part in (parts := tree.parts_of(below.child)) and not parts & _ROLLING
        for below in tree.urdf.subtree_joints(joint.child)
    )


# The parts that roll: a link named so is no other part, whatever corner its name gives.
_ROLLING = frozenset({"wheel", "caster"})
