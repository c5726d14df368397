"""The JSON of the parts of solutions and assignments (solver.solving.contracts): a configuration
with its components, counts as runs, and the default configuration's components; the expected
JSON written by hand for rules counted by hand (tests.handcounted)."""

from __future__ import annotations

from solver import solve
from solver.solving.contracts import configuration_data, default_components, integer_runs
from tests.handcounted import rules_of, team_of


def test_sorted_numbers_read_as_runs_of_consecutive_ones() -> None:
    assert integer_runs([1, 2, 3, 7, 9, 10]) == [(1, 3), (7, 7), (9, 10)]
    assert integer_runs([]) == []


def test_a_configuration_is_its_number_type_robots_and_the_values_each_component_serves() -> None:
    solution = solve(team_of())
    first = solution.configurations[0]
    assert configuration_data(solution.rules, first) == {
        "number": 1,
        "kinematic_type": "UGV",
        "valid_robots": 4,
        "components": [
            {"characteristic": "kinematic_type", "component": "UGV", "values": ["UGV"]},
            {"characteristic": "sensor_type", "component": "visual", "values": ["camera", "lidar"]},
            {
                "characteristic": "sensor_count",
                "component": "few",
                "range": [1, 2],
                "clusters": [1, 2],
                "counts": [[1, 2]],
            },
        ],
    }


def test_counts_a_component_serves_with_a_hole_are_written_as_runs() -> None:
    # The UGV takes 3, 5 and 6 sensors: "many" (clusters of 2) serves 3 and 5..6.
    solution = solve(team_of("team:\n  UGV: {sensor_type: [camera], sensor_count: [3, 5, 6]}\n"))
    (many,) = solution.configurations
    *_, counts = configuration_data(solution.rules, many)["components"]
    assert counts == {
        "characteristic": "sensor_count",
        "component": "many",
        "range": [3, 6],
        "clusters": [2, 3],
        "counts": [[3, 3], [5, 6]],
    }


def test_the_default_configuration_has_every_component_of_every_characteristic() -> None:
    assert default_components(rules_of()) == {
        "kinematic_type": ["UGV", "UAV"],
        "sensor_type": ["visual", "audio"],
        "sensor_count": ["few", "many"],
    }
