"""An emulated ROS 2 robot on DDS: one process, one participant, as an rclcpp/rclpy process is.

Written from the ROS 2 design article "Topic and Service name mapping to DDS", the rmw_dds_common
messages and rmw_cyclonedds_cpp, not from the project's reader. On the wire it does what a ROS 2
process with the Cyclone DDS middleware does at start-up:

* one DDS participant per process (since Foxy), with a writer of ``ros_discovery_info``
  (``rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_``: the participant's gid, and per node
  its namespace, name and the gids of its readers and writers; a gid is the endpoint's 16-byte
  GUID in a 24-byte array before Iron (``--gid 24``), a 16-byte array from Iron on (``--gid 16``));
  reliable, transient-local, keep-last 1, as rmw_dds_common's graph cache publishes it;
* a topic ``/ns/name`` of type ``pkg/msg/Type`` as the DDS topic ``rt/ns/name`` of type
  ``pkg::msg::dds_::Type_``; a service server as readers of ``rq/ns/srvRequest`` and writers
  of ``rr/ns/srvReply``;
* ``/<ns>/robot_description`` (``std_msgs/msg/String``) written once, reliable and
  transient-local, as robot_state_publisher does.

What is NOT emulated: the payload layout of topics other than ``std_msgs/msg/String`` (their
types carry the ROS 2 type names, with one placeholder field: only discovery sees them), QoS
other than the above, security, shared memory.

Driven by JSON lines on stdin, one command each, answered by ``ok`` on stdout::

    {"node": "/uav1/camera_driver", "publish": [["/uav1/camera/image_raw",
     "sensor_msgs/msg/Image"]], "subscribe": [], "services": []}
    {"describe": "/uav1", "file": "/tmp/uav1.urdf"}      # or "text": "..."
    {"drop": "/uav1/camera_driver"}                       # the node's endpoints vanish
    {"latch": "/uav1/teleop_ui/link", "text": "LTE"}      # a String, reliable and
                                                          # transient-local (a robot's value)
    {"echo": "/bench/ping", "to": "/bench/pong"}           # answers each String on the
                                                          # first topic with it on the second
"""

import json
import sys
import types
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import array, sequence, uint8
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

LATCHED = Qos(
    Policy.Reliability.Reliable(1_000_000_000),
    Policy.Durability.TransientLocal,
    Policy.History.KeepLast(1),
)


def mangled_type(ros_type: str) -> str:
    package, kind, name = ros_type.split("/")
    return f"{package}::{kind}::dds_::{name}_"


_STRUCTS: dict[str, type] = {}


def struct(type_name: str) -> type:
    """An IDL struct carrying the DDS type name (a placeholder field, see the docstring)."""
    if type_name not in _STRUCTS:
        if type_name == "std_msgs::msg::dds_::String_":

            @dataclass
            class String(IdlStruct, typename=type_name):
                data: str

            _STRUCTS[type_name] = String
        else:

            def body(namespace: dict[str, Any]) -> None:
                namespace["__annotations__"] = {"placeholder": uint8}

            _STRUCTS[type_name] = dataclass(
                types.new_class("Msg", (IdlStruct,), {"typename": type_name}, body)
            )
    return _STRUCTS[type_name]


def discovery_types(size: int) -> tuple[Any, Any, Any]:
    @dataclass
    class Gid(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
        data: array[uint8, size]  # type: ignore[valid-type,type-arg]  # an IDL type, not Python

    @dataclass
    class NodeEntitiesInfo(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
        node_namespace: str
        node_name: str
        reader_gid_seq: sequence[Gid]  # type: ignore[type-arg]  # an IDL type, not Python
        writer_gid_seq: sequence[Gid]  # type: ignore[type-arg]  # an IDL type, not Python

    @dataclass
    class ParticipantEntitiesInfo(
        IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"
    ):
        gid: Gid
        node_entities_info_seq: sequence[NodeEntitiesInfo]  # type: ignore[type-arg]  # an IDL type, not Python

    return Gid, NodeEntitiesInfo, ParticipantEntitiesInfo


class Robot:
    def __init__(self, domain: int, gid_size: int) -> None:
        self.participant = DomainParticipant(domain)
        self.gid_size = gid_size
        self.Gid, self.Node, self.Info = discovery_types(gid_size)
        self.info_writer = DataWriter(
            self.participant, Topic(self.participant, "ros_discovery_info", self.Info), qos=LATCHED
        )
        self.nodes: dict[str, tuple[list[Any], list[Any]]] = {}  # name -> (readers, writers)
        self.topics: dict[tuple[str, str], Any] = {}
        self.latched: dict[str, Any] = {}

    def gid(self, entity: Any) -> Any:
        raw = entity.guid.bytes
        return self.Gid(list(raw + bytes(self.gid_size - len(raw))))

    def topic(self, dds_name: str, ros_type: str) -> Any:
        key = (dds_name, ros_type)
        if key not in self.topics:
            self.topics[key] = Topic(self.participant, dds_name, struct(mangled_type(ros_type)))
        return self.topics[key]

    def add_node(
        self,
        name: str,
        publish: list[list[str]],
        subscribe: list[list[str]],
        services: list[list[str]],
    ) -> None:
        readers, writers = self.nodes.setdefault(name, ([], []))
        for topic, ros_type in publish:
            writers.append(DataWriter(self.participant, self.topic("rt" + topic, ros_type)))
        for topic, ros_type in subscribe:
            readers.append(DataReader(self.participant, self.topic("rt" + topic, ros_type)))
        for service, ros_type in services:
            readers.append(
                DataReader(
                    self.participant, self.topic(f"rq{service}Request", ros_type + "_Request")
                )
            )
            writers.append(
                DataWriter(
                    self.participant, self.topic(f"rr{service}Reply", ros_type + "_Response")
                )
            )
        self.announce()

    def describe(self, namespace: str, text: str) -> None:
        node = namespace.rstrip("/") + "/robot_state_publisher"
        _readers, writers = self.nodes.setdefault(node, ([], []))
        writer = DataWriter(
            self.participant,
            self.topic("rt" + namespace.rstrip("/") + "/robot_description", "std_msgs/msg/String"),
            qos=LATCHED,
        )
        writer.write(struct("std_msgs::msg::dds_::String_")(text))
        writers.append(writer)
        self.announce()

    def latch(self, topic: str, text: str) -> None:
        """Write ``text`` on ``topic`` (``std_msgs/msg/String``, reliable, transient-local) from
        a node of the robot, as a launch file's latched publisher does."""
        namespace = topic.split("/teleop_ui/", maxsplit=1)[0]
        _readers, writers = self.nodes.setdefault(f"{namespace}/teleop_ui_values", ([], []))
        if topic not in self.latched:
            writer = DataWriter(
                self.participant, self.topic("rt" + topic, "std_msgs/msg/String"), qos=LATCHED
            )
            self.latched[topic] = writer
            writers.append(writer)
        self.latched[topic].write(struct("std_msgs::msg::dds_::String_")(text))
        self.announce()

    def drop(self, name: str) -> None:
        readers, writers = self.nodes.pop(name, ([], []))
        for entity in (*readers, *writers):
            entity.__del__()
        self.announce()

    def echo(self, topic: str, answer: str) -> None:
        """Answer each ``std_msgs/msg/String`` on ``topic`` with the same on ``answer``, from a
        data-available listener (a benchmark's peer for the watcher's answers)."""
        from cyclonedds.core import Listener

        string = "std_msgs/msg/String"
        writer = DataWriter(self.participant, self.topic("rt" + answer, string), qos=LATCHED)

        def repeat(reader: Any) -> None:
            for sample in reader.take(N=64):
                info = getattr(sample, "sample_info", None)
                if info is None or info.valid_data:  # not a disposal notice
                    writer.write(sample)

        listener = Listener(on_data_available=repeat)  # type: ignore[no-untyped-call]  # cyclonedds has no hints
        reader = DataReader(
            self.participant, self.topic("rt" + topic, string), qos=LATCHED, listener=listener
        )
        self.nodes.setdefault("/bench/echo", ([], []))[0].append(reader)
        self.nodes["/bench/echo"][1].append(writer)

    def announce(self) -> None:
        nodes = []
        for name, (readers, writers) in sorted(self.nodes.items()):
            namespace, _, base = name.rpartition("/")
            nodes.append(
                self.Node(
                    namespace or "/",
                    base,
                    [self.gid(r) for r in readers],
                    [self.gid(w) for w in writers],
                )
            )
        self.info_writer.write(self.Info(self.gid(self.participant), nodes))


def main() -> None:
    domain, gid_size = int(sys.argv[1]), int(sys.argv[2])
    robot = Robot(domain, gid_size)
    print("ok", flush=True)
    for line in sys.stdin:
        command = json.loads(line)
        if "node" in command:
            robot.add_node(
                command["node"],
                command.get("publish", []),
                command.get("subscribe", []),
                command.get("services", []),
            )
        elif "describe" in command:
            text = (
                command["text"]
                if "text" in command
                else Path(command["file"]).read_text(encoding="utf-8")
            )
            robot.describe(command["describe"], text)
        elif "latch" in command:
            robot.latch(command["latch"], command["text"])
        elif "drop" in command:
            robot.drop(command["drop"])
        elif "echo" in command:
            robot.echo(command["echo"], command["to"])
        print("ok", flush=True)


if __name__ == "__main__":
    main()
