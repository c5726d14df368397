"""``teleop-ui identify`` as a user runs it: the report, its formats, the shipped examples and
the marine rules.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import ROOT, run_cli
from tests.identify import builders


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


def test_a_flawed_srdf_is_a_warning_and_exit_0_and_strict_makes_it_exit_2(tmp_path: Path) -> None:
    urdf, srdf = tmp_path / "arm.urdf", tmp_path / "arm.srdf"
    urdf.write_text(builders.manipulator().text(), encoding="utf-8")
    srdf.write_text('<robot name="arm6">\n<!-- a -- b -->\n</robot>\n', encoding="utf-8")
    result = run_cli("identify", urdf, "--srdf", srdf)
    assert result.returncode == 0, result.stderr
    assert f"  warning: {srdf}:2:" in result.stdout
    assert "structure:      Manipulator" in result.stdout
    strict = run_cli("identify", urdf, "--srdf", srdf, "--strict")
    assert strict.returncode == 2
    assert strict.stderr.startswith(f"{srdf}:2:")


def test_describe_drafts_a_description_check_accepts_and_identify_reads_back(
    tmp_path: Path,
) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(builders.ugv().text(), encoding="utf-8")
    draft = run_cli("identify", urdf, "--describe")
    assert draft.returncode == 0, draft.stderr
    assert draft.stdout.startswith("# Teleoperation description of rover")
    beside = tmp_path / "rover.teleop.yaml"
    beside.write_text(draft.stdout, encoding="utf-8")
    assert run_cli("check", beside).returncode == 0
    read = run_cli("identify", urdf, "--format", "json")
    assert json.loads(read.stdout)["declared"] == str(beside)
    # Drafting again reads no description: the draft is what identification found.
    assert run_cli("identify", urdf, "--describe").stdout == draft.stdout


def _characteristics(data: dict[str, object]) -> tuple[object, ...]:
    sensors = data["sensors"]
    controls = data["motion_controls"]
    assert isinstance(sensors, list)
    assert isinstance(controls, list)
    return (
        data["kinematic_type"],
        sorted(c["motion_control"] for c in controls),
        sorted((s["kind"], s["sensor_type"], s["count"]) for s in sensors),
    )


def _rover_with_sensors() -> builders.RobotText:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    robot.add(builders.gazebo_sensor("base_link", "camera", "front_camera"))
    robot.add(builders.gazebo_sensor("base_link", "imu", "imu"))
    return robot


ROUND_TRIP = {
    "a rover with a lidar, a camera and an IMU": (_rover_with_sensors, ()),
    "a mobile manipulator": (builders.mobile_manipulator, ()),
    "a quadruped": (builders.quadruped, ()),
    "a surface vessel under the marine rules": (
        builders.surface_vessel,
        ("--rules", str(ROOT / "rules" / "marine.yaml")),
    ),
}


@pytest.mark.parametrize(("make", "options"), ROUND_TRIP.values(), ids=ROUND_TRIP.keys())
def test_a_draft_checks_clean_and_read_with_teleop_gives_the_same_characteristics(
    make: object, options: tuple[str, ...], tmp_path: Path
) -> None:
    assert callable(make)
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(make().text(), encoding="utf-8")
    first = json.loads(run_cli("identify", urdf, *options, "--format", "json").stdout)
    draft = run_cli("identify", urdf, *options, "--describe")
    assert draft.returncode == 0, draft.stderr
    elsewhere = tmp_path / "drafts" / "robot.yaml"  # not beside the URDF: only --teleop reads it
    elsewhere.parent.mkdir()
    elsewhere.write_text(draft.stdout, encoding="utf-8")
    checked = run_cli("check", elsewhere)
    assert (checked.returncode, checked.stdout.strip()) == (
        0,
        "1 file checked: 0 errors, 0 warnings, 0 info",
    )
    again = run_cli("identify", urdf, *options, "--teleop", elsewhere, "--format", "json")
    data = json.loads(again.stdout)
    assert data["declared"] == str(elsewhere)
    assert "disagreements" not in data  # present only when the two differ
    assert _characteristics(data) == _characteristics(first)


def test_teleop_names_a_description_whose_declared_values_win_and_differences_show(
    tmp_path: Path,
) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(builders.ugv().text(), encoding="utf-8")
    described = tmp_path / "mine.yaml"
    described.write_text(
        "teleop: 1\nmotion_controls:\n  - {control: Waypoint, action: /go}\n", encoding="utf-8"
    )
    result = run_cli("identify", urdf, "--teleop", described, "--format", "json")
    data = json.loads(result.stdout)
    assert [c["motion_control"] for c in data["motion_controls"]] == ["Waypoint"]
    assert data["disagreements"] == [
        "motion control Driving: read (urdf: 4 wheel joint(s) that turn), not declared: left out",
        "motion control Waypoint: declared (mine.yaml:3: action /go), not read from the "
        "description: kept",
    ]


def _rover_package(tmp_path: Path) -> Path:
    """A rover's description package and a navigation package that launches it with
    move_base; the description file."""
    src = tmp_path / "ws" / "src"
    for name, relative, text in (
        ("rover_description", "urdf/rover.urdf", _rover_with_sensors().text()),
        (
            "rover_navigation",
            "launch/nav.launch",
            "<include file='$(find rover_description)'/><node pkg='move_base' type='move_base'/>",
        ),
    ):
        (src / name / relative).parent.mkdir(parents=True)
        (src / name / "package.xml").write_text(f"<package><name>{name}</name></package>")
        (src / name / relative).write_text(text, encoding="utf-8")
    return src / "rover_description" / "urdf" / "rover.urdf"


def test_identify_reads_the_packages_around_a_description_for_the_controls_they_ship(
    tmp_path: Path,
) -> None:
    urdf = _rover_package(tmp_path)
    result = run_cli("identify", urdf)
    assert result.returncode == 0, result.stderr
    assert (
        "  Waypoint        package rover_navigation: rover_navigation/launch/nav.launch "
        "(move_base)\n" in result.stdout
    )
    alone = run_cli("identify", urdf, "--no-packages")
    assert "package rover_navigation" not in alone.stdout
    copy = tmp_path / "rover.urdf"
    copy.write_text(urdf.read_text(encoding="utf-8"), encoding="utf-8")
    named = run_cli("identify", copy, "--package", urdf.parent.parent)
    assert "package rover_navigation: rover_navigation/launch/nav.launch" in named.stdout


def test_a_workspace_named_for_a_description_in_no_package_is_read_as_its_repository(
    tmp_path: Path,
) -> None:
    urdf = tmp_path / "sim" / "rover.urdf"
    urdf.parent.mkdir()
    urdf.write_text(_rover_with_sensors().text(), encoding="utf-8")
    (tmp_path / "sim" / "go.py").write_text("nav2_simple_commander", encoding="utf-8")
    result = run_cli("identify", urdf, "--workspace", tmp_path / "sim")
    assert result.returncode == 0, result.stderr
    assert "  Waypoint        package sim: go.py (nav2_simple_commander)\n" in result.stdout
    gone = run_cli("identify", urdf, "--workspace", tmp_path / "gone")
    assert f"  note: workspace {tmp_path / 'gone'}: no folder there; none is read\n" in gone.stdout


def test_a_description_in_no_package_is_read_with_no_repository_unless_one_is_named(
    tmp_path: Path,
) -> None:
    # A clone around it may be a tool's own, its code naming the example robots it ships.
    clone = tmp_path / "rover_sim"
    (clone / ".git").mkdir(parents=True)
    (clone / "models").mkdir()
    urdf = clone / "models" / "rover.urdf"
    urdf.write_text(_rover_with_sensors().text(), encoding="utf-8")
    (clone / "go.py").write_text("nav2_simple_commander", encoding="utf-8")
    assert "package rover_sim" not in run_cli("identify", urdf).stdout
    named = run_cli("identify", urdf, "--workspace", clone)
    assert "  Waypoint        package rover_sim: go.py (nav2_simple_commander)\n" in named.stdout
    alone = run_cli("identify", urdf, "--workspace", clone, "--no-packages")
    assert "package rover_sim" not in alone.stdout
