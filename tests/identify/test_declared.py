"""A declared teleoperation description wins over what identification reads, and every
disagreement between the two is said, never dropped."""

from __future__ import annotations

import os
from pathlib import Path

from solver.core.rules import default_rules_path, load_rules
from solver.files.yamlio import parse_document
from solver.identify import identify, identify_urdf, load_profile
from solver.identify.declared import Characteristics, with_declared
from solver.identify.interfaces import Control
from solver.identify.sensors import Sensor
from solver.ros.description import TeleopDescription, parse_description
from tests.identify import builders


def described(text: str) -> TeleopDescription:
    return parse_description(parse_document("teleop: 1\n" + text, "robot.teleop.yaml"))


def rover_text() -> str:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    return robot.text()


READ = Characteristics(
    "UGV",
    "UGV",
    (Control("Driving", "urdf: 4 wheel joint(s) that turn"),),
    (Sensor("lidar", "LIDAR", 1, "urdf: laser"),),
)


def declared(text: str) -> Characteristics:
    return with_declared(READ, described(text), load_profile(), load_rules(default_rules_path()))


def test_a_declared_structure_is_the_rule_sets_type_for_it() -> None:
    found = declared("kinematic_type: Quadruped\n")
    # The article's rule set has no quadruped: the structure is declared, its type is none.
    assert (found.structure, found.kinematic_type) == ("Quadruped", None)
    assert found.disagreements == (
        "kinematic type: declared Quadruped (robot.teleop.yaml:2, no kinematic type in "
        "'Mortimer et al. 2017'), identification read UGV (type UGV): the declared value wins",
    )


def test_a_type_declared_for_this_rule_set_by_its_name_wins() -> None:
    rules = load_rules(default_rules_path())
    found = declared(f"kinematic_type: Quadruped\nkinematic_types: {{{rules.name}: UGV}}\n")
    assert (found.structure, found.kinematic_type) == ("UGV", "UGV")
    assert found.disagreements == ()


def test_a_type_that_is_neither_a_structure_nor_the_rule_sets_is_said_and_not_used() -> None:
    found = declared("kinematic_type: Hovercraft\n")
    assert (found.structure, found.kinematic_type) == ("UGV", "UGV")
    assert found.disagreements == (
        "kinematic type 'Hovercraft' (robot.teleop.yaml:2) is neither a kinematic type of "
        "'Mortimer et al. 2017' nor a structure of the profile: not used",
    )


def test_declared_motion_controls_replace_the_read_ones_and_say_what_differs() -> None:
    found = declared(
        "motion_controls:\n"
        "  - {control: Waypoint, action: /nav, type: nav2_msgs/action/NavigateToPose}\n"
    )
    assert found.motion_controls == (
        Control("Waypoint", "robot.teleop.yaml:3: action /nav (nav2_msgs/action/NavigateToPose)"),
    )
    assert found.disagreements == (
        "motion control Driving: read (urdf: 4 wheel joint(s) that turn), not declared: left out",
        "motion control Waypoint: declared (robot.teleop.yaml:3: action /nav "
        "(nav2_msgs/action/NavigateToPose)), not read from the description: kept",
    )


def test_declared_sensors_replace_the_read_ones_mapped_to_the_rule_sets_types() -> None:
    found = declared("sensors:\n  - {kind: lidar, count: 2}\n  - {kind: depth_camera, topic: /d}\n")
    assert [(s.kind, s.sensor_type, s.count) for s in found.sensors] == [
        ("lidar", "LIDAR", 2),
        ("depth_camera", "RGB-D Camera", 1),
    ]
    assert found.disagreements == (
        "sensor lidar: declared x2 (robot.teleop.yaml:3), read x1: the declared count wins",
        "sensor depth_camera: declared (robot.teleop.yaml:4: /d), not read: kept",
    )


def test_a_section_left_out_keeps_what_was_read() -> None:
    found = declared("robot: rover\n")
    assert found == READ


def test_a_description_beside_the_urdf_is_read_and_named_in_the_evidence(tmp_path: Path) -> None:
    (tmp_path / "rover.urdf").write_text(rover_text(), encoding="utf-8")
    (tmp_path / "rover.teleop.yaml").write_text(
        "teleop: 1\nmotion_controls:\n  - {control: Driving, topic: /rover/cmd_vel}\n",
        encoding="utf-8",
    )
    result = identify(tmp_path / "rover.urdf")
    assert result.declared == str(tmp_path / "rover.teleop.yaml")
    assert "declared: rover.teleop.yaml (its values win)" in result.evidence
    assert [c.motion_control for c in result.motion_controls] == ["Driving"]
    assert identify(tmp_path / "rover.urdf", look_beside=False).declared is None


def test_a_description_that_cannot_be_read_is_a_located_warning_and_is_not_used(
    tmp_path: Path,
) -> None:
    (tmp_path / "rover.urdf").write_text(rover_text(), encoding="utf-8")
    broken = tmp_path / "rover.teleop.yaml"
    broken.write_text("teleop: 1\nsensors: {kind: lidar}\n", encoding="utf-8")
    result = identify(tmp_path / "rover.urdf")
    assert result.declared is None
    assert [(w.location.file, w.location.line) for w in result.warnings] == [(str(broken), 2)]
    assert result.warnings[0].message.endswith("(the teleoperation description is not read)")
    assert result.structure == "UGV"


def test_identify_urdf_takes_a_description_read_before() -> None:
    result = identify_urdf(rover_text(), description=described("kinematic_type: Manipulator\n"))
    assert (result.structure, result.kinematic_type) == ("Manipulator", "Manipulator")
    assert result.disagreements


def test_a_strangers_file_beside_the_robot_is_never_quoted(tmp_path: Path) -> None:
    (tmp_path / "rover.urdf").write_text(rover_text(), encoding="utf-8")
    for secret in ("root:$6$hunter2hash:19000:0:99999:7:::\n", "{hunter2: [unclosed\n"):
        (tmp_path / "rover.teleop.yaml").write_text(secret, encoding="utf-8")
        result = identify(tmp_path / "rover.urdf")
        assert result.declared is None
        assert result.warnings
        assert not any("hunter2" in str(w) for w in result.warnings)


def test_a_description_that_is_a_fifo_is_refused_without_waiting_for_a_writer(
    tmp_path: Path,
) -> None:
    (tmp_path / "rover.urdf").write_text(rover_text(), encoding="utf-8")
    fifo = tmp_path / "rover.teleop.yaml"
    os.mkfifo(fifo)
    result = identify(tmp_path / "rover.urdf", teleop=fifo)  # returns: no writer is waited for
    assert result.declared is None
    assert [w.location.file for w in result.warnings] == [str(fifo)]
