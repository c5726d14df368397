"""One robot's layout: identified from its URDF, its configuration, topics under its name."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_robot_layout_uses_its_namespace_and_its_own_sensor_tiles(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "x.json"
    assert (
        main(
            [
                "layouts",
                "--robot",
                str(EXAMPLES / "diff_drive_lidar.urdf"),
                "--team",
                "case2",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    assert "diff_drive_lidar: configuration 11" in capsys.readouterr().out
    layout = json.loads(out.read_text())
    # One LIDAR: one point-cloud tile, not the five its configuration allows.
    assert layout["configById"]["3D!p02"]["topics"] == {
        "/diff_drive_lidar/points": {"visible": True}
    }
    assert layout["configById"]["Teleop!p01"]["topic"] == "/diff_drive_lidar/cmd_vel"


def test_robot_layout_without_a_team_exits_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert (
        main(
            ["layouts", "--robot", str(EXAMPLES / "quadrotor.urdf"), "-o", str(tmp_path / "y.json")]
        )
        == 2
    )
    assert "--robot needs --team" in capsys.readouterr().err
