"""The joints a joint command names, read from a robot's description.

A ``trajectory_msgs/JointTrajectory`` that a layout's Publish panel sends must name the robot's
own joints (a controller rejects a trajectory of joints it does not drive). They are the
actuated joints of the robot's limbs (arms, legs, head, as :mod:`solver.identify.limbs` finds
them; not its wheels), proximal to distal, limb after limb; a mimic joint follows another
and is left out (where one stands in for its driver in a limb, the driver is named). Each
starts at 0, or at the limit nearest 0 when 0 lies outside its limits.

Not here: the message around them (:mod:`solver.layouts.samples`).
"""

from __future__ import annotations

from solver.identify.body import Body
from solver.identify.readers.urdf import Urdf
from solver.ros.joints import JointStart

__all__ = ["command_joints"]


def command_joints(urdf: Urdf, body: Body | None) -> tuple[JointStart, ...]:
    """The limbs' actuated joints of ``urdf``, each with a start position within its limits."""
    if body is None:
        return ()
    starts: dict[str, JointStart] = {}
    for limb in body.limbs:
        for name in limb.joints:
            joint = urdf.joint(name)
            if joint is not None and joint.mimic is not None:
                # A follower standing in for its driver (a gear pair): the driver is commanded.
                joint = urdf.joint(joint.mimic)
            if joint is None or not joint.actuated or joint.name in starts:
                continue
            position = 0.0
            if joint.lower is not None and position < joint.lower:
                position = joint.lower
            if joint.upper is not None and position > joint.upper:
                position = joint.upper
            starts[joint.name] = JointStart(joint.name, position)
    return tuple(starts.values())
