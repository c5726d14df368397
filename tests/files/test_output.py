"""How every output is written (solver.files.output): JSON as Python's encoder writes it with
every invisible character escaped, aligned text tables of one line a row, and CSV cells no
spreadsheet runs as formulas."""

from __future__ import annotations

import csv
import io
import json

import pytest

from solver.files.output import csv_cell, csv_text, dumps, json_printable, text_table

# ---- JSON ----------------------------------------------------------------------------------


def test_indented_json_is_what_pythons_encoder_writes_whatever_the_values() -> None:
    nested: list[object] = []
    nested.append(nested)
    values = [
        {"a": [1, 2.5, -0.0, 1e300, 1e-7, None, True, False, "x\u2028y", {}], "b": [], "c": {}},
        {"runs": [[1, 5], [7, 7]], "names": ["a", "b"], "mixed": [1, "a", [2.0]]},
        {1: "a whole-number key"},
        ("a", "tuple"),
        [float("nan"), float("inf"), -float("inf")],
        "\x00\u202e\ud800 unprintable",
        10**40,
    ]
    for value in values:
        expected = json_printable(json.dumps(value, indent=2, ensure_ascii=False)) + "\n"
        assert dumps(value) == expected
    with pytest.raises(ValueError, match="Circular reference"):
        dumps(nested)


def test_json_on_one_line_is_compact_and_keeps_text_as_written() -> None:
    assert dumps({"name": "Drohne \u00fc", "n": [1, 2]}, indent=None) == (
        '{"name": "Drohne \u00fc", "n": [1, 2]}\n'
    )


def test_an_invisible_character_in_json_text_is_written_as_its_escape() -> None:
    assert json_printable('"a\u202eb"') == '"a\\u202eb"'
    assert json_printable('"\U000e0041"') == '"\\udb40\\udc41"'  # a tag character: a pair
    assert json.loads(json_printable('"a\u202eb"')) == "a\u202eb"


# ---- text tables ----------------------------------------------------------------------------


def test_a_text_table_aligns_its_columns_and_right_aligns_numbers() -> None:
    table = text_table(["type", "robots"], [["UAV", 12], ["UGV", 7]], right=[False, True])
    assert table == "type  robots\nUAV       12\nUGV        7\n"


def test_a_line_break_in_a_cell_never_starts_a_line_of_the_table() -> None:
    table = text_table(["name"], [["rover\nFORGED"], [None]])
    assert table.splitlines() == ["name", "rover\\nFORGED", ""]


# ---- CSV ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("cell", "shown"),
    [
        ('=HYPERLINK("http://x")', '\'=HYPERLINK("http://x")'),
        ("+1+2", "'+1+2"),
        ("-2+3", "'-2+3"),
        ("@SUM(A1)", "'@SUM(A1)"),
        ("\tx", "'\tx"),
        ("\rx", "'\rx"),
        ("=1+2", "'=1+2"),
        ("-3", "-3"),
        ("UAV", "UAV"),
        ("Camera", "Camera"),
        (5, 5),
        (3, 3),
    ],
)
def test_csv_cells_that_read_as_formulas_are_neutralised(cell: object, shown: object) -> None:
    assert csv_cell(cell) == shown


@pytest.mark.parametrize(
    "cell",
    [
        "\uff1d1+2",  # fullwidth = (a Japanese or Chinese keyboard types it; spreadsheets read =)
        "\uff0b1+2",  # fullwidth +
        "\uff0d1+2",  # fullwidth -
        "\uff20SUM(A1)",  # fullwidth @
        "\ufe66HYPERLINK()",  # small = (and the other compatibility forms of the four)
        "\ufe62 1",
        "\ufe63 1",
        "\ufe6bSUM(A1)",
        "\u207c1",  # superscript =
        " =1+2",  # after spaces, which a spreadsheet may trim
        "\u3000=1+2",  # after an ideographic space
        "\xa0@SUM(A1)",  # after a no-break space
        "\n=1+2",  # a line break first
    ],
)
def test_every_form_of_a_formula_start_is_neutralised_issue_36(cell: str) -> None:
    assert csv_cell(cell) == "'" + cell


@pytest.mark.parametrize(
    "cell", ["-3", "+1.5", "Camera", "ロボット", "\u2212 not a minus sign", " 5", "a=b"]
)
def test_text_that_starts_like_no_formula_is_left_as_it_is(cell: str) -> None:
    assert csv_cell(cell) == cell


def test_csv_text_reads_back_as_its_rows_with_formulas_neutralised() -> None:
    text = csv_text([["team", "robots"], ["=cmd|calc", 3], ["a,b", 'say "hi"']])
    assert list(csv.reader(io.StringIO(text))) == [
        ["team", "robots"],
        ["'=cmd|calc", "3"],
        ["a,b", 'say "hi"'],
    ]
    assert text == 'team,robots\n\'=cmd|calc,3\n"a,b","say ""hi"""\n'  # one line end: \n
