"""``teleop-ui fleet`` as a user runs it: a folder of robots made a team that ``solve``
accepts, its JSON, and the robots it cannot identify listed with why.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from solver.core.team import load_team
from tests.conftest import ROOT, run_cli
from tests.identify import builders


def write_fleet(folder: Path) -> Path:
    folder.mkdir()
    rover = builders.ugv()
    rover.add(builders.gazebo_sensor("laser", "ray", "laser"))
    (folder / "rover.urdf").write_text(rover.text())
    (folder / "rover.topics.txt").write_text(
        "/cmd_vel geometry_msgs/Twist\n/move_base/goal move_base_msgs/MoveBaseActionGoal\n"
    )
    drone = builders.quadrotor()
    drone.add(builders.gazebo_sensor("cam", "camera", "cam"))
    (folder / "drone.urdf").write_text(drone.text())
    (folder / "dog.urdf").write_text(builders.quadruped().text())
    (folder / "broken.urdf").write_text('<robot name="b"><link name="a"></robot>')
    (folder / "notes.txt").write_text("not a robot")
    return folder


def test_fleet_writes_a_team_that_solve_accepts_and_lists_failures(tmp_path: Path) -> None:
    folder = write_fleet(tmp_path / "robots")
    team = tmp_path / "team.yaml"
    result = run_cli("fleet", folder, "-o", team)
    assert result.returncode == 0, result.stderr
    assert "not identified: broken:" in result.stdout
    assert "[1/4] broken" in result.stderr  # plain progress lines when not on a terminal
    lines = {line.split()[0]: line for line in result.stdout.splitlines()[1:4]}
    assert "Quadruped" in lines["dog"]
    assert "UAV" in lines["drone"]
    assert "UGV" in lines["rover"]
    loaded = load_team(team)
    assert loaded.kinematic_types == ("UAV", "UGV")
    ugv = loaded.selection("UGV")
    assert ugv is not None
    assert ugv.domains[1] == ("Driving", "Waypoint")
    assert ugv.domains[2] == ("LIDAR",)
    assert ugv.domains[3] == (1,)
    text = team.read_text()
    assert "# not in the rule set: dog (Quadruped)" in text
    assert "# not identified: broken:" in text
    solved = run_cli("solve", team)
    assert solved.returncode == 0, solved.stderr


def test_fleet_json_is_a_list_of_identifications(tmp_path: Path) -> None:
    folder = write_fleet(tmp_path / "robots")
    result = run_cli("fleet", folder, "--format", "json")
    data = json.loads(result.stdout)
    assert [d["robot"] for d in data] == ["dog", "copter", "rover"]
    assert "not identified: broken" in result.stderr


def test_fleet_of_an_empty_folder_exits_2(tmp_path: Path) -> None:
    (tmp_path / "none").mkdir()
    result = run_cli("fleet", tmp_path / "none")
    assert result.returncode == 2
    assert "no robot descriptions" in result.stderr


def test_fleet_writes_every_value_for_a_type_with_nothing_identified(tmp_path: Path) -> None:
    folder = tmp_path / "bases"
    folder.mkdir()
    # A base trimmed of its moving parts: fixed wheel joints, no sensor. A UGV (with doubt)
    # that shows no motion control: its wheels do not turn and nothing drives them.
    trimmed = builders.RobotText("trimmed")
    trimmed.fixed("base_link", "left_wheel")
    trimmed.fixed("base_link", "right_wheel")
    (folder / "trimmed.urdf").write_text(trimmed.text())
    team = tmp_path / "team.yaml"
    result = run_cli("fleet", folder, "-o", team)
    assert result.returncode == 0, result.stderr
    assert "    {}   # nothing identified to narrow: every value allowed" in team.read_text()
    loaded = load_team(team)
    selection = loaded.selection("UGV")
    assert selection is not None
    for characteristic, domain in zip(
        loaded.rules.characteristics[1:], selection.domains[1:], strict=True
    ):
        assert domain == characteristic.values


def _without_permission_override(*args: str | Path) -> list[str]:
    """``teleop-ui ARGS`` run so that file modes apply: root drops its override capabilities."""
    command = [sys.executable, "-m", "solver", *map(str, args)]
    if os.geteuid() != 0:
        return command
    setpriv = shutil.which("setpriv")
    if setpriv is None:
        pytest.skip("running as root without setpriv: file modes cannot be enforced")
    return [setpriv, "--bounding-set", "-dac_override,-dac_read_search", "--", *command]


def test_fleet_of_an_unreadable_folder_exits_2_naming_it(tmp_path: Path) -> None:
    folder = write_fleet(tmp_path / "robots")
    folder.chmod(0o000)
    try:
        result = subprocess.run(
            _without_permission_override("fleet", folder),
            capture_output=True,
            text=True,
            cwd=ROOT,
            check=False,
        )
    finally:
        folder.chmod(0o755)
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    assert f"{folder}: cannot list this folder: Permission denied" in result.stderr


def test_fleet_lists_an_unreadable_robot_file_as_not_identified(tmp_path: Path) -> None:
    folder = write_fleet(tmp_path / "robots")
    (folder / "drone.urdf").chmod(0o000)
    result = subprocess.run(
        _without_permission_override("fleet", folder),
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert f"not identified: drone: {folder / 'drone.urdf'}: permission denied" in result.stdout
    assert "rover " in result.stdout


def test_fleet_lists_dangling_and_looping_links_as_not_identified(tmp_path: Path) -> None:
    folder = write_fleet(tmp_path / "robots")
    (folder / "gone.urdf").symlink_to("nothere.urdf")
    (folder / "loop1.urdf").symlink_to("loop2.urdf")
    (folder / "loop2.urdf").symlink_to("loop1.urdf")
    (folder / "sub.urdf").mkdir()
    result = run_cli("fleet", folder)
    assert result.returncode == 0, result.stderr
    assert "not identified: gone:" in result.stdout
    assert "not identified: loop1:" in result.stdout
    assert "not identified: loop2:" in result.stdout
    assert "sub" not in result.stdout


def test_fleet_lists_the_warnings_of_a_flawed_robot_and_strict_refuses_it(tmp_path: Path) -> None:
    folder = tmp_path / "robots"
    folder.mkdir()
    (folder / "gripper.urdf").write_text(
        '<robot name="g">\n<link name="finger"/>\n<joint name="finger_joint" type="prismatic">\n'
        '<parent link="flange"/><child link="finger"/>\n</joint>\n</robot>\n'
    )
    (folder / "rover.urdf").write_text(builders.ugv().text())
    shown = run_cli("fleet", folder).stdout
    assert f"warning: {folder / 'gripper.urdf'}:4: joint[finger_joint].parent:" in shown
    strict = run_cli("fleet", folder, "--strict").stdout
    assert f"not identified: gripper: {folder / 'gripper.urdf'}:4:" in strict
