"""Topics from real bags written with rosbags: ROS 1 .bag, ROS 2 .db3 and .mcap."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from solver.errors import InputError
from solver.identify.readers.bags import read_bag_topics
from solver.ros.names import Topic
from tests.conftest import run_cli
from tests.identify import builders

TOPICS = [
    ("/scan", "sensor_msgs/msg/LaserScan"),
    ("/camera/image_raw", "sensor_msgs/msg/Image"),
    ("/cmd_vel", "geometry_msgs/msg/Twist"),
    ("/move_base/goal", "move_base_msgs/msg/MoveBaseActionGoal"),
]


def write_ros1(path: Path) -> Path:
    store = get_typestore(Stores.ROS1_NOETIC)
    # move_base_msgs is not in the noetic store: register a stand-in with the same name.
    store.register(get_types_from_msg("int32 x", "move_base_msgs/msg/MoveBaseActionGoal"))
    with Writer1(path) as writer:
        for topic, kind in TOPICS:
            writer.add_connection(topic, kind, typestore=store)
    return path


def write_ros2(folder: Path, plugin: StoragePlugin) -> Path:
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Writer2(folder, version=8, storage_plugin=plugin) as writer:
        for topic, kind in TOPICS[:3]:
            writer.add_connection(topic, kind, typestore=store)
    return folder


def test_a_ros1_bag_gives_its_topics_and_types(tmp_path: Path) -> None:
    topics = read_bag_topics(write_ros1(tmp_path / "run.bag"))
    assert topics[0] == Topic("/scan", "sensor_msgs/LaserScan")
    assert [t.name for t in topics] == [name for name, _ in TOPICS]


@pytest.mark.parametrize(
    ("plugin", "suffix"), [(StoragePlugin.SQLITE3, ".db3"), (StoragePlugin.MCAP, ".mcap")]
)
def test_a_ros2_bag_folder_and_its_storage_file_both_read(
    tmp_path: Path, plugin: StoragePlugin, suffix: str
) -> None:
    folder = write_ros2(tmp_path / "run2", plugin)
    storage = next(folder.glob(f"*{suffix}"))
    assert read_bag_topics(folder) == read_bag_topics(storage)
    assert Topic("/cmd_vel", "geometry_msgs/Twist") in read_bag_topics(storage)


def test_a_file_that_is_not_a_bag_is_refused(tmp_path: Path) -> None:
    (tmp_path / "x.bag").write_bytes(b"not a bag at all")
    with pytest.raises(InputError, match="cannot read as a ROS 1 or ROS 2 bag"):
        read_bag_topics(tmp_path / "x.bag")
    with pytest.raises(InputError, match="no such bag"):
        read_bag_topics(tmp_path / "missing.bag")


def test_identify_with_a_bag_adds_sensors_and_controls(tmp_path: Path) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(builders.ugv().text(), encoding="utf-8")
    bag = write_ros1(tmp_path / "run.bag")
    result = run_cli("identify", urdf, "--bag", bag, "--format", "json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert [(s["kind"], s["sensor_type"], s["source"]) for s in data["sensors"]] == [
        ("lidar", "LIDAR", "bag run.bag: /scan"),
        ("camera", "2D Camera", "bag run.bag: /camera"),
    ]
    assert [c["motion_control"] for c in data["motion_controls"]] == ["Driving", "Waypoint"]
