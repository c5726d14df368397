"""Serve a Lichtblick web build on the loopback with the headers the app asks for.

usage: python serve.py BUILD_DIR PORT    (BUILD_DIR: the checkout's web/.webpack)

The app's own dev server sends cross-origin isolation headers (packages/suite-web
webpackConfigs.ts); Python's http.server does not, so they are added here.
"""

from __future__ import annotations

import functools
import http.server
import sys
from typing import Any


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {  # noqa: RUF012 - the base class declares it a plain dict
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
    }

    def end_headers(self) -> None:
        self.send_header("Cross-Origin-Opener-Policy", "same-origin")
        self.send_header("Cross-Origin-Embedder-Policy", "credentialless")
        self.send_header("Cache-Control", "no-store")
        super().end_headers()

    def log_message(self, *args: Any) -> None:
        del args  # quiet


def main() -> None:
    root, port = sys.argv[1], int(sys.argv[2])
    handler = functools.partial(Handler, directory=root)
    http.server.ThreadingHTTPServer(("127.0.0.1", port), handler).serve_forever()


if __name__ == "__main__":
    main()
