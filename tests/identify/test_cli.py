"""`teleop-ui identify` and `teleop-ui fleet` as a user runs them."""

from __future__ import annotations

import json
from pathlib import Path

from solver.team import load_team
from tests.conftest import run_cli
from tests.identify import builders


def write_fleet(folder: Path) -> Path:
    folder.mkdir()
    rover = builders.ugv()
    rover.add(builders.gazebo_sensor("laser", "ray", "laser"))
    (folder / "rover.urdf").write_text(rover.text())
    (folder / "rover.topics.txt").write_text("/cmd_vel geometry_msgs/Twist\n"
                                             "/move_base/goal move_base_msgs/MoveBaseActionGoal\n")
    drone = builders.quadrotor()
    drone.add(builders.gazebo_sensor("cam", "camera", "cam"))
    (folder / "drone.urdf").write_text(drone.text())
    (folder / "dog.urdf").write_text(builders.quadruped().text())
    (folder / "broken.urdf").write_text('<robot name="b"><link name="a"></robot>')
    (folder / "notes.txt").write_text("not a robot")
    return folder


def test_identify_prints_a_readable_report_with_ui_configurations(tmp_path: Path) -> None:
    path = tmp_path / "rover.urdf"
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("laser", "ray", "laser"))
    path.write_text(robot.text())
    result = run_cli("identify", path, "--team", "case2")
    assert result.returncode == 0, result.stderr
    assert "structure:      UGV  (confidence 0.95)" in result.stdout
    assert "4 wheel joint(s): wheel_left_joint" in result.stdout
    assert "UI configurations in team 'Case 2':" in result.stdout
    assert "(default)" in result.stdout  # no motion control without topics: the default


def test_identify_output_is_byte_identical_across_runs(tmp_path: Path) -> None:
    path = tmp_path / "dual.urdf"
    path.write_text(builders.torso().text())
    first = run_cli("identify", path, "--format", "json")
    assert first.stdout == run_cli("identify", path, "--format", "json").stdout
    assert json.loads(first.stdout)["structure"] == "Torso"


def test_a_missing_file_or_bad_arg_exits_2(tmp_path: Path) -> None:
    missing = run_cli("identify", tmp_path / "none.urdf")
    assert missing.returncode == 2
    assert "no such file" in missing.stderr
    path = tmp_path / "r.urdf"
    path.write_text(builders.ugv().text())
    bad = run_cli("identify", path, "--arg", "nonsense")
    assert bad.returncode == 2
    assert "NAME:=VALUE" in bad.stderr


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
