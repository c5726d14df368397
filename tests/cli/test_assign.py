"""``teleop-ui assign`` as a user runs it: a robot's values given on the command line, or read
from a real ROS master (``--master``) or a ROS 2 graph (``--ros2``, real Cyclone DDS
participants on loopback).
"""

from __future__ import annotations

import json
from pathlib import Path

from solver.live.graph import MISSING
from solver.solving.solution import Solution
from tests.conftest import ROOT, run_cli
from tests.live.fleet import (
    drone_configuration,
    expected,
    put_drone,
    put_rover,
    rover_configuration,
)
from tests.live.ros2_graph import Domain
from tests.live.roscore import Roscore, TestNode

# ---- values given on the command line --------------------------------------------------------


def test_assign_gives_the_configuration_number_and_components() -> None:
    result = run_cli(
        "assign",
        "--team",
        "rules/teams/case3.yaml",
        "kinematic_type=UAV",
        "motion_control=Flight",
        "sensor_type=2D Camera",
        "sensor_count=3",
    )
    assert result.returncode == 0
    assert result.stdout.splitlines()[:5] == [
        "UI configuration 1 for kinematic_type=UAV motion_control=Flight "
        "sensor_type=2D Camera sensor_count=3",
        "  Robot Kinematic Type: UAV",
        "  Robot Motion Control: Flight",
        "  Sensor Type: visual display",
        "  No. of Sensors: individual (3: 3 clusters)",
    ]


def test_assign_answers_an_invalid_robot_with_the_default_and_exits_0() -> None:
    result = run_cli(
        "assign",
        "--team",
        "case3",
        "-f",
        "json",
        "kinematic_type=Quadruped",
        "motion_control=Walking",
        "sensor_type=360 Camera",
        "sensor_count=4",
    )
    assert result.returncode == 0
    data = json.loads(result.stdout)
    assert (data["configuration"], data["default"]) == (103, True)
    assert data["reasons"] == ["unknown robot kinematic type 'Quadruped'"]
    assert data["relevant_components"]["sensor_type"] == ["spherical display"]


def test_assign_with_an_unknown_characteristic_name_exits_2() -> None:
    result = run_cli("assign", "--team", "case1", "colour=red")
    assert result.returncode == 2
    assert "unknown characteristic 'colour'" in result.stderr


# ---- a ROS master ----------------------------------------------------------------------------


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


def test_assign_reads_a_robots_declared_description_and_says_where_it_differs(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_rover(node, "/ugv1")  # its topics show Driving
    node.set_param(
        "/ugv1/teleop_description",
        "teleop: 1\nmotion_controls:\n  - {control: Waypoint, action: /ugv1/navigate_to_pose}\n",
    )
    put_rover(node, "/ugv2")
    node.set_param("/ugv2/teleop_description", "teleop: 2\n")
    ask = ("assign", "--master", master.uri, "--team", "case3", "-f", "json", "--robot")
    declared = run_cli(*ask, "/ugv1")
    assert declared.returncode == 0, declared.stderr
    data = json.loads(declared.stdout)
    assert data["combination"]["motion_control"] == "Waypoint"
    assert data["configuration"] == expected(
        solution,
        kinematic_type="UGV",
        motion_control="Waypoint",
        sensor_type="LIDAR",
        sensor_count="1",
    )
    said = [note for note in data["notes"] if note.startswith("declared and read differ")]
    assert [note.split(": ")[1] for note in said] == [
        "motion control Driving",
        "motion control Waypoint",
    ]
    hostile = run_cli(*ask, "/ugv2")
    assert hostile.returncode == 0, hostile.stderr
    data = json.loads(hostile.stdout)
    assert data["configuration"] == rover_configuration(solution)
    [note] = data["notes"]
    assert note.startswith("/ugv2/teleop_description:1:")
    assert note.endswith("; not used: what identification read stands")


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


# ---- a ROS 2 graph ---------------------------------------------------------------------------


def test_assign_ros2_answers_for_one_robot_and_refuses_an_unknown_one(
    domain: Domain, solution: Solution
) -> None:
    domain.drone("/uav1")
    domain.rover("/ugv1", gid_size=24)
    result = run_cli(
        "assign",
        "--ros2",
        "--domain",
        str(domain.id),
        "--team",
        "case3",
        "--robot",
        "/ugv1",
        "-f",
        "json",
    )
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert (data["robot"], data["configuration"]) == ("/ugv1", rover_configuration(solution))
    unknown = run_cli(
        "assign", "--ros2", "--domain", str(domain.id), "--team", "case3", "--robot", "/uav2"
    )
    assert unknown.returncode == 2
    assert unknown.stderr.startswith(f"<arguments>: no robot /uav2 on ros2://domain/{domain.id}")
    assert "robots there: /uav1, /ugv1" in unknown.stderr
