"""A ROS 2 graph read straight from DDS with Eclipse Cyclone DDS: no ROS 2 installation needed.

ROS 2's DDS middlewares (rmw_cyclonedds_cpp, rmw_fastrtps_cpp, rmw_connextdds) map the ROS
graph onto plain DDS, as the ROS 2 design article "Topic and Service name mapping to DDS" and
the rmw sources define it; this module reads that mapping back:

* a topic ``/ns/name`` is the DDS topic ``rt/ns/name``; a service ``/ns/srv`` is the pair
  ``rq/ns/srvRequest`` / ``rr/ns/srvReply``; an action's topics are ``rt/ns/act/_action/...``;
* a type ``pkg/msg/Type`` is the DDS type ``pkg::msg::dds_::Type_`` (``srv``, ``action`` too);
* every DDS writer and reader is announced in the built-in ``DCPSPublication`` /
  ``DCPSSubscription`` topics (topic name, type name, endpoint GUID), and vanishes from them
  when its participant leaves;
* node names are not DDS entities: every participant publishes ``ros_discovery_info``
  (``rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_``: its gid and, per node, namespace,
  name and the gids of its readers and writers). A gid is the endpoint's 16-byte GUID, carried
  in a 24-byte array before ROS 2 Iron and a 16-byte one from Iron on: both layouts are read,
  each with a reader of its own, and matched on the first 16 bytes;
* ``robot_state_publisher`` publishes ``/<ns>/robot_description`` (``std_msgs/msg/String``)
  reliable and transient-local, once: the reader here asks for transient-local to get it late.
  A robot's teleoperation description is read the same way, from a latched String topic
  ``/<ns>/teleop_description`` beside it.

Robots are then found as on a ROS 1 master: the graph is turned into the neutral
:class:`~solver.live.graph.Observation` (a written ``rt/<ns>/robot_description`` stands for the
parameter ``/<ns>/robot_description``), and :mod:`solver.live.discovery` does the rest.

The operator's selection and the answer are topics (ROS 2 has no parameter server), all
``std_msgs/msg/String``, reliable and transient-local, so that an rclpy or rclcpp station uses
them with standard messages: ``/teleop_ui/active_robot`` in (the robot's namespace), with
``/teleop_ui/active_<characteristic>`` for any characteristic of the rule set (as the ROS 1
parameters of those names; an empty string clears one: a reader is made for each such topic
someone writes, at most :data:`MAX_REQUEST_TOPICS`), and ``/teleop_ui/ui_configuration`` out
(the JSON object a ROS 1 watcher writes to the parameter of that name; ``null`` with no active
robot). An operator station writes the selection through the same source
(:meth:`DdsGraph.set_param` on an ``active_*`` key: ``teleop-ui switch``,
:mod:`solver.live.operator`). A robot's own values are String topics
``/<ns>/teleop_ui/<characteristic>``, read as descriptions are. Watchers announce themselves
on ``/teleop_ui/watchers`` (:mod:`solver.live.rivals`); a watcher's name ends in its
participant's GUID, so whether it still runs is whether that participant is on the domain. A
sample on those ``/teleop_ui`` topics, the answer's included, wakes the watcher for them alone
(:meth:`DdsGraph.observe_params`); anything else discovered or written wakes it for the whole
graph.

*The answer is anyone's to write*: DDS without DDS Security has no access control, so any
participant can publish on ``/teleop_ui/ui_configuration``. The newest sample read is the
answer there; when it is not what this watcher last wrote, its next write goes out again (the
watcher writes when the answer there is no running watcher's, :mod:`solver.live.watcher`), so
a forged answer is replaced as a ROS 1 parameter set by anyone is. Unlike a parameter, a topic
has no one newest value: DDS orders no two writers, and a writer keeps its last sample for the
readers it matches later, so a station can get another participant's answer *after* the
watcher's (a forger's that matched the station late, or any such writer's when the station
joins), and keep it. So while another participant has a writer of the answer topic and the
newest answer read is this watcher's, it is written again :data:`REASSERT_FIRST` seconds after
each write, then at gaps doubling up to :data:`REASSERT_LIMIT`: such a station shows the
forgery for that long at most. (A forger's writer looks like any other: a second watcher's
keeps the schedule going too, one repeated answer every :data:`REASSERT_LIMIT` seconds. A source
that only reads, an operator station's or a snapshot's, has no answer writer.)

*Discovery window.* :meth:`DdsGraph.settle` waits until nothing new was discovered for
:data:`DISCOVERY_QUIET` seconds (at most :data:`DISCOVERY_LIMIT`): the watcher's first
``synced`` then lists the robots that were already there.

Bounds: a description longer than :data:`~solver.identify.readers.safexml.MAX_XML_BYTES` is not
identified (the robot is reported with a located error); a sample that cannot be decoded is
that robot's error too. Nothing one participant sends stops the source.

Not here: identification and events (the watcher's, the same for ROS 1).
"""

# No "from __future__ import annotations": Cyclone DDS resolves the IDL field annotations of
# the classes built in _types() at run time, in their own scope.
import functools
import json
import os
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from solver.errors import InputError
from solver.live.graph import MISSING, DescriptionStore, Observation
from solver.live.values import bounded_json
from solver.untrusted import shown

__all__ = [
    "ACTIVE_TOPIC",
    "ANSWER_TOPIC",
    "DISCOVERY_LIMIT",
    "DISCOVERY_QUIET",
    "MAX_ANNOUNCEMENTS",
    "MAX_REQUEST_TOPICS",
    "REASSERT_FIRST",
    "REASSERT_LIMIT",
    "WATCHERS_TOPIC",
    "DdsGraph",
    "Reassertion",
    "dds_topic",
    "dds_type",
    "message_types",
    "ros_name",
    "ros_type",
]

ACTIVE_TOPIC = "/teleop_ui/active_robot"
ANSWER_TOPIC = "/teleop_ui/ui_configuration"
# Watchers say who they are here (solver.live.rivals).
WATCHERS_TOPIC = "/teleop_ui/watchers"
# Under /teleop_ui, what is not the operator's selection.
_NOT_REQUESTS = ("ui_configuration", "watchers")
# Readers of /teleop_ui/<name> topics (the operator's active_*) at most; announcements kept.
MAX_REQUEST_TOPICS = 64
MAX_ANNOUNCEMENTS = 16
# The discovery window: a snapshot waits until nothing new was discovered for DISCOVERY_QUIET
# seconds, and at most DISCOVERY_LIMIT seconds.
DISCOVERY_QUIET = 0.5
DISCOVERY_LIMIT = 5.0
# The answer written again (see the module docstring) REASSERT_FIRST seconds after it was
# written, then at gaps doubling up to REASSERT_LIMIT, while another participant has a writer
# of the answer topic and the newest answer read is still this watcher's.
REASSERT_FIRST = 1.0
REASSERT_LIMIT = 30.0
_STRING = "std_msgs::msg::dds_::String_"
_DISCOVERY = "ros_discovery_info"
# The topic has no key: every participant's node list is one instance. Lists of participants
# found at once (each writer's last, sent as it is matched) are kept until a poll takes them,
# not written over.
_DISCOVERY_DEPTH = 256
_PREFIXES = {"rt/": "", "rq/": "Request", "rr/": "Reply"}


def dds_topic(name: str, prefix: str = "rt/") -> str:
    """``/uav1/robot_description`` -> ``rt/uav1/robot_description``."""
    return prefix + name.strip("/")


def ros_name(topic: str) -> tuple[str, str] | None:
    """A DDS topic's ROS name and prefix (``rt/``, ``rq/``, ``rr/``); ``None`` for others."""
    for prefix, suffix in _PREFIXES.items():
        if topic.startswith(prefix):
            rest = topic[len(prefix) :]
            if suffix and rest.endswith(suffix):
                rest = rest[: -len(suffix)]
            return "/" + rest, prefix
    return None


def dds_type(ros: str) -> str:
    """``std_msgs/msg/String`` -> ``std_msgs::msg::dds_::String_``."""
    package, kind, name = ros.split("/")
    return f"{package}::{kind}::dds_::{name}_"


def ros_type(dds: str) -> str:
    """``sensor_msgs::msg::dds_::Image_`` -> ``sensor_msgs/msg/Image``; others unchanged."""
    parts = dds.split("::")
    if len(parts) == 4 and parts[2] == "dds_" and parts[3].endswith("_"):
        return f"{parts[0]}/{parts[1]}/{parts[3][:-1]}"
    return dds


@functools.cache
def _dds_write() -> Any:
    """``dds_write`` of the library cyclonedds loaded, as ctypes calls it (set up once)."""
    import ctypes

    from cyclonedds.internal import DDS

    function = DDS._dll_handle.dds_write
    function.restype = ctypes.c_int32
    function.argtypes = [ctypes.c_int32, ctypes.c_void_p]
    return function


def write(writer: Any, sample: Any) -> None:
    """``writer.write(sample)``, with the GIL let go while DDS delivers it.

    cyclonedds' ``DataWriter.write`` calls ``dds_write`` from its C extension holding the GIL,
    and ``dds_write`` delivers to this process's readers itself, waiting for a reader's
    listener that is running. A listener is Python (:meth:`DdsGraph._changed`): a DDS thread
    running it for another participant's sample waits for the GIL, so the two threads would
    wait for each other for ever (seen: a forged answer arriving while the watcher wrote its
    own). Called through ctypes, which lets the GIL go for the call, ``dds_write`` takes the
    same serialized sample (cyclonedds' own ``Sample`` container: bytes and their size) and
    the listener runs. A cyclonedds without these parts gets its own ``write``.
    """
    import ctypes

    from cyclonedds.core import DDSException
    from cyclonedds.topic import Sample

    version = getattr(writer, "_use_version_2", MISSING)
    reference = getattr(writer, "_ref", None)
    if version is MISSING or not isinstance(reference, int):
        writer.write(sample)
        return
    data = sample.serialize(use_version_2=version)
    data = data.ljust((len(data) + 3) & ~3, b"\0")  # as DataWriter.write pads it
    buffer = ctypes.create_string_buffer(data, len(data))
    container = Sample(ctypes.cast(buffer, ctypes.c_void_p), len(data))
    code = _dds_write()(reference, ctypes.byref(container))
    if code < 0:
        raise DDSException(code, f"Occurred while writing sample in {writer!r}")


@dataclass(frozen=True, slots=True)
class Reassertion:
    """When the watcher's answer goes out again (see the module docstring): ``due`` (a
    ``time.monotonic()`` instant; ``None``: never), then ``gap`` seconds after that."""

    due: float | None = None
    gap: float = REASSERT_FIRST

    @classmethod
    def after_write(cls, now: float) -> "Reassertion":
        """The schedule that starts when the answer was written at ``now``."""
        return cls(now + REASSERT_FIRST, REASSERT_FIRST)

    def is_due(self, now: float) -> bool:
        """Whether the schedule has come to its next write at ``now``."""
        return self.due is not None and now >= self.due

    def at(self, now: float, *, own_newest: bool, others: bool) -> "tuple[bool, Reassertion]":
        """Whether to write the answer again at ``now``, and the schedule after: again when
        due while the newest answer read is the watcher's own (``own_newest``) and another
        participant has a writer of the answer topic (``others``); with either gone the
        schedule ends (the watcher's next write starts another)."""
        if not self.is_due(now):
            return False, self
        if not (own_newest and others):
            return False, Reassertion()
        gap = min(2 * self.gap, REASSERT_LIMIT)
        return True, Reassertion(now + gap, gap)


@dataclass(frozen=True, slots=True)
class _Endpoint:
    topic: str
    type_name: str
    participant: bytes
    writer: bool


def message_types() -> Any:
    """``std_msgs/msg/String`` and, by gid size (24 before Iron, 16 from Iron on), the
    ``rmw_dds_common`` discovery types (Gid, NodeEntitiesInfo, ParticipantEntitiesInfo) as
    Cyclone DDS IDL classes; built on first use: ``cyclonedds`` is an optional extra."""
    return _types()


def _types() -> Any:
    """The DDS types, built on first use: ``cyclonedds`` is an optional extra."""
    from dataclasses import dataclass as idl_dataclass

    from cyclonedds.idl import IdlStruct
    from cyclonedds.idl.types import array, sequence, uint8

    @idl_dataclass
    class String(IdlStruct, typename=_STRING):
        data: str

    def discovery(size: int) -> Any:
        @idl_dataclass
        class Gid(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
            data: array[uint8, size]  # type: ignore[valid-type,type-arg]  # an IDL type, not Python's

        @idl_dataclass
        class NodeEntitiesInfo(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
            node_namespace: str
            node_name: str
            reader_gid_seq: sequence[Gid]  # type: ignore[type-arg]  # an IDL type
            writer_gid_seq: sequence[Gid]  # type: ignore[type-arg]  # an IDL type

        @idl_dataclass
        class ParticipantEntitiesInfo(
            IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"
        ):
            gid: Gid
            node_entities_info_seq: sequence[NodeEntitiesInfo]  # type: ignore[type-arg]  # IDL

        return Gid, NodeEntitiesInfo, ParticipantEntitiesInfo

    return String, {24: discovery(24), 16: discovery(16)}


def _require_cyclonedds() -> None:
    try:
        import cyclonedds.domain  # noqa: F401
    except ImportError as error:
        raise InputError.at(
            "<arguments>",
            "--ros2 needs the Cyclone DDS Python binding: pip install 'teleop-ui[ros2]'",
        ) from error


def _join(participant: Any, domain: int) -> Any:
    """A participant on ``domain``; a located error when Cyclone DDS refuses (a malformed
    ``CYCLONEDDS_URI``, an interface that does not exist)."""
    from cyclonedds.core import DDSException

    try:
        return participant(domain)
    except DDSException as error:
        configuration = os.environ.get("CYCLONEDDS_URI")
        where = "CYCLONEDDS_URI" if configuration else "<network>"
        shown_configuration = f" ({shown(configuration, quoted=True)})" if configuration else ""
        raise InputError.at(
            where,
            f"Cyclone DDS cannot join domain {domain} with this configuration"
            f"{shown_configuration}: {shown(str(error))}",
        ) from None


def _latched(depth: int = 1) -> Any:
    from cyclonedds.qos import Policy, Qos

    return Qos(
        Policy.Reliability.Reliable(1_000_000_000),
        Policy.Durability.TransientLocal,
        Policy.History.KeepLast(depth),
    )


class _DescriptionReaders:
    """One transient-local reader per followed ``/<ns>/robot_description``."""

    def __init__(self, graph: "DdsGraph", limit: int) -> None:
        self.graph = graph
        self.limit = limit
        self._lock = threading.Lock()
        self._readers: dict[str, Any] = {}
        self._values: dict[str, Any] = {}

    def sync(self, keys: Iterable[str]) -> None:
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        wanted = {"/" + key.strip("/") for key in keys}
        with self._lock:
            for key in sorted(set(self._readers) - wanted):
                self._readers.pop(key).__del__()  # deletes the DDS reader (idempotent)
                self._values.pop(key, None)
            for key in sorted(wanted - set(self._readers)):
                topic = Topic(self.graph.participant, dds_topic(key), self.graph.string_type)
                self._readers[key] = DataReader(
                    self.graph.participant, topic, qos=_latched(), listener=self.graph.listener
                )
                self._values[key] = MISSING
        self.read()

    def read(self) -> None:
        with self._lock:
            for key, reader in self._readers.items():
                try:
                    samples = reader.take(N=4)
                except Exception as error:  # undecodable: that robot's error, no one else's
                    self._values[key] = InputError.at(
                        key, f"cannot decode the message ({type(error).__name__})"
                    )
                    continue
                for sample in samples:
                    text = getattr(sample, "data", None)
                    if isinstance(text, str):
                        self._values[key] = text

    def get(self, key: str) -> Any:
        """The text, :data:`MISSING`, or an :class:`InputError` (the watcher reports it)."""
        with self._lock:
            return self._values.get("/" + key.strip("/"), MISSING)

    def keys(self) -> tuple[str, ...]:
        with self._lock:
            return tuple(sorted(self._readers))

    def reset(self) -> None:
        """Nothing to forget: a DDS domain does not restart, and a reader dropped here would
        have to wait for the transient-local sample again."""

    def close(self) -> None:
        with self._lock:
            for reader in self._readers.values():
                reader.__del__()
            self._readers.clear()
            self._values.clear()


class DdsGraph:
    """The ROS 2 graph on DDS domain ``domain``, as the watcher's source (see the docstring).

    Cyclone DDS is configured as usual, by ``CYCLONEDDS_URI`` (interfaces, peers, multicast).
    """

    timeout = 0.0

    def __init__(
        self,
        domain: int = 0,
        *,
        caller_id: str | None = None,
        limit: int | None = None,
        answers: bool = True,
    ) -> None:
        """``answers=False``: a participant that reads the graph only (a snapshot, ``assign``,
        an operator station) has no writer of the answer topic, so no watcher takes it for
        a running watcher, nor for another writer of the answer (:class:`Reassertion`)."""
        _require_cyclonedds()
        from cyclonedds.builtin import (
            BuiltinDataReader,
            BuiltinTopicDcpsParticipant,
            BuiltinTopicDcpsPublication,
            BuiltinTopicDcpsSubscription,
        )
        from cyclonedds.core import Listener
        from cyclonedds.domain import DomainParticipant
        from cyclonedds.pub import DataWriter
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        from solver.identify.readers.safexml import MAX_XML_BYTES

        self.domain = domain
        self.name = f"ros2://domain/{domain}"
        self.on_change: Callable[[], None] | None = None
        self.on_params: Callable[[], None] | None = None
        self.on_stop: Callable[[str], None] | None = None  # a DDS graph never asks to stop
        self.listener = Listener(  # type: ignore[no-untyped-call]  # cyclonedds has no hints
            on_data_available=lambda _reader: self._changed()
        )
        # The operator's selection and the announcements: the watched parameters alone.
        self.params_listener = Listener(  # type: ignore[no-untyped-call]  # no hints
            on_data_available=lambda _reader: self._params_changed()
        )
        self.string_type, discovery = _types()
        self.participant = _join(DomainParticipant, domain)
        self._own = self.participant.guid.bytes
        # The participant's GUID in the name: whether a watcher runs is whether it is there.
        self.caller_id = caller_id or f"/teleop_ui_watch_{os.getpid()}_{self._own.hex()}"
        self._publications = BuiltinDataReader(
            self.participant, BuiltinTopicDcpsPublication, listener=self.listener
        )
        self._subscriptions = BuiltinDataReader(
            self.participant, BuiltinTopicDcpsSubscription, listener=self.listener
        )
        # Participants are found before their endpoints: one found with none yet is still
        # being discovered (Observation.discovering).
        self._participant_reader = BuiltinDataReader(
            self.participant, BuiltinTopicDcpsParticipant, listener=self.listener
        )
        self._discovery = [
            DataReader(
                self.participant,
                Topic(self.participant, _DISCOVERY, types[2]),
                qos=_latched(_DISCOVERY_DEPTH),
                listener=self.listener,
            )
            for types in discovery.values()
        ]
        self._requests: dict[str, Any] = {}  # /teleop_ui/<name> -> its reader
        answer = Topic(self.participant, dds_topic(ANSWER_TOPIC), self.string_type)
        self._answer_writer = (
            DataWriter(self.participant, answer, qos=_latched()) if answers else None
        )
        # Anyone on the domain can write the answer: a sample wakes the watcher, which puts
        # its own back when that one is not a running watcher's.
        self._answer_reader = DataReader(
            self.participant, answer, qos=_latched(), listener=self.params_listener
        )
        watchers = Topic(self.participant, dds_topic(WATCHERS_TOPIC), self.string_type)
        # Made on the first announcement: a graph that only looks (a snapshot, an operator's
        # station) writes none, so a switch does not wait for a sample that never comes.
        self._watchers_topic = watchers
        self._announce_writer: Any = None
        self._announce_reader = DataReader(
            self.participant,
            watchers,
            qos=_latched(MAX_ANNOUNCEMENTS),
            listener=self.params_listener,
        )
        self._descriptions = _DescriptionReaders(self, limit or MAX_XML_BYTES)
        self.descriptions: DescriptionStore = self._descriptions
        self._endpoints: dict[bytes, _Endpoint] = {}
        self._participants: set[bytes] = set()  # the others found, alive
        self._nodes: dict[bytes, dict[bytes, str]] = {}  # participant -> endpoint -> node
        self._request_values: dict[str, Any] = {}
        self._announced: dict[str, tuple[bytes | None, Any]] = {}  # key -> (participant, value)
        self._answer_value: Any = MISSING
        self._written: str | None = None
        self._reassertion = Reassertion()  # when the answer goes out again, if it does
        self._announcement: str | None = None
        # The operator's selection, when this participant writes one (``teleop-ui switch``).
        self._selection_writers: dict[str, Any] = {}

    def _changed(self) -> None:
        callback = self.on_change
        if callback is not None:
            callback()

    def _params_changed(self) -> None:
        callback = self.on_params
        if callback is not None:
            callback()

    # -- what the watcher calls ----------------------------------------------------------

    @property
    def node_uri(self) -> str | None:
        return None  # no node API: DDS tells the participants what changed

    def get_pid(self) -> int:
        return self.domain  # a DDS domain does not restart: one "pid" for its lifetime

    def resync(self, namespace: str) -> None:  # noqa: ARG002 - the protocol's
        self.descriptions.reset()

    def running_watcher(self, node: str) -> tuple[bool, str | None]:
        """Whether the watcher ``node`` runs: its name ends in its participant's GUID, and that
        participant is on the domain with a writer of the answer topic."""
        participant = _participant_of(node)
        if participant is None:
            return False, f"whose name carries no DDS participant ({shown(node)}): not a watcher's"
        answer = dds_topic(ANSWER_TOPIC)
        running = any(
            e.participant == participant and e.writer and e.topic == answer
            for e in self._endpoints.values()
        )
        return running, None

    def cut_off(self, when: float | None) -> None:
        """Nothing to cut: no call on DDS waits."""

    def set_param(self, key: str, value: Any) -> None:
        """The answer (``/teleop_ui/ui_configuration``, as JSON), or the operator's selection
        (``/teleop_ui/active_*``, as text: ``teleop-ui switch``)."""
        if _selection_key(key):
            self._select(key, str(value))
        else:
            self._write(json.dumps(value, sort_keys=True))

    def delete_param(self, key: str) -> None:
        """The answer ``null``; a selection cleared (an empty string, as the convention says)."""
        if _selection_key(key):
            self._select(key, "")
        else:
            self._write("null")

    def _select(self, key: str, text: str) -> None:
        """``text`` on the selection topic ``key``, from a writer of this participant's own
        (reliable, transient-local: a watcher that comes later still reads it while this
        participant stays), at most :data:`MAX_REQUEST_TOPICS` of them."""
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        writer = self._selection_writers.get(key)
        if writer is None:
            if len(self._selection_writers) >= MAX_REQUEST_TOPICS:
                raise InputError.at(
                    key, f"at most {MAX_REQUEST_TOPICS} selection topics from one participant"
                )
            topic = Topic(self.participant, dds_topic(key), self.string_type)
            writer = DataWriter(self.participant, topic, qos=_latched())
            self._selection_writers[key] = writer
        write(writer, self.string_type(text))

    def _write(self, text: str) -> None:
        if self._answer_writer is None:
            return  # a source that reads only writes no answer (nor takes one back)
        if text != self._written:
            write(self._answer_writer, self.string_type(text))
            self._written = text
            self._reassertion = Reassertion.after_write(time.monotonic())

    @property
    def reassertion(self) -> Reassertion:
        """When this watcher's answer goes out again, if it does (:class:`Reassertion`)."""
        return self._reassertion

    def _reassert(self) -> None:
        """The answer written again when it is due (see the module docstring and
        :class:`Reassertion`); the endpoints are looked through only then, not every poll."""
        now = time.monotonic()
        if not self._reassertion.is_due(now):
            return
        answer = dds_topic(ANSWER_TOPIC)
        others = any(
            e.writer and e.topic == answer and e.participant != self._own
            for e in self._endpoints.values()
        )
        again, self._reassertion = self._reassertion.at(
            now, own_newest=self._written is not None, others=others
        )
        if again and self._written is not None:  # only a source with a writer has written
            write(self._answer_writer, self.string_type(self._written))

    def announce(self, value: dict[str, Any]) -> None:
        """Publish who this watcher is on ``/teleop_ui/watchers`` (gone with the participant)."""
        text = json.dumps(value, sort_keys=True)
        if text != self._announcement:
            if self._announce_writer is None:
                from cyclonedds.pub import DataWriter

                self._announce_writer = DataWriter(
                    self.participant, self._watchers_topic, qos=_latched()
                )
            write(self._announce_writer, self.string_type(text))
            self._announcement = text

    def close(self) -> None:
        """Leave the domain: the participant and everything it made are deleted (idempotent)."""
        self.on_change = self.on_params = None
        self.descriptions.close()
        self.participant.__del__()

    def settle(
        self,
        stopped: Callable[[], bool] = lambda: False,
        *,
        quiet: float = DISCOVERY_QUIET,
        limit: float = DISCOVERY_LIMIT,
    ) -> None:
        """Wait until discovery is quiet (nothing new for ``quiet`` seconds: no endpoint,
        node, description or robot value, and no participant found without its endpoints; at
        most ``limit``, or until ``stopped()``): what a
        snapshot reports as every robot must give the other participants time to be found."""
        start = last_change = time.monotonic()
        seen: tuple[Any, ...] = ()
        while time.monotonic() - start < limit and not stopped():
            observation = self.observe("/teleop_ui")
            self.descriptions.sync(name for name in observation.param_names if _followed(name))
            followed = self.descriptions.keys()
            now = (observation, tuple(self.descriptions.get(key) is MISSING for key in followed))
            if now != seen:
                seen, last_change = now, time.monotonic()
            elif time.monotonic() - last_change >= quiet and not observation.discovering:
                return
            time.sleep(0.05)

    def observe(self, namespace: str) -> Observation:
        """The graph now, as the watcher reads a ROS 1 master (see the module docstring)."""
        self._read_participants()
        self._read_endpoints()
        # The participants that have an endpoint, once per look: a participant found without
        # one is still being discovered, and one with none left takes its node names with it.
        alive = {endpoint.participant for endpoint in self._endpoints.values()}
        self._read_discovery(alive)
        self._descriptions.read()
        self._follow_requests()
        self._read_requests()
        self._read_answer()
        self._read_announcements()
        self._reassert()
        publishers, subscribers, types, written = self._graph()
        params = self._params()
        return Observation(
            pid=self.domain,
            publishers=tuple((t, tuple(sorted(n))) for t, n in sorted(publishers.items())),
            subscribers=tuple((t, tuple(sorted(n))) for t, n in sorted(subscribers.items())),
            topic_types=tuple(sorted(types.items())),
            param_names=tuple(sorted(written | {f"{namespace}/{k}" for k, _ in params})),
            params=params,
            discovering=self._discovering(alive),
        )

    def _discovering(self, alive: set[bytes]) -> bool:
        """A participant is found whose endpoints are not all found yet: it has none (every
        ROS 2 node's participant has some: its ``ros_discovery_info`` writer and reader), or
        its ``ros_discovery_info`` names a reader or writer not yet discovered (DDS announces
        each endpoint apart; the rmw announces the node's list anew at each one it makes)."""
        if not self._participants <= alive:
            return True
        return any(gid not in self._endpoints for nodes in self._nodes.values() for gid in nodes)

    def observe_params(self, namespace: str) -> tuple[int, tuple[tuple[str, Any], ...]]:  # noqa: ARG002 - the protocol's
        """The selection, the answer and the announcements read now; the graph as last read."""
        self._read_requests()
        self._read_answer()
        self._read_announcements()
        return self.domain, self._params()

    def _params(self) -> tuple[tuple[str, Any], ...]:
        """The ``/teleop_ui`` topics as the parameters a ROS 1 master would hold there."""
        params: list[tuple[str, Any]] = sorted(self._request_values.items())
        if self._answer_value is not MISSING:
            params.append(("ui_configuration", self._answer_value))
        announced = {key: value for key, (_, value) in self._announced.items()}
        if announced:
            params.append(("watchers", announced))
        return tuple(sorted(params))

    # -- reading the domain --------------------------------------------------------------

    def _graph(
        self,
    ) -> tuple[dict[str, set[str]], dict[str, set[str]], dict[str, str], set[str]]:
        """Publishers, subscribers and types by ROS name, and the names of the String topics
        that stand for parameters (descriptions, robots' own values)."""
        node_of: dict[bytes, str] = {}
        for nodes in self._nodes.values():
            node_of.update(nodes)
        publishers: dict[str, set[str]] = {}
        subscribers: dict[str, set[str]] = {}
        types: dict[str, str] = {}
        written: set[str] = set()
        for key, endpoint in self._endpoints.items():
            named = ros_name(endpoint.topic)
            # The watcher's own readers are not part of any robot; a service's replies say
            # nothing a request does not.
            if endpoint.participant == self._own or named is None or named[1] == "rr/":
                continue
            name, prefix = named
            node = node_of.get(key) or f"/_participant_{endpoint.participant.hex()[:12]}"
            # A service server reads requests: it is "subscribed" to the service, as a
            # command; a client writes them.
            side = publishers if endpoint.writer else subscribers
            side.setdefault(name, set()).add(node)
            types.setdefault(name, ros_type(endpoint.type_name))
            if endpoint.writer and prefix == "rt/" and _parameter_like(name, endpoint.type_name):
                written.add(name)
        return publishers, subscribers, types, written

    def _follow_requests(self) -> None:
        """A reader for each ``/teleop_ui/<name>`` String topic someone writes (the operator's
        ``active_*``), at most :data:`MAX_REQUEST_TOPICS`."""
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        for endpoint in list(self._endpoints.values()):
            named = ros_name(endpoint.topic)
            if not endpoint.writer or named is None or endpoint.type_name != _STRING:
                continue
            parts = named[0].strip("/").split("/")
            if len(parts) != 2 or parts[0] != "teleop_ui" or parts[1] in _NOT_REQUESTS:
                continue
            if parts[1] in self._requests or len(self._requests) >= MAX_REQUEST_TOPICS:
                continue
            self._requests[parts[1]] = DataReader(
                self.participant,
                Topic(self.participant, endpoint.topic, self.string_type),
                qos=_latched(),
                listener=self.params_listener,
            )

    def _read_requests(self) -> None:
        for name, reader in self._requests.items():
            for sample in reader.take(N=16):
                text = getattr(sample, "data", None)
                if not isinstance(text, str):
                    continue
                if text.strip():
                    self._request_values[name] = text.strip()
                else:  # an empty string clears the selection, as deleting the parameter
                    self._request_values.pop(name, None)

    def _read_answer(self) -> None:
        for sample in self._answer_reader.take(N=16):
            text = getattr(sample, "data", None)
            if isinstance(text, str):
                if text != self._written:
                    # Another writer's (or an older one of ours): the topic no longer holds
                    # what this watcher wrote, so its next write must go out again.
                    self._written = None
                try:
                    value = bounded_json(text)
                except ValueError:  # not JSON, too long or too deep: not an answer to keep
                    value = text
                self._answer_value = MISSING if value is None else value

    def _read_announcements(self) -> None:
        """Other watchers' announcements, by watcher; those whose participant left are gone."""
        for sample in self._announce_reader.take(N=MAX_ANNOUNCEMENTS):
            text = getattr(sample, "data", None)
            try:
                value = bounded_json(text) if isinstance(text, str) else None
            except ValueError:
                continue
            watcher = value.get("watcher") if isinstance(value, dict) else None
            if isinstance(watcher, str) and len(watcher) <= 200:
                self._announced[watcher.strip("/")] = (_participant_of(watcher), value)
        alive = {endpoint.participant for endpoint in self._endpoints.values()}
        self._announced = {
            key: (participant, value)
            for key, (participant, value) in list(self._announced.items())[-MAX_ANNOUNCEMENTS:]
            if participant in alive
        }

    def _read_participants(self) -> None:
        for sample in self._participant_reader.take(N=10_000):
            key = sample.key.bytes
            if not _alive(sample):
                self._participants.discard(key)
            elif key != self._own:
                self._participants.add(key)

    def _read_endpoints(self) -> None:
        for reader, writer in ((self._publications, True), (self._subscriptions, False)):
            for sample in reader.take(N=100_000):
                key = sample.key.bytes
                if _alive(sample) and getattr(sample, "topic_name", None) is not None:
                    self._endpoints[key] = _Endpoint(
                        sample.topic_name, sample.type_name, sample.participant_key.bytes, writer
                    )
                else:
                    self._endpoints.pop(key, None)

    def _read_discovery(self, alive: set[bytes]) -> None:
        """The node names each participant announces; ``alive``: the participants with an
        endpoint (the others' names are dropped). A list is taken only from the participant it
        names (its writer's): another participant's would rename that one's nodes, or keep a
        look waiting for endpoints it never makes."""
        for reader in self._discovery:
            try:
                samples = reader.take(N=10_000)
            except Exception:  # a malformed announcement names no node: not fatal
                continue
            for sample in samples:
                gid = getattr(sample, "gid", None)
                owner = None if gid is None else bytes(gid.data)[:16]
                if owner is None or _writer_participant(reader, sample) != owner:
                    continue
                nodes: dict[bytes, str] = {}
                for info in sample.node_entities_info_seq:
                    namespace = "/" + str(info.node_namespace).strip("/")
                    node = (namespace.rstrip("/") + "/" + str(info.node_name)).replace("//", "/")
                    for endpoint in (*info.reader_gid_seq, *info.writer_gid_seq):
                        nodes[bytes(endpoint.data)[:16]] = node
                self._nodes[owner] = nodes
        for participant in [p for p in self._nodes if p not in alive]:
            del self._nodes[participant]


def _alive(sample: Any) -> bool:
    """A built-in topic's sample says its entity is there (not disposed or gone)."""
    from cyclonedds.core import InstanceState

    info = getattr(sample, "sample_info", None)
    return info is None or info.instance_state == InstanceState.Alive


def _writer_participant(reader: Any, sample: Any) -> bytes | None:
    """The GUID of the participant whose writer sent ``sample`` to ``reader``, or ``None`` when
    that writer is not known (it left)."""
    info = getattr(sample, "sample_info", None)
    if info is None:
        return None
    try:
        writer = reader.get_matched_publication_data(info.publication_handle)
    except Exception:  # a writer gone between the sample and the question
        return None
    return None if writer is None else bytes(writer.participant_key.bytes)


def _selection_key(key: str) -> bool:
    """``/teleop_ui/active_<name>``: a topic of the operator's selection, not the answer."""
    parts = key.strip("/").split("/")
    return len(parts) == 2 and parts[0] == "teleop_ui" and parts[1].startswith("active_")


def _participant_of(watcher: str) -> bytes | None:
    """The participant GUID a watcher's name ends in (``..._<32 hex digits>``), or ``None``."""
    tail = watcher.rsplit("_", 1)[-1]
    if len(tail) != 32:
        return None
    try:
        return bytes.fromhex(tail)
    except ValueError:
        return None


# String topics that stand for a robot's parameters of these names (solver.live.discovery).
_DESCRIPTIONS = ("robot_description", "teleop_description")


def _parameter_like(name: str, type_name: str) -> bool:
    """A String topic standing for a parameter: a description (the URDF, or the robot's
    teleoperation description), or a robot's own value."""
    if type_name != _STRING:
        return False
    parts = name.strip("/").split("/")
    return parts[-1] in _DESCRIPTIONS or (len(parts) >= 2 and parts[-2] == "teleop_ui")


def _followed(name: str) -> bool:
    """What a one-shot look reads before it reports: descriptions and robots' own values."""
    return name.endswith(tuple(f"/{d}" for d in _DESCRIPTIONS)) or (
        "/teleop_ui/" in name and not name.startswith("/teleop_ui/")
    )
