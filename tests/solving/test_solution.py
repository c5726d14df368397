"""Solving the article's teams under the shipped rule set."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from solver import load_team, solve
from tests.conftest import TEAMS, holds_alone

WriteFile = Callable[[str, str], Path]


@pytest.mark.parametrize(
    ("team", "robots", "configurations"), [("figure8", 90, 8), ("case1", 30, 6), ("case2", 110, 18)]
)
def test_solve_reproduces_the_published_figures_of(
    team: str, robots: int, configurations: int
) -> None:
    solution = solve(load_team(TEAMS / f"{team}.yaml"))
    assert (solution.totals.valid_robots, solution.totals.ui_configurations) == (
        robots,
        configurations,
    )


def test_case_3_under_the_articles_stated_rules_gives_872_robots_and_102_configurations() -> None:
    # SPEC section 4's closed form per type: |M| x |S| x I robots and
    # |M| x |groups(S)| x |arrangements(1..I)| configurations.
    expected = {
        "UAV": (2 * 3 * 5, 2 * 3 * 1),
        "UGV": (2 * 4 * 10, 2 * 3 * 2),
        "Mobile Manipulator": (4 * 6 * 13, 4 * 4 * 3),
        "Humanoid": (3 * 6 * 25, 3 * 3 * 4),
    }
    solution = solve(load_team(TEAMS / "case3.yaml"))
    assert {
        t.kinematic_type: (t.valid_robots, t.ui_configurations) for t in solution.by_type
    } == expected
    assert (solution.totals.valid_robots, solution.totals.ui_configurations) == (872, 102)


def test_the_case_3_hypothesis_reproduces_the_published_820_and_99() -> None:
    solution = solve(load_team(TEAMS / "case3-hypothesis.yaml"))
    assert (solution.totals.valid_robots, solution.totals.ui_configurations) == (820, 99)


def test_configurations_are_numbered_by_type_then_component_order() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    names = [
        (c.kinematic_type, *(component.name for component in c.components[1:]))
        for c in solution.configurations
    ]
    assert names[:3] == [
        ("UAV", "Flight", "visual display", "individual"),
        ("UAV", "Flight", "spherical display", "individual"),
        ("UAV", "Flight", "point cloud", "individual"),
    ]
    assert names[6] == ("UGV", "Driving", "visual display", "individual")
    order = [
        [
            ("UAV", "UGV").index(n[0]),
            ("Flight", "Driving", "Waypoint").index(n[1]),
            ("visual display", "spherical display", "audio", "point cloud").index(n[2]),
            ("individual", "clusters of 2").index(n[3]),
        ]
        for n in names
    ]
    assert order == sorted(order)
    assert [c.number for c in solution.configurations] == list(range(1, 19))
    assert solution.default_configuration == 19


def test_every_configuration_serves_robots_whose_values_are_in_its_components() -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))
    for configuration in solution.configurations:
        for component, served in zip(configuration.components, configuration.served, strict=True):
            assert set(served) <= set(component.values)
    assert sum(c.robots for c in solution.configurations) == 872


def test_the_configuration_of_a_robot_is_found_by_its_values() -> None:
    solution = solve(load_team(TEAMS / "case3.yaml"))
    configuration = solution.configuration_for(("Humanoid", "Walking", "3D Camera", 17))
    assert configuration is not None
    assert [c.name for c in configuration.components] == [
        "Humanoid",
        "Walking",
        "visual display",
        "clusters of 5",
    ]
    assert configuration.clusters(3) == (4, 5)


def rules_with(write_file: WriteFile, extra: str) -> Path:
    return write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [UAV, UGV]}
  motion_control: {values: [Flight, Driving, Waypoint]}
  sensor_type:
    values: [a, b, c]
    components:
"""
        + extra,
    )


def test_rule_constraints_remove_robots_the_rules_forbid(write_file: WriteFile) -> None:
    rules_with(
        write_file,
        """\
      - {name: one, values: [a, b, c]}
constraints:
  - name: Flight only for UAVs
    when: {motion_control: Flight}
    require: {kinematic_type: UAV}
""",
    )
    team = load_team(write_file("t.yaml", "rules: rules.yaml\nteam:\n  UAV: {}\n  UGV: {}\n"))
    solution = solve(team)
    assert [(t.valid_robots, t.ui_configurations) for t in solution.by_type] == [(9, 3), (6, 2)]


def test_overlapping_components_get_a_proven_minimum_of_configurations(
    write_file: WriteFile,
) -> None:
    rules_with(
        write_file,
        """\
      - {name: X, values: [a, b]}
      - {name: Y, values: [b, c]}
""",
    )
    team = load_team(
        write_file("t.yaml", "rules: rules.yaml\nteam:\n  UAV: {motion_control: Flight}\n")
    )
    solution = solve(team)
    assert solution.totals.ui_configurations == 2
    assert solution.proven_minimal
    served = [c.served[2] for c in solution.configurations]
    assert served == [("a", "b"), ("c",)]


def test_a_value_in_no_component_leaves_its_robots_unserved(write_file: WriteFile) -> None:
    rules_with(write_file, "      - {name: X, values: [a, b]}\n")
    team = load_team(
        write_file("t.yaml", "rules: rules.yaml\nteam:\n  UGV: {motion_control: Driving}\n")
    )
    totals = solve(team).totals
    assert (totals.valid_robots, totals.ui_configurations, totals.unserved_robots) == (3, 1, 1)


def test_solving_holds_the_cycle_collector_off_and_leaves_it_on() -> None:
    # Hundreds of configurations: thousands of objects, none in a cycle (solver/collector.py).
    # In an interpreter of its own: the collector's switch is one per process.
    holds_alone(
        """
        import gc
        from solver import load_team, solve

        team = load_team("search-and-rescue")
        assert gc.isenabled()
        started = []

        def seen(phase, info):
            if phase == "start":
                started.append(info["generation"])

        gc.callbacks.append(seen)
        try:
            solution = solve(team)
        finally:
            gc.callbacks.remove(seen)
        assert len(solution.configurations) > 700  # a collection every 700 new objects otherwise
        # At most the one deferred collection, as the collector comes back on at the end.
        assert len(started) <= 1, started
        assert gc.isenabled()
        """
    )
