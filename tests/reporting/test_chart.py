"""What the charts show, as data: ticks, shades and text widths checked against matplotlib's own
numbers (its colour map, its font metrics), the bars and the matrix against the solution."""

from __future__ import annotations

import itertools
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from solver import Solution, load_team, solve
from solver.reporting.chart import (
    BLUES,
    bars_chart,
    blues,
    component_matrix,
    matrix_chart,
    nice_ticks,
    radar_chart,
    text_width,
)


@pytest.fixture(scope="module")
def case3() -> Solution:
    return solve(load_team("case3"))


@given(st.integers(min_value=1, max_value=10**12))
def test_nice_ticks_start_at_zero_reach_the_highest_and_are_few_round_steps(highest: int) -> None:
    ticks = nice_ticks(highest)
    step = ticks[1] - ticks[0]
    assert ticks[0] == 0
    assert ticks[-1] >= highest > ticks[-2]
    assert all(b - a == step for a, b in itertools.pairwise(ticks))
    assert len(ticks) <= 7
    assert str(step).rstrip("0") in ("1", "2", "5")


def test_the_shades_are_matplotlibs_blues() -> None:
    from matplotlib import colormaps
    from matplotlib.colors import to_hex, to_rgb

    for share in (0.0, 0.1, 0.37, 0.5, 0.61, 0.9, 1.0):
        ours = to_rgb(blues(share))
        theirs = colormaps["Blues"](share)[:3]
        # matplotlib's map has 256 steps; ours is the same line through the same 9 colours.
        assert all(abs(a - b) < 3 / 255 for a, b in zip(ours, theirs, strict=True)), share
    assert blues(0.0) == BLUES[0] == to_hex(colormaps["Blues"](0.0))
    assert blues(1.0) == BLUES[-1] == to_hex(colormaps["Blues"](1.0))


@pytest.mark.parametrize(
    "text", ["Mobile Manipulator: 312 valid robots, 48 UI configurations", "UAV", "0123456789"]
)
def test_text_widths_are_dejavu_sans_as_matplotlib_measures_it(text: str) -> None:
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    width, _, _ = TextToPath().get_text_width_height_descent(
        text, FontProperties(family="DejaVu Sans", size=10), ismath=False
    )
    # Advance widths only: kerning ("AV") makes matplotlib's a few per cent narrower.
    assert text_width(text, 10) == pytest.approx(width, rel=0.04)


def test_the_bars_are_each_types_counts_on_round_ticks(case3: Solution) -> None:
    chart = bars_chart(case3)
    assert chart.categories == ("UAV", "UGV", "Mobile\nManipulator", "Humanoid")
    assert [s.values for s in chart.series] == [(30, 80, 312, 450), (6, 12, 48, 36)]
    assert chart.yticks == (0, 100, 200, 300, 400, 500)
    assert chart.ytop >= 450


def test_the_matrix_shades_a_cell_by_the_share_of_the_types_robots(case3: Solution) -> None:
    chart = matrix_chart(case3)
    uav = chart.rows.index("UAV")
    flight = chart.columns.index("Flight")
    # 15 of the UAV's 30 robots fly by Flight: half, the middle of the Blues.
    assert chart.fills[uav][flight] == blues(0.5)
    assert [c.text for c in chart.cells if (c.x, c.y) == (flight, uav)] == ["3"]


def test_the_radar_layers_are_the_teams_types_in_order(case3: Solution) -> None:
    chart = radar_chart(case3)
    assert [layer.name for layer in chart.layers] == [
        "UAV",
        "UGV",
        "Mobile Manipulator",
        "Humanoid",
    ]
    assert chart.layers[0].width > chart.layers[-1].width
    assert chart.title == "Case 3: 872 valid robots, 102 UI configurations"


OVERLAPPING = """\
characteristics:
  kinematic_type: {values: [UAV, UGV]}
  motion_control: {values: [Flight, Driving, Waypoint]}
  sensor_type:
    values: [a, b, c, d]
    components:
      - {name: X, values: [a, b]}
      - {name: Y, values: [b, c]}
  sensor_count: {values: [1, 2, 3]}
constraints:
  - name: Flight needs b or c
    when: {motion_control: Flight}
    require: {sensor_type: [b, c]}
  - name: three sensors are a or b
    when: {sensor_count: 3}
    require: {sensor_type: [a, b]}
"""


@pytest.mark.parametrize("engine", ["auto", "fast", "csp"])
@pytest.mark.parametrize("team_name", ["case1", "case3", "search-and-rescue", "overlapping"])
def test_the_matrix_of_the_counts_is_the_matrix_of_the_listed_configurations(
    write_file: Callable[[str, str], Path], team_name: str, engine: str
) -> None:
    # Counted (by structure, where it applies: no configuration listed) and tallied from every
    # configuration listed, the matrix is the same, overlapping components and unserved
    # values (d) too.
    if team_name == "overlapping":
        write_file("rules.yaml", OVERLAPPING)
        team = load_team(write_file("t.yaml", "rules: rules.yaml\nteam:\n  UAV: {}\n  UGV: {}\n"))
    else:
        team = load_team(team_name)
    counted = solve(team, engine=engine, count_only=True)
    listed = solve(team, engine=engine)
    assert not counted.configurations
    assert component_matrix(counted) == component_matrix(listed)
    assert matrix_chart(counted) == matrix_chart(listed)
