"""Limbs: the chains the actuated joints form once the single-joint roles are taken out.

The actuated joints that play no single-joint role (:mod:`solver.identify.actuation`) form a
contracted tree (fixed joints squeezed out). Maximal unbranched paths in it are *chains*: a
chain that ends in a leaf is a *limb*, one that ends where the tree branches is *trunk* (a
waist, a torso lift). :func:`find_limbs` finds them.

Each limb is a *leg*, *head* or *arm* by which pattern most of its joints and links match,
within the profile's thresholds; an unnamed chain of at least ``arm_min_joints`` joints, or one
ending in a gripper, is an arm; on a flying body any chain of two joints or more is. A limb
carrying wheels, rotors or thrusters (Pepper's hip/knee over its wheeled base, a tilt-rotor
unit, a boat's steered engine) is a *mount*, not a limb, except legs that each end in a wheel,
three or more of them (a wheel-legged robot walks on them). Anything else (a flipper, a 2-joint
pan unit without a name) is *other*. Where names say nothing, two equal long chains on a
humanoid's pelvis below named arms are its legs (:func:`legs_at_the_pelvis`).

Not here: fingers and hands (:mod:`solver.identify.hands`), the body they make
(:mod:`solver.identify.body`).
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, replace

from solver.identify.readers.urdf import Joint
from solver.identify.roles import Role
from solver.identify.tree import JointTree
from solver.untrusted import shown

__all__ = ["LIMB_KINDS", "Limb", "find_limbs", "legs_at_the_pelvis", "sort_limbs"]

# A spherical (ball) joint is outside the URDF spec but real files have it: a shoulder, a hip.
_LIMB_JOINTS = ("revolute", "continuous", "prismatic", "spherical")
LIMB_KINDS = ("leg", "arm", "head")
# An unnamed pair of chains on the root this long, beside named arms higher up, are legs.
_LEG_BY_PLACE_JOINTS = 5
# Legs that each end in a wheel are legs (a wheel-legged robot) when there are this many.
_WHEEL_LEGS = 3
# On a flying body, a chain this long hanging from it is an arm (an aerial manipulator's arm).
_FLYING_ARM_JOINTS = 2
# Roles a single joint plays that make it part of the base, not of a limb.
_MOUNTED = ("wheel", "steering", "caster", "rotor", "thruster")


@dataclass(frozen=True, slots=True)
class Limb:
    """A terminal chain of actuated joints, proximal to distal."""

    kind: str  # leg, arm, head, mount, other
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
        if branches:
            trunk.extend(j.name for j in chain)
            starts.extend(branches)
            continue
        marks = set().union(*(carries.get(j.name, set()) for j in chain))
        limbs.append(_classify(tree, chain, chain[0].parent, marks, flying))
    wheel_legs = sum(1 for limb in limbs if limb.kind == "wheel_leg")
    limbs = [
        replace(limb, kind="leg" if wheel_legs >= _WHEEL_LEGS else "mount")
        if limb.kind == "wheel_leg"
        else limb
        for limb in limbs
    ]
    return sort_limbs(tree, limbs), trunk, hosts


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
            elif joint.actuated and joint.type in _LIMB_JOINTS:
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
    named_parts = [tree.parts_of(j.name) | tree.parts_of(j.child) for j in chain]
    scores = {kind: sum(1 for parts in named_parts if kind in parts) for kind in LIMB_KINDS}
    if _tip_matches(tree, "leg", chain[-1]):
        scores["leg"] += 1
    named = any(scores.values())
    # Degrees of freedom, not joints: a ball-joint shoulder moves like three hinges.
    length = sum(3 if j.type == "spherical" else 1 for j in chain)
    kind, why = _named_kind(tree, scores, length, gripper)
    if mounted:
        if mounted == ["wheel"] and kind == "leg":
            return Limb("wheel_leg", names, base, tip, gripper, named, f"{why}, on a wheel")
        return Limb("mount", names, base, tip, gripper, named, f"carries {', '.join(mounted)}")
    if kind is not None:
        return Limb(kind, names, base, tip, gripper, named, why)
    if length >= tree.profile.limb("arm_min_joints") or (gripper and length >= 2):
        why = "ends in a gripper" if gripper else f"an unnamed chain of {length} joints"
        return Limb("arm", names, base, tip, gripper, named, why)
    if flying and length >= _FLYING_ARM_JOINTS and not named:
        why = f"a chain of {length} joints hanging from a flying body"
        return Limb("arm", names, base, tip, gripper, named, why)
    return Limb("other", names, base, tip, gripper, named, "no name or shape of a limb")


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
        if kind == "arm" and (length >= tree.profile.limb("arm_min_joints") or gripper):
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


def _tip_matches(tree: JointTree, part: str, joint: Joint) -> bool:
    """A link held by a fixed joint somewhere below ``joint`` is named as ``part`` (a foot)."""
    return any(
        not below.movable and part in tree.parts_of(below.child)
        for below in tree.urdf.subtree_joints(joint.child)
    )
