"""Reading a MoveIt SRDF: planning groups, chains, end effectors and virtual joints.

:func:`parse_srdf` reads SRDF text safely (:mod:`solver.identify.safexml`) into a frozen
:class:`Srdf`. Given the robot's :class:`~solver.identify.urdf.Urdf`, every link and joint a
group, chain, end effector or virtual joint names is checked to exist, and every problem is
reported at once with the file, line and element. ``group_state`` and ``disable_collisions``
are not read: they say nothing about what the robot is.

What the groups mean (arm groups -> Joint, end effectors -> End Effector) is decided in
:mod:`solver.identify.motion` and :mod:`solver.identify.structure`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from solver.errors import Fault, InputError, Location
from solver.identify.safexml import line_of, parse_xml

if TYPE_CHECKING:
    from lxml import etree

    from solver.identify.urdf import Urdf

__all__ = ["EndEffector", "Group", "Srdf", "VirtualJoint", "parse_srdf"]

VIRTUAL_JOINT_TYPES = ("fixed", "floating", "planar")


@dataclass(frozen=True, slots=True)
class Group:
    name: str
    joints: tuple[str, ...] = ()
    links: tuple[str, ...] = ()
    chains: tuple[tuple[str, str], ...] = ()
    subgroups: tuple[str, ...] = ()
    line: int | None = None


@dataclass(frozen=True, slots=True)
class EndEffector:
    name: str
    parent_link: str
    group: str
    parent_group: str | None = None
    line: int | None = None


@dataclass(frozen=True, slots=True)
class VirtualJoint:
    name: str
    type: str
    parent_frame: str
    child_link: str
    line: int | None = None


@dataclass(frozen=True)
class Srdf:
    name: str
    file: str
    groups: tuple[Group, ...] = ()
    end_effectors: tuple[EndEffector, ...] = ()
    virtual_joints: tuple[VirtualJoint, ...] = ()

    def group(self, name: str) -> Group | None:
        return next((g for g in self.groups if g.name == name), None)

    @property
    def end_effector_groups(self) -> frozenset[str]:
        return frozenset(e.group for e in self.end_effectors)

    def arm_groups(self, min_joints: int) -> tuple[Group, ...]:
        """Groups that plan a serial arm: a chain, or ``min_joints`` joints, not an end effector.

        A group made of other groups (``arms: [arm_left, arm_right]``) is not counted again.
        """
        found = []
        for group in self.groups:
            if group.subgroups and not group.joints and not group.chains:
                continue
            if group.name in self.end_effector_groups and not group.chains:
                continue
            if group.chains or len(group.joints) >= min_joints:
                found.append(group)
        return tuple(found)


def parse_srdf(text: str | bytes, file: str = "<string>", urdf: Urdf | None = None) -> Srdf:
    """Parse SRDF text; with ``urdf``, check every name it uses against the robot."""
    root = parse_xml(text, file)
    if root.tag != "robot":
        raise InputError.at(file, f"root element is <{root.tag}>, expected <robot> (is this an "
                                  "SRDF?)", line=line_of(root), path=str(root.tag),
                            code="srdf")
    reader = _Reader(file, urdf)
    groups = reader.groups(root)
    effectors = reader.end_effectors(root, {g.name for g in groups})
    virtual = reader.virtual_joints(root)
    if reader.faults:
        raise InputError(reader.faults)
    return Srdf((root.get("name") or "").strip(), file, groups, effectors, virtual)


def _name(element: etree._Element, attribute: str = "name") -> str:
    return (element.get(attribute) or "").strip()


class _Reader:
    """Collects located faults while reading the SRDF's elements."""

    def __init__(self, file: str, urdf: Urdf | None) -> None:
        self.file = file
        self.urdf = urdf
        self.faults: list[Fault] = []

    def fault(self, line: int | None, path: str, message: str) -> None:
        self.faults.append(Fault(Location(self.file, line, None, path), message, "srdf"))

    def link(self, element: etree._Element, path: str, link: str) -> None:
        if not link:
            self.fault(line_of(element), path, "missing link name")
        elif self.urdf is not None and not self.urdf.has_link(link):
            self.fault(line_of(element), path,
                       f"link {link!r} is not in the URDF ({self.urdf.file})")

    def joint(self, element: etree._Element, path: str, joint: str) -> None:
        if not joint:
            self.fault(line_of(element), path, "missing joint name")
        elif self.urdf is not None and self.urdf.joint(joint) is None:
            self.fault(line_of(element), path,
                       f"joint {joint!r} is not in the URDF ({self.urdf.file})")

    def groups(self, root: etree._Element) -> tuple[Group, ...]:
        groups = []
        for element in root.findall("group"):
            name = _name(element)
            path = f"group[{name}]"
            if not name:
                self.fault(line_of(element), "group", "a <group> without a name")
            for item in element.findall("joint"):
                self.joint(item, f"{path}.joint", _name(item))
            for item in element.findall("link"):
                self.link(item, f"{path}.link", _name(item))
            chains = []
            for chain in element.findall("chain"):
                base, tip = _name(chain, "base_link"), _name(chain, "tip_link")
                self.link(chain, f"{path}.chain.base_link", base)
                self.link(chain, f"{path}.chain.tip_link", tip)
                chains.append((base, tip))
            groups.append(Group(name, tuple(_name(j) for j in element.findall("joint")),
                                tuple(_name(k) for k in element.findall("link")),
                                tuple(chains),
                                tuple(_name(g) for g in element.findall("group")),
                                line_of(element)))
        names = {g.name for g in groups}
        for group in groups:
            for sub in group.subgroups:
                if sub not in names:
                    self.fault(group.line, f"group[{group.name}]",
                               f"subgroup {sub!r} is not defined")
        return tuple(groups)

    def end_effectors(self, root: etree._Element, groups: set[str]
                      ) -> tuple[EndEffector, ...]:
        found = []
        for element in root.findall("end_effector"):
            name, group = _name(element), _name(element, "group")
            path = f"end_effector[{name}]"
            self.link(element, f"{path}.parent_link", _name(element, "parent_link"))
            if group not in groups:
                self.fault(line_of(element), f"{path}.group",
                           f"end effector {name!r} names group {group!r}, which is not "
                           "defined")
            found.append(EndEffector(name, _name(element, "parent_link"), group,
                                     element.get("parent_group"), line_of(element)))
        return tuple(found)

    def virtual_joints(self, root: etree._Element) -> tuple[VirtualJoint, ...]:
        found = []
        for element in root.findall("virtual_joint"):
            name, kind = _name(element), _name(element, "type")
            path = f"virtual_joint[{name}]"
            if kind not in VIRTUAL_JOINT_TYPES:
                self.fault(line_of(element), f"{path}.type",
                           f"unknown virtual joint type {kind!r}; SRDF virtual joints are "
                           f"{', '.join(VIRTUAL_JOINT_TYPES)}")
            self.link(element, f"{path}.child_link", _name(element, "child_link"))
            found.append(VirtualJoint(name, kind, _name(element, "parent_frame"),
                                      _name(element, "child_link"), line_of(element)))
        return tuple(found)
