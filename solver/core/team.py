"""Team selections: which values robots of each kinematic type in a team may have.

A team file names its rule set and, for every kinematic type present in the team, the values of
the other characteristics its robots may take::

    name: Case 1
    rules: ../paper.yaml        # optional, relative to this file; default: the shipped rules
    team:
      UAV:
        motion_control: [Flight, Waypoint]
        sensor_type: [2D Camera, 360 Camera, RGB-D Camera]
        sensor_count: 5         # a lone number for an integer characteristic: 1..5
    published:                  # optional: figures a publication reports for this team
      valid_robots: 30
      ui_configurations: 6

A characteristic a type does not mention may take every value of its domain. Selections use the
forms of :func:`solver.core.rules.read_selection`.

Not here: what the selection produces (:mod:`solver.solving.solution`).
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass, field
from pathlib import Path

from solver.collector import collector_paused
from solver.core.constraints import Value
from solver.core.rules import (
    default_rules_path,
    load_rules,
    read_selection,
    shipped_name,
    shipped_path,
)
from solver.core.ruleset import Characteristic, RuleSet, Run
from solver.errors import InputError, Location, TeamError, did_you_mean
from solver.files.filekind import require_kind
from solver.files.reader import Reader
from solver.files.yamlio import Document, load_document
from solver.limits import limit
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "Published",
    "Team",
    "TypeSelection",
    "full_team",
    "load_team",
    "parse_team",
    "resolve_team_path",
    "shipped_rule_sets",
    "shipped_rules_path",
]

_TEAM_KEYS = {"name", "description", "rules", "team", "published"}
_PUBLISHED_KEYS = {"source", "valid_robots", "ui_configurations"}


@dataclass(frozen=True, slots=True)
class TypeSelection:
    """The values robots of one kinematic type may have: one tuple per characteristic.

    ``domains`` follows the rule set's characteristic order, each tuple in domain order; the
    team key's tuple is just the kinematic type itself.
    """

    kinematic_type: str
    domains: tuple[tuple[Value, ...], ...]
    location: Location | None = field(default=None, compare=False)

    @property
    def size(self) -> int:
        """Robots the selection allows before any rule constraint is applied."""
        total = 1
        for domain in self.domains:
            total *= len(domain)
        return total


@dataclass(frozen=True, slots=True)
class Published:
    """Figures a publication reports for this team, to compare with what the rules give."""

    valid_robots: int
    ui_configurations: int
    source: str = ""


@dataclass(frozen=True)
class Team:
    """A team selection bound to the rule set it is read against."""

    name: str
    file: str
    rules: RuleSet
    selections: tuple[TypeSelection, ...]
    published: Published | None = None
    description: str = ""
    # The `team:` key in the file: where a refusal about the whole team points.
    location: Location | None = field(default=None, compare=False)

    def __repr__(self) -> str:  # short, for notebooks: the fields are one attribute away
        return (
            f"<Team {shown(self.name, quoted=True)} ({self.file}): "
            f"{', '.join(self.kinematic_types)}; "
            f"rules {shown(self.rules.name, quoted=True)}>"
        )

    def selection(self, kinematic_type: str) -> TypeSelection | None:
        return next((s for s in self.selections if s.kinematic_type == kinematic_type), None)

    @property
    def kinematic_types(self) -> tuple[str, ...]:
        return tuple(s.kinematic_type for s in self.selections)


def full_team(rules: RuleSet) -> Team:
    """The whole design space of a rule set: every kinematic type, every value selected."""
    key = rules.key_position
    selections = []
    for value in rules.key.values:
        domains = [c.values for c in rules.characteristics]
        domains[key] = (value,)
        selections.append(TypeSelection(str(value), tuple(domains), rules.key.location))
    return Team(
        f"every value of {rules.name}",
        rules.file,
        rules,
        tuple(selections),
        location=rules.key.location,
    )


def resolve_team_path(text: str) -> Path:
    """A team file path as given, or the name of a shipped team (``case3``) when no such file."""
    path = Path(text)
    # os.path's probes, not Path's: a name the system refuses (too long) is "not there" to
    # them, where Path's raise; reading the file then says what is wrong with it.
    if os.path.exists(path) or path.suffix:
        return path
    shipped = shipped_path("teams", f"{text}.yaml")
    return shipped if os.path.isfile(shipped) else path


def load_team(
    path: str | Path, rules: RuleSet | str | Path | None = None, *, display: str | None = None
) -> Team:
    """Read a team file and the rule set it refers to (or ``rules``, which overrides it).

    Raises :class:`TeamError` for the team file, :class:`RulesError` or :class:`InputError`
    for the rule set, each listing every problem found with its location.
    """
    if isinstance(path, str) and display is None:
        # A shipped team's name (``load_team("case3")``) as on the command line.
        resolved = resolve_team_path(path)
        display, path = (
            (shipped_name(resolved) or path, resolved) if resolved != Path(path) else (None, path)
        )
    document = load_document(path, display=display)
    return parse_team(document, rules, folder=Path(path).parent)


@collector_paused()  # building many values: see solver/collector.py
def parse_team(
    document: Document, rules: RuleSet | str | Path | None = None, *, folder: Path | None = None
) -> Team:
    """Build a :class:`Team` from a loaded document (see :func:`load_team`).

    A relative ``rules:`` path resolves against ``folder`` (default: the document's folder).
    A rule set or a profile raises :class:`InputError` saying so, not its fields as unknown.
    """
    require_kind(document, "team")
    reader = Reader(document)
    # Without `team:` the file may be anything (/etc/shadow parses as a mapping): none of
    # its keys is quoted as an unknown field.
    top = reader.top("team file", needs="team")
    if top is None:
        raise TeamError(reader.faults)
    reader.unknown_keys((), top, _TEAM_KEYS, "team file field")
    name = reader.string(("name",), "team name", required=False, default=Path(document.file).stem)
    description = reader.string(("description",), "description", required=False, limit=None)
    rule_set = _resolve_rules(
        reader, top, rules, Path(document.file).parent if folder is None else folder
    )
    published = _read_published(reader, top)
    selections = _read_selections(reader, rule_set) if rule_set is not None else ()
    if reader.faults or rule_set is None:
        raise TeamError(reader.faults)
    where = reader.document.location(("team",), key=True)
    return Team(name, document.file, rule_set, selections, published, description, where)


def _resolve_rules(
    reader: Reader, top: dict[str, object], rules: RuleSet | str | Path | None, folder: Path
) -> RuleSet | None:
    if isinstance(rules, RuleSet):
        return rules
    if rules is not None:
        return load_rules(rules)
    if "rules" not in top:
        return load_rules(default_rules_path(), display=shipped_name(default_rules_path()))
    text = reader.string(("rules",), "rules file", limit=None)
    if not text:
        return None
    relative = folder / text  # the OS resolves ".." (symlinks included); normpath is for show
    shipped = shipped_rules_path(text, folder)
    if shipped is not None:
        return load_rules(shipped)  # a shipped rule set by its name: `rules: extended`
    resolved = os.path.normpath(Path(reader.file).parent / text)
    try:
        return load_rules(relative, display=resolved)
    except InputError as error:
        if any(fault.location.line is not None for fault in error.faults):
            raise  # the rules file exists but is not valid YAML: its own faults say where
        reasons = "; ".join(fault.message for fault in error.faults)
        if not Path(text).suffix and "/" not in text:
            names = ", ".join(shipped_rule_sets())
            reasons += f" (a shipped rule set is named by its name: {names})"
        reader.fault(
            ("rules",),
            f"cannot use rules file {shown(text, quoted=True)} "
            f"(resolved to {shown(resolved, limit=SHOWN_FILE_NAME_CHARS)}): {reasons}",
            code="unknown-reference",
        )
        return None


def shipped_rules_path(text: str, folder: Path) -> Path | None:
    """The shipped rule set a team file's ``rules: NAME`` names (``extended`` is
    ``rules/extended.yaml`` of the package, wherever installed), else ``None``: a bare name
    (no folder, no suffix) that is no file beside the team and is a shipped rule set's name.
    So a team names a shipped set the same way on every machine."""
    if not text or "/" in text or "\\" in text or Path(text).suffix or text.startswith("."):
        return None
    if os.path.lexists(folder / text):
        return None  # a file of that name beside the team is what it names
    return shipped_path(f"{text}.yaml") if text in shipped_rule_sets() else None


@functools.cache
def shipped_rule_sets() -> tuple[str, ...]:
    """The names of the rule sets shipped with the package (``paper``, ``extended``, ...)."""
    from solver.files.filekind import file_kind

    found = []
    for path in sorted(shipped_path().glob("*.yaml")):
        if file_kind(load_document(path)) == "rules":
            found.append(path.stem)
    return tuple(found)


def _read_published(reader: Reader, top: dict[str, object]) -> Published | None:
    if "published" not in top:
        return None
    spec = reader.mapping(("published",), "published figures")
    reader.unknown_keys(("published",), spec, _PUBLISHED_KEYS, "published field")
    robots = reader.integer(("published", "valid_robots"), "published valid_robots")
    configurations = reader.integer(
        ("published", "ui_configurations"), "published ui_configurations"
    )
    source = reader.string(("published", "source"), "source", required=False, limit=None)
    for key, figure in (("valid_robots", robots), ("ui_configurations", configurations)):
        if figure is not None and figure < 0:
            reader.fault(
                ("published", key),
                f"published {key} must not be negative, got {figure}",
                code="out-of-range",
            )
    if robots is None or configurations is None or robots < 0 or configurations < 0:
        return None
    return Published(robots, configurations, source)


def _read_selections(reader: Reader, rules: RuleSet) -> tuple[TypeSelection, ...]:
    section = reader.mapping(("team",), "team (a mapping of kinematic type -> selections)")
    reader.within(limit("kinematic-types"), len(section), ("team",), key=True)
    key = rules.key
    if not section and isinstance(reader.get(("team",)), dict):
        reader.fault(("team",), "the team selects no kinematic type", code="empty-selection")
    found: dict[str, TypeSelection] = {}
    maxima = _Maxima()
    for type_name in section:
        path = ("team", type_name)
        if key.index(type_name) is None:
            reader.fault(
                path,
                f"unknown {key.label.lower()} {shown(type_name, quoted=True)}"
                f"{did_you_mean(type_name, [str(v) for v in key.values])}; "
                f"the rules ({rules.file}) have: "
                f"{', '.join(str(v) for v in key.values)}",
                key=True,
                code="unknown-reference",
            )
            continue
        selection = _read_type(reader, rules, type_name, maxima)
        if selection is not None:
            found[type_name] = selection
    return tuple(found[str(v)] for v in key.values if str(v) in found)


def _in_order(characteristic: Characteristic, allowed: frozenset[Value]) -> tuple[Value, ...]:
    """The values of ``characteristic`` in ``allowed``, in declared order.

    A team selecting up to 100,000 counts for each of 100 types would otherwise test every
    count in Python for every type: the whole domain is shared, a few values are sorted, and
    anything else is filtered at C speed.
    """
    values = characteristic.values
    if len(allowed) >= len(values) and allowed.issuperset(values):
        return values
    positions = characteristic.positions
    if 8 * len(allowed) < len(values):
        return tuple(sorted((v for v in allowed if v in positions), key=positions.__getitem__))
    return tuple(filter(allowed.__contains__, values))


class _Maxima:
    """``sensor_count: N`` selections (a maximum: 1..N) of one team file, each made once.

    A rule file's counts are a :class:`~solver.core.ruleset.Run`, so 1..N is a slice of them: no set
    of N counts is built and filtered per type, and types with the same maximum share one
    tuple, so reading follows the file rather than the counts.
    """

    def __init__(self) -> None:
        self.domains: dict[tuple[str, int], tuple[Value, ...]] = {}

    def domain(self, characteristic: Characteristic, raw: object) -> tuple[Value, ...] | None:
        """The values of ``characteristic`` up to ``raw``, or None: read it the general way
        (anything but a whole number in a run of counts, whose faults that reading reports)."""
        values = characteristic.values
        if not isinstance(values, Run) or (end := values.position(raw)) is None:
            return None
        key = (characteristic.name, end)
        if key not in self.domains:
            self.domains[key] = values[: end + 1]
        return self.domains[key]


def _read_type(
    reader: Reader, rules: RuleSet, type_name: str, maxima: _Maxima
) -> TypeSelection | None:
    path = ("team", type_name)
    raw = reader.get(path)
    if raw is None:
        reader.fault(
            path,
            f"no selections for {shown(type_name, quoted=True)}; list its characteristics' values "
            "(or write {} to allow every value)",
            code="empty-selection",
        )
        return None
    spec = reader.mapping(path, f"selections for {shown(type_name, quoted=True)}")
    others = [c.name for c in rules.characteristics if c.name != rules.team_key]
    if rules.team_key in spec:
        reader.fault(
            (*path, rules.team_key),
            f"{shown(rules.team_key, quoted=True)} is given by the entry itself "
            f"({shown(type_name, quoted=True)}); remove it",
            key=True,
        )
    reader.unknown_keys(
        path, {k: v for k, v in spec.items() if k != rules.team_key}, others, "characteristic"
    )
    domains: list[tuple[Value, ...]] = []
    complete = True
    for characteristic in rules.characteristics:
        if characteristic.name == rules.team_key:
            domains.append((type_name,))
        elif characteristic.name not in spec:
            domains.append(characteristic.values)
        elif (shared := maxima.domain(characteristic, spec[characteristic.name])) is not None:
            domains.append(shared)
        else:
            selection = read_selection(
                reader, (*path, characteristic.name), characteristic, exact=False, described=False
            )
            if selection is None:
                complete = False
                continue
            domains.append(_in_order(characteristic, selection[0]))
    if not complete:
        return None
    return TypeSelection(type_name, tuple(domains), reader.document.location(path, key=True))
