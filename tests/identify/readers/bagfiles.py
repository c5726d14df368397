"""Small bags for the tests, real ones written with rosbags and hostile ones written by hand.

The hostile ones follow the formats' own specifications (ROS 1 bag format 2.0, the ROS 2
SQLite schema rosbag2 writes, MCAP's record layout), built from the bytes up, so each holds
exactly the one thing a test is about.
"""

from __future__ import annotations

import sqlite3
import struct
import sys
from pathlib import Path
from typing import Literal

from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import CompressionFormat, CompressionMode, StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_typestore

if sys.version_info >= (3, 14):
    from compression import zstd
else:
    from backports import zstd

ROS1_STORE = get_typestore(Stores.ROS1_NOETIC)
ROS2_STORE = get_typestore(Stores.ROS2_HUMBLE)
TOPICS = (("/scan", "sensor_msgs/msg/LaserScan"), ("/cmd_vel", "geometry_msgs/msg/Twist"))


def ros1(path: Path, messages: int = 3) -> Path:
    """A ROS 1 bag with two topics and a few messages on each (so it has chunks and indexes)."""
    with Writer1(path) as writer:
        for topic, kind in TOPICS:
            connection = writer.add_connection(topic, kind, typestore=ROS1_STORE)
            for i in range(messages):
                writer.write(connection, 1000 + i, b"\0" * 8)  # never decoded by a reader
    return path


def ros2(folder: Path, plugin: StoragePlugin, *, version: Literal[8, 9] = 9) -> Path:
    """A ROS 2 bag folder with two topics and one message on each; its storage file."""
    with Writer2(folder, version=version, storage_plugin=plugin) as writer:
        for topic, kind in TOPICS:
            connection = writer.add_connection(topic, kind, typestore=ROS2_STORE)
            writer.write(connection, 1000, b"\0" * 8)
    suffix = ".db3" if plugin == StoragePlugin.SQLITE3 else ".mcap"
    return next(folder.glob(f"*{suffix}"))


def file_compressed_ros2(folder: Path) -> Path:
    """A ROS 2 bag folder whose storage file is compressed whole (``compression_mode: file``)."""
    writer = Writer2(folder, version=9, storage_plugin=StoragePlugin.SQLITE3)
    writer.set_compression(CompressionMode.FILE, CompressionFormat.ZSTD)
    with writer:
        for topic, kind in TOPICS:
            writer.add_connection(topic, kind, typestore=ROS2_STORE)
    return next(folder.glob("*.zstd"))


def zstd_of_zeros(size: int) -> bytes:
    """``size`` zero bytes, zstd-compressed a MiB at a time (a gigabyte takes 32 KB)."""
    compressor = zstd.ZstdCompressor()
    parts = [compressor.compress(b"\0" * min(2**20, size - done)) for done in range(0, size, 2**20)]
    return b"".join(parts) + compressor.flush()


def db3(path: Path, topics: list[tuple[str, str]], *, definitions: int = 0) -> Path:
    """A ROS 2 SQLite bag (schema 4, as rosbag2 Iron writes it) with ``topics`` and
    ``definitions`` distinct message definitions."""
    with sqlite3.connect(path) as connection:
        connection.executescript(
            "CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);"
            "INSERT INTO schema VALUES (4, 'iron');"
            "CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL,"
            " metadata TEXT NOT NULL);"
            "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,"
            " serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL,"
            " type_description_hash TEXT NOT NULL);"
            "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,"
            " timestamp INTEGER NOT NULL, data BLOB NOT NULL);"
            "CREATE INDEX timestamp_idx ON messages (timestamp ASC);"
            "CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL,"
            " encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL,"
            " type_description_hash TEXT NOT NULL);"
        )
        connection.executemany(
            "INSERT INTO topics VALUES (?, ?, ?, 'cdr', '', '')",
            [(i + 1, name, kind) for i, (name, kind) in enumerate(topics)],
        )
        connection.executemany(
            "INSERT INTO message_definitions VALUES (?, ?, 'ros2msg', 'int32 x', '')",
            [(i + 1, f"pkg/msg/T{i}") for i in range(definitions)],
        )
    return path


def record(op: int, body: bytes) -> bytes:
    """An MCAP record: opcode, length, body."""
    return bytes([op]) + struct.pack("<Q", len(body)) + body


def string(text: str) -> bytes:
    raw = text.encode()
    return struct.pack("<I", len(raw)) + raw


MAGIC = b"\x89MCAP0\r\n"


def mcap(path: Path, chunks: list[tuple[int, bytes]]) -> Path:
    """An MCAP of ``ros2`` profile with no summary (so a reader scans its chunks); each chunk
    is (uncompressed size it declares, zstd data)."""
    body = [MAGIC, record(0x01, string("ros2") + string("hand-written"))]
    for declared, data in chunks:
        head = struct.pack("<QQQI", 0, 0, declared, 0) + string("zstd")
        body.append(record(0x06, head + struct.pack("<Q", len(data)) + data))
    body.append(record(0x02, struct.pack("<QQI", 0, 0, 0)))
    body.append(MAGIC)
    path.write_bytes(b"".join(body))
    return path


def ros1_with_repeated_chunk_infos(path: Path, copies: int = 40) -> Path:
    """A real ROS 1 bag whose chunk-info records (the index after the connections) are repeated
    ``copies`` times, its header counting them all: every copy makes a full reader index every
    message once more."""
    from rosbags.rosbag1.reader import Header, RecordType

    ros1(path, messages=500)
    data = bytearray(path.read_bytes())
    with path.open("rb") as bio:
        bio.readline()
        header = Header.read(bio, RecordType.BAGHEADER)
        bio.seek(header.get_uint64("index_pos"))
        for _ in range(header.get_uint32("conn_count")):
            Header.read(bio, RecordType.CONNECTION)
            Header.read(bio)
        infos = bytes(data[bio.tell() :])
    field = data.index(b"chunk_count=") + len(b"chunk_count=")
    (count,) = struct.unpack_from("<I", data, field)
    struct.pack_into("<I", data, field, count * copies)
    path.write_bytes(bytes(data) + infos * (copies - 1))
    return path
