"""Reading the topics of bags with many topics: time grows with the topics, not faster.

Bags are recorded by robots and passed around; their index is what ``identify --bag`` reads.
Bags of 2,500 and 10,000 topics are written with rosbags in each format: a ROS 1 ``.bag``, a
ROS 2 bag folder (``metadata.yaml`` beside its ``.db3``) and the ``.db3`` alone. Before the
change of issue 19, 20,000 topics took 16 s (ROS 1) and 33 s (ROS 2 .db3). Writing them takes
rosbags about a minute on a loaded machine, so they are written once and kept under
``build/test-data`` (:func:`tests.data.cached`), for every later run. Each round asserts the
number of topics it read. ``test_growth_ratio`` reports the time at 4x the topics over the time
at 1x (about 4 when linear, 16 when quadratic), measured in the same run, and asserts only the
counts it timed.

Run: ``pytest benchmarks/bench_bags.py --benchmark-only``.
"""

from __future__ import annotations

import time
from importlib.metadata import version
from pathlib import Path

import pytest
from pytest_benchmark.fixture import BenchmarkFixture
from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_typestore

from solver.identify.readers.bags import read_bag_topics
from tests.data import cached

SIZES = (2_500, 10_000)
STORE = get_typestore(Stores.ROS2_HUMBLE)


def ros1(folder: Path, topics: int) -> Path:
    path = folder / f"ros1-{topics}.bag"
    with Writer1(path) as writer:
        for i in range(topics):
            writer.add_connection(f"/robot/t{i}", "std_msgs/msg/String", typestore=STORE)
    return path


def ros2_folder(folder: Path, topics: int) -> Path:
    path = folder / f"ros2-{topics}"
    with Writer2(path, version=8, storage_plugin=StoragePlugin.SQLITE3) as writer:
        for i in range(topics):
            writer.add_connection(f"/robot/t{i}", "std_msgs/msg/String", typestore=STORE)
    return path


FORMATS = ("ROS 1 .bag", "ROS 2 folder", "ROS 2 .db3")


def write_bags(folder: Path) -> None:
    for topics in SIZES:
        ros1(folder, topics)
        ros2_folder(folder, topics)


@pytest.fixture(scope="module")
def bags() -> dict[tuple[str, int], Path]:
    """Every format at every size, written once and cached (see the module docstring); the
    ``.db3`` is the one in the ROS 2 folder, read alone."""
    folder = cached(f"bags-{'-'.join(map(str, SIZES))}-rosbags-{version('rosbags')}", write_bags)
    found = {}
    for topics in SIZES:
        found["ROS 1 .bag", topics] = folder / f"ros1-{topics}.bag"
        found["ROS 2 folder", topics] = folder / f"ros2-{topics}"
        found["ROS 2 .db3", topics] = next(found["ROS 2 folder", topics].glob("*.db3"))
    return found


@pytest.mark.parametrize("topics", SIZES, ids=[f"{n} topics" for n in SIZES])
@pytest.mark.parametrize("kind", list(FORMATS), ids=list(FORMATS))
def test_reading_the_topics_of_a_big_bag(
    benchmark: BenchmarkFixture, bags: dict[tuple[str, int], Path], kind: str, topics: int
) -> None:
    benchmark.group = f"bag topics: {kind}"
    found = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pedantic is unannotated
        read_bag_topics, args=(bags[kind, topics],), rounds=1, iterations=1
    )
    assert len(found) == topics
    assert found[-1].name == f"/robot/t{topics - 1}"


def test_growth_ratio(
    bags: dict[tuple[str, int], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    """Time at 4x the topics over time at 1x, for each format, measured in this run."""
    lines = []
    for kind in FORMATS:
        seconds = []
        for topics in SIZES:
            start = time.perf_counter()
            found = read_bag_topics(bags[kind, topics])
            seconds.append(time.perf_counter() - start)
            assert len(found) == topics
        lines.append(
            f"{kind}: {SIZES[0]} topics {seconds[0]:.3f} s, {SIZES[1]} topics "
            f"{seconds[1]:.3f} s; 4x topics: {seconds[1] / seconds[0]:.1f}x time"
        )
    with capsys.disabled():
        print("\n" + "\n".join(lines))
    assert len(lines) == len(FORMATS)
