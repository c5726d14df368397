"""Fixtures' helpers for the ROS 2 live tests: a loopback-only Cyclone DDS configuration and
emulated robots (:mod:`tests.live.ros2_robot`) as separate processes, as real robots are.

The configuration keeps every test on 127.0.0.1: the loopback interface only, no multicast,
unicast discovery to 127.0.0.1 (participant indices up to 120, so that tens of participants on
one host find each other), and a domain id of its own per test.
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from solver.live.sources.ros2 import write
from tests.conftest import ROOT
from tests.live.fleet import drone_text, rover_text

CONFIG = """<?xml version="1.0" encoding="UTF-8"?>
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

_DOMAINS = itertools.count(os.getpid() % 50)
# tools/test.sh runs the suite in pytest-xdist workers (gw0, gw1, ...), each a process of its
# own: worker w of n takes the ids w, w + n, w + 2n ..., so no two workers share a domain.
_WORKER = int(os.environ.get("PYTEST_XDIST_WORKER", "gw0").removeprefix("gw") or 0)
_WORKERS = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))


def next_domain() -> int:
    """A DDS domain id no earlier test of this run, in any worker, used (ids 20 to 219)."""
    return (next(_DOMAINS) * _WORKERS + _WORKER) % 200 + 20


def write_config(directory: Path) -> str:
    path = directory / "cyclonedds.xml"
    path.write_text(CONFIG, encoding="utf-8")
    return path.as_uri()


class EmulatedRobot:
    """One ROS 2 process on the domain (see :mod:`tests.live.ros2_robot`)."""

    def __init__(self, domain: int, env: dict[str, str], gid_size: int = 16) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "tests.live.ros2_robot", str(domain), str(gid_size)],
            cwd=ROOT,
            env=env,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )
        self._answer()

    def _answer(self) -> None:
        assert self.process.stdout is not None
        line = self.process.stdout.readline()
        if line.strip() != "ok":
            raise AssertionError(f"the emulated robot did not start: {line!r}")

    def send(self, **command: Any) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(json.dumps(command) + "\n")
        self.process.stdin.flush()
        self._answer()

    def node(
        self,
        name: str,
        publish: Sequence[tuple[str, str]] = (),
        subscribe: Sequence[tuple[str, str]] = (),
        services: Sequence[tuple[str, str]] = (),
    ) -> None:
        self.send(
            node=name, publish=list(publish), subscribe=list(subscribe), services=list(services)
        )

    def latch(self, topic: str, text: str) -> None:
        """A latched String from the robot: its own value (``/ns/teleop_ui/<name>``)."""
        self.send(latch=topic, text=text)

    def describe(self, namespace: str, text: str, directory: Path) -> None:
        path = directory / f"{namespace.strip('/').replace('/', '_') or 'root'}.urdf"
        path.write_text(text, encoding="utf-8")
        self.send(describe=namespace, file=str(path))

    def kill(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait(timeout=30)
        for stream in (self.process.stdin, self.process.stdout):
            if stream is not None:
                stream.close()


class Operator:
    """An operator station as an rclpy node would be one: it publishes the active robot and
    reads the answer, both ``std_msgs/msg/String``, reliable and transient-local."""

    def __init__(self, domain: int) -> None:
        from cyclonedds.domain import DomainParticipant
        from cyclonedds.pub import DataWriter
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        from tests.live.ros2_robot import LATCHED, struct

        self.String = struct("std_msgs::msg::dds_::String_")
        self.participant = DomainParticipant(domain)
        self.writers: dict[str, Any] = {
            name: DataWriter(
                self.participant,
                Topic(self.participant, f"rt/teleop_ui/{name}", self.String),
                qos=LATCHED,
            )
            for name in ("active_robot", "active_motion_control")
        }
        self.writer = self.writers["active_robot"]
        # One topic object for the answers: a test writing hostile answers reuses it rather
        # than creating the same topic again in this participant while the watcher's thread
        # creates its own (once seen failing with DDS_RETCODE_BAD_PARAMETER under load).
        self.answer_topic: Any = Topic(
            self.participant, "rt/teleop_ui/ui_configuration", self.String
        )
        self.reader: Any = DataReader(self.participant, self.answer_topic, qos=LATCHED)
        self.answers: list[Any] = []

    def activate(self, robot: str) -> None:
        write(self.writer, self.String(robot))  # the GIL let go: the watcher runs here too

    def control(self, motion_control: str) -> None:
        """Select the motion control to answer for (an empty string clears it)."""
        self.select("motion_control", motion_control)

    def select(self, name: str, value: str) -> None:
        """Select a value of the characteristic ``name`` on ``/teleop_ui/active_<name>`` (an
        empty string clears it)."""
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from tests.live.ros2_robot import LATCHED

        key = f"active_{name}"
        if key not in self.writers:
            self.writers[key] = DataWriter(
                self.participant,
                Topic(self.participant, f"rt/teleop_ui/{key}", self.String),
                qos=LATCHED,
            )
        write(self.writers[key], self.String(value))

    def answer(self) -> Any:
        """The newest answer read so far (``None`` before any)."""
        for sample in self.reader.take(N=64):
            self.answers.append(json.loads(sample.data))
        return self.answers[-1] if self.answers else None

    def close(self) -> None:
        for entity in (self.reader, *self.writers.values(), self.participant):
            entity.__del__()


class Domain:
    """A DDS domain of this test's own, on loopback, and the robots started on it."""

    def __init__(self, directory: Path, env: dict[str, str]) -> None:
        self.id = next_domain()
        self.directory = directory
        self.env = env
        self.robots: list[EmulatedRobot] = []

    def robot(self, gid_size: int = 16) -> EmulatedRobot:
        self.robots.append(EmulatedRobot(self.id, self.env, gid_size))
        return self.robots[-1]

    def drone(self, namespace: str, gid_size: int = 16) -> EmulatedRobot:
        robot = self.robot(gid_size)
        robot.node(
            f"{namespace}/camera_driver",
            publish=[(f"{namespace}/camera/image_raw", "sensor_msgs/msg/Image")],
        )
        robot.describe(namespace, drone_text(), self.directory)
        return robot

    def rover(self, namespace: str, gid_size: int = 16) -> EmulatedRobot:
        robot = self.robot(gid_size)
        robot.node(
            f"{namespace}/base_driver",
            subscribe=[(f"{namespace}/cmd_vel", "geometry_msgs/msg/Twist")],
            publish=[(f"{namespace}/scan", "sensor_msgs/msg/LaserScan")],
        )
        robot.describe(namespace, rover_text(), self.directory)
        return robot
