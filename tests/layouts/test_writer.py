"""``layouts TEAM -o DIR`` writes the folder as one unit, says what it replaced, obeys the
``written-files`` limit, and a run stopped by SIGTERM leaves nothing behind."""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import pytest

from solver import limits, load_team, solve
from solver.errors import TooLargeError
from solver.layouts import load_presentation, write_layouts
from solver.layouts.writer import write_layout_folder
from solver.limits import limit
from tests.conftest import ROOT, run_cli


def test_rviz_files_written_where_lichtblick_layouts_were_leave_no_json_behind(
    tmp_path: Path,
) -> None:
    solution = solve(load_team("case1"))
    write_layout_folder(solution, load_presentation(), tmp_path, "foxglove", preview=True)
    done = write_layout_folder(solution, load_presentation(), tmp_path, "rviz")
    assert [path.name for path in done.paths][-1] == "config-007-default.rviz"
    assert done.replaced == ()
    assert done.removed == (
        *(f"config-{n:03d}.json" for n in range(1, 7)),
        "config-007-default.json",
        "preview.html",
    )
    assert sorted(path.suffix for path in tmp_path.iterdir()) == [".rviz"] * 7


def test_a_preview_is_written_with_the_layouts_it_draws(tmp_path: Path) -> None:
    solution = solve(load_team("case1"))
    done = write_layout_folder(solution, load_presentation(), tmp_path, preview=True)
    assert done.paths[-1] == tmp_path / "preview.html"
    page = done.paths[-1].read_text()
    assert page.count("<figure>") == 7


def _team(folder: Path, configurations: int) -> Path:
    """A team whose configurations are one per value of a characteristic: small layouts."""
    values = ", ".join(f"v{i}" for i in range(configurations))
    (folder / "rules.yaml").write_text(
        f"name: many\ncharacteristics:\n  kinematic_type:\n    values: [UGV]\n"
        f"  motion_control:\n    values: [{values}]\n",
        encoding="utf-8",
    )
    team = folder / "team.yaml"
    team.write_text("name: many\nrules: rules.yaml\nteam:\n  UGV: {}\n", encoding="utf-8")
    return team


def test_layouts_of_more_files_than_the_limit_are_refused_before_solving(tmp_path: Path) -> None:
    most = limit("written-files").value
    out = tmp_path / "out"
    result = run_cli("layouts", _team(tmp_path, most), "-o", out)
    assert result.returncode == 2, result.stderr
    assert f"{out}: {most + 1} files to write" in result.stderr
    assert f"at most {most} are accepted (limit 'written-files'" in result.stderr
    assert not out.exists()


def test_layouts_up_to_the_limit_are_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(limits._BY_NAME, "written-files", replace(limit("written-files"), value=10))
    solution = solve(load_team(_team(tmp_path, 9)))
    written = write_layouts(solution, load_presentation(), tmp_path / "out")
    assert len(written) == 10 == len(list((tmp_path / "out").iterdir()))
    more = solve(load_team(_team(tmp_path, 10)))
    with pytest.raises(TooLargeError, match=r"11 files to write"):
        write_layouts(more, load_presentation(), tmp_path / "more")
    assert not (tmp_path / "more").exists()


def test_layouts_stopped_by_sigterm_leave_no_temporary_and_no_layout(tmp_path: Path) -> None:
    out = tmp_path / "out"
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", "layouts", _team(tmp_path, 1500), "-o", out],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        # The event: the first temporaries are written (each is written and synced in turn).
        while not (out.is_dir() and any(p.suffix == ".tmp" for p in out.iterdir())):
            assert process.poll() is None, process.communicate()
            time.sleep(0.005)
        process.send_signal(signal.SIGTERM)
        _, stderr = process.communicate(timeout=60)
    finally:
        process.kill()
    assert process.returncode == 143, stderr
    assert stderr.strip() == "terminated"
    assert list(out.iterdir()) == []  # no temporary, and all layouts or none
