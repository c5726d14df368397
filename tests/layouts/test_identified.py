"""A real robot's layout from its description, as a library call: identified, given the
configuration of the combination it starts in, laid out under its namespace."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver import InputError, Solution, assign, identified_layout, load_team, solve

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DIFF_DRIVE = EXAMPLES / "diff_drive_lidar.urdf"


@pytest.fixture(scope="module")
def case2() -> Solution:
    return solve(load_team("case2"))


def test_a_robot_is_laid_out_in_the_configuration_it_starts_in_under_its_own_name(
    case2: Solution,
) -> None:
    done = identified_layout(DIFF_DRIVE, case2)
    assert done.identification.robot == "diff_drive_lidar"
    starts_in = assign(
        case2, kinematic_type="UGV", motion_control="Driving", sensor_type="LIDAR", sensor_count=1
    )
    assert done.assignment == starts_in
    layout = json.loads(done.layout.text)
    assert layout["configById"]["Teleop!p01"]["topic"] == "/diff_drive_lidar/cmd_vel"
    assert done.layout.warnings == ()


def test_values_given_beside_identification_choose_the_configuration(case2: Solution) -> None:
    done = identified_layout(DIFF_DRIVE, case2, given={"sensor_count": "6"})
    six_lidars = assign(
        case2, kinematic_type="UGV", motion_control="Driving", sensor_type="LIDAR", sensor_count=6
    )
    assert done.assignment == six_lidars
    assert done.assignment.number != identified_layout(DIFF_DRIVE, case2).assignment.number


def test_a_namespace_given_replaces_the_robots_name_in_every_topic(case2: Solution) -> None:
    done = identified_layout(DIFF_DRIVE, case2, namespace="/dd", fmt="rviz")
    assert done.layout.text.startswith("# teleop-ui: UI configuration 11, for the robot under /dd.")
    assert "/diff_drive_lidar/" not in done.layout.text


def test_real_topics_from_a_topic_list_feed_the_panels(case2: Solution, tmp_path: Path) -> None:
    topics = tmp_path / "topics.txt"
    topics.write_text("/dd/base/cmd_vel geometry_msgs/msg/Twist\n", encoding="utf-8")
    done = identified_layout(DIFF_DRIVE, case2, topics=topics)
    layout = json.loads(done.layout.text)
    assert layout["configById"]["Teleop!p01"]["topic"] == "/dd/base/cmd_vel"
    # No point cloud among them: that panel keeps the template, with a warning located there.
    assert [fault.location.file for fault in done.layout.warnings] == [str(topics)]


def test_a_robot_whose_name_makes_no_namespace_is_a_located_error_at_its_description(
    case2: Solution, tmp_path: Path
) -> None:
    urdf = tmp_path / "r.urdf"
    urdf.write_text('<robot name="9lives"><link name="base"/></robot>\n', encoding="utf-8")
    with pytest.raises(InputError) as caught:
        identified_layout(urdf, case2)
    assert str(caught.value).startswith(f"{urdf}: '/9lives' is not a ROS 2 namespace")
    assert str(caught.value).endswith("give one with --namespace /NAME")
