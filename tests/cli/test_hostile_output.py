"""What a command writes from a stranger's names runs nowhere: CSV cells that read as formulas
are neutralised in every CSV, SARIF messages hold no link, escape sequences reach a terminal as
text, and a line break in a robot's name starts no line of a team file.
"""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest

from solver.cli._terminal import escape_controls
from tests.cli.hostile import team_file, with_paper_rules
from tests.conftest import run_cli

# ---- injections ----------------------------------------------------------------------------


def test_batch_summary_and_solve_csv_neutralise_formula_names(tmp_path: Path) -> None:
    with_paper_rules(tmp_path)
    team = team_file(tmp_path, name="'=cmd|calc'")
    result = run_cli("batch", team, "-o", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out" / "summary.csv").read_text())))
    assert rows[0]["team"] == "'=cmd|calc"
    solved = run_cli("solve", team, "--format", "csv")
    assert "\n=" not in solved.stdout
    assert not solved.stdout.startswith("=")


def test_robots_csv_neutralises_formula_values(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text(
        "characteristics:\n  kind: {values: ['=1+1', B]}\n  n: {range: {min: -1, max: 0}}\n"
    )
    team = tmp_path / "t.yaml"
    team.write_text("rules: r.yaml\nteam:\n  '=1+1': {}\n")
    result = run_cli("robots", team)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[1:] == ["1,'=1+1,-1", "2,'=1+1,0"]


@pytest.mark.parametrize("sign", ["\uff1d", "\uff0b", "\uff0d", "\uff20", "\ufe66"])
def test_every_csv_the_tool_writes_neutralises_fullwidth_formula_starts(
    tmp_path: Path, sign: str
) -> None:
    # Issue 36.14d: U+FF1D HYPERLINK(...) got no leading quote; a spreadsheet reads it as "=".
    formula = f"{sign}HYPERLINK(x)"
    rules = tmp_path / "r.yaml"
    rules.write_text(
        f"name: '{formula}'\ncharacteristics:\n  kind: {{values: ['{formula}', B]}}\n"
        "  n: {range: {min: 1, max: 2}}\n",
        encoding="utf-8",
    )
    team = tmp_path / "t.yaml"
    team.write_text(f"name: '{formula}'\nrules: r.yaml\nteam:\n  '{formula}': {{}}\n", "utf-8")
    assert run_cli("batch", team, "-o", tmp_path / "out").returncode == 0
    outputs = [
        (tmp_path / "out" / "summary.csv").read_text(encoding="utf-8"),
        run_cli("solve", team, "--format", "csv").stdout,
        run_cli("solve", team, "--format", "csv", "--list").stdout,
        run_cli("robots", team).stdout,
    ]
    for output in outputs:
        cells = [cell for row in csv.reader(io.StringIO(output)) for cell in row]
        assert f"'{formula}" in cells, output
        assert formula not in cells, output


def test_sarif_output_of_check_escapes_a_bracketed_name(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text(
        "characteristics:\n  kind: {values: [A, B]}\n  x: {values: [u, v]}\n"
        "constraints:\n  - name: '[x](javascript:alert(1))'\n"
        "    when: {kind: A}\n    require: {x: [u]}\n"
        "  - name: '[x](javascript:alert(1))'\n"
        "    when: {kind: A}\n    require: {x: [u]}\n"
    )
    result = run_cli("check", rules, "--format", "sarif")
    assert result.returncode in (0, 1), result.stderr
    texts = [r["message"]["text"] for r in json.loads(result.stdout)["runs"][0]["results"]]
    assert all("[x]" not in text for text in texts)


# ---- terminals and team files ----------------------------------------------------------------


def test_terminal_output_shows_escape_sequences_escaped(tmp_path: Path) -> None:
    with_paper_rules(tmp_path)
    team = team_file(tmp_path, name='"\\e[2Jevil\\u202e"')
    result = run_cli("solve", team)
    assert result.returncode == 0, result.stderr
    assert "\x1b" not in result.stdout
    assert "\u202e" not in result.stdout
    assert result.stdout.startswith("\\x1b[2Jevil\\u202e")
    assert escape_controls("tab\tand\nnewline\x07") == "tab\tand\nnewline\\x07"


def test_terminal_errors_show_escape_sequences_escaped(tmp_path: Path) -> None:
    team = team_file(tmp_path, rules='"\\e]0;pwned\\a"')
    result = run_cli("solve", team)
    assert result.returncode == 2
    assert "\x1b" not in result.stderr
    assert "\x07" not in result.stderr


def test_fleet_writes_a_newline_in_a_robot_name_as_an_escape(tmp_path: Path) -> None:
    from tests.identify import builders

    folder = tmp_path / "robots"
    folder.mkdir()
    (folder / "rover\nUAV: {}\n#.urdf").write_text(builders.ugv().text())
    team = tmp_path / "team.yaml"
    result = run_cli("fleet", folder, "-o", team)
    assert result.returncode == 0, result.stderr
    from solver import load_team

    assert load_team(team).kinematic_types == ("UGV",)
