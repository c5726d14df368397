"""Load faults of files that are YAML become findings under stable check ids."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from solver.check import check_files
from solver.check.load import check_id
from solver.errors import Fault, InputError, Location
from solver.files.yamlio import parse_document
from tests.check.helpers import findings


def test_duplicate_key_names_the_first_occurrence_and_the_rest_is_still_checked() -> None:
    found = findings("duplicate-key.yaml")
    [duplicate] = [f for f in found if f.check == "duplicate-key"]
    assert duplicate.message == (
        "characteristics.sensor_count.components[0].min: duplicate key 'min' (first at line 21)"
    )
    # The first 'min' was kept, so the rule set loads and its bound is still reported.
    assert [f.check for f in found] == ["bound", "duplicate-key"]


def test_duplicate_value_names_the_first_occurrence() -> None:
    [duplicate] = findings("duplicate-value.yaml", check="duplicate-value")
    assert "duplicate value 'Lidar' in 'sensor_type' (first at" in duplicate.message
    assert duplicate.message.endswith("duplicate-value.yaml:7:22)")


def test_unknown_reference_suggests_the_closest_name() -> None:
    [unknown] = findings("unknown-reference.yaml")
    assert unknown.check == "unknown-reference"
    assert unknown.message.endswith("unknown sensor_type value 'Micro' (did you mean 'Mic'?)")


def test_other_format_faults_are_schema_findings() -> None:
    [fault] = findings("schema.yaml")
    assert (fault.check, fault.level) == ("schema", "error")
    assert "cluster_size must be a whole number, got a string ('two')" in fault.message


def test_a_team_whose_rules_have_errors_is_not_checked_and_the_errors_are_reported() -> None:
    found = findings("not-checked.team.yaml")
    assert [(Path(f.location.file).name, f.check) for f in found] == [
        ("not-checked.team.yaml", "not-checked"),
        ("unknown-reference.yaml", "unknown-reference"),
    ]
    assert found[0].message.endswith("unknown-reference.yaml has errors")


def test_a_team_with_an_unknown_kinematic_type_is_an_unknown_reference(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file("team.yaml", "team:\n  Quadruped:\n    motion_control: [Walking]\n")
    [unknown] = check_files([team]).findings
    assert (unknown.check, unknown.line, unknown.column) == ("unknown-reference", 2, 3)
    assert "unknown robot kinematic type 'Quadruped'" in unknown.message


def test_a_team_naming_a_missing_rules_file_is_an_unknown_reference(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file("team.yaml", "rules: nowhere.yaml\nteam:\n  UAV: {}\n")
    [unknown] = check_files([team]).findings
    assert (unknown.check, unknown.line) == ("unknown-reference", 1)
    assert "cannot use rules file 'nowhere.yaml'" in unknown.message


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("characteristics: [\n", ":2:1"),  # not YAML
        ("a: !!python/object:os.system x\n", ":1:4"),  # a tag that would run code
    ],
)
def test_a_file_that_is_not_usable_yaml_raises_with_its_location(
    write_file: Callable[[str, str], Path], text: str, where: str
) -> None:
    bad = write_file("bad.yaml", text)
    with pytest.raises(InputError) as raised:
        check_files([bad])
    assert where in str(raised.value)


def test_every_unusable_file_is_named_at_once(
    tmp_path: Path, write_file: Callable[[str, str], Path]
) -> None:
    broken = write_file("broken.yaml", "team: [\n")
    with pytest.raises(InputError) as raised:
        check_files([tmp_path / "missing.yaml", broken, tmp_path])
    text = str(raised.value)
    assert "missing.yaml: no such file" in text
    assert "broken.yaml:2:1" in text
    assert "is a directory" in text


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        ("unknown-reference", "unknown-reference"),
        ("duplicate-value", "duplicate-value"),
        ("duplicate-key", "duplicate-key"),
        ("wrong-type", "schema"),
        ("missing-field", "schema"),
        ("unknown-field", "schema"),
        ("out-of-range", "schema"),
        ("empty-selection", "schema"),
        ("invalid", "schema"),
    ],
)
def test_loader_codes_map_to_check_ids(code: str, expected: str) -> None:
    assert check_id(Fault(Location("x.yaml", 1, 1), "m", code)) == expected


def test_duplicate_keys_are_kept_as_faults_only_when_the_caller_tolerates_them() -> None:
    # A team file: a file of no kind has its faults without its keys (issue 36.13).
    text = "team: {}\na: 1\na: 2\nb: 3\n"
    with pytest.raises(InputError, match="duplicate key 'a'"):
        parse_document(text, "x.yaml")
    document = parse_document(text, "x.yaml", tolerate={"duplicate-key"})
    assert document.data == {"team": {}, "a": 1, "b": 3}
    assert [(f.code, f.location.line) for f in document.tolerated] == [("duplicate-key", 3)]
    with pytest.raises(InputError, match="recursive alias"):
        parse_document("a: &x [*x]\n", "x.yaml", tolerate={"duplicate-key"})
