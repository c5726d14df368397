"""Partitioning valid robots into UI configurations (solver.core.partition): one per combination
of components where every value is in one, the fewest where values are in several, none for a
value in no component; numbered kinematic type first. Counted by hand (tests.handcounted)."""

from __future__ import annotations

from solver import solve
from solver.core.model import robots
from solver.core.partition import PartitionClass, partition, sort_key, unsorted
from tests.handcounted import OVERLAPPING_RULES, rules_of, team_of


def test_robots_whose_values_are_each_in_one_component_are_classed_by_their_components() -> None:
    team = team_of()
    ugv, _ = team.selections
    found = partition(team.rules, "UGV", robots(team.rules, ugv.domains))
    assert (found.valid_robots, found.unserved_robots, found.proven_minimal) == (9, 0, True)
    assert found.classes == (
        PartitionClass((0, 0, 0), 4, (("UGV",), ("camera", "lidar"), (1, 2))),
        PartitionClass((0, 0, 1), 2, (("UGV",), ("camera", "lidar"), (5,))),
        PartitionClass((0, 1, 0), 2, (("UGV",), ("microphone",), (1, 2))),
        PartitionClass((0, 1, 1), 1, (("UGV",), ("microphone",), (5,))),
    )


def test_values_in_two_components_take_the_fewest_configurations_and_a_gap_takes_none() -> None:
    # camera needs "one", microphone "two", lidar can use either, sonar is in no component.
    rules = rules_of(OVERLAPPING_RULES)
    every = [("UGV", sensor) for sensor in ("camera", "lidar", "microphone", "sonar")]
    found = partition(rules, "UGV", every)
    assert (found.valid_robots, found.unserved_robots) == (4, 1)
    assert found.classes == (
        PartitionClass((0, 0), 2, (("UGV",), ("camera", "lidar"))),  # lidar: the lower number
        PartitionClass((0, 1), 1, (("UGV",), ("microphone",))),
    )


def test_a_robot_that_can_use_either_component_joins_the_one_another_robot_needs() -> None:
    rules = rules_of(OVERLAPPING_RULES)
    found = partition(rules, "UGV", [("UGV", "lidar"), ("UGV", "microphone")])
    assert found.classes == (PartitionClass((0, 1), 2, (("UGV",), ("lidar", "microphone"))),)


def test_the_numbering_order_puts_the_kinematic_type_first_wherever_it_is_declared() -> None:
    rules = rules_of(
        "team_key: kind\ncharacteristics:\n  sensor: {values: [a, b]}\n"
        "  kind: {values: [UGV, UAV]}\n  count: {range: {min: 1, max: 2}}\n"
    )
    assert sort_key(rules, ("sensor", "kind", "count")) == ("kind", "sensor", "count")
    assert unsorted(rules, ("kind", "sensor", "count")) == ("sensor", "kind", "count")


def test_a_configuration_knows_the_clusters_its_counts_take() -> None:
    # "many" (3..6, clusters of 2) serves the UAV's counts 3..6: 2 to 3 clusters.
    *_, many = solve(team_of()).configurations
    assert [component.name for component in many.components] == ["UAV", "visual", "many"]
    assert many.clusters(2) == (2, 3)
    assert many.valid_robots == 8
    assert repr(many) == "<Configuration 6 (UAV): UAV / visual / many; 8 valid robots>"
