"""A Lichtblick layout against Lichtblick's own rules (``lichtblick.yaml``): every problem at once.

Each problem is a :class:`~solver.errors.Fault` located at its path in the layout, with a
stable ``code``:

============================  ===========================================================
``lichtblick-import``          what the app's import (``validateLayoutData``) refuses
``lichtblick-tree``            the panel tree: split nodes, ids without a config, orphans
                               (a Tab panel's tabs are trees of their own, walked too)
``lichtblick-panel-type``      a panel type the app does not register
``lichtblick-config``          a config key the panel does not read, or a value of the wrong type
``lichtblick-message-path``    a path the message-path grammar refuses, or only half-written
``ros-topic-name``             a topic (alone or in a path) that is not a full ROS 2 name
``lichtblick-title-hidden``    a title on a panel whose toolbar never shows one
``lichtblick-modified``        a key the app fills in on opening: the layout shows as modified
``lichtblick-grid``            a 3D panel without the reference grid the app's own layout has
``lichtblick-publish``         a Publish panel without a complete, meaningful message
``lichtblick-teleop-topic``    two Teleop panels driving one command topic
``lichtblick-label-cut``       an Indicator label line longer than a tile shows (it is cut)
``lichtblick-plot-legend``     series of one Plot whose legend names read alike once cut
``namespace``                  a topic the layout publishes on, outside the robot's namespace
``teleop-ui-follower``         this project's follower panel without the Tab panel it switches
                               beside it, or mapping a robot's configuration to no tab of it
============================  ===========================================================

A Tab panel's tabs are mounted one at a time: the panels of each tab are one screen, so the
rules about a screen (one pad per command topic, publishers in the robot's namespace, whose
namespace their own topics say) apply to each tab's panels on their own, and to the panels
outside any tab on theirs. Panel types are Lichtblick's own and the extension panels this
project ships (``extension_panels`` in the data file).

Not here: writing layouts (:mod:`solver.layouts.foxglove`); RViz2 (:mod:`.rviz`).
"""

from __future__ import annotations

import collections
import json
import re
from collections.abc import Collection, Iterator, Mapping
from dataclasses import dataclass
from typing import Any, TypeGuard

from solver.errors import Fault, Location
from solver.layouts.checks.data import field_values, lichtblick_rules, type_problems
from solver.layouts.checks.messagepath import MessagePathError, parse_message_path
from solver.ros.names import (
    common_namespace,
    full_topic_name_problem,
    in_namespace,
    normalise_type,
)
from solver.untrusted import shown

__all__ = ["check_lichtblick", "robot_namespace"]

# Plot/utils/config.ts isReferenceLinePlotPathType: !isNaN(parseFloat(value)), a leading number.
_REFERENCE_LINE = re.compile(r"\s*[+-]?(\d|\.\d|Infinity)")
_MAX_TREE_NODES = 100_000
_TAB = "Tab"


@dataclass(frozen=True, slots=True)
class _Node:
    """A node of the panel tree as walked: a panel id, a split or anything else; where it is;
    the tab it is in (``""``: in none; else the Tab panel's id and the tab's index); and, for
    a node that is a branch of a split, the other branch (``None`` otherwise)."""

    node: Any
    path: str
    tab: str
    sibling: Any = None


def check_lichtblick(
    layout: Any,
    file: str = "<layout>",
    *,
    namespace: str | None = None,
    topic_types: Mapping[str, Collection[str]] | None = None,
) -> tuple[Fault, ...]:
    """Every way ``layout`` (parsed JSON) breaks a rule of ``lichtblick.yaml``.

    ``namespace``: the robot's (``/robot1``); by default :func:`robot_namespace`. Topics the
    layout publishes on must lie in it. ``topic_types``: topic -> its possible message types,
    where known (a point-cloud topic must carry the colour settings the app would add).
    """
    faults = list(_import(layout, file))
    if not isinstance(layout, dict) or not isinstance(layout.get("configById"), dict):
        return tuple(faults)
    configs: dict[str, Any] = layout["configById"]
    nodes, cut_at = _walk(layout.get("layout"), configs)
    faults.extend(_tree(nodes, cut_at, configs, file))
    types = {
        topic: {normalise_type(t) for t in kinds} for topic, kinds in (topic_types or {}).items()
    }
    for panel_id, config in configs.items():
        faults.extend(_panel(str(panel_id), config, file, types))
    # One screen at a time: the panels of each tab, and those outside every tab; a tab's
    # robot is the one the follower beside its Tab panel names for it, where there is one.
    robots = _tab_robots(nodes, configs)
    for tab, screen in _screens(configs, nodes, robots).items():
        own = namespace or robots.get(tab) or robot_namespace({"configById": screen})
        faults.extend(_teleop_topics(screen, file))
        if own is not None:
            faults.extend(_namespace(screen, own, file))
    faults.extend(_followers(nodes, configs, file))
    return tuple(faults)


def tree_faults(layout: Any, file: str = "<layout>") -> tuple[Fault, ...]:
    """What the import refuses, the panel tree (tabs included) and unknown panel types: the
    shape of a layout alone, in time linear in its size (for a writer to check what it built;
    :func:`check_lichtblick` checks every rule)."""
    faults = list(_import(layout, file))
    if not isinstance(layout, dict) or not isinstance(layout.get("configById"), dict):
        return tuple(faults)
    configs: dict[str, Any] = layout["configById"]
    nodes, cut_at = _walk(layout.get("layout"), configs)
    faults.extend(_tree(nodes, cut_at, configs, file))
    for panel_id in configs:
        kind = str(panel_id).partition("!")[0]
        if _spec(kind) is None and kind not in lichtblick_rules()["panel_types"]:
            where = f"configById.{shown(panel_id)}"
            unknown = f"unknown panel type {shown(kind, quoted=True)}"
            faults.append(_fault(file, where, unknown, "lichtblick-panel-type"))
    return tuple(faults)


def _spec(kind: str) -> Mapping[str, Any] | None:
    """The rules of a panel type: Lichtblick's own, or an extension panel's of this project."""
    rules = lichtblick_rules()
    found: Mapping[str, Any] | None = rules["panels"].get(kind)
    return found if found is not None else rules["extension_panels"].get(kind)


def robot_namespace(layout: Any) -> str | None:
    """The namespace the robot's own topics in ``layout`` share (``/robot1``), or None.

    The robot's topics are those the panels show or command: every topic field and every
    path's topic, except the click-to-publish topics whose defaults are the app's own.
    """
    names: list[str] = []
    configs = layout.get("configById") if isinstance(layout, dict) else None
    for panel_id, config in (configs or {}).items():
        spec = _spec(str(panel_id).partition("!")[0])
        if spec is None or not isinstance(config, dict):
            continue
        skipped = set(spec.get("app_defaults", ()))
        for reference in spec.get("topics", ()):
            if reference not in skipped:
                names.extend(v for _, v in field_values(config, reference) if isinstance(v, str))
        for reference in spec.get("paths", ()):
            for _, value in field_values(config, reference):
                topic = _path_topic(value)
                if topic is not None:
                    names.append(topic)
    return common_namespace(names)


def _fault(file: str, path: str, message: str, code: str) -> Fault:
    return Fault(Location(file, path=path), message, code=code)


def _import(layout: Any, file: str) -> Iterator[Fault]:
    """util/layout.ts validateLayoutData, and the types of LayoutData's fields."""
    rules = lichtblick_rules()["layout"]
    if not isinstance(layout, dict):
        yield _fault(file, "", "a layout is a JSON object", "lichtblick-import")
        return
    for key in rules["required"]:
        if key not in layout:
            yield _fault(file, key, "missing (the import refuses the file)", "lichtblick-import")
    # The tree is checked on its own; its nodes are not of one type.
    for path, problem in type_problems(layout, rules["type"], ""):
        yield _fault(file, path.lstrip("."), problem, "lichtblick-import")


def _walk(root: Any, configs: dict[str, Any]) -> tuple[list[_Node], str | None]:
    """The panel tree's nodes, depth first, the trees of every Tab panel's tabs included (each
    Tab panel entered once: a Tab inside its own tab is a panel shown twice, not a loop); and
    where the walk stopped when the tree has more than ``_MAX_TREE_NODES`` nodes."""
    nodes: list[_Node] = []
    stack = [] if root is None else [_Node(root, "layout", "")]
    entered: set[str] = set()
    while stack:
        item = stack.pop()
        if len(nodes) >= _MAX_TREE_NODES:
            return nodes, item.path
        nodes.append(item)
        node = item.node
        if isinstance(node, dict):
            for key, other in (("second", "first"), ("first", "second")):
                if key in node:
                    branch = _Node(node[key], f"{item.path}.{key}", item.tab, node.get(other))
                    stack.append(branch)
        elif isinstance(node, str) and node.partition("!")[0] == _TAB and node not in entered:
            entered.add(node)
            stack.extend(reversed(_tab_trees(node, configs.get(node))))
    return nodes, None


def _tab_trees(panel_id: str, config: Any) -> list[_Node]:
    """The root of each tab's panel tree in a Tab panel's config (tabs without one: none)."""
    tabs = config.get("tabs") if isinstance(config, dict) else None
    if not isinstance(tabs, list):
        return []
    return [
        _Node(
            tab["layout"],
            f"configById.{shown(panel_id)}.tabs[{index}].layout",
            f"{panel_id}[{index}]",
        )
        for index, tab in enumerate(tabs)
        if isinstance(tab, dict) and tab.get("layout") is not None
    ]


def _tree(
    nodes: list[_Node], cut_at: str | None, configs: dict[str, Any], file: str
) -> Iterator[Fault]:
    seen: list[str] = []
    for item in nodes:
        node, path = item.node, item.path
        if isinstance(node, str):
            seen.append(node)
            if node not in configs:
                yield _fault(file, path, "a panel id with no config", "lichtblick-tree")
        elif isinstance(node, dict):
            yield from _split(node, path, file)
        else:
            yield _fault(file, path, "neither a panel id nor a split", "lichtblick-tree")
    if cut_at is not None:
        yield _fault(file, cut_at, "the panel tree is too large to check", "lichtblick-tree")
        return
    counts = collections.Counter(seen)  # linear: team layouts are checked as watch writes them
    for panel_id in sorted(counts):
        if counts[panel_id] > 1:
            yield _fault(file, "layout", f"{shown(panel_id)} appears twice", "lichtblick-tree")
    for panel_id in configs:
        if panel_id not in counts:
            where = f"configById.{shown(panel_id)}"
            yield _fault(file, where, "not in the panel tree: never shown", "lichtblick-tree")


def _split(node: dict[str, Any], path: str, file: str) -> Iterator[Fault]:
    for where, problem in type_problems(node, lichtblick_rules()["layout"]["split"], path):
        yield _fault(file, where, problem, "lichtblick-tree")
    for key in ("direction", "first", "second"):
        if key not in node:
            yield _fault(file, f"{path}.{key}", "missing in a split", "lichtblick-tree")
    percent = node.get("splitPercentage")
    if _is_number(percent) and not 0 <= percent <= 100:
        yield _fault(file, f"{path}.splitPercentage", "must be 0..100", "lichtblick-tree")


def _is_number(value: Any) -> TypeGuard[int | float]:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _panel(panel_id: str, config: Any, file: str, types: dict[str, set[str]]) -> Iterator[Fault]:
    rules = lichtblick_rules()
    kind = panel_id.partition("!")[0]
    base = f"configById.{shown(panel_id)}"
    spec = _spec(kind)
    if spec is None and kind not in rules["panel_types"]:
        unknown = f"unknown panel type {shown(kind, quoted=True)}"
        yield _fault(file, base, unknown, "lichtblick-panel-type")
        return
    if not isinstance(config, dict):
        yield _fault(file, base, "a panel config is an object", "lichtblick-config")
        return
    yield from _titles(kind, config, base, file)
    if spec is None:
        return  # a panel type whose config keys the rules do not list
    own = {key: value for key, value in config.items() if key not in rules["title_keys"]}
    for path, problem in type_problems(own, spec["type"], base):
        yield _fault(file, path, problem, "lichtblick-config")
    yield from _names(kind, config, spec, base, file)
    yield from _filled(config, spec, base, file, types)
    if "grid_layer" in spec and kind == "3D":
        yield from _grid(config, spec["grid_layer"]["layerId"], base, file)
    rate = config.get("publishRate")
    if kind == "Teleop" and _is_number(rate) and rate <= 0:
        never = "must be above 0: the pad never publishes"
        yield _fault(file, f"{base}.publishRate", never, "lichtblick-config")
    if kind == "Publish":
        yield from _publish(config, base, file)
    if kind == _TAB:
        yield from _active_tab(config, base, file)
    if "label_lines" in spec:
        yield from _label_lines(config, spec["label_lines"], base, file)
    if "legend_prefix" in spec:
        yield from _legend(config, spec["legend_prefix"], base, file)


def _titles(kind: str, config: dict[str, Any], base: str, file: str) -> Iterator[Fault]:
    rules = lichtblick_rules()
    for key, spec in rules["title_keys"].items():
        if key not in config:
            continue
        for path, problem in type_problems(config[key], spec, f"{base}.{key}"):
            yield _fault(file, path, problem, "lichtblick-config")
        if kind in rules["titles_not_shown"]:
            yield _fault(
                file,
                f"{base}.{key}",
                f"a {kind} panel draws its own toolbar: this title is never shown",
                "lichtblick-title-hidden",
            )


def _names(
    kind: str, config: dict[str, Any], spec: Mapping[str, Any], base: str, file: str
) -> Iterator[Fault]:
    """Topics must be full ROS 2 names; paths must parse and name such topics."""
    for reference in spec.get("topics", ()):
        for path, value in field_values(config, reference):
            if isinstance(value, str) and (problem := full_topic_name_problem(value)):
                yield _fault(file, f"{base}.{path}", f"topic {problem}", "ros-topic-name")
    optional = set(spec.get("may_be_empty", ()))
    for reference in spec.get("paths", ()):
        for path, value in field_values(config, reference):
            if value == "" and reference in optional:
                continue
            yield from _message_path(value, f"{base}.{path}", file, plot=kind == "Plot")


def _grid(config: dict[str, Any], grid: str, base: str, file: str) -> Iterator[Fault]:
    layers = config.get("layers")
    if not isinstance(layers, dict) or not any(
        isinstance(layer, dict) and layer.get("layerId") == grid for layer in layers.values()
    ):
        yield _fault(
            file,
            f"{base}.layers",
            f"no {grid} layer: the scene has no reference grid (the app's own default 3D panel "
            "has one)",
            "lichtblick-grid",
        )


def _label_lines(
    config: dict[str, Any], rule: Mapping[str, Any], base: str, file: str
) -> Iterator[Fault]:
    """Indicator labels: never wrapped, so a line past ``width`` characters is cut."""
    width = rule["width"]
    for reference in rule["labels"]:
        for path, value in field_values(config, reference):
            if not isinstance(value, str):
                continue  # a type problem, reported
            longest = max((len(line) for line in value.split("\n")), default=0)
            if longest > width:
                yield _fault(
                    file,
                    f"{base}.{path}",
                    f"a line of {longest} characters: the label never wraps, and a tile shows "
                    f"about {width} (break it with newlines)",
                    "lichtblick-label-cut",
                )


def _legend(config: dict[str, Any], prefix: int, base: str, file: str) -> Iterator[Fault]:
    """Plot series named alike in their first ``prefix`` characters read alike in the legend."""
    paths = config.get("paths")
    if not isinstance(paths, list):
        return
    seen: dict[str, int] = {}
    for index, item in enumerate(paths):
        if not isinstance(item, dict):
            continue
        label, value = item.get("label"), item.get("value")
        name = label if isinstance(label, str) and label else value
        if not isinstance(name, (str, int, float)) or isinstance(name, bool):
            continue
        start = str(name)[:prefix]
        if start in seen:
            yield _fault(
                file,
                f"{base}.paths[{index}]",
                f"named like series {seen[start]} in its first {prefix} characters "
                f"({shown(start, quoted=True)}): a narrow legend cuts the rest and the two read "
                "alike (give each a short label)",
                "lichtblick-plot-legend",
            )
        else:
            seen[start] = index


def _message_path(value: Any, path: str, file: str, *, plot: bool) -> Iterator[Fault]:
    if not isinstance(value, str) or (plot and _REFERENCE_LINE.match(value)):
        return  # a type problem (reported), or a Plot reference line such as "0.5"
    try:
        parsed = parse_message_path(value)
    except MessagePathError as error:
        yield _fault(
            file, path, f"not a message path: {error.faults[0].message}", "lichtblick-message-path"
        )
        return
    if parsed.incomplete:
        yield _fault(
            file,
            path,
            "a half-written message path (a trailing '.', an empty {} filter or a bare $): "
            "the app marks it invalid",
            "lichtblick-message-path",
        )
    if problem := full_topic_name_problem(parsed.topic):
        yield _fault(file, path, f"the path's topic {problem}", "ros-topic-name")


def _path_topic(value: Any) -> str | None:
    if not isinstance(value, str):
        return None
    try:
        return parse_message_path(value).topic
    except MessagePathError:
        return None


def _filled(
    config: dict[str, Any],
    spec: Mapping[str, Any],
    base: str,
    file: str,
    types: dict[str, set[str]],
) -> Iterator[Fault]:
    deep = set(spec.get("deep", ()))
    for key, default in spec.get("filled", {}).items():
        if key not in config:
            yield _fault(
                file,
                f"{base}.{key}",
                f"missing: the app adds {_json(default)} when the layout opens, and the layout "
                "shows as modified",
                "lichtblick-modified",
            )
        elif key in deep and isinstance(default, dict) and isinstance(config[key], dict):
            for sub, value in default.items():
                if sub not in config[key]:
                    yield _fault(
                        file,
                        f"{base}.{key}.{sub}",
                        f"missing: the app adds {_json(value)} when the layout opens, and the "
                        "layout shows as modified",
                        "lichtblick-modified",
                    )
    colour = {normalise_type(t) for t in spec.get("colour_on_first_message", ())}
    topics = config.get("topics")
    if not colour or not isinstance(topics, dict):
        return
    for topic, settings in topics.items():
        if types.get(topic, set()) & colour and not (
            isinstance(settings, dict) and "colorField" in settings
        ):
            yield _fault(
                file,
                f"{base}.topics.{shown(topic)}.colorField",
                "missing: on the first message the app picks a colour field and saves it "
                "(colorField, colorMode, colorMap), and the layout shows as modified",
                "lichtblick-modified",
            )


def _publish(config: dict[str, Any], base: str, file: str) -> Iterator[Fault]:
    """panels/Publish/index.tsx parseInput, and a message worth sending for the datatype."""
    text = config.get("value", lichtblick_rules()["panels"]["Publish"]["filled"]["value"])
    if not isinstance(text, str):
        return  # a type problem, reported
    where = f"{base}.value"
    try:
        message = json.loads(text)
    except (ValueError, RecursionError):  # RecursionError: a hostile "[[[[...", 100,000 deep
        yield _fault(
            file, where, "not JSON: the Publish button stays disabled", "lichtblick-publish"
        )
        return
    if not isinstance(message, dict):
        yield _fault(file, where, "the message must be a JSON object", "lichtblick-publish")
        return
    if not message:
        yield _fault(
            file,
            where,
            "an empty message: pressing Publish sends every field zero or empty (the app's "
            "ROS 2 writer even sent bytes a strict reader rejects for {})",
            "lichtblick-publish",
        )
        return
    datatype = config.get("datatype")
    if not isinstance(datatype, str) or not datatype:
        yield _fault(
            file,
            f"{base}.datatype",
            "no message schema: the panel cannot publish",
            "lichtblick-publish",
        )
        return
    sample = lichtblick_rules()["samples"].get(normalise_type(datatype))
    if sample is None:
        return  # a datatype the rules hold no sample of: its fields are not checked
    for path, problem in _shape(message, sample, where):
        yield _fault(file, path, problem, "lichtblick-publish")
    if normalise_type(datatype) == "trajectory_msgs/JointTrajectory":
        yield from _trajectory(message, where, file)


def _shape(value: Any, sample: Any, path: str) -> Iterator[tuple[str, str]]:
    """Where ``value`` has another shape than Lichtblick's sample message of its type."""
    if isinstance(sample, dict):
        yield from _shape_object(value, sample, path)
    elif isinstance(sample, list):
        if not isinstance(value, list):
            yield path, "must be a list"
            return
        for index, item in enumerate(value):
            yield from _shape(item, sample[0], f"{path}[{index}]")
    elif isinstance(sample, bool):
        if not isinstance(value, bool):
            yield path, "must be true or false"
    elif isinstance(sample, (int, float)):
        if not _is_number(value):
            yield path, "must be a number"
    elif not isinstance(value, str):
        yield path, "must be a string"


def _shape_object(value: Any, sample: dict[str, Any], path: str) -> Iterator[tuple[str, str]]:
    if not isinstance(value, dict):
        yield path, "must be an object"
        return
    for key in sample:
        if key not in value:
            yield f"{path}:{key}", "missing field (the app's sample message has it)"
    for key, item in value.items():
        if key in sample:
            yield from _shape(item, sample[key], f"{path}:{key}")
        else:
            yield f"{path}:{shown(key)}", "not a field of this message type"


def _trajectory(message: dict[str, Any], where: str, file: str) -> Iterator[Fault]:
    names = message.get("joint_names")
    points = message.get("points")
    if not isinstance(names, list) or not names or not all(isinstance(n, str) and n for n in names):
        yield _fault(
            file,
            f"{where}:joint_names",
            "a trajectory names its joints (none here, or an empty name)",
            "lichtblick-publish",
        )
        return
    if not isinstance(points, list) or not points:
        yield _fault(
            file, f"{where}:points", "a trajectory has at least one point", "lichtblick-publish"
        )
        return
    for index, point in enumerate(points):
        positions = point.get("positions") if isinstance(point, dict) else None
        if not isinstance(positions, list) or len(positions) != len(names):
            yield _fault(
                file,
                f"{where}:points[{index}].positions",
                f"needs one position per joint ({len(names)})",
                "lichtblick-publish",
            )


def _teleop_topics(configs: dict[str, Any], file: str) -> Iterator[Fault]:
    first: dict[str, str] = {}
    for panel_id, config in configs.items():
        if str(panel_id).partition("!")[0] != "Teleop" or not isinstance(config, dict):
            continue
        topic = config.get("topic")
        if not isinstance(topic, str):
            continue
        if topic in first:
            yield _fault(
                file,
                f"configById.{shown(panel_id)}.topic",
                f"{shown(first[topic])} already drives this topic: two pads command one robot "
                "(one velocity panel per command topic)",
                "lichtblick-teleop-topic",
            )
        else:
            first[topic] = str(panel_id)


def _namespace(configs: dict[str, Any], namespace: str, file: str) -> Iterator[Fault]:
    for panel_id, config in configs.items():
        spec = _spec(str(panel_id).partition("!")[0])
        if spec is None or not isinstance(config, dict):
            continue
        merged = _completed(spec, config)
        for reference in spec.get("publishes", ()):
            for path, value in field_values(merged, reference):
                if isinstance(value, str) and not in_namespace(value, namespace):
                    given = "the app's default " if _unset(config, reference) else ""
                    yield _fault(
                        file,
                        f"configById.{shown(panel_id)}.{path}",
                        f"the panel publishes on {given}{shown(value, quoted=True)}, outside the "
                        f"robot's namespace {shown(namespace, quoted=True)}",
                        "namespace",
                    )


def _completed(spec: Mapping[str, Any], config: dict[str, Any]) -> dict[str, Any]:
    """``config`` as the app completes it: missing keys filled, deep keys merged key by key."""
    merged = {**spec.get("filled", {}), **config}
    for key in spec.get("deep", ()):
        default, own = spec.get("filled", {}).get(key), config.get(key)
        if isinstance(default, dict) and isinstance(own, dict):
            merged[key] = {**default, **own}
    return merged


def _unset(config: dict[str, Any], reference: str) -> bool:
    return not any(True for _ in field_values(config, reference))


def _json(value: Any) -> str:
    text = json.dumps(value, separators=(", ", ": "))
    return text if len(text) <= 60 else text[:57] + "..."


def _active_tab(config: dict[str, Any], base: str, file: str) -> Iterator[Fault]:
    """util/layout.ts validateTabPanelConfig: ``activeTabIdx`` names one of the tabs."""
    index, tabs = config.get("activeTabIdx"), config.get("tabs")
    if not _is_number(index) or not isinstance(tabs, list):
        return  # a type problem, or a key the app fills in: reported
    if index != int(index) or not 0 <= index < len(tabs):
        yield _fault(
            file,
            f"{base}.activeTabIdx",
            f"names no tab (the panel has {len(tabs)}): the app replaces the whole config with "
            "its default, one empty tab",
            "lichtblick-config",
        )


def _screens(
    configs: dict[str, Any], nodes: list[_Node], robots: Mapping[str, str]
) -> dict[str, dict[str, Any]]:
    """The panels' configs by what is on screen at once: each robot's tab (by its Tab panel's
    id and its index, ``Tab!x[2]``, as a follower names it in ``robots``), and those outside
    every such tab (``""``: with an id in no tree), in ``configs``' order. A Tab panel no
    follower switches (a cluster of one robot's sensors) is part of the screen it sits in."""
    tab_of = {item.node: item.tab for item in nodes if isinstance(item.node, str)}

    def screen(tab: str) -> str:
        for _ in range(len(tab_of) + 1):  # a Tab inside its own tab ends, as the walk does
            if not tab or tab in robots:
                return tab
            tab = tab_of.get(tab.rpartition("[")[0], "")
        return tab

    screens: dict[str, dict[str, Any]] = {}
    for panel_id, config in configs.items():
        screens.setdefault(screen(tab_of.get(panel_id, "")), {})[panel_id] = config
    return screens


def _tab_robots(nodes: list[_Node], configs: dict[str, Any]) -> dict[str, str]:
    """The robot of each tab (``Tab!x[2]`` -> ``/uav1``), as a follower beside a Tab panel maps
    them: a tab holds that robot's screen, its publishers in that robot's namespace."""
    robots: dict[str, str] = {}
    for item in nodes:
        sibling = item.sibling
        if not (isinstance(item.node, str) and isinstance(sibling, str)):
            continue
        spec = lichtblick_rules()["extension_panels"].get(item.node.partition("!")[0], {})
        config = configs.get(item.node)
        if spec.get("sibling") != _TAB or not isinstance(config, dict):
            continue
        mapping = config.get("tabs")
        for entry in mapping if isinstance(mapping, list) else []:
            if not isinstance(entry, dict):
                continue
            tab, robot = entry.get("tab"), entry.get("robot")
            if isinstance(robot, str) and _is_number(tab) and tab == int(tab):
                robots.setdefault(f"{sibling}[{int(tab)}]", robot)
    return robots


def _followers(nodes: list[_Node], configs: dict[str, Any], file: str) -> Iterator[Fault]:
    """An extension panel that acts on the panel beside it (``sibling`` in its rules) has one
    of that type there; the follower's tabs name tabs of it, each (robot, configuration)
    once."""
    extensions = lichtblick_rules()["extension_panels"]
    for item in nodes:
        if not isinstance(item.node, str):
            continue
        wanted = extensions.get(item.node.partition("!")[0], {}).get("sibling")
        if wanted is None:
            continue
        sibling = item.sibling
        if not (isinstance(sibling, str) and sibling.partition("!")[0] == wanted):
            yield _fault(
                file,
                item.path,
                f"no {wanted} panel beside it (the other branch of its split): the panel can "
                f"switch that one only",
                "teleop-ui-follower",
            )
            continue
        yield from _follower_tabs(
            configs.get(item.node), configs.get(sibling), f"configById.{shown(item.node)}", file
        )


def _follower_tabs(config: Any, beside: Any, base: str, file: str) -> Iterator[Fault]:
    if not isinstance(config, dict) or not isinstance(beside, dict):
        return  # reported as a tree or config problem
    tabs = beside.get("tabs")
    count = len(tabs) if isinstance(tabs, list) else 0
    mapping = config.get("tabs")
    first: dict[tuple[str, float], int] = {}
    for index, entry in enumerate(mapping if isinstance(mapping, list) else []):
        if not isinstance(entry, dict):
            continue  # a type problem, reported
        if not _names_a_tab(entry.get("tab"), count):
            yield _fault(
                file,
                f"{base}.tabs[{index}].tab",
                f"names no tab of the Tab panel beside it (it has {count})",
                "teleop-ui-follower",
            )
        robot, number = entry.get("robot"), entry.get("configuration")
        if not isinstance(robot, str) or not _is_number(number):
            continue
        if (robot, number) in first:
            yield _fault(
                file,
                f"{base}.tabs[{index}]",
                f"the robot and configuration of tabs[{first[robot, number]}] again: the "
                "follower shows one tab per pair",
                "teleop-ui-follower",
            )
        else:
            first[robot, number] = index
    default = config.get("defaultTab")
    if default is not None and not _names_a_tab(default, count):
        yield _fault(
            file,
            f"{base}.defaultTab",
            f"names no tab of the Tab panel beside it (it has {count})",
            "teleop-ui-follower",
        )


def _names_a_tab(value: Any, count: int) -> bool:
    """Whether ``value`` is the index of one of ``count`` tabs (a value of another type is a
    type problem, reported on its own: taken as naming one here)."""
    if not _is_number(value):
        return True
    return value == int(value) and 0 <= value < count
