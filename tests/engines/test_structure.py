"""Counting from structure: exact at any size, and honest about when it cannot."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from solver import load_team, solve
from solver.engines import Memo, structure
from solver.engines.structure import component_use, count
from solver.errors import StructureTooComplex, TooLargeError
from tests.conftest import TEAMS

WriteFile = Callable[[str, str], Path]


def test_counts_the_article_case_3_per_type() -> None:
    team = load_team(TEAMS / "case3.yaml")
    memo = Memo()
    found = [count(team.rules, selection, memo) for selection in team.selections]
    assert [(c.valid_robots, c.ui_configurations) for c in found] == [
        (30, 6),
        (80, 12),
        (312, 48),
        (450, 36),
    ]


def test_counts_10_to_the_30_robots_exactly(write_file: WriteFile) -> None:
    characteristics = "".join(
        f"  c{i}: {{values: [a, b, c, d, e, f, g, h, i, j], components: "
        f"[{{name: low, values: [a, b, c, d, e]}}, {{name: high, values: [f, g, h, i, j]}}]}}\n"
        for i in range(30)
    )
    write_file(
        "rules.yaml", "characteristics:\n  kinematic_type: {values: [T]}\n" + characteristics
    )
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n"))
    totals = solve(team, count_only=True).totals
    assert totals.valid_robots == 10**30
    assert totals.ui_configurations == 2**30


def test_types_with_the_same_structure_are_counted_once(write_file: WriteFile) -> None:
    # A constraint links the characteristics (without one, counting is a product of factors
    # and needs no memo): UAV and UGV meet it alike, so their counts are one structure's.
    write_file(
        "rules.yaml",
        "characteristics:\n"
        "  kinematic_type: {values: [UAV, UGV, Humanoid]}\n"
        "  motion_control: {values: [Flight, Driving, Walking]}\n"
        "  sensor_count: {range: {min: 1, max: 9}}\n"
        "constraints:\n"
        "  - name: Walking is for legged robots\n"
        "    when: {motion_control: Walking}\n"
        "    require: {kinematic_type: [Humanoid]}\n",
    )
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam: {UAV: {}, UGV: {}}\n"))
    memo = Memo()
    uav, ugv = (count(team.rules, selection, memo) for selection in team.selections)
    assert len(memo.counts) == 1
    assert (uav.kinematic_type, ugv.kinematic_type) == ("UAV", "UGV")
    assert (uav.valid_robots, uav.ui_configurations) == (ugv.valid_robots, ugv.ui_configurations)
    assert (uav.valid_robots, uav.ui_configurations) == (2 * 9, 2 * 9)


def test_linked_characteristics_too_many_to_count_fall_back_to_enumeration(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [T]}
  a: {values: [a1, a2, a3]}
  b: {values: [b1, b2, b3]}
constraints:
  - forbid: {a: a1, b: b1}
""",
    )
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n"))
    monkeypatch.setattr(structure, "BLOCK_LIMIT", 4)
    with pytest.raises(StructureTooComplex, match="constraints link a, b into 9 class"):
        count(team.rules, team.selections[0])
    solution = solve(team)
    assert [t.method for t in solution.by_type] == ["fast"]
    assert solution.totals.valid_robots == 8
    with pytest.raises(TooLargeError, match="cannot count by structure"):
        solve(team, engine="structure")


def test_enumerating_more_than_the_limit_is_refused_with_the_count(write_file: WriteFile) -> None:
    team = load_team(TEAMS / "case3.yaml")
    with pytest.raises(TooLargeError) as caught:
        solve(team, engine="fast", max_robots=100)
    # UAV (30) and UGV (80) are within the limit; the Mobile Manipulator (312) is not.
    assert (
        "Mobile Manipulator: enumerating 312 robots is refused (more than 100, see "
        "--max-robots; limit 'robots', docs/security.md); use --count-only for exact counts "
        "without enumeration" in str(caught.value)
    )
    assert solve(team, count_only=True, max_robots=100).totals.valid_robots == 872


def test_listing_more_configurations_than_the_limit_is_refused() -> None:
    team = load_team(TEAMS / "case3.yaml")
    # The limit holds for the whole team (102 configurations), refused before any is built.
    with pytest.raises(
        TooLargeError,
        match=r"Case 3: 102 UI configurations to list; at most 40 are accepted "
        r"\(limit 'configurations'",
    ):
        solve(team, max_configurations=40)


def test_component_use_counts_configurations_and_robots_per_component_without_listing(
    write_file: WriteFile,
) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [UAV, UGV]}
  motion_control: {values: [Flight, Driving, Waypoint]}
  sensor_type:
    values: [a, b, c]
    components:
      - {name: X, values: [a, b]}
      - {name: Y, values: [c]}
  sensor_count: {values: [1, 2, 3]}
constraints:
  - name: Flight only for UAVs
    when: {motion_control: Flight}
    require: {kinematic_type: UAV}
""",
    )
    team = load_team(write_file("t.yaml", "rules: rules.yaml\nteam:\n  UGV: {}\n"))
    rules = team.rules
    use = component_use(rules, team.selections[0])
    assert use is not None

    def of(characteristic: str, value: str) -> tuple[int, int]:
        position = rules.names.index(characteristic)
        found = rules.characteristics[position]
        at = found.index(value)
        assert at is not None
        (component,) = found.membership[at]
        return use[position, component]

    # UGV: Driving or Waypoint, a/b (X) or c (Y), 1..3 sensors: 18 robots, 2 x 2 x 3 = 12
    # configurations.
    assert of("sensor_type", "a") == (2 * 3, 2 * 2 * 3)  # X: a and b
    assert of("sensor_type", "c") == (2 * 3, 2 * 1 * 3)  # Y: c
    assert of("motion_control", "Driving") == (2 * 3, 3 * 3)
    assert of("sensor_count", "1") == (2 * 2, 2 * 3)
    assert (rules.names.index("motion_control"), 0) not in use  # Flight: never a UGV's


def test_long_selections_without_constraints_count_as_their_robots_enumerated(
    write_file: WriteFile,
) -> None:
    # More than FREE_VALUES values of a characteristic are counted by their classes, the rest
    # value by value; counts 121..200 and sensor "z" are in no component (unserved robots).
    write_file(
        "rules.yaml",
        "characteristics:\n"
        "  kinematic_type: {values: [A, B, C]}\n"
        "  sensor: {values: [x, y, z], components: [{name: xy, values: [x, y]}]}\n"
        "  sensor_count:\n"
        "    range: {min: 1, max: 200}\n"
        "    components: [{name: few, min: 1, max: 50}, {name: many, min: 51, max: 120}]\n",
    )
    every_other = ", ".join(str(n) for n in range(1, 200, 2))  # 100 counts, not a range
    team = load_team(
        write_file(
            "team.yaml",
            "rules: rules.yaml\nteam:\n"
            "  A: {sensor_count: 150}\n"
            f"  B: {{sensor: [x, z], sensor_count: [{every_other}]}}\n"
            "  C: {sensor: [z], sensor_count: 40}\n",
        )
    )
    assert len(team.selections[0].domains[2]) > structure.FREE_VALUES
    counted = solve(team, count_only=True).by_type
    enumerated = solve(team, engine="fast").by_type
    figures = [(t.valid_robots, t.ui_configurations, t.unserved_robots) for t in counted]
    assert figures == [(t.valid_robots, t.ui_configurations, t.unserved_robots) for t in enumerated]
    # By hand: A: 3 sensors x 150 counts, served 2 x 120, configurations 1 x 2.
    assert figures[0] == (450, 2, 450 - 240)
    assert figures[2] == (40, 0, 40)
