"""Installing the project leaves a ROS install working: nothing on PATH shadows a ROS tool; the
wheel carries the shipped rule sets and teams."""

from __future__ import annotations

import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

from tests.conftest import ROOT, RULES
from tests.live.roscore import Roscore

# Commands of ROS 1 (Debian's ros-core) and ROS 2 that a Python package could shadow; roscore
# itself runs `rosversion`, which pip's rospkg installs in a form that knows no ROS packages.
ROS_COMMANDS = (
    "rosversion",
    "roscore",
    "rosmaster",
    "roslaunch",
    "rosrun",
    "rosparam",
    "rostopic",
    "rosnode",
    "rosservice",
    "ros2",
    "catkin_make",
    "colcon",
)


def test_this_environment_has_no_script_named_like_a_ros_command() -> None:
    scripts = Path(sys.executable).parent
    assert [name for name in ROS_COMMANDS if (scripts / name).exists()] == []


def test_a_real_roscore_starts_with_this_environment_first_on_path(tmp_path: Path) -> None:
    core = Roscore(tmp_path)
    assert str(Path(sys.executable).parent) == core.environment()["PATH"].split(":")[0]
    core.start()
    try:
        assert core.process is not None
        assert core.process.poll() is None
    finally:
        core.kill()


def test_the_wheel_ships_every_rule_set_and_team(tmp_path: Path) -> None:
    """A real wheel, built from a copy of the sources, holds each file of rules/ and
    rules/teams/ (the marine rule set and its team among them)."""
    source = tmp_path / "source"
    source.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, source / name)
    shutil.copytree(ROOT / "rules", source / "rules")
    shutil.copytree(
        ROOT / "solver",
        source / "solver",
        symlinks=True,
        ignore=shutil.ignore_patterns("__pycache__"),
    )
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            str(source),
            "--no-deps",
            "--no-build-isolation",
            "-q",
            "-w",
            str(tmp_path / "dist"),
        ],
        check=True,
        capture_output=True,
    )
    [wheel] = (tmp_path / "dist").glob("*.whl")
    shipped = {
        name for name in zipfile.ZipFile(wheel).namelist() if name.startswith("solver/rules/")
    }
    expected = {
        f"solver/rules/{path.relative_to(RULES).as_posix()}"
        for path in [*RULES.glob("*.yaml"), *RULES.glob("teams/*.yaml")]
    }
    assert expected <= shipped
    assert {"solver/rules/marine.yaml", "solver/rules/teams/marine-survey.yaml"} <= shipped
