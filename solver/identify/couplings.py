"""Joints that move together: mimic couplings, folded into the actuator that drives them.

A mimic joint follows another (URDF ``<mimic joint=...>``): a gear's driven wheel, a linkage's
passive bar, a gripper's second jaw. A driver and all its followers (followers of followers
included) are one motion, driven by one actuator; :func:`couplings` finds the groups and where
each motion acts in the body:

* A driver whose own subtree holds nothing else that moves (a drive gear drawn beside the
  joint it turns, a crank beside the knee it works) acts where a follower outside that
  subtree is, when that follower carries the body on (an arm drawn as gear pairs) or sits in
  another chain (a leg's parallel linkage): the follower *stands in* for the driver in the joint
  tree the limbs are read from, so the arm reads as one chain and the linkage as the leg's
  knee, not as extra limbs.
* A driver whose followers sit side by side with it on one link, turning about one line, with
  nothing beyond them, closes jaws: a gripper of one motion (:func:`jaw_groups`).

Every walk here is linear in the joints and bounded (mimic chains are followed with a visited
set: a mimic loop or a mimic naming a joint that does not exist is read as no coupling).

Not here: what a gripper or a limb is (:mod:`solver.identify.actuation`,
:mod:`solver.identify.limbs`).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field

from solver.identify.pose import local_axis, parallel
from solver.identify.readers.urdf import Joint, Urdf

__all__ = ["Couplings", "Walk", "couplings", "jaw_groups"]

# Jaws side by side come in twos (a parallel gripper), threes (a three-jaw chuck) or fours (two
# jaws of a parallel linkage, an inner and an outer knuckle each).
_MOST_JAWS = 4
# Mimic ratios closer than this are one ratio; a ratio this small moves nothing.
_NO_RATIO = 1e-6
# How far up a follower is looked at for the chain it sits in (a knee is a joint or two below
# the hip its crank turns beside): bounds the walk on a hostile description.
_MOST_STEPS_UP = 16
# The steps every walk below the couplings' joints may take in all, for one description.
_MOST_STEPS = 200_000


@dataclass(frozen=True)
class Couplings:
    """The mimic groups of one description: who follows whom, and who stands in for whom."""

    followers: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    driver_of: Mapping[str, str] = field(default_factory=dict)
    # driver -> the follower that acts for it in the joint tree.
    stand_ins: Mapping[str, str] = field(default_factory=dict)

    def drives(self, joint: Joint) -> bool:
        """The joint moves a chain on its own account: actuated and not stood in for, or a
        follower standing in for its driver."""
        if joint.name in self.stand_ins:
            return False
        return joint.actuated or joint.name in self._standing

    @functools.cached_property
    def _standing(self) -> frozenset[str]:
        return frozenset(self.stand_ins.values())

    def driver(self, name: str) -> str:
        """The joint whose actuator moves ``name`` (itself when it follows nobody)."""
        return self.driver_of.get(name, name)


def couplings(urdf: Urdf) -> Couplings:
    """The mimic groups of ``urdf`` and their stand-ins (see the module docstring)."""
    driver_of = _drivers(urdf)
    followers: dict[str, list[str]] = {}
    for follower, driver in driver_of.items():
        followers.setdefault(driver, []).append(follower)
    groups = {driver: tuple(names) for driver, names in followers.items()}
    walk = Walk(urdf)
    stand_ins: dict[str, str] = {}
    for driver, names in groups.items():
        stand_in = _stand_in(urdf, driver, names, walk, driver_of)
        if stand_in is not None:
            stand_ins[driver] = stand_in
    return Couplings(groups, driver_of, stand_ins)


def _drivers(urdf: Urdf) -> dict[str, str]:
    """Each mimic joint's driver: the actuated joint at the end of its mimic chain. A chain
    that loops, or ends at a joint missing or unable to move, is no coupling. Each joint is
    resolved once (a chain of a thousand mimics costs a thousand steps, not a million)."""
    resolved: dict[str, str | None] = {}
    for joint in urdf.joints:
        path: list[str] = []
        on_path: set[str] = set()
        current: Joint | None = joint
        answer: str | None = None
        while current is not None:
            if current.name in resolved:
                answer = resolved[current.name]
                break
            if current.name in on_path:  # a loop
                break
            if current.mimic is None:
                answer = current.name if current.actuated else None
                break
            path.append(current.name)
            on_path.add(current.name)
            current = urdf.joint(current.mimic)
        for name in path:
            resolved[name] = answer
        if joint.mimic is None:
            resolved.setdefault(joint.name, joint.name if joint.actuated else None)
    return {
        joint.name: driver
        for joint in urdf.joints
        if joint.mimic is not None
        and joint.movable
        and (driver := resolved.get(joint.name)) is not None
        and driver != joint.name
    }


class Walk:
    """Whether something moves below a joint beyond a group, within one budget of steps for
    the whole description (past it, a joint is taken to carry the body on: a stranger's
    thousand followers of long chains cost a bounded walk)."""

    def __init__(self, urdf: Urdf) -> None:
        self.urdf = urdf
        self.steps = _MOST_STEPS

    def moves_beyond(self, name: str, group: set[str]) -> bool:
        joint = self.urdf.joint(name)
        if joint is None:
            return False
        stack = list(self.urdf.children(joint.child))
        while stack:
            self.steps -= 1
            if self.steps < 0:
                return True
            below = stack.pop()
            if below.movable and below.name not in group:
                return True
            stack.extend(self.urdf.children(below.child))
        return False

    def below(self, name: str, names: tuple[str, ...]) -> set[str]:
        """The joints of ``names`` in the subtree of ``name``."""
        wanted = set(names)
        found: set[str] = set()
        joint = self.urdf.joint(name)
        if joint is None:
            return found
        stack = list(self.urdf.children(joint.child))
        while stack and self.steps > 0:
            self.steps -= 1
            below = stack.pop()
            if below.name in wanted:
                found.add(below.name)
            stack.extend(self.urdf.children(below.child))
        return found


def _stand_in(
    urdf: Urdf,
    driver: str,
    names: tuple[str, ...],
    walk: Walk,
    driver_of: Mapping[str, str],
) -> str | None:
    """The follower that acts for ``driver`` in the tree, or None (see the module docstring)."""
    joint = urdf.joint(driver)
    if joint is None:
        return None
    group = {driver, *names}
    if walk.moves_beyond(driver, group):
        return None  # the driver carries the body on itself: it acts where it is
    own = walk.below(driver, names)
    outside = [name for name in names if name not in own]
    others = group | set(driver_of)
    for name in outside:
        if walk.moves_beyond(name, others):
            return name  # a driven joint that carries the rest (a gear pair)
    for name in outside:
        if _in_another_chain(urdf, name, joint.parent, group):
            return name  # a follower in another chain (a linkage's knee)
    return None


def _in_another_chain(urdf: Urdf, name: str, stop: str, group: set[str]) -> bool:
    """Between the follower ``name`` and the link ``stop`` (the driver's parent) some actuated
    joint outside the group moves it: it sits in another chain. A few steps up at most."""
    follower = urdf.joint(name)
    joint = None if follower is None else urdf.parent_joint(follower.parent)
    for _ in range(_MOST_STEPS_UP):
        if joint is None or joint.child == stop:
            return False
        if joint.actuated and joint.name not in group:
            return True
        joint = urdf.parent_joint(joint.parent)
    return False


def jaw_groups(urdf: Urdf, found: Couplings) -> list[tuple[str, ...]]:
    """Joints of one motion that close side by side: on one link, turning or sliding about one
    line, nothing beyond them but their own followers; two or three of them (jaws)."""
    walk = Walk(urdf)
    groups = []
    for driver, names in found.followers.items():
        members = [j for j in (urdf.joint(n) for n in (driver, *names)) if j is not None]
        group = {j.name for j in members}
        by_parent: dict[str, list[Joint]] = {}
        for joint in members:
            if not walk.moves_beyond(joint.name, group):
                by_parent.setdefault(joint.parent, []).append(joint)
        for on_one_link in by_parent.values():
            # The jaws: every joint of the motion on the link, or its followers there alone (a
            # lever between them, the driver, works them at a ratio of its own).
            followers = [j for j in on_one_link if j.name != driver]
            lever = len(followers) < len(on_one_link)  # the driver is on the link
            if (2 <= len(on_one_link) <= _MOST_JAWS and _alike(on_one_link, 1.0)) or (
                lever
                and 2 <= len(followers) <= _MOST_JAWS
                and _alike(followers, abs(followers[0].multiplier))
                and _mirrored(followers)
            ):
                groups.append(tuple(sorted(group)))
                break
    return groups


def _mirrored(jaws: list[Joint]) -> bool:
    """Two of the jaws move opposite ways (they close on each other), not one way (gears,
    wheels a motor turns)."""
    moves = [tuple(jaw.multiplier * a for a in local_axis(jaw)) for jaw in jaws]
    return any(
        sum(a * b for a, b in zip(one, other, strict=True)) < 0
        for at, one in enumerate(moves)
        for other in moves[at + 1 :]
    )


def _alike(jaws: list[Joint], ratio: float) -> bool:
    """Jaws of one kind, each with limits, turning or sliding about parallel axes, each as far
    as the other: each at ``ratio`` (but for its sign) to the motion, and that ratio not none
    (a jaw mirrors the other at 1 or -1; jaws a lever between them works follow it at one
    ratio; a gear pair turns by its ratio)."""
    first = jaws[0]
    return ratio > _NO_RATIO and all(
        jaw.type == first.type
        and jaw.type in ("revolute", "prismatic")
        and abs(abs(jaw.multiplier) - ratio) < _NO_RATIO
        and parallel(local_axis(jaw), local_axis(first))
        for jaw in jaws
    )
