"""What a layout shows, whatever the viewer: its panels with their names and resolved topics.

Every target renders a :class:`Plan`, so a Lichtblick layout and an RViz2 file of the same
configuration show the same things on the same topics. A plan is made for a :class:`Robot`:

- a template (``Robot()``): topics in the root namespace (``/cmd_vel``), or relative to the
  viewer's own namespace where the viewer expands names (RViz2: ``cmd_vel``, re-targeted with
  ``rviz2 --ros-args -r __ns:=/robot1``);
- a robot under a namespace (``Robot("/robot1")``): every topic under it (``/robot1/cmd_vel``);
- with the robot's real topics (from a topic list, a bag or the live graph): a panel takes its
  real topic and that topic's message type.

Command panels of one kind on one topic are one panel (three Teleop pads on one ``cmd_vel``
would be three ways to drive one robot at once): the merged panel is named after each
component it serves (``Flight, Driving, Walking``). The namespace every panel's topic shares
is the robot's namespace (:attr:`Plan.namespace`): what a viewer publishes on its own (3D
click tools, RViz2's goal tool, the robot description it reads) is put there.

Not here: the component -> panel mapping (:mod:`solver.layouts.presentation`); matching real
topics to panels (:mod:`solver.layouts.topics`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

from solver.core.partition import Configuration
from solver.errors import InputError
from solver.layouts.grammar import DEFAULT_GRAMMAR, Grammar
from solver.layouts.ordering import ordered
from solver.layouts.presentation import ROBOT, PanelSpec, Presentation
from solver.layouts.tiling import MAX_TABS, cluster_size, tiles
from solver.ros.joints import JointStart
from solver.ros.names import (
    Topic,
    common_namespace,
    full_topic_name_problem,
    in_namespace,
    normalise_type,
)
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = [
    "COMMAND_PANELS",
    "Panel",
    "Plan",
    "Robot",
    "check_namespace",
    "is_command",
    "panel_entries",
    "plan_layout",
    "template_topic",
]

# Panels that send to the robot: one per command topic.
COMMAND_PANELS = ("Teleop", "Publish")
POSE = "geometry_msgs/PoseStamped"


@dataclass(frozen=True)
class Robot:
    """What is known of the robot a layout is for; ``Robot()`` knows nothing (a template).

    ``namespace``: ``/robot1`` (None: the root namespace, or relative names where the viewer
    expands them). ``topics``: (component, tile) -> the robot's real topic for that panel.
    ``joints``: the joints a joint command names (None: not known). ``described``: one
    robot's layout, made from its description (``layouts --robot``, ``watch --layouts``).
    """

    namespace: str | None = None
    topics: Mapping[tuple[str, int], Topic] = field(default_factory=lambda: MappingProxyType({}))
    joints: tuple[JointStart, ...] | None = None
    described: bool = False


@dataclass(frozen=True, slots=True)
class Panel:
    """One panel of a plan: what it presents (``spec``), its name, topic and message types."""

    spec: PanelSpec
    name: str  # "visual display 2", "Flight, Driving, Walking"
    topic: str
    types: tuple[str, ...]  # the real topic's type when known, else the presentation's
    real: bool = False  # the topic is one the robot really has
    cluster: int = 0  # the Equation (2) cluster (1, 2, ...) of a clustered sensor; 0: none
    characteristic: str = ""  # the characteristic its component belongs to ("sensor_type")

    @property
    def kind(self) -> str:
        return self.spec.panel

    @property
    def is_goal(self) -> bool:
        """A 3D panel where the operator clicks a goal pose (a waypoint, an end-effector goal)."""
        return self.kind == "3D" and POSE in {normalise_type(t) for t in self.spec.types}


@dataclass(frozen=True)
class Plan:
    """The panels of one layout, in order, and the namespace their topics share."""

    number: int  # the UI configuration's number
    default: bool  # the default configuration
    panels: tuple[Panel, ...]
    namespace: str  # "/robot1"; "" for the root namespace or relative names
    relative: bool  # topics relative to the viewer's namespace (RViz2 templates)
    joints: tuple[JointStart, ...] | None = None  # the joints a joint command names
    described: bool = False  # one robot's layout, from its description
    grammar: Grammar = DEFAULT_GRAMMAR  # how it is laid out (:mod:`solver.layouts.design`)

    def topic(self, name: str) -> str:
        """``name`` (``clicked_point``) in the robot's namespace, as this plan spells topics."""
        if self.relative and not self.namespace:
            return name
        return f"{self.namespace}/{name}"

    @property
    def whom(self) -> str:
        """Whom the layout is for, in words: ``for the robot under /robot1``."""
        if self.namespace:
            return f"for the robot under {self.namespace}"
        if any(panel.real for panel in self.panels):
            return "for the robot whose own topics it names"
        return "topics in the root namespace (/cmd_vel)"

    @property
    def goals(self) -> tuple[Panel, ...]:
        """The panels where the operator sets a goal pose, in panel order."""
        return tuple(panel for panel in self.panels if panel.is_goal)


def is_command(spec: PanelSpec) -> bool:
    """Does the panel send to the robot (rather than show what the robot sends)?"""
    return spec.panel in COMMAND_PANELS or POSE in {normalise_type(t) for t in spec.types}


def check_namespace(namespace: str, where: str, *, what: str = "") -> str:
    """``namespace`` as a layout uses it (``/robot1``, no trailing ``/``; ``""`` for ``/``);
    a located :class:`~solver.errors.InputError` at ``where`` if it is no ROS 2 namespace
    (``what`` says what to do instead)."""
    name = namespace.rstrip("/")
    if namespace.startswith("/") and not name:
        return ""  # the root namespace
    problem = full_topic_name_problem(name)
    if problem:
        raise InputError.at(
            where,
            f"{shown(namespace, quoted=True)} is not a ROS 2 namespace: it {problem}" + what,
        )
    return name


def template_topic(
    spec: PanelSpec, namespace: str | None, tile: int, *, relative: bool = False
) -> str:
    """The presentation's topic for one tile, resolved under ``namespace``.

    ``<robot>/points`` is ``/robot1/points`` under ``/robot1``, ``/points`` in the root
    namespace, ``points`` when ``relative``; tiles after the first get ``_2``, ``_3``, ...
    (the first keeps the plain name, which a robot with one such sensor has).
    A template without ``<robot>`` is absolute as written, or relative to the robot.
    """
    template = spec.topic
    suffix = f"_{tile + 1}" if tile > 0 else ""
    if template.startswith(ROBOT):
        rest = template[len(ROBOT) :].lstrip("/")
    elif template.startswith("/"):
        return template + suffix
    else:
        rest = template
    if namespace:
        return f"{namespace}/{rest}{suffix}"
    return f"{rest}{suffix}" if relative else f"/{rest}{suffix}"


def panel_entries(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    tile_count: int | None = None,
) -> list[tuple[PanelSpec, int]]:
    """Each panel spec of ``configuration`` and its number of tiles (the sensor component:
    one per sensor shown, :func:`~solver.layouts.tiling.tiles`), in panel order.

    ``None`` is the default configuration: every component, one tile each.
    """
    rules = solution.rules
    entries: list[tuple[PanelSpec, int]] = []
    if configuration is None:
        for characteristic in rules.characteristics[1:]:
            if characteristic.kind == "integer":
                continue
            entries.extend(
                (presentation.spec(component.name), 1) for component in characteristic.components
            )
        return entries
    # One robot shows its own sensors; a template, the most its configuration serves.
    count = tile_count if tile_count is not None else tiles(rules, configuration)
    # Position 0 is the kinematic type (the layout's subject, not a panel); the integer
    # characteristic is the tiling of the sensor panel, not a panel of its own.
    sensor_position = next(
        (position for position, c in enumerate(rules.characteristics) if c.name == "sensor_type"),
        -1,
    )
    for position, component in enumerate(configuration.components):
        characteristic = rules.characteristics[position]
        if position == 0 or characteristic.kind == "integer":
            continue
        entries.append(
            (presentation.spec(component.name), count if position == sensor_position else 1)
        )
    return entries


def plan_layout(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    robot: Robot | None = None,
    *,
    tile_count: int | None = None,
    relative: bool = False,
) -> Plan:
    """The plan of ``configuration``'s layout (``None``: the default configuration) for
    ``robot`` (default: a template); ``relative``: templates take relative names."""
    robot = robot if robot is not None else Robot()
    # At most MAX_TABS sensors a cluster, as tiles() counts them (a rule set of its own may
    # cluster far more coarsely: one Tab panel of hundreds of tabs shows nothing useful).
    size = min(cluster_size(solution.rules, configuration), MAX_TABS)
    owner = {c.name: ch.name for ch in solution.rules.characteristics for c in ch.components}
    panels: list[Panel] = []
    for spec, count in panel_entries(solution, configuration, presentation, tile_count):
        tiles_ = []
        of = owner.get(spec.component, "")
        for tile in range(count):
            name = spec.component + (f" {tile + 1}" if count > 1 else "")
            real = robot.topics.get((spec.component, tile))
            if real is not None:
                tiles_.append(
                    Panel(spec, name, real.name, (real.type,), real=True, characteristic=of)
                )
            else:
                topic = template_topic(spec, robot.namespace, tile, relative=relative)
                tiles_.append(Panel(spec, name, topic, spec.types, characteristic=of))
        if count > 1:
            tiles_ = ordered(tiles_, _named, presentation.grammar)
        panels.extend(_clustered(tiles_, size if count > 1 else 1))
    merged = _merge_commands(panels)
    namespace = _namespace(robot, merged)
    if configuration is None:
        number, default = solution.default_configuration, True
    else:
        number, default = configuration.number, False
    return Plan(
        number,
        default,
        merged,
        namespace,
        relative,
        robot.joints,
        robot.described,
        presentation.grammar,
    )


def _named(panel: Panel) -> tuple[str, str]:
    return panel.topic, panel.name


def _clustered(sensors: list[Panel], size: int) -> list[Panel]:
    """The sensors in Equation (2)'s clusters of ``size``, in order (``size`` 1: individually)."""
    if size <= 1:
        return sensors
    return [replace(panel, cluster=index // size + 1) for index, panel in enumerate(sensors)]


def _namespace(robot: Robot, panels: tuple[Panel, ...]) -> str:
    """The robot's namespace: as given, unless its real topics lie elsewhere; then the
    namespace they share (the root, "", when they share none)."""
    given = robot.namespace or ""
    names = [panel.topic for panel in panels if panel.real]
    if not names or all(in_namespace(name, given) for name in names):
        return given
    return common_namespace(panel.topic for panel in panels if panel.topic.startswith("/")) or ""


def _merge_commands(panels: list[Panel]) -> tuple[Panel, ...]:
    """One command panel per (kind, topic): the first keeps its place, named after all."""
    first: dict[tuple[str, str], int] = {}
    merged: list[Panel] = []
    for panel in panels:
        key = (panel.kind, panel.topic)
        if panel.kind not in COMMAND_PANELS:
            merged.append(panel)
        elif key in first:
            index = first[key]
            kept = merged[index]
            merged[index] = replace(kept, name=f"{kept.name}, {panel.name}")
        else:
            first[key] = len(merged)
            merged.append(panel)
    return tuple(merged)
