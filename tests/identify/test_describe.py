"""identify --describe: a teleoperation description drafted from what was found, the evidence as
comments; the draft checks clean, and read back it gives the same characteristics."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import jsonschema
import pytest
import yaml

from solver import check_files
from solver.files.yamlio import parse_document
from solver.identify import Identification, identify
from solver.identify.describe import draft_description
from solver.ros.description import parse_description
from tests.conftest import ROOT
from tests.identify import builders
from tests.identify.builders import RobotText

SCHEMA = json.loads((ROOT / "docs" / "schema" / "teleop.schema.json").read_text("utf-8"))


def rover() -> RobotText:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("base_link", "ray", "laser"))
    robot.add(builders.gazebo_sensor("base_link", "camera", "front_camera"))
    return robot


ROBOTS = {
    "a rover with a lidar": rover,
    "a quadrotor": builders.quadrotor,
    "an arm": builders.manipulator,
    "a humanoid": builders.humanoid,
    "a hand": builders.hand,
}


def characteristics(found: Identification) -> tuple[object, ...]:
    return (
        found.kinematic_type,
        sorted(c.motion_control for c in found.motion_controls),
        sorted((s.kind, s.sensor_type, s.count) for s in found.sensors),
    )


@pytest.mark.parametrize("make", ROBOTS.values(), ids=ROBOTS.keys())
def test_draft_check_identify_gives_back_the_same_characteristics(
    make: Callable[[], RobotText], tmp_path: Path
) -> None:
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(make().text(), encoding="utf-8")
    first = identify(urdf)
    draft = tmp_path / "robot.teleop.yaml"
    draft.write_text(draft_description(first), encoding="utf-8")
    assert check_files([draft]).findings == ()
    jsonschema.validate(yaml.safe_load(draft.read_text("utf-8")), SCHEMA)
    again = identify(urdf)  # reads the draft beside it
    assert again.declared == str(draft)
    assert again.disagreements == ()
    assert characteristics(again) == characteristics(first)


def test_each_value_of_the_draft_sits_below_the_evidence_that_found_it(tmp_path: Path) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(rover().text(), encoding="utf-8")
    text = draft_description(identify(urdf))
    lines = text.splitlines()
    driving = lines.index('  - control: "Driving"')
    assert lines[driving - 2] == "  # urdf: 4 wheel joint(s) that turn"
    assert lines[driving - 1] == "  # the usual name on a ROS 2 graph: write the robot's own"
    assert lines[driving + 1 : driving + 3] == [
        '    topic: "/cmd_vel"',
        '    type: "geometry_msgs/msg/Twist"',
    ]
    assert '  - kind: "lidar"' in lines
    assert "#   4 wheel joint(s): wheel_left_joint, wheel_right_joint, wheel_rear_left_joint, " in (
        text
    )


def test_a_topic_the_robots_topics_showed_is_drafted_instead_of_the_usual_one(
    tmp_path: Path,
) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(rover().text(), encoding="utf-8")
    topics = tmp_path / "topics.txt"
    topics.write_text("/rover/cmd_vel geometry_msgs/Twist\n", encoding="utf-8")
    text = draft_description(identify(urdf, topic_lists=[topics]))
    assert '    topic: "/rover/cmd_vel"\n    type: "geometry_msgs/Twist"' in text


@pytest.mark.parametrize(
    "name",
    [
        'x"\nkinematic_type: Humanoid\n#',  # a line break and a quote in the robot's name
        "\u202ebidi\u202c and \U0001f916",  # a bidi override and a character past U+FFFF
        "r" * 300,  # longer than a name may be
    ],
    ids=["a forged line", "bidi and an astral character", "300 characters"],
)
def test_a_strangers_robot_name_starts_no_line_of_its_own(name: str, tmp_path: Path) -> None:
    robot = rover()
    robot.name = name
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(
        robot.text().replace('name="' + name + '"', 'name="' + _attribute(name) + '"'),
        encoding="utf-8",
    )
    result = identify(urdf)
    text = draft_description(result)
    described = parse_description(parse_document(text, "draft.teleop.yaml"))
    assert described.kinematic_type == "UGV"
    assert described.robot in (result.robot, None)
    assert all(
        line.startswith(("#", " ", "teleop:", "robot:", "kinematic_type:", "motion", "sensors"))
        for line in text.splitlines()
    )


def _attribute(text: str) -> str:
    """``text`` as an XML attribute value (a line break kept as a character reference)."""
    return (
        text.replace("&", "&amp;")
        .replace('"', "&quot;")
        .replace("<", "&lt;")
        .replace("\n", "&#10;")
    )
