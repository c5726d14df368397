"""Bounded XML-RPC (issue 23 item 5, issue 31 item 3): a deadline for the whole call, a byte
cap on replies compressed or not, no DTD, no value built deeper than the depth bound.

Every peer here is a hostile server the test runs on loopback (:mod:`tests.live.hostile`); the
tests wait for events and assert what ended the call, never how long it took.
"""

from __future__ import annotations

import threading
import time
import xmlrpc.client
from collections.abc import Callable, Iterator

import pytest

from solver.live.graph import MAX_DEPTH, TOO_DEEP, MasterError, MasterUnreachable
from solver.live.sources.ros1.master import MasterClient, ReplyTooLarge
from solver.live.sources.ros1.rpc import MAX_REPLY_BYTES, loads
from tests.live.hostile import (
    Behaviour,
    RawServer,
    answering,
    deep_xml,
    flooding,
    gzip_bomb,
    trickling,
)

REPLY = "<?xml version='1.0'?><methodResponse><params><param>{}</param></params></methodResponse>"


@pytest.fixture
def serve() -> Iterator[Callable[[Behaviour], RawServer]]:
    started: list[RawServer] = []

    def start(behaviour: Behaviour) -> RawServer:
        started.append(RawServer(behaviour))
        return started[-1]

    yield start
    for server in started:
        server.close()


def test_a_reply_trickling_a_byte_a_second_ends_at_the_calls_deadline(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    server = serve(trickling)
    client = MasterClient(server.uri, timeout=1.0)
    with pytest.raises(MasterUnreachable, match="did not answer in time"):
        client.get_pid()  # each byte comes well within 1 s: only a whole-call deadline ends it
    assert server.asked.is_set()
    client.close()


def test_a_call_is_cut_off_from_another_thread_however_long_its_deadline(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    """What SIGTERM does to a watcher blocked on a master with --timeout 3600."""
    server = serve(trickling)
    client = MasterClient(server.uri, timeout=3600.0)

    def stop_when_asked() -> None:
        if server.asked.wait(60):
            client.cut_off(time.monotonic())

    stopper = threading.Thread(target=stop_when_asked)
    stopper.start()
    with pytest.raises(MasterUnreachable, match="did not answer in time"):
        client.get_pid()
    stopper.join()
    client.close()


@pytest.mark.parametrize("chunked", [False, True], ids=["declared", "chunked"])
def test_a_reply_past_the_cap_is_refused(
    serve: Callable[[Behaviour], RawServer], chunked: bool
) -> None:
    server = serve(flooding(chunked=chunked))
    client = MasterClient(server.uri, timeout=600.0)
    with pytest.raises(ReplyTooLarge) as caught:
        client.get_pid()
    assert str(caught.value) == (
        f"{server.uri}: getPid: not read: a reply larger than {MAX_REPLY_BYTES} bytes"
    )
    client.close()


def test_a_gzip_bomb_is_inflated_no_further_than_the_cap(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    bomb = gzip_bomb(MAX_REPLY_BYTES + 1024 * 1024)
    assert len(bomb) < MAX_REPLY_BYTES // 100  # small on the wire, large inflated
    server = serve(answering(bomb, "Content-Encoding: gzip\r\n"))
    client = MasterClient(server.uri, timeout=600.0)
    with pytest.raises(ReplyTooLarge, match=f"larger than {MAX_REPLY_BYTES} bytes"):
        client.get_param("/x")
    client.close()


def test_a_gzip_reply_within_the_cap_is_read(serve: Callable[[Behaviour], RawServer]) -> None:
    import gzip

    body = gzip.compress(xmlrpc.client.dumps(([1, "", 77],), methodresponse=True).encode())
    server = serve(answering(body, "Content-Encoding: gzip\r\n"))
    client = MasterClient(server.uri)
    assert client.get_pid() == 77
    client.close()


@pytest.mark.parametrize(
    ("headers", "body", "message"),
    [
        ("Content-Encoding: br\r\n", b"...", "a reply in content encoding 'br'"),
        ("Content-Encoding: gzip\r\n", b"not gzip", "gzip that does not inflate"),
        (
            "",
            b'<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaa">]><methodResponse/>',
            "a DTD, which XML-RPC never holds",
        ),
        (
            "",
            REPLY.format(
                "<value><struct><member><name>a</name></member></struct></value>"
            ).encode(),
            "malformed XML-RPC (IndexError)",
        ),
    ],
    ids=["brotli", "bad-gzip", "dtd", "struct-without-value"],
)
def test_replies_that_are_not_plain_xml_rpc_are_refused_as_not_a_master(
    serve: Callable[[Behaviour], RawServer], headers: str, body: bytes, message: str
) -> None:
    server = serve(answering(body, headers))
    client = MasterClient(server.uri)
    with pytest.raises(MasterError, match="not a ROS master: unreadable XML-RPC reply") as caught:
        client.get_pid()
    assert message in str(caught.value)
    assert not isinstance(caught.value, MasterUnreachable)
    client.close()


def test_values_deeper_than_the_bound_are_not_built() -> None:
    (value,), method = loads(REPLY.format(deep_xml(3000)).encode())
    assert method is None
    for _ in range(MAX_DEPTH):
        assert isinstance(value, list)
        assert len(value) == 1
        value = value[0]
    assert value is TOO_DEEP
    (shallow,), _ = loads(REPLY.format(deep_xml(3)).encode())
    assert shallow == [[["x"]]]


def test_a_deep_reply_from_a_server_reads_as_too_deep(
    serve: Callable[[Behaviour], RawServer],
) -> None:
    body = REPLY.format(
        "<value><array><data><value><int>1</int></value><value>ok</value>"
        + deep_xml(100_000)
        + "</data></array></value>"
    ).encode()
    server = serve(answering(body))
    client = MasterClient(server.uri)
    value = client.get_param("/x")
    levels = 0
    while isinstance(value, list):
        (value,) = value
        levels += 1
    assert value is TOO_DEEP  # the reply's own array is the first of the 64 levels
    assert levels == MAX_DEPTH - 1
    client.close()
