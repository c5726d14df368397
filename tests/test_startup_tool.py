"""tools/startup_cpu.py times start-up against a bare interpreter and the floor of its imports."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "startup_cpu.py"


def test_it_prints_each_process_with_its_ratio_to_the_bare_interpreter() -> None:
    done = subprocess.run(
        [sys.executable, str(SCRIPT), "--rounds", "1"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    )
    rows = [line for line in done.stdout.splitlines() if line.startswith("| ")][1:]
    names = [row.split("|")[1].strip() for row in rows]
    assert names == [
        "bare interpreter",
        "imports only: PyYAML, dataclasses",
        "imports only: PyYAML, dataclasses, lxml",
        "solve case3",
        "identify a URDF",
        "peer script",
        "identify peer script",
    ]
    assert rows[0].count("(1.0x)") == 2


def test_a_command_that_fails_is_named_and_ends_the_run(tmp_path: Path) -> None:
    spec = importlib.util.spec_from_file_location("startup_cpu", SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    command = [sys.executable, "-c", "raise SystemExit(3)"]
    with pytest.raises(SystemExit, match=r"raise SystemExit\(3\) failed \(3\)"):
        tool.cpu_ms(command, str(tmp_path), {})
