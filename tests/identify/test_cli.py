"""`teleop-ui identify` and `teleop-ui fleet` as a user runs them."""

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
    # Wheels that turn mean the base is driven: Driving, without a topic list.
    assert "UGV, Driving, LIDAR, 1" in result.stdout


def test_identify_output_is_byte_identical_across_runs(tmp_path: Path) -> None:
    path = tmp_path / "dual.urdf"
    path.write_text(builders.torso().text())
    first = run_cli("identify", path, "--format", "json")
    assert first.stdout == run_cli("identify", path, "--format", "json").stdout
    assert json.loads(first.stdout)["structure"] == "Torso"


@pytest.mark.parametrize("team", [[], ["--team", "case2"]], ids=["alone", "with a team"])
def test_identify_text_ends_with_its_last_line_not_a_blank_one(
    tmp_path: Path, team: list[str]
) -> None:
    path = tmp_path / "rover.urdf"
    path.write_text(builders.ugv().text())
    result = run_cli("identify", path, *team)
    assert result.returncode == 0, result.stderr
    assert result.stdout.endswith("\n")
    assert not result.stdout.endswith("\n\n")


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


@pytest.mark.parametrize(
    ("example", "srdf", "structure", "sensors", "controls"),
    [
        ("quadrotor.urdf", None, "UAV", [("imu", None), ("camera", "2D Camera")], ["Flight"]),
        # A driven base with a lidar: Waypoint, as a guess (navigation is in launch files).
        ("diff_drive_lidar.urdf", None, "UGV", [("lidar", "LIDAR")], ["Driving", "Waypoint"]),
        ("arm_gripper.urdf", "arm_gripper.srdf", "Manipulator", [], ["Joint", "End Effector"]),
    ],
    ids=["quadrotor", "diff drive with a lidar", "arm with a gripper and its SRDF"],
)
def test_the_shipped_examples_identify_as_what_they_are(
    example: str,
    srdf: str | None,
    structure: str,
    sensors: list[tuple[str, str | None]],
    controls: list[str],
) -> None:
    extra = ["--srdf", str(ROOT / "examples" / srdf)] if srdf else []
    result = run_cli("identify", ROOT / "examples" / example, *extra, "--format", "json")
    assert result.returncode == 0, result.stderr
    shown = json.loads(result.stdout)
    assert shown["structure"] == structure
    assert [(s["kind"], s["sensor_type"]) for s in shown["sensors"]] == sensors
    assert [c["motion_control"] for c in shown["motion_controls"]] == controls
    assert "warnings" not in shown


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


def test_the_marine_rules_give_a_vessel_its_own_kinematic_type(tmp_path: Path) -> None:
    boat = builders.surface_vessel()
    boat.add(builders.gazebo_sensor("base_link", "sonar", "front_sonar"))
    boat.add(builders.gazebo_sensor("base_link", "camera", "bow_camera"))
    path = tmp_path / "boat.urdf"
    path.write_text(boat.text())
    paper = json.loads(run_cli("identify", path, "--format", "json").stdout)
    assert (paper["structure"], paper["kinematic_type"]) == ("Surface Vessel", None)
    result = run_cli("identify", path, "--rules", "rules/marine.yaml", "--format", "json", cwd=ROOT)
    assert result.returncode == 0, result.stderr
    marine = json.loads(result.stdout)
    assert (marine["structure"], marine["kinematic_type"]) == ("Surface Vessel", "Surface Vessel")
    assert not any("Other under it" in line for line in marine["evidence"])
    assert [(s["kind"], s["sensor_type"]) for s in marine["sensors"]] == [
        ("sonar", "Sonar"),
        ("camera", "2D Camera"),
    ]
    assert [c["motion_control"] for c in marine["motion_controls"]] == ["Driving"]


def test_the_marine_team_configures_an_underwater_vehicle_by_its_sonar_and_dvl(
    tmp_path: Path,
) -> None:
    rov = builders.underwater_vehicle()
    rov.add(builders.gazebo_sensor("base_link", "sonar", "imaging_sonar"))
    rov.add(builders.model_plugin("dvl", "libuuv_gazebo_ros_dvl_plugin.so"))
    path = tmp_path / "rov.urdf"
    path.write_text(rov.text())
    result = run_cli("identify", path, "--team", "marine-survey", "--format", "json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["kinematic_type"] == "Underwater Vehicle"
    assert [(s["kind"], s["sensor_type"]) for s in data["sensors"]] == [
        ("sonar", "Sonar"),
        ("dvl", "DVL"),
    ]
    # Driving (its thruster), Waypoint (a guess: thrusters and a DVL) x Sonar, DVL; two sensors.
    given = [
        (
            c["combination"]["motion_control"],
            c["combination"]["sensor_type"],
            c["combination"]["sensor_count"],
        )
        for c in data["combinations"]
    ]
    assert given == [
        ("Driving", "Sonar", "2"),
        ("Driving", "DVL", "2"),
        ("Waypoint", "Sonar", "2"),
        ("Waypoint", "DVL", "2"),
    ]
    assert not any(c["default"] for c in data["combinations"])
    assert len({c["configuration"] for c in data["combinations"]}) == 4
