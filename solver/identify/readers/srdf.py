"""Reading a MoveIt SRDF: planning groups, chains, end effectors and virtual joints.

:func:`parse_srdf` reads SRDF text safely (:mod:`solver.identify.readers.safexml`) into a frozen
:class:`Srdf`. Given the robot's :class:`~solver.identify.readers.urdf.Urdf`, every link and joint a
group, chain, end effector or virtual joint names is checked to exist, and every problem is
reported at once with the file, line and element. ``group_state`` and ``disable_collisions``
are not read: they say nothing about what the robot is.

What the groups mean (arm groups -> Joint, end effectors -> End Effector) is decided in
:mod:`solver.identify.motion` and :mod:`solver.identify.classifier`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from solver.errors import Fault, InputError, Location
from solver.identify.readers.safexml import line_of, parse_xml
from solver.untrusted import shown

if TYPE_CHECKING:
    from lxml import etree

    from solver.identify.readers.urdf import Urdf

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
    # Items dropped because the URDF lacks them, and other flaws read past (strict=False).
    warnings: tuple[Fault, ...] = ()

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


def parse_srdf(
    text: str | bytes, file: str = "<string>", urdf: Urdf | None = None, *, strict: bool = True
) -> Srdf:
    """Parse SRDF text; with ``urdf``, check every name it uses against the robot.

    ``strict`` (the default): every problem is an error, all reported at once. With
    ``strict=False`` the SRDF is supporting evidence, read as srdfdom does: a joint, link,
    chain or subgroup the URDF (or the SRDF) lacks is dropped from its group with a located
    warning in :attr:`Srdf.warnings`, and the rest is kept.
    """
    warnings: list[Fault] | None = None if strict else []
    root = parse_xml(text, file, warnings=warnings)
    if root.tag != "robot":
        raise InputError.at(
            file,
            f"root element is <{root.tag}>, expected <robot> (is this an SRDF?)",
            line=line_of(root),
            path=str(root.tag),
            code="srdf",
        )
    reader = _Reader(file, urdf)
    virtual = reader.virtual_joints(root)
    reader.virtual = {v.name for v in virtual}
    groups = reader.groups(root)
    effectors = reader.end_effectors(root, {g.name for g in groups})
    if strict and reader.faults:
        raise InputError(reader.faults)
    return replace(
        Srdf((root.get("name") or "").strip(), file, groups, effectors, virtual),
        warnings=(*(warnings or ()), *reader.faults),
    )


def _name(element: etree._Element, attribute: str = "name") -> str:
    return (element.get(attribute) or "").strip()


class _Reader:
    """Collects located faults while reading the SRDF's elements."""

    def __init__(self, file: str, urdf: Urdf | None) -> None:
        self.file = file
        self.urdf = urdf
        self.faults: list[Fault] = []
        self.virtual: set[str] = set()  # a group may list the SRDF's own virtual joint

    def fault(self, line: int | None, path: str, message: str) -> None:
        self.faults.append(Fault(Location(self.file, line, None, path), message, "srdf"))

    def link(self, element: etree._Element, path: str, link: str) -> bool:
        """Whether ``link`` can be used; a located fault when not."""
        if not link:
            self.fault(line_of(element), path, "missing link name")
            return False
        if self.urdf is not None and not self.urdf.has_link(link):
            self.fault(
                line_of(element),
                path,
                f"link {shown(link, quoted=True)} is not in the URDF ({self.urdf.file})",
            )
            return False
        return True

    def joint(self, element: etree._Element, path: str, joint: str) -> bool:
        """Whether ``joint`` can be used; a located fault when not."""
        if not joint:
            self.fault(line_of(element), path, "missing joint name")
            return False
        if self.urdf is not None and self.urdf.joint(joint) is None and joint not in self.virtual:
            self.fault(
                line_of(element),
                path,
                f"joint {shown(joint, quoted=True)} is not in the URDF ({self.urdf.file})",
            )
            return False
        return True

    def groups(self, root: etree._Element) -> tuple[Group, ...]:
        groups = []
        for element in root.findall("group"):
            name = _name(element)
            path = f"group[{name}]"
            if not name:
                self.fault(line_of(element), "group", "a <group> without a name")
            joints = tuple(
                _name(j)
                for j in element.findall("joint")
                if self.joint(j, f"{path}.joint", _name(j))
            )
            links = tuple(
                _name(k) for k in element.findall("link") if self.link(k, f"{path}.link", _name(k))
            )
            chains = []
            for chain in element.findall("chain"):
                base, tip = _name(chain, "base_link"), _name(chain, "tip_link")
                if self.link(chain, f"{path}.chain.base_link", base) & self.link(
                    chain, f"{path}.chain.tip_link", tip
                ):
                    chains.append((base, tip))
            groups.append(
                Group(
                    name,
                    joints,
                    links,
                    tuple(chains),
                    tuple(_name(g) for g in element.findall("group")),
                    line_of(element),
                )
            )
        names = {g.name for g in groups}
        kept = []
        for group in groups:
            for sub in group.subgroups:
                if sub not in names:
                    self.fault(
                        group.line,
                        f"group[{group.name}]",
                        f"subgroup {shown(sub, quoted=True)} is not defined",
                    )
            kept.append(replace(group, subgroups=tuple(s for s in group.subgroups if s in names)))
        return tuple(kept)

    def end_effectors(self, root: etree._Element, groups: set[str]) -> tuple[EndEffector, ...]:
        found = []
        for element in root.findall("end_effector"):
            name, group = _name(element), _name(element, "group")
            path = f"end_effector[{name}]"
            usable = self.link(element, f"{path}.parent_link", _name(element, "parent_link"))
            if group not in groups:
                self.fault(
                    line_of(element),
                    f"{path}.group",
                    f"end effector {shown(name, quoted=True)} names group "
                    f"{shown(group, quoted=True)}, which is not defined",
                )
                usable = False
            if usable:
                found.append(
                    EndEffector(
                        name,
                        _name(element, "parent_link"),
                        group,
                        element.get("parent_group"),
                        line_of(element),
                    )
                )
        return tuple(found)

    def virtual_joints(self, root: etree._Element) -> tuple[VirtualJoint, ...]:
        found = []
        for element in root.findall("virtual_joint"):
            name, kind = _name(element), _name(element, "type")
            path = f"virtual_joint[{name}]"
            usable = kind in VIRTUAL_JOINT_TYPES
            if not usable:
                self.fault(
                    line_of(element),
                    f"{path}.type",
                    f"unknown virtual joint type {shown(kind, quoted=True)}; SRDF virtual "
                    f"joints are "
                    f"{', '.join(VIRTUAL_JOINT_TYPES)}",
                )
            if self.link(element, f"{path}.child_link", _name(element, "child_link")) and usable:
                found.append(
                    VirtualJoint(
                        name,
                        kind,
                        _name(element, "parent_frame"),
                        _name(element, "child_link"),
                        line_of(element),
                    )
                )
        return tuple(found)
