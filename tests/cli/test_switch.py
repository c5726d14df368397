"""``teleop-ui switch`` as an operator runs it, against a real ``teleop-ui watch`` process: on a
ROS 2 graph of real Cyclone DDS participants on loopback (``--ros2``), and on a real roscore
(``--master``). Expected configurations come from :func:`solver.assign` (tests.live.fleet), not
from the command under test.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from solver.layouts.checks import check_lichtblick
from solver.live.graph import MISSING
from solver.solving.solution import Solution
from tests.conftest import run_cli
from tests.live.fleet import (
    drone_configuration,
    expected,
    put_drone,
    put_rover,
    rover_configuration,
)
from tests.live.ros2_graph import Domain
from tests.live.roscore import Roscore, TestNode
from tests.live.watching import WatchProcess


def synced(*robots: str) -> Callable[[dict[str, Any]], bool]:
    return lambda e: e["event"] == "synced" and e.get("robots") == list(robots)


def selected(robot: str, **values: str | None) -> Callable[[dict[str, Any]], bool]:
    """A ``selection_changed`` event of the watcher for ``robot`` with ``values`` asked
    (``None``: not asked)."""
    return lambda e: (
        e["event"] == "selection_changed"
        and e["robot"] == robot
        and all(e["active"].get(name) == value for name, value in values.items())
    )


def uav_waypoint(solution: Solution) -> int:
    return expected(
        solution,
        kinematic_type="UAV",
        motion_control="Waypoint",
        sensor_type="2D Camera",
        sensor_count="1",
    )


# ---- ROS 2 -------------------------------------------------------------------------------------


@pytest.fixture
def ros2_watch(
    domain: Domain, watch_process: Callable[..., WatchProcess]
) -> Callable[..., WatchProcess]:
    """``teleop-ui watch --ros2`` on the test's domain, once it has read the drone and the
    rover already there."""

    def start(*extra: str) -> WatchProcess:
        watch = watch_process(
            "--ros2", "--domain", str(domain.id), "--team", "case3", *extra, env=domain.env
        )
        watch.wait_for(synced("/uav1", "/ugv1"), "synced with both robots")
        return watch

    domain.drone("/uav1")
    domain.rover("/ugv1")
    return start


def switch_ros2(domain: Domain, *args: str) -> Any:
    """``switch`` on the domain, looking for the robot and a running watcher, and waiting for its
    answer, for up to a minute each (both end on what they wait for: a busy machine may discover
    a watcher's participant seconds late); ``args`` may give shorter ones."""
    return run_cli(
        "switch", "--ros2", "--domain", str(domain.id), "--look", "60", "--wait", "60", *args
    )


def test_switch_on_ros2_makes_the_robot_active_and_prints_the_watchers_answer(
    domain: Domain, ros2_watch: Callable[..., WatchProcess], solution: Solution
) -> None:
    watch = ros2_watch()
    result = switch_ros2(domain, "/ugv1")
    assert (result.returncode, result.stderr) == (0, "")
    first, by = result.stdout.splitlines()[:2]
    assert (
        first
        == f"/ugv1 -> UI configuration {rover_configuration(solution)}  <- UGV, Driving, LIDAR, 1"
    )
    assert by.startswith("  answered by /teleop_ui_watch_")
    assert by.endswith(" for team Case 3")
    watch.wait_for(selected("/ugv1"), "the watcher's selection of /ugv1")

    # The value asked for is written beside the robot, and answered: the answer names both.
    result = switch_ros2(domain, "uav1", "motion_control=Waypoint", "--format", "json")
    assert (result.returncode, result.stderr) == (0, "")
    data = json.loads(result.stdout)
    assert data["graph"] == f"ros2://domain/{domain.id}"
    assert (data["robot"], data["selection"]) == ("/uav1", {"motion_control": "Waypoint"})
    assert data["rules"] == "rules/paper.yaml"  # announced by the watcher, and shipped
    answer = data["answer"]
    assert (answer["robot"], answer["configuration"]) == ("/uav1", uav_waypoint(solution))
    assert answer["combination"]["motion_control"] == "Waypoint"
    assert answer["notes"] == [
        "/uav1 does not offer motion_control 'Waypoint' (it has Flight); using it as asked"
    ]
    watch.wait_for(selected("/uav1", motion_control="Waypoint"), "the watcher's new selection")


def test_switch_clear_lets_the_robots_own_value_apply_again(
    domain: Domain, ros2_watch: Callable[..., WatchProcess], solution: Solution
) -> None:
    """A value cleared is in no answer: the switch waits for the watcher's answer to the whole
    selection, not the first that names the robot (the old value read before the clear)."""
    ros2_watch()
    asked = switch_ros2(domain, "/uav1", "motion_control=Waypoint")
    assert asked.returncode == 0, asked.stderr
    assert f"UI configuration {uav_waypoint(solution)}" in asked.stdout
    # Another robot: Waypoint would be valid for the rover too (a configuration of its own).
    rover = switch_ros2(domain, "/ugv1", "--clear", "--format", "json")
    assert rover.returncode == 0, rover.stderr
    data = json.loads(rover.stdout)
    assert data["selection"] == {
        "kinematic_type": None,
        "motion_control": None,
        "sensor_type": None,
        "sensor_count": None,
    }
    assert data["answer"]["configuration"] == rover_configuration(solution)
    assert data["answer"]["combination"]["motion_control"] == "Driving"
    # The same robot, one value cleared by hand (NAME=).
    assert switch_ros2(domain, "/uav1", "motion_control=Waypoint").returncode == 0
    cleared = switch_ros2(domain, "/uav1", "motion_control=", "--format", "json")
    assert cleared.returncode == 0, cleared.stderr
    data = json.loads(cleared.stdout)
    assert data["selection"] == {"motion_control": None}
    assert data["answer"]["configuration"] == drone_configuration(solution)


def test_switch_prints_the_answers_layouts_whole_and_the_layout_passes_the_checks(
    domain: Domain, ros2_watch: Callable[..., WatchProcess], solution: Solution, tmp_path: Path
) -> None:
    folder = tmp_path / ("a-folder-with-a-long-name-" * 4)
    ros2_watch("--layouts", str(folder))
    result = switch_ros2(domain, "/ugv1", "--format", "json")
    assert result.returncode == 0, result.stderr
    layouts = json.loads(result.stdout)["answer"]["layouts"]
    number = rover_configuration(solution)
    path = Path(layouts["foxglove"]["path"])
    assert path == folder.absolute() / "ugv1" / f"config-{number:03d}.json"
    layout = json.loads(path.read_text(encoding="utf-8"))
    assert check_lichtblick(layout, str(path)) == ()
    # The text names every path whole, each on its own line: nothing an operator copies is cut.
    text = switch_ros2(domain, "/ugv1")
    assert text.returncode == 0, text.stderr
    lines = text.stdout.splitlines()
    assert f"  layout foxglove  {path}" in lines
    team = folder.absolute() / "team.json"
    assert f"  layout team      {team} (tab {layouts['team']['tab']})" in lines
    assert "cut from" not in text.stdout


def test_switch_refuses_what_is_no_selection_and_writes_nothing(
    domain: Domain, ros2_watch: Callable[..., WatchProcess], solution: Solution
) -> None:
    watch = ros2_watch()
    refusals = {
        # NAME and VALUE against the rule set the running watcher announces (not given here).
        ("/uav1", "motion_contrl=Flight"): "<arguments>: motion_contrl: unknown characteristic "
        "'motion_contrl' (did you mean 'motion_control'?); the rules (rules/paper.yaml) have: "
        "kinematic_type, motion_control, sensor_type, sensor_count\n",
        ("/uav1", "motion_control=Flite"): "<arguments>: motion_control: 'Flite' is not a value "
        "of motion_control (did you mean 'Flight'?); the rules (rules/paper.yaml) have: Joint, "
        "Flight, Driving, Walking, End Effector, Waypoint\n",
        ("/uav9",): "<arguments>: ROBOT: no robot /uav9 on ros2://domain/{domain} (no "
        "/uav9/robot_description) (did you mean '/uav1'?); robots there: /uav1, /ugv1\n",
        ("/uav 1",): "<arguments>: ROBOT: the robot '/uav 1' is no ROS name: it has a character "
        "other than a letter, a digit, '_' or '/' at 5\n",
    }
    for args, message in refusals.items():
        result = switch_ros2(domain, *args)
        assert (result.returncode, result.stdout) == (2, ""), args
        assert result.stderr == message.format(domain=domain.id)
    # Nothing was written: the watcher's next selection is the first switch that was not refused.
    assert switch_ros2(domain, "/ugv1").returncode == 0
    first = watch.wait_for(lambda e: e["event"] == "selection_changed", "a selection")
    assert (first["robot"], first["active"]["motion_control"]) == ("/ugv1", None)


def test_a_selection_no_watcher_answers_says_so_within_the_wait(domain: Domain) -> None:
    domain.drone("/uav1")
    result = switch_ros2(domain, "/uav1", "motion_control=Flight", "--wait", "1", "--look", "1")
    assert (result.returncode, result.stdout) == (1, "")
    # No watcher announces a rule set: the names were checked for their syntax only.
    assert result.stderr == (
        "switch: NAME=VALUE checked for syntax only: no running watcher on "
        f"ros2://domain/{domain.id} announces its rule set\n"
        f"switch: no watcher answered /uav1 Flight on ros2://domain/{domain.id} within 1 s (no "
        "answer is there): the selection was offered while switch waited (a watcher started "
        "later does not see it); is a watcher running there (teleop-ui watch)?\n"
    )


# ---- ROS 1 -------------------------------------------------------------------------------------


@pytest.fixture
def ros1_watch(
    master: Roscore, node: TestNode, watch_process: Callable[..., WatchProcess]
) -> WatchProcess:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    watch = watch_process("--master", master.uri, "--team", "case3")
    watch.wait_for(synced("/uav1", "/ugv1"), "synced with both robots")
    return watch


def test_switch_on_a_ros_master_sets_the_parameters_and_prints_the_answer(
    master: Roscore, node: TestNode, ros1_watch: WatchProcess, solution: Solution
) -> None:
    result = run_cli("switch", "--master", master.uri, "/uav1", "motion_control=Waypoint")
    assert (result.returncode, result.stderr) == (0, "")
    lines = result.stdout.splitlines()
    assert lines[0] == (
        f"/uav1 Waypoint -> UI configuration {uav_waypoint(solution)}  <- UAV, Waypoint, "
        "2D Camera, 1"
    )
    assert lines[1].startswith("  answered by /teleop_ui_watch_")
    assert lines[2] == (
        "  note: /uav1 does not offer motion_control 'Waypoint' (it has Flight); using it as asked"
    )
    assert node.get_param("/teleop_ui/active_robot") == "/uav1"
    assert node.get_param("/teleop_ui/active_motion_control") == "Waypoint"
    assert node.get_param("/teleop_ui/ui_configuration")["configuration"] == uav_waypoint(solution)

    # A value the team does not select for the robot: the default, and the reason, printed.
    result = run_cli("switch", "--master", master.uri, "/ugv1", "motion_control=Flight")
    assert result.returncode == 0, result.stderr
    default = expected(
        solution,
        kinematic_type="UGV",
        motion_control="Flight",
        sensor_type="LIDAR",
        sensor_count="1",
    )
    assert result.stdout.splitlines()[0] == (
        f"/ugv1 Flight -> UI configuration {default} (default): motion_control 'Flight' is not "
        "selected for UGV in team 'Case 3'  <- UGV, Flight, LIDAR, 1"
    )

    # --clear deletes the other selections: the rover's own motion control applies again.
    result = run_cli("switch", "--master", master.uri, "/ugv1", "--clear", "--format", "json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["answer"]["configuration"] == rover_configuration(solution)
    assert node.get_param("/teleop_ui/active_motion_control") is MISSING
    ros1_watch.wait_for(selected("/ugv1", motion_control=None), "the cleared selection")


def test_switch_on_a_ros_master_refuses_and_writes_nothing(
    master: Roscore, node: TestNode, ros1_watch: WatchProcess
) -> None:
    hostile = [
        ("/uav1\n/ugv1",),
        ("../../etc/passwd",),
        ("/uav1", "motion_control=\x1b[2J"),
        ("/uav1", "x" * 5000 + "=Flight"),
        ("/uav1", "motion_control=" + "9" * 400),
        ("/uav1", "robot=/ugv1"),
        ("/" + "a" * 300,),
        ("/uav1", "sensor_count=٣"),
    ]
    for args in hostile:
        result = run_cli("switch", "--master", master.uri, *args, "--team", "case3")
        assert (result.returncode, result.stdout) == (2, ""), args
        assert result.stderr.startswith("<arguments>: "), result.stderr
        assert result.stderr.count("\n") == 1, result.stderr
        assert "\x1b" not in result.stderr
    # The rule set the watcher announces refuses too, before anything is written.
    result = run_cli("switch", "--master", master.uri, "/uav1", "sensor_type=Sonar")
    assert result.returncode == 2
    assert "'Sonar' is not a value of sensor_type" in result.stderr
    assert node.get_param("/teleop_ui/active_robot") is MISSING
    assert node.get_param("/teleop_ui/active_sensor_type") is MISSING


def test_switch_lists_the_masters_robots_escaped_when_the_robot_is_not_there(
    master: Roscore, node: TestNode
) -> None:
    put_drone(node, "/uav1")
    # A name written backwards on a terminal (a right-to-left override), and a line break.
    node.set_param("/evil\u202egnp.exe\nok/robot_description", "<robot name='x'/>")
    result = run_cli("switch", "--master", master.uri, "/uav2", "--team", "case3")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"<arguments>: ROBOT: no robot /uav2 on {master.uri} (no /uav2/robot_description) "
        "(did you mean '/uav1'?); robots there: /evil\\u202egnp.exe\\nok, /uav1\n"
    )
    assert node.get_param("/teleop_ui/active_robot") is MISSING


def test_a_master_without_a_watcher_gives_no_answer_and_exit_1(
    master: Roscore, node: TestNode
) -> None:
    put_drone(node, "/uav1")
    result = run_cli("switch", "--master", master.uri, "/uav1", "--team", "case3", "--wait", "0.5")
    assert (result.returncode, result.stdout) == (1, "")
    assert result.stderr == (
        f"switch: no watcher answered /uav1 on {master.uri} within 0.5 s (no answer is there): "
        "the selection is written; is a watcher running there (teleop-ui watch)?\n"
    )
    # The master keeps the selection, for a watcher that comes later.
    assert node.get_param("/teleop_ui/active_robot") == "/uav1"
    data = run_cli(
        "switch", "--master", master.uri, "/uav1", "--team", "case3", "--wait", "0.5", "-f", "json"
    )
    assert data.returncode == 1
    assert json.loads(data.stdout)["answer"] is None


def test_a_master_that_is_not_there_is_exit_2() -> None:
    from tests.live.roscore import free_port

    uri = f"http://127.0.0.1:{free_port()}"
    result = run_cli("switch", "--master", uri, "/uav1", "--team", "case3")
    assert (result.returncode, result.stdout) == (2, "")
    assert "cannot reach the ROS master" in result.stderr
