"""A robot's teleoperation description: read into frozen values, or refused with every problem
at its line; hostile files bounded, nothing in them run."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.errors import InputError, TooLargeError
from solver.files.yamlio import parse_document
from solver.limits import limit
from solver.ros.description import (
    DeclaredControl,
    DescriptionError,
    TeleopDescription,
    description_beside,
    load_description,
    parse_description,
    parse_description_text,
)

ROVER = """\
teleop: 1
robot: rover
kinematic_type: UGV
kinematic_types: {Field rules: Rover}
motion_controls:
  - control: Driving
    topic: /rover/cmd_vel
    type: geometry_msgs/msg/Twist
  - {control: Waypoint, action: /rover/navigate_to_pose, type: nav2_msgs/action/NavigateToPose}
sensors:
  - {kind: lidar, topic: /rover/scan}
  - {kind: camera, topics: [/rover/left/image_raw, /rover/right/image_raw]}
  - {kind: imu}
"""


def read(text: str, name: str = "rover.teleop.yaml") -> TeleopDescription:
    return parse_description(parse_document(text, name))


def faults_of(text: str) -> list[tuple[int | None, str, str]]:
    with pytest.raises(DescriptionError) as caught:
        read(text)
    return [(f.location.line, f.location.path, f.message) for f in caught.value.faults]


def test_a_description_reads_into_its_declared_values() -> None:
    described = read(ROVER)
    assert (described.robot, described.kinematic_type) == ("rover", "UGV")
    assert described.kinematic_type_for("Field rules") == "Rover"
    assert described.kinematic_type_for("Mortimer et al. 2017") is None
    assert [(c.control, c.carrier, c.name, c.type) for c in described.motion_controls] == [
        ("Driving", "topic", "/rover/cmd_vel", "geometry_msgs/msg/Twist"),
        ("Waypoint", "action", "/rover/navigate_to_pose", "nav2_msgs/action/NavigateToPose"),
    ]
    # A sensor's count is its topics' number, or one.
    assert [(s.kind, s.count, len(s.topics)) for s in described.sensors] == [
        ("lidar", 1, 1),
        ("camera", 2, 2),
        ("imu", 1, 0),
    ]


def test_each_declared_value_knows_its_line() -> None:
    described = read(ROVER)
    assert described.where(described.kinematic_type_location) == "rover.teleop.yaml:3"
    assert described.where(described.motion_controls[0].location) == "rover.teleop.yaml:6"
    assert described.where(described.sensors[1].location) == "rover.teleop.yaml:12"


def test_every_problem_is_reported_at_once_each_at_its_line() -> None:
    found = faults_of(
        "teleop: 1\n"
        "colour: red\n"
        "motion_controls:\n"
        "  - {control: Driving, topic: cmd_vel}\n"
        "  - {control: Flight, topic: /a, action: /b}\n"
        "  - {control: Joint, service: /arm/move, type: not a type}\n"
        "  - {control: Driving, topic: /again}\n"
        "sensors:\n"
        "  - {kind: lidar, count: 0}\n"
        "  - {kind: camera, topic: /c, topics: [/d]}\n"
        "  - {count: 2}\n"
    )
    assert found == [
        (2, "colour", found[0][2]),
        (4, "motion_controls[0].topic", found[1][2]),
        (5, "motion_controls[1]", found[2][2]),
        (6, "motion_controls[2].type", found[3][2]),
        (
            7,
            "motion_controls[3].control",
            "motion control 'Driving' is declared twice (first at entry 0)",
        ),
        (9, "sensors[0].count", "sensor count must be 1 to 1000, got 0"),
        (10, "sensors[1]", "a sensor names topic or topics, not both"),
        (11, "sensors[2].kind", "missing sensor kind"),
    ]
    assert found[0][2].startswith("unknown field 'colour'")
    assert "is not absolute" in found[1][2]
    assert "exactly one of topic, action or service" in found[2][2]
    assert "pkg/Name" in found[3][2]


def test_a_file_without_teleop_is_no_description_and_nothing_of_it_is_quoted() -> None:
    found = faults_of("root:$6$hunter2hash:19000:0:99999:7:::\n")
    assert len(found) == 1
    assert "hunter2" not in found[0][2]


def test_another_version_is_refused_at_its_line() -> None:
    assert faults_of("teleop: 2\n") == [
        (1, "teleop", "format version 2 is not read; this reader reads version 1")
    ]


def test_a_description_past_the_entries_limit_is_refused_before_its_entries_are_read() -> None:
    entries = limit("description-entries").value + 1
    text = "teleop: 1\nsensors:\n" + "  - {kind: imu}\n" * entries
    with pytest.raises(TooLargeError) as caught:
        read(text)
    assert "limit 'description-entries'" in str(caught.value)
    assert caught.value.faults[0].location.line == 1


def test_an_alias_bomb_is_refused_by_the_yaml_reader_at_its_line(tmp_path: Path) -> None:
    bomb = tmp_path / "bomb.teleop.yaml"
    lines = ["teleop: 1", "kinematic_types:", "  a: &a [x, x, x, x, x, x, x, x, x, x]"]
    for i in range(8):
        earlier = f"*{chr(97 + i)}"
        lines.append(f"  {chr(98 + i)}: &{chr(98 + i)} [{', '.join([earlier] * 9)}]")
    bomb.write_text("\n".join(lines) + "\n", encoding="utf-8")
    with pytest.raises(InputError) as caught:
        load_description(bomb)
    assert "alias bomb" in str(caught.value)
    assert caught.value.faults[0].location.line == 3


def test_names_are_data_a_substitution_or_a_command_is_no_ros_name() -> None:
    found = faults_of(
        "teleop: 1\nmotion_controls:\n"
        "  - {control: Driving, topic: '$(rm -rf /)'}\n"
        "  - {control: Flight, topic: '~/cmd_vel'}\n"
    )
    assert [path for _, path, _ in found] == [
        "motion_controls[0].topic",
        "motion_controls[1].topic",
    ]


def test_a_description_sits_beside_its_robot_as_robot_teleop_yaml() -> None:
    assert description_beside("pkg/urdf/rover.urdf") == Path("pkg/urdf/rover.teleop.yaml")
    assert description_beside("rover.urdf.xacro") == Path("rover.teleop.yaml")
    assert description_beside("rover.xacro") == Path("rover.teleop.yaml")


def test_a_declared_control_is_a_frozen_value() -> None:
    control = read(ROVER).motion_controls[0]
    assert isinstance(control, DeclaredControl)
    with pytest.raises(AttributeError):
        control.name = "/other"  # type: ignore[misc]  # frozen: the test checks it refuses


def test_a_description_from_a_live_graph_is_read_up_to_its_bound_and_refused_past_it() -> None:
    bound = limit("description-bytes").value
    text = ROVER + "#" * (bound - len(ROVER))
    assert len(text) == bound
    assert parse_description_text(text, "/ugv1/teleop_description") == read(
        text, "/ugv1/teleop_description"
    )
    with pytest.raises(TooLargeError) as caught:
        parse_description_text(text + "#", "/ugv1/teleop_description")
    [fault] = caught.value.faults
    assert fault.location.file == "/ugv1/teleop_description"
    assert "limit 'description-bytes'" in fault.message
