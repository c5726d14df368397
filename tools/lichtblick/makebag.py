"""A small ROS 2 bag (MCAP storage) with one robot's topics, to drive Lichtblick with.

usage: python makebag.py OUT_DIR NAMESPACE [--scan] [--tiles N]

Five seconds at 10 Hz of what the presentation profile's panels show, under NAMESPACE
(``/robot1``): camera and 360 camera images, point clouds, wrenches and audio bytes (tiles
``_2`` .. ``_5`` of each too), and ``/tf`` (map -> base_link -> camera) so that 3D panels
have frames; ``--scan`` adds ``NAMESPACE/scan`` (``sensor_msgs/msg/LaserScan``); ``--tiles N``
writes ``_2`` .. ``_N`` instead of 5 (10 for a configuration of 6..10 sensors in clusters of 2).
Written with rosbags.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import numpy as np
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

STORE = get_typestore(Stores.ROS2_JAZZY)
STORE.register(get_types_from_msg("uint8[] data", "audio_common_msgs/msg/AudioData"))
T = STORE.types
TILES = 5


def header(stamp: int, frame: str = "base_link") -> Any:
    time = T["builtin_interfaces/msg/Time"](sec=stamp // 10**9, nanosec=stamp % 10**9)
    return T["std_msgs/msg/Header"](stamp=time, frame_id=frame)


def image(stamp: int, shift: int) -> Any:
    width, height = 160, 120
    x = np.arange(width, dtype=np.uint16)[None, :].repeat(height, 0)
    y = np.arange(height, dtype=np.uint16)[:, None].repeat(width, 1)
    red = (x * 255 // width + shift) % 256
    rgb = np.stack([red, y * 255 // height, np.full((height, width), 128)], -1)
    return T["sensor_msgs/msg/Image"](
        header=header(stamp, "camera"),
        height=height,
        width=width,
        encoding="rgb8",
        is_bigendian=0,
        step=width * 3,
        data=rgb.astype(np.uint8).reshape(-1),
    )


def cloud(stamp: int, k: int) -> Any:
    angles = np.linspace(0, 2 * math.pi, 400, endpoint=False)
    radius = 3 + np.sin(6 * angles + k / 5)
    xyz = np.stack([radius * np.cos(angles), radius * np.sin(angles), 0.2 * np.sin(3 * angles)])
    points = xyz.T.astype(np.float32)
    field = T["sensor_msgs/msg/PointField"]
    fields = [field(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    return T["sensor_msgs/msg/PointCloud2"](
        header=header(stamp),
        height=1,
        width=len(points),
        fields=fields,
        is_bigendian=False,
        point_step=12,
        row_step=12 * len(points),
        data=np.frombuffer(points.tobytes(), np.uint8),
        is_dense=True,
    )


def scan(stamp: int, k: int) -> Any:
    count = 180
    ranges = 3 + np.sin(6 * np.arange(count) / count * math.pi + k / 5)
    return T["sensor_msgs/msg/LaserScan"](
        header=header(stamp),
        angle_min=-math.pi / 2,
        angle_max=math.pi / 2,
        angle_increment=math.pi / count,
        time_increment=0.0,
        scan_time=0.1,
        range_min=0.1,
        range_max=10.0,
        ranges=ranges.astype(np.float32),
        intensities=np.zeros(count, dtype=np.float32),
    )


def wrench(stamp: int, k: int) -> Any:
    vector = T["geometry_msgs/msg/Vector3"]
    force = vector(x=math.sin(k / 5), y=math.cos(k / 5), z=0.5)
    body = T["geometry_msgs/msg/Wrench"](force=force, torque=vector(x=0.0, y=0.0, z=0.1))
    return T["geometry_msgs/msg/WrenchStamped"](header=header(stamp), wrench=body)


def transforms(stamp: int) -> Any:
    vector, quaternion = T["geometry_msgs/msg/Vector3"], T["geometry_msgs/msg/Quaternion"]

    def link(parent: str, child: str, x: float) -> Any:
        pose = T["geometry_msgs/msg/Transform"](
            translation=vector(x=x, y=0.0, z=0.0),
            rotation=quaternion(x=0.0, y=0.0, z=0.0, w=1.0),
        )
        return T["geometry_msgs/msg/TransformStamped"](
            header=header(stamp, parent), child_frame_id=child, transform=pose
        )

    links = [link("map", "base_link", 0.0), link("base_link", "camera", 0.2)]
    return T["tf2_msgs/msg/TFMessage"](transforms=links)


def main() -> None:
    out, namespace = Path(sys.argv[1]), sys.argv[2].rstrip("/")
    tiles = int(sys.argv[sys.argv.index("--tiles") + 1]) if "--tiles" in sys.argv else TILES
    audio = T["audio_common_msgs/msg/AudioData"](data=np.arange(32, dtype=np.uint8))
    with Writer(out, version=9, storage_plugin=StoragePlugin.MCAP) as writer:
        connections: dict[str, Any] = {}

        def put(topic: str, kind: str, message: Any, stamp: int) -> None:
            if topic not in connections:
                connections[topic] = writer.add_connection(topic, kind, typestore=STORE)
            writer.write(connections[topic], stamp, STORE.serialize_cdr(message, kind))

        start = 1_700_000_000 * 10**9
        for k in range(50):
            stamp = start + k * 100_000_000
            put("/tf", "tf2_msgs/msg/TFMessage", transforms(stamp), stamp)
            for tile in range(tiles):
                end = "" if tile == 0 else f"_{tile + 1}"
                kind = "sensor_msgs/msg/Image"
                put(
                    f"{namespace}/camera/image_raw{end}",
                    kind,
                    image(stamp, 5 * k + 40 * tile),
                    stamp,
                )
                put(f"{namespace}/camera360/image_raw{end}", kind, image(stamp, 128 + 5 * k), stamp)
                put(
                    f"{namespace}/points{end}",
                    "sensor_msgs/msg/PointCloud2",
                    cloud(stamp, k + 7 * tile),
                    stamp,
                )
                put(
                    f"{namespace}/wrench{end}",
                    "geometry_msgs/msg/WrenchStamped",
                    wrench(stamp, k + 7 * tile),
                    stamp,
                )
                put(f"{namespace}/audio{end}", "audio_common_msgs/msg/AudioData", audio, stamp)
            if "--scan" in sys.argv:
                put(f"{namespace}/scan", "sensor_msgs/msg/LaserScan", scan(stamp, k), stamp)
    print(out)


if __name__ == "__main__":
    main()
