"""One answer to "is this file a team, a rule set or a profile?", and every command gives it."""

from __future__ import annotations

import csv
from collections.abc import Callable
from pathlib import Path

import pytest

from solver.check.runner import check_files
from solver.core.rules import load_rules
from solver.core.team import load_team
from solver.errors import InputError
from solver.files.filekind import describe, file_kind, require_kind
from solver.files.yamlio import load_document, parse_document
from tests.conftest import RULES, TEAMS, run_cli

# A team file that also carries a rule set's field: it is a team (with one unknown field).
TEAM_WITH_CHARACTERISTICS = """\
name: Mixed
characteristics: {}
team:
  UAV: {motion_control: [Flight], sensor_type: [2D Camera], sensor_count: 2}
"""


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("team: {}\n", "team"),
        (TEAM_WITH_CHARACTERISTICS, "team"),
        ("name: x\nrules: paper.yaml\n", "team"),
        ("name: x\ncharacteristics: {}\n", "rules"),
        ("characteristics: {}\npatterns: {}\n", "profile"),
        ("name: x\n", None),
        ("- a list\n", None),
    ],
)
def test_the_kind_of_a_file_is_decided_by_its_top_level_keys(
    text: str, kind: str | None, write_file: Callable[[str, str], Path]
) -> None:
    assert file_kind(load_document(write_file("file.yaml", text))) == kind


def test_the_shipped_files_are_of_the_kind_their_folder_says() -> None:
    kinds = {path.name: file_kind(load_document(path)) for path in RULES.glob("*.yaml")}
    assert kinds == {
        "paper.yaml": "rules",
        "paper-case3-hypothesis.yaml": "rules",
        "extended.yaml": "rules",
        "marine.yaml": "rules",
        "identification.yaml": "profile",
        "presentation.yaml": "presentation",
    }
    assert {file_kind(load_document(path)) for path in TEAMS.glob("*.yaml")} == {"team"}


def test_check_batch_and_count_all_read_a_team_with_characteristics_as_a_team(
    write_file: Callable[[str, str], Path], tmp_path: Path
) -> None:
    mixed = write_file("teams/mixed.yaml", TEAM_WITH_CHARACTERISTICS)
    unknown_field = "unknown team file field 'characteristics'"
    report = check_files([mixed])
    assert [finding.check for finding in report.findings] == ["schema"]
    assert unknown_field in report.findings[0].message
    count = run_cli("count", mixed)
    assert count.returncode == 2
    assert unknown_field in count.stderr
    run_cli("batch", tmp_path / "teams", "-o", tmp_path / "out")
    with (tmp_path / "out" / "summary.csv").open(encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert [(row["status"], unknown_field in row["message"]) for row in rows] == [("failed", True)]


def test_solving_a_rule_set_says_it_is_a_rule_set_and_to_pass_a_team() -> None:
    result = run_cli("solve", "rules/paper.yaml")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr.splitlines() == [
        "rules/paper.yaml:6:1: this is a rule set, not a team file (it has 'characteristics:' "
        "and no 'team:'); pass a team (a file with 'rules:' naming this file and 'team:' "
        "selecting values per kinematic type, or a shipped team such as case3); "
        "`teleop-ui count FILE` counts every robot of a rule set"
    ]


def test_loading_the_wrong_kind_of_file_raises_a_located_input_error() -> None:
    with pytest.raises(InputError) as team_as_rules:
        load_rules(TEAMS / "case1.yaml")
    assert "this is a team file, not a rule set" in str(team_as_rules.value)
    with pytest.raises(InputError) as profile_as_team:
        load_team(RULES / "identification.yaml")
    (fault,) = profile_as_team.value.faults
    assert (fault.location.line, fault.code) == (6, "wrong-kind")
    assert fault.message.startswith("this is an identification profile, not a team file")


@pytest.mark.parametrize(
    ("name", "what", "why"),
    [
        (
            "identification.yaml",
            "an identification profile",
            "it has 'extends:', or 'characteristics:' and profile sections such as 'patterns:'",
        ),
        ("presentation.yaml", "a presentation profile", "it has 'profile: presentation'"),
    ],
)
def test_check_says_a_profile_is_not_checked_and_batch_skips_it(
    name: str, what: str, why: str, tmp_path: Path
) -> None:
    report = check_files([RULES / name])
    assert [(f.check, f.level, f.message) for f in report.findings] == [
        (
            "not-checked",
            "info",
            f"not checked: {what} (check reads rule sets, teams and teleoperation descriptions)",
        )
    ]
    run_cli("batch", RULES / name, "-o", tmp_path / "out")
    with (tmp_path / "out" / "summary.csv").open(encoding="utf-8") as stream:
        (row,) = csv.DictReader(stream)
    assert (row["status"], row["message"]) == ("skipped", f"not a team file: {what} ({why})")


def test_a_teleoperation_description_is_its_own_kind_and_no_team() -> None:
    document = parse_document("teleop: 1\nrobot: rover\n", "rover.teleop.yaml")
    assert file_kind(document) == "teleop"
    assert describe("teleop") == "a teleoperation description"
    with pytest.raises(InputError) as caught:
        require_kind(document, "team")
    assert caught.value.faults[0].message.startswith(
        "this is a teleoperation description, not a team file (it has 'teleop:'); pass a team"
    )
