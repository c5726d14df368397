"""What every command's shared options do (:mod:`solver.cli._common`): a team is a file or a
shipped team's name, from any folder, and a name that is neither lists the shipped teams.
"""

from __future__ import annotations

from pathlib import Path

from tests.conftest import run_cli


def test_shipped_teams_and_the_default_rules_work_from_any_directory(tmp_path: Path) -> None:
    result = run_cli("solve", "case1", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "reproduced" in result.stdout


def test_an_unknown_shipped_team_name_lists_the_shipped_teams() -> None:
    for command in ("solve", "count", "robots"):
        result = run_cli(command, "case9")
        assert result.returncode == 2
        assert result.stderr == (
            "case9: no such file, and no shipped team of that name; shipped teams: case1, "
            "case2, case3, case3-hypothesis, figure8, marine-survey, search-and-rescue\n"
        )
