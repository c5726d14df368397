"""Dead values and components, globally and per kinematic type."""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings

from solver.check import check_files
from solver.check.context import RulesContext
from solver.check.dead import DEAD_VALUE
from solver.core.analysis import Analysis
from solver.core.model import robots
from solver.core.rules import load_rules
from solver.core.ruleset import RuleSet
from tests.check.helpers import findings, fixture, rule_sets, valid_robots
from tests.conftest import RULES


def test_dead_value_names_every_constraint_needed_to_exclude_it() -> None:
    microphone, counts = findings("dead-value.yaml", check="dead-value")
    assert microphone.message.startswith(
        "sensor_type 'Mic' can appear in no valid robot: excluded by 'microphones only on "
        "ground robots' ("
    )
    assert "'no microphone on ground robots'" in microphone.message
    assert microphone.message.endswith(" together")
    assert counts.message.startswith(
        "sensor_count 9..10 can appear in no valid robot: excluded by 'at most 8 sensors' ("
    )


def test_dead_values_are_absent_from_every_valid_robot() -> None:
    rules = load_rules(fixture("dead-value.yaml"))
    found = list(robots(rules, [c.values for c in rules.characteristics]))
    assert found
    assert all(robot[2] != "Mic" and int(robot[3]) <= 8 for robot in found)


def test_a_component_whose_values_are_all_dead_is_never_needed() -> None:
    [dead] = findings("dead-component.yaml", check="dead-component")
    assert dead.message == (
        "sensor_type component 'audio' is never needed: no valid robot "
        "has any of its values ('Mic')"
    )


def test_values_one_kinematic_type_loses_are_information_with_their_reason() -> None:
    messages = [f.message for f in findings("constrained.yaml", check="dead-for-type")]
    assert messages == [
        "no valid UAV robot has sensor_type 'Mic': excluded by 'no microphone on drones' "
        f"({fixture('constrained.yaml')}:36:5); so it never needs component 'audio'",
        "no valid UGV robot has motion_control 'Flight': excluded by 'Flight only for UAVs' "
        f"({fixture('constrained.yaml')}:30:5)",
        "no valid Arm robot has motion_control 'Flight': excluded by 'Flight only for UAVs' "
        f"({fixture('constrained.yaml')}:30:5)",
    ]


def test_values_dead_everywhere_are_not_repeated_per_type() -> None:
    assert findings("dead-component.yaml", check="dead-for-type") == []


@settings(max_examples=100, deadline=None)
@given(rule_sets())
def test_dead_named_values_are_those_in_no_valid_robot_by_brute_force(rules: RuleSet) -> None:
    everyone = valid_robots(rules, [c.values for c in rules.characteristics])
    if not everyone:
        return  # a void rule set reports the conflict, not dead values
    expected = [
        f"characteristics.{c.name}.values[{i}]"
        for position, c in enumerate(rules.characteristics)
        if position and c.kind == "categorical"
        for i, value in enumerate(c.values)
        if all(robot[position] != value for robot in everyone)
    ]
    found = [
        f.location.path
        for f in DEAD_VALUE.run(RulesContext(rules, Analysis(rules)))
        if ".values[" in f.location.path
    ]
    assert found == expected


def test_values_a_type_loses_to_different_constraints_each_get_their_own_reason() -> None:
    extended = RULES / "extended.yaml"
    uav = next(
        f
        for f in check_files([extended]).findings
        if f.check == "dead-for-type" and f.message.startswith("no valid UAV robot")
    )
    assert uav.message == (
        "no valid UAV robot has motion_control 'Walking', 'End Effector': 'Walking' excluded by "
        f"'Walking is for legged robots' ({extended}:60:5); 'End Effector' excluded by 'End "
        f"Effector control needs an arm' ({extended}:63:5)"
    )
    assert "together" not in uav.message


LOSSES = """\
characteristics:
  kind: {values: [Rover, Drone]}
  control: {values: [Drive, Fly, Point]}
  sensor: {values: [Camera, Lidar]}
  count: {range: {min: 1, max: 10}}
constraints:
  - {name: pointing needs a camera, when: {control: Point}, require: {sensor: Camera}}
  - {name: no camera on drones, forbid: {kind: Drone, sensor: Camera}}
  - {name: drones carry 3 or more, forbid: {kind: Drone, count: {max: 2}}}
  - {name: drones carry at most 8, forbid: {kind: Drone, count: {min: 9}}}
"""


def test_a_type_losing_a_value_to_two_constraints_at_once_says_together(tmp_path: Path) -> None:
    rules = tmp_path / "losses.yaml"
    rules.write_text(LOSSES, encoding="utf-8")
    messages = [f.message for f in check_files([rules]).findings if f.check == "dead-for-type"]
    assert (
        f"no valid Drone robot has control 'Point': excluded by 'pointing needs a camera' "
        f"({rules}:7:5) and 'no camera on drones' ({rules}:8:5) together" in messages
    )


def test_counts_a_type_loses_to_different_constraints_are_given_per_run(tmp_path: Path) -> None:
    rules = tmp_path / "losses.yaml"
    rules.write_text(LOSSES, encoding="utf-8")
    messages = [f.message for f in check_files([rules]).findings if f.check == "dead-for-type"]
    assert (
        f"no valid Drone robot has count 1..2, 9..10: 1..2 excluded by 'drones carry 3 or "
        f"more' ({rules}:9:5); 9..10 excluded by 'drones carry at most 8' ({rules}:10:5)"
        in messages
    )
