"""``watch --layouts DIR`` writes each robot's layouts on its real topics and names the active
robot's in selection events: on a real roscore, and on real Cyclone DDS participants."""

from __future__ import annotations

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
from solver.live.events import RobotAdded, SelectionChanged
from solver.live.layouts import LiveLayouts
from solver.live.robot import identify_robot
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
from tests.live.ros2_graph import EmulatedRobot, next_domain, write_config
from tests.live.roscore import Roscore, TestNode, wait_until
from tests.live.test_cli import WatchProcess

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
        ["ugv1", "uav1", rover.name, drone.name]
    )


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
    warnings = layouts.update(RobotAdded(1, robot))
    assert warnings == [
        "no layout for /ugv-1: /ugv-1: '/ugv-1' is not a ROS 2 namespace: it has a character "
        "other than a letter, a digit, '_' or '/' at 5"
    ]
    request = Request("/ugv-1")
    event = SelectionChanged(2, request, select(request, {"/ugv-1": robot}, solution))
    assert layouts.path(event) is None
    assert list(tmp_path.iterdir()) == []


def test_the_root_robot_and_a_mode_it_lacks_get_layouts_too(
    solution: Solution, profile: Profile, tmp_path: Path
) -> None:
    camera = (Topic("camera/image_raw", "sensor_msgs/Image", "published"),)
    robot = _identified("/", drone_text(), camera, solution, profile)
    layouts = LiveLayouts(tmp_path, solution)
    # A drone that has no command topic yet keeps the presentation's, and says so.
    assert layouts.update(RobotAdded(1, robot)) == [
        "/ topics: Flight: the robot has no subscribed topic of type geometry_msgs/Twist for "
        "this Teleop panel; it keeps the presentation's topic /cmd_vel"
    ]
    own = tmp_path / f"config-{drone_configuration(solution):03d}.json"
    assert _topics(_layout(own))["Image"] == "/camera/image_raw"
    # Asked for Driving, which a drone lacks: the default configuration, written on demand.
    request = Request("/", (("motion_control", "Driving"),))
    event = SelectionChanged(2, request, select(request, {"/": robot}, solution))
    default = tmp_path / f"config-{solution.default_configuration:03d}-default.json"
    assert layouts.path(event) == str(default)
    assert _faults(default, {}) == []


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
    assert layouts.update(RobotAdded(1, robot)) == [
        f"no layout for /ugv1: {out / 'ugv1'}: is a link inside the output folder; refused: "
        "a write never follows a link there (someone else may have put it there)"
    ]
    assert list(elsewhere.iterdir()) == []
    request = Request("/ugv1")
    event = SelectionChanged(2, request, select(request, {"/ugv1": robot}, solution))
    assert layouts.path(event) is None


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


def test_the_watcher_writes_at_most_written_files_layouts_and_says_so_once(
    solution: Solution, profile: Profile, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 20,000 robots wrote 30,000 files (82 MB): every layout the watcher writes counts.
    _lower(monkeypatch, "written-files", 3)
    robots = _rovers(5, solution, profile)
    layouts = LiveLayouts(tmp_path, solution)
    warnings = [w for index, r in enumerate(robots) for w in layouts.update(RobotAdded(index, r))]
    assert warnings == [
        f"no layout for /ugv4 (nor for later robots: the watcher's layouts reached a limit): "
        f"{tmp_path}: 4 files to write (every layout the watcher writes); at most 3 are "
        "accepted (limit 'written-files', docs/security.md)"
    ]
    assert sorted(p.parent.name for p in tmp_path.rglob("*.json")) == ["ugv1", "ugv2", "ugv3"]
    # A robot past the bound has no layout: its selection says null.
    request = Request("/ugv5")
    event = SelectionChanged(9, request, select(request, {"/ugv5": robots[4]}, solution))
    assert layouts.path(event) is None
    # A robot already written is written again as it changes: the same files, no more.
    assert layouts.update(RobotAdded(10, robots[0])) == []
    assert len(list(tmp_path.rglob("*.json"))) == 3


def test_the_watcher_writes_at_most_written_bytes_in_all(
    solution: Solution, profile: Profile, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    robots = _rovers(3, solution, profile)
    LiveLayouts(tmp_path / "probe", solution).update(RobotAdded(1, robots[0]))
    (one,) = (tmp_path / "probe").rglob("*.json")
    size = one.stat().st_size
    _lower(monkeypatch, "written-bytes", 2 * size + size // 2)
    out = tmp_path / "out"
    layouts = LiveLayouts(out, solution)
    warnings = [w for index, r in enumerate(robots) for w in layouts.update(RobotAdded(index, r))]
    assert len(warnings) == 1
    assert warnings[0].startswith("no layout for /ugv3 (nor for later robots: ")
    assert f"{3 * size} bytes to write (every layout the watcher writes)" in warnings[0]
    assert "(limit 'written-bytes', docs/security.md)" in warnings[0]
    assert sorted(p.parent.name for p in out.rglob("*.json")) == ["ugv1", "ugv2"]
