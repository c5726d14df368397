"""Cluster order (solver.layouts.ordering): the article's three organisations of clusters,
alphabetical, most commonly used (a declared priority) and by data rate (bytes per second per
topic, read from a bag message by message), chosen in the grammar or with --cluster-order."""

from __future__ import annotations

import json
import os
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from solver import load_team, solve
from solver.cli import main
from solver.errors import InputError
from solver.identify.readers.bags import RATE_LIMITS, read_bag_rates
from solver.layouts.design import design
from solver.layouts.ordering import natural, with_order, without_data
from solver.layouts.plan import plan_layout
from solver.layouts.presentation import load_presentation

PRESENTATION = Path(__file__).resolve().parents[2] / "rules" / "presentation.yaml"


def _clusters(presentation_path: Path | None = None, **order: object) -> list[str]:
    """The case2 UGV of 6..10 cameras (clusters of 2): each tile's title."""
    solution = solve(load_team("case2"))
    presentation = with_order(load_presentation(presentation_path), **order)  # type: ignore[arg-type]  # keywords of with_order
    configuration = solution.configurations[7]
    return [tile.title for tile in design(plan_layout(solution, configuration, presentation)).tiles]


def test_alphabetical_reads_numbers_as_numbers() -> None:
    assert sorted(["/c_10", "/c_2", "/c"], key=natural) == ["/c", "/c_2", "/c_10"]
    assert _clusters()[:2] == [
        "visual display, cluster 1 (1, 2)",
        "visual display, cluster 2 (3, 4)",
    ]


def test_priority_puts_the_declared_sensors_first(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(
        PRESENTATION.read_text().replace(
            "    order: alphabetical",
            "    order: priority\n    priority: [image_raw_7, visual display 3]",
        )
    )
    assert _clusters(path)[:3] == [
        "visual display, cluster 1 (7, 3)",
        "visual display, cluster 2 (1, 2)",
        "visual display, cluster 3 (4, 5)",
    ]


def test_data_rate_puts_the_busiest_topics_first() -> None:
    rates = {"/camera/image_raw_9": 10.0, "/camera/image_raw_4": 2000.0}
    assert _clusters(order="data rate", rates=rates)[:2] == [
        "visual display, cluster 1 (4, 9)",
        "visual display, cluster 2 (1, 2)",
    ]


def test_an_order_without_its_data_is_a_located_error(tmp_path: Path) -> None:
    presentation = load_presentation()
    with pytest.raises(InputError) as caught:
        with_order(presentation, "data rate")
    assert str(caught.value.faults[0]) == (
        "--cluster-order: the data rate order needs each topic's bytes per second: --rates-bag BAG"
    )
    path = tmp_path / "p.yaml"
    path.write_text(PRESENTATION.read_text().replace("order: alphabetical", "order: data rate"))
    with pytest.raises(InputError) as caught:
        with_order(load_presentation(path))
    (fault,) = caught.value.faults
    line = next(n for n, text in enumerate(path.read_text().splitlines(), 1) if "data rate" in text)
    assert (fault.location.file, fault.location.line) == (str(path), line)
    assert fault.location.path == "grammar.clusters.order"
    with pytest.raises(InputError, match="--cluster-order: unknown cluster order 'loudest'"):
        with_order(presentation, "loudest")
    with pytest.raises(InputError, match="--rates-bag: is for the 'data rate' order"):
        with_order(presentation, "alphabetical", {})


def test_an_order_without_its_data_where_no_bag_is_read_is_applied_alphabetically(
    tmp_path: Path,
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(PRESENTATION.read_text().replace("order: alphabetical", "order: data rate"))
    line = next(n for n, text in enumerate(path.read_text().splitlines(), 1) if "data rate" in text)
    applied, fault = without_data(load_presentation(path), "layouts --robot")
    assert applied.grammar.order == "alphabetical"
    assert fault is not None
    assert str(fault) == (
        f"{path}:{line}: grammar.clusters.order: 'data rate' was asked for and needs each "
        "topic's bytes per second, from a bag, which layouts --robot does not have: ordered "
        "alphabetically"
    )
    assert applied.grammar.order_note == fault.message
    shipped = load_presentation()
    assert without_data(shipped, "layouts --robot") == (shipped, None)


def test_layouts_robot_writes_the_order_it_applied_and_warns_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(PRESENTATION.read_text().replace("order: alphabetical", "order: data rate"))
    out = tmp_path / "robot.json"
    urdf = PRESENTATION.parents[1] / "examples" / "quadrotor.urdf"
    args = ["layouts", "--robot", str(urdf), "--team", "case2", "--presentation", str(path)]
    assert main([*args, "-o", str(out)]) == 0
    warnings = [line for line in capsys.readouterr().err.splitlines() if "data rate" in line]
    assert warnings == [
        f"warning: {path}:{_line(path, 'data rate')}: grammar.clusters.order: 'data rate' was "
        "asked for and needs each topic's bytes per second, from a bag, which layouts --robot "
        "does not have: ordered alphabetically"
    ]
    design = json.loads(out.read_text())["globalVariables"]["teleop_ui_design"]
    assert design["clusterOrder"] == "alphabetical"
    assert design["clusterOrderNote"].endswith("ordered alphabetically")


def _line(path: Path, text: str) -> int:
    return next(n for n, line in enumerate(path.read_text().splitlines(), 1) if text in line)


def _bag(
    path: Path, prefix: str = "", names: tuple[str, str] = ("image_raw_3", "image_raw_7")
) -> Path:
    """A ROS 1 bag over two seconds: image_raw_3 sends 2 x 1000 bytes, image_raw_7 2 x 500
    (under ``prefix``/camera; ``names``: other topics' last parts)."""
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    topics = [f"{prefix}/camera/{name}" for name in names]
    with Writer(path) as writer:
        for name, size in zip(topics, (1000, 500), strict=True):
            connection = writer.add_connection(name, "sensor_msgs/msg/Image", typestore=store)
            for stamp in (1_000_000_000, 3_000_000_000):
                writer.write(connection, stamp, bytes(size))
    return path


def test_a_bags_rates_are_its_topics_bytes_over_its_span(tmp_path: Path) -> None:
    assert read_bag_rates(_bag(tmp_path / "run.bag")) == {
        "/camera/image_raw_3": 1000.0,  # 2000 bytes over 2 s
        "/camera/image_raw_7": 500.0,
    }


def test_layouts_order_by_data_rate_and_say_so_in_the_layout(tmp_path: Path) -> None:
    bag = _bag(tmp_path / "run.bag")
    out = tmp_path / "out"
    args = ["layouts", "case2", "-o", str(out), "--cluster-order", "data rate"]
    assert main([*args, "--rates-bag", str(bag)]) == 0
    layout = json.loads((out / "config-008.json").read_text())
    assert layout["globalVariables"]["teleop_ui_design"]["clusterOrder"] == "data rate"
    first = layout["configById"]["Tab!c01"]["tabs"]
    assert [tab["title"] for tab in first] == ["camera 3", "camera 7"]


def test_a_bag_recorded_under_a_namespace_orders_the_template_layouts_by_last_part(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Recorded as /uav1/camera/image_raw_3 and _7; the layouts (no --namespace) name
    # /camera/image_raw_3 and _7: each found by its last part, the only topic ending so.
    bag = _bag(tmp_path / "run.bag", prefix="/uav1")
    out = tmp_path / "out"
    args = ["layouts", "case2", "-o", str(out), "--cluster-order", "data rate"]
    assert main([*args, "--rates-bag", str(bag)]) == 0
    assert "warning" not in capsys.readouterr().err
    layout = json.loads((out / "config-008.json").read_text())
    assert layout["globalVariables"]["teleop_ui_design"]["clusterOrder"] == "data rate"
    tabs = layout["configById"]["Tab!c01"]["tabs"]
    assert [tab["title"] for tab in tabs] == ["camera 3", "camera 7"]


def test_a_last_part_two_topics_of_the_bag_end_in_is_not_matched() -> None:
    rates = {"/a/camera/image_raw_4": 2000.0, "/b/camera/image_raw_4": 10.0}
    assert _clusters(order="data rate", rates=rates)[:1] == ["visual display, cluster 1 (1, 2)"]


def test_a_bag_holding_no_sensor_topic_is_said_and_the_layout_says_what_was_applied(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bag = _bag(tmp_path / "run.bag", names=("odom", "battery"))
    out = tmp_path / "out"
    args = ["layouts", "case2", "-o", str(out), "--cluster-order", "data rate"]
    assert main([*args, "--rates-bag", str(bag)]) == 0
    warnings = [line for line in capsys.readouterr().err.splitlines() if "warning" in line]
    (warning,) = warnings
    # The layouts' sensor topics named (the first three, natural order), and the bag's.
    assert warning.startswith(
        f"warning: {bag}: no sensor topic of the layouts (/audio, /audio_2, /audio_3 and "
    )
    assert warning.endswith(
        "more) is in the bag, by name or by its last part (the bag's topics: "
        "/camera/battery, /camera/odom): the data rate order found no rates; ordered "
        "alphabetically"
    )
    design = json.loads((out / "config-008.json").read_text())["globalVariables"]
    assert design["teleop_ui_design"]["clusterOrder"] == "alphabetical"
    assert (
        design["teleop_ui_design"]["clusterOrderNote"]
        == warnings[0].partition(": ")[2].partition(": ")[2]
    )


def test_a_data_rate_order_without_a_bag_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    assert main(["layouts", "case2", "-o", str(out), "--cluster-order", "data rate"]) == 2
    assert "--rates-bag BAG" in capsys.readouterr().err
    assert not out.exists()


def test_a_bag_larger_than_the_readers_memory_is_read_message_by_message(tmp_path: Path) -> None:
    # 200 messages of 1 MB (200 MB) read by a child allowed 160 MiB of address space in all
    # (Python and rosbags included): only streaming gets through. (A 1.2 GB bag read the same
    # way in 0.4 s: docs/layouts.md.)
    from rosbags.rosbag2 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    bag = tmp_path / "big"
    blob = bytes(1_000_000)
    with Writer(bag, version=8) as writer:
        connection = writer.add_connection(
            "/camera/image_raw", "sensor_msgs/msg/Image", typestore=store
        )
        for n in range(200):
            writer.write(connection, n * 10_000_000, blob)
    limits = replace(RATE_LIMITS, memory_bytes=160 * 2**20)
    # 200,000,000 bytes over the span from the first message to the last, 1.99 s.
    assert read_bag_rates(bag, limits=limits) == {"/camera/image_raw": round(2e8 / 1.99, 3)}


@pytest.mark.parametrize(
    ("name", "content"),
    [
        ("cut.bag", b"#ROSBAG V2.0\n" + b"\xff" * 64),  # a header cut off
        ("noise.bag", bytes(range(256)) * 64),  # no bag at all
        ("empty.db3", b""),  # a ROS 2 database of nothing
    ],
)
def test_a_rates_bag_that_cannot_be_read_is_a_located_error_and_nothing_is_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str, content: bytes
) -> None:
    bag = tmp_path / name
    bag.write_bytes(content)
    out = tmp_path / "out"
    args = ["layouts", "case2", "-o", str(out), "--cluster-order", "data rate"]
    assert main([*args, "--rates-bag", str(bag)]) == 2
    error = capsys.readouterr().err
    # The bag named, the reason said: unreadable, or past a bound of its reader (the cut
    # header declares a record of gigabytes: "bag refused: needs more than 512 MiB").
    assert error.startswith((f"{bag}: cannot read", f"{bag}: bag refused: "))
    assert "Traceback" not in error
    assert not out.exists()


def test_a_rates_bag_that_is_a_pipe_is_refused_before_it_is_opened(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pipe = tmp_path / "pipe.bag"
    os.mkfifo(pipe)
    args = ["layouts", "case2", "-o", str(tmp_path / "out"), "--cluster-order", "data rate"]
    assert main([*args, "--rates-bag", str(pipe)]) == 2
    assert "not a bag file or folder (a device or pipe?)" in capsys.readouterr().err


def test_a_ros1_chunk_that_decompresses_huge_is_refused_at_the_chunk_bound(tmp_path: Path) -> None:
    import bz2

    # 50 KB on disk: each chunk is its own bz2 stream followed by 1,024 streams of a MiB of
    # zeros, 1 GiB decompressed (rosbags' bz2 reads every stream: the message offsets still
    # point into the first).
    bomb = bz2.compress(bytes(2**20)) * 1024

    def compress(data: bytes) -> bytes:
        return bz2.compress(data) + bomb

    bag = _ros1_bag(tmp_path / "bomb.bag", [(1, 100), (2, 100)], compress)
    assert bag.stat().st_size < 100_000
    with pytest.raises(InputError) as caught:
        read_bag_rates(bag)
    assert str(caught.value) == (
        f"{bag}: bag refused: a chunk decompresses to more than {RATE_LIMITS.chunk_bytes} bytes"
    )


def test_a_ros1_chunk_read_again_and_again_is_counted_each_time(tmp_path: Path) -> None:
    # Two chunks whose messages alternate in time (A at 1 s and 3 s, B at 2 s and 4 s): read
    # in time order, each chunk is decompressed twice, 4 x 1.2 MB for 2.4 MB of chunks.
    size = 600_000
    bag = _ros1_bag(tmp_path / "interleaved.bag", [(1, size), (3, size), (2, size), (4, size)])
    limits = replace(RATE_LIMITS, bag_bytes=3_000_000)
    with pytest.raises(InputError, match="decompress to more than 3000000 bytes in all"):
        read_bag_rates(bag, limits=limits)
    # Read once each, the same chunks pass (4 x 600,000 bytes over 3 s).
    ordered = _ros1_bag(tmp_path / "ordered.bag", [(1, size), (2, size), (3, size), (4, size)])
    assert read_bag_rates(ordered, limits=limits) == {"/camera/image_raw": 800_000.0}


def _ros1_bag(path: Path, messages: list[tuple[int, int]], compress: Any = None) -> Path:
    """A bz2-compressed ROS 1 bag of one topic: (timestamp in s, size) per message, a chunk
    written whenever 1 MiB is passed; ``compress``: what the chunks are written as instead."""
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    writer = Writer(path)
    writer.set_compression(Writer.CompressionFormat.BZ2)
    if compress is not None:
        writer.compressor = compress
    with writer:
        connection = writer.add_connection(
            "/camera/image_raw", "sensor_msgs/msg/Image", typestore=store
        )
        for second, size in messages:
            writer.write(connection, second * 10**9, bytes(size))
    return path
