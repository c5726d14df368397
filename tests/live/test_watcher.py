"""The watcher on a real roscore: robots come and go, the operator switches, the master dies."""

from __future__ import annotations

import xmlrpc.client
from collections.abc import Callable
from typing import Any

from solver.core.team import load_team
from solver.identify.profile import Profile
from solver.live.events import event_data
from solver.live.graph import MISSING
from solver.live.sources import graph_address
from solver.live.sources.ros1 import MasterGraph
from solver.live.sources.ros1.master import MasterClient
from solver.live.watcher import Watcher, open_watcher
from solver.solving.solution import Solution, solve
from tests.conftest import TEAMS
from tests.live.conftest import Recorder
from tests.live.fleet import (
    drone_configuration,
    drone_text,
    expected,
    large_text,
    put_drone,
    put_rover,
    rover_configuration,
    rover_text,
    still_rover_text,
)
from tests.live.roscore import Roscore, TestNode, wait_until

Start = Callable[..., Recorder]


def kinds(events: list[dict[str, Any]]) -> list[str]:
    return [e["event"] for e in events]


def test_snapshot_reports_every_robot_then_synced(
    master: Roscore, node: TestNode, solution: Solution, profile: Profile
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/team/ugv1")
    with Watcher(master.uri, solution, profile, push=False) as watcher:
        data = [event_data(e, solution) for e in watcher.snapshot()]
    assert kinds(data) == ["robot_added", "robot_added", "synced"]
    assert [d["seq"] for d in data] == [1, 2, 3]
    assert [d["robot"] for d in data[:2]] == ["/team/ugv1", "/uav1"]  # namespace order
    synced = data[2]
    by_robot = {d["robot"]: d for d in data[:2]}
    assert by_robot["/uav1"]["kinematic_type"] == "UAV"
    assert by_robot["/uav1"]["combinations"] == [
        {
            "combination": {
                "kinematic_type": "UAV",
                "motion_control": "Flight",
                "sensor_type": "2D Camera",
                "sensor_count": "1",
            },
            "configuration": drone_configuration(solution),
            "default": False,
            "reasons": [],
        }
    ]
    assert by_robot["/team/ugv1"]["kinematic_type"] == "UGV"
    assert by_robot["/team/ugv1"]["combinations"][0]["configuration"] == rover_configuration(
        solution
    )
    assert synced["robots"] == ["/team/ugv1", "/uav1"]
    assert synced["master"] == master.uri


def test_a_watcher_opened_on_an_address_reads_the_graph_there_through_the_lookup(
    master: Roscore, node: TestNode, solution: Solution, profile: Profile
) -> None:
    put_drone(node, "/uav1")
    address = graph_address(master=master.uri)
    with open_watcher(address, solution, profile, push=False) as watcher:
        assert isinstance(watcher.source, MasterGraph)
        data = [event_data(e, solution) for e in watcher.snapshot()]
    assert kinds(data) == ["robot_added", "synced"]
    assert data[0]["robot"] == "/uav1"
    assert data[1]["master"] == master.uri


def test_the_root_namespace_is_a_robot_of_its_own(
    master: Roscore, node: TestNode, solution: Solution, profile: Profile
) -> None:
    node.set_param("/robot_description", rover_text())
    node.subscribe("/base_driver", [("/cmd_vel", "geometry_msgs/Twist")])
    node.publish("/laser_driver", [("/scan", "sensor_msgs/LaserScan")])
    put_drone(node, "/uav1")
    with Watcher(master.uri, solution, profile, push=False) as watcher:
        data = [event_data(e, solution) for e in watcher.snapshot()]
    root = next(d for d in data if d.get("robot") == "/")
    assert root["kinematic_type"] == "UGV"
    assert root["combinations"][0]["configuration"] == rover_configuration(solution)
    # roscore's own /rosout topics are the root robot's, but say nothing about it.
    assert [s["kind"] for s in root["sensors"]] == ["lidar"]
    drone = next(d for d in data if d.get("robot") == "/uav1")
    assert [s["source"] for s in drone["sensors"]] == ["topics: /camera"]


def test_a_robot_is_added_changed_and_removed_as_its_nodes_come_and_go(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")
    mark = watch.mark()
    node.set_param("/ugv7/robot_description", still_rover_text())
    added = watch.wait_for_event("robot_added", "/ugv7", after=mark)
    assert added["kinematic_type"] == "UGV"
    assert added["motion_controls"] == []  # nothing drives it yet
    assert added["combinations"][0]["default"] is True
    assert "no motion_control given" in added["combinations"][0]["reasons"]

    mark = watch.mark()
    node.subscribe("/ugv7/base_driver", [("/ugv7/cmd_vel", "geometry_msgs/Twist")])
    changed = watch.wait_for_event("robot_changed", "/ugv7", after=mark)
    assert [c["motion_control"] for c in changed["motion_controls"]] == ["Driving"]
    assert "motion_controls" in changed["changed"]
    assert changed["combinations"][0]["configuration"] == expected(
        solution, kinematic_type="UGV", motion_control="Driving"
    )

    mark = watch.mark()
    node.delete_param("/ugv7/robot_description")
    removed = watch.wait_for_event("robot_removed", "/ugv7", after=mark)
    assert removed == {"seq": removed["seq"], "event": "robot_removed", "robot": "/ugv7"}
    seqs = [d["seq"] for d in watch.data()]
    assert seqs == list(range(1, len(seqs) + 1))


def test_a_description_set_again_in_place_is_pushed_and_reported(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    put_drone(node, "/shape")
    # With an hour between polls only the master's push (paramUpdate to the watcher's node)
    # can bring this change within the test's wait.
    watch = start_watcher(master.uri, interval=3600.0)
    watch.wait_for_event("synced")
    mark = watch.mark()
    node.set_param("/shape/robot_description", rover_text())
    changed = watch.wait_for_event("robot_changed", "/shape", after=mark)
    assert changed["kinematic_type"] == "UGV"
    assert "kinematic_type" in changed["changed"]


def test_a_malformed_description_is_reported_and_the_others_go_on(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    node.set_param("/broken/robot_description", '<robot name="b">\n  <link name="a">\n</robot>\n')
    node.set_param("/number/robot_description", 42)
    put_drone(node, "/uav1")
    watch = start_watcher(master.uri)
    broken = watch.wait_for_event("robot_added", "/broken")
    assert broken["kinematic_type"] is None
    assert broken["combinations"] == []
    assert broken["error"].startswith("/broken/robot_description:3:")
    assert "malformed XML" in broken["error"]
    number = watch.wait_for_event("robot_added", "/number")
    assert number["error"] == "/number/robot_description: expected URDF text, got int"
    drone = watch.wait_for_event("robot_added", "/uav1")
    assert drone["combinations"][0]["configuration"] == drone_configuration(solution)
    watch.wait_for_event("synced")
    # Fixing the description turns the error into a robot.
    mark = watch.mark()
    node.set_param("/broken/robot_description", drone_text())
    fixed = watch.wait_for_event("robot_changed", "/broken", after=mark)
    assert fixed["error"] is None
    assert fixed["kinematic_type"] == "UAV"


def test_switching_the_active_robot_gives_its_configuration_and_writes_it_back(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")

    mark = watch.mark()
    node.set_param("/teleop_ui/active_motion_control", "Flight")
    node.set_param("/teleop_ui/active_robot", "uav1")  # relative names are accepted
    selected = watch.wait_for(
        lambda d: (
            d["event"] == "selection_changed"
            and d["robot"] == "/uav1"
            and d["assignment"] is not None
        ),
        "selection of /uav1",
        after=mark,
    )
    assert selected["active"]["motion_control"] == "Flight"
    assert selected["assignment"]["configuration"] == drone_configuration(solution)
    assert selected["assignment"]["default"] is False
    written = wait_until(lambda: _result(node, "/uav1"), 60, "ui_configuration for /uav1")
    assert written["configuration"] == drone_configuration(solution)
    assert written["components"] == selected["assignment"]["components"]
    assert "kinematic_type" in written
    assert None not in written.values()

    mark = watch.mark()
    node.set_param("/teleop_ui/active_motion_control", "Driving")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    switched = watch.wait_for(
        lambda d: (
            d["event"] == "selection_changed"
            and d["robot"] == "/ugv1"
            and d["active"]["motion_control"] == "Driving"
        ),
        "selection of /ugv1 Driving",
        after=mark,
    )
    assert switched["assignment"]["configuration"] == rover_configuration(solution)
    assert wait_until(lambda: _result(node, "/ugv1"), 60, "ui_configuration for /ugv1")[
        "configuration"
    ] == rover_configuration(solution)

    mark = watch.mark()
    node.delete_param("/teleop_ui/active_robot")
    cleared = watch.wait_for(
        lambda d: d["event"] == "selection_changed" and d["robot"] is None,
        "cleared selection",
        after=mark,
    )
    assert cleared["assignment"] is None
    wait_until(
        lambda: node.get_param("/teleop_ui/ui_configuration") is MISSING,
        60,
        "ui_configuration deleted",
    )


def _result(node: TestNode, robot: str) -> dict[str, Any] | None:
    value = node.get_param("/teleop_ui/ui_configuration")
    return value if isinstance(value, dict) and value.get("robot") == robot else None


def _writer(node: TestNode) -> str | None:
    value = node.get_param("/teleop_ui/ui_configuration")
    return value.get("watcher") if isinstance(value, dict) else None


def test_a_second_watcher_with_another_team_leaves_the_first_answer_until_it_is_gone(
    master: Roscore, node: TestNode, start_watcher: Start, profile: Profile
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_motion_control", "Flight")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    first = start_watcher(master.uri)
    mine = first.watcher.caller_id
    wait_until(lambda: _writer(node) == mine, 60, "the first watcher's answer")

    case1 = solve(load_team(TEAMS / "case1.yaml"))
    second = Recorder(Watcher(master.uri, case1, profile), case1)
    try:
        held = second.wait_for_event("selection_changed")
        assert held["assignment"]["team"] == "Case 1"
        assert held["notes"] == [
            f"/teleop_ui/ui_configuration not written: the watcher {mine} answers there with "
            f"configuration {drone_configuration(first.solution)}; run one watcher per graph, "
            "give every watcher the same team and rules, or start this one with --insist"
        ]
        second.wait_for_event("synced")
        # Each reports the other, with both teams.
        theirs = second.wait_for_event("rival")
        assert (theirs["watcher"], theirs["team"], theirs["own_team"], theirs["policy"]) == (
            mine,
            "Case 3",
            "Case 1",
            "yield",
        )
        ours = first.wait_for_event("rival")
        assert (ours["watcher"], ours["team"], ours["own_team"]) == (
            second.watcher.caller_id,
            "Case 1",
            "Case 3",
        )
        value = node.get_param("/teleop_ui/ui_configuration")
        assert (value["watcher"], value["team"]) == (mine, "Case 3")
        assert [d["event"] for d in first.data()].count("selection_changed") == 1

        mark = second.mark()
        first.stop()  # closing releases its node: the answer is free to take over
        taken = wait_until(
            lambda: _writer(node) == second.watcher.caller_id, 60, "the second watcher's answer"
        )
        assert taken
        assert node.get_param("/teleop_ui/ui_configuration")["team"] == "Case 1"
        freed = second.wait_for_event("selection_changed", after=mark)
        assert freed["notes"] == []
        assert second.wait_for_event("rival_gone", after=mark)["watcher"] == mine
    finally:
        second.stop()


def test_watchers_with_the_same_team_leave_each_others_equal_answer(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    first = start_watcher(master.uri)
    wait_until(lambda: _writer(node) == first.watcher.caller_id, 60, "the first answer")
    second = start_watcher(master.uri)
    selected = second.wait_for_event("selection_changed")
    second.wait_for_event("synced")
    assert not any("not written" in note for note in selected["notes"])
    assert _writer(node) == first.watcher.caller_id


def test_an_unknown_active_robot_gets_the_default_with_the_reason(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav9")
    watch = start_watcher(master.uri)
    selected = watch.wait_for_event("selection_changed")
    assert selected["assignment"]["configuration"] == solution.default_configuration
    assert selected["assignment"]["default"] is True
    assert selected["assignment"]["reasons"][0] == "no robot /uav9 on the master (robots: /uav1)"
    written = wait_until(lambda: _result(node, "/uav9"), 60, "default written back")
    assert written["default"] is True
    assert "components" not in written


def test_irrelevant_topics_change_nothing_and_identify_nothing(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    put_drone(node, "/uav1")
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")
    cache = watch.watcher.cache
    before = (cache.hits, cache.misses)
    node.publish(
        "/uav1/diagnostics",
        [
            ("/uav1/diagnostics", "diagnostic_msgs/DiagnosticArray"),
            ("/uav1/tf", "tf2_msgs/TFMessage"),
        ],
    )
    # A relevant change after the irrelevant one: once it is seen, so was the first.
    mark = watch.mark()
    node.subscribe("/uav1/nav", [("/uav1/move_base/goal", "move_base_msgs/MoveBaseActionGoal")])
    changed = watch.wait_for_event("robot_changed", "/uav1", after=mark)
    assert [c["motion_control"] for c in changed["motion_controls"]] == ["Flight", "Waypoint"]
    assert kinds(watch.data(mark)) == ["robot_changed"]
    assert (cache.hits, cache.misses) == (before[0], before[1] + 1)


def test_a_large_description_is_parsed_once(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    text = large_text()
    assert len(text) > 1_000_000
    node.set_param("/big1/robot_description", text)
    watch = start_watcher(master.uri)
    first = watch.wait_for_event("robot_added", "/big1")
    assert first["kinematic_type"] == "Humanoid"
    watch.wait_for_event("synced")
    cache = watch.watcher.cache
    assert (cache.hits, cache.misses) == (0, 1)
    # A second robot of the same model, under another namespace: answered from the cache.
    mark = watch.mark()
    node.set_param("/big2/robot_description", text)
    second = watch.wait_for_event("robot_added", "/big2", after=mark)
    assert second["kinematic_type"] == "Humanoid"
    assert (cache.hits, cache.misses) == (1, 1)
    # The same text set again on the first: no event, nothing parsed.
    node.set_param("/big1/robot_description", text)
    mark = watch.mark()
    put_drone(node, "/uav1")
    watch.wait_for_event("robot_added", "/uav1", after=mark)
    assert kinds(watch.data(mark)) == ["robot_added"]
    assert cache.misses == 2  # the drone only


def test_a_killed_master_is_lost_then_back_with_a_full_resync(
    own_roscore: Roscore, start_watcher: Start, solution: Solution
) -> None:
    node = TestNode(own_roscore.uri)
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    node.set_param("/uav2/robot_description", drone_text())
    node.set_param("/teleop_ui/active_robot", "/uav1")
    watch = start_watcher(own_roscore.uri, interval=0.1, max_backoff=0.5)
    watch.wait_for_event("synced")
    before = watch.data()
    assert sorted(d["robot"] for d in before if d["event"] == "robot_added") == [
        "/uav1",
        "/uav2",
        "/ugv1",
    ]

    mark = watch.mark()
    own_roscore.kill()
    lost = watch.wait_for_event("master_lost", after=mark)
    assert lost["master"] == own_roscore.uri
    # Refused, or reset when the kill lands in the middle of a call: both say so.
    assert lost["error"] in {
        "cannot reach the ROS master (Connection refused)",
        "cannot reach the ROS master (Connection reset by peer)",
    }

    own_roscore.start()
    # The robots' nodes come back, all but /uav2, plus a new one. The watcher may resync at
    # any moment of this; a consumer replaying the events must end with exactly these robots.
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    put_drone(node, "/uav3")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    wait_until(
        lambda: replay(watch.data()) == {"/uav1", "/uav3", "/ugv1"},
        60,
        "the robots back after the restart",
    )
    after = watch.data(mark)
    assert after[0]["event"] == "master_lost"
    assert kinds(after).count("master_back") == 1
    back = kinds(after).index("master_back")
    assert set(kinds(after[1:back])) <= {"master_lost"}  # nothing while the master was away
    assert "synced" in kinds(after[back:])
    seqs = [d["seq"] for d in watch.data()]
    assert seqs == list(range(1, len(seqs) + 1))
    # The selection is answered again, and written back to the new master.
    written = wait_until(lambda: _result(node, "/uav1"), 60, "ui_configuration after resync")
    assert written["configuration"] == drone_configuration(solution)
    node.close()


def replay(events: list[dict[str, Any]]) -> set[str]:
    """The robots a consumer following the documented contract knows after ``events``: it
    forgets everything at master_lost, and a robot is never added twice or removed unknown."""
    robots: set[str] = set()
    for data in events:
        if data["event"] == "master_lost":
            robots.clear()
        elif data["event"] == "robot_added":
            assert data["robot"] not in robots, f"{data['robot']} added twice"
            robots.add(data["robot"])
        elif data["event"] == "robot_removed":
            assert data["robot"] in robots, f"{data['robot']} removed but not known"
            robots.remove(data["robot"])
        elif data["event"] == "synced":
            assert set(data["robots"]) == robots
    return robots


def test_a_master_restarted_between_two_polls_is_noticed_by_its_pid(
    own_roscore: Roscore, start_watcher: Start
) -> None:
    node = TestNode(own_roscore.uri)
    put_drone(node, "/uav1")
    watch = start_watcher(own_roscore.uri, interval=3600.0)
    watch.wait_for_event("synced")
    mark = watch.mark()
    own_roscore.kill()
    own_roscore.start()
    put_rover(node, "/ugv1")
    watch.watcher.wake()
    lost = watch.wait_for_event("master_lost", after=mark)
    assert lost["error"].startswith("the master restarted (process ")
    watch.wait_for_event("master_back", after=mark)
    synced = watch.wait_for_event("synced", after=mark)
    assert synced["robots"] == ["/ugv1"]
    node.close()


def test_resync_after_a_restart_answers_from_the_cache(
    own_roscore: Roscore, start_watcher: Start
) -> None:
    node = TestNode(own_roscore.uri)
    text = large_text(2000)
    node.set_param("/big/robot_description", text)
    watch = start_watcher(own_roscore.uri, interval=0.1, max_backoff=0.5)
    watch.wait_for_event("synced")
    cache = watch.watcher.cache
    assert cache.misses == 1
    mark = watch.mark()
    own_roscore.kill()
    watch.wait_for_event("master_lost", after=mark)
    own_roscore.start()
    node.set_param("/big/robot_description", text)
    # The restarted master may be read before the parameter is set again: the robot comes
    # back in the resynchronisation or in a poll after it, its description from the cache.
    watch.wait_for_event("robot_added", "/big", after=mark)
    assert cache.misses == 1
    assert cache.hits >= 1
    node.close()


def test_a_shutdown_call_to_its_node_stops_the_watcher_cleanly(
    master: Roscore, node: TestNode, start_watcher: Start
) -> None:
    put_drone(node, "/uav1")
    watch = start_watcher(master.uri)
    watch.wait_for_event("synced")
    client = MasterClient(master.uri, caller_id="/rosnode", timeout=5.0)
    api = client.lookup_node(watch.watcher.caller_id)
    assert api is not None
    assert api == watch.watcher.node_uri
    # What a master (or a tool) does to stop a node: look it up, call its shutdown.
    reply: Any = xmlrpc.client.ServerProxy(api).shutdown("/rosnode", "user request")
    assert reply[0] == 1
    watch.thread.join(timeout=60)
    assert not watch.thread.is_alive()
    assert watch.error is None
    assert watch.watcher.stop_reason == "user request"
    watch.watcher.close()
    # Closed: its parameter subscriptions are gone, and so is the node.
    assert client.lookup_node(watch.watcher.caller_id) is None
    client.close()


def test_a_switch_is_answered_from_teleop_ui_alone_and_the_graph_waits_for_its_poll(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    # No poll of the whole graph after the first: what is pushed is all the watcher reads.
    watch = start_watcher(master.uri, interval=3600.0)
    watch.wait_for_event("synced")
    mark = watch.mark()
    # Neither pushed nor polled: the rover's navigation stack stays unseen...
    node.subscribe("/ugv1/navigation", [("/ugv1/move_base/goal", "move_base_msgs/MoveBaseGoal")])
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    selected = watch.wait_for_event("selection_changed", after=mark)
    assert selected["robot"] == "/ugv1"
    assert selected["assignment"]["configuration"] == rover_configuration(solution)
    # ... as the switch was answered from /teleop_ui alone, with the robots the watcher had.
    assert kinds(watch.data(mark)) == ["selection_changed"]
    mark = watch.mark()
    # A description is pushed too, and read with the whole graph: the waypoint goal shows.
    node.set_param("/uav1/robot_description", rover_text())
    changed = watch.wait_for_event("robot_changed", "/uav1", after=mark)
    assert changed["kinematic_type"] == "UGV"
    rover = watch.wait_for_event("robot_changed", "/ugv1", after=mark)
    assert [c["motion_control"] for c in rover["motion_controls"]] == ["Driving", "Waypoint"]


# A rover's own teleoperation description: it is driven to waypoints, not by velocity.
DECLARED = (
    "teleop: 1\nmotion_controls:\n  - control: Waypoint\n    action: /ugv1/navigate_to_pose\n"
)


def test_a_declared_teleoperation_description_wins_and_a_hostile_one_leaves_the_guess(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_rover(node, "/ugv1")  # read from its topics: Driving
    node.set_param("/ugv1/teleop_description", DECLARED)
    watch = start_watcher(master.uri)
    added = watch.wait_for_event("robot_added", "/ugv1")
    assert [c["motion_control"] for c in added["motion_controls"]] == ["Waypoint"]
    assert added["motion_controls"][0]["source"].endswith(": action /ugv1/navigate_to_pose")
    assert added["declared"] == "/ugv1/teleop_description"
    [dropped, kept] = added["disagreements"]
    assert dropped.startswith("motion control Driving: read (")
    assert dropped.endswith("left out")
    assert kept.startswith("motion control Waypoint: declared (")
    assert kept.endswith("kept")
    assert added["combinations"][0]["configuration"] == expected(
        solution,
        kinematic_type="UGV",
        motion_control="Waypoint",
        sensor_type="LIDAR",
        sensor_count="1",
    )
    # A hostile description (a topic that is no ROS name, a command in it) is a located
    # warning: the robot is what its topics show again.
    mark = watch.mark()
    node.set_param(
        "/ugv1/teleop_description",
        "teleop: 1\nmotion_controls:\n  - {control: Driving, topic: $(rm -rf ~)}\n",
    )
    changed = watch.wait_for_event("robot_changed", "/ugv1", after=mark)
    assert [c["motion_control"] for c in changed["motion_controls"]] == ["Driving"]
    assert "declared" not in changed
    assert changed["combinations"][0]["configuration"] == rover_configuration(solution)
    warning = watch.wait_for_event("warning", after=mark)
    assert warning["where"].startswith("/ugv1/teleop_description:3:")
    assert warning["message"].startswith("motion_controls[0].topic: ")
    assert warning["message"].endswith("; not used: what identification read stands")


def test_a_teleoperation_description_past_its_bound_or_not_text_is_a_warning_only(
    master: Roscore, node: TestNode, start_watcher: Start, solution: Solution
) -> None:
    put_rover(node, "/ugv1")
    put_rover(node, "/ugv2")
    node.set_param("/ugv1/teleop_description", "teleop: 1\n#" + "x" * (1 << 20))
    node.set_param("/ugv2/teleop_description", 42)
    watch = start_watcher(master.uri)
    for namespace in ("/ugv1", "/ugv2"):
        robot = watch.wait_for_event("robot_added", namespace)
        assert robot["error"] is None
        assert robot["combinations"][0]["configuration"] == rover_configuration(solution)
    too_long = watch.wait_for(
        lambda d: d["event"] == "warning" and d["where"] == "/ugv1/teleop_description",
        "the warning about /ugv1",
    )
    assert "limit 'description-bytes'" in too_long["message"]
    not_text = watch.wait_for(
        lambda d: d["event"] == "warning" and d["where"] == "/ugv2/teleop_description",
        "the warning about /ugv2",
    )
    assert not_text["message"].startswith(
        "expected a teleoperation description (YAML text), got int"
    )
