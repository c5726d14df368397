"""Reading a URDF into an immutable robot description, checked as a tree.

:func:`parse_urdf` takes URDF *text* (from a file, a compiled xacro, or ``/robot_description``
on a ROS master) and returns a :class:`Urdf`: links, joints, Gazebo sensors and model plugins,
and the joints that have a transmission or a ``ros2_control`` interface. The whole document is
validated and every problem is reported at once, each with the file, line and element: a joint
whose parent or child link does not exist, an unknown joint type, duplicate names, a link with
two parents, cycles, several root links, an empty robot.

A :class:`Urdf` also answers the tree questions the classifier asks (root, children, subtree).

Not here: what the body is (:mod:`solver.identify.body`), what the sensors are
(:mod:`solver.identify.sensors`), xacro (:mod:`solver.identify.xacros`).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

from solver.errors import Fault, InputError, Location
from solver.identify.safexml import line_of, parse_xml

if TYPE_CHECKING:
    from lxml import etree

__all__ = ["JOINT_TYPES", "Joint", "Link", "PluginTag", "SensorTag", "Urdf", "parse_urdf"]

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
# Plugin parameters kept for the classifiers: short text values (joint names, topics, frames).
_MAX_PARAM_TEXT = 200


@dataclass(frozen=True, slots=True)
class Link:
    name: str
    line: int | None = None


@dataclass(frozen=True, slots=True)
class Joint:
    """One joint; ``movable`` is false for fixed joints and zero-range revolute/prismatic ones."""

    name: str
    type: str
    parent: str
    child: str
    line: int | None = None
    mimic: str | None = None
    lower: float | None = None
    upper: float | None = None

    @property
    def movable(self) -> bool:
        if self.type == "fixed":
            return False
        # RotorS and others mount sensors on revolute joints with lower == upper: fixed in effect.
        return not (self.type in ("revolute", "prismatic") and self.lower is not None
                    and self.lower == self.upper)

    @property
    def actuated(self) -> bool:
        """Movable and driven on its own (a mimic joint follows another joint)."""
        return self.movable and self.mimic is None


@dataclass(frozen=True, slots=True)
class PluginTag:
    """A Gazebo ``<plugin>``: inside a ``<sensor>``, or a model plugin under ``<gazebo>``."""

    name: str
    filename: str
    reference: str | None = None
    line: int | None = None
    # (tag, text) of the plugin's simple child elements: topics, frames, joint names.
    params: tuple[tuple[str, str], ...] = ()

    def param(self, *tags: str) -> str | None:
        """The text of the first of ``tags`` the plugin sets (case-insensitive)."""
        wanted = {t.lower() for t in tags}
        return next((text for tag, text in self.params if tag.lower() in wanted), None)

    @property
    def text(self) -> str:
        """Everything that names this plugin, for pattern matching."""
        return " ".join([self.name, self.filename, *(text for _, text in self.params)])


@dataclass(frozen=True, slots=True)
class SensorTag:
    """A URDF ``<sensor>`` or Gazebo ``<sensor type=...>`` element."""

    name: str
    type: str
    link: str | None
    line: int | None = None
    origin: str = "gazebo"  # "gazebo" (<gazebo><sensor type>) or "urdf" (top-level <sensor>)
    plugins: tuple[PluginTag, ...] = ()
    horizontal_samples: int | None = None
    vertical_samples: int | None = None
    horizontal_fov: float | None = None
    camera_count: int = 0

    @property
    def text(self) -> str:
        """Everything that names this sensor, for pattern matching."""
        return " ".join([self.name, self.link or "", *(p.text for p in self.plugins)])


@dataclass(frozen=True)
class Urdf:
    """A robot description: links, joints, sensors, plugins, checked to form one tree."""

    name: str
    file: str
    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    sensors: tuple[SensorTag, ...] = ()
    plugins: tuple[PluginTag, ...] = ()
    # Joints named by a <transmission> or a <ros2_control> block: driven by a controller.
    controlled_joints: frozenset[str] = frozenset()
    root: str = ""

    @cached_property
    def _children(self) -> dict[str, tuple[Joint, ...]]:
        found: dict[str, list[Joint]] = {link.name: [] for link in self.links}
        for joint in self.joints:
            found[joint.parent].append(joint)
        return {name: tuple(joints) for name, joints in found.items()}

    @cached_property
    def _parent_joint(self) -> dict[str, Joint]:
        return {joint.child: joint for joint in self.joints}

    @cached_property
    def _joint_by_name(self) -> dict[str, Joint]:
        return {joint.name: joint for joint in self.joints}

    def children(self, link: str) -> tuple[Joint, ...]:
        """The joints whose parent is ``link``, in document order."""
        return self._children.get(link, ())

    def parent_joint(self, link: str) -> Joint | None:
        return self._parent_joint.get(link)

    def joint(self, name: str) -> Joint | None:
        return self._joint_by_name.get(name)

    def has_link(self, name: str) -> bool:
        return name in self._children

    def subtree_joints(self, link: str) -> Iterator[Joint]:
        """Every joint below ``link``, depth first in document order."""
        stack = list(reversed(self.children(link)))
        while stack:
            joint = stack.pop()
            yield joint
            stack.extend(reversed(self.children(joint.child)))


def parse_urdf(text: str | bytes, file: str = "<string>") -> Urdf:
    """Parse and check URDF text; :class:`InputError` lists every problem found."""
    root = parse_xml(text, file)
    return _Builder(file).build(root)


class _Builder:
    def __init__(self, file: str) -> None:
        self.file = file
        self.faults: list[Fault] = []

    def fault(self, element: etree._Element | None, path: str, message: str,
              code: str = "urdf") -> None:
        line = None if element is None else line_of(element)
        self.faults.append(Fault(Location(self.file, line, None, path), message, code))

    def build(self, root: etree._Element) -> Urdf:
        if root.tag != "robot":
            raise InputError.at(self.file, f"root element is <{root.tag}>, expected <robot> "
                                           "(is this a URDF?)", line=line_of(root),
                                path=str(root.tag), code="urdf")
        name = (root.get("name") or "").strip()
        links = self._links(root)
        joints = self._joints(root, {link.name for link in links})
        sensors = self._sensors(root)
        plugins = tuple(_plugin(p, g.get("reference")) for g in root.findall("gazebo")
                        for p in g.findall("plugin"))
        controlled = frozenset(self._controlled(root))
        top = ""
        if links and not self.faults:
            top = self._check_tree(root, links, joints)
        if not links and not self.faults:
            self.fault(root, "robot", f"robot {name!r} has no links: an empty robot "
                                      "cannot be identified", code="urdf-empty")
        if self.faults:
            raise InputError(self.faults)
        return Urdf(name or "robot", self.file, links, joints, sensors, plugins, controlled,
                    top)

    def _links(self, root: etree._Element) -> tuple[Link, ...]:
        found: dict[str, Link] = {}
        for element in root.findall("link"):
            name = (element.get("name") or "").strip()
            if not name:
                self.fault(element, "link", "a <link> without a name")
            elif name in found:
                self.fault(element, f"link[{name}]", f"duplicate link {name!r} (first at "
                                                     f"line {found[name].line})")
            else:
                found[name] = Link(name, line_of(element))
        return tuple(found.values())

    def _joints(self, root: etree._Element, links: set[str]) -> tuple[Joint, ...]:
        found: dict[str, Joint] = {}
        for element in root.findall("joint"):
            joint = self._joint(element, links)
            if joint is None:
                continue
            if joint.name in found:
                self.fault(element, f"joint[{joint.name}]", f"duplicate joint {joint.name!r} "
                                                            f"(first at line "
                                                            f"{found[joint.name].line})")
                continue
            found[joint.name] = joint
        return tuple(found.values())

    def _joint(self, element: etree._Element, links: set[str]) -> Joint | None:
        name = (element.get("name") or "").strip()
        path = f"joint[{name}]" if name else "joint"
        ok = True
        if not name:
            self.fault(element, path, "a <joint> without a name")
            ok = False
        kind = (element.get("type") or "").strip()
        if kind not in JOINT_TYPES:
            shown = f"unknown joint type {kind!r}" if kind else "missing joint type"
            self.fault(element, f"{path}.type", f"{shown}; URDF joint types are "
                                                f"{', '.join(JOINT_TYPES)}")
            ok = False
        ends: dict[str, str] = {}
        for end in ("parent", "child"):
            tag = element.find(end)
            link = (tag.get("link") or "").strip() if tag is not None else ""
            if tag is None or not link:
                self.fault(element if tag is None else tag, f"{path}.{end}",
                           f"joint {name!r} has no <{end} link=...>")
                ok = False
            elif link not in links:
                self.fault(tag, f"{path}.{end}", f"joint {name!r} names {end} link {link!r}, "
                                                 "which does not exist",
                           code="urdf-missing-link")
                ok = False
            ends[end] = link
        if ok and ends["parent"] == ends["child"]:
            self.fault(element, path, f"joint {name!r} connects link {ends['parent']!r} to "
                                      "itself (a cycle)", code="urdf-cycle")
            ok = False
        if not ok:
            return None
        limit = element.find("limit")
        mimic = element.find("mimic")
        return Joint(name, kind, ends["parent"], ends["child"], line_of(element),
                     None if mimic is None else (mimic.get("joint") or "").strip() or None,
                     self._number(limit, "lower", path), self._number(limit, "upper", path))

    def _number(self, element: etree._Element | None, attribute: str, path: str
                ) -> float | None:
        if element is None or element.get(attribute) is None:
            return None
        text = element.get(attribute, "")
        try:
            return float(text)
        except ValueError:
            self.fault(element, f"{path}.limit.{attribute}", f"limit {attribute} is not a "
                                                            f"number: {text!r}")
            return None

    def _check_tree(self, root: etree._Element, links: tuple[Link, ...],
                    joints: tuple[Joint, ...]) -> str:
        parents: dict[str, Joint] = {}
        elements = {e.get("name"): e for e in root.findall("joint")}
        for joint in joints:
            if joint.child in parents:
                first = parents[joint.child]
                self.fault(elements.get(joint.name), f"joint[{joint.name}].child",
                           f"link {joint.child!r} has two parent joints: {first.name!r} "
                           f"(line {first.line}) and {joint.name!r}; a URDF is a tree",
                           code="urdf-cycle")
            else:
                parents[joint.child] = joint
        if self.faults:
            return ""
        roots = [link for link in links if link.name not in parents]
        if not roots:
            self.fault(root, "robot", "every link has a parent joint: the joints form a "
                                      "cycle, there is no root link", code="urdf-cycle")
            return ""
        reached = self._reachable(roots[0].name, joints)
        cyclic = [link for link in links if link.name not in reached
                  and link not in roots and self._on_cycle(link.name, parents)]
        if cyclic:
            names = ", ".join(repr(link.name) for link in cyclic)
            joint = parents[cyclic[0].name]
            self.fault(elements.get(joint.name), f"joint[{joint.name}]",
                       f"joints form a cycle through links {names}", code="urdf-cycle")
        if len(roots) > 1:
            names = ", ".join(f"{link.name!r} (line {link.line})" for link in roots)
            self.fault(root, "robot", f"{len(roots)} root links (links with no parent "
                                      f"joint): {names}; a URDF has exactly one root",
                       code="urdf-roots")
        return roots[0].name

    @staticmethod
    def _reachable(start: str, joints: tuple[Joint, ...]) -> set[str]:
        below: dict[str, list[str]] = {}
        for joint in joints:
            below.setdefault(joint.parent, []).append(joint.child)
        seen = {start}
        stack = [start]
        while stack:
            for child in below.get(stack.pop(), []):
                if child not in seen:
                    seen.add(child)
                    stack.append(child)
        return seen

    @staticmethod
    def _on_cycle(link: str, parents: dict[str, Joint]) -> bool:
        seen = set()
        current = link
        while current in parents:
            if current in seen:
                return True
            seen.add(current)
            current = parents[current].parent
        return current == link

    def _sensors(self, root: etree._Element) -> tuple[SensorTag, ...]:
        found = []
        for gazebo in root.findall("gazebo"):
            reference = gazebo.get("reference")
            for sensor in gazebo.findall("sensor"):
                found.append(_sensor(sensor, reference, "gazebo"))
        # URDF's own <sensor> element (urdfdom): <sensor name><parent link/><camera|ray/>.
        for sensor in root.findall("sensor"):
            parent = sensor.find("parent")
            link = None if parent is None else parent.get("link")
            kind = sensor.get("type") or next((child.tag for child in sensor
                                               if isinstance(child.tag, str)
                                               and child.tag not in ("parent", "origin")),
                                              "")
            found.append(_sensor(sensor, link, "urdf", str(kind)))
        return tuple(found)

    @staticmethod
    def _controlled(root: etree._Element) -> Iterator[str]:
        for transmission in root.findall("transmission"):
            for joint in transmission.findall("joint"):
                if joint.get("name"):
                    yield str(joint.get("name"))
        for control in root.findall("ros2_control"):
            for joint in control.findall("joint"):
                if joint.get("name"):
                    yield str(joint.get("name"))


def _sensor(element: etree._Element, link: str | None, origin: str,
            kind: str | None = None) -> SensorTag:
    samples: dict[str, int | None] = {}
    for axis in ("horizontal", "vertical"):
        node = element.find(f".//scan/{axis}/samples")
        samples[axis] = _integer(node.text if node is not None else None)
    fov = element.find(".//horizontal_fov")
    cameras = len(element.findall("camera")) + len(element.findall(".//camera[@name]"))
    return SensorTag(
        name=(element.get("name") or "").strip(),
        type=(kind if kind is not None else element.get("type") or "").strip().lower(),
        link=link, line=line_of(element), origin=origin,
        plugins=tuple(_plugin(p, link) for p in element.iter("plugin")),
        horizontal_samples=samples["horizontal"], vertical_samples=samples["vertical"],
        horizontal_fov=_float(fov.text if fov is not None else None),
        camera_count=cameras)


def _plugin(element: etree._Element, reference: str | None) -> PluginTag:
    params = []
    for child in element:
        if isinstance(child.tag, str) and len(child) == 0 and child.text and child.text.strip():
            params.append((child.tag, child.text.strip()[:_MAX_PARAM_TEXT]))
    return PluginTag((element.get("name") or "").strip(),
                     (element.get("filename") or "").strip(), reference, line_of(element),
                     tuple(params))


def _integer(text: str | None) -> int | None:
    try:
        return None if text is None else int(float(text.strip()))
    except ValueError:
        return None


def _float(text: str | None) -> float | None:
    try:
        return None if text is None else float(text.strip())
    except ValueError:
        return None

