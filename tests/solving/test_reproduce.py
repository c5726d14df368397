"""The article's figures beside a selection made by hand."""

from __future__ import annotations

from solver.core.team import parse_team
from solver.files.yamlio import parse_document
from solver.solving.reproduce import published_for

CASE_3_BY_HAND = """\
name: my design
team:
  Humanoid:
    motion_control: [Joint, Walking, Waypoint]
    sensor_type: [2D Camera, 3D Camera, LIDAR, RGB-D Camera, Speaker, Microphone]
    sensor_count: 25
  UAV:
    motion_control: [Waypoint, Flight]
    sensor_type: [2D Camera, 360 Camera, RGB-D Camera]
    sensor_count: 5
  UGV:
    motion_control: [Driving, Waypoint]
    sensor_type: [2D Camera, LIDAR, Speaker, Microphone]
    sensor_count: {max: 10}
  Mobile Manipulator:
    motion_control: [Joint, Driving, End Effector, Waypoint]
    sensor_type: [2D Camera, RGB-D Camera, LIDAR, Speaker, Microphone, Force Sensor]
    sensor_count: 13
"""


def test_case_3_selected_by_hand_gets_the_articles_published_figures() -> None:
    team = parse_team(parse_document(CASE_3_BY_HAND, "mine.yaml"))
    published = published_for(team)
    assert published is not None
    assert (published.valid_robots, published.ui_configurations) == (820, 99)


def test_a_selection_the_article_did_not_publish_gets_none() -> None:
    text = CASE_3_BY_HAND.replace("sensor_count: 25", "sensor_count: 24")
    assert published_for(parse_team(parse_document(text, "mine.yaml"))) is None
