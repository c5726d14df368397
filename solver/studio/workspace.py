"""What one running studio holds: the rule sets it may use, what it was started with, uploads,
and the solutions it has already computed.

The studio reads only what its user named at start (a team or rule set, ``--fleet`` folders)
and the rule sets shipped with the package. Everything else arrives as an upload: written into
the studio's own private folder (mode 0700, removed at exit; one a studio killed outright left
is removed by the next studio of the same account) under a name of the studio's making, then
read back through the project's bounded readers, as a file named on the command line would be.
No request names a path: rule sets, fleets and folders are chosen by id.

Nothing a request writes outlives it but an uploaded rule set, which the user asked to keep:
uploaded teams and robot descriptions are removed once read, and a kept rule set's file when
it is dropped. Kept rule sets are bounded in number and in bytes, so the folder is too.

Solutions are cached by the team file a selection stands for, so a page, its charts and its
JSON ask the library once; the cache is bounded by the memory its solutions take, however many
teams (or names of one team) are asked for.

Not here: the URL form of a selection (:mod:`solver.studio.selection`), HTTP.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import os
import re
import shutil
import tempfile
import threading
from collections import OrderedDict
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal, TypeVar

from solver import InputError, RuleSet, Solution, Team, load_rules, load_team, solve
from solver.core.forbidden import Removed, excluded_by_rules
from solver.core.rules import shipped_name, shipped_path
from solver.files.filekind import file_kind
from solver.files.yamlio import MAX_FILE_BYTES, load_document
from solver.solving.reproduce import published_for
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
# Uploaded rule sets and identified fleets kept (the oldest are dropped first), and the bytes
# of the kept rule sets' files together (one file may be the bounded readers' 16 MiB).
MAX_KEPT_RULE_SETS = 32
MAX_KEPT_RULE_BYTES = 32 * 1024 * 1024
MAX_KEPT_FLEETS = 8
# Teams kept by the selection they stand for, and the memory the kept solutions may take.
MAX_KEPT_TEAMS = 128
MAX_KEPT_SOLUTION_BYTES = 256 * 1024 * 1024
# Solutions solved (and checks run) at the same time, at most (one per core of a small
# machine).
MAX_SOLVING = 2
# Checks' answers kept by the selection they checked.
MAX_KEPT_CHECKS = 64
# Seconds the rule set's exclusions (the values its constraints rule out, shown disabled) may
# take to find.
EXCLUSION_SECONDS = 2.0
# The private folder's name: the studio's process id follows it.
FOLDER_PREFIX = "teleop-ui-studio-"

Origin = Literal["shipped", "start", "upload"]
# A check's JSON, and the selection's team file it read (solver.studio.service).
Checked = tuple[dict[str, Any], str | None]
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
    """A dictionary that keeps its newest entries: at most ``size`` of them, and at most
    ``most_bytes`` by ``weigh`` (an entry heavier than that alone is not kept). ``dropped`` is
    told of each entry it lets go."""

    def __init__(
        self,
        size: int,
        *,
        most_bytes: int | None = None,
        weigh: Callable[[V], int] = lambda _value: 0,
        dropped: Callable[[V], None] = lambda _value: None,
    ) -> None:
        super().__init__()
        self.size = size
        self.most_bytes = most_bytes
        self.weigh = weigh
        self.dropped = dropped
        self.weights: dict[K, int] = {}

    @property
    def bytes(self) -> int:
        return sum(self.weights.values())

    def keep(self, key: K, value: V) -> V:
        weight = self.weigh(value)
        if self.most_bytes is not None and weight > self.most_bytes:
            return value
        if key in self:
            self._drop(key)
        self[key] = value
        self.weights[key] = weight
        while len(self) > self.size or (
            self.most_bytes is not None and self.bytes > self.most_bytes
        ):
            self._drop(next(iter(self)))
        return value

    def _drop(self, key: K) -> None:
        value = self.pop(key)
        self.weights.pop(key, None)
        self.dropped(value)


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
        self._uploads: _Kept[str, RuleSource] = _Kept(
            MAX_KEPT_RULE_SETS,
            most_bytes=MAX_KEPT_RULE_BYTES,
            weigh=_file_bytes,
            dropped=self._forget,
        )
        self._teams: _Kept[tuple[str, Selection], Team] = _Kept(MAX_KEPT_TEAMS)
        self._solutions: _Kept[tuple[str, str, bool], Solution] = _Kept(
            MAX_KEPT_TEAMS, most_bytes=MAX_KEPT_SOLUTION_BYTES, weigh=solution_bytes
        )
        self._excluded: dict[str, dict[tuple[str, str], dict[str, Removed]]] = {}
        self.fleets: _Kept[str, Fleet] = _Kept(MAX_KEPT_FLEETS)
        self._checks: _Kept[tuple[str, Selection, float | None], Checked] = _Kept(MAX_KEPT_CHECKS)
        self._whatifs: _Kept[tuple[str, Selection, str], Any] = _Kept(MAX_KEPT_CHECKS)
        self._counter = 0
        # Solutions being made, by key, and how many may be made at once.
        self._making: dict[object, threading.Event] = {}
        self._solving = threading.BoundedSemaphore(MAX_SOLVING)
        # What-if's own slot (one made at a time), and how many were asked for (the newest
        # waiting is made; older ones waiting are dropped).
        self._wondering = threading.Condition(threading.Lock())
        self._whatif_busy = False
        self._whatifs_asked = 0
        # Made last: a start file that cannot be read leaves no folder behind.
        remove_abandoned_folders()
        self.folder = Path(tempfile.mkdtemp(prefix=f"{FOLDER_PREFIX}{os.getpid()}-"))
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

    def opener(self, address: str) -> Path:
        """A page of the private folder that leads a browser on to ``address`` (which holds the
        token: a browser given a file instead keeps the token off its command line, which every
        account of the machine may read)."""
        from html import escape

        path = self.folder / "open.html"
        link = escape(address, quote=True)
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
        with os.fdopen(fd, "w", encoding="utf-8") as page:
            page.write(
                '<!doctype html><meta charset="utf-8">'
                f'<meta http-equiv="refresh" content="0;url={link}">'
                f'<title>teleop-ui studio</title><a href="{link}">Open the studio</a>\n'
            )
        return path

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
        try:
            kind = file_kind(load_document(path, display=display))
        except BaseException:
            shutil.rmtree(path.parent, ignore_errors=True)
            raise
        if kind not in ("rules", None):
            shutil.rmtree(path.parent, ignore_errors=True)
            raise InputError.at(
                display, f"this is not a rule set (it is {kind} file); upload a rule set here"
            )
        try:
            rules = load_rules(path, display=display)
        except BaseException:
            shutil.rmtree(path.parent, ignore_errors=True)
            raise
        with self._lock:
            return self._uploads.keep(rules_id, RuleSource(rules_id, rules, path, "upload"))

    def read_team(self, upload: Upload, source: RuleSource) -> Team:
        """An uploaded team file, read against ``source``'s rules (its own ``rules:`` line is
        not followed: the studio reads no path a stranger's file names)."""
        with self.scratch("teams") as folder:
            path = folder / safe_file_name(upload.name)
            path.write_bytes(upload.data)
            return load_team(path, source.rules, display=shown_name(upload.name))

    def private_folder(self, kind: str) -> Path:
        """A new, empty folder of the studio's own under its private folder."""
        with self._lock:
            self._counter += 1
            folder = self.folder / kind / str(self._counter)
        folder.mkdir(parents=True, mode=0o700)
        return folder

    @contextlib.contextmanager
    def scratch(self, kind: str) -> Iterator[Path]:
        """A new, empty private folder for one request's files, removed when it is done."""
        folder = self.private_folder(kind)
        try:
            yield folder
        finally:
            shutil.rmtree(folder, ignore_errors=True)

    def _private_file(self, kind: str, upload: Upload) -> Path:
        path = self.private_folder(kind) / safe_file_name(upload.name)
        path.write_bytes(upload.data)
        return path

    def _forget(self, source: RuleSource) -> None:
        """A kept rule set dropped: its file and what was computed of it go too."""
        self._excluded.pop(source.id, None)
        shutil.rmtree(source.path.parent, ignore_errors=True)

    # -- teams and solutions ---------------------------------------------------------------

    def team(self, selection: Selection, source: RuleSource) -> Team:
        """The team ``selection`` stands for, with the published figures of a shipped team
        that selects the same (:func:`solver.solving.reproduce.published_for`)."""
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
        constraints (:func:`solver.core.forbidden.excluded_by_rules`), computed once, within
        :data:`EXCLUSION_SECONDS` (past them none is shown: a page never waits longer)."""
        from solver.deadline import Deadline
        from solver.errors import TimeLimitError

        with self._lock:
            found = self._excluded.get(source.id)
        if found is None:
            found = {}
            deadline = Deadline.start("check-seconds", "exclusions", EXCLUSION_SECONDS)
            try:
                removed_values = excluded_by_rules(source.rules, deadline=deadline)
            except TimeLimitError:
                removed_values = ()
            for removed in removed_values:
                where = (removed.kinematic_type, removed.characteristic)
                for value in removed.values:
                    found.setdefault(where, {})[str(value)] = removed
            with self._lock:
                self._excluded[source.id] = found
        return found

    def kept_check(
        self, key: tuple[str, Selection, float | None], make: Callable[[], Checked]
    ) -> Checked:
        """A check's answer for ``key`` (rule set, selection, budget), made once while kept."""
        return self._cached(self._checks, key, make)

    def kept_whatif(self, key: tuple[str, Selection, str], make: Callable[[], V]) -> V | None:
        """What-if's answer for ``key`` (rule set, selection), made once while kept, in a slot
        of its own: one what-if made at a time, never in one of the :data:`MAX_SOLVING` slots
        the solutions and checks use (what-if tries thousands of changes; the totals must not
        wait for it). ``None`` when a newer what-if was asked while this one waited for its
        slot: the page that asked has moved on, and the newer one is made instead."""
        with self._wondering:
            self._whatifs_asked += 1
            ticket = self._whatifs_asked
            self._wondering.notify_all()
            while True:
                with self._lock:
                    found = self._whatifs.get(key)
                    if found is not None:
                        self._whatifs.move_to_end(key)
                        return found  # type: ignore[no-any-return]
                if ticket != self._whatifs_asked:
                    return None
                if not self._whatif_busy:
                    break
                self._wondering.wait()
            self._whatif_busy = True
        try:
            value = make()
            with self._lock:
                return self._whatifs.keep(key, value)  # type: ignore[no-any-return]
        finally:
            with self._wondering:
                self._whatif_busy = False
                self._wondering.notify_all()

    @property
    def whatifs_asked(self) -> int:
        """How many what-ifs were asked for so far (a test waits for its own to be asked)."""
        with self._wondering:
            return self._whatifs_asked

    def _cached(self, kept: _Kept[K, V], key: K, make: Callable[[], V]) -> V:
        """``kept[key]``, made by ``make`` when missing: once, however many ask at the same
        time, and at most :data:`MAX_SOLVING` made at once (each may take much memory)."""
        while True:
            with self._lock:
                found = kept.get(key)
                if found is not None:
                    kept.move_to_end(key)
                    return found
                making = self._making.get(key)
                if making is None:
                    making = self._making[key] = threading.Event()
                    break
            making.wait()
        try:
            with self._solving:
                value = make()
            with self._lock:
                return kept.keep(key, value)
        finally:
            with self._lock:
                del self._making[key]
            making.set()

    def fleet_id(self, fleet: Fleet) -> str:
        with self._lock:
            self._counter += 1
            fleet_id = f"fleet-{self._counter}"
            self.fleets.keep(fleet_id, fleet)
        return fleet_id


def _team_key(team: Team) -> str:
    return repr((team.name, team.selections, team.published))


def _file_bytes(source: RuleSource) -> int:
    try:
        return source.path.stat().st_size
    except OSError:
        return 0


def solution_bytes(solution: Solution) -> int:
    """About the memory ``solution`` takes, never less (tests/studio/test_workspace.py checks
    it against what the allocator counts): a fixed part, and per configuration its object,
    its key, components and served values (a tuple of 8-byte references each, the key's
    integers as objects of their own)."""
    total = 4096 + 512 * len(solution.by_type)
    for configuration in solution.configurations:
        total += (
            224
            + 92 * len(configuration.key)
            + 64
            + 8 * len(configuration.components)
            + 64
            + sum(64 + 8 * len(served) for served in configuration.served)
        )
    return total


def remove_abandoned_folders() -> None:
    """Remove the private folders of this account's studios that no longer run (killed outright,
    they could not remove their own)."""
    parent = Path(tempfile.gettempdir())
    mine = os.getuid()
    for folder in parent.glob(f"{FOLDER_PREFIX}*-*"):
        pid = folder.name[len(FOLDER_PREFIX) :].split("-", 1)[0]
        try:
            details = folder.lstat()
        except OSError:
            continue
        if not pid.isdigit() or details.st_uid != mine or not _is_folder(details.st_mode):
            continue
        if not _running(int(pid)):
            shutil.rmtree(folder, ignore_errors=True)


def _is_folder(mode: int) -> bool:
    import stat

    return stat.S_ISDIR(mode)


def _running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def _rules_path(team_path: Path) -> Path:
    """The file a started team's rule set was read from (its ``rules:``, else the default)."""
    document = load_document(team_path)
    data = document.data
    text = data.get("rules") if isinstance(data, dict) else None
    if isinstance(text, str) and text:
        return team_path.parent / text
    return shipped_path("paper.yaml")
