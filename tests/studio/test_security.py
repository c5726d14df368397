"""The studio's fence: who may ask, who may cause work, how much, and what is left behind.

Against the real server where a socket is involved (loopback only); the token of a studio
bound elsewhere is tested on the ASGI application itself, so no test listens beyond loopback.
Every hostile request is written here, as an attacker would send it.
"""

from __future__ import annotations

import asyncio
import json
import socket
from collections.abc import MutableMapping
from concurrent.futures import ThreadPoolExecutor
from typing import Any
from urllib.parse import urlsplit

import pytest

from solver.studio.security import MAX_QUERY_BYTES, Guard, cookie_name, loopback
from solver.studio.server import address
from solver.studio.workspace import MAX_UPLOAD_BYTES, MAX_UPLOAD_FILES
from tests.studio.conftest import Server, StartStudio
from tests.studio.test_pages import _multipart

RULES = b"characteristics:\n  t: {values: [a, b]}\n  c: {values: [x, y]}\n"


def raw(server: Server, head: str, body: bytes = b"") -> tuple[str, bytes]:
    """Send a request as written; the status line of the answer and the answer whole. A
    server that answers and closes before it has read everything sent resets the connection:
    what was answered until then is returned ("" when nothing was)."""
    where = urlsplit(server.url)
    answer = b""
    with socket.create_connection((where.hostname, where.port), timeout=120) as connection:
        try:
            connection.sendall(head.encode("latin-1") + body)
            while chunk := connection.recv(65536):
                answer += chunk
                if b"\r\n\r\n" in answer and b"connection: close" not in answer.lower():
                    break
        except (ConnectionResetError, BrokenPipeError):
            pass
    return answer.split(b"\r\n", 1)[0].decode("latin-1"), answer


def host(server: Server) -> str:
    return f"127.0.0.1:{urlsplit(server.url).port}"


# -- who may ask -----------------------------------------------------------------------------


def test_a_request_without_the_token_is_refused_on_loopback_and_learns_nothing(
    start_studio: StartStudio, tmp_path: Any
) -> None:
    # Another account on the machine knows the port (it is in the process list) but not the
    # token; it asks for the source of the user's private rule set.
    private = tmp_path / "fleet-rules.yaml"
    private.write_text("name: secret fleet\n" + RULES.decode(), encoding="utf-8")
    server = start_studio(str(private))
    for path in ("/rules/source", "/api/count?type=a", "/", "/api/live"):
        status, answer = raw(server, f"GET {path} HTTP/1.1\r\nHost: {host(server)}\r\n\r\n")
        assert status.startswith("HTTP/1.1 401"), (path, status)
        assert b"secret" not in answer
        assert b"token" in answer
    # A wrong token, a cookie of another port's studio, a token given twice: the same.
    port = urlsplit(server.url).port or 0
    for header in (
        f"Cookie: {cookie_name(port)}=wrong",
        f"Cookie: {cookie_name(port + 1)}={server.token}",
        "Authorization: Bearer wrong",
    ):
        status, _ = raw(
            server, f"GET /api/count HTTP/1.1\r\nHost: {host(server)}\r\n{header}\r\n\r\n"
        )
        assert status.startswith("HTTP/1.1 401"), header
    twice = f"token={server.token}&token=x"
    status, _ = raw(server, f"GET /api/count?{twice} HTTP/1.1\r\nHost: {host(server)}\r\n\r\n")
    assert status.startswith("HTTP/1.1 401")


def test_a_person_without_the_token_is_told_where_to_find_it_in_a_page(studio: Server) -> None:
    status, answer = raw(
        studio,
        f"GET / HTTP/1.1\r\nHost: {host(studio)}\r\nSec-Fetch-Mode: navigate\r\n"
        "Accept: text/html\r\n\r\n",
    )
    assert status.startswith("HTTP/1.1 401")
    assert b"content-type: text/html" in answer.lower()
    assert b"open the address it printed" in answer


def test_the_printed_address_sets_this_ports_cookie_and_drops_the_token_from_the_address(
    studio: Server,
) -> None:
    port = urlsplit(studio.url).port or 0
    status, answer = raw(
        studio,
        f"GET /configurations?type=UAV&token={studio.token} HTTP/1.1\r\n"
        f"Host: {host(studio)}\r\nSec-Fetch-Mode: navigate\r\nSec-Fetch-Site: none\r\n\r\n",
    )
    assert status.startswith("HTTP/1.1 303")
    head = answer.decode("latin-1").lower()
    assert "location: /configurations?type=uav\r\n" in head
    assert f"set-cookie: {cookie_name(port)}={studio.token.lower()}; path=/; httponly; " in head
    assert "samesite=strict" in head
    # The cookie is enough from then on; a program may send the token as a header instead.
    cookie = f"Cookie: {cookie_name(port)}={studio.token}\r\n"
    status, _ = raw(
        studio, f"GET /api/count?type=UAV HTTP/1.1\r\nHost: {host(studio)}\r\n{cookie}\r\n"
    )
    assert status.startswith("HTTP/1.1 200")
    assert studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0


def test_a_host_name_of_another_site_is_not_served(studio: Server) -> None:
    # A page elsewhere that rebinds its own name to 127.0.0.1 still sends its own Host.
    bearer = f"Authorization: Bearer {studio.token}\r\n"
    status, _ = raw(studio, f"GET / HTTP/1.1\r\nHost: evil.example\r\n{bearer}\r\n")
    assert status.endswith("421 Misdirected Request")
    port = urlsplit(studio.url).port
    status, _ = raw(studio, f"GET / HTTP/1.1\r\nHost: localhost:{port}\r\n{bearer}\r\n")
    assert status.startswith("HTTP/1.1 200")


# -- who may cause work ----------------------------------------------------------------------


@pytest.mark.parametrize("site", ["cross-site", "same-site"])
def test_a_request_from_another_site_is_refused_even_a_get_with_the_cookie(
    studio: Server, site: str
) -> None:
    # A page on another port of 127.0.0.1 is same-site: the browser sends it the cookie.
    port = urlsplit(studio.url).port or 0
    cookie = f"Cookie: {cookie_name(port)}={studio.token}\r\n"
    for path in ("/api/layouts.zip?type=UAV", "/?type=UAV", "/api/team.yaml?type=UAV"):
        status, answer = raw(
            studio,
            f"GET {path} HTTP/1.1\r\nHost: {host(studio)}\r\n{cookie}"
            f"Sec-Fetch-Site: {site}\r\nSec-Fetch-Mode: no-cors\r\n\r\n",
        )
        assert status.startswith("HTTP/1.1 403"), path
        assert b"cross-site" in answer
    assert studio.kept_files() == []
    # A link elsewhere that carries the token was made by someone who holds it: it opens.
    status, _ = raw(
        studio,
        f"GET /?type=UAV&token={studio.token} HTTP/1.1\r\nHost: {host(studio)}\r\n"
        f"Sec-Fetch-Site: {site}\r\nSec-Fetch-Mode: navigate\r\n\r\n",
    )
    assert status.startswith("HTTP/1.1 303")


def test_a_change_from_another_site_is_refused_and_from_the_studio_allowed(
    studio: Server,
) -> None:
    body, headers = _multipart("file", "rules.yaml", RULES)
    origin = studio.base.rstrip("/")
    status, answer = studio.request(
        "POST", "/api/rules", body, {**headers, "origin": "http://evil.example"}
    )
    assert status == 403
    assert "Origin differs" in json.loads(answer)["error"]
    status, _ = studio.request(
        "POST", "/api/rules", body, {**headers, "sec-fetch-site": "cross-site", "origin": origin}
    )
    assert status == 403
    status, answer = studio.request("POST", "/api/rules", body, {**headers, "origin": origin})
    assert status == 200
    assert json.loads(answer)["id"].startswith("upload-")


def test_gets_leave_no_file_behind_and_only_a_kept_rule_set_stays(studio: Server) -> None:
    team = b"team:\n  UAV: {motion_control: [Flight]}\n"
    for path, upload in (
        ("/api/layouts.zip?type=UAV", None),
        ("/?type=UAV&UAV.motion_control=Flight", None),
        ("/api/findings?type=UAV", None),
        ("/api/check?type=UAV", None),
        ("/api/team?rules=paper", ("team.yaml", team)),
        ("/api/identify?type=UAV", ("r.urdf", b'<robot name="r"><link name="base"/></robot>')),
    ):
        if upload is None:
            status, _ = studio.get(path)
        else:
            status, _ = studio.request("POST", path, *_multipart("file", *upload))
        assert status == 200, path
        assert studio.kept_files() == [], path
    body, headers = _multipart("file", "mine.yaml", RULES)
    assert studio.request("POST", "/api/rules", body, headers)[0] == 200
    assert [p.name for p in studio.kept_files()] == ["mine.yaml"]


def test_a_rule_set_upload_that_fails_leaves_nothing(studio: Server) -> None:
    for name, data in (("bad.yaml", b"characteristics: [\n"), ("team.yaml", b"team: {}\n")):
        body, headers = _multipart("file", name, data)
        assert studio.request("POST", "/api/rules", body, headers)[0] == 422
    assert studio.kept_files() == []


# -- how much --------------------------------------------------------------------------------


def test_a_chunked_body_is_refused_whatever_its_content_length_says(studio: Server) -> None:
    # A small Content-Length and Transfer-Encoding: chunked: the chunks would be read.
    body = b"10000\r\n" + b"x" * 65536 + b"\r\n"
    status, answer = raw(
        studio,
        f"POST /api/rules HTTP/1.1\r\nHost: {host(studio)}\r\n"
        f"Authorization: Bearer {studio.token}\r\n"
        "Content-Type: multipart/form-data; boundary=x\r\nContent-Length: 10\r\n"
        "Transfer-Encoding: chunked\r\n\r\n",
        body,
    )
    assert status.startswith("HTTP/1.1 411")
    assert b"not be chunked" in answer
    assert studio.kept_files() == []
    assert studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0


def test_a_body_larger_than_the_limit_is_refused_before_it_is_read(studio: Server) -> None:
    status, _ = raw(
        studio,
        f"POST /api/identify HTTP/1.1\r\nHost: {host(studio)}\r\n"
        f"Authorization: Bearer {studio.token}\r\n"
        f"Content-Type: multipart/form-data; boundary=x\r\n"
        f"Content-Length: {MAX_UPLOAD_BYTES + 1}\r\n\r\n",
    )
    assert status.startswith("HTTP/1.1 413")
    assert studio.json("/api/solve?type=UAV")["totals"]["valid_robots"] > 0


def test_a_query_past_its_bound_is_refused_before_it_is_read_as_a_selection(
    studio: Server,
) -> None:
    flood = "UAV.sensor_type=" + "x" * MAX_QUERY_BYTES
    status, answer = studio.get(f"/api/solve?type=UAV&{flood}")
    assert status == 414
    assert "at most" in json.loads(answer)["error"]
    # Four times as long: past what the server reads of a request's head at all (it answers
    # 400 and closes, which may reach the sender as a reset).
    line, _ = raw(studio, f"GET /?{flood * 4} HTTP/1.1\r\nHost: {host(studio)}\r\n\r\n")
    assert line in ("", "HTTP/1.1 400 Bad Request")
    assert studio.json("/api/count?type=UAV")["totals"]["valid_robots"] > 0


def test_too_many_files_in_one_upload_are_refused_with_a_located_error(studio: Server) -> None:
    boundary = "many"
    parts = b"".join(
        f'--{boundary}\r\nContent-Disposition: form-data; name="file"; filename="r{i}.urdf"'
        f"\r\n\r\n<robot/>\r\n".encode()
        for i in range(MAX_UPLOAD_FILES + 1)
    )
    status, answer = studio.request(
        "POST",
        "/api/identify",
        parts + f"--{boundary}--\r\n".encode(),
        {"content-type": f"multipart/form-data; boundary={boundary}"},
    )
    assert status == 422
    assert "upload refused" in json.loads(answer)["faults"][0]["message"]


def test_no_request_names_a_path_the_studio_reads(studio: Server) -> None:
    status, answer = studio.get("/api/solve?rules=../../../../etc/passwd&type=UAV")
    assert status == 422
    fault = json.loads(answer)["faults"][0]
    assert fault["path"] == "rules"
    assert "no rule set" in fault["message"]
    # A team file's own `rules:` line names a path: it is not followed.
    team = b"rules: /etc/shadow\nteam:\n  UAV: {motion_control: [Flight]}\n"
    body, headers = _multipart("file", "team.yaml", team)
    status, answer = studio.request("POST", "/api/team?rules=paper", body, headers)
    assert status == 200, answer
    assert ["type", "UAV"] in json.loads(answer)["query"]
    status, _ = studio.get("/static/../pages.py")
    assert status == 404


def test_every_answer_carries_the_content_security_policy(studio: Server) -> None:
    _, answer = raw(studio, f"GET /api/count HTTP/1.1\r\nHost: {host(studio)}\r\n\r\n")
    head = answer.decode("latin-1").lower()
    assert "script-src 'self'" in head
    assert "default-src 'none'" in head
    assert "x-content-type-options: nosniff" in head


# -- a studio bound beyond loopback: the guard alone -----------------------------------------

# A documentation address (RFC 5737): nothing listens there, the guard only compares names.
HOST = "192.0.2.7"


def call(path: str, query: str = "", headers: dict[str, str] | None = None) -> Any:
    """One request to a guard for a studio bound to ``HOST``, no socket: (status, headers)."""
    sent: list[MutableMapping[str, Any]] = []

    async def inner(scope: Any, receive: Any, send: Any) -> None:
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": b"ok"})

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": b""}

    async def send(message: MutableMapping[str, Any]) -> None:
        sent.append(message)

    guard = Guard(inner, host=HOST, port=8765, token="s3cret", max_body=10)
    scope = {
        "type": "http",
        "method": "GET",
        "path": path,
        "raw_path": path.encode(),
        "query_string": query.encode(),
        "headers": [(k.encode(), v.encode()) for k, v in (headers or {}).items()],
    }
    # On a thread of its own: the browser tests' Playwright keeps an event loop on this one.
    with ThreadPoolExecutor(1) as pool:
        pool.submit(asyncio.run, guard(scope, receive, send)).result()
    return sent[0]["status"], dict(sent[0]["headers"])


def test_a_studio_bound_beyond_loopback_asks_for_its_token_whatever_host_name_is_used() -> None:
    assert not loopback(HOST)
    assert all(loopback(name) for name in ("127.0.0.1", "::1", "localhost"))
    assert address(HOST, 8765, "s3cret") == "http://192.0.2.7:8765/?token=s3cret"
    host = {"host": "robots.lab.example:8765"}
    assert call("/", headers=host)[0] == 401
    navigation = {**host, "sec-fetch-mode": "navigate"}
    status, headers = call("/configurations", "token=s3cret&type=UAV", navigation)
    assert status == 303
    assert headers[b"location"] == b"/configurations?type=UAV"
    assert headers[b"set-cookie"].decode().startswith(f"{cookie_name(8765)}=s3cret;")
    assert call("/", headers={**host, "cookie": f"{cookie_name(8765)}=s3cret"})[0] == 200
    assert call("/", headers={**host, "cookie": f"{cookie_name(8765)}=wrong"})[0] == 401
    assert call("/api/solve", headers={**host, "authorization": "Bearer s3cret"})[0] == 200
    # A program's request with the token in its address is served as it is.
    assert call("/api/solve", "token=s3cret", host)[0] == 200


def test_a_loopback_address_carries_its_token_too() -> None:
    assert address("127.0.0.1", 1, "t") == "http://127.0.0.1:1/?token=t"
    assert address("::1", 1, "t") == "http://[::1]:1/?token=t"
