"""`teleop-ui robots TEAM`: every valid robot with its configuration number, as CSV.

Target (issue 14): at least 10x the throughput of a plain peer doing the same work on the same
team: python-constraint2's solution iterator, a dict from component tuple to configuration
number, and :func:`csv.writer`. Both write to memory; the ratio is in tools/bench_table.py.

Target (issue 29): `robots TEAM | head -1000` streams from the first robot, whatever the team:
the first 1,000 lines of teams of 409,600 and 64,000,000 robots (each its own configuration),
of 512,000 robots whose values overlap and of 409,599 robots whose two characteristics a rule
links take about what those of a team of 1,600 robots take (it was 25.8 s and about 1 GB at 640
values), and listing all 409,600 robots peaks at the memory of listing the first 1,000.
"""

from __future__ import annotations

import contextlib
import csv
import hashlib
import io
import tracemalloc
from collections.abc import Callable
from pathlib import Path

import pytest
import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.conftest import Scale, Scaled
from solver import Team, load_team, solve
from solver.core.model import build_problem
from solver.reporting.listing import write_robots

# 2 types x 5 motion controls x (20 sensor types x 1..1000 sensors - 100 forbidden): 199,000
# robots in 2 x 5 x 5 x 5 = 250 configurations, with a constraint.
LISTED = Scale(
    types=2, motions=5, sensors=20, groups=5, counts=1_000, arrangements=5, forbidden=100
)


def listing(team: Team) -> str:
    """What `teleop-ui robots TEAM` does: solve, then write every robot."""
    buffer = io.StringIO()
    write_robots(solve(team), buffer)
    return buffer.getvalue()


def peer_listing(team: Team) -> tuple[str, int]:
    """The peer: python-constraint2's iterator, a dict of configurations, csv.writer."""
    rules = team.rules
    names = rules.names
    # The component of each value, per characteristic (every value here has exactly one).
    component = [
        {value: members[0] for value, members in zip(c.values, c.membership, strict=True)}
        for c in rules.characteristics
    ]
    numbers: dict[tuple[int, ...], int] = {}
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["configuration", *names])
    for selection in team.selections:
        problem = build_problem(rules, selection.domains)
        assert problem is not None
        for found in problem.getSolutionIter():
            robot = [found[name] for name in names]
            key = tuple([table[value] for table, value in zip(component, robot, strict=True)])
            number = numbers.setdefault(key, len(numbers) + 1)
            writer.writerow([number, *robot])
    return buffer.getvalue(), len(numbers)


def test_list_robots_as_csv(benchmark: BenchmarkFixture, scaled: Scaled) -> None:
    team: Team = scaled(LISTED)
    text = benchmark(listing, team)
    lines = text.splitlines()
    assert len(lines) == 1 + LISTED.robots == 1 + 199_000
    assert len({line.split(",", 1)[0] for line in lines[1:]}) == LISTED.configurations == 250


def test_list_robots_as_csv_python_constraint_peer(
    benchmark: BenchmarkFixture, scaled: Scaled
) -> None:
    team: Team = scaled(LISTED)
    # One round: the peer takes seconds, which is the point of the comparison.
    text, configurations = benchmark.pedantic(  # type: ignore[no-untyped-call]  # untyped
        peer_listing, args=(team,), rounds=1, iterations=1
    )
    assert len(text.splitlines()) == 1 + LISTED.robots
    assert configurations == LISTED.configurations


def test_list_robots_as_jsonl(benchmark: BenchmarkFixture, scaled: Scaled) -> None:
    team: Team = scaled(LISTED)

    def jsonl() -> str:
        buffer = io.StringIO()
        write_robots(solve(team), buffer, fmt="jsonl")
        return buffer.getvalue()

    lines = benchmark(jsonl).splitlines()
    assert len(lines) == LISTED.robots
    assert lines[
        -1
    ] == '{"configuration": 250, "kinematic_type": "T1", "motion_control": "M4", ' + (
        '"sensor_type": "S19", "sensor_count": 1000}'
    )


class _Head(io.StringIO):
    """A stream that closes after ``lines`` lines, as ``head`` does: writing past them raises
    :class:`BrokenPipeError`."""

    def __init__(self, lines: int) -> None:
        super().__init__()
        self.left = lines

    def write(self, text: str) -> int:
        if self.left <= 0:
            raise BrokenPipeError
        lines = text.split("\n")[:-1] if text.endswith("\n") else text.split("\n")
        if len(lines) >= self.left:
            kept = "\n".join(lines[: self.left]) + "\n"
            self.left = 0
            return super().write(kept)
        self.left -= len(lines)
        return super().write(text)


def head(team: Team, lines: int) -> str:
    """What `teleop-ui robots TEAM | head -LINES` does, in-process."""
    stream = _Head(lines)
    with contextlib.suppress(BrokenPipeError):
        write_robots(solve(team, count_only=True), stream)
    return stream.getvalue()


def wide(folder: Path, characteristics: int, values: int, *, linked: bool = False) -> Team:
    """One kinematic type; characteristics of ``values`` values, each its own component; with
    ``linked``, a rule forbidding the first value of c0 beside the first of c1."""
    rules: dict[str, object] = {
        "characteristics": {
            "kinematic_type": {"values": ["T0"]},
            **{
                f"c{c}": {"values": [f"c{c}v{i}" for i in range(values)]}
                for c in range(characteristics)
            },
        }
    }
    if linked:
        rules["constraints"] = [{"forbid": {"c0": "c0v0", "c1": "c1v0"}}]
    (folder / "rules.yaml").write_text(yaml.safe_dump(rules, sort_keys=False), encoding="utf-8")
    (folder / "team.yaml").write_text("rules: rules.yaml\nteam:\n  T0: {}\n", encoding="utf-8")
    return load_team(folder / "team.yaml")


def windows(folder: Path, values: int) -> Team:
    """Three characteristics of ``values`` values in windows of four sliding by two."""
    from benchmarks.bench_overlap import team

    return team(folder, values)


# name -> (team maker, robots, configurations)
HEADS: dict[str, tuple[Callable[[Path], Team], int, int]] = {
    "2 x 40 values": (lambda f: wide(f, 2, 40), 1_600, 1_600),
    "2 x 640 values": (lambda f: wide(f, 2, 640), 409_600, 409_600),
    "3 x 400 values": (lambda f: wide(f, 3, 400), 64_000_000, 64_000_000),
    "3 x 80 values in windows": (lambda f: windows(f, 80), 512_000, 8_000),
    "2 x 640 values, linked": (lambda f: wide(f, 2, 640, linked=True), 409_599, 409_599),
}


@pytest.fixture(scope="module")
def heads(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Team]:
    return {name: make(tmp_path_factory.mktemp("head")) for name, (make, _, _) in HEADS.items()}


@pytest.mark.parametrize("name", list(HEADS))
def test_first_1000_robots(benchmark: BenchmarkFixture, heads: dict[str, Team], name: str) -> None:
    team = heads[name]
    _, robots, configurations = HEADS[name]
    lines = benchmark(head, team, 1000).splitlines()
    assert lines[0].startswith("configuration,kinematic_type,c0,")
    assert len(lines) == 1000  # the header and 999 robots
    first = [int(line.split(",", 1)[0]) for line in lines[1:]]
    if robots == configurations:  # each robot its own configuration, in listing order
        assert first == list(range(1, 1000))
    else:  # windows: the first robots are c0v0, c1v0, c2v0 .. c2v79, then c1v1 ...
        assert first[0] == 1
        assert max(first) <= configurations


def test_listing_every_robot_peaks_where_the_first_1000_do(heads: dict[str, Team]) -> None:
    team = heads["2 x 640 values"]
    peaks = []
    for lines in (1000, 409_600 + 1):
        tracemalloc.start()
        written = head(team, lines)
        peaks.append(tracemalloc.get_traced_memory()[1] - len(written) * 2)
        tracemalloc.stop()
        assert written.count("\n") == min(lines, 1 + 409_600)
    # The text written is kept by the test's stream; what listing holds besides it is a block.
    assert peaks[1] < 2 * peaks[0] + (1 << 20)


# ---- issue 42: the whole command against a handwritten numpy listing of the same bytes -------
# Target: `teleop-ui robots TEAM` (in-process, through the command line's terminal-safe output)
# at least 1.0x a numpy listing written for this team alone; the ratio is in tools/bench_table.py.
LONG_VALUES = 1_900  # 2 x 1,900 values: 3,610,000 robots, each its own configuration


class _Sink:
    """Standard output for both listings: what was written is hashed and counted, not kept."""

    def __init__(self) -> None:
        self.digest = hashlib.sha256()
        self.size = 0

    def write(self, text: str) -> int:
        self.digest.update(text.encode())
        self.size += len(text)
        return len(text)

    def flush(self) -> None:
        return None

    def isatty(self) -> bool:
        return False


def command_listing(team_file: Path) -> tuple[str, int]:
    """`teleop-ui robots TEAM > file`, in-process: the command line's own streams and all."""
    from solver.cli import main

    sink = _Sink()
    with contextlib.redirect_stdout(sink):
        assert main(["robots", str(team_file)]) == 0
    return sink.digest.hexdigest(), sink.size


def numpy_listing(values: int) -> tuple[str, int]:
    """The peer: the same CSV made by numpy for this team alone (one type, two characteristics,
    each robot its own configuration, numbered in listing order: no lookup), written at once."""
    import numpy as np

    sink = _Sink()
    first = np.array([f",T0,c0v{i}," for i in range(values)], dtype=object)
    second = np.array([f"c1v{i}\n" for i in range(values)], dtype=object)
    pieces = np.empty((values * values, 2), dtype=object)
    pieces[:, 0] = list(map(str, range(1, values * values + 1)))
    pieces[:, 1] = np.add.outer(first, second).reshape(-1)
    sink.write("configuration,kinematic_type,c0,c1\n")
    sink.write("".join(pieces.reshape(-1).tolist()))
    return sink.digest.hexdigest(), sink.size


@pytest.fixture(scope="module")
def long_team(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("long")
    wide(folder, 2, LONG_VALUES)
    return folder / "team.yaml"


def test_robots_command_lists_3_6_million_robots(
    benchmark: BenchmarkFixture, long_team: Path
) -> None:
    digest, size = benchmark(command_listing, long_team)
    assert (digest, size) == numpy_listing(LONG_VALUES)  # byte for byte the peer's


def test_robots_numpy_listing_peer(benchmark: BenchmarkFixture) -> None:
    _, size = benchmark(numpy_listing, LONG_VALUES)
    assert size > LONG_VALUES**2 * len("1,T0,c0v0,c1v0\n")
