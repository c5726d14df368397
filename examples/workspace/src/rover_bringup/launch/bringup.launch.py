"""The rover: its description, a keyboard teleop in a terminal, and its navigation."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    description = os.path.join(
        get_package_share_directory("rover_description"), "urdf", "rover.urdf"
    )
    with open(description, encoding="utf-8") as stream:
        urdf = stream.read()
    navigation = os.path.join(
        get_package_share_directory("rover_navigation"), "launch", "navigation.launch.py"
    )
    return LaunchDescription(
        [
            Node(
                package="robot_state_publisher",
                executable="robot_state_publisher",
                parameters=[{"robot_description": urdf}],
            ),
            Node(
                package="teleop_twist_keyboard",
                executable="teleop_twist_keyboard",
                prefix="xterm -e",
            ),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(navigation)),
        ]
    )
