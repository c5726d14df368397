"""A check past its budgets: the command line refuses the rule set with the file and the limit
named (exit 2, nothing on stdout); a partial run (what the studio asks for) returns what it
found with an ``unfinished`` finding instead, and normal rule sets never meet either."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest

from solver import limits
from solver.check import check_files, get
from solver.errors import Location, TimeLimitError, TooLargeError
from solver.limits import limit
from tests.check.helpers import fixture, intricate_rules
from tests.conftest import ROOT, run_cli

WriteFile = Callable[[str, str], Path]


@pytest.fixture(scope="module")
def intricate(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Written by the test: checking it in full takes minutes (see its generator)."""
    path = tmp_path_factory.mktemp("intricate") / "intricate.yaml"
    path.write_text(intricate_rules(), encoding="utf-8")
    return path


def _every_pair_forbidden(write_file: WriteFile) -> Path:
    """No robot at all: the SAT search needs 2 conflicts to see it."""
    every = "".join(f"  - forbid: {{a: {a}, b: {b}}}\n" for a in ("a1", "a2") for b in ("b1", "b2"))
    return write_file(
        "pairs.yaml",
        "characteristics:\n  kinematic_type: {values: [A]}\n"
        "  a: {values: [a1, a2]}\n  b: {values: [b1, b2]}\nconstraints:\n" + every,
    )


def test_the_command_line_refuses_a_rule_set_past_its_time_limit_naming_file_and_limit(
    intricate: Path,
) -> None:
    result = run_cli("check", "--time-limit", "0.5", intricate)
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == (
        f"{intricate}: check stopped after 0.5 s (limit 'check-seconds', docs/security.md; "
        "--time-limit sets it)\n"
    )


def test_the_python_api_raises_a_located_time_limit_error(intricate: Path) -> None:
    with pytest.raises(TimeLimitError) as caught:
        check_files([intricate], time_limit=0.5)
    (fault,) = caught.value.faults
    assert fault.location == Location(str(intricate))
    assert fault.message.startswith("check stopped after 0.5 s (limit 'check-seconds'")


def test_a_partial_run_past_its_time_returns_what_it_found_and_says_it_stopped(
    intricate: Path,
) -> None:
    report = check_files([intricate], time_limit=0.5, partial=True)
    assert report.stopped is not None
    assert report.stopped.location == Location(str(intricate))
    assert report.stopped.level == get("unfinished").level == "warning"
    assert report.stopped.message == (
        "check stopped after 0.5 s (limit 'check-seconds', docs/security.md; --time-limit "
        "sets it): the checks did not finish, so findings may be missing"
    )
    # It stops while finding each type's live values, before any finding of the rule set.
    assert report.findings == (report.stopped,)
    assert report.exit_status() == 0
    assert report.exit_status(strict=True) == 1


def test_a_partial_run_past_the_conflicts_of_one_rule_set_still_checks_the_others(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(limits._BY_NAME, "conflicts", replace(limit("conflicts"), value=1))
    pairs = _every_pair_forbidden(write_file)
    with pytest.raises(TooLargeError, match="limit 'conflicts'"):
        check_files([pairs])
    report = check_files([pairs, fixture("literal-equation-2.yaml")], partial=True)
    assert report.stopped is not None
    assert (report.stopped.location.file, report.stopped.location.path) == (
        str(pairs),
        "constraints",
    )
    assert "at most 1 are accepted (limit 'conflicts', docs/security.md): the checks did " in (
        report.stopped.message
    )
    # The other rule set was checked in full: its four gaps are there.
    assert [f.check for f in report.findings].count("coverage-gap") == 4


def test_a_partial_run_can_leave_the_unfinished_finding_out(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(limits._BY_NAME, "conflicts", replace(limit("conflicts"), value=1))
    report = check_files([_every_pair_forbidden(write_file)], partial=True, disable=["unfinished"])
    assert report.stopped is None
    assert report.findings == ()


@pytest.mark.parametrize(
    "files",
    [
        ["rules/paper.yaml", "rules/teams/case3.yaml"],
        ["rules/extended.yaml", "rules/teams/search-and-rescue.yaml"],
        ["rules/marine.yaml", "rules/teams/marine-survey.yaml"],
        [
            "tests/fixtures/check/constrained.yaml",
            "tests/fixtures/check/team-forbidden-value.team.yaml",
        ],
    ],
)
def test_shipped_rule_sets_check_alike_with_and_without_a_partial_report(files: list[str]) -> None:
    paths = [ROOT / name for name in files]
    whole = check_files(paths)
    partial = check_files(paths, partial=True)
    assert partial.stopped is None
    assert partial == whole
