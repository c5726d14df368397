"""Hands and grippers: the joints that move fingers, found by name and by place.

A gripper joint (named so by the profile, or on a link named as a hand or palm:
:mod:`solver.identify.roles`) moves a finger, and so does every movable joint below one (a
finger's phalanges): :func:`gripper_closure`. Fingers whose chains carry no names are still
told by where they are, side by side on one palm in threes or more (short chains, or chains
of many joints no longer than a finger: a soft or flexure finger), or in a two-finger
gripper's pair, short and close together (:func:`finger_groups`).
Jaws are told by where they are too (:func:`jaws`): joints side by side on one link that turn
or slide about one line with nothing beyond them but their own followers (a linkage of mimic
joints), closed by one motion (mimic joints follow one driver; not on a head, where a mirrored
pair, or a pair swinging both ways about the line between them, is ears or eyelids, nor such a
swinging pair that is a body's only motions, a tilt-rotor's two motor mounts) or, at the
end of a chain of two joints or more, each by its own (a humanoid's split gripper; two that
turn without limits, as a sloppy file writes jaws, only at the end of an arm: a wheel-leg's hub
on the slides that place it in a simulator's world carries rim halves, no jaws); so are the
joints of a body whose every motion is one motor's, turning on its link about three directions
or more (a linkage gripper's fingers spread about its palm). A hand is counted by its fingers,
one tip per finger (:func:`finger_tips`).

Not here: the limb a hand ends (:mod:`solver.identify.limbs`), the other single-joint roles
(:mod:`solver.identify.actuation`).
"""

from __future__ import annotations

import math
import re
from collections import Counter
from itertools import islice, pairwise

from solver.identify.couplings import Walk, jaw_groups
from solver.identify.limbs import Limb, chain_ends, joint_span, joint_words, moved_by, tips_meet
from solver.identify.placement import MACHINE_TRAVEL, placement
from solver.identify.pose import Vector, distance, local_axis, parallel, perpendicular, within
from solver.identify.readers.urdf import Joint
from solver.identify.tree import JointTree

__all__ = [
    "endless_jaws",
    "finger_groups",
    "finger_tips",
    "gripper_closure",
    "jaws",
    "limbs_named_for_a_hand",
    "stacked_grippers",
]

# Joints with a travel a file writes (a jaw's, a finger's).
_LIMITED = ("revolute", "prismatic")
# Parts whose names make a joint no jaw (a pair of eyes, two wheels, two legs).
_NOT_JAWS = ("head", "leg", "wheel", "caster", "rotor", "thruster", "fin", "wing", "track")
# A head's own moving parts, by their names (a droid's antennas, a pet's ears, eyelids): on a
# head, no gripper's jaws, though two of them swing side by side at the end of a neck. Only
# that: such a joint alone makes no head (a rover's hinged radio antenna is no pan/tilt unit),
# nor are a gripper's jaws at an arm's end anything else, whatever they are called.
_HEAD_PARTS = re.compile(r"antenna|(^|[_/])ears?([_/]|$)|eyelid|eyebrow", re.IGNORECASE)
# Words of a finger's joints (or the links they move): a hand's finger, not a gripper's jaw.
_FINGER = re.compile(r"finger|thumb|knuckle|phalan", re.IGNORECASE)
# A link named as a hand, and the names of a hand's parts that are no whole arm.
_HAND = re.compile(r"(^|[_/lr])hand([_/]|$)", re.IGNORECASE)
_NOT_A_HAND = re.compile(rf"{_FINGER.pattern}|palm|jaw|claw|grip", re.IGNORECASE)
# A hand's bones, as a display hand names its fingers' joints and links (``metacarpals``,
# ``proximal``, ``intermediate``, ``distal``, a phalanx): a chain of them one joint longer than a
# finger is one (:func:`_finger_like`).
_FINGER_BONE = re.compile(r"metacarpal|phalan|proximal|intermediate|distal", re.IGNORECASE)
# A frame at a finger's end (``fingertip_1``, ``thumb_tip``).
_FINGERTIP = re.compile(r"(finger|thumb)[_-]?tip", re.IGNORECASE)
# A split gripper's jaws hang at the end of a chain of at least this many driven joints; jaws
# written as joints that turn without limits, at the end of an arm's (``arm_min_joints``).
_CHAIN_BEFORE_JAWS = 2
# Places this close (metres) are one place.
_SAME = 1e-4
# The farthest apart (metres) the first joints of a palm's fingers are: a hand's breadth (the
# sets' hands, a humanoid's to a three-finger industrial gripper's, span up to 0.19 m). Chains
# farther apart on one body are its own parts: an aircraft's control surfaces, a base's flaps.
_HAND_BREADTH = 0.3
# A joint turning through this much goes all the way round: no finger's.
_FULL_TURN = 2 * math.pi - 1e-6
# Two sliding jaws sit apart along one line within this share of their distance across it
# (a CAD export places a finger a few millimetres off the line).
_ASIDE = 0.1
# A body's one motion turning joints on one link about this many directions or more closes
# fingers spread about a palm; a follower's ratio this small moves nothing.
_ABOUT_A_PALM = 3
_STILL = 1e-6
# The farthest a finger reaches from its first joint to its tip (metres): a hand's finger is
# about 0.1 m, a gripper's jaw less; an arm, even a small one, reaches farther.
_FINGER_REACH = 0.15
# The farthest a finger's last joint is from its first (metres): a hand's longest finger's
# knuckles span under 0.1 m, a large gripper's finger less than this; an arm's shoulder and
# elbow are farther apart.
_FINGER_LENGTH = 0.2
# Chains taken as fingers by their size on one palm, at most (a hand has five, a claw a few
# more): past this, a stranger's thousands of chains are no fingers, not compared pair by pair.
_MOST_SIZED_FINGERS = 16


def jaws(tree: JointTree, taken: set[str]) -> dict[str, str]:
    """Jaw joints (see the module docstring), each with the evidence that found it."""
    found: dict[str, str] = {}
    for group in jaw_groups(tree.urdf, tree.couplings):
        driver = tree.couplings.driver(group[0])
        if (
            taken.isdisjoint(group)
            and not any(_named_otherwise(tree, n) for n in group)
            and not _on_a_head(tree, _parent_link(tree, driver))
        ):
            why = f"one motion ({driver}, {len(group) - 1} mimic joint(s)) closes jaws side by side"
            found.update(dict.fromkeys(group, why))
    found.update(_jaw_pairs(tree, taken | set(found)))
    found.update(_one_motion(tree, taken | set(found)))
    return found


def endless_jaws(tree: JointTree, taken: set[str]) -> dict[str, str]:
    """Two endless joints side by side at the end of an arm (:func:`_jaw_pairs`), each with
    the evidence that found it: read once the wheels are known (``taken``), as a sloppy file
    writes a gripper's jaws, and twin wheels on a wheel-leg's shin are wheels first."""
    return _jaw_pairs(tree, taken, endless=True)


def _one_motion(tree: JointTree, taken: set[str]) -> dict[str, str]:
    """A body whose every motion is one limited driver's (:func:`_sole_driver`), the joints of
    that motion on the driver's link turning about :data:`_ABOUT_A_PALM` directions or more,
    square to one line (fingers spread about a palm; gears and a lever's jaws turn about one):
    a gripper's linkage one motor closes."""
    motions = [joint for joint in tree.urdf.joints if joint.movable]
    driver = _sole_driver(tree, motions, taken)
    if driver is None:
        return {}
    directions: list[tuple[float, float, float]] = []
    for joint in motions:
        axis = local_axis(joint)
        if joint.parent == driver.parent and not any(parallel(axis, d) for d in directions):
            directions.append(axis)
    if len(directions) < _ABOUT_A_PALM or not _about_one_line(directions):
        return {}
    why = f"the body's only motion ({driver.name}) closes a linkage spread about its palm"
    return dict.fromkeys((joint.name for joint in motions), why)


def _sole_driver(tree: JointTree, motions: list[Joint], taken: set[str]) -> Joint | None:
    """The one limited joint every one of ``motions`` is or follows, each follower moving and
    none named as another part nor ``taken``; None when there is no such joint."""
    drivers = {tree.couplings.driver(joint.name) for joint in motions}
    driver = tree.urdf.joint(drivers.pop()) if len(drivers) == 1 else None
    if (
        driver is None
        or driver.type not in ("revolute", "prismatic")
        or driver.lower is None
        or not taken.isdisjoint(joint.name for joint in motions)
        or any(abs(joint.multiplier) <= _STILL for joint in motions)
        or any(_named_otherwise(tree, joint.name) for joint in motions)
    ):
        return None
    return driver


def _about_one_line(directions: list[tuple[float, float, float]]) -> bool:
    """Every direction square to one line (the palm's axis): fingers spread round a palm
    hinge about tangents to it; a gearbox's shafts (along x, y and z) do not."""
    (ax, ay, az), (bx, by, bz) = directions[0], directions[1]
    normal = (ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx)
    return all(perpendicular(normal, axis) for axis in directions[2:])


def _jaw_pairs(tree: JointTree, taken: set[str], *, endless: bool = False) -> dict[str, str]:
    """Two limited joints (with ``endless``, two endless ones) side by side on one link, each
    driven on its own and moving nothing but its own followers (a leaf, or a jaw's linkage of
    mimic joints): jaws at the end of a chain (endless ones at the end of an arm:
    :func:`_ends_an_arm`), or a gripper's whole body (its only motions), unless they swing both
    ways about the line between them (:func:`_ears`: they never close on each other; a
    tilt-rotor's two motor mounts). At the end of a chain that is no head's, two hinges
    mirroring each other (:func:`_twins`) are jaws too, and so are such twins that each carry
    one fingertip hinge of their own within a finger's reach (:func:`_tipped_twins`)."""
    by_parent: dict[str, list[Joint]] = {}
    tipped: set[str] = set()  # jaws that carry a fingertip hinge of their own
    walk = Walk(tree.urdf)
    for joint in tree.urdf.joints:
        if joint.name in taken or not _may_be_a_jaw(joint, endless=endless):
            continue
        if not _moves_alone(tree, joint, walk):
            if endless or not _tipped(tree, joint):
                continue
            tipped.add(joint.name)
        by_parent.setdefault(joint.parent, []).append(joint)
    _pair_on_one_body(tree, by_parent)
    motions = [joint.name for joint in tree.urdf.joints if joint.movable]
    # The joints that place the body, once (not for every pair), when an endless pair needs them.
    pairs = endless and any(len(pair) == 2 for pair in by_parent.values())
    placing = _placing(tree) if pairs else frozenset()
    found: dict[str, str] = {}
    for link, pair in by_parent.items():
        if len(pair) != 2 or any(_named_otherwise(tree, j.name) for j in pair):
            continue
        if tipped & {joint.name for joint in pair}:
            why = _tipped_twins(tree, link, pair)
        else:
            why = _pair_why(tree, link, pair, motions, placing)
        if why:
            found.update(dict.fromkeys((j.name for j in pair), why))
    return found


def _pair_on_one_body(tree: JointTree, by_parent: dict[str, list[Joint]]) -> None:
    """Two joints of ``by_parent``, each alone on its link, whose links are fixed to one body
    and no other joint of it is there: a pair on that body, each written in its frame
    (:meth:`~solver.identify.pose.Poses.hung_from`), as a gripper whose two jaws hinge on
    plates fixed to its palm is (``by_parent`` changed in place)."""
    on_body: dict[str, list[str]] = {}
    tops: dict[str, str] = {}  # one memo for every walk: each link walked once in all
    for link in by_parent:
        on_body.setdefault(_rigid_top(tree, link, tops), []).append(link)
    for body, links in on_body.items():
        if len(links) != 2 or body in links or any(len(by_parent[k]) != 1 for k in links):
            continue
        pair = [tree.poses.hung_from(body, by_parent.pop(link)[0]) for link in links]
        by_parent[body] = pair


def _rigid_top(tree: JointTree, link: str, tops: dict[str, str]) -> str:
    """The link ``link`` is fixed below (through joints that cannot move), itself when it
    hangs from a movable joint or from none (a loop ends the walk); every link walked is
    remembered in ``tops``, so many links cost one walk of the tree at most."""
    walked = [link]
    seen = {link}
    top = link
    while top not in tops:
        joint = tree.urdf.parent_joint(top)
        if joint is None or joint.movable or joint.parent in seen:
            break
        top = joint.parent
        walked.append(top)
        seen.add(top)
    top = tops.get(top, top)
    for each in walked:
        tops[each] = top
    return top


def _may_be_a_jaw(joint: Joint, *, endless: bool) -> bool:
    """``joint`` is driven and limited (with ``endless``, turns for ever: continuous, or
    revolute with a range no real stop has, which no limited jaw has either)."""
    if not joint.actuated:
        return False
    if endless:
        return joint.endless
    return joint.type in _LIMITED and joint.lower is not None and not joint.endless


def _tipped_twins(tree: JointTree, link: str, pair: list[Joint]) -> str:
    """Why two hinges on ``link``, one at least carrying a fingertip hinge (:func:`_tipped`),
    are jaws: they mirror each other (:func:`_twins`) at the end of a chain that is no head's,
    each reaching no farther than a finger (its fingertip's joint within
    :data:`_FINGER_REACH`); "" when they are not (two short arms on a torso travel alike)."""
    if not (_twins(pair) and _ends_a_chain(tree, link) and not _on_a_head(tree, link)):
        return ""
    for joint in pair:
        tip = next((j for j in tree.urdf.children(joint.child) if j.movable), None)
        if tip is None:
            continue
        if distance(tree.poses.place(joint.child), tree.poses.place(tip.child)) > _FINGER_REACH:
            return ""
    return f"one of two hinges mirroring each other at the end of a chain ({link}), tipped"


def _pair_why(
    tree: JointTree,
    link: str,
    pair: list[Joint],
    motions: list[str],
    placing: frozenset[str] = frozenset(),
) -> str:
    """Why two joints on ``link`` are jaws (see :func:`_jaw_pairs`), or "" when they are not
    (``placing``: the joints that place the body, for endless ones)."""
    beside = _side_by_side(pair, exactly=_on_a_head(tree, link))
    if any(joint.type == "continuous" for joint in pair):
        # Jaws a sloppy file lets turn for ever: side by side at the end of an arm, no head's.
        if beside and _ends_an_arm(tree, link, placing) and not _on_a_head(tree, link):
            return f"one of two jaws side by side at the end of an arm ({link}), turning freely"
        return ""
    at_the_end = _ends_a_chain(tree, link)
    if at_the_end and beside and not (_head_parts(pair) and _on_a_head(tree, link)):
        return f"one of two jaws side by side at the end of a chain ({link})"
    if at_the_end and _twins(pair) and not _on_a_head(tree, link):
        return f"one of two hinges mirroring each other at the end of a chain ({link})"
    if beside and _only_motions(tree, pair, motions) and not _ears(pair):
        return f"one of two jaws side by side, the body's only motions ({link})"
    return ""


def _moves_alone(tree: JointTree, joint: Joint, walk: Walk) -> bool:
    """Nothing moves below ``joint`` but joints that follow it (a jaw's own linkage, its mimic
    joints closing a four-bar): what it carries moves by it alone (``walk`` bounds the walks
    of the whole description)."""
    if joint.child not in tree.moving_below:
        return True
    followers = set(tree.couplings.followers.get(joint.name, ()))
    return not walk.moves_beyond(joint.name, followers)


def _tipped(tree: JointTree, joint: Joint) -> bool:
    """What ``joint`` moves carries one limited hinge of its own and nothing else that moves,
    a leaf: a jaw whose tip an open linkage draws as a joint of its own (a servo gripper's
    finger and fingertip, each written as a hinge, no mimic between them)."""
    if joint.child not in tree.moving_below:
        return False
    # Two movable joints at most are looked for (a long chain below is walked no further).
    below = list(islice((j for j in tree.urdf.subtree_joints(joint.child) if j.movable), 2))
    return (
        len(below) == 1
        and below[0].parent == joint.child
        and below[0].type == "revolute"
        and below[0].lower is not None
    )


def _only_motions(tree: JointTree, pair: list[Joint], motions: list[str]) -> bool:
    """Every movable joint of the body (``motions``) is one of ``pair`` or follows one (a mimic
    joint): a gripper on its own, its two jaws each driven. Stops at the first other joint."""
    names = {joint.name for joint in pair}
    return all(name in names or tree.couplings.driver(name) in names for name in motions)


def _named_otherwise(tree: JointTree, name: str) -> bool:
    joint = tree.urdf.joint(name)
    parts = tree.parts_of(name) | (tree.parts_of(joint.child) if joint else frozenset())
    return any(part in parts for part in _NOT_JAWS)


def _side_by_side(pair: list[Joint], exactly: bool = False) -> bool:
    """Two joints of one kind about parallel axes, placed apart along one line only: for two
    sliding joints, within :data:`_ASIDE` of their distance across it (a CAD export's fingers),
    else (``exactly``, or hinges: eyelids, one-joint arms) to :data:`_SAME`."""
    one, other = pair
    offsets = [abs(a - b) for a, b in zip(one.origin, other.origin, strict=True)]
    slack = 0.0 if exactly or one.type != "prismatic" else max(offsets) * _ASIDE
    apart = [offset > max(_SAME, slack) for offset in offsets]
    return (
        one.type == other.type and parallel(local_axis(one), local_axis(other)) and sum(apart) <= 1
    )


def _head_parts(pair: list[Joint]) -> bool:
    """Ears by their swing (:func:`_ears`), or a head's parts by their names
    (:data:`_HEAD_PARTS`, on either joint or the link it moves)."""
    return _ears(pair) or any(_HEAD_PARTS.search(f"{j.name} {j.child}") for j in pair)


def _ears(pair: list[Joint]) -> bool:
    """Two hinges placed apart along their own axis, each with written limits (no placeholder)
    travelling as far either way: they never close on each other (jaws close one way, as
    pliers' or a clamshell's do). On a head, ears that swing; as a body's only motions, a
    tilt-rotor's two motor mounts (:func:`_pair_why`)."""
    one, other = pair
    (ax, ay, az), (bx, by, bz) = one.origin, other.origin
    between = (bx - ax, by - ay, bz - az)
    if one.type != "revolute" or not parallel(local_axis(one), between):
        return False
    return all(
        joint.lower is not None
        and joint.upper is not None
        and joint.lower < joint.upper
        and abs(joint.lower + joint.upper) <= _SAME
        for joint in pair
    )


def _twins(pair: list[Joint]) -> bool:
    """Two hinges that mirror each other: about parallel axes, turning opposite ways over the
    same travel (opposite axes and the same limits, or one axis and opposite limits), as a CAD
    export's jaws placed apart along and across their axes are. Not two slides (a snake's last
    module pushes two pads out), nor two hinges that turn alike or over a travel symmetric
    about zero (wheels, say)."""
    one, other = pair
    travel, mirror = _travel(one), _travel(other)
    if not (one.type == other.type == "revolute" and travel and mirror):
        return False
    if abs(travel[0] + travel[1]) <= _SAME:
        return False  # a travel symmetric about zero mirrors itself: it says nothing
    axis, other_axis = local_axis(one), local_axis(other)
    if not parallel(axis, other_axis):
        return False
    if sum(a * b for a, b in zip(axis, other_axis, strict=True)) > 0:
        mirror = (-mirror[1], -mirror[0])  # about one axis: a mirror turns the other way
    return abs(travel[0] - mirror[0]) <= _SAME and abs(travel[1] - mirror[1]) <= _SAME


def _travel(joint: Joint) -> tuple[float, float] | None:
    """A hinge's limits (lower, upper), or None when it has none written."""
    if joint.lower is None or joint.upper is None:
        return None
    return joint.lower, joint.upper


def _on_a_head(tree: JointTree, link: str) -> bool:
    """The nearest joint that moves ``link`` is named as a head's and not as an arm's (a
    neck's pan and tilt: two mirrored hinges there are eyelids or ears, not jaws; an arm's
    ``shoulder_pan`` far above a gripper is no head)."""
    name = moved_by(tree.urdf, link, {})
    joint = tree.urdf.joint(name) if name is not None else None
    return joint is not None and tree.matches("head", joint) and not tree.matches("arm", joint)


def _parent_link(tree: JointTree, name: str) -> str:
    joint = tree.urdf.joint(name)
    return "" if joint is None else joint.parent


def _ends_a_chain(tree: JointTree, link: str) -> bool:
    """At least two driven joints move ``link`` (it is the end of a chain, not the base)."""
    return _driven_above(tree, link, _CHAIN_BEFORE_JAWS)


def _ends_an_arm(tree: JointTree, link: str, placing: frozenset[str]) -> bool:
    """At least an arm's joints (``arm_min_joints``) drive ``link``, not counting the joints
    that place the body in the world (``placing``: :func:`_placing`) nor slides that travel as
    far (:data:`MACHINE_TRAVEL`: a wheel-leg's hub on the slides that move it in its plane is no
    arm's end)."""
    return _driven_above(tree, link, tree.profile.limb("arm_min_joints"), placing)


def _placing(tree: JointTree) -> frozenset[str]:
    """The joints that place the body in the world: a floating or planar joint, a simulator's
    or a planner's root joints (:func:`~solver.identify.placement.placement`)."""
    where = placement(tree)
    return frozenset((*where.placing, *where.floating, *where.planar))


def _driven_above(
    tree: JointTree, link: str, joints: int, placing: frozenset[str] | None = None
) -> bool:
    """At least ``joints`` driven joints move ``link`` (with ``placing``, not those it names nor
    slides that place the body)."""
    driven = 0
    joint = tree.urdf.parent_joint(link)
    for _ in range(64):
        if joint is None:
            break
        placed = placing is not None and (joint.name in placing or _places(joint))
        driven += tree.drives(joint) and not placed
        if driven >= joints:
            return True
        joint = tree.urdf.parent_joint(joint.parent)
    return False


def _places(joint: Joint) -> bool:
    """A slide whose written travel reaches a simulator's world (:data:`MACHINE_TRAVEL` or
    more): it places the body, no arm's."""
    return (
        joint.type == "prismatic"
        and joint.lower is not None
        and joint.upper is not None
        and joint.upper - joint.lower >= MACHINE_TRAVEL
    )


def stacked_grippers(tree: JointTree, grippers: list[str]) -> list[str]:
    """The gripper-named joints that are an arm: every gripper joint of the body one upon
    another in one unbranched chain, each driven on its own, of more than ``arm_min_joints``
    (a lift, a tilt and a turn, then the jaw), and more than ``finger_max_joints`` when one of
    them is named as a finger's (a finger of four joints is a finger); or such a chain of more
    than both whose last joint carries the gripper's jaws side by side, each carrying no other
    (an exporter that named every part of a six-joint arm ``Jaw_N``; a gripper's own lift,
    tilt and wrist under its jaws stay the gripper's). A gripper's jaws stand side by side or
    follow one motion; stacked so, the joints that carry the others are the arm that carries
    it. Those, in document order."""
    joints = [j for j in (tree.urdf.joint(name) for name in grippers) if j is not None]
    shortest = tree.profile.limb("arm_min_joints")
    if any(_FINGER.search(f"{joint.name} {joint.child}") for joint in joints):
        shortest = max(shortest, tree.profile.limb("finger_max_joints"))
    carried = _carried(tree, joints)
    carriers = sorted(carried, key=tree.order)
    driven = {joint.name for joint in joints if joint.actuated}
    roots = len(joints) - sum(carried.values())
    if roots != 1 or not set(carriers) <= driven:
        return []  # two chains, or a carrier that follows another's motion
    fans = [name for name in carriers if carried[name] > 1]
    if not fans:  # one chain: the jaw at its end driven too (jaws following one motion)
        return carriers if len(joints) > shortest and len(driven) == len(joints) else []
    # The chain's last joint carries the jaws: one fan, at the end (jaws carry nothing); and
    # more joints than a finger's most below them (a gripper's own lift, tilt and wrist under
    # its two jaws are the gripper's).
    longest = max(shortest, tree.profile.limb("finger_max_joints"))
    return carriers if fans == carriers[-1:] and len(carriers) > longest else []


def limbs_named_for_a_hand(tree: JointTree, grippers: list[str]) -> list[str]:
    """The gripper-named joints that are an arm named for the hand it ends in: a chain whose
    first joint, on the body nothing moves, carries a link named as a hand (``Right_hand``; no
    finger's, jaw's or palm's part), below which one unbranched chain of joints named for no
    gripper part goes on, ``arm_min_joints`` in all or more. A hand carries its fingers side by
    side from a palm at an arm's end; one named so at the body, carrying a single chain of
    joints, is the arm a small humanoid's exporter named for its hand (1805). Those, in
    document order."""
    found: list[str] = []
    known: dict[str, str | None] = {}
    named = set(grippers)
    for name in grippers:
        joint = tree.urdf.joint(name)
        if joint is None or not joint.movable or not _HAND.search(joint.child):
            continue
        if _NOT_A_HAND.search(f"{joint.name} {joint.child}"):
            continue
        if moved_by(tree.urdf, joint.parent, known) is not None:
            continue  # at an arm's end, or on a wrist
        chain = [joint, *_one_chain_below(tree, joint)]
        if len(chain) < tree.profile.limb("arm_min_joints") or any(
            "gripper" in tree.parts_of(below.name) | tree.parts_of(below.child)
            for below in chain[1:]
        ):
            continue
        found += [below.name for below in chain if below.name in named]
    return sorted(found, key=tree.order)


def _one_chain_below(tree: JointTree, joint: Joint) -> list[Joint]:
    """The movable joints below ``joint``, one under another, while each link carries one
    (through fixed joints); empty when some link carries two or more (fingers side by side)."""
    chain: list[Joint] = []
    link = joint.child
    while True:
        rigid = (link, *tree.urdf.fixed_below(link))
        below = [j for part in rigid for j in tree.urdf.children(part) if j.movable]
        if not below:
            return chain
        if len(below) > 1:
            return []
        chain.append(below[0])
        link = below[0].child


def _carried(tree: JointTree, joints: list[Joint]) -> Counter[str]:
    """How many of ``joints`` each of them carries (is the nearest movable joint above)."""
    known: dict[str, str | None] = {}
    above = {joint.name: moved_by(tree.urdf, joint.parent, known) for joint in joints}
    return Counter(name for name in above.values() if name is not None and name in above)


def gripper_closure(tree: JointTree, grippers: set[str]) -> set[str]:
    """``grippers`` and every movable joint below one (finger phalanges); one pass."""
    found = set(grippers)
    stack = [(tree.urdf.root, False)]
    while stack:
        link, inside = stack.pop()
        for joint in tree.urdf.children(link):
            below = inside or joint.name in grippers
            if inside and joint.movable:
                found.add(joint.name)
            stack.append((joint.child, below))
    return found


def finger_tips(tree: JointTree, grippers: set[str]) -> list[str]:
    """Gripper joints with no movable gripper joint below: one per finger."""
    above: set[str] = set()
    for name in grippers:
        joint = tree.urdf.joint(name)
        if joint is None or not joint.movable:
            continue
        parent = tree.urdf.parent_joint(joint.parent)
        while parent is not None and parent.name not in above:
            above.add(parent.name)
            parent = tree.urdf.parent_joint(parent.parent)
    tips = [
        name
        for name in grippers
        if name not in above and (joint := tree.urdf.joint(name)) is not None and joint.movable
    ]
    return sorted(tips, key=tree.order)


def finger_groups(
    tree: JointTree,
    limbs: list[Limb],
    *,
    grounded: bool = False,
    flying: bool = False,
    walks_on: frozenset[str | None] = frozenset(),
    grippers: frozenset[str] = frozenset(),
) -> set[str]:
    """Joints of unnamed short chains hanging from one palm (a link, and the links fixed to it:
    a metacarpal each) in threes or more: fingers (also where each ends in a named fingertip,
    and then one joint longer than a finger: :func:`_ends_in_a_fingertip`; and chains of more
    joints no longer than a finger, a flexure finger's: :func:`_finger_sized`, unless their tips
    meet: :func:`_tips_meet`);
    failing that, fingers that spread on joints of their own, chains beside a thumb, and a
    two-finger gripper's two short chains close together (:func:`_two_fingers`).

    A claw or a hand whose fingers carry no names still has them side by side on a palm; arms
    and legs on one link come in ones and twos. On a body that moves on the ground, chains on
    its root link are the base's own (a tracked vehicle's flippers), not fingers; on a body that
    flies, chains on the airframe (the root and the links fixed to it) are its own (a blimp's
    rudders and elevators); nor are chains on the trunk a pair of legs hangs from
    (``walks_on``: the nearest joint above each leg's base that moves, None for the root's
    rigid body): a humanoid's two arms and neck.
    """
    by_base: dict[str, list[Limb]] = {}  # short unnamed chains, by the link they start on
    # By the rigid body the chains start on (a finger may start on a metacarpal link of its own,
    # fixed to the palm): the short unnamed ones, and every arm or other chain, named or not.
    by_palm: dict[str | None, list[Limb]] = {}
    on_palm: dict[str | None, list[Limb]] = {}
    longest = tree.profile.limb("finger_max_joints")
    known: dict[str, str | None] = {}
    sized: set[str | None] = set()  # palms holding a chain taken by its size alone
    for limb in limbs:
        if grounded and limb.base == tree.urdf.root:
            continue
        body = moved_by(tree.urdf, limb.base, known)
        if (walks_on and body in walks_on) or limb.kind not in ("arm", "other"):
            continue
        if flying and body is None:
            continue
        on_palm.setdefault(body, []).append(limb)
        taken = None if limb.named else _finger_like(tree, limb, longest)
        if taken is None:
            continue
        if taken == "size":
            sized.add(body)
        by_base.setdefault(limb.base, []).append(limb)
        by_palm.setdefault(body, []).append(limb)
    found = _on_one_palm(tree, by_palm, sized)
    if found:
        return found | _thumbs_spun_at_the_tip(tree, by_palm, on_palm, found)
    # The bodies a gripper joint starts from: a thumb named so, on a carpal link fixed to the
    # palm.
    palms = frozenset(
        moved_by(tree.urdf, joint.parent, known)
        for name in grippers
        if (joint := tree.urdf.joint(name)) is not None
    )
    return (
        _spread_fingers(tree, by_base)
        or _beside_a_thumb(tree, on_palm, palms)
        or _two_fingers(tree, by_palm, on_palm)
        or _two_fingers_on_an_arm(tree, by_palm, on_palm)
    )


def _on_one_palm(
    tree: JointTree, by_palm: dict[str | None, list[Limb]], sized: set[str | None]
) -> set[str]:
    """The joints of the chains on a palm holding enough of them to be a hand's fingers, the
    tips of a palm's chains taken by their size apart (:func:`_tips_meet`)."""
    return {
        name
        for body, group in by_palm.items()
        if len(group) >= tree.profile.limb("hand_min_fingers")
        and (body not in sized or not _tips_meet(tree, group))
        and _within_a_hand(tree, group)
        for limb in group
        for name in limb.joints
    }


def _within_a_hand(tree: JointTree, group: list[Limb]) -> bool:
    """Chains each no longer than a finger, starting within a hand's breadth of each other
    (:data:`_HAND_BREADTH`): fingers on one palm, not an aircraft's ailerons and tail, nor a
    frame's pendulums two metres apart beside a stage that slides (a hinge or a slide moves
    no finger of its own that far from the others)."""
    if any(_longer_than_a_finger(tree, limb) for limb in group):
        return False
    places = [place for limb in group if (place := _start(tree, limb)) is not None]
    return within(places, _HAND_BREADTH)


def _longer_than_a_finger(tree: JointTree, limb: Limb) -> bool:
    """The chain's last joint is farther from its first than a finger's knuckles reach."""
    return len(limb.joints) > 1 and joint_span(tree, limb) > _FINGER_LENGTH


def _start(tree: JointTree, limb: Limb) -> Vector | None:
    """Where the chain's first joint turns, at rest; None for a joint the file lacks."""
    joint = tree.urdf.joint(limb.joints[0])
    return None if joint is None else tree.poses.place(joint.child)


def _thumbs_spun_at_the_tip(
    tree: JointTree,
    by_palm: dict[str | None, list[Limb]],
    on_palm: dict[str | None, list[Limb]],
    found: set[str],
) -> set[str]:
    """The joints of the unnamed chains no longer than a finger whose last joint turns endless
    (:func:`_spun_at_its_tip`) on a palm whose other chains are a hand's fingers (``found``),
    starting within a hand's breadth of them (:func:`_in_the_hand`): that hand's thumb, its
    tip's joint written endless by a CAD export (a hand carries no wheel on a pivot among its
    fingers)."""
    longest = tree.profile.limb("finger_max_joints")
    thumbs: set[str] = set()
    for body, chains in on_palm.items():
        fingers = [limb for limb in by_palm.get(body, []) if set(limb.joints) <= found]
        if len(fingers) < tree.profile.limb("hand_min_fingers"):
            continue
        starts = [place for limb in fingers if (place := _start(tree, limb)) is not None]
        if not starts:
            continue
        box = _box(starts)
        for limb in chains:
            spun = len(limb.joints) <= longest and _spun_at_its_tip(tree, limb)
            if spun and not limb.named and _in_the_hand(tree, limb, box):
                thumbs.update(limb.joints)
    return thumbs


def _box(places: list[Vector]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The smallest box round ``places`` (its two opposite corners)."""
    return tuple(map(min, zip(*places, strict=True))), tuple(map(max, zip(*places, strict=True)))


def _in_the_hand(
    tree: JointTree, limb: Limb, box: tuple[tuple[float, ...], tuple[float, ...]]
) -> bool:
    """The chain is no longer than a finger and starts where the box round the fingers' starts,
    grown to hold it, still fits in a hand's breadth (its diagonal: every two starts within
    reach, checked once per chain however many fingers the palm holds)."""
    start = _start(tree, limb)
    if start is None or _longer_than_a_finger(tree, limb):
        return False
    low, high = box
    sides = [max(h, c) - min(lo, c) for lo, h, c in zip(low, high, start, strict=True)]
    return all(math.isfinite(side) for side in sides) and math.hypot(*sides) <= _HAND_BREADTH


def _spun_at_its_tip(tree: JointTree, limb: Limb) -> bool:
    """The chain's last joint turns endless at the end of limited ones: a wheel spun on its
    pivot, unless it is a hand's (:func:`_thumbs_spun_at_the_tip`)."""
    types = [joint.type for name in limb.joints if (joint := tree.urdf.joint(name)) is not None]
    return bool(types) and types[-1] == "continuous" and bool(set(types[:-1]) - {"continuous"})


def _finger_like(tree: JointTree, limb: Limb, longest: int) -> str | None:
    """How an unnamed chain is a finger's: ``"joints"`` (no more joints than a finger has, one
    more ending in a named fingertip), ``"size"`` (:func:`_finger_sized`), or ``None``."""
    joints = len(limb.joints)
    if _spun_at_its_tip(tree, limb):
        # A finger bends within limits, or turns endless all through where a CAD export wrote
        # no limits; an endless joint at the end of limited ones spins a wheel on its pivot.
        return None
    if joints <= longest or (
        joints == longest + 1 and (_ends_in_a_fingertip(tree, limb) or _named_by_bones(tree, limb))
    ):
        return "joints"
    return "size" if _finger_sized(tree, limb) else None


def _named_by_bones(tree: JointTree, limb: Limb) -> bool:
    """Every joint of the chain, or the link it moves, names a hand's bone
    (:data:`_FINGER_BONE`: ``left_index_metacarpals_joint``, ``left_proximal``)."""
    return all(_FINGER_BONE.search(words) for words in joint_words(tree, limb))


def _finger_sized(tree: JointTree, limb: Limb) -> bool:
    """``limb`` is no longer than a finger reaches (:data:`_FINGER_REACH`, along its links from
    its first joint to its tip, however it is bent at rest) on more joints than a finger has: a
    soft or flexure finger drawn as a row of short links, its bending split among them; an arm,
    even a small one folded at rest, is longer, a snake's modules longer still. A chain drawn at
    no place says nothing of its size; one that slides (a Stewart platform's strut) or has two
    joints at one point past its first (a universal or ball joint of a linkage written as
    hinges; a finger's base may turn two ways at one point) is no finger by its size."""
    joints = [tree.urdf.joint(name) for name in limb.joints]
    if any(joint is None or joint.type == "prismatic" for joint in joints):
        return False  # a strut slides (a Stewart platform's leg); a flexure finger bends
    places = [tree.poses.place(joint.child) for joint in joints if joint is not None]
    places.append(tree.poses.place(limb.tip))
    steps = [distance(a, b) for a, b in pairwise(places)]
    if any(step <= _SAME for step in steps[1:-1]):
        return False  # joints at one point past the first: a universal or ball joint (a linkage's)
    length = sum(steps)
    return _SAME < length <= _FINGER_REACH


def _tips_meet(tree: JointTree, group: list[Limb]) -> bool:
    """The chains' tips meet (:func:`~solver.identify.limbs.tips_meet`, in space, not across
    the ground: a hand may point any way): one platform's linkage (a small delta's arms), no
    fingers. More than :data:`_MOST_SIZED_FINGERS` chains are not compared pair by pair and count
    as meeting."""
    ends = chain_ends(tree, group)
    if ends is None or len(ends) > _MOST_SIZED_FINGERS:
        return True  # a stranger's thousands of chains are not compared pair by pair
    return tips_meet([start for start, _ in ends], [tip for _, tip in ends], distance)


def _ends_in_a_fingertip(tree: JointTree, limb: Limb) -> bool:
    """``limb`` ends in a fingertip's frame: its last link, or a leaf link fixed below it, named
    as a finger's or thumb's tip (``fingertip_1``, ``thumb_tip``), and no gripper on it. Such a
    chain is a finger even with one joint more than a finger has (a rotation at its base); a
    jaw, a finger's mount or a knuckle on an arm's wrist names no tip."""
    return not limb.gripper and any(
        _FINGERTIP.search(link) and not tree.urdf.children(link)
        for link in (limb.tip, *tree.urdf.fixed_below(limb.tip))
    )


def _two_fingers(
    tree: JointTree,
    by_palm: dict[str | None, list[Limb]],
    on_palm: dict[str | None, list[Limb]],
) -> set[str]:
    """Two unnamed short chains, the body's only chains but its legs and heads, both on its
    root's rigid body (a gripper alone), each reaching no farther than a finger
    (:data:`_FINGER_REACH`, from its first joint to its last link), starting apart but closer
    to each other than half the shorter one's reach: a two-finger gripper whose fingers bend
    on joints of their own. A
    torso's two arms start a shoulder's width apart and reach farther, or start at one place
    (the chest's middle, the shoulder's offset on their second joint); chains on a moving body
    are a head's or a tool's; chains drawn at no place (every joint at its parent's origin) say
    nothing of their size."""
    group = by_palm.get(None, [])
    if len(group) != 2 or sum(len(chains) for chains in on_palm.values()) != 2:
        return set()
    ends = chain_ends(tree, group)
    if ends is None:
        return set()
    reaches = [distance(start, end) for start, end in ends]
    apart = distance(ends[0][0], ends[1][0])
    if min(reaches) <= _SAME or max(reaches) > _FINGER_REACH:
        return set()
    if not _SAME < apart <= min(reaches) / 2:
        return set()
    return {name for limb in group for name in limb.joints}


def _two_fingers_on_an_arm(
    tree: JointTree,
    by_palm: dict[str | None, list[Limb]],
    on_palm: dict[str | None, list[Limb]],
) -> set[str]:
    """Two unnamed short chains, the only chains on a body that ends an arm (:func:`_arm_end`),
    each reaching no farther than a finger (:data:`_FINGER_REACH`, from its first joint to its
    last link, or to that link's mass centre: a jaw of one joint reaches as far as its mass
    sits) and starting apart within that reach: a two-finger gripper whose fingers bend on
    joints of their own, at an arm's wrist. A torso's two arms reach farther, a head's two
    eyes turn about one point each (they reach nowhere)."""
    found: set[str] = set()
    known: dict[str, str | None] = {}
    # How many movable joints each body (by the joint that moves it) carries.
    carrying = Counter(
        moved_by(tree.urdf, joint.parent, known) for joint in tree.urdf.joints if joint.movable
    )
    for palm, group in by_palm.items():
        if palm is None or len(group) != 2 or len(on_palm.get(palm, [])) != 2:
            continue
        ends = chain_ends(tree, group)
        if ends is None or not _arm_end(tree, palm, known, carrying):
            continue
        reaches = [
            max(distance(start, end), distance(start, tree.poses.mass_centre(limb.tip) or end))
            for (start, end), limb in zip(ends, group, strict=True)
        ]
        apart = distance(ends[0][0], ends[1][0])
        if (
            min(reaches) > _SAME
            and max(reaches) <= _FINGER_REACH
            and _SAME < apart <= _FINGER_REACH
        ):
            found.update(name for limb in group for name in limb.joints)
    return found


def _arm_end(
    tree: JointTree, palm: str, known: dict[str, str | None], carrying: Counter[str | None]
) -> bool:
    """The body ``palm`` (by the joint that moves it) ends a chain of at least the profile's
    ``arm_min_joints`` movable joints from the root's body, each body on the way carrying
    nothing else that moves (``carrying``: how many movable joints each body carries; an arm's
    links, one after the other). Walks up at most that many joints."""
    joints, body = 0, palm
    while joints < tree.profile.limb("arm_min_joints"):
        joint = tree.urdf.joint(body)
        if joint is None:
            return False
        joints += 1
        above = moved_by(tree.urdf, joint.parent, known)
        if above is None:
            break
        if carrying[above] != 1:
            return False
        body = above
    return joints >= tree.profile.limb("arm_min_joints")


def _palm_of(
    tree: JointTree, spread: Joint, known: dict[str, str | None], carried: Counter[str | None]
) -> str | None:
    """The body a finger's spreading joint hangs from (by the joint that moves it; None: the
    root's), or, when that body is turned by one joint carrying this spread alone (a thumb's
    rotation toward the palm), the body that joint hangs from."""
    body = moved_by(tree.urdf, spread.parent, known)
    rotation = None if body is None else tree.urdf.joint(body)
    if rotation is None or carried[body] != 1:
        return body
    return moved_by(tree.urdf, rotation.parent, known)


def _beside_a_thumb(
    tree: JointTree, by_body: dict[str | None, list[Limb]], palms: frozenset[str | None]
) -> set[str]:
    """Chains on the rigid body a thumb starts from, three or more in all and none longer than a
    finger and its carpometacarpal joint: the palm's fingers, even where a name says otherwise
    (a carpal joint named for the wrist). A thumb is a chain ending in a gripper that, with the
    finger joints below it, is no longer than a finger (an arm ending in a gripper is longer),
    or gripper joints on the body itself (``palms``: a thumb named so); a palm has one (a
    torso's two short arms each ending in a gripper are no thumbs)."""
    longest = tree.profile.limb("finger_max_joints")
    found: set[str] = set()
    for body, group in by_body.items():
        named_thumb = body in palms
        if len(group) < tree.profile.limb("hand_min_fingers") - named_thumb:
            continue
        if any(len(limb.joints) > longest + 1 for limb in group):
            continue  # a chain longer than any finger: an arm beside it, no palm
        thumbs = [
            limb
            for limb in group
            if limb.gripper
            and len(limb.joints) + _movable_below(tree, limb.tip, longest) <= longest
        ]
        if len(thumbs) + named_thumb == 1:  # two short arms ending in grippers: no thumbs
            found.update(name for limb in group for name in limb.joints)
    return found


def _movable_below(tree: JointTree, link: str, most: int) -> int:
    """How many movable joints hang below ``link`` (counted up to ``most`` + 1 only)."""
    count, stack = 0, [link]
    while stack and count <= most:
        for joint in tree.urdf.children(stack.pop()):
            count += joint.movable
            stack.append(joint.child)
    return count


def _spread_fingers(tree: JointTree, by_base: dict[str, list[Limb]]) -> set[str]:
    """Fingers that each spread on a joint of their own (abduction) before they branch: the
    short chains' bases each moved by one joint from one body (the palm), in threes or more,
    no chain counting its spreading joint longer than a finger. The spreading joints are
    fingers' too. A joint that turns all the way round and carries only chains of one joint
    spreads no finger: a wheel-leg's hub with its two rim halves (a hand exported with every
    joint continuous still spreads fingers of two joints or more)."""
    longest = tree.profile.limb("finger_max_joints")
    by_palm: dict[str | None, list[Joint]] = {}
    known: dict[str, str | None] = {}
    # How many movable joints each body (by the joint that moves it) carries.
    alone = Counter(
        moved_by(tree.urdf, joint.parent, known) for joint in tree.urdf.joints if joint.movable
    )
    for base, group in by_base.items():
        spread = tree.urdf.parent_joint(base)
        if (
            spread is None
            or not spread.movable
            or (spread.turns(_FULL_TURN) and all(len(limb.joints) == 1 for limb in group))
            or any(len(limb.joints) + 1 > longest for limb in group)
        ):
            continue
        # The palm: what carries the spreading joint's link (a metacarpal fixed to it each),
        # through a thumb's rotation that carries this spread alone.
        by_palm.setdefault(_palm_of(tree, spread, known, alone), []).append(spread)
    found: set[str] = set()
    for spreads in by_palm.values():
        if len(spreads) >= tree.profile.limb("hand_min_fingers"):
            found.update(joint.name for joint in spreads)
            for joint in spreads:
                found.update(name for limb in by_base[joint.child] for name in limb.joints)
    return found
