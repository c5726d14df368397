"""Benchmark: writing every layout of a team of 10^4 UI configurations (issue 39), the
team's consistency score that ``teleop-ui layouts`` reports with them, and the data-rate
cluster order from a bag of 1 GB.

A generated rule set (``benchmarks/conftest.py``'s :class:`Scale`): one kinematic type, 25
motion controls, 40 sensor types in 20 groups, counts 1..20 in 20 arrangements (arrangement
``a`` is the count a+1, in one cluster of a+1): 25 x 20 x 20 = 10,000 configurations, each
laid out by the shipped grammar (a rule set of its own: every component a titled placeholder,
the motion control docked left, the first sensor the primary view). The shipped
``written-files`` limit (2,000) refuses such a team; the benchmark lifts it to measure the
writer at the scale the issue asks for. With timing off (``--benchmark-disable``) the team is
25 x 4 x 4 = 400 configurations: the same code, the counts asserted.

The data-rate order reads a bag of 1 GB (ROS 1 ``.bag`` and ROS 2 folder: ten cameras,
camera n sending n x 180 kB a message, 100 messages each) in the bag reader's child process
allowed 256 MiB of address space in all (Python and rosbags included): only a reader that
streams the bag message by message gets through, so the peak memory is asserted by the
child's own limit, well below the bag's size. The big bags are written only for a run that
times (a few seconds each, removed afterwards); with timing off they hold 4 messages a camera
of n x 20 kB (4.4 MB), read by the same code, the same order asserted.

Run: ``python -m pytest benchmarks/bench_layouts.py``.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.conftest import Scale, Scaled
from solver import limits, load_team, solve
from solver.identify.readers.bags import RATE_LIMITS, read_bag_rates
from solver.layouts import load_presentation
from solver.layouts.checks.quality import team_consistency
from solver.layouts.design import design
from solver.layouts.ordering import with_order
from solver.layouts.plan import plan_layout
from solver.layouts.writer import write_layout_folder

BIG = Scale(types=1, motions=25, sensors=40, groups=20, counts=20, arrangements=20)
SMALL = Scale(types=1, motions=25, sensors=8, groups=4, counts=4, arrangements=4)


def _scale(benchmark: BenchmarkFixture) -> Scale:
    return BIG if benchmark.enabled else SMALL


def test_write_every_layout_of_a_team_of_10k_configurations(
    benchmark: BenchmarkFixture,
    scaled: Scaled,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    scale = _scale(benchmark)
    solution = solve(scaled(scale))
    assert len(solution.configurations) == scale.configurations
    files = scale.configurations + 1  # and the default configuration's
    bound = replace(limits.limit("written-files"), value=files)
    monkeypatch.setitem(limits._BY_NAME, "written-files", bound)  # pylint: disable=protected-access
    presentation = load_presentation()
    done = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        write_layout_folder,
        args=(solution, presentation, tmp_path / "out"),
        rounds=1,
        iterations=1,
    )
    assert len(done.paths) == files
    # The last configuration: the last motion control, group and arrangement, a+1 = counts
    # sensors in one cluster (a Tab panel) and the motion control's panel.
    last = json.loads(done.paths[-2].read_text())
    panels = [key for key in last["configById"] if not key.startswith("Tab!")]
    assert len(panels) == scale.counts + 1
    assert sum(key.startswith("Tab!") for key in last["configById"]) == 1


def test_the_consistency_of_a_team_of_10k_configurations(
    benchmark: BenchmarkFixture, scaled: Scaled
) -> None:
    scale = _scale(benchmark)
    solution = solve(scaled(scale))
    found = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        team_consistency, args=(solution, load_presentation()), rounds=1, iterations=1
    )
    # Each motion control is in groups x arrangements configurations, each sensor group in
    # motions x arrangements: every pair of them shares it, and each keeps its region.
    # The default configuration shows every one of them once more.
    per_motion = scale.groups * scale.arrangements + 1
    per_group = scale.motions * scale.arrangements + 1
    pairs = scale.motions * math.comb(per_motion, 2) + scale.groups * math.comb(per_group, 2)
    assert (found.same, found.pairs, found.moved) == (pairs, pairs, ())


# Camera n (of ten) sends messages of n x SIZE bytes: the busiest is the last alphabetically.
BIG_BAG = (100, 180_000)  # messages a camera, SIZE: 100 x 55 x 180 kB = 990 MB
SMALL_BAG = (4, 20_000)  # timing off: 4.4 MB
READER_MEMORY = 256 * 2**20  # the child's whole address space, well below the bag


def _camera_bag(folder: Path, fmt: str, messages: int, size: int) -> Path:
    """Ten cameras (``/camera/image_raw``, ``_2`` .. ``_10``), interleaved in time, 0.1 s
    apart, camera n's messages n x ``size`` bytes."""
    from rosbags.typesys import Stores, get_typestore

    topics = ["/camera/image_raw", *(f"/camera/image_raw_{n}" for n in range(2, 11))]
    blobs = [bytes(n * size) for n in range(1, 11)]
    if fmt == "ROS 1 .bag":
        from rosbags.rosbag1 import Writer as Writer1

        path = folder / "cameras.bag"
        writer: Any = Writer1(path)
        store = get_typestore(Stores.ROS1_NOETIC)
    else:
        from rosbags.rosbag2 import Writer as Writer2

        path = folder / "cameras"
        writer = Writer2(path, version=8)
        store = get_typestore(Stores.ROS2_HUMBLE)
    with writer:
        connections = [
            writer.add_connection(topic, "sensor_msgs/msg/Image", typestore=store)
            for topic in topics
        ]
        for index in range(messages):
            for connection, blob in zip(connections, blobs, strict=True):
                writer.write(connection, (index + 1) * 100_000_000, blob)
    return path


@pytest.mark.parametrize("fmt", ["ROS 1 .bag", "ROS 2 folder"])
def test_data_rate_order_from_a_bag_of_1_gb_streams_it(
    benchmark: BenchmarkFixture,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    fmt: str,
) -> None:
    messages, size = BIG_BAG if benchmark.enabled else SMALL_BAG
    bag = _camera_bag(tmp_path, fmt, messages, size)
    total = messages * size * sum(range(1, 11))
    on_disk = sum(p.stat().st_size for p in ([bag] if bag.is_file() else bag.iterdir()))
    assert on_disk > total  # the messages and the bag's own records
    limits_ = replace(RATE_LIMITS, memory_bytes=READER_MEMORY)
    solution = solve(load_team("case2"))
    presentation = load_presentation()

    def order() -> list[str]:
        rates = read_bag_rates(bag, limits=limits_)
        ordered = with_order(presentation, "data rate", rates)
        laid = design(plan_layout(solution, solution.configurations[7], ordered))
        return [tile.title for tile in laid.tiles if tile.component == "visual display"]

    titles = benchmark.pedantic(order, rounds=1, iterations=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    # case2's configuration 8: ten cameras in clusters of 2, the busiest (camera 10) first.
    assert titles == [
        "visual display, cluster 1 (10, 9)",
        "visual display, cluster 2 (8, 7)",
        "visual display, cluster 3 (6, 5)",
        "visual display, cluster 4 (4, 3)",
        "visual display, cluster 5 (2, 1)",
    ]
    if benchmark.enabled:  # with timing off the sizes say nothing
        with capsys.disabled():
            print(f"\n{fmt}: {on_disk / 1e9:.2f} GB read by a child of {READER_MEMORY >> 20} MiB")
