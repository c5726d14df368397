"""A real robot's characteristic combinations and the UI configuration of each
(solver.identify.combinations): one per motion control x sensor type, the default with its
reasons where the team has no configuration, values given beside identification replacing
what it found, and the characteristics nothing gave."""

from __future__ import annotations

import pytest

from solver.core.team import load_team
from solver.errors import InputError
from solver.identify import combinations, identify_urdf, load_profile
from solver.identify.combinations import missing
from solver.solving.solution import solve
from tests.conftest import TEAMS
from tests.identify import builders


def test_a_ugv_gets_a_ui_configuration_per_control_and_sensor_type() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    result = identify_urdf(builders.sensing_rover())
    found = combinations(result, solution, load_profile())
    # Driven by its plugin; Waypoint guessed from the drive and the lidar.
    assert [dict(c.values) for c in found] == [
        {
            "kinematic_type": "UGV",
            "motion_control": control,
            "sensor_type": sensor,
            "sensor_count": "2",
        }
        for control in ("Driving", "Waypoint")
        for sensor in ("LIDAR", "2D Camera")
    ]
    numbers = [c.assignment.number for c in found]
    assert all(not c.assignment.is_default for c in found)
    assert len(set(numbers)) == 4  # each control and each sensor type presented differently


def test_a_quadruped_gets_the_default_configuration_with_the_reason() -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))
    robot = builders.quadruped()
    robot.add(builders.CAMERA)
    found = combinations(identify_urdf(robot.text()), solution, load_profile())
    assignment = found[0].assignment
    assert assignment.is_default
    assert assignment.number == solution.default_configuration
    assert any("unknown robot kinematic type 'Quadruped'" in r for r in assignment.reasons)


def test_a_value_given_beside_identification_replaces_what_it_found() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    found = combinations(
        identify_urdf(builders.sensing_rover()),
        solution,
        load_profile(),
        {"motion_control": "Waypoint"},
    )
    assert [dict(c.values)["motion_control"] for c in found] == ["Waypoint", "Waypoint"]
    assert [dict(c.values)["sensor_type"] for c in found] == ["LIDAR", "2D Camera"]


def test_a_given_name_the_rules_lack_is_refused_as_assign_refuses_it() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    with pytest.raises(InputError, match="battery"):
        combinations(
            identify_urdf(builders.sensing_rover()), solution, load_profile(), {"battery": "full"}
        )


def test_the_characteristics_no_combination_has_a_value_for_are_missing() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    bare = identify_urdf(builders.ugv().text())  # wheels that turn, and no sensor at all
    found = combinations(bare, solution, load_profile())
    assert [dict(c.values) for c in found] == [
        {"kinematic_type": "UGV", "motion_control": "Driving"}
    ]
    assert missing(found, solution) == ("sensor_type", "sensor_count")
    assert (
        missing(
            combinations(identify_urdf(builders.sensing_rover()), solution, load_profile()),
            solution,
        )
        == ()
    )
