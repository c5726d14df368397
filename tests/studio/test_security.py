"""The studio's fence: who may ask, who may change, how much, and what can be read.

Against the real server where a socket is involved (loopback only); the token of a studio
bound elsewhere is tested on the ASGI application itself, so no test listens beyond loopback.
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

from solver.studio.security import COOKIE, Guard, loopback
from solver.studio.server import address
from solver.studio.workspace import MAX_UPLOAD_BYTES, MAX_UPLOAD_FILES
from tests.studio.conftest import Server
from tests.studio.test_pages import _multipart


def raw(server: Server, head: str) -> str:
    """Send a request head as written and read the status line of the answer."""
    where = urlsplit(server.url)
    with socket.create_connection((where.hostname, where.port), timeout=120) as connection:
        connection.sendall(head.encode("latin-1"))
        return connection.makefile("rb").readline().decode("latin-1").strip()


def test_a_host_name_of_another_site_is_not_served(studio: Server) -> None:
    # A page elsewhere that rebinds its own name to 127.0.0.1 still sends its own Host.
    assert raw(studio, "GET / HTTP/1.1\r\nHost: evil.example\r\n\r\n").endswith(
        "421 Misdirected Request"
    )
    port = urlsplit(studio.url).port
    assert raw(studio, f"GET / HTTP/1.1\r\nHost: localhost:{port}\r\n\r\n").startswith(
        "HTTP/1.1 200"
    )


def test_a_change_from_another_site_is_refused_and_from_the_studio_allowed(
    studio: Server,
) -> None:
    body, headers = _multipart("file", "rules.yaml", b"characteristics:\n  t: {values: [a]}\n")
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


def test_a_body_larger_than_the_limit_is_refused_before_it_is_read(studio: Server) -> None:
    port = urlsplit(studio.url).port
    status = raw(
        studio,
        f"POST /api/identify HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n"
        f"Content-Type: multipart/form-data; boundary=x\r\n"
        f"Content-Length: {MAX_UPLOAD_BYTES + 1}\r\n\r\n",
    )
    assert status.startswith("HTTP/1.1 413")
    assert studio.json("/api/solve?type=UAV")["totals"]["valid_robots"] > 0


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
    import urllib.request

    with urllib.request.urlopen(studio.url, timeout=120) as response:
        policy = response.headers["content-security-policy"]
        assert "script-src 'self'" in policy
        assert "default-src 'none'" in policy
        assert response.headers["x-content-type-options"] == "nosniff"


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


def test_a_studio_bound_beyond_loopback_asks_for_its_token() -> None:
    assert not loopback(HOST)
    assert all(loopback(name) for name in ("127.0.0.1", "::1", "localhost"))
    assert address(HOST, 8765, "s3cret") == "http://192.0.2.7:8765/?token=s3cret"
    host = {"host": f"{HOST}:8765"}
    assert call("/", headers=host)[0] == 401
    status, headers = call("/configurations", "token=s3cret&type=UAV", host)
    assert status == 303
    assert headers[b"location"] == b"/configurations?type=UAV"
    cookie = headers[b"set-cookie"].decode()
    assert cookie.startswith(f"{COOKIE}=s3cret;")
    assert "HttpOnly" in cookie
    assert call("/", headers={**host, "cookie": f"{COOKIE}=s3cret"})[0] == 200
    assert call("/", headers={**host, "cookie": f"{COOKIE}=wrong"})[0] == 401
    bearer = {**host, "authorization": "Bearer s3cret"}
    assert call("/api/solve", headers=bearer)[0] == 200


@pytest.mark.parametrize("host", ["127.0.0.1", "localhost"])
def test_a_loopback_studio_needs_no_token(host: str) -> None:
    assert address(host, 1, None) == f"http://{host}:1/"
