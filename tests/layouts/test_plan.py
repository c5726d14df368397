"""A layout's plan: which panels, named how, on which topics, for a template or a robot."""

from __future__ import annotations

import pytest

from solver import load_team, solve
from solver.errors import InputError
from solver.layouts import Robot, load_presentation
from solver.layouts.plan import check_namespace, plan_layout, template_topic
from solver.layouts.presentation import PanelSpec
from solver.ros.names import Topic
from tests.handcounted import SMALL_RULES, team_of

CAMERA = PanelSpec("visual display", "Image", "<robot>/camera/image_raw", ("sensor_msgs/Image",))


def test_a_template_topic_is_full_in_the_root_namespace_relative_or_under_a_namespace() -> None:
    assert template_topic(CAMERA, None, 0) == "/camera/image_raw"
    assert template_topic(CAMERA, None, 0, relative=True) == "camera/image_raw"
    assert template_topic(CAMERA, "/uav1", 0) == "/uav1/camera/image_raw"
    assert template_topic(CAMERA, "/uav1", 0, relative=True) == "/uav1/camera/image_raw"


def test_tiles_after_the_first_are_numbered_from_two() -> None:
    assert [template_topic(CAMERA, "/r", tile) for tile in range(3)] == [
        "/r/camera/image_raw",
        "/r/camera/image_raw_2",
        "/r/camera/image_raw_3",
    ]


def test_a_template_without_the_robot_is_absolute_as_written_or_relative_to_the_robot() -> None:
    tf = PanelSpec("frames", "3D", "/tf", ())
    scan = PanelSpec("scanner", "3D", "scan", ())
    assert template_topic(tf, "/r", 0) == "/tf"
    assert template_topic(scan, "/r", 0) == "/r/scan"
    assert template_topic(scan, None, 0) == "/scan"
    assert template_topic(scan, None, 0, relative=True) == "scan"


def test_a_rule_set_clustering_coarser_than_the_cap_gets_clusters_of_at_most_25_sensors() -> None:
    # A rule set of its own: clusters of 1000 sensors. 625 sensors are shown (25 clusters of
    # 25, docs/layouts.md), never one Tab panel of 625 tabs.
    rules = SMALL_RULES.replace("max: 6}\n", "max: 1000}\n").replace(
        "max: 6, cluster_size: 2", "max: 1000, cluster_size: 1000"
    )
    solution = solve(team_of("name: t\nteam:\n  UGV: {sensor_count: [1000]}\n", rules))
    plan = plan_layout(solution, solution.configurations[0], load_presentation())
    clusters = [panel.cluster for panel in plan.panels if panel.cluster]
    assert len(clusters) == 625
    assert sorted(set(clusters)) == list(range(1, 26))
    assert {clusters.count(number) for number in range(1, 26)} == {25}


def test_velocity_components_on_one_topic_are_one_panel_named_after_each() -> None:
    solution = solve(load_team("case3"))
    plan = plan_layout(solution, None, load_presentation(), Robot("/h1"))
    pads = [(panel.name, panel.topic) for panel in plan.panels if panel.kind == "Teleop"]
    assert pads == [("Flight, Driving, Walking", "/h1/cmd_vel")]
    assert plan.namespace == "/h1"
    assert [panel.name for panel in plan.goals] == ["End Effector", "Waypoint"]


def test_real_topics_outside_the_given_namespace_make_the_namespace_they_share() -> None:
    solution = solve(load_team("case1"))
    configuration = solution.configurations[0]  # Flight, visual display
    real = {
        ("Flight", 0): Topic("/px4/cmd_vel", "geometry_msgs/msg/Twist"),
        ("visual display", 0): Topic("/px4/front/image", "sensor_msgs/msg/Image"),
    }
    robot = Robot("/uav1", real)
    plan = plan_layout(solution, configuration, load_presentation(), robot, tile_count=1)
    assert [(p.topic, p.types, p.real) for p in plan.panels] == [
        ("/px4/cmd_vel", ("geometry_msgs/msg/Twist",), True),
        ("/px4/front/image", ("sensor_msgs/msg/Image",), True),
    ]
    assert plan.namespace == "/px4"
    assert plan.topic("clicked_point") == "/px4/clicked_point"


def test_a_relative_template_spells_the_robots_own_topics_relative() -> None:
    solution = solve(load_team("case1"))
    plan = plan_layout(solution, None, load_presentation(), relative=True)
    assert plan.namespace == ""
    assert plan.topic("robot_description") == "robot_description"
    assert all(not panel.topic.startswith("/") for panel in plan.panels)


@pytest.mark.parametrize(
    ("given", "namespace"),
    [("/robot1", "/robot1"), ("/robot1/", "/robot1"), ("/", ""), ("/a/b", "/a/b")],
)
def test_a_namespace_is_a_full_ros2_name(given: str, namespace: str) -> None:
    assert check_namespace(given, "--namespace") == namespace


@pytest.mark.parametrize(
    ("given", "problem"),
    [
        ("robot1", "is not absolute"),
        ("/my-robot", "has a character other than a letter"),
        ("/2nd", "has a name part starting with a digit"),
        ("", "is empty"),
    ],
)
def test_a_namespace_that_is_no_ros2_name_is_a_located_error(given: str, problem: str) -> None:
    with pytest.raises(InputError) as caught:
        check_namespace(given, "--namespace")
    assert str(caught.value).startswith("--namespace: ")
    assert problem in str(caught.value)
