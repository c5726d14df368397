"""Every layout the project writes, for the shipped teams and the example robots, through the
viewers' own rules (issue 26).

Each test runs one family of rules over every file (each family was an item of issue 26 that
the writers broke, marked ``xfail(strict=True)`` until the writer's fix). The files come from
the command line, as a user gets them: ``teleop-ui layouts TEAM -o DIR [--format rviz]`` for
every team in ``rules/teams/`` and ``layouts --robot URDF --team TEAM`` for every robot in
``examples/`` (and one with a real topic list whose scanner is a ``LaserScan``).
"""

from __future__ import annotations

import contextlib
import functools
import html
import io
import json
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml

from solver import load_team, solve
from solver.cli import main
from solver.errors import Fault
from solver.layouts import Presentation, load_presentation
from solver.layouts.checks import check_lichtblick, check_rviz
from solver.layouts.checks.quality import consistency, leaf_rects, measure, quality_faults
from solver.layouts.checks.rviz import robot_namespace
from solver.layouts.foxglove import TAB_TITLE_CHARS
from solver.layouts.preview import preview_svg
from solver.solving.solution import Solution
from tests.conftest import ROOT, TEAMS

EXAMPLES = ROOT / "examples"
ROBOTS = sorted(path.stem for path in EXAMPLES.glob("*.urdf"))
ROBOT_TEAMS = ("case1", "case2", "case3")
GROUPS = ("teams", "robots")
# A real topic list (``name type`` lines) for the LIDAR robot: its scanner is a LaserScan.
SCAN_TOPICS = (
    "/diff_drive_lidar/scan sensor_msgs/msg/LaserScan\n"
    "/diff_drive_lidar/cmd_vel geometry_msgs/msg/Twist\n"
)


@dataclass(frozen=True)
class Written:
    """One file the project wrote, with what the checks need to know about its robot."""

    path: Path
    solution: Solution
    configuration: int
    topics: dict[str, list[str]]  # real topics given with --topics: name -> [type]
    # The robot's namespace where the run names it (layouts --robot: /ROBOT_NAME); None: the
    # checks infer it from the file's topics (a file of one topic, /quadrotor/camera/image_raw,
    # would give /quadrotor/camera).
    namespace: str | None = None


@functools.cache
def _solution(team: str) -> Solution:
    return solve(load_team(team))


def _cli(*args: str | Path) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main([str(arg) for arg in args]) == 0
    return out.getvalue()


@pytest.fixture(scope="module")
def written(tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[str, str], list[Written]]:
    """(group, format) -> every file the command line writes; group is teams or robots."""
    root = tmp_path_factory.mktemp("layouts")
    files: dict[tuple[str, str], list[Written]] = {}
    for fmt in ("foxglove", "rviz"):
        teams: list[Written] = []
        for team_file in sorted(TEAMS.glob("*.yaml")):
            solution = _solution(str(team_file))
            out = root / fmt / team_file.stem
            _cli("layouts", team_file, "-o", out, "--format", fmt)
            for path in sorted(out.iterdir()):
                number = int(re.findall(r"\d+", path.name)[0])
                teams.append(Written(path, solution, number, {}))
        files["teams", fmt] = teams
        robots: list[Written] = []
        suffix = "json" if fmt == "foxglove" else "rviz"
        runs: list[tuple[str, str, Path | None]] = [
            (robot, team, None) for robot in ROBOTS for team in ROBOT_TEAMS
        ]
        topics_file = root / "scan-topics.txt"
        topics_file.write_text(SCAN_TOPICS, encoding="utf-8")
        runs.append(("diff_drive_lidar", "case2", topics_file))
        for robot, team, topics in runs:
            solution = _solution(team)
            out = root / fmt / f"{robot}-{team}{'-topics' if topics else ''}.{suffix}"
            extra: list[str | Path] = ["--topics", topics] if topics else []
            said = _cli("layouts", "--robot", EXAMPLES / f"{robot}.urdf", "--team", team,
                        "-o", out, "--format", fmt, *extra)  # fmt: skip
            number = int(re.search(r"configuration (\d+)", said).group(1))  # type: ignore[union-attr]  # layouts always says it
            real: dict[str, list[str]] = {}
            if topics:
                real = {n: [t] for n, t in (line.split() for line in SCAN_TOPICS.splitlines())}
            robots.append(Written(out, solution, number, real, f"/{robot}"))
        files["robots", fmt] = robots
    return files


def _components(written: Written) -> set[str]:
    solution = written.solution
    if written.configuration == solution.default_configuration:
        return {c.name for ch in solution.rules.characteristics for c in ch.components}
    configuration = next(c for c in solution.configurations if c.number == written.configuration)
    return {component.name for component in configuration.components}


def _topic_types(
    presentation: Presentation, written: Written, topics: list[str]
) -> dict[str, list[str]]:
    """Each topic's possible types: the real ones given, else the presentation's for the component
    whose topic template ends the same way (``.../camera/image_raw_2`` is a visual display)."""
    types = dict(written.topics)
    for topic in topics:
        if topic in types:
            continue
        stem = re.sub(r"_\d+$", "", topic)
        for spec in presentation.panels:
            tail = spec.topic.split("<robot>", 1)[-1]
            if spec.types and stem.endswith(tail):
                types[topic] = list(spec.types)
                break
    return types


def _lichtblick_topics(layout: Any) -> list[str]:
    topics: list[str] = []
    for config in layout["configById"].values():
        topics.extend(config.get("topics", {}))
        for key in ("topic", "topicName", "topicPath"):
            if isinstance(config.get(key), str):
                topics.append(config[key])
        if isinstance(config.get("imageMode"), dict) and "imageTopic" in config["imageMode"]:
            topics.append(config["imageMode"]["imageTopic"])
    return topics


def _rviz_topics(document: Any) -> list[str]:
    displays = document["Visualization Manager"]["Displays"]
    return [d["Topic"]["Value"] for d in displays if isinstance(d.get("Topic"), dict)]


def _pose_topics(presentation: Presentation, written: Written, document: Any) -> set[str]:
    """Where the configuration's pose-goal components take goals, in the file's namespace."""
    namespace = written.namespace or robot_namespace(document)
    components = _components(written)
    topics: set[str] = set()
    for spec in presentation.panels:
        if spec.component in components and "geometry_msgs/PoseStamped" in spec.types:
            tail = spec.topic.split("<robot>/", 1)[-1]
            topics |= {f"{namespace}/{tail}"} if namespace else {tail, f"/{tail}"}
    return topics


@pytest.fixture(scope="module")
def faults(written: dict[tuple[str, str], list[Written]]) -> dict[tuple[str, str], list[Fault]]:
    """(group, format) -> every fault of every file, found once for all the tests."""
    return {key: list(_check(files, key[1])) for key, files in written.items()}


def _check(files: list[Written], fmt: str) -> Iterator[Fault]:
    presentation = load_presentation()
    for written in files:
        text = written.path.read_text(encoding="utf-8")
        if fmt == "foxglove":
            layout = json.loads(text)
            types = _topic_types(presentation, written, _lichtblick_topics(layout))
            found = check_lichtblick(
                layout, str(written.path), namespace=written.namespace, topic_types=types
            )
        else:
            # libyaml's loader where present: a thousand files read at PyYAML's pace are slow.
            document = yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
            types = _topic_types(presentation, written, _rviz_topics(document))
            pose = _pose_topics(presentation, written, document)
            found = check_rviz(
                document,
                str(written.path),
                namespace=written.namespace,
                topic_types=types,
                pose_topics=pose,
            )
        yield from found


def _first(
    faults: dict[tuple[str, str], list[Fault]], group: str, fmt: str, codes: tuple[str, ...]
) -> list[str]:
    """The first few faults of these codes, as a reader would see them."""
    return [str(fault) for fault in faults[group, fmt] if fault.code in codes][:5]


def test_every_group_has_files(written: dict[tuple[str, str], list[Written]]) -> None:
    counts = {key: len(files) for key, files in written.items()}
    assert counts["teams", "foxglove"] == counts["teams", "rviz"] > 1000
    assert counts["robots", "foxglove"] == len(ROBOTS) * len(ROBOT_TEAMS) + 1


# -- Lichtblick ------------------------------------------------------------------------------


@pytest.mark.parametrize("group", GROUPS)
def test_lichtblick_imports_every_layout_and_reads_every_key_of_the_right_type(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    codes = ("lichtblick-import", "lichtblick-tree", "lichtblick-panel-type", "lichtblick-config")
    assert _first(faults, group, "foxglove", codes) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_lichtblick_topic_is_a_full_ros2_name_and_every_path_parses(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    codes = ("ros-topic-name", "lichtblick-message-path")
    assert _first(faults, group, "foxglove", codes) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_panel_title_is_shown(faults: dict[tuple[str, str], list[Fault]], group: str) -> None:
    assert _first(faults, group, "foxglove", ("lichtblick-title-hidden",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_layout_opens_unmodified(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "foxglove", ("lichtblick-modified",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_publish_panel_holds_a_whole_sample_message(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "foxglove", ("lichtblick-publish",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_one_velocity_panel_drives_each_command_topic(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "foxglove", ("lichtblick-teleop-topic",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_no_lichtblick_panel_publishes_outside_the_robots_namespace(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "foxglove", ("namespace",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_3d_panel_has_a_reference_grid(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "foxglove", ("lichtblick-grid",)) == []


# -- RViz2 -----------------------------------------------------------------------------------


@pytest.mark.parametrize("group", GROUPS)
def test_every_rviz_file_has_the_sections_rviz2_saves(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("rviz-file",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_rviz_display_tool_and_view_is_one_rviz2_has(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("rviz-display", "rviz-view")) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_rviz_topic_is_a_ros2_name(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("ros-topic-name",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_every_rviz_display_shows_its_topics_message_type(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("rviz-display-type",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_the_goal_tool_publishes_where_the_configurations_pose_component_listens(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("rviz-tool",)) == []


@pytest.mark.parametrize("group", GROUPS)
def test_rviz_robot_description_and_tools_lie_in_the_robots_namespace(
    faults: dict[tuple[str, str], list[Fault]], group: str
) -> None:
    assert _first(faults, group, "rviz", ("namespace",)) == []


def test_every_fault_found_belongs_to_one_of_the_tests_above(
    faults: dict[tuple[str, str], list[Fault]],
) -> None:
    tested = {
        "foxglove": {
            "lichtblick-import", "lichtblick-tree", "lichtblick-panel-type", "lichtblick-config",
            "ros-topic-name", "lichtblick-message-path", "lichtblick-title-hidden",
            "lichtblick-modified", "lichtblick-publish", "lichtblick-teleop-topic", "namespace",
            "lichtblick-grid",
        },
        "rviz": {
            "rviz-file", "rviz-display", "rviz-view", "ros-topic-name", "rviz-display-type",
            "rviz-tool", "namespace",
        },
    }  # fmt: skip
    for (_group, fmt), found in faults.items():
        assert {fault.code for fault in found} <= tested[fmt]


# Issue 39: every layout designed for an operator, measured as written.


@pytest.mark.parametrize("group", GROUPS)
def test_every_layout_meets_the_quality_limits(
    written: dict[tuple[str, str], list[Written]], group: str
) -> None:
    measured = [
        (w.path, measure(json.loads(w.path.read_text()))) for w in written[group, "foxglove"]
    ]
    found = [str(f) for path, q in measured for f in quality_faults(q, str(path))]
    assert found == []
    # What the limits of checks/quality.yaml allow, found on the files: a primary view of at
    # least half the screen, no tile under 320x180 at 1920x1080, at most 12 tiles.
    assert min(q.primary_share for _, q in measured) >= 50
    assert min(q.smallest_width for _, q in measured) >= 320
    assert min(q.smallest_height for _, q in measured) >= 180
    assert max(q.tiles for _, q in measured) <= 12


@pytest.mark.parametrize("group", GROUPS)
def test_every_title_names_the_component_and_the_topic_and_every_tab_fits(
    written: dict[tuple[str, str], list[Written]], group: str
) -> None:
    titled = tabs = 0
    for item in written[group, "foxglove"]:
        for panel_id, config in json.loads(item.path.read_text())["configById"].items():
            for tab in config.get("tabs", []) if panel_id.startswith("Tab!") else []:
                assert len(tab["title"]) <= TAB_TITLE_CHARS, (item.path, tab["title"])
                tabs += 1
            title = config.get("lichtblickPanelTitle")
            if title is None:
                continue
            component, _, topic = title.split(" (")[0].partition(" \u00b7 ")
            rest = {key: value for key, value in config.items() if "PanelTitle" not in key}
            # The topic named is one the panel shows or sends on.
            assert component
            assert topic.startswith("/")
            assert json.dumps(topic) in json.dumps(rest) or f'"{topic}.' in json.dumps(rest), (
                item.path,
                title,
            )
            titled += 1
    assert titled > 0
    assert tabs > 0


def test_every_shipped_team_puts_a_shared_component_in_the_same_region_in_every_configuration(
    written: dict[tuple[str, str], list[Written]],
) -> None:
    # The default configuration counted too: operators switch to it (every robot the team
    # does not know gets it).
    places: dict[str, list[dict[str, str]]] = {}
    defaults = 0
    for item in written["teams", "foxglove"]:
        defaults += item.configuration == item.solution.default_configuration
        layout = json.loads(item.path.read_text())
        places.setdefault(item.path.parent.name, []).append(dict(measure(layout).places))
    scores = {team: consistency(found) for team, found in places.items()}
    assert {team: score.score for team, score in scores.items()} == {
        team.stem: 100.0 for team in TEAMS.glob("*.yaml")
    }
    assert all(score.pairs > 0 for score in scores.values())  # each team shares components
    assert defaults == len(places)


def _rviz_order(document: Any) -> list[str]:
    """The names of an RViz2 file's displays (a group's: its displays'), after grid and model."""
    names: list[str] = []
    for display in document["Visualization Manager"]["Displays"][2:]:
        inner = display.get("Displays") or [display]
        names.extend(item["Name"].split(":")[0] for item in inner)
    return names


def _titles(configs: dict[str, Any], leaf: str) -> list[str]:
    """What a tile shows: its panel's title (a Tab panel's: its tabs' panels' titles)."""
    ids = [tab["layout"] for tab in configs[leaf]["tabs"]] if leaf.startswith("Tab!") else [leaf]
    titles = [configs[i].get("lichtblickPanelTitle", configs[i].get("topicPath", "")) for i in ids]
    # "visual display 3 · /robot1/camera/image_raw_3 (placeholder: ...)": the component.
    return [title.split(" (")[0].split(" \u00b7 ")[0] for title in titles]


def _lichtblick_order(layout: Any) -> list[str]:
    """The panels' titles in the order of the design note's tiles."""
    note = layout["globalVariables"]["teleop_ui_design"]["tiles"]
    leaves = dict.fromkeys(tile["panel"] for tile in note)
    return [title for leaf in leaves for title in _titles(layout["configById"], leaf)]


def _lichtblick_tiles(layout: Any) -> list[tuple[tuple[str, ...], tuple[float, ...]]]:
    """Each tile's titles and its rectangle on a 320x200 thumbnail, from the split tree."""
    rects = leaf_rects(layout["layout"], 320, 200)
    configs = layout["configById"]
    return sorted(
        (
            # A Tab panel shows its tabs' titles (the sensors' short names); a panel its own.
            tuple(tab["title"] for tab in configs[leaf]["tabs"])
            if leaf.startswith("Tab!")
            else tuple(_titles(configs, leaf)),
            _rounded(r.x, r.y, r.width, r.height),
        )
        for leaf, r in rects.items()
    )


def _preview_tiles(layout: Any) -> list[tuple[tuple[str, ...], tuple[float, ...]]]:
    """Each rectangle the HTML preview draws and the titles it labels it with."""
    found = []
    drawn = re.findall(
        r'<rect x="([\d.]+)" y="([\d.]+)" width="([\d.]+)" height="([\d.]+)"[^>]*/>'
        r"<text[^>]*>([^<]*)</text>",
        preview_svg(layout),
    )
    for x, y, w, h, label in drawn:
        title = html.unescape(label).partition(": ")[2]
        parts = title.removeprefix("tabs ").split(" | ") if title.startswith("tabs ") else [title]
        names = tuple(part.split(" (")[0].split(" \u00b7 ")[0] for part in parts)
        found.append((names, _rounded(float(x), float(y), float(w), float(h))))
    return sorted(found)


def _rounded(*values: float) -> tuple[float, ...]:
    return tuple(round(value) for value in values)


@pytest.mark.parametrize("group", GROUPS)
def test_the_lichtblick_layout_the_rviz2_file_and_the_preview_agree(
    written: dict[tuple[str, str], list[Written]], group: str
) -> None:
    pairs = zip(written[group, "foxglove"], written[group, "rviz"], strict=True)
    compared = 0
    for fox, rviz in pairs:
        layout = json.loads(fox.path.read_text())
        document = yaml.load(
            rviz.path.read_text(), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)
        )
        order = _lichtblick_order(layout)
        if any(name.startswith("/") for name in order):
            continue  # a Raw Messages panel shows its topic, not the component: no name to compare
        assert _preview_tiles(layout) == _lichtblick_tiles(layout), fox.path
        assert _rviz_order(document) == order, rviz.path
        compared += 1
    assert compared > len(written[group, "foxglove"]) // 2
