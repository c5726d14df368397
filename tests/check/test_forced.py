"""Values and components forced on every robot of a kinematic type."""

from __future__ import annotations

from solver.core.model import robots
from solver.core.rules import load_rules
from tests.check.helpers import findings, fixture


def test_core_value_is_reported_with_the_constraint_that_forces_it() -> None:
    [core] = findings("constrained.yaml", check="core-value")
    assert core.message == (
        "every valid UAV robot has motion_control 'Flight': forced by "
        f"'UAVs fly' ({fixture('constrained.yaml')}:33:5)"
    )


def test_a_core_value_is_what_every_valid_robot_of_the_type_has() -> None:
    rules = load_rules(fixture("constrained.yaml"))
    domains = [("UAV",), *(c.values for c in rules.characteristics[1:])]
    assert {robot[1] for robot in robots(rules, domains)} == {"Flight"}


def test_core_component_is_reported_when_several_of_its_values_remain() -> None:
    [core] = findings("core-component.yaml", check="core-component")
    assert core.message.startswith(
        "every valid UGV robot needs sensor_type component 'visual' "
        "(its values 'Camera', 'Lidar' remain): forced by 'no "
        "microphone on ground robots'"
    )


def test_rules_without_constraints_force_nothing() -> None:
    assert [f for f in findings("base.yaml") if f.check.startswith("core")] == []
