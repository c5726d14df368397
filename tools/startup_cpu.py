"""Whole-process CPU time of teleop-ui's start-up against a bare interpreter and the floor.

Runs, with the interpreter that runs this script, each of these as a child process, in turns
(round after round, so that all of them see the same machine), and prints the median and the
minimum CPU time of each (user + system, from the kernel's accounting) and its ratio to the
bare interpreter:

* a bare interpreter (``python -c 'print(872)'``);
* the floor: an interpreter that only imports PyYAML and ``dataclasses``, which ``solve``
  cannot do without, and the same with lxml's ``etree``, which ``identify`` adds;
* ``python -m solver solve case3`` and ``python -m solver identify`` of a URDF;
* ``tools/peer_case3.py``, Case 3 written directly with PyYAML and python-constraint2, and
  ``tools/peer_identify.py``, the example URDF read directly with lxml.

The children start in an empty temporary folder, so ``python -m solver`` is the installed
package, never a source tree in the current folder. Measure a user's install by running this
script with that install's interpreter: an editable install (``pip install -e``, the test
venv) loads its import finder in every interpreter, the bare one included, which raises the
bare figure and lowers every ratio.

    .venv/bin/python tools/startup_cpu.py [--rounds 25]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def commands(python: str) -> dict[str, list[str]]:
    """What is measured, by name; the first is the bare interpreter."""
    return {
        "bare interpreter": [python, "-c", "print(872)"],
        "imports only: PyYAML, dataclasses": [python, "-c", "import yaml, dataclasses"],
        "imports only: PyYAML, dataclasses, lxml": [
            python,
            "-c",
            "import yaml, dataclasses, lxml.etree",
        ],
        "solve case3": [python, "-m", "solver", "solve", "case3"],
        "identify a URDF": [
            python,
            "-m",
            "solver",
            "identify",
            str(ROOT / "examples" / "diff_drive_lidar.urdf"),
        ],
        "peer script": [python, str(ROOT / "tools" / "peer_case3.py")],
        "identify peer script": [python, str(ROOT / "tools" / "peer_identify.py")],
    }


def cpu_ms(command: list[str], folder: str, environment: dict[str, str]) -> float:
    """CPU milliseconds of one run of ``command``; SystemExit naming it if it fails."""
    child = subprocess.Popen(
        command, cwd=folder, env=environment, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    assert child.stderr is not None
    errors = child.stderr.read()
    child.stderr.close()
    _, status, usage = os.wait4(child.pid, 0)
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode:
        raise SystemExit(f"{' '.join(command)} failed ({child.returncode}): {errors.decode()}")
    return (usage.ru_utime + usage.ru_stime) * 1000


def measure(rounds: int) -> dict[str, list[float]]:
    """CPU milliseconds of each command, one per round (after one round not counted)."""
    # As after `pip install`: bytecode written and used; nothing from a source tree.
    environment = {
        k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")
    }
    runs = commands(sys.executable)
    times: dict[str, list[float]] = {name: [] for name in runs}
    with tempfile.TemporaryDirectory() as folder:
        for round_ in range(rounds + 1):
            for name, command in runs.items():
                spent = cpu_ms(command, folder, environment)
                if round_:
                    times[name].append(spent)
    return times


def table(times: dict[str, list[float]]) -> str:
    """The Markdown table: median and minimum of each, and their ratios to the first."""
    bare = next(iter(times.values()))
    bare_median, bare_min = statistics.median(bare), min(bare)
    lines = [
        "| CPU time of the whole process | median | min |",
        "|---|---:|---:|",
    ]
    for name, spent in times.items():
        median, least = statistics.median(spent), min(spent)
        lines.append(
            f"| {name} | {median:.1f} ms ({median / bare_median:.1f}x) "
            f"| {least:.1f} ms ({least / bare_min:.1f}x) |"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--rounds", type=int, default=25, help="rounds counted (default 25)")
    args = parser.parse_args(argv)
    if args.rounds < 1:
        parser.error("--rounds must be at least 1")
    print(f"{sys.executable} (Python {sys.version.split()[0]}), {args.rounds} rounds")
    print(table(measure(args.rounds)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
