"""The studio's fence, as one ASGI middleware in front of every request.

* **Who may ask.** Bound to loopback, only ``Host`` names of this machine are served (a web page
  elsewhere cannot reach the studio by rebinding a name of its own to 127.0.0.1). Bound to any
  other address (``--host``), every request needs the token printed at start: once in the
  address (``?token=...``, then kept in a same-site cookie) or as ``Authorization: Bearer``.
* **Who may change.** A request that changes state (anything but GET and HEAD) must come from
  the studio's own pages: a browser's ``Origin`` or ``Sec-Fetch-Site`` naming another site is
  refused. Programs that send neither (a notebook, curl) are served.
* **How much.** A request body must say its length (``Content-Length``) and be at most
  :data:`~solver.studio.workspace.MAX_UPLOAD_BYTES`; more is refused before it is read.
* **What a page may do.** Every response carries a Content Security Policy that lets a page
  load only the studio's own scripts, styles and images (no inline script, no other site), and
  no ``Referer`` to other sites.

Not here: what is read once a request is let in (:mod:`solver.studio.workspace`).
"""

from __future__ import annotations

import hmac
import json
from collections.abc import Awaitable, Callable, MutableMapping
from http.cookies import SimpleCookie
from typing import Any
from urllib.parse import parse_qsl, urlencode

__all__ = ["COOKIE", "HEADERS", "Guard", "loopback"]

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
App = Callable[[Scope, Receive, Send], Awaitable[None]]

COOKIE = "teleop_ui_studio"
HEADERS: tuple[tuple[bytes, bytes], ...] = (
    (
        b"content-security-policy",
        b"default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
        b"connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'",
    ),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"same-origin"),
    (b"cross-origin-opener-policy", b"same-origin"),
    (b"cross-origin-resource-policy", b"same-origin"),
    (b"x-frame-options", b"DENY"),
)
_SAFE_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})


def loopback(host: str) -> bool:
    """Whether ``host`` names this machine only (127.0.0.0/8, ::1, localhost)."""
    import ipaddress

    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


class Guard:
    """See the module docstring. ``port`` is the port the studio listens on."""

    def __init__(self, app: App, *, host: str, port: int, token: str | None, max_body: int) -> None:
        self.app = app
        self.token = token
        self.max_body = max_body
        self.hosts = {f"{name}:{port}" for name in ("127.0.0.1", "localhost", "[::1]")}
        self.hosts.add(f"[{host}]:{port}" if ":" in host else f"{host}:{port}")

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = {k.decode("latin-1"): v.decode("latin-1") for k, v in scope["headers"]}
        host = headers.get("host", "")
        if self.token is None and host not in self.hosts:
            await _refuse(send, 421, f"this studio answers to {sorted(self.hosts)[0]} only")
            return
        if self.token is not None:
            verdict = _token(scope, headers, self.token)
            if verdict == "missing":
                await _refuse(
                    send,
                    401,
                    "this studio needs the token it printed at start: open the address it "
                    "printed (with ?token=...)",
                )
                return
            if verdict == "in-address":
                await _redirect_keeping_token(scope, send, self.token)
                return
        if scope["method"] not in _SAFE_METHODS:
            refused = _cross_site(headers, host)
            if refused:
                await _refuse(send, 403, refused)
                return
            length = headers.get("content-length")
            if length is None and headers.get("transfer-encoding"):
                await _refuse(send, 411, "a request body must say its length (Content-Length)")
                return
            if length is not None and (not length.isdigit() or int(length) > self.max_body):
                await _refuse(
                    send, 413, f"a request body may be at most {self.max_body} bytes; refused"
                )
                return

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message["headers"] = [*message.get("headers", []), *HEADERS]
            await send(message)

        await self.app(scope, receive, send_with_headers)


def _token(scope: Scope, headers: dict[str, str], token: str) -> str:
    """``ok``, ``in-address`` (given as ``?token=``: to be moved into a cookie) or ``missing``."""
    wanted = token.encode()
    cookie = SimpleCookie()
    try:
        cookie.load(headers.get("cookie", ""))
    except Exception:
        cookie = SimpleCookie()
    given = cookie.get(COOKIE)
    if given is not None and hmac.compare_digest(given.value.encode(), wanted):
        return "ok"
    bearer = headers.get("authorization", "")
    if bearer.startswith("Bearer ") and hmac.compare_digest(bearer[7:].encode(), wanted):
        return "ok"
    query = dict(parse_qsl(scope.get("query_string", b"").decode("latin-1")))
    if hmac.compare_digest(query.get("token", "").encode(), wanted):
        return "in-address"
    return "missing"


def _cross_site(headers: dict[str, str], host: str) -> str:
    """Why a state-changing request is refused as coming from another site ("" if it is not).

    A browser's own word (``Sec-Fetch-Site``) decides where it is given; else ``Origin`` must
    be the studio's (a browser may send ``Origin: null`` for its own pages' forms, and then it
    sends ``Sec-Fetch-Site`` too)."""
    site = headers.get("sec-fetch-site")
    if site is not None:
        if site in ("same-origin", "none"):
            return ""
        return "a change may only come from the studio's own pages (cross-site request)"
    origin = headers.get("origin")
    if origin is not None and origin not in (f"http://{host}", f"https://{host}"):
        return "a change may only come from the studio's own pages (Origin differs)"
    return ""


async def _refuse(send: Send, status: int, message: str) -> None:
    body = json.dumps({"error": message, "faults": []}).encode()
    await send(
        {
            "type": "http.response.start",
            "status": status,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(body)).encode()),
                *HEADERS,
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})


async def _redirect_keeping_token(scope: Scope, send: Send, token: str) -> None:
    """The same address without the token, which from now on travels in a cookie."""
    query = [
        (k, v)
        for k, v in parse_qsl(scope.get("query_string", b"").decode("latin-1"), True)
        if k != "token"
    ]
    path: bytes = scope.get("raw_path") or b"/"
    location = path + (f"?{urlencode(query)}".encode("ascii") if query else b"")
    cookie = f"{COOKIE}={token}; Path=/; HttpOnly; SameSite=Strict"
    await send(
        {
            "type": "http.response.start",
            "status": 303,
            "headers": [
                (b"location", location),
                (b"set-cookie", cookie.encode()),
                (b"content-length", b"0"),
                *HEADERS,
            ],
        }
    )
    await send({"type": "http.response.body", "body": b""})
