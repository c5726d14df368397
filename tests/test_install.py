"""Installing the project leaves a ROS install working: nothing on PATH shadows a ROS tool."""

from __future__ import annotations

import sys
from pathlib import Path

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
