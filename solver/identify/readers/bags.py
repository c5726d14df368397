"""Topics and message types recorded in a bag, read with ``rosbags`` (no ROS needed), bounded.

ROS 1 ``.bag`` files, ROS 2 bag folders and their ``.db3`` / ``.mcap`` files are read from
their index only (topic, message type), never their messages, in time linear in their topics.
Every topic is returned with an unknown direction: a bag records what was published, not who
subscribed.

A bag comes from a stranger, and the bag library cannot bound what it does with one: a ROS 2
database can define its tables as views that run forever and spill into the temporary folder,
a ROS 1 bag can repeat its index records until reading it takes gigabytes, an MCAP chunk can
declare a gigabyte inside a few kilobytes. So every bag is read in a child process
(:mod:`solver.identify.readers.bag_child`, started by :mod:`solver.identify.limited`) within
:class:`BagLimits`: CPU time and memory (the child's own resource limits), wall-clock time and
temporary space (watched from here: the child's temporary folder is private, and removed
afterwards), decompressed bytes per chunk and per bag (counted by the child). Past any of them
the bag is refused with an error naming it and the bound; so is a bag the library cannot read.

Not here: what the topics mean (:mod:`solver.identify.interfaces`).
"""

from __future__ import annotations

import os
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from solver.errors import InputError
from solver.extras import require
from solver.identify.limited import Finished, run_limited
from solver.ros.names import Topic, normalise_type
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = ["RATE_LIMITS", "BagLimits", "read_bag_rates", "read_bag_topics"]

_MIB = 2**20


@dataclass(frozen=True, slots=True)
class BagLimits:
    """What reading one bag may use; past any of them the bag is refused, naming the bound.

    A real bag's index reads in well under a second and a few tens of MB whatever its size,
    since no message is read: these bounds stop only hostile or broken bags.
    """

    cpu_seconds: int = 10
    wall_seconds: float = 20.0
    memory_bytes: int = 512 * _MIB  # address space of the reading process
    temp_bytes: int = 256 * _MIB  # its private temporary folder, and any one file it writes
    chunk_bytes: int = 64 * _MIB  # one compressed chunk, decompressed
    bag_bytes: int = 512 * _MIB  # every chunk of the bag, decompressed
    answer_bytes: int = 64 * _MIB  # the topic list it hands back


def read_bag_topics(
    path: str | Path, *, display: str | None = None, limits: BagLimits = BagLimits()
) -> tuple[Topic, ...]:
    """The (topic, type) pairs a bag recorded, in the bag's connection order, without repeats."""
    require("rosbags", feature="reading bag files (identify --bag)")
    name = shown(display if display is not None else str(path), limit=SHOWN_FILE_NAME_CHARS)
    pairs = _read_in_child(_checked(Path(path), name), name, limits)
    topics = dict.fromkeys(Topic(topic, normalise_type(kind)) for topic, kind in pairs)
    return tuple(topics)


# Reading every message of a bag takes time linear in its bytes and messages (a 1 GB bag of
# images: under a second from the page cache, seconds from disk, docs/security.md); its
# memory stays that of one chunk or message (and a ROS 1 bag's index), whatever its size. A
# stranger's bag ends within seconds: 30 s of CPU, 40 s in all, and 4 GiB decompressed (a
# 1 GB bag compressed 4:1; every chunk at most 64 MiB, each read counted, so chunks read
# again and again cannot spin), past which the bag is refused, naming the bound.
RATE_LIMITS = BagLimits(cpu_seconds=30, wall_seconds=40.0, bag_bytes=4 * 2**30)


def read_bag_rates(
    path: str | Path, *, display: str | None = None, limits: BagLimits = RATE_LIMITS
) -> dict[str, float]:
    """Bytes per second of each topic a bag recorded (its bytes over the bag's span, as
    ``ros2 topic bw`` over the recording), every message read once, streaming."""
    require("rosbags", feature="reading bag files (layouts --rates-bag)")
    name = shown(display if display is not None else str(path), limit=SHOWN_FILE_NAME_CHARS)
    bag = _checked(Path(path), name)
    answer = _read_in_child(bag, name, limits, rates=True)
    rows = [(str(t), int(n), int(a), int(b)) for t, n, a, b in answer]
    if not rows:
        return {}
    span = (max(row[3] for row in rows) - min(row[2] for row in rows)) / 1e9
    seconds = span if span > 0 else 1.0
    return {topic: round(total / seconds, 3) for topic, total, _, _ in sorted(rows)}


def _checked(bag: Path, name: str) -> Path:
    """``bag`` resolved, or a located error for a name that is no bag file or folder."""
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
    except OSError as error:  # a name past the file system's limits
        raise InputError.at(
            name, f"not a usable file name ({error.strerror})", code="bag"
        ) from None
    return bag.resolve()


def _read_in_child(bag: Path, name: str, limits: BagLimits, *, rates: bool = False) -> list[Any]:
    """The child's answer: (topic, type) pairs, or with ``rates`` its rows of four."""
    temporary = Path(tempfile.mkdtemp(prefix="teleop-ui-bag-"))
    try:
        finished = run_limited(
            [str(Path(__file__).with_name("bag_child.py")), *_library_paths()],
            {
                "path": str(bag),
                "cpu_seconds": limits.cpu_seconds,
                "memory_bytes": limits.memory_bytes,
                "temp_bytes": limits.temp_bytes,
                "chunk_bytes": limits.chunk_bytes,
                "bag_bytes": limits.bag_bytes,
                "rates": rates,
            },
            wall_seconds=limits.wall_seconds,
            answer_bytes=limits.answer_bytes,
            env={"TMPDIR": str(temporary), "SQLITE_TMPDIR": str(temporary)},
            cwd=str(temporary),
            watch=lambda: "temp" if _size(temporary) > limits.temp_bytes else None,
        )
    finally:
        shutil.rmtree(temporary, ignore_errors=True)
    answer = finished.answer
    if answer is None or finished.returncode != 0:
        raise InputError.at(name, _why_stopped(finished, limits), code="bag-limit")
    if answer.get("ok"):
        pairs = answer.get("rates" if rates else "pairs")
        if isinstance(pairs, list):
            if rates:
                return pairs
            return [(str(topic), str(kind)) for topic, kind in pairs]
    message = shown(str(answer.get("message") or "no reason given"), limit=200)
    kind = answer.get("kind")
    if kind == "limit":
        raise InputError.at(name, f"bag refused: {message}", code="bag-limit")
    if kind == "reader":
        raise InputError.at(name, f"cannot read as a ROS 1 or ROS 2 bag: {message}", code="bag")
    # rosbags parses files strangers recorded; a corrupt or truncated one ends in whatever its
    # parser trips over (TypeError, struct.error, UnicodeDecodeError...): this bag's problem.
    raise InputError.at(
        name,
        f"cannot read bag (corrupt or truncated?): {shown(answer.get('type'))}: {message}",
        code="bag",
    )


def _why_stopped(finished: Finished, limits: BagLimits) -> str:
    if finished.stopped == "temp":
        return (
            f"bag refused: reading it needed more than {limits.temp_bytes} bytes of temporary space"
        )
    if finished.stopped == "time":
        return f"bag refused: reading it took more than {limits.wall_seconds:g} s"
    if finished.oversized:
        return f"bag refused: its topic list is larger than {limits.answer_bytes} bytes"
    reason = {
        24: f"reading it used more than {limits.cpu_seconds} s of CPU",
        9: f"reading it used more than {limits.cpu_seconds} s of CPU or "
        f"{limits.memory_bytes // _MIB} MiB of memory",
        25: f"reading it wrote a file larger than {limits.temp_bytes} bytes",
    }.get(finished.signal or 0)
    if reason is not None:
        return f"bag refused: {reason}"
    return f"the bag reader ended without an answer (exit status {finished.returncode})"


def _library_paths() -> list[str]:
    """Where the child finds rosbags and its dependencies: this interpreter's import folders
    (``-S`` leaves ``.pth`` files unread, so they are passed as they are here)."""
    return [p for p in sys.path if p and os.path.isdir(p)]


def _size(folder: Path) -> int:
    """Bytes in the files under ``folder`` (the child's temporary folder)."""
    total = 0
    for root, _, files in os.walk(folder):
        for file in files:
            try:
                total += os.lstat(os.path.join(root, file)).st_size
            except OSError:
                continue  # removed meanwhile
    return total
