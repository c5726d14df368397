"""Sensors on frames a description only draws, that a driver of the robot's packages
publishes in."""

from __future__ import annotations

from solver.identify import load_profile
from solver.identify.frames import named_frames, sensors_on_frames
from solver.identify.identification import identify_urdf
from solver.identify.readers.urdf import parse_urdf
from solver.identify.readers.workspace import ShippedFile, Workspace
from solver.identify.sensors import sensors_from_urdf

PROFILE = load_profile()


def fixed(parent: str, child: str) -> str:
    return (
        f'<link name="{child}"/><joint name="{child}_joint" type="fixed">'
        f'<parent link="{parent}"/><child link="{child}"/></joint>'
    )


# A rover drawn for its TF tree: an IMU, a GPS and an RGB-D camera's frames, and a lidar with
# a simulated <sensor> of its own.
ROVER = (
    '<robot name="rover"><link name="base_link"/>'
    + fixed("base_link", "imu_link")
    + fixed("base_link", "gps_link")
    + fixed("base_link", "camera_link")
    + fixed("camera_link", "camera_color_frame")
    + fixed("camera_color_frame", "camera_color_optical_frame")
    + fixed("camera_link", "camera_depth_frame")
    + fixed("camera_depth_frame", "camera_depth_optical_frame")
    + fixed("base_link", "laser")
    + '<gazebo reference="laser"><sensor type="ray" name="scan"><ray><scan><horizontal>'
    "<samples>720</samples></horizontal></scan></ray></sensor></gazebo></robot>"
)


def shipping(**texts: str) -> Workspace:
    files = tuple(ShippedFile("rover_bringup", path, text) for path, text in texts.items())
    return Workspace("/ws/src", "rover_description", ("rover_bringup",), files)


DRIVERS = shipping(
    imu_launch='<node pkg="imu_driver"><param name="frame_id" value="imu_link"/></node>',
    camera_yaml="camera:\n  color_frame_id: camera_color_optical_frame\n"
    "  depth_frame_id: /camera_depth_optical_frame\n",
    lidar_yaml="frame_id: laser\nodom_frame: odom\nbase_frame: base_link\n",
)


def kinds(packages: Workspace | None, text: str = ROVER) -> dict[str, int]:
    found = identify_urdf(text, file="rover.urdf", profile=PROFILE, packages=packages)
    return {sensor.kind: sensor.count for sensor in found.sensors}


def test_a_frame_a_driver_publishes_in_is_a_sensor_told_by_its_name() -> None:
    assert kinds(DRIVERS) == {"lidar": 1, "imu": 1, "depth_camera": 1}


def test_without_the_packages_a_bare_frame_is_no_sensor() -> None:
    assert kinds(None) == {"lidar": 1}


def test_a_frame_no_driver_names_is_no_sensor() -> None:
    # gps_link is drawn, and nothing publishes in it.
    assert "gps" not in kinds(DRIVERS)


def test_every_way_a_frame_id_is_written_is_read() -> None:
    urdf = parse_urdf(ROVER, "rover.urdf")
    written = {
        "a": 'self.declare_parameter("frame_id", "imu_link")',
        "b": "msg.header.frame_id = 'gps_link'",
        "c": "<arg name='x'/><param name='camera_frame' value='camera_link' />",
        "d": 'Node(parameters=[{"frame_id": "laser"}])',
        "e": "ros2 run driver node --ros-args -p frame_id:=base_link",
    }
    assert set(named_frames(shipping(**written), urdf)) == {
        "imu_link",
        "gps_link",
        "camera_link",
        "laser",
        "base_link",
    }


def test_the_streams_of_one_camera_are_one_rgbd_camera() -> None:
    urdf = parse_urdf(ROVER, "rover.urdf")
    found = sensors_on_frames(DRIVERS, urdf, PROFILE, ())
    cameras = [d for d in found if "camera" in d.kind]
    assert [(d.kind, d.link) for d in cameras] == [("depth_camera", "camera_link")]


def test_the_descriptions_own_sensor_wins() -> None:
    # The lidar's frame is named by its driver: the declared lidar, not a second one.
    urdf = parse_urdf(ROVER, "rover.urdf")
    found = sensors_on_frames(DRIVERS, urdf, PROFILE, sensors_from_urdf(urdf, PROFILE))
    assert sorted(d.kind for d in found) == ["depth_camera", "imu"]
    # An IMU the description declares with no link (a model plugin) is the IMU.
    with_imu = ROVER.replace(
        "</robot>",
        '<gazebo><plugin name="imu" filename="libhector_gazebo_ros_imu.so"/></gazebo></robot>',
    )
    assert kinds(DRIVERS, with_imu)["imu"] == 1


def test_the_evidence_names_the_frame_and_the_file() -> None:
    found = identify_urdf(ROVER, file="rover.urdf", profile=PROFILE, packages=DRIVERS)
    imu = next(sensor for sensor in found.sensors if sensor.kind == "imu")
    assert imu.source == "packages: imu_link (frame id in imu_launch)"


def test_a_device_the_description_declares_a_sensor_on_gets_no_second_one() -> None:
    # A colour camera declared on camera_link: its depth frame is that device's stream.
    declared = ROVER.replace(
        "</robot>",
        '<gazebo reference="camera_link"><sensor type="camera" name="rgb"/></gazebo></robot>',
    )
    assert kinds(DRIVERS, declared) == {"lidar": 1, "camera": 1, "imu": 1}


def test_a_kind_the_description_declares_keeps_the_descriptions_count() -> None:
    two_more = shipping(cams_yaml="front:\n  frame_id: front_cam\nrear:\n  frame_id: rear_cam\n")
    drawn = ROVER.replace(
        "</robot>", fixed("base_link", "front_cam") + fixed("base_link", "rear_cam") + "</robot>"
    )
    declared = drawn.replace(
        "</robot>",
        '<gazebo reference="camera_link"><sensor type="camera" name="rgb"/></gazebo></robot>',
    )
    assert kinds(two_more, declared)["camera"] == 1
    assert kinds(two_more, drawn)["camera"] == 2  # no camera declared: the drivers' two


# Two RGB-D cameras a driver names (realsense2_camera, orbbec_camera build their frames from
# camera_name): one drawn as camera_front and its streams, one as camera_top_base_link.
CAMERAS = (
    '<robot name="base"><link name="base_link"/>'
    + fixed("base_link", "camera_front")
    + fixed("camera_front", "camera_front_mount")
    + fixed("camera_front_mount", "camera_front_color_frame")
    + fixed("camera_front_mount", "camera_front_depth_frame")
    + fixed("base_link", "camera_top_base_link")
    + fixed("camera_top_base_link", "camera_top_depth_optical_frame")
    + "</robot>"
)


def test_a_camera_driver_named_publishes_in_the_frames_it_builds_from_its_name() -> None:
    bringup = shipping(
        bringup_py='Node(package="orbbec_camera", parameters=[{"camera_name": "camera_front"}])',
        top_launch='<arg name="camera_name" value="camera_top"/>',
    )
    urdf = parse_urdf(CAMERAS, "base.urdf")
    assert named_frames(bringup, urdf) == {
        "camera_front": "bringup_py",
        "camera_top_base_link": "top_launch",
    }
    # A depth stream's frame beneath the named one says the camera is an RGB-D camera.
    assert kinds(bringup, CAMERAS) == {"depth_camera": 2}
