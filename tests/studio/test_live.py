"""The live view in a real browser, on a ROS 2 graph of real Cyclone DDS participants on
loopback (the emulated robots of the live tests) and on a real ROS 1 master (Debian's
``roscore``, the robots' descriptions and topics registered as their nodes would): a robot
appears, the operator switches to another, one disappears. Expected configurations come from
:func:`solver.assign` (tests.live.fleet), not from the studio.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Page, expect

from solver import load_team, solve
from solver.layouts.checks import check_lichtblick
from solver.live.graph import MISSING
from solver.studio.live import summary
from tests.live.conftest import _require_roscore
from tests.live.fleet import drone_configuration, put_drone, put_rover, rover_configuration
from tests.live.ros2_graph import Domain
from tests.live.roscore import Roscore, TestNode, wait_until
from tests.studio.conftest import Server, StartStudio


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
    expect(page.locator("#event-log")).to_contain_text("Robot joined: /uav1 is a UAV")

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
    expect(page.locator("#event-log")).to_contain_text("Robot left: /ugv1")
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
        expect(page.locator("#event-log")).to_contain_text("Robot joined: /uav1 is a UAV")

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

        # A click in the page switches back, on the master, as `teleop-ui switch` does.
        drone.locator("button.robot").click()
        expect(drone).to_have_attribute("aria-current", "true")
        expect(page.locator("#switch-status")).to_contain_text(
            f"/uav1: UI configuration {drone_configuration(solution)}"
        )
        assert node.get_param("/teleop_ui/active_robot") == "/uav1"

        # The rover goes: its description is taken away and its nodes leave the master.
        node.delete_param("/ugv1/robot_description")
        node.unpublish("/ugv1/laser_driver", ["/ugv1/scan"])
        node.unsubscribe("/ugv1/base_driver", ["/ugv1/cmd_vel"])
        expect(rover).to_have_count(0)
        expect(page.locator("#event-log")).to_contain_text("Robot left: /ugv1")
        expect(drone).to_have_count(1)
        state = server.json("/api/live")
        assert [robot["robot"] for robot in state["robots"]] == ["/uav1"]
    finally:
        node.clear()
        node.close()


def test_a_click_on_a_robot_or_one_of_its_values_makes_it_active_with_its_layout(
    start_studio: StartStudio, page: Page, domain: Domain, tmp_path: Path
) -> None:
    solution = solve(load_team("case3"))
    folder = tmp_path / "layouts"
    server = start_studio(
        "case3", "--ros2", "--domain", str(domain.id), "--layouts", str(folder), env=domain.env
    )
    domain.drone("/uav1")
    domain.rover("/ugv1")
    # The page's own selection is another team (UAVs alone): the header names the feed's.
    page.goto(server.at("live?type=UAV"))
    expect(page.locator("#context-team")).to_have_text("Case 3")
    expect(page.locator("#context-rules")).to_have_text("Mortimer et al. 2017")
    rover = page.locator('tr[data-robot="/ugv1"]')
    drone = page.locator('tr[data-robot="/uav1"]')
    expect(rover.locator("td.configurations")).to_have_text(str(rover_configuration(solution)))
    expect(drone.locator("td.configurations")).to_have_text(str(drone_configuration(solution)))

    rover.locator("button.robot").click()
    expect(rover).to_have_attribute("aria-current", "true")
    number = rover_configuration(solution)
    expect(page.locator("#live-selection")).to_contain_text(f"UI configuration {number}")
    expect(page.locator("#switch-status")).to_contain_text(f"/ugv1: UI configuration {number}")
    written = folder.absolute() / "ugv1" / f"config-{number:03d}.json"
    expect(rover.locator("td.robot-layout code.path").first).to_have_text(str(written))
    assert check_lichtblick(json.loads(written.read_text(encoding="utf-8")), str(written)) == ()

    # A value of the drone: the drone becomes active with it.
    drone.locator('button.value[value="motion_control=Flight"]').click()
    expect(drone).to_have_attribute("aria-current", "true")
    expect(rover).not_to_have_attribute("aria-current", "true")
    expect(drone.locator('button.value[value="motion_control=Flight"]')).to_have_attribute(
        "aria-pressed", "true"
    )
    number = drone_configuration(solution)
    expect(page.locator("#live-selection")).to_contain_text(
        f"Active: /uav1, motion_control Flight: UI configuration {number}"
    )
    written = folder.absolute() / "uav1" / f"config-{number:03d}.json"
    expect(drone.locator("td.robot-layout code.path").first).to_have_text(str(written))
    log = page.locator("#event-log")
    expect(log).to_contain_text(
        "This studio switched to /uav1 (motion_control Flight); the watcher"
    )
    expect(log).to_contain_text(
        f"The active robot is /uav1 (motion_control Flight): UI configuration {number} "
        "(UAV, Flight, 2D Camera, 1)"
    )

    # The layout the page links, and its preview, are the drone's as the watcher wrote it.
    link = drone.locator("a.download")
    expect(link).to_have_text(f"layout of configuration {number}")
    status, body = server.get(str(link.get_attribute("href")))
    assert status == 200
    assert json.loads(body) == json.loads(written.read_text(encoding="utf-8"))
    preview = drone.locator("img.preview")
    expect(preview).to_have_attribute(
        "alt", f"the panels of /uav1's layout in configuration {number}"
    )
    wait_until(
        lambda: preview.evaluate("image => image.complete && image.naturalWidth > 0") or None,
        60,
        "the preview drawn",
    )


def post_switch(server: Server, body: bytes, headers: dict[str, str] | None = None) -> Any:
    status, answer = server.request(
        "POST",
        "/api/live/switch",
        body,
        {"content-type": "application/json", **(headers or {})},
    )
    return status, json.loads(answer)


def test_the_switch_is_refused_from_another_site_without_the_token_or_when_wrong(
    start_studio: StartStudio, roscore: Roscore
) -> None:
    import urllib.error
    import urllib.request

    node = TestNode(roscore.uri)
    try:
        put_drone(node, "/uav1")
        server = start_studio("case3", "--master", roscore.uri)
        wait_until(
            lambda: server.json("/api/live")["robots"] or None, 60, "the drone in the live feed"
        )
        body = json.dumps({"robot": "/uav1"}).encode()
        # Without the token: a stranger on this machine.
        request = urllib.request.Request(
            server.base + "api/live/switch",
            data=body,
            method="POST",
            headers={"content-type": "application/json"},
        )
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(request, timeout=60)
        assert refused.value.code == 401
        # With the token (a cookie the browser sends anywhere), from another site's page.
        for headers in (
            {"sec-fetch-site": "cross-site"},
            {"sec-fetch-site": "same-site"},
            {"origin": "http://evil.example"},
        ):
            status, answer = post_switch(server, body, headers)
            assert status == 403, headers
            assert answer["faults"] == []
        # What is no switch: located faults, nothing written.
        wrong = {
            b'{"robot": "/uav 1"}': "<arguments>: ROBOT: the robot '/uav 1' is no ROS name",
            b'{"robot": "/uav1", "values": {"motion_contrl": "Flight"}}': "unknown "
            "characteristic 'motion_contrl' (did you mean 'motion_control'?)",
            b'{"robot": "/uav1", "values": {"motion_control": "Flite"}}': "'Flite' is not a "
            "value of motion_control (did you mean 'Flight'?)",
            b'{"robot": "/uav2"}': "no robot /uav2 on",
            b'{"robot": "/uav1", "wait": 3600}': '"wait" is seconds from 0.01 to 30',
            b"[" * 100_000: "a switch is at most 16384 bytes of JSON",
            b"[" * 100: "a switch is a JSON object: nested deeper than 64 levels",
            b"\xff": "a switch is a JSON object",
            b'{"robot": ["/uav1"]}': 'a switch is a JSON object with "robot": "/NAME"',
        }
        for sent, message in wrong.items():
            status, answer = post_switch(server, sent)
            assert status == 422, sent[:40]
            (fault,) = answer["faults"]
            assert message in f"{fault['file']}: {fault['path']}: {fault['message']}", answer
        assert node.get_param("/teleop_ui/active_robot") is MISSING
        # From a program with the token: made, and answered by the studio's own watcher.
        status, answer = post_switch(server, body)
        assert status == 200, answer
        solution = solve(load_team("case3"))
        assert answer["answer"]["configuration"] == drone_configuration(solution)
        assert node.get_param("/teleop_ui/active_robot") == "/uav1"
        # The page's form, without its script: the switch is made, then the Live view shows it.
        status, _ = server.request(
            "POST",
            "/live/switch",
            b"robot=%2Fuav1&value=motion_control%3DWaypoint",
            {"content-type": "application/x-www-form-urlencoded"},
        )
        assert status == 200  # the Live view, after the studio's 303
        assert node.get_param("/teleop_ui/active_motion_control") == "Waypoint"
    finally:
        node.clear()
        node.close()


def test_each_event_reads_as_a_sentence_with_what_the_graph_wrote_escaped() -> None:
    assert summary(
        {
            "event": "selection_changed",
            "robot": "/ugv1",
            "active": {"motion_control": "Flight", "sensor_type": None},
            "assignment": {
                "combination": {"kinematic_type": "UGV", "motion_control": "Flight"},
                "configuration": 103,
                "default": True,
                "reasons": ["motion_control 'Flight' is not selected for UGV in team 'Case 3'"],
            },
            "notes": ["/ugv1 does not offer motion_control 'Flight' (it has Driving)"],
        }
    ) == (
        "The active robot is /ugv1 (motion_control Flight): the default UI configuration 103 "
        "(UGV, Flight), because motion_control 'Flight' is not selected for UGV in team "
        "'Case 3'; note: /ugv1 does not offer motion_control 'Flight' (it has Driving)"
    )
    assert summary({"event": "selection_changed", "robot": None}) == (
        "No robot is active (/teleop_ui/active_robot is not set)"
    )
    assert summary(
        {"event": "switch", "robot": "/uav1", "selection": {"motion_control": None}}
    ) == ("This studio switched to /uav1; no watcher answered in time")
    assert summary({"event": "robot_removed", "robot": "/evil\n\u202eforged"}) == (
        "Robot left: /evil\\n\\u202eforged"
    )
    assert summary(
        {"event": "robot_added", "robot": "/broken", "error": "line 1: malformed\nline 2"}
    ) == ("Robot joined: /broken cannot be identified: line 1: malformed")
