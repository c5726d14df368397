"""A team selection in a URL's query string, and back: the page's state is its address.

The query holds what a team file holds, so a state can be bookmarked and shared:

==============================  ===============================================================
``rules=ID``                    the rule set (a shipped one by name, ``start``, an upload)
``name=TEXT``                   the team's name
``type=T``                      a kinematic type in the team (repeated, one per type)
``T.c=V``                       a value of characteristic ``c`` that type ``T`` may have
                                (repeated); no ``T.c`` at all: every value; only empty ones:
                                none (a located error, as an empty list in a team file is)
``T.c.min=A``, ``T.c.max=B``    a whole-number characteristic's range (a lone maximum reads
                                as ``first..B``, as ``sensor_count: 5`` does in a team file)
==============================  ===============================================================

A query is turned into a team by writing the team file it stands for and reading that with the
library's own reader (:func:`solver.core.team.parse_team`), so every mistake is the located
error a team file would give (``team.UAV.motion_control[1]: unknown robot motion control
'Waypont' (did you mean 'Waypoint'?)``), and :func:`query_of` is the inverse.

Not here: which rule set an id names (:mod:`solver.studio.workspace`), solving.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import yaml

from solver import RuleSet, Team
from solver.core.team import parse_team
from solver.files.yamlio import parse_document
from solver.solving.teamfile import selection_form

__all__ = ["SELECTION_FILE", "Selection", "parse_query", "query_of", "team_of"]

# How a selection is named in messages: it is no file (``<selection>: team.UAV...: ...``).
SELECTION_FILE = "<selection>"
# Parameters that are not part of a team: the view, paging, a robot to look up.
_RESERVED = frozenset({"rules", "name", "type"})


@dataclass(frozen=True)
class Selection:
    """What a query string selects, still as text: ``values[(type, characteristic)]``."""

    rules: str
    name: str
    types: tuple[str, ...]
    values: tuple[tuple[tuple[str, str], tuple[str, ...]], ...]
    ranges: tuple[tuple[tuple[str, str], tuple[str | None, str | None]], ...]


def parse_query(pairs: Iterable[tuple[str, str]], rules: RuleSet, rules_id: str) -> Selection:
    """The selection in query ``pairs`` (names matched against ``rules``' characteristics)."""
    names = sorted(rules.names, key=len, reverse=True)
    name = ""
    types: list[str] = []
    values: dict[tuple[str, str], list[str]] = {}
    ranges: dict[tuple[str, str], list[str | None]] = {}
    for key, value in pairs:
        if key == "name":
            name = value
        elif key == "type":
            if value not in types:
                types.append(value)
        elif key in _RESERVED or "." not in key:
            continue
        else:
            _place(key, value, names, values, ranges)
    return Selection(
        rules_id,
        name,
        tuple(types),
        tuple((k, tuple(v)) for k, v in values.items()),
        tuple((k, (v[0], v[1])) for k, v in ranges.items()),
    )


def _place(
    key: str,
    value: str,
    names: Sequence[str],
    values: dict[tuple[str, str], list[str]],
    ranges: dict[tuple[str, str], list[str | None]],
) -> None:
    for characteristic in names:
        for suffix, end in ((".min", 0), (".max", 1), ("", None)):
            tail = f".{characteristic}{suffix}"
            if key.endswith(tail) and len(key) > len(tail):
                where = (key[: -len(tail)], characteristic)
                if end is None:
                    values.setdefault(where, []).append(value)
                else:
                    ranges.setdefault(where, [None, None])[end] = value
                return


def _number(text: str) -> object:
    """A count as the team file would hold it: an int when it is one, else the text (whose
    error the reader then reports)."""
    stripped = text.strip()
    if stripped.isascii() and stripped.lstrip("+-").isdigit() and len(stripped) < 20:
        return int(stripped)
    return text


def team_document(selection: Selection, rules: RuleSet) -> str:
    """The team file a selection stands for (YAML text; names written by the YAML emitter)."""
    values = dict(selection.values)
    ranges = dict(selection.ranges)
    team: dict[str, dict[str, object]] = {}
    for kinematic_type in selection.types:
        entry: dict[str, object] = {}
        for characteristic in rules.characteristics:
            where = (kinematic_type, characteristic.name)
            if characteristic.name == rules.team_key:
                continue
            if where in values:
                chosen = [v for v in values[where] if v != ""]
                if characteristic.kind == "integer":
                    entry[characteristic.name] = [_number(v) for v in chosen]
                else:
                    entry[characteristic.name] = chosen
            elif characteristic.kind == "integer" and where in ranges:
                low, high = ranges[where]
                if low is None and high is not None:
                    entry[characteristic.name] = _number(high)
                else:
                    bounds = {"min": low, "max": high}
                    entry[characteristic.name] = {
                        k: _number(v) for k, v in bounds.items() if v is not None
                    }
        team[kinematic_type] = entry
    document = {"name": selection.name or "studio team", "team": team}
    return yaml.safe_dump(document, sort_keys=False, allow_unicode=True, width=2**31 - 1)


def team_of(selection: Selection, rules: RuleSet) -> Team:
    """The team a selection stands for, read as a team file is (located errors and all)."""
    text = team_document(selection, rules)
    return parse_team(parse_document(text, SELECTION_FILE), rules)


def query_of(team: Team, rules_id: str) -> list[tuple[str, str]]:
    """The query pairs that select ``team`` (the inverse of :func:`parse_query` and
    :func:`team_of`): characteristics left open are left out."""
    rules = team.rules
    pairs = [("rules", rules_id), ("name", team.name)]
    for selection in team.selections:
        pairs.append(("type", selection.kinematic_type))
    for selection in team.selections:
        prefix = selection.kinematic_type
        for characteristic, domain in zip(rules.characteristics, selection.domains, strict=True):
            if characteristic.name == rules.team_key:
                continue
            form = selection_form(characteristic, domain)
            key = f"{prefix}.{characteristic.name}"
            if form is None:
                continue
            if isinstance(form, int):
                pairs.append((f"{key}.max", str(form)))
            elif isinstance(form, dict):
                pairs += [(f"{key}.min", str(form["min"])), (f"{key}.max", str(form["max"]))]
            elif isinstance(form, list):
                pairs += [(key, str(value)) for value in form]
    return pairs
