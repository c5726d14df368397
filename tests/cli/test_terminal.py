"""Output a terminal, a log or an editor trusts (:mod:`solver.cli._terminal`): a name from a
stranger's file never starts a line of its own, never reaches the terminal as an invisible or
controlling character, and a long value is echoed cut short with a mark; every format we write
reads back, with its own reader, as the names written. (An output stream that closes or fills:
tests/cli/test_cli.py.)
"""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest
import yaml

from solver.cli import main

# What a forged line would start with, and characters that must never reach an output raw:
# controls, a C1 control, line and paragraph separators, bidi controls, the soft hyphen, a
# zero-width joiner, tag characters.
FORGED = "FORGED"
INVISIBLE = ("\x1b", "\x85", "\u2028", "\u2029", "\u202e", "\u061c", "\xad", "\u200d", "\U000e0041")

RULES = r"""name: "R\nFORGED\u202erules"
description: "d\n# FORGED heading\n- FORGED item"
team_key: kind
characteristics:
  kind:
    label: "Kind\nFORGED\x85label"
    values: ["UAV\nFORGED\u2028kind", "UGV\x1b[2J"]
  control:
    label: "Control\u2029FORGED"
    values: ["Fly\nFORGED\u061cv", "Drive\r\nFORGED\xadd"]
    components:
      - name: "pad\nFORGED\u200dcomp"
        values: ["Fly\nFORGED\u061cv", "Drive\r\nFORGED\xadd"]
  count:
    label: "N\rFORGED"
    range: {min: 1, max: 3}
    components:
      - {name: "one\nFORGED\U000e0041c", min: 1, max: 3, cluster_size: 1}
constraints:
  - name: "c\nFORGED constraint"
    when: {control: ["Fly\nFORGED\u061cv"]}
    require: {kind: ["UAV\nFORGED\u2028kind"]}
"""

TEAM = r"""name: "T\nFORGED\u202eteam"
rules: rules.yaml
team:
  "UAV\nFORGED\u2028kind":
    control: ["Fly\nFORGED\u061cv", "Drive\r\nFORGED\xadd"]
    count: 3
  "UGV\x1b[2J":
    control: ["Drive\r\nFORGED\xadd"]
    count: 2
"""


@pytest.fixture
def team(tmp_path: Path) -> Path:
    (tmp_path / "rules.yaml").write_text(RULES, encoding="utf-8")
    path = tmp_path / "team.yaml"
    path.write_text(TEAM, encoding="utf-8")
    return path


def run(capsys: pytest.CaptureFixture[str], *args: str | Path) -> tuple[int, str, str]:
    """The command line in this process: status, standard output, standard error."""
    status = main([str(arg) for arg in args])
    out, err = capsys.readouterr()
    return status, out, err


def assert_no_forged_line(text: str) -> None:
    assert text  # something was written
    for line in text.splitlines():  # str.splitlines: every line break Unicode knows
        assert not line.lstrip().startswith(FORGED), line
    for char in INVISIBLE:
        assert char not in text


# ---- text output: one line stays one line -----------------------------------------------


@pytest.mark.parametrize(
    ("args", "status"),
    [
        (["solve", "{team}"], 0),
        (["solve", "{team}", "--list"], 0),
        (["count", "{team}"], 0),
        (["check", "{rules}", "{team}"], 0),
        (["check", "--format", "parsable", "{rules}", "{team}"], 0),
        (["assign", "-t", "{team}", "kind=UAV\nFORGED\u2028kind", "control=Fly\nFORGED\u061cv"], 0),
        (["assign", "-t", "{team}", "kind=UGV\nFORGED\u202e", "count=2"], 0),
        (["solve", "{folder}/nothing\nFORGED here.yaml"], 2),
        (["solve", "{folder}/team.yaml", "--rules", "{folder}/no\nFORGED\u202e.yaml"], 2),
    ],
    ids=[
        "solve",
        "solve-list",
        "count",
        "check",
        "check-parsable",
        "assign",
        "assign-default",
        "error",
        "error-rules",
    ],
)
def test_no_name_starts_a_line_of_text_output(
    team: Path, capsys: pytest.CaptureFixture[str], args: list[str], status: int
) -> None:
    places = {"team": str(team), "rules": str(team.parent / "rules.yaml"), "folder": team.parent}
    result, out, err = run(capsys, *(arg.format(**places) for arg in args))
    assert result == status, err
    assert_no_forged_line(out + err)
    assert "\\nFORGED" in out + err  # the name is there, its line break shown as \n


def test_check_findings_stay_one_per_line(team: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, out, _ = run(capsys, "check", "--format", "parsable", team.parent / "rules.yaml")
    assert status in (0, 1)
    lines = out.splitlines()
    assert lines
    assert all(line.startswith(str(team.parent / "rules.yaml") + ":") for line in lines)


def test_a_markdown_view_on_standard_output_adds_no_heading(
    team: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from markdown_it import MarkdownIt

    status, out, _ = run(capsys, "solve", team, "--list", "--format", "markdown")
    assert status == 0
    tokens = MarkdownIt("commonmark").enable("table").parse(out)
    headings = [t for t in tokens if t.type == "heading_open"]
    assert len(headings) == 1  # the team's own, on one line
    assert_no_forged_line(out)


# ---- echoes are cut ------------------------------------------------------------------------


def test_a_huge_value_on_the_command_line_is_echoed_cut_short(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # Longer than any characteristic value may be (200): refused before any work, by its
    # size, and never echoed whole.
    status, out, err = run(capsys, "assign", "-t", "case3", "kinematic_type=" + "U" * 1_000_000)
    assert status == 2
    assert len(out + err) < 2_000
    assert "kinematic_type: a value of 1,000,000 characters" in err


def test_a_9_megabyte_robot_name_is_echoed_cut_short(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    urdf = tmp_path / "big.urdf"
    urdf.write_text(f'<robot name="{"N" * 9_000_000}"><link name="base"/></robot>')
    status, out, err = run(capsys, "identify", urdf)
    assert status == 0, err
    assert len(out + err) < 5_000
    assert out.startswith("N" * 60 + "... (cut from 9,000,000 characters)  (")


def test_a_3_megabyte_link_name_is_echoed_cut_short_in_the_evidence(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    big = "L" * 3_000_000
    urdf = tmp_path / "big.urdf"
    urdf.write_text(
        f'<robot name="r"><link name="base"/><link name="{big}"/>'
        f'<joint name="j" type="revolute"><parent link="base"/><child link="{big}"/></joint>'
        f'<gazebo reference="{big}"><sensor name="{big}" type="camera"/></gazebo></robot>'
    )
    status, out, err = run(capsys, "identify", urdf)
    assert status == 0, err
    assert len(out + err) < 5_000
    assert "... (cut from 3,000,000 characters)" in out


# ---- every format reads back as the names written -----------------------------------------


def test_csv_reads_back_with_the_names_as_written(team: Path) -> None:
    from solver import load_team, solve
    from solver.reporting.render import render_solution

    solution = solve(load_team(team))
    rows = list(csv.reader(io.StringIO(render_solution(solution, "csv", configurations=True))))
    assert rows[0] == ["number", "kind", "control", "count", "valid_robots"]
    assert {row[1] for row in rows[1:]} == {"UAV\nFORGED\u2028kind", "UGV\x1b[2J"}
    assert {row[2] for row in rows[1:]} == {"pad\nFORGED\u200dcomp"}


def test_json_on_standard_output_reads_back_with_the_names_as_written(
    team: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, out, _ = run(capsys, "solve", team, "--list", "--format", "json")
    assert status == 0
    assert out.isascii() or all(char not in out for char in INVISIBLE)
    data = json.loads(out)
    assert data["team"] == "T\nFORGED\u202eteam"
    assert {t["kinematic_type"] for t in data["by_type"]} == {
        "UAV\nFORGED\u2028kind",
        "UGV\x1b[2J",
    }


def test_sarif_reads_back_with_the_names_as_written(
    team: Path, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    from sarif import loader

    status, out, _ = run(capsys, "check", "--format", "sarif", team.parent / "rules.yaml", team)
    assert status in (0, 1)
    path = tmp_path / "check.sarif"
    path.write_text(out, encoding="utf-8")
    results = loader.load_sarif_file(str(path)).get_results()
    messages = [result["message"]["text"] for result in results]
    assert any("forced by 'c\\nFORGED constraint'" in message for message in messages)
    assert_no_forged_line("\n".join(messages))


def test_the_team_file_fleet_writes_reads_back_with_its_comments_on_their_lines(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from tests.identify import builders

    folder = tmp_path / "robots"
    folder.mkdir()
    for name in ("uav\nUGV: {}", "uav\u2028# x", "quad #1\x85x"):
        (folder / f"{name}.urdf").write_text(builders.quadrotor().text())
    output = tmp_path / "team.yaml"
    status, out, err = run(capsys, "fleet", folder, "-o", output)
    assert status == 0, err
    assert_no_forged_line(out)  # the table of robots: one line each
    text = output.read_text(encoding="utf-8")
    assert all(char not in text for char in INVISIBLE)
    team = yaml.safe_load(text)
    assert list(team["team"]) == ["UAV"]
    assert "  UAV:   # quad #1\\x85x, uav\\nUGV: {}, uav\\u2028# x\n" in text


# ---- letters drawn as nothing (issue 36.14a) ---------------------------------------------------

# The Hangul fillers are letters to str.isprintable; a terminal draws them as nothing.
FILLERS = ("\u115f", "\u1160", "\u3164", "\uffa0")
# A kinematic type at the 200-character bound for names: tables show such names whole.
LONG_TYPE = "U" * 196 + "".join(FILLERS)
FILLER_RULES = rf"""name: "R\u3164rules"
characteristics:
  kind:
    label: "Kind\u115f"
    values: ["{LONG_TYPE}", "UGV\uffa0"]
  n: {{range: {{min: 1, max: 2}}}}
"""
FILLER_TEAM = rf"""name: "T\u3164team"
rules: rules.yaml
team:
  "{LONG_TYPE}": {{}}
  "UGV\uffa0": {{}}
"""


@pytest.mark.parametrize(
    "args",
    [["solve", "{team}"], ["solve", "{team}", "--list"], ["count", "{team}"], ["batch", "{team}"]],
    ids=["solve", "solve-list", "count", "batch"],
)
def test_letters_drawn_as_nothing_reach_no_terminal_and_long_names_are_escaped_whole(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], args: list[str]
) -> None:
    (tmp_path / "rules.yaml").write_text(FILLER_RULES, encoding="utf-8")
    team = tmp_path / "team.yaml"
    team.write_text(FILLER_TEAM, encoding="utf-8")
    more = ["-o", str(tmp_path / "out")] if args[0] == "batch" else []
    status, out, err = run(capsys, *(a.format(team=team) for a in args), *more)
    assert status == 0, err
    assert not any(filler in out + err for filler in FILLERS)
    escaped = "U" * 196 + "\\u115f\\u1160\\u3164\\uffa0"
    if args[0] == "batch":
        assert "T\\u3164team" in out
        assert "R\\u3164rules" in out
    else:
        assert escaped in out  # the whole name, as the table shows it, escaped


def test_json_on_a_terminal_escapes_letters_drawn_as_nothing_and_reads_back_the_same(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # A variation selector past U+FFFF: the terminal's escape (\U000e0100) is no JSON escape.
    selector = ("UGV\\uffa0", "UGV\\U000e0100")
    (tmp_path / "rules.yaml").write_text(FILLER_RULES.replace(*selector), encoding="utf-8")
    team = tmp_path / "team.yaml"
    team.write_text(FILLER_TEAM.replace(*selector), encoding="utf-8")
    status, out, _ = run(capsys, "solve", team, "--format", "json")
    assert status == 0
    assert not any(char in out for char in (*FILLERS, "\U000e0100"))
    data = json.loads(out)  # a JSON escape, not the terminal's \U000e0100
    assert data["team"] == "T\u3164team"
    assert {t["kinematic_type"] for t in data["by_type"]} == {LONG_TYPE, "UGV\U000e0100"}


def test_the_terminal_net_escapes_letters_drawn_as_nothing() -> None:
    from solver.cli._terminal import escape_controls

    assert escape_controls("a\u3164b\tc\n\u2800") == "a\\u3164b\tc\n\\u2800"
