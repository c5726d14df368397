"""The README and the docs/ pages stay true: command outputs, reproduction table, test command."""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

import pytest

from solver.reporting.render import render_comparisons
from solver.solving.reproduce import compare
from tests.conftest import ROOT, run_cli

README = (ROOT / "README.md").read_text(encoding="utf-8")
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


def _text(page: Path) -> str:
    return page.read_text(encoding="utf-8")


def console_examples() -> list[tuple[str, str]]:
    """(command, expected output) for every ``$ teleop-ui ...`` line of a ```console block."""
    examples = []
    blocks = [
        block for page in PAGES for block in re.findall(r"```console\n(.*?)```", _text(page), re.S)
    ]
    for block in blocks:
        command = None
        output: list[str] = []
        for line in block.splitlines():
            if line.startswith("$ "):
                if command is not None:
                    examples.append((command, "\n".join(output)))
                command, output = line[2:], []
            else:
                output.append(line)
        if command is not None:
            examples.append((command, "\n".join(output)))
    return examples


def test_the_readme_has_console_examples() -> None:
    assert len(console_examples()) >= 8


@pytest.mark.parametrize(("command", "expected"), console_examples(), ids=lambda value: value[:60])
def test_every_console_example_prints_what_the_readme_shows(
    command: str, expected: str, tmp_path: Path
) -> None:
    # Run where the repository's files are visible under the same names but anything the
    # command writes (reports, plots) lands in a scratch folder, not in the repository.
    for name in ("rules", "tests", "docs", "examples"):
        (tmp_path / name).symlink_to(ROOT / name)
    words = shlex.split(command)
    assert words[0] == "teleop-ui"
    result = run_cli(*words[1:], cwd=tmp_path)
    assert (result.stdout + result.stderr).rstrip("\n") == expected.rstrip("\n")


def test_the_batch_example_is_what_a_second_run_prints_after_a_typo(tmp_path: Path) -> None:
    example = re.search(
        r"```\n\$ (teleop-ui batch [^\n]*)\n(.*?)\$ echo \$\?\n(\d+)\n```",
        _text(ROOT / "docs" / "reports.md"),
        re.S,
    )
    assert example is not None
    command, expected, status = example.groups()
    shutil.copytree(ROOT / "rules", tmp_path / "rules")
    words = shlex.split(command)[1:]
    assert run_cli(*words, cwd=tmp_path).returncode == 0
    (tmp_path / "rules" / "teams" / "typo.yaml").write_text(
        "rules: ../paper.yaml\nteam:\n"
        "  UAV: {motion_control: [Flite], sensor_type: [2D Camera], sensor_count: 2}\n",
        encoding="utf-8",
    )
    second = run_cli(*words, cwd=tmp_path)
    assert second.returncode == int(status)
    # The summary table goes to stdout; progress and the closing line to stderr, around it.
    table = [line for line in expected.splitlines() if line.startswith(("file ", "rules/"))]
    assert second.stdout.splitlines() == table
    assert second.stderr.splitlines() == [
        line for line in expected.splitlines() if line not in table
    ]


def test_the_reproduction_table_is_the_output_of_reproduce() -> None:
    page = _text(ROOT / "docs" / "reproduction.md")
    table = page.split("<!-- reproduction-table -->\n", 1)[1].split(
        "<!-- /reproduction-table -->", 1
    )[0]
    assert table == render_comparisons(compare(), "markdown")


def test_ci_runs_exactly_the_readme_test_command() -> None:
    quick_start = README.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    assert "bash tools/test.sh" in quick_start
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    commands = [
        line for line in ci.splitlines() if line and not line.startswith(("#", "set ", "cd "))
    ]
    assert commands == ["bash tools/test.sh"]
