"""Benchmark: every command at the edge of its limits (docs/security.md, solver/limits.py).

Each input is as large as the limits accept, or close, and is built so that the counts it must
give are known from its construction; the claim is that each ends within seconds on this
project's 2-core machine. One round each: they are the slow cases by design.

Run: ``python -m pytest benchmarks/bench_limits.py`` (timings), or with ``--benchmark-disable``
to only assert the counts.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import ParamSpec, TypeVar

from pytest_benchmark.fixture import BenchmarkFixture

from solver import load_team, solve
from solver.check import check_files
from solver.errors import TooLargeError
from solver.identify.readers.topics import read_topic_list
from solver.limits import limit
from tests.check.helpers import pigeonhole_rules

P = ParamSpec("P")
T = TypeVar("T")


def _team(folder: Path, types: int, motions: int, counts: int) -> Path:
    """Types x motion controls x 1..counts, every value its own component."""
    kinds = [f"T{i}" for i in range(types)]
    (folder / "rules.yaml").write_text(
        f"name: edge\ncharacteristics:\n  kinematic_type:\n    values: [{', '.join(kinds)}]\n"
        f"  m:\n    values: [{', '.join(f'm{i}' for i in range(motions))}]\n"
        f"  n:\n    range: {{min: 1, max: {counts}}}\n",
        encoding="utf-8",
    )
    team = folder / "team.yaml"
    team.write_text(
        "rules: rules.yaml\nteam:\n" + "".join(f"  {k}: {{}}\n" for k in kinds), encoding="utf-8"
    )
    return team


def _once(
    benchmark: BenchmarkFixture, function: Callable[P, T], *args: P.args, **kwargs: P.kwargs
) -> T:
    """``function(*args, **kwargs)`` timed once, and what it returned."""
    result: T = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        function, args=args, kwargs=kwargs, rounds=1, iterations=1
    )
    return result


def test_solve_lists_450000_configurations(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    team = load_team(_team(tmp_path, 5, 3, 30_000))
    solution = _once(benchmark, solve, team)
    assert solution.totals.ui_configurations == 450_000
    assert len(solution.configurations) == 450_000


def test_csp_engine_at_its_limit(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    robots = limit("csp-robots").value
    team = load_team(_team(tmp_path, 1, 4, robots // 4))
    solution = _once(benchmark, solve, team, engine="csp", count_only=True)
    assert solution.totals.valid_robots == robots


def test_fast_engine_at_its_limit(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    rows = limit("fast-rows").value
    counts = limit("values").value
    team = load_team(_team(tmp_path, 1, rows // counts, counts))
    solution = _once(benchmark, solve, team, engine="fast", count_only=True)
    assert solution.totals.valid_robots == rows


def test_count_with_20000_components(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    most = limit("components").value
    listed = "".join(f"      - {{name: g{i}, values: v{i}}}\n" for i in range(most))
    rules = tmp_path / "components.yaml"
    rules.write_text(
        "name: components\ncharacteristics:\n  kinematic_type:\n    values: [A, B]\n"
        f"  x:\n    values: [{', '.join(f'v{i}' for i in range(most))}]\n"
        f"    components:\n{listed}",
        encoding="utf-8",
    )

    def count() -> int:
        from solver.core.rules import load_rules
        from solver.core.team import full_team

        return solve(full_team(load_rules(rules)), count_only=True).totals.ui_configurations

    assert _once(benchmark, count) == 2 * most


def test_check_2000_constraints(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    most = limit("constraints").value
    kinds = [f"K{i}" for i in range(100)]
    rules = tmp_path / "constraints.yaml"
    # Type t loses the 20 sensor types t..t+19 (of 40, around): each sensor type stays live
    # for other types, so no value is dead anywhere and each type has one dead-for-type.
    forbid = "".join(
        f"  - forbid: {{kinematic_type: K{i % 100}, s: S{(i % 100 + i // 100) % 40}}}\n"
        for i in range(most)
    )
    rules.write_text(
        "name: constraints\ncharacteristics:\n"
        f"  kinematic_type:\n    values: [{', '.join(kinds)}]\n"
        f"  s:\n    values: [{', '.join(f'S{j}' for j in range(40))}]\n"
        f"constraints:\n{forbid}",
        encoding="utf-8",
    )
    report = _once(benchmark, check_files, [rules])
    found = [f for f in report.findings if f.check == "dead-for-type"]
    assert len(found) == 100


def test_check_refuses_a_pigeonhole_at_the_conflicts_limit(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    # 16 characteristics of 15 values, no two alike (1,800 forbids): no robot exists, and
    # resolution (so the SAT solver) takes exponentially many conflicts to prove it.
    rules = tmp_path / "pigeonhole.yaml"
    rules.write_text(pigeonhole_rules(16, 15), encoding="utf-8")

    def refused() -> str:
        try:
            check_files([rules])
        except TooLargeError as error:
            return str(error)
        return ""

    assert "(limit 'conflicts'" in str(_once(benchmark, refused))


def test_read_100000_topic_lines(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    most = limit("topics").value
    topics = tmp_path / "topics.txt"
    topics.write_text("".join(f"/t{i} sensor_msgs/LaserScan\n" for i in range(most)))
    assert len(_once(benchmark, read_topic_list, topics)) == most


def _wide_rules(folder: Path, forbids: int) -> Path:
    """One kinematic type and as many characteristics of 1..1000 as the ``all-values`` limit
    takes; forbid ``k`` kills value ``k // 249 + 1`` of characteristic ``c{k % 249}`` alone."""
    wide = (limit("all-values").value - 1) // 1000
    rules = folder / "wide.yaml"
    forbid = "".join(f"  - forbid: {{c{k % wide}: {k // wide + 1}}}\n" for k in range(forbids))
    rules.write_text(
        "name: wide\ncharacteristics:\n  kinematic_type:\n    values: [T]\n"
        + "".join(f"  c{i}:\n    range: {{min: 1, max: 1000}}\n" for i in range(wide))
        + (f"constraints:\n{forbid}" if forbids else ""),
        encoding="utf-8",
    )
    return rules


def test_count_all_values_a_rule_set_takes(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    rules = _wide_rules(tmp_path, 0)
    (tmp_path / "team.yaml").write_text("rules: wide.yaml\nteam:\n  T: {}\n", encoding="utf-8")

    def count() -> int:
        return solve(load_team(tmp_path / "team.yaml"), count_only=True).totals.valid_robots

    assert rules.read_text().count("range:") == 249
    assert _once(benchmark, count) == 1000**249


def test_check_all_values_and_2000_constraints(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    rules = _wide_rules(tmp_path, limit("constraints").value)
    report = _once(benchmark, check_files, [rules])
    dead = [f for f in report.findings if f.check == "dead-value"]
    # One finding per characteristic, naming its dead values: 2,000 forbids reach all 249.
    assert len(dead) == 249
    assert len({f.location.line for f in dead}) == 249


def test_read_a_workspace_at_its_byte_bound(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    """300 packages that all name each other, each a launch file at the per-file bound: the
    walk stops at the byte bound with a note; every package read is the robot's (each names
    the description), and no more was read than the bound."""
    from solver.identify.readers import workspace

    names = [f"pkg_{i:04d}" for i in range(300)]
    words = " ".join(names) + " nav2_bringup "
    text = words * (workspace.MAX_FILE_BYTES // len(words))
    for name in names:
        (tmp_path / name / "launch").mkdir(parents=True)
        (tmp_path / name / "package.xml").write_text(f"<package><name>{name}</name></package>")
        (tmp_path / name / "launch" / "a.launch").write_text(text)
    found = _once(benchmark, workspace.read_workspace, tmp_path / names[0])
    assert found is not None
    assert len(found.files) == -(-workspace.MAX_TOTAL_BYTES // len(text))
    assert len(found.packages) == len(found.files)
    assert "more than 48 MiB of files" in found.notes[0]


def test_read_a_workspace_of_20000_packages(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    """20,000 one-file packages that each name the description (60,000 entries and more, past
    the entry bound): the walk stops, every package read is the robot's, and the evidence line
    names 12 and counts the rest."""
    from solver.identify.readers import workspace

    own = tmp_path / "rover_description"
    own.mkdir()
    (own / "package.xml").write_text("<package><name>rover_description</name></package>")
    for i in range(20_000):
        folder = tmp_path / f"u{i:05d}"
        folder.mkdir()
        (folder / "package.xml").write_text(f"<package><name>u{i:05d}</name></package>")
        (folder / "a.launch").write_text("rover_description")
    found = _once(benchmark, workspace.read_workspace, own)
    assert found is not None
    assert len(found.packages) == len(found.files) + 1  # the description's package has none
    assert not found.complete
    assert found.shown_packages.endswith(f" and {len(found.packages) - 12:,} more")


def test_read_the_frames_of_a_4000_link_chain_each_named(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    """A stranger's description of 4,000 camera links chained by fixed joints, each named a
    frame id in a file, and a file of 10,000 camera names no link has: each link's rule is
    found once, each link is climbed from once to the topmost named frame of its run (then a
    device's body is at most three joints up), at most 64 camera names are looked up. Every
    link is a named frame under the first one: one run, one camera."""
    from solver.identify import load_profile
    from solver.identify.frames import sensors_on_frames
    from solver.identify.readers.urdf import parse_urdf
    from solver.identify.readers.workspace import ShippedFile, Workspace

    links, parent = 4000, "base_link"
    parts = ['<robot name="r"><link name="base_link"/>']
    for i in range(links):
        parts.append(
            f'<link name="cam{i}_link"/><joint name="j{i}" type="fixed">'
            f'<parent link="{parent}"/><child link="cam{i}_link"/></joint>'
        )
        parent = f"cam{i}_link"
    urdf = parse_urdf("".join(parts) + "</robot>", "r.urdf")
    named = "".join(f"frame_id: cam{i}_link\n" for i in range(links))
    names = "".join(f"camera_name: nothing_{i}\n" for i in range(10_000))
    files = (ShippedFile("r_bringup", "a.yaml", named), ShippedFile("r_bringup", "b.yaml", names))
    packages = Workspace("/ws/src", "r_description", ("r_bringup",), files)
    found = _once(benchmark, sensors_on_frames, packages, urdf, load_profile(), ())
    assert [d.kind for d in found] == ["camera"]
