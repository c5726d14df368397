"""Sensors and motion controls from (topic, type, direction) triples."""

from __future__ import annotations

import pytest

from solver.identify import Topic, controls_from_topics, load_profile, sensors_from_topics
from solver.identify.interfaces import device_of

PROFILE = load_profile()


def sensed(*topics: Topic) -> list[tuple[str, str]]:
    return [(d.kind, d.name) for d in sensors_from_topics(topics, PROFILE)]


def controls(structure: str, *topics: Topic) -> list[str]:
    return [c.motion_control for c in controls_from_topics(topics, PROFILE, structure)]


def test_topics_of_one_device_count_once_as_its_strongest_kind() -> None:
    assert sensed(
        Topic("/camera/rgb/image_raw", "sensor_msgs/Image"),
        Topic("/camera/rgb/image_raw/compressed", "sensor_msgs/CompressedImage"),
        Topic("/camera/depth/image_raw", "sensor_msgs/Image"),
        Topic("/front/scan", "sensor_msgs/LaserScan"),
        Topic("/rear/scan", "sensor_msgs/LaserScan"),
    ) == [("depth_camera", "/camera"), ("lidar", "/front"), ("lidar", "/rear")]


def test_device_of_strips_stream_segments_but_keeps_one() -> None:
    assert device_of("/scan", PROFILE) == "/scan"
    assert device_of("/head/camera/image_raw/compressed", PROFILE) == "/head/camera"


@pytest.mark.parametrize(
    ("topic", "kind"),
    [
        (Topic("/velodyne_points", "sensor_msgs/PointCloud2"), "lidar"),
        (Topic("/stereo/disparity", "stereo_msgs/DisparityImage"), "stereo_camera"),
        (Topic("/ft_sensor/wrench", "geometry_msgs/WrenchStamped"), "force_torque"),
        (Topic("/audio/audio", "audio_common_msgs/AudioData", "published"), "microphone"),
        (Topic("/speech", "audio_common_msgs/AudioData", "subscribed"), "speaker"),
        (Topic("/robotsound", "sound_play/SoundRequest", "subscribed"), "speaker"),
        (Topic("/sonar_front", "sensor_msgs/Range"), "sonar"),
        (Topic("/ultrasound/rear", "sensor_msgs/Range"), "sonar"),
        (Topic("/cliff/left", "sensor_msgs/Range"), "ir_range"),
        (Topic("/theta/image_raw", "sensor_msgs/Image"), "camera"),
        (Topic("/omni_camera/image_raw", "sensor_msgs/Image"), "wide_angle_camera"),
    ],
)
def test_message_types_map_to_sensor_kinds(topic: Topic, kind: str) -> None:
    assert [k for k, _ in sensed(topic)] == [kind]


def test_what_the_robot_only_subscribes_to_is_not_its_sensor() -> None:
    assert sensed(Topic("/map_image", "sensor_msgs/Image", "subscribed")) == []


@pytest.mark.parametrize(
    ("structure", "control"),
    [
        ("UGV", "Driving"),
        ("Mobile Manipulator", "Driving"),
        ("UAV", "Flight"),
        ("Humanoid", "Walking"),
        ("Quadruped", "Walking"),
        ("Hexapod", "Walking"),
        ("Biped", "Walking"),
        ("Legged Mobile Manipulator", "Walking"),
        ("Aerial Manipulator", "Flight"),
        ("Surface Vessel", "Driving"),
        ("Underwater Vehicle", "Driving"),
    ],
)
def test_a_velocity_command_is_the_structures_control(structure: str, control: str) -> None:
    assert controls(structure, Topic("/cmd_vel", "geometry_msgs/Twist", "subscribed")) == [control]


@pytest.mark.parametrize(
    ("topic", "control"),
    [
        (Topic("/move_base/goal", "move_base_msgs/MoveBaseActionGoal"), "Waypoint"),
        (Topic("/move_base_simple/goal", "geometry_msgs/PoseStamped"), "Waypoint"),
        (
            Topic("/navigate_to_pose/_action/status", "action_msgs/GoalStatusArray", "published"),
            "Waypoint",
        ),
        (
            Topic("/firefly/command/trajectory", "trajectory_msgs/MultiDOFJointTrajectory"),
            "Waypoint",
        ),
        (Topic("/arm_controller/command", "trajectory_msgs/JointTrajectory"), "Joint"),
        (
            Topic(
                "/arm_controller/follow_joint_trajectory/goal",
                "control_msgs/FollowJointTrajectoryActionGoal",
            ),
            "Joint",
        ),
        (Topic("/move_group/goal", "moveit_msgs/MoveGroupActionGoal"), "End Effector"),
        (Topic("/arm_controller/cartesian_twist/command", "geometry_msgs/Twist"), "End Effector"),
        (Topic("/footstep", "humanoid_nav_msgs/StepTarget"), "Walking"),
        (Topic("/command/roll_pitch_yawrate_thrust", "mav_msgs/RollPitchYawrateThrust"), "Flight"),
        # Flight setpoints: an attitude is flown, a position is a waypoint.
        (Topic("/mavros/setpoint_raw/attitude", "mavros_msgs/AttitudeTarget"), "Flight"),
        (Topic("/mavros/setpoint_raw/local", "mavros_msgs/PositionTarget"), "Waypoint"),
        (Topic("/action/pose/goal", "hector_uav_msgs/PoseActionGoal"), "Waypoint"),
        (
            Topic(
                "/navigate_to_pose/_action/feedback",
                "nav2_msgs/NavigateToPose_FeedbackMessage",
                "published",
            ),
            "Waypoint",
        ),
        (Topic("/follow_waypoints/_action/status", "action_msgs/GoalStatusArray"), "Waypoint"),
        (
            Topic("/move_group/feedback", "moveit_msgs/MoveGroup_FeedbackMessage", "published"),
            "End Effector",
        ),
        (Topic("/servo_node/delta_joint_cmds", "control_msgs/JointJog"), "Joint"),
        (Topic("/cmd_pose", "geometry_msgs/Pose2D"), "Walking"),
    ],
)
def test_commands_map_to_motion_controls(topic: Topic, control: str) -> None:
    assert controls("UGV", topic) == [control]


def test_a_command_the_robot_publishes_is_not_its_control() -> None:
    assert controls("UGV", Topic("/cmd_vel", "geometry_msgs/Twist", "published")) == []


def test_a_control_lists_the_topics_that_show_it() -> None:
    found = controls_from_topics(
        [
            Topic("/cmd_vel", "geometry_msgs/Twist"),
            Topic("/joy_teleop/cmd_vel", "geometry_msgs/Twist"),
        ],
        PROFILE,
        "UGV",
        "topics.txt",
    )
    assert found[0].source == (
        "topics.txt: /cmd_vel (geometry_msgs/Twist), /joy_teleop/cmd_vel (geometry_msgs/Twist)"
    )


def test_a_topic_name_and_its_type_are_each_cut_on_their_own() -> None:
    long_name = "/" + "n" * 91 + "/cmd_vel"
    [nav, long] = controls_from_topics(
        [
            Topic("/navigate_to_pose/_action/status", "action_msgs/GoalStatusArray"),
            Topic(long_name, "geometry_msgs/Twist"),
        ],
        PROFILE,
        "UGV",
        "t",
    )
    # 62 characters together: neither part is past the cut.
    assert nav.source == "t: /navigate_to_pose/_action/status (action_msgs/GoalStatusArray)"
    assert long.source == (
        f"t: {long_name[:60]}... (cut from 100 characters) (geometry_msgs/Twist)"
    )
