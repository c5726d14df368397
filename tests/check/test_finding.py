"""What a check reports (solver.check.finding): a finding is one linter line whatever its names
hold, findings sort as a linter lists them, and a check makes findings at its own level."""

from __future__ import annotations

from collections.abc import Iterator

from solver.check.finding import LEVELS, Check, Finding, Related
from solver.errors import Location


def test_a_finding_is_one_linter_line() -> None:
    finding = Finding(Location("rules.yaml", 12, 5), "warning", "dead-value", "'x' is never used")
    assert str(finding) == "rules.yaml:12:5: [warning] 'x' is never used (dead-value)"


def test_a_finding_without_a_position_is_shown_at_the_top_of_its_file() -> None:
    finding = Finding(Location("team.yaml"), "error", "void-type", "no robot")
    assert (finding.line, finding.column) == (1, 1)
    assert str(finding) == "team.yaml:1:1: [error] no robot (void-type)"


def test_a_line_break_in_a_message_or_a_file_name_never_starts_a_line() -> None:
    finding = Finding(Location("a\nb.yaml", 1, 1), "info", "c", "'x\nFORGED' is odd\x1b[2J")
    assert str(finding) == "a\\nb.yaml:1:1: [info] 'x\\nFORGED' is odd\\x1b[2J (c)"


def test_findings_sort_by_file_line_and_column_then_check_and_message() -> None:
    at = Location
    found = [
        Finding(at("b.yaml", 1, 1), "info", "a", "m"),
        Finding(at("a.yaml", 10, 1), "info", "a", "m"),
        Finding(at("a.yaml", 2, 7), "info", "z", "m"),
        Finding(at("a.yaml", 2, 7), "info", "a", "n"),
        Finding(at("a.yaml"), "info", "a", "m"),
    ]
    ordered = sorted(found, key=lambda f: f.sort_key)
    assert [(f.location.file, f.location.line, f.check) for f in ordered] == [
        ("a.yaml", None, "a"),
        ("a.yaml", 2, "a"),
        ("a.yaml", 2, "z"),
        ("a.yaml", 10, "a"),
        ("b.yaml", 1, "a"),
    ]


def test_related_places_explain_a_finding_but_do_not_make_it_another() -> None:
    here = Location("rules.yaml", 3, 1)
    plain = Finding(here, "error", "conflict", "m")
    explained = Finding(here, "error", "conflict", "m", (Related(Location("r", 9), "with"),))
    assert plain == explained


def test_a_check_makes_findings_at_its_own_level_and_sums_itself_up_in_a_sentence() -> None:
    def run(names: list[str]) -> Iterator[Finding]:
        for name in names:
            yield unused.finding(Location("rules.yaml", 1, 1), f"{name} is unused")

    unused = Check(
        "unused-name",
        "warning",
        "rules",
        "A name nothing uses. It may be a typo of another name.",
        run,
    )
    assert [str(f) for f in unused.run(["a"])] == [
        "rules.yaml:1:1: [warning] a is unused (unused-name)"
    ]
    assert unused.summary == "A name nothing uses."
    assert LEVELS == ("error", "warning", "info")  # the summary line's order
