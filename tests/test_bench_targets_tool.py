"""tools/bench_targets.py makes the one table of every speed target from one benchmark run."""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "bench_targets.py"


@pytest.fixture(scope="module")
def tool() -> ModuleType:
    spec = importlib.util.spec_from_file_location("bench_targets", SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_targets"] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def _run(medians: dict[str, float], extra: dict[str, dict[str, Any]] | None = None) -> Any:
    return {
        "datetime": "2026-11-29T05:00:00",
        "machine_info": {"cpu": {"brand_raw": "a test CPU", "count": 2}},
        "benchmarks": [
            {"name": name, "stats": {"median": median}, "extra_info": (extra or {}).get(name, {})}
            for name, median in medians.items()
        ],
    }


def _row(text: str, what: str) -> list[str]:
    line = next(line for line in text.splitlines() if f"| {what} |" in line)
    return [cell.strip() for cell in line.split("|")[1:-1]]


def test_a_speedup_target_is_the_peers_median_over_ours_with_its_floor(tool: ModuleType) -> None:
    cpu = "test_whole_process_cpu[{}]".format
    run = tool.Run.of(
        _run(
            {
                cpu("peer script"): 0.050,
                cpu("solve case3"): 0.040,  # 50 / 40 = 1.25x: met at >= 1.2x
                cpu("imports only: PyYAML, dataclasses"): 0.025,  # floor 50 / 25 = 2x
            }
        )
    )
    row = _row(tool.table(run), "`teleop-ui solve case3`, whole process, CPU")
    assert row[0] == "42.3"
    assert row[3:] == [">= 1.2x", "2.00x", "1.25x", "met"]


def test_a_growth_target_takes_the_worst_doubling_and_can_be_missed(tool: ModuleType) -> None:
    names = [f"test_check_doubled_rule_sets[x{n}]" for n in (1, 2, 4)]
    run = tool.Run.of(_run(dict(zip(names, [0.1, 0.2, 0.52], strict=True))))  # 2.0x, 2.6x
    row = _row(tool.table(run), "`check` growth per doubling of the rule set (x1 -> x2 -> x4)")
    assert row[3:] == ["<= 2.5x", "2.00x", "2.60x", "**missed**"]


def test_a_figure_recorded_by_the_benchmark_is_read_from_its_extra_info(tool: ModuleType) -> None:
    name = "test_batch_whole_process_two_workers_against_one[400 teams]"
    run = tool.Run.of(_run({name: 1.0}, {name: {"j2_over_j1": 1.7}}))
    row = _row(tool.table(run), "`batch -j2` over `batch -j1`, 400 teams of Case 3, wall clock")
    assert row[3:] == [">= 1.6x", "2.00x", "1.70x", "met"]


def test_a_target_the_run_did_not_measure_says_so(tool: ModuleType) -> None:
    text = tool.table(tool.Run.of(_run({})))
    assert f"0 of {len(tool.TARGETS)} targets measured" in text
    row = _row(text, "`robots`, every robot of 3,610,000 listed, byte-identical")
    assert row[5:] == ["not in this run", ""]


def test_the_filter_names_every_benchmark_function_a_target_reads(tool: ModuleType) -> None:
    needed = tool.needed()
    assert "test_whole_process_cpu" in needed
    assert "test_count_rings_in_several_characteristics" in needed
    assert all("[" not in name for name in needed)
    collected = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "benchmarks",
            "--collect-only",
            "-q",
            "-p",
            "no:cacheprovider",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    functions = {
        line.split("::")[-1].split("[")[0] for line in collected.splitlines() if "::" in line
    }
    assert set(needed) <= functions  # no target reads a benchmark that does not exist


def test_write_replaces_only_the_table_between_its_markers(
    tool: ModuleType, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    docs = tmp_path / "benchmarks.md"
    docs.write_text(f"# Benchmarks\n\nbefore\n{tool.START}\nold table\n{tool.END}\nafter\n")
    monkeypatch.setattr(tool, "DOCS", docs)
    run = tmp_path / "run.json"
    run.write_text(json.dumps(_run({})))
    assert tool.main([str(run), "--write"]) == 0
    text = docs.read_text()
    assert "old table" not in text
    assert text.startswith("# Benchmarks\n\nbefore\n<!-- targets -->\nOne run, 2026-11-29")
    assert text.endswith("<!-- /targets -->\nafter\n")


def test_the_docs_hold_the_table_block() -> None:
    text = (ROOT / "docs" / "benchmarks.md").read_text(encoding="utf-8")
    assert text.count("<!-- targets -->") == 1
    assert text.count("<!-- /targets -->") == 1
