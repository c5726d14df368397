"""Robots the live tests put on a real master, as their nodes would at start-up.

Each helper sets the robot's ``robot_description`` (URDF text from
:mod:`tests.identify.builders`) and registers its nodes' topics through the master API under
the robot's namespace. The expected UI configurations are asked of :func:`solver.assign`
directly, from the combination the robot should have, not of the code under test.
"""

from __future__ import annotations

from solver.solving.assignment import assign
from solver.solving.solution import Solution
from tests.identify import builders
from tests.live.roscore import TestNode


def drone_text() -> str:
    return builders.quadrotor().text()


def rover_text() -> str:
    return builders.ugv().text()


def still_rover_text() -> str:
    """A base trimmed of its moving parts (fixed wheels): a UGV that shows no motion control
    until something on the graph drives it."""
    robot = builders.RobotText("still_rover")
    robot.fixed(robot.root, "left_wheel")
    robot.fixed(robot.root, "right_wheel")
    return robot.text()


def large_text(markers: int = 6000) -> str:
    """A humanoid with thousands of fixed marker links: about 1.5 MB of URDF."""
    robot = builders.humanoid()
    for index in range(markers):
        robot.fixed(robot.root, f"marker_{index:05d}_link_with_a_long_descriptive_name")
    return robot.text()


def put_drone(node: TestNode, namespace: str) -> None:
    """A quadrotor (UAV, Flight from its rotors) publishing one camera."""
    node.set_param(f"{namespace}/robot_description", drone_text())
    node.publish(
        f"{namespace}/camera_driver", [(f"{namespace}/camera/image_raw", "sensor_msgs/Image")]
    )


def put_rover(node: TestNode, namespace: str) -> None:
    """A wheeled rover (UGV) driven by cmd_vel, with one laser scanner."""
    node.set_param(f"{namespace}/robot_description", rover_text())
    node.subscribe(f"{namespace}/base_driver", [(f"{namespace}/cmd_vel", "geometry_msgs/Twist")])
    node.publish(f"{namespace}/laser_driver", [(f"{namespace}/scan", "sensor_msgs/LaserScan")])


def expected(solution: Solution, **values: str) -> int:
    """The configuration number :func:`solver.assign` gives ``values``."""
    return assign(solution, values).number


def drone_configuration(solution: Solution) -> int:
    return expected(
        solution,
        kinematic_type="UAV",
        motion_control="Flight",
        sensor_type="2D Camera",
        sensor_count="1",
    )


def rover_configuration(solution: Solution) -> int:
    return expected(
        solution,
        kinematic_type="UGV",
        motion_control="Driving",
        sensor_type="LIDAR",
        sensor_count="1",
    )
