"""Solving many teams at once: find the files, solve them in parallel, summarise, skip reruns.

``teleop-ui batch`` is built from four steps, each a function here:

1. :func:`find_teams` turns file names, shipped team names (``case3``), folders (searched
   recursively for ``*.yaml`` and ``*.yml``) and glob patterns (``**`` included) into a list
   of team files.
2. :func:`make_jobs` gives each file its outputs in the ``teams/`` folder of the output folder,
   mirroring the files' folders below their deepest common folder (``teams/a/x.yaml`` ->
   ``OUT/teams/a/x.json``), and decides which are already up to date.
3. :func:`run_batch` solves the rest in worker processes (one, or as many as asked) and
   yields one :class:`Outcome` per team as it finishes. A bad team file is an outcome with its
   located error, never an exception that stops the others; a team that crashes its worker
   (a signal) fails alone, and a fresh worker takes the teams after it. A rule set or an
   identification profile (:func:`solver.files.filekind.file_kind`; a folder such as
   ``rules/`` holds all kinds) is *skipped*.
4. :func:`write_summary` writes ``summary.csv`` and ``summary.md``: one row per team in input
   order, naming each team's rule set.

**Layout.** The top of the output folder holds only the summaries and ``.stamps/``; every
per-team output is below ``teams/``. So no team's name can collide with them: a team file
called ``summary.yaml`` gets ``OUT/teams/summary.md``, never the batch's ``OUT/summary.md``.

Every result is written atomically (:func:`solver.files.atomic.write_atomic`): an interrupted
batch leaves finished teams complete and no half-written result (a stamp, below, is a record,
written in place). Nothing is written, read back or removed through a link inside the output
folder (``OUT/teams -> elsewhere``, planted by someone who can write there): that team fails,
naming the link.

**Up to date.** Beside each team's outputs a *stamp* (``OUT/.stamps/<name>.json``, written
last) records the SHA-256 of the team file and of the rule file it used, the teleop-ui version,
the options that shape the outputs and the SHA-256 of the team's JSON as written. A rerun skips
a team when its stamp matches, its outputs exist and its JSON still has that hash. Content
hashes, not modification times: a ``git checkout`` or a copy changes times without changing
content, and two edits within the file system's time resolution would look alike. Reading and
hashing three small files costs far less than solving. A team that fails leaves no outputs and
no stamp (stale ones are removed), so it is tried again next time.

**A crash (power cut, kernel panic).** One file per team is durable: its JSON is written to a
temporary, flushed to the disk (``fsync``) and only then renamed onto its name (a report and
its charts likewise, before the stamp). The stamp is written after them, in place
(:func:`solver.files.atomic.overwrite`: no temporary, no rename, no ``fsync``, never through a
link): it is a record that lets a rerun skip work, not a result. After a crash or a kill a
stamp may be missing, empty, cut or the previous one, and the JSON's rename may be lost while
the stamp's write is kept (the system orders neither unless told); each case costs at most
solving the team again, never a stale result taken for a current one: a stamp that is not
valid JSON (a JSON object cut before its closing brace is none), or names other input
hashes, or a JSON hash the file on disk does not have (its rename was lost and the old file
is there), does not match. The JSON on disk is always a whole one, old or new. What is not
checked: a report whose rename was lost while its stamp and JSON were kept is the previous
report of that team (reports are not hashed; rerun with ``--force`` after a crash to be sure).

Not here: progress display and exit status (``solver/cli/batch.py``), the per-team JSON shape
(:func:`solver.solving.solution.solution_data`), reports (:mod:`solver.reporting.report`).
"""

from __future__ import annotations

import contextlib
import csv
import functools
import glob
import io
import json
import os
import time
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal, cast

from solver import __version__  # the installed version: its metadata is read from it
from solver.core.rules import default_rules_path, shipped_name
from solver.core.team import parse_team, resolve_team_path, shipped_rules_path
from solver.errors import Fault, InputError, Location, SolverError, Terminated
from solver.files.atomic import (
    link_inside,
    overwrite,
    remove_output,
    remove_temporaries,
    write_atomic,
)
from solver.files.filekind import describe, file_kind, why
from solver.files.inputfile import read_bounded, read_text, sha256_bounded, sha256_hex
from solver.files.output import csv_row, dumps
from solver.files.yamlio import MAX_FILE_BYTES, load_hashed
from solver.limits import limit
from solver.reporting import markdown
from solver.untrusted import SHOWN_FILE_NAME_CHARS
from solver.untrusted import shown as shown_text

if TYPE_CHECKING:
    import hashlib
    from multiprocessing.connection import Connection
    from multiprocessing.context import ForkServerContext, SpawnContext
    from multiprocessing.process import BaseProcess

__all__ = [
    "Job",
    "Outcome",
    "SummaryRow",
    "find_teams",
    "make_jobs",
    "run_batch",
    "run_job",
    "summary_csv",
    "summary_markdown",
    "write_summary",
]

Status = Literal["ok", "failed", "skipped"]
Action = Literal["solved", "up to date", "failed", "skipped"]
ReportFormat = Literal["html", "markdown"]

_PATTERN_CHARACTERS = set("*?[")
_TEAM_SUFFIXES = (".yaml", ".yml")
_REPORT_SUFFIX: dict[ReportFormat, str] = {"html": ".html", "markdown": ".md"}
STAMPS = ".stamps"
TEAM_OUTPUTS = "teams"
SUMMARY_FILES = ("summary.csv", "summary.md")


@dataclass(frozen=True, slots=True)
class Job:
    """One team file and where its outputs go."""

    team_file: Path
    shown: str  # the file as the user's pattern found it
    out: Path  # the output folder
    output: Path  # the per-team JSON
    stamp: Path
    report: Path | None = None  # the per-team report, when asked for
    rules: str | None = None  # a rule file that overrides the team's own
    # An up-to-date team's summary row, from its JSON as read when that was decided.
    kept: SummaryRow | None = None

    @property
    def up_to_date(self) -> bool:
        """Whether a rerun skips the team (see "Up to date" in the module docstring)."""
        return self.kept is not None

    @property
    def options(self) -> dict[str, Any]:
        """What besides the input files shapes the outputs (recorded in the stamp)."""
        return {
            "rules": None if self.rules is None else str(Path(self.rules).resolve()),
            "report": None if self.report is None else self.report.suffix,
        }

    @property
    def outputs(self) -> tuple[Path, ...]:
        """Every file the job writes besides its stamp (a Markdown report's charts too)."""
        if self.report is None:
            return (self.output,)
        if self.report.suffix != _REPORT_SUFFIX["markdown"]:
            return (self.output, self.report)
        from solver.reporting.report import image_names

        return (self.output, *image_names(self.report).values(), self.report)


@dataclass(frozen=True, slots=True)
class SummaryRow:
    """One line of the summary: what a team gave, or why it gave nothing."""

    file: str
    status: Status
    team: str = ""
    rules: str = ""
    rules_file: str = ""
    kinematic_types: int | None = None
    valid_robots: int | None = None
    ui_configurations: int | None = None
    default_configuration: int | None = None
    published: str = ""
    reproduced: str = ""
    output: str = ""
    message: str = ""


@dataclass(frozen=True, slots=True)
class Outcome:
    """What became of one job: the summary row, what was done, how long it took."""

    job: Job
    action: Action
    row: SummaryRow
    seconds: float = 0.0

    @property
    def failed(self) -> bool:
        return self.row.status == "failed"


# ---- 1. finding the team files -------------------------------------------------------------


def find_teams(patterns: Sequence[str]) -> list[tuple[Path, str]]:
    """The team files named by ``patterns``: ``(path, shown)`` pairs in a stable order.

    A folder gives every ``*.yaml``/``*.yml`` below it, a glob pattern its matching files,
    each sorted by name; a name that is no file but a shipped team's (``case3``) gives that
    team, shown as ``rules/teams/case3.yaml``. The patterns keep their order and a file named
    twice counts once. A pattern that names nothing, or an empty one, is an
    :class:`InputError` (all such patterns are reported).
    """
    found: list[tuple[Path, str]] = []
    seen: set[Path] = set()
    faults = []
    for pattern in patterns:
        shown_as: str | None = None
        if not pattern.strip():
            # Path("") is the current folder: an empty pattern (an unset shell variable)
            # would quietly batch everything below it.
            faults.append(
                Fault(
                    Location("<arguments>"),
                    f"empty pattern {pattern!r}: name "
                    "team files, folders or globs ('.' for the current folder)",
                    "no-match",
                )
            )
            continue
        # os.path's probes say False for a name the system refuses (too long, say) where
        # Path's raise; such a name is then "no such file", as the system would say.
        if _PATTERN_CHARACTERS & set(pattern):
            matches = sorted(m for m in _glob(pattern) if os.path.isfile(m))
        elif os.path.isdir(pattern):
            matches = sorted(
                str(p)
                for p in Path(pattern).rglob("*")
                if p.suffix.lower() in _TEAM_SUFFIXES and p.is_file()
            )
        elif os.path.isfile(pattern):
            matches = [pattern]
        elif os.path.isfile(shipped := resolve_team_path(pattern)):
            matches, shown_as = [str(shipped)], shipped_name(shipped) or str(shipped)
        else:
            faults.append(Fault(Location(_shown_name(pattern)), _missing(pattern), "no-match"))
            continue
        if not matches:
            what = (
                "folder holds no .yaml or .yml file"
                if os.path.isdir(pattern)
                else "pattern matches no file"
            )
            faults.append(Fault(Location(_shown_name(pattern)), what, "no-match"))
        for match in matches:
            resolved = Path(match).resolve()
            if resolved not in seen:
                seen.add(resolved)
                found.append((Path(match), shown_as or match))
                limit("batch-teams").check(len(found), pattern, noun="team files or more")
    if faults:
        raise InputError(faults)
    return found


def _glob(pattern: str) -> list[str]:
    """What ``glob.glob(pattern, recursive=True)`` finds, in a bounded walk.

    Python's glob follows every link to a folder under ``**``: a folder holding a link to
    itself or to its parent is searched again at every level (two such links: 2**40 paths, a
    batch that never ends). Here a pattern with ``**`` is matched against one walk of the
    folders below its fixed start, entering each folder once (by device and inode), so a link
    is followed to a folder not seen yet and never round a loop. Hidden names are matched
    only by a part that starts with ``.``, as glob does.
    """
    parts = pattern.split(os.sep)
    if "**" not in parts:
        return glob.glob(pattern)  # no recursion: as deep as the pattern, whatever the links
    if pattern.endswith(os.sep):
        return []  # folders only: no team file
    fixed = next(i for i, part in enumerate(parts) if glob.has_magic(part))
    start = os.sep.join(parts[:fixed]) or (os.sep if pattern.startswith(os.sep) else "")
    wanted = [part for part in parts[fixed:] if part]
    hidden = any(part.startswith(".") for part in wanted)
    found = []
    for folder, names in _walk_once(start or os.curdir, hidden=hidden):
        below = () if folder == "" else tuple(folder.split(os.sep))
        for name in names:
            if _glob_match(wanted, [*below, name]):
                found.append(os.path.join(start, folder, name))
    return found


def _walk_once(top: str, *, hidden: bool) -> Iterator[tuple[str, list[str]]]:
    """Each folder below ``top`` (its path relative to ``top``) and the names in it; a folder
    reached again (through a link) is not entered again; hidden folders only if ``hidden``."""
    seen: set[tuple[int, int]] = set()
    for folder, folders, files in os.walk(top, followlinks=True):
        try:
            here = os.stat(folder)
        except OSError:
            folders[:] = []
            continue
        if (here.st_dev, here.st_ino) in seen:
            folders[:] = []
            continue
        seen.add((here.st_dev, here.st_ino))
        # Sorted: a folder reached by two paths is found by the first in name order.
        folders[:] = sorted(name for name in folders if hidden or not name.startswith("."))
        relative = os.path.relpath(folder, top)
        yield ("" if relative == os.curdir else relative), sorted([*folders, *files])


def _glob_match(pattern: Sequence[str], names: Sequence[str]) -> bool:
    """Whether the path ``names`` matches the parts of ``pattern`` as glob reads them: ``**``
    stands for any number of folders (none included); a wildcard matches a hidden name only
    when it starts with ``.`` itself, and ``**`` never does."""
    import fnmatch

    @functools.cache
    def matches(i: int, k: int) -> bool:  # pattern[i:] matches names[k:]
        if i == len(pattern):
            return k == len(names)
        part = pattern[i]
        if part == "**" and i == len(pattern) - 1:  # what is left, at least one name: a file
            return k < len(names) and not any(name.startswith(".") for name in names[k:])
        if part == "**":
            more = k < len(names) and not names[k].startswith(".") and matches(i, k + 1)
            return matches(i + 1, k) or more
        if k == len(names):
            return False
        name = names[k]
        if not glob.has_magic(part):
            fits = name == part
        else:
            fits = (part.startswith(".") or not name.startswith(".")) and fnmatch.fnmatchcase(
                name, part
            )
        return fits and matches(i + 1, k + 1)

    return matches(0, 0)


def _missing(pattern: str) -> str:
    """Why ``pattern``, neither a glob, a file, a folder nor a shipped team, names nothing."""
    try:
        os.stat(pattern)
    except FileNotFoundError:
        return "no such file or folder"
    except OSError as error:
        return f"cannot use: {error.strerror or error}"  # "File name too long", say
    except ValueError:
        return "not a usable file name (it contains a NUL byte)"
    return "not a regular file or folder (a pipe, a device or a socket): refused"


def _shown_name(name: str) -> str:
    return shown_text(name, limit=SHOWN_FILE_NAME_CHARS)


# ---- 2. planning the outputs ---------------------------------------------------------------


def _relative_names(paths: Sequence[Path]) -> list[Path]:
    """Each file's path below the deepest folder common to all, without its suffix."""
    if not paths:
        return []
    resolved = [p.resolve() for p in paths]
    root = Path(os.path.commonpath([str(p.parent) for p in resolved]))
    names = [p.relative_to(root).with_suffix("") for p in resolved]
    # Two files differing only in suffix (x.yaml, x.yml) keep their suffixes apart.
    counts: dict[Path, int] = {}
    for name in names:
        counts[name] = counts.get(name, 0) + 1
    return [
        p.relative_to(root) if counts[n] > 1 else n for p, n in zip(resolved, names, strict=True)
    ]


def make_jobs(
    teams: Sequence[tuple[Path, str]],
    out: str | Path,
    *,
    rules: str | None = None,
    report: ReportFormat | None = None,
    force: bool = False,
) -> list[Job]:
    """One :class:`Job` per team file, in order, with ``up_to_date`` decided (see module).

    With a ``report`` and no matplotlib (the ``plots`` extra), a
    :class:`~solver.errors.MissingExtraError` before anything is solved: every report draws
    charts, so every team would fail for the same reason."""
    if report is not None:
        from solver.reporting.plot import require_matplotlib

        require_matplotlib()
    folder = Path(out)
    outputs = folder / TEAM_OUTPUTS  # apart from the summaries: see "Layout" above
    jobs = []
    for (path, shown), name in zip(teams, _relative_names([p for p, _ in teams]), strict=True):
        output = outputs / f"{name}.json"
        job = Job(
            path,
            shown,
            folder,
            output,
            folder / STAMPS / f"{name}.json",
            None if report is None else outputs / f"{name}{_REPORT_SUFFIX[report]}",
            rules,
        )
        jobs.append(job if force else replace(job, kept=_kept_row(job)))
    return jobs


def _sha256(path: Path) -> str | None:
    # Bounded like every read: a team's `rules: /dev/zero` must not be hashed forever.
    return sha256_bounded(path, limit=MAX_FILE_BYTES)


def _read_json(path: Path) -> Any:
    try:
        return json.loads(read_text(path, limit=MAX_FILE_BYTES, what="JSON file"))
    except (SolverError, ValueError, RecursionError):
        return None


def _json_and_hash(path: Path) -> tuple[Any, str | None]:
    """The JSON in ``path`` (``None`` if there is none) and the SHA-256 of its bytes, from one
    bounded read."""
    try:
        data = read_bounded(path, limit=MAX_FILE_BYTES, what="JSON file")
    except SolverError:
        return None, None
    try:
        return json.loads(data), sha256_hex(data)
    except (ValueError, RecursionError):
        return None, sha256_hex(data)


def _kept_row(job: Job) -> SummaryRow | None:
    """The summary row of a team whose outputs are up to date (from its JSON, read once, as
    its hash is checked); ``None`` when it must be solved again."""
    if any(link_inside(path, within=job.out) for path in (job.stamp, *job.outputs)):
        return None  # never read through a link there: writing will say what is wrong
    stamp = _read_json(job.stamp)
    if (
        not isinstance(stamp, dict)
        or stamp.get("teleop_ui") != __version__
        or stamp.get("options") != job.options
    ):
        return None
    if not all(p.is_file() for p in job.outputs):
        return None
    output, output_hash = _json_and_hash(job.output)
    if not isinstance(output, dict) or stamp.get("output_sha256") != output_hash:
        return None  # its rename lost in a crash, or the file edited since (see module)
    if stamp.get("team_sha256") != _sha256(job.team_file):
        return None
    rules_file = stamp.get("rules_file")
    if not isinstance(rules_file, str) or stamp.get("rules_sha256") != _sha256(Path(rules_file)):
        return None
    if not _summarisable(output):
        return None  # a JSON planted under a matching stamp: solved again, overwritten
    return _row(job, output)


def _summarisable(output: dict[str, Any]) -> bool:
    """Whether a team's JSON has the shapes its summary row reads."""
    return (
        isinstance(output.get("totals", {}), dict)
        and isinstance(output.get("by_type", []), list)
        and isinstance(output.get("warnings", []), list)
    )


# ---- 3. solving ---------------------------------------------------------------------------


def _rules_file(job: Job, data: Any) -> Path:
    """The rule file a team uses, found as :func:`solver.core.team.load_team` finds it."""
    if job.rules is not None:
        return Path(job.rules)
    if isinstance(data, dict) and isinstance(data.get("rules"), str) and data["rules"]:
        named, folder = str(data["rules"]), job.team_file.parent
        return shipped_rules_path(named, folder) or folder / named  # `rules: extended`
    return default_rules_path()


def _row(job: Job, data: dict[str, Any]) -> SummaryRow:
    """A summary row from a team's JSON (the same for a fresh solve and an up-to-date one)."""
    totals = data.get("totals", {})
    published = data.get("published")
    figures = reproduced = ""
    if isinstance(published, dict):
        figures = f"{published.get('valid_robots')} / {published.get('ui_configurations')}"
        agrees = (published.get("valid_robots"), published.get("ui_configurations")) == (
            totals.get("valid_robots"),
            totals.get("ui_configurations"),
        )
        reproduced = "yes" if agrees else "no"
    return SummaryRow(
        file=job.shown,
        status="ok",
        team=str(data.get("team", "")),
        rules=str(data.get("rules", "")),
        rules_file=str(data.get("rules_file", "")),
        kinematic_types=len(data.get("by_type", [])),
        valid_robots=totals.get("valid_robots"),
        ui_configurations=totals.get("ui_configurations"),
        default_configuration=data.get("default_configuration"),
        published=figures,
        reproduced=reproduced,
        message="; ".join(f"warning: {w}" for w in data.get("warnings", [])),
        output=" ".join(
            p.relative_to(job.out).as_posix() for p in (job.output, job.report) if p is not None
        ),
    )


def _remove_outputs(job: Job) -> None:
    """A failed team leaves nothing that could pass for a current result (and removes nothing
    through a link inside the output folder)."""
    for path in (job.stamp, *job.outputs):
        remove_output(path, within=job.out)


def run_job(job: Job) -> Outcome:
    """Solve one team and write its outputs; any failure becomes a failed :class:`Outcome`.

    Runs in a worker process: it takes and returns only picklable values, and catches every
    ``Exception`` so that one team's problem (even a bug) is reported, not raised.
    """
    # The workers' own modules: the batch process itself never solves (see _WORKER_MODULES).
    from solver.reporting.plot import check_chart_size
    from solver.reporting.render import solution_chunks
    from solver.reporting.report import write_report
    from solver.solving.solution import solution_data, solve

    started = time.perf_counter()
    try:
        # Hashed and read from the same bytes: the stamp names exactly the text solved.
        document, team_hash = load_hashed(job.team_file, display=job.shown)
        kind = file_kind(document)
        if kind in ("rules", "profile", "presentation", "teleop"):
            row = SummaryRow(
                file=job.shown,
                status="skipped",
                message=f"not a team file: {describe(kind)} ({why(kind)})",
            )
            return Outcome(job, "skipped", row, time.perf_counter() - started)
        rules_file = _rules_file(job, document.data)
        rules_hash = _sha256(rules_file)
        team = parse_team(document, job.rules, folder=job.team_file.parent)
        if job.report is not None:
            check_chart_size(team)  # before solving: a report of it could not be drawn
        solution = solve(team)
        data = solution_data(solution)  # the summary row's figures
        # The JSON of `solve --format json --list`, streamed into the file (durably: see
        # "A crash" above) and hashed on the way for the stamp.
        digest = _digest()
        chunks = solution_chunks(solution, "json", configurations=True)
        write_atomic(job.output, _hashed(chunks, digest), within=job.out)
        if job.report is not None:
            write_report(solution, job.report, within=job.out)
        stamp = {
            "teleop_ui": __version__,
            "team_file": str(job.team_file.resolve()),
            "team_sha256": team_hash,
            "rules_file": str(rules_file.resolve()),
            "rules_sha256": rules_hash,
            "options": job.options,
            "output_sha256": digest.hexdigest(),
        }
        # In place, not atomic, not flushed: a stamp lost or cut only means solving again.
        overwrite(job.stamp, dumps(stamp), within=job.out)
    except SolverError as error:
        message = str(error)
    except Exception as error:  # one team's bug must not stop the batch: report it
        message = f"{job.shown}: internal error (please report it): {type(error).__name__}: {error}"
    except BaseException:  # stopped (the batch interrupted): none of this team's files stay
        _remove_outputs(job)
        raise
    else:
        return Outcome(job, "solved", _row(job, data), time.perf_counter() - started)
    _remove_outputs(job)
    return Outcome(
        job,
        "failed",
        SummaryRow(file=job.shown, status="failed", message=message),
        time.perf_counter() - started,
    )


def _digest() -> hashlib._Hash:
    import hashlib  # as solver.files.inputfile: only `batch` digests

    return hashlib.sha256()


def _hashed(chunks: Iterable[str], digest: hashlib._Hash) -> Iterator[bytes]:
    """``chunks`` encoded as the file holds them (UTF-8, as :mod:`solver.files.atomic` writes
    text), each added to ``digest`` on the way."""
    for chunk in chunks:
        data = chunk.encode("utf-8", "backslashreplace")
        digest.update(data)
        yield data


def run_batch(jobs: Sequence[Job], workers: int = 1) -> Iterator[Outcome]:
    """Outcomes of ``jobs``: the up-to-date ones first, the others as they finish.

    Teams are solved in ``workers`` worker processes (at least one, whatever the count), each
    solving team after team: a team that crashes its worker (a signal, the kernel's memory
    limit) fails alone, with the signal named, a fresh worker takes the teams after it, and
    the batch always ends with every team's outcome. With several workers the order of the
    outcomes is the order they finish in (the summary restores input order).
    """
    pending = []
    for job in jobs:
        if job.kept is not None:
            yield Outcome(job, "up to date", job.kept)
        else:
            pending.append(job)
    if pending:
        yield from _in_workers(pending, workers)


def _in_workers(jobs: Sequence[Job], workers: int) -> Iterator[Outcome]:
    """Each job in a worker process; a worker that dies fails its own job only."""
    # Imported here: only solving needs them, and `import solver` stays quick.
    import collections
    from multiprocessing.connection import wait

    context = _context()
    queue = collections.deque(jobs)
    # Each worker is handed a few jobs at a time (fewer messages for the batch to send, which
    # does not parallelise), few enough that the workers end together.
    chunk = max(1, min(_MOST_JOBS_HANDED, len(jobs) // (4 * max(workers, 1))))
    busy: dict[Connection, tuple[BaseProcess, collections.deque[Job]]] = {}

    def start() -> tuple[BaseProcess, Connection]:
        mine, theirs = context.Pipe()
        process = context.Process(
            target=_worker, args=(theirs, os.getpid()), name="teleop-ui batch worker", daemon=True
        )
        process.start()
        theirs.close()
        return process, mine

    def hand(process: BaseProcess, connection: Connection) -> None:
        handed = collections.deque(queue.popleft() for _ in range(min(chunk, len(queue))))
        busy[connection] = (process, handed)
        # A worker dead already (killed as it started) cannot take them: wait() below then
        # finds its end of the pipe closed, and the first job fails as the worker's.
        with contextlib.suppress(OSError):
            connection.send(list(handed))

    try:
        for _ in range(min(max(workers, 1), len(queue))):
            hand(*start())
        while busy:
            for ready in wait(list(busy)):
                connection = cast("Connection", ready)
                process, handed = busy[connection]
                job = handed.popleft()
                try:
                    action, row, seconds = connection.recv()
                    outcome = Outcome(job, action, row, seconds)
                except (EOFError, OSError):  # the worker died solving this team
                    del busy[connection]
                    connection.close()
                    process.join()
                    outcome = _died(job, process.exitcode)
                    queue.extendleft(reversed(handed))  # the teams after it: a fresh worker
                    handed.clear()
                    if queue:
                        process, connection = start()
                yield outcome
                if handed:
                    continue
                busy.pop(connection, None)
                if queue:
                    hand(process, connection)
                elif not connection.closed:
                    connection.send(None)  # no more work: the worker returns
                    connection.close()
                    process.join(timeout=5)
    finally:  # interrupted (Ctrl-C, an error in the caller): stop the workers still solving
        for connection, (process, _) in busy.items():
            process.terminate()
            connection.close()
            process.join(timeout=5)


def _context() -> ForkServerContext | SpawnContext:
    """How workers are started. Not fork: the caller may be running threads (a progress bar's
    refresh thread), and a forked child can inherit a lock some thread held. forkserver
    starts workers from a clean single-threaded server."""
    import multiprocessing

    if "forkserver" in multiprocessing.get_all_start_methods():
        context = multiprocessing.get_context("forkserver")
        # The workers' code imported once, by the server, before it forks them: each worker
        # would otherwise import it anew (a quarter of a second of CPU each).
        context.set_forkserver_preload([__name__, *_WORKER_MODULES])
        return context
    return multiprocessing.get_context("spawn")


# What only the workers import (run_job's modules): the batch process does not, which shortens
# its start-up, and the forkserver imports them once for all its workers.
_WORKER_MODULES = (
    "solver.engines.structure",  # the engine `solve` picks for every shipped team
    "solver.reporting.plot",
    "solver.reporting.render",
    "solver.reporting.report",
    "solver.solving.solution",
)

# The most jobs handed to a worker at once.
_MOST_JOBS_HANDED = 8


def _died(job: Job, exitcode: int | None) -> Outcome:
    """The outcome of a team whose worker ended without answering."""
    import signal

    how = f"exit status {exitcode}"
    if exitcode is not None and exitcode < 0:
        try:
            how = f"killed by {signal.Signals(-exitcode).name}"
        except ValueError:
            how = f"killed by signal {-exitcode}"
    message = f"{job.shown}: the worker process solving it died ({how}); the other teams go on"
    _remove_outputs(job)
    for path in (job.stamp, *job.outputs):
        remove_temporaries(path, within=job.out)  # a worker killed outright removed none
    return Outcome(job, "failed", SummaryRow(file=job.shown, status="failed", message=message))


def _worker(connection: Connection, batch_pid: int) -> None:
    """A worker process: solve the teams it is handed (a few at a time, each answered as it
    is solved: the batch then knows which one a worker died on), until told to stop.

    Ctrl-C reaches the whole process group; only the batch answers it, by ending its busy
    workers with SIGTERM. Here SIGTERM unwinds the stack (:class:`~solver.errors.Terminated`),
    so the team being solved leaves no file and no temporary, and the worker then ends by the
    signal, with no traceback.
    """
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _terminate)
    _watch_parent(batch_pid)
    try:
        while True:
            try:
                jobs: list[Job] | None = connection.recv()
            except EOFError:  # the batch is gone
                return
            if jobs is None:
                return
            for job in jobs:
                # Without the job, which the batch has: less to pickle and unpickle.
                outcome = run_job(job)
                connection.send((outcome.action, outcome.row, outcome.seconds))
    except Terminated:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGTERM)


def _terminate(number: int, _frame: object) -> None:
    raise Terminated(number)


def _watch_parent(batch_pid: int) -> None:
    """In a worker: end as soon as the batch process is gone.

    A ``kill -9`` of the batch gives it no chance to stop its workers; they would live on. A
    daemon thread checks every half second that the batch process still exists and that this
    worker's parent (the forkserver, or the batch itself under spawn) is the same; when not,
    it sends the worker SIGTERM, so a file being written removes its temporary
    (:mod:`solver.files.atomic`), and ends it outright a second later.
    """
    import signal
    import threading

    parent = os.getppid()

    def watch() -> None:
        while True:
            time.sleep(0.5)
            try:
                os.kill(batch_pid, 0)
                gone = False
            except ProcessLookupError:
                gone = True
            except PermissionError:
                gone = False  # the pid exists (reused by someone else's: the ppid check below)
            if gone or os.getppid() != parent:
                os.kill(os.getpid(), signal.SIGTERM)
                time.sleep(1.0)
                os._exit(1)  # no cleanup left to do: the batch that wanted the results is gone

    threading.Thread(target=watch, name="watch-batch", daemon=True).start()


# ---- 4. the summary -----------------------------------------------------------------------

_FIELDS = (
    "file",
    "status",
    "team",
    "rules",
    "rules_file",
    "kinematic_types",
    "valid_robots",
    "ui_configurations",
    "default_configuration",
    "published",
    "reproduced",
    "output",
    "message",
)


def _cells(row: SummaryRow) -> list[str]:
    return ["" if getattr(row, f) is None else str(getattr(row, f)) for f in _FIELDS]


def summary_csv(rows: Sequence[SummaryRow]) -> str:
    """The summary as CSV: a header line, then one row per team (cells that a spreadsheet
    would read as a formula are neutralised: :func:`solver.files.output.csv_cell`)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(_FIELDS)
    writer.writerows(csv_row(_cells(row)) for row in rows)
    return buffer.getvalue()


def summary_markdown(rows: Sequence[SummaryRow]) -> str:
    """The summary as a Markdown page: counts, then one table row per team.

    Names and messages are escaped (:mod:`solver.reporting.markdown`): they come from the team
    files.
    """
    counts = {
        status: sum(1 for r in rows if r.status == status) for status in ("ok", "failed", "skipped")
    }
    headers = [
        "file",
        "status",
        "team",
        "rules",
        "valid robots",
        "UI configurations",
        "published",
        "reproduced",
        "output",
        "message",
    ]
    table = [
        [
            r.file,
            r.status,
            r.team,
            r.rules,
            r.valid_robots,
            r.ui_configurations,
            r.published,
            r.reproduced,
            r.output,
            r.message.replace("\n", "; "),
        ]
        for r in rows
    ]
    return (
        f"# Batch summary\n\n{len(rows)} team files: {counts['ok']} ok, "
        f"{counts['failed']} failed, {counts['skipped']} skipped\n\n"
        + markdown.table(
            headers, table, [False, False, False, False, True, True, False, False, False, False]
        )
    )


def write_summary(
    outcomes: Sequence[Outcome], jobs: Sequence[Job], out: str | Path
) -> tuple[list[SummaryRow], list[Path]]:
    """Write ``summary.csv`` and ``summary.md`` in ``out``, rows in the order of ``jobs``."""
    by_job = {o.job: o.row for o in outcomes}
    rows = [by_job[job] for job in jobs if job in by_job]
    folder = Path(out)
    written = [
        write_atomic(folder / SUMMARY_FILES[0], summary_csv(rows), within=folder),
        write_atomic(folder / SUMMARY_FILES[1], summary_markdown(rows), within=folder),
    ]
    return rows, written
