"""What one running studio holds: the rule sets it may use, what it was started with, uploads,
and the solutions it has already computed.

The studio reads only what its user named at start (a team or rule set, ``--fleet`` folders)
and the rule sets shipped with the package. Everything else arrives as an upload: written into
the studio's own private folder (mode 0700, removed at exit) under a name of the studio's
making, then read back through the project's bounded readers, as a file named on the command
line would be. No request names a path: rule sets, fleets and folders are chosen by id.

Solutions are cached by the team file a selection stands for, so a page, its charts and its
JSON ask the library once.

Not here: the URL form of a selection (:mod:`solver.studio.selection`), HTTP.
"""

from __future__ import annotations

import dataclasses
import hashlib
import re
import shutil
import tempfile
import threading
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Literal, TypeVar

from solver.core.forbidden import Removed, excluded_by_rules
from solver.core.reproduce import published_for
from solver.core.rules import load_rules, shipped_name, shipped_path
from solver.core.ruleset import RuleSet
from solver.core.solution import Solution, solve
from solver.core.team import Team, load_team
from solver.errors import InputError
from solver.files.filekind import file_kind
from solver.files.yamlio import MAX_FILE_BYTES, load_document
from solver.studio.selection import SELECTION_FILE, Selection, team_of
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from solver.identify.fleet import Fleet

__all__ = [
    "MAX_FILE_BYTES",
    "MAX_UPLOAD_BYTES",
    "MAX_UPLOAD_FILES",
    "RuleSource",
    "Upload",
    "Workspace",
    "safe_file_name",
]

# One request's body (every file of an upload together) at most, and files per upload.
MAX_UPLOAD_BYTES = 64 * 1024 * 1024
MAX_UPLOAD_FILES = 64
# Uploaded rule sets and identified fleets kept (the oldest are dropped first).
MAX_KEPT_RULE_SETS = 32
MAX_KEPT_FLEETS = 8
# Solutions kept by the team they solve.
MAX_KEPT_SOLUTIONS = 128

Origin = Literal["shipped", "start", "upload"]
K = TypeVar("K")
V = TypeVar("V")


@dataclass(frozen=True)
class RuleSource:
    """A rule set the studio may use, under the id a URL names it by."""

    id: str
    rules: RuleSet
    path: Path
    origin: Origin

    @property
    def label(self) -> str:
        where = {"shipped": "shipped", "start": "given at start", "upload": "uploaded"}
        return f"{self.rules.name} ({shown_name(self.rules.file)}, {where[self.origin]})"


@dataclass(frozen=True)
class Upload:
    """One uploaded file: the name its sender gave it, and its bytes."""

    name: str
    data: bytes


class _Kept(OrderedDict[K, V]):
    """A dictionary that keeps its newest ``size`` entries."""

    def __init__(self, size: int) -> None:
        super().__init__()
        self.size = size

    def keep(self, key: K, value: V) -> V:
        self[key] = value
        self.move_to_end(key)
        while len(self) > self.size:
            self.popitem(last=False)
        return value


_SAFE = re.compile(r"[^A-Za-z0-9._-]")


def safe_file_name(name: str) -> str:
    """A file name of the studio's making for an upload called ``name``: its last path part,
    letters, digits, ``.``, ``_`` and ``-`` only, no leading dot, at most 100 characters."""
    base = re.split(r"[/\\]", name)[-1]
    cleaned = _SAFE.sub("_", base).lstrip(".")[-100:]
    return cleaned or "upload"


def shown_name(name: str) -> str:
    """A file name as a message shows it (escaped, cut)."""
    return shown(name, limit=SHOWN_FILE_NAME_CHARS)


class Workspace:
    """The studio's state; every method may be called from several threads at once."""

    def __init__(
        self,
        *,
        start: Path | None = None,
        start_display: str | None = None,
        folders: Sequence[Path] = (),
    ) -> None:
        self._lock = threading.RLock()
        self.folders = tuple(folders)
        self._sources: dict[str, RuleSource] = {}
        for path in sorted(shipped_path().glob("*.yaml")):
            if file_kind(load_document(path)) == "rules":
                rules = load_rules(path)
                self._sources[path.stem] = RuleSource(path.stem, rules, path, "shipped")
        self.default_rules = "paper"
        self.start_team: Team | None = None
        if start is not None:
            self._start(start, start_display or str(start))
        self._uploads: _Kept[str, RuleSource] = _Kept(MAX_KEPT_RULE_SETS)
        self._teams: _Kept[tuple[str, Selection], Team] = _Kept(MAX_KEPT_SOLUTIONS)
        self._solutions: _Kept[tuple[str, str, bool], Solution] = _Kept(MAX_KEPT_SOLUTIONS)
        self._excluded: dict[str, dict[tuple[str, str], dict[str, Removed]]] = {}
        self.fleets: _Kept[str, Fleet] = _Kept(MAX_KEPT_FLEETS)
        self._counter = 0
        # Made last: a start file that cannot be read leaves no folder behind.
        self.folder = Path(tempfile.mkdtemp(prefix="teleop-ui-studio-"))
        self.folder.chmod(0o700)

    def _start(self, path: Path, display: str) -> None:
        document = load_document(path, display=display)
        if file_kind(document) == "rules":
            rules = load_rules(path, display=display)
            self._sources["start"] = RuleSource("start", rules, path, "start")
            self.default_rules = "start"
            return
        team = load_team(path, display=display)
        self.start_team = team
        shipped = shipped_name(Path(team.rules.file))
        match = next(
            (s for s in self._sources.values() if shipped and s.rules.file == team.rules.file),
            None,
        )
        if match is None:
            # The team's own rule set: the path its team file names, resolved by the library.
            rules_path = _rules_path(path)
            self._sources["start"] = RuleSource("start", team.rules, rules_path, "start")
            self.default_rules = "start"
        else:
            self.default_rules = match.id

    def close(self) -> None:
        """Remove the private folder and everything uploaded into it."""
        shutil.rmtree(self.folder, ignore_errors=True)

    # -- rule sets -------------------------------------------------------------------------

    @property
    def rule_sources(self) -> tuple[RuleSource, ...]:
        with self._lock:
            return (*self._sources.values(), *self._uploads.values())

    def source(self, rules_id: str | None) -> RuleSource:
        """The rule set a URL names (the default one for ``None`` or ``""``)."""
        wanted = rules_id or self.default_rules
        with self._lock:
            found = self._sources.get(wanted) or self._uploads.get(wanted)
        if found is None:
            known = ", ".join(s.id for s in self.rule_sources)
            raise InputError.at(
                SELECTION_FILE,
                f"no rule set {shown(wanted, quoted=True)} in this studio (uploads last while it "
                f"runs); it has: {known}",
                path="rules",
                code="unknown-reference",
            )
        return found

    def add_rules(self, upload: Upload) -> RuleSource:
        """Read an uploaded rule set (:class:`~solver.errors.SolverError` with every problem,
        located in the file as its sender named it)."""
        digest = hashlib.sha256(upload.data).hexdigest()[:16]
        rules_id = f"upload-{digest}"
        with self._lock:
            if rules_id in self._uploads:
                return self._uploads[rules_id]
        path = self._private_file("rules", upload)
        display = shown_name(upload.name)
        document = load_document(path, display=display)
        kind = file_kind(document)
        if kind not in ("rules", None):
            raise InputError.at(
                display, f"this is not a rule set (it is {kind} file); upload a rule set here"
            )
        rules = load_rules(path, display=display)
        with self._lock:
            return self._uploads.keep(rules_id, RuleSource(rules_id, rules, path, "upload"))

    def read_team(self, upload: Upload, source: RuleSource) -> Team:
        """An uploaded team file, read against ``source``'s rules (its own ``rules:`` line is
        not followed: the studio reads no path a stranger's file names)."""
        path = self._private_file("teams", upload)
        return load_team(path, source.rules, display=shown_name(upload.name))

    def private_folder(self, kind: str) -> Path:
        """A new, empty folder of the studio's own under its private folder."""
        with self._lock:
            self._counter += 1
            folder = self.folder / kind / str(self._counter)
        folder.mkdir(parents=True, mode=0o700)
        return folder

    def _private_file(self, kind: str, upload: Upload) -> Path:
        path = self.private_folder(kind) / safe_file_name(upload.name)
        path.write_bytes(upload.data)
        return path

    # -- teams and solutions ---------------------------------------------------------------

    def team(self, selection: Selection, source: RuleSource) -> Team:
        """The team ``selection`` stands for, with the published figures of a shipped team
        that selects the same (:func:`solver.core.reproduce.published_for`)."""
        # Kept by the selection itself: writing its team file on every request cost more
        # than counting (a YAML dump in pure Python).
        key = (source.id, selection)
        with self._lock:
            found = self._teams.get(key)
        if found is None:
            team = team_of(selection, source.rules)
            found = dataclasses.replace(team, published=published_for(team))
            with self._lock:
                self._teams.keep(key, found)
        return found

    def solution(self, team: Team, source: RuleSource, *, listed: bool = False) -> Solution:
        """``solve(team)``, counts only unless ``listed``; each solved once while kept."""
        key = (source.id, _team_key(team), listed)
        return self._cached(self._solutions, key, lambda: solve(team, count_only=not listed))

    def excluded(self, source: RuleSource) -> dict[tuple[str, str], dict[str, Removed]]:
        """``(type, characteristic) -> {value text: why excluded}`` for the rule set's
        constraints (:func:`solver.core.forbidden.excluded_by_rules`), computed once."""
        with self._lock:
            found = self._excluded.get(source.id)
        if found is None:
            found = {}
            for removed in excluded_by_rules(source.rules):
                where = (removed.kinematic_type, removed.characteristic)
                for value in removed.values:
                    found.setdefault(where, {})[str(value)] = removed
            with self._lock:
                self._excluded[source.id] = found
        return found

    def _cached(self, kept: _Kept[K, V], key: K, make: Callable[[], V]) -> V:
        with self._lock:
            found = kept.get(key)
            if found is not None:
                kept.move_to_end(key)
                return found
        value = make()
        with self._lock:
            return kept.keep(key, value)

    def fleet_id(self, fleet: Fleet) -> str:
        with self._lock:
            self._counter += 1
            fleet_id = f"fleet-{self._counter}"
            self.fleets.keep(fleet_id, fleet)
        return fleet_id


def _team_key(team: Team) -> str:
    return repr((team.name, team.selections, team.published))


def _rules_path(team_path: Path) -> Path:
    """The file a started team's rule set was read from (its ``rules:``, else the default)."""
    document = load_document(team_path)
    data = document.data
    text = data.get("rules") if isinstance(data, dict) else None
    if isinstance(text, str) and text:
        return team_path.parent / text
    return shipped_path("paper.yaml")
