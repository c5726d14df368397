"""The studio as an ASGI application: pages, the JSON API, the scripts and styles it ships,
behind the fence (:mod:`solver.studio.security`).

Not here: listening on a port (:mod:`solver.studio.server`).
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.schemas import SchemaGenerator
from starlette.staticfiles import StaticFiles

from solver import __version__
from solver.studio import api, pages
from solver.studio.security import Guard
from solver.studio.service import Studio
from solver.studio.workspace import MAX_UPLOAD_BYTES

__all__ = ["STATIC", "make_app"]

STATIC = Path(__file__).parent / "static"

_SCHEMAS = SchemaGenerator(
    {
        "openapi": "3.0.0",
        "info": {
            "title": "teleop-ui studio",
            "version": __version__,
            "description": "The JSON of the teleop-ui command line (--format json) over "
            "HTTP. A selection travels in the query string as the studio's pages hold it: "
            "rules=ID, name=TEXT, type=T (repeated), T.c=V (repeated), T.c.min=A, "
            "T.c.max=B.",
        },
    }
)


def make_app(studio: Studio, *, host: str, port: int, token: str) -> Guard:
    """The studio's application for ``studio``, answering as the server at ``host:port``."""

    async def openapi(_: Request) -> Response:
        return JSONResponse(_SCHEMAS.get_schema(routes=api.routes()))

    @asynccontextmanager
    async def lifespan(_: Starlette) -> AsyncIterator[None]:
        if studio.live is not None:
            studio.live.start()
        try:
            yield
        finally:
            if studio.live is not None:
                studio.live.stop()

    app = Starlette(
        routes=[
            *pages.routes(),
            *api.routes(),
            Route("/openapi.json", openapi),
            Mount("/static", StaticFiles(directory=STATIC), name="static"),
        ],
        lifespan=lifespan,
    )
    app.state.studio = studio
    # The live event streams open now (solver.studio.api bounds them).
    app.state.streams = set()
    return Guard(app, host=host, port=port, token=token, max_body=MAX_UPLOAD_BYTES)
