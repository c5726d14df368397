"""Assigning one characteristic combination its UI configuration, or the default one."""

from __future__ import annotations

import pytest

from solver import InputError, Solution, assign, load_team, parse_combination, solve
from solver.errors import SolverError
from tests.conftest import TEAMS


@pytest.fixture(scope="module")
def case3() -> Solution:
    return solve(load_team(TEAMS / "case3.yaml"))


def test_a_valid_combination_gets_its_configuration(case3: Solution) -> None:
    result = assign(
        case3,
        {
            "kinematic_type": "UAV",
            "motion_control": "Flight",
            "sensor_type": "2D Camera",
            "sensor_count": "3",
        },
    )
    assert not result.is_default
    assert result.configuration == case3.configuration_for(("UAV", "Flight", "2D Camera", 3))
    assert result.number == 1


def test_an_unknown_kinematic_type_gets_the_default_with_the_known_components(
    case3: Solution,
) -> None:
    result = assign(
        case3,
        {
            "kinematic_type": "Quadruped",
            "motion_control": "Walking",
            "sensor_type": "360 Camera",
            "sensor_count": 2,
        },
    )
    assert result.is_default
    assert result.number == 103
    assert result.reasons == ("unknown robot kinematic type 'Quadruped'",)
    assert dict(result.relevant) == {
        "motion_control": ("Walking",),
        "sensor_type": ("spherical display",),
        "sensor_count": ("individual",),
    }


def test_more_sensors_than_the_maximum_gets_the_default(case3: Solution) -> None:
    result = assign(
        case3,
        {
            "kinematic_type": "UGV",
            "motion_control": "Driving",
            "sensor_type": "LIDAR",
            "sensor_count": 12,
        },
    )
    assert result.is_default
    assert result.reasons == ("12 is more than the UGV maximum of 10 for sensor_count",)


def test_a_value_outside_the_team_selection_gets_the_default(case3: Solution) -> None:
    result = assign(
        case3,
        {
            "kinematic_type": "UAV",
            "motion_control": "Driving",
            "sensor_type": "LIDAR",
            "sensor_count": 1,
        },
    )
    assert result.reasons == (
        "motion_control 'Driving' is not selected for UAV in team 'Case 3'",
        "sensor_type 'LIDAR' is not selected for UAV in team 'Case 3'",
    )


def test_a_kinematic_type_outside_the_team_gets_the_default(case3: Solution) -> None:
    result = assign(
        case3,
        {
            "kinematic_type": "Torso",
            "motion_control": "Joint",
            "sensor_type": "LIDAR",
            "sensor_count": 1,
        },
    )
    assert result.reasons == (
        "robot kinematic type 'Torso' is not in team 'Case 3' (it has "
        "UAV, UGV, Mobile Manipulator, Humanoid)",
    )


def test_missing_and_malformed_values_are_reasons_not_errors(case3: Solution) -> None:
    result = assign(case3, {"kinematic_type": "UAV", "sensor_count": "many"})
    assert result.reasons == (
        "no motion_control given",
        "no sensor_type given",
        "sensor_count 'many' is not a whole number in 1..50",
    )
    assert dict(result.relevant) == {"kinematic_type": ("UAV",)}


def test_an_unknown_characteristic_name_is_a_usage_error(case3: Solution) -> None:
    with pytest.raises(
        InputError,
        match="unknown characteristic 'sensor_typ' "
        r"\(did you mean 'sensor_type'\?\)",
    ):
        assign(case3, {"sensor_typ": "LIDAR"})


def test_combinations_are_parsed_from_name_value_pairs() -> None:
    assert parse_combination(["kinematic_type=UAV", "sensor_type=2D Camera"]) == {
        "kinematic_type": "UAV",
        "sensor_type": "2D Camera",
    }
    with pytest.raises(InputError, match="expected NAME=VALUE"):
        parse_combination(["UAV"])
    with pytest.raises(InputError, match="given twice"):
        parse_combination(["a=1", "a=2"])


def test_a_5000_digit_number_given_to_assign_in_python_is_a_located_error() -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))
    with pytest.raises(SolverError, match="sensor_count: a whole number too large"):
        assign(solution, kinematic_type="UAV", sensor_count=10**5000)
    unknown = assign(solution, kinematic_type="UAV", sensor_count="9" * 5000)
    assert unknown.is_default  # as text: no value of the rules, answered with the default
