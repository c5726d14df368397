"""One robot's layout: identified from its URDF, its configuration, topics under its name."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
# A PointCloud2 topic's colour, set in the layout (the app would pick it on the first message
# and mark the layout modified): height, with the app's own colour map.
_CLOUD = {"visible": True, "colorField": "z", "colorMode": "colormap", "colorMap": "turbo"}


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
    # The template's topic may be a LaserScan or a PointCloud2: coloured by intensity, which
    # both can have (a LaserScan can only be coloured by intensity or range).
    assert layout["configById"]["3D!p02"]["topics"] == {
        "/diff_drive_lidar/points": {
            "visible": True,
            "colorField": "intensity",
            "colorMode": "colormap",
            "colorMap": "turbo",
        }
    }
    assert layout["configById"]["Teleop!p01"]["topic"] == "/diff_drive_lidar/cmd_vel"
    # Written again for another robot from its description, not as a team's layouts (which
    # know neither its joints nor its real topics).
    assert layout["globalVariables"]["teleop_ui_layout"] == (
        "teleop-ui: UI configuration 11, for the robot under /diff_drive_lidar; for a robot "
        "under /NAME: teleop-ui layouts --robot URDF --team TEAM -o FILE --namespace /NAME "
        "(--topics FILE: its own topics)"
    )


def _robot_layout(tmp_path: Path, *extra: str) -> int:
    return main(
        [
            "layouts",
            "--robot",
            str(EXAMPLES / "diff_drive_lidar.urdf"),
            "--team",
            "case2",
            *extra,
        ]
    )


def test_robot_layout_takes_its_real_topics_from_a_topic_list(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    topics = tmp_path / "topics.txt"
    topics.write_text(
        "Published topics:\n"
        " * /dd/front/points [sensor_msgs/PointCloud2] 1 publisher\n"
        " * /dd/cmd_vel_echo [geometry_msgs/Twist] 1 publisher\n"
        "Subscribed topics:\n"
        " * /dd/base/cmd_vel [geometry_msgs/Twist] 1 subscriber\n"
    )
    out = tmp_path / "x.json"
    assert _robot_layout(tmp_path, "--topics", str(topics), "-o", str(out)) == 0
    assert capsys.readouterr().err == ""
    config = json.loads(out.read_text())["configById"]
    assert config["3D!p02"]["topics"] == {"/dd/front/points": _CLOUD}
    # The Teleop panel takes the topic the robot subscribes to, not the one it publishes.
    assert config["Teleop!p01"]["topic"] == "/dd/base/cmd_vel"


def test_a_panel_the_robot_has_no_topic_for_keeps_the_presentations_with_a_located_warning(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    topics = tmp_path / "topics.txt"
    topics.write_text("/dd/cmd_vel geometry_msgs/Twist\n")
    out = tmp_path / "x.rviz"
    assert _robot_layout(tmp_path, "--topics", str(topics), "-o", str(out), "--format", "rviz") == 0
    err = capsys.readouterr().err
    assert (
        f"warning: {topics}: point cloud: the robot has no published topic of type "
        "sensor_msgs/LaserScan, sensor_msgs/PointCloud2 for this 3D panel; "
        "it keeps the presentation's topic /diff_drive_lidar/points"
    ) in err
    text = out.read_text()
    assert "Value: /diff_drive_lidar/points" in text
    # RViz2 has no display for velocity commands: a placeholder that names the topic.
    assert "Name: 'Driving: /dd/cmd_vel (placeholder: no RViz2 display" in text


def test_robot_layout_takes_its_real_topics_from_a_ros1_bag(tmp_path: Path) -> None:
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    bag = tmp_path / "run.bag"
    with Writer(bag) as writer:
        writer.add_connection("/lidar/points", "sensor_msgs/msg/PointCloud2", typestore=store)
        writer.add_connection("/teleop/cmd_vel", "geometry_msgs/msg/Twist", typestore=store)
    out = tmp_path / "x.json"
    assert _robot_layout(tmp_path, "--bag", str(bag), "-o", str(out)) == 0
    config = json.loads(out.read_text())["configById"]
    assert config["3D!p02"]["topics"] == {"/lidar/points": _CLOUD}
    assert config["Teleop!p01"]["topic"] == "/teleop/cmd_vel"


def test_an_arms_joint_command_names_the_joints_of_its_description(tmp_path: Path) -> None:
    out = tmp_path / "arm.json"
    urdf = EXAMPLES / "arm_gripper.urdf"
    assert main(["layouts", "--robot", str(urdf), "--team", "case3", "-o", str(out)]) == 0
    configs = json.loads(out.read_text())["configById"]
    publish = next(config for key, config in configs.items() if key.startswith("Publish!"))
    assert publish["topicName"] == "/arm_gripper/joint_trajectory"
    message = json.loads(publish["value"])
    assert message["joint_names"][:3] == [
        "shoulder_pan_joint",
        "shoulder_lift_joint",
        "elbow_joint",
    ]
    assert message["points"][0]["positions"] == [0.0] * len(message["joint_names"])


def test_velocity_pads_of_one_template_share_the_robots_real_command_topic(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    topics = tmp_path / "topics.txt"
    topics.write_text("/dd/base/cmd_vel geometry_msgs/msg/Twist\n")
    out = tmp_path / "x.json"
    # case3 has no Manipulator: the arm gets the default configuration, every component.
    urdf = str(EXAMPLES / "arm_gripper.urdf")
    status = main(
        ["layouts", "--robot", urdf, "--team", "case3", "--topics", str(topics), "-o", str(out)]
    )
    assert status == 0
    assert "Teleop" not in capsys.readouterr().err  # no pad left on a template
    configs = json.loads(out.read_text())["configById"]
    pads = [c for key, c in configs.items() if key.startswith("Teleop!")]
    assert [(pad["topic"], pad["foxglovePanelTitle"]) for pad in pads] == [
        ("/dd/base/cmd_vel", "Flight, Driving, Walking \u00b7 /dd/base/cmd_vel")
    ]
