"""``teleop-ui`` itself (:func:`solver.cli.main`): the command table and ``--help``, what a
command imports at start-up, ``python -m solver`` as the same command line, and output streams
that close or fill, for every command.
"""

from __future__ import annotations

import functools
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import ROOT, TEAMS, run_cli

# ---- the command table, start-up, python -m solver -------------------------------------------


def test_help_lists_the_commands_of_the_table_in_its_order() -> None:
    from solver.cli import COMMANDS

    result = run_cli("--help")
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    # Each command starts a line of its own, indented by four spaces, with its help beside it.
    listed = [line.split()[0] for line in lines if line.startswith("    ") and line[4] != " "]
    assert listed == list(COMMANDS) == sorted(COMMANDS)


def test_the_command_table_lists_each_command_module_and_a_helper_module_is_no_command() -> None:
    from solver.cli import COMMANDS

    modules = sorted(p.stem for p in (ROOT / "solver" / "cli").glob("*.py"))
    helpers = [name for name in modules if name.startswith("_")]
    assert sorted(COMMANDS) == [name for name in modules if name not in helpers]
    assert all(module == f"solver.cli.{name}" for name, module in COMMANDS.items())


def test_python_dash_m_solver_is_the_same_command_line() -> None:
    script = subprocess.run(
        [Path(sys.executable).parent / "teleop-ui", "reproduce"],
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=False,
    )
    assert script.returncode == 0
    assert script.stdout == run_cli("reproduce").stdout


# What a plain URDF's `identify` has no use for: UI configurations, layouts, the live graph,
# the xacro sandbox, the children that read bags, an SRDF's reader (start-up time, issue 29).
NOT_FOR_A_URDF = (
    "solver.solving.assignment",
    "solver.solving.solution",
    "solver.identify.fleet",
    "solver.identify.limited",
    "solver.identify.readers.srdf",
    "solver.identify.xacro.compiler",
    "solver.layouts",
    "solver.live",
)


@functools.cache
def _commands_in_a_fresh_interpreter() -> tuple[str, list[str], str, list[str]]:
    """`identify` of a URDF then `solve case3`, in one fresh interpreter: each one's status and
    the project modules it loaded."""
    script = (
        "import contextlib, io, json, sys\n"
        "from solver.cli import main\n"
        "loaded = []\n"
        "for argv in (['identify', 'examples/diff_drive_lidar.urdf'], ['solve', 'case3']):\n"
        "    before = set(sys.modules)\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        status = main(argv)\n"
        "    new = sorted(m for m in set(sys.modules) - before if m.startswith('solver'))\n"
        "    loaded.append((str(status), new))\n"
        "print(json.dumps(loaded))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, check=True
    )
    (identify_status, identify_loaded), (solve_status, solve_loaded) = json.loads(done.stdout)
    return identify_status, identify_loaded, solve_status, solve_loaded


def test_a_command_imports_its_own_module_and_no_other_command() -> None:
    _, _, status, loaded = _commands_in_a_fresh_interpreter()
    assert status == "0"
    assert "solver.cli.solve" in loaded
    assert "solver.cli.watch" not in loaded
    assert "solver.cli.identify" not in loaded
    # Nor what Case 3 does not use: HiGHS's exact cover, assigning a robot.
    assert "solver.core.cover" not in loaded
    assert "solver.solving.assignment" not in loaded


def test_a_command_that_loads_numpy_starts_no_openblas_threads_unless_the_user_asks() -> None:
    """numpy's OpenBLAS starts a thread per core on import, spinning while numpy loads; no
    command multiplies matrices. The process's own threads are counted by the kernel."""
    script = (
        "import os, sys\n"
        "from solver.cli import main\n"
        "sys.stdout = open(os.devnull, 'w')\n"
        "assert main(['robots', 'case3']) == 0\n"
        "import numpy\n"
        "print(len(os.listdir('/proc/self/task')), os.environ['OPENBLAS_NUM_THREADS'],"
        " file=sys.stderr)\n"
    )

    def threads(**given: str) -> str:
        env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"} | given
        found = subprocess.run(
            [sys.executable, "-c", script],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        return found.stderr.strip()

    assert threads() == "1 1"
    if (os.cpu_count() or 1) > 1:  # a user's own setting stands
        assert threads(OPENBLAS_NUM_THREADS="2") == "2 2"


def test_identifying_a_urdf_loads_no_configurations_layouts_live_graph_nor_xacro_sandbox() -> None:
    status, loaded, _, _ = _commands_in_a_fresh_interpreter()
    assert status == "0"
    assert "solver.identify.identification" in loaded
    unneeded = [m for m in loaded if m.startswith(NOT_FOR_A_URDF)]
    assert unneeded == []


# ---- output streams that close or fill: real processes ---------------------------------------


WRITING_COMMANDS = [
    ["solve", "case3", "--list"],
    ["robots", str(TEAMS / "search-and-rescue.yaml")],
    ["check", str(ROOT / "rules" / "paper.yaml")],
    ["export", "case1", "--format", "uvl"],
    ["identify", str(ROOT / "examples" / "diff_drive_lidar.urdf")],
]


def _solver(*args: str, stdout: Any, stderr: Any) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "solver", *args],
        cwd=ROOT,
        stdout=stdout,
        stderr=stderr,
        check=False,
        timeout=600,
    )


@pytest.mark.parametrize("args", WRITING_COMMANDS, ids=[c[0] for c in WRITING_COMMANDS])
def test_a_closed_standard_output_ends_with_one_line_and_status_2(args: list[str]) -> None:
    script = 'exec "$@" >&-'
    result = subprocess.run(
        ["sh", "-c", script, "sh", sys.executable, "-m", "solver", *args],
        cwd=ROOT,
        capture_output=False,
        stderr=subprocess.PIPE,
        check=False,
        timeout=600,
    )
    assert result.returncode == 2
    assert result.stderr.decode() == (
        "teleop-ui: cannot write to standard output: Bad file descriptor\n"
    )


@pytest.mark.parametrize("args", WRITING_COMMANDS, ids=[c[0] for c in WRITING_COMMANDS])
def test_a_full_standard_output_ends_with_one_line_and_status_2(args: list[str]) -> None:
    with open("/dev/full", "wb") as full:
        result = _solver(*args, stdout=full, stderr=subprocess.PIPE)
    assert result.returncode == 2
    assert result.stderr.decode() == (
        "teleop-ui: cannot write to standard output: No space left on device\n"
    )


@pytest.mark.parametrize("args", WRITING_COMMANDS[:2], ids=[c[0] for c in WRITING_COMMANDS[:2]])
def test_a_pipe_closed_by_its_reader_ends_quietly(args: list[str]) -> None:
    # The reader takes one line and goes (| head -1); the command has far more to write than
    # a pipe holds, so its next write finds the pipe closed.
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", *args],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert process.stdout is not None
    assert process.stdout.readline()
    process.stdout.close()
    _, err = process.communicate(timeout=600)
    assert process.returncode == 0
    assert err == b""


def test_an_error_with_standard_error_closed_still_exits_2() -> None:
    result = subprocess.run(
        ["sh", "-c", 'exec "$@" 2>&-', "sh", sys.executable, "-m", "solver", "solve", "nothing"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        check=False,
        timeout=600,
    )
    assert result.returncode == 2
    assert result.stdout == b""


def test_an_error_with_standard_error_full_still_exits_2() -> None:
    with open("/dev/full", "wb") as full:
        result = _solver("solve", "nothing", stdout=subprocess.PIPE, stderr=full)
    assert result.returncode == 2
    assert result.stdout == b""
