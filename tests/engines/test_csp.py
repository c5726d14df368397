"""The reference engine (solver.engines.csp): counts and configurations from every valid robot
python-constraint lists, on rules counted by hand (tests.handcounted)."""

from __future__ import annotations

from solver.engines import Counts, csp
from tests.handcounted import OVERLAPPING_RULES, team_of


def test_the_reference_counts_each_kinematic_type_of_the_team() -> None:
    team = team_of()
    assert [csp.count(team.rules, selection) for selection in team.selections] == [
        Counts("UGV", 9, 4, 0),
        Counts("UAV", 12, 2, 0),
    ]


def test_the_reference_lists_every_valid_robot_and_no_forbidden_one() -> None:
    team = team_of()
    _, uav = team.selections
    listed = list(csp.robots(team.rules, uav))
    assert len(listed) == len(set(listed)) == 12  # camera or lidar, 1 to 6 sensors
    assert {sensor for _, sensor, _ in listed} == {"camera", "lidar"}


def test_the_reference_partitions_overlapping_components_into_the_fewest_configurations() -> None:
    team = team_of("team: {UGV: {}}", OVERLAPPING_RULES)
    (ugv,) = team.selections
    found = csp.partition(team.rules, ugv)
    assert [(c.robots, c.served[1]) for c in found.classes] == [
        (2, ("camera", "lidar")),
        (1, ("microphone",)),
    ]
    assert csp.count(team.rules, ugv) == Counts("UGV", 4, 2, 1)  # sonar: in no component
