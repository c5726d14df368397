"""The studio's fence, as one ASGI middleware in front of every request.

* **Who may ask.** Every request carries the token the studio printed at start, on loopback
  too (another account on the machine reaches 127.0.0.1 as easily as its owner does): once in
  the address (``?token=...``; a page visited so is sent on to the same address without it,
  with the token in a same-site cookie of this port's own) or as ``Authorization: Bearer``.
  A connection from another account of this machine is refused even with the token, where the
  kernel says whose it is (:mod:`solver.studio.peers`). Bound to loopback, only ``Host`` names
  of this machine are served (a web page elsewhere cannot reach the studio by rebinding a name
  of its own to 127.0.0.1).
* **Who may cause work.** A request from another site (``Sec-Fetch-Site``: ``cross-site``,
  or ``same-site``, which another port of 127.0.0.1 is) is refused whatever its method, but
  for a page opened from an address that carries the token (whoever links it holds the
  token). A request that changes state (anything but GET and HEAD) must moreover come from the
  studio's own pages: an ``Origin`` naming another site is refused. Programs that send neither
  (a notebook, curl) are served when they carry the token.
* **How much.** An address (its query) is at most :data:`MAX_QUERY_BYTES`; a request body
  must say its length (``Content-Length``, no ``Transfer-Encoding``) and be at most
  ``max_body`` bytes, refused before it is read; and the bytes actually read are counted, so
  no header can make the studio read more.
* **What a page may do.** Every response carries a Content Security Policy that lets a page
  load only the studio's own scripts, styles and images (no inline script, no other site), and
  no ``Referer`` to other sites.

Not here: connections (how many, how long a head may take: :mod:`solver.studio.connections`),
what is read once a request is let in (:mod:`solver.studio.workspace`).
"""

from __future__ import annotations

import hmac
import html
import json
from collections.abc import Awaitable, Callable, MutableMapping
from http.cookies import SimpleCookie
from typing import Any
from urllib.parse import parse_qsl, urlencode

from solver.addresses import loopback
from solver.studio.peers import same_account

__all__ = ["HEADERS", "MAX_QUERY_BYTES", "Guard", "cookie_name", "loopback"]

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
App = Callable[[Scope, Receive, Send], Awaitable[None]]

# Bytes of an address's query at most: a selection of a thousand values (about 40 KB) travels
# in the address when pages are used without scripts.
MAX_QUERY_BYTES = 64 * 1024
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
_NO_TOKEN = (
    "this studio needs the token it printed at start: open the address it printed "
    "(http://...?token=...), or send the header Authorization: Bearer TOKEN"
)


def cookie_name(port: int) -> str:
    """The cookie of the studio on ``port``: a browser sends a host's cookies to every port of
    it, so each studio names its own."""
    return f"teleop_ui_studio_{port}"


class Guard:
    """See the module docstring. ``port`` is the port the studio listens on."""

    def __init__(self, app: App, *, host: str, port: int, token: str, max_body: int) -> None:
        self.app = app
        self.token = token.encode()
        self.cookie = cookie_name(port)
        self.max_body = max_body
        self.hosts: frozenset[str] | None = None
        if loopback(host):
            names = {f"{name}:{port}" for name in ("127.0.0.1", "localhost", "[::1]")}
            names.add(f"[{host}]:{port}" if ":" in host else f"{host}:{port}")
            self.hosts = frozenset(names)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = {k.decode("latin-1"): v.decode("latin-1") for k, v in scope["headers"]}
        navigation = _navigation(headers)
        refused = self._refused(scope, headers)
        if refused is not None:
            await _refuse(send, *refused, page=navigation)
            return
        if navigation and scope["method"] in ("GET", "HEAD") and self._token_in_query(scope):
            await self._redirect_keeping_token(scope, send)
            return
        await self.app(scope, _bounded(receive, self.max_body), _with_headers(send))

    def _refused(self, scope: Scope, headers: dict[str, str]) -> tuple[int, str] | None:
        """``(status, why)`` for a request the fence refuses, else ``None``."""
        host = headers.get("host", "")
        if self.hosts is not None and host not in self.hosts:
            return 421, f"this studio answers to {sorted(self.hosts)[0]} only"
        if not same_account(scope.get("client"), scope.get("server")):
            return 403, "this studio serves the account that started it only"
        if len(scope.get("query_string", b"")) > MAX_QUERY_BYTES:
            return 414, f"an address may hold at most {MAX_QUERY_BYTES} bytes of query; refused"
        site = headers.get("sec-fetch-site")
        if site in ("cross-site", "same-site") and not (
            _navigation(headers) and self._token_in_query(scope)
        ):
            return 403, "a request may only come from the studio's own pages (cross-site request)"
        if not (self._token_in_headers(headers) or self._token_in_query(scope)):
            return 401, _NO_TOKEN
        if scope["method"] in _SAFE_METHODS:
            return None
        origin = headers.get("origin")
        if (
            site is None
            and origin is not None
            and origin not in (f"http://{host}", f"https://{host}")
        ):
            return 403, "a change may only come from the studio's own pages (Origin differs)"
        if "transfer-encoding" in headers:
            return 411, "a request body must say its length (Content-Length), not be chunked"
        length = headers.get("content-length", "0")
        if not (length.isascii() and length.isdigit()) or int(length) > self.max_body:
            return 413, f"a request body may be at most {self.max_body} bytes; refused"
        return None

    def _token_in_headers(self, headers: dict[str, str]) -> bool:
        cookie = SimpleCookie()
        try:
            cookie.load(headers.get("cookie", ""))
        except Exception:
            cookie = SimpleCookie()
        given = cookie.get(self.cookie)
        if given is not None and hmac.compare_digest(given.value.encode(), self.token):
            return True
        bearer = headers.get("authorization", "")
        return bearer.startswith("Bearer ") and hmac.compare_digest(
            bearer[7:].encode("latin-1"), self.token
        )

    def _token_in_query(self, scope: Scope) -> bool:
        query = scope.get("query_string", b"")
        if b"token=" not in query:
            return False
        given = [v for k, v in parse_qsl(query.decode("latin-1")) if k == "token"]
        return len(given) == 1 and hmac.compare_digest(given[0].encode("latin-1"), self.token)

    async def _redirect_keeping_token(self, scope: Scope, send: Send) -> None:
        """The same address without the token, which from now on travels in a cookie."""
        query = [
            (k, v)
            for k, v in parse_qsl(scope.get("query_string", b"").decode("latin-1"), True)
            if k != "token"
        ]
        path: bytes = scope.get("raw_path") or b"/"
        location = path + (f"?{urlencode(query)}".encode("ascii") if query else b"")
        cookie = f"{self.cookie}={self.token.decode()}; Path=/; HttpOnly; SameSite=Strict"
        await send(
            {
                "type": "http.response.start",
                "status": 303,
                "headers": [
                    (b"location", location),
                    (b"set-cookie", cookie.encode()),
                    (b"content-length", b"0"),
                    (b"cache-control", b"no-store"),
                    *HEADERS,
                ],
            }
        )
        await send({"type": "http.response.body", "body": b""})


def _navigation(headers: dict[str, str]) -> bool:
    """Whether a browser opens the address as a page (not a script's or an image's request)."""
    mode = headers.get("sec-fetch-mode")
    if mode is not None:
        return mode == "navigate"
    return "text/html" in headers.get("accept", "")


def _bounded(receive: Receive, most: int) -> Receive:
    """``receive`` that hands on at most ``most`` bytes of body: past them the request reads as
    one whose client went away, whatever its headers said."""
    read = 0

    async def bounded() -> Message:
        nonlocal read
        message = await receive()
        if message["type"] == "http.request":
            read += len(message.get("body", b""))
            if read > most:
                return {"type": "http.disconnect"}
        return message

    return bounded


def _with_headers(send: Send) -> Send:
    async def send_with_headers(message: Message) -> None:
        if message["type"] == "http.response.start":
            message["headers"] = [*message.get("headers", []), *HEADERS]
        await send(message)

    return send_with_headers


_PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>teleop-ui studio: {status}</title></head>
<body><h1>teleop-ui studio</h1><p>{message}</p></body></html>
"""


async def _refuse(send: Send, status: int, message: str, *, page: bool = False) -> None:
    if page:
        body = _PAGE.format(status=status, message=html.escape(message)).encode()
        kind = b"text/html; charset=utf-8"
    else:
        body = json.dumps({"error": message, "faults": []}).encode()
        kind = b"application/json"
    await send(
        {
            "type": "http.response.start",
            "status": status,
            "headers": [
                (b"content-type", kind),
                (b"content-length", str(len(body)).encode()),
                (b"connection", b"close"),
                *HEADERS,
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})
