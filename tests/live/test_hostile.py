"""Hostile robots, masters, nodes and values: none takes the operator's station down.

Issue 18: one hostile robot on a real roscore must not take the operator's station down.

Every robot here publishes something the readers refuse or did not expect: a Gazebo ray sensor
with ``<samples>inf</samples>`` (an OverflowError in the URDF reader before it was fixed), a
description past the XML reader's size cap, text that is not XML. The watcher (in a thread, and
``watch --once`` / ``assign --master`` as a user runs them) must report each as that robot's
error and keep serving the good robots beside them. The cases after the size cap still raise
after the reader's own fixes, so these tests hold whatever the reader does with ``inf``.

Issues 23 (items 5 and 6), 30 (items 4 and 7) and 31 (items 2 and 3): a master that trickles,
floods or sends a gzip bomb; values thousands of levels deep or megabytes long; a spoofed
``paramUpdate`` on the watcher's own port; a rival node that registered ``rosrpc://evil:1/`` or
whose API answers slowly; a malformed ``ROS_MASTER_URI``. Each ends as a located error (exit 2),
a note in an event, or is ignored, never a traceback, a hang or a signal. The peers are small
hostile servers the tests run (:mod:`tests.live.hostile`) and a real roscore; hypothesis sets
random values as ``/teleop_ui`` parameters and descriptions on the real master.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import xmlrpc.client
from collections.abc import Callable, Iterator
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from solver.identify.identification import Identification, IdentificationCache
from solver.identify.profile import Profile
from solver.identify.readers.safexml import MAX_XML_BYTES
from solver.live.events import event_data
from solver.live.sources.ros1.master import MasterClient
from solver.live.sources.ros1.rpc import MAX_REPLY_BYTES
from solver.live.values import MAX_SELECTION_CHARS
from solver.live.watcher import Watcher
from solver.solving.solution import Solution
from tests.conftest import ROOT, run_cli
from tests.identify import builders
from tests.live.conftest import Recorder
from tests.live.fleet import (
    drone_configuration,
    drone_text,
    put_drone,
    put_rover,
    rover_configuration,
    rover_text,
)
from tests.live.hostile import (
    RAW,
    Behaviour,
    FakeMaster,
    RawServer,
    TricklingClients,
    answering,
    deep_xml,
    empty_graph,
    flooding,
    gzip_bomb,
    post_raw,
    raw_set_param,
    trickling,
)
from tests.live.roscore import Roscore, TestNode, wait_until

Start = Callable[..., Recorder]


def infinite_samples_text() -> str:
    """A rover whose laser claims infinitely many samples (``1e999`` in its vertical scan)."""
    robot = builders.ugv()
    robot.add(
        builders.gazebo_sensor(
            robot.root,
            "ray",
            "front_laser",
            "<ray><scan><horizontal><samples>inf</samples></horizontal>"
            "<vertical><samples>1e999</samples></vertical></scan></ray>",
        )
    )
    return robot.text()


def oversized_text() -> str:
    """A well-formed URDF one comment longer than the reader's cap."""
    text = builders.quadrotor().text()
    return text.replace("</robot>", "<!--" + "x" * (MAX_XML_BYTES + 1) + "-->\n</robot>")


def put_hostile(node: TestNode) -> None:
    node.set_param("/inf/robot_description", infinite_samples_text())
    node.set_param("/huge/robot_description", oversized_text())
    node.set_param("/garbage/robot_description", "\x7fELF this is not a robot description")


def by_robot(events: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    return {e["robot"]: e for e in events if e["event"] == "robot_added"}


def assert_hostile_reported(robots: dict[str, dict[str, Any]]) -> None:
    huge = robots["/huge"]
    assert huge["combinations"] == []
    assert huge["error"].startswith("/huge/robot_description")
    assert f"larger than {MAX_XML_BYTES} bytes" in huge["error"]
    garbage = robots["/garbage"]
    assert garbage["combinations"] == []
    assert garbage["error"].startswith("/garbage/robot_description:1:")
    # The reader may accept ``inf`` (ignored with a warning) or refuse it: either way the
    # robot is reported, and never as a traceback.
    assert robots["/inf"]["error"] is None or robots["/inf"]["error"].startswith(
        "/inf/robot_description"
    )


def test_hostile_robots_are_reported_and_the_watcher_keeps_serving_the_others(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_hostile(node)
    put_drone(node, "/uav1")
    watch = start_watcher(master.uri)
    synced = watch.wait_for_event("synced")
    assert synced["robots"] == ["/garbage", "/huge", "/inf", "/uav1"]
    robots = by_robot(watch.data())
    assert_hostile_reported(robots)
    assert robots["/uav1"]["combinations"][0]["configuration"] == drone_configuration(solution)
    # Still serving: a robot that comes later is identified, and the operator's switch answered.
    mark = watch.mark()
    put_rover(node, "/ugv1")
    # Its description may be read before its topics are registered: wait for the full robot.
    watch.wait_for(
        lambda d: (
            d.get("robot") == "/ugv1"
            and bool(d.get("combinations"))
            and d["combinations"][0]["configuration"] == rover_configuration(solution)
        ),
        "/ugv1 identified as a rover",
        after=mark,
    )
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    selected = watch.wait_for(
        lambda d: d["event"] == "selection_changed" and d["robot"] == "/ugv1",
        "selection of /ugv1",
        after=mark,
    )
    assert selected["assignment"]["configuration"] == rover_configuration(solution)
    # Selecting the hostile robot gives the default, with a reason, not a crash.
    mark = watch.mark()
    node.set_param("/teleop_ui/active_robot", "/huge")
    hostile = watch.wait_for(
        lambda d: d["event"] == "selection_changed" and d["robot"] == "/huge",
        "selection of /huge",
        after=mark,
    )
    assert hostile["assignment"] is not None


class _BrokenReader(IdentificationCache):
    """Identification raising what no reader declares, for one description: a stand-in for
    the next reader bug (an OverflowError was the last one), which the watcher must contain."""

    def identify_urdf(self, urdf_text: str | bytes, **options: Any) -> Identification:
        if "front_laser" in (urdf_text if isinstance(urdf_text, str) else ""):
            raise OverflowError("cannot convert float infinity to integer")
        return super().identify_urdf(urdf_text, **options)


def test_an_exception_no_reader_declares_stays_that_robots_error(
    master: Roscore, node: TestNode, solution: Solution, profile: Profile
) -> None:
    node.set_param("/inf/robot_description", infinite_samples_text())
    put_drone(node, "/uav1")
    with Watcher(master.uri, solution, profile, push=False, cache=_BrokenReader()) as watcher:
        robots = by_robot([event_data(e, solution) for e in watcher.snapshot()])
    assert robots["/inf"]["error"] == (
        "/inf/robot_description: cannot identify (OverflowError: "
        "cannot convert float infinity to integer)"
    )
    assert robots["/uav1"]["error"] is None


def test_watch_once_reports_hostile_robots_and_exits_0(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_hostile(node)
    put_rover(node, "/ugv1")
    result = run_cli(
        "watch", "--master", master.uri, "--team", "case3", "--once", "--format", "json"
    )
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    assert events[-1]["robots"] == ["/garbage", "/huge", "/inf", "/ugv1"]
    robots = by_robot(events)
    assert_hostile_reported(robots)
    assert robots["/ugv1"]["combinations"][0]["configuration"] == rover_configuration(solution)


def test_assign_master_answers_beside_a_hostile_robot_and_refuses_it_located(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_hostile(node)
    put_drone(node, "/uav1")
    good = run_cli(
        "assign", "--master", master.uri, "--team", "case3", "--robot", "/uav1", "-f", "json"
    )
    assert good.returncode == 0, good.stderr
    assert json.loads(good.stdout)["configuration"] == drone_configuration(solution)
    for robot in ("/huge", "/garbage"):
        bad = run_cli("assign", "--master", master.uri, "--team", "case3", "--robot", robot)
        assert bad.returncode == 2
        assert "Traceback" not in bad.stderr
        assert f"robot {robot} cannot be identified: {robot}/robot_description" in bad.stderr
    inf = run_cli("assign", "--master", master.uri, "--team", "case3", "--robot", "/inf")
    assert inf.returncode in (0, 2)
    assert "Traceback" not in inf.stderr


# -- hostile masters (issue 23 item 5, issue 31 item 3) ----------------------------------------


@pytest.fixture
def serve() -> Iterator[Callable[[Behaviour], RawServer]]:
    started: list[RawServer] = []

    def start(behaviour: Behaviour) -> RawServer:
        started.append(RawServer(behaviour))
        return started[-1]

    yield start
    for server in started:
        server.close()


def assert_refused(result: Any, message: str) -> None:
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    assert message in result.stderr, result.stderr


def test_watch_once_on_a_master_replying_a_byte_a_second_ends_at_its_timeout(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    master = serve(trickling)
    result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once", "--timeout", "2")
    assert_refused(result, "")
    assert result.stderr == (
        f"{master.uri}: the ROS master did not answer in time: is roscore running there? "
        "(--wait waits for it)\n"
    )


def test_sigterm_ends_a_watch_blocked_on_a_trickling_master(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    """--timeout 3600 on a master that trickles: only SIGTERM can end the call, and does."""
    master = serve(trickling)
    command = ["watch", "--master", master.uri, "--team", "case3", "--timeout", "3600"]
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", *command],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        assert master.asked.wait(60), "the watcher never called the master"
        process.send_signal(signal.SIGTERM)
        stdout, stderr = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate(timeout=60)
    assert (process.returncode, stdout) == (0, "")
    assert stderr == "watch stopped: terminated (SIGTERM)\n"


HUGE = [
    pytest.param(flooding(chunked=False), id="declared-300MB"),
    pytest.param(flooding(chunked=True), id="endless-chunks"),
    pytest.param(
        answering(gzip_bomb(MAX_REPLY_BYTES + 1024 * 1024), "Content-Encoding: gzip\r\n"),
        id="gzip-bomb",
    ),
]


@pytest.mark.parametrize("behaviour", HUGE)
@pytest.mark.parametrize("command", ["watch", "assign"])
def test_a_reply_past_the_cap_is_refused_by_watch_and_assign(
    serve: Callable[[Behaviour], RawServer], behaviour: Behaviour, command: str
) -> None:
    master = serve(behaviour)
    options = ["--once"] if command == "watch" else ["--robot", "/uav1"]
    # A deadline far beyond the time 32 MiB take on a loaded machine: the cap, not the
    # deadline, is what must end the read.
    result = run_cli(
        command, "--master", master.uri, "--team", "case3", "--timeout", "600", *options
    )
    assert_refused(result, f"not read: a reply larger than {MAX_REPLY_BYTES} bytes")
    assert result.stderr.startswith(f"{master.uri}: ")


def test_a_master_serving_a_value_3000_levels_deep_gets_a_note() -> None:
    master = FakeMaster(
        empty_graph({"/teleop_ui/active_robot": RAW}), raw=deep_xml(3000, "<value>/uav1</value>")
    )
    try:
        result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
        assign = run_cli("assign", "--master", master.uri, "--team", "case3")
    finally:
        master.close()
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    assert [e["event"] for e in events] == ["selection_changed", "synced"]
    # Built to MAX_DEPTH levels, no further: a list, as far as anyone reads it.
    assert events[0]["notes"] == ["/teleop_ui/active_robot ignored: expected text, got a list"]
    assert_refused(assign, "no --robot given and no /teleop_ui/active_robot set")


# -- deep and huge values on a real master (issue 23 item 6, issue 30 item 7) ------------------


def test_deep_and_huge_selection_values_on_a_real_master_are_notes_with_short_echoes(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    # Within what rosmaster itself can send back (its marshaller recurses), past ours:
    raw_set_param(master.uri, "/teleop_ui/active_robot", deep_xml(200))
    # Past what rosmaster can send: it answers getParam with a fault.
    raw_set_param(master.uri, "/teleop_ui/active_sensor_type", deep_xml(3000))
    node.set_param("/teleop_ui/active_motion_control", "F" * 10_000_000)
    raw_set_param(master.uri, "/deep/robot_description", deep_xml(3000))
    result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    assert len(result.stdout) < 20_000  # no echo of the 10 MB value (was 20 MB of output)
    events = [json.loads(line) for line in result.stdout.splitlines()]
    robots = by_robot(events)
    assert robots["/deep"]["error"].startswith(
        "/deep/robot_description: cannot be read from the master: XML-RPC fault"
    )
    assert robots["/uav1"]["combinations"][0]["configuration"] == drone_configuration(solution)
    (selection,) = [e for e in events if e["event"] == "selection_changed"]
    assert selection["robot"] is None
    assert selection["active"]["motion_control"] is None
    notes = selection["notes"]
    assert notes[0] == "/teleop_ui/active_robot ignored: expected text, got a list"
    assert notes[1] == (
        f"/teleop_ui/active_motion_control ignored: 10,000,000 characters, longer than "
        f"{MAX_SELECTION_CHARS} ({'F' * 60}... (cut from 10,000,000 characters))"
    )
    assert notes[2].startswith(
        "/teleop_ui/active_sensor_type ignored: expected text, got an unreadable value "
        "(cannot be read from the master: XML-RPC fault"
    )
    answer = run_cli(
        "assign", "--master", master.uri, "--team", "case3", "--robot", "/uav1", "-f", "json"
    )
    assert answer.returncode == 0, answer.stderr
    assert json.loads(answer.stdout)["configuration"] == drone_configuration(solution)


def test_a_description_the_master_cannot_send_is_that_robots_error_beside_a_readable_selection(
    master: Roscore, node: TestNode, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    # rosmaster fails the whole multicall on it: the descriptions are then read one by one.
    raw_set_param(master.uri, "/deep/robot_description", deep_xml(3000))
    result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
    assert result.returncode == 0, result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    robots = by_robot(events)
    assert robots["/deep"]["error"].startswith(
        "/deep/robot_description: cannot be read from the master: XML-RPC fault"
    )
    (selection,) = [e for e in events if e["event"] == "selection_changed"]
    assert selection["robot"] == "/uav1"
    assert selection["assignment"]["configuration"] == drone_configuration(solution)


# -- the watcher's own port (issue 31 item 2) ----------------------------------------------------


def test_a_spoofed_param_update_changes_nothing_the_master_holds(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    """Anyone can call paramUpdate on the watcher's node: the value is read from the master."""
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    watch = start_watcher(master.uri)
    watch.wait_for(
        lambda d: d["event"] == "selection_changed" and d["robot"] == "/uav1", "selection"
    )
    assert watch.watcher.node_uri is not None
    mark = watch.mark()
    spoof = xmlrpc.client.ServerProxy(watch.watcher.node_uri)
    assert spoof.paramUpdate("/master", "/uav1/robot_description/", rover_text()) == [1, "", 0]
    assert spoof.paramUpdate("/master", "/teleop_ui/active_robot", "/ugv1") == [1, "", 0]
    # A genuine change after the spoof: the poll that reports it has read everything after it.
    node.set_param("/teleop_ui/active_motion_control", "Flight")
    marker = watch.wait_for(
        lambda d: d["event"] == "selection_changed" and d["active"]["motion_control"] == "Flight",
        "the genuine change",
        after=mark,
    )
    assert marker["robot"] == "/uav1"
    assert marker["assignment"]["configuration"] == drone_configuration(solution)
    assert [d["event"] for d in watch.data(mark)] == ["selection_changed"]
    written = node.get_param("/teleop_ui/ui_configuration")
    assert (written["robot"], written["kinematic_type"]) == ("/uav1", "UAV")


def test_a_forged_answer_naming_no_watcher_is_reported_and_replaced(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    """Issue 36 item 8, as on ROS 2: anyone can set the answer; a watcher that finds one no
    running watcher wrote says so in a warning and writes its own again."""
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    watch = start_watcher(master.uri)
    mine = watch.watcher.caller_id
    wait_until(lambda: _writer(node) == mine, 60, "the watcher's answer")
    mark = watch.mark()
    forged = {"watcher": "/ghost\nrival", "robot": "/uav1", "configuration": 999}
    node.set_param("/teleop_ui/ui_configuration", forged, node="/forger")
    warning = watch.wait_for(
        lambda d: d["event"] == "warning" and d["where"] == "/teleop_ui/ui_configuration",
        "the forged answer reported",
        after=mark,
    )
    assert warning["message"] == (
        "an answer in the name of /ghost\\nrival, which is no running watcher: replaced by "
        "this watcher's"
    )
    wait_until(lambda: _writer(node) == mine, 60, "the watcher's answer again")
    written = node.get_param("/teleop_ui/ui_configuration")
    assert written["configuration"] == drone_configuration(solution)


def _writer(node: TestNode) -> Any:
    value = node.get_param("/teleop_ui/ui_configuration")
    return value.get("watcher") if isinstance(value, dict) else None


def _answered_kind(node: TestNode) -> tuple[Any, Any] | None:
    """The kinematic type and configuration of the answer on the master."""
    value = node.get_param("/teleop_ui/ui_configuration")
    if not isinstance(value, dict):
        return None
    return value.get("combination", {}).get("kinematic_type"), value.get("configuration")


def test_a_neighbour_trickling_at_the_watchers_node_cannot_freeze_its_answer(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    """Issue 36 item 7: 32 connections trickling a byte at a time into the watcher's node API
    held its request slots, the master's paramUpdate for a changed description was lost, and
    the answer kept the old robot's configuration for good."""
    put_rover(node, "/r1")
    node.set_param("/r1/robot_description", drone_text())  # a UAV's description at first
    node.set_param("/teleop_ui/active_robot", "/r1")
    watch = start_watcher(master.uri)
    wait_until(lambda: (_answered_kind(node) or ("",))[0] == "UAV", 60, "the UAV's answer")
    assert watch.watcher.node_uri is not None
    attack = TricklingClients(watch.watcher.node_uri, 32)
    try:
        attack.wait_ended(64)  # the node's slots are full and changing hands
        node.set_param("/r1/robot_description", rover_text())
        attack.wait_ended(attack.ended + 64)  # the attack goes on after the change
    finally:
        attack.close()
    wait_until(
        lambda: _answered_kind(node) == ("UGV", rover_configuration(solution)),
        60,
        "the answer for the robot's new description",
    )
    assert watch.error is None


def test_a_description_push_the_master_never_sends_is_healed_by_a_later_poll(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    """Issue 36 item 7: anyone can unsubscribe the watcher's node from the master in its name
    (the master believes any caller id); the change then comes by no push at all, and the
    watcher's polls read the description again."""
    put_rover(node, "/r1")
    node.set_param("/r1/robot_description", drone_text())
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")
    assert watch.watcher.node_uri is not None
    neighbour = MasterClient(master.uri, caller_id=watch.watcher.caller_id)
    neighbour.unsubscribe_param(watch.watcher.node_uri, "/r1/robot_description")
    neighbour.close()
    mark = watch.mark()
    node.set_param("/r1/robot_description", rover_text())
    changed = watch.wait_for_event("robot_changed", "/r1", after=mark)
    assert changed["kinematic_type"] == "UGV"
    assert [c["configuration"] for c in changed["combinations"]] == [rover_configuration(solution)]


def _claim(node: TestNode, writer: str, api: str) -> MasterClient:
    """A node ``writer`` registered with node API ``api``, its answer left on the master."""
    rival = MasterClient(node.master, caller_id=writer, timeout=10.0)
    rival.register_publisher(f"{writer}/chatter", "std_msgs/String", api)
    node.set_param(
        "/teleop_ui/ui_configuration", {"watcher": writer, "robot": "/uav1", "configuration": 999}
    )
    return rival


def test_a_rival_registered_with_a_rosrpc_api_is_overwritten_with_a_note(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    rival = _claim(node, "/evil", "rosrpc://evil:1/")
    try:
        watch = start_watcher(master.uri)
        selected = watch.wait_for_event("selection_changed")
        assert selected["assignment"]["configuration"] == drone_configuration(solution)
        assert selected["notes"] == [
            "/teleop_ui/ui_configuration was written by /evil, whose node API "
            "rosrpc://evil:1/ is no XML-RPC address: not a watcher's; overwritten"
        ]
        wait_until(
            lambda: (
                node.get_param("/teleop_ui/ui_configuration").get("watcher")
                == watch.watcher.caller_id
            ),
            60,
            "the answer taken over",
        )
        once = run_cli("watch", "--master", master.uri, "--team", "case3", "--once")
        assert once.returncode == 0, once.stderr
    finally:
        rival.unregister_publisher("/evil/chatter", "rosrpc://evil:1/")
        rival.close()


def test_a_rival_whose_node_answers_a_byte_a_second_does_not_hold_the_watcher(
    master: Roscore,
    node: TestNode,
    start_watcher: Start,
    solution: Solution,
    serve: Callable[[Behaviour], RawServer],
) -> None:
    slow = serve(trickling)
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    rival = _claim(node, "/slow", slow.uri)
    try:
        watch = start_watcher(master.uri, timeout=3600.0)
        wait_until(
            lambda: (
                node.get_param("/teleop_ui/ui_configuration").get("watcher")
                == watch.watcher.caller_id
            ),
            60,
            "the answer taken over",
        )
        assert slow.asked.is_set()  # it was asked, and not waited for
        mark = watch.mark()
        put_rover(node, "/ugv1")
        node.set_param("/teleop_ui/active_robot", "/ugv1")
        switched = watch.wait_for(
            lambda d: d["event"] == "selection_changed" and d["robot"] == "/ugv1",
            "the switch to /ugv1",
            after=mark,
        )
        assert switched["assignment"]["configuration"] in (
            rover_configuration(solution),
            solution.default_configuration,  # topics may come a poll after the description
        )
    finally:
        rival.unregister_publisher("/slow/chatter", slow.uri)
        rival.close()


def test_the_watchers_node_refuses_oversized_dtd_and_deep_requests_and_goes_on(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    put_drone(node, "/uav1")
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")
    api = watch.watcher.node_uri
    assert api is not None
    oversized = post_raw(api, f"POST / HTTP/1.1\r\nContent-Length: {MAX_REPLY_BYTES + 1}")
    assert oversized.startswith(b"HTTP/1.0 413") or oversized.startswith(b"HTTP/1.1 413")
    dtd = b'<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "a">]><methodCall/>'
    refused = post_raw(api, f"POST / HTTP/1.1\r\nContent-Length: {len(dtd)}", dtd)
    assert b"<name>faultCode</name>" in refused
    deep = (
        "<?xml version='1.0'?><methodCall><methodName>paramUpdate</methodName><params>"
        "<param><value>/x</value></param><param><value>/teleop_ui/x</value></param>"
        f"<param>{deep_xml(100_000)}</param></params></methodCall>"
    ).encode()
    answered = post_raw(api, f"POST / HTTP/1.1\r\nContent-Length: {len(deep)}", deep)
    assert b"<int>1</int>" in answered
    shutdown: Any = xmlrpc.client.ServerProxy(api).shutdown("/x", "bye\n[forged line]" + "x" * 500)
    assert shutdown[0] == 1
    wait_until(lambda: not watch.thread.is_alive(), 60, "the watcher to stop")
    assert watch.error is None
    assert watch.watcher.stop_reason == (
        "bye\\n[forged line]" + "x" * 43 + "... (cut from 517 characters)"
    )


# -- malformed addresses (issue 30 item 4) -------------------------------------------------------


@pytest.mark.parametrize(
    "uri", ["http://[::1", "http://[zz]:11311", "http://exa mple:11311", "http://h:99999"]
)
def test_a_malformed_ros_master_uri_is_a_usage_error(uri: str) -> None:
    environment = {**os.environ, "ROS_MASTER_URI": uri}
    result = subprocess.run(
        [sys.executable, "-m", "solver", "watch", "--team", "case3", "--once"],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert_refused(
        result,
        "<arguments>: ROS_MASTER_URI: expected a ROS master URI like http://127.0.0.1:11311, "
        f"got {uri!r}",
    )
    given = run_cli("assign", "--master", uri, "--team", "case3", "--robot", "/uav1")
    assert_refused(given, "<arguments>: --master: expected a ROS master URI like")


# -- hypothesis: random values as parameters of a real master ------------------------------------

LIVE_FUZZ = settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[
        HealthCheck.too_slow,
        HealthCheck.function_scoped_fixture,
        HealthCheck.data_too_large,
    ],
)
# What XML-RPC can carry: 32-bit integers, floats, XML 1.0 text, bytes, lists, structs.
_xml_text = st.text(
    st.characters(exclude_categories=("Cs", "Cc", "Cn")) | st.sampled_from("\n\t"), max_size=200
)
# Parameter names (struct keys): what a rosparam name may hold.
_names = st.text("abcdefghijklmnopqrstuvwxyz_0123456789", min_size=1, max_size=8)
_scalars = (
    _xml_text
    | st.integers(-(2**31), 2**31 - 1)
    | st.floats()
    | st.booleans()
    | st.binary(max_size=40)
    | st.just("<robot name='r'><link name='a'/></robot>")
    | st.just("/uav1")
)
_values = st.recursive(
    _scalars,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(_names, inner),
    max_leaves=12,
)
_KEYS = [
    "/teleop_ui/active_robot",
    "/teleop_ui/active_motion_control",
    "/teleop_ui/active_sensor_type",
    "/teleop_ui/ui_configuration",
    "/fuzz/robot_description",
    "/fuzz/robot_description_semantic",
]


@LIVE_FUZZ
@given(params=st.dictionaries(st.sampled_from(_KEYS), _values, min_size=1))
def test_random_parameter_values_on_a_real_master_never_reach_a_traceback(
    master: Roscore, solution: Solution, profile: Profile, params: dict[str, Any]
) -> None:
    writer = MasterClient(master.uri, caller_id="/fuzzer", timeout=30.0)
    try:
        for key in _KEYS:
            writer.delete_param(key)
        for key, value in params.items():
            writer.set_param(key, value)
        with Watcher(master.uri, solution, profile, push=False) as watcher:
            events = [event_data(e, solution) for e in watcher.snapshot()]
        assert events[-1]["event"] == "synced"
        for event in events:
            json.dumps(event)
            for note in event.get("notes", []):
                assert len(note) < 1000
                assert note.isprintable()
    finally:
        for key in _KEYS:
            writer.delete_param(key)
        writer.close()
