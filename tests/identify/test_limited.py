"""A piece run in a fresh, limited interpreter (solver.identify.limited): one JSON request in,
one JSON answer out, an isolated interpreter with only the environment given, and a child
that runs too long, writes too much or is told to stop ended with its whole process group.
"""

from __future__ import annotations

import time
from pathlib import Path

from solver.identify.limited import run_limited

CEILING = 600.0  # seconds: a last resort; each test ends on an event long before


def script(folder: Path, body: str) -> str:
    path = folder / "child.py"
    path.write_text("import json, os, subprocess, sys, time\n" + body, encoding="utf-8")
    return str(path)


def gone(pid: int) -> bool:
    """Whether process ``pid`` has ended (a zombie waiting for its parent has)."""
    try:
        fields = (Path("/proc") / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return True
    return fields[0] == "Z"


def test_the_child_answers_its_request_in_an_isolated_interpreter(tmp_path: Path) -> None:
    child = script(
        tmp_path,
        "request = json.load(sys.stdin)\n"
        "print(json.dumps({'got': request, 'environment': sorted(os.environ),\n"
        "    'isolated': sys.flags.isolated, 'no_site': sys.flags.no_site}))\n",
    )
    finished = run_limited(
        [child], {"bag": "run.db3"}, wall_seconds=CEILING, answer_bytes=4096, env={"ONLY": "1"}
    )
    assert finished.answer == {
        "got": {"bag": "run.db3"},
        "environment": ["LANG", "ONLY", "PATH"],
        "isolated": 1,
        "no_site": 1,
    }
    assert (finished.returncode, finished.stopped, finished.signal) == (0, None, None)


def test_an_answer_larger_than_allowed_is_not_read_past_its_bound(tmp_path: Path) -> None:
    child = script(tmp_path, "sys.stdout.write(json.dumps({'x': 'y' * 1000}))\n")  # fits a pipe
    finished = run_limited([child], {}, wall_seconds=CEILING, answer_bytes=100)
    assert finished.oversized
    assert finished.answer is None


def test_an_answer_that_is_no_json_object_is_no_answer(tmp_path: Path) -> None:
    child = script(tmp_path, "print('[1, 2]')\n")
    finished = run_limited([child], {}, wall_seconds=CEILING, answer_bytes=100)
    assert finished.answer is None
    assert finished.returncode == 0


def test_a_child_past_its_wall_clock_is_killed_and_says_so(tmp_path: Path) -> None:
    child = script(tmp_path, "print(json.dumps({'early': True}), flush=True)\ntime.sleep(3600)\n")
    finished = run_limited([child], {}, wall_seconds=0.5, answer_bytes=100)
    assert finished.stopped == "time"
    assert finished.signal == 9
    assert finished.answer is None  # what a stopped child wrote is never taken as its answer


def test_a_child_the_watch_stops_is_killed_with_every_process_it_started(tmp_path: Path) -> None:
    marker = tmp_path / "grandchild.pid"
    child = script(
        tmp_path,
        "sleeper = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(3600)'])\n"
        f"open({str(marker)!r}, 'w').write(str(sleeper.pid))\n"
        "time.sleep(3600)\n",
    )

    def watch() -> str | None:
        return "grown" if marker.is_file() and marker.read_text() else None

    finished = run_limited([child], {}, wall_seconds=CEILING, answer_bytes=100, watch=watch)
    assert finished.stopped == "grown"
    assert finished.signal == 9
    grandchild = int(marker.read_text())
    for _ in range(3000):  # SIGKILL reached the whole group; the kernel ends it (60 s ceiling)
        if gone(grandchild):
            break
        time.sleep(0.02)
    assert gone(grandchild)


def test_a_child_writing_past_its_bound_is_stopped_at_once_not_at_its_wall_clock(
    tmp_path: Path,
) -> None:
    # Far more than a pipe holds: left unread, the child would wait in its write until the
    # wall-clock limit killed it ("time"); it is stopped as soon as the bound is passed.
    child = script(tmp_path, "sys.stdout.write('x' * 10_000_000)\nsys.stdout.flush()\n")
    finished = run_limited([child], {}, wall_seconds=CEILING, answer_bytes=1000)
    assert finished.oversized
    assert finished.stopped is None
    assert finished.signal == 9
