"""Checking files: read each one, run the checks that apply, collect sorted findings.

Files are told apart by content, as every command tells them
(:func:`solver.files.filekind.file_kind`): team files, rule sets, robots' teleoperation
descriptions (read by :mod:`solver.ros.description`, every problem a located finding), and
identification profiles (not checked, said with ``not-checked``); a file of no recognisable kind
is read as a rule set. Team files are checked against

1. the rule set given with ``rules=`` (``--rules``), which is checked too; else
2. the one rule set among the files, when there is exactly one (``teleop-ui check
   my_rules.yaml rules/teams/*.yaml`` reads every team against ``my_rules.yaml``); else
3. the team's own ``rules:`` (default: the shipped paper rules), whose findings are then not
   reported unless it is among the files too.

Faults a loader finds in a file that is YAML become findings (:mod:`solver.check.load`); a file
that cannot be read or is not YAML at all makes the whole run unusable: :func:`check_files`
raises one :class:`~solver.errors.InputError` naming every such file and reports nothing
else. Files are only ever read.

A run has a time budget (the ``check-seconds`` limit, or ``time_limit``: a
:class:`~solver.deadline.Deadline` every SAT question and every per-type loop looks at), and
each rule set's SAT search a budget of conflicts. Past either the run raises (the command line
exits 2); with ``partial=True`` it returns what it found instead, with an ``unfinished``
finding (:mod:`solver.check.unfinished`): past the conflicts, the other files are still
checked; past the time, nothing more is.

Not here: the checks (the other modules of this package), printing (:mod:`solver.check.render`).
"""

from __future__ import annotations

import os
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

from solver.check.context import RulesContext, TeamContext
from solver.check.finding import LEVELS, Check, Finding, Level
from solver.check.load import LoadContext
from solver.check.registry import LOAD_CHECKS, RULE_CHECKS, TEAM_CHECKS, check_ids
from solver.check.unfinished import UNFINISHED, stopped
from solver.core.analysis import Analysis
from solver.core.rules import default_rules_path, parse_rules
from solver.core.ruleset import RuleSet
from solver.core.team import parse_team
from solver.deadline import Deadline
from solver.errors import (
    Fault,
    InputError,
    Location,
    RulesError,
    TeamError,
    TimeLimitError,
    TooLargeError,
)
from solver.files.filekind import FileKind, describe, file_kind
from solver.files.yamlio import Document, load_document
from solver.limits import limit
from solver.ros.description import DescriptionError, parse_description

__all__ = ["Report", "check_files", "is_team_document"]

# What check reads, as a file it does not read is told.
_READ = "check reads rule sets, teams and teleoperation descriptions"
# Load faults that still leave a usable document (the first of two duplicate keys is kept).
TOLERATED = frozenset({"duplicate-key"})


@dataclass(frozen=True)
class Report:
    """The findings of one run, sorted by location, and the files that were checked."""

    files: tuple[str, ...]
    findings: tuple[Finding, ...]

    @property
    def stopped(self) -> Finding | None:
        """The first ``unfinished`` finding of a partial run that stopped (``None``: the
        checks finished)."""
        return next((f for f in self.findings if f.check == UNFINISHED.id), None)

    def count(self, level: Level) -> int:
        return sum(1 for finding in self.findings if finding.level == level)

    @property
    def counts(self) -> dict[Level, int]:
        return {level: self.count(level) for level in LEVELS}

    def exit_status(self, *, strict: bool = False) -> int:
        """0 clean, 1 with findings at error level (or warning level when ``strict``)."""
        if self.count("error") or (strict and self.count("warning")):
            return 1
        return 0


def is_team_document(document: Document) -> bool:
    """Whether a loaded file is a team selection (:func:`solver.files.filekind.file_kind`)."""
    return file_kind(document) == "team"


Context = TypeVar("Context", RulesContext, TeamContext)


class _OutOfTime(Exception):
    """A partial run's time is spent: no more file is checked."""


@dataclass
class _Run:
    """The state of one :func:`check_files` call (nothing outlives it)."""

    disabled: frozenset[str]
    deadline: Deadline
    partial: bool = False
    findings: dict[Finding, None] = field(default_factory=dict)
    unusable: list[Fault] = field(default_factory=list)
    rule_sets: dict[Path, RuleSet | None] = field(default_factory=dict)
    # Keyed by identity; the rule set is kept alive beside its analysis so no id is reused.
    analyses: dict[int, tuple[RuleSet, Analysis]] = field(default_factory=dict)

    def add(self, findings: Iterable[Finding]) -> None:
        for finding in findings:
            self.findings.setdefault(finding, None)

    def load(self, path: Path, display: str) -> Document | None:
        try:
            return load_document(path, display=display, tolerate=TOLERATED)
        except InputError as error:
            self.unusable.extend(error.faults)
            return None

    def report_faults(
        self, faults: Sequence[Fault], skipped: tuple[tuple[Location, str], ...] = ()
    ) -> None:
        context = LoadContext(tuple(faults), skipped)
        for check in LOAD_CHECKS:
            if check.id not in self.disabled:
                self.add(check.run(context))

    def analysis(self, rules: RuleSet) -> Analysis:
        """One analysis per rule set, shared by the rule set's checks and its teams'."""
        if id(rules) not in self.analyses:
            self.analyses[id(rules)] = (rules, Analysis(rules, deadline=self.deadline))
        return self.analyses[id(rules)][1]

    def run_checks(self, checks: tuple[Check[Context], ...], context: Context) -> None:
        """Each check not disabled, its findings added as they come. Past the time or the
        conflicts, a partial run keeps them and says it stopped (:mod:`~solver.check.
        unfinished`); past the time it raises :class:`_OutOfTime`, as nothing more can run."""
        try:
            for check in checks:
                if check.id not in self.disabled:
                    context.analysis.check_time()
                    self.add(check.run(context))
        except TooLargeError as error:  # the conflicts or the time of the analysis
            if not self.partial:
                raise
            if UNFINISHED.id not in self.disabled:
                self.add([stopped(error)])
            if isinstance(error, TimeLimitError):
                raise _OutOfTime from None

    def rules_file(
        self, path: Path, display: str, document: Document | None = None, *, check: bool = True
    ) -> RuleSet | None:
        """Load (once) and, when ``check``, run every rule check on one rule set file."""
        key = path.resolve()
        if key in self.rule_sets and not check:
            return self.rule_sets[key]
        if document is None:
            document = self.load(path, display)
            if document is None:
                return None
        if check:
            self.report_faults(document.tolerated)
        try:
            rules: RuleSet | None = parse_rules(document)
        except RulesError as error:
            self.report_faults(error.faults)
            rules = None
        self.rule_sets[key] = rules
        if rules is not None and check:
            self.run_checks(RULE_CHECKS, RulesContext(rules, self.analysis(rules)))
        return rules

    def team_file(
        self, path: Path, document: Document, against: RuleSet | None, against_name: str | None
    ) -> None:
        self.report_faults(document.tolerated)
        if against_name is None:
            own = _own_rules(path, document)
            if own is not None:
                against = self.rules_file(own[0], own[1], check=False)
                against_name = own[1]
        if against is None and against_name is not None:
            self.report_faults(
                (),
                (
                    (
                        document.location(("rules",), key=True),
                        f"not checked: its rule set {against_name} has errors",
                    ),
                ),
            )
            return
        try:
            team = parse_team(document, against, folder=path.parent)
        except (TeamError, RulesError) as error:
            self.report_faults(error.faults)
            return
        except InputError as error:
            self.unusable.extend(error.faults)
            return
        self.run_checks(TEAM_CHECKS, TeamContext(team, document, self.analysis(team.rules)))

    def teleop_file(self, document: Document) -> None:
        """A robot's teleoperation description: its load faults as findings (too many entries:
        refused, as every input past a limit is)."""
        self.report_faults(document.tolerated)
        try:
            parse_description(document)
        except DescriptionError as error:
            self.report_faults(error.faults)
        except TooLargeError as error:
            self.unusable.extend(error.faults)


def _own_rules(path: Path, document: Document) -> tuple[Path, str] | None:
    """The rule set a team file names, as (path to read, name to show); ``None`` when the team
    loader should report the problem itself (not a string, no such file)."""
    data: dict[Any, Any] = document.data
    text = next((value for key, value in data.items() if str(key) == "rules"), None)
    if not any(str(key) == "rules" for key in data):
        default = default_rules_path()
        return default, str(default)
    if not isinstance(text, str) or not text.strip():
        return None
    relative = path.parent / text.strip()
    if not relative.is_file():
        return None
    return relative, os.path.normpath(Path(document.file).parent / text.strip())


def check_files(
    paths: Sequence[str | Path],
    *,
    rules: str | Path | None = None,
    disable: Collection[str] = (),
    time_limit: float | None = None,
    partial: bool = False,
) -> Report:
    """Check rule set and team files; see the module docstring for which rules a team meets.

    ``disable``: check ids to leave out. ``time_limit``: the seconds the run may take (default:
    the ``check-seconds`` limit, docs/security.md). Raises :class:`InputError` when a file
    cannot be read or is not YAML (every such file is named), :class:`ValueError` for an
    unknown check id, :class:`~solver.errors.TimeLimitError` past the time limit and
    :class:`~solver.errors.TooLargeError` past the ``conflicts`` limit. With ``partial``, the
    last two are not raised: the report holds what was found until then and an
    ``unfinished`` finding (:attr:`Report.stopped`), as the studio needs to answer a page in
    time::

        report = check_files(files, time_limit=2.0, partial=True)
        if report.stopped is not None: ...  # "check stopped after 2 s (limit ...)"
    """
    unknown = sorted(set(disable) - set(check_ids()))
    if unknown:
        raise ValueError(f"unknown check id(s): {', '.join(unknown)}")
    run = _Run(frozenset(disable), Deadline.start("check-seconds", "check", time_limit), partial)
    files = _files_to_read(paths, rules)
    documents = [(Path(name), d) for name in files if (d := run.load(Path(name), name)) is not None]
    if rules is not None:
        _require_a_rule_set(run, documents, rules)
    kinds = [file_kind(d) for _, d in documents]
    _note_files_not_checked(run, documents, kinds)
    rule_docs = [
        (p, d) for (p, d), kind in zip(documents, kinds, strict=True) if kind in ("rules", None)
    ]
    team_docs = [(p, d) for (p, d), kind in zip(documents, kinds, strict=True) if kind == "team"]
    for (_, document), kind in zip(documents, kinds, strict=True):
        if kind == "teleop":
            run.teleop_file(document)
    try:
        loaded = {p: run.rules_file(p, d.file, d) for p, d in rule_docs}
        against, against_name = _rule_set_for_teams(rules, rule_docs, loaded)
        for path, document in team_docs:
            run.team_file(path, document, against, against_name)
    except _OutOfTime:
        pass  # a partial run: what was found is the report
    if run.unusable:
        raise InputError(_sorted_faults(run.unusable))
    findings = sorted(run.findings, key=lambda finding: finding.sort_key)
    return Report(tuple(files), tuple(findings))


def _files_to_read(paths: Sequence[str | Path], rules: str | Path | None) -> list[str]:
    """The files named, within the limit, with ``--rules`` first when it is not among them."""
    files = [str(path) for path in paths]
    limit("check-files").check(len(files), "<arguments>")
    if rules is not None and str(rules) not in files:
        files.insert(0, str(rules))
    return files


def _require_a_rule_set(
    run: _Run, documents: list[tuple[Path, Document]], rules: str | Path
) -> None:
    """``--rules`` naming a team, profile or presentation makes the run unusable."""
    given = next((d for p, d in documents if str(p) == str(rules)), None)
    given_kind = None if given is None else file_kind(given)
    if given_kind is not None and given_kind != "rules":
        run.unusable.append(
            Fault(
                Location(str(rules)),
                f"is {describe(given_kind)}; --rules needs a rule set",
                "invalid",
            )
        )


def _note_files_not_checked(
    run: _Run, documents: list[tuple[Path, Document]], kinds: list[FileKind | None]
) -> None:
    """Profiles and presentations (rules/ holds them; they are no rule sets): said, not read."""
    for (_, document), kind in zip(documents, kinds, strict=True):
        if kind in ("profile", "presentation"):
            note = f"not checked: {describe(kind)} ({_READ})"
            run.report_faults((), ((document.location(), note),))


def _rule_set_for_teams(
    rules: str | Path | None,
    rule_docs: list[tuple[Path, Document]],
    loaded: dict[Path, RuleSet | None],
) -> tuple[RuleSet | None, str | None]:
    """The rule set every team is read against, and its name: ``--rules``, else the one rule
    set among the files; (None, None) when each team goes by its own ``rules:``."""
    if rules is not None:
        return next((r for p, r in loaded.items() if str(p) == str(rules)), None), str(rules)
    if len(rule_docs) == 1:
        return loaded[rule_docs[0][0]], rule_docs[0][1].file
    return None, None


def _sorted_faults(faults: list[Fault]) -> list[Fault]:
    unique = list(dict.fromkeys(faults))
    return sorted(
        unique, key=lambda f: (f.location.file, f.location.line or 0, f.location.column or 0)
    )
