"""Benchmark: how ``teleop-ui check`` grows along each axis of a rule set (issue 29, item 2).

Four families of generated rule sets, each at three sizes that double; what ``check`` must
report is known from how each was built, and asserted. The claim is the growth per doubling
(the ratio of neighbouring sizes in one run; docs/benchmarks.md has them): at most 2.5 on all
four. It was exponential in chained constraints (x2.4 per added characteristic, 29.7 s at 18),
quadratic in characteristics (17.8 s at 10,000) and in kinematic types (44.6 s at 6,144),
while python-constraint answered the questions; then about 4 on chained constraints while each
question was a solve over the whole chain.

* **types**: T kinematic types, one ``forbid {type, sensor}`` each: ``dead-for-type`` per type.
* **values**: V sensor types for 10 kinematic types, 5 forbidden per type, one forbidden
  outright: ``dead-for-type`` per type and one ``dead-value``.
* **characteristics**: C characteristics of three values; every tenth has its first value
  forbidden: ``dead-value`` each, the others are free.
* **chained**: N characteristics of three values, each linked to the next by a constraint
  (``a`` is never followed by ``c``), named in shuffled order (python-constraint assigns
  variables by name, so a chain it walks out of order was its worst case); every third starts
  a trap of four constraints that makes its ``a`` impossible: ``dead-value`` each, with those
  four constraints as the reason.

Run: ``python -m pytest benchmarks/bench_check_growth.py`` (timings), or with
``--benchmark-disable`` to only assert the findings.
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable
from pathlib import Path

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver.check import Report, check_files

# Sizes per axis: each family at n, 2n, 4n.
# The largest: 2,000 types (one constraint each, the `constraints` limit), 40,000 values, 997
# characteristics and 997 chained (the `characteristics` limit is 1,000 with the type).
SIZES = {"types": 500, "values": 10_000, "characteristics": 249, "chained": 249}
DOUBLINGS = (1, 2, 4)


def types_text(count: int) -> tuple[str, set[tuple[str, str]]]:
    kinds = [f"K{i}" for i in range(count)]
    lines = [
        "name: types",
        "characteristics:",
        f"  kinematic_type:\n    values: [{', '.join(kinds)}]",
        f"  sensor:\n    values: [{', '.join(f'S{j}' for j in range(20))}]",
        "constraints:",
    ]
    lines += [
        f"  - forbid: {{kinematic_type: {kind}, sensor: S{i % 20}}}" for i, kind in enumerate(kinds)
    ]
    expected = {
        ("dead-for-type", f"characteristics.kinematic_type.values[{i}]") for i in range(count)
    }
    return "\n".join(lines) + "\n", expected


def values_text(count: int) -> tuple[str, set[tuple[str, str]]]:
    kinds = [f"K{i}" for i in range(10)]
    lines = [
        "name: values",
        "characteristics:",
        f"  kinematic_type:\n    values: [{', '.join(kinds)}]",
        f"  sensor:\n    values: [{', '.join(f'S{j}' for j in range(count))}]",
        "constraints:",
        f"  - forbid: {{sensor: S{count - 1}}}",
    ]
    step = count // 60
    lines += [
        f"  - forbid: {{kinematic_type: {kind}, sensor: S{(5 * i + j) * step}}}"
        for i, kind in enumerate(kinds)
        for j in range(5)
    ]
    expected = {("dead-value", f"characteristics.sensor.values[{count - 1}]")}
    expected |= {
        ("dead-for-type", f"characteristics.kinematic_type.values[{i}]") for i in range(10)
    }
    return "\n".join(lines) + "\n", expected


def characteristics_text(count: int) -> tuple[str, set[tuple[str, str]]]:
    lines = ["name: characteristics", "characteristics:", "  kinematic_type:\n    values: [K1, K2]"]
    lines += [f"  c{i}:\n    values: [a, b, c]" for i in range(count - 1)]
    lines.append("constraints:")
    dead = range(0, count - 1, 10)
    lines += [f"  - forbid: {{c{i}: a}}" for i in dead]
    expected = {("dead-value", f"characteristics.c{i}.values[0]") for i in dead}
    return "\n".join(lines) + "\n", expected


def chained_text(count: int) -> tuple[str, set[tuple[str, str]]]:
    order = list(range(count))
    random.Random(count).shuffle(order)
    name = [f"x{order[i]:04d}" for i in range(count)]
    lines = ["name: chained", "characteristics:", "  kinematic_type:\n    values: [K1, K2]"]
    lines += [f"  {name[i]}:\n    values: [a, b, c]" for i in range(count)]
    lines.append("constraints:")
    traps = range(0, count - 2, 3)
    # Each characteristic is linked to the next: by "a is never followed by c", or, inside a
    # trap, by the trap's own "when a, require b" (a link there would be redundant).
    lines += [
        f"  - forbid: {{{name[i]}: a, {name[i + 1]}: c}}"
        for i in range(count - 1)
        if (i - 1) not in traps
    ]
    for i in traps:
        first, second, third = name[i], name[i + 1], name[i + 2]
        lines += [
            f"  - forbid: {{{first}: a, {second}: b}}",
            f"  - when: {{{second}: a}}\n    require: {{{third}: b}}",
            f"  - forbid: {{{first}: a, {third}: b}}",
        ]
    expected = {("dead-value", f"characteristics.{name[i]}.values[0]") for i in traps}
    return "\n".join(lines) + "\n", expected


FAMILIES: dict[str, Callable[[int], tuple[str, set[tuple[str, str]]]]] = {
    "types": types_text,
    "values": values_text,
    "characteristics": characteristics_text,
    "chained": chained_text,
}


def _problems(report: Report) -> set[tuple[str, str]]:
    return {(f.check, f.location.path) for f in report.findings if f.check != "bound"}


@pytest.mark.parametrize("scale", DOUBLINGS, ids=[f"x{s}" for s in DOUBLINGS])
@pytest.mark.parametrize("axis", list(FAMILIES))
def test_check_growth(benchmark: BenchmarkFixture, tmp_path: Path, axis: str, scale: int) -> None:
    text, expected = FAMILIES[axis](SIZES[axis] * scale)
    rules = tmp_path / f"{axis}.yaml"
    rules.write_text(text, encoding="utf-8")
    # pytest-benchmark ships no type hints.
    report = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        check_files, args=([rules],), rounds=3, iterations=1
    )
    assert _problems(report) == expected
    if axis == "chained":
        # Each trap's reason is its own four constraints: the link and the trap's three.
        for finding in report.findings:
            if finding.check == "dead-value":
                assert len(re.findall(r"'constraint \d+'", finding.message)) == 4
