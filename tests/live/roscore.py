"""A real ROS master for tests and benchmarks: ``roscore`` on a free loopback port.

:class:`Roscore` starts Debian's ``roscore`` (rosmaster plus the rosout node, as robots run it)
in its own process group, with ``ROS_HOME`` and ``ROS_LOG_DIR`` in a temporary folder and
``ROS_IP=127.0.0.1`` so that it binds and advertises the loopback address only. It is ready
when its XML-RPC API answers. :meth:`Roscore.kill` kills the whole group at once (a crash, as
the watcher must survive it); :meth:`Roscore.start` brings it back on the same port.

:class:`TestNode` is a ROS node API (an XML-RPC server on loopback answering the calls the
master makes: ``publisherUpdate``, ``paramUpdate``, ``shutdown``, ``getPid``), with helpers that
register publishers and subscribers and set descriptions through the master API, as a robot's
nodes do when they start.
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, TypeVar
from xmlrpc.server import SimpleXMLRPCRequestHandler, SimpleXMLRPCServer

from solver.live.graph import MasterError
from solver.live.sources.ros1.master import MasterClient
from tests.processes import end, marked

T = TypeVar("T")

# What roscore itself puts on the parameter server.
ROSCORE_PARAMS = frozenset({"/run_id", "/roslaunch", "/rosversion", "/rosdistro"})
ROSCORE_MARK = "TELEOP_UI_TEST_ROSCORE"
STARTUP_TIMEOUT = 120.0  # seconds; a loaded 2-core machine starts roscore slowly


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def roscore_available() -> bool:
    return shutil.which("roscore") is not None


class Roscore:
    """A ``roscore -p PORT`` process group on 127.0.0.1 (see the module docstring)."""

    def __init__(self, home: Path, port: int | None = None) -> None:
        self.home = home
        self.port = port or free_port()
        self.uri = f"http://127.0.0.1:{self.port}/"
        self.process: subprocess.Popen[bytes] | None = None
        self.starts = 0
        self.mark = f"{os.getpid()}-{self.port}-{id(self)}"

    def environment(self) -> dict[str, str]:
        env = {
            k: v
            for k, v in os.environ.items()
            if k not in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_NAMESPACE")
        }
        env.update(ROS_HOME=str(self.home), ROS_LOG_DIR=str(self.home / "log"), ROS_IP="127.0.0.1")
        # Every process of this roscore (rosmaster and rosout too, in sessions of their own)
        # carries this mark, so kill() finds them all, even one started a moment before.
        env[ROSCORE_MARK] = self.mark
        # This environment's scripts come first on PATH, as in a shell where it is activated:
        # installing the project must not put anything there that breaks roscore (pip's
        # rospkg, for one, installs a `rosversion` that knows no ROS packages).
        scripts = str(Path(sys.executable).parent)
        env["PATH"] = os.pathsep.join([scripts, env.get("PATH", "")])
        return env

    def start(self) -> None:
        self.starts += 1
        log = (self.home / f"roscore-{self.starts}.log").open("wb")
        self.process = subprocess.Popen(
            ["roscore", "-p", str(self.port)],
            stdout=log,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,
            env=self.environment(),
            start_new_session=True,
        )
        log.close()
        client = MasterClient(self.uri, caller_id="/test_probe", timeout=2.0)
        try:
            wait_until(
                lambda: self._answers(client),
                STARTUP_TIMEOUT,
                f"roscore on port {self.port} (log: {self.home})",
            )
            # The master answers before roslaunch has written its parameters and rosout has
            # registered: a test that counts the graph's changes would count those.
            wait_until(
                lambda: self._settled(client),
                STARTUP_TIMEOUT,
                f"roscore's own parameters and rosout on port {self.port} (log: {self.home})",
            )
        finally:
            client.close()

    def _settled(self, client: MasterClient) -> bool:
        graph = client.observe(None)
        return (
            _top_level(graph.param_names) >= ROSCORE_PARAMS
            and any(topic == "/rosout_agg" for topic, _ in graph.publishers)
            and any(topic == "/rosout" for topic, _ in graph.subscribers)
        )

    def _answers(self, client: MasterClient) -> bool:
        if self.process is not None and self.process.poll() is not None:
            log = (self.home / f"roscore-{self.starts}.log").read_text(errors="replace")
            raise RuntimeError(f"roscore exited with {self.process.returncode}:\n{log}")
        try:
            client.get_pid()
        except MasterError:
            return False
        return True

    def kill(self) -> None:
        """SIGKILL roscore and everything it started, at once, and reap it.

        roslaunch starts rosmaster and rosout each in a session of their own (``setsid``), so
        killing roscore's process group alone would leave the master running, and a rosout
        being started at that moment is in no list yet: every process carrying this roscore's
        mark is killed until none is left (:mod:`tests.processes`).
        """
        if self.process is None:
            return
        process, self.process = self.process, None
        process.kill()
        wait_until(self._ended, 60, f"roscore on port {self.port} to end")
        process.wait(timeout=60)
        client = MasterClient(self.uri, caller_id="/test_probe", timeout=1.0)
        try:
            wait_until(lambda: not self._answers(client), 60, "roscore to go away")
        finally:
            client.close()

    def _ended(self) -> bool:
        left = marked(self.mark, variable=ROSCORE_MARK)
        end(left)
        return not left


def _top_level(param_names: Iterable[str]) -> set[str]:
    """The top-level names of ``param_names`` (``/roslaunch`` for ``/roslaunch/uris/host``)."""
    return {"/" + name.strip("/").split("/")[0] for name in param_names}


def wait_until(
    condition: Callable[[], T | None], timeout: float, what: str, step: float = 0.02
) -> T:
    """Poll ``condition`` until it returns something true; generous timeouts, no assertions
    on durations."""
    deadline = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise TimeoutError(f"gave up waiting for {what} after {timeout:.0f} s")
        time.sleep(step)


class _Quiet(SimpleXMLRPCRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


class _Server(SimpleXMLRPCServer):
    allow_reuse_address = True


class TestNode:
    """A node API on loopback, so the master has a real node to call for our registrations."""

    __test__ = False  # not a pytest test class

    def __init__(self, master: str) -> None:
        self.master = master
        self.server = _Server(
            ("127.0.0.1", 0), requestHandler=_Quiet, logRequests=False, allow_none=False
        )
        self.api = f"http://127.0.0.1:{self.server.server_address[1]}/"
        self.calls: list[tuple[str, tuple[Any, ...]]] = []
        self.registered: set[tuple[str, str, str]] = set()
        for name in ("publisherUpdate", "paramUpdate", "shutdown", "getPid"):
            self.server.register_function(self._recorder(name), name)
        self.thread = threading.Thread(
            target=self.server.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True
        )
        self.thread.start()

    def _recorder(self, name: str) -> Callable[..., list[Any]]:
        def record(*args: Any) -> list[Any]:
            self.calls.append((name, args))
            return [1, "", os.getpid() if name == "getPid" else 0]

        return record

    def client(self, node: str) -> MasterClient:
        return MasterClient(self.master, caller_id=node, timeout=5.0)

    def publish(self, node: str, topics: Iterable[tuple[str, str]]) -> None:
        client = self.client(node)
        for topic, message_type in topics:
            client.register_publisher(topic, message_type, self.api)
            self.registered.add(("publisher", node, topic))
        client.close()

    def subscribe(self, node: str, topics: Iterable[tuple[str, str]]) -> None:
        client = self.client(node)
        for topic, message_type in topics:
            client.register_subscriber(topic, message_type, self.api)
            self.registered.add(("subscriber", node, topic))
        client.close()

    def clear(self) -> None:
        """Unregister everything this node registered and delete every parameter but
        roscore's own: the master is as roscore started it."""
        self.unregister_all()
        client = self.client("/test_cleaner")
        for name in _top_level(client.observe().param_names):
            if name not in ROSCORE_PARAMS:
                client.delete_param(name)
        client.close()

    def unregister_all(self) -> None:
        """Unregister every publisher and subscriber this node registered."""
        for side, node, topic in sorted(self.registered):
            client = self.client(node)
            if side == "publisher":
                client.unregister_publisher(topic, self.api)
            else:
                client.unregister_subscriber(topic, self.api)
            client.close()
        self.registered.clear()

    def unpublish(self, node: str, topics: Iterable[str]) -> None:
        client = self.client(node)
        for topic in topics:
            client.unregister_publisher(topic, self.api)
        client.close()

    def unsubscribe(self, node: str, topics: Iterable[str]) -> None:
        client = self.client(node)
        for topic in topics:
            client.unregister_subscriber(topic, self.api)
        client.close()

    def set_param(self, key: str, value: Any, node: str = "/operator_station") -> None:
        client = self.client(node)
        client.set_param(key, value)
        client.close()

    def delete_param(self, key: str, node: str = "/operator_station") -> None:
        client = self.client(node)
        client.delete_param(key)
        client.close()

    def get_param(self, key: str) -> Any:
        client = self.client("/test_reader")
        try:
            return client.get_param(key)
        finally:
            client.close()

    def close(self) -> None:
        self.server.shutdown()
        self.server.server_close()
