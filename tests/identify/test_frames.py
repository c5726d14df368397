"""Sensors on frames a description only draws, that a driver of the robot's packages
publishes in."""

from __future__ import annotations

import pytest

from solver.identify import load_profile
from solver.identify.frames import _Naming, named_frames, sensors_on_frames
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


def drawn(*frames: tuple[str, str]) -> str:
    """A robot drawn as frames only: each (parent, child) a fixed joint, from ``base_link``."""
    joints = "".join(fixed(parent, child) for parent, child in frames)
    return f'<robot name="r"><link name="base_link"/>{joints}</robot>'


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


def test_every_way_a_driver_is_given_its_frame_id_is_read() -> None:
    urdf = parse_urdf(ROVER.replace("</robot>", fixed("base_link", "r1/imu") + "</robot>"), "r")
    written = {
        "a": 'self.declare_parameter("frame_id", "imu_link")',
        "b": "msg.header.frame_id = 'gps_link'",
        "c": "<param name='camera_frame' type='string' value='camera_link' />",
        "d": 'Node(parameters=[{"frame_id": "laser"}])',
        "e": "ros2 run driver node --ros-args -p frame_id:=base_link",
        "f": '<arg name="imu_frame" default="$(arg ns)/r1/imu"/>',
    }
    assert named_frames(shipping(**written), urdf, PROFILE) == {
        "imu_link": "frame id in a",
        "gps_link": "frame id in b",
        "camera_link": "frame id in c",
        "laser": "frame id in d",
        "base_link": "frame id in e",
        "r1/imu": "frame id in f",
    }


def test_a_frame_id_a_node_joins_to_its_prefix_names_the_frame() -> None:
    """roscpp's ``tf::resolve(tf_prefix_, "x")`` and a namespace added before the quoted
    frame id (``prefix + "/x"``) give the frame ``x``; a variable alone names none."""
    urdf = parse_urdf(ROVER, "r")
    written = {
        "a": 'range.header.frame_id = tf::resolve(tf_prefix_, "imu_link");',
        "b": 'fix.header.frame_id = tf_prefix_ + "/gps_link";',
        "c": "self.frame_id = self.namespace + 'laser'",
        "d": 'camera.frame_id = os.path.join(ns, "camera_link")',
    }
    assert named_frames(shipping(**written), urdf, PROFILE) == {
        "imu_link": "frame id in a",
        "gps_link": "frame id in b",
        "laser": "frame id in c",
        "camera_link": "frame id in d",
    }


@pytest.mark.parametrize(
    "text",
    [
        'frame = cv2.putText(frame, "laser offline", (10, 30), font, 1, color)',
        'frame_id = tf_buffer.lookup_transform(target, "imu_link", now)',
        'if not frame_id: print(node_name, "gps_link frame_id not set")',
        'if frame_id == prefix + "laser": pass',
    ],
)
def test_a_quoted_name_in_another_call_or_a_test_names_no_frame(text: str) -> None:
    """Only a call that resolves or joins a name, or a prefix added, after an assignment: a
    text drawn on an image, a transform looked up, a log line, a comparison name none."""
    assert named_frames(shipping(node_py=text), parse_urdf(ROVER, "r"), PROFILE) == {}


# A cleaning robot drawn as frames: four cliff sensors, two light-bumper IR sensors, two
# bumper switches, and its driver's lists of their frames.
CLEANER = drawn(
    *[("base_link", f"{side}_cliff_sensor_link") for side in ("left", "front_left", "right")],
    *[("base_link", f"{side}_ir_sensor_link") for side in ("left", "right")],
    *[("base_link", f"{side}_bumper_link") for side in ("left", "right")],
)


@pytest.mark.parametrize(
    "driver",
    [
        'std::string cliff_frame_id[3] = {"left_cliff_sensor_link", "front_left_cliff_sensor_link",'
        ' "right_cliff_sensor_link"};\n'
        'std::string ir_bumper_frame_id[2] = {"left_ir_sensor_link", "right_ir_sensor_link"};\n'
        'std::string bumper_frame_id[2] = {"left_bumper_link", "right_bumper_link"};',
        "cliff_frame_ids: [left_cliff_sensor_link, front_left_cliff_sensor_link, "
        "/right_cliff_sensor_link]\nir_frame_ids: ['left_ir_sensor_link', 'right_ir_sensor_link']\n"
        "bumper_frame_ids: [left_bumper_link, right_bumper_link]",
    ],
)
def test_a_list_of_frame_ids_a_driver_is_given_names_a_device_each(driver: str) -> None:
    assert kinds(shipping(driver_cpp=driver), CLEANER) == {"ir_range": 5, "contact": 2}
    # Without the driver's lists, bare frames are no sensors; nor with a list of the frames a
    # node looks transforms up in.
    assert kinds(shipping(driver_cpp="int cliff_count = 3;"), CLEANER) == {}
    for looked_up in (
        "target_frame_ids: [left_bumper_link, right_bumper_link]",
        "source_frame_ids: [left_cliff_sensor_link]",
        "ignore_frame_ids: [left_bumper_link]",
        "self.frame_ids = ['base_link', 'left_cliff_sensor_link', 'left_bumper_link']",
        "keyframe_ids: [left_bumper_link]",
    ):
        assert kinds(shipping(listener_yaml=looked_up), CLEANER) == {}, looked_up


def test_a_cars_front_or_rear_bumper_is_part_of_its_body_no_switch() -> None:
    car = drawn(("base_link", "front_bumper_link"), ("base_link", "left_bumper"))
    named = shipping(radar_yaml="frame_id: front_bumper_link", bumper_yaml="frame_id: left_bumper")
    assert kinds(named, car) == {"contact": 1}


def test_a_link_written_under_a_namespace_of_its_own_is_named_by_its_last_segment() -> None:
    # The description's xacro wrote its prefix (rc_1/), the driver's launch a variable of its
    # own ($(var rc)/): the one link ending so is the frame.
    urdf = parse_urdf(drawn(("base_link", "rc_1/front_lidar"), ("base_link", "rc_1/imu")), "r")
    drivers = shipping(lidar_yaml='laser_frame_id: "$(var rc)/front_lidar"\n')
    assert named_frames(drivers, urdf, PROFILE) == {"rc_1/front_lidar": "frame id in lidar_yaml"}


def test_a_last_segment_two_namespaced_links_share_names_neither() -> None:
    urdf = parse_urdf(drawn(("base_link", "a/front_lidar"), ("base_link", "b/front_lidar")), "r")
    drivers = shipping(lidar_yaml='laser_frame_id: "$(var rc)/front_lidar"\n')
    assert named_frames(drivers, urdf, PROFILE) == {}


@pytest.mark.parametrize(
    "default",
    [
        "self.frame_id = rospy.get_param('~frame_id', 'imu_link')",
        "frame_id = LaunchConfiguration('frame_id', default='imu_link')",
        "DeclareLaunchArgument('imu_frame', default_value='/imu_link')",
        'private_nh.param("frame_id", frame_id_, std::string("imu_link"));',
        'nh.param<std::string>("imu_frame_id", frame, "imu_link");',
    ],
)
def test_a_parameters_default_frame_id_is_read(default: str) -> None:
    urdf = parse_urdf(ROVER, "rover.urdf")
    assert named_frames(shipping(node=default), urdf, PROFILE) == {"imu_link": "frame id in node"}


def test_a_default_given_to_another_key_or_outside_a_param_call_names_no_frame() -> None:
    urdf = parse_urdf(ROVER, "rover.urdf")
    others = shipping(
        node='nh.param("odom_frame", odom_frame_, std::string("imu_link"));\n'
        "self.declare_parameter('frame_id', frame)\nget_param('~topic', 'imu_link')\n"
        "ROS_INFO(\"frame_id\", frame, \"imu_link\");\nprint('frame_id', frame_id, 'imu_link')\n"
    )
    assert named_frames(others, urdf, PROFILE) == {}


def test_a_frame_a_node_only_looks_up_is_no_drivers() -> None:
    urdf = parse_urdf(ROVER, "rover.urdf")
    consumers = shipping(
        nav_yaml="target_frame: camera_link\nrobot_base_frame: laser\n",
        node_py='tf.lookup_transform(target_frame, "imu_link", now)',
        ns_yaml="frame_id: robot2/gps_link\n",  # another robot's: its last segment is read
    )
    assert named_frames(consumers, urdf, PROFILE) == {"gps_link": "frame id in ns_yaml"}


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
    assert named_frames(bringup, urdf, PROFILE) == {
        "camera_front": "camera name in bringup_py",
        "camera_top_base_link": "camera name in top_launch",
    }
    # A depth stream's frame beneath the named one says the camera is an RGB-D camera.
    assert kinds(bringup, CAMERAS) == {"depth_camera": 2}


# A car drawn for its TF tree: one camera_link, nothing beneath it.
CAR = drawn(("base_link", "camera_link"))


def frames_and_kinds(packages: Workspace, text: str) -> tuple[dict[str, str], dict[str, int]]:
    """The frames ``packages`` name in the robot ``text``, and the sensors read from them."""
    return named_frames(packages, parse_urdf(text, "r.urdf"), PROFILE), kinds(packages, text)


# A depth camera's driver launched in a file, the robot drawn, and the frame it names there (how).
DEPTH_DRIVERS = [
    pytest.param(
        '<include file="$(find-pkg-share realsense2_camera)/launch/rs_launch.py">'
        '<arg name="enable_gyro" value="true"/></include>',
        CAR,
        ("camera_link", "default camera name in launch"),
        id="given-no-name-its-default-camera",
    ),
    pytest.param(
        # The RealSense is d435_link; camera_link is another camera nothing here names.
        '<include file="$(find realsense2_camera)/launch/rs_camera.launch">'
        '<arg name="camera" value="d435"/></include>',
        drawn(("base_link", "camera_link"), ("base_link", "d435_link")),
        ("d435_link", "camera name in launch"),
        id="ros1-camera-argument",
    ),
    pytest.param(
        'share = get_package_share_directory("depthai_ros_driver")\n'
        'launch_arguments={"name": name, "parent_frame": "3d_camera_link"}',
        drawn(("base_link", "3d_camera_link")),
        ("3d_camera_link", "parent frame in launch"),
        id="depthai-parent-frame",
    ),
    pytest.param(
        '<node pkg="depthai_ros_driver" exec="camera_node"/>',
        drawn(("base_link", "oak")),
        ("oak", "default camera name in launch"),
        id="depthai-default-oak",
    ),
]


@pytest.mark.parametrize(("launch", "robot", "named"), DEPTH_DRIVERS)
def test_a_depth_camera_driver_launched_names_a_depth_camera(
    launch: str, robot: str, named: tuple[str, str]
) -> None:
    # Its driver says what the frame's name may not: a depth camera.
    assert frames_and_kinds(shipping(launch=launch), robot) == (
        dict([named]),
        {"depth_camera": 1},
    )


def test_the_depth_camera_is_told_whichever_file_names_its_frame_first() -> None:
    both = shipping(
        a_yaml="frame_id: camera_link\n",
        b_py='Node(package="orbbec_camera", parameters=[{"enable_depth": True}])',
    )
    assert kinds(both, CAR) == {"depth_camera": 1}


def test_a_depth_camera_driver_mentioned_but_not_launched_names_no_camera() -> None:
    for text in (
        "# realsense2_camera parameters, unused on this robot\n",
        "colcon build --packages-skip realsense2_camera\n",
    ):
        assert kinds(shipping(notes_yaml=text), CAR) == {}


def test_a_camera_another_driver_names_is_the_camera_its_frame_says() -> None:
    usb = shipping(cam_launch='<node pkg="usb_cam"><param name="camera_name" value="camera"/>')
    assert kinds(usb, CAR) == {"camera": 1}
    # Beside a depth camera's driver in one file, a name given is no sign of which driver
    # takes it: the camera is the one its frame says.
    beside = shipping(
        cams_launch='<include file="$(find realsense2_camera)/launch/rs_camera.launch"/>'
        '<node pkg="usb_cam"><param name="camera_name" value="camera"/></node>'
    )
    assert kinds(beside, CAR) == {"camera": 1}


@pytest.mark.parametrize(
    "launch",
    [
        '<node pkg="usb_cam" type="usb_cam_node"/>',
        '<node type="raspicam_node" pkg="raspicam_node">'
        '<param name="camera_frame_id" value="raspicam"/></node>',
        "Node(package='camera_ros', executable='camera_node', name='webcam_node')",
        "ros2 run v4l2_camera v4l2_camera_node",
    ],
)
def test_a_camera_driver_launched_naming_no_link_names_the_descriptions_one_camera(
    launch: str,
) -> None:
    # The driver publishes in a frame id of its own (`raspicam`): the camera it runs is the one
    # the description draws, its body with its optical frame beneath it.
    car = drawn(("base_link", "cam_link"), ("cam_link", "cam_optical_frame"))
    assert frames_and_kinds(shipping(launch=launch), car) == (
        {"cam_link": "camera driver launched in launch"},
        {"camera": 1},
    )
    # Of two cameras it says nothing of which; a mention launches nothing.
    two = drawn(("base_link", "front_camera_link"), ("base_link", "rear_camera_link"))
    assert kinds(shipping(launch=launch), two) == {}
    assert kinds(shipping(notes_yaml="# usb_cam and camera_ros are not used\n"), car) == {}


@pytest.mark.parametrize(
    "launch",
    [
        "Node(package='bno055', executable='bno055', parameters=[params])",
        '<node pkg="openzen_sensor" type="openzen_sensor_node" name="imu"/>',
        '<include file="$(find xsens_mti_driver)/launch/xsens_mti_node.launch"/>',
    ],
)
def test_an_imu_driver_launched_naming_no_link_names_the_descriptions_one_imu(launch: str) -> None:
    body = drawn(("base_link", "imu_link"), ("base_link", "laser"))
    assert frames_and_kinds(shipping(launch=launch), body) == (
        {"imu_link": "IMU driver launched in launch"},
        {"imu": 1},
    )
    # Of two IMUs it says nothing of which.
    two = drawn(("base_link", "imu_front"), ("base_link", "imu_back"))
    assert kinds(shipping(launch=launch), two) == {}


def test_a_driver_naming_no_link_leaves_a_camera_another_file_names_as_that_file_says() -> None:
    # A webcam named by its optical frame, and a RealSense launched whose frames the
    # description does not draw: the drawn camera stays the webcam.
    car = drawn(("base_link", "front_camera_link"), ("front_camera_link", "front_camera_optical"))
    files = shipping(
        usb_launch='<node pkg="usb_cam"><param name="frame_id" value="front_camera_optical"/>',
        rs_launch='<include file="$(find realsense2_camera)/launch/rs_camera.launch"/>',
    )
    assert kinds(files, car) == {"camera": 1}
    # A camera whose name says thermal is no depth camera's.
    thermal = drawn(("base_link", "thermal_camera_link"))
    assert kinds(shipping(rs_launch=files.files[1].text), thermal) == {}


def test_a_pan_tilt_cameras_links_are_its_one_camera() -> None:
    # camera_pan_link -> camera_tilt_link -> camera_link: one camera, the run's topmost link.
    head = (
        '<robot name="r"><link name="base_link"/>'
        + "".join(
            f'<link name="{child}"/><joint name="{child}_j" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/><axis xyz="0 0 1"/>'
            '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            for parent, child, kind in (
                ("base_link", "camera_pan_link", "revolute"),
                ("camera_pan_link", "camera_tilt_link", "revolute"),
                ("camera_tilt_link", "camera_link", "fixed"),
            )
        )
        + "</robot>"
    )
    launched = shipping(launch='<node pkg="usb_cam" type="usb_cam_node"/>')
    assert frames_and_kinds(launched, head) == (
        {"camera_pan_link": "camera driver launched in launch"},
        {"camera": 1},
    )


def test_a_depth_camera_driver_whose_default_name_is_no_link_names_the_one_camera() -> None:
    # openni_launch's camera is `camera`, kinect2_bridge's `kinect2`: the description calls its
    # one Kinect `kinect`, with its depth frame beneath.
    kinect = drawn(("base_link", "kinect"), ("kinect", "kinect_depth_frame"))
    for launch in (
        '<include file="$(find openni_launch)/launch/openni.launch"/>',
        '<include file="$(find kinect2_bridge)/launch/kinect2_bridge.launch"/>',
    ):
        assert frames_and_kinds(shipping(launch=launch), kinect) == (
            {"kinect": "depth camera driver launched in launch"},
            {"depth_camera": 1},
        )


def test_an_infrared_range_frame_a_driver_publishes_in_is_an_ir_range_sensor() -> None:
    base = drawn(
        ("base_link", "ir_front_left_link"),
        ("base_link", "ir_front_right_link"),
        ("base_link", "camera_link"),
        ("camera_link", "camera_ir_frame"),
    )
    broadcasters = shipping(
        controllers_yaml="left:\n  ros__parameters:\n    frame_id: ir_front_left_link\n"
        "right:\n  ros__parameters:\n    frame_id: ir_front_right_link\n"
        "depth:\n  ros__parameters:\n    frame_id: camera_ir_frame\n"
    )
    # The camera's infrared stream is the camera's.
    assert kinds(broadcasters, base) == {"ir_range": 2, "camera": 1}


def test_an_ultrasound_frame_a_driver_publishes_in_is_a_sonar() -> None:
    base = drawn(("base_link", "ultrasound_front"), ("base_link", "ultrasonic_rear"))
    named = shipping(
        driver_cc='range.header.frame_id = "ultrasound_front";\n'
        'range.header.frame_id = "ultrasonic_rear";\n'
    )
    assert kinds(named, base) == {"sonar": 2}


def test_a_time_of_flight_rangers_frame_a_driver_publishes_in_is_an_ir_range_sensor() -> None:
    frames = ("vl53l0x_0", "tof_rear", "time_of_flight_left", "toffee")
    base = drawn(*(("base_link", frame) for frame in frames))
    named = shipping(driver_cc="".join(f'msg.header.frame_id = "{f}";\n' for f in frames))
    assert kinds(named, base) == {"ir_range": 3}


def test_a_time_of_flight_cameras_depth_frame_is_a_depth_camera() -> None:
    base = drawn(("base_link", "tof_depth_frame"))
    named = shipping(driver_yaml="frame_id: tof_depth_frame\n")
    assert kinds(named, base) == {"depth_camera": 1}


def test_a_frame_whose_name_holds_ir_inside_a_word_is_no_ir_range_sensor() -> None:
    base = drawn(("base_link", "air_speed_link"), ("base_link", "flir_link"))
    named = shipping(drivers_yaml="frame_id: air_speed_link\nframe_id: flir_link\n")
    assert "ir_range" not in kinds(named, base)


def test_a_camera_name_is_its_link_or_name_link_before_any_link_it_begins() -> None:
    urdf = parse_urdf(
        '<robot name="r"><link name="base_link"/>'
        + fixed("base_link", "front_imu_link")
        + fixed("base_link", "front_camera_optical")
        + fixed("base_link", "side_link")
        + fixed("base_link", "side_camera_frame")
        + "</robot>",
        "r.urdf",
    )
    named = shipping(launch_py='{"camera_name": "front"}, {"camera_name": "side"}')
    # `front` is no link: the first of its links that is a camera's, not its IMU's; `side`
    # is drawn as side_link.
    assert set(named_frames(named, urdf, PROFILE)) == {"front_camera_optical", "side_link"}


def test_an_imu_inside_a_camera_is_an_imu_beside_the_camera() -> None:
    """A D435i: its IMU frame hangs from the camera's body; both are devices."""
    d435i = drawn(
        ("base_link", "camera_link"),
        ("camera_link", "camera_depth_optical_frame"),
        ("camera_link", "camera_imu_optical_frame"),
    )
    driver = shipping(
        rs_launch='{"camera_name": "camera"}, {"imu_frame_id": "camera_imu_optical_frame"}'
    )
    assert kinds(driver, d435i) == {"depth_camera": 1, "imu": 1}


def test_a_stereo_depth_camera_named_for_its_maker_is_an_rgbd_camera() -> None:
    """Luxonis' OAK-D cameras frame their streams oak_rgb_camera_frame, oakd_left_...,
    oak-d-base-frame (its driver's default): a maker's name, as a RealSense's is."""
    oaks = (
        '<robot name="r"><link name="base_link"/>'
        + fixed("base_link", "oak0_rgb_camera_frame")
        + fixed("base_link", "oakd_link")
        + fixed("base_link", "oak-d-base-frame")
        + fixed("base_link", "cloak_camera_frame")
        + "</robot>"
    )
    driver = shipping(
        front_yaml="frame_id: oak0_rgb_camera_frame\n",
        rear_yaml="frame_id: oakd_link\n",
        mast_yaml="frame_id: oak-d-base-frame\n",
        hood_yaml="frame_id: cloak_camera_frame\n",
    )
    assert kinds(driver, oaks) == {"depth_camera": 3, "camera": 1}


def test_at_most_64_camera_names_are_looked_up() -> None:
    urdf = parse_urdf(CAMERAS, "base.urdf")
    many = "".join(f'{{"camera_name": "nothing_{n}"}}\n' for n in range(64))
    late = shipping(names_py=many + '{"camera_name": "camera_front"}')
    assert named_frames(late, urdf, PROFILE) == {}
    assert named_frames(shipping(names_py=many[:-1]), urdf, PROFILE) == {}


def test_only_a_cameras_body_is_named_by_the_camera_frames_beneath_it() -> None:
    # A compass module carrying a camera: the compass is named by its own frame.
    mast = (
        '<robot name="r"><link name="base_link"/>'
        + fixed("base_link", "compass_link")
        + fixed("compass_link", "camera_link")
        + "</robot>"
    )
    assert kinds(shipping(mag_yaml="frame_id: compass_link\n"), mast) == {"magnetometer": 1}


def test_a_frame_named_for_a_sonar_model_is_a_sonar() -> None:
    # A Ping360 or a BlueView imaging sonar's frame says its model, not "sonar".
    vehicle = (
        '<robot name="auv"><link name="base_link"/>'
        + fixed("base_link", "ping360_link")
        + fixed("base_link", "blueview")
        + "</robot>"
    )
    drivers = shipping(
        ping_yaml="ping360_node:\n  frame_id: auv/ping360_link\n",
        blueview_launch="<rosparam>frame_id: blueview</rosparam>",
    )
    assert kinds(drivers, vehicle) == {"sonar": 2}


def sonar_ring(names: list[str]) -> str:
    """A base with a sonar frame per name, each 0.2 m farther along x."""
    frames = "".join(placed("base_link", name, 0.2 * i) for i, name in enumerate(names))
    return f'<robot name="r"><link name="base_link"/>{frames}</robot>'


def test_a_frame_id_no_link_has_names_the_numbered_links_it_begins_a_device_each() -> None:
    ring = sonar_ring([f"ultrasonic_link_{i}" for i in range(4)])
    driver = shipping(kit_yaml="ultrasonic_sensor_node:\n  frame_id: ultrasonic_link\n")
    assert kinds(driver, ring) == {"sonar": 4}
    assert kinds(driver, sonar_ring(["ultrasonic_link_0", "ultrasonic_link"])) == {"sonar": 1}
    # A link of the frame id's own name is the one it names, numbered links beside it or not.
    both = sonar_ring(["ultrasonic_link", "ultrasonic_link_0", "ultrasonic_link_1"])
    assert kinds(driver, both) == {"sonar": 1}
    # One numbered link is no series: the frame id names nothing.
    assert kinds(driver, sonar_ring(["ultrasonic_link_0"])) == {}
    # The number may follow the name with no separator (`sonar1`, `sonar2`).
    plain = shipping(kit_yaml="frame_id: sonar\n")
    assert kinds(plain, sonar_ring(["sonar1", "sonar2"])) == {"sonar": 2}


def test_a_numbered_series_is_named_once_however_often_the_files_give_it() -> None:
    # A stranger's file may give one frame id a million times: the series is walked once.
    naming = _Naming(parse_urdf(sonar_ring(["s_0", "s_1", "s_2"]), "r.urdf"), PROFILE)
    assert naming.numbered("s_") == ["s_0", "s_1", "s_2"]
    assert naming.numbered("s_") == []


@pytest.mark.parametrize(
    "code",
    [
        'sprintf(buffer, "sonar%d_link", i);',
        'frame = "sonar%02d_link" % i',
        'frame = f"sonar{i}_link"',
        'frame = "sonar{}_link".format(i)',
    ],
)
def test_a_frame_name_made_from_a_numbered_template_names_each_link_it_makes(code: str) -> None:
    ring = sonar_ring(["sonar0_link", "sonar1_link", "sonar2_link", "bumper_link"])
    assert kinds(shipping(driver_cpp=code), ring) == {"sonar": 3}
    # A template no two links fit names none.
    assert kinds(shipping(driver_cpp=code.replace("_link", "_frame")), ring) == {}


def placed(parent: str, child: str, x: float) -> str:
    return (
        f'<link name="{child}"/><joint name="{child}_joint" type="fixed">'
        f'<parent link="{parent}"/><child link="{child}"/><origin xyz="{x} 0 0"/></joint>'
    )


def lasers_at(*places: float, declared: str = "") -> str:
    """Lasers hung from one scan link at ``places`` along x (``base_scan_0`` ...)."""
    return (
        '<robot name="r"><link name="base_link"/>'
        + fixed("base_link", "base_scan")
        + "".join(placed("base_scan", f"base_scan_{i}", x) for i, x in enumerate(places))
        + declared
        + "</robot>"
    )


def drivers_of(count: int) -> Workspace:
    """One driver configuration per laser, each given its own frame."""
    return shipping(
        **{f"laser_{i}_yaml": f'lidar:\n  frame_id: "base_scan_{i}"\n' for i in range(count)}
    )


def test_two_lasers_a_driver_each_publishes_in_apart_on_one_link_are_two_lidars() -> None:
    text = lasers_at(0.15, -0.15)
    assert kinds(drivers_of(2), text) == {"lidar": 2}
    found = sensors_on_frames(drivers_of(2), parse_urdf(text, "r.urdf"), PROFILE, ())
    assert sorted(str(d.link) for d in found) == ["base_scan_0", "base_scan_1"]


def test_two_frames_of_one_body_close_together_are_one_device() -> None:
    # A lidar's mount frame and its scan frame, 5 cm apart, or 10 cm: one laser.
    assert kinds(drivers_of(2), lasers_at(0.15, 0.10)) == {"lidar": 1}
    assert kinds(drivers_of(2), lasers_at(0.2, 0.1)) == {"lidar": 1}


def test_a_cameras_streams_far_apart_are_still_one_camera() -> None:
    """A stereo pair's colour and depth frames, 12 cm apart on one camera body."""
    camera = (
        '<robot name="r"><link name="base_link"/>'
        + fixed("base_link", "camera_link")
        + placed("camera_link", "camera_color_frame", 0.06)
        + placed("camera_link", "camera_depth_frame", -0.06)
        + "</robot>"
    )
    driver = shipping(
        color_yaml="color_frame_id: camera_color_frame\ndepth_frame_id: camera_depth_frame\n"
    )
    assert kinds(driver, camera) == {"depth_camera": 1}


def test_one_cameras_frames_named_at_two_depths_of_a_deep_mount_are_one_camera() -> None:
    """A RealSense on a gripper: its depth frame and optical frame hang three and four joints
    below the gripper's camera link, and a script names both: one camera, not two."""
    camera = drawn(
        ("base_link", "gripper_camera_link"),
        ("gripper_camera_link", "camera_bottom_screw_frame"),
        ("camera_bottom_screw_frame", "camera_link"),
        ("camera_link", "camera_depth_frame"),
        ("camera_depth_frame", "camera_depth_optical_frame"),
    )
    scripts = shipping(
        calibrate_py='pose.header.frame_id = "camera_depth_optical_frame"\n',
        pick_py='cloud.header.frame_id = "camera_depth_frame"\n',
    )
    assert kinds(scripts, camera) == {"depth_camera": 1}


def test_two_cameras_under_one_mount_named_like_a_camera_stay_two_cameras() -> None:
    """Two RealSense trees hung from one ``camera_mount``: a script names a frame of each, deep
    in its own tree; neither frame is above the other, so they are two cameras."""
    trees = [("base_link", "camera_mount")]
    for side in ("front", "rear"):
        trees += [
            ("camera_mount", f"{side}_camera_bottom_screw_frame"),
            (f"{side}_camera_bottom_screw_frame", f"{side}_camera_link"),
            (f"{side}_camera_link", f"{side}_camera_depth_frame"),
            (f"{side}_camera_depth_frame", f"{side}_camera_depth_optical_frame"),
            (f"{side}_camera_link", f"{side}_camera_color_frame"),
            (f"{side}_camera_color_frame", f"{side}_camera_color_optical_frame"),
        ]
    scripts = shipping(
        front_py='cloud.header.frame_id = "front_camera_depth_optical_frame"\n',
        rear_py='image.header.frame_id = "rear_camera_color_optical_frame"\n',
    )
    assert sum(kinds(scripts, drawn(*trees)).values()) == 2


def test_one_bodys_frames_are_told_apart_at_eight_places_at_most() -> None:
    eight = [float(i) for i in range(8)]
    assert kinds(drivers_of(8), lasers_at(*eight)) == {"lidar": 8}
    # A ninth place: the body's frames are one device again, each compared with eight at most.
    assert kinds(drivers_of(9), lasers_at(*eight, 8.0)) == {"lidar": 1}


def test_lasers_on_a_body_the_description_declares_a_sensor_on_add_nothing() -> None:
    imu = '<gazebo reference="base_scan"><sensor type="imu" name="imu"/></gazebo>'
    assert kinds(drivers_of(2), lasers_at(0.15, -0.15, declared=imu)) == {"imu": 1}
