"""Markdown that shows names as written (solver.reporting.markdown): escaped text, paragraphs,
headings and tables, rendered as a viewer renders them (tests.reporting.viewer)."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from solver.reporting import markdown
from tests.reporting.viewer import Cells, parsed, viewer

PRINTABLE = st.text(alphabet=st.characters(min_codepoint=32, max_codepoint=126))


def test_markup_and_html_in_a_name_are_escaped_to_show_as_written() -> None:
    assert markdown.escape("<b>*x*</b> & a|b") == "&lt;b&gt;\\*x\\*&lt;/b&gt; &amp; a\\|b"
    assert markdown.escape("a\nb\u202e") == "a\\\\nb\\\\u202e"  # shown, then escaped
    assert markdown.escape(None) == ""


def test_a_line_that_would_start_a_heading_or_a_list_is_escaped_at_its_start() -> None:
    assert markdown.paragraph("# not a heading\n1. not a list\n- nor this") == (
        "\\# not a heading\n1\\. not a list\n\\- nor this"
    )


def test_a_heading_is_one_line_of_single_spaces_and_keeps_a_closing_hash() -> None:
    assert markdown.heading(2, "C#\n  and  more #") == "## C# and more \\#"


def test_a_link_target_is_percent_encoded_from_the_file_names_bytes() -> None:
    assert markdown.link_target("my report (1).png") == "my%20report%20%281%29.png"
    assert markdown.link_target("r\udcff.png") == "r%FF.png"  # not UTF-8: its own byte


def test_a_table_right_aligns_the_columns_asked_for_and_keeps_each_row_on_a_line() -> None:
    assert markdown.table(["type", "robots"], [["UAV\nUGV", 3], [None, 10]], [False, True]) == (
        "| type | robots |\n|---|---:|\n| UAV UGV | 3 |\n|  | 10 |\n"
    )


@given(PRINTABLE)
def test_a_markdown_table_cell_shows_any_text_as_written(text: str) -> None:
    cells = Cells()
    cells.feed(viewer(markdown.table(["name"], [[text]])))
    cells.close()
    assert set(cells.tags) <= {"table", "thead", "tbody", "tr", "th", "td"}
    assert cells.cells == ["name", text.strip()]


@given(st.lists(PRINTABLE.filter(str.strip), min_size=1, max_size=3))
def test_a_markdown_paragraph_shows_any_lines_as_written(lines: list[str]) -> None:
    page = parsed(viewer(markdown.paragraph("\n".join(lines))))
    assert set(page.tags) == {"p"}
    assert "".join(page.text).strip() == "\n".join(line.strip() for line in lines)


@given(PRINTABLE.filter(str.strip))
def test_a_markdown_heading_shows_any_name_as_written(name: str) -> None:
    page = parsed(viewer(markdown.heading(1, name)))
    assert page.tags == ["h1"]
    assert "".join(page.text).strip() == " ".join(name.split())
