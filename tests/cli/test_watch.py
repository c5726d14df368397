"""``teleop-ui watch`` as a user runs it: against a real roscore (``--master``), and on a ROS 2
graph of real Cyclone DDS participants on loopback (``--ros2``).
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from solver.live.graph import MISSING
from solver.live.sources.ros1.master import MasterClient
from solver.solving.solution import Solution
from tests.conftest import ROOT, run_cli
from tests.live.fleet import drone_configuration, put_drone, put_rover, rover_configuration
from tests.live.ros2_graph import Domain
from tests.live.roscore import Roscore, TestNode, free_port, roscore_available, wait_until
from tests.live.watching import TIMEOUT, WatchProcess

# ---- a ROS master ----------------------------------------------------------------------------


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


# ---- a ROS 2 graph ---------------------------------------------------------------------------


def test_watch_ros2_once_prints_the_graph_as_json_lines(domain: Domain, solution: Solution) -> None:
    domain.drone("/uav1", gid_size=24)
    domain.rover("/ugv1")
    result = run_cli("watch", "--ros2", "--domain", str(domain.id), "--team", "case3", "--once")
    assert result.returncode == 0, result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    assert [e["event"] for e in events] == ["robot_added", "robot_added", "synced"]
    assert events[-1] == {
        "seq": 3,
        "event": "synced",
        "master": f"ros2://domain/{domain.id}",
        "robots": ["/uav1", "/ugv1"],
    }
    assert events[0]["combinations"][0]["configuration"] == drone_configuration(solution)
    assert events[1]["combinations"][0]["configuration"] == rover_configuration(solution)


def test_watch_ros2_refuses_a_master_or_a_bad_domain_with_exit_2() -> None:
    bad = run_cli("watch", "--ros2", "--domain", "300", "--team", "case3", "--once")
    assert (bad.returncode, bad.stderr) == (
        2,
        "<arguments>: DDS domain id must be 0..232, got '300'\n",
    )
    both = run_cli("watch", "--ros2", "--master", "http://127.0.0.1:1/", "--team", "case3")
    assert both.returncode == 2
    assert both.stderr == "<arguments>: --ros2 reads a DDS domain: give --domain N, not --master\n"


def test_watch_ros2_wait_waits_for_the_first_robot(domain: Domain) -> None:
    """Issue 27: `--wait` on DDS waits for a robot (a domain is never down)."""
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "solver",
            "watch",
            "--ros2",
            "--domain",
            str(domain.id),
            "--team",
            "case3",
            "--wait",
            "--once",
        ],
        cwd=ROOT,
        env=domain.env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        assert process.stderr is not None
        waiting = process.stderr.readline()
        assert waiting == f"waiting for a robot on ros2://domain/{domain.id}\n"
        domain.drone("/uav1")
        out, err = process.communicate(timeout=TIMEOUT)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
        process.wait(timeout=TIMEOUT)
    assert (process.returncode, err) == (0, "")
    events = [json.loads(line) for line in out.splitlines()]
    assert [(e["event"], e.get("robot")) for e in events] == [
        ("robot_added", "/uav1"),
        ("synced", None),
    ]


# ---- --serve and --viewer-origin (issue 38; the server itself: tests/live/test_server.py) ----


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--serve", "0"], "--serve: needs --layouts DIR: the folder it serves\n"),
        (
            ["--serve", "0", "--layouts", "LAYOUTS", "--once"],
            "--serve: a snapshot (--once) ends at once: nothing to serve\n",
        ),
        (
            ["--viewer-origin", "http://127.0.0.1:8080"],
            "--viewer-origin: only with --serve: who may read what it serves\n",
        ),
        (
            ["--serve", "0.0.0.0:8770", "--layouts", "LAYOUTS"],
            "--serve: '0.0.0.0' is not a loopback address: the server has no token and serves "
            "this machine only (127.0.0.1, ::1 or localhost)\n",
        ),
        (
            ["--serve", "0", "--layouts", "LAYOUTS", "--viewer-origin", "*"],
            "--viewer-origin: expected an origin such as http://127.0.0.1:8080 (scheme, host "
            "and port only), got '*'\n",
        ),
    ],
)
def test_serving_options_are_checked_before_the_graph_is_read(
    tmp_path: Path, options: list[str], message: str
) -> None:
    layouts = str(tmp_path / "layouts")
    uri = f"http://127.0.0.1:{free_port()}/"  # nothing there: the graph is never reached
    args = [layouts if option == "LAYOUTS" else option for option in options]
    result = run_cli("watch", "--master", uri, "--team", "case3", *args)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", message)
    assert not (tmp_path / "layouts").exists()


def test_a_serve_port_already_taken_is_exit_2(tmp_path: Path) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = run_cli(
            "watch", "--master", f"http://127.0.0.1:{free_port()}/", "--team", "case3",
            "--layouts", tmp_path / "layouts", "--serve", f"127.0.0.1:{port}",
        )  # fmt: skip
    assert result.returncode == 2
    assert result.stderr.startswith(f"--serve: cannot listen on 127.0.0.1:{port}: ")
    assert "Traceback" not in result.stderr
