"""Benchmark: small teams and whole processes against their peers (issue 29, items 5 and 6).

All in CPU time, so a busy machine does not move the figures:

* Case 3 in-process, ``solve(load_team(...))``, against ``tools/peer_case3.py`` (PyYAML's C
  loader and python-constraint2, written directly); also with the rule set read anew each time
  (``parse_rules`` + ``parse_team``: the first team of a process), as the rule set is otherwise
  read once per process while its text is unchanged. Target: the tool at least 3x faster.
* Whole processes (CPU time of the child, from the kernel's accounting), those of
  ``tools/startup_cpu.py``: a bare interpreter, ``teleop-ui solve case3``, the peer script and
  ``teleop-ui identify`` of a URDF. Target: ``solve`` and ``identify`` at most 3x the bare
  interpreter. Beside them, the floor any program with the tool's dependencies pays before
  doing anything: an interpreter that only imports PyYAML and ``dataclasses`` (what ``solve``
  cannot do without), and the same with lxml's ``etree`` (``identify``'s floor).
* What a ``batch`` worker does per team (:func:`solver.reporting.batch.run_job`: hashes, read,
  solve, the listing JSON written durably and the stamp) for 50 copies of Case 3, against a
  plain loop over the Python API (``load_team``, ``solve``, compact ``json.dumps`` of
  ``Solution.to_dict()`` into a file). Target (issue 42): the worker's CPU per team at most
  the loop's.
* ``teleop-ui batch`` of 400 copies of Case 3 as a whole process with ``-j1`` and ``-j2``,
  alternated: the wall-clock ratio (target: ``-jN`` on N cores at least 0.8N x ``-j1``) and
  the CPU per team of all its processes. Figures in ``extra_info`` and printed; counts
  checked, no time asserted.

The ratios are printed by ``tools/bench_table.py``. Run:
``python -m pytest benchmarks/bench_small.py --benchmark-only``.
"""

from __future__ import annotations

import importlib.util
import json
import os
import resource
import shutil
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver import load_team, solve
from solver.core.rules import parse_rules
from solver.core.team import parse_team
from solver.files.yamlio import load_document
from solver.reporting.batch import find_teams, make_jobs, run_job
from tests.conftest import ROOT, RULES, TEAMS

CASE3 = TEAMS / "case3.yaml"
COPIES = 50
# As a user runs it after `pip install .`: bytecode is cached, so let Python write and use it.
ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _tool(name: str) -> ModuleType:
    """A script of tools/ (no package) as a module."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "tools" / f"{name}.py")
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _children_cpu() -> float:
    """CPU seconds of the children this process has waited for."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _case3() -> tuple[int, int]:
    totals = solve(load_team(CASE3)).totals
    return totals.valid_robots, totals.ui_configurations


def _case3_rules_read_anew() -> tuple[int, int]:
    rules = parse_rules(load_document(RULES / "paper.yaml", display="rules/paper.yaml"))
    totals = solve(parse_team(load_document(CASE3), rules)).totals
    return totals.valid_robots, totals.ui_configurations


@pytest.mark.benchmark(timer=time.process_time)
def test_case3_read_and_solved_in_process(benchmark: BenchmarkFixture) -> None:
    assert benchmark(_case3) == (872, 102)


@pytest.mark.benchmark(timer=time.process_time)
def test_case3_read_and_solved_in_process_rules_read_anew(benchmark: BenchmarkFixture) -> None:
    assert benchmark(_case3_rules_read_anew) == (872, 102)


@pytest.mark.benchmark(timer=time.process_time)
def test_case3_python_constraint_peer_in_process(benchmark: BenchmarkFixture) -> None:
    assert benchmark(_tool("peer_case3").solve_case3, CASE3) == (872, 102)


def _run(command: list[str]) -> str:
    return subprocess.run(
        command, cwd=ROOT, env=ENVIRONMENT, check=True, capture_output=True, text=True
    ).stdout


# What each process of tools/startup_cpu.py (the one list of what start-up is measured
# against) must print, so that each timed run is known to have done its work.
_PRINTS: dict[str, Callable[[str], bool]] = {
    "bare interpreter": lambda out: out == "872\n",
    "imports only: PyYAML, dataclasses": lambda out: out == "",
    "imports only: PyYAML, dataclasses, lxml": lambda out: out == "",
    "solve case3": lambda out: "total                        872                102" in out,
    "identify a URDF": lambda out: "UGV" in out,
    "peer script": lambda out: out == "872 102\n",
    "identify peer script": lambda out: out == "UGV lidar:1 Driving\n",
}
PROCESSES: dict[str, tuple[list[str], Callable[[str], bool]]] = {
    name: (command, _PRINTS[name])
    for name, command in _tool("startup_cpu").commands(sys.executable).items()
}


@pytest.mark.benchmark(timer=_children_cpu)
@pytest.mark.parametrize("name", list(PROCESSES))
def test_whole_process_cpu(benchmark: BenchmarkFixture, name: str) -> None:
    command, expected = PROCESSES[name]
    _run(command)  # compile bytecode first
    output = benchmark.pedantic(  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
        _run, args=(command,), rounds=15, iterations=1, warmup_rounds=1
    )
    assert expected(output)


def _copies(folder: Path) -> list[Path]:
    teams = folder / "teams"
    teams.mkdir()
    shutil.copy(RULES / "paper.yaml", folder / "paper.yaml")
    text = CASE3.read_text(encoding="utf-8")
    for index in range(COPIES):
        (teams / f"case3-{index:02d}.yaml").write_text(text, encoding="utf-8")
    return sorted(teams.iterdir())


@pytest.mark.benchmark(timer=time.process_time)
def test_batch_worker_solves_50_teams(benchmark: BenchmarkFixture, tmp_path: Path) -> None:
    _copies(tmp_path)
    jobs = make_jobs(find_teams([str(tmp_path / "teams")]), tmp_path / "out", force=True)

    def work() -> list[tuple[str, int | None]]:
        return [(o.action, o.row.valid_robots) for o in map(run_job, jobs)]

    outcomes = benchmark.pedantic(work, rounds=5, iterations=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    assert outcomes == [("solved", 872)] * COPIES


@pytest.mark.benchmark(timer=time.process_time)
def test_plain_loop_over_the_api_solves_50_teams(
    benchmark: BenchmarkFixture, tmp_path: Path
) -> None:
    files = _copies(tmp_path)
    out = tmp_path / "out"
    out.mkdir()

    def loop() -> list[int]:
        found = []
        for file in files:
            solution = solve(load_team(file))
            data = solution.to_dict()
            (out / f"{file.stem}.json").write_text(json.dumps(data), encoding="utf-8")
            found.append(data["totals"]["valid_robots"])
        return found

    assert benchmark.pedantic(loop, rounds=5, iterations=1) == [872] * COPIES  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints


# Teams of a whole batch: start-up (about 0.3 s of the batch, its forkserver and the first
# worker) is serial, so the smaller batch measures it beside the scaling, the larger one the
# scaling of the solving itself.
BATCH_COPIES = (400, 2000)


# Runs a command and prints the CPU seconds of it and every process below it: the workers
# are the forkserver's children and the forkserver outlives the batch, so the batch's own
# accounting misses them; as a subreaper this process inherits and waits for them all.
_ALL_CPU = """
import ctypes, os, resource, subprocess, sys
ctypes.CDLL(None).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)
while True:
    try:
        os.wait()
    except ChildProcessError:
        break
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(usage.ru_utime + usage.ru_stime)
"""


def _batch_process(teams: Path, out: Path, workers: int, copies: int) -> tuple[float, float]:
    """Wall-clock and CPU seconds (the batch and its workers) of one whole ``batch``."""
    shutil.rmtree(out, ignore_errors=True)
    started = time.perf_counter()
    command = [sys.executable, "-m", "solver", "batch", str(teams), "-o", str(out)]
    cpu = float(_run([sys.executable, "-c", _ALL_CPU, *command, f"-j{workers}"]))
    wall = time.perf_counter() - started
    rows = (out / "summary.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(rows) == copies
    assert all(",ok,Case 3" in row and ",872,102," in row for row in rows), rows[:2]
    return wall, cpu


@pytest.mark.benchmark(timer=time.perf_counter)
@pytest.mark.parametrize("copies", BATCH_COPIES, ids=lambda n: f"{n} teams")
def test_batch_whole_process_two_workers_against_one(
    benchmark: BenchmarkFixture, tmp_path: Path, copies: int
) -> None:
    teams = tmp_path / "teams"
    teams.mkdir()
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")  # the team's `rules:`
    text = CASE3.read_text(encoding="utf-8")
    for index in range(copies):
        (teams / f"case3-{index:04d}.yaml").write_text(text, encoding="utf-8")
    figures: dict[int, list[tuple[float, float]]] = {1: [], 2: []}

    def pair() -> None:  # alternated: both see the same machine
        for workers in (1, 2):
            figures[workers].append(_batch_process(teams, tmp_path / "out", workers, copies))

    benchmark.pedantic(pair, rounds=5, iterations=1, warmup_rounds=1)  # type: ignore[no-untyped-call]  # pytest-benchmark has no hints
    wall = {n: sorted(w for w, _ in runs)[len(runs) // 2] for n, runs in figures.items()}
    cpu = {n: sorted(c for _, c in runs)[len(runs) // 2] for n, runs in figures.items()}
    benchmark.extra_info.update(
        {
            "teams": copies,
            "wall_j1_s": wall[1],
            "wall_j2_s": wall[2],
            "j2_over_j1": wall[1] / wall[2],
            "cpu_per_team_j1_ms": 1000 * cpu[1] / copies,
            "cpu_per_team_j2_ms": 1000 * cpu[2] / copies,
        }
    )
    print(benchmark.extra_info)
