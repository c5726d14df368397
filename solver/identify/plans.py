"""What an SRDF plans, read against the body the URDF shows: its arms and its hands.

MoveIt configurations plan more than arms: legs (a quadruped's ``lf_leg``), a torso lift, the
whole body, pairs of limbs. :func:`arm_plans` keeps the planning groups that move an arm: not
mostly on the legs or on the trunk, over fewer than three limbs, and not extending another
such group (Fetch's ``arm_with_torso``; chains are expanded to their joints through the URDF,
so a chain group from the torso to a hand extends the hand's arm). :func:`hand_effectors`
keeps the end effectors that are not feet (a leg's end effector is where it stands).

Not here: reading the SRDF (:mod:`solver.identify.srdf`).
"""

from __future__ import annotations

from solver.identify.body import Body
from solver.identify.srdf import EndEffector, Group, Srdf
from solver.identify.urdf import Urdf

__all__ = ["arm_plans", "hand_effectors"]


def arm_plans(
    body: Body, srdf: Srdf, min_joints: int, urdf: Urdf | None = None
) -> tuple[Group, ...]:
    """The SRDF's planning groups that each plan one arm of ``body``."""
    legs = {j for limb in body.limbs if limb.kind == "leg" for j in limb.joints}
    trunk = set(body.trunk)
    limb_of = {j: index for index, limb in enumerate(body.limbs) for j in limb.joints}
    joints = {g.name: _group_joints(g, urdf) for g in srdf.groups}
    groups = [
        g
        for g in srdf.arm_groups(min_joints)
        if 2 * len(joints[g.name] & legs) <= len(joints[g.name])
        and 2 * len(joints[g.name] & trunk) <= len(joints[g.name])
        and len({limb_of[j] for j in joints[g.name] if j in limb_of}) < 3
    ]
    return tuple(
        g
        for g in groups
        if not any(other is not g and joints[other.name] < joints[g.name] for other in groups)
    )


def hand_effectors(body: Body, srdf: Srdf, urdf: Urdf | None = None) -> tuple[EndEffector, ...]:
    """The SRDF's end effectors that are not on a leg (feet)."""
    if urdf is None:
        return srdf.end_effectors
    legs = {j for limb in body.limbs if limb.kind == "leg" for j in limb.joints}
    return tuple(e for e in srdf.end_effectors if _moved_by(urdf, e.parent_link) not in legs)


def _moved_by(urdf: Urdf, link: str) -> str | None:
    """The nearest movable joint above ``link`` (None at the root)."""
    joint = urdf.parent_joint(link)
    while joint is not None and not joint.movable:
        joint = urdf.parent_joint(joint.parent)
    return None if joint is None else joint.name


def _group_joints(group: Group, urdf: Urdf | None) -> frozenset[str]:
    """The joints a group names, with those along its chains (tip up to base), the movable
    ones only, where the URDF is known."""
    found = set(group.joints)
    if urdf is None:
        return frozenset(found)
    for base, tip in group.chains:
        link = tip
        while link != base and (joint := urdf.parent_joint(link)) is not None:
            found.add(joint.name)
            link = joint.parent
    return frozenset(name for name in found if (j := urdf.joint(name)) is None or j.movable)
