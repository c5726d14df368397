"""Topics and message types recorded in a bag, read with the ``rosbags`` library (no ROS needed).

ROS 1 ``.bag`` files, ROS 2 bag folders and their ``.db3`` / ``.mcap`` files are read with
``rosbags``, each with its format's own reader (see :func:`_connections`). Only the connection
metadata is used (topic, message type), never the messages, so a large bag costs no more than
its index, in time linear in its topics. Every topic is returned with an unknown direction: a
bag records what was published, not who subscribed.

Not here: what the topics mean (:mod:`solver.identify.interfaces`).
"""

from __future__ import annotations

from pathlib import Path

from solver.errors import InputError
from solver.extras import require
from solver.ros.names import Topic, normalise_type
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = ["read_bag_topics"]


def _short(error: BaseException, limit: int = 120) -> str:
    """A parser's message, escaped and cut: it may quote bytes of the bag."""
    text = str(error).encode("unicode_escape", "backslashreplace").decode("ascii")
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _connections(bag: Path) -> list[tuple[str, str]]:
    """(topic, type) pairs from the reader for this kind of bag, in connection order.

    Not :class:`rosbags.highlevel.AnyReader` where a format's own reader serves: AnyReader
    parses every connection's message definition (8,000 topics: a second), and a ROS 2 bag
    folder's ``metadata.yaml`` is read with a pure-Python YAML parser (20,000 topics: half a
    minute). A storage file's own index holds the same pairs and reads in linear time.
    """
    from rosbags.highlevel import AnyReader
    from rosbags.rosbag1 import Reader as Reader1
    from rosbags.rosbag2 import Reader as Reader2

    if bag.is_file() and bag.suffix == ".bag":
        with Reader1(bag) as reader:
            return [(c.topic, c.msgtype) for c in reader.connections]
    storage = (
        [bag]
        if bag.is_file() and bag.suffix in _ROS2_STORAGE
        else sorted(p for p in bag.iterdir() if p.suffix in _ROS2_STORAGE)
        if bag.is_dir()
        else []
    )
    if storage:
        pairs = []
        for file in storage:
            with Reader2(file) as reader:
                pairs += [(c.topic, c.msgtype) for c in reader.connections]
        return pairs
    with AnyReader([bag]) as any_reader:
        return [(c.topic, c.msgtype) for c in any_reader.connections]


_ROS2_STORAGE = (".db3", ".mcap")


def read_bag_topics(path: str | Path, *, display: str | None = None) -> tuple[Topic, ...]:
    """The (topic, type) pairs a bag recorded, in the bag's connection order, without repeats."""
    require("rosbags", feature="reading bag files (identify --bag)")
    from rosbags.highlevel import AnyReaderError
    from rosbags.rosbag1 import ReaderError as Reader1Error
    from rosbags.rosbag2 import ReaderError as Reader2Error

    name = shown(display if display is not None else str(path), limit=SHOWN_FILE_NAME_CHARS)
    bag = Path(path)
    try:
        if not bag.exists():
            raise InputError.at(name, "no such bag file or folder", code="bag")
        if not (bag.is_file() or bag.is_dir()):
            # A FIFO would wait for a writer forever, /dev/zero would be read forever.
            raise InputError.at(name, "not a bag file or folder (a device or pipe?)", code="bag")
    except InputError:
        raise
    except ValueError:  # a NUL byte in the name
        raise InputError.at(name, "not a usable file name", code="bag") from None
    try:
        pairs = _connections(bag)
    except (AnyReaderError, Reader1Error, Reader2Error) as error:
        raise InputError.at(
            name, f"cannot read as a ROS 1 or ROS 2 bag: {_short(error)}", code="bag"
        ) from None
    except RecursionError:
        raise InputError.at(name, "cannot read bag: nested too deeply", code="bag") from None
    except Exception as error:
        # rosbags parses files strangers recorded; a corrupt or truncated one (an MCAP holding
        # only its magic bytes) ends in whatever its parser trips over (TypeError, struct.error,
        # UnicodeDecodeError...). Each is this bag's problem, said with its name, never a
        # traceback.
        raise InputError.at(
            name,
            f"cannot read bag (corrupt or truncated?): {type(error).__name__}: {_short(error)}",
            code="bag",
        ) from None
    topics = dict.fromkeys(Topic(topic, normalise_type(kind)) for topic, kind in pairs)
    return tuple(topics)
