"""Nav2 for the rover, with its parameters."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    nav2 = os.path.join(
        get_package_share_directory("nav2_bringup"), "launch", "navigation_launch.py"
    )
    parameters = os.path.join(
        get_package_share_directory("rover_navigation"), "config", "nav2_params.yaml"
    )
    return LaunchDescription(
        [
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(nav2),
                launch_arguments={"params_file": parameters}.items(),
            )
        ]
    )
