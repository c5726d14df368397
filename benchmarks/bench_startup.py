"""Benchmark: start-up of ``teleop-ui solve case3`` against a bare interpreter, one run.

Both are whole processes started the same way from the same interpreter, so the ratio
``solve / bare`` (reported by ``tools/bench_table.py``; goal at most 4) is what our imports and
work add to what any Python program pays, whatever the machine.

Run: ``python -m pytest benchmarks/bench_startup.py``.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from pytest_benchmark.fixture import BenchmarkFixture

ROOT = Path(__file__).resolve().parent.parent
# As a user runs it after `pip install .`: bytecode is cached (pip compiles it), so let Python
# write and use it even where the environment turns that off.
ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _run(command: list[str]) -> str:
    return subprocess.run(
        command, cwd=ROOT, env=ENVIRONMENT, check=True, capture_output=True, text=True
    ).stdout


def test_start_bare_interpreter(benchmark: BenchmarkFixture) -> None:
    output = benchmark(_run, [sys.executable, "-c", "print(872)"])
    assert output == "872\n"


def test_start_solve_case3(benchmark: BenchmarkFixture) -> None:
    command = [sys.executable, "-m", "solver", "solve", "rules/teams/case3.yaml"]
    _run(command)  # compile bytecode first
    output = benchmark(_run, command)
    assert "total                        872                102" in output
