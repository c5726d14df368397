"""An emulated ROS 2 fleet on loopback, to try ``watch --ros2`` with: ``teleop-ui demo ros2``.

What runs are real DDS participants (Eclipse Cyclone DDS) behaving on the wire as ROS 2
processes with ``rmw_cyclonedds_cpp`` do: one participant per robot; its topics as ``rt/``
DDS topics with ROS 2 type names; ``ros_discovery_info`` naming its nodes and their readers
and writers; a ``robot_description`` (``std_msgs/msg/String``) written once, reliable and
transient-local, as ``robot_state_publisher`` writes it. The fleet (:data:`ROBOTS`):

* ``/uav1``, a quadrotor: four rotor joints and a camera; publishes ``camera/image_raw``;
* ``/ugv1``, a differential-drive base: driven wheels, a caster and a laser scanner; takes
  ``cmd_vel`` and ``goal_pose`` (navigation goals), publishes ``scan``;
* ``/arm1``, a six-joint arm with a parallel gripper: takes joint trajectories
  (``arm_controller/joint_trajectory``), publishes ``wrist_camera/image_raw``;

and an operator station (:class:`OperatorStation`) that makes each robot active in turn, with
each of its motion controls, every few seconds (``/teleop_ui/active_robot``, and
``/teleop_ui/active_<characteristic>`` for the characteristic the shipped profile fills with
motion controls), and reports the answer a watcher gives (``/teleop_ui/ui_configuration``).
Any participant on the domain can write that answer, so the operator reads it as the watcher
reads one (:func:`~solver.live.values.bounded_json`: 1 MiB, 64 levels, checked before
decoding) and shows each value in it escaped and cut (:func:`~solver.live.values.shown_value`).

**Not emulated**: message payloads other than ``std_msgs/msg/String`` (the other topics carry
their real ROS 2 type names but no data: only discovery sees them), ROS 2 itself (no rclcpp,
no other DDS vendor), security, shared memory, real networks. Everything stays on loopback
when Cyclone DDS is configured with :data:`LOOPBACK_CONFIG` (what :func:`loopback_uri`
writes).

The ROS 2 names and types are :mod:`solver.live.sources.ros2`'s, imported where used (as the
rest of the shared machinery, this module imports no source at module level).

Not here: reading a graph (:mod:`solver.live.sources.ros2`).
"""

# No "from __future__ import annotations": Cyclone DDS resolves the IDL field annotations of
# the placeholder classes at run time.
import json
import threading
import types
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final

__all__ = [
    "LOOPBACK_CONFIG",
    "ROBOTS",
    "TEAM",
    "Answer",
    "DemoRobot",
    "OperatorStation",
    "demo_team",
    "emulated_fleet",
    "loopback_uri",
]

# Cyclone DDS on the loopback interface only: no multicast, unicast discovery to 127.0.0.1
# (participant indices up to 120, so that tens of participants on one host find each other).
LOOPBACK_CONFIG: Final = """\
<?xml version="1.0" encoding="UTF-8"?>
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain id="any">
    <General>
      <Interfaces><NetworkInterface address="127.0.0.1"/></Interfaces>
      <AllowMulticast>false</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>120</MaxAutoParticipantIndex>
      <Peers><Peer address="127.0.0.1"/></Peers>
    </Discovery>
  </Domain>
</CycloneDDS>
"""

_STRING = "std_msgs/msg/String"

# A team of the article's rules that has the three robots' kinematic types (what
# :func:`demo_team` writes for the watcher to read).
# (``control`` and ``count``: the rule set's names for the shipped profile's roles.)
TEAM: Final = """\
name: Demo fleet
rules: {rules}
team:
  UAV: {{{control}: [Flight, Waypoint], {count}: 5}}
  UGV: {{{control}: [Driving, Waypoint], {count}: 5}}
  Manipulator: {{{control}: [Joint, End Effector], {count}: 5}}
"""


def control_name() -> str:
    """The characteristic the operator switches: the shipped profile's motion control."""
    from solver.identify.profile import MOTION_CONTROL, load_profile

    return load_profile().role(MOTION_CONTROL)


def demo_team(directory: Path) -> Path:
    """Write :data:`TEAM` (under the shipped article's rules) to ``directory``."""
    from solver.core.rules import default_rules_path
    from solver.identify.profile import SENSOR_COUNT, load_profile

    path = directory / "demo-team.yaml"
    text = TEAM.format(
        rules=json.dumps(str(default_rules_path())),
        control=control_name(),
        count=load_profile().role(SENSOR_COUNT),
    )
    path.write_text(text, encoding="utf-8")
    return path


def loopback_uri(directory: Path) -> str:
    """Write :data:`LOOPBACK_CONFIG` to ``directory`` and return its ``CYCLONEDDS_URI``."""
    path = directory / "cyclonedds.xml"
    path.write_text(LOOPBACK_CONFIG, encoding="utf-8")
    return path.as_uri()


def _joint(name: str, kind: str, parent: str, child: str, extra: str = "") -> str:
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
        f'<child link="{child}"/>{extra}</joint>'
    )


def _robot(name: str, links: Sequence[str], joints: Sequence[str], extra: str = "") -> str:
    body = "".join(f'<link name="{link}"/>' for link in links) + "".join(joints)
    return f'<?xml version="1.0"?>\n<robot name="{name}">{body}{extra}</robot>\n'


_LIMIT = '<limit lower="-3.14" upper="3.14" effort="20" velocity="2"/>'
_ARM_JOINTS = ("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3")

QUADROTOR: Final = _robot(
    "quadrotor",
    ["base_link", "camera_link", *(f"rotor_{i}" for i in range(4))],
    [
        *(_joint(f"rotor_{i}_joint", "continuous", "base_link", f"rotor_{i}") for i in range(4)),
        _joint("camera_joint", "fixed", "base_link", "camera_link"),
    ],
    '<gazebo reference="camera_link"><sensor type="camera" name="down_camera"/></gazebo>',
)
DIFF_DRIVE: Final = _robot(
    "diff_drive_lidar",
    ["base_link", "left_wheel", "right_wheel", "caster", "laser"],
    [
        _joint("left_wheel_joint", "continuous", "base_link", "left_wheel"),
        _joint("right_wheel_joint", "continuous", "base_link", "right_wheel"),
        _joint("caster_joint", "fixed", "base_link", "caster"),
        _joint("laser_joint", "fixed", "base_link", "laser"),
    ],
    '<gazebo reference="laser"><sensor type="ray" name="lidar"/></gazebo>'
    '<gazebo><plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">'
    "<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>"
    "</plugin></gazebo>",
)
ARM: Final = _robot(
    "arm_gripper",
    [
        "base_link",
        *(f"{joint}_link" for joint in _ARM_JOINTS),
        "gripper_base",
        "left_finger",
        "right_finger",
    ],
    [
        *(
            _joint(f"{joint}_joint", "revolute", parent, f"{joint}_link", _LIMIT)
            for parent, joint in zip(
                ["base_link", *(f"{j}_link" for j in _ARM_JOINTS)], _ARM_JOINTS, strict=False
            )
        ),
        _joint("gripper_mount", "fixed", "wrist_3_link", "gripper_base"),
        _joint("left_finger_joint", "prismatic", "gripper_base", "left_finger", _LIMIT),
        _joint(
            "right_finger_joint",
            "prismatic",
            "gripper_base",
            "right_finger",
            _LIMIT + '<mimic joint="left_finger_joint"/>',
        ),
    ],
)


@dataclass(frozen=True, slots=True)
class DemoRobot:
    """One emulated robot: its namespace, description, and its nodes' topics (relative to the
    namespace, with ROS 2 types); ``controls``: the motion controls the operator switches
    through."""

    namespace: str
    description: str
    publishes: tuple[tuple[str, str], ...]
    subscribes: tuple[tuple[str, str], ...]
    controls: tuple[str, ...]


ROBOTS: Final = (
    DemoRobot(
        "/uav1", QUADROTOR, (("camera/image_raw", "sensor_msgs/msg/Image"),), (), ("Flight",)
    ),
    DemoRobot(
        "/ugv1",
        DIFF_DRIVE,
        (("scan", "sensor_msgs/msg/LaserScan"),),
        (("cmd_vel", "geometry_msgs/msg/Twist"), ("goal_pose", "geometry_msgs/msg/PoseStamped")),
        ("Driving", "Waypoint"),
    ),
    DemoRobot(
        "/arm1",
        ARM,
        (("wrist_camera/image_raw", "sensor_msgs/msg/Image"),),
        (("arm_controller/joint_trajectory", "trajectory_msgs/msg/JointTrajectory"),),
        ("Joint",),
    ),
)


def _latched() -> Any:
    from cyclonedds.qos import Policy, Qos

    return Qos(
        Policy.Reliability.Reliable(1_000_000_000),
        Policy.Durability.TransientLocal,
        Policy.History.KeepLast(1),
    )


_PLACEHOLDERS: dict[str, type] = {}


def _placeholder(ros_type: str) -> type:
    """An IDL struct carrying ``ros_type``'s DDS name and one byte: only discovery sees it."""
    from solver.live.sources.ros2 import dds_type

    name = dds_type(ros_type)
    if name not in _PLACEHOLDERS:
        from dataclasses import dataclass as idl_dataclass

        from cyclonedds.idl import IdlStruct
        from cyclonedds.idl.types import uint8

        def body(namespace: dict[str, Any]) -> None:
            namespace["__annotations__"] = {"placeholder": uint8}

        _PLACEHOLDERS[name] = idl_dataclass(
            types.new_class("Placeholder", (IdlStruct,), {"typename": name}, body)
        )
    return _PLACEHOLDERS[name]


class _Participant:
    """One ROS 2 process on the domain: a participant and its ``ros_discovery_info``."""

    def __init__(self, domain: int) -> None:
        from cyclonedds.domain import DomainParticipant
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from solver.live.sources.ros2 import message_types

        self.string, discovery = message_types()
        self.gid_type, self.node_type, self.info_type = discovery[16]
        self.participant = DomainParticipant(domain)
        self.info = DataWriter(
            self.participant,
            Topic(self.participant, "ros_discovery_info", self.info_type),
            qos=_latched(),
        )
        self.nodes: dict[str, tuple[list[Any], list[Any]]] = {}

    def gid(self, entity: Any) -> Any:
        return self.gid_type(list(entity.guid.bytes))

    def writer(self, node: str, topic: str, ros_type: str, *, latched: bool = False) -> Any:
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from solver.live.sources.ros2 import dds_topic

        kind = self.string if ros_type == _STRING else _placeholder(ros_type)
        writer = DataWriter(
            self.participant,
            Topic(self.participant, dds_topic(topic), kind),
            qos=_latched() if latched else None,
        )
        self.nodes.setdefault(node, ([], []))[1].append(writer)
        return writer

    def reader(self, node: str, topic: str, ros_type: str, *, latched: bool = False) -> Any:
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        from solver.live.sources.ros2 import dds_topic

        kind = self.string if ros_type == _STRING else _placeholder(ros_type)
        reader = DataReader(
            self.participant,
            Topic(self.participant, dds_topic(topic), kind),
            qos=_latched() if latched else None,
        )
        self.nodes.setdefault(node, ([], []))[0].append(reader)
        return reader

    def announce(self) -> None:
        nodes = []
        for name, (readers, writers) in sorted(self.nodes.items()):
            namespace, _, base = name.rpartition("/")
            nodes.append(
                self.node_type(
                    namespace or "/",
                    base,
                    [self.gid(r) for r in readers],
                    [self.gid(w) for w in writers],
                )
            )
        self.info.write(self.info_type(self.gid(self.participant), nodes))

    def close(self) -> None:
        self.participant.__del__()


def _start_robot(robot: DemoRobot, domain: int) -> _Participant:
    process = _Participant(domain)
    namespace = robot.namespace.rstrip("/")
    for topic, ros_type in robot.publishes:
        process.writer(f"{namespace}/driver", f"{namespace}/{topic}", ros_type)
    for topic, ros_type in robot.subscribes:
        process.reader(f"{namespace}/driver", f"{namespace}/{topic}", ros_type)
    description = process.writer(
        f"{namespace}/robot_state_publisher",
        f"{namespace}/robot_description",
        _STRING,
        latched=True,
    )
    description.write(process.string(robot.description))
    process.announce()
    return process


@dataclass(frozen=True, slots=True)
class Answer:
    """One sample of ``/teleop_ui/ui_configuration`` as the operator read it: its JSON
    ``value``, or, when it could not be decoded, its ``text`` and the ``error``."""

    value: Any
    text: str = ""
    error: str | None = None


class OperatorStation:
    """An operator station, as an rclpy node would be one: it publishes the active robot and
    the value of the characteristic ``control`` (``/teleop_ui/active_<control>``), and reads the
    answer (all ``std_msgs/msg/String``, reliable and transient-local)."""

    def __init__(self, domain: int, control: str) -> None:
        self.process = _Participant(domain)
        node = "/operator_station"
        self.robot = self.process.writer(node, "/teleop_ui/active_robot", _STRING, latched=True)
        self.control = self.process.writer(
            node, f"/teleop_ui/active_{control}", _STRING, latched=True
        )
        self.answers = self.process.reader(
            node, "/teleop_ui/ui_configuration", _STRING, latched=True
        )
        self.process.announce()

    def select(self, robot: str, control: str) -> None:
        from solver.live.sources.ros2 import write  # the GIL let go: see there

        write(self.control, self.process.string(control))
        write(self.robot, self.process.string(robot))

    def answer(self) -> "Answer | None":
        """The newest answer since the last call (``None`` if none came), decoded as the
        watcher decodes answers (:func:`~solver.live.values.bounded_json`): any participant
        on the domain may write one."""
        from solver.live.values import bounded_json

        newest = None
        for sample in self.answers.take(N=64):
            text = getattr(sample, "data", None)
            if isinstance(text, str):
                try:
                    newest = Answer(bounded_json(text))
                except ValueError as error:  # not JSON, longer or deeper than the bounds
                    newest = Answer(None, text, str(error))
        return newest

    def close(self) -> None:
        self.process.close()


def _switches(robots: Sequence[DemoRobot]) -> Iterator[tuple[str, str]]:
    while True:
        for robot in robots:
            for control in robot.controls:
                yield robot.namespace, control


@contextmanager
def emulated_fleet(domain: int, robots: Sequence[DemoRobot] = ROBOTS) -> Iterator[OperatorStation]:
    """The robots on ``domain`` and an operator station, left when the block ends."""
    started: list[_Participant] = []
    operator = None
    try:
        started = [_start_robot(robot, domain) for robot in robots]
        operator = OperatorStation(domain, control_name())
        yield operator
    finally:
        if operator is not None:
            operator.close()
        for process in started:
            process.close()


def run_demo(
    domain: int,
    every: float,
    say: Callable[[str], None],
    stopped: threading.Event,
    *,
    rounds: int | None = None,
) -> None:
    """The fleet on ``domain``; the operator switches every ``every`` seconds (``rounds``
    times, or until ``stopped``), saying what it selects and the answer it got before."""
    with emulated_fleet(domain) as operator:
        say(
            f"{len(ROBOTS)} emulated robots on DDS domain {domain}: "
            + ", ".join(robot.namespace for robot in ROBOTS)
        )
        plan = _switches(ROBOTS)
        done = 0
        while not stopped.is_set() and (rounds is None or done < rounds):
            robot, control = next(plan)
            operator.select(robot, control)
            say(f"operator selects {robot} {control}")
            if stopped.wait(every):
                break
            answer = operator.answer()
            say(_answered(answer))
            done += 1


def _answered(answer: "Answer | None") -> str:
    """What the operator says of ``answer``: every value a stranger wrote shown escaped and
    cut (:func:`~solver.live.values.shown_value`), so no answer starts a line of its own."""
    from solver.live.values import kind_of, shown_value

    if answer is None:
        return "  no answer yet (is a watcher running? teleop-ui watch --ros2 ...)"
    if answer.error is not None:
        return f"  answer: unreadable ({answer.error}): {shown_value(answer.text)}"
    value = answer.value
    if value is None:
        return "  answer: none (no active robot)"
    if not isinstance(value, dict):
        return f"  answer: not a watcher's answer ({kind_of(value)})"

    def field(name: str) -> str:
        return shown_value(value[name]) if name in value else "?"

    default = " (default)" if value.get("default") is True else ""
    return (
        f"  answer: UI configuration {field('configuration')}{default} for {field('robot')} "
        f"from {field('watcher')}"
    )
