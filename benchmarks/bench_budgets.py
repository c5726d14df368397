"""Benchmark: inputs within every size limit that took up to two minutes, and how a budget
stops the rest (issue 36, item 6).

* **20,000 types over 100,000 counts** (154 KB): every type's live counts were compared with
  the counts live anywhere, value by value (``dead-for-type``), and their union made set by
  set: 49 s. 100 types lose one count each: 100 ``dead-for-type`` findings.
* **20,000 types and one constraint about any type, over 100,000 counts**: each type's live
  counts were a set of their own, 100,000 each (2,000 types: 54 s and 8.2 GB; 20,000 would
  need some 80 GB). Only the bound is reported.
* **5,000 components, one per count, ``count --symbolic``**: the arrangement function has a
  piece per count; sympy simplified each piece against the ones before and evaluated it piece
  by piece: 44 s (8.5 s at 1,000). Asserted: the counts at the team's maxima.
* **An intricate rule set** (:func:`tests.check.helpers.intricate_rules`, 108 KB: 1,000
  types, each with a constraint of its own beside 1,000 about every type, over 1,000
  characteristics): 111 s of CPU and 2.8 GB to check in full, 99 s and 480 MB since; what is
  timed is a partial check with a 2 s budget (the studio's way), which must stop with an
  ``unfinished`` finding. The time over 2 s is how late a budget stops a run.

Run: ``python -m pytest benchmarks/bench_budgets.py`` (timings), or with
``--benchmark-disable`` to only assert the findings and counts.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import ParamSpec, TypeVar

from pytest_benchmark.fixture import BenchmarkFixture

from solver.check import Report, check_files
from tests.check.helpers import intricate_rules
from tests.conftest import run_cli

TYPES, COUNTS, LOSING = 20_000, 100_000, 100

P = ParamSpec("P")
T = TypeVar("T")


def _once(
    benchmark: BenchmarkFixture, function: Callable[P, T], *args: P.args, **kwargs: P.kwargs
) -> T:
    """``function(*args, **kwargs)`` timed once, and what it returned."""
    result: T = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        function, args=args, kwargs=kwargs, rounds=1, iterations=1
    )
    return result


def test_check_20000_types_over_100000_counts(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    rules = tmp_path / "types.yaml"
    rules.write_text(
        "name: many types\ncharacteristics:\n"
        f"  kinematic_type:\n    values: [{', '.join(f'K{i}' for i in range(TYPES))}]\n"
        f"  sensor_count:\n    range: {{min: 1, max: {COUNTS}}}\n"
        "constraints:\n"
        + "".join(
            f"  - forbid: {{kinematic_type: K{i}, sensor_count: {i + 1}}}\n" for i in range(LOSING)
        ),
        encoding="utf-8",
    )
    report: Report = _once(benchmark, check_files, [rules])
    found = [f for f in report.findings if f.check == "dead-for-type"]
    assert len(found) == LOSING
    assert found[0].message.startswith("no valid K0 robot has sensor_count 1: excluded by")
    assert {f.check for f in report.findings} == {"bound", "dead-for-type"}


def test_check_20000_types_sharing_one_constraint_over_100000_counts(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    rules = tmp_path / "shared.yaml"
    rules.write_text(
        "name: one constraint\ncharacteristics:\n"
        f"  kinematic_type:\n    values: [{', '.join(f'K{i}' for i in range(TYPES))}]\n"
        "  sensor_type: {values: [camera, lidar]}\n"
        f"  sensor_count:\n    range: {{min: 1, max: {COUNTS}}}\n"
        "constraints:\n  - forbid: {sensor_type: lidar, sensor_count: 1}\n",
        encoding="utf-8",
    )
    report: Report = _once(benchmark, check_files, [rules])
    assert [f.check for f in report.findings] == ["bound"]


def test_count_symbolic_of_5000_components(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    counts = 5_000
    rules = tmp_path / "components.yaml"
    rules.write_text(
        "characteristics:\n  kinematic_type: {values: [A, B]}\n"
        f"  sensor_count:\n    range: {{min: 1, max: {counts}}}\n    components:\n"
        + "".join(f"      - {{name: c{i}, min: {i}, max: {i}}}\n" for i in range(1, counts + 1)),
        encoding="utf-8",
    )
    result = _once(benchmark, run_cli, "count", rules, "--symbolic", "-f", "json")
    data = json.loads(result.stdout)
    assert data["at_team_maxima"]["valid_robots"] == 2 * counts
    assert data["at_team_maxima"]["ui_configurations"] == 2 * counts
    assert data["at_team_maxima"]["equal_to_exact_count"] is True


def test_a_partial_check_of_an_intricate_rule_set_stops_at_its_budget(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    rules = tmp_path / "intricate.yaml"
    rules.write_text(intricate_rules(), encoding="utf-8")
    report: Report = _once(benchmark, check_files, [rules], time_limit=2.0, partial=True)
    assert report.stopped is not None
    assert report.stopped.message.startswith("check stopped after 2 s (limit 'check-seconds'")
