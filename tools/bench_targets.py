"""Every speed target of the project in one table: its peer, its floor and today's ratio.

The table in docs/benchmarks.md ("Every target, from one run") is made by this tool from one
pytest-benchmark run, so that every ratio in it compares things measured side by side on the
same machine at the same time:

    python tools/bench_targets.py --tests              # the benchmarks it needs, as a -k filter
    python -m pytest benchmarks -k "$(python tools/bench_targets.py --tests)" -p no:randomly \\
        --benchmark-only --benchmark-json=run.json
    python tools/bench_targets.py run.json             # prints the table
    python tools/bench_targets.py run.json --write     # replaces it in docs/benchmarks.md

A target is a ratio and a bound: ``peer / ours >= goal`` (how many times faster than the peer),
``ours / peer <= goal`` (at most that many times the peer's time), or a growth ``<= goal``
(how much slower when the input doubles). The floor column is the best
ratio the target could reach, where a benchmark measures that floor (start-up: a process that
only imports what the command cannot do without), or the bound a growth cannot beat (2x for
doubling the work). Medians; a benchmark missing from the run shows as "not in this run".
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path
from typing import Any

DOCS = Path(__file__).resolve().parent.parent / "docs" / "benchmarks.md"
START, END = "<!-- targets -->", "<!-- /targets -->"


@dataclass(frozen=True)
class Run:
    """What one benchmark run measured: each benchmark's median and its extra figures."""

    medians: dict[str, float]
    extra: dict[str, dict[str, Any]]
    when: str = ""
    machine: str = ""

    @classmethod
    def of(cls, data: dict[str, Any]) -> Run:
        benchmarks = data.get("benchmarks", [])
        cpu = data.get("machine_info", {}).get("cpu", {})
        return cls(
            {b["name"]: b["stats"]["median"] for b in benchmarks},
            {b["name"]: b.get("extra_info", {}) for b in benchmarks},
            str(data.get("datetime", ""))[:10],
            f"{cpu.get('brand_raw', 'this machine')}, {cpu.get('count', '?')} cores",
        )


@dataclass(frozen=True)
class Figure:
    """A number a run gives (None when the run lacks what it needs), and the benchmarks read."""

    benchmarks: tuple[str, ...]
    compute: Callable[[Run], float | None]

    def __call__(self, run: Run) -> float | None:
        return self.compute(run)


def over(slower: str, faster: str) -> Figure:
    """The median of ``slower`` over the median of ``faster``."""

    def compute(run: Run) -> float | None:
        if slower in run.medians and faster in run.medians:
            return run.medians[slower] / run.medians[faster]
        return None

    return Figure((slower, faster), compute)


def worst_growth(names: Sequence[str]) -> Figure:
    """The largest ratio of one benchmark's median to the one before (the input doubled)."""

    def compute(run: Run) -> float | None:
        if not all(name in run.medians for name in names):
            return None
        return max(run.medians[b] / run.medians[a] for a, b in pairwise(names))

    return Figure(tuple(names), compute)


def extra(name: str, key: str) -> Figure:
    """A figure the benchmark ``name`` recorded in its ``extra_info`` under ``key``."""

    def compute(run: Run) -> float | None:
        value = run.extra.get(name, {}).get(key)
        return float(value) if isinstance(value, int | float) else None

    return Figure((name,), compute)


def constant(value: float) -> Figure:
    """A floor no benchmark needs to measure (a growth cannot beat the work it does)."""
    return Figure((), lambda _run: value)


@dataclass(frozen=True)
class Target:
    """One target: what is compared, with what, the bound, and the best it could be."""

    issue: str
    what: str
    peer: str
    ratio: Figure
    goal: float
    at_least: bool  # peer / ours >= goal; else a growth or a cost <= goal
    floor: Figure | None = None

    def row(self, run: Run) -> str:
        value = self.ratio(run)
        sign = ">=" if self.at_least else "<="
        if value is None:
            shown, verdict = "not in this run", ""
        else:
            met = value >= self.goal if self.at_least else value <= self.goal
            shown, verdict = f"{value:.2f}x", "met" if met else "**missed**"
        best = self.floor(run) if self.floor is not None else None
        floor = "" if best is None else f"{best:.2f}x"
        return (
            f"| {self.issue} | {self.what} | {self.peer} | {sign} {self.goal:g}x | {floor} "
            f"| {shown} | {verdict} |"
        )


def _cpu(name: str) -> str:
    return f"test_whole_process_cpu[{name}]"


_RINGS = "test_count_rings_in_several_characteristics"
_STUDIO = "test_studio_answers_a_change_of_case_3"

TARGETS: tuple[Target, ...] = (
    Target(
        "42.1",
        "count, overlapping components in two characteristics: growth per doubling, 80..640 values",
        "the same at half the values",
        worst_growth([f"{_RINGS}[{n}-2]" for n in (80, 160, 320, 640)]),
        2.5,
        at_least=False,
        floor=constant(1.0),
    ),
    Target(
        "42.1",
        "the same in three characteristics",
        "the same at half the values",
        worst_growth([f"{_RINGS}[{n}-3]" for n in (80, 160, 320, 640)]),
        2.5,
        at_least=False,
        floor=constant(1.0),
    ),
    Target(
        "42.2",
        "`robots`, every robot of 3,610,000 listed, byte-identical",
        "a numpy listing of the same bytes",
        over("test_robots_numpy_listing_peer", "test_robots_command_lists_3_6_million_robots"),
        1.0,
        at_least=True,
    ),
    Target(
        "42.3",
        "`teleop-ui solve case3`, whole process, CPU",
        "PyYAML + python-constraint2 script (tools/peer_case3.py)",
        over(_cpu("peer script"), _cpu("solve case3")),
        1.2,
        at_least=True,
        floor=over(_cpu("peer script"), _cpu("imports only: PyYAML, dataclasses")),
    ),
    Target(
        "42.3",
        "`teleop-ui identify` of a small URDF, whole process, CPU",
        "lxml script (tools/peer_identify.py)",
        over(_cpu("identify peer script"), _cpu("identify a URDF")),
        1.2,
        at_least=True,
        floor=over(_cpu("identify peer script"), _cpu("imports only: PyYAML, dataclasses, lxml")),
    ),
    Target(
        "42.4",
        "`batch` worker, CPU per team (Case 3, 50 teams, durable JSON and stamp)",
        "a loop over the public API writing compact JSON",
        over("test_plain_loop_over_the_api_solves_50_teams", "test_batch_worker_solves_50_teams"),
        1.0,
        at_least=True,
    ),
    *(
        Target(
            "42.4",
            f"`batch -j2` over `batch -j1`, {teams:,} teams of Case 3, wall clock",
            "`batch -j1`",
            extra(f"test_batch_whole_process_two_workers_against_one[{teams} teams]", "j2_over_j1"),
            1.6,
            at_least=True,
            floor=constant(2.0),
        )
        for teams in (400, 2000)
    ),
    Target(
        "42.5",
        "in-process `count` of Case 3, its time over the peer's",
        "its closed form, written by hand",
        extra("test_count_of_case_3_against_its_closed_form", "ratio_to_closed_form"),
        10,
        at_least=False,
        floor=constant(1.0),
    ),
    Target(
        "42.5",
        "studio: a change of selection, Case 3, its CPU over the peer's",
        "a handwritten Starlette handler calling the same function",
        extra(_STUDIO, "cpu_ratio_to_http_peer"),
        2,
        at_least=False,
        floor=constant(1.0),
    ),
    Target(
        "29",
        "`check` growth per doubling of the rule set (x1 -> x2 -> x4)",
        "the same at half the size",
        worst_growth([f"test_check_doubled_rule_sets[x{n}]" for n in (1, 2, 4)]),
        2.5,
        at_least=False,
        floor=constant(2.0),
    ),
    Target(
        "29",
        "read + count growth per doubling of the values (5,120 -> 20,480)",
        "the same at half the values",
        worst_growth([f"test_count_growth_in_values[{n}]" for n in (5120, 10240, 20480)]),
        2.5,
        at_least=False,
        floor=constant(2.0),
    ),
    Target(
        "29",
        "read + `check` growth per doubling of the values (5,120 -> 20,480)",
        "the same at half the values",
        worst_growth([f"test_check_growth_in_values[{n}]" for n in (5120, 10240, 20480)]),
        2.5,
        at_least=False,
        floor=constant(2.0),
    ),
    Target(
        "14",
        "fast enumeration + partition of 999,000 robots",
        "python-constraint2's solution iterator alone",
        over("test_iterate_1e6_python_constraint", "test_enumerate_1e6_fast"),
        200,
        at_least=True,
    ),
    Target(
        "14",
        "`robots` as CSV, 199,000 robots",
        "python-constraint2 iterator + dict + csv.writer",
        over("test_list_robots_as_csv_python_constraint_peer", "test_list_robots_as_csv"),
        10,
        at_least=True,
    ),
    Target(
        "29",
        "ROS 2 `watch`, 100 robots: active robot -> configuration, its median over the peer's",
        "a bare DDS echo round trip",
        over(
            "test_active_robot_message_to_published_configuration[100 robots]",
            "test_bare_dds_echo_round_trip_peer[100 robots]",
        ),
        3,
        at_least=False,
        floor=constant(1.0),
    ),
    Target(
        "38",
        "ROS 2 `watch --layouts --serve`, 100 robots: active robot -> configuration and "
        "layouts, its median over the peer's",
        "a bare DDS echo round trip",
        over(
            "test_active_robot_message_to_published_configuration[100 robots, layouts]",
            "test_bare_dds_echo_round_trip_peer[100 robots, layouts]",
        ),
        2,
        at_least=False,
        floor=constant(1.0),
    ),
)


def needed(targets: Sequence[Target] = TARGETS) -> list[str]:
    """The benchmarks the targets read, by function name (for a ``-k`` filter)."""
    names = {
        name.split("[", 1)[0]
        for target in targets
        for figure in (target.ratio, target.floor)
        if figure is not None
        for name in figure.benchmarks
    }
    return sorted(names)


def table(run: Run, targets: Sequence[Target] = TARGETS) -> str:
    """The Markdown table of ``targets`` as ``run`` measured them."""
    measured = [t for t in targets if t.ratio(run) is not None]
    lines = [
        f"One run, {run.when or 'undated'}, {run.machine}: {len(measured)} of {len(targets)} "
        "targets measured. Today: the peer's time over ours for a goal of at least (>=), our "
        "time over the peer's for a goal of at most (<=), or for a growth the time at twice "
        "the input over the time at the input. Floor: the best the ratio could be (measured, "
        "or the growth of the work itself, or the peer's own time).",
        "",
        "| issue | target | peer | goal | floor | today | |",
        "|---|---|---|---:|---:|---:|---|",
    ]
    lines += [t.row(run) for t in targets]
    return "\n".join(lines) + "\n"


def replace_between(text: str, body: str) -> str:
    """``text`` with what lies between the START and END markers replaced by ``body``."""
    head, found, rest = text.partition(START)
    if not found or END not in rest:
        raise SystemExit(f"{DOCS}: no {START} ... {END} block to replace")
    _, tail = rest.split(END, 1)
    return f"{head}{START}\n{body}{END}{tail}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("json", type=Path, nargs="?", help="pytest --benchmark-json output")
    parser.add_argument("--write", action="store_true", help="replace the table in the docs")
    parser.add_argument("--tests", action="store_true", help="print the -k filter of the run")
    args = parser.parse_args(argv)
    if args.tests:
        print(" or ".join(needed()))
        return 0
    if args.json is None:
        parser.error("a benchmark run (JSON) is needed, or --tests")
    run = Run.of(json.loads(args.json.read_text(encoding="utf-8")))
    text = table(run)
    if args.write:
        DOCS.write_text(replace_between(DOCS.read_text(encoding="utf-8"), text), encoding="utf-8")
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
