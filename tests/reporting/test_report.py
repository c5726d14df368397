"""Reports: one self-contained HTML page or Markdown with its charts beside it."""

from __future__ import annotations

import errno
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from markdown_it import MarkdownIt

from solver import Solution, load_team, solve
from solver.errors import InputError
from solver.reporting.report import (
    image_names,
    render_html,
    render_markdown,
    report_format,
    reproduction_note,
    write_report,
)
from tests.conftest import TEAMS
from tests.reporting.viewer import Cells, parsed, viewer


@pytest.fixture(scope="module")
def case3() -> Solution:
    return solve(load_team(TEAMS / "case3.yaml"))


@pytest.fixture(scope="module")
def case3_html(case3: Solution) -> str:
    return render_html(case3)


def test_html_report_fetches_nothing_from_the_network(case3_html: str) -> None:
    page = parsed(case3_html)
    assert not {"script", "link", "iframe", "object", "embed"} & set(page.tags)
    assert page.references
    # Embedded images, and links to the page's own sections (the contents): nothing fetched.
    assert all(
        value.startswith("data:") or (tag == "a" and value.startswith("#"))
        for tag, _, value in page.references
    )
    policy = next(
        m["content"] for m in page.meta if m.get("http-equiv") == "Content-Security-Policy"
    )
    assert policy is not None
    assert "default-src 'none'" in policy


def test_html_report_embeds_the_matrix_radar_and_bar_charts_as_svg(case3_html: str) -> None:
    images = [value for tag, _, value in parsed(case3_html).references if tag == "img"]
    assert len(images) == 3
    assert all(i.startswith("data:image/svg+xml;base64,") for i in images)


def test_html_report_tables_give_the_counts_of_each_type(case3_html: str) -> None:
    text = " ".join(parsed(case3_html).text)
    for figure in ("Mobile Manipulator", "312", "48", "6.50", "872", "102", "8.55"):
        assert figure in text
    assert "bound T = 900 (6 x 6 x 5 x 5)" in text
    assert "default UI configuration: 103" in text


def test_report_says_when_published_figures_are_not_reproduced(
    case3: Solution, case3_html: str
) -> None:
    note = reproduction_note(case3)
    assert note == (
        "published: 820 valid robots / 99 UI configurations (Mortimer et al. 2017, "
        "Section 4 and Table 2): NOT reproduced: these rules give 872 / 102",
        False,
    )
    assert note[0] in case3_html
    assert 'class="note differs"' in case3_html


def test_report_says_when_published_figures_are_reproduced() -> None:
    solution = solve(load_team(TEAMS / "case1.yaml"))
    note = reproduction_note(solution)
    assert note is not None
    assert note[0].startswith("published: 30 valid robots / 6 UI configurations (")
    assert note[0].endswith("): reproduced")
    assert note[1] is True
    assert f"> **{note[0]}**" in render_markdown(solution)


def test_report_has_no_reproduction_note_for_a_team_without_published_figures(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file(
        "t.yaml",
        "team:\n  UAV:\n    motion_control: [Flight]\n"
        "    sensor_type: [2D Camera]\n    sensor_count: 2\n",
    )
    solution = solve(load_team(team))
    assert reproduction_note(solution) is None
    assert "published" not in render_markdown(solution)
    assert 'class="note' not in render_html(solution, charts={})


def test_report_lists_every_configuration_with_its_components(
    case3: Solution, case3_html: str
) -> None:
    markdown = render_markdown(case3)
    rows = [
        line
        for line in markdown.splitlines()
        if line.startswith("| ") and line.split(" | ")[0][2:].isdigit()
    ]
    assert [int(r.split(" | ")[0][2:]) for r in rows] == list(range(1, 104))
    assert rows[0] == (
        "| 1 | UAV | Flight | visual display: 2D Camera | individual: 1..5 (1..5 clusters) | 5 |"
    )
    assert rows[-1].startswith("| 103 | default: every component |")
    assert "clusters of 5: 16..25 (4..5 clusters)" in case3_html


def test_report_shows_each_types_selection_with_count_ranges(case3: Solution) -> None:
    markdown = render_markdown(case3)
    assert (
        "| Mobile Manipulator | Joint, Driving, End Effector, Waypoint | 2D Camera, "
        "Speaker, Microphone, Force Sensor, LIDAR, RGB-D Camera | 1..13 |"
    ) in markdown


def test_report_escapes_names_from_the_team_file(write_file: Callable[[str, str], Path]) -> None:
    team = write_file(
        "t.yaml",
        "name: '<script>alert(1)</script> & co'\nteam:\n  UAV:\n"
        "    motion_control: [Flight]\n    sensor_count: 1\n",
    )
    page = render_html(solve(load_team(team)), charts={})
    assert "<script>" not in page
    assert "&lt;script&gt;alert(1)&lt;/script&gt; &amp; co" in page


def test_markdown_report_writes_its_png_charts_beside_it_and_links_them(
    case3: Solution, tmp_path: Path
) -> None:
    target = tmp_path / "case3.md"
    written = write_report(case3, target)
    radar, bars = image_names(target)["radar"], image_names(target)["bars"]
    assert written == [radar, bars, target]
    assert radar.name == "case3-radar.png"
    assert radar.read_bytes().startswith(b"\x89PNG")
    assert bars.read_bytes().startswith(b"\x89PNG")
    text = target.read_text(encoding="utf-8")
    assert "](case3-radar.png)" in text
    assert "](case3-bars.png)" in text


def test_reports_are_byte_identical_from_run_to_run(case3: Solution, tmp_path: Path) -> None:
    first, second = tmp_path / "a", tmp_path / "b"
    for folder in (first, second):
        write_report(case3, folder / "r.html")
        write_report(case3, folder / "r.md")
    for name in ("r.html", "r.md", "r-radar.png", "r-bars.png"):
        assert (first / name).read_bytes() == (second / name).read_bytes(), name


@pytest.mark.parametrize(
    ("name", "fmt"),
    [("x.html", "html"), ("x.HTM", "html"), ("x.md", "markdown"), ("x.markdown", "markdown")],
)
def test_report_format_follows_the_extension(name: str, fmt: str) -> None:
    assert report_format(name) == fmt


def test_report_format_refuses_an_unknown_extension() -> None:
    with pytest.raises(InputError) as caught:
        report_format("out/case3.pdf")
    assert str(caught.value) == (
        "out/case3.pdf: cannot tell the report format from '.pdf'; "
        "name the file .html, .htm, .md, .markdown"
    )


def test_markdown_report_escapes_names_from_the_rule_and_team_files(
    write_file: Callable[[str, str], Path],
) -> None:
    write_file(
        "r.yaml",
        'name: "<script>alert(1)</script>"\ncharacteristics:\n'
        '  kinematic_type: {values: ["<img src=x onerror=alert(1)>", "a|b", '
        '"*bold*"]}\n  s:\n    label: "</title><b>x</b>"\n'
        '    values: ["`code`", "[link](javascript:alert(1))", "<b>"]\n',
    )
    team = write_file(
        "t.yaml",
        'name: "Team <i>x</i> | pipe"\ndescription: "# <script>d'
        '</script>"\nrules: r.yaml\nteam:\n'
        '  "<img src=x onerror=alert(1)>": {}\n  "a|b": {}\n'
        '  "*bold*": {}\n',
    )
    solution = solve(load_team(team))
    page = parsed(viewer(render_markdown(solution, {"radar": "my report-radar.png"})))
    assert set(page.tags) <= {
        "h1",
        "h2",
        "p",
        "em",
        "table",
        "thead",
        "tbody",
        "tr",
        "th",
        "td",
        "ul",
        "li",
        "img",
    }
    assert [value for _, _, value in page.references] == ["my%20report-radar.png"]
    text = "".join(page.text)
    for name in (
        "Team <i>x</i> | pipe",
        "# <script>d</script>",
        "rules: <script>alert(1)</script>",
        "<img src=x onerror=alert(1)>",
        "*bold*",
        "</title><b>x</b>",
        "`code`",
        "[link](javascript:alert(1))",
    ):
        assert name in text
    cells = Cells()
    cells.feed(viewer(render_markdown(solution)))
    rows = [cells.cells[i : i + 4] for i in range(len(cells.cells))]
    assert ["5", "a|b", "[link](javascript:alert(1))", "1"] in rows  # one cell each


# ---- all or nothing ----------------------------------------------------------------------------


def test_markdown_report_that_fails_midway_puts_back_the_files_it_replaced(
    case3: Solution, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "case3.md"
    names = image_names(target)
    for path in (names["radar"], names["bars"], target):
        path.write_bytes(b"before")
    real_replace = os.replace
    calls: list[str] = []

    def replace_failing_on_the_page(source: Any, destination: Any, **folders: Any) -> None:
        # A rename that fails after the charts were renamed into place (a disk error):
        # it cannot be provoked on purpose, so it is injected here. (Renames are made in the
        # open folder: names relative to it, src_dir_fd and dst_dir_fd.)
        calls.append(Path(destination).name)
        if Path(destination).name == target.name:
            raise OSError(errno.EIO, "Input/output error")
        real_replace(source, destination, **folders)

    monkeypatch.setattr(os, "replace", replace_failing_on_the_page)
    with pytest.raises(InputError) as caught:
        write_report(case3, target)
    assert str(caught.value) == f"{target}: cannot write: Input/output error"
    assert calls[:3] == ["case3-radar.png", "case3-bars.png", "case3.md"]
    assert [p.read_bytes() for p in (names["radar"], names["bars"], target)] == [b"before"] * 3
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "case3-bars.png",
        "case3-radar.png",
        "case3.md",
    ]


def test_html_report_has_contents_and_folds_long_tables(case3_html: str) -> None:
    contents = case3_html.split('<nav class="contents">', 1)[1].split("</nav>", 1)[0]
    assert contents.count("<a href=") == 5  # no constraints section: the paper has none
    for anchor in ("counts", "charts", "selections", "configurations", "layouts"):
        assert f'href="#{anchor}"' in contents
        assert f'<h2 id="{anchor}">' in case3_html
    # 103 configuration rows and 60 layout thumbnails are folded; the 4 selections are not.
    assert case3_html.count("<details>") == 2
    assert "<summary>show all 103 rows</summary>" in case3_html


# ---- a line break in a name injects nothing ---------------------------------------------------

FORGING_RULES = r"""name: "rules\n# FORGED rules heading"
characteristics:
  kinematic_type:
    label: "Type\n## FORGED label"
    values: ["UAV\n# FORGED heading\u202e", "UGV\r\n- FORGED item"]
  s:
    label: "S\u2028# FORGED"
    values: ["a\n\n# FORGED", "b\u2029===\nFORGED"]
"""
FORGING_TEAM = r"""name: "Team\n# FORGED team heading"
description: "line one\n# FORGED description heading\n- FORGED item"
rules: r.yaml
team:
  "UAV\n# FORGED heading\u202e": {}
  "UGV\r\n- FORGED item": {}
"""


def _forging_solution(write_file: Callable[[str, str], Path]) -> Solution:
    write_file("r.yaml", FORGING_RULES)
    return solve(load_team(write_file("t.yaml", FORGING_TEAM)))


def test_a_line_break_in_a_name_adds_no_heading_or_list_to_a_markdown_report(
    write_file: Callable[[str, str], Path],
) -> None:
    text = render_markdown(_forging_solution(write_file))
    tokens = MarkdownIt("commonmark").enable("table").parse(text)
    headings = [
        tokens[i + 1].content for i, token in enumerate(tokens) if token.type == "heading_open"
    ]
    # The page's title (the team's name, on its one line) and its own sections: nothing else.
    assert headings[0] == "Team # FORGED team heading"
    assert not any("FORGED" in heading for heading in headings[1:])
    assert not any(
        "FORGED" in tokens[i + 2].content
        for i, token in enumerate(tokens)
        if token.type == "list_item_open"
    )
    # The description keeps its lines as text: none became a heading or an item.
    paragraphs = [
        tokens[i + 1].content for i, token in enumerate(tokens) if token.type == "paragraph_open"
    ]
    assert any("FORGED description heading" in paragraph for paragraph in paragraphs)
    for char in ("\u202e", "\u2028", "\u2029", "\r"):
        assert char not in text


def test_an_html_report_shows_line_breaks_and_bidi_controls_as_escapes(
    write_file: Callable[[str, str], Path],
) -> None:
    html = render_html(_forging_solution(write_file))
    for char in ("\u202e", "\u2028", "\u2029", "\r"):
        assert char not in html
    page = parsed(html)
    assert "Team\\n# FORGED team heading" in page.text
    assert "UAV\\n# FORGED heading\\u202e" in page.text
