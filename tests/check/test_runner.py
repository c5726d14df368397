"""Checking many files at once: which rules a team is read against, exit status, safety."""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from pathlib import Path

import pytest

from solver.check import check_files
from solver.errors import InputError, SolverError
from tests.check.helpers import fixture
from tests.conftest import RULES, TEAMS


def _checks(files: list[Path], **options: object) -> list[tuple[str, str]]:
    report = check_files(files, **options)  # type: ignore[arg-type]  # keywords of several types
    return [(Path(f.location.file).name, f.check) for f in report.findings]


def test_teams_are_checked_against_the_one_rule_set_among_the_files() -> None:
    # Against base.yaml (no constraints) nothing is forbidden; its own constrained.yaml
    # forbids two of its selections.
    assert _checks([fixture("base.yaml"), fixture("team-forbidden-value.team.yaml")]) == [
        ("base.yaml", "bound")
    ]
    assert [check for _, check in _checks([fixture("team-forbidden-value.team.yaml")])] == [
        "team-forbidden-value"
    ] * 2


def test_rules_option_wins_and_its_rule_set_is_checked_too() -> None:
    found = _checks(
        [fixture("base.yaml"), fixture("team-forbidden-value.team.yaml")],
        rules=fixture("constrained.yaml"),
    )
    assert ("constrained.yaml", "core-value") in found
    assert [c for c in found if c[1] == "team-forbidden-value"] == [
        ("team-forbidden-value.team.yaml", "team-forbidden-value")
    ] * 2


def test_with_two_rule_sets_teams_use_their_own_rules() -> None:
    found = _checks(
        [
            fixture("base.yaml"),
            fixture("inclusive-equation-2.yaml"),
            fixture("team-forbidden-value.team.yaml"),
        ]
    )
    assert found.count(("team-forbidden-value.team.yaml", "team-forbidden-value")) == 2


def test_a_team_against_rules_that_fail_to_load_is_not_checked() -> None:
    found = _checks([fixture("schema.yaml"), fixture("clean.team.yaml")])
    assert found == [("clean.team.yaml", "not-checked"), ("schema.yaml", "schema")]


def test_the_same_file_twice_reports_each_finding_once() -> None:
    once = check_files([fixture("void.yaml")]).findings
    assert check_files([fixture("void.yaml"), fixture("void.yaml")]).findings == once


def test_disabled_checks_do_not_report_and_unknown_ids_are_refused() -> None:
    found = _checks([fixture("literal-equation-2.yaml")], disable=["coverage-gap", "bound"])
    assert found == [("literal-equation-2.yaml", "unbounded-range")]
    with pytest.raises(ValueError, match="unknown check id"):
        check_files([fixture("base.yaml")], disable=["no-such-check"])


def test_exit_status_is_1_for_errors_and_for_warnings_only_when_strict() -> None:
    warnings_only = check_files([fixture("unbounded-range.yaml")])
    assert warnings_only.exit_status() == 0
    assert warnings_only.exit_status(strict=True) == 1
    assert check_files([fixture("void.yaml")]).exit_status() == 1
    assert check_files([fixture("constrained.yaml")]).exit_status(strict=True) == 0


def test_the_shipped_rule_sets_and_teams_have_no_problem() -> None:
    report = check_files(
        [
            RULES / "paper.yaml",
            *sorted(
                p
                for p in TEAMS.glob("*.yaml")
                if p.stem not in ("search-and-rescue", "marine-survey")
            ),
        ]
    )
    assert [f.check for f in report.findings] == ["bound"]
    hypothesis = check_files([RULES / "paper-case3-hypothesis.yaml"])
    assert [f.check for f in hypothesis.findings] == ["bound"]


def test_checking_never_modifies_the_files_it_reads(
    tmp_path: Path, write_file: Callable[[str, str], Path]
) -> None:
    files = [
        write_file(name, fixture(name).read_text(encoding="utf-8"))
        for name in ("duplicate-key.yaml", "constrained.yaml", "void-type.yaml")
    ]
    team = write_file(
        "team.yaml", fixture("team-forbidden-value.team.yaml").read_text(encoding="utf-8")
    )
    before = {
        p: (p.stat().st_mtime_ns, hashlib.sha256(p.read_bytes()).hexdigest())
        for p in tmp_path.iterdir()
    }
    check_files([*files, team])
    after = {
        p: (p.stat().st_mtime_ns, hashlib.sha256(p.read_bytes()).hexdigest())
        for p in tmp_path.iterdir()
    }
    assert after == before


def test_a_team_file_given_as_the_rules_is_unusable_input() -> None:
    with pytest.raises(InputError, match="is a team file; --rules needs a rule set"):
        check_files([fixture("base.yaml")], rules=fixture("clean.team.yaml"))


TELEOP = "teleop: 1\nmotion_controls:\n  - {control: Driving, topic: /cmd_vel}\n"


def test_a_teleoperation_description_that_reads_clean_has_no_finding(tmp_path: Path) -> None:
    described = tmp_path / "rover.teleop.yaml"
    described.write_text(TELEOP, encoding="utf-8")
    assert check_files([described]).findings == ()


def test_every_problem_of_a_teleoperation_description_is_a_located_finding(
    tmp_path: Path,
) -> None:
    described = tmp_path / "rover.teleop.yaml"
    described.write_text(
        TELEOP + "  - {control: Driving, topic: cmd_vel}\nsensors: [{kind: lidar, count: -1}]\n",
        encoding="utf-8",
    )
    report = check_files([described])
    assert [(f.check, f.location.line, f.location.path) for f in report.findings] == [
        ("duplicate-value", 4, "motion_controls[1].control"),
        ("schema", 4, "motion_controls[1].topic"),
        ("schema", 5, "sensors[0].count"),
    ]
    assert report.exit_status() == 1


def test_a_teleoperation_description_past_its_limit_makes_the_run_unusable(
    tmp_path: Path,
) -> None:
    described = tmp_path / "big.teleop.yaml"
    described.write_text("teleop: 1\nsensors:\n" + "  - {kind: imu}\n" * 1001, encoding="utf-8")
    with pytest.raises(SolverError, match="limit 'description-entries'"):
        check_files([described])
