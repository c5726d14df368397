"""The team the Fleet view makes from identified robots ("Make a team from these robots").

It is the selection ``teleop-ui fleet -o`` writes (:func:`solver.identify.team_text`), with two
differences a designer clicking in the page needs:

- **A name of its own**, from the robots (``Fleet: arm_gripper, diff_drive_lidar, quadrotor``),
  never the name of the team the page held before.
- **Nothing the robots do not have.** ``team_text`` leaves a characteristic with nothing
  identified out of a type's selection, which a team file reads as *every value*: an arm with no
  sensors then allows every sensor type and every count (1,000 robots and 50 configurations
  under the article's rules). A rule set cannot say "no sensor": every robot it counts has one
  value of every characteristic (the article's No. of Sensors is 1..50), so the studio selects
  the smallest selection instead: the first value the rules allow that type (one a constraint
  excludes is skipped), for a count its minimum. Each such choice is a :class:`Narrowed`, said
  in the page and written in the team file as a comment.

Not here: identifying (:mod:`solver.identify.fleet`), the page.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass

from solver.core.ruleset import RuleSet
from solver.core.team import Team
from solver.identify.fleet import Fleet, FleetEntry
from solver.identify.profile import MOTION_CONTROL, SENSOR_COUNT, SENSOR_TYPE, Profile
from solver.untrusted import shown

__all__ = ["Narrowed", "fleet_name", "narrowed", "narrowings"]

# Robots named in a team's name; the rest are counted ("and 4 more").
NAMED_ROBOTS = 3
# Characters of one robot's name in the team's name (file names are a stranger's).
NAME_CHARS = 30

# (type, characteristic) -> {value text: why a constraint excludes it}.
Excluded = Mapping[tuple[str, str], Mapping[str, object]]


@dataclass(frozen=True)
class Narrowed:
    """A characteristic of a type the robots have nothing of, selected as small as the rules
    allow (``value``) instead of every value."""

    kinematic_type: str
    characteristic: str
    label: str
    value: str
    robots: tuple[str, ...]
    count: bool  # a whole-number characteristic (the number of sensors)

    @property
    def sentence(self) -> str:
        robots = ", ".join(shown(r, limit=NAME_CHARS) for r in self.robots)
        nothing = f"{robots} ({self.kinematic_type}): no {self.label} identified"
        if self.count:
            why = f"the rules count from {self.value}, never 0"
        else:
            why = "the rules cannot select none, every robot has one"
        return (
            f"{nothing}; {why}, so the team takes the smallest selection, "
            f"{self.label} {self.value}, not every value."
        )


def fleet_name(fleet: Fleet) -> str:
    """A team name from the fleet's identified robots (their file names), in their order."""
    robots = [shown(e.name, limit=NAME_CHARS) for e in fleet.entries if e.identification]
    named = ", ".join(robots[:NAMED_ROBOTS])
    more = len(robots) - NAMED_ROBOTS
    return f"Fleet: {named}" + (f" and {more} more" if more > 0 else "")


def narrowings(
    fleet: Fleet, rules: RuleSet, profile: Profile, excluded: Excluded
) -> tuple[Narrowed, ...]:
    """Every characteristic of a type that ``team_text`` would leave open because none of the
    type's robots has anything of it, with the smallest selection taken instead."""
    found: list[Narrowed] = []
    for kinematic_type in (str(v) for v in rules.key.values):
        entries = [
            e
            for e in fleet.entries
            if e.identification is not None and e.identification.kinematic_type == kinematic_type
        ]
        if entries:
            found += _type_narrowings(kinematic_type, entries, rules, profile, excluded)
    return tuple(found)


def _type_narrowings(
    kinematic_type: str,
    entries: list[FleetEntry],
    rules: RuleSet,
    profile: Profile,
    excluded: Excluded,
) -> list[Narrowed]:
    idents = [e.identification for e in entries if e.identification is not None]
    had = {
        profile.role(MOTION_CONTROL): {c.motion_control for i in idents for c in i.motion_controls},
        profile.role(SENSOR_TYPE): {t for i in idents for t in i.sensor_types},
    }
    most = max(i.sensor_count for i in idents)
    robots = tuple(e.name for e in entries)
    found = []
    for characteristic in rules.characteristics:
        name = characteristic.name
        values = [str(v) for v in characteristic.values]
        if name in had:
            empty = not had[name].intersection(values)
        else:
            empty = name == profile.role(SENSOR_COUNT) and most < min(map(int, values))
        allowed = [v for v in values if v not in excluded.get((kinematic_type, name), {})]
        if empty and allowed:
            count = characteristic.kind == "integer"
            found.append(
                Narrowed(kinematic_type, name, characteristic.label, allowed[0], robots, count)
            )
    return found


def narrowed(team: Team, found: tuple[Narrowed, ...], name: str) -> Team:
    """``team`` named ``name``, each :class:`Narrowed` characteristic holding its one value."""
    rules = team.rules
    selections = []
    for selection in team.selections:
        domains = list(selection.domains)
        for item in found:
            if item.kinematic_type == selection.kinematic_type:
                position = rules.names.index(item.characteristic)
                characteristic = rules.characteristics[position]
                domains[position] = tuple(v for v in characteristic.values if str(v) == item.value)
        selections.append(dataclasses.replace(selection, domains=tuple(domains)))
    return dataclasses.replace(team, name=name, selections=tuple(selections))
