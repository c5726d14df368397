"""A folder of robots from a stranger: no link out of it is followed, and nothing of a file
beside a description that is not of its kind reaches the output or the team file written."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.core.rules import load_rules
from solver.identify.fleet import identify_fleet
from solver.identify.profile import load_profile
from tests.conftest import RULES, run_cli
from tests.identify import builders

SECRET = "root:$6$hunter2hash:19000:0:99999:7:::\n"
TOPICS = "/cmd_vel geometry_msgs/Twist\n"


def robots_beside(tmp_path: Path) -> tuple[Path, Path]:
    """A folder holding two rovers, and outside it a secret and a valid URDF."""
    folder = tmp_path / "robots"
    folder.mkdir()
    (folder / "rover.urdf").write_text(builders.ugv().text())
    (folder / "scout.urdf").write_text(builders.tracked().text())
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "shadow").write_text(SECRET)
    (outside / "robot.urdf").write_text(builders.quadrotor().text())
    return folder, outside


def fleet_output(folder: Path, team: Path) -> str:
    """Everything `fleet -o` shows and writes."""
    result = run_cli("fleet", folder, "-o", team)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    return result.stdout + result.stderr + team.read_text()


@pytest.mark.parametrize(
    "entry",
    ["drone.urdf", "drone.srdf", "drone.topics", "drone.topics.txt", "drone.teleop.yaml"],
)
def test_no_link_out_of_the_folder_is_followed(tmp_path: Path, entry: str) -> None:
    folder, outside = robots_beside(tmp_path)
    if entry != "drone.urdf":
        (folder / "drone.urdf").write_text(builders.quadrotor().text())
    target = outside / ("robot.urdf" if entry == "drone.urdf" else "shadow")
    (folder / entry).symlink_to(target)
    shown = fleet_output(folder, tmp_path / "team.yaml")
    assert f"not identified: drone: {folder / entry}: a link to a file outside the folder" in shown
    assert "hunter2" not in shown
    assert "UAV" not in shown.split("not identified")[0]  # the linked-to quadrotor is not read


def test_a_link_through_a_link_inside_the_folder_is_followed_to_its_end(tmp_path: Path) -> None:
    folder, outside = robots_beside(tmp_path)
    (folder / "relay").symlink_to(outside / "shadow")
    (folder / "rover.topics").symlink_to("relay")
    shown = fleet_output(folder, tmp_path / "team.yaml")
    assert "not identified: rover:" in shown
    assert "hunter2" not in shown


def test_a_link_to_a_file_inside_the_folder_is_read(tmp_path: Path) -> None:
    folder, _ = robots_beside(tmp_path)
    (folder / "lists").mkdir()
    (folder / "lists" / "rover.topics").write_text(TOPICS)
    (folder / "rover.topics").symlink_to("lists/rover.topics")
    rules = load_rules(RULES / "paper.yaml")
    fleet = identify_fleet(folder, rules=rules, profile=load_profile())
    assert fleet.failed == ()
    rover = fleet.identified[0]
    assert [control.motion_control for control in rover.motion_controls] == ["Driving"]


def test_a_folder_given_through_a_link_is_scanned(tmp_path: Path) -> None:
    folder, _ = robots_beside(tmp_path)
    (folder / "rover.topics").write_text(TOPICS)
    (tmp_path / "linked").symlink_to(folder)
    rules = load_rules(RULES / "paper.yaml")
    fleet = identify_fleet(tmp_path / "linked", rules=rules, profile=load_profile())
    assert fleet.failed == ()


def test_an_srdf_beside_a_robot_that_is_no_xml_is_a_warning_never_quoted(tmp_path: Path) -> None:
    folder, _ = robots_beside(tmp_path)
    (folder / "rover.srdf").write_text(SECRET)  # a supporting file: the URDF is read alone
    shown = fleet_output(folder, tmp_path / "team.yaml")
    assert f"warning: {folder / 'rover.srdf'}:1:1: malformed XML" in shown
    assert "2 robot(s) identified, 0 not" in shown
    assert "hunter2" not in shown


@pytest.mark.parametrize("entry", ["rover.topics", "rover.bag"])
def test_a_file_beside_a_robot_that_is_not_of_its_kind_is_never_quoted(
    tmp_path: Path, entry: str
) -> None:
    folder, _ = robots_beside(tmp_path)
    (folder / entry).write_text(SECRET)  # a copy, not a link: read, found not its kind
    shown = fleet_output(folder, tmp_path / "team.yaml")
    assert f"not identified: rover: {folder / entry}" in shown
    assert "hunter2" not in shown


def test_a_folder_of_robots_inside_a_package_reads_no_package_around_them(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text("<package><name>fleet_pkg</name></package>")
    (tmp_path / "nav.launch").write_text("<node pkg='move_base'/>")
    robots = tmp_path / "robots"
    robots.mkdir()
    rover = builders.ugv()
    rover.add(builders.model_plugin("drive", "libgazebo_ros_diff_drive.so"))
    rover.fixed(rover.root, "laser")
    rover.add(builders.LASER)
    (robots / "rover.urdf").write_text(rover.text())
    fleet = identify_fleet(robots, rules=load_rules(RULES / "paper.yaml"), profile=load_profile())
    [entry] = fleet.entries
    assert entry.identification is not None
    controls = {c.motion_control: c.source for c in entry.identification.motion_controls}
    assert controls["Waypoint"].startswith("urdf: likely, not declared")
    assert not any("packages read" in line for line in entry.identification.evidence)
