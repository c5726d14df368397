"""Benchmark: reading a team file whose types each select a maximum count.

100 kinematic types each select two sensor types and ``sensor_count: N`` (a maximum) out of a
rule set's 1..100,000 counts, against the same team over 1..1,000 counts (the same team file,
maximums scaled). The ratio ``100,000 counts / 1,000 counts`` (``tools/bench_table.py``) says
how much reading follows the counts rather than the file; a yaml.CSafeLoader parse of the
100,000-count team file is the peer for what reading the file alone costs.

Refusing a nest 16 MB long (``[`` or ``- `` repeated) against one 1 KB long: the pre-scan stops
at the 65th level, so what is left in proportion to the length is one pass over the bytes (the
NUL check, libyaml's copy of the text); a ratio near 16,000 would mean reading on, and one far
above it, work growing faster than the input (``[`` x 40,000 took 8 s before the pre-scan).

Run: ``python -m pytest benchmarks/bench_team.py``.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from solver import load_team
from solver.errors import InputError
from solver.files.yamlio import parse_document

TYPES = 100


def _write(directory: Path, counts: int) -> Path:
    names = [f"K{i}" for i in range(TYPES)]
    (directory / "rules.yaml").write_text(
        "name: many counts\ncharacteristics:\n"
        f"  kinematic_type:\n    values: [{', '.join(names)}]\n"
        "  sensor_type:\n    values: [A, B, C]\n"
        f"  sensor_count:\n    range: {{min: 1, max: {counts}}}\n",
        encoding="utf-8",
    )
    team = directory / "team.yaml"
    top = counts - counts // 100  # each type's maximum: all but the top 1% of counts
    team.write_text(
        "rules: rules.yaml\nteam:\n"
        + "".join(
            f"  {name}:\n    sensor_type: [A, B]\n    sensor_count: {top}\n" for name in names
        ),
        encoding="utf-8",
    )
    return team


@pytest.mark.parametrize("counts", [1_000, 100_000], ids=["1e3 counts", "1e5 counts"])
def test_read_team_of_100_types(benchmark: BenchmarkFixture, tmp_path: Path, counts: int) -> None:
    team_file = _write(tmp_path, counts)
    # pytest-benchmark ships no type hints.
    team = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        load_team, args=(team_file,), rounds=5, iterations=1
    )
    assert len(team.selections) == TYPES
    top = counts - counts // 100
    assert {len(s.domains[2]) for s in team.selections} == {top}


def test_parse_team_file_with_libyaml(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    text = _write(tmp_path, 100_000).read_text(encoding="utf-8")
    data = benchmark(yaml.load, text, Loader=yaml.CSafeLoader)
    assert len(data["team"]) == TYPES


# Refusing a nest: '[' and '- ' repeated, located where the 65th level opens.
NESTS = {"[": "1:66", "- ": "1:131"}


@pytest.mark.parametrize("length", [1_000, 16_000_000], ids=["1 KB", "16 MB"])
@pytest.mark.parametrize("opener", list(NESTS), ids=["flow", "block"])
def test_refuse_a_deep_nest(benchmark: BenchmarkFixture, opener: str, length: int) -> None:
    text = opener * (length // len(opener))

    def refuse() -> str:
        try:
            parse_document(text, "deep.yaml")
        except InputError as error:
            return str(error)
        return ""

    message = benchmark(refuse)
    assert message == f"deep.yaml:{NESTS[opener]}: nested more than 64 levels deep; refused"
