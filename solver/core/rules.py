"""Reading rule set files: the YAML a user writes -> a :class:`~solver.core.ruleset.RuleSet`.

The README documents the format; :func:`load_rules` reads it, reporting every problem in the
file at once, each with its line and field. Nothing about the article's four characteristics is
known to the code: ``rules/paper.yaml`` is data like any other rule file.
:func:`read_selection` reads the forms a set of values takes in rule and team files.

Not here: the rule set's types (:mod:`solver.core.ruleset`), team files (:mod:`solver.core.team`).
"""

from __future__ import annotations

from _thread import allocate_lock
from collections.abc import Iterable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any, Literal

from solver.collector import collector_paused
from solver.core.constraints import Condition, RuleConstraint, Value
from solver.core.ruleset import Characteristic, Component, Kind, RuleSet, Run, one_component_each
from solver.errors import RulesError, did_you_mean
from solver.files.filekind import require_kind
from solver.files.inputfile import read_text
from solver.files.reader import Reader, type_name
from solver.files.yamlio import (
    MAX_FILE_BYTES,
    Document,
    PathPart,
    parse_document,
)
from solver.limits import limit
from solver.untrusted import shown

__all__ = [
    "default_rules_path",
    "load_rules",
    "parse_rules",
    "read_selection",
    "shipped_name",
    "shipped_path",
]

YPath = tuple[PathPart, ...]

_RULES_KEYS = {
    "name",
    "description",
    "source",
    "bound",
    "team_key",
    "characteristics",
    "constraints",
}
_CHARACTERISTIC_KEYS = {"label", "description", "values", "range", "components"}
_CATEGORICAL_COMPONENT_KEYS = {"name", "description", "values"}
_INTEGER_COMPONENT_KEYS = {"name", "description", "min", "above", "max", "below", "cluster_size"}
_CONSTRAINT_KEYS = {"name", "description", "when", "require", "forbid"}
_SELECTION_KEYS = {"min", "max", "not", "component"}


def shipped_path(*parts: str) -> Path:
    """A file shipped with the package (``rules/...``), wherever the package is installed."""
    return Path(__file__).parent.parent.joinpath("rules", *parts)


def shipped_name(path: Path) -> str | None:
    """``rules/teams/case3.yaml`` for a shipped file (wherever installed), else ``None``.

    Shipped files are shown by this stable name, not by their install location.
    """
    root = shipped_path().resolve()
    try:
        return "rules/" + path.resolve().relative_to(root).as_posix()
    except ValueError:
        return None


def default_rules_path() -> Path:
    """The article's rule set, used when a team file names no rules."""
    return shipped_path("paper.yaml")


def load_rules(path: str | Path, *, display: str | None = None) -> RuleSet:
    """Read a rule set file; :class:`RulesError` lists every problem with its location.

    A shipped rule set is shown by its stable name (``rules/paper.yaml``) unless ``display``.
    Rule sets read are kept by name and text (16 at most, each of at most 256 KB, the oldest
    dropped first), so a file read again unchanged is not parsed again; safe to call from many
    threads at once (the studio does)."""
    if display is None:
        display = shipped_name(Path(path))
    name = display if display is not None else str(path)
    text = read_text(path, display=name, limit=MAX_FILE_BYTES, what="YAML file")
    # Teams that share a rule set (a batch, the studio, a loop over the Python API) read it
    # once per process while its text stays the same: the text is the key, so an edited file
    # is read again. A RuleSet is a frozen value, safe to share.
    key = (name, text)
    with _READ_LOCK:
        found = _READ.get(key)
    if found is not None:
        return found
    # Parsed outside the lock: threads reading other files are not held up. Two threads that
    # read the same new file at once both parse it, and the first one kept stays.
    found = parse_rules(parse_document(text, name))
    if len(text) <= _KEPT_CHARS:
        with _READ_LOCK:
            kept = _READ.setdefault(key, found)
            while len(_READ) > _KEPT_FILES:
                del _READ[next(iter(_READ))]  # the oldest
        return kept
    return found


# Rule sets read in this process by (shown name, text): at most _KEPT_FILES, of at most
# _KEPT_CHARS characters each (the shipped ones are under 10,000). The studio reads from many
# threads: every look into _READ and every change to it holds _READ_LOCK.
_READ: dict[tuple[str, str], RuleSet] = {}
_READ_LOCK = allocate_lock()  # threading's Lock, without importing threading
_KEPT_FILES = 16
_KEPT_CHARS = 1 << 18


@collector_paused()  # building many values: see solver/collector.py
def parse_rules(document: Document) -> RuleSet:
    """Build a :class:`RuleSet` from an already loaded document.

    Raises :class:`InputError` for a team file or a profile (they are no broken rule sets)."""
    require_kind(document, "rules")
    reader = Reader(document)
    top = reader.top("rule set", needs="characteristics")
    if top is None:
        raise RulesError(reader.faults)
    reader.unknown_keys((), top, _RULES_KEYS, "rule set field")
    name = reader.string(
        ("name",), "rule set name", required=False, default=Path(document.file).stem
    )
    description = reader.string(("description",), "description", required=False, limit=None)
    source = reader.string(("source",), "source", required=False, limit=None)
    bound = reader.integer(("bound",), "bound", required=False)
    if bound is not None and bound < 1:
        reader.fault(("bound",), f"bound must be positive, got {bound}", code="out-of-range")

    characteristics = _read_characteristics(reader)
    by_name = {c.name: c for c in characteristics}
    team_key = _read_team_key(reader, top, characteristics)
    constraints = _read_constraints(reader, by_name)
    if reader.faults:
        raise RulesError(reader.faults)
    return RuleSet(
        name=name,
        file=document.file,
        characteristics=tuple(characteristics),
        team_key=team_key,
        constraints=tuple(constraints),
        declared_bound=bound,
        description=description,
        source=source,
        document=document,
    )


def _read_team_key(
    reader: Reader, top: dict[str, Any], characteristics: list[Characteristic]
) -> str:
    if not characteristics:
        return ""
    names = [c.name for c in characteristics]
    key = reader.string(("team_key",), "team_key") if "team_key" in top else names[0]
    if key not in names:
        reader.fault(
            ("team_key",),
            f"team_key names no characteristic: "
            f"{shown(key, quoted=True)}{did_you_mean(key, names)}",
            code="unknown-reference",
        )
        return characteristics[0].name
    chosen = characteristics[names.index(key)]
    if chosen.kind != "categorical":
        reader.fault(
            ("team_key",),
            f"team_key {shown(key, quoted=True)} must be a categorical characteristic "
            "(a list of values); without a team_key it is the first "
            "characteristic",
            code="invalid",
        )
    if chosen.declared_components:
        reader.fault(
            ("characteristics", key, "components"),
            f"{shown(key, quoted=True)} is the team key: each of its values is its own component, "
            "so it cannot declare components",
            code="invalid",
        )
    return key


def _read_characteristics(reader: Reader) -> list[Characteristic]:
    section = reader.mapping(
        ("characteristics",), "characteristics (a mapping of name -> definition)"
    )
    if not section and isinstance(reader.get(("characteristics",)), dict):
        reader.fault(
            ("characteristics",),
            "a rule set needs at least one characteristic",
            code="missing-field",
        )
    reader.within(limit("characteristics"), len(section), ("characteristics",), key=True)
    found = []
    # Ranges are no YAML values, so the reader's bound does not hold them: count them here.
    values = 0
    components = 0
    for name in section:
        if not name.strip() or not name.isprintable():
            reader.fault(
                ("characteristics", name),
                "a characteristic needs a name of visible characters, "
                f"got {shown(name, quoted=True)}",
                key=True,
                code="invalid",
            )
            continue
        characteristic = _read_characteristic(reader, ("characteristics", name), name)
        if characteristic is not None:
            found.append(characteristic)
            values += len(characteristic.values)
            reader.within(limit("all-values"), values, ("characteristics", name), key=True)
            if characteristic.declared_components:
                components += len(characteristic.components)
                reader.within(limit("components"), components, ("characteristics", name), key=True)
    return found


def _read_characteristic(reader: Reader, path: YPath, name: str) -> Characteristic | None:
    spec = reader.mapping(path, f"characteristic {shown(name, quoted=True)}")
    if not spec:
        return None
    reader.unknown_keys(path, spec, _CHARACTERISTIC_KEYS, "characteristic field")
    label = reader.string((*path, "label"), "label", required=False, default=name)
    description = reader.string((*path, "description"), "description", required=False, limit=None)
    location = reader.document.location(path, key=True)
    if ("values" in spec) == ("range" in spec):
        reader.fault(
            path,
            f"characteristic {shown(name, quoted=True)} needs exactly one of 'values' (named "
            "values) or 'range' (whole numbers)",
            code="missing-field",
        )
        return None
    kind: Kind
    if "values" in spec:
        kind = "categorical"
        values: tuple[Value, ...] = _read_categorical_values(reader, (*path, "values"), name)
    else:
        kind = "integer"
        values = _read_integer_range(reader, (*path, "range"), name)
    if not values:
        return None
    components: Sequence[Component]
    membership: Sequence[tuple[int, ...]]
    if "components" in spec:
        components = _read_components(reader, (*path, "components"), name, kind, values)
        declared = True
        holders: dict[Value, list[int]] = {}
        for component in components:
            for value in component.values:
                holders.setdefault(value, []).append(component.index)
        membership = tuple(tuple(holders.get(value, ())) for value in values)
    else:  # value i is component i, made when asked for (100,000 counts are common)
        components, membership = one_component_each(values)
        declared = False
    return Characteristic(
        name=name,
        label=label,
        kind=kind,
        values=values,
        components=components,
        membership=membership,
        declared_components=declared,
        description=description,
        location=location,
    )


def _read_categorical_values(reader: Reader, path: YPath, name: str) -> tuple[str, ...]:
    raw = reader.get(path)
    if isinstance(raw, list):
        reader.within(limit("values"), len(raw), path, noun=f"values of {shown(name, quoted=True)}")
    items = reader.names(path, f"values of {shown(name, quoted=True)}")
    seen: dict[str, YPath] = {}
    for item_path, value in items:
        if not value:
            reader.fault(item_path, "empty value name", code="wrong-type")
        elif value in seen:
            reader.fault(
                item_path,
                f"duplicate value {shown(value, quoted=True)} in {shown(name, quoted=True)} "
                f"(first at "
                f"{reader.document.location(seen[value])})",
                code="duplicate-value",
            )
        else:
            seen[value] = item_path
    if not seen and reader.get(path) is not None:
        reader.fault(
            path, f"characteristic {shown(name, quoted=True)} has no values", code="empty-selection"
        )
    return tuple(seen)


def _read_integer_range(reader: Reader, path: YPath, name: str) -> Run | tuple[()]:
    raw = reader.get(path)
    low: int | None
    high: int | None
    if isinstance(raw, list):
        # A list is a set of values everywhere else (a team's `sensor_count: [2, 6]` is {2, 6});
        # so a range has one spelling, a mapping, and `[1, 50]` here is refused, not guessed.
        listed = ", ".join(str(item) for item in raw) if len(raw) <= 4 else "..."
        example = f"{{min: {raw[0]}, max: {raw[1]}}}" if len(raw) == 2 else "{min: 1, max: 50}"
        reader.fault(
            path,
            f"range of {shown(name, quoted=True)} is a list ([{listed}]), but a list means a set "
            f"of values (a team's `{name}: [2, 6]` is 2 and 6); write the range "
            f"as {example}",
            code="wrong-type",
        )
        return ()
    if not isinstance(raw, dict):
        reader.fault(
            path,
            f"range of {shown(name, quoted=True)} must be {{min: a, max: b}}, got {type_name(raw)}",
            code="wrong-type",
        )
        return ()
    spec = reader.mapping(path, "range")
    reader.unknown_keys(path, spec, {"min", "max"}, "range field")
    low = reader.integer((*path, "min"), f"{name} range minimum")
    high = reader.integer((*path, "max"), f"{name} range maximum")
    if low is None or high is None:
        return ()
    if low > high:
        reader.fault(
            path,
            f"range of {shown(name, quoted=True)} is inverted: min {low} > max {high}",
            code="out-of-range",
        )
        return ()
    reader.within(
        limit("values"),
        high - low + 1,
        path,
        noun=f"values in the range of {shown(name, quoted=True)}",
    )
    return Run(range(low, high + 1))


def _read_components(
    reader: Reader, path: YPath, name: str, kind: Kind, values: tuple[Value, ...]
) -> tuple[Component, ...]:
    raw = reader.get(path)
    if not isinstance(raw, list) or not raw:
        reader.fault(
            path,
            f"components of {shown(name, quoted=True)} must be a non-empty list, got "
            f"{type_name(raw)}",
            code="wrong-type",
        )
        return ()
    reader.within(limit("components"), len(raw), path, noun=f"components of {name!r}")
    # Each value's position, made once: a component's members are looked up and put in domain
    # order in the time of its own values (20,000 components took minutes when each walked the
    # whole domain).
    positions = {str(value): index for index, value in enumerate(values)}
    components: list[Component] = []
    names: dict[str, YPath] = {}
    for index in range(len(raw)):
        item_path = (*path, index)
        spec = reader.mapping(item_path, "component")
        if not spec:
            continue
        allowed = _CATEGORICAL_COMPONENT_KEYS if kind == "categorical" else _INTEGER_COMPONENT_KEYS
        reader.unknown_keys(item_path, spec, allowed, f"{kind} component field")
        component_name = reader.string((*item_path, "name"), "component name")
        if component_name in names:
            first = reader.document.location(names[component_name])
            reader.fault(
                (*item_path, "name"),
                f"duplicate component {shown(component_name, quoted=True)} (first at {first})",
                code="duplicate-value",
            )
        names.setdefault(component_name, (*item_path, "name"))
        description = reader.string(
            (*item_path, "description"), "description", required=False, limit=None
        )
        component = Component(
            component_name,
            len(components),
            (),
            description,
            location=reader.document.location(item_path),
        )
        if kind == "categorical":
            members = _read_members(reader, (*item_path, "values"), name, values, positions)
            components.append(replace(component, values=members))
        else:
            components.append(_read_arrangement(reader, item_path, component, values))
    return tuple(components)


def _read_members(
    reader: Reader,
    path: YPath,
    name: str,
    values: tuple[Value, ...],
    positions: dict[str, int],
) -> tuple[Value, ...]:
    members: set[str] = set()
    for item_path, value in reader.names(path, "component values"):
        if value not in positions:
            reader.fault(
                item_path,
                f"unknown {name} value {shown(value, quoted=True)}{did_you_mean(value, positions)}",
                code="unknown-reference",
            )
        elif value in members:
            reader.fault(
                item_path,
                f"{shown(value, quoted=True)} is listed twice in this component",
                code="duplicate-value",
            )
        members.add(value)
    return tuple(values[i] for i in sorted(positions[v] for v in members if v in positions))


def _read_arrangement(
    reader: Reader, path: YPath, component: Component, values: tuple[Value, ...]
) -> Component:
    """``component`` with the range, cluster size and member counts its spec declares."""
    spec = reader.mapping(path, "component")
    low = _read_end(reader, path, spec, inclusive="min", exclusive="above", step=1)
    high = _read_end(reader, path, spec, inclusive="max", exclusive="below", step=-1)
    if not spec.keys() & {"min", "above", "max", "below"}:
        reader.fault(
            path,
            f"arrangement {shown(component.name, quoted=True)} needs a range: "
            "min/above and/or max/below",
            code="missing-field",
        )
    cluster_size = _read_cluster_size(reader, path, spec)
    members = _counts_within(values, low, high)
    return replace(component, values=members, low=low, high=high, cluster_size=cluster_size)


def _read_end(
    reader: Reader,
    path: YPath,
    spec: dict[str, Any],
    *,
    inclusive: Literal["min", "max"],
    exclusive: Literal["above", "below"],
    step: Literal[1, -1],
) -> int | None:
    """One end of an arrangement's range, inclusive as declared (``above: 5`` is ``min: 6``),
    or None where the spec leaves it open; giving both spellings is a fault."""
    if inclusive in spec and exclusive in spec:
        reader.fault(
            path,
            f"give either '{inclusive}' (inclusive) or '{exclusive}' (exclusive), not both",
        )
    if inclusive in spec:
        return reader.integer((*path, inclusive), inclusive)
    if exclusive in spec:
        bound = reader.integer((*path, exclusive), exclusive)
        return None if bound is None else bound + step
    return None


def _read_cluster_size(reader: Reader, path: YPath, spec: dict[str, Any]) -> int:
    """How many counts one UI element shows: the spec's ``cluster_size``, 1 by default."""
    if "cluster_size" not in spec:
        return 1
    size = reader.integer((*path, "cluster_size"), "cluster_size")
    if size is None:
        return 1
    if size < 1:
        reader.fault(
            (*path, "cluster_size"),
            f"cluster_size must be at least 1, got {size}",
            code="out-of-range",
        )
        return 1
    return size


def _counts_within(
    values: tuple[Value, ...], low: int | None, high: int | None
) -> tuple[Value, ...]:
    """The counts of ``values`` in ``low..high`` (an open end reaches the run's own end).

    The counts are a run low..high: the members are a slice of it, found by arithmetic."""
    first, last = int(values[0]), int(values[-1])
    start = first if low is None else max(low, first)
    stop = last if high is None else min(high, last)
    return tuple(values[start - first : stop - first + 1]) if start <= stop else ()


def _read_constraints(
    reader: Reader, characteristics: dict[str, Characteristic]
) -> list[RuleConstraint]:
    raw = reader.get(("constraints",))
    if raw is None:
        return []
    if not isinstance(raw, list):
        reader.fault(
            ("constraints",), f"constraints must be a list, got {type_name(raw)}", code="wrong-type"
        )
        return []
    reader.within(limit("constraints"), len(raw), ("constraints",), key=True)
    found = []
    named = 0  # values the conditions name: a {min, max} over 100,000 counts names them all
    for index in range(len(raw)):
        constraint = _read_constraint(reader, ("constraints", index), index, characteristics)
        if constraint is not None:
            found.append(constraint)
            named += sum(len(c.allowed) for c in (*constraint.when, *constraint.conditions))
            reader.within(limit("condition-values"), named, ("constraints", index))
    return found


def _read_constraint(
    reader: Reader, path: YPath, index: int, characteristics: dict[str, Characteristic]
) -> RuleConstraint | None:
    spec = reader.mapping(path, "constraint")
    if not spec:
        return None
    reader.unknown_keys(path, spec, _CONSTRAINT_KEYS, "constraint field")
    name = reader.string(
        (*path, "name"), "constraint name", required=False, default=f"constraint {index + 1}"
    )
    location = reader.document.location(path)
    if ("require" in spec) == ("forbid" in spec):
        reader.fault(
            path, "a constraint needs exactly one of 'require' or 'forbid'", code="missing-field"
        )
        return None
    if "forbid" in spec and "when" in spec:
        reader.fault(
            (*path, "when"),
            "'when' goes with 'require'; a 'forbid' rule already "
            "lists the whole forbidden combination",
        )
        return None
    when = _read_conditions(reader, (*path, "when"), characteristics) if "when" in spec else ()
    kind: Literal["require", "forbid"] = "forbid" if "forbid" in spec else "require"
    conditions = _read_conditions(reader, (*path, kind), characteristics)
    if not conditions:
        return None
    return RuleConstraint(name, kind, when, conditions, location)


def _read_conditions(
    reader: Reader, path: YPath, characteristics: dict[str, Characteristic]
) -> tuple[Condition, ...]:
    spec = reader.mapping(path, "conditions (a mapping of characteristic -> values)")
    if not spec and isinstance(reader.get(path), dict):
        reader.fault(path, "no conditions given", code="empty-selection")
    conditions = []
    for name in spec:
        if name not in characteristics:
            reader.fault(
                (*path, name),
                f"unknown characteristic "
                f"{shown(name, quoted=True)}{did_you_mean(name, characteristics)}",
                key=True,
                code="unknown-reference",
            )
            continue
        selection = read_selection(reader, (*path, name), characteristics[name], exact=True)
        if selection is not None:
            conditions.append(Condition(name, selection[0], selection[1]))
    return tuple(conditions)


def read_selection(
    reader: Reader,
    path: YPath,
    characteristic: Characteristic,
    *,
    exact: bool,
    described: bool = True,
) -> tuple[frozenset[Value], str] | None:
    """A set of values of ``characteristic`` as a rule or team file writes it.

    Forms: one value; a list of values; or a mapping with any of ``min``/``max`` (integers),
    ``not`` (values to leave out) and ``component`` (the values of named components), which
    are intersected. A lone whole number means exactly that count when ``exact`` (constraints)
    and "1..N", a maximum, when not (team files: ``sensor_count: 5``).
    Returns the allowed set and a short text for messages (empty for a list or a value when not
    ``described``: a team's selections are never quoted), or ``None`` after recording faults.
    """
    raw = reader.get(path)
    if isinstance(raw, dict):
        return _read_selection_mapping(reader, path, characteristic, raw)
    if isinstance(raw, list):
        if not raw:
            reader.fault(
                path,
                f"empty selection for {shown(characteristic.name, quoted=True)}",
                code="empty-selection",
            )
            return None
        chosen: dict[Value, None] = {}  # in the order written; a set to find twice-listed
        before = len(reader.faults)
        for index, item in enumerate(raw):
            value = _read_value(reader, (*path, index), characteristic, item)
            if value is not None and value in chosen:
                reader.fault(
                    (*path, index),
                    f"{shown(value, quoted=True)} is listed twice",
                    code="duplicate-value",
                )
            elif value is not None:
                chosen[value] = None
        if len(reader.faults) > before:
            return None
        return frozenset(chosen), _describe(characteristic, list(chosen)) if described else ""
    if raw is None:
        reader.fault(
            path,
            f"no values selected for {shown(characteristic.name, quoted=True)}",
            code="empty-selection",
        )
        return None
    if (
        characteristic.kind == "integer"
        and not exact
        and isinstance(raw, int)
        and not isinstance(raw, bool)
    ):
        return _read_maximum(reader, path, characteristic, raw)
    value = _read_value(reader, path, characteristic, raw)
    if value is None:
        return None
    return frozenset({value}), _describe(characteristic, [value]) if described else ""


def _read_maximum(
    reader: Reader, path: YPath, characteristic: Characteristic, maximum: int
) -> tuple[frozenset[Value], str] | None:
    low, high = int(characteristic.values[0]), int(characteristic.values[-1])
    if maximum < low:
        reader.fault(
            path,
            f"{characteristic.name} maximum must be at least {low}, got {maximum}",
            code="out-of-range",
        )
        return None
    if maximum > high:
        reader.fault(
            path,
            f"{characteristic.name} maximum {maximum} exceeds the rule set's maximum of {high}",
            code="out-of-range",
        )
        return None
    return frozenset(range(low, maximum + 1)), f"in {low}..{maximum}"


def _read_value(
    reader: Reader, path: YPath, characteristic: Characteristic, raw: Any
) -> Value | None:
    if characteristic.kind == "integer":
        if isinstance(raw, bool) or not isinstance(raw, int):
            reader.fault(
                path,
                f"{characteristic.name} values are whole numbers, got {type_name(raw)}",
                code="wrong-type",
            )
            return None
        if characteristic.index(raw) is None:
            low, high = characteristic.values[0], characteristic.values[-1]
            reader.fault(
                path,
                f"{characteristic.name} {raw} is outside the rule set's range {low}..{high}",
                code="out-of-range",
            )
            return None
        return int(raw)
    if isinstance(raw, bool) or not isinstance(raw, str | int | float):
        reader.fault(
            path, f"{characteristic.name} values are names, got {type_name(raw)}", code="wrong-type"
        )
        return None
    text = str(raw).strip()
    if characteristic.index(text) is None:
        names = [str(v) for v in characteristic.values]
        reader.fault(
            path,
            f"unknown {characteristic.label.lower()} "
            f"{shown(text, quoted=True)}{did_you_mean(text, names)}",
            code="unknown-reference",
        )
        return None
    return text


def _read_selection_mapping(
    reader: Reader, path: YPath, characteristic: Characteristic, spec: dict[Any, Any]
) -> tuple[frozenset[Value], str] | None:
    keys = {str(k): v for k, v in spec.items()}
    reader.unknown_keys(path, keys, _SELECTION_KEYS, "selection field")
    allowed: set[Value] = set(characteristic.values)
    parts = []
    before = len(reader.faults)
    if "min" in keys or "max" in keys:
        allowed, text = _read_bounds(reader, path, characteristic, allowed)
        parts.append(text)
    if "component" in keys:
        members: set[Value] = set()
        named = reader.names((*path, "component"), "component names")
        for item_path, name in named:
            component = characteristic.component(name)
            if component is None:
                names = [c.name for c in characteristic.components]
                reader.fault(
                    item_path,
                    f"unknown {characteristic.name} component "
                    f"{shown(name, quoted=True)}{did_you_mean(name, names)}",
                    code="unknown-reference",
                )
            else:
                members.update(component.values)
        allowed &= members
        parts.append("in component " + ", ".join(repr(name) for _, name in named))
    if "not" in keys:
        raw = keys["not"]
        items = list(enumerate(raw)) if isinstance(raw, list) else [(None, raw)]
        excluded: list[Value] = []
        for index, item in items:
            item_path = (*path, "not") if index is None else (*path, "not", index)
            value = _read_value(reader, item_path, characteristic, item)
            if value is not None:
                excluded.append(value)
        allowed -= set(excluded)
        parts.append("not in " + _set_text(characteristic, excluded))
    if len(reader.faults) > before:
        return None
    if not allowed:
        reader.fault(
            path,
            f"selection for {shown(characteristic.name, quoted=True)} leaves no values",
            code="empty-selection",
        )
        return None
    return frozenset(allowed), " and ".join(parts)


def _read_bounds(
    reader: Reader, path: YPath, characteristic: Characteristic, allowed: set[Value]
) -> tuple[set[Value], str]:
    """``allowed`` cut to a selection's ``min``/``max``, and how to say it."""
    if characteristic.kind != "integer":
        reader.fault(
            path,
            f"min/max apply to whole-number characteristics; "
            f"{shown(characteristic.name, quoted=True)} has named values",
            code="wrong-type",
        )
        return allowed, ""
    low = reader.integer((*path, "min"), "min", required=False)
    high = reader.integer((*path, "max"), "max", required=False)
    first, last = int(characteristic.values[0]), int(characteristic.values[-1])
    for key, bound in (("min", low), ("max", high)):
        if bound is not None and not first <= bound <= last:
            reader.fault(
                (*path, key),
                f"{characteristic.name} {key} {bound} is outside the "
                f"rule set's range {first}..{last}",
                code="out-of-range",
            )
    kept: set[Value] = {
        v
        for v in allowed
        if isinstance(v, int) and (low is None or v >= low) and (high is None or v <= high)
    }
    return kept, f"in {'' if low is None else low}..{'' if high is None else high}"


def _set_text(characteristic: Characteristic, values: Iterable[Value]) -> str:
    chosen = set(values)
    return "{" + ", ".join(str(v) for v in characteristic.values if v in chosen) + "}"


def _describe(characteristic: Characteristic, values: list[Value]) -> str:
    if len(set(values)) == 1:
        return f"is {values[0]}"
    return "in " + _set_text(characteristic, values)
