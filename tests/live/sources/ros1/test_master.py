"""The master client: real roscore replies, and every way a call can go wrong."""

from __future__ import annotations

import socket
import threading
import xmlrpc.client
from collections.abc import Iterator
from typing import Any
from xmlrpc.server import SimpleXMLRPCServer

import pytest

from solver.errors import InputError
from solver.live.graph import MISSING, MasterError, MasterUnreachable
from solver.live.sources.ros1.master import MasterClient, is_loopback, master_uri
from tests.live.roscore import Roscore, TestNode, free_port


def test_observe_reads_pid_graph_and_parameter_names(master: Roscore, node: TestNode) -> None:
    node.publish("/uav1/camera_driver", [("/uav1/camera/image_raw", "sensor_msgs/Image")])
    node.subscribe("/uav1/base", [("/uav1/cmd_vel", "geometry_msgs/Twist")])
    node.set_param("/teleop_ui/active_robot", "/uav1")
    client = MasterClient(master.uri, caller_id="/reader")
    observation = client.observe("/teleop_ui")
    assert observation.pid == client.get_pid() > 0
    assert ("/uav1/camera/image_raw", ("/uav1/camera_driver",)) in observation.publishers
    assert ("/uav1/cmd_vel", ("/uav1/base",)) in observation.subscribers
    assert ("/uav1/cmd_vel", "geometry_msgs/Twist") in observation.topic_types
    assert "/teleop_ui/active_robot" in observation.param_names
    assert observation.params == (("active_robot", "/uav1"),)
    client.close()


def test_observe_params_reads_the_pid_and_the_watched_parameters_alone(
    master: Roscore, node: TestNode
) -> None:
    node.set_param("/teleop_ui/active_robot", "/uav1")
    node.set_param("/teleop_ui/active_motion_control", "Flight")
    node.set_param("/elsewhere", "not read")
    client = MasterClient(master.uri, caller_id="/reader")
    assert client.observe_params("/teleop_ui") == (
        client.get_pid(),
        (("active_motion_control", "Flight"), ("active_robot", "/uav1")),
    )
    assert client.observe_params("/nothing_here") == (client.get_pid(), ())
    client.close()


def test_a_large_graph_that_did_not_change_is_read_as_the_same_observation(
    master: Roscore, node: TestNode
) -> None:
    # About 100 KB of parameter names: a reply worth comparing before it is parsed again.
    node.set_param("/fleet", {f"robot_{i:04d}_with_a_long_name": i for i in range(2000)})
    node.set_param("/teleop_ui/active_robot", "/uav1")
    client = MasterClient(master.uri, caller_id="/reader")
    first = client.observe("/teleop_ui")
    assert "/fleet/robot_1999_with_a_long_name" in first.param_names
    again = client.observe("/teleop_ui")
    assert again == first
    assert again.param_names is first.param_names  # the same bytes: not parsed again
    # The operator's switch changes /teleop_ui, not the graph's reply.
    node.set_param("/teleop_ui/active_robot", "/ugv1")
    switched = client.observe("/teleop_ui")
    assert switched.params == (("active_robot", "/ugv1"),)
    assert switched.param_names is first.param_names
    node.set_param("/fleet/robot_2000_with_a_long_name", 2000)
    assert "/fleet/robot_2000_with_a_long_name" in client.observe("/teleop_ui").param_names
    node.publish("/uav1/camera_driver", [("/uav1/camera/image_raw", "sensor_msgs/Image")])
    assert ("/uav1/camera/image_raw", ("/uav1/camera_driver",)) in client.observe().publishers
    client.close()


def test_parameters_round_trip_and_a_missing_one_is_missing(master: Roscore) -> None:
    client = MasterClient(master.uri, caller_id="/writer")
    value = {"number": 3, "default": False, "components": [{"name": "UAV"}], "note": "é"}
    client.set_param("/teleop_ui/test_value", value)
    assert client.get_param("/teleop_ui/test_value") == value
    assert client.get_param("/no/such/param") is MISSING
    assert client.get_params(["/teleop_ui/test_value", "/nope"]) == {
        "/teleop_ui/test_value": value,
        "/nope": MISSING,
    }
    client.delete_param("/teleop_ui/test_value")
    client.delete_param("/teleop_ui/test_value")  # deleting twice is fine: the end state holds
    assert client.get_param("/teleop_ui/test_value") is MISSING
    client.close()


def test_a_closed_port_is_unreachable_naming_the_master() -> None:
    uri = f"http://127.0.0.1:{free_port()}/"
    client = MasterClient(uri, timeout=5.0)
    with pytest.raises(MasterUnreachable) as caught:
        client.observe()
    assert str(caught.value).startswith(f"{uri}: cannot reach the ROS master (")
    assert isinstance(caught.value, ConnectionError)


@pytest.fixture
def silent_server() -> Iterator[str]:
    """A port that accepts connections and never answers."""
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen(8)
        yield f"http://127.0.0.1:{server.getsockname()[1]}/"


def test_a_master_that_never_answers_times_out(silent_server: str) -> None:
    client = MasterClient(silent_server, timeout=0.5)
    with pytest.raises(MasterUnreachable, match="did not answer in time"):
        client.get_pid()


def _serve(server: Any) -> threading.Thread:
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    return thread


def test_a_web_server_is_not_a_master(web_server: str) -> None:
    client = MasterClient(web_server)
    with pytest.raises(MasterError, match="not a ROS master: HTTP 404") as caught:
        client.observe()
    assert not isinstance(caught.value, MasterUnreachable)


@pytest.mark.parametrize(
    ("reply", "message"),
    [
        ("hello", r"getPid: not a ROS master's reply \(expected \[code, message, value\]\)"),
        ([1, "ok", "not a pid"], r"getPid: not a ROS master's reply \(expected a process id\)"),
        ([0, "internal failure", 0], "getPid: the master failed: internal failure"),
    ],
)
def test_replies_a_master_never_gives_are_master_errors(reply: Any, message: str) -> None:
    server = SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False, allow_none=True)
    server.register_function(lambda _caller: reply, "getPid")
    _serve(server)
    client = MasterClient(f"http://127.0.0.1:{server.server_address[1]}/")
    with pytest.raises(MasterError, match=message):
        client.get_pid()
    server.shutdown()
    server.server_close()


def test_without_multicall_observe_falls_back_to_one_call_per_method(
    master: Roscore, node: TestNode
) -> None:
    """A relay to the real master that offers the ROS master API but not system.multicall."""
    node.set_param("/relayed/robot_description", "<robot/>")
    upstream = xmlrpc.client.ServerProxy(master.uri)
    relay = SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False, allow_none=True)
    for method in ("getPid", "getSystemState", "getTopicTypes", "getParamNames", "getParam"):
        relay.register_function(getattr(upstream, method), method)
    _serve(relay)
    client = MasterClient(f"http://127.0.0.1:{relay.server_address[1]}/")
    observation = client.observe("/teleop_ui")
    assert "/relayed/robot_description" in observation.param_names
    assert client.get_params(["/relayed/robot_description"]) == {
        "/relayed/robot_description": "<robot/>"
    }
    relay.shutdown()
    relay.server_close()


@pytest.mark.parametrize(
    ("given", "normalised"),
    [
        ("http://127.0.0.1:11311", "http://127.0.0.1:11311/"),
        ("http://localhost:11311/", "http://localhost:11311/"),
        ("http://[::1]:11311", "http://[::1]:11311/"),
    ],
)
def test_master_uri_accepts_http_host_and_port(given: str, normalised: str) -> None:
    assert master_uri(given) == normalised


@pytest.mark.parametrize(
    "given",
    [
        "127.0.0.1:11311",
        "https://127.0.0.1:11311",
        "http://127.0.0.1",
        "http://127.0.0.1:port",
        "http://127.0.0.1:11311/RPC2",
        "",
        "http://[::1",
        "http://[zz]:11311",
        "http://exa mple:11311",
        "http://h:99999",
        "http://h\x00st:11311",
    ],
)
def test_master_uri_rejects_anything_else(given: str) -> None:
    with pytest.raises(InputError, match=r"expected a ROS master URI|no ROS master given"):
        master_uri(given)


def test_master_uri_defaults_to_ros_master_uri(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_MASTER_URI", "http://127.0.0.1:11411")
    assert master_uri(None) == "http://127.0.0.1:11411/"
    monkeypatch.delenv("ROS_MASTER_URI")
    with pytest.raises(InputError, match="pass --master"):
        master_uri(None)


def test_loopback_masters_are_recognised() -> None:
    assert is_loopback("http://127.0.0.1:1/")
    assert is_loopback("http://localhost:1/")
    assert is_loopback("http://[::1]:1/")
    assert not is_loopback("http://10.0.0.2:11311/")
    assert not is_loopback("http://robot.local:11311/")
