"""Placing a master's topic graph on its robots, as every poll of ``teleop-ui watch`` does.

A generated observation (what one ``getSystemState`` + ``getTopicTypes`` + ``getParamNames``
round trip returns): R robots under ``/robot<i>``, each with T topics of its own, half camera
images published by the robot's driver node and half ``cmd_vel``-like commands it subscribes
to, plus as many ``tf``/``rosout`` topics that no identification rule reads, and a root-level
teleop node publishing to every robot's commands. Each round asserts what each robot was
given, counted from how the graph was built.

The placement was O(robots x topics x robots) (each topic's owner looked for among all robots,
for each robot): 20 robots with 100 topics each took 0.61 s per poll (median of 5, measured
here before the change), now 29 ms. It is one pass over the graph; the two sizes below show it
growing with the graph (ten times the robots, about ten times the time), not with its square.
"""

from __future__ import annotations

import pytest
from pytest_benchmark.fixture import BenchmarkFixture

from solver.identify.profile import load_profile
from solver.live.discovery import RobotSource, discover
from solver.live.graph import Observation

IMAGE = "sensor_msgs/Image"
TWIST = "geometry_msgs/Twist"
IRRELEVANT = "tf2_msgs/TFMessage"


def graph(robots: int, topics: int) -> Observation:
    publishers: dict[str, list[str]] = {}
    subscribers: dict[str, list[str]] = {}
    types: dict[str, str] = {}
    params = []
    for r in range(robots):
        ns = f"/robot{r}"
        params.append(f"{ns}/robot_description")
        for t in range(topics // 2):
            image, command, noise = f"{ns}/camera{t}/image_raw", f"{ns}/cmd{t}", f"{ns}/tf{t}"
            publishers[image] = [f"{ns}/camera_driver"]
            subscribers[image] = ["/rviz"]
            publishers[command] = ["/teleop"]
            subscribers[command] = [f"{ns}/base_driver"]
            publishers[noise] = [f"{ns}/state_publisher"]
            types.update({image: IMAGE, command: TWIST, noise: IRRELEVANT})
    return Observation(
        pid=1,
        publishers=tuple((k, tuple(v)) for k, v in sorted(publishers.items())),
        subscribers=tuple((k, tuple(v)) for k, v in sorted(subscribers.items())),
        topic_types=tuple(sorted(types.items())),
        param_names=tuple(sorted(params)),
    )


@pytest.mark.parametrize(
    ("robots", "topics"),
    [(20, 100), (200, 100)],
    ids=["20 robots x 100 topics", "200 robots x 100 topics"],
)
def test_placing_the_topic_graph(benchmark: BenchmarkFixture, robots: int, topics: int) -> None:
    seen = graph(robots, topics)
    profile = load_profile()
    found: tuple[RobotSource, ...] = benchmark(discover, seen, profile)
    assert [source.namespace for source in found] == sorted(f"/robot{r}" for r in range(robots))
    for source in found:
        # Each robot's own node decides the direction; tf topics are read by no rule.
        assert sorted((t.type, t.direction) for t in source.topics) == sorted(
            [(IMAGE, "published")] * (topics // 2) + [(TWIST, "subscribed")] * (topics // 2)
        )
