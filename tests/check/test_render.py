"""Rendering reports: linter text, parsable lines, JSON, and SARIF 2.1.0 read back by a real
SARIF reader (Microsoft's sarif-tools)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from sarif import loader

from solver.check import ALL_CHECKS, Report, check_files, render
from solver.check.render import sarif_text
from tests.check.helpers import fixture

TEXT_LINE = re.compile(
    r"^(?P<file>[^:]+):(?P<line>\d+):(?P<column>\d+): "
    r"\[(?P<level>error|warning|info)\] (?P<message>.+) \((?P<check>[a-z-]+)\)$"
)


@pytest.fixture(scope="module")
def report() -> Report:
    """Rules and a team with errors, warnings, information and related locations."""
    return check_files(
        [
            fixture("void-type.yaml"),
            fixture("literal-equation-2.yaml"),
            fixture("team-forbidden-value.team.yaml"),
        ],
        rules=fixture("constrained.yaml"),
    )


def test_text_is_one_linter_line_per_finding_in_location_order_then_a_summary(
    report: Report,
) -> None:
    *lines, summary = render(report, "text").splitlines()
    parsed = [TEXT_LINE.match(line) for line in lines]
    assert all(parsed)
    keys = [(m["file"], int(m["line"]), int(m["column"])) for m in parsed if m]
    assert keys == sorted(keys)
    assert [m["check"] for m in parsed if m] == [f.check for f in report.findings]
    counts = report.counts
    assert summary == (
        f"4 files checked: {counts['error']} errors, {counts['warning']} "
        f"warnings, {counts['info']} info"
    )


def test_summary_line_uses_singular_for_one() -> None:
    text = render(check_files([fixture("bound-mismatch.yaml")]), "text")
    assert text.splitlines()[-1] == "1 file checked: 1 error, 0 warnings, 1 info"


def test_parsable_is_the_compiler_form_without_summary(report: Report) -> None:
    lines = render(report, "parsable").splitlines()
    assert len(lines) == len(report.findings)
    first = report.findings[0]
    assert lines[0] == (
        f"{first.location.file}:{first.line}:{first.column}: {first.level}: "
        f"{first.message} [{first.check}]"
    )


def test_json_carries_findings_summary_and_related_locations(report: Report) -> None:
    data = json.loads(render(report, "json"))
    assert data["files"] == list(report.files)
    assert data["summary"] == report.counts
    assert len(data["findings"]) == len(report.findings)
    conflict = next(f for f in data["findings"] if f["check"] == "conflict")
    assert set(conflict) == {
        "file",
        "line",
        "column",
        "path",
        "level",
        "check",
        "message",
        "related",
    }
    assert [r["line"] for r in conflict["related"]] == [35]


def test_sarif_is_read_back_by_a_sarif_reader_with_every_finding(
    report: Report, tmp_path: Path
) -> None:
    path = tmp_path / "check.sarif"
    path.write_text(render(report, "sarif"), encoding="utf-8")
    records = loader.load_sarif_file(str(path)).get_records()
    severity = {"error": "error", "warning": "warning", "info": "note"}
    assert [
        (r["Location"], r["Line"], r["Severity"], r["Code"], r["Description"]) for r in records
    ] == [
        # Absolute paths become file: URIs, as SARIF wants.
        (Path(f.location.file).as_uri(), f.line, severity[f.level], f.check, f.message)
        for f in report.findings
    ]


def test_sarif_declares_every_check_as_a_rule_and_points_results_at_them(report: Report) -> None:
    log = json.loads(render(report, "sarif"))
    assert log["version"] == "2.1.0"
    assert log["$schema"].endswith("sarif-2.1.0.json")
    [run] = log["runs"]
    rules = run["tool"]["driver"]["rules"]
    assert [rule["id"] for rule in rules] == [check.id for check in ALL_CHECKS]
    assert {rule["defaultConfiguration"]["level"] for rule in rules} == {"error", "warning", "note"}
    for result in run["results"]:
        assert rules[result["ruleIndex"]]["id"] == result["ruleId"]
        region = result["locations"][0]["physicalLocation"]["region"]
        assert region["startLine"] >= 1
        assert region["startColumn"] >= 1
    conflict = next(r for r in run["results"] if r["ruleId"] == "conflict")
    assert [r["id"] for r in conflict["relatedLocations"]] == [1]


def test_sarif_messages_hold_no_link() -> None:
    assert sarif_text("[x](javascript:alert(1))") == "\\[x\\](javascript:alert(1))"
    assert sarif_text("a\\[b") == "a\\\\\\[b"
    assert sarif_text("plain (text)") == "plain (text)"


def test_every_format_is_identical_on_a_second_run(report: Report) -> None:
    again = check_files(
        [
            fixture("void-type.yaml"),
            fixture("literal-equation-2.yaml"),
            fixture("team-forbidden-value.team.yaml"),
        ],
        rules=fixture("constrained.yaml"),
    )
    for format_ in ("text", "parsable", "json", "sarif"):
        assert render(report, format_) == render(again, format_)
