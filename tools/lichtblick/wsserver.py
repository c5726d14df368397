"""A Foxglove WebSocket server that plays a ROS 2 bag in a loop, as a live robot would, and
records, decoded, every message the operator's panels publish (JSON lines).

usage: python wsserver.py BAG_DIR PORT RECORD.jsonl

It announces itself as a ROS 2 (jazzy) source that accepts client publishing in CDR, as
foxglove_bridge does, so Lichtblick's Teleop, Publish and 3D click tools publish to it; each
advertisement and each message (decoded by rosbags, or its bytes when it does not decode)
becomes one line of RECORD.jsonl.
"""

from __future__ import annotations

import asyncio
import json
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
from foxglove_websocket.server import FoxgloveServer, FoxgloveServerListener
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

STORE = get_typestore(Stores.ROS2_JAZZY)
STORE.register(get_types_from_msg("uint8[] data", "audio_common_msgs/msg/AudioData"))


def plain(value: Any) -> Any:
    """A decoded message as JSON data."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if hasattr(value, "__dataclass_fields__"):
        return {
            k: plain(getattr(value, k)) for k in value.__dataclass_fields__ if k != "__msgtype__"
        }
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    return value


def ros2_name(name: str) -> str:
    """``geometry_msgs/Twist`` (as Lichtblick advertises it) -> ``geometry_msgs/msg/Twist``."""
    parts = name.split("/")
    return f"{parts[0]}/msg/{parts[1]}" if len(parts) == 2 else name


class Recorder(FoxgloveServerListener):
    def __init__(self, record: Path) -> None:
        self.out = record.open("a", encoding="utf-8")
        self.channels: dict[int, Any] = {}

    def line(self, **item: Any) -> None:
        self.out.write(json.dumps({"t": time.time(), **item}) + "\n")
        self.out.flush()

    async def on_client_advertise(self, server: FoxgloveServer, channel: Any) -> None:
        del server
        self.channels[channel["id"]] = channel
        self.line(op="advertise", topic=channel["topic"], schemaName=channel["schemaName"])

    async def on_client_unadvertise(self, server: FoxgloveServer, channel_id: Any) -> None:
        del server
        self.line(op="unadvertise", topic=self.channels.get(channel_id, {}).get("topic"))

    async def on_client_message(
        self, server: FoxgloveServer, channel_id: Any, payload: bytes
    ) -> None:
        del server
        channel = self.channels[channel_id]
        try:
            message = plain(STORE.deserialize_cdr(bytes(payload), ros2_name(channel["schemaName"])))
        except Exception as error:  # recorded, not hidden: the app sent bytes that do not decode
            message = {"undecodable": repr(error), "hex": bytes(payload).hex()}
        self.line(
            op="message", topic=channel["topic"], schemaName=channel["schemaName"], msg=message
        )


async def serve(bag: Path, port: int, record: Path) -> None:
    with Reader(bag) as reader:
        messages = [(c.id, t, bytes(d)) for c, t, d in reader.messages()]
        connections = list(reader.connections)
    async with FoxgloveServer(
        "127.0.0.1",
        port,
        "teleop-ui check",
        capabilities=["clientPublish"],
        supported_encodings=["cdr"],
        metadata={"ROS_DISTRO": "jazzy"},
    ) as server:
        server.set_listener(Recorder(record))
        ids = {}
        for c in connections:
            channel = {
                "topic": c.topic,
                "encoding": "cdr",
                "schemaName": c.msgtype,
                "schema": c.msgdef.data,
                "schemaEncoding": "ros2msg",
            }
            ids[c.id] = await server.add_channel(channel)
        first = messages[0][1]
        while True:
            base = time.time_ns()
            for connection, stamp, data in messages:
                delay = (base + stamp - first - time.time_ns()) / 1e9
                if delay > 0:
                    await asyncio.sleep(delay)
                await server.send_message(ids[connection], time.time_ns(), data)


if __name__ == "__main__":
    asyncio.run(serve(Path(sys.argv[1]), int(sys.argv[2]), Path(sys.argv[3])))
