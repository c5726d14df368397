"""Identification from text (solver.identify.identification): its cache, topics that confirm
what a description can only guess, and mutated URDFs identified or refused."""

from __future__ import annotations

from hypothesis import given

from solver.errors import SolverError
from solver.files.yamlio import parse_document
from solver.identify import (
    IdentificationCache,
    Topic,
    TopicSource,
    content_key,
    identify_urdf,
    load_profile,
)
from solver.ros.description import TeleopDescription, parse_description
from tests.hostile import FUZZ, mutations
from tests.identify import builders


def test_the_cache_answers_the_same_content_without_identifying_again() -> None:
    cache = IdentificationCache(maxsize=2)
    first = cache.identify_urdf(builders.sensing_rover())
    again = cache.identify_urdf(builders.sensing_rover().encode("utf-8"))
    assert again is first
    assert (cache.hits, cache.misses) == (1, 1)
    cache.identify_urdf(builders.quadrotor().text())
    cache.identify_urdf(builders.manipulator().text())
    assert len(cache) == 2


def test_the_content_key_changes_with_every_input() -> None:
    text = builders.sensing_rover()
    topics = [TopicSource("master", (Topic("/cmd_vel", "geometry_msgs/Twist"),))]
    keys = {
        content_key(text),
        content_key(text + " "),
        content_key(text, srdf_text="<robot/>"),
        content_key(text, topics=topics),
        content_key(text, profile=load_profile()),
    }
    assert len(keys) == 5


def test_topics_confirm_the_waypoint_a_description_can_only_guess() -> None:
    topics = [
        TopicSource(
            "live",
            (
                Topic("/move_base/goal", "move_base_msgs/MoveBaseActionGoal"),
                Topic("/scan", "sensor_msgs/LaserScan", "published"),
            ),
        )
    ]
    result = identify_urdf(builders.sensing_rover(), topics=topics)
    assert [(c.motion_control, c.source) for c in result.motion_controls] == [
        ("Driving", "urdf: drive plugin libgazebo_ros_diff_drive.so"),
        (
            "Waypoint",
            "urdf: likely, not declared: Driving and a lidar sensor, what navigation needs; "
            "live: /move_base/goal (move_base_msgs/MoveBaseActionGoal)",
        ),
    ]
    lidar = result.sensors[0]
    assert (lidar.kind, lidar.count, lidar.source) == ("lidar", 1, "urdf: laser; live: /scan")


@FUZZ
@given(data=mutations(builders.ugv().text().encode()))
def test_mutated_urdfs_are_identified_or_refused(data: bytes) -> None:
    try:
        identify_urdf(data, file="fuzz.urdf")
    except SolverError as error:
        message = str(error)
    else:
        return
    assert message.startswith("fuzz.urdf")


def test_an_srdf_cut_short_is_a_located_warning_the_urdf_read_alone() -> None:
    srdf = '<?xml version="1.0"?>\n<robot name="arm6">\n<group name="arm">\n'
    result = identify_urdf(builders.manipulator().text(), srdf_text=srdf, srdf_file="arm6.srdf")
    assert result.structure == "Manipulator"
    (warning,) = result.warnings
    assert warning.location.file == "arm6.srdf"
    assert warning.message.endswith("(the SRDF is not read; the URDF alone is)")


def test_a_comment_xml_rejects_and_ros_reads_is_a_located_warning_and_read_on() -> None:
    # "--" inside a comment is not XML; ROS's URDF parser (TinyXML2) reads it.
    srdf = '<?xml version="1.0"?>\n<robot name="arm6">\n<!-- set up -- by hand --->\n</robot>\n'
    urdf = builders.manipulator().text().replace("<robot", "<!-- made -- by hand -->\n<robot", 1)
    result = identify_urdf(urdf, srdf_text=srdf, srdf_file="arm6.srdf")
    assert result.structure == "Manipulator"
    assert [(w.location.file, w.location.line, w.code) for w in result.warnings] == [
        ("<string>", 2, "xml-comment"),
        ("arm6.srdf", 3, "xml-comment"),
    ]


def test_the_cache_tells_robots_apart_by_their_declared_description() -> None:
    def declared(control: str) -> TeleopDescription:
        text = f"teleop: 1\nmotion_controls:\n  - {{control: {control}, topic: /cmd_vel}}\n"
        return parse_description(parse_document(text, "r.teleop.yaml"))

    cache = IdentificationCache()
    text = builders.ugv().text()
    plain = cache.identify_urdf(text)
    flying = cache.identify_urdf(text, description=declared("Flight"))
    again = cache.identify_urdf(text, description=declared("Flight"))
    assert [c.motion_control for c in plain.motion_controls] == ["Driving"]
    assert [c.motion_control for c in flying.motion_controls] == ["Flight"]
    assert again is flying
    assert (cache.misses, cache.hits) == (2, 1)
