"""``teleop-ui demo ros2``: emulated robots and an operator on loopback that a watcher follows."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from solver.core.team import load_team
from solver.identify.profile import load_profile
from solver.live.demo import LOOPBACK_CONFIG, ROBOTS, demo_team
from solver.live.sources.ros2 import DdsGraph
from solver.live.watcher import Watcher
from solver.solving.solution import solve
from tests.conftest import ROOT
from tests.live.conftest import EVENT_TIMEOUT, Recorder
from tests.live.ros2_graph import CONFIG, EmulatedRobot, next_domain, write_config


@pytest.fixture
def loopback(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, str]:
    monkeypatch.setenv("CYCLONEDDS_URI", write_config(tmp_path))
    return dict(os.environ)


def start_demo(domain: int, loopback: dict[str, str], *, every: str) -> subprocess.Popen[str]:
    """``teleop-ui demo ros2`` on ``domain``, its operator switching every ``every`` seconds."""
    return subprocess.Popen(
        [sys.executable, "-m", "solver", "demo", "ros2", "--domain", str(domain), "--every", every],
        cwd=ROOT,
        env=loopback,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )


def test_the_demo_configuration_is_the_loopback_one_the_tests_use() -> None:
    assert LOOPBACK_CONFIG == CONFIG


def test_a_watcher_follows_the_demo_fleet_and_the_operator_gets_its_answers(
    loopback: dict[str, str], tmp_path: Path
) -> None:
    domain = next_domain()
    demo = start_demo(domain, loopback, every="0.3")
    solution = solve(load_team(demo_team(tmp_path)))
    source = DdsGraph(domain)
    watch = Recorder(Watcher(source.name, solution, load_profile(), source=source), solution)
    try:
        assert demo.stdout is not None
        assert demo.stdout.readline().startswith(
            "teleop-ui demo: Cyclone DDS configured by CYCLONEDDS_URI (as given)"
        )
        for robot in ROBOTS:
            added = watch.wait_for_event("robot_added", robot.namespace)
            configurations = [c for c in added["combinations"] if not c["default"]]
            assert configurations, added
        # The operator switches through every robot; the watcher answers each. The robot and
        # its motion control are two topics, read as each arrives: a selection may show one
        # before the other, and the answer to both follows.
        for robot in ROBOTS:
            answered = watch.wait_for(
                lambda d, robot=robot: (  # type: ignore[misc]  # mypy: a default in a lambda
                    d["event"] == "selection_changed"
                    and d["robot"] == robot.namespace
                    and d["active"]["motion_control"] in robot.controls
                ),
                f"the operator selecting {robot.namespace}",
            )
            assert answered["assignment"] is not None
            assert answered["assignment"]["default"] is False
        while not (line := demo.stdout.readline()).startswith("  answer: UI configuration"):
            assert line, "the demo ended before it reported an answer"
        assert f"from {watch.watcher.caller_id}" in line
        demo.send_signal(signal.SIGTERM)
        assert demo.wait(timeout=EVENT_TIMEOUT) == 0
        for robot in ROBOTS:
            watch.wait_for_event("robot_removed", robot.namespace)
    finally:
        watch.stop()
        if demo.poll() is None:
            os.killpg(demo.pid, signal.SIGKILL)
        demo.wait(timeout=EVENT_TIMEOUT)
        for stream in (demo.stdout, demo.stderr):
            if stream is not None:
                stream.close()


def _line(demo: subprocess.Popen[str], wanted: str) -> list[str]:
    """The demo's lines up to and including the first that contains ``wanted`` (it prints two
    lines a round: a generous ceiling of rounds, never a measure)."""
    assert demo.stdout is not None
    lines: list[str] = []
    while wanted not in (line := demo.stdout.readline()):
        assert line, f"the demo ended before it said {wanted!r}: {lines[-5:]}"
        assert len(lines) < 1000, f"the demo never said {wanted!r}: {lines[-5:]}"
        lines.append(line)
    return [*lines, line]


def test_the_demo_operator_reads_a_hostile_answer_bounded_and_shows_it_escaped(
    loopback: dict[str, str],
) -> None:
    """Issue 36 item 9: another participant's answer 200,000 levels deep ended the demo with a
    RecursionError, and a robot name holding a line break printed a forged line."""
    domain = next_domain()
    hostile = EmulatedRobot(domain, loopback)
    hostile.latch("/teleop_ui/ui_configuration", "[" * 200_000)
    demo = start_demo(domain, loopback, every="0.2")
    try:
        deep = _line(demo, "answer: unreadable")[-1]
        assert deep == (
            "  answer: unreadable (nested deeper than 64 levels): "
            + "[" * 60
            + "... (cut from 200,000 characters)\n"
        )
        forged = "/uav1\nanswer: UI configuration 1 for /forged from /teleop_ui_watch_1"
        hostile.latch(
            "/teleop_ui/ui_configuration",
            json.dumps({"configuration": 7, "robot": forged, "watcher": "/w\x1b[2J"}),
        )
        seen = _line(demo, "answer: UI configuration 7")
        assert seen[-1] == (
            "  answer: UI configuration 7 for /uav1\\nanswer: UI configuration 1 for "
            "/forged from /teleop_ui... (cut from 68 characters) from /w\\x1b[2J\n"
        )
        assert not any(line.startswith("answer:") for line in seen)
        demo.send_signal(signal.SIGTERM)
        assert demo.wait(timeout=EVENT_TIMEOUT) == 0
        assert demo.stderr is not None
        assert demo.stderr.read() == ""
    finally:
        hostile.kill()
        if demo.poll() is None:
            os.killpg(demo.pid, signal.SIGKILL)
        demo.wait(timeout=EVENT_TIMEOUT)
        for stream in (demo.stdout, demo.stderr):
            if stream is not None:
                stream.close()


def test_the_ros1_demo_fleet_runs_where_only_the_tool_is_installed() -> None:
    # The README installs `.[all]`, without the test tools: the demo fleet of docs/live.md
    # (tools/demo_fleet.py) must start without pytest.
    code = (
        "import sys; sys.modules['pytest'] = None\n"
        "import runpy; runpy.run_path('tools/demo_fleet.py', run_name='demo')\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
