"""``teleop-ui report``: a page written, or exit 2 with nothing written."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from tests.conftest import run_cli


def test_report_command_writes_a_self_contained_page(tmp_path: Path) -> None:
    result = run_cli("report", "rules/teams/case1.yaml", "-o", tmp_path / "case1.html")
    assert result.returncode == 0, result.stderr
    assert f"wrote {tmp_path / 'case1.html'}" in result.stderr
    assert "<h1>Case 1</h1>" in (tmp_path / "case1.html").read_text(encoding="utf-8")


def test_report_command_on_a_bad_team_file_gives_the_located_error_and_exit_2(
    write_file: Callable[[str, str], Path], tmp_path: Path
) -> None:
    bad = write_file("bad.yaml", "team:\n  UAV:\n    motion_control: [Flite]\n")
    result = run_cli("report", bad, "-o", tmp_path / "bad.html")
    assert result.returncode == 2
    assert (
        f"{bad}:3:22: team.UAV.motion_control[0]: unknown robot motion control 'Flite' "
        "(did you mean 'Flight'?)" in result.stderr
    )
    assert "Traceback" not in result.stderr
    assert not (tmp_path / "bad.html").exists()


def test_report_command_with_an_unknown_extension_exits_2_and_writes_nothing(
    tmp_path: Path,
) -> None:
    result = run_cli("report", "case1", "-o", tmp_path / "case1.txt")
    assert result.returncode == 2
    assert "cannot tell the report format from '.txt'" in result.stderr
    assert "Traceback" not in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_report_command_onto_a_folder_exits_2_and_leaves_no_charts(tmp_path: Path) -> None:
    (tmp_path / "d.md").mkdir()
    result = run_cli("report", "case1", "-o", "d.md", cwd=tmp_path)
    assert result.returncode == 2
    assert "d.md: is a folder; cannot write a file there" in result.stderr
    assert "Traceback" not in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d.md"]
