"""Hands and grippers: the joints that move fingers, found by name and by place.

A gripper joint (named so by the profile, or on a link named as a hand or palm:
:mod:`solver.identify.roles`) moves a finger, and so does every movable joint below one (a
finger's phalanges): :func:`gripper_closure`. Fingers whose chains carry no names are still
told by where they are, side by side on one link in threes or more (:func:`finger_groups`).
A hand is counted by its fingers, one tip per finger (:func:`finger_tips`).

Not here: the limb a hand ends (:mod:`solver.identify.limbs`), the other single-joint roles
(:mod:`solver.identify.actuation`).
"""

from __future__ import annotations

from solver.identify.limbs import Limb
from solver.identify.tree import JointTree

__all__ = ["finger_groups", "finger_tips", "gripper_closure"]


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


def finger_groups(tree: JointTree, limbs: list[Limb], *, grounded: bool = False) -> set[str]:
    """Joints of unnamed short chains hanging from one link in threes or more: fingers (also
    where each ends in a named fingertip).

    A claw or a hand whose fingers carry no names still has them side by side on a palm; arms
    and legs on one link come in ones and twos. On a body that moves on the ground, chains on
    its root link are the base's own (a tracked vehicle's flippers), not fingers.
    """
    by_base: dict[str, list[Limb]] = {}
    longest = tree.profile.limb("finger_max_joints")
    for limb in limbs:
        if grounded and limb.base == tree.urdf.root:
            continue
        if limb.kind in ("arm", "other") and not limb.named and len(limb.joints) <= longest:
            by_base.setdefault(limb.base, []).append(limb)
    found: set[str] = set()
    for group in by_base.values():
        if len(group) >= tree.profile.limb("hand_min_fingers"):
            found.update(name for limb in group for name in limb.joints)
    return found
