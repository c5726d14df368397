"""Benchmark: overlapping components, each value in two, as values per characteristic double.

Three characteristics of N values each, with components that are windows of four values
sliding by two (w_s holds values 2s .. 2s + 3), so every value but the first two and the last
two is in two components. From the construction alone: N^3 valid robots; a characteristic's
fewest windows serving all its values are the N / 4 disjoint ones (no window holds values
four apart, so values 0, 4, 8, ... need one each), and three characteristics need
(N / 4)^3 configurations: no cover of the product is smaller than the product of those
packings.

Counting (``solve(count_only=True)``, what ``teleop-ui count`` does) should grow by at most
2.5x per doubling of N: the three characteristics vary independently, so their covers are found
apart and multiplied, and the 64,000 or 512,000 robot classes are never listed. Solving lists
the configurations, which grow 8x per doubling: its ratio is reported beside that. It was 6.7 s
at 40 values and 141 s at 80 (x21), half of it a quadratic filter before a single program over
every class.

Rings in several characteristics (issue 42). Each characteristic of N values in N / 4 blocks
of four (a, b, c, d) and three components per block that overlap in a ring: {a, b, d},
{b, c, d}, {c, a}, so every value is in two components and any two values of a block share
one. A block alone needs two components (each misses one value), but no two values of it are
apart, so it packs only one: a ring's cover is not as large as its packing, and covers no
longer multiply. From the construction alone: blocks are apart (no component spans two), so
the fewest configurations add over each choice of one block per characteristic; for two
characteristics a pair of blocks needs 3 (nine elements of four keys, each key in four of
them: at least 9 / 4; the diagonal serves all), so 3 (N / 4)^2; for three, a triple needs 5
(no 4 of its 27 keys serve its 27 elements, the five (0, 0, 0), (0, 1, 1), (1, 0, 1),
(1, 1, 0), (2, 2, 2) do: ``tests/core/test_cover.py`` tries every set of keys), so
5 (N / 4)^3. Counting was one HiGHS program over the product of the characteristics (0.47 s at
80 values in two, refused after 10 s at 160); it should grow by at most 2.5x per doubling up
to 640 values. The medians' growth per doubling is printed at the end of the module (``-s``).

Run: ``python -m pytest benchmarks/bench_overlap.py --benchmark-only -p no:cacheprovider -s``.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml
from pytest_benchmark.fixture import BenchmarkFixture

from solver import Team, load_team, solve

CHARACTERISTICS = 3


def rules(values: int) -> dict[str, object]:
    characteristics: dict[str, object] = {"kinematic_type": {"values": ["T0"]}}
    for c in range(CHARACTERISTICS):
        names = [f"c{c}v{i}" for i in range(values)]
        characteristics[f"c{c}"] = {
            "values": names,
            "components": [
                {"name": f"c{c}w{s}", "values": names[2 * s : 2 * s + 4]}
                for s in range(values // 2 - 1)
            ],
        }
    return {"name": f"windows over {values}", "characteristics": characteristics}


def rings(values: int, characteristics: int) -> dict[str, object]:
    """Rings of three components over each block of four values (see the module docstring)."""
    found: dict[str, object] = {"kinematic_type": {"values": ["T0"]}}
    for c in range(characteristics):
        names = [f"c{c}v{i}" for i in range(values)]
        components = []
        for b in range(values // 4):
            a, b_, c_, d = names[4 * b : 4 * b + 4]
            components += [
                {"name": f"c{c}x{b}", "values": [a, b_, d]},
                {"name": f"c{c}y{b}", "values": [b_, c_, d]},
                {"name": f"c{c}z{b}", "values": [c_, a]},
            ]
        found[f"c{c}"] = {"values": names, "components": components}
    return {"name": f"rings over {values}", "characteristics": found}


# Configurations one choice of a block per characteristic needs, by how many characteristics.
RING_COVER = {1: 2, 2: 3, 3: 5}


def team(folder: Path, values: int, made: dict[str, object] | None = None) -> Team:
    """The windows team of ``values`` (or the rule set ``made``) written to ``folder``."""
    (folder / "rules.yaml").write_text(
        yaml.safe_dump(rules(values) if made is None else made, sort_keys=False),
        encoding="utf-8",
    )
    (folder / "team.yaml").write_text("rules: rules.yaml\nteam:\n  T0: {}\n", encoding="utf-8")
    return load_team(folder / "team.yaml")


@pytest.fixture(scope="module")
def teams(tmp_path_factory: pytest.TempPathFactory) -> dict[int, Team]:
    made = {n: team(tmp_path_factory.mktemp(f"windows{n}"), n) for n in (20, 40, 80, 160)}
    solve(made[20])  # HiGHS and numpy imported once, outside the timings
    return made


@pytest.mark.parametrize("values", [20, 40, 80, 160])
def test_count_overlapping_windows(
    benchmark: BenchmarkFixture, teams: dict[int, Team], values: int
) -> None:
    solution = benchmark(solve, teams[values], count_only=True)
    assert solution.totals.valid_robots == values**CHARACTERISTICS
    assert solution.totals.ui_configurations == (values // 4) ** CHARACTERISTICS
    assert solution.totals.unserved_robots == 0


@pytest.mark.parametrize("values", [20, 40, 80])
def test_solve_overlapping_windows(
    benchmark: BenchmarkFixture, teams: dict[int, Team], values: int
) -> None:
    solution = benchmark(solve, teams[values])
    assert len(solution.configurations) == (values // 4) ** CHARACTERISTICS
    assert sum(c.robots for c in solution.configurations) == values**CHARACTERISTICS
    assert solution.proven_minimal


# ---- issue 42: rings in two and three characteristics ------------------------------------------
RING_VALUES = (80, 160, 320, 640)


@pytest.fixture(scope="module")
def ring_teams(tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[int, int], Team]:
    made = {
        (k, n): team(tmp_path_factory.mktemp(f"rings{k}x{n}"), n, rings(n, k))
        for k in (2, 3)
        for n in RING_VALUES
    }
    solve(made[2, 80], count_only=True)  # HiGHS imported once, outside the timings
    return made


@pytest.fixture(scope="module")
def medians() -> Iterator[dict[tuple[int, int], float]]:
    """Each ring benchmark's median, by (characteristics, values); their growth per doubling is
    printed when the module ends (nothing when timing is off)."""
    found: dict[tuple[int, int], float] = {}
    yield found
    for k in (2, 3):
        times = [found[k, n] for n in RING_VALUES if (k, n) in found]
        if len(times) < len(RING_VALUES):
            continue
        growth = ", ".join(f"{b / a:.2f}x" for a, b in itertools.pairwise(times))
        shown = ", ".join(f"{t * 1e3:.2f} ms" for t in times)
        print(f"\nrings in {k} characteristics, {RING_VALUES} values: {shown}; growth {growth}")


@pytest.mark.parametrize("characteristics", [2, 3])
@pytest.mark.parametrize("values", RING_VALUES)
def test_count_rings_in_several_characteristics(
    benchmark: BenchmarkFixture,
    ring_teams: dict[tuple[int, int], Team],
    medians: dict[tuple[int, int], float],
    characteristics: int,
    values: int,
) -> None:
    solution = benchmark(solve, ring_teams[characteristics, values], count_only=True)
    blocks = values // 4
    assert solution.totals.valid_robots == values**characteristics
    assert (
        solution.totals.ui_configurations == RING_COVER[characteristics] * blocks**characteristics
    )
    assert solution.totals.unserved_robots == 0
    if benchmark.stats is not None:
        medians[characteristics, values] = benchmark.stats.stats.median
