"""Shared fixtures: paths to the shipped rule sets and teams, and a CLI runner."""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
import textwrap
from collections.abc import Callable
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
RULES = ROOT / "rules"
TEAMS = RULES / "teams"


@pytest.fixture
def write_file(tmp_path: Path) -> Callable[[str, str], Path]:
    """Write ``text`` to ``name`` under a temporary folder and return its path."""

    def write(name: str, text: str) -> Path:
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        return path

    return write


class _Kept(io.BytesIO):
    """A byte buffer that keeps its bytes when the command closes the stream over it."""

    def close(self) -> None:
        pass


def run_cli(*args: str | Path, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """Run the command line in this process, as yamllint's tests do, capturing its output.

    The same ``main`` a user's ``teleop-ui`` calls, with standard output and error captured as
    UTF-8 text, an empty standard input and ``cwd`` (default: the repository) as the working
    folder; ``SystemExit`` (argparse's usage errors) becomes the exit status. It answers like
    :func:`run_process`, in a fraction of the time. Tests whose point is the process itself
    (start-up, signals, closed streams, the environment, resource limits) use
    :func:`run_process`.
    """
    from solver.cli import main

    argv = [os.fspath(arg) for arg in args]
    out, err = _Kept(), _Kept()
    streams = sys.stdin, sys.stdout, sys.stderr
    folder = Path.cwd()
    sys.stdin = io.TextIOWrapper(io.BytesIO(b""), encoding="utf-8")
    sys.stdout = io.TextIOWrapper(out, encoding="utf-8", write_through=True)
    sys.stderr = io.TextIOWrapper(err, encoding="utf-8", write_through=True)
    os.chdir(cwd or ROOT)
    try:
        status = main(argv)
    except SystemExit as exit:
        status = _exit_status(exit.code)
    finally:
        for stream in (sys.stdout, sys.stderr):
            with contextlib.suppress(ValueError):  # closed by the command
                stream.flush()
        sys.stdin, sys.stdout, sys.stderr = streams
        os.chdir(folder)
    return subprocess.CompletedProcess(
        ["teleop-ui", *argv],
        status,
        out.getvalue().decode("utf-8", "replace"),
        err.getvalue().decode("utf-8", "replace"),
    )


def _exit_status(code: object) -> int:
    if code is None:
        return 0
    return code if isinstance(code, int) else 1


def run_process(
    *args: str | Path, cwd: Path | None = None, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess[str]:
    """Run ``python -m solver`` in a new process, as a user would, capturing text output."""
    return subprocess.run(
        [sys.executable, "-m", "solver", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd or ROOT,
        env=env,
        check=False,
        timeout=600,
    )


def holds_alone(check: str) -> None:
    """Run ``check`` (Python source) in an interpreter of its own; its assertions must hold.

    For what is one per process, such as the cycle collector's switch: a thread another test
    left running in the same test worker (a studio, a watcher) may use it meanwhile.
    """
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(check)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
