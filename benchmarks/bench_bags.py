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

The big bags are written only for a run that times. With timing off (``--benchmark-disable``,
as ``tools/test.sh`` runs the benchmarks, or under xdist) every benchmark still runs once, on
bags of 25 and 100 topics written in a moment: the same code reads them and the same counts
are asserted.

Run: ``pytest benchmarks/bench_bags.py --benchmark-only``.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass
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

SIZES = (2_500, 10_000)  # timed
SMALL = (25, 100)  # timing off: the same code, the same counts asserted
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


def write_bags(folder: Path, sizes: tuple[int, int] = SIZES) -> None:
    for topics in sizes:
        ros1(folder, topics)
        ros2_folder(folder, topics)


@dataclass(frozen=True)
class Bags:
    """Every format at two sizes, the second 4x the first; the ``.db3`` is the one in the ROS 2
    folder, read alone."""

    folder: Path
    sizes: tuple[int, int]

    def path(self, kind: str, topics: int) -> Path:
        if kind == "ROS 1 .bag":
            return self.folder / f"ros1-{topics}.bag"
        if kind == "ROS 2 folder":
            return self.folder / f"ros2-{topics}"
        return next((self.folder / f"ros2-{topics}").glob("*.db3"))


@pytest.fixture(scope="module")
def big_bags() -> Bags:
    """Written once and cached (see the module docstring)."""
    key = f"bags-{'-'.join(map(str, SIZES))}-rosbags-{version('rosbags')}"
    return Bags(cached(key, functools.partial(write_bags, sizes=SIZES)), SIZES)


@pytest.fixture(scope="module")
def small_bags(tmp_path_factory: pytest.TempPathFactory) -> Bags:
    folder = tmp_path_factory.mktemp("bags")
    write_bags(folder, SMALL)
    return Bags(folder, SMALL)


@pytest.fixture
def bags(benchmark: BenchmarkFixture, request: pytest.FixtureRequest) -> Bags:
    """The big bags when this run times, else the small ones (see the module docstring)."""
    found: Bags = request.getfixturevalue("big_bags" if benchmark.enabled else "small_bags")
    return found


@pytest.mark.parametrize("size", [0, 1], ids=["1x topics", "4x topics"])
@pytest.mark.parametrize("kind", list(FORMATS), ids=list(FORMATS))
def test_reading_the_topics_of_a_big_bag(
    benchmark: BenchmarkFixture, bags: Bags, kind: str, size: int
) -> None:
    topics = bags.sizes[size]
    benchmark.group = f"bag topics: {kind}"
    found = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pedantic is unannotated
        read_bag_topics, args=(bags.path(kind, topics),), rounds=1, iterations=1
    )
    assert len(found) == topics
    assert found[-1].name == f"/robot/t{topics - 1}"


def test_growth_ratio(
    benchmark: BenchmarkFixture, bags: Bags, capsys: pytest.CaptureFixture[str]
) -> None:
    """Time at 4x the topics over time at 1x, for each format, measured in this run."""

    def growth() -> list[str]:
        lines = []
        for kind in FORMATS:
            seconds = []
            for topics in bags.sizes:
                start = time.perf_counter()
                found = read_bag_topics(bags.path(kind, topics))
                seconds.append(time.perf_counter() - start)
                assert len(found) == topics
            lines.append(
                f"{kind}: {bags.sizes[0]} topics {seconds[0]:.3f} s, {bags.sizes[1]} topics "
                f"{seconds[1]:.3f} s; 4x topics: {seconds[1] / seconds[0]:.1f}x time"
            )
        return lines

    benchmark.group = "bag topics: growth"
    lines: list[str] = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pedantic is unannotated
        growth, rounds=1, iterations=1
    )
    if benchmark.enabled:  # with timing off the times say nothing
        with capsys.disabled():
            print("\n" + "\n".join(lines))
    assert len(lines) == len(FORMATS)
