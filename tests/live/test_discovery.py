"""Robots and their topics from what a master reports (getParamNames, getSystemState, ...)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from solver.identify.profile import Profile
from solver.live.discovery import (
    RobotSource,
    discover,
    normalise_namespace,
    robot_namespaces,
    robot_topics,
)
from solver.live.graph import Observation
from solver.ros.names import Topic

# Pure functions, but a loaded machine can take longer than hypothesis's default 200 ms for an
# example: no deadline (durations are measured by the benchmarks, not asserted by tests).
NO_DEADLINE = settings(deadline=None)

IMAGE = "sensor_msgs/Image"
TWIST = "geometry_msgs/Twist"
SCAN = "sensor_msgs/LaserScan"


def observation(
    publishers: dict[str, list[str]],
    subscribers: dict[str, list[str]],
    types: dict[str, str],
    params: list[str],
) -> Observation:
    return Observation(
        pid=1,
        publishers=tuple((t, tuple(n)) for t, n in sorted(publishers.items())),
        subscribers=tuple((t, tuple(n)) for t, n in sorted(subscribers.items())),
        topic_types=tuple(sorted(types.items())),
        param_names=tuple(sorted(params)),
    )


def test_every_namespace_with_a_robot_description_is_a_robot_the_root_too() -> None:
    names = [
        "/robot_description",
        "/uav1/robot_description",
        "/team/ugv1/robot_description",
        "/uav1/robot_description_semantic",
        "/robot_description_x",
        "/rosdistro",
        "/arm/robot_description/extra",
    ]
    assert robot_namespaces(names) == ("/", "/team/ugv1", "/uav1")


def test_namespaces_are_normalised_to_absolute_names_without_a_trailing_slash() -> None:
    assert [normalise_namespace(t) for t in ("uav1", "/uav1/", "", "/", "//a//b/")] == [
        "/uav1",
        "/uav1",
        "/",
        "/",
        "/a/b",
    ]


_segment = st.from_regex(r"[a-z][a-z0-9_]{0,6}", fullmatch=True)
_namespace = st.lists(_segment, max_size=3).map(lambda parts: "/" + "/".join(parts))


@NO_DEADLINE
@given(st.lists(_namespace, max_size=6))
def test_robot_namespaces_are_exactly_those_with_a_description(namespaces: list[str]) -> None:
    names = [ns.rstrip("/") + "/robot_description" for ns in namespaces]
    names += [ns.rstrip("/") + "/other" for ns in namespaces]
    assert robot_namespaces(names) == tuple(sorted(set(namespaces)))


def test_the_robots_own_nodes_decide_the_direction(profile: Profile) -> None:
    seen = observation(
        publishers={"/uav1/cmd_vel": ["/teleop"], "/uav1/camera/image_raw": ["/uav1/camera"]},
        subscribers={"/uav1/cmd_vel": ["/uav1/base"], "/uav1/camera/image_raw": ["/rviz"]},
        types={"/uav1/cmd_vel": TWIST, "/uav1/camera/image_raw": IMAGE},
        params=["/uav1/robot_description"],
    )
    assert robot_topics(("/uav1",), seen, profile)["/uav1"] == (
        Topic("camera/image_raw", IMAGE, "published"),
        Topic("cmd_vel", TWIST, "subscribed"),
    )


def test_with_no_node_of_the_robot_both_sides_count(profile: Profile) -> None:
    """One simulator node serving every robot (Gazebo) publishes and subscribes for them."""
    seen = observation(
        publishers={"/uav1/camera/image_raw": ["/gazebo"], "/uav1/cmd_vel": ["/teleop"]},
        subscribers={"/uav1/camera/image_raw": ["/rviz"], "/uav1/cmd_vel": ["/gazebo"]},
        types={"/uav1/camera/image_raw": IMAGE, "/uav1/cmd_vel": TWIST},
        params=["/uav1/robot_description"],
    )
    assert robot_topics(("/uav1",), seen, profile)["/uav1"] == (
        Topic("camera/image_raw", IMAGE, "published"),
        Topic("camera/image_raw", IMAGE, "subscribed"),
        Topic("cmd_vel", TWIST, "published"),
        Topic("cmd_vel", TWIST, "subscribed"),
    )


def test_a_topic_belongs_to_the_deepest_robot_and_the_root_takes_the_rest(profile: Profile) -> None:
    seen = observation(
        publishers={
            "/team/ugv1/scan": ["/team/ugv1/laser"],
            "/team/scan": ["/team/laser"],
            "/scan": ["/laser"],
            "/elsewhere/scan": ["/laser2"],
        },
        subscribers={},
        types=dict.fromkeys(("/team/ugv1/scan", "/team/scan", "/scan", "/elsewhere/scan"), SCAN),
        params=["/robot_description", "/team/robot_description", "/team/ugv1/robot_description"],
    )
    namespaces = robot_namespaces(seen.param_names)
    assert robot_topics(namespaces, seen, profile)["/team/ugv1"] == (
        Topic("scan", SCAN, "published"),
    )
    assert robot_topics(namespaces, seen, profile)["/team"] == (Topic("scan", SCAN, "published"),)
    assert robot_topics(namespaces, seen, profile)["/"] == (
        Topic("elsewhere/scan", SCAN, "published"),
        Topic("scan", SCAN, "published"),
    )


def test_topics_no_profile_rule_reads_or_without_a_type_are_left_out(profile: Profile) -> None:
    seen = observation(
        publishers={
            "/uav1/tf": ["/uav1/x"],
            "/uav1/diagnostics": ["/uav1/x"],
            "/uav1/untyped": ["/uav1/x"],
            "/uav1/any": ["/uav1/x"],
            "/uav1/camera/image_raw": ["/uav1/x"],
        },
        subscribers={},
        types={
            "/uav1/tf": "tf2_msgs/TFMessage",
            "/uav1/diagnostics": "diagnostic_msgs/DiagnosticArray",
            "/uav1/any": "*",
            "/uav1/camera/image_raw": IMAGE,
        },
        params=["/uav1/robot_description"],
    )
    assert robot_topics(("/uav1",), seen, profile)["/uav1"] == (
        Topic("camera/image_raw", IMAGE, "published"),
    )


def test_discover_finds_the_moveit_semantic_description_beside_the_urdf(profile: Profile) -> None:
    seen = observation(
        {},
        {},
        {},
        ["/arm/robot_description", "/arm/robot_description_semantic", "/uav1/robot_description"],
    )
    arm, uav = discover(seen, profile)
    assert (arm.namespace, arm.description_key, arm.semantic_key) == (
        "/arm",
        "/arm/robot_description",
        "/arm/robot_description_semantic",
    )
    assert (uav.namespace, uav.semantic_key) == ("/uav1", None)


def test_discover_finds_a_teleoperation_description_beside_the_urdf(profile: Profile) -> None:
    seen = observation(
        {},
        {},
        {},
        [
            "/ugv1/robot_description",
            "/ugv1/teleop_description",
            "/ugv2/robot_description",
            "/lost/teleop_description",  # no robot_description: no robot
        ],
    )
    ugv1, ugv2 = discover(seen, profile)
    assert (ugv1.namespace, ugv1.teleop_key) == ("/ugv1", "/ugv1/teleop_description")
    assert (ugv2.namespace, ugv2.teleop_key) == ("/ugv2", None)


@NO_DEADLINE
@given(
    st.lists(_namespace, min_size=1, max_size=5, unique=True),
    st.lists(st.lists(_segment, min_size=1, max_size=4), max_size=12),
)
def test_no_topic_is_given_to_two_robots(
    profile: Profile, namespaces: list[str], topics: list[list[str]]
) -> None:
    names = ["/" + "/".join(parts) for parts in topics]
    seen = observation(
        {name: ["/node"] for name in names},
        {},
        dict.fromkeys(names, SCAN),
        [ns.rstrip("/") + "/robot_description" for ns in namespaces],
    )
    found = robot_namespaces(seen.param_names)
    owners: dict[str, str] = {}
    for namespace, owned in robot_topics(found, seen, profile).items():
        for topic in owned:
            absolute = namespace.rstrip("/") + "/" + topic.name
            assert absolute not in owners, f"{absolute}: {owners.get(absolute)} and {namespace}"
            owners[absolute] = namespace


def _deepest(name: str, namespaces: list[str]) -> str | None:
    """The owner by the definition: the longest namespace that is a proper prefix by segments."""
    inside = [ns for ns in namespaces if ns == "/" or name.startswith(ns + "/")]
    return max(inside, key=len, default=None)


@NO_DEADLINE
@given(
    st.lists(_namespace, min_size=1, max_size=5, unique=True),
    st.lists(st.lists(_segment, min_size=1, max_size=4), max_size=12),
)
def test_each_topic_goes_to_the_deepest_namespace_containing_it(
    profile: Profile, namespaces: list[str], topics: list[list[str]]
) -> None:
    names = sorted({"/" + "/".join(parts) for parts in topics})
    seen = observation(
        {name: ["/node"] for name in names},
        {},
        dict.fromkeys(names, SCAN),
        [ns.rstrip("/") + "/robot_description" for ns in namespaces],
    )
    found = robot_topics(namespaces, seen, profile)
    given_to = {
        (ns.rstrip("/") + "/" + topic.name): ns for ns, owned in found.items() for topic in owned
    }
    assert given_to == {
        name: _deepest(name, namespaces) for name in names if _deepest(name, namespaces) is not None
    }


def test_a_robots_keys_are_its_descriptions_and_its_own_values_the_rules_name() -> None:
    robot = RobotSource(
        "/uav1",
        "/uav1/robot_description",
        None,  # no SRDF
        (),
        (("comm_link", "/uav1/teleop_ui/comm_link"), ("colour", "/uav1/teleop_ui/colour")),
        "/uav1/teleop_description",
    )
    assert robot.keys({"comm_link", "sensor_type"}) == [
        "/uav1/robot_description",
        "/uav1/teleop_description",
        "/uav1/teleop_ui/comm_link",
    ]
