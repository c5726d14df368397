"""A robot's real topics in its layout's panels (solver.layouts.topics): each panel takes a topic
of a type its component lists and a direction that fits, one named like the template first,
one topic a tile; a panel left without one keeps the presentation's topic, with a warning."""

from __future__ import annotations

from solver.layouts.presentation import PanelSpec
from solver.layouts.topics import match_topics
from solver.ros.names import Topic

CAMERAS = PanelSpec("visual display", "Image", "<robot>/image_raw", ("sensor_msgs/msg/Image",))
PAD = PanelSpec("Flight", "Teleop", "<robot>/cmd_vel", ("geometry_msgs/Twist",))
DRIVE = PanelSpec("Driving", "Teleop", "<robot>/cmd_vel", ("geometry_msgs/Twist",))


def test_a_sensor_panel_takes_published_topics_of_its_type_the_templates_name_first() -> None:
    topics = [
        Topic("/r/a_camera", "sensor_msgs/Image", "published"),
        Topic("/r/front/image_raw", "sensor_msgs/Image", "published"),
        Topic("/r/sink/image_raw", "sensor_msgs/Image", "subscribed"),  # the robot reads it
        Topic("/r/scan", "sensor_msgs/LaserScan", "published"),
    ]
    chosen, warnings = match_topics([(CAMERAS, 2)], topics, "robot.topics", "/r")
    assert chosen == {
        ("visual display", 0): Topic("/r/front/image_raw", "sensor_msgs/Image", "published"),
        ("visual display", 1): Topic("/r/a_camera", "sensor_msgs/Image", "published"),
    }
    assert warnings == ()


def test_a_tile_left_without_a_topic_keeps_the_presentations_with_a_located_warning() -> None:
    topics = [Topic("/r/front/image_raw", "sensor_msgs/Image", None)]  # direction unknown: fits
    chosen, warnings = match_topics([(CAMERAS, 2)], topics, "robot.topics", "/r")
    assert list(chosen) == [("visual display", 0)]
    (warning,) = warnings
    assert str(warning) == (
        "robot.topics: visual display 2: the robot has no published topic of type "
        "sensor_msgs/Image for this Image panel; it keeps the presentation's topic "
        "/r/image_raw_2"
    )


def test_command_pads_on_one_template_share_the_robots_one_command_topic() -> None:
    twist = Topic("/r/cmd_vel", "geometry_msgs/Twist", "subscribed")
    chosen, warnings = match_topics([(PAD, 1), (DRIVE, 1)], [twist], "robot.topics", "/r")
    assert chosen == {("Flight", 0): twist, ("Driving", 0): twist}
    assert warnings == ()


def test_a_topic_the_robot_publishes_is_never_a_command_panels() -> None:
    published = Topic("/r/cmd_vel", "geometry_msgs/Twist", "published")
    chosen, warnings = match_topics([(PAD, 1)], [published], "robot.topics", "/r")
    assert chosen == {}
    assert [w.message.split(";")[0] for w in warnings] == [
        "the robot has no subscribed topic of type geometry_msgs/Twist for this Teleop panel"
    ]
