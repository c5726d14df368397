"""The suite ends what it starts: the run's mark finds every process a test started, and a run
that leaves one alive fails (:mod:`tests.leaks`)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from tests.conftest import ROOT
from tests.leaks import GRACE_VARIABLE
from tests.live.roscore import wait_until
from tests.processes import MARK, end, marked, run_mark


def test_a_process_started_by_a_test_carries_the_runs_mark_and_is_found_and_ended() -> None:
    child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
    try:
        found = wait_until(
            lambda: [p for p in marked(run_mark()) if p.pid == child.pid], 60, "the child"
        )
        assert "time.sleep(600)" in found[0].command
        end(found)
        assert child.wait(timeout=60) != 0
        assert child.pid not in {p.pid for p in marked(run_mark())}
    finally:
        child.kill()
        child.wait()


def test_a_run_that_leaves_a_process_alive_fails_and_ends_it(tmp_path: Path) -> None:
    pid_file = tmp_path / "pid"
    # The leak says it runs once it does: a process that has just been started may still be
    # inside exec, with no environment to read yet (the run's mark is read from it).
    leak = (
        "import os, time; "
        f"open({str(pid_file) + '.part'!r}, 'w').write(str(os.getpid())); "
        f"os.rename({str(pid_file) + '.part'!r}, {str(pid_file)!r}); "
        "time.sleep(600)"
    )
    (tmp_path / "test_leak.py").write_text(
        "import os, subprocess, sys, time\n"
        "def test_leaks():\n"
        f"    child = subprocess.Popen([sys.executable, '-c', {leak!r}], start_new_session=True)\n"
        f"    while not os.path.exists({str(pid_file)!r}):\n"
        "        assert child.poll() is None, 'the leak ended before it said it runs'\n"
        "        time.sleep(0.01)\n",
        encoding="utf-8",
    )
    # A run of its own (not nested in this one): without this run's mark in its environment.
    environment = {k: v for k, v in os.environ.items() if k != MARK}
    environment["PYTHONPATH"] = str(ROOT)
    environment[GRACE_VARIABLE] = "1"  # the leak sleeps for ten minutes: no need to wait ten s
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "tests.leaks", "-q", str(tmp_path)],
        cwd=tmp_path,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert result.returncode == 1, result.stdout
    assert "still alive at the end (killed now)" in result.stdout
    leaked = int(pid_file.read_text())
    assert wait_until(lambda: not _alive(leaked), 60, "the leaked process to end")


def _alive(pid: int) -> bool:
    try:  # a zombie has no environment left: it has ended
        return bool(Path(f"/proc/{pid}/environ").read_bytes())
    except OSError:
        return False
