"""Coverage of values by components: gaps, overlaps, inverted, empty and unbounded ranges."""

from __future__ import annotations

import re

from tests.check.helpers import findings


def _gap_counts(file: str) -> list[str]:
    return [
        re.match(r"sensor_count (\S+) is in no component", f.message).group(1)  # type: ignore[union-attr]  # every gap says it
        for f in findings(file, check="coverage-gap")
    ]


def test_check_reports_exactly_the_gaps_at_sensor_count_1_6_11_and_16() -> None:
    """The article's equation 2 read literally (strict lower bounds)."""
    assert _gap_counts("literal-equation-2.yaml") == ["1", "6", "11", "16"]


def test_literal_equation_2_has_no_other_problem_than_its_gaps_and_open_last_range() -> None:
    problems = [f.check for f in findings("literal-equation-2.yaml") if f.level != "info"]
    assert problems == ["coverage-gap"] * 4 + ["unbounded-range"]


def test_inclusive_equation_2_has_no_gap() -> None:
    assert _gap_counts("inclusive-equation-2.yaml") == []


def test_gap_message_names_the_arrangements_on_either_side_as_the_file_wrote_them() -> None:
    message = findings("literal-equation-2.yaml", check="coverage-gap")[1].message
    assert message == (
        "sensor_count 6 is in no component: 'individual' (above: 1, max: 5) ends "
        "at 5 and 'clusters of 2' (above: 6, max: 10) starts at 7; robots with "
        "it get the default UI configuration"
    )


def test_check_reports_a_sensor_type_in_no_presentation_group() -> None:
    [gap] = findings("coverage-gap.yaml", check="coverage-gap")
    assert gap.message.startswith("sensor_type 'Mic' is in no component")


def test_consecutive_missing_counts_are_one_finding() -> None:
    [gap] = findings("inverted-range.yaml", check="coverage-gap")
    assert gap.message.startswith(
        "sensor_count 6..10 is in no component: 'few' (min: 1, max: 5) ends at 5;"
    )


def test_check_reports_a_count_in_two_arrangements() -> None:
    [overlap] = findings("coverage-overlap.yaml", check="coverage-overlap")
    assert overlap.message == (
        "sensor_count 6 is in 2 components: 'few' (min: 1, max: 6) and 'many' (min: 6, max: 10)"
    )


def test_check_reports_a_sensor_type_in_two_groups_at_its_second_listing() -> None:
    [overlap] = findings("nested-components.yaml", check="coverage-overlap")
    assert overlap.message == "sensor_type 'Camera' is in 2 components: 'visual' and 'any sensor'"
    assert (overlap.line, overlap.column) == (16, 18)


def test_check_reports_an_inverted_arrangement() -> None:
    [inverted] = findings("inverted-range.yaml", check="inverted-range")
    assert "'many' (min: 10, max: 6) has an inverted range" in inverted.message


def test_check_reports_components_that_serve_no_value() -> None:
    messages = [f.message for f in findings("empty-component.yaml", check="empty-component")]
    assert messages == [
        "sensor_type component 'spare' serves no value",
        "sensor_count component 'lots' (min: 11, max: 20) serves no value: sensor_count only "
        "takes 1..10",
    ]


def test_check_reports_an_arrangement_without_upper_bound() -> None:
    [open_range] = findings("unbounded-range.yaml", check="unbounded-range")
    assert open_range.message.startswith(
        "sensor_count component 'many' (min: 6) has no upper bound: it reaches the range's end (10)"
    )


def test_literal_equation_2_last_arrangement_is_open_above_25() -> None:
    [open_range] = findings("literal-equation-2.yaml", check="unbounded-range")
    assert "'clusters of 10' (above: 25) has no upper bound" in open_range.message
