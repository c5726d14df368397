"""Sensors from <sensor> elements and plugins, mapped to the rule set's sensor types."""

from __future__ import annotations

import pytest

from solver.files.yamlio import parse_document
from solver.identify import identify_urdf, load_profile
from solver.identify.profile import parse_profile
from solver.identify.readers.urdf import parse_urdf
from solver.identify.sensors import sensors_from_urdf
from tests.conftest import RULES
from tests.identify import builders

RAY = (
    "<ray><scan><horizontal><samples>{h}</samples></horizontal>"
    "<vertical><samples>{v}</samples></vertical></scan></ray>"
)


def kinds(
    *sensors: str, robot: builders.RobotText | None = None
) -> list[tuple[str, str | None, int]]:
    """(kind, sensor type, count) read from ``robot`` (a wheeled base unless given) with
    ``sensors`` added."""
    robot = robot or builders.ugv()
    for sensor in sensors:
        robot.add(sensor)
    return [(s.kind, s.sensor_type, s.count) for s in identify_urdf(robot.text()).sensors]


def bare(name: str, link: str = "base_link") -> str:
    """A URDF ``<sensor>`` with no kind element (no ``<camera>``, ``<ray>``, ...)."""
    return f'  <sensor name="{name}" update_rate="20"><parent link="{link}"/></sensor>'


@pytest.mark.parametrize(
    ("element", "expected"),
    [
        (
            builders.gazebo_sensor(
                "cam", "camera", "front_camera", plugin="libgazebo_ros_camera.so"
            ),
            ("camera", "2D Camera", 1),
        ),
        (
            builders.gazebo_sensor(
                "cam", "depth", "kinect", plugin="libgazebo_ros_openni_kinect.so"
            ),
            ("depth_camera", "RGB-D Camera", 1),
        ),
        (builders.gazebo_sensor("cam", "multicamera", "stereo"), ("stereo_camera", "3D Camera", 1)),
        (
            builders.gazebo_sensor(
                "cam",
                "wideanglecamera",
                "panorama",
                "<camera><horizontal_fov>6.283</horizontal_fov></camera>",
            ),
            ("wide_angle_camera", "360 Camera", 1),
        ),
        (
            builders.gazebo_sensor("laser", "ray", "hokuyo", RAY.format(h=720, v=1)),
            ("lidar", "LIDAR", 1),
        ),
        (
            builders.gazebo_sensor("laser", "gpu_ray", "velodyne", RAY.format(h=1800, v=16)),
            ("lidar", "LIDAR", 1),
        ),
        (
            builders.gazebo_sensor("front", "ray", "sonar_front", plugin="libgazebo_ros_range.so"),
            ("sonar", None, 1),
        ),
        (builders.gazebo_sensor("cliff_left", "ray", "cliff_sensor_left"), ("ir_range", None, 1)),
        # A line follower's reflectance sensor, faked with a camera of one pixel.
        (builders.gazebo_sensor("lt", "camera", "line_tracking_left"), ("ir_range", None, 1)),
        (
            builders.gazebo_sensor(
                "tof_1", "ray", "tof_1", RAY.format(h=10, v=10), "libhector_gazebo_ros_sonar.so"
            ),
            ("ir_range", None, 1),
        ),
        (
            builders.gazebo_sensor("tof_lidar", "gpu_ray", "tof_lidar", RAY.format(h=720, v=1)),
            ("lidar", "LIDAR", 1),
        ),
        (
            builders.gazebo_sensor("wrist", "force_torque", "ft"),
            ("force_torque", "Force Sensor", 1),
        ),
        (builders.gazebo_sensor("bumper", "contact", "bumper"), ("contact", "Force Sensor", 1)),
        (builders.gazebo_sensor("imu_link", "imu", "imu"), ("imu", None, 1)),
        (builders.gazebo_sensor("gps_link", "gps", "gps"), ("gps", None, 1)),
    ],
)
def test_each_sensor_element_maps_to_its_kind_and_sensor_type(
    element: str, expected: tuple[str, str | None, int]
) -> None:
    assert kinds(element) == [expected]


def test_a_urdf_sensor_element_is_read_too() -> None:
    element = (
        '  <sensor name="head_cam" update_rate="30"><parent link="base_link"/>'
        '<camera><image width="640" height="480"/></camera></sensor>'
    )
    assert kinds(element) == [("camera", "2D Camera", 1)]


def test_a_urdf_sensor_without_a_kind_element_is_told_by_its_name() -> None:
    found = kinds(
        bare("gyrometer_SENSOR"),
        bare("rfsensor_SENSOR"),
        bare("lhsensor_SENSOR"),
        bare("wrist_ft_sensor", "r_wrist"),
        bare("mystery"),
    )
    assert found == [
        ("imu", None, 1),
        ("force_torque", "Force Sensor", 3),
        ("unknown", None, 1),
    ]


def test_a_model_exported_from_sdf_keeps_its_sensors_names_and_they_tell_their_kinds() -> None:
    # A subterranean challenge rover's URDF: each SDF sensor written again with no kind element.
    robot = builders.ugv()
    robot.joint("mast_joint", "fixed", robot.root, "mast")
    found = kinds(
        *map(bare, ("front_laser", "lidar_back", "magnetometer", "air_pressure", "gps_antenna")),
        bare("depth_camera_up"),
        bare("camera_rear", "mast"),
        robot=robot,
    )
    assert sorted(found) == [
        ("barometer", None, 1),
        ("camera", "2D Camera", 1),
        ("depth_camera", "RGB-D Camera", 1),
        ("gps", None, 1),
        ("lidar", "LIDAR", 2),
        ("magnetometer", None, 1),
    ]


def test_a_sensor_without_a_kind_element_is_not_misread_by_a_part_of_its_name() -> None:
    # Two cameras named stereo, left and right, are one stereo camera; a scan frame is a
    # lidar's, a scan matcher's name is no device; a sonar's range is a sonar's.
    found = kinds(
        bare("stereo_left"),
        bare("stereo_right"),
        bare("front_scan"),
        bare("scan_matcher"),
        bare("sonar_distance"),
    )
    assert sorted(found) == [
        ("lidar", "LIDAR", 1),
        ("sonar", None, 1),
        ("stereo_camera", "3D Camera", 1),
        ("unknown", None, 1),
    ]


def test_a_depth_gauge_without_a_kind_element_on_a_submarine_is_no_camera() -> None:
    found = kinds(bare("depth_gauge"), robot=builders.underwater_vehicle())
    assert [kind for kind, _, _ in found] == ["pressure"]


def test_a_ros2_control_sensor_named_for_a_camera_or_a_lidar_reads_no_image_or_scan() -> None:
    found = kinds(
        hardware_sensor("camera_pose", "x", "y", "z"),
        hardware_sensor("lidar", "value"),
    )
    assert found == []


@pytest.mark.parametrize("declared", [True, False])
def test_gazebo_0x_namespaced_sensors_and_controllers_are_read(declared: bool) -> None:
    # Undeclared, as a 2011 file its team never ran through a strict parser: each element is
    # kept under its prefixed name (a located warning) and read the same.
    old = "http://playerstage.sourceforge.net/gazebo/xmlschema/#"
    text = builders.ugv().text()
    if declared:
        text = text.replace(
            "<robot ", f'<robot xmlns:sensor="{old}sensor" xmlns:controller="{old}controller" '
        )
    text = text.replace(
        "</robot>",
        '<gazebo reference="base_link"><sensor:ray name="base_laser">'
        '<controller:gazebo_ros_laser name="c" plugin="libgazebo_ros_laser.so"/></sensor:ray>'
        '<sensor:camera name="head_cam"/></gazebo>'
        '<gazebo><controller:gazebo_ros_imu name="imu_controller" plugin="libgazebo_ros_imu.so"/>'
        "</gazebo></robot>",
    )
    found = identify_urdf(text).sensors
    assert [(s.kind, s.sensor_type, s.count) for s in found] == [
        ("lidar", "LIDAR", 1),
        ("camera", "2D Camera", 1),
        ("imu", None, 1),
    ]


def test_model_plugins_count_as_sensors_but_ground_truth_does_not() -> None:
    found = kinds(
        builders.model_plugin("imu_sim", "libhector_gazebo_ros_imu.so"),
        builders.model_plugin("gps_sim", "libhector_gazebo_ros_gps.so"),
        builders.model_plugin("baro", "libhector_gazebo_ros_baro.so"),
        builders.model_plugin("groundtruth", "libgazebo_ros_p3d.so"),
        builders.model_plugin("floating_base_pose", "libgazebo_world_odometry.so"),
        builders.model_plugin(
            "imugt_plugin", "librotors_gazebo_imu_plugin.so", "<linkName>imugt_link</linkName>"
        ),
        builders.model_plugin(
            "odometry_sensor",
            "librotors_gazebo_odometry_plugin.so",
            "<linkName>ground_truth/odometry_link</linkName>",
        ),
        # The simulator's link poses, published under a sensor's name.
        builders.model_plugin("link_state_sensor", "libxbot2_gz_link_state_sensor.so"),
    )
    assert found == [("imu", None, 1), ("gps", None, 1), ("barometer", None, 1)]


def test_a_sensor_element_whose_plugin_publishes_ground_truth_is_no_device() -> None:
    # A ranger and, on its link, its noise-free twin a comment calls ground truth.
    ray = "libgazebo_ros_ray_sensor.so"
    found = kinds(
        builders.gazebo_sensor("laser", "ray", "front_laser", plugin=ray),
        builders.gazebo_sensor("laser", "ray", "gt_laser", plugin=ray),
    )
    assert found == [("lidar", "LIDAR", 1)]


def test_a_sensor_element_named_for_ground_truth_is_no_device_even_without_a_plugin() -> None:
    # An SDF export keeps a 3D lidar and its noise-free twin, each with no plugin: the twin's
    # name says what it is (fresh set 1815). A word that only holds the letters is a device.
    fan = "<ray><scan><horizontal><samples>512</samples></horizontal></scan></ray>"
    found = kinds(
        builders.gazebo_sensor("laser", "ray", "front_laser", fan),
        builders.gazebo_sensor("laser", "ray", "front_laser_truth", fan),
    )
    assert found == [("lidar", "LIDAR", 1)]
    trusty = kinds(builders.gazebo_sensor("laser", "ray", "trusty_laser", fan))
    assert trusty == [("lidar", "LIDAR", 1)]


def test_a_plugin_is_an_imu_by_the_word_imu_not_by_those_letters_inside_another() -> None:
    # A go-kart's vehicle simulator plugin holds the letters of "imu" (s-imu-lator).
    found = kinds(
        builders.model_plugin("simulator_gazebo_plugin", "libsimulator_gazebo_plugin.so"),
        builders.model_plugin("imu_plugin", "libgazebo_ros_imu.so"),
    )
    assert found == [("imu", None, 1)]
    # A CamelCase plugin name says IMU as a word.
    camel = kinds(builders.model_plugin("body_imu", "libMyRobotIMU.so"))
    assert camel == [("imu", None, 1)]


def test_a_plugin_feeding_a_counted_element_is_the_same_sensor() -> None:
    found = kinds(
        builders.gazebo_sensor("imu_link", "imu", "imu"),
        builders.model_plugin(
            "imu_plugin", "libgazebo_ros_imu.so", "<bodyName>imu_link</bodyName>"
        ),
    )
    assert found == [("imu", None, 1)]


def test_a_plugin_naming_its_body_and_the_frame_an_element_of_its_kind_is_on_feeds_it() -> None:
    # The plugin hangs on the base (its <bodyName>) and reports in imu_link (its <frameName>),
    # where the element is: one IMU declared twice. Naming only the base, it is a device of
    # its own.
    element = builders.gazebo_sensor("imu_link", "imu", "imu")
    for params, count in (
        ("<bodyName>base_link</bodyName><frameName>imu_link</frameName>", 1),
        ("<bodyName>base_link</bodyName>", 2),
    ):
        robot = builders.ugv()
        robot.fixed(robot.root, "imu_link")
        plugin = builders.model_plugin("imu_plugin", "libgazebo_ros_imu.so", params)
        assert kinds(element, plugin, robot=robot) == [("imu", None, count)]


def test_a_plugin_on_the_body_publishing_where_an_element_of_its_kind_does_is_that_sensor() -> None:
    # An IMU plugin on the base (its <bodyName>) and an IMU element on imu_link, both
    # publishing on /quad_imu: one stream, one IMU declared twice. On a topic of its own, the
    # plugin is a device of its own.
    inner = '<plugin name="imu_sensor_plugin" filename="libgazebo_ros_imu_sensor.so">'
    element = builders.gazebo_sensor(
        "imu_link", "imu", "imu", inner + "<topicName>quad_imu</topicName></plugin>"
    )
    for topic, count in (("/quad_imu", 1), ("body_imu", 2)):
        robot = builders.ugv()
        robot.fixed(robot.root, "imu_link")
        params = f"<bodyName>base_link</bodyName><topicName>{topic}</topicName>"
        plugin = builders.model_plugin("imu_plugin", "libgazebo_ros_imu.so", params)
        assert kinds(element, plugin, robot=robot) == [("imu", None, count)]


def test_a_force_plugin_naming_the_joint_a_gazebo_force_sensor_is_on_is_the_same_sensor() -> None:
    # builders.ugv() has wheel_left_joint: a force/torque sensor on a joint measures at its
    # child link, the link a plugin naming the joint measures at.
    assert kinds(
        builders.gazebo_sensor("wheel_left_joint", "force_torque", "wheel_fts"),
        builders.model_plugin(
            "ft_sensor", "libgazebo_ros_ft_sensor.so", "<jointName>wheel_left_joint</jointName>"
        ),
    ) == [("force_torque", "Force Sensor", 1)]


def test_counts_add_up_per_kind_and_only_presented_sensors_count() -> None:
    robot = builders.ugv()
    for name in ("front", "rear"):
        robot.add(builders.gazebo_sensor(f"{name}_laser", "ray", f"{name}_laser"))
    robot.add(builders.gazebo_sensor("imu_link", "imu", "imu"))
    result = identify_urdf(robot.text())
    assert [(s.kind, s.count) for s in result.sensors] == [("lidar", 2), ("imu", 1)]
    assert result.sensor_count == 2
    assert result.sensors[0].source == "urdf: front_laser, rear_laser"


def test_a_profile_can_map_lidars_by_their_scan_planes() -> None:
    text = (
        (RULES / "identification.yaml")
        .read_text(encoding="utf-8")
        .replace("  lidar: LIDAR", "  lidar: {single_plane: 2D Scanning, multi_plane: 3D Scanning}")
    )
    profile = parse_profile(parse_document(text, "planes.yaml"))
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("a", "ray", "planar", RAY.format(h=720, v=1)))
    robot.add(builders.gazebo_sensor("b", "gpu_ray", "vlp16", RAY.format(h=1800, v=16)))
    result = identify_urdf(robot.text(), profile=profile)
    assert [(s.sensor_type, s.count) for s in result.sensors] == [
        ("2D Scanning", 1),
        ("3D Scanning", 1),
    ]


def test_an_unknown_sensor_type_is_listed_under_its_own_name() -> None:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("x", "magic_eye", "m"))
    detections = sensors_from_urdf(parse_urdf(robot.text()), load_profile())
    assert [d.kind for d in detections] == ["magic_eye"]


def test_a_sensor_declared_in_gazebo_and_as_a_urdf_sensor_on_its_joint_counts_once() -> None:
    # builders.ugv() has wheel_left_link: the camera sits on it for this test.
    assert kinds(
        builders.gazebo_sensor("wheel_left_link", "camera", "front_camera"),
        '  <sensor name="front_camera_urdf" update_rate="30">'
        '<parent joint="wheel_left_joint"/><camera><image width="640" height="480"/>'
        "</camera></sensor>",
    ) == [("camera", "2D Camera", 1)]


def _kinds(text: str) -> dict[str, int]:
    from solver.identify import identify_urdf

    return {s.kind: s.count for s in identify_urdf(text).sensors}


def test_sensors_count_by_physical_device() -> None:
    from tests.identify.builders import RobotText, gazebo_sensor, model_plugin

    robot = RobotText("devices")
    robot.fixed(robot.root, "dvl_link")
    robot.fixed("dvl_link", "beam0")
    robot.fixed("dvl_link", "beam1")
    robot.add(model_plugin("dvl", "libdvl_plugin.so", "<link_name>dvl_link</link_name>"))
    robot.add(gazebo_sensor("beam0", "ray", "dvl_beam0"))
    robot.add(gazebo_sensor("beam1", "ray", "dvl_beam1"))
    robot.fixed(robot.root, "rgbd_link")
    robot.add(gazebo_sensor("rgbd_link", "depth", "rgbd_depth"))
    robot.add(gazebo_sensor("rgbd_link", "camera", "rgbd_colour"))
    robot.fixed(robot.root, "plain_cam")
    robot.add(
        gazebo_sensor(
            "plain_cam",
            "camera",
            "front",
            plugin="libgazebo_ros_camera.so",
        )
        .replace("</plugin>", "")
        .replace('.so"/>', '.so"><topic>depth/image</topic></plugin>')
    )
    for joint in ("j1", "j2"):
        robot.chain(robot.root, [joint])
        robot.add(model_plugin("ft", "libft_sensor.so", f"<jointName>{joint}</jointName>"))
    robot.add(model_plugin("pinger", "libpinger_sensor.so"))
    robot.add(model_plugin("sniffer", "libgas_sniffer_sensor.so"))
    assert _kinds(robot.text()) == {
        "dvl": 1,
        "depth_camera": 1,
        "camera": 1,
        "force_torque": 2,
        "acoustic_positioning": 1,
        "unknown": 1,
    }


@pytest.mark.parametrize("filename", ["libmil_passive_sonar_gazebo.so", "libhydrophones.so"])
def test_a_hydrophone_array_is_acoustic_positioning(filename: str) -> None:
    # A passive sonar listens for a pinger and gives its direction; an active one ranges.
    robot = builders.underwater_vehicle()
    robot.add(builders.model_plugin("hydrophones", filename))
    robot.add(builders.gazebo_sensor("sonar_link", "sonar", "imaging_sonar"))
    assert _kinds(robot.text()) == {"acoustic_positioning": 1, "sonar": 1}


def test_a_magnetic_plugin_is_a_magnetometer_but_a_magnetic_wheel_is_none() -> None:
    robot = builders.ugv()
    robot.add(builders.model_plugin("compass", "libhector_gazebo_ros_magnetic.so"))
    robot.add(builders.model_plugin("mag", "librotors_gazebo_magnetometer_plugin.so"))
    robot.add(builders.model_plugin("field", "libmagnetic_field_plugin.so"))
    robot.add(builders.model_plugin("sensor", "libmagnetic_sensor_plugin.so"))
    robot.add(builders.model_plugin("grip", "libmagnetic_wheel_gazebo_plugin.so"))
    robot.add(builders.model_plugin("hold", "libmagnet_gripper_plugin.so"))
    robot.add(builders.model_plugin("coil", "libelectromagnetic.so"))
    robot.add(builders.model_plugin("magnetic_hand", "libmagnetic.so"))  # holds a grasp
    assert _kinds(robot.text()) == {"magnetometer": 4}


def test_gazebos_logical_camera_is_the_camera_a_robot_detects_objects_with() -> None:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("gripper", "logical_camera", "gripper_logical_camera"))
    assert _kinds(robot.text()) == {"camera": 1}


def test_a_wind_sensor_plugin_is_an_anemometer() -> None:
    robot = builders.surface_vessel()
    robot.add(builders.model_plugin("wind_sensor", "libWindSensorPlugin.so"))
    assert _kinds(robot.text())["anemometer"] == 1


def test_a_stereo_pair_declared_as_two_cameras_is_one_stereo_camera() -> None:
    robot = builders.ugv()
    for side in ("l", "r"):
        robot.add(builders.gazebo_sensor("head", "camera", f"wide_stereo_{side}_camera"))
    robot.add(builders.gazebo_sensor("head", "camera", "left_eye_camera"))
    robot.add(builders.gazebo_sensor("head", "camera", "right_eye_camera"))
    found = [(d.kind, d.name) for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    # Two cameras not named stereo stay two cameras.
    assert found == [
        ("stereo_camera", "wide_stereo_l+r_camera"),
        ("camera", "left_eye_camera"),
        ("camera", "right_eye_camera"),
    ]


def zeds(*rigs: tuple[str, float, float]) -> list[tuple[str, str]]:
    """A ZED 2 per rig (prefix, x, yaw), each side a camera named ``zed2_<side>_camera_sensor``
    (one macro's names) on an optical frame of its own 6 cm apart across the rig."""
    robot = builders.ugv()
    for prefix, x, yaw in rigs:
        for side, y in (("left", 0.03), ("right", -0.03)):
            frame = f"{prefix}zed2_{side}_camera_optical_frame"
            builders.placed(
                robot, f"{frame}_joint", "fixed", "base_link", frame,
                xyz=f"{x} {y} 0.3", rpy=f"0 0 {yaw}",
            )  # fmt: skip
            robot.add(builders.gazebo_sensor(frame, "camera", f"zed2_{side}_camera_sensor"))
    return [(d.kind, d.name) for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]


def test_a_zeds_two_sided_cameras_are_one_stereo_camera() -> None:
    # Stereolabs' ZED 2, each side declared as a camera on its own optical frame; two of one
    # macro, named alike, front and rear, pair by their frames.
    assert zeds(("", 0.2, 0)) == [("stereo_camera", "zed2_left+right_camera_sensor")]
    assert [kind for kind, _ in zeds(("front_", 0.3, 0), ("rear_", -0.3, 3.14))] == [
        "stereo_camera",
        "stereo_camera",
    ]


def zed_eyes(left: tuple[str, ...], right: tuple[str, ...]) -> list[str]:
    """A ZED 2 whose eyes' frames, 12 cm apart, carry the streams named (``raw``: a camera
    ``zed2_<side>_raw_camera``; ``rect``: a camera ``zed2_<side>_camera``; ``depth``: a depth
    sensor ``zed2_<side>_camera``); the kinds read."""
    robot = builders.ugv()
    for side, y, streams in (("left", 0.06, left), ("right", -0.06, right)):
        frame = f"{side}_camera_link"
        builders.placed(robot, f"{side}_joint", "fixed", "base_link", frame, xyz=f"0 {y} 0.3")
        for stream in streams:
            name = f"zed2_{side}_raw_camera" if stream == "raw" else f"zed2_{side}_camera"
            kind = "depth" if stream == "depth" else "camera"
            robot.add(builders.gazebo_sensor(frame, kind, name))
    return [d.kind for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]


def test_a_zed_whose_left_eye_gives_the_depth_is_one_stereo_camera() -> None:
    # A simulated ZED 2: raw and depth streams on the left eye, raw and rectified on the right.
    assert zed_eyes(("raw", "depth"), ("raw", "rect")) == ["stereo_camera"]
    # Both eyes simulated as depth sensors: two depth cameras, no camera to pair.
    assert zed_eyes(("depth",), ("depth",)) == ["depth_camera", "depth_camera"]


def test_two_zeds_cameras_far_apart_looking_away_stay_two_cameras() -> None:
    robot = builders.ugv()
    for side, y, yaw in (("left", 0.4, 1.57), ("right", -0.4, -1.57)):
        builders.placed(
            robot, f"{side}_mount", "fixed", "base_link", f"{side}_zed_link",
            xyz=f"0 {y} 0.3", rpy=f"0 0 {yaw}",
        )  # fmt: skip
        robot.add(builders.gazebo_sensor(f"{side}_zed_link", "camera", f"{side}_zed_camera"))
    found = [d.kind for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    assert found == ["camera", "camera"]


@pytest.mark.parametrize("sides", [("left", "right"), ("l", "r")])
def test_a_devices_two_sided_channels_on_one_frame_are_one_stereo_camera(
    sides: tuple[str, str],
) -> None:
    robot = builders.ugv()
    for side in sides:
        robot.add(builders.gazebo_sensor("link_nav_cam", "camera", f"nav_cam/{side}"))
        robot.add(builders.gazebo_sensor("loc_camera_link", "camera", f"loc_cam_{side}"))
    found = [(d.kind, d.name) for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    assert found == [
        ("stereo_camera", f"nav_cam/{sides[0]}+{sides[1]}"),
        ("stereo_camera", f"loc_cam_{sides[0]}+{sides[1]}"),
    ]


@pytest.mark.parametrize(
    ("left", "right"),
    [
        ("nav_camera_link", "mast_camera_link"),  # two frames named by no side
        ("mast", "mast"),  # one frame not named for a camera
        ("base_link", "base_link"),  # the root, where a description puts any sensor
    ],
)
def test_sided_cameras_not_on_one_camera_frame_stay_two_cameras(left: str, right: str) -> None:
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor(left, "camera", "cam_left"))
    robot.add(builders.gazebo_sensor(right, "camera", "cam_right"))
    found = [d.kind for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    assert found == ["camera", "camera"]


def side_cameras(*, gap: float, yaw: float) -> list[tuple[str, str]]:
    """Two cameras named alike on a left and a right frame ``gap`` apart, each turned by
    ``yaw`` away from the middle."""
    robot = builders.ugv()
    for side, sign in (("left", 1), ("right", -1)):
        builders.placed(
            robot, f"duo_{side}_joint", "fixed", "base_link", f"duo_{side}_link",
            xyz=f"0.2 {sign * gap / 2} 0.1", rpy=f"0 0 {sign * yaw}",
        )  # fmt: skip
        robot.add(builders.gazebo_sensor(f"duo_{side}_link", "camera", "camera"))
    return [(d.kind, d.name) for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]


def test_two_cameras_on_frames_a_side_apart_looking_one_way_are_one_stereo_camera() -> None:
    assert side_cameras(gap=0.03, yaw=0) == [("stereo_camera", "camera")]


@pytest.mark.parametrize(
    ("gap", "yaw"),
    [(0.03, 1.57), (0.6, 0)],
    ids=["looking out of each side", "farther apart than a stereo baseline"],
)
def test_two_cameras_on_a_left_and_a_right_frame_otherwise_stay_two(gap: float, yaw: float) -> None:
    assert side_cameras(gap=gap, yaw=yaw) == [("camera", "camera"), ("camera", "camera")]


def topic_cameras(*, gap: float, streams: tuple[str, str]) -> list[tuple[str, str]]:
    """Two cameras named for their sides on two frames ``gap`` apart looking one way, each
    publishing as ``streams`` says (a Gazebo ``<topic>`` or a ROS 1 plugin's camera name)."""
    robot = builders.ugv()
    for side, sign, stream in (("left", 1, streams[0]), ("right", -1, streams[1])):
        link = builders.placed(
            robot, f"{side}_eye_joint", "fixed", "base_link", f"{side}_eye",
            xyz=f"0.2 {sign * gap / 2} 0.1",
        )  # fmt: skip
        robot.add(builders.gazebo_sensor(link, "camera", f"{side}_camera_sensor", stream))
    return [(d.kind, d.name) for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]


def plugin_named(camera: str) -> str:
    plugin = '<plugin name="cam" filename="libgazebo_ros_camera.so">'
    return f"{plugin}<cameraName>{camera}</cameraName></plugin>"


@pytest.mark.parametrize(
    "streams",
    [
        ("<topic>/stereo/left/image_raw</topic>", "<topic>/stereo/right/image_raw</topic>"),
        (plugin_named("stereo/left"), plugin_named("stereo/right")),
        ("<topic>/front_stereo/left</topic>", "<topic>/front_stereo/right</topic>"),
    ],
    ids=["gazebo topics", "ros 1 camera names", "a stereo word in a topic's segment"],
)
def test_two_cameras_publishing_as_a_stereo_pairs_sides_are_one_stereo_camera(
    streams: tuple[str, str],
) -> None:
    assert topic_cameras(gap=0.1, streams=streams) == [
        ("stereo_camera", "left+right_camera_sensor")
    ]


@pytest.mark.parametrize(
    ("gap", "streams"),
    [
        (0.1, ("<topic>/cameras/left/image</topic>", "<topic>/cameras/right/image</topic>")),
        (0.6, ("<topic>/stereo/left/image_raw</topic>", "<topic>/stereo/right/image_raw</topic>")),
        (0.1, ("<topic>/stereographic/left</topic>", "<topic>/stereographic/right</topic>")),
        (0.1, ("<topic>/stereo/image_raw</topic>", "<topic>/stereo/image_raw</topic>")),
    ],
    ids=[
        "no stereo in the topics",
        "farther apart than a stereo baseline",
        "stereographic",
        "one topic naming no side",
    ],
)
def test_two_cameras_publishing_otherwise_stay_two(gap: float, streams: tuple[str, str]) -> None:
    assert topic_cameras(gap=gap, streams=streams) == [
        ("camera", "left_camera_sensor"),
        ("camera", "right_camera_sensor"),
    ]


def test_two_rigs_of_one_macro_publishing_alike_are_two_stereo_cameras_by_their_frames() -> None:
    # A front and a rear rig, every camera named alike and publishing on the macro's fixed
    # topics: four cameras on one topic pair no two by it, and each rig pairs by its frames.
    robot = builders.ugv()
    for rig, x in (("front", 0.3), ("rear", -0.3)):
        for side, y in (("left", 0.05), ("right", -0.05)):
            link = builders.placed(
                robot, f"{rig}_{side}_joint", "fixed", "base_link", f"{rig}_{side}_cam",
                xyz=f"{x} {y} 0.2",
            )  # fmt: skip
            topic = f"<topic>/stereo/{side}/image_raw</topic>"
            robot.add(builders.gazebo_sensor(link, "camera", "cam", topic))
    found = [d.kind for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    assert found == ["stereo_camera", "stereo_camera"]


def test_two_cameras_of_one_name_on_two_wrists_that_move_apart_stay_two() -> None:
    robot = builders.ugv()
    for side, y in (("left", 0.03), ("right", -0.03)):
        wrist = robot.chain("base_link", [f"{side}_wrist"])
        builders.placed(
            robot, f"{side}_camera_joint", "fixed", wrist, f"{side}_camera_link", xyz=f"0 {y} 0"
        )
        robot.add(builders.gazebo_sensor(f"{side}_camera_link", "camera", "camera"))
    found = [d.kind for d in sensors_from_urdf(parse_urdf(robot.text()), load_profile())]
    assert found == ["camera", "camera"]


@pytest.mark.parametrize(
    "filename", ["libplugin_depth.so", "libdepth.so", "depth_plugin.so", "libmil_depth_gazebo.so"]
)
def test_a_plugin_that_says_only_depth_on_a_vessel_is_its_depth_gauge(filename: str) -> None:
    robot = builders.underwater_vehicle()
    robot.add(builders.model_plugin("gauge", filename))
    robot.add(builders.model_plugin("cam", "libgazebo_ros_depth_camera.so"))
    assert _kinds(robot.text()) == {"pressure": 1}


def test_gazebo_sim_systems_are_no_sensors_their_sensor_elements_are() -> None:
    found = kinds(
        builders.model_plugin("gz::sim::systems::Imu", "gz-sim-imu-system"),
        builders.model_plugin("gz::sim::systems::Sensors", "gz-sim-sensors-system"),
        builders.model_plugin("ignition::gazebo::systems::Imu", "ignition-gazebo-imu-system"),
        builders.model_plugin("control", "gz_ros2_control-system"),
        builders.gazebo_sensor("imu_link", "imu", "imu"),
    )
    assert found == [("imu", None, 1)]


def test_a_gazebo_sim_custom_sensor_is_told_by_its_names_as_one_with_no_type() -> None:
    # Robotec's GPU lidar (RGL) runs as a `custom` sensor on the lidar's link.
    rgl = builders.gazebo_sensor(
        "lidar_link", "custom", "RGLsensor", plugin="RGLServerPluginInstance"
    )
    assert kinds(rgl) == [("lidar", "LIDAR", 1)]
    # One whose names tell nothing stays a device of its own kind.
    assert kinds(builders.gazebo_sensor("box", "custom", "thing")) == [("custom", None, 1)]


def ray(link: str, name: str, samples: int, sweep: float, reach: float) -> str:
    scan = (
        f"<ray><scan><horizontal><samples>{samples}</samples><min_angle>{-sweep / 2}</min_angle>"
        f"<max_angle>{sweep / 2}</max_angle></horizontal></scan>"
        f"<range><max>{reach}</max></range></ray>"
    )
    return builders.gazebo_sensor(link, "gpu_lidar", name, scan)


@pytest.mark.parametrize(
    ("fov", "kind"),
    [
        (None, "camera"),
        (2.88, "camera"),
        (3.1415, "camera"),
        (3.3, "wide_angle_camera"),
        (6.2831, "wide_angle_camera"),
        (170.0, "camera"),
    ],
)
def test_a_wide_angle_camera_is_panoramic_only_when_it_sees_more_than_a_half_turn(
    fov: float | None, kind: str
) -> None:
    # A fisheye lens written as Gazebo's wideanglecamera (165 degrees, 180) is a camera; one
    # that sees more than a half-turn is a panoramic camera; one that says no field of view
    # is a camera (Gazebo's default view is 60 degrees), and so is one whose field of view is
    # more than a full turn (170 degrees written where radians belong says no more than that).
    inner = "" if fov is None else f"<camera><horizontal_fov>{fov}</horizontal_fov></camera>"
    found = kinds(builders.gazebo_sensor("cam", "wideanglecamera", "front_fisheye", inner))
    assert [k for k, _, _ in found] == [kind]


def test_a_one_ray_range_sensor_is_no_lidar_and_four_of_them_stay_four() -> None:
    # Told apart by what they cast, not their names (fl_range, ..., and a lidar beside them).
    found = kinds(
        *(
            ray(f"{corner}_range", f"{corner}_range", 1, 0.02, 0.9)
            for corner in ("fl", "fr", "rl", "rr")
        ),
        ray("laser", "rplidar", 1600, 6.28, 12.0),
    )
    assert found == [("ir_range", None, 4), ("lidar", "LIDAR", 1)]


def test_a_fan_of_rays_that_reaches_a_metre_at_most_is_a_proximity_ranger_not_a_lidar() -> None:
    # A ring of proximity sensors a simulator fakes with one full turn of rays half a metre
    # long; the same fan reaching twelve metres, or saying no range, is a lidar.
    assert kinds(ray("laser_link", "hero_laser", 360, 6.28, 0.5)) == [("ir_range", None, 1)]
    assert kinds(ray("laser_link", "hero_laser", 360, 6.28, 1.0)) == [("ir_range", None, 1)]
    assert kinds(ray("laser_link", "hero_laser", 360, 6.28, 12.0)) == [("lidar", "LIDAR", 1)]
    fan = "<ray><scan><horizontal><samples>360</samples></horizontal></scan></ray>"
    assert kinds(builders.gazebo_sensor("laser", "ray", "laser", fan)) == [("lidar", "LIDAR", 1)]
    # A range of zero or less, which no simulator casts, says nothing of the device.
    assert kinds(ray("laser_link", "hokuyo", 720, 4.7, 0.0)) == [("lidar", "LIDAR", 1)]
    assert kinds(ray("laser_link", "hokuyo", 720, 4.7, -30.0)) == [("lidar", "LIDAR", 1)]


def test_rays_fanned_over_less_than_twenty_degrees_are_one_beam_a_range_finder() -> None:
    # A single-beam laser written as two samples 0.02 degrees apart measures one distance, and
    # so does a narrow laser ranger's fan of three rays over 3.6 degrees; rays fanned over 30
    # degrees sweep, as a lidar's do.
    assert kinds(ray("tool", "laser_distance", 2, 0.0004, 2.0)) == [("ir_range", None, 1)]
    assert kinds(ray("front", "laser_one", 3, 0.0628, 5.0)) == [("ir_range", None, 1)]
    assert kinds(ray("tool", "laser_distance", 2, 0.34, 2.0)) == [("ir_range", None, 1)]
    assert kinds(ray("tool", "laser_distance", 2, 0.36, 2.0)) == [("lidar", "LIDAR", 1)]
    assert kinds(ray("tool", "laser_distance", 2, 0.52, 2.0)) == [("lidar", "LIDAR", 1)]


def cone(name: str, samples: int, across: float, tall: float) -> str:
    """A ray sensor of ``samples`` x ``samples`` rays, ``across`` radians wide, ``tall`` high."""

    def axis(span: float) -> str:
        return (
            f"<samples>{samples}</samples><min_angle>{-span / 2}</min_angle>"
            f"<max_angle>{span / 2}</max_angle>"
        )

    scan = (
        f"<ray><scan><horizontal>{axis(across)}</horizontal><vertical>{axis(tall)}</vertical>"
        "</scan><range><max>40</max></range></ray>"
    )
    return builders.gazebo_sensor(f"{name}_link", "ray", name, scan)


def test_a_grid_of_rays_a_degree_or_two_across_both_ways_is_one_beam_a_range_finder() -> None:
    # A laser altimeter written as 5 x 5 rays over 1.7 degrees each way (a Garmin LIDAR-Lite
    # in a drone's model) measures one distance; the same grid fanned 30 degrees high is a
    # vertical scanner, and one swept a full turn with 16 layers over 30 degrees is a 3D lidar.
    assert kinds(cone("garmin", 5, 0.03, 0.03)) == [("ir_range", None, 1)]
    assert kinds(cone("garmin", 5, 0.03, 0.52)) == [("lidar", "LIDAR", 1)]
    assert kinds(cone("velodyne", 16, 6.28, 0.52)) == [("lidar", "LIDAR", 1)]
    robot = builders.ugv()
    robot.add(cone("garmin", 5, 0.03, 0.52))
    (tag,) = parse_urdf(robot.text()).sensors
    assert tag.vertical_sweep == pytest.approx(0.52)


def test_a_ray_sensor_left_at_zero_samples_is_read_by_its_type_not_as_one_ray() -> None:
    # Gazebo casts no ray for <samples>0</samples>: the count says nothing of the device.
    for samples in (0, -1):
        assert kinds(ray("laser", "head_hokuyo", samples, 3.14, 25.0)) == [("lidar", "LIDAR", 1)]


def range_finder(name: str, radiation: str, *, ros2: bool = False) -> str:
    """A cone of 10 x 10 rays (a range plugin's beam) whose plugin says what it casts (ROS 1's
    gazebo_ros_range, or ROS 2's ray sensor plugin putting out a Range)."""
    grid = "<samples>10</samples><min_angle>-0.13</min_angle><max_angle>0.13</max_angle>"
    scan = (
        f"<ray><scan><horizontal>{grid}</horizontal><vertical>{grid}</vertical></scan>"
        "<range><max>4.5</max></range></ray>"
    )
    plugin = (
        f'<plugin name="{name}_range" filename="libgazebo_ros_range.so">'
        f"<topicName>{name}</topicName><radiation>{radiation}</radiation></plugin>"
    )
    if ros2:
        plugin = (
            f'<plugin name="{name}_controller" filename="libgazebo_ros_ray_sensor.so">'
            "<output_type>sensor_msgs/Range</output_type>"
            f"<radiation_type>{radiation}</radiation_type></plugin>"
        )
    return builders.gazebo_sensor(f"{name}_link", "ray", name, scan + plugin)


def test_a_range_plugins_radiation_tells_a_sonar_and_an_infrared_ranger_from_a_lidar() -> None:
    # Named only by place (front_c, front_l): the wave the plugin casts says what they are.
    found = kinds(
        range_finder("front_c", "ultrasound"),
        range_finder("front_l", "ultrasound"),
        range_finder("rear", "infrared"),
    )
    assert found == [("sonar", None, 2), ("ir_range", None, 1)]
    # ROS 2's ray sensor plugin says it in <radiation_type>: six sonars were read as lidars.
    found = kinds(
        range_finder("front", "ultrasound", ros2=True),
        range_finder("side_left", "ultrasound", ros2=True),
        range_finder("rear", "infrared", ros2=True),
    )
    assert found == [("sonar", None, 2), ("ir_range", None, 1)]


def test_a_ray_plugin_putting_out_a_scan_is_a_lidar_whatever_wave_it_was_copied_with() -> None:
    # ROS 2's ray sensor plugin copied from a range finder's example keeps its
    # <radiation_type>infrared</radiation_type> when made to put out a LaserScan: a sweep of
    # 720 rays over a whole turn, 10 m, was read as an infrared ranger.
    sweep = (
        "<ray><scan><horizontal><samples>720</samples><min_angle>-3.14</min_angle>"
        "<max_angle>3.14</max_angle></horizontal></scan><range><max>10.0</max></range></ray>"
    )
    for output in ("sensor_msgs/LaserScan", "sensor_msgs/PointCloud2"):
        plugin = (
            '<plugin name="lidar_controller" filename="libgazebo_ros_ray_sensor.so">'
            f"<output_type>{output}</output_type><radiation_type>infrared</radiation_type>"
            "</plugin>"
        )
        found = kinds(builders.gazebo_sensor("base_scan", "ray", "head_sensor", sweep + plugin))
        assert found == [("lidar", "LIDAR", 1)], output


def test_a_ray_sensor_read_from_its_element_knows_its_sweep_and_reach() -> None:
    robot = builders.ugv()
    robot.add(ray("laser", "rplidar", 1600, 6.28, 12.0))
    (tag,) = parse_urdf(robot.text()).sensors
    assert (tag.horizontal_samples, tag.max_range) == (1600, 12.0)
    assert tag.sweep == pytest.approx(6.28)


def included(uri: str, name: str = "gps0", parent: str = "base_link") -> str:
    """A Gazebo model added by ``<include>`` and fixed to ``parent`` by a joint beside it."""
    return (
        f"  <gazebo><include><uri>{uri}</uri><pose>0.1 0 0 0 0 0</pose><name>{name}</name>"
        f'</include><joint name="{name}_joint" type="fixed"><child>{name}::link</child>'
        f"<parent>{parent}</parent></joint></gazebo>"
    )


def test_a_gps_model_a_description_includes_is_a_gps_on_the_link_it_is_fixed_to() -> None:
    robot = builders.quadrotor()
    robot.add(included("model://gps"))
    detections = sensors_from_urdf(parse_urdf(robot.text()), load_profile())
    assert [(d.kind, d.name, d.link) for d in detections] == [("gps", "gps0", "base_link")]
    # A flown body with a position fix could fly to waypoints (a guess, said so).
    controls = {c.motion_control for c in identify_urdf(robot.text()).motion_controls}
    assert controls == {"Flight", "Waypoint"}


@pytest.mark.parametrize(
    "uri",
    ["model://ground_plane", "model://my_sensor_mount", "file://gps/model.sdf", "model://"],
    ids=["not a sensor", "says only 'sensor'", "not a model URI", "no model name"],
)
def test_an_included_model_whose_name_names_no_sensor_kind_adds_none(uri: str) -> None:
    robot = builders.quadrotor()
    robot.add(included(uri))
    assert sensors_from_urdf(parse_urdf(robot.text()), load_profile()) == ()


ALTIMETER = builders.gazebo_sensor("base_link", "altimeter", "pressure_sensor")


def test_a_barometer_on_a_body_below_the_water_is_a_depth_gauge() -> None:
    def found(robot: builders.RobotText) -> dict[str, int]:
        robot.add(ALTIMETER)
        return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}

    # Below the water a pressure sensor measures depth; in the air, altitude; on a hull at the
    # surface, the weather.
    assert found(builders.underwater_vehicle()) == {"pressure": 1}
    assert found(builders.quadrotor()) == {"barometer": 1}
    assert found(builders.surface_vessel()) == {"barometer": 1}


def test_a_pitot_tube_of_gazebo_sim_is_an_airspeed_sensor_as_the_airspeed_plugins_are() -> None:
    plane = builders.quadrotor()
    plane.add(builders.gazebo_sensor("base_link", "air_speed", "pitot"))
    assert {s.kind: s.count for s in identify_urdf(plane.text()).sensors} == {"airspeed": 1}


# A depth gauge a simulator fakes with one ray cast down, as student AUVs write it.
ONE_RAY = (
    "<ray><scan><horizontal><samples>1</samples><min_angle>0</min_angle>"
    "<max_angle>0</max_angle></horizontal></scan><range><min>0.5</min><max>30</max></range></ray>"
)


@pytest.mark.parametrize(("link", "name"), [("base_link", "depth_sensor"), ("bar30_link", "ray")])
def test_a_range_finder_named_for_depth_below_the_water_is_a_depth_gauge(
    link: str, name: str
) -> None:
    def found(robot: builders.RobotText) -> dict[str, int]:
        if link != robot.root:
            robot.fixed(robot.root, link)
        robot.add(builders.gazebo_sensor(link, "ray", name, ONE_RAY))
        return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}

    assert found(builders.underwater_vehicle()) == {"pressure": 1}
    # In the air or on the ground, one ray is a range finder, whatever its name.
    assert found(builders.ugv()) == {"ir_range": 1}


@pytest.mark.parametrize(
    ("link", "name"),
    [
        ("base_link", "depth_sounder"),
        ("depth_camera_link", "ray"),
        ("base_link", "max_depth_range"),
    ],
)
def test_a_range_finder_whose_name_only_holds_depth_stays_a_range_finder(
    link: str, name: str
) -> None:
    robot = builders.underwater_vehicle()
    if link != robot.root:
        robot.fixed(robot.root, link)
    robot.add(builders.gazebo_sensor(link, "ray", name, ONE_RAY))
    assert {s.kind: s.count for s in identify_urdf(robot.text()).sensors} == {"ir_range": 1}


def rgbd_on_sibling_frames(mount_on_root: bool = False) -> builders.RobotText:
    """A Kinect declared as two Gazebo sensors, a colour stream on its rgb frame and a depth
    stream on its depth frame, both fixed to the camera's own link (or straight to the root)."""
    robot = builders.ugv()
    mount = robot.root if mount_on_root else robot.fixed(robot.root, "kinect_link")
    robot.fixed(mount, "kinect_rgb_frame")
    robot.fixed(mount, "kinect_depth_frame")
    robot.add(builders.gazebo_sensor("kinect_rgb_frame", "camera", "camera"))
    robot.add(builders.gazebo_sensor("kinect_depth_frame", "depth_camera", "depth_camera1"))
    return robot


def test_depth_streams_on_sibling_frames_of_one_camera_link_are_one_rgbd_camera() -> None:
    one = identify_urdf(rgbd_on_sibling_frames().text()).sensors
    assert [(s.kind, s.count) for s in one] == [("depth_camera", 1)]
    # Frames fixed straight to the body are no one device's: two depth cameras.
    two = identify_urdf(rgbd_on_sibling_frames(mount_on_root=True).text()).sensors
    assert [(s.kind, s.count) for s in two] == [("depth_camera", 2)]


def test_a_plain_camera_beside_a_depth_camera_on_one_camera_link_stays_a_camera() -> None:
    robot = builders.ugv()
    head = robot.fixed(robot.root, "head_link")
    robot.fixed(head, "top_camera_frame")
    robot.fixed(head, "depth_frame")
    robot.add(builders.gazebo_sensor("top_camera_frame", "camera", "top_camera"))
    robot.add(builders.gazebo_sensor("depth_frame", "depth_camera", "depth"))
    found = {s.kind: s.count for s in identify_urdf(robot.text()).sensors}
    assert found == {"camera": 1, "depth_camera": 1}


def realsense_on_its_body(mount: str) -> dict[str, int]:
    """A D435 declared as four Gazebo cameras, colour, two infrared and depth, each on its own
    frame fixed to ``mount`` (a link fixed on a head), as a realsense xacro writes it."""
    robot = builders.ugv()
    head = robot.fixed(robot.root, "head_link")
    body = robot.fixed(head, mount) if mount != "head_link" else head
    for stream, kind in (("color", "camera"), ("infra1", "camera"), ("infra2", "camera")):
        robot.fixed(body, f"cam_{stream}_frame")
        robot.add(builders.gazebo_sensor(f"cam_{stream}_frame", kind, stream))
    robot.fixed(body, "cam_depth_frame")
    robot.add(builders.gazebo_sensor("cam_depth_frame", "depth", "depth"))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_cameras_on_frames_fixed_to_an_rgbd_cameras_own_link_are_its_streams() -> None:
    assert realsense_on_its_body("camera_link") == {"depth_camera": 1}
    # The same frames on a head (no camera's body): three cameras and a depth camera.
    assert realsense_on_its_body("head_link") == {"camera": 3, "depth_camera": 1}


def realsense_below_its_body(body: str, *, apart: float = 0.0, extra: str = "") -> dict[str, int]:
    """A D435 as another realsense macro writes it: the depth stream on the camera's ``body``
    link itself (``camera_link``), the colour and infrared cameras on frames named for it
    beneath it, through its depth frame (``camera_color_frame``), the right infrared frame
    ``apart`` metres across; ``extra``: more of the description."""
    robot = builders.ugv()
    robot.fixed(robot.root, body)
    robot.add(builders.gazebo_sensor(body, "depth", "depth"))
    stem = body.rsplit("_", 1)[0]
    depth = robot.fixed(body, f"{stem}_depth_frame")
    for stream, y in (("color", 0.0), ("infra1", 0.0), ("infra2", -apart)):
        frame = f"{stem}_{stream}_frame"
        builders.placed(robot, f"{stream}_joint", "fixed", depth, frame, xyz=f"0 {y} 0")
        robot.add(builders.gazebo_sensor(frame, "camera", stream))
    robot.add(extra)
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_cameras_on_frames_beneath_an_rgbd_cameras_body_carrying_its_depth_are_its_streams() -> (
    None
):
    assert realsense_below_its_body("camera_link", apart=0.05) == {"depth_camera": 1}
    # Past a camera's reach, or beneath a link that is no camera's body: cameras of their own.
    assert realsense_below_its_body("camera_link", apart=0.5) == {"camera": 1, "depth_camera": 1}
    assert realsense_below_its_body("head_link") == {"camera": 3, "depth_camera": 1}


def realsense_on_undrawn_frames(*streams: str) -> dict[str, int]:
    """A D435's four Gazebo sensors on frames the file does not draw (a realsense macro whose
    frames were left out): ``camera_depth_frame`` and a camera on each of ``streams``."""
    robot = builders.ugv()
    robot.add(builders.gazebo_sensor("camera_depth_frame", "depth", "depth"))
    for frame in streams:
        robot.add(builders.gazebo_sensor(frame, "camera", frame))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_streams_on_frames_not_drawn_named_for_one_camera_are_one_rgbd_camera() -> None:
    frames = ("camera_color_frame", "camera_infra1_frame", "camera_infra2_frame")
    assert realsense_on_undrawn_frames(*frames) == {"depth_camera": 1}
    # A camera on an undrawn frame named for another camera's body, or for no stream after
    # the camera word (a rear camera, a second device's colour frame), is a camera of its own.
    for other in ("rear_camera_frame", "camera_rear_frame", "camera2_color_frame"):
        assert realsense_on_undrawn_frames(other) == {"camera": 1, "depth_camera": 1}


def realsense_on_optical_frames(colour_turn: str) -> dict[str, int]:
    """A D435 as the realsense2_description macro draws it, with Gazebo Sim sensors on its
    optical frames: ``head_camera_link`` on a head, a colour and a depth frame fixed beneath
    it (the colour frame 1.5 cm across), each with an optical frame turned the optical way
    (``-pi/2 0 -pi/2``) carrying the stream; the colour optical frame turned ``colour_turn``."""
    robot = builders.ugv()
    head = robot.fixed(robot.root, "head_link")
    body = robot.fixed(head, "head_camera_link")
    optical = "-1.5708 0 -1.5708"
    for stream, y, turn, kind in (
        ("color", "0.015", colour_turn, "camera"),
        ("depth", "0", optical, "depth"),
    ):
        frame = builders.placed(
            robot, f"{stream}_joint", "fixed", body, f"head_camera_{stream}_frame", xyz=f"0 {y} 0"
        )
        link = f"head_camera_{stream}_optical_frame"
        builders.placed(robot, f"{stream}_optical_joint", "fixed", frame, link, rpy=turn)
        robot.add(builders.gazebo_sensor(link, kind, f"head_camera_{stream}"))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_colour_and_depth_streams_on_an_rgbd_cameras_optical_frames_are_one_device() -> None:
    assert realsense_on_optical_frames("-1.5708 0 -1.5708") == {"depth_camera": 1}
    # A colour stream turned another way (facing back) is a camera of its own.
    assert realsense_on_optical_frames("-1.5708 0 1.5708") == {"camera": 1, "depth_camera": 1}


def test_a_camera_and_a_depth_camera_of_two_devices_on_one_camera_bracket_stay_two() -> None:
    robot = builders.ugv()
    bracket = robot.fixed(robot.root, "camera_mount")
    # A webcam named for the bracket and a time-of-flight camera named for nothing, 16 cm apart.
    for frame, y, kind in (
        ("camera_webcam_link", "0.08", "camera"),
        ("tof_link", "-0.08", "depth"),
    ):
        builders.placed(robot, f"{frame}_joint", "fixed", bracket, frame, xyz=f"0 {y} 0")
        robot.add(builders.gazebo_sensor(frame, kind, frame))
    found = {s.kind: s.count for s in identify_urdf(robot.text()).sensors}
    assert found == {"camera": 1, "depth_camera": 1}


def bolted(name: str, joint: str, *, under: str = "camera_link") -> str:
    """A camera ``name`` on its own frame under ``under``, by ``joint``'s kind and place."""
    kind, _, place = joint.partition(" ")
    return (
        f'<link name="{name}_frame"/><joint name="{name}_joint" type="{kind}">'
        f'<parent link="{under}"/><child link="{name}_frame"/>{place}'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        + builders.gazebo_sensor(f"{name}_frame", "camera", name)
    )


@pytest.mark.parametrize(
    "other",
    [
        # A thermal camera 4 cm beneath the body, on a frame not named for it.
        bolted("thermal", 'fixed <origin xyz="0 0 -0.04"/>'),
        # A rear camera named for the body, 6 cm behind it and facing back.
        bolted("camera_rear", 'fixed <origin xyz="-0.06 0 0" rpy="0 0 3.14159"/>'),
        # A camera named for the body on a joint that moves it.
        bolted("camera_pan", 'revolute <origin xyz="0 0 -0.02"/>'),
        # A camera named for the body three fixed joints down.
        '<link name="camera_a"/><joint name="ja" type="fixed"><parent link="camera_link"/>'
        '<child link="camera_a"/></joint><link name="camera_b"/><joint name="jb" type="fixed">'
        '<parent link="camera_a"/><child link="camera_b"/></joint>'
        + bolted("camera_deep", "fixed", under="camera_b"),
    ],
    ids=["thermal", "rear", "moved", "deep"],
)
def test_a_camera_bolted_beneath_an_rgbd_cameras_body_that_is_no_stream_stays_a_camera(
    other: str,
) -> None:
    found = realsense_below_its_body("camera_link", extra=other)
    assert found == {"camera": 1, "depth_camera": 1}


def test_colour_and_depth_streams_on_one_link_read_as_depth_cameras_are_one_device() -> None:
    # A realsense's colour stream is read as a depth camera by its device's name; on the link
    # of its depth stream it is the same camera.
    robot = builders.ugv()
    robot.fixed(robot.root, "camera_link")
    robot.add(builders.gazebo_sensor("camera_link", "camera", "realsense_d435_color"))
    robot.add(builders.gazebo_sensor("camera_link", "depth_camera", "realsense_d435_depth"))
    found = [(s.kind, s.count) for s in identify_urdf(robot.text()).sensors]
    assert found == [("depth_camera", 1)]


def test_an_airspeed_plugin_is_an_airspeed_sensor_not_a_barometer() -> None:
    robot = builders.quadrotor()
    robot.add(builders.model_plugin("fcu_airspeed", "libairspeed_plugin.so"))
    robot.add(builders.model_plugin("fcu_baro", "libbarometer_plugin.so"))
    found = {s.kind: (s.sensor_type, s.count) for s in identify_urdf(robot.text()).sensors}
    assert found == {"airspeed": (None, 1), "barometer": (None, 1)}


def two_depth_cameras(mount: str, rear_xyz: str, rear_rpy: str) -> dict[str, int]:
    """A front and a rear depth camera, each on its own link fixed to ``mount`` (``base_link``
    under a ``base_footprint`` root, or a mast on it); the front one at 0.3 m ahead."""
    robot = builders.RobotText("rover", root="base_footprint")
    robot.fixed(robot.root, "base_link")
    if mount != "base_link":
        robot.fixed("base_link", mount)
    for side, xyz, rpy in (("front", "0.3 0 0.2", "0 0 0"), ("rear", rear_xyz, rear_rpy)):
        robot.joint(
            f"{side}_camera_joint",
            "fixed",
            mount,
            f"{side}_camera_link",
            f'<origin xyz="{xyz}" rpy="{rpy}"/>',
        )
        robot.add(builders.gazebo_sensor(f"{side}_camera_link", "depth", f"{side}_realsense"))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_depth_cameras_on_separate_links_of_one_mount_are_one_camera_each() -> None:
    # Apart on base_link (behind, facing back), and on a mast, 0.5 m apart facing one way.
    assert two_depth_cameras("base_link", "-0.3 0 0.2", "0 0 3.14159") == {"depth_camera": 2}
    assert two_depth_cameras("mast_link", "0.3 0 0.7", "0 0 0") == {"depth_camera": 2}
    # Two frames 2.5 cm apart facing one way are one device's streams (a Kinect's).
    assert two_depth_cameras("base_link", "0.3 0.025 0.2", "0 0 0") == {"depth_camera": 1}
    # Close but facing apart: two cameras.
    assert two_depth_cameras("base_link", "0.3 0.025 0.2", "0 0 3.14159") == {"depth_camera": 2}


def test_a_camera_element_with_a_colour_plugin_is_a_camera_whatever_the_product_name() -> None:
    """A camera sensor named for an RGB-D product but simulated by a plain camera plugin streams
    colour only; a depth plugin or a depth name makes it a depth camera."""
    realsense = builders.gazebo_sensor(
        "cam", "camera", "realsense_r200", plugin="libgazebo_ros_camera.so"
    )
    assert kinds(realsense) == [("camera", "2D Camera", 1)]
    kinect = builders.gazebo_sensor(
        "cam", "camera", "kinect", plugin="libgazebo_ros_openni_kinect.so"
    )
    assert kinds(kinect) == [("depth_camera", "RGB-D Camera", 1)]


def stereo_with_depth(
    depth_origin: str, depth: str = "zed_depth"
) -> list[tuple[str, str | None, int]]:
    """A stereo pair on a camera's centre frame and a depth stream on a frame fixed to it."""
    robot = builders.ugv()
    robot.joint("center_joint", "fixed", robot.root, "zed_center", '<origin xyz="0.2 0 0.4"/>')
    robot.joint("pair_joint", "fixed", "zed_center", "zed_pair", f'<origin xyz="{depth_origin}"/>')
    robot.add(builders.gazebo_sensor("zed_pair", "multicamera", "zed_stereo"))
    robot.add(builders.gazebo_sensor("zed_center", "depth", depth))
    return [(s.kind, s.sensor_type, s.count) for s in identify_urdf(robot.text()).sensors]


def test_a_depth_stream_beside_a_stereo_pair_is_the_pairs_depth_one_device() -> None:
    assert stereo_with_depth("0.01 0 0.01") == [("stereo_camera", "3D Camera", 1)]
    assert sorted(stereo_with_depth("0.5 0 0")) == [  # half a metre apart: two devices
        ("depth_camera", "RGB-D Camera", 1),
        ("stereo_camera", "3D Camera", 1),
    ]


def test_an_rgbd_cameras_depth_beside_a_stereo_pair_is_a_device_of_its_own() -> None:
    # A head carrying a stereo pair and an ASUS Xtion on one frame.
    assert sorted(stereo_with_depth("0.01 0 0.01", depth="asus_xtion_depth")) == [
        ("depth_camera", "RGB-D Camera", 1),
        ("stereo_camera", "3D Camera", 1),
    ]


def test_gazebo_sims_lidar_spelling_of_a_ray_sensor_is_told_apart_by_the_same_words() -> None:
    # Gazebo Sim writes an infrared proximity sensor's or a sonar's rays as a gpu_lidar.
    grid = "<samples>5</samples><min_angle>-0.09</min_angle><max_angle>0.09</max_angle>"
    scan = f"<lidar><scan><horizontal>{grid}</horizontal><vertical>{grid}</vertical></scan></lidar>"
    found = kinds(
        builders.gazebo_sensor("ir_front", "gpu_lidar", "ir_intensity_front", scan),
        builders.gazebo_sensor("sonar_rear", "gpu_lidar", "sonar_rear", scan),
        ray("laser", "rplidar", 720, 6.28, 12.0),
    )
    assert found == [("ir_range", None, 1), ("sonar", None, 1), ("lidar", "LIDAR", 1)]


def test_a_one_ray_rangers_own_topic_says_its_device_before_its_one_ray_does() -> None:
    # Gazebo Sim's one-ray gpu_lidar named for nothing, publishing on `.../sonar`: a sonar; with
    # a topic that names nothing, a range finder by its one ray. A camera publishing on a depth
    # topic stays a camera (topics are what a device feeds, read for rangers only).
    one_ray = "<lidar><scan><horizontal><samples>1</samples></horizontal></scan></lidar>"
    found = kinds(
        builders.gazebo_sensor(
            "front", "gpu_lidar", "gpu_lidar", f"<topic>model/r/sonar</topic>{one_ray}"
        ),
        builders.gazebo_sensor(
            "rear", "gpu_lidar", "gpu_lidar_2", f"<topic>model/r/range</topic>{one_ray}"
        ),
        builders.gazebo_sensor("eye", "camera", "eye", "<topic>eye/depth/image</topic>"),
    )
    assert found == [("sonar", None, 1), ("ir_range", None, 1), ("camera", "2D Camera", 1)]


def test_an_ultrasonic_rangers_name_cut_short_still_says_sonar() -> None:
    # A farm robot's four ultrasonic rangers as gpu_lidars of ten rays over 60 degrees,
    # reaching 4 m: `US1_sensor` on `US1_scan_link`, `ultra_front`. A word holding the letters
    # (`status`, `bus_link`, `ultralight`) is no such name.
    found = kinds(
        ray("US1_scan_link", "US1_sensor", 10, 1.04, 4.0),
        ray("front_link", "ultra_front", 10, 1.04, 4.0),
        ray("bus_link", "ultralight_status", 10, 1.04, 4.0),
    )
    assert found == [("sonar", None, 2), ("lidar", "LIDAR", 1)]


def hardware_sensor(name: str, *readings: str, frame: str = "") -> str:
    """A ``<ros2_control>`` system with one ``<sensor>`` reading ``readings``."""
    states = "".join(f'<state_interface name="{reading}"/>' for reading in readings)
    param = f'<param name="frame_id">{frame}</param>' if frame else ""
    return (
        '<ros2_control name="hw" type="system"><hardware><plugin>mock</plugin></hardware>'
        f'<sensor name="{name}">{states}{param}</sensor></ros2_control>'
    )


WRENCH = ("force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z")


def test_a_ros2_control_sensor_is_told_by_what_it_reads() -> None:
    found = kinds(
        hardware_sensor("wrist", *WRENCH, frame="flange"),
        hardware_sensor("left_load_cell", "force"),  # a gripper's one-axis load cell
        hardware_sensor("body", "orientation.x", "angular_velocity.x", "linear_acceleration.x"),
        hardware_sensor("tcp_pose", "position.x", "orientation.w"),  # a pose: computed
        hardware_sensor("external_wrench_in_base", *WRENCH),  # the controller's estimate
        hardware_sensor("estimated_tcp_wrench", *WRENCH),
        hardware_sensor("battery", "voltage"),
    )
    assert sorted(found) == [("force_torque", "Force Sensor", 2), ("imu", None, 1)]


def rendered_camera(name: str, *topics: str) -> str:
    """A ``<ros2_control>`` system with one ``<sensor>`` naming ``topics`` (parameters
    ``<topic>_topic``), as mujoco_ros2_control declares a camera it renders."""
    params = "".join(f'<param name="{t}_topic">/{name}/{t}</param>' for t in topics)
    return (
        f'<ros2_control name="{name}_sim" type="system">'
        "<hardware><plugin>mujoco</plugin></hardware>"
        f'<sensor name="{name}"><param name="frame_name">{name}_frame</param>{params}'
        "</sensor></ros2_control>"
    )


def test_a_ros2_control_sensor_naming_where_its_images_go_is_a_camera_a_simulator_renders() -> None:
    found = kinds(
        rendered_camera("front", "info", "image", "depth"),
        rendered_camera("rear", "image"),
        rendered_camera("mast", "info"),  # no image topic: told by its name, and it says nothing
    )
    assert sorted(found) == [("camera", "2D Camera", 1), ("depth_camera", "RGB-D Camera", 1)]


def test_a_rendered_camera_naming_its_point_cloud_is_a_depth_camera_and_a_scan_a_lidar() -> None:
    # A fork of mujoco_ros2_control renders a camera's depth as a cloud (``pointcloud_topic``,
    # no image topic); its rangefinder lidar names its scan's settings and topic.
    lidar = rendered_camera("mast", "laserscan").replace(
        "</sensor>", '<param name="angle_increment">0.01</param></sensor>'
    )
    # One angle alone is any sensor's setting (an encoder's range): no lidar by it.
    angle = rendered_camera("dial").replace(
        "</sensor>", '<param name="min_angle">-1.0</param></sensor>'
    )
    found = kinds(
        rendered_camera("left", "pointcloud"),
        rendered_camera("right", "pointcloud"),
        rendered_camera("front", "depth"),
        lidar,
        angle,
    )
    assert sorted(found) == [("depth_camera", "RGB-D Camera", 3), ("lidar", "LIDAR", 1)]


def test_a_ros2_control_sensor_whose_readings_say_nothing_is_told_by_its_name() -> None:
    """A hand's fingertip sensors read x, y, z and its palm's ranger a value (a MuJoCo hand's
    ros2_control): their names say what they are; a name that says nothing adds none."""
    found = kinds(
        hardware_sensor("thumb_tip_force", "x", "y", "z"),
        hardware_sensor("index_tip_force", "x", "y", "z"),
        hardware_sensor("palm_range", "value"),
        hardware_sensor("status_word", "value"),
    )
    assert sorted(found) == [("force_torque", "Force Sensor", 2), ("ir_range", None, 1)]


def test_a_ros2_control_magnetometer_pressure_gauge_and_named_dvl_are_read() -> None:
    found = kinds(
        hardware_sensor("compass", "magnetic_field.x", "magnetic_field.y"),
        hardware_sensor("depth", "fluid_pressure"),
        hardware_sensor("dvl_sensor", "linear_velocity.x", "angular_velocity.x", "distance_z"),
        hardware_sensor("wheel_odometry", "linear_velocity.x"),  # odometry: no device of a kind
    )
    assert sorted(kind for kind, _, _ in found) == ["barometer", "dvl", "magnetometer"]


def test_a_ros2_control_sensor_block_reading_an_attitude_through_joints_is_an_imu() -> None:
    # A balancing robot's IMU chip, its roll, pitch and yaw written on the wheels' joints.
    states = (
        '<state_interface name="yaw"/><state_interface name="pitch"/><state_interface name="roll"/>'
    )
    gyro = (
        '<ros2_control name="Gyro" type="sensor"><hardware><plugin>hw/ICM20948</plugin>'
        f'</hardware><joint name="left_wheel">{states}</joint>'
        f'<joint name="right_wheel">{states}</joint></ros2_control>'
    )
    assert kinds(gyro) == [("imu", None, 1)]
    # A sensor block reading only its joints' positions is an encoder's: no device.
    encoder = gyro.replace(states, '<state_interface name="position"/>')
    assert kinds(encoder) == []
    # A system's joints read their own motion, whatever their interfaces are named.
    assert kinds(gyro.replace('type="sensor"', 'type="system"')) == []


def test_a_ros2_control_device_named_external_is_still_a_device() -> None:
    # An IMU or a force sensor mounted outside the robot's body: external, measured.
    found = kinds(
        hardware_sensor("external_imu", "angular_velocity.x", "linear_acceleration.x"),
        hardware_sensor("external_ft_sensor", *WRENCH),
    )
    assert sorted(found) == [("force_torque", "Force Sensor", 1), ("imu", None, 1)]


def test_twenty_thousand_force_sensors_on_one_link_are_told_apart_in_linear_time() -> None:
    # Each is compared with the names and sources kept so far, as sets (pair by pair, 14 s).
    sensors = "".join(
        builders.gazebo_sensor("base_link", "force_torque", f"ft{i}") for i in range(20_000)
    )
    assert kinds(sensors) == [("force_torque", "Force Sensor", 20_000)]


def test_a_ros2_control_sensor_that_names_a_device_declared_elsewhere_adds_none() -> None:
    found = kinds(
        builders.gazebo_sensor("imu_link", "imu", "imu_sensor"),
        hardware_sensor("imu_sensor", "orientation.x", "angular_velocity.x"),
        hardware_sensor("ft", *WRENCH),
    )
    assert sorted(found) == [("force_torque", "Force Sensor", 1), ("imu", None, 1)]


def test_a_sensor_on_an_sdf_link_a_gazebo_block_adds_is_the_models() -> None:
    # PX4's models insert a GPS on a link of its own, written in SDF inside <gazebo>.
    found = kinds(
        '<gazebo><link name="gps0_link"><pose>0 0 0 0 0 0</pose>'
        '<sensor name="gps" type="gps">'
        '<plugin filename="libgazebo_gps_plugin.so" name="gps_plugin"/></sensor></link></gazebo>'
    )
    assert found == [("gps", None, 1)]
    nested = kinds(
        '<gazebo><model name="gps0"><link name="link">'
        '<sensor name="gps" type="gps"><plugin filename="libgazebo_gps_plugin.so" name="g"/>'
        '</sensor></link></model><joint name="gps0_joint" type="fixed"><parent>base_link</parent>'
        "<child>gps0::link</child></joint></gazebo>"
    )
    assert nested == [("gps", None, 1)]  # PX4's: a model of its own, joined to the body


def test_a_sensor_written_inside_a_urdf_link_as_sdf_writes_it_is_that_links() -> None:
    found = kinds(
        '<link name="imu_link"><sensor name="imu_sensor" type="imu"><always_on>true</always_on>'
        '</sensor><sensor name="imager" type="camera"><camera/></sensor></link>'
    )
    assert sorted(found) == [("camera", "2D Camera", 1), ("imu", None, 1)]


def test_a_sensor_declared_inside_its_link_and_again_in_gazebo_counts_once() -> None:
    found = kinds(
        '<link name="cam_link"><sensor name="cam_a" type="camera"><camera/></sensor></link>'
        '<gazebo reference="cam_link"><sensor name="camera_sensor" type="camera"><camera/>'
        "</sensor></gazebo>"
    )
    assert found == [("camera", "2D Camera", 1)]


def test_two_nested_gps_models_are_two_gps_and_links_inside_sensors_are_no_models_links() -> None:
    two = kinds(
        '<gazebo><model name="gps0"><link name="link"><sensor name="gps" type="gps"/></link>'
        '</model><model name="gps1"><link name="link"><sensor name="gps" type="gps"/></link>'
        "</model></gazebo>"
    )
    assert two == [("gps", None, 2)]
    # 120 links and sensors nested in one another: a stranger's file is read once, its first.
    nested = "".join(f'<link name="l{i}"><sensor name="s{i}" type="camera">' for i in range(120))
    nested += "</sensor></link>" * 120
    assert kinds(f"<gazebo>{nested}</gazebo>") == [("camera", "2D Camera", 1)]


def test_a_dvl_on_the_hull_and_its_beams_on_frames_below_it_are_one_device() -> None:
    from tests.identify.builders import RobotText, gazebo_sensor, model_plugin

    auv = RobotText("auv")
    dvl = auv.fixed(auv.root, "dvl_link")
    for i in range(4):
        auv.fixed(dvl, f"dvl_beam{i}_link")
        auv.add(gazebo_sensor(f"dvl_beam{i}_link", "ray", f"dvl_beam{i}"))
    # The DVL plugin names the hull (the root), not the beams' frame.
    auv.add(
        model_plugin("dvl", "libuuv_gazebo_ros_dvl_plugin.so", "<link_name>base_link</link_name>")
    )
    assert _kinds(auv.text())["dvl"] == 1
    # On a body a joint moves apart from the hull, another DVL is another device.
    turret = auv.chain(auv.root, ["turret"])
    auv.add(gazebo_sensor(turret, "ray", "dvl_up"))
    assert _kinds(auv.text())["dvl"] == 2


def test_two_dvls_declared_as_such_are_two_devices() -> None:
    from tests.identify.builders import RobotText, gazebo_sensor

    auv = RobotText("auv")
    for side in ("down", "up"):
        auv.fixed(auv.root, f"dvl_{side}_link")
        auv.add(gazebo_sensor(f"dvl_{side}_link", "dvl", f"dvl_{side}", plugin=f"libdvl_{side}.so"))
    assert _kinds(auv.text())["dvl"] == 2


def test_a_ray_sensor_plugin_outside_any_sensor_element_is_told_by_its_names_and_topics() -> None:
    # libgazebo_ros_ray_sensor.so written straight under <gazebo> says nothing of its rays:
    # what it publishes tells a range finder, an ultrasonic one a sonar, a scan (even in a
    # frame named for a range finder) or nothing a lidar. Another plugin that only says it is a
    # sensor stays one of unknown kind, whatever its topics say (a wheel encoder's distance,
    # a contact sensor named for a simulation).
    robot = builders.ugv()
    ray = "libgazebo_ros_ray_sensor.so"
    for name, params in [
        ("tof_left_plugin", "<ros><remapping>range:=/distance/left</remapping></ros>"),
        ("tof_right_plugin", "<output_type>sensor_msgs/Range</output_type>"),
        ("front_plugin", "<ros><remapping>range:=/ultrasonic/front</remapping></ros>"),
        (
            "hokuyo_plugin",
            "<output_type>sensor_msgs/LaserScan</output_type>"
            "<frame_name>laser_range_finder</frame_name>",
        ),
    ]:
        robot.add(builders.model_plugin(name, ray, params))
    robot.add(
        builders.model_plugin(
            "encoder", "libwheel_encoder_sensor.so", "<topic>wheel/distance</topic>"
        )
    )
    robot.add(builders.model_plugin("bumper_simulation", "libcontact_sensor.so"))
    assert _kinds(robot.text()) == {"ir_range": 2, "sonar": 1, "lidar": 1, "unknown": 2}


def test_an_imu_declared_for_gazebo_again_as_an_accelerometer_and_its_plugin_outside_is_one() -> (
    None
):
    # iCub-style descriptions declare each IMU three times: a Gazebo <sensor type="imu"> running
    # a plugin, a URDF <sensor type="accelerometer"> of the same name on the same link, and the
    # same plugin (name, file, settings) again outside any sensor. One device; an accelerometer
    # alone is an IMU's part, an IMU; a different plugin outside is a device of its own.
    robot = builders.ugv()
    robot.fixed(robot.root, "head")
    config = "<yarpConfigurationFile>model://bot/conf/head_inertial.ini</yarpConfigurationFile>"
    plugin = f'<plugin name="yarp_imu" filename="libgazebo_yarp_imu.so">{config}</plugin>'
    robot.add(
        f'  <gazebo reference="head"><sensor name="head_imu" type="imu">{plugin}</sensor></gazebo>'
    )
    robot.add('  <sensor name="head_imu" type="accelerometer"><parent link="head"/></sensor>')
    robot.add(f"  <gazebo>{plugin}</gazebo>")
    assert _kinds(robot.text()) == {"imu": 1}
    waist = plugin.replace("head_inertial", "waist_inertial")
    robot.add(f"  <gazebo>{waist}</gazebo>")
    assert _kinds(robot.text()) == {"imu": 2}


def test_accelerometers_declared_apart_on_one_link_are_as_many_imus_and_a_gyroscope_pairs_up() -> (
    None
):
    # A skin's boards each carry an accelerometer: iDynTree-style descriptions declare each as a
    # URDF <sensor type="accelerometer"> with a Gazebo <sensor type="imu"> twin of its name. Three
    # on a forearm are three devices; a gyroscope beside one of them is that board's, and a
    # chest's accelerometer and gyroscope are one IMU.
    robot = builders.ugv()
    robot.fixed(robot.root, "forearm")
    robot.fixed(robot.root, "chest")
    for link, name, part in [
        ("forearm", "forearm_acc_1", "accelerometer"),
        ("forearm", "forearm_acc_2", "accelerometer"),
        ("forearm", "forearm_acc_3", "accelerometer"),
        ("forearm", "forearm_gyro_1", "gyroscope"),
        ("chest", "chest_acc", "accelerometer"),
        ("chest", "chest_gyro", "gyroscope"),
    ]:
        twin = f'<sensor name="{name}" type="imu"><always_on>1</always_on></sensor>'
        robot.add(f'  <gazebo reference="{link}">{twin}</gazebo>')
        robot.add(f'  <sensor name="{name}" type="{part}"><parent link="{link}"/></sensor>')
    assert _kinds(robot.text()) == {"imu": 4}


def lidars_at(*mounts: tuple[str, str, str]) -> dict[str, int]:
    """A base carrying one lidar ``<sensor>`` on each of ``mounts`` (a frame, its origin's xyz
    and rpy, fixed to the base), as two lidar macros included at one mount write it."""
    robot = builders.ugv()
    for frame, xyz, rpy in mounts:
        robot.joint(
            f"{frame}_joint", "fixed", robot.root, frame, f'<origin xyz="{xyz}" rpy="{rpy}"/>'
        )
        robot.add(builders.gazebo_sensor(frame, "ray", frame))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_one_lidar_declared_on_two_frames_at_one_place_is_one_device() -> None:
    # Two frames 7 mm apart facing forward: no two lidars fit there.
    twins = lidars_at(
        ("lidar_link", "0.074 -0.04 0.0845", "0 0 0"), ("laser", "0.074 -0.04 0.0775", "0 0 0")
    )
    assert twins == {"lidar": 1}


def cameras_at_one_mount(*fovs: float) -> dict[str, int]:
    """A base carrying cameras of the fields of view ``fovs`` (radians), each on a frame of its
    own, all at one place facing one way (a sensor kit whose calibration is still a guess)."""
    robot = builders.ugv()
    for i, fov in enumerate(fovs):
        frame = f"camera_{i}_link"
        robot.joint(f"camera_{i}_joint", "fixed", robot.root, frame, '<origin xyz="0.3 0 0.3"/>')
        lens = f"<camera><horizontal_fov>{fov}</horizontal_fov></camera>"
        robot.add(builders.gazebo_sensor(frame, "camera", f"camera_{i}", lens))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_a_narrow_and_a_wide_camera_at_one_mount_are_two_one_declared_twice_is_one() -> None:
    assert cameras_at_one_mount(0.52, 2.1) == {"camera": 2}
    assert cameras_at_one_mount(1.2, 1.2) == {"camera": 1}


def test_lidars_a_hand_apart_or_facing_apart_at_one_place_are_two() -> None:
    stacked = lidars_at(("lidar_2d", "0 0 0.2", "0 0 0"), ("lidar_3d", "0 0 0.3", "0 0 0"))
    assert stacked == {"lidar": 2}
    back_to_back = lidars_at(
        ("front_laser", "0 0 0.2", "0 0 0"), ("rear_laser", "0 0 0.2", "0 0 3.14159")
    )
    assert back_to_back == {"lidar": 2}


def lidars_on_a_turret_and_below_it(turret: str) -> dict[str, int]:
    """A base with a turret on a joint of type ``turret`` 0.2 m up, one lidar fixed on the
    turret 0.1 m out and one fixed on the base at that same place."""
    robot = builders.ugv()
    robot.joint(
        "turret",
        turret,
        robot.root,
        "turret_link",
        '<origin xyz="0 0 0.2"/><axis xyz="0 0 1"/>',
    )
    robot.joint(
        "turret_lidar_joint", "fixed", "turret_link", "turret_lidar", '<origin xyz="0.1 0 0"/>'
    )
    robot.joint("base_lidar_joint", "fixed", robot.root, "base_lidar", '<origin xyz="0.1 0 0.2"/>')
    robot.add(builders.gazebo_sensor("turret_lidar", "ray", "turret_lidar"))
    robot.add(builders.gazebo_sensor("base_lidar", "ray", "base_lidar"))
    return {s.kind: s.count for s in identify_urdf(robot.text()).sensors}


def test_a_lidar_on_a_turret_and_one_on_the_base_below_it_are_two() -> None:
    # One place at rest, two bodies: the turret's lidar turns with it.
    assert lidars_on_a_turret_and_below_it("continuous") == {"lidar": 2}
    # The turret welded fast: one body, one place, one lidar declared twice.
    assert lidars_on_a_turret_and_below_it("fixed") == {"lidar": 1}


def test_a_ring_of_cameras_at_one_point_facing_apart_is_as_many_cameras() -> None:
    robot = builders.ugv()
    for i in range(8):
        robot.joint(
            f"cam{i}_joint",
            "fixed",
            robot.root,
            f"cam{i}",
            f'<origin xyz="0 0 0.5" rpy="0 0 {i * 0.785398}"/>',
        )
        robot.add(builders.gazebo_sensor(f"cam{i}", "camera", f"cam{i}"))
    assert {s.kind: s.count for s in identify_urdf(robot.text()).sensors} == {"camera": 8}


def test_ten_thousand_lidars_at_one_place_facing_two_ways_are_two_in_linear_time() -> None:
    # Each frame is compared with the first kept frames of the cells around it (pair by pair
    # with every kept frame, a stranger's crowd of frames facing apart would cost n squared).
    mounts = [(f"laser{i}", "0 0 0.5", f"0 0 {3.14159 * (i % 2)}") for i in range(10_000)]
    assert lidars_at(*mounts) == {"lidar": 2}


def test_gazebo_sims_label_cameras_beside_a_camera_are_no_devices() -> None:
    # A bounding-box or segmentation camera draws the simulator's labels: ground truth.
    robot = builders.ugv()
    robot.fixed(robot.root, "camera_optical_frame")
    for kind, name in (
        ("camera", "front"),
        ("boundingbox_camera", "bb_front"),
        ("segmentation_camera", "seg_front"),
    ):
        robot.add(builders.gazebo_sensor("camera_optical_frame", kind, name))
    assert {s.kind: s.count for s in identify_urdf(robot.text()).sensors} == {"camera": 1}
