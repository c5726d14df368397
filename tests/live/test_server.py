"""``watch --layouts DIR --serve``: the answer and the layouts on loopback, read-only, over real
sockets; a switch on real Cyclone DDS participants reaches the event stream with its layouts;
and every fence: origins, hosts, paths, links, sizes, heads, connections, streams."""

from __future__ import annotations

import http.client
import json
import os
import signal
import socket
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from solver.errors import InputError
from solver.layouts.checks import check_lichtblick
from solver.live import server as serving
from solver.live.server import AnswerServer, ServeAddress, serve_address, viewer_origin
from solver.solving.solution import Solution
from tests.live.fleet import rover_configuration
from tests.live.ros2_graph import Domain, Operator
from tests.live.roscore import wait_until
from tests.live.watching import TIMEOUT, WatchProcess

VIEWER = "http://127.0.0.1:8080"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    """A layouts folder as the watcher leaves it: a robot's layout and the team layout."""
    out = tmp_path / "layouts"
    (out / "uav1").mkdir(parents=True)
    (out / "uav1" / "config-001.json").write_text('{"configById": {}}\n', encoding="utf-8")
    (out / "team.json").write_text('{"team": true}\n', encoding="utf-8")
    return out


@pytest.fixture
def server(folder: Path) -> Iterator[AnswerServer]:
    with AnswerServer(folder, ServeAddress("127.0.0.1", 0), [VIEWER]) as running:
        yield running


class Answer:
    """A response: status, headers (lower-case names) and body."""

    def __init__(self, response: http.client.HTTPResponse) -> None:
        self.status = response.status
        self.headers = {k.lower(): v for k, v in response.getheaders()}
        self.body = response.read()


def get(
    server: AnswerServer, path: str, headers: dict[str, str] | None = None, method: str = "GET"
) -> Answer:
    connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=TIMEOUT)
    try:
        connection.request(method, path, headers=headers or {})
        return Answer(connection.getresponse())
    finally:
        connection.close()


class Stream:
    """An event stream as a browser's EventSource reads it: ``data:`` lines, in order."""

    def __init__(self, port: int, origin: str | None = VIEWER) -> None:
        self.socket = socket.create_connection(("127.0.0.1", port), timeout=TIMEOUT)
        head = f"GET /answer/events HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n"
        head += f"Origin: {origin}\r\n" if origin else ""
        self.socket.sendall((head + "Accept: text/event-stream\r\n\r\n").encode())
        self.reader = self.socket.makefile("rb")
        self.status = self.reader.readline().decode()
        self.headers: dict[str, str] = {}
        while (line := self.reader.readline().decode().rstrip("\r\n")) != "":
            name, _, value = line.partition(":")
            self.headers[name.lower()] = value.strip()

    def next(self) -> Any:
        """The next answer on the stream (keep-alive comments skipped; a last-resort ceiling)."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            line = self.reader.readline().decode()
            if not line:
                raise AssertionError("the stream ended")
            if line.startswith("data: "):
                return json.loads(line[len("data: ") :])
        raise AssertionError("no answer on the stream")

    def close(self) -> None:
        self.reader.close()
        self.socket.close()


def test_the_answer_is_served_whole_and_as_events_as_it_changes(server: AnswerServer) -> None:
    first = get(server, "/answer")
    assert (first.status, first.body) == (200, b"null")
    assert first.headers["content-type"] == "application/json"
    assert first.headers["cache-control"] == "no-store"
    stream = Stream(server.port)
    try:
        assert stream.status.startswith("HTTP/1.1 200")
        assert stream.headers["content-type"] == "text/event-stream"
        assert stream.next() is None  # the current answer first
        answer = {"robot": "/uav1", "configuration": 1, "note": "a\nb\u2028c"}
        server.publish(answer)
        assert stream.next() == answer  # one data line, whatever the answer holds
        assert json.loads(get(server, "/answer").body) == answer
        server.publish(None)
        assert stream.next() is None
    finally:
        stream.close()


def test_cors_headers_go_to_the_viewers_origins_only(server: AnswerServer) -> None:
    viewer = get(server, "/answer", {"Origin": VIEWER})
    assert viewer.headers["access-control-allow-origin"] == VIEWER
    assert viewer.headers["vary"] == "Origin"
    # Another page: refused, and no header that would let its script read anything.
    other = get(server, "/layouts/team.json", {"Origin": "http://evil.example"})
    assert other.status == 403
    assert "access-control-allow-origin" not in other.headers
    assert b"team" not in other.body
    # No origin (curl, a bookmark): served, with no CORS header.
    plain = get(server, "/layouts/team.json")
    assert (plain.status, plain.body) == (200, b'{"team": true}\n')
    assert "access-control-allow-origin" not in plain.headers
    # An event stream for another page is refused before it holds a place.
    stream = Stream(server.port, origin="null")
    try:
        assert stream.status.startswith("HTTP/1.1 403")
    finally:
        stream.close()


def test_another_sites_page_cannot_load_it_without_cors_but_a_person_can_open_it(
    server: AnswerServer,
) -> None:
    # An <img src=".../answer/events"> on any page: it could read nothing, but sixteen would
    # hold every stream the viewer needs.
    loaded = {"Sec-Fetch-Site": "cross-site", "Sec-Fetch-Mode": "no-cors"}
    assert get(server, "/answer/events", loaded).status == 403
    assert get(server, "/answer", {**loaded, "Sec-Fetch-Site": "same-site"}).status == 403
    # A person following a link from another site sees the answer (the page learns nothing).
    opened = {"Sec-Fetch-Site": "cross-site", "Sec-Fetch-Mode": "navigate"}
    assert get(server, "/answer", opened).status == 200
    # The viewer's own requests carry its origin.
    viewer = {"Sec-Fetch-Site": "same-site", "Sec-Fetch-Mode": "cors", "Origin": VIEWER}
    assert get(server, "/answer", viewer).status == 200


def test_a_host_of_another_name_is_refused_against_dns_rebinding(server: AnswerServer) -> None:
    rebound = get(server, "/answer", {"Host": f"attacker.example:{server.port}"})
    assert rebound.status == 421
    assert get(server, "/answer", {"Host": f"localhost:{server.port}"}).status == 200


def test_only_reading_is_answered(server: AnswerServer) -> None:
    assert get(server, "/answer", method="POST").status == 405
    assert get(server, "/answer", method="DELETE").status == 405
    head = get(server, "/layouts/team.json", method="HEAD")
    assert (head.status, head.body, head.headers["content-length"]) == (200, b"", "15")


@pytest.mark.parametrize(
    ("path", "status"),
    [
        ("/layouts/../escape.json", 403),
        ("/layouts/%2e%2e/escape.json", 403),
        ("/layouts/uav1/%2E%2E/%2e%2e/escape.json", 403),
        ("/layouts/.hidden.json", 403),
        ("/layouts/.team.json.abcdefgh.tmp", 403),
        ("/layouts/uav1//config-001.json", 403),
        ("/layouts/uav1\\config-001.json", 403),
        ("/layouts/%ff.json", 400),
        ("/layouts/notes.txt", 404),
        ("/layouts/missing.json", 404),
        ("/layouts/uav1", 404),
        ("/elsewhere", 404),
    ],
)
def test_names_outside_the_folder_or_of_other_files_are_refused(
    server: AnswerServer, folder: Path, path: str, status: int
) -> None:
    (folder.parent / "escape.json").write_text('{"secret": 1}', encoding="utf-8")
    (folder / "notes.txt").write_text("private", encoding="utf-8")
    (folder / ".hidden.json").write_text("{}", encoding="utf-8")
    answer = get(server, path)
    assert answer.status == status
    assert b"secret" not in answer.body
    assert b"private" not in answer.body


def test_links_planted_in_the_folder_are_never_followed(
    server: AnswerServer, folder: Path, tmp_path: Path
) -> None:
    secret = tmp_path / "secret"
    secret.mkdir()
    (secret / "config-001.json").write_text('{"secret": 1}', encoding="utf-8")
    (folder / "stolen.json").symlink_to(secret / "config-001.json")
    (folder / "ugv1").symlink_to(secret, target_is_directory=True)
    for path in ("/layouts/stolen.json", "/layouts/ugv1/config-001.json"):
        answer = get(server, path)
        assert answer.status == 403, path
        assert b"secret" not in answer.body


def test_a_file_too_large_or_no_regular_file_is_refused(server: AnswerServer, folder: Path) -> None:
    with (folder / "huge.json").open("wb") as huge:
        huge.truncate(serving.MAX_FILE_BYTES + 1)  # sparse: no disk taken
    assert get(server, "/layouts/huge.json").status == 413
    os.mkfifo(folder / "pipe.json")  # opening it for reading would block a plain server
    assert get(server, "/layouts/pipe.json").status == 403
    (folder / "folder.json").mkdir()
    assert get(server, "/layouts/folder.json").status == 403
    assert get(server, "/layouts/team.json").status == 200  # and it still serves


def test_a_malformed_or_oversized_head_is_refused(server: AnswerServer) -> None:
    def raw(head: bytes) -> bytes:
        """What the server answers ``head`` with, until it closes (a reset: it stopped reading)."""
        answer = b""
        with socket.create_connection(("127.0.0.1", server.port), timeout=TIMEOUT) as client:
            client.sendall(head)
            try:
                while chunk := client.recv(4096):
                    answer += chunk
            except ConnectionResetError:
                pass
        return answer

    host = f"Host: 127.0.0.1:{server.port}\r\n".encode()
    assert raw(b"GET /answer\r\n" + host + b"\r\n").startswith(b"HTTP/1.1 400")
    assert raw(b"GET /answer HTTP/1.1\r\n" + host + host + b"\r\n").startswith(b"HTTP/1.1 400")
    many = b"".join(f"X-{i}: 1\r\n".encode() for i in range(serving.MAX_HEADERS + 1))
    assert raw(b"GET /answer HTTP/1.1\r\n" + many + b"\r\n").startswith(b"HTTP/1.1 431")
    # A head past MAX_HEAD_BYTES is not read on: the connection is closed unanswered.
    huge = b"GET /answer HTTP/1.1\r\nX: " + b"a" * serving.MAX_HEAD_BYTES + b"\r\n\r\n"
    assert raw(huge) == b""


def test_a_head_that_never_completes_is_closed(
    folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(serving, "HEAD_SECONDS", 0.5)
    with (
        AnswerServer(folder, ServeAddress("127.0.0.1", 0)) as server,
        socket.create_connection(("127.0.0.1", server.port), timeout=TIMEOUT) as client,
    ):
        client.sendall(b"GET /answer HTTP/1.1\r\n")  # and nothing more, ever
        assert _closed_unanswered(client)


def _closed_unanswered(client: socket.socket) -> bool:
    """Whether the server closed ``client`` without a byte of answer (a reset when what the
    client sent was still unread)."""
    client.settimeout(TIMEOUT)
    try:
        return client.recv(4096) == b""
    except ConnectionResetError:
        return True


def test_stalled_connections_make_room_for_a_prompt_one(
    folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(serving, "MAX_CONNECTIONS", 4)
    with AnswerServer(folder, ServeAddress("127.0.0.1", 0)) as server:
        stalled = [socket.create_connection(("127.0.0.1", server.port)) for _ in range(4)]
        try:
            for client in stalled:
                client.sendall(b"GET /ans")
            # One more, prompt: served; the connection that waited longest was closed for it.
            assert get(server, "/answer").status == 200
            assert _closed_unanswered(stalled[0])
        finally:
            for client in stalled:
                client.close()


def test_event_streams_are_bounded(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(serving, "MAX_STREAMS", 2)
    with AnswerServer(folder, ServeAddress("127.0.0.1", 0), [VIEWER]) as server:
        streams = [Stream(server.port) for _ in range(2)]
        try:
            for stream in streams:
                assert stream.next() is None
            extra = Stream(server.port)
            assert extra.status.startswith("HTTP/1.1 503")
            extra.close()
            # A stream that ends gives its place back.
            streams.pop().close()
            wait_until(
                lambda: Stream(server.port).status.startswith("HTTP/1.1 200"),
                TIMEOUT,
                "a free place",
            )
        finally:
            for stream in streams:
                stream.close()


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("8770", ServeAddress("127.0.0.1", 8770)),
        ("0", ServeAddress("127.0.0.1", 0)),
        ("127.0.0.2:8770", ServeAddress("127.0.0.2", 8770)),
        ("localhost:1", ServeAddress("127.0.0.1", 1)),
        ("[::1]:8770", ServeAddress("::1", 8770)),
    ],
)
def test_a_serve_address_is_a_loopback_host_and_a_port(text: str, expected: ServeAddress) -> None:
    assert serve_address(text) == expected


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("0.0.0.0:8770", "'0.0.0.0' is not a loopback address"),
        ("192.168.1.2:8770", "is not a loopback address"),
        ("example.com:80", "is not a loopback address"),
        ("65536", "a port from 0 to 65535"),
        ("http://127.0.0.1:8770", "is not a loopback address"),
        ("8770x", "a port from 0 to 65535"),
        ("\u0661\u0662", "a port from 0 to 65535"),  # Arabic-Indic digits are no port
    ],
)
def test_a_serve_address_elsewhere_is_a_located_refusal(text: str, says: str) -> None:
    with pytest.raises(InputError) as refused:
        serve_address(text)
    (fault,) = refused.value.faults
    assert fault.location.file == "--serve"
    assert says in fault.message


def test_a_viewer_origin_is_scheme_host_and_port_as_a_browser_sends_it() -> None:
    assert viewer_origin("http://127.0.0.1:8080") == "http://127.0.0.1:8080"
    assert viewer_origin("HTTP://LocalHost:8080/") == "http://localhost:8080"
    assert viewer_origin("https://[::1]") == "https://[::1]"
    for bad in ("*", "null", "127.0.0.1:8080", "http://h/x", "http://h?x", "file:///x"):
        with pytest.raises(InputError):
            viewer_origin(bad)


def test_a_port_taken_is_a_located_refusal(server: AnswerServer, folder: Path) -> None:
    with pytest.raises(InputError) as refused:
        AnswerServer(folder, ServeAddress("127.0.0.1", server.port)).start()
    (fault,) = refused.value.faults
    assert fault.location.file == "--serve"
    assert fault.message.startswith(f"cannot listen on 127.0.0.1:{server.port}: ")


# ---- watch --serve, end to end -----------------------------------------------------------


def test_a_switch_reaches_the_event_stream_with_its_layouts_served(
    domain: Domain, solution: Solution, tmp_path: Path
) -> None:
    domain.drone("/uav1")
    domain.rover("/ugv1")
    out = tmp_path / "layouts"
    watch = WatchProcess(
        "--ros2", "--domain", str(domain.id), "--team", "case3", "--layouts", str(out),
        "--serve", "127.0.0.1:0", env=domain.env,
    )  # fmt: skip
    operator = Operator(domain.id)
    try:
        line = wait_until(
            lambda: next((s for s in watch.stderr if s.startswith("serving on ")), None),
            TIMEOUT,
            "the address",
        )
        base = line.split()[2]
        port = int(base.rsplit(":", 1)[1])
        watch.wait_for(lambda e: e["event"] == "synced", "synced")
        stream = Stream(port)
        try:
            assert stream.headers["access-control-allow-origin"] == VIEWER
            assert stream.next() is None  # no active robot yet
            operator.activate("/ugv1")
            answer = stream.next()
        finally:
            stream.close()
        # The answer's layouts, served where it says, byte for byte the files it names.
        assert (answer["robot"], answer["configuration"]) == (
            "/ugv1",
            rover_configuration(solution),
        )
        for link in answer["layouts"].values():
            assert link["url"].startswith(f"{base}/layouts/")
            served = _fetch(link["url"])
            assert served == Path(link["path"]).read_bytes()
        team = json.loads(Path(answer["layouts"]["team"]["path"]).read_bytes())
        follower = team["configById"]["teleop-ui.follower!follower"]
        assert follower["answerUrl"] == f"{base}/answer/events"
        assert check_lichtblick(team, topic_types={"/ugv1/scan": ["sensor_msgs/LaserScan"]}) == ()
        watch.process.send_signal(signal.SIGTERM)
        assert watch.wait() == 0
    finally:
        operator.close()
        watch.kill()
    assert "Traceback" not in "".join(watch.stderr)


def _fetch(url: str) -> bytes:
    host, _, path = url.removeprefix("http://").partition("/")
    address, _, port = host.rpartition(":")
    connection = http.client.HTTPConnection(address, int(port), timeout=TIMEOUT)
    try:
        connection.request("GET", "/" + path, headers={"Origin": VIEWER})
        response = connection.getresponse()
        assert response.status == 200
        assert response.getheader("Access-Control-Allow-Origin") == VIEWER
        return response.read()
    finally:
        connection.close()
