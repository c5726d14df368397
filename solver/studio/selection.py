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

A query is turned into a team by the library's own team reader
(:func:`solver.core.team.parse_team`), given the data of the team file it stands for
(:func:`team_data`; :func:`team_document` is that file), so every mistake is the located error a
team file would give (``team.UAV.motion_control[1]: unknown robot motion control 'Waypont' (did
you mean 'Waypoint'?)``), and :func:`query_of` is the inverse. The data goes to the reader as it
is, not written as YAML and parsed back (that cost a selection change half its time): only data
the YAML reader would refuse (a NUL, an unpaired surrogate, text or a number past its bounds) is
written and read back, so its refusal is the YAML reader's own, word for word.

Not here: which rule set an id names (:mod:`solver.studio.workspace`), solving.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import yaml

from solver import RuleSet, Team
from solver.core.team import parse_team
from solver.files.yamlio import MAX_KEY_CHARS, MAX_NODES, Document, parse_document
from solver.solving.teamfile import selection_form

__all__ = [
    "SELECTION_FILE",
    "Selection",
    "parse_query",
    "query_of",
    "team_data",
    "team_document",
    "team_of",
]

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
    names = tuple(sorted(rules.names, key=len, reverse=True))
    name = ""
    types: dict[str, None] = {}  # in the order given, each once
    values: dict[tuple[str, str], list[str]] = {}
    ranges: dict[tuple[str, str], list[str | None]] = {}
    for key, value in pairs:
        if key == "name":
            name = value
        elif key == "type":
            types.setdefault(value)
        elif key in _RESERVED or "." not in key:
            continue
        elif (found := _where(key, names)) is not None:
            where, end = found
            if end is None:
                values.setdefault(where, []).append(value)
            else:
                ranges.setdefault(where, [None, None])[end] = value
    return Selection(
        rules_id,
        name,
        tuple(types),
        tuple((k, tuple(v)) for k, v in values.items()),
        tuple((k, (v[0], v[1])) for k, v in ranges.items()),
    )


def _split(key: str, names: tuple[str, ...]) -> tuple[tuple[str, str], int | None] | None:
    """What a query key names: ((type, characteristic), 0 for ``.min``, 1 for ``.max``, None
    for a value), the longest characteristic name that ends it first; ``None``: nothing."""
    for characteristic in names:
        for suffix, end in ((".min", 0), (".max", 1), ("", None)):
            tail = f".{characteristic}{suffix}"
            if key.endswith(tail) and len(key) > len(tail):
                return (key[: -len(tail)], characteristic), end
    return None


# A page asks about the same few keys on every change: each short one is matched once.
_split_kept = functools.lru_cache(maxsize=1024)(_split)


def _where(key: str, names: tuple[str, ...]) -> tuple[tuple[str, str], int | None] | None:
    """:func:`_split`, kept for keys as short as names are (a stranger's long keys are not)."""
    return _split_kept(key, names) if len(key) <= MAX_KEY_CHARS else _split(key, names)


# A whole number as a query may write it: ASCII digits, one sign at most.
_WHOLE = re.compile(r"[+-]?[0-9]+")
# What the YAML reader refuses in a value or a key: a NUL, an unpaired surrogate.
_NOT_TEXT = re.compile("[\x00\ud800-\udfff]")
# Whole numbers past 2**63 mean nothing in a team file (the YAML reader refuses them).
_MAX_INT_BITS = 63


def _number(text: str) -> object:
    """A count as the team file would hold it: an int when it is one, else the text (whose
    error the reader then reports)."""
    stripped = text.strip()
    if len(stripped) < 20 and stripped.isascii() and _WHOLE.fullmatch(stripped):
        return int(stripped)
    return text


def team_data(selection: Selection, rules: RuleSet) -> dict[str, Any]:
    """The data of the team file a selection stands for (what :func:`team_document` writes)."""
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
    return {"name": selection.name or "studio team", "team": team}


def team_document(selection: Selection, rules: RuleSet) -> str:
    """The team file a selection stands for (YAML text; names written by the YAML emitter)."""
    document = team_data(selection, rules)
    return yaml.safe_dump(document, sort_keys=False, allow_unicode=True, width=2**31 - 1)


def team_of(selection: Selection, rules: RuleSet) -> Team:
    """The team a selection stands for, read as a team file is (located errors and all)."""
    data = team_data(selection, rules)
    if not _plain(data):
        # Something the YAML reader refuses: its refusal, exactly, from the file itself.
        return parse_team(parse_document(team_document(selection, rules), SELECTION_FILE), rules)
    return parse_team(Document(SELECTION_FILE, data), rules)


def _plain(data: dict[str, Any]) -> bool:
    """Whether the YAML reader would read ``data`` (:func:`team_data`'s), written as YAML, back
    as it is and without a fault: fewer keys and values than
    :data:`~solver.files.yamlio.MAX_NODES`, every number within 63 bits, every text and key at
    most :data:`~solver.files.yamlio.MAX_KEY_CHARS` characters (a longer value is rare enough
    to take the YAML way) without a NUL or an unpaired surrogate."""
    texts: list[str] = [data["name"]]
    numbers: list[int] = []
    for kinematic_type, entry in data["team"].items():
        texts.append(kinematic_type)
        for characteristic, chosen in entry.items():
            texts.append(characteristic)
            items = chosen if isinstance(chosen, list) else [chosen]
            if isinstance(chosen, dict):
                texts += chosen  # "min", "max"
                items = list(chosen.values())
            for item in items:
                (numbers if isinstance(item, int) else texts).append(item)
    return (
        len(texts) + len(numbers) < MAX_NODES
        and max(map(len, texts)) <= MAX_KEY_CHARS
        and not _NOT_TEXT.search("".join(texts))
        and all(number.bit_length() <= _MAX_INT_BITS for number in numbers)
    )


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
