"""``watch --layouts DIR`` writes each robot's layouts on its real topics and the team layout,
and its answer and selection events say where the active robot's are: on a real roscore, and
on real Cyclone DDS participants."""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Callable, Iterator
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from solver import limits
from solver.identify.identification import IdentificationCache
from solver.identify.profile import Profile
from solver.layouts.checks import check_lichtblick
from solver.live.discovery import RobotSource
from solver.live.graph import MISSING
from solver.live.layouts import LiveLayouts
from solver.live.robot import LiveRobot, identify_robot
from solver.live.selection import Request, select
from solver.ros.names import Topic
from solver.solving.solution import Solution
from tests.conftest import run_cli
from tests.live.fleet import (
    drone_configuration,
    drone_text,
    put_drone,
    put_rover,
    rover_configuration,
    rover_text,
)
from tests.live.ros2_graph import Domain, EmulatedRobot, Operator, next_domain, write_config
from tests.live.roscore import Roscore, TestNode, wait_until
from tests.live.watching import WatchProcess

TIMEOUT = 60.0


def _layout(path: Path) -> dict[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))  # type: ignore[no-any-return]  # json gives Any


def _topics(layout: dict[str, Any]) -> dict[str, str]:
    """Panel type -> the topic it shows or drives (the first such panel of each type)."""
    found: dict[str, str] = {}
    for key, config in layout["configById"].items():
        kind = key.partition("!")[0]
        topic = (
            config.get("topic")
            or config.get("imageMode", {}).get("imageTopic")
            or next(iter(config.get("topics", {})), None)
        )
        if topic is not None:
            found.setdefault(kind, topic)
    return found


def _faults(path: Path, types: dict[str, list[str]]) -> list[str]:
    """What the viewer's own rules say of a written layout."""
    return [str(f) for f in check_lichtblick(_layout(path), str(path), topic_types=types)]


def _sync(layouts: LiveLayouts, *robots: LiveRobot) -> list[str]:
    """The watcher's call when ``robots`` are every robot and each is new or changed; the
    warnings it gave."""
    layouts.sync({r.namespace: r for r in robots}, [r.namespace for r in robots])
    return layouts.take_warnings()


def _foxglove(layouts: LiveLayouts, request: Request, solution: Solution, *robots: Any) -> Any:
    """The path of the active robot's layout the answer to ``request`` names, or None."""
    selection = select(request, {r.namespace: r for r in robots}, solution)
    links = {link.target: link for link in layouts.links(selection)}
    return links["foxglove"].path if "foxglove" in links else None


def _tabs(team: dict[str, Any]) -> dict[tuple[str, int], dict[str, Any]]:
    """(robot, configuration) -> its tab in a team layout, as the follower maps them."""
    tabs = team["configById"]["Tab!robots"]["tabs"]
    mapping = team["configById"]["teleop-ui.follower!follower"]["tabs"]
    return {(m["robot"], m["configuration"]): tabs[m["tab"]] for m in mapping}


def _tab_topics(team: dict[str, Any], tab: dict[str, Any]) -> dict[str, str]:
    """Panel type -> topic of the panels a tab of the team layout shows."""
    leaves: list[str] = []
    stack = [tab["layout"]]
    while stack:
        node = stack.pop()
        if isinstance(node, str):
            leaves.append(node)
        else:
            stack += [node["second"], node["first"]]
    return _topics({"configById": {k: team["configById"][k] for k in leaves}})


def test_watch_once_writes_each_robots_layout_and_names_the_active_ones(
    master: Roscore, node: TestNode, solution: Solution, tmp_path: Path
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    out = tmp_path / "layouts"
    result = run_cli("watch", "--master", master.uri, "--team", "case3", "--once", "--layouts", out)
    assert result.returncode == 0, result.stderr
    events = [json.loads(line) for line in result.stdout.splitlines()]
    selection = next(e for e in events if e["event"] == "selection_changed")
    rover = out / "ugv1" / f"config-{rover_configuration(solution):03d}.json"
    assert selection["layout"] == str(rover)
    # Two robots, one configuration each: the team layout's tabs are /uav1's, then /ugv1's.
    assert selection["layouts"] == {
        "foxglove": {"path": str(rover)},
        "team": {"path": str(out / "team.json"), "tab": 1},
    }
    assert all("layout" not in e for e in events if e["event"] != "selection_changed")
    # The rover's panels are on its own topics, as the graph has them: the scanner is a
    # LaserScan (coloured by intensity), the pad drives the topic its base subscribes to.
    layout = _layout(rover)
    assert _topics(layout) == {"Teleop": "/ugv1/cmd_vel", "3D": "/ugv1/scan"}
    scan = next(c for k, c in layout["configById"].items() if k.startswith("3D!"))
    assert scan["topics"]["/ugv1/scan"]["colorField"] == "intensity"
    assert _faults(rover, {"/ugv1/scan": ["sensor_msgs/LaserScan"]}) == []
    drone = out / "uav1" / f"config-{drone_configuration(solution):03d}.json"
    assert _topics(_layout(drone)) == {"Teleop": "/uav1/cmd_vel", "Image": "/uav1/camera/image_raw"}
    assert _faults(drone, {}) == []
    assert sorted(p.name for p in out.rglob("*")) == sorted(
        ["ugv1", "uav1", rover.name, drone.name, "team.json"]
    )
    # The team layout: a tab per robot's configuration, each on that robot's topics, and
    # every rule of the viewer kept (each tab a screen of its own).
    team = _layout(out / "team.json")
    tabs = _tabs(team)
    assert list(tabs) == [
        ("/uav1", drone_configuration(solution)),
        ("/ugv1", rover_configuration(solution)),
    ]
    assert _tab_topics(team, tabs["/ugv1", rover_configuration(solution)]) == _topics(layout)
    assert team["configById"]["Tab!robots"]["tabs"][1]["title"].startswith(
        f"/ugv1: {rover_configuration(solution)} ("
    )
    assert _faults(out / "team.json", {"/ugv1/scan": ["sensor_msgs/LaserScan"]}) == []


def test_a_robot_appearing_and_renaming_a_topic_gets_its_layout_written_again(
    master: Roscore, node: TestNode, solution: Solution, tmp_path: Path
) -> None:
    out = tmp_path / "layouts"
    watch = WatchProcess("--master", master.uri, "--team", "case3", "--layouts", str(out))
    try:
        watch.wait_for(lambda e: e["event"] == "synced", "synced")
        put_rover(node, "/ugv1")
        rover = out / "ugv1" / f"config-{rover_configuration(solution):03d}.json"
        wait_until(rover.exists, TIMEOUT, "the rover's layout")
        assert _topics(_layout(rover))["3D"] == "/ugv1/scan"
        # The scanner's driver moves it: the robot changes, its layout follows.
        node.publish("/ugv1/laser_driver", [("/ugv1/front/scan", "sensor_msgs/LaserScan")])
        node.unpublish("/ugv1/laser_driver", ["/ugv1/scan"])
        watch.wait_for(
            lambda e: e["event"] == "robot_changed" and "topics" in e["changed"], "robot_changed"
        )
        wait_until(
            lambda: _topics(_layout(rover))["3D"] == "/ugv1/front/scan", TIMEOUT, "the new scan"
        )
        # Written atomically: no temporary file is left beside the layout.
        assert [p.name for p in rover.parent.iterdir()] == [rover.name]
    finally:
        watch.kill()
    assert "Traceback" not in "".join(watch.stderr)


def _identified(namespace: str, text: str, topics: tuple[Topic, ...], solution: Solution,
                profile: Profile) -> Any:  # fmt: skip
    source = RobotSource(namespace, f"{namespace}/robot_description", None, topics)
    return identify_robot(
        source, text, cache=IdentificationCache(), solution=solution, profile=profile
    )


def test_a_robot_whose_namespace_is_no_ros2_name_gets_no_layout_and_a_warning(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    scan = (Topic("scan", "sensor_msgs/LaserScan", "published"),)
    robot = _identified("/ugv-1", rover_text(), scan, solution, profile)
    layouts = LiveLayouts(tmp_path, solution)
    warnings = _sync(layouts, robot)
    assert warnings == [
        "no layout for /ugv-1: /ugv-1: '/ugv-1' is not a ROS 2 namespace: it has a character "
        "other than a letter, a digit, '_' or '/' at 5"
    ]
    assert _foxglove(layouts, Request("/ugv-1"), solution, robot) is None
    # Asked on every poll while it is active, the refused layout is not tried or warned again.
    for _ in range(3):
        assert _foxglove(layouts, Request("/ugv-1"), solution, robot) is None
    assert layouts.take_warnings() == []
    # The team layout has no tab for it, and nothing else was written.
    assert [p.name for p in tmp_path.iterdir()] == ["team.json"]
    assert _tabs(_layout(tmp_path / "team.json")) == {}


def test_a_presentation_ordering_by_data_rate_is_applied_alphabetically_and_said_once(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    # watch --layouts reads no bag: the order the file asks for cannot be applied.
    from solver.layouts.presentation import load_presentation

    file = tmp_path / "presentation.yaml"
    shipped = Path(__file__).resolve().parents[2] / "rules" / "presentation.yaml"
    file.write_text(shipped.read_text().replace("order: alphabetical", "order: data rate"))
    line = next(n for n, text in enumerate(file.read_text().splitlines(), 1) if "data rate" in text)
    scan = (Topic("scan", "sensor_msgs/LaserScan", "published"),)
    robot = _identified("/ugv1", rover_text(), scan, solution, profile)
    out = tmp_path / "out"
    layouts = LiveLayouts(out, solution, load_presentation(file, solution.rules))
    warnings = [w for w in _sync(layouts, robot) if "data rate" in w]
    assert warnings == [
        f"{file}:{line}: grammar.clusters.order: 'data rate' was asked for and needs each "
        "topic's bytes per second, from a bag, which watch --layouts does not have: ordered "
        "alphabetically"
    ]
    robot2 = _identified("/ugv2", rover_text(), scan, solution, profile)
    assert [w for w in _sync(layouts, robot, robot2) if "data rate" in w] == []  # said once
    design = _layout(next(out.glob("ugv1/*.json")))["globalVariables"]["teleop_ui_design"]
    assert design["clusterOrder"] == "alphabetical"
    assert "watch --layouts does not have" in design["clusterOrderNote"]


def test_the_root_robot_and_a_mode_it_lacks_get_layouts_too(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    camera = (Topic("camera/image_raw", "sensor_msgs/Image", "published"),)
    robot = _identified("/", drone_text(), camera, solution, profile)
    layouts = LiveLayouts(tmp_path, solution)
    # A drone that has no command topic yet keeps the presentation's, and says so.
    assert _sync(layouts, robot) == [
        "/ topics: Flight: the robot has no subscribed topic of type geometry_msgs/Twist for "
        "this Teleop panel; it keeps the presentation's topic /cmd_vel"
    ]
    own = tmp_path / f"config-{drone_configuration(solution):03d}.json"
    assert _topics(_layout(own))["Image"] == "/camera/image_raw"
    # Asked for Driving, which a drone lacks: the default configuration, written on demand.
    request = Request("/", (("motion_control", "Driving"),))
    default = tmp_path / f"config-{solution.default_configuration:03d}-default.json"
    assert _foxglove(layouts, request, solution, robot) == str(default)
    assert _faults(default, {}) == []
    # The team layout keeps the robot's own combinations: the default is no tab of it.
    selection = select(request, {"/": robot}, solution)
    (team,) = (link for link in layouts.links(selection) if link.target == "team")
    assert (team.path, team.tab) == (str(tmp_path / "team.json"), None)
    assert list(_tabs(_layout(tmp_path / "team.json"))) == [("/", drone_configuration(solution))]


@pytest.fixture
def dds(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Callable[[], EmulatedRobot]]:
    """Emulated ROS 2 processes on a loopback DDS domain of this test's own."""
    monkeypatch.setenv("CYCLONEDDS_URI", write_config(tmp_path))
    domain = next_domain()
    monkeypatch.setenv("ROS_DOMAIN_ID", str(domain))
    robots: list[EmulatedRobot] = []

    def start() -> EmulatedRobot:
        robots.append(EmulatedRobot(domain, dict(os.environ)))
        return robots[-1]

    yield start
    for robot in robots:
        robot.kill()


def test_watch_ros2_writes_a_layout_on_the_graphs_own_names_and_types(
    dds: Callable[[], EmulatedRobot], solution: Solution, tmp_path: Path
) -> None:
    robot = dds()
    robot.node(
        "/ugv1/base_driver",
        subscribe=[("/ugv1/base/cmd_vel", "geometry_msgs/msg/Twist")],
        publish=[("/ugv1/lidar/points", "sensor_msgs/msg/PointCloud2")],
    )
    robot.describe("/ugv1", rover_text(), tmp_path)
    out = tmp_path / "layouts"
    result = run_cli("watch", "--ros2", "--team", "case3", "--once", "--layouts", out)
    assert result.returncode == 0, result.stderr
    (written,) = (out / "ugv1").iterdir()
    layout = _layout(written)
    assert _topics(layout) == {"Teleop": "/ugv1/base/cmd_vel", "3D": "/ugv1/lidar/points"}
    cloud = next(c for k, c in layout["configById"].items() if k.startswith("3D!"))
    assert cloud["topics"]["/ugv1/lidar/points"]["colorField"] == "z"  # a PointCloud2
    assert _faults(written, {"/ugv1/lidar/points": ["sensor_msgs/msg/PointCloud2"]}) == []


# ---- a planted link and a bound on what the watcher writes (issue 36.10 and 36.11) ------------


def test_a_folder_link_planted_for_a_robot_is_never_written_through(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    out, elsewhere = tmp_path / "layouts", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (out / "ugv1").symlink_to(elsewhere, target_is_directory=True)
    (robot,) = _rovers(1, solution, profile)
    layouts = LiveLayouts(out, solution)
    assert _sync(layouts, robot) == [
        f"no layout for /ugv1: {out / 'ugv1'}: is a link inside the output folder; refused: "
        "a write never follows a link there (someone else may have put it there)"
    ]
    assert list(elsewhere.iterdir()) == []
    assert _foxglove(layouts, Request("/ugv1"), solution, robot) is None


def test_a_link_planted_as_the_team_layout_is_never_written_through(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    out, elsewhere = tmp_path / "layouts", tmp_path / "elsewhere.json"
    out.mkdir()
    elsewhere.write_text("mine", encoding="utf-8")
    (out / "team.json").symlink_to(elsewhere)
    (robot,) = _rovers(1, solution, profile)
    layouts = LiveLayouts(out, solution)
    (warning,) = _sync(layouts, robot)
    assert warning.startswith(f"no team layout: {out / 'team.json'}: is a link; refused")
    assert elsewhere.read_text(encoding="utf-8") == "mine"
    # The robot's own layout is written; the answer names no team layout.
    links = layouts.links(select(Request("/ugv1"), {"/ugv1": robot}, solution))
    assert [link.target for link in links] == ["foxglove"]
    # Said once: the same robots again make no new attempt and no new warning.
    layouts.sync({"/ugv1": robot}, [])
    assert layouts.take_warnings() == []


def _lower(monkeypatch: pytest.MonkeyPatch, name: str, value: int) -> None:
    # pylint: disable=protected-access
    monkeypatch.setitem(limits._BY_NAME, name, replace(limits.limit(name), value=value))


def _rovers(count: int, solution: Solution, profile: Profile) -> list[Any]:
    scan = (
        Topic("scan", "sensor_msgs/LaserScan", "published"),
        Topic("cmd_vel", "geometry_msgs/Twist", "subscribed"),
    )
    return [
        _identified(f"/ugv{index}", rover_text(), scan, solution, profile)
        for index in range(1, count + 1)
    ]


def _one_by_one(layouts: LiveLayouts, robots: list[Any]) -> list[str]:
    """The robots joining the graph one after another: the warnings."""
    warnings: list[str] = []
    for count in range(1, len(robots) + 1):
        present = robots[:count]
        layouts.sync({r.namespace: r for r in present}, [present[-1].namespace])
        warnings += layouts.take_warnings()
    return warnings


def test_the_watcher_writes_at_most_written_files_layouts_and_says_so_once(
    solution: Solution, profile: Profile, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 20,000 robots wrote 30,000 files (82 MB): every layout the watcher writes counts, the
    # team layout too (one file, written again in place).
    _lower(monkeypatch, "written-files", 4)
    robots = _rovers(5, solution, profile)
    layouts = LiveLayouts(tmp_path, solution)
    assert _one_by_one(layouts, robots) == [
        f"no layout for /ugv4 (nor for later robots: the watcher's layouts reached a limit): "
        f"{tmp_path}: 5 files to write (every layout the watcher writes); at most 4 are "
        "accepted (limit 'written-files', docs/security.md)"
    ]
    assert sorted(p.parent.name for p in tmp_path.rglob("config-*.json")) == [
        "ugv1",
        "ugv2",
        "ugv3",
    ]
    # A robot past the bound has no layout (its answer names none) and no tab.
    assert _foxglove(layouts, Request("/ugv5"), solution, robots[4]) is None
    assert [robot for robot, _ in _tabs(_layout(tmp_path / "team.json"))] == [
        "/ugv1",
        "/ugv2",
        "/ugv3",
    ]
    # A robot already written is written again as it changes: the same files, no more.
    layouts.sync({r.namespace: r for r in robots}, ["/ugv1"])
    assert layouts.take_warnings() == []
    assert len(list(tmp_path.rglob("*.json"))) == 4


def test_the_watcher_writes_at_most_written_bytes_in_all(
    solution: Solution, profile: Profile, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    robots = _rovers(3, solution, profile)
    _sync(LiveLayouts(tmp_path / "probe", solution), robots[0])
    one = next((tmp_path / "probe").rglob("config-*.json"))
    size = one.stat().st_size
    # The team layout holds the robots' panels again (not their design notes): two robots and
    # their team layout fit in four robots' bytes, a third robot does not.
    _lower(monkeypatch, "written-bytes", 4 * size)
    out = tmp_path / "out"
    layouts = LiveLayouts(out, solution)
    (warning,) = _one_by_one(layouts, robots)
    assert warning.startswith("no layout for /ugv3 (nor for later robots: ")
    assert "bytes to write (every layout the watcher writes)" in warning
    assert "(limit 'written-bytes', docs/security.md)" in warning
    assert sorted(p.parent.name for p in out.rglob("config-*.json")) == ["ugv1", "ugv2"]
    assert sum(p.stat().st_size for p in out.rglob("*.json")) <= 4 * size


# ---- the answer carries its layouts (issue 38) ---------------------------------------------


def _answer_layouts(answer: dict[str, Any], types: dict[str, list[str]]) -> dict[str, Any]:
    """What an answer's layouts are: each file there, passing the viewer's rules; the team
    layout's tab that of the answer's (robot, configuration), holding that robot's panels."""
    layouts = answer["layouts"]
    own, team = Path(layouts["foxglove"]["path"]), Path(layouts["team"]["path"])
    assert own.is_absolute()
    assert team.is_absolute()
    assert _faults(own, types) == []
    assert _faults(team, types) == []
    tabs = _tabs(_layout(team))
    shown = _layout(team)["configById"]["Tab!robots"]["tabs"][layouts["team"]["tab"]]
    assert shown == tabs[answer["robot"], answer["configuration"]]
    assert _tab_topics(_layout(team), shown) == _topics(_layout(own))
    return layouts  # type: ignore[no-any-return]  # JSON


def test_the_ros1_answer_carries_its_layouts_which_pass_the_checks(
    master: Roscore, node: TestNode, solution: Solution, tmp_path: Path
) -> None:
    put_drone(node, "/uav1")
    put_rover(node, "/ugv1")
    out = tmp_path / "layouts"
    watch = WatchProcess("--master", master.uri, "--team", "case3", "--layouts", str(out))
    try:
        watch.wait_for(lambda e: e["event"] == "synced", "synced")
        node.set_param("/teleop_ui/active_robot", "/ugv1")
        event = watch.wait_for(
            lambda e: e["event"] == "selection_changed" and e["robot"] == "/ugv1", "the switch"
        )
        answer = wait_until(
            lambda: (a := node.get_param("/teleop_ui/ui_configuration")) != MISSING and a,
            TIMEOUT,
            "the answer",
        )
    finally:
        watch.kill()
    assert answer["configuration"] == rover_configuration(solution)
    layouts = _answer_layouts(answer, {"/ugv1/scan": ["sensor_msgs/LaserScan"]})
    rover = out / "ugv1" / f"config-{rover_configuration(solution):03d}.json"
    # Not served: paths only (ROS 1 parameters have no null: no url key at all).
    assert layouts == {
        "foxglove": {"path": str(rover)},
        "team": {"path": str(out / "team.json"), "tab": 1},
    }
    assert event["layouts"] == layouts


def test_the_ros2_answer_carries_its_layouts_which_pass_the_checks(
    domain: Domain, solution: Solution, tmp_path: Path
) -> None:
    domain.drone("/uav1")
    domain.rover("/ugv1")
    out = tmp_path / "layouts"
    watch = WatchProcess(
        "--ros2", "--domain", str(domain.id), "--team", "case3", "--layouts", str(out),
        env=domain.env,
    )  # fmt: skip
    operator = Operator(domain.id)
    try:
        watch.wait_for(lambda e: e["event"] == "synced", "synced")
        operator.activate("/uav1")
        answer = wait_until(
            lambda: (a := operator.answer()) is not None and a.get("robot") == "/uav1" and a,
            TIMEOUT,
            "the answer",
        )
    finally:
        operator.close()
        watch.kill()
    assert answer["configuration"] == drone_configuration(solution)
    layouts = _answer_layouts(answer, {})
    assert layouts["foxglove"]["path"] == str(
        out / "uav1" / f"config-{drone_configuration(solution):03d}.json"
    )
    assert layouts["team"] == {"path": str(out / "team.json"), "tab": 0}


def test_the_team_layout_is_written_again_when_a_robot_joins_or_goes(
    master: Roscore, node: TestNode, solution: Solution, tmp_path: Path
) -> None:
    put_drone(node, "/uav1")
    out = tmp_path / "layouts"
    team = out / "team.json"
    watch = WatchProcess("--master", master.uri, "--team", "case3", "--layouts", str(out))
    drone = ("/uav1", drone_configuration(solution))
    rover = ("/ugv1", rover_configuration(solution))

    def pairs() -> list[tuple[str, int]]:
        return list(_tabs(_layout(team))) if team.exists() else []

    try:
        watch.wait_for(lambda e: e["event"] == "synced", "synced")
        assert pairs() == [drone]
        put_rover(node, "/ugv1")
        wait_until(lambda: pairs() == [drone, rover], TIMEOUT, "the rover's tab")
        node.delete_param("/uav1/robot_description")
        wait_until(lambda: pairs() == [rover], TIMEOUT, "the drone's tab gone")
        # The drone's own files stay (a robot gone keeps its folder); the team layout holds
        # what is on the graph.
        assert (out / "uav1").is_dir()
        assert _faults(team, {"/ugv1/scan": ["sensor_msgs/LaserScan"]}) == []
    finally:
        watch.kill()
    assert "Traceback" not in "".join(watch.stderr)


def test_the_text_format_shows_a_long_layout_path_whole(
    master: Roscore, node: TestNode, solution: Solution, tmp_path: Path
) -> None:
    # Cut to 60 characters before (".../config-103-default.jso... (cut from 61 characters)"):
    # a path the tool made is the operator's to copy, not a stranger's string.
    put_rover(node, "/ugv1")
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    out = tmp_path / ("a-folder-whose-name-is-long-enough-to-be-cut-" * 2) / "layouts"
    result = run_cli(
        "watch", "--master", master.uri, "--team", "case3", "--once", "--format", "text",
        "--layouts", out,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    rover = out / "ugv1" / f"config-{rover_configuration(solution):03d}.json"
    lines = result.stdout.splitlines()
    assert f"layout          foxglove: {rover}" in lines
    assert f"layout          team (tab 0): {out / 'team.json'}" in lines
    assert "cut from" not in result.stdout


def test_a_hostile_namespace_from_the_graph_reaches_no_file_name_or_address(
    domain: Domain, tmp_path: Path
) -> None:
    # DDS topic names may hold what ROS names may not: '..', '%', '\\'. Such a robot is
    # reported, gets no layout and no tab, and its answer names nothing outside the folder.
    hostile = ["/..", "/a/../../b", "/%2e%2e", "/a\\b"]
    domain.directory = tmp_path / "descriptions"
    domain.directory.mkdir()
    robot = domain.robot()
    for namespace in [*hostile, "/ugv1"]:
        robot.describe(namespace, rover_text(), domain.directory)
    out = tmp_path / "work" / "layouts"
    watch = WatchProcess(
        "--ros2", "--domain", str(domain.id), "--team", "case3", "--layouts", str(out),
        "--serve", "0", env=domain.env,
    )  # fmt: skip
    operator = Operator(domain.id)
    answers: list[dict[str, Any]] = []

    def answer_for(namespace: str) -> Any:
        answer = operator.answer()
        return answer if answer and answer["robot"] == namespace else None

    try:
        watch.wait_for(lambda e: e["event"] == "synced" and len(e["robots"]) == 5, "synced")
        for namespace in hostile:
            operator.activate(namespace)
            answers.append(
                wait_until(
                    functools.partial(answer_for, namespace), TIMEOUT, f"the answer for {namespace}"
                )
            )
    finally:
        operator.close()
        watch.kill()
    (serving,) = [line for line in watch.stderr if line.startswith("serving on ")]
    base = serving.split()[2]
    for answer in answers:
        # No layout of its own, no tab (the answer leaves out what is null, as on ROS 1).
        assert answer["layouts"] == {
            "team": {"path": str(out / "team.json"), "url": f"{base}/layouts/team.json"}
        }
    # Written: the good robot's layout and the team layout, in the folder, and nothing else
    # anywhere (the test's own files aside).
    written = sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*") if p.is_file())
    assert [w for w in written if not w.startswith("descriptions/")] == [
        "cyclonedds.xml",
        "work/layouts/team.json",
        f"work/layouts/ugv1/{next((out / 'ugv1').iterdir()).name}",
    ]
    assert [robot for robot, _ in _tabs(_layout(out / "team.json"))] == ["/ugv1"]
