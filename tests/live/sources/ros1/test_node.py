"""The watcher's node API, and description parameters kept current by the master's pushes."""

from __future__ import annotations

import os
import queue
import select
import socket
import time
import xmlrpc.client
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest

from solver.errors import InputError
from solver.live.graph import MISSING
from solver.live.sources.ros1.descriptions import REREAD_AFTER, Descriptions
from solver.live.sources.ros1.master import MasterClient
from solver.live.sources.ros1.node import MAX_CONNECTIONS, NodeServer, callback_host
from tests.live.hostile import TricklingClients, post_raw
from tests.live.roscore import Roscore, TestNode, wait_until

TIMEOUT = 60.0


class Pushes:
    def __init__(self) -> None:
        self.updates: queue.Queue[str] = queue.Queue()
        self.shutdowns: list[str] = []

    def update(self, key: str) -> None:
        self.updates.put(key)

    def shutdown(self, message: str) -> None:
        self.shutdowns.append(message)


@contextmanager
def lone_node() -> Iterator[NodeServer]:
    """A started node whose master is not asked (its callers are the test's), closed after."""
    pushes = Pushes()
    server = NodeServer("127.0.0.1", "http://127.0.0.1:11311/", pushes.update, pushes.shutdown)
    server.start()
    try:
        yield server
    finally:
        server.close()


def test_the_master_says_which_subscribed_parameter_changed(
    master: Roscore, node: TestNode
) -> None:
    pushes = Pushes()
    server = NodeServer("127.0.0.1", master.uri, pushes.update, pushes.shutdown)
    server.start()
    client = MasterClient(master.uri, caller_id="/listener")
    assert client.subscribe_param(server.uri, "/pushed/robot_description") is MISSING
    node.set_param("/pushed/robot_description", "<robot name='a'/>")
    # Only the key is passed on: the value of a push is never believed (issue 31).
    assert pushes.updates.get(timeout=TIMEOUT) == "/pushed/robot_description/"
    node.delete_param("/pushed/robot_description")
    assert pushes.updates.get(timeout=TIMEOUT) == "/pushed/robot_description/"
    client.unsubscribe_param(server.uri, "/pushed/robot_description")
    server.close()
    client.close()


def test_the_node_answers_what_ros_tools_ask_and_shuts_down_on_request(master: Roscore) -> None:
    pushes = Pushes()
    server = NodeServer("127.0.0.1", master.uri, pushes.update, pushes.shutdown)
    server.start()
    proxy = xmlrpc.client.ServerProxy(server.uri)
    assert proxy.getPid("/rosnode") == [1, "", os.getpid()]
    assert proxy.getMasterUri("/rosnode") == [1, "", master.uri]
    assert proxy.getBusInfo("/rosnode") == [1, "", []]
    refused: Any = proxy.requestTopic("/rosnode", "/x", [["TCPROS"]])
    assert refused[0] == -1
    done: Any = proxy.shutdown("/rosnode", "bye")
    assert done[0] == 1
    assert pushes.shutdowns == ["bye"]
    server.close()


def test_the_node_echoes_nothing_a_caller_sends_back_longer_than_a_line() -> None:
    # A reply as long as the request would keep a thread writing to a caller that reads it
    # slowly: the topic a caller asks for comes back cut.
    with lone_node() as server:
        refused: Any = xmlrpc.client.ServerProxy(server.uri).requestTopic(
            "/rosnode", "/x" * 500_000, [["TCPROS"]]
        )
        assert refused[0] == -1
        assert len(refused[1]) < 200
        assert "cut from 1,000,000 characters" in refused[1]


def test_an_encoded_body_is_refused_unread_and_a_forged_fault_is_not_echoed_whole() -> None:
    # The standard handler inflates a gzip body (20 MB from a small one) and names any other
    # encoding in its error, however long (a folded header of megabytes); a methodResponse
    # carrying a fault came back with the caller's whole text.
    with lone_node() as server:
        call = b"<?xml version='1.0'?><methodCall><methodName>getPid</methodName></methodCall>"
        for encoding in ("gzip", "x" * 60_000):
            head = f"POST / HTTP/1.1\r\nContent-Length: {len(call)}\r\nContent-Encoding: {encoding}"
            refused = post_raw(server.uri, head, call)
            assert refused.split(b"\r\n", 1)[0].split(b" ", 1)[1].startswith(b"415")
            assert len(refused) < 1_000
        fault = xmlrpc.client.dumps(xmlrpc.client.Fault(1, "x" * 1_000_000)).encode()
        answer = post_raw(server.uri, f"POST / HTTP/1.1\r\nContent-Length: {len(fault)}", fault)
        assert b"<name>faultCode</name>" in answer
        assert len(answer) < 2_000
        assert xmlrpc.client.ServerProxy(server.uri).getPid("/rosnode") == [1, "", os.getpid()]


def test_a_node_cannot_listen_on_an_address_of_another_machine() -> None:
    pushes = Pushes()
    with pytest.raises(InputError, match="set ROS_IP to an address of this machine"):
        NodeServer("192.0.2.1", "http://192.0.2.2:11311/", pushes.update, pushes.shutdown)


def test_the_callback_address_follows_ros_conventions(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_IP", raising=False)
    monkeypatch.delenv("ROS_HOSTNAME", raising=False)
    assert callback_host("http://127.0.0.1:11311/") == "127.0.0.1"
    assert callback_host("http://localhost:11311/") == "127.0.0.1"
    monkeypatch.setenv("ROS_HOSTNAME", "station.local")
    assert callback_host("http://10.1.2.3:11311/") == "station.local"
    monkeypatch.setenv("ROS_IP", "10.1.2.4")
    assert callback_host("http://10.1.2.3:11311/") == "10.1.2.4"
    assert callback_host("http://127.0.0.1:11311/") == "127.0.0.1"  # loopback wins


def test_descriptions_are_read_once_then_again_when_the_master_says_they_changed(
    master: Roscore, node: TestNode
) -> None:
    node.set_param("/d1/robot_description", "first")
    client = MasterClient(master.uri, caller_id="/descriptions_test")
    store: Descriptions
    pushed: queue.Queue[str] = queue.Queue()

    def hint(key: str) -> None:
        if store.push(key):
            pushed.put("/" + key.strip("/"))

    server = NodeServer("127.0.0.1", master.uri, hint, lambda _: None)
    server.start()
    store = Descriptions(client, server.uri)
    keys = ["/d1/robot_description", "/d2/robot_description"]
    store.sync(keys)
    assert store.get("/d1/robot_description") == "first"
    assert store.get("/d2/robot_description") is MISSING
    node.set_param("/d2/robot_description", "second")
    node.set_param("/d1/robot_description", "changed")
    assert {pushed.get(timeout=TIMEOUT), pushed.get(timeout=TIMEOUT)} == set(keys)
    store.sync(keys)  # the loop's next poll: what was pushed is read from the master
    assert store.get("/d2/robot_description") == "second"
    assert store.get("/d1/robot_description") == "changed"
    node.delete_param("/d1/robot_description")
    assert pushed.get(timeout=TIMEOUT) == "/d1/robot_description"
    store.sync(keys)
    assert store.get("/d1/robot_description") is MISSING
    assert store.push("/not/followed") is False
    assert client.lookup_node(client.caller_id) == server.uri
    store.sync(["/d2/robot_description"])
    assert store.keys() == ("/d2/robot_description",)
    store.close()
    # Every subscription is gone, so the master forgot the node.
    assert client.lookup_node(client.caller_id) is None
    server.close()
    client.close()


class _Overtaken(MasterClient):
    """The real client; the description changes on the master, and the master says so,
    after the subscription's reply left it with the older value."""

    store: Descriptions
    node: TestNode

    def subscribe_param(self, caller_api: str, key: str) -> Any:
        value = super().subscribe_param(caller_api, key)
        self.node.set_param(key, "newer")
        self.store.push(key)
        return value


def test_a_change_after_the_subscription_reply_is_read_in_the_same_sync(
    master: Roscore, node: TestNode
) -> None:
    node.set_param("/race/robot_description", "older")
    client = _Overtaken(master.uri, caller_id="/race_test")
    client.node = node
    server = NodeServer("127.0.0.1", master.uri, lambda _: None, lambda _: None)
    server.start()
    client.store = Descriptions(client, server.uri)
    client.store.sync(["/race/robot_description"])
    assert client.store.get("/race/robot_description") == "newer"
    client.store.close()
    server.close()


def test_without_a_node_descriptions_are_read_with_get_param(
    master: Roscore, node: TestNode
) -> None:
    node.set_param("/once/robot_description", "text")
    client = MasterClient(master.uri, caller_id="/once_test")
    store = Descriptions(client)
    store.sync(["/once/robot_description", "/none/robot_description"])
    assert store.get("/once/robot_description") == "text"
    assert store.get("/none/robot_description") is MISSING
    assert client.lookup_node(client.caller_id) is None  # it never registered anything
    client.close()


def test_a_request_trickling_in_is_cut_off_at_the_deadline_and_the_node_goes_on() -> None:
    pushes = Pushes()
    master = "http://127.0.0.1:11311/"  # never called: the node only answers
    server = NodeServer("127.0.0.1", master, pushes.update, pushes.shutdown, deadline=1.0)
    server.start()
    host, port = server.uri.removeprefix("http://").rstrip("/").rsplit(":", 1)
    with socket.create_connection((host, int(port)), timeout=TIMEOUT) as connection:
        connection.sendall(b"POST / HTTP/1.1\r\nContent-Length: 100000\r\n\r\n")
        # A byte whenever the server has said nothing for a fifth of a second: each read is
        # well within the per-read timeout, so only the deadline of the whole request ends it.
        ended = False
        give_up = time.monotonic() + TIMEOUT  # a generous ceiling, never a measure
        while not ended:
            assert time.monotonic() < give_up, "the trickling request was never cut off"
            readable, _, _ = select.select([connection], [], [], 0.2)
            if readable:
                ended = connection.recv(1024) == b""
                continue
            try:
                connection.sendall(b"<")
            except (BrokenPipeError, ConnectionResetError):
                ended = True
    assert pushes.updates.empty()
    # The slot is free again: a well-formed call is answered.
    assert xmlrpc.client.ServerProxy(server.uri).getMasterUri("/rosnode") == [1, "", master]
    server.close()


def test_a_request_read_in_time_is_answered_however_long_it_takes_past_the_deadline() -> None:
    """A deep request of the largest size parses for about a second, longer on a busy machine:
    the deadline that cuts off a trickle must not cut off the answer to a request read whole."""
    deadline = 0.2
    accepted = time.monotonic()

    def slow_update(key: str) -> None:
        # Work that outlasts the request's deadline, as a slow parse does on a loaded machine.
        while time.monotonic() < accepted + 3 * deadline:
            time.sleep(deadline / 4)
        pushes.update(key)

    pushes = Pushes()
    master = "http://127.0.0.1:11311/"  # never called: the node only answers
    server = NodeServer("127.0.0.1", master, slow_update, pushes.shutdown, deadline=deadline)
    server.start()
    try:
        accepted = time.monotonic()
        answer = xmlrpc.client.ServerProxy(server.uri).paramUpdate("/master", "/uav1/x", "x")
        assert answer == [1, "", 0]
        assert pushes.updates.get(timeout=TIMEOUT) == "/uav1/x"
    finally:
        server.close()


def test_a_fresh_request_is_served_while_more_connections_than_slots_trickle() -> None:
    """Issue 36 item 7: 32 connections trickling a byte at a time held the node's 16 slots, and
    the master's paramUpdate was closed unanswered. Now the oldest request still being read
    gives its slot to a newcomer."""
    pushes = Pushes()
    master = "http://127.0.0.1:11311/"  # never called: the node only answers
    server = NodeServer("127.0.0.1", master, pushes.update, pushes.shutdown)
    server.start()
    attack = TricklingClients(server.uri, 2 * MAX_CONNECTIONS)
    try:
        # Every slot taken and changing hands: the node is cutting the tricklers off.
        attack.wait_ended(2 * MAX_CONNECTIONS)
        for key in ("/uav1/robot_description", "/teleop_ui/active_robot"):
            answer = xmlrpc.client.ServerProxy(server.uri).paramUpdate("/master", key, "x")
            assert answer == [1, "", 0]
            assert pushes.updates.get(timeout=TIMEOUT) == key
    finally:
        attack.close()
        server.close()


def test_a_change_whose_push_never_came_is_read_again_by_a_later_sync(
    master: Roscore, node: TestNode
) -> None:
    """Issue 36 item 7: a lost push left a description as it was for good. Whoever can reach
    the master can unsubscribe the node in its name; the values are read again anyway."""
    node.set_param("/lost/robot_description", "first")
    client = MasterClient(master.uri, caller_id="/lost_push_test")
    pushes = Pushes()
    server = NodeServer("127.0.0.1", master.uri, pushes.update, pushes.shutdown)
    server.start()
    store = Descriptions(client, server.uri)
    try:
        store.sync(["/lost/robot_description"])
        assert store.get("/lost/robot_description") == "first"
        neighbour = MasterClient(master.uri, caller_id=client.caller_id)
        neighbour.unsubscribe_param(server.uri, "/lost/robot_description")
        neighbour.close()
        node.set_param("/lost/robot_description", "second")

        # The watcher's polls: each sync reads again what is REREAD_AFTER seconds old.
        def polled() -> bool:
            store.sync(["/lost/robot_description"])
            return bool(store.get("/lost/robot_description") == "second")

        wait_until(polled, TIMEOUT + REREAD_AFTER, "the change read again", step=0.05)
        assert pushes.updates.empty()  # no push came: the master was told to send none
    finally:
        store.close()
        server.close()
        client.close()
