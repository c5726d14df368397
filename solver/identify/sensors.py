"""Sensors: found in a URDF or in topics, merged, and mapped to the rule set's sensor types.

A *detection* is one physical sensor seen by one source: a Gazebo ``<sensor type=...>`` or URDF
``<sensor>`` element, a Gazebo model plugin that simulates a sensor without an element (hector's
IMU, GPS, barometer; RotorS' IMU and odometry), or a device in a topic list or bag
(:mod:`solver.identify.interfaces`). The profile's rules give each its *kind* (``lidar``,
``depth_camera``, ``sonar``, ...). Plugins that publish simulation ground truth are skipped, and
a plugin that feeds an element already counted (same kind, same link) is the same sensor.

:func:`merge` turns detections into one :class:`Sensor` per kind and sensor type. Sources are
views of the same robot, so a kind's count is the largest any one source reports (a URDF lidar
and a ``/scan`` topic are one lidar). Each kind's sensor type comes from the profile's
``sensor_types`` and must exist in the rule set; a kind with no presentation (IMU, GPS, sonar)
is listed with ``sensor_type`` ``None`` and does not count toward the number of sensors.

Not here: reading topic lists (:mod:`solver.identify.topics`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from solver.core.rules import RuleSet
from solver.identify.profile import Profile
from solver.identify.urdf import PluginTag, SensorTag, Urdf

__all__ = ["Detection", "Sensor", "merge", "presented_count", "sensors_from_urdf"]

_LINK_PARAMS = ("linkName", "bodyName", "frameName", "frameId", "frame_name", "link_name")


@dataclass(frozen=True, slots=True)
class Detection:
    """One sensor seen by one source."""

    kind: str
    name: str
    source: str
    link: str | None = None
    vertical_samples: int | None = None


@dataclass(frozen=True, slots=True)
class Sensor:
    """All sensors of one kind (and sensor type): the JSON ``sensors`` entries."""

    kind: str
    sensor_type: str | None
    count: int
    source: str


def sensors_from_urdf(urdf: Urdf, profile: Profile, source: str = "urdf") -> tuple[Detection, ...]:
    """The sensors a URDF declares, in document order."""
    found: list[Detection] = []
    declared = {(_element_kind(t, profile), t.link) for t in urdf.sensors if t.origin == "gazebo"}
    for tag in urdf.sensors:
        kind = _element_kind(tag, profile)
        if tag.origin == "urdf" and tag.link is not None and (kind, tag.link) in declared:
            continue  # one physical sensor declared as a Gazebo <sensor> and a URDF <sensor>
        found.append(Detection(kind, tag.name or tag.type, source, tag.link, tag.vertical_samples))
    seen = {(d.kind, d.link) for d in found}
    for plugin in urdf.plugins:
        simulated = _plugin_kind(plugin, profile)
        if simulated is None:
            continue
        link = plugin.param(*_LINK_PARAMS) or plugin.reference
        if (simulated, link) in seen:
            continue  # the plugin publishes a sensor element already counted
        seen.add((simulated, link))
        found.append(Detection(simulated, plugin.name or plugin.filename, source, link))
    return tuple(found)


def _element_kind(tag: SensorTag, profile: Profile) -> str:
    kind = tag.type or "unknown"  # a URDF <sensor> with no kind element: told by its name
    for rule in profile.element_rules:
        if rule.accepts(kind, tag.text):
            return rule.kind
    return kind


def _plugin_kind(plugin: PluginTag, profile: Profile) -> str | None:
    truth = profile.ground_truth
    if truth is not None and truth.search(plugin.text):
        return None
    target = plugin.filename or plugin.name
    return next((rule.kind for rule in profile.plugin_rules if rule.accepts(None, target)), None)


def merge(detections: Iterable[Detection], profile: Profile, rules: RuleSet) -> tuple[Sensor, ...]:
    """One :class:`Sensor` per (kind, sensor type), in order of first detection."""
    sensor_types = _rule_values(rules, profile.role("sensor_type"))
    groups: dict[tuple[str, str | None], dict[str, list[Detection]]] = {}
    for detection in detections:
        mapping = profile.sensor_type_mapping(detection.kind)
        sensor_type = (
            None if mapping is None else mapping.sensor_type_for(detection.vertical_samples)
        )
        if sensor_type is not None and sensor_type not in sensor_types:
            sensor_type = None
        groups.setdefault((detection.kind, sensor_type), {}).setdefault(
            detection.source, []
        ).append(detection)
    found = []
    for (kind, sensor_type), by_source in groups.items():
        count = max(len(items) for items in by_source.values())
        source = "; ".join(f"{name}: {_names(items)}" for name, items in by_source.items())
        found.append(Sensor(kind, sensor_type, count, source))
    return tuple(found)


def presented_count(sensors: Sequence[Sensor]) -> int:
    """How many sensors have a presentation in the rule set (the article's No. of Sensors)."""
    return sum(sensor.count for sensor in sensors if sensor.sensor_type is not None)


def _rule_values(rules: RuleSet, name: str) -> frozenset[str]:
    if name not in rules.names:
        return frozenset()
    return frozenset(str(v) for v in rules.characteristic(name).values)


def _names(items: Sequence[Detection], limit: int = 4) -> str:
    names = list(dict.fromkeys(d.name for d in items))
    shown = ", ".join(names[:limit])
    return shown + (f", ... ({len(names)} in all)" if len(names) > limit else "")
