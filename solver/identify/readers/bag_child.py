"""The child process that reads the topics of one bag, behind resource limits.

:func:`solver.identify.readers.bags.read_bag_topics` runs this file as a script in a fresh
interpreter (:mod:`solver.identify.limited`), with the folders of ``rosbags`` and its
dependencies as arguments and one JSON request on stdin. It imports nothing from the package,
so it starts in the time ``rosbags`` takes to import. It

* lowers its own limits first: address space, CPU seconds, the size of any file it writes
  (temporary files go to the private folder the parent watches), open files, no core file;
* reads only each format's index, never a message, so time and memory follow the number of
  topics, not of messages:

  - a ROS 1 ``.bag``: the connection records at the bag's index position, through rosbags'
    own record reader (``rosbags.rosbag1.reader.Header``, ``Reader.read_connection``); the
    per-message index that ``Reader.open`` builds (150 bytes and 7 µs per message) is skipped;
  - a ROS 2 ``.db3``: the ``topics`` table, read-only and immutable, after checking that
    ``topics`` and ``messages`` are plain tables (a view or virtual table runs the bag's own
    SQL), with SQLite's temporary storage in memory and its heap capped;
  - a ROS 2 ``.mcap``: rosbags' MCAP reader, its summary when there is one; where it scans the
    chunks instead, each is decompressed into at most the size it declares, at most
    ``chunk_bytes`` each and ``bag_bytes`` in all (and so is each chunk of a ROS 1 bag whose
    messages are read: at most ``chunk_bytes``, every read counted in ``bag_bytes``);
  - a bag folder: each storage file in it as above, or rosbags' ``AnyReader`` where it holds
    none (a file-compressed bag, decompressed into the private temporary folder);

* with ``"rates": true`` in the request, reads every message instead, one at a time, and
  answers each topic's bytes and first and last timestamps (``layouts --rates-bag``);
* answers with one JSON object on stdout: ``{"ok": true, "pairs": [[topic, type], ...]}``, or
  ``{"ok": false, "kind": ..., "message": ...}`` (``kind``: ``reader`` for what the bag
  library refused, ``limit`` for a bound, ``error`` for anything its parsers tripped over).

Not here: starting it, the wall-clock and temporary-space bounds, the messages
(:mod:`solver.identify.readers.bags`).
"""

from __future__ import annotations

import errno
import json
import resource
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["Refused", "main"]

_ROS2_STORAGE = (".db3", ".mcap")
_OPEN_FILES = 256
# SQLite's own allocations (pages, sorts, temporary tables) stop here, below the address space.
_SQLITE_HEAP = 128 * 2**20


class Refused(Exception):
    """A bound this child keeps (decompressed bytes, a view in a bag database)."""

    def __init__(self, message: str, kind: str = "limit") -> None:
        super().__init__(message)
        self.kind = kind


def main() -> None:
    sys.path[:0] = sys.argv[1:]
    request: dict[str, Any] = json.loads(sys.stdin.read(1 << 20))
    _limit(request)
    sys.stdout.write(json.dumps(_answer(request)))
    sys.stdout.flush()


def _answer(request: dict[str, Any]) -> dict[str, Any]:
    try:
        if request.get("rates"):
            return {"ok": True, "rates": _rates(Path(request["path"]), request)}
        return {"ok": True, "pairs": _pairs(Path(request["path"]), request)}
    except Refused as refused:
        return {"ok": False, "kind": refused.kind, "message": str(refused)}
    except MemoryError:
        memory = request["memory_bytes"] // 2**20
        return {"ok": False, "kind": "limit", "message": f"needs more than {memory} MiB"}
    except RecursionError:
        return {"ok": False, "kind": "error", "message": "nested too deeply"}
    except Exception as error:
        if isinstance(error, OSError) and error.errno == errno.EFBIG:
            temp = request["temp_bytes"]
            message = f"needs more than {temp} bytes of temporary space"
            return {"ok": False, "kind": "limit", "message": message}
        kind = "reader" if type(error).__name__.endswith("ReaderError") else "error"
        return {"ok": False, "kind": kind, "type": type(error).__name__, "message": str(error)}


def _limit(request: dict[str, Any]) -> None:
    memory, cpu, temp = request["memory_bytes"], request["cpu_seconds"], request["temp_bytes"]
    resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
    resource.setrlimit(resource.RLIMIT_FSIZE, (temp, temp))
    resource.setrlimit(resource.RLIMIT_NOFILE, (_OPEN_FILES, _OPEN_FILES))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def _pairs(bag: Path, request: dict[str, Any]) -> list[tuple[str, str]]:
    """(topic, type) pairs from the reader for this kind of bag, in connection order."""
    _cap_decompression(request["chunk_bytes"], request["bag_bytes"])
    if bag.is_file() and bag.suffix == ".bag":
        return _ros1(bag)
    if bag.is_file() and bag.suffix in _ROS2_STORAGE:
        return _storage(bag)
    storage = sorted(p for p in bag.iterdir() if p.suffix in _ROS2_STORAGE) if bag.is_dir() else []
    for file in storage:
        if not file.is_file():  # a FIFO would wait for a writer until the wall clock ends it
            raise Refused(f"{file.name}: not a regular file", kind="reader")
    if storage:
        return [pair for file in storage for pair in _storage(file)]
    from rosbags.highlevel import AnyReader

    with AnyReader([bag]) as reader:
        return [(c.topic, c.msgtype) for c in reader.connections]


def _rates(bag: Path, request: dict[str, Any]) -> list[tuple[str, int, int, int]]:
    """(topic, bytes, first, last timestamp in ns) of every topic, its messages read one at a
    time (rosbags' readers stream them; a ROS 1 bag's per-message index is held, 150 bytes a
    message)."""
    _cap_decompression(request["chunk_bytes"], request["bag_bytes"])
    if bag.is_file() and bag.suffix == ".bag":
        from rosbags.rosbag1 import Reader as Reader1

        opened: Any = Reader1(bag)
    else:
        from rosbags.rosbag2 import Reader as Reader2

        opened = Reader2(bag)
    seen: dict[str, list[int]] = {}
    with opened as reader:
        for connection, timestamp, data in reader.messages():
            found = seen.setdefault(connection.topic, [0, timestamp, timestamp])
            found[0] += len(data)
            found[1], found[2] = min(found[1], timestamp), max(found[2], timestamp)
    return [(topic, total, first, last) for topic, (total, first, last) in seen.items()]


def _storage(file: Path) -> list[tuple[str, str]]:
    if file.suffix == ".db3":
        return _db3(file)
    from rosbags.rosbag2 import Reader

    with Reader(file) as reader:
        return [(c.topic, c.msgtype) for c in reader.connections]


def _ros1(path: Path) -> list[tuple[str, str]]:
    """The connection records of a ROS 1 bag (version 2.0), as ``Reader.open`` reads them."""
    from rosbags.rosbag1 import Reader, ReaderError
    from rosbags.rosbag1.reader import Header, RecordType

    with path.open("rb") as bio:
        if bio.readline(64) != b"#ROSBAG V2.0\n":
            raise ReaderError("File magic is invalid (not a ROS 1 bag of version 2.0).")
        header = Header.read(bio, RecordType.BAGHEADER)
        index_pos = header.get_uint64("index_pos")
        conn_count = header.get_uint32("conn_count")
        encryptor = header.get_string("encryptor") if "encryptor" in header else ""
        if encryptor:
            raise ReaderError(f"Bag encryption {encryptor!r} is not supported.")
        if index_pos == 0:
            raise ReaderError("Bag is not indexed, reindex before reading.")
        bio.seek(index_pos)
        reader = Reader(path)
        reader.bio = bio
        return [(c.topic, c.msgtype) for c in (reader.read_connection() for _ in range(conn_count))]


def _db3(path: Path) -> list[tuple[str, str]]:
    """The ``topics`` table of a ROS 2 SQLite bag, without running any SQL the bag defines."""
    import sqlite3

    from rosbags.rosbag2 import ReaderError

    uri = f"{path.resolve().as_uri()}?mode=ro&immutable=1"
    try:
        connection = sqlite3.connect(uri, uri=True)
    except sqlite3.Error as error:
        raise ReaderError(f"Cannot open database {path}: {error}") from None
    try:
        connection.execute("PRAGMA temp_store = MEMORY")
        connection.execute(f"PRAGMA hard_heap_limit = {_SQLITE_HEAP}")
        tables = {
            name: (kind, str(sql or ""))
            for name, kind, sql in connection.execute(
                "SELECT name, type, sql FROM sqlite_master WHERE name IN ('topics', 'messages')"
            )
        }
        for name in ("topics", "messages"):
            kind, sql = tables.get(name, ("missing", ""))
            if sql.upper().startswith("CREATE VIRTUAL"):
                kind = "a virtual table"
            if kind != "table":
                raise Refused(
                    f"not a ROS 2 bag database: its {name!r} is {kind}, not a table "
                    "(a view or virtual table would run the bag's own SQL)",
                    kind="reader",
                )
        rows = connection.execute("SELECT name, type FROM topics ORDER BY id")
        return [(str(name), str(kind)) for name, kind in rows]
    except sqlite3.Error as error:
        raise ReaderError(f"Cannot read database {path}: {error}") from None
    finally:
        connection.close()


def _cap_decompression(chunk_bytes: int, bag_bytes: int) -> None:
    """Decompress each MCAP chunk into at most the size it declares, and each ROS 1 chunk
    (which declares none rosbags reads) into at most ``chunk_bytes``, every chunk read
    counted against ``bag_bytes`` (a ROS 1 chunk read again, its messages interleaved in time
    with another chunk's, counted again)."""
    import bz2

    from lz4.frame import LZ4FrameDecompressor  # type: ignore[import-untyped]  # no stubs
    from rosbags.rosbag1 import reader as ros1
    from rosbags.rosbag2 import storage_mcap

    if sys.version_info >= (3, 14):
        from compression import zstd
    else:
        from backports import zstd
    spent = [0]

    def capped(make: Callable[[], Any]) -> Callable[[bytes, int], bytes]:
        def decompress(data: bytes, size: int) -> bytes:
            if size > chunk_bytes:
                raise Refused(
                    f"a chunk declares {size} bytes decompressed; at most {chunk_bytes} are read"
                )
            spent[0] += size
            if spent[0] > bag_bytes:
                raise Refused(f"its chunks decompress to more than {bag_bytes} bytes in all")
            return _frames(make, data, size)

        return decompress

    def counted(size: int) -> None:
        spent[0] += size
        if spent[0] > bag_bytes:
            raise Refused(f"its chunks decompress to more than {bag_bytes} bytes in all")

    def ros1_capped(make: Callable[[], Any] | None) -> Callable[[bytes], bytes]:
        def decompress(data: bytes) -> bytes:
            found = data if make is None else _frames(make, data, chunk_bytes)
            if len(found) > chunk_bytes:
                raise Refused(f"a chunk decompresses to more than {chunk_bytes} bytes")
            counted(len(found))
            return found

        return decompress

    storage_mcap.DECOMPRESSORS["zstd"] = capped(zstd.ZstdDecompressor)
    storage_mcap.DECOMPRESSORS["lz4"] = capped(LZ4FrameDecompressor)
    ros1.decompressors["bz2"] = ros1_capped(bz2.BZ2Decompressor)
    ros1.decompressors["lz4"] = ros1_capped(LZ4FrameDecompressor)
    ros1.decompressors["none"] = ros1_capped(None)


def _frames(make: Callable[[], Any], data: bytes, size: int) -> bytes:
    """The frames in ``data``, decompressed to at most ``size + 1`` bytes in all."""
    parts: list[bytes] = []
    total = 0
    rest = data
    while rest and total <= size:
        decompressor = make()
        part: bytes = decompressor.decompress(rest, max_length=size + 1 - total)
        parts.append(part)
        total += len(part)
        if not decompressor.eof:
            break  # past the declared size, or the stream ends early: rosbags says which
        rest = decompressor.unused_data
    return b"".join(parts)


if __name__ == "__main__":
    main()
