"""Topics from real bags written with rosbags: ROS 1 .bag, ROS 2 .db3 and .mcap."""

from __future__ import annotations

import json
import os
import sqlite3
import struct
import tempfile
from pathlib import Path

import pytest
from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from solver.errors import InputError, SolverError
from solver.identify import identify
from solver.identify.readers.bags import BagLimits, read_bag_topics
from solver.ros.names import Topic
from tests.conftest import run_cli
from tests.identify import builders
from tests.identify.readers import bagfiles

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


@pytest.mark.parametrize(
    "content",
    [b"\x89MCAP0\r\n", b"\x89MCAP0\r\n" + b"\x00" * 64, b"#ROSBAG V2.0\n", os.urandom(4096)],
)
@pytest.mark.parametrize("suffix", [".mcap", ".bag", ".db3"])
def test_a_corrupt_bag_is_a_located_error(tmp_path: Path, content: bytes, suffix: str) -> None:
    bag = tmp_path / f"run{suffix}"
    bag.write_bytes(content)
    with pytest.raises(SolverError) as raised:
        read_bag_topics(bag)
    assert str(raised.value).startswith(str(bag))


def test_a_device_given_as_a_bag_is_refused_without_reading_it() -> None:
    with pytest.raises(SolverError, match="not a bag file or folder"):
        read_bag_topics("/dev/zero")


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


def write_ros2_topics(folder: Path, topics: list[tuple[str, str]]) -> Path:
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Writer2(folder, version=8, storage_plugin=StoragePlugin.SQLITE3) as writer:
        for topic, kind in topics:
            writer.add_connection(topic, kind, typestore=store)
    return folder


def write_ros1_topics(path: Path, topics: list[tuple[str, str]]) -> Path:
    store = get_typestore(Stores.ROS1_NOETIC)
    known = set(store.types)
    for _, kind in topics:  # types the noetic store lacks (mavros): stand-ins of that name
        if kind not in known:
            store.register(get_types_from_msg("int32 x", kind))
    with Writer1(path) as writer:
        for topic, kind in topics:
            writer.add_connection(topic, kind, typestore=store)
    return path


def test_a_bag_shows_what_a_humanoid_offers_walking_navigation_and_joint_goals(
    tmp_path: Path,
) -> None:
    bag = write_ros2_topics(
        tmp_path / "walk",
        [
            ("/cmd_vel", "geometry_msgs/msg/Twist"),
            ("/navigate_to_pose/_action/status", "action_msgs/msg/GoalStatusArray"),
            ("/arm_controller/joint_trajectory", "trajectory_msgs/msg/JointTrajectory"),
        ],
    )
    urdf = tmp_path / "humanoid.urdf"
    urdf.write_text(builders.humanoid().text(), encoding="utf-8")
    result = identify(urdf, bags=[bag])
    assert result.structure == "Humanoid"
    found = {c.motion_control: c.source for c in result.motion_controls}
    assert found["Walking"] == (
        "urdf: likely, not declared: 2 legs to walk on; bag walk: /cmd_vel (geometry_msgs/Twist)"
    )
    assert found["Waypoint"] == (
        "bag walk: /navigate_to_pose/_action/status (action_msgs/GoalStatusArray)"
    )
    assert found["Joint"].endswith(
        "bag walk: /arm_controller/joint_trajectory (trajectory_msgs/JointTrajectory)"
    )


def test_a_bag_shows_a_drones_flight_and_position_setpoints(tmp_path: Path) -> None:
    bag = write_ros1_topics(
        tmp_path / "flight.bag",
        [
            ("/mavros/setpoint_raw/attitude", "mavros_msgs/msg/AttitudeTarget"),
            ("/mavros/setpoint_raw/local", "mavros_msgs/msg/PositionTarget"),
        ],
    )
    urdf = tmp_path / "copter.urdf"
    urdf.write_text(builders.quadrotor().text(), encoding="utf-8")
    found = {c.motion_control: c.source for c in identify(urdf, bags=[bag]).motion_controls}
    assert found["Flight"] == (
        "urdf: 4 rotor joint(s); bag flight.bag: /mavros/setpoint_raw/attitude "
        "(mavros_msgs/AttitudeTarget)"
    )
    assert found["Waypoint"] == (
        "bag flight.bag: /mavros/setpoint_raw/local (mavros_msgs/PositionTarget)"
    )


def test_a_bag_shows_a_vessel_driven_by_velocity_commands(tmp_path: Path) -> None:
    bag = write_ros2_topics(tmp_path / "sea", [("/cmd_vel", "geometry_msgs/msg/Twist")])
    urdf = tmp_path / "boat.urdf"
    urdf.write_text(builders.surface_vessel().text(), encoding="utf-8")
    result = identify(urdf, bags=[bag])
    assert result.structure == "Surface Vessel"
    assert [(c.motion_control, c.source) for c in result.motion_controls] == [
        ("Driving", "urdf: 2 thruster(s); bag sea: /cmd_vel (geometry_msgs/Twist)")
    ]


# ---- issue 23.3 and 31.4: hostile bags, each within its bound ---------------------------------


DEFAULT = BagLimits()
# Empty records (an opcode and a zero length: nine zero bytes each) fill these chunks exactly.
RECORDS_OF_A_MIB = 9 * (2**20 // 9)


def refusal(bag: Path, limits: BagLimits = DEFAULT) -> str:
    """The located refusal reading ``bag`` ends with; its message."""
    with pytest.raises(InputError) as caught:
        read_bag_topics(bag, limits=limits)
    fault = caught.value.faults[0]
    assert fault.location.file == str(bag)
    assert fault.code in {"bag", "bag-limit"}
    return fault.message


@pytest.fixture
def private_temp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Where the bag reader makes its private temporary folder, for the test to look at."""
    folder = tmp_path / "tmp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


RECURSIVE = (
    "WITH RECURSIVE r(n) AS (SELECT 1 UNION ALL SELECT n + 1 FROM r) SELECT n AS id, {columns} "
    "FROM r"
)


def test_message_definitions_that_are_a_recursive_view_are_never_read(
    tmp_path: Path, private_temp: Path
) -> None:
    # The 16 KB bag: it ran forever and filled the temporary folder.
    storage = bagfiles.ros2(tmp_path / "run", StoragePlugin.SQLITE3)
    with sqlite3.connect(storage) as connection:
        connection.executescript(
            "DROP TABLE message_definitions; CREATE VIEW message_definitions AS "
            + RECURSIVE.format(
                columns="'x/msg/Y' AS topic_type, 'ros2msg' AS encoding, "
                "'int32 x' AS encoded_message_definition, '' AS type_description_hash"
            )
        )
    assert [t.name for t in read_bag_topics(storage)] == ["/scan", "/cmd_vel"]
    assert list(private_temp.iterdir()) == []


@pytest.mark.parametrize(
    ("table", "replacement", "kind"),
    [
        (
            "topics",
            "CREATE VIEW topics AS "
            + RECURSIVE.format(columns="'/t' AS name, 'std_msgs/msg/String' AS type"),
            "view",
        ),
        ("messages", "CREATE VIRTUAL TABLE messages USING fts5(data)", "a virtual table"),
    ],
    ids=["topics-a-recursive-view", "messages-a-virtual-table"],
)
def test_a_database_whose_tables_run_its_own_sql_is_refused(
    tmp_path: Path, table: str, replacement: str, kind: str
) -> None:
    storage = bagfiles.ros2(tmp_path / "run", StoragePlugin.SQLITE3)
    with sqlite3.connect(storage) as connection:
        connection.executescript(f"DROP TABLE {table}; {replacement}")
    message = refusal(storage)
    assert f"its {table!r} is {kind}, not a table" in message


def test_fifty_thousand_topics_with_as_many_definitions_are_read_within_the_bounds(
    tmp_path: Path,
) -> None:
    # The reader library matches every topic against every definition (51 s here); the topics
    # table alone is read in one pass, well inside the CPU bound that would refuse it.
    topics = [(f"/robot/t{i}", f"pkg/msg/T{i}") for i in range(50_000)]
    storage = bagfiles.db3(tmp_path / "many.db3", topics, definitions=50_000)
    found = read_bag_topics(storage)
    assert len(found) == 50_000
    assert found[-1] == Topic("/robot/t49999", "pkg/T49999")


def test_a_ros1_bag_whose_chunk_index_repeats_40_times_gives_its_topics(tmp_path: Path) -> None:
    # A full reader indexes every message once per copy (677 MB for the bag); the
    # topics are in the connection records, read alone.
    bag = bagfiles.ros1_with_repeated_chunk_infos(tmp_path / "repeated.bag", copies=40)
    assert [t.name for t in read_bag_topics(bag)] == ["/scan", "/cmd_vel"]


def test_a_ros1_bag_header_declaring_4_gib_is_refused_within_the_memory_bound(
    tmp_path: Path,
) -> None:
    bag = tmp_path / "huge-header.bag"
    bag.write_bytes(b"#ROSBAG V2.0\n" + struct.pack("<I", 0xFFFFFFF0) + b"\0" * 64)
    assert "needs more than 512 MiB" in refusal(bag)


def test_an_mcap_chunk_declaring_a_gibibyte_is_refused_before_it_is_decompressed(
    tmp_path: Path,
) -> None:
    # The 32 KB MCAP took 1-2 GB of memory.
    bag = bagfiles.mcap(tmp_path / "bomb.mcap", [(2**30, bagfiles.zstd_of_zeros(2**30))])
    assert "a chunk declares 1073741824 bytes decompressed; at most 67108864" in refusal(bag)


def test_an_mcap_chunk_expanding_past_what_it_declares_is_cut_at_its_declaration(
    tmp_path: Path,
) -> None:
    bag = bagfiles.mcap(tmp_path / "liar.mcap", [(1024, bagfiles.zstd_of_zeros(256 * 2**20))])
    assert "Chunk size mismatch: expected 1024 bytes, got 1025" in refusal(bag)


def test_the_chunks_of_one_bag_are_decompressed_to_at_most_its_bound_in_all(
    tmp_path: Path,
) -> None:
    chunk = (RECORDS_OF_A_MIB, bagfiles.zstd_of_zeros(RECORDS_OF_A_MIB))
    bag = bagfiles.mcap(tmp_path / "many-chunks.mcap", [chunk] * 4)
    limits = BagLimits(chunk_bytes=2**20, bag_bytes=3 * 2**20)
    assert "its chunks decompress to more than 3145728 bytes in all" in refusal(bag, limits)


def test_a_file_compressed_bag_expanding_past_the_temporary_space_is_refused(
    tmp_path: Path, private_temp: Path
) -> None:
    folder = tmp_path / "compressed"
    bagfiles.file_compressed_ros2(folder).write_bytes(bagfiles.zstd_of_zeros(8 * 2**20))
    message = refusal(folder, BagLimits(temp_bytes=2**20))
    assert "needs more than 1048576 bytes of temporary space" in message
    assert list(private_temp.iterdir()) == []


def test_a_bag_that_keeps_its_reader_busy_is_stopped_at_the_cpu_bound(tmp_path: Path) -> None:
    # 48 MiB of empty records, read nine bytes at a time.
    size = 48 * RECORDS_OF_A_MIB
    bag = bagfiles.mcap(tmp_path / "busy.mcap", [(size, bagfiles.zstd_of_zeros(size))])
    assert "reading it used more than 1 s of CPU" in refusal(bag, BagLimits(cpu_seconds=1))


def test_a_bag_whose_metadata_never_ends_is_stopped_at_the_wall_clock_bound(
    tmp_path: Path,
) -> None:
    folder = tmp_path / "waiting"
    folder.mkdir()
    os.mkfifo(folder / "metadata.yaml")  # read by the reader, written by no one
    assert "reading it took more than 1 s" in refusal(folder, BagLimits(wall_seconds=1))


def test_a_storage_file_that_is_a_fifo_is_refused_at_once(tmp_path: Path) -> None:
    folder = tmp_path / "fifo"
    folder.mkdir()
    os.mkfifo(folder / "run.db3")
    assert "run.db3: not a regular file" in refusal(folder)


@pytest.mark.parametrize("kind", ["recursive-view", "mcap-bomb"])
def test_identify_refuses_a_hostile_bag_with_exit_2_and_its_name(tmp_path: Path, kind: str) -> None:
    urdf = tmp_path / "rover.urdf"
    urdf.write_text(builders.ugv().text(), encoding="utf-8")
    if kind == "mcap-bomb":
        bag = bagfiles.mcap(tmp_path / "bomb.mcap", [(2**30, bagfiles.zstd_of_zeros(2**30))])
    else:
        bag = bagfiles.db3(tmp_path / "view.db3", [("/scan", "sensor_msgs/msg/LaserScan")])
        with sqlite3.connect(bag) as connection:
            connection.executescript(
                "DROP TABLE topics; CREATE VIEW topics AS "
                + RECURSIVE.format(columns="'/t' AS name, 'std_msgs/msg/String' AS type")
            )
    result = run_cli("identify", urdf, "--bag", bag)
    assert result.returncode == 2
    assert result.stderr.startswith(f"{bag}: ")
    assert "Traceback" not in result.stderr
    assert result.stdout == ""
