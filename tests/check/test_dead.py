"""Dead values and components, globally and per kinematic type."""

from __future__ import annotations

from hypothesis import given, settings

from solver.check.analysis import Analysis
from solver.check.context import RulesContext
from solver.check.dead import DEAD_VALUE
from solver.model import robots
from solver.rules import RuleSet, load_rules
from tests.check.helpers import findings, fixture, rule_sets, valid_robots


def test_dead_value_names_every_constraint_needed_to_exclude_it() -> None:
    microphone, counts = findings("dead-value.yaml", check="dead-value")
    assert microphone.message.startswith(
        "sensor_type 'Mic' can appear in no valid robot: excluded by 'microphones only on "
        "ground robots' (")
    assert "'no microphone on ground robots'" in microphone.message
    assert microphone.message.endswith(" together")
    assert counts.message.startswith("sensor_count 9..10 can appear in no valid robot: "
                                     "excluded by 'at most 8 sensors' (")


def test_dead_values_are_absent_from_every_valid_robot() -> None:
    rules = load_rules(fixture("dead-value.yaml"))
    found = list(robots(rules, [c.values for c in rules.characteristics]))
    assert found
    assert all(robot[2] != "Mic" and int(robot[3]) <= 8 for robot in found)


def test_a_component_whose_values_are_all_dead_is_never_needed() -> None:
    [dead] = findings("dead-component.yaml", check="dead-component")
    assert dead.message == ("sensor_type component 'audio' is never needed: no valid robot "
                            "has any of its values ('Mic')")


def test_values_one_kinematic_type_loses_are_information_with_their_reason() -> None:
    messages = [f.message for f in findings("constrained.yaml", check="dead-for-type")]
    assert messages == [
        "no valid UAV robot has sensor_type 'Mic': excluded by 'no microphone on drones' "
        f"({fixture('constrained.yaml')}:36:5); so it never needs component 'audio'",
        "no valid UGV robot has motion_control 'Flight': excluded by 'Flight only for UAVs' "
        f"({fixture('constrained.yaml')}:30:5)",
        "no valid Arm robot has motion_control 'Flight': excluded by 'Flight only for UAVs' "
        f"({fixture('constrained.yaml')}:30:5)"]


def test_values_dead_everywhere_are_not_repeated_per_type() -> None:
    assert findings("dead-component.yaml", check="dead-for-type") == []


@settings(max_examples=100, deadline=None)
@given(rule_sets())
def test_dead_named_values_are_those_in_no_valid_robot_by_brute_force(rules: RuleSet) -> None:
    everyone = valid_robots(rules, [c.values for c in rules.characteristics])
    if not everyone:
        return  # a void rule set reports the conflict, not dead values
    expected = [f"characteristics.{c.name}.values[{i}]"
                for position, c in enumerate(rules.characteristics)
                if position and c.kind == "categorical"
                for i, value in enumerate(c.values)
                if all(robot[position] != value for robot in everyone)]
    found = [f.location.path for f in DEAD_VALUE.run(RulesContext(rules, Analysis(rules)))
             if ".values[" in f.location.path]
    assert found == expected
