"""Benchmark: ``teleop-ui check`` on a large generated rule set.

50 kinematic types, 8 motion controls, 100 sensor types in 11 presentation groups, 1..50
sensors in 5 arrangements, and 200 constraints. The rule set is built so that what a correct
checker must report is known from its construction, independently of the checker:

* 187 ``forbid {type, sensor}`` pairs, all distinct, at most four per type and two per sensor
  type (no value dies, none is redundant), and 7 rules "motion control M_k only outside a
  block of five types" (``dead-for-type`` for 35 types);
* planted faults: a sensor type in no group (``coverage-gap``), a sensor type forbidden
  outright (``dead-value``) that is alone in its group (``dead-component``), a type voided by
  two rules (``void-type`` and one ``conflict``), a type forced to one motion control
  (``core-value``), a rule entailed by one of the pairs (``redundant-constraint``), a rule
  that excludes nothing (``tautology``), and a declared bound that differs from T.

A second benchmark checks 1,000 overlapping arrangements over 1..10,010 counts: the
``non-transitive`` check must find the 999 neighbouring pairs without comparing every pair of
arrangements value by value.

The same rule set is also checked with types, sensor types and pairs doubled twice
(:func:`test_check_doubled_rule_sets`): the time per doubling is the scaling claim.

Run: ``python -m pytest benchmarks/bench_check.py`` (timings), or with ``--benchmark-disable``
to only assert the findings.
"""

from __future__ import annotations

import re
import time
from collections import Counter
from pathlib import Path

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver.check import Report, check_files

TYPES = 50
MOTIONS = 8
SENSORS = 100
PAIRS = 187  # with the 13 planted and block rules: 200 constraints
BLOCK = 5  # types per "motion control M_k only outside this block" rule

VOID_TYPE = TYPES - 1  # K49: voided by two rules
CORE_TYPE = TYPES - 2  # K48: forced to motion control M0
GAP_SENSOR = SENSORS - 2  # S98: in no presentation group
DEAD_SENSOR = SENSORS - 1  # S99: forbidden outright, alone in the group 'spare'


def _type(i: int) -> str:
    return f"K{i:02d}"


def _sensor(j: int) -> str:
    return f"S{j:02d}"


def pairs(scale: int = 1) -> list[tuple[int, int]]:
    """Distinct (type, sensor) pairs: n -> (n mod 48s, 37 n mod 98s) is injective for
    n < lcm(48s, 98s) (37 is prime to 98s for s a power of two)."""
    types, sensors = TYPES * scale, SENSORS * scale
    return [(n % (types - 2), (37 * n) % (sensors - 2)) for n in range(PAIRS * scale)]


def blocks() -> list[tuple[int, list[int]]]:
    """Motion control k (1..7) is forbidden for the block of types 5(k-1) .. 5(k-1)+4."""
    return [(k, list(range(BLOCK * (k - 1), BLOCK * k))) for k in range(1, MOTIONS)]


def rule_text(scale: int = 1) -> str:
    """The generated rule set as a YAML file; ``scale`` multiplies types, sensor types and pairs
    (the planted faults are the last two types and sensor types)."""
    types, sensors = TYPES * scale, SENSORS * scale
    void_type, core_type, gap_sensor, dead_sensor = types - 1, types - 2, sensors - 2, sensors - 1
    lines = [
        "name: benchmark rule set",
        "bound: 20000  # wrong on purpose: T = 22000",
        "characteristics:",
        "  kinematic_type:",
        f"    values: [{', '.join(_type(i) for i in range(types))}]",
        "  motion_control:",
        f"    values: [{', '.join(f'M{k}' for k in range(MOTIONS))}]",
        "  sensor_type:",
        f"    values: [{', '.join(_sensor(j) for j in range(sensors))}]",
        "    components:",
    ]
    for group in range(sensors // 10):
        members = [j for j in range(10 * group, 10 * group + 10) if j < gap_sensor]
        lines += [
            f"      - name: g{group}",
            f"        values: [{', '.join(_sensor(j) for j in members)}]",
        ]
    lines += [
        "      - name: spare",
        f"        values: [{_sensor(dead_sensor)}]",
        "  sensor_count:",
        "    range: {min: 1, max: 50}",
        "    components:",
    ]
    for low, high, size in ((1, 5, 1), (6, 10, 2), (11, 15, 3), (16, 25, 5), (26, 50, 10)):
        lines += [
            f"      - name: clusters of {size}",
            f"        min: {low}",
            f"        max: {high}",
            f"        cluster_size: {size}",
        ]
    lines.append("constraints:")
    for i, j in pairs(scale):
        lines += [
            f"  - name: no {_sensor(j)} on {_type(i)}",
            f"    forbid: {{kinematic_type: {_type(i)}, sensor_type: {_sensor(j)}}}",
        ]
    for k, block in blocks():
        allowed = [_type(i) for i in range(types) if i not in block]
        lines += [
            f"  - name: M{k} only outside block {k}",
            f"    when: {{motion_control: M{k}}}",
            f"    require: {{kinematic_type: [{', '.join(allowed)}]}}",
        ]
    lines += [
        f"  - name: {_type(void_type)} few",
        f"    forbid: {{kinematic_type: {_type(void_type)}, sensor_count: {{max: 25}}}}",
        f"  - name: {_type(void_type)} many",
        f"    forbid: {{kinematic_type: {_type(void_type)}, sensor_count: {{min: 26}}}}",
        f"  - name: no {_sensor(dead_sensor)}",
        f"    forbid: {{sensor_type: {_sensor(dead_sensor)}}}",
        f"  - name: {_type(core_type)} uses M0",
        f"    when: {{kinematic_type: {_type(core_type)}}}",
        "    require: {motion_control: M0}",
        "  - name: S05 means S05 or S06",
        "    when: {sensor_type: S05}",
        "    require: {sensor_type: [S05, S06]}",
        "  - name: no S00 on K00 with few sensors",
        "    forbid: {kinematic_type: K00, sensor_type: S00, sensor_count: {max: 3}}",
    ]
    return "\n".join(lines) + "\n"


def expected_problems(scale: int = 1) -> set[tuple[str, str]]:
    """The warnings and errors the planted faults must produce (check, path)."""
    types, sensors = TYPES * scale, SENSORS * scale
    planted = PAIRS * scale + MOTIONS - 1  # index of the first planted constraint
    return {
        ("coverage-gap", f"characteristics.sensor_type.values[{sensors - 2}]"),
        ("dead-value", f"characteristics.sensor_type.values[{sensors - 1}]"),
        ("dead-component", f"characteristics.sensor_type.components[{sensors // 10}]"),
        ("void-type", f"characteristics.kinematic_type.values[{types - 1}]"),
        ("conflict", f"constraints[{planted}]"),
        ("tautology", f"constraints[{planted + 4}]"),
        ("redundant-constraint", f"constraints[{planted + 5}]"),
        ("bound-mismatch", "bound"),
    }


EXPECTED_PROBLEMS = expected_problems()


def expected_dead_for_type(scale: int = 1) -> set[tuple[str, str]]:
    """(type's path, characteristic) for every type that loses values to its constraints."""
    expected = {
        (f"characteristics.kinematic_type.values[{i}]", "sensor_type") for i, _ in pairs(scale)
    }
    expected |= {
        (f"characteristics.kinematic_type.values[{i}]", "motion_control")
        for _, block in blocks()
        for i in block
    }
    return expected


def _assert_findings(report: Report, scale: int = 1) -> None:
    problems = {(f.check, f.location.path) for f in report.findings if f.level != "info"}
    assert problems == expected_problems(scale)
    counts = Counter(f.check for f in report.findings)
    assert counts["bound"] == 1
    assert counts["core-value"] == 1
    dead_for_type = {
        (f.location.path, re.search(r" has (\w+) ", f.message).group(1))  # type: ignore[union-attr]  # every one says it
        for f in report.findings
        if f.check == "dead-for-type"
    }
    assert dead_for_type == expected_dead_for_type(scale)
    typed = TYPES * scale - 2  # every type but the void and core ones loses a sensor type
    assert counts["dead-for-type"] == typed + 35
    assert len(report.findings) == len(expected_problems(scale)) + 2 + typed + 35


def test_check_large_rule_set(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    rules = tmp_path / "large.yaml"
    rules.write_text(rule_text(), encoding="utf-8")
    # pytest-benchmark ships no type hints.
    report = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        check_files, args=([rules],), rounds=3, iterations=1
    )
    _assert_findings(report)


# CPU time, five rounds: the growth ratio is the claim, and three rounds of wall time on a
# shared machine moved it by half from run to run (1.9x then 2.8x for the same code).
@pytest.mark.benchmark(timer=time.process_time)
@pytest.mark.parametrize("scale", [1, 2, 4], ids=["x1", "x2", "x4"])
def test_check_doubled_rule_sets(benchmark: BenchmarkFixture, tmp_path: Path, scale: int) -> None:
    """The large rule set with types, sensor types and constraints doubled, then doubled again.

    The growth per doubling (x2/x1 and x4/x2 in the report of ``tools/bench_table.py``) is the
    claim: near-linear, at most 2.5; it was 2.9 and 5.3 while ``Analysis.classes`` walked every
    value against every condition of every constraint for each question.
    """
    rules = tmp_path / f"large-x{scale}.yaml"
    rules.write_text(rule_text(scale), encoding="utf-8")
    # pytest-benchmark ships no type hints.
    report = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        check_files, args=([rules],), rounds=5, iterations=1
    )
    _assert_findings(report, scale)


SLIDING = 1000  # arrangements of 15 counts, each overlapping the next by 5


def sliding_text() -> str:
    """Arrangement k covers 10k+1 .. 10k+15 of 1..10010: only neighbours overlap."""
    windows = "\n".join(
        f"      - {{name: w{k}, min: {10 * k + 1}, max: {10 * k + 15}}}" for k in range(SLIDING)
    )
    return (
        "name: sliding arrangements\ncharacteristics:\n  kind: {values: [A, B]}\n  n:\n"
        f"    range: {{min: 1, max: {10 * SLIDING + 10}}}\n    components:\n{windows}\n"
    )


def test_check_non_transitive_of_1000_sliding_arrangements(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    rules = tmp_path / "sliding.yaml"
    rules.write_text(sliding_text(), encoding="utf-8")
    # pytest-benchmark ships no type hints.
    report = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        check_files, args=([rules],), rounds=3, iterations=1
    )
    counts = Counter(f.check for f in report.findings)
    # Each neighbouring pair: 10k+1 ~ 10k+11 ~ 10k+16, and 5 counts in both.
    assert counts["non-transitive"] == SLIDING - 1
    assert counts["coverage-overlap"] == SLIDING - 1
