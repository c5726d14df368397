"""The live view in a real browser, on a ROS 2 graph of real Cyclone DDS participants on
loopback (the emulated robots of the live tests) and on a real ROS 1 master (Debian's
``roscore``, the robots' descriptions and topics registered as their nodes would): a robot
appears, the operator switches to another, one disappears. Expected configurations come from
:func:`solver.assign` (tests.live.fleet), not from the studio.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from solver import load_team, solve
from tests.live.conftest import _require_roscore
from tests.live.fleet import drone_configuration, put_drone, put_rover, rover_configuration
from tests.live.roscore import Roscore, TestNode
from tests.live.sources.test_ros2 import Domain
from tests.studio.conftest import StartStudio


@pytest.fixture
def domain(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Domain]:
    from tests.live.ros2_graph import write_config

    # The operator's participant lives in this process: loopback for it too.
    monkeypatch.setenv("CYCLONEDDS_URI", write_config(tmp_path))
    monkeypatch.setenv("ROS_DOMAIN_ID", "999")  # never used: the studio is given its domain
    found = Domain(tmp_path, dict(os.environ))
    yield found
    for robot in found.robots:
        robot.kill()


def test_robots_appear_switch_and_disappear_in_the_live_view(
    start_studio: StartStudio, page: Page, domain: Domain
) -> None:
    from tests.live.ros2_graph import Operator

    solution = solve(load_team("case3"))
    server = start_studio("case3", "--ros2", "--domain", str(domain.id), env=domain.env)
    page.goto(server.at("live"))
    expect(page.locator("#live-status")).to_contain_text(f"ROS 2 domain {domain.id}: synced")

    domain.drone("/uav1")
    drone = page.locator('tr[data-robot="/uav1"]')
    expect(drone).to_contain_text("UAV")
    expect(drone.locator("td.configurations")).to_have_text(str(drone_configuration(solution)))
    expect(page.locator("#event-log")).to_contain_text("robot_added /uav1")

    rover = domain.rover("/ugv1")
    row = page.locator('tr[data-robot="/ugv1"]')
    expect(row.locator("td.configurations")).to_have_text(str(rover_configuration(solution)))

    operator = Operator(domain.id)
    try:
        operator.activate("/uav1")
        expect(drone).to_have_attribute("aria-current", "true")
        expect(page.locator("#live-selection")).to_contain_text(
            f"UI configuration {drone_configuration(solution)}"
        )
        operator.activate("/ugv1")
        expect(row).to_have_attribute("aria-current", "true")
        expect(drone).not_to_have_attribute("aria-current", "true")
        expect(page.locator("#live-selection")).to_contain_text(
            f"UI configuration {rover_configuration(solution)}"
        )
    finally:
        operator.close()

    rover.kill()
    expect(row).to_have_count(0)
    expect(page.locator("#event-log")).to_contain_text("robot_removed /ugv1")
    expect(drone).to_have_count(1)
    # The same state as JSON, for an operator station.
    state = server.json("/api/live")
    assert [robot["robot"] for robot in state["robots"]] == ["/uav1"]


@pytest.fixture
def roscore(tmp_path: Path) -> Iterator[Roscore]:
    """A roscore of this test's own on loopback (the live tests' master)."""
    _require_roscore()
    (tmp_path / "ros").mkdir()
    core = Roscore(tmp_path / "ros")
    core.start()
    yield core
    core.kill()


def test_robots_appear_switch_and_disappear_in_the_live_view_of_a_ros_master(
    start_studio: StartStudio, page: Page, roscore: Roscore
) -> None:
    solution = solve(load_team("case3"))
    server = start_studio("case3", "--master", roscore.uri)
    page.goto(server.at("live"))
    expect(page.locator("#live-status")).to_contain_text(f"{roscore.uri}: synced")

    node = TestNode(roscore.uri)
    try:
        put_drone(node, "/uav1")
        drone = page.locator('tr[data-robot="/uav1"]')
        expect(drone).to_contain_text("UAV")
        expect(drone.locator("td.configurations")).to_have_text(str(drone_configuration(solution)))
        expect(page.locator("#event-log")).to_contain_text("robot_added /uav1")

        put_rover(node, "/ugv1")
        rover = page.locator('tr[data-robot="/ugv1"]')
        expect(rover.locator("td.configurations")).to_have_text(str(rover_configuration(solution)))

        # The operator station names its active robot on the master, as `watch` reads it.
        node.set_param("/teleop_ui/active_robot", "/uav1")
        expect(drone).to_have_attribute("aria-current", "true")
        expect(page.locator("#live-selection")).to_contain_text(
            f"UI configuration {drone_configuration(solution)}"
        )
        node.set_param("/teleop_ui/active_robot", "/ugv1")
        expect(rover).to_have_attribute("aria-current", "true")
        expect(drone).not_to_have_attribute("aria-current", "true")
        expect(page.locator("#live-selection")).to_contain_text(
            f"UI configuration {rover_configuration(solution)}"
        )

        # The rover goes: its description is taken away and its nodes leave the master.
        node.delete_param("/ugv1/robot_description")
        node.unpublish("/ugv1/laser_driver", ["/ugv1/scan"])
        node.unsubscribe("/ugv1/base_driver", ["/ugv1/cmd_vel"])
        expect(rover).to_have_count(0)
        expect(page.locator("#event-log")).to_contain_text("robot_removed /ugv1")
        expect(drone).to_have_count(1)
        state = server.json("/api/live")
        assert [robot["robot"] for robot in state["robots"]] == ["/uav1"]
    finally:
        node.clear()
        node.close()
