"""A robot's joint tree as the body's steps read it, built once per description.

Every step of :func:`~solver.identify.body.detect_body` asks the same few questions of the
tree: where a joint comes in document order (listings are deterministic), which parts the
profile's patterns name in a joint or a link, which model plugins the profile reads as a part,
and which links have a movable joint somewhere below them (a rotor or a wheel is a leaf: none
below), which joints move together (mimic couplings, :mod:`solver.identify.couplings`) and
where each part is at rest (:mod:`solver.identify.pose`). :class:`JointTree` answers them, each
worked out in one pass.

Not here: what the answers mean (:mod:`solver.identify.actuation`, :mod:`~solver.identify.limbs`,
:mod:`~solver.identify.hands`, :mod:`~solver.identify.vehicle`,
:mod:`~solver.identify.placement`), one joint's role (:mod:`solver.identify.roles`).
"""

from __future__ import annotations

from functools import cached_property

from solver.identify.couplings import Couplings, couplings
from solver.identify.pose import Poses
from solver.identify.profile import PartMatcher, Profile
from solver.identify.readers.urdf import Joint, Urdf
from solver.identify.roles import RoleReader

__all__ = ["JointTree"]

# Sensor element types a pan/tilt unit points (cameras of every kind, rays, lidars, sonars).
_POINTED = ("camera", "depth", "ray", "lidar", "sonar", "rgbd", "thermal")


class JointTree:
    """One description with the profile that reads it (see the module docstring)."""

    def __init__(self, urdf: Urdf, profile: Profile) -> None:
        self.urdf = urdf
        self.profile = profile
        # Document order of each joint, for deterministic listings (one pass, not one per ask).
        self.index = {joint.name: i for i, joint in enumerate(urdf.joints)}
        self.parts_of = PartMatcher(profile.patterns)
        self.reader = RoleReader(urdf, profile, self.parts_of)
        # Mimic groups: one actuator each, and the followers that stand in for their drivers.
        self.couplings: Couplings = couplings(urdf)
        # Links with a movable joint somewhere below them (a rotor is a leaf: none below).
        self.moving_below: set[str] = set()
        for joint in urdf.joints:
            if joint.movable:
                link: str | None = joint.parent
                while link is not None and link not in self.moving_below:
                    self.moving_below.add(link)
                    parent = urdf.parent_joint(link)
                    link = None if parent is None else parent.parent

    @cached_property
    def poses(self) -> Poses:
        """Every link's place and every joint's axis at rest, in the root's frame."""
        return Poses(self.urdf)

    @cached_property
    def lowest_frame(self) -> float:
        """The height of the lowest link frame as the body rests (0 with no link): where a
        wheel's bottom reaches, the ground or a footprint frame drawn on it."""
        return min((self.poses.place(link.name)[2] for link in self.urdf.links), default=0.0)

    @cached_property
    def bolted(self) -> frozenset[str]:
        """The links fixed to a root named ``world`` (the root too: a body bolted in place, no
        joint between them moves); none when the root is named otherwise."""
        root = self.urdf.root
        if root.lower() != "world":
            return frozenset()
        return frozenset((root, *self.urdf.fixed_below(root)))

    @cached_property
    def sensor_links(self) -> frozenset[str]:
        """Links that carry a sensor a pan/tilt unit points: cameras, lidars, range finders."""
        return frozenset(
            tag.link
            for tag in self.urdf.sensors
            if tag.link is not None and any(word in tag.type for word in _POINTED)
        )

    def drives(self, joint: Joint) -> bool:
        """The joint moves a chain on its own account (see :mod:`solver.identify.couplings`)."""
        return self.couplings.drives(joint)

    def matches(self, part: str, joint: Joint) -> bool:
        """The profile's pattern for ``part`` names the joint or its child link."""
        return part in self.parts_of(joint.name) or part in self.parts_of(joint.child)

    def tread(self, joint: Joint) -> bool:
        """The joint is named as a track's and does not slide: a tread's sprocket or segment.
        A carriage that slides on a linear track (a rail, a gantry's axis, a table game's
        pusher) moves along it; nothing rolls. On a body whose carriages slide on such a track
        (:attr:`on_a_rail`), a track-named joint that cannot move fixes the rail's frames: no
        tread either."""
        if not self.matches("track", joint) or self._slides(joint):
            return False
        return joint.movable or not self.on_a_rail

    @cached_property
    def on_a_rail(self) -> bool:
        """A track-named joint slides: a carriage on a linear track (a robot's floor rail)."""
        return any(
            self._slides(joint) and self.matches("track", joint) for joint in self.urdf.joints
        )

    @staticmethod
    def _slides(joint: Joint) -> bool:
        return joint.type == "prismatic" and joint.movable

    def labels(self, part: str) -> tuple[str, ...]:
        """The model plugins the profile reads as ``part``, each named once."""
        return tuple(
            dict.fromkeys(self.reader.plugin_label(p) for p in self.reader.plugins_of(part))
        )

    def order(self, name: str) -> int:
        """Where the joint ``name`` comes in the document (0 for a name it lacks)."""
        return self.index.get(name, 0)
