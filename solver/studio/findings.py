"""Where the selection view shows each of the linter's findings: at the control it concerns.

``teleop-ui check`` locates a finding by file and YAML path: a value of the rule set
(``characteristics.sensor_type.values[3]``), a component, a constraint, or a value the
selection ticks (``team.UAV.motion_control[1]`` in the selection's team file). The selection
view has a control for each kinematic type, characteristic and value; :func:`places` tells which
controls a finding belongs to, so that each control carries the findings about it:

=================================================  =============================================
the finding is at                                  shown at
=================================================  =============================================
a value of a characteristic in the rules           that value's control, in every type
a value of the kinematic type (the team key)       that type's control
a component                                        the controls of the values it serves
a characteristic in the rules (its range, ...)     that characteristic's controls
a constraint                                       the values it excludes (shown disabled)
``team.T.c[i]``, ``team.T.c``, ``team.T``          that value, characteristic, type of T
anything else (the bound, the team as a whole)     the selection as a whole
=================================================  =============================================

Paths are matched against the paths the rule set's and the selection's own documents give their
values (never parsed back from text), so a name holding dots or brackets cannot be misplaced.

Not here: running the checks (:mod:`solver.check`), drawing the page (templates, script).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from solver import Characteristic, RuleSet
from solver.check.context import item_path
from solver.core.forbidden import Removed
from solver.files.yamlio import Document, PathPart, format_path

__all__ = ["Place", "Places", "place_data", "places", "rule_places", "selection_places"]


@dataclass(frozen=True, order=True)
class Place:
    """A control of the selection view: a value (all three set), a characteristic (no value),
    a kinematic type (only the type) or the selection as a whole (nothing). An empty type
    with a characteristic means that characteristic's control in every type."""

    kinematic_type: str = ""
    characteristic: str = ""
    value: str = ""


# A document path (as ``check`` writes it) -> the controls a finding there belongs to.
Places = dict[str, tuple[Place, ...]]


def _add(table: Places, path: Sequence[PathPart], found: Iterable[Place]) -> None:
    table[format_path(path)] = tuple(sorted(set(found)))


def rule_places(
    rules: RuleSet, excluded: Mapping[tuple[str, str], Mapping[str, Removed]]
) -> Places:
    """The controls of everything a rule set's findings can be located at.

    ``excluded`` is what the rule set's constraints exclude per (type, characteristic), as the
    view shows it (:meth:`solver.studio.workspace.Workspace.excluded`).
    """
    table: Places = {}
    for characteristic in rules.characteristics:
        _characteristic_places(table, rules, characteristic)
    by_constraint: dict[int, list[Place]] = {}
    positions = {id(c): i for i, c in enumerate(rules.constraints)}
    for (kinematic_type, name), reasons in excluded.items():
        for value, removed in reasons.items():
            for constraint in removed.constraints:
                by_constraint.setdefault(positions[id(constraint)], []).append(
                    Place(kinematic_type, name, value)
                )
    for index in range(len(rules.constraints)):
        _add(table, ("constraints", index), by_constraint.get(index, ()))
    return table


def _characteristic_places(table: Places, rules: RuleSet, characteristic: Characteristic) -> None:
    """A characteristic, its values and its components: the kinematic type's values are the
    types' own controls; a count's values and arrangements are its range control."""
    base: tuple[PathPart, ...] = ("characteristics", characteristic.name)
    key = characteristic.name == rules.team_key
    name = characteristic.name

    def place(value: object) -> Place:
        if key:
            return Place(str(value))
        if characteristic.kind == "integer":
            return Place("", name)
        return Place("", name, str(value))

    _add(table, base, [Place() if key else Place("", name)])
    if characteristic.kind != "integer":
        for value in characteristic.values:
            _add(table, item_path(rules.document, (*base, "values"), value), [place(value)])
    for component in characteristic.components:
        # An arrangement may hold 100,000 counts: its place is the range control, once.
        served = component.values if characteristic.kind != "integer" else component.values[:1]
        _add(table, (*base, "components", component.index), map(place, served))


def selection_places(document: Document) -> Places:
    """The controls of everything in the selection's team file (``team.T.c[i]`` and up)."""
    table: Places = {"team": (Place(),)}
    team = document.data.get("team") if isinstance(document.data, dict) else None
    for kinematic_type, entry in (team or {}).items():
        name = str(kinematic_type)
        _add(table, ("team", name), [Place(name)])
        for characteristic, chosen in (entry or {}).items():
            where: tuple[PathPart, ...] = ("team", name, str(characteristic))
            _add(table, where, [Place(name, str(characteristic))])
            if isinstance(chosen, list):
                for index, value in enumerate(chosen):
                    _add(table, (*where, index), [Place(name, str(characteristic), str(value))])
    return table


def places(path: str, table: Places) -> tuple[Place, ...]:
    """The controls of a finding at ``path``: those of the longest known path it lies in
    (a component's ``min`` lies in the component); none when it lies in nothing known."""
    probe = path
    while probe:
        found = table.get(probe)
        if found is not None:
            return found
        cut = max(probe.rfind("."), probe.rfind("["))
        probe = probe[:cut] if cut > 0 else ""
    return ()


def place_data(place: Place) -> dict[str, str]:
    return {
        "type": place.kinematic_type,
        "characteristic": place.characteristic,
        "value": place.value,
    }
