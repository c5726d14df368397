"""The studio's JSON HTTP API: the command line's ``--format json``, over HTTP.

Every page of the studio is drawn from these answers, and an operator station or a notebook can
ask them too (``GET /openapi.json`` describes them). A selection travels in the query string as
the pages' addresses hold it (:mod:`solver.studio.selection`). A request the library refuses
gets its located faults (status 422, :func:`problem`), the same faults the command line prints;
the server goes on serving. Handlers raise, and the application's exception handlers answer
(:mod:`solver.studio.app`): no handler catches errors of its own.

Not here: the answers themselves (:mod:`solver.studio.service`).
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING, Any
from urllib.parse import urlencode

from starlette.concurrency import run_in_threadpool
from starlette.datastructures import UploadFile
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import JSONResponse, Response, StreamingResponse
from starlette.routing import BaseRoute, Route

from solver import InputError, SolverError
from solver.files.yamlio import MAX_FILE_BYTES
from solver.studio.service import Studio, faults_data
from solver.studio.workspace import MAX_UPLOAD_FILES, Upload

if TYPE_CHECKING:
    from solver.studio.live import LiveFeed

__all__ = ["INTERNAL_ERROR", "internal_error", "problem", "read_uploads", "routes"]

Handler = Callable[[Request], Awaitable[Response]]
# Seconds an event stream waits for an event before a keep-alive comment.
KEEP_ALIVE = 15.0
# Event streams open at once, at most (a page of the Live view holds one; they hold no thread).
MAX_STREAMS = 32


# What a request that failed unexpectedly is told (the details go to the server's console).
INTERNAL_ERROR = "internal error (the studio's console has the details)"


def problem(error: SolverError, status: int = 422) -> JSONResponse:
    """A located error's answer: its faults as JSON, as ``--format json`` gives them."""
    return JSONResponse(faults_data(error), status_code=status)


def internal_error() -> JSONResponse:
    """The answer to a request that failed unexpectedly (500): no details, which are the
    console's."""
    return JSONResponse({"error": INTERNAL_ERROR, "faults": []}, status_code=500)


def _studio(request: Request) -> Studio:
    studio: Studio = request.app.state.studio
    return studio


def _pairs(request: Request) -> list[tuple[str, str]]:
    return list(request.query_params.multi_items())


async def read_uploads(
    request: Request, field: str = "file"
) -> tuple[list[Upload], dict[str, str]]:
    """The files of a multipart upload (each at most the bounded readers' limit) and its other
    fields; a located error for anything past the limits."""
    try:
        form = await request.form(max_files=MAX_UPLOAD_FILES, max_fields=64)
    except HTTPException as error:
        # Starlette's word for a malformed upload or one past the limits (files, fields).
        raise InputError.at("<upload>", f"upload refused: {error.detail}") from None
    uploads = []
    fields: dict[str, str] = {}
    try:
        for key, value in form.multi_items():
            if isinstance(value, UploadFile):
                if key != field:
                    continue
                data = await value.read(MAX_FILE_BYTES + 1)
                name = value.filename or "upload"
                if len(data) > MAX_FILE_BYTES:
                    raise InputError.at(
                        name,
                        f"file is larger than {MAX_FILE_BYTES} bytes; refused",
                        code="too-large",
                    )
                if data or name:
                    uploads.append(Upload(name, data))
            else:
                fields[key] = value
    finally:
        await form.close()
    return uploads, fields


def _json(call: Callable[[Studio, list[tuple[str, str]]], Any]) -> Handler:
    async def handler(request: Request) -> Response:
        studio = _studio(request)
        pairs = _pairs(request)
        return JSONResponse(await run_in_threadpool(call, studio, pairs))

    return handler


async def solve(request: Request) -> Response:
    """The team's counts: `teleop-ui solve --format json` (`--count-only`; `list=1` lists).
    ---
    summary: Solve the selected team
    parameters:
      - {name: rules, in: query, schema: {type: string}, description: rule set id}
      - name: type
        in: query
        schema: {type: array, items: {type: string}}
        description: kinematic types
      - name: list
        in: query
        schema: {type: string, enum: ["1"]}
        description: list every configuration
    responses:
      200: {description: the JSON of `teleop-ui solve --format json`}
      422: {description: located faults}
    """
    listed = request.query_params.get("list") == "1"
    return await _json(lambda s, p: s.solve_data(p, listed=listed))(request)


async def count(request: Request) -> Response:
    """Counts per type: `teleop-ui count --format json`.
    ---
    summary: Count the selected team
    responses:
      200: {description: by_type and totals}
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.count_data(p))(request)


async def configurations(request: Request) -> Response:
    """One page of UI configurations, numbered as `teleop-ui solve --list` numbers them.
    ---
    summary: Configurations by page
    parameters:
      - {name: offset, in: query, schema: {type: integer, minimum: 0}}
      - {name: limit, in: query, schema: {type: integer, minimum: 1, maximum: 500}}
    responses:
      200: {description: total, offset, limit and the configurations}
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.configurations_data(p))(request)


async def configuration(request: Request) -> Response:
    """One UI configuration with its components.
    ---
    summary: One configuration
    parameters:
      - {name: number, in: path, required: true, schema: {type: integer}}
    responses:
      200: {description: the configuration as `solve --format json --list` gives it}
      422: {description: located faults}
    """
    text = request.path_params["number"]
    number = int(text) if text.isdigit() and len(text) < 18 else -1
    return await _json(lambda s, p: s.configuration_data(p, number))(request)


async def robots(request: Request) -> Response:
    """One page of valid robots with their configuration (`teleop-ui robots --format jsonl`).
    ---
    summary: Robots by page
    parameters:
      - {name: offset, in: query, schema: {type: integer, minimum: 0}}
      - {name: limit, in: query, schema: {type: integer, minimum: 1, maximum: 500}}
      - name: configuration
        in: query
        schema: {type: integer}
        description: only this configuration's robots
    responses:
      200: {description: total, offset and the robots}
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.robots_data(p))(request)


async def assign(request: Request) -> Response:
    """The configuration of one robot: `teleop-ui assign --format json`.
    ---
    summary: Assign one combination
    parameters:
      - name: robot.kinematic_type
        in: query
        schema: {type: string}
        description: "one per characteristic: robot.NAME=VALUE"
    responses:
      200: {description: the JSON of `teleop-ui assign --format json`}
      422: {description: located faults (an unknown characteristic name)}
    """
    return await _json(lambda s, p: s.assign_data(p))(request)


async def check(request: Request) -> Response:
    """The linter on the rule set and the selected team: `teleop-ui check --format json`.
    ---
    summary: Check the rule set and team
    responses:
      200: {description: files, summary and findings with their check ids}
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.check_data(p))(request)


async def findings(request: Request) -> Response:
    """The linter's findings, each with the controls of the selection view it concerns.
    ---
    summary: Check findings placed at the selection's controls
    responses:
      200:
        description: >-
          `teleop-ui check --format json`, each finding with `places` (a list of
          {type, characteristic, value}; empty strings mean every type, the type's own control
          or the selection as a whole) and the rule set's id as `rules`
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.findings_data(p))(request)


def _download(
    call: Callable[[Studio, list[tuple[str, str]]], str | bytes], media: str, name: str
) -> Handler:
    async def handler(request: Request) -> Response:
        body = await run_in_threadpool(call, _studio(request), _pairs(request))
        return Response(
            body,
            media_type=media,
            headers={"content-disposition": f'attachment; filename="{name}"'},
        )

    return handler


async def team_yaml(request: Request) -> Response:
    """The team as a team file (`teleop-ui solve FILE` solves it).
    ---
    summary: Export the team YAML
    responses:
      200: {description: a team file, with each type's counts as comments}
      422: {description: located faults}
    """
    return await _download(lambda s, p: s.team_text(p), "application/yaml", "team.yaml")(request)


async def report_html(request: Request) -> Response:
    """The HTML report of `teleop-ui report`.
    ---
    summary: Export the HTML report
    responses:
      200: {description: one self-contained HTML page}
    """
    return await _download(lambda s, p: s.report_html(p), "text/html", "report.html")(request)


async def layouts_zip(request: Request) -> Response:
    """Foxglove/Lichtblick and RViz2 layouts of every configuration (`teleop-ui layouts`).
    ---
    summary: Export the layouts, zipped
    responses:
      200: {description: "a zip: foxglove/*.json and rviz/*.rviz"}
    """
    return await _download(lambda s, p: s.layouts_zip(p), "application/zip", "layouts.zip")(request)


async def model_uvl(request: Request) -> Response:
    """The design space as a UVL feature model (`teleop-ui export --format uvl`).
    ---
    summary: Export the UVL model
    responses:
      200: {description: a UVL file}
    """
    return await _download(lambda s, p: s.uvl_text(p), "text/plain", "team.uvl")(request)


async def chart(request: Request) -> Response:
    """A chart of `teleop-ui report` as SVG: radar (Figure 9), bars or the component matrix;
    `panel`: the radar chart as the selection page shows it beside the totals (larger texts,
    no title, each type's values per spoke a group the keyboard reaches, with its text).
    ---
    summary: A chart
    parameters:
      - name: kind
        in: path
        required: true
        schema: {type: string, enum: [radar, bars, matrix, panel]}
    responses:
      200: {description: an SVG image}
      422: {description: located faults}
    """
    kind = request.path_params["kind"]
    body = await run_in_threadpool(_studio(request).chart_svg, _pairs(request), kind)
    return Response(body, media_type="image/svg+xml")


async def upload_rules(request: Request) -> Response:
    """Upload a rule set (multipart field `file`); it is read as `teleop-ui check` reads one.
    ---
    summary: Upload a rule set
    requestBody:
      content:
        multipart/form-data:
          schema: {type: object, properties: {file: {type: string, format: binary}}}
    responses:
      200: {description: the id that names it in a selection (`rules=ID`)}
      422: {description: located faults of the file}
    """
    uploads, _ = await read_uploads(request)
    if len(uploads) != 1:
        raise InputError.at("<upload>", "upload exactly one rule set file")
    source = await run_in_threadpool(_studio(request).add_rules, uploads[0])
    return JSONResponse({"id": source.id, "name": source.rules.name, "file": source.rules.file})


async def upload_team(request: Request) -> Response:
    """Upload a team file (multipart field `file`), read against the selected rule set.
    ---
    summary: Upload a team
    responses:
      200: {description: the query that selects it}
      422: {description: located faults of the file}
    """
    uploads, _ = await read_uploads(request)
    if len(uploads) != 1:
        raise InputError.at("<upload>", "upload exactly one team file")
    pairs = _pairs(request)
    query = await run_in_threadpool(_studio(request).read_team, uploads[0], pairs)
    return JSONResponse({"query": query})


async def identify(request: Request) -> Response:
    """Identify uploaded robot descriptions (field `file`, repeated): `teleop-ui fleet`.
    Xacro files are never compiled here.
    ---
    summary: Identify uploaded robots
    responses:
      200: {description: "fleet id, and per robot the JSON of `teleop-ui identify` (or its error)"}
      422: {description: located faults}
    """
    uploads, _ = await read_uploads(request)
    studio = _studio(request)
    data = await run_in_threadpool(studio.identify_uploads, uploads, _pairs(request))
    return JSONResponse(data)


async def identify_folder(request: Request) -> Response:
    """Identify the robots of a folder given at start (`--fleet DIR`), by its index.
    ---
    summary: Identify a folder given at start
    parameters:
      - {name: index, in: path, required: true, schema: {type: integer}}
    responses:
      200: {description: as for an upload}
      422: {description: located faults}
    """
    text = request.path_params["index"]
    index = int(text) if text.isdigit() and len(text) < 6 else -1
    studio = _studio(request)
    data = await run_in_threadpool(studio.identify_folder, index, _pairs(request))
    return JSONResponse(data)


async def fleet_team(request: Request) -> Response:
    """The team selection of an identified fleet (`teleop-ui fleet -o TEAM`).
    ---
    summary: Make a team from a fleet
    responses:
      200: {description: the team file and the query that selects it}
      422: {description: located faults}
    """
    fleet_id = request.path_params["fleet"]
    studio = _studio(request)
    data = await run_in_threadpool(studio.fleet_team, fleet_id, _pairs(request))
    return JSONResponse(data)


async def live_state(request: Request) -> Response:
    """The live graph now: robots with their configurations, the operator's selection.
    ---
    summary: The live graph
    responses:
      200:
        description: >-
          source, status, team and rules (what the feed answers for), robots (as watch events
          give them), selection, answers (per robot, the last answer naming it that carried
          layouts: configuration, watcher, layouts)
    """
    feed = _studio(request).live
    if feed is None:
        return JSONResponse({"source": None, "status": "off", "robots": [], "selection": None})
    state = feed.state()
    return JSONResponse(
        {
            "source": state.source,
            "status": state.status,
            "team": state.team,
            "rules": state.rules,
            "robots": list(state.robots),
            "selection": state.selection,
            "answers": state.answers,
            "last": state.last,
        }
    )


async def live_events(request: Request) -> Response:
    """The watcher's events as they come (Server-Sent Events; each `data:` is one event of
    `teleop-ui watch`, with the studio's own `seq`). `Last-Event-ID` resumes.
    ---
    summary: The live events
    responses:
      200: {description: text/event-stream}
    """
    feed = _studio(request).live
    if feed is None:
        raise InputError.at("<live>", "the studio was started without --ros2 or --master")
    text = request.headers.get("last-event-id") or request.query_params.get("after", "")
    after = int(text) if text.isdigit() and len(text) < 18 else 0
    streams: set[object] = request.app.state.streams
    if len(streams) >= MAX_STREAMS:
        return JSONResponse(
            {
                "error": f"{MAX_STREAMS} live event streams are open already (a page each); "
                "close one and reload",
                "faults": [],
            },
            status_code=503,
            headers={"retry-after": "10"},
        )
    token = object()
    streams.add(token)

    async def stream() -> Any:
        import json

        try:
            seq = after
            while not feed.stopped:
                events = await feed.next_events(seq, KEEP_ALIVE)
                if not events:
                    yield ": keep-alive\n\n"
                    continue
                for event in events:
                    seq = event["seq"]
                    yield f"id: {seq}\ndata: {json.dumps(event, ensure_ascii=False)}\n\n"
        finally:
            streams.discard(token)

    return StreamingResponse(stream(), media_type="text/event-stream")


# Bytes of a switch's request body at most (a robot and a few values).
MAX_SWITCH_BYTES = 16 * 1024
# Seconds a switch from the API may wait for the watcher's answer, at most.
MAX_SWITCH_WAIT = 30.0


def _feed(request: Request) -> LiveFeed:
    feed = _studio(request).live
    if feed is None:
        raise InputError.at("<live>", "the studio was started without --ros2 or --master")
    return feed


async def live_switch(request: Request) -> Response:
    """Make a robot (and values of its characteristics) the operator's active selection on
    the live graph, as `teleop-ui switch` does, and wait for the watcher's answer. The body is
    JSON: `{"robot": "/uav1", "values": {"motion_control": "Flight"}, "clear": true,
    "wait": 5}` (`values`, `clear` and `wait` optional; `clear` by default when no value is
    given or another robot was active).
    ---
    summary: Switch the active robot
    requestBody:
      content:
        application/json:
          schema:
            type: object
            properties:
              robot: {type: string}
              values: {type: object, additionalProperties: {type: string}}
              clear: {type: boolean}
              wait: {type: number, minimum: 0.01, maximum: 30}
    responses:
      200: {description: "the JSON of `teleop-ui switch --format json`"}
      202: {description: "the same, `answer` null: written, no watcher answered in time"}
      422: {description: "located faults (no ROS name, no such characteristic, value or robot)"}
    """
    feed = _feed(request)
    length = request.headers.get("content-length", "0")
    if not (length.isascii() and length.isdigit()) or int(length) > MAX_SWITCH_BYTES:
        raise InputError.at("<request>", f"a switch is at most {MAX_SWITCH_BYTES} bytes of JSON")
    robot, values, clear, wait = _switch_body(await request.body())
    from solver.live.operator import switched_data

    switched = await run_in_threadpool(feed.switch, robot, values, clear=clear, wait=wait)
    status = 200 if switched.answer is not None else 202
    return JSONResponse(switched_data(switched), status_code=status)


def _switch_body(body: bytes) -> tuple[str, dict[str, str], bool | None, float | None]:
    """A switch's JSON body read (see :func:`live_switch`); a located error for anything
    else."""
    from solver.live.values import bounded_json

    try:
        data = bounded_json(body.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as error:
        raise InputError.at("<request>", f"a switch is a JSON object: {error}") from None
    if not isinstance(data, dict) or not isinstance(data.get("robot"), str):
        raise InputError.at("<request>", 'a switch is a JSON object with "robot": "/NAME"')
    values = data.get("values", {})
    if not isinstance(values, dict) or not all(
        isinstance(k, str) and isinstance(v, str) for k, v in values.items()
    ):
        raise InputError.at("<request>", '"values" is an object of NAME: "VALUE"', path="values")
    clear = data.get("clear")
    if clear is not None and not isinstance(clear, bool):
        raise InputError.at("<request>", '"clear" is true or false', path="clear")
    wait = data.get("wait")
    if wait is not None and (
        isinstance(wait, bool)
        or not isinstance(wait, int | float)
        or not 0.01 <= wait <= MAX_SWITCH_WAIT
    ):
        raise InputError.at(
            "<request>", f'"wait" is seconds from 0.01 to {MAX_SWITCH_WAIT:g}', path="wait"
        )
    return data["robot"], values, clear, None if wait is None else float(wait)


def _robot_layout_query(request: Request) -> tuple[LiveFeed, str, int]:
    feed = _feed(request)
    robot = request.query_params.get("robot", "")
    text = request.query_params.get("configuration", "")
    if not (text.isascii() and text.isdigit() and len(text) < 18):
        raise InputError.at("<request>", "configuration=N: a whole number", path="configuration")
    return feed, robot, int(text)


async def live_layout(request: Request) -> Response:
    """A live robot's Lichtblick layout of one UI configuration, as `watch --layouts` writes
    it (its real topics and joints), made by the studio.
    ---
    summary: A live robot's layout
    parameters:
      - {name: robot, in: query, required: true, schema: {type: string}}
      - {name: configuration, in: query, required: true, schema: {type: integer}}
    responses:
      200: {description: a Lichtblick / Foxglove layout (JSON)}
      422: {description: "no such robot on the graph, or no layout for it"}
    """
    feed, robot, configuration = _robot_layout_query(request)
    text = await run_in_threadpool(feed.layout, robot, configuration)
    if text is None:
        raise _no_layout(robot, configuration)
    from solver.layouts.foxglove import layout_filename

    name = layout_filename(configuration)
    return Response(
        text,
        media_type="application/json",
        headers={"content-disposition": f'attachment; filename="{name}"'},
    )


async def live_preview(request: Request) -> Response:
    """The panels of a live robot's layout of one UI configuration, as an SVG thumbnail.
    ---
    summary: A live robot's layout preview
    parameters:
      - {name: robot, in: query, required: true, schema: {type: string}}
      - {name: configuration, in: query, required: true, schema: {type: integer}}
    responses:
      200: {description: an SVG image}
      422: {description: "no such robot on the graph, or no layout for it"}
    """
    import json

    from solver.layouts.preview import preview_svg

    feed, robot, configuration = _robot_layout_query(request)
    text = await run_in_threadpool(feed.layout, robot, configuration)
    if text is None:
        raise _no_layout(robot, configuration)
    svg = preview_svg(json.loads(text), 240, 150)
    return Response(
        svg, media_type="image/svg+xml", headers={"cache-control": "private, max-age=600"}
    )


async def whatif(request: Request) -> Response:
    """What-if: the single changes of the team (a value dropped, a count's maximum lowered
    below an arrangement) ranked by UI configurations saved, then valid robots lost; counted
    exactly by the counting engines, none listed.
    ---
    summary: What-if suggestions
    responses:
      200: {description: "`suggestions` (best first, at most 10), each with `query` to apply"}
      409: {description: "`superseded`: a newer what-if was asked while this one waited"}
      422: {description: located faults}
    """
    data = await run_in_threadpool(_studio(request).whatif_data, _pairs(request))
    return JSONResponse(data, status_code=409 if data.get("superseded") else 200)


async def whatif_apply(request: Request) -> Response:
    """Apply a what-if change to the rule set (`change`, as a suggestion's `rules_change`
    names it): the changed rule set is kept as an uploaded one is.
    ---
    summary: Apply a what-if change to the rule set
    responses:
      200: {description: "`query`: the same selection under the changed rule set"}
      422: {description: located faults}
    """
    pairs = await run_in_threadpool(_studio(request).whatif_apply, _pairs(request))
    return JSONResponse({"query": urlencode(pairs)})


async def configuration_map(request: Request) -> Response:
    """The configuration map: a row per component, a column per configuration and the default.
    ---
    summary: The configuration map
    parameters:
      - {name: component, in: query, schema: {type: string}, description: "CHARACTERISTIC:NAME"}
      - {name: pick, in: query, schema: {type: integer}, description: "compared (repeated)"}
      - {name: sort, in: query, schema: {type: string, enum: [number, robots, type]}}
    responses:
      200: {description: "`rows`, `columns` (each with `cells`), `compared`"}
      422: {description: located faults}
    """
    return await _json(lambda s, p: s.map_data(p))(request)


async def designs(request: Request) -> Response:
    """The design folder (`studio --designs DIR`): each design, or why an entry is refused.
    ---
    summary: List the designs
    responses:
      200: {description: "`designs`: `{name, problem}` each (no problem: a design)"}
      422: {description: located faults (no design folder)}
    """

    def listed(studio: Studio, _pairs: list[tuple[str, str]]) -> dict[str, Any]:
        entries, left_out = studio.designs_list()
        return {
            "designs": [{"name": e.name, "problem": e.problem} for e in entries],
            "left_out": left_out,
        }

    return await _json(listed)(request)


async def design_diff(request: Request) -> Response:
    """What changed from design `a` to design `b`: types and values added and removed, and
    each one's counts with the change.
    ---
    summary: Compare two designs
    responses:
      200: {description: "`changes`, `valid_robots`, `ui_configurations` (of each) and `change`"}
      422: {description: located faults (no such design, no team, a rule set not allowed)}
    """

    def diff(studio: Studio, pairs: list[tuple[str, str]]) -> dict[str, Any]:
        found = dict(pairs)
        return studio.design_diff(found.get("a", ""), found.get("b", ""))

    return await _json(diff)(request)


def _no_layout(robot: str, configuration: int) -> InputError:
    from solver.untrusted import shown

    return InputError.at(
        "<live>",
        f"no layout of {shown(robot, quoted=True)} in UI configuration {configuration}: no "
        "such robot on the graph, not identified, no ROS 2 name, or no such configuration",
    )


def routes() -> list[BaseRoute]:
    return [
        Route("/api/solve", solve),
        Route("/api/count", count),
        Route("/api/configurations", configurations),
        Route("/api/configurations/{number}", configuration),
        Route("/api/robots", robots),
        Route("/api/assign", assign),
        Route("/api/check", check),
        Route("/api/findings", findings),
        Route("/api/team.yaml", team_yaml),
        Route("/api/report.html", report_html),
        Route("/api/layouts.zip", layouts_zip),
        Route("/api/model.uvl", model_uvl),
        Route("/api/map", configuration_map),
        Route("/api/whatif", whatif),
        Route("/api/whatif/apply", whatif_apply, methods=["POST"]),
        Route("/api/designs", designs),
        Route("/api/designs/diff", design_diff),
        Route("/api/charts/{kind}.svg", chart),
        Route("/api/rules", upload_rules, methods=["POST"]),
        Route("/api/team", upload_team, methods=["POST"]),
        Route("/api/identify", identify, methods=["POST"]),
        Route("/api/fleet/folders/{index}", identify_folder, methods=["POST"]),
        Route("/api/fleet/{fleet}/team", fleet_team, methods=["POST"]),
        Route("/api/live", live_state),
        Route("/api/live/events", live_events),
        Route("/api/live/switch", live_switch, methods=["POST"]),
        Route("/api/live/layout.json", live_layout),
        Route("/api/live/preview.svg", live_preview),
    ]
