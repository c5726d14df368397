"""Benchmark: drawing the radar chart, and batch runs with and without up-to-date skipping.

* the article's Case 3 as a PNG radar chart (figure built and rendered);
* a radar chart with a count spoke of 100,000 values (its cost must not follow the values);
* 40 copies of Case 3 solved by ``batch`` in one process (``--force``): JSON and summary;
* the same 40 teams again, all up to date: what a rerun costs (hashes, no solving).

Run: ``python -m pytest benchmarks/bench_reports.py`` (timings), or with
``--benchmark-disable`` to only assert the results.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from matplotlib.collections import LineCollection
from matplotlib.patches import PathPatch
from pytest_benchmark.fixture import BenchmarkFixture

from solver import load_team, solve
from solver.reporting.batch import find_teams, make_jobs, run_batch
from solver.reporting.chart import MIN_TICK_GAP
from solver.reporting.plot import figure_bytes, radar_figure
from tests.conftest import RULES, TEAMS

COPIES = 40


def test_radar_chart_of_case3_as_png(benchmark: BenchmarkFixture) -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))

    def draw() -> tuple[int, bytes]:
        figure = radar_figure(solution)
        regions = sum(isinstance(p, PathPatch) for p in figure.axes[0].patches)
        return regions, figure_bytes(figure, "png")

    regions, png = benchmark(draw)
    assert regions == 4
    assert png.startswith(b"\x89PNG")


def _teams(tmp_path: Path) -> Path:
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")
    folder = tmp_path / "teams"
    folder.mkdir()
    for index in range(COPIES):
        shutil.copy(TEAMS / "case3.yaml", folder / f"case3-{index:02d}.yaml")
    return folder


def test_batch_solves_40_teams_in_one_process(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    found = find_teams([str(_teams(tmp_path))])

    def run() -> list[tuple[str, int | None]]:
        jobs = make_jobs(found, tmp_path / "out", force=True)
        return [(o.action, o.row.valid_robots) for o in run_batch(jobs, workers=1)]

    outcomes = benchmark(run)
    assert outcomes == [("solved", 872)] * COPIES


def test_batch_rerun_of_40_unchanged_teams_solves_nothing(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    found = find_teams([str(_teams(tmp_path))])
    list(run_batch(make_jobs(found, tmp_path / "out"), workers=1))

    def rerun() -> list[tuple[str, int | None]]:
        jobs = make_jobs(found, tmp_path / "out")
        return [(o.action, o.row.ui_configurations) for o in run_batch(jobs, workers=1)]

    outcomes = benchmark(rerun)
    assert outcomes == [("up to date", 102)] * COPIES


WIDE = 100_000  # the most values a whole-number characteristic may have


def test_radar_chart_of_a_count_spoke_of_100000_values_as_png(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    (tmp_path / "wide.yaml").write_text(
        "characteristics:\n  kind: {values: [Rover, Drone]}\n"
        f"  count: {{range: {{min: 1, max: {WIDE}}}}}\n",
        encoding="utf-8",
    )
    (tmp_path / "t.yaml").write_text(
        f"rules: wide.yaml\nteam:\n  Rover: {{count: {WIDE}}}\n  Drone: {{count: [1, 2, 3]}}\n",
        encoding="utf-8",
    )
    solution = solve(load_team(tmp_path / "t.yaml"))

    def draw() -> tuple[int, int, bytes]:
        figure = radar_figure(solution)
        ax = figure.axes[0]
        ticks = next(c for c in ax.collections if c.get_label() == "_ticks count")
        labels = sum(str(t.get_label()) == "tick count" for t in ax.texts)
        assert isinstance(ticks, LineCollection)
        return len(ticks.get_segments()), labels, figure_bytes(figure, "png")

    marks, labels, png = benchmark(draw)
    assert marks == labels  # a mark per label, not per value
    assert 2 <= labels <= 1 + int(1 / MIN_TICK_GAP)
    assert png.startswith(b"\x89PNG")
