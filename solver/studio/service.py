"""Every question the studio answers, as data: the JSON of the API and what the pages show.

Each function takes the query of a page (its selection, :mod:`solver.studio.selection`) and
calls the same public functions the command line calls, returning the same JSON:
``solve --format json`` (:func:`solution_data`), ``count``, ``assign``, ``check``, ``robots``,
``identify``/``fleet``. Nothing here counts, solves or identifies by itself.

Not here: HTTP and HTML (:mod:`solver.studio.api`, :mod:`solver.studio.pages`).
"""

from __future__ import annotations

import copy
import functools
import io
import threading
import zipfile
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from solver import InputError, RuleSet, Solution, SolverError, Team, assign
from solver.reporting.svg import CHART_KINDS, chart_svg
from solver.solving.assignment import assignment_data
from solver.solving.contracts import configuration_data
from solver.solving.solution import counts_data, solution_data
from solver.solving.teamfile import team_yaml
from solver.studio.selection import SELECTION_FILE, Selection, parse_query, query_of
from solver.studio.workspace import (
    MAX_UPLOAD_FILES,
    RuleSource,
    Upload,
    Workspace,
    safe_file_name,
)

if TYPE_CHECKING:
    from solver import Profile
    from solver.studio.live import LiveFeed

__all__ = [
    "CHART_KINDS",
    "MAX_PAGE",
    "PAGE_CHECK_SECONDS",
    "Chosen",
    "Studio",
    "faults_data",
]

Pairs = Sequence[tuple[str, str]]
# Rows of one page of configurations or robots, at most.
MAX_PAGE = 500
# Files an upload of robot descriptions may hold, by how their names end.
DESCRIPTION_SUFFIXES = (".urdf", ".urdf.xacro", ".xacro", ".srdf", ".topics", ".topics.txt")
# A robot looked up is given as robot.<characteristic>=<value>.
ROBOT_PREFIX = "robot."
# Seconds the selection view gives the check of a selection (the Check view and the API give
# it the documented check-seconds): past them, what it found so far and that it stopped.
PAGE_CHECK_SECONDS = 2.0


@dataclass(frozen=True)
class Chosen:
    """A page's selection resolved: the rule set, the selection as text, and the team (``None``
    while no kinematic type is selected)."""

    source: RuleSource
    selection: Selection
    team: Team | None

    @property
    def rules(self) -> RuleSet:
        return self.source.rules

    def require(self) -> Team:
        if self.team is None:
            raise InputError.at(
                SELECTION_FILE,
                "the team selects no kinematic type; include one first",
                path="team",
                code="empty-selection",
            )
        return self.team


def faults_data(error: SolverError) -> dict[str, Any]:
    """A located error as JSON: every fault with its file, line, column and path."""
    return {
        "error": str(error),
        "faults": [
            {
                "file": fault.location.file,
                "line": fault.location.line,
                "column": fault.location.column,
                "path": fault.location.path,
                "message": fault.message,
                "code": fault.code,
            }
            for fault in error.faults
        ],
    }


def _first(pairs: Pairs, name: str) -> str | None:
    return next((value for key, value in pairs if key == name), None)


def _whole(
    pairs: Pairs, name: str, default: int, *, least: int = 0, most: int | None = None
) -> int:
    text = _first(pairs, name)
    if text is None or text == "":
        return default
    if not (text.isascii() and text.isdigit()) or len(text) > 18:
        raise InputError.at(
            SELECTION_FILE, f"{name} must be a whole number, got {text[:60]!r}", path=name
        )
    number = int(text)
    if number < least or (most is not None and number > most):
        bound = f"{least}..{most}" if most is not None else f"at least {least}"
        raise InputError.at(SELECTION_FILE, f"{name} must be {bound}, got {number}", path=name)
    return number


class Studio:
    """The studio's answers over one :class:`Workspace` (and a live feed when started so)."""

    def __init__(
        self, workspace: Workspace, live: LiveFeed | None = None, profile: Profile | None = None
    ) -> None:
        self.workspace = workspace
        self.live = live
        # The identification profile of Fleet (``studio --profile``; the shipped one if none).
        self._profile = profile
        # matplotlib's rc settings are global: one report's charts are drawn at a time.
        self._drawing = threading.Lock()

    def profile(self) -> Profile:
        """The identification profile given at start, else the shipped one."""
        if self._profile is None:
            from solver import load_profile

            self._profile = load_profile()
        return self._profile

    # -- the selection -----------------------------------------------------------------------

    def chosen(self, pairs: Pairs) -> Chosen:
        """The rule set and team a query selects (a located :class:`SolverError` if wrong)."""
        source = self.workspace.source(_first(pairs, "rules"))
        selection = parse_query(pairs, source.rules, source.id)
        team = self.workspace.team(selection, source) if selection.types else None
        return Chosen(source, selection, team)

    def solution(self, chosen: Chosen, *, listed: bool = False) -> Solution:
        return self.workspace.solution(chosen.require(), chosen.source, listed=listed)

    def solve_data(self, pairs: Pairs, *, listed: bool = False) -> dict[str, Any]:
        """``teleop-ui solve --format json`` (``--count-only`` unless ``listed``; with
        ``--list`` when ``listed``)."""
        chosen = self.chosen(pairs)
        return solution_data(self.solution(chosen, listed=listed), configurations=listed)

    def count_data(self, pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui count --format json``."""
        return counts_data(self.solution(self.chosen(pairs)))

    def configurations_data(self, pairs: Pairs) -> dict[str, Any]:
        """One page of the configurations (``offset``, ``limit``), as ``solve --list``."""
        chosen = self.chosen(pairs)
        solution = self.solution(chosen, listed=True)
        offset = _whole(pairs, "offset", 0)
        limit = _whole(pairs, "limit", 50, least=1, most=MAX_PAGE)
        page = solution.configurations[offset : offset + limit]
        return {
            "team": solution.team.name,
            "total": len(solution.configurations),
            "offset": offset,
            "limit": limit,
            "default_configuration": solution.default_configuration,
            "configurations": [configuration_data(solution.rules, c) for c in page],
        }

    def configuration_data(self, pairs: Pairs, number: int) -> dict[str, Any]:
        """One configuration (``default_configuration`` names the default one)."""
        chosen = self.chosen(pairs)
        solution = self.solution(chosen, listed=True)
        found = next((c for c in solution.configurations if c.number == number), None)
        if found is None:
            raise InputError.at(
                SELECTION_FILE,
                f"no UI configuration {number}: this team has 1..{len(solution.configurations)}"
                f" and the default {solution.default_configuration}",
                path="configuration",
            )
        return configuration_data(solution.rules, found)

    def robots_data(self, pairs: Pairs) -> dict[str, Any]:
        """One page of ``teleop-ui robots --format jsonl`` (of one configuration with
        ``configuration=N``): ``{"configuration": N, <characteristic>: value, ...}`` rows."""
        from solver.reporting.listing import robots_page

        chosen = self.chosen(pairs)
        solution = self.solution(chosen, listed=True)
        offset = _whole(pairs, "offset", 0)
        limit = _whole(pairs, "limit", 50, least=1, most=MAX_PAGE)
        number = _first(pairs, "configuration")
        configuration = None if not number else _whole(pairs, "configuration", 0, least=1)
        total = solution.totals.valid_robots
        if configuration is not None:
            found = next((c for c in solution.configurations if c.number == configuration), None)
            total = 0 if found is None else found.robots
        names = solution.rules.names
        return {
            "team": solution.team.name,
            "configuration": configuration,
            "total": total,
            "offset": offset,
            "limit": limit,
            "robots": [
                {"configuration": n, **dict(zip(names, robot, strict=True))}
                for n, robot in robots_page(solution, offset, limit, configuration=configuration)
            ],
        }

    def assign_data(self, pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui assign --format json`` for the robot given as ``robot.<name>=value``."""
        chosen = self.chosen(pairs)
        solution = self.solution(chosen, listed=True)
        combination = {
            key[len(ROBOT_PREFIX) :]: value
            for key, value in pairs
            if key.startswith(ROBOT_PREFIX) and value != ""
        }
        return assignment_data(solution, assign(solution, combination))

    def check_data(self, pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui check --format json`` on the rule set and the team the page selects;
        findings in the team are located in ``<selection>`` by their path. The check has its
        documented time budget; spent, the findings so far and an ``unfinished`` one."""
        return self._checked(self.chosen(pairs), None)[0]

    def _checked(self, chosen: Chosen, seconds: float | None) -> tuple[dict[str, Any], str | None]:
        """The check's JSON within ``seconds`` (``None``: the ``check-seconds`` limit), and the
        selection's team file it read (``None``: no team); each selection checked once while
        kept."""
        key = (chosen.source.id, chosen.selection, seconds)
        data, text = self.workspace.kept_check(key, lambda: self._check(chosen, seconds))
        return copy.deepcopy(data), text

    def _check(self, chosen: Chosen, seconds: float | None) -> tuple[dict[str, Any], str | None]:
        from solver import check_files
        from solver.check.render import json_data

        source = chosen.source
        files = [source.path]
        shown = {str(source.path): source.rules.file}
        text = None
        with self.workspace.scratch("check") as folder:
            if chosen.team is not None:
                team_path = folder / "team.yaml"
                text = team_yaml(chosen.team, rules_reference=str(source.path.resolve()))
                team_path.write_text(text, encoding="utf-8")
                files.append(team_path)
                shown[str(team_path)] = SELECTION_FILE
            data = json_data(check_files(files, time_limit=seconds, partial=True))
        data["files"] = [shown.get(f, f) for f in data["files"]]

        def relabel(message: str) -> str:
            # Messages cite files as the page names them, not where the studio keeps them.
            for path, name in shown.items():
                message = message.replace(path, name)
            return message

        for finding in data["findings"]:
            finding["file"] = shown.get(finding["file"], finding["file"])
            finding["message"] = relabel(finding["message"])
            for related in finding["related"]:
                related["file"] = shown.get(related["file"], related["file"])
                related["message"] = relabel(related["message"])
        return data, text

    def findings_data(self, pairs: Pairs) -> dict[str, Any]:
        """:meth:`check_data` within :data:`PAGE_CHECK_SECONDS` (the selection view asks it on
        every change, and never waits longer), each finding with the controls of the
        selection view it concerns
        (``places``: ``{"type", "characteristic", "value"}``, :mod:`solver.studio.findings`;
        none: the rule set or selection as a whole) and the rule set's id (``rules``), whose
        text ``/rules/source?rules=ID`` shows with its lines numbered."""
        from solver.files.yamlio import parse_document
        from solver.studio.findings import place_data, places, rule_places, selection_places

        chosen = self.chosen(pairs)
        data, text = self._checked(chosen, PAGE_CHECK_SECONDS)
        source = chosen.source
        tables = {
            source.rules.file: rule_places(source.rules, self.workspace.excluded(source)),
            SELECTION_FILE: {}
            if text is None
            else selection_places(parse_document(text, SELECTION_FILE)),
        }
        for finding in data["findings"]:
            table = tables.get(finding["file"], {})
            finding["places"] = [place_data(p) for p in places(finding["path"], table)]
        data["rules"] = source.id
        return data

    def rules_text(self, pairs: Pairs) -> tuple[RuleSource, str]:
        """The rule set a page names and its text (as read now, through the bounded reader)."""
        from solver.files.inputfile import read_text
        from solver.files.yamlio import MAX_FILE_BYTES

        source = self.workspace.source(_first(pairs, "rules"))
        text = read_text(
            source.path, display=source.rules.file, limit=MAX_FILE_BYTES, what="rule set"
        )
        return source, text

    # -- exports -----------------------------------------------------------------------------

    def team_text(self, pairs: Pairs) -> str:
        """The team as a team file, with each type's counts as comments."""
        chosen = self.chosen(pairs)
        team = chosen.require()
        solution = self.solution(chosen)
        reference = None
        if chosen.source.id != "paper":
            # Where the rule set is on this machine; a shipped one by its installed place.
            reference = str(chosen.source.path.resolve())
        return team_yaml(
            team,
            solution=solution,
            rules_reference=reference,
            header=(
                "Team selection made in teleop-ui studio; `teleop-ui solve FILE` solves it.",
                f"Rule set: {chosen.rules.name} ({chosen.rules.file}).",
            ),
        )

    def report_html(self, pairs: Pairs) -> str:
        """``teleop-ui report TEAM -o FILE.html``: the HTML report."""
        from solver import render_html

        solution = self.solution(self.chosen(pairs), listed=True)
        with self._drawing:
            return render_html(solution)

    def uvl_text(self, pairs: Pairs) -> str:
        """``teleop-ui export TEAM --format uvl``."""
        from solver import team_to_uvl

        return team_to_uvl(self.chosen(pairs).require())

    def layouts_zip(self, pairs: Pairs) -> bytes:
        """``teleop-ui layouts`` for Foxglove/Lichtblick and for RViz2, one zip of both."""
        from solver import load_presentation
        from solver.layouts.targets import TARGETS
        from solver.layouts.writer import check_layout_count, layout_texts
        from solver.limits import limit

        solution = self.solution(self.chosen(pairs), listed=True)
        presentation = load_presentation()
        check_layout_count(len(solution.configurations), "<layouts.zip>")
        most = limit("written-bytes")
        buffer = io.BytesIO()
        written = 0
        # Built in memory, one layout at a time: nothing is written to disk for a download.
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
            for fmt in TARGETS:
                for name, text in layout_texts(solution, presentation, fmt):
                    data = "".join(text).encode("utf-8")
                    written += len(data)
                    most.check(written, "<layouts.zip>", noun="bytes of layouts")
                    # A fixed date: the same team gives the same bytes.
                    info = zipfile.ZipInfo(f"{fmt}/{name}", date_time=(2017, 3, 14, 0, 0, 0))
                    info.compress_type = zipfile.ZIP_DEFLATED
                    archive.writestr(info, data)
        return buffer.getvalue()

    def chart_svg(self, pairs: Pairs, kind: str) -> bytes:
        """A chart of ``report`` (radar, bars or the component matrix) as SVG: the chart
        ``report`` draws (:mod:`solver.reporting.chart`), written straight as SVG."""
        if kind not in CHART_KINDS:
            raise InputError.at(
                SELECTION_FILE, f"no chart {kind[:40]!r}; charts: {', '.join(CHART_KINDS)}"
            )
        chosen = self.chosen(pairs)
        # Every chart, the component matrix too, from the counts: the matrix is tallied by
        # structure where it applies (no configuration listed).
        return chart_svg(self.solution(chosen), kind)

    # -- uploads -----------------------------------------------------------------------------

    def add_rules(self, upload: Upload) -> RuleSource:
        return self.workspace.add_rules(upload)

    def read_team(self, upload: Upload, pairs: Pairs) -> list[tuple[str, str]]:
        """The query that selects an uploaded team (read against the page's rule set)."""
        source = self.workspace.source(_first(pairs, "rules"))
        team = self.workspace.read_team(upload, source)
        return query_of(team, source.id)

    def identify_uploads(self, uploads: Sequence[Upload], pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui fleet`` on uploaded descriptions (never compiling xacro)."""
        if not uploads:
            raise InputError.at("<upload>", "no files were uploaded; choose URDF or SRDF files")
        if len(uploads) > MAX_UPLOAD_FILES:
            raise InputError.at(
                "<upload>",
                f"{len(uploads)} files uploaded; at most {MAX_UPLOAD_FILES} at a time",
                code="too-large",
            )
        names: set[str] = set()
        for upload in uploads:
            name = safe_file_name(upload.name)
            if not name.endswith(DESCRIPTION_SUFFIXES):
                raise InputError.at(
                    name,
                    "not a robot description: upload NAME.urdf (or .urdf.xacro, .xacro), "
                    "NAME.srdf and NAME.topics files",
                    code="invalid",
                )
            if name in names:
                raise InputError.at(name, "uploaded twice (file names must differ)")
            names.add(name)
        with self.workspace.scratch("fleet") as folder:
            for upload in uploads:
                (folder / safe_file_name(upload.name)).write_bytes(upload.data)
            return self._identify(folder, pairs, shown="")

    def identify_folder(self, index: int, pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui fleet DIR`` on a folder given at start (``--fleet``), by its index."""
        folders = self.workspace.folders
        if not 0 <= index < len(folders):
            raise InputError.at(
                "<fleet>", f"no folder {index}: the studio was given {len(folders)} (--fleet)"
            )
        return self._identify(folders[index], pairs, shown=None)

    def _identify(self, folder: Any, pairs: Pairs, *, shown: str | None) -> dict[str, Any]:
        from solver import identify_fleet
        from solver.identify import identification_data
        from solver.identify.combinations import combinations

        chosen = self.chosen(pairs)
        profile = self.profile()
        fleet = identify_fleet(folder, rules=chosen.rules, profile=profile, trust_xacro=False)
        solution = None if chosen.team is None else self.solution(chosen, listed=True)
        prefix = f"{folder}/"

        def relabel(text: str) -> str:
            # Uploads are shown by their own names, not where the studio keeps them.
            return text.replace(prefix, "") if shown is not None else text

        robots = []
        for entry in fleet.entries:
            if entry.identification is None:
                robots.append(
                    {
                        "robot": entry.name,
                        "file": relabel(entry.file),
                        "error": relabel(entry.error or ""),
                    }
                )
                continue
            found = entry.identification
            data = identification_data(
                found,
                () if solution is None else combinations(found, solution, profile),
                solution,
            )
            data["file"] = relabel(data["file"])
            for warning in data.get("warnings", []):
                warning["file"] = relabel(str(warning["file"]))
            data["error"] = None
            robots.append(data)
        fleet_id = self.workspace.fleet_id(fleet)
        return {
            "fleet": fleet_id,
            "folder": "<upload>" if shown is not None else str(folder),
            "identified": len(fleet.identified),
            "failed": len(fleet.failed),
            "robots": robots,
        }

    def fleet_team(self, fleet_id: str, pairs: Pairs) -> dict[str, Any]:
        """``teleop-ui fleet -o TEAM``: the team file of an identified fleet and the query that
        selects it in the page."""
        from solver.core.team import parse_team
        from solver.files.yamlio import parse_document
        from solver.identify import team_text

        fleet = self.workspace.fleets.get(fleet_id)
        if fleet is None:
            raise InputError.at(
                "<fleet>", f"no fleet {fleet_id[:40]!r}: identify the robots again", path="fleet"
            )
        source = self.workspace.source(_first(pairs, "rules"))
        name = _first(pairs, "name") or "fleet"
        text = team_text(fleet, source.rules, self.profile(), name=name)
        team = parse_team(parse_document(text, "<fleet team>"), source.rules)
        return {"yaml": text, "query": query_of(team, source.id)}

    # -- what the pages list -----------------------------------------------------------------

    def shipped_teams(self, source: RuleSource) -> list[tuple[str, list[tuple[str, str]]]]:
        """Shipped teams (and the one given at start) that use ``source``'s rules, with the
        query of each."""
        found: list[tuple[str, list[tuple[str, str]]]] = []
        start = self.workspace.start_team
        if start is not None and start.rules.file == source.rules.file:
            found.append((f"{start.name} (given at start)", query_of(start, source.id)))
        for team in _shipped_teams():
            if team.rules.file == source.rules.file:
                found.append((team.name, query_of(team, source.id)))
        return found


@functools.cache
def _shipped_teams() -> tuple[Team, ...]:
    from solver import load_team
    from solver.core.rules import shipped_name, shipped_path

    return tuple(
        load_team(path, display=shipped_name(path) or str(path))
        for path in sorted(shipped_path("teams").glob("*.yaml"))
    )


def robot_pairs(pairs: Iterable[tuple[str, str]]) -> dict[str, str]:
    """The robot a page looks up: ``robot.<characteristic>=value`` pairs."""
    return {k[len(ROBOT_PREFIX) :]: v for k, v in pairs if k.startswith(ROBOT_PREFIX)}
