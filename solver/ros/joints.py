"""A joint a joint command names, with the position a sample command sends it to.

Identification finds these joints in a robot's description (:mod:`solver.identify.joints`); a
layout's Publish panel names them in its sample ``trajectory_msgs/JointTrajectory``
(:mod:`solver.layouts.samples`). Neither needs the other, so the type they hand over lives here,
with the rest of the ROS vocabulary.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["JointStart"]


@dataclass(frozen=True, slots=True)
class JointStart:
    """A joint a joint command names, and the position a sample command sends it to."""

    name: str
    position: float
