"""`teleop-ui watch` and `teleop-ui assign --master` as a user runs them, against a real roscore."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from solver.live.graph import MISSING
from solver.live.sources.ros1.master import MasterClient
from solver.solving.solution import Solution
from tests.conftest import ROOT, run_cli
from tests.live.fleet import drone_configuration, put_drone, put_rover, rover_configuration
from tests.live.roscore import Roscore, TestNode, free_port, roscore_available, wait_until

TIMEOUT = 60.0


class WatchProcess:
    """``python -m solver watch ...`` in a subprocess, its output lines collected as they come."""

    def __init__(self, *args: str, env: dict[str, str] | None = None) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "solver", "watch", *args],
            cwd=ROOT,
            text=True,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            env=env,
        )
        self.stdout: list[str] = []
        self.stderr: list[str] = []
        self.readers = [
            threading.Thread(target=self._read, args=(stream, lines), daemon=True)
            for stream, lines in (
                (self.process.stdout, self.stdout),
                (self.process.stderr, self.stderr),
            )
        ]
        for reader in self.readers:
            reader.start()

    @staticmethod
    def _read(stream: Any, lines: list[str]) -> None:
        for line in stream:
            lines.append(line)

    def events(self) -> list[dict[str, Any]]:
        return [json.loads(line) for line in list(self.stdout)]

    def wait_for(self, predicate: Callable[[dict[str, Any]], bool], what: str) -> dict[str, Any]:
        def found() -> dict[str, Any] | None:
            if self.process.poll() is not None and not any(map(predicate, self.events())):
                raise AssertionError(
                    f"watch exited ({self.process.returncode}) before {what}:"
                    f" {''.join(self.stderr)}"
                )
            return next((e for e in self.events() if predicate(e)), None)

        return wait_until(found, TIMEOUT, what)

    def interrupt(self) -> int:
        self.process.send_signal(signal.SIGINT)
        return self.wait()

    def wait(self) -> int:
        code = self.process.wait(timeout=TIMEOUT)
        for reader in self.readers:
            reader.join(timeout=TIMEOUT)
        return code

    def kill(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait(timeout=TIMEOUT)


@pytest.fixture
def watch_process() -> Iterator[Callable[..., WatchProcess]]:
    started: list[WatchProcess] = []

    def start(*args: str, env: dict[str, str] | None = None) -> WatchProcess:
        started.append(WatchProcess(*args, env=env))
        return started[-1]

    yield start
    for process in started:
        process.kill()


def test_once_prints_one_snapshot_as_json_lines_identical_from_run_to_run(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    first = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
    assert first.returncode == 0, first.stderr
    assert first.stderr == ""
    lines = first.stdout.splitlines()
    events = [json.loads(line) for line in lines]
    assert [e["event"] for e in events] == [
        "robot_added",
        "robot_added",
        "selection_changed",
        "synced",
    ]
    assert [e["seq"] for e in events] == [1, 2, 3, 4]
    assert list(events[0]) == [
        "seq",
        "event",
        "robot",
        "name",
        "structure",
        "kinematic_type",
        "confidence",
        "sensor_count",
        "sensors",
        "motion_controls",
        "given",
        "combinations",
        "missing",
        "error",
        "topics",
    ]
    assert events[2]["assignment"]["configuration"] == rover_configuration(solution)
    assert events[3]["robots"] == ["/uav1", "/ugv1"]
    again = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
    assert again.stdout == first.stdout


def test_once_as_text_reads_as_sentences(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/broken/robot_description", "<robot>")
    result = run_cli(
        "watch", "--master", master.uri, "--team", "case3", "--once", "--format", "text"
    )
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "robot added     /broken  cannot be identified:"
    assert lines[1].startswith("                  /broken/robot_description:1:")
    assert lines[2] == (
        "robot added     /uav1  copter: UAV (structure UAV, confidence 0.95); "
        "1 sensor(s); motion controls Flight"
    )
    assert lines[3] == (
        f"                  UI configuration {drone_configuration(solution)}  "
        "<- UAV, Flight, 2D Camera, 1"
    )
    assert lines[4] == "synced          2 robot(s): /broken, /uav1"


def test_an_unreachable_master_exits_2_with_a_clear_message(tmp_path: Path) -> None:
    uri = f"http://127.0.0.1:{free_port()}/"
    result = run_cli("watch", "--master", uri, "--team", "case3")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == (
        f"{uri}: cannot reach the ROS master (Connection refused): is "
        "roscore running there? (--wait waits for it)\n"
    )


def test_no_master_anywhere_and_bad_options_exit_2() -> None:
    environment = {k: v for k, v in os.environ.items() if k != "ROS_MASTER_URI"}
    result = subprocess.run(
        [sys.executable, "-m", "solver", "watch", "--team", "case3"],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
        timeout=TIMEOUT,
    )
    assert result.returncode == 2
    assert "pass --master http://HOST:PORT or set ROS_MASTER_URI" in result.stderr
    for bad in (
        ["--interval", "0"],
        ["--interval", "0.0001"],
        ["--interval", "soon"],
        ["--timeout", "7200"],
        ["--master", "127.0.0.1:11311"],
    ):
        result = run_cli("watch", "--team", "case3", *bad)
        assert result.returncode == 2, bad
        assert "Traceback" not in result.stderr


def test_wait_does_not_wait_for_a_server_that_is_not_a_master(web_server: str) -> None:
    """--wait waits for a master that does not answer yet; a web server answers, wrongly."""
    result = run_cli("watch", "--wait", "--master", web_server, "--team", "case3")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == f"{web_server}: getPid: not a ROS master: HTTP 404 Not Found\n"


def test_ros_master_uri_is_used_when_no_master_is_given(master: Roscore, node: TestNode) -> None:
    put_drone(node, "/uav1")
    environment = {**os.environ, "ROS_MASTER_URI": master.uri.rstrip("/")}
    result = subprocess.run(
        [sys.executable, "-m", "solver", "watch", "--team", "case3", "--once"],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
        timeout=TIMEOUT,
    )
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout.splitlines()[-1])["master"] == master.uri


def test_ctrl_c_ends_a_watch_cleanly(
    master: Roscore, node: TestNode, watch_process: Callable[..., WatchProcess]
) -> None:
    put_drone(node, "/uav1")
    watch = watch_process("--master", master.uri, "--team", "case3")
    watch.wait_for(lambda e: e["event"] == "synced", "synced")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    watch.wait_for(lambda e: e["event"] == "selection_changed", "selection_changed")
    code = watch.interrupt()
    assert code in (0, 130)
    assert "Traceback" not in "".join(watch.stderr)
    assert [e["seq"] for e in watch.events()] == list(range(1, len(watch.events()) + 1))


def test_sigterm_ends_a_watch_cleanly_too(
    master: Roscore, node: TestNode, watch_process: Callable[..., WatchProcess]
) -> None:
    put_drone(node, "/uav1")
    watch = watch_process("--master", master.uri, "--team", "case3", "--format", "text")
    wait_until(lambda: any(line.startswith("synced") for line in watch.stdout), TIMEOUT, "synced")
    watch.process.send_signal(signal.SIGTERM)
    assert watch.wait() == 0
    assert "".join(watch.stderr) == "watch stopped: terminated (SIGTERM)\n"


def test_an_answer_left_by_a_killed_watch_is_taken_over(
    master: Roscore, node: TestNode, watch_process: Callable[..., WatchProcess]
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    killed = watch_process("--master", master.uri, "--team", "case1")

    def answer(team: str) -> dict[str, Any] | None:
        value = node.get_param("/teleop_ui/ui_configuration")
        return value if isinstance(value, dict) and value.get("team") == team else None

    left = wait_until(lambda: answer("Case 1"), TIMEOUT, "the first watch's answer")
    killed.kill()  # SIGKILL: no unsubscribing, the master still lists its node
    client = MasterClient(master.uri, caller_id="/rosnode", timeout=5.0)
    assert client.lookup_node(left["watcher"]) is not None
    client.close()

    second = watch_process("--master", master.uri, "--team", "case3")
    taken = wait_until(lambda: answer("Case 3"), TIMEOUT, "the answer taken over")
    assert taken["watcher"] != left["watcher"]
    selected = second.wait_for(lambda e: e["event"] == "selection_changed", "selection")
    assert not any("not written" in note for note in selected["notes"])


def test_wait_waits_for_the_master_to_come_up(
    tmp_path: Path, watch_process: Callable[..., WatchProcess]
) -> None:
    if not roscore_available():
        pytest.fail("roscore is not installed (tools/test.sh installs Debian's ros-core)")
    core = Roscore(tmp_path, free_port())
    watch = watch_process("--master", core.uri, "--team", "case3", "--wait", "--interval", "0.1")
    wait_until(lambda: "".join(watch.stderr), TIMEOUT, "the waiting note")
    assert "".join(watch.stderr).startswith(f"waiting for the ROS master at {core.uri} (")
    assert watch.process.poll() is None
    assert watch.stdout == []
    try:
        core.start()
        node = TestNode(core.uri)
        put_drone(node, "/uav1")
        added = watch.wait_for(lambda e: e["event"] == "robot_added", "robot_added")
        assert added["robot"] == "/uav1"
        node.close()
        assert watch.interrupt() in (0, 130)
    finally:
        core.kill()


def test_a_master_killed_under_a_running_watch_is_lost_and_back(
    own_roscore: Roscore, watch_process: Callable[..., WatchProcess]
) -> None:
    node = TestNode(own_roscore.uri)
    put_drone(node, "/uav1")
    watch = watch_process("--master", own_roscore.uri, "--team", "case3", "--interval", "0.1")
    watch.wait_for(lambda e: e["event"] == "synced", "synced")
    own_roscore.kill()
    watch.wait_for(lambda e: e["event"] == "master_lost", "master_lost")
    own_roscore.start()
    put_drone(node, "/uav1")
    back = watch.wait_for(lambda e: e["event"] == "master_back", "master_back")
    watch.wait_for(lambda e: e["event"] == "robot_added" and e["seq"] > back["seq"], "/uav1 again")
    assert watch.process.poll() is None
    assert watch.interrupt() in (0, 130)
    assert "Traceback" not in "".join(watch.stderr)
    node.close()


def test_assign_reads_the_robot_from_the_master(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    result = run_cli(
        "assign",
        "--master",
        master.uri,
        "--team",
        "case3",
        "--robot",
        "/uav1",
        "motion_control=Flight",
        "--format",
        "json",
    )
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["robot"] == "/uav1"
    assert data["combination"] == {
        "kinematic_type": "UAV",
        "motion_control": "Flight",
        "sensor_type": "2D Camera",
        "sensor_count": "1",
    }
    assert data["configuration"] == drone_configuration(solution)
    assert data["notes"] == []
    text = run_cli(
        "assign",
        "--master",
        master.uri,
        "--team",
        "case3",
        "--robot",
        "uav1",
        "motion_control=Waypoint",
    )
    assert text.returncode == 0, text.stderr
    assert text.stdout.startswith("robot /uav1\nUI configuration ")
    assert text.stdout.endswith(
        "  note: /uav1 does not offer motion_control 'Waypoint' (it "
        "has Flight); using it as asked\n"
    )


def test_assign_reads_with_the_profile_given(
    master: Roscore, node: TestNode, tmp_path: Path
) -> None:
    shipped = (ROOT / "rules" / "identification.yaml").read_text(encoding="utf-8")
    assert shipped.count("kinematic_types: [UAV]") == 1
    profile = tmp_path / "flying-is-driving.yaml"
    profile.write_text(
        shipped.replace("kinematic_types: [UAV]", "kinematic_types: [UGV]"), encoding="utf-8"
    )
    put_drone(node, "/uav1")
    result = run_cli(
        "assign",
        "--master",
        master.uri,
        "--team",
        "case3",
        "--robot",
        "/uav1",
        "--profile",
        profile,
        "-f",
        "json",
    )
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["combination"]["kinematic_type"] == "UGV"
    offline = run_cli("assign", "--team", "case3", "--profile", profile, "kinematic_type=UAV")
    assert (offline.returncode, offline.stderr) == (
        2,
        "<arguments>: --profile needs --master URL\n",
    )


def test_assign_without_robot_answers_the_active_selection(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_rover(node, "/ugv1")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    node.set_param("/teleop_ui/active_motion_control", "Driving")
    result = run_cli("assign", "--master", master.uri, "--team", "case3", "-f", "json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert (data["robot"], data["configuration"]) == ("/ugv1", rover_configuration(solution))
    # assign only reads: nothing is written back.
    assert node.get_param("/teleop_ui/ui_configuration") is MISSING


def test_assign_errors_on_the_master_exit_2(master: Roscore, node: TestNode) -> None:
    put_drone(node, "/uav1")
    node.set_param("/broken/robot_description", "<robot name='b'><link name='a'></robot>")
    unknown = run_cli("assign", "--master", master.uri, "--team", "case3", "--robot", "/uav2")
    assert unknown.returncode == 2
    assert unknown.stderr == (
        f"<arguments>: no robot /uav2 on {master.uri} (no "
        "/uav2/robot_description) (did you mean '/uav1'?); robots "
        "there: /broken, /uav1\n"
    )
    broken = run_cli("assign", "--master", master.uri, "--team", "case3", "--robot", "/broken")
    assert broken.returncode == 2
    assert broken.stderr.startswith(
        f"{master.uri}: robot /broken cannot be identified: /broken/robot_description:1:"
    )
    nobody = run_cli("assign", "--master", master.uri, "--team", "case3")
    assert nobody.returncode == 2
    assert "no --robot given and no /teleop_ui/active_robot set" in nobody.stderr
    bad_name = run_cli(
        "assign", "--master", master.uri, "--team", "case3", "--robot", "/uav1", "colour=red"
    )
    assert bad_name.returncode == 2
    assert "unknown characteristic 'colour'" in bad_name.stderr


def test_assign_without_master_keeps_its_old_rules() -> None:
    nothing = run_cli("assign", "--team", "case3")
    assert nothing.returncode == 2
    assert "give at least one NAME=VALUE (or --master URL)" in nothing.stderr
    robot = run_cli("assign", "--team", "case3", "--robot", "/uav1", "kinematic_type=UAV")
    assert robot.returncode == 2
    assert "--robot needs --master URL" in robot.stderr


def test_once_only_looks_the_master_keeps_no_answer_of_it(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
    assert result.returncode == 0, result.stderr
    selection = [json.loads(line) for line in result.stdout.splitlines()][1]
    assert selection["assignment"]["configuration"] == drone_configuration(solution)
    assert node.get_param("/teleop_ui/ui_configuration") is MISSING
    assert node.get_param("/teleop_ui/watchers") is MISSING


def test_a_watch_that_stops_takes_its_answer_back(
    master: Roscore, node: TestNode, watch_process: Callable[..., WatchProcess]
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    watch = watch_process("--master", master.uri, "--team", "case3")
    wait_until(
        lambda: isinstance(node.get_param("/teleop_ui/ui_configuration"), dict),
        TIMEOUT,
        "the answer",
    )
    watch.process.send_signal(signal.SIGTERM)
    assert watch.wait() == 0
    # Left there, it would name a node that no longer runs: an operator station would show it.
    assert node.get_param("/teleop_ui/ui_configuration") is MISSING
