"""Constraints as data (solver.core.constraints): when a require or a forbid rule holds, which
characteristics it reads, and the line a rule author recognises."""

from __future__ import annotations

import itertools

import pytest

from solver.core.constraints import Condition, RuleConstraint, Value
from solver.errors import Location

FLIGHT = Condition("motion_control", frozenset({"Flight"}), "is Flight")
UAV = Condition("kinematic_type", frozenset({"UAV"}), "is UAV")
FORCE = Condition("sensor_type", frozenset({"Force Sensor"}), "is Force Sensor")
HERE = Location("rules.yaml", 7)

FLIGHT_ONLY_FOR_UAVS = RuleConstraint("Flight only for UAVs", "require", (FLIGHT,), (UAV,), HERE)
NO_FORCE_ON_DRONES = RuleConstraint("no force on drones", "forbid", (), (UAV, FORCE), HERE)
ALWAYS_A_UAV = RuleConstraint("a fleet of drones", "require", (), (UAV,), HERE)

ROBOTS = [
    {"kinematic_type": kind, "motion_control": control, "sensor_type": sensor}
    for kind, control, sensor in itertools.product(
        ["UAV", "UGV"], ["Flight", "Waypoint"], ["Force Sensor", "2D Camera"]
    )
]


def robot(kind: str, control: str, sensor: str) -> dict[str, Value]:
    return {"kinematic_type": kind, "motion_control": control, "sensor_type": sensor}


def test_a_condition_holds_for_the_values_it_allows_and_reads_as_written() -> None:
    either = Condition("sensor_count", frozenset({1, 2}), "in 1..2")
    assert either.holds(1)
    assert not either.holds(3)
    assert str(either) == "sensor_count in 1..2"


def test_a_require_rule_holds_unless_its_when_holds_and_its_requirement_does_not() -> None:
    assert FLIGHT_ONLY_FOR_UAVS.holds(robot("UAV", "Flight", "2D Camera"))
    assert not FLIGHT_ONLY_FOR_UAVS.holds(robot("UGV", "Flight", "2D Camera"))
    assert FLIGHT_ONLY_FOR_UAVS.holds(robot("UGV", "Waypoint", "2D Camera"))  # no Flight asked


def test_a_require_rule_without_when_is_always_required() -> None:
    assert ALWAYS_A_UAV.holds(robot("UAV", "Waypoint", "2D Camera"))
    assert not ALWAYS_A_UAV.holds(robot("UGV", "Waypoint", "2D Camera"))


def test_a_forbid_rule_holds_unless_all_its_conditions_hold_together() -> None:
    assert not NO_FORCE_ON_DRONES.holds(robot("UAV", "Flight", "Force Sensor"))
    assert NO_FORCE_ON_DRONES.holds(robot("UGV", "Waypoint", "Force Sensor"))
    assert NO_FORCE_ON_DRONES.holds(robot("UAV", "Flight", "2D Camera"))


@pytest.mark.parametrize(
    ("rule", "broken"),
    [
        (FLIGHT_ONLY_FOR_UAVS, [("UGV", "Flight", "Force Sensor"), ("UGV", "Flight", "2D Camera")]),
        (
            NO_FORCE_ON_DRONES,
            [("UAV", "Flight", "Force Sensor"), ("UAV", "Waypoint", "Force Sensor")],
        ),
    ],
)
def test_the_predicate_for_the_solver_breaks_exactly_the_robots_the_rule_forbids(
    rule: RuleConstraint, broken: list[tuple[str, str, str]]
) -> None:
    predicate = rule.predicate()
    refused = [
        (r["kinematic_type"], r["motion_control"], r["sensor_type"])
        for r in ROBOTS
        if not predicate(*(r[name] for name in rule.characteristics))
    ]
    assert refused == broken


def test_a_rule_reads_each_characteristic_once_in_the_order_it_mentions_them() -> None:
    assert FLIGHT_ONLY_FOR_UAVS.characteristics == ("motion_control", "kinematic_type")
    twice = RuleConstraint("twice", "require", (UAV,), (UAV, FORCE), HERE)
    assert twice.characteristics == ("kinematic_type", "sensor_type")


def test_a_rule_describes_itself_as_its_author_wrote_it_with_its_name_escaped() -> None:
    assert FLIGHT_ONLY_FOR_UAVS.describe() == (
        "'Flight only for UAVs' (when motion_control is Flight require kinematic_type is UAV)"
    )
    assert NO_FORCE_ON_DRONES.describe() == (
        "'no force on drones' (forbid kinematic_type is UAV and sensor_type is Force Sensor)"
    )
    assert ALWAYS_A_UAV.describe() == "'a fleet of drones' (require kinematic_type is UAV)"
    forged = RuleConstraint("x\nFORGED", "require", (), (UAV,), HERE)
    assert "\n" not in forged.describe()


def test_two_rules_that_say_the_same_are_equal_wherever_they_were_written() -> None:
    elsewhere = RuleConstraint(
        "Flight only for UAVs", "require", (FLIGHT,), (UAV,), Location("other.yaml", 99)
    )
    assert elsewhere == FLIGHT_ONLY_FOR_UAVS
