"""A robot's declared teleoperation description, read into its identification: declared wins.

Identification reads a body and guesses what drives it; a robot package that ships a
teleoperation description (:mod:`solver.ros.description`) says so itself. :func:`with_declared`
takes the :class:`Characteristics` identification found and a description and gives them the
description's values, each with where it is written, and keeps what identification read beside
them: every disagreement is a line of its own (``disagreements``), never silently dropped.

* *Kinematic type*: the description's type for this rule set (``kinematic_types``, by the rule
  set's name), else its ``kinematic_type``: a kinematic type of the rule set as it is, or a
  structure of the profile, mapped to the rule set's type as identification maps it. A value
  that is neither is said and not used.
* *Motion controls*: the declared list replaces what was read or guessed; each control's source
  is its place in the file and what carries it (``robot.teleop.yaml:7: topic /cmd_vel``).
* *Sensors*: the declared list replaces what was read, kind by kind, each mapped to the rule
  set's sensor type by the profile; a count that differs from the description's is said.

A section the description leaves out (no ``motion_controls:``) leaves what identification read.

Not here: reading the file (:mod:`solver.ros.description`), drafting one
(:mod:`solver.identify.describe`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from solver.core.ruleset import RuleSet
from solver.identify.classifier import kinematic_type_for
from solver.identify.interfaces import Control
from solver.identify.profile import Profile
from solver.identify.sensors import Sensor, sensor_type_of
from solver.ros.description import DeclaredControl, DeclaredSensor, TeleopDescription
from solver.untrusted import shown

__all__ = ["Characteristics", "with_declared"]


@dataclass(frozen=True)
class Characteristics:
    """What identification gives a robot, and what a description changed in it."""

    structure: str
    kinematic_type: str | None
    motion_controls: tuple[Control, ...]
    sensors: tuple[Sensor, ...]
    disagreements: tuple[str, ...] = ()


def with_declared(
    result: Characteristics, description: TeleopDescription, profile: Profile, rules: RuleSet
) -> Characteristics:
    """``result`` with the description's values, its disagreements said (module docstring)."""
    said: list[str] = []
    structure, kinematic_type = _kinematic(result, description, profile, rules, said)
    controls = result.motion_controls
    if description.motion_controls:
        controls = _controls(result, description, said)
    sensors = result.sensors
    if description.sensors:
        sensors = _sensors(result, description, profile, rules, said)
    return Characteristics(
        structure, kinematic_type, controls, sensors, (*result.disagreements, *said)
    )


def _kinematic(
    result: Characteristics,
    description: TeleopDescription,
    profile: Profile,
    rules: RuleSet,
    said: list[str],
) -> tuple[str, str | None]:
    """The structure and kinematic type to report (see the module docstring)."""
    values = {str(v) for v in rules.key.values}
    for_rules = description.kinematic_type_for(rules.name)
    written = for_rules or description.kinematic_type
    if written is None:
        return result.structure, result.kinematic_type
    where = description.where(description.kinematic_type_location)
    structure = result.structure
    if written in values:
        declared: str | None = written
        if written in profile.structure_names:
            structure = written
    elif written in profile.structure_names:
        structure = written
        declared = kinematic_type_for(written, profile, rules)
    else:
        said.append(
            f"kinematic type {shown(written, quoted=True)} ({where}) is neither a kinematic type "
            f"of {shown(rules.name, quoted=True)} nor a structure of the profile: not used"
        )
        return result.structure, result.kinematic_type
    if declared != result.kinematic_type or structure != result.structure:
        typed = "" if declared == written else f", {_type_name(declared, rules)}"
        read = _type_name(result.kinematic_type, rules)
        said.append(
            f"kinematic type: declared {shown(written)} ({where}{typed}), identification read "
            f"{shown(result.structure)} ({read}): the declared value wins"
        )
    return structure, declared


def _type_name(kinematic_type: str | None, rules: RuleSet) -> str:
    if kinematic_type is None:
        return f"no kinematic type in {shown(rules.name, quoted=True)}"
    return f"type {shown(kinematic_type)}"


def _controls(
    result: Characteristics, description: TeleopDescription, said: list[str]
) -> tuple[Control, ...]:
    found = {c.motion_control: c for c in result.motion_controls}
    declared = [_control(description, entry) for entry in description.motion_controls]
    names = {c.motion_control for c in declared}
    for control in result.motion_controls:
        if control.motion_control not in names:
            said.append(
                f"motion control {shown(control.motion_control)}: read ({control.source}), not "
                "declared: left out"
            )
    for control in declared:
        if control.motion_control not in found:
            said.append(
                f"motion control {shown(control.motion_control)}: declared ({control.source}), "
                "not read from the description: kept"
            )
    return tuple(declared)


def _control(description: TeleopDescription, entry: DeclaredControl) -> Control:
    carried = f"{entry.carrier} {shown(entry.name)}"
    if entry.type is not None:
        carried += f" ({shown(entry.type)})"
    return Control(entry.control, f"{description.where(entry.location)}: {carried}")


def _sensors(
    result: Characteristics,
    description: TeleopDescription,
    profile: Profile,
    rules: RuleSet,
    said: list[str],
) -> tuple[Sensor, ...]:
    read: dict[str, int] = {}
    for sensor in result.sensors:
        read[sensor.kind] = read.get(sensor.kind, 0) + sensor.count
    declared: dict[str, Sensor] = {}
    for entry in description.sensors:
        sensor = _sensor(description, entry, profile, rules)
        if sensor.kind in declared:  # two entries of one kind: one sensor of both counts
            first = declared[sensor.kind]
            sensor = replace(first, count=first.count + sensor.count)
        declared[sensor.kind] = sensor
    for kind, count in read.items():
        if kind not in declared:
            said.append(f"sensor {shown(kind)} x{count}: read, not declared: left out")
        elif declared[kind].count != count:
            said.append(
                f"sensor {shown(kind)}: declared x{declared[kind].count} "
                f"({declared[kind].source}), read x{count}: the declared count wins"
            )
    for kind, sensor in declared.items():
        if kind not in read:
            said.append(f"sensor {shown(kind)}: declared ({sensor.source}), not read: kept")
    return tuple(declared.values())


def _sensor(
    description: TeleopDescription, entry: DeclaredSensor, profile: Profile, rules: RuleSet
) -> Sensor:
    source = description.where(entry.location)
    if entry.topics:
        source += ": " + ", ".join(shown(topic) for topic in entry.topics[:4])
    return Sensor(entry.kind, sensor_type_of(entry.kind, profile, rules), entry.count, source)
