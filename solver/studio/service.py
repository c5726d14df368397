"""Every question the studio answers, as data: the JSON of the API and what the pages show.

Each function takes the query of a page (its selection, :mod:`solver.studio.selection`) and
calls the same public functions the command line calls, returning the same JSON:
``solve --format json`` (:func:`solution_data`), ``count``, ``assign``, ``check``, ``robots``,
``identify``/``fleet``. Nothing here counts, solves or identifies by itself.

Not here: HTTP and HTML (:mod:`solver.studio.api`, :mod:`solver.studio.pages`).
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import io
import os
import threading
import zipfile
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from solver import InputError, RuleSet, Solution, SolverError, Team, assign
from solver.reporting.svg import CHART_KINDS, chart_svg, panel_radar_svg
from solver.solving.assignment import assignment_data
from solver.solving.contracts import configuration_data
from solver.solving.solution import counts_data, solution_data
from solver.solving.teamfile import team_yaml
from solver.studio.designs import DESIGNS_FILE, Designs, Entry
from solver.studio.fleetteam import fleet_name, narrowed, narrowings
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
    from solver.core.partition import Configuration
    from solver.core.team import TypeSelection
    from solver.studio.live import LiveFeed
    from solver.studio.whatif import Suggestion

__all__ = [
    "CHART_KINDS",
    "MAX_MAP_COLUMNS",
    "MAX_PAGE",
    "PAGE_CHECK_SECONDS",
    "Chosen",
    "Studio",
    "faults_data",
]

Pairs = Sequence[tuple[str, str]]
# Rows of one page of configurations or robots, at most.
MAX_PAGE = 500
# Columns of the configuration map at a time, and configurations compared at once, at most.
MAX_MAP_COLUMNS = 500
# How the map's columns may be ordered (``sort=``), the first the default: by number, by the
# valid robots served (most first), by kinematic type (the rules' order, then number).
MAP_SORTS = ("number", "robots", "type")
MAX_PICKED = 12
# What-if suggestions answered at most (the best), and the seconds its changes may take to try.
MAX_SUGGESTIONS = 10
WHATIF_SECONDS = 2.0
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


def _apply_query(suggestion: Suggestion, chosen: Chosen) -> str:
    """The query that applies a what-if suggestion: the changed selection's own, or (a change
    to the rule set, applied by ``POST /whatif/apply``) the page's selection and the change."""
    from urllib.parse import urlencode

    if suggestion.rules_change:
        pairs = query_of(suggestion.team, chosen.source.id)
        return urlencode([*pairs, ("change", suggestion.rules_change)])
    return urlencode(query_of(suggestion.team, chosen.source.id))


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
        self,
        workspace: Workspace,
        live: LiveFeed | None = None,
        profile: Profile | None = None,
        designs: Designs | None = None,
    ) -> None:
        self.workspace = workspace
        self.live = live
        # The design folder given at start (``studio --designs DIR``), if any.
        self.designs = designs
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
        if found is None and number == solution.default_configuration:
            return default_data(solution)
        if found is None:
            raise InputError.at(
                SELECTION_FILE,
                f"no UI configuration {number}: this team has 1..{len(solution.configurations)}"
                f" and the default {solution.default_configuration}",
                path="configuration",
            )
        return configuration_data(solution.rules, found)

    def map_data(self, pairs: Pairs) -> dict[str, Any]:
        """The configuration map (as FeatureIDE's): a row per component of the rules (by the
        names the rules give them), a column per configuration and the default one last; a
        cell says what the configuration's component serves. ``component=CHARACTERISTIC:NAME``
        keeps the columns that have that component; ``sort`` orders them (:data:`MAP_SORTS`,
        the default one always last); ``offset`` pages the columns
        (:data:`MAX_MAP_COLUMNS` at a time); ``pick=N`` (repeated, at most
        :data:`MAX_PICKED`) compares those configurations, the default one too."""
        chosen = self.chosen(pairs)
        solution = self.solution(chosen, listed=True)
        rules = solution.rules
        rows = [(c.name, part.name) for c in rules.characteristics for part in c.components]
        wanted = _first(pairs, "component") or ""
        if wanted and tuple(wanted.split(":", 1)) not in rows:
            raise InputError.at(
                SELECTION_FILE,
                f"no component {shown_text(wanted)} in the rules; name it CHARACTERISTIC:NAME",
                path="component",
            )
        # Filtered on the configurations themselves, and only the page shown (and those
        # compared) written out: a team of 500,000 configurations is not built whole.
        order = _map_sort(pairs)
        # The default configuration, last whatever the order: it has every component.
        kept: list[Configuration | None] = [*_map_order(rules, solution, wanted, order), None]
        offset = _whole(pairs, "offset", 0)
        columns = [_column(solution, c) for c in kept[offset : offset + MAX_MAP_COLUMNS]]
        picked = _picked(pairs)
        by_number = {c["number"]: c for c in columns}
        compared = [by_number.get(n) or self.configuration_data(pairs, n) for n in picked]
        return {
            "team": solution.team.name,
            "total": len(kept),
            "offset": offset,
            "limit": MAX_MAP_COLUMNS,
            "component": wanted,
            "sort": order,
            "sorts": list(MAP_SORTS),
            "default_configuration": solution.default_configuration,
            "rows": [{"characteristic": c, "component": n} for c, n in rows],
            "columns": [
                {
                    "number": c["number"],
                    "kinematic_type": c["kinematic_type"],
                    "valid_robots": c["valid_robots"],
                    "default": bool(c.get("default")),
                    "cells": [_cell(c, characteristic, name) for characteristic, name in rows],
                }
                for c in columns
            ],
            "compared": compared,
        }

    def whatif_data(self, pairs: Pairs) -> dict[str, Any]:
        """What-if (:mod:`solver.studio.whatif`): the single changes of the team that save UI
        configurations, best first (at most :data:`MAX_SUGGESTIONS`), each with its counts
        after and the query that applies it; how many of the changes were tried, why the rest
        were not, and those tried but not counted (the first :data:`MAX_SUGGESTIONS`).
        ``{"superseded": true}`` when a newer what-if was asked while this one waited (it
        is not made: :meth:`Workspace.kept_whatif`)."""
        from solver.studio.whatif import what_if

        chosen = self.chosen(pairs)
        team = chosen.require()
        key = (chosen.source.id, chosen.selection, "what-if")
        solution = self.solution(chosen)  # counted once: what-if starts from it
        totals = solution.totals
        found = self.workspace.kept_whatif(
            key, lambda: what_if(team, seconds=WHATIF_SECONDS, base=solution)
        )
        if found is None:
            return {"team": team.name, "superseded": True}
        suggestions = []
        for suggestion in found.suggestions[:MAX_SUGGESTIONS]:
            suggestions.append(
                {
                    "change": suggestion.text,
                    "type": suggestion.kinematic_type,
                    "characteristic": suggestion.characteristic,
                    "kind": suggestion.kind,
                    "value": suggestion.value,
                    "ui_configurations_saved": suggestion.configurations_saved,
                    "valid_robots_lost": suggestion.robots_lost,
                    "after": {
                        "valid_robots": totals.valid_robots - suggestion.robots_lost,
                        "ui_configurations": totals.ui_configurations
                        - suggestion.configurations_saved,
                    },
                    "query": _apply_query(suggestion, chosen),
                    "rules_change": suggestion.rules_change,
                }
            )
        return {
            "team": team.name,
            "totals": {
                "valid_robots": totals.valid_robots,
                "ui_configurations": totals.ui_configurations,
            },
            "tried": found.tried,
            "total": found.total,
            "stopped": found.stopped,
            "left_out": [
                {"change": left.change, "reason": left.reason}
                for left in found.left_out[:MAX_SUGGESTIONS]
            ],
            "left_out_count": len(found.left_out),
            "found": len(found.suggestions),
            "suggestions": suggestions,
        }

    def whatif_apply(self, pairs: Pairs) -> list[tuple[str, str]]:
        """Apply what-if's change to the rule set named by ``change``
        (:attr:`solver.studio.whatif.RuleChange.key`): the changed rule set is kept as an
        uploaded one is (:meth:`Workspace.add_rules`, its file in the private folder), and the
        query that selects the same team under it is answered."""
        from solver.studio.whatif import changed_rules_text

        chosen = self.chosen(pairs)
        team = chosen.require()
        text = changed_rules_text(chosen.rules, _first(pairs, "change") or "")
        stem = Path(chosen.rules.file).stem
        source = self.workspace.add_rules(Upload(f"{stem}-whatif.yaml", text.encode()))
        return query_of(dataclasses.replace(team, rules=source.rules), source.id)

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
        return team_yaml(
            team,
            solution=solution,
            rules_reference=rules_reference(chosen.source),
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

    def layouts_refused(self, pairs: Pairs) -> str:
        """Why the layouts of the selection cannot be exported (too many files for the
        ``written-files`` limit), from its counts alone, before anything is listed or written
        (``""``: they can)."""
        from solver.layouts.writer import check_layout_count

        totals = self.solution(self.chosen(pairs)).totals
        try:
            check_layout_count(totals.ui_configurations, "<layouts.zip>")
        except SolverError as error:
            return error.faults[0].message
        return ""

    def layouts_zip(self, pairs: Pairs) -> bytes:
        """``teleop-ui layouts`` for Foxglove/Lichtblick and for RViz2, one zip of both."""
        from solver import load_presentation
        from solver.layouts.targets import TARGETS
        from solver.layouts.writer import check_layout_count, layout_texts
        from solver.limits import limit

        chosen = self.chosen(pairs)
        # Refused from the counts, before a configuration is listed (layouts_refused).
        check_layout_count(self.solution(chosen).totals.ui_configurations, "<layouts.zip>")
        solution = self.solution(chosen, listed=True)
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
        if kind not in (*CHART_KINDS, "panel"):
            raise InputError.at(
                SELECTION_FILE,
                f"no chart {kind[:40]!r}; charts: {', '.join(CHART_KINDS)}, panel",
            )
        chosen = self.chosen(pairs)
        # Every chart, the component matrix too, from the counts: the matrix is tallied by
        # structure where it applies (no configuration listed). The panel: the radar chart
        # beside the selection's totals, its texts readable at the panel's width and each
        # value a stop of the keyboard (solver.reporting.svg.panel_radar_svg).
        if kind == "panel":
            return panel_radar_svg(self.solution(chosen))
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
        narrow = narrowings(fleet, chosen.rules, profile, self.workspace.excluded(chosen.source))
        return {
            "fleet": fleet_id,
            "team_name": fleet_name(fleet),
            "narrowed": [n.sentence for n in narrow],
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
        # A name of its own (never the page's team's), and nothing the robots do not have
        # (solver.studio.fleetteam).
        name = fleet_name(fleet)
        text = team_text(fleet, source.rules, self.profile(), name=name)
        found = narrowings(fleet, source.rules, self.profile(), self.workspace.excluded(source))
        team = narrowed(parse_team(parse_document(text, "<fleet team>"), source.rules), found, name)
        text = team_yaml(
            team,
            header=(
                f"Team made by teleop-ui studio from {len(fleet.identified)} identified robot(s).",
                *(n.sentence for n in found),
            ),
        )
        return {
            "yaml": text,
            "query": query_of(team, source.id),
            "narrowed": [n.sentence for n in found],
        }

    # -- designs (``--designs DIR``) -----------------------------------------------------------

    def design_folder(self) -> Designs:
        if self.designs is None:
            raise InputError.at(
                DESIGNS_FILE, "the studio was started without --designs DIR", path="designs"
            )
        return self.designs

    def designs_list(self) -> tuple[list[Entry], int]:
        """The design folder's entries (designs and refusals) and how many were left out."""
        return self.design_folder().entries()

    def save_design(self, name: str, pairs: Pairs) -> str:
        """The page's selection saved as design ``name`` (the team takes that name); its
        file name. A design under an uploaded rule set is refused: the upload is gone when
        the studio stops, and the design could not be read again."""
        from solver.studio.designs import design_name

        folder = self.design_folder()
        name = design_name(name)
        pairs = [(k, v) for k, v in pairs if k != "name"] + [("name", name)]
        chosen = self.chosen(pairs)
        team = chosen.require()
        if chosen.source.origin == "upload":
            raise InputError.at(
                DESIGNS_FILE,
                "a design under an uploaded rule set is not saved: the upload is gone when the "
                "studio stops; put the rule set in a file and start the studio with it",
                path="rules",
            )
        text = team_yaml(
            team,
            solution=self.solution(chosen),
            rules_reference=rules_reference(chosen.source, folder.folder),
            header=(
                f"Design {name}, saved by teleop-ui studio; `teleop-ui solve FILE` solves it.",
            ),
        )
        return folder.save(name, text)

    def delete_design(self, name: str) -> None:
        self.design_folder().delete(name)

    def design_query(self, name: str) -> list[tuple[str, str]]:
        """The query that selects design ``name`` (located errors: no design, no team, a rule
        set the studio may not read)."""
        from solver.core.team import parse_team
        from solver.files.filekind import require_kind

        folder = self.design_folder()
        document = folder.read(name)
        require_kind(document, "team")
        source = self._design_source(document, folder)
        team = parse_team(document, source.rules)
        return query_of(team, source.id)

    def _design_source(self, document: Any, folder: Designs) -> RuleSource:
        """The rule set a design names: none (the article's), a shipped one by its name, or
        the one given at start by its path from the design folder; nothing else is read."""
        data = document.data
        if not isinstance(data, dict) or "rules" not in data:
            return self.workspace.source("paper")
        text = data["rules"]  # `rules:` with nothing is no rule set (`solve` refuses it too)
        allowed = []
        for source in self.workspace.rule_sources:
            if source.origin == "shipped":
                allowed.append(source.id)
                if text == source.id:
                    return source
            elif source.origin == "start":
                # As `teleop-ui solve` reads it: from the folder the OS opens (through a link in
                # the folder's own path), as `save_design` wrote it.
                here = folder.folder.resolve()
                allowed.append(os.path.relpath(source.path.resolve(), here))
                given = os.path.normpath(os.path.join(here, str(text)))
                if given == os.path.normpath(source.path.resolve()):
                    return source
        where = document.location(("rules",))
        raise InputError.at(
            document.file,
            f"rules {shown_text(text)}: a design names a shipped rule set or the one given "
            f"at start ({', '.join(allowed)}); this studio reads no other path",
            line=where.line,
            column=where.column,
            path="rules",
            code="unknown-reference",
        )

    def design_diff(self, first: str, second: str) -> dict[str, Any]:
        """What changed from design ``first`` to ``second``: kinematic types and values added
        and removed (per type and characteristic), and the counts of each with the change."""
        chosen = [self.chosen(self.design_query(name)) for name in (first, second)]
        teams = [c.require() for c in chosen]
        totals = [self.solution(c).totals for c in chosen]
        changes = _team_changes(teams[0], teams[1])
        return {
            "designs": [first, second],
            "rules": [c.rules.name for c in chosen],
            "changes": changes,
            "valid_robots": [t.valid_robots for t in totals],
            "ui_configurations": [t.ui_configurations for t in totals],
            "change": {
                "valid_robots": totals[1].valid_robots - totals[0].valid_robots,
                "ui_configurations": totals[1].ui_configurations - totals[0].ui_configurations,
            },
        }

    # -- what the pages list -----------------------------------------------------------------

    def starts(self) -> list[tuple[str, str, list[tuple[str, str]]]]:
        """Every team to start from in one click, whatever its rule set: the one given at
        start, then the shipped ones (the article's cases first), each as (name, rule set id,
        query)."""
        found: list[tuple[str, str, list[tuple[str, str]]]] = []
        by_file = {s.rules.file: s for s in self.workspace.rule_sources if s.origin != "upload"}
        start = self.workspace.start_team
        if start is not None and start.rules.file in by_file:
            given = by_file[start.rules.file]
            found.append((f"{start.name} (given at start)", given.id, query_of(start, given.id)))
        teams = sorted(_shipped_teams(), key=lambda t: (not t.name.startswith("Case"), t.name))
        for team in teams:
            source = by_file.get(team.rules.file)
            if source is not None:
                found.append((team.name, source.id, query_of(team, source.id)))
        return found

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


def default_data(solution: Solution) -> dict[str, Any]:
    """The default configuration as :func:`~solver.solving.contracts.configuration_data`
    writes a configuration: every component of every characteristic. It serves the robots the
    selection leaves out (a value not selected, a count beyond the range), so no valid robot."""
    return {
        "number": solution.default_configuration,
        "kinematic_type": "default",
        "default": True,
        "valid_robots": 0,
        "components": [
            {
                "characteristic": c.name,
                "component": "every component",
                "values": [part.name for part in c.components],
            }
            for c in solution.rules.characteristics
        ],
    }


def _map_sort(pairs: Pairs) -> str:
    """The map's order ``sort=`` names (:data:`MAP_SORTS`; by number when none)."""
    order = _first(pairs, "sort") or MAP_SORTS[0]
    if order not in MAP_SORTS:
        raise InputError.at(
            SELECTION_FILE,
            f"no map order {shown_text(order)}; sort by one of {', '.join(MAP_SORTS)}",
            path="sort",
        )
    return order


def _map_order(rules: RuleSet, solution: Solution, wanted: str, order: str) -> list[Configuration]:
    """The configurations that have the component ``wanted`` (all when none), in ``order``:
    by number, by the valid robots served (most first, then number) or by kinematic type (the
    rules' order of the types, then number). The sorts are stable on the numbered list."""
    kept = list(solution.configurations)
    if wanted:
        place, name = _component_place(rules, wanted)
        kept = [c for c in kept if c.components[place].name == name]
    if order == "robots":
        kept.sort(key=lambda c: -c.robots)
    elif order == "type":
        types = {str(value): i for i, value in enumerate(rules.key.values)}
        kept.sort(key=lambda c: types.get(c.kinematic_type, len(types)))
    return kept


def _component_place(rules: RuleSet, wanted: str) -> tuple[int, str]:
    """``(the characteristic's place, the component's name)`` of ``CHARACTERISTIC:NAME``."""
    characteristic, name = wanted.split(":", 1)
    names = [c.name for c in rules.characteristics]
    return names.index(characteristic), name


def _column(solution: Solution, configuration: Configuration | None) -> dict[str, Any]:
    """One column of the map: a configuration as ``configuration_data`` writes it, or the
    default one (``None``)."""
    if configuration is None:
        return default_data(solution)
    return configuration_data(solution.rules, configuration)


def _cell(column: dict[str, Any], characteristic: str, component: str) -> str:
    """What ``column``'s ``component`` of ``characteristic`` serves ("" when it has none)."""
    if column.get("default"):
        return "yes"
    for entry in column["components"]:
        if entry["characteristic"] == characteristic and entry["component"] == component:
            if "values" in entry:
                return ", ".join(map(str, entry["values"]))
            return ", ".join(f"{a}" if a == b else f"{a}..{b}" for a, b in entry["counts"])
    return ""


def _picked(pairs: Pairs) -> list[int]:
    """The configurations ``pick=N`` names (whole numbers, each once, at most
    :data:`MAX_PICKED`)."""
    found: list[int] = []
    for key, value in pairs:
        if key != "pick" or not (value.isascii() and value.isdigit()) or len(value) > 18:
            continue
        if int(value) not in found:
            found.append(int(value))
    if len(found) > MAX_PICKED:
        raise InputError.at(
            SELECTION_FILE,
            f"{len(found)} configurations picked; compare at most {MAX_PICKED} at once",
            path="pick",
        )
    return found


def shown_text(value: object) -> str:
    """A value from a stranger's file, quoted and escaped for a message."""
    from solver.untrusted import shown

    return shown(str(value), quoted=True)


def _team_changes(before: Team, after: Team) -> list[dict[str, Any]]:
    """Per kinematic type: added or removed whole, or each characteristic's values added and
    removed (by value, in the rule set's order). Characteristics are matched by name: two
    designs under different rule sets may order them differently, or have one the other
    lacks (all its values added, or removed)."""
    old = {s.kinematic_type: s for s in before.selections}
    new = {s.kinematic_type: s for s in after.selections}
    changes: list[dict[str, Any]] = []
    for name in [*old, *(n for n in new if n not in old)]:
        if name not in new or name not in old:
            changes.append({"type": name, "change": "removed" if name in old else "added"})
            continue
        was = _domains(before, old[name])
        now = _domains(after, new[name])
        for key in [*now, *(n for n in was if n not in now)]:
            change = _values_changed((now.get(key) or was[key])[0], was, now)
            if change is not None:
                changes.append({"type": name, **change})
    return changes


Domains = dict[str, tuple[Any, tuple[Any, ...]]]


def _values_changed(characteristic: Any, was: Domains, now: Domains) -> dict[str, Any] | None:
    """The values of ``characteristic`` added and removed from ``was`` to ``now`` (``None``:
    no change)."""
    kept = was[characteristic.name][1] if characteristic.name in was else ()
    made = now[characteristic.name][1] if characteristic.name in now else ()
    added = _shown_values(characteristic, [v for v in made if v not in kept])
    removed = _shown_values(characteristic, [v for v in kept if v not in made])
    if not (added or removed):
        return None
    return {"characteristic": characteristic.name, "added": added, "removed": removed}


def _domains(team: Team, selection: TypeSelection) -> Domains:
    """``selection``'s values by characteristic name (the team key left out), each with its
    characteristic."""
    rules = team.rules
    return {
        c.name: (c, domain)
        for c, domain in zip(rules.characteristics, selection.domains, strict=True)
        if c.name != rules.team_key
    }


def _shown_values(characteristic: Any, values: list[Any]) -> list[str]:
    """Values as a diff shows them: counts in runs (``6..13``), other values one by one."""
    if characteristic.kind != "integer":
        return [str(v) for v in values]
    runs: list[list[int]] = []
    for count in sorted(int(v) for v in values):
        if runs and runs[-1][1] == count - 1:
            runs[-1][1] = count
        else:
            runs.append([count, count])
    return [str(a) if a == b else f"{a}..{b}" for a, b in runs]


def rules_reference(source: RuleSource, folder: Path | None = None) -> str | None:
    """What a team file written by the studio says in ``rules:`` for ``source``: nothing for
    the article's rules (a team naming none is read against them), a shipped set by its name
    (``extended``: it solves on any machine with teleop-ui), any other by its path, relative
    to ``folder`` (where the file is kept) when given, else absolute."""
    if source.origin == "shipped":
        return None if source.id == "paper" else source.id
    path = source.path.resolve()
    if folder is not None:
        return os.path.relpath(path, folder.resolve())
    return str(path)


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
