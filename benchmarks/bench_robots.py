"""`teleop-ui robots TEAM`: every valid robot with its configuration number, as CSV.

Target (issue 14): at least 10x the throughput of a plain peer doing the same work on the same
team: python-constraint2's solution iterator, a dict from component tuple to configuration
number, and :func:`csv.writer`. Both write to memory; the ratio is in tools/bench_table.py.
"""

from __future__ import annotations

import csv
import io

from pytest_benchmark.fixture import BenchmarkFixture

from benchmarks.conftest import Scale
from solver import Team, solve
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


def test_list_robots_as_csv(benchmark: BenchmarkFixture, scaled) -> None:  # type: ignore[no-untyped-def]
    team: Team = scaled(LISTED)
    text = benchmark(listing, team)
    lines = text.splitlines()
    assert len(lines) == 1 + LISTED.robots == 1 + 199_000
    assert len({line.split(",", 1)[0] for line in lines[1:]}) == LISTED.configurations == 250


def test_list_robots_as_csv_python_constraint_peer(benchmark: BenchmarkFixture, scaled) -> None:  # type: ignore[no-untyped-def]
    team: Team = scaled(LISTED)
    # One round: the peer takes seconds, which is the point of the comparison.
    text, configurations = benchmark.pedantic(  # type: ignore[no-untyped-call]  # untyped
        peer_listing, args=(team,), rounds=1, iterations=1
    )
    assert len(text.splitlines()) == 1 + LISTED.robots
    assert configurations == LISTED.configurations


def test_list_robots_as_jsonl(benchmark: BenchmarkFixture, scaled) -> None:  # type: ignore[no-untyped-def]
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
