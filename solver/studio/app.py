"""The studio as an ASGI application: pages, the JSON API, the scripts and styles it ships,
behind the fence (:mod:`solver.studio.security`).

Errors are answered in one place, Starlette's application-level exception handlers
(:data:`EXCEPTION_HANDLERS`), for every page and API handler alike, and the studio goes on
serving:

* a located error (:class:`~solver.errors.SolverError`): status 422, the page asked for with
  its faults (:func:`solver.studio.pages.refused`), or the faults as JSON
  (:func:`solver.studio.api.problem`);
* a client gone, or cut off past the body's bound (``ClientDisconnect``): a bare 400 that
  closes the connection, quietly (no one is left to read it);
* anything else: status 500, the page saying so or ``{"error": ..., "faults": []}``, and the
  traceback on standard error (Starlette raises the error again after this answer, and
  uvicorn writes it to its error log, stderr).

Not here: listening on a port (:mod:`solver.studio.server`).
"""

from __future__ import annotations

from collections.abc import AsyncIterator, Mapping
from contextlib import asynccontextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from starlette.applications import Starlette
from starlette.requests import ClientDisconnect, Request
from starlette.responses import JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.schemas import SchemaGenerator
from starlette.staticfiles import StaticFiles

from solver import SolverError, __version__
from solver.studio import api, pages
from solver.studio.security import Guard
from solver.studio.service import Studio
from solver.studio.workspace import MAX_UPLOAD_BYTES

if TYPE_CHECKING:
    from starlette.types import HTTPExceptionHandler

__all__ = ["EXCEPTION_HANDLERS", "STATIC", "make_app"]

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


async def _refused(request: Request, error: Exception) -> Response:
    """A located error: the page asked for with its faults, or the faults as JSON (422)."""
    assert isinstance(error, SolverError)  # the class it is registered for
    page = pages.page_of(request)
    return api.problem(error) if page is None else pages.refused(page, error)


async def _gone(request: Request, error: Exception) -> Response:
    """The client is gone, or was cut off past the body's bound (:mod:`solver.studio.security`):
    no one to answer, and nothing worth a traceback."""
    del request, error
    return Response(status_code=400, headers={"connection": "close"})


async def _failed(request: Request, error: Exception) -> Response:
    """Anything unexpected (500). Starlette raises ``error`` again once this is sent: uvicorn
    writes its traceback to standard error and serves on."""
    del error
    page = pages.page_of(request)
    return api.internal_error() if page is None else pages.failed(page)


# Exception class -> its handler; ``Exception`` is Starlette's last resort for the rest.
EXCEPTION_HANDLERS: Mapping[Any, HTTPExceptionHandler] = {
    SolverError: _refused,
    ClientDisconnect: _gone,
    Exception: _failed,
}


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
        exception_handlers=EXCEPTION_HANDLERS,
    )
    app.state.studio = studio
    # The live event streams open now (solver.studio.api bounds them).
    app.state.streams = set()
    return Guard(app, host=host, port=port, token=token, max_body=MAX_UPLOAD_BYTES)
