"""What an SRDF plans, read against the body the URDF shows: its arms and its hands.

MoveIt configurations plan more than arms: legs (a quadruped's ``lf_leg``), a torso lift, the
whole body, pairs of limbs, a gripper's jaws. :func:`arm_plans` keeps the planning groups that
move an arm: not only over a gripper's joints, of as many joints as an arm needs (a chain to a
spinning lidar's motor is none), its joints that move the body along (wheels, casters,
steering, rotors, thrusters, fins) aside, not mostly on the legs, on a head (a pan/tilt
pointing a sensor) or on the trunk, over fewer than three limbs, and not extending another
such group (Fetch's ``arm_with_torso``; chains are expanded to their joints through the URDF,
so a chain group from the torso to a hand extends the hand's arm). :func:`hand_effectors`
keeps the end effectors that are not feet (a leg's end effector is where it stands);
:func:`leg_plans` the groups each on a leg (a walker's MoveIt configuration plans its legs).

Not here: reading the SRDF (:mod:`solver.identify.readers.srdf`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from solver.identify.body import Body
from solver.identify.limbs import moved_by
from solver.identify.readers.urdf import Urdf

if TYPE_CHECKING:
    from solver.identify.readers.srdf import EndEffector, Group, Srdf

__all__ = ["MOST_GROUPS", "arm_plans", "hand_effectors", "leg_plans"]

# A real SRDF has tens of groups; a stranger's file may have hundreds of thousands. Only this
# many candidate arm groups are compared (each with each), and chains are walked for at most
# _MOST_STEPS joints in all: a hostile SRDF ends in milliseconds, not minutes.
MOST_GROUPS = 256
_MOST_STEPS = 200_000
# The joint roles that move the body along (solver.identify.roles): no arm is planned on them.
_LOCOMOTION = frozenset({"wheel", "steering", "caster", "rotor", "thruster", "fin"})


def arm_plans(
    body: Body, srdf: Srdf, min_joints: int, urdf: Urdf | None = None
) -> tuple[Group, ...]:
    """The SRDF's planning groups that each plan one arm of ``body`` (among its first
    :data:`MOST_GROUPS` candidates); groups with the same joints count once."""
    limb_of = {j: index for index, limb in enumerate(body.limbs) for j in limb.joints}
    fingers = {role.joint for role in body.roles if role.role == "finger"}
    not_arms = _not_arms(body)
    # What moves the body along plans no arm: a group is judged by its other joints (a rover's
    # group of its wheels has none; a whole body's, wheels and arm, is its arm's).
    moving = {role.joint for role in body.roles if role.role in _LOCOMOTION}
    walker = _Chains(urdf)
    by_joints: dict[frozenset[str], Group] = {}
    for group in srdf.arm_groups(min_joints)[:MOST_GROUPS]:
        joints = walker.joints(group) - moving
        if (
            not joints <= fingers  # a gripper's group, however it is named
            # a chain of fewer joints than an arm (a spinning lidar's motor) plans none
            and (urdf is None or len(joints) >= min_joints)
            and not _mostly_on(joints, not_arms)
            and len({limb_of[j] for j in joints if j in limb_of}) < 3
        ):
            by_joints.setdefault(joints, group)
    return tuple(
        group
        for joints, group in by_joints.items()
        if not any(other < joints for other in by_joints)
    )


def _not_arms(body: Body) -> list[set[str]]:
    """The joints a group planning an arm may not lie mostly on: each kind of them. Legs, heads
    (a pan/tilt pointing a sensor), the trunk."""
    limbs = [
        {j for limb in body.limbs if limb.kind == kind for j in limb.joints}
        for kind in ("leg", "head")
    ]
    return [*limbs, set(body.trunk)]


def leg_plans(
    body: Body, srdf: Srdf, min_joints: int, urdf: Urdf | None = None
) -> tuple[Group, ...]:
    """The SRDF's planning groups (among its first :data:`MOST_GROUPS` candidates) of as many
    joints as an arm group, each lying mostly on one of ``body``'s legs: a walker's MoveIt
    configuration plans its legs (their joints take goals)."""
    legs = [set(limb.joints) for limb in body.limbs if limb.kind == "leg"]
    if not legs:
        return ()
    walker = _Chains(urdf)
    found = []
    for group in srdf.arm_groups(min_joints)[:MOST_GROUPS]:
        joints = walker.joints(group)
        # as many joints as an arm group needs: an ankle's chain alone plans no leg
        if (urdf is None or len(joints) >= min_joints) and _mostly_on(joints, legs):
            found.append(group)
    return tuple(found)


def _mostly_on(joints: frozenset[str], parts: list[set[str]]) -> bool:
    """More than half of ``joints`` are joints of one of ``parts``."""
    return any(2 * len(joints & part) > len(joints) for part in parts)


def hand_effectors(body: Body, srdf: Srdf, urdf: Urdf | None = None) -> tuple[EndEffector, ...]:
    """The SRDF's end effectors that are not on a leg (feet)."""
    if urdf is None:
        return srdf.end_effectors
    legs = {j for limb in body.limbs if limb.kind == "leg" for j in limb.joints}
    known: dict[str, str | None] = {}  # link -> the nearest movable joint above it
    return tuple(
        effector
        for effector in srdf.end_effectors
        if moved_by(urdf, effector.parent_link, known) not in legs
    )


class _Chains:
    """The movable joints of groups, their chains walked through the URDF (tip up to base),
    each chain once, within a budget of steps."""

    def __init__(self, urdf: Urdf | None) -> None:
        self.urdf = urdf
        self.steps = _MOST_STEPS
        self.walked: dict[tuple[str, str], frozenset[str]] = {}

    def joints(self, group: Group) -> frozenset[str]:
        found = set(group.joints)
        urdf = self.urdf
        if urdf is None:
            return frozenset(found)
        for chain in group.chains:
            if chain not in self.walked:
                self.walked[chain] = self._walk(urdf, *chain)
            found |= self.walked[chain]
        return frozenset(name for name in found if (j := urdf.joint(name)) is None or j.movable)

    def _walk(self, urdf: Urdf, base: str, tip: str) -> frozenset[str]:
        path = []
        link = tip
        while link != base and self.steps > 0 and (joint := urdf.parent_joint(link)) is not None:
            self.steps -= 1
            path.append(joint.name)
            link = joint.parent
        return frozenset(path)
