"""``teleop-ui export``: the team's feature model on standard output."""

from __future__ import annotations

import pytest

from solver.cli import main


def test_export_command_prints_the_model(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["export", "case1", "--format", "uvl"]) == 0
    out = capsys.readouterr().out
    assert "motion_control_Waypoint" in out
    assert out.startswith("namespace Team\n")
