"""Every characteristic of a rule set of the user's own is live, on a real ROS 1 master.

The rule set, team and profile (:mod:`tests.live.own_rules`) use names the article never does
and add two characteristics identification knows nothing of: ``autonomy``, which the operator
chooses, and ``link``, fixed per robot. Expected numbers come from :func:`solver.assign`.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from solver.identify.profile import Profile
from solver.live.given import parse_fixed
from solver.live.watcher import Watcher
from solver.solving.solution import Solution
from tests.conftest import run_cli
from tests.live.conftest import Recorder
from tests.live.fleet import put_drone, put_rover
from tests.live.own_rules import drone, rover, write_own
from tests.live.roscore import Roscore, TestNode, wait_until

Start = Callable[..., Recorder]


@pytest.fixture
def own(tmp_path: Path) -> tuple[Solution, Profile]:
    return write_own(tmp_path)


@pytest.fixture
def watch_own(own: tuple[Solution, Profile], master: Roscore) -> Iterator[Start]:
    """``watch_own(*set_pairs, **options)``: a watcher of the own rules on the master."""
    solution, profile = own
    started: list[Recorder] = []

    def start(*pairs: str, **options: Any) -> Recorder:
        fixed = parse_fixed(pairs, solution.rules)
        watcher = Watcher(master.uri, solution, profile, fixed=fixed, **options)
        started.append(Recorder(watcher, solution))
        return started[-1]

    yield start
    for recorder in started:
        recorder.stop()


def answer(node: TestNode) -> dict[str, Any]:
    """The answer on the master (empty when there is none)."""
    value = node.get_param("/teleop_ui/ui_configuration")
    return value if isinstance(value, dict) else {}


def selected(watch: Recorder, what: str, *, after: int, **active: str) -> dict[str, Any]:
    """The first selection at or after ``after`` whose asked values include ``active``."""
    return watch.wait_for(
        lambda d: (
            d["event"] == "selection_changed"
            and d["assignment"] is not None
            and all(d["active"].get(name) == value for name, value in active.items())
        ),
        what,
        after=after,
    )


def test_the_operators_choice_of_a_characteristic_of_the_users_own_changes_the_configuration(
    node: TestNode, watch_own: Start, own: tuple[Solution, Profile]
) -> None:
    solution, _ = own
    put_drone(node, "/uav1")
    watch = watch_own("/uav1:link=LTE")
    added = watch.wait_for_event("robot_added", "/uav1")
    assert added["kinematic_type"] == "Quadcopter"
    assert added["given"] == {"link": {"value": "LTE", "source": "--set /uav1:link=LTE"}}
    # Nothing gives the autonomy yet: the default, and how to give it.
    (combination,) = added["combinations"]
    assert combination["combination"] == {
        "frame": "Quadcopter",
        "mode": "Flight",
        "feed": "2D Camera",
        "sensors": "1",
        "link": "LTE",
    }
    assert combination["reasons"] == ["no autonomy given"]
    assert added["missing"] == [
        {
            "characteristic": "autonomy",
            "how": "the operator's /teleop_ui/active_autonomy, the robot's "
            "/uav1/teleop_ui/autonomy, or --set autonomy=VALUE when the watcher starts "
            "(values: teleoperated, supervised)",
        }
    ]
    watch.wait_for_event("synced")

    mark = watch.mark()
    node.set_param("/teleop_ui/active_autonomy", "teleoperated")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    first = selected(watch, "teleoperated", after=mark, autonomy="teleoperated")
    teleoperated = drone(solution, autonomy="teleoperated", link="LTE")
    assert (first["robot"], first["assignment"]["configuration"]) == ("/uav1", teleoperated)
    assert first["assignment"]["default"] is False
    assert first["active"] == {
        "frame": None,
        "mode": None,
        "feed": None,
        "sensors": None,
        "autonomy": "teleoperated",
        "link": None,
    }
    written = wait_until(
        lambda: (v := answer(node)) and v.get("configuration") == teleoperated and v,
        60,
        "the teleoperated answer",
    )
    assert written["combination"]["autonomy"] == "teleoperated"

    mark = watch.mark()
    node.set_param("/teleop_ui/active_autonomy", "supervised")
    second = selected(watch, "supervised", after=mark, autonomy="supervised")
    supervised = drone(solution, autonomy="supervised", link="LTE")
    assert second["assignment"]["configuration"] == supervised
    assert supervised != teleoperated
    assert second["notes"] == []


def test_a_robots_own_parameter_gives_it_a_value_over_the_fixed_one(
    node: TestNode, watch_own: Start, own: tuple[Solution, Profile]
) -> None:
    solution, _ = own
    put_rover(node, "/ugv1")
    put_drone(node, "/uav1")
    node.set_param("/ugv1/teleop_ui/link", "Tether")
    watch = watch_own("link=Wi-Fi", "autonomy=supervised")
    tethered = watch.wait_for_event("robot_added", "/ugv1")
    assert tethered["given"] == {
        "autonomy": {"value": "supervised", "source": "--set"},
        "link": {"value": "Tether", "source": "/ugv1/teleop_ui/link"},
    }
    assert tethered["missing"] == []
    assert [c["configuration"] for c in tethered["combinations"]] == [
        rover(solution, autonomy="supervised", link="Tether")
    ]
    wireless = watch.wait_for_event("robot_added", "/uav1")
    assert wireless["given"]["link"] == {"value": "Wi-Fi", "source": "--set"}
    watch.wait_for_event("synced")

    mark = watch.mark()
    node.set_param("/ugv1/teleop_ui/link", "LTE")
    changed = watch.wait_for_event("robot_changed", "/ugv1", after=mark)
    assert changed["given"]["link"]["value"] == "LTE"
    assert "given" in changed["changed"]
    # The operator's choice comes first of all.
    mark = watch.mark()
    node.set_param("/teleop_ui/active_link", "Tether")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    chosen = selected(watch, "Tether asked", after=mark, link="Tether")
    assert chosen["assignment"]["combination"]["link"] == "Tether"
    assert chosen["assignment"]["configuration"] == rover(
        solution, autonomy="supervised", link="Tether"
    )


def test_names_the_rules_do_not_know_and_values_that_are_not_text_are_located_warnings(
    node: TestNode, watch_own: Start
) -> None:
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_autonmy", "supervised")  # a typo
    node.set_param("/teleop_ui/active_motion_control", "Flight")  # the article's name
    node.set_param("/uav1/teleop_ui/colour", "red")
    node.set_param("/uav1/teleop_ui/link", 5)
    watch = watch_own()
    watch.wait_for_event("synced")
    warnings = {d["where"]: d["message"] for d in watch.data() if d["event"] == "warning"}
    known = "it has frame, mode, feed, sensors, autonomy, link: ignored"
    assert warnings == {
        "/teleop_ui/active_autonmy": "the rule set has no characteristic 'autonmy' "
        f"(did you mean 'autonomy'?); {known}",
        "/teleop_ui/active_motion_control": "the rule set has no characteristic "
        f"'motion_control'; {known}",
        "/uav1/teleop_ui/colour": f"the rule set has no characteristic 'colour'; {known}",
        "/uav1/teleop_ui/link": "/uav1/teleop_ui/link ignored: expected text, got a number (5)",
    }
    # Once while it lasts: a later poll does not repeat them; a new one is reported.
    mark = watch.mark()
    node.set_param("/teleop_ui/active_speed", "fast")
    new = watch.wait_for_event("warning", after=mark)
    assert new["where"] == "/teleop_ui/active_speed"
    assert [d["where"] for d in watch.data(mark) if d["event"] == "warning"] == [
        "/teleop_ui/active_speed"
    ]


def test_an_insisting_watcher_of_another_team_takes_the_answer_and_both_report_the_rival(
    node: TestNode, watch_own: Start, own: tuple[Solution, Profile], tmp_path: Path
) -> None:
    from solver.core.team import load_team
    from solver.solving.solution import solve

    solution, profile = own
    put_drone(node, "/uav1")
    node.set_param("/teleop_ui/active_robot", "/uav1")
    first = watch_own("link=LTE", "autonomy=supervised")
    mine = first.watcher.caller_id
    wait_until(
        lambda: answer(node).get("watcher") == mine,
        60,
        "the first watcher's answer",
    )
    other = solve(load_team(tmp_path / "other-team.yaml"))
    second = Recorder(Watcher(node.master, other, profile, policy="insist"), other)
    try:
        rival = second.wait_for_event("rival")
        assert (rival["watcher"], rival["team"], rival["own_team"], rival["policy"]) == (
            mine,
            "Own live team",
            "Other live team",
            "insist",
        )
        seen = first.wait_for_event("rival")
        assert (seen["watcher"], seen["team"], seen["policy"]) == (
            second.watcher.caller_id,
            "Other live team",
            "yield",
        )
        taken = wait_until(
            lambda: (v := answer(node)).get("watcher") == second.watcher.caller_id and v,
            60,
            "the insisting watcher's answer",
        )
        assert taken["team"] == "Other live team"
        # The first yields to it, and says so; it does not write back.
        held = first.wait_for(
            lambda d: (
                d["event"] == "selection_changed"
                and any("not written" in note for note in d["notes"])
            ),
            "the first watcher yielding",
        )
        assert held["notes"][-1].startswith(
            f"/teleop_ui/ui_configuration not written: the watcher {second.watcher.caller_id} "
        )
        assert answer(node)["watcher"] == second.watcher.caller_id
    finally:
        second.stop()
    # Gone: its announcement with it, and the first takes the answer back.
    assert first.wait_for_event("rival_gone")["watcher"] == second.watcher.caller_id
    wait_until(
        lambda: answer(node).get("watcher") == mine,
        60,
        "the answer back to the first watcher",
    )
    assert solution.team.name == "Own live team"


def test_watch_and_assign_take_set_and_the_composed_profile_on_the_command_line(
    master: Roscore, node: TestNode, own: tuple[Solution, Profile], tmp_path: Path
) -> None:
    solution, _ = own
    put_drone(node, "/uav1")
    node.set_param("/uav1/teleop_ui/autonomy", "teleoperated")
    common = ("--team", tmp_path / "own-team.yaml", "--profile", tmp_path / "own-profile.yaml")
    result = run_cli("watch", "--master", master.uri, *common, "--set", "/uav1:link=LTE", "--once")
    assert result.returncode == 0, result.stderr
    (added,) = [json.loads(line) for line in result.stdout.splitlines()][:1]
    assert [c["configuration"] for c in added["combinations"]] == [
        drone(solution, autonomy="teleoperated", link="LTE")
    ]
    answer = run_cli("assign", "--master", master.uri, *common, "--robot", "/uav1", "link=Tether")
    assert answer.returncode == 0, answer.stderr
    assert f"UI configuration {drone(solution, autonomy='teleoperated', link='Tether')} " in (
        answer.stdout
    )
    wrong = run_cli("watch", "--master", master.uri, *common, "--set", "lnk=LTE", "--once")
    assert (wrong.returncode, wrong.stdout) == (2, "")
    assert wrong.stderr.startswith("--set: unknown characteristic 'lnk' (did you mean 'link'?)")
