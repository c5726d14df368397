"""Topics and message types recorded in a bag, read with the ``rosbags`` library (no ROS needed).

ROS 1 ``.bag`` files, ROS 2 bag folders and their ``.db3`` / ``.mcap`` files are all read
through :class:`rosbags.highlevel.AnyReader`; only the connection metadata is used (topic,
message type), never the messages, so a large bag costs no more than its index. Every topic is
returned with an unknown direction: a bag records what was published, not who subscribed.

Not here: what the topics mean (:mod:`solver.identify.interfaces`).
"""

from __future__ import annotations

from pathlib import Path

from solver.errors import InputError
from solver.identify.topics import Topic, normalise_type

__all__ = ["read_bag_topics"]


def read_bag_topics(path: str | Path, *, display: str | None = None) -> tuple[Topic, ...]:
    """The (topic, type) pairs a bag recorded, in the bag's connection order, without repeats."""
    from rosbags.highlevel import AnyReader, AnyReaderError

    name = display if display is not None else str(path)
    bag = Path(path)
    if not bag.exists():
        raise InputError.at(name, "no such bag file or folder", code="bag")
    try:
        with AnyReader([bag]) as reader:
            pairs = [(c.topic, c.msgtype) for c in reader.connections]
    except AnyReaderError as error:
        raise InputError.at(name, f"cannot read as a ROS 1 or ROS 2 bag: {error}",
                            code="bag") from None
    except (OSError, ValueError, KeyError) as error:
        raise InputError.at(name, f"cannot read bag: {error}", code="bag") from None
    topics = dict.fromkeys(Topic(topic, normalise_type(kind)) for topic, kind in pairs)
    return tuple(topics)
