"""The radar chart (the article's Figure 9) and the bar chart, read from matplotlib's objects."""

from __future__ import annotations

import itertools
import json
import math
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from matplotlib.collections import LineCollection
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import PathPatch
from matplotlib.text import Text

from solver import Solution, load_rules, load_team, solve
from solver.errors import InputError, SolverError
from solver.reporting.chart import (
    INNER_RADIUS,
    MAX_MATRIX_COLUMNS,
    MAX_SPOKE_LABELS,
    MAX_SPOKE_VALUES,
    MIN_TICK_GAP,
    RadarAxis,
    component_matrix,
    radar_axes,
    runs,
)
from solver.reporting.plot import (
    bars_figure,
    figure_bytes,
    matrix_figure,
    radar_figure,
    write_plot,
)
from tests.conftest import RULES, TEAMS
from tests.hostile import FUZZ, NAME_CHARS

THREE_RULES = """\
name: Three
characteristics:
  kind:
    label: Kind
    values: [Arm, Drone]
  control:
    label: Control
    values: [Teleop, Waypoint, Gesture]
  count:
    label: Count
    range: {min: 1, max: 8}
"""
THREE_TEAM = """\
name: Gappy
rules: three.yaml
team:
  Arm: {control: [Teleop], count: 3}
  Drone: {control: [Teleop, Gesture], count: [2, 3, 4, 7, 8]}
"""


def _solved(name: str) -> Solution:
    return solve(load_team(TEAMS / f"{name}.yaml"))


@pytest.fixture(scope="module")
def case1() -> Solution:
    return _solved("case1")


@pytest.fixture(scope="module")
def case3() -> Solution:
    return _solved("case3")


@pytest.fixture
def gappy(write_file: Callable[[str, str], Path]) -> Solution:
    write_file("three.yaml", THREE_RULES)
    return solve(load_team(write_file("gappy.yaml", THREE_TEAM)))


def _texts(figure: Figure, prefix: str) -> list[Text]:
    return [t for t in figure.axes[0].texts if str(t.get_label()).startswith(prefix)]


def _regions(figure: Figure) -> dict[str, PathPatch]:
    return {str(p.get_label()): p for p in figure.axes[0].patches if isinstance(p, PathPatch)}


def _runs_drawn(figure: Figure, kinematic_type: str) -> list[Line2D]:
    return [line for line in figure.axes[0].lines if line.get_label() == f"run {kinematic_type}"]


Point = tuple[float, float]


def _ends(line: Line2D) -> tuple[Point, Point]:
    """The first and last point of a drawn line."""
    xy = np.asarray(line.get_xydata(), dtype=float)
    return (float(xy[0][0]), float(xy[0][1])), (float(xy[-1][0]), float(xy[-1][1]))


def _near(a: Point, b: Point) -> bool:
    return math.isclose(a[0], b[0], abs_tol=1e-9) and math.isclose(a[1], b[1], abs_tol=1e-9)


def _axis(solution: Solution, name: str) -> RadarAxis:
    return next(a for a in radar_axes(solution.team) if a.characteristic.name == name)


# ---- spokes and labels -------------------------------------------------------------------


def test_radar_has_one_spoke_titled_per_characteristic_of_the_paper_rules(case3: Solution) -> None:
    titles = [t.get_text() for t in _texts(radar_figure(case3), "axis ")]
    assert titles == [
        "Robot Kinematic Type",
        "Robot Motion Control",
        "Sensor Type",
        "No. of Sensors",
    ]


def test_radar_has_one_spoke_per_characteristic_of_any_rule_set(gappy: Solution) -> None:
    titles = [t.get_text() for t in _texts(radar_figure(gappy), "axis ")]
    assert titles == ["Kind", "Control", "Count"]


def test_radar_spokes_are_evenly_spread_around_the_centre(gappy: Solution) -> None:
    angles = [a.angle for a in radar_axes(gappy.team)]
    steps = {round((angles[i] - angles[i + 1]) % (2 * math.pi), 9) for i in range(2)}
    assert steps == {round(2 * math.pi / 3, 9)}


def test_radar_labels_every_value_of_a_categorical_spoke_in_declared_order(case3: Solution) -> None:
    labels = [t.get_text() for t in _texts(radar_figure(case3), "tick sensor_type")]
    assert labels == list(load_rules(RULES / "paper.yaml").characteristic("sensor_type").values)


def test_radar_count_spoke_ends_at_the_largest_count_the_team_selects(case3: Solution) -> None:
    labels = [t.get_text() for t in _texts(radar_figure(case3), "tick sensor_count")]
    assert labels[0] == "1"
    assert labels[-1] == "25"
    assert {"5", "10", "13"} <= set(labels)  # an arrangement's end, a type's maximum


def test_radar_labels_of_the_paper_values_do_not_overlap_and_stay_on_the_page(
    case3: Solution,
) -> None:
    figure = radar_figure(case3)
    renderer = figure.canvas.get_renderer()  # type: ignore[attr-defined]  # Agg canvas only
    texts = _texts(figure, "tick ") + _texts(figure, "axis ")
    boxes = [t.get_window_extent(renderer) for t in texts]
    page = figure.bbox
    overlapping = [
        (a.get_text(), b.get_text())
        for (a, box_a), (b, box_b) in itertools.combinations(zip(texts, boxes, strict=True), 2)
        if box_a.overlaps(box_b)
    ]
    assert overlapping == []
    assert all(
        page.x0 <= b.x0 and b.x1 <= page.x1 and page.y0 <= b.y0 and b.y1 <= page.y1 for b in boxes
    )


def test_radar_titles_of_flat_spokes_stay_on_the_page() -> None:
    # Five characteristics: two spokes lie almost flat, their titles written out sideways.
    figure = radar_figure(_solved("search-and-rescue"))
    renderer = figure.canvas.get_renderer()  # type: ignore[attr-defined]  # Agg canvas only
    page = figure.bbox
    titles = _texts(figure, "axis ")
    assert len(titles) == 5
    for title in titles:
        box = title.get_window_extent(renderer)
        assert page.x0 <= box.x0, title.get_text()
        assert box.x1 <= page.x1, title.get_text()


def test_radar_shows_only_selected_values_on_a_spoke_with_too_many_to_label(
    write_file: Callable[[str, str], Path],
) -> None:
    many = [f"Sensor {i:02d}" for i in range(MAX_SPOKE_VALUES + 3)]
    write_file(
        "many.yaml",
        "characteristics:\n  kind:\n    values: [Rover]\n"
        f"  sensor:\n    label: Sensor\n    values: [{', '.join(many)}]\n",
    )
    team = write_file(
        "t.yaml",
        "rules: many.yaml\nteam:\n  Rover:\n    sensor: [Sensor 03, Sensor 04, Sensor 11]\n",
    )
    figure = radar_figure(solve(load_team(team)))
    assert [t.get_text() for t in _texts(figure, "tick sensor")] == [
        "Sensor 03",
        "Sensor 04",
        "Sensor 11",
    ]
    assert "(selected values)" in _texts(figure, "axis sensor")[0].get_text()


def _thousand_names(write_file: Callable[[str, str], Path]) -> Solution:
    """One characteristic of 1,000 names, each its own component, all selected."""
    names = ", ".join(f"w{i:04d}" for i in range(1000))
    write_file(
        "names.yaml",
        "characteristics:\n  kind:\n    values: [Rover]\n"
        f"  widget:\n    label: Widget\n    values: [{names}]\n",
    )
    return solve(load_team(write_file("t.yaml", "rules: names.yaml\nteam:\n  Rover: {}\n")))


def test_radar_labels_every_kth_of_a_thousand_names_and_says_so(
    write_file: Callable[[str, str], Path],
) -> None:
    figure = radar_figure(_thousand_names(write_file))
    labels = [t.get_text() for t in _texts(figure, "tick widget")]
    assert len(labels) == MAX_SPOKE_LABELS + 1  # every 25th name, and the last
    assert labels[:2] == ["w0000", "w0025"]
    assert labels[-1] == "w0999"
    assert f"({len(labels)} of 1000 values labelled)" in _texts(figure, "axis widget")[0].get_text()


def test_the_component_matrix_of_a_thousand_components_has_a_column_per_characteristic(
    write_file: Callable[[str, str], Path],
) -> None:
    solution = _thousand_names(write_file)
    _, columns, cells = component_matrix(solution)
    assert MAX_MATRIX_COLUMNS < 1000
    assert columns == [("Widget", "1000 components")]
    assert cells == [[(1000, 1000)]]


def _wide(write_file: Callable[[str, str], Path], high: int) -> Solution:
    """Two types on a count spoke of 1..``high`` with three arrangements."""
    write_file(
        "wide.yaml",
        "characteristics:\n  kind:\n    values: [Rover, Drone]\n"
        f"  count:\n    label: Count\n    range: {{min: 1, max: {high}}}\n"
        "    components:\n      - {name: few, max: 7}\n"
        f"      - {{name: some, min: 8, max: {high // 3}}}\n"
        f"      - {{name: many, min: {high // 3 + 1}}}\n",
    )
    team = write_file(
        "t.yaml",
        f"rules: wide.yaml\nteam:\n  Rover: {{count: {high}}}\n"
        f"  Drone: {{count: [1, 2, 3, {high // 2}]}}\n",
    )
    return solve(load_team(team))


def _greedy_labels(axis: RadarAxis, wanted: list[int]) -> list[str]:
    """The labelling rule as the README states it, value by value."""
    placed: list[int] = []
    for value in wanted:
        if (
            axis.low <= value <= axis.high
            and value not in placed
            and all(
                abs(axis.radius(value) - axis.radius(other)) >= MIN_TICK_GAP for other in placed
            )
        ):
            placed.append(value)
    return [str(v) for v in sorted(placed)]


@pytest.mark.parametrize("high", [30, 100_000])
def test_radar_labels_a_count_spoke_by_the_greedy_rule_at_any_size(
    high: int, write_file: Callable[[str, str], Path]
) -> None:
    solution = _wide(write_file, high)
    count = _axis(solution, "count")
    wanted = [1, high, high, high // 2, 7, high // 3, high, *range(1, high + 1)]
    labels = [t.get_text() for t in _texts(radar_figure(solution), "tick count")]
    assert labels == _greedy_labels(count, wanted)


def test_radar_of_100000_counts_draws_as_many_artists_as_one_of_30(
    write_file: Callable[[str, str], Path],
) -> None:
    # A tick mark per value would be 100,000 strokes merging into a bar: past a few pixels
    # apart, only the labelled values get a mark.
    drawn = []
    for high in (30, 100_000):
        figure = radar_figure(_wide(write_file, high))
        ax = figure.axes[0]
        ticks = next(c for c in ax.collections if c.get_label() == "_ticks count")
        assert isinstance(ticks, LineCollection)
        labels = _texts(figure, "tick count")
        drawn.append((len(ax.lines), len(ax.collections), len(ax.texts)))
        if high == 30:
            assert len(ticks.get_segments()) == 30  # every value, as before
        else:
            assert len(ticks.get_segments()) == len(labels)
    assert drawn[0] == drawn[1]


# ---- regions --------------------------------------------------------------------------------


def test_radar_draws_one_shaded_region_per_kinematic_type_of_the_team(case3: Solution) -> None:
    regions = _regions(radar_figure(case3))
    assert list(regions) == ["UAV", "UGV", "Mobile Manipulator", "Humanoid"]
    colours = {tuple(p.get_facecolor()) for p in regions.values()}
    assert len(colours) == 4
    assert all(0 < to_rgba(p.get_facecolor())[3] < 0.5 for p in regions.values())  # see-through


def test_radar_draws_a_contiguous_count_selection_as_one_continuous_band(case1: Solution) -> None:
    figure = radar_figure(case1)
    count = _axis(case1, "sensor_count")
    strokes = [
        _ends(line) for line in _runs_drawn(figure, "UAV") if _near(_ends(line)[0], count.point(1))
    ]
    assert len(strokes) == 1
    assert _near(strokes[0][1], count.point(5))
    # The band: a shaded quadrilateral spanning 1..5 on the count spoke.
    polygons = [
        np.asarray(p, dtype=float)
        for p in _regions(figure)["UAV"].get_path().to_polygons(closed_only=False)
    ]
    spans = [
        p
        for p in polygons
        if _near((p[0, 0], p[0, 1]), count.point(1)) and _near((p[1, 0], p[1, 1]), count.point(5))
    ]
    assert spans


def test_radar_splits_a_selection_with_gaps_into_separate_bands(gappy: Solution) -> None:
    figure = radar_figure(gappy)
    count = _axis(gappy, "count")
    ends = sorted(
        (round(math.hypot(*first), 9), round(math.hypot(*last), 9))
        for first, last in map(_ends, _runs_drawn(figure, "Drone"))
        if _near(first, count.point(2)) or _near(first, count.point(7))
    )
    assert ends == sorted(
        (round(count.radius(a), 9), round(count.radius(b), 9)) for a, b in [(2, 4), (7, 8)]
    )


def test_radar_joins_every_run_to_every_run_on_the_next_spoke(gappy: Solution) -> None:
    # Drone: kind 1 run, control 2 runs (Teleop; Gesture), count 2 runs: 1x2 + 2x2 + 2x1.
    path = _regions(radar_figure(gappy))["Drone"].get_path()
    assert len(path.to_polygons(closed_only=False)) == 2 + 4 + 2


def test_radar_marks_a_single_value_with_a_dot(gappy: Solution) -> None:
    kind = _axis(gappy, "kind")
    dots = [
        line
        for line in _runs_drawn(radar_figure(gappy), "Arm")
        if _near(_ends(line)[0], kind.point("Arm"))
    ]
    assert len(dots) == 1
    assert dots[0].get_marker() == "o"


def test_radar_spoke_positions_run_from_the_inner_radius_to_the_tip(case3: Solution) -> None:
    motion = _axis(case3, "motion_control")
    assert motion.radius("Joint") == pytest.approx(INNER_RADIUS)
    assert motion.radius("Waypoint") == pytest.approx(1.0)


# ---- legend and titles --------------------------------------------------------------------


def test_radar_legend_gives_each_types_valid_robots_and_configurations(case3: Solution) -> None:
    legend = radar_figure(case3).legends[0]
    assert [t.get_text() for t in legend.get_texts()] == [
        "UAV: 30 valid robots, 6 UI configurations",
        "UGV: 80 valid robots, 12 UI configurations",
        "Mobile Manipulator: 312 valid robots, 48 UI configurations",
        "Humanoid: 450 valid robots, 36 UI configurations",
    ]


def test_radar_legend_counts_one_robot_in_the_singular(
    write_file: Callable[[str, str], Path],
) -> None:
    team = write_file(
        "one.yaml",
        "team:\n  UAV:\n    motion_control: [Flight]\n"
        "    sensor_type: [2D Camera]\n    sensor_count: 1\n",
    )
    figure = radar_figure(solve(load_team(team)))
    assert [t.get_text() for t in figure.legends[0].get_texts()] == [
        "UAV: 1 valid robot, 1 UI configuration"
    ]


def test_radar_title_gives_the_team_totals(case3: Solution) -> None:
    texts = [t.get_text() for t in radar_figure(case3).texts]
    assert "Case 3: 872 valid robots, 102 UI configurations" in texts


# ---- bars ------------------------------------------------------------------------------------


def test_bars_set_valid_robots_beside_configurations_for_each_type(case3: Solution) -> None:
    ax = bars_figure(case3).axes[0]
    heights = {str(c.get_label()): [round(b.get_height()) for b in c] for c in ax.containers}
    assert heights == {"valid robots": [30, 80, 312, 450], "UI configurations": [6, 12, 48, 36]}
    assert [t.get_text().replace("\n", " ") for t in ax.get_xticklabels()] == [
        "UAV",
        "UGV",
        "Mobile Manipulator",
        "Humanoid",
    ]
    legend = ax.get_legend()
    assert legend is not None
    assert [t.get_text() for t in legend.get_texts()] == ["valid robots", "UI configurations"]


# ---- runs ------------------------------------------------------------------------------------


def test_runs_group_values_that_are_neighbours_in_the_domain() -> None:
    sensor = load_rules(RULES / "paper.yaml").characteristic("sensor_type")
    assert runs(sensor, ["LIDAR", "Speaker", "2D Camera", "Microphone", "RGB-D Camera"]) == [
        ("2D Camera", "2D Camera"),
        ("Speaker", "Microphone"),
        ("LIDAR", "RGB-D Camera"),
    ]


@given(st.sets(st.integers(min_value=1, max_value=50)))
def test_runs_cover_exactly_the_values_and_leave_gaps_between_them(chosen: set[int]) -> None:
    count = load_rules(RULES / "paper.yaml").characteristic("sensor_count")
    found = runs(count, sorted(chosen))
    covered = [v for first, last in found for v in range(int(first), int(last) + 1)]
    assert covered == sorted(chosen)
    assert all(int(b[0]) > int(a[1]) + 1 for a, b in itertools.pairwise(found))


# ---- files -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "magic"), [("radar.png", b"\x89PNG"), ("radar.svg", b"<?xml"), ("radar.PDF", b"%PDF")]
)
def test_write_plot_picks_the_format_from_the_extension(
    case1: Solution, tmp_path: Path, name: str, magic: bytes
) -> None:
    written = write_plot(case1, tmp_path / name)
    assert written.read_bytes().startswith(magic)


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_plots_are_byte_identical_from_run_to_run(tmp_path: Path, fmt: str) -> None:
    # Separate processes under different hash seeds: what a user running the command twice sees.
    for seed in ("0", "1"):
        subprocess.run(
            [
                sys.executable,
                "-m",
                "solver",
                "solve",
                "case3",
                "--plot",
                str(tmp_path / f"{seed}.{fmt}"),
            ],
            check=True,
            capture_output=True,
            timeout=600,
            env={**os.environ, "PYTHONHASHSEED": seed},
        )
    assert (tmp_path / f"0.{fmt}").read_bytes() == (tmp_path / f"1.{fmt}").read_bytes()


def test_svg_plots_carry_no_date(case1: Solution) -> None:
    assert b"<dc:date>" not in figure_bytes(radar_figure(case1), "svg")


def test_write_plot_refuses_an_unknown_extension_and_writes_nothing(
    case1: Solution, tmp_path: Path
) -> None:
    with pytest.raises(InputError) as caught:
        write_plot(case1, tmp_path / "radar.jpg")
    assert "'.jpg'" in str(caught.value)
    assert ".png, .svg, .pdf" in str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_the_component_matrix_accounts_for_every_robot_and_configuration_of_each_type(
    case3: Solution,
) -> None:
    rows, columns, cells = component_matrix(case3)
    assert rows == ["UAV", "UGV", "Mobile Manipulator", "Humanoid"]
    labels = sorted({label for label, _ in columns})
    for summary, row in zip(case3.by_type, cells, strict=True):
        for label in labels:
            group = [cell for (name, _), cell in zip(columns, row, strict=True) if name == label]
            # Each configuration uses exactly one component of each characteristic.
            assert sum(used for used, _ in group) == summary.ui_configurations
            assert sum(robots for _, robots in group) == summary.valid_robots


def test_the_component_matrix_leaves_blank_what_a_type_never_needs(case3: Solution) -> None:
    rows, columns, cells = component_matrix(case3)
    uav = cells[rows.index("UAV")]
    assert uav[columns.index(("Robot Motion Control", "Walking"))] == (0, 0)
    assert uav[columns.index(("Robot Motion Control", "Flight"))] == (3, 15)


# ---- names are drawn as written, never parsed as mathtext or TeX ----------------------------

# What made matplotlib's mathtext raise (issue 30.1): TeX commands that read files, unknown
# commands, 95 nested braces, stacked superscripts; and a newline, shown as its escape.
TEX_NAMES = (
    r"$\input{/etc/passwd}$",
    r"$\foo{x}$",
    "$" + "{" * 95 + "x" + "}" * 95 + "$",
    "$x^{^{^2}}$",
    r"$\sqrt{\frac{1}{0}}$",
    "a$b",
    "c\\$",
    "two\nlines",
)
TEX_RULES = f"""\
name: '{TEX_NAMES[1]}'
team_key: kind
characteristics:
  kind:
    label: '{TEX_NAMES[0]}'
    values: ['{TEX_NAMES[2]}', '{TEX_NAMES[3]}', "two\\nlines"]
  control:
    label: '{TEX_NAMES[4]}'
    values: ['{TEX_NAMES[0]}', '{TEX_NAMES[5]}', '{TEX_NAMES[6]}']
    components:
      - {{name: '{TEX_NAMES[3]}', values: ['{TEX_NAMES[0]}', '{TEX_NAMES[5]}']}}
      - {{name: '{TEX_NAMES[6]}', values: ['{TEX_NAMES[6]}']}}
"""
TEX_TEAM = f"""\
name: '{TEX_NAMES[4]}'
rules: tex.yaml
team:
  '{TEX_NAMES[2]}': {{}}
  '{TEX_NAMES[3]}': {{control: ['{TEX_NAMES[0]}']}}
  "two\\nlines": {{}}
"""


@pytest.fixture
def tex_team(write_file: Callable[[str, str], Path]) -> Path:
    write_file("tex.yaml", TEX_RULES)
    return write_file("tex-team.yaml", TEX_TEAM)


def _svg_texts(figure: Figure) -> str:
    """Every text of the figure as the SVG holds it when text is kept as text."""
    import io
    import re
    from html import unescape

    import matplotlib

    buffer = io.BytesIO()
    with matplotlib.rc_context({"svg.fonttype": "none"}):
        figure.savefig(buffer, format="svg")
    found = re.findall(r"<text[^>]*>(.*?)</text>", buffer.getvalue().decode(), flags=re.S)
    return "\n".join(unescape(re.sub(r"<[^>]+>", "", text)) for text in found)


@pytest.mark.parametrize("draw", [radar_figure, bars_figure, matrix_figure])
def test_every_chart_draws_tex_like_names_as_written(
    draw: Callable[[Solution], Figure], tex_team: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import matplotlib

    # Whatever a matplotlibrc says: no TeX run, no mathtext parsed.
    monkeypatch.setitem(matplotlib.rcParams, "text.usetex", True)
    monkeypatch.setitem(matplotlib.rcParams, "text.parse_math", True)
    figure = draw(solve(load_team(tex_team)))
    for fmt in ("png", "svg", "pdf"):
        assert figure_bytes(figure, fmt)
    # (findobj makes the axes' lazy ticks, empty texts never drawn: those are left out.)
    texts = [t for t in figure.findobj(Text) if t.get_text()]
    assert texts
    assert all(not t.get_usetex() and not t.get_parse_math() for t in texts)
    drawn = _svg_texts(figure)
    assert r"$\sqrt{\frac{1}{0}}$" in drawn  # the team's name, in every chart's title
    assert "two\\nlines" in drawn or draw is matrix_figure
    assert "two\nlines" not in drawn


def test_radar_draws_every_tex_like_value_as_written(tex_team: Path) -> None:
    figure = radar_figure(solve(load_team(tex_team)))
    figure_bytes(figure, "png")
    drawn = _svg_texts(figure)
    for name in (r"$\input{/etc/passwd}$", "$x^{^{^2}}$", "a$b", "c\\$", r"$\foo{x}$"):
        assert name in drawn


# Any name a stranger may write (tests.hostile.NAME_CHARS), four at a time.
NAMES = st.text(NAME_CHARS, min_size=1, max_size=40).filter(lambda n: n.strip() == n and n)


@FUZZ
@given(names=st.lists(NAMES, min_size=4, max_size=4, unique=True))
def test_any_names_are_drawn_on_every_chart(
    tmp_path_factory: pytest.TempPathFactory, names: list[str]
) -> None:
    folder = tmp_path_factory.mktemp("chart")
    quoted = [json.dumps(name) for name in names]  # a JSON string is a YAML string
    (folder / "rules.yaml").write_text(
        f"name: {quoted[0]}\nteam_key: kind\ncharacteristics:\n"
        f"  kind:\n    label: {quoted[1]}\n    values: [{quoted[2]}, {quoted[3]}]\n"
        f"  count:\n    label: {quoted[0]}\n    range: {{min: 1, max: 3}}\n"
        f"    components:\n      - {{name: {quoted[3]}, min: 1, max: 3, cluster_size: 1}}\n",
        encoding="utf-8",
    )
    (folder / "team.yaml").write_text(
        f"name: {quoted[1]}\nrules: rules.yaml\nteam:\n  {quoted[2]}: {{}}\n  {quoted[3]}: {{}}\n",
        encoding="utf-8",
    )
    try:
        solution = solve(load_team(folder / "team.yaml"))
    except SolverError:
        return  # a name the rules refuse (a duplicate once stripped, say) is a located error
    for draw in (radar_figure, bars_figure, matrix_figure):
        assert figure_bytes(draw(solution), "svg")


def test_reports_and_batch_reports_draw_tex_like_names(tex_team: Path, tmp_path: Path) -> None:
    from solver.cli import main

    assert main(["report", str(tex_team), "-o", str(tmp_path / "r.html")]) == 0
    assert main(["report", str(tex_team), "-o", str(tmp_path / "r.md")]) == 0
    out = tmp_path / "batch"
    assert main(["batch", str(tex_team), "-o", str(out), "--report", "html"]) == 0
    for page in (tmp_path / "r.html", *out.rglob("*.html")):
        assert r"$\sqrt{\frac{1}{0}}$" in page.read_text(encoding="utf-8")
