"""What the joints do one at a time: wheels, steering, casters, rotors, thrusters, fins, grippers.

:func:`joint_roles` gives each moving joint that plays a single-joint role that role, with the
evidence that decided it, actuation first and names last:

1. what :class:`~solver.identify.roles.RoleReader` reads of the joint: a plugin that names it,
   then its shape, then its name. Joints that cannot move (fixed, or revolute/prismatic with
   lower == upper) play none;
2. wheels without names, told by where they are: endless leaves hanging below a link, at least
   one on each side of it;
3. casters, a vertical swivel carrying one wheel; a caster driven through a transmission is no
   caster (its swivel steers, its wheel drives);
4. rotors too few to fly are dropped (one spinning leaf is a motor or a tool);
5. every movable joint below a gripper joint moves a finger.

Not here: the roles of the chains the other joints form (:mod:`solver.identify.limbs`).
"""

from __future__ import annotations

from collections.abc import Mapping

from solver.identify.hands import gripper_closure
from solver.identify.readers.urdf import Joint
from solver.identify.roles import Role, main_axis
from solver.identify.tree import JointTree

__all__ = ["joint_roles", "with_role"]

_Z_AXIS = 2


def joint_roles(tree: JointTree) -> dict[str, Role]:
    """Wheels, casters, rotors, thrusters, fins and gripper joints, each with its evidence."""
    urdf = tree.urdf
    roles: dict[str, Role] = {}
    for joint in urdf.joints:
        role = tree.reader.read(joint, tree.moving_below)
        if role is not None:
            roles[joint.name] = role
    for name in _unnamed_wheels(tree, set(roles)):
        roles[name] = Role(
            name, "wheel", "an unnamed endless leaf below its link, wheels on both sides"
        )
    roles.update(tree.reader.casters({n: r for n, r in roles.items() if r.role == "wheel"}))
    for name, role in list(roles.items()):
        driven = urdf.joint(name)
        if role.role == "caster" and driven is not None and name in urdf.controlled_joints:
            # A driven caster is no caster: its swivel steers, its wheels drive.
            if main_axis(driven.axis) == _Z_AXIS:
                roles[name] = Role(name, "steering", "a vertical swivel with a transmission")
            else:
                roles[name] = Role(name, "wheel", "a caster's wheel with a transmission")
    rotors = [n for n, r in roles.items() if r.role == "rotor"]
    if rotors and len(rotors) < tree.profile.limb("min_rotors"):
        for name in rotors:  # one spinning leaf is a motor or a tool, not flight
            del roles[name]
    grippers = gripper_closure(tree, {n for n, r in roles.items() if r.role == "gripper"})
    for name in grippers - set(roles):
        roles[name] = Role(name, "gripper", "moves a finger: below a gripper joint")
    return roles


def with_role(roles: Mapping[str, Role], role: str) -> list[str]:
    """The joints of ``roles`` that play ``role``, in the order they were found."""
    return [name for name, r in roles.items() if r.role == role]


def _unnamed_wheels(tree: JointTree, taken: set[str]) -> list[str]:
    """Unnamed spinning leaves below a link, on both its sides: wheels.

    A base whose wheel joints carry no name (``fl_joint`` on ``fl_Link``) still has them where
    wheels are: continuous joints (no limits, they turn for ever) that carry nothing that
    moves, hanging below the link they are on, at least one on each side of it. Fingers have
    limits; rotors sit level with or above their body.
    """
    below: dict[str, list[Joint]] = {}
    for joint in tree.urdf.joints:
        if (
            joint.type == "continuous"
            and joint.actuated
            and joint.name not in taken
            and joint.child not in tree.moving_below
            and not (tree.parts_of(joint.name) | tree.parts_of(joint.child))
            and joint.origin[2] < 0
        ):
            below.setdefault(joint.parent, []).append(joint)
    found: list[str] = []
    for joints in below.values():
        sides = {j.origin[1] > 0 for j in joints if j.origin[1] != 0}
        if len(joints) >= 2 and sides == {True, False}:
            found.extend(j.name for j in joints)
    return found
