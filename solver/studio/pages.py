"""The studio's pages: server-rendered HTML that works without scripts, made livelier by the
small scripts in ``static/`` (updates as you click, undo and redo, live events).

Each page shows what an API answer holds (:mod:`solver.studio.service`), drawn by a template in
``templates/`` (Jinja2, every value escaped). The selection a page shows is its address
(:mod:`solver.studio.selection`), so every link carries it along, and forms that change
something post back to the studio itself and land on an address that shows the result.

A page's handler starts by making its :class:`Page` (kept with the request) and raises what
fails; the application's exception handlers (:mod:`solver.studio.app`) then show that page
with the located faults (:func:`refused`, status 422) or say it failed (:func:`failed`, 500).

Not here: the JSON (:mod:`solver.studio.api`), the answers (:mod:`solver.studio.service`).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any
from urllib.parse import urlencode

import jinja2
from starlette.concurrency import run_in_threadpool
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import HTMLResponse, RedirectResponse, Response
from starlette.routing import BaseRoute, Route

from solver import Characteristic, Fault, InputError, RuleSet, SolverError
from solver.core.forbidden import Removed
from solver.solving.reproduce import published_note
from solver.studio.api import INTERNAL_ERROR, read_uploads
from solver.studio.selection import SELECTION_FILE
from solver.studio.service import CHART_KINDS, MAX_PAGE, Chosen, Studio, robot_pairs
from solver.untrusted import shown

__all__ = ["failed", "page_of", "refused", "routes", "selection_pairs"]

Pairs = Sequence[tuple[str, str]]
PER_PAGE = 50
# The views, in the order the navigation shows them: (path, title).
VIEWS = (
    ("/", "Selection"),
    ("/configurations", "Configurations"),
    ("/map", "Map"),
    ("/robots", "Robots"),
    ("/charts", "Charts"),
    ("/check", "Check"),
    ("/fleet", "Fleet"),
    ("/export", "Export"),
    ("/designs", "Designs"),
    ("/live", "Live"),
    ("/api", "API"),
)


@functools.cache
def _environment() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.PackageLoader("solver.studio", "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
    )


def selection_pairs(pairs: Pairs) -> list[tuple[str, str]]:
    """The pairs of a query that make its selection (not the view, paging or a robot)."""
    return [
        (k, v)
        for k, v in pairs
        if k in ("rules", "name", "type") or ("." in k and not k.startswith("robot."))
    ]


def _query(pairs: Pairs, **extra: object) -> str:
    items = list(pairs) + [(k, str(v)) for k, v in extra.items() if v is not None]
    return urlencode(items)


@dataclass
class Page:
    """What every page template receives."""

    request: Request
    studio: Studio
    pairs: list[tuple[str, str]]
    title: str
    chosen: Chosen | None = None
    faults: list[Fault] = field(default_factory=list)

    @property
    def selection_query(self) -> str:
        return _query(selection_pairs(self.pairs))

    def link(self, path: str, **extra: object) -> str:
        query = _query(selection_pairs(self.pairs), **extra)
        return f"{path}?{query}" if query else path

    def render(self, template: str, status: int = 200, **context: Any) -> HTMLResponse:
        body = (
            _environment()
            .get_template(template)
            .render(
                page=self,
                views=VIEWS,
                path=self.request.url.path,
                live=self.studio.live is not None,
                **context,
            )
        )
        return HTMLResponse(body, status_code=status)


def _page(request: Request, title: str) -> Page:
    """The page ``request`` asks for, kept with the request: an error its handler raises is
    shown in it (:func:`refused`, :func:`failed`)."""
    studio: Studio = request.app.state.studio
    page = Page(request, studio, list(request.query_params.multi_items()), title)
    request.state.page = page
    return page


def page_of(request: Request) -> Page | None:
    """The page ``request`` asked for, when it asked for one (not the JSON API)."""
    page = getattr(request.state, "page", None)
    return page if isinstance(page, Page) else None


def _choose(page: Page) -> Chosen | None:
    """The page's selection, or ``None`` with its faults recorded for the page to show."""
    try:
        page.chosen = page.studio.chosen(page.pairs)
    except SolverError as error:
        page.faults.extend(error.faults)
        # The rule set alone, so the controls still show.
        try:
            source = page.studio.workspace.source(_first(page.pairs, "rules"))
        except SolverError:
            source = page.studio.workspace.source(None)
        from solver.studio.selection import parse_query

        page.chosen = Chosen(source, parse_query(page.pairs, source.rules, source.id), None)
        return None
    return page.chosen


def _first(pairs: Pairs, name: str) -> str | None:
    return next((v for k, v in pairs if k == name), None)


def refused(page: Page, error: SolverError) -> Response:
    """``page`` showing the located errors that stopped it (status 422), with the selection's
    controls as far as they could be read."""
    page.faults.extend(error.faults)
    if page.chosen is None:
        _choose(page)
    return page.render("error.html", status=422)


def failed(page: Page) -> Response:
    """``page`` saying that something unexpected failed (status 500); the details are the
    console's."""
    page.faults.append(Fault(page_location(), INTERNAL_ERROR, "internal"))
    return page.render("error.html", status=500)


def page_location() -> Any:
    from solver import Location

    return Location("<studio>")


# -- the selection (the article's Figure 8) ----------------------------------------------------


@dataclass(frozen=True)
class ValueControl:
    value: str
    components: str
    checked: bool
    excluded: str  # why the rules' constraints exclude it ("" when they do not)
    # The selection names it (not only "every value"): an excluded value named is kept in
    # the form, so the page says what it costs; one only implied is not added by a change.
    named: bool = False


@dataclass(frozen=True)
class CharacteristicControl:
    key: str  # the query name: "<type>.<characteristic>"
    name: str
    label: str
    kind: str
    values: tuple[ValueControl, ...] = ()
    low: int = 0
    high: int = 0
    minimum: int = 0
    maximum: int = 0
    components: str = ""
    # Where ticking the type starts: the first value the rules allow the type, or the counts of
    # the first arrangement (a small selection, said in the page, rather than everything).
    start: str = ""
    start_most: int = 0


@dataclass(frozen=True)
class TypeControl:
    """A kinematic type's controls. A type not shown on a page too large to hold every type
    has none: its part of the selection is ``carried`` as the address holds it."""

    name: str
    included: bool
    shown: bool
    characteristics: tuple[CharacteristicControl, ...]
    carried: tuple[tuple[str, str], ...] = ()


# Value controls one selection page holds at most with every type shown; a rule set with more
# is shown one type at a time (1,000 types of 999 characteristics made a page of 1.5 GB).
MAX_PAGE_CONTROLS = 20_000


def shown_view(rules: RuleSet, view: str) -> str:
    """The view a page shows: ``view``, but the first kinematic type instead of ``all`` when
    every type's controls together are more than :data:`MAX_PAGE_CONTROLS`."""
    if view != "all":
        return view
    per_type = sum(
        len(c.values) if c.kind != "integer" else 1
        for c in rules.characteristics
        if c.name != rules.team_key
    )
    if per_type * len(rules.key.values) <= MAX_PAGE_CONTROLS:
        return view
    return str(rules.key.values[0])


def _components_text(characteristic: Characteristic, value: object) -> str:
    return ", ".join(c.name for c in characteristic.components_of(value))  # type: ignore[arg-type]  # a Value


def _type_controls(page: Page, view: str) -> list[TypeControl]:
    chosen = page.chosen
    if chosen is None:
        return []
    rules = chosen.rules
    selection = chosen.selection
    excluded = page.studio.workspace.excluded(chosen.source)
    values = dict(selection.values)
    ranges = dict(selection.ranges)
    controls = []
    collapsed = view != "all"
    for kinematic_type in (str(v) for v in rules.key.values):
        shown_here = view in ("", "all") or view == kinematic_type
        included = kinematic_type in selection.types
        if collapsed and not shown_here:
            # Not drawn: its part of the selection travels on as the address holds it.
            prefix = f"{kinematic_type}."
            carried = tuple((k, v) for k, v in page.pairs if k.startswith(prefix))
            controls.append(TypeControl(kinematic_type, included, False, (), carried))
            continue
        characteristics = tuple(
            _integer_control(values, ranges, kinematic_type, characteristic)
            if characteristic.kind == "integer"
            else _categorical_control(values, kinematic_type, characteristic, excluded)
            for characteristic in rules.characteristics
            if characteristic.name != rules.team_key
        )
        controls.append(TypeControl(kinematic_type, included, shown_here, characteristics))
    return controls


# The values a selection names, by (type, characteristic), as text.
ChosenValues = dict[tuple[str, str], tuple[str, ...]]


def _integer_control(
    values: ChosenValues,
    ranges: dict[tuple[str, str], tuple[str | None, str | None]],
    kinematic_type: str,
    characteristic: Characteristic,
) -> CharacteristicControl:
    """The two sliders of a count characteristic, as the selection sets them."""
    where = (kinematic_type, characteristic.name)
    low, high = int(characteristic.values[0]), int(characteristic.values[-1])
    given = [v for v in values.get(where, ()) if v.strip().isdigit()]
    start, end = ranges.get(where, (None, None))
    minimum = _bounded(start, low, high, low)
    maximum = _bounded(end, low, high, high)
    if given:
        minimum, maximum = min(map(int, given)), max(map(int, given))
    components = "; ".join(f"{c.name}: {c.describe_range()}" for c in characteristic.components)
    first = next((c for c in characteristic.components if low in c.values), None)
    start_most = high if first is None else min(high, max(int(v) for v in first.values))
    return CharacteristicControl(
        f"{kinematic_type}.{characteristic.name}",
        characteristic.name,
        characteristic.label,
        "integer",
        low=low,
        high=high,
        minimum=minimum,
        maximum=maximum,
        components=components if len(components) < 400 else "",
        start_most=start_most,
    )


def _categorical_control(
    values: ChosenValues,
    kinematic_type: str,
    characteristic: Characteristic,
    excluded: dict[tuple[str, str], dict[str, Removed]],
) -> CharacteristicControl:
    """A box per value, ticked as the selection says, disabled where the rules exclude it."""
    where = (kinematic_type, characteristic.name)
    chosen_values = values.get(where)
    reasons = excluded.get(where, {})
    start = next((str(v) for v in characteristic.values if str(v) not in reasons), "")
    return CharacteristicControl(
        f"{kinematic_type}.{characteristic.name}",
        characteristic.name,
        characteristic.label,
        "categorical",
        start=start,
        values=tuple(
            ValueControl(
                str(value),
                _components_text(characteristic, value),
                chosen_values is None or str(value) in chosen_values,
                ""
                if str(value) not in reasons
                else " and ".join(
                    f"{shown(c.name, quoted=True)} ({c.location})"
                    for c in reasons[str(value)].constraints
                ),
                chosen_values is not None and str(value) in chosen_values,
            )
            for value in characteristic.values
        ),
    )


@dataclass(frozen=True)
class ShownFinding:
    """A finding of ``check`` as the selection view shows it at a control: its level, check id
    and message, and where it is (``where``) with a link there (``link``): the rule set's text
    at its line, or the finding on the Check page for a place in the selection."""

    level: str
    check: str
    message: str
    where: str
    link: str


Slot = tuple[str, str, str]  # (type, characteristic, value) of a control; ("", "", ""): general


def _placed_findings(
    page: Page, data: dict[str, Any], kinematic_types: Sequence[str]
) -> dict[Slot, list[ShownFinding]]:
    """The findings of :meth:`Studio.findings_data` by the control that shows them (a finding
    about a value of the rules is shown at that value in every type); findings about no control
    under ``("", "", "")``."""
    found: dict[Slot, list[ShownFinding]] = {}
    for index, finding in enumerate(data["findings"]):
        if finding["file"] == SELECTION_FILE:
            where = f"{SELECTION_FILE}: {finding['path'] or 'the selection'}"
            link = f"{page.link('/check')}#finding-{index}"
        else:
            where = f"{finding['file']}:{finding['line']}:{finding['column']}"
            link = f"/rules/source?{urlencode([('rules', data['rules'])])}#L{finding['line']}"
        shown_finding = ShownFinding(
            finding["level"], finding["check"], finding["message"], where, link
        )
        slots: list[Slot] = []
        for place in finding["places"] or [{"type": "", "characteristic": "", "value": ""}]:
            kinematic_type, characteristic, value = (
                place["type"],
                place["characteristic"],
                place["value"],
            )
            if not kinematic_type and characteristic:
                slots += [(t, characteristic, value) for t in kinematic_types]
            else:
                slots.append((kinematic_type, characteristic, value))
        for slot in dict.fromkeys(slots):
            found.setdefault(slot, []).append(shown_finding)
    return found


def _bounded(text: str | None, low: int, high: int, default: int) -> int:
    if text is None or not text.strip().isdigit() or len(text) > 18:
        return default
    return min(max(int(text), low), high)


async def selection(request: Request) -> Response:
    page = _page(request, "Selection")
    start = page.studio.workspace.start_team
    if not page.pairs and start is not None:
        # The bare address shows the team the studio was started with.
        source = page.studio.workspace.source(None)
        from solver.studio.selection import query_of

        return RedirectResponse(f"/?{_query(query_of(start, source.id))}", status_code=303)

    def work() -> dict[str, Any]:
        _choose(page)
        chosen = page.chosen
        assert chosen is not None
        view = shown_view(chosen.rules, _first(page.pairs, "view") or "all")
        data = None
        note = None
        if chosen.team is not None:
            try:
                solution = page.studio.solution(chosen)
                data = page.studio.solve_data(page.pairs)
                note = published_note(solution)
            except SolverError as error:
                page.faults.extend(error.faults)
        checked = None
        whatif = None
        findings: dict[Slot, list[ShownFinding]] = {}
        # What-if is never made for the page's load (the script asks for it afterwards); a
        # page without scripts asks for it with whatif=1.
        if data is not None and not page.faults and _first(page.pairs, "whatif") == "1":
            whatif = page.studio.whatif_data(page.pairs)
            whatif = None if whatif.get("superseded") else whatif
        if not page.faults:
            checked = page.studio.findings_data(page.pairs)
            types = [str(v) for v in chosen.rules.key.values]
            findings = _placed_findings(page, checked, types)
        return {
            "checked": checked,
            "whatif": whatif,
            "findings": findings,
            "view": view,
            "types": _type_controls(page, view),
            "data": data,
            "note": note,
            "sources": page.studio.workspace.rule_sources,
            "teams": [
                (name, _query(pairs)) for name, pairs in page.studio.shipped_teams(chosen.source)
            ],
            "starts": [
                (name, rules_id, _query(pairs)) for name, rules_id, pairs in page.studio.starts()
            ],
            "chart_query": page.selection_query,
        }

    context = await run_in_threadpool(work)
    return page.render("selection.html", status=422 if page.faults else 200, **context)


# -- configurations, robots, one robot ---------------------------------------------------------


async def configurations(request: Request) -> Response:
    page = _page(request, "Configurations")

    def work() -> dict[str, Any]:
        offset = _number(page.pairs, "offset", 0)
        pairs = [*page.pairs, ("offset", str(offset)), ("limit", str(PER_PAGE))]
        data = page.studio.configurations_data(_only_last(pairs))
        chosen = page.chosen = page.studio.chosen(page.pairs)
        a, b = _first(page.pairs, "a"), _first(page.pairs, "b")
        compared = None
        if a and b:
            left = page.studio.configuration_data(page.pairs, _number(page.pairs, "a", 0))
            right = page.studio.configuration_data(page.pairs, _number(page.pairs, "b", 0))
            labels = {c.name: c.label for c in chosen.rules.characteristics}
            compared = _compare(left, right, labels)
        return {
            "data": data,
            "compared": compared,
            "a": a or "",
            "b": b or "",
            "characteristics": [(c.name, c.label) for c in chosen.rules.characteristics],
            "offset": offset,
            "per_page": PER_PAGE,
        }

    return page.render("configurations.html", **await run_in_threadpool(work))


def _compare(
    left: dict[str, Any], right: dict[str, Any], labels: dict[str, str]
) -> list[dict[str, Any]]:
    """Two configurations side by side, by the names the rules give (``Robot Kinematic
    Type``: ``UAV``, not ``kinematic_type``: ``UAV: UAV``)."""
    rows = []
    for one, other in zip(left["components"], right["components"], strict=True):
        rows.append(
            {
                "characteristic": labels.get(one["characteristic"], one["characteristic"]),
                "left": _named_component_text(one),
                "right": _named_component_text(other),
                "differs": one["component"] != other["component"],
            }
        )
    rows.insert(
        0,
        {
            "characteristic": "valid robots",
            "left": str(left["valid_robots"]),
            "right": str(right["valid_robots"]),
            "differs": False,
        },
    )
    return rows


def _component_text(entry: dict[str, Any]) -> str:
    if "values" in entry:
        return f"{entry['component']}: {', '.join(map(str, entry['values']))}"
    runs = ", ".join(f"{a}" if a == b else f"{a}..{b}" for a, b in entry["counts"])
    return f"{entry['component']}: {runs} ({entry['clusters'][0]}..{entry['clusters'][1]} clusters)"


def _named_component_text(entry: dict[str, Any]) -> str:
    """A component by the name the rules give it, and what it serves where that says more
    than its name (``audio: Speaker, Microphone``; ``UGV``, not ``UGV: UGV``)."""
    if "values" in entry and [str(v) for v in entry["values"]] == [entry["component"]]:
        return str(entry["component"])
    return _component_text(entry)


def _number(pairs: Pairs, name: str, default: int) -> int:
    text = _first(pairs, name)
    if text is None or not text.isdigit() or len(text) > 18:
        return default
    return int(text)


def _only_last(pairs: Sequence[tuple[str, str]]) -> list[tuple[str, str]]:
    """``pairs`` with only the last of each paging parameter (``offset``, ``limit``)."""
    last = {k: v for k, v in pairs if k in ("offset", "limit")}
    return [(k, v) for k, v in pairs if k not in last] + list(last.items())


async def configuration_map(request: Request) -> Response:
    """The configuration map: components as rows, configurations (the default one too) as
    columns; filtered by a component, several picked to compare."""
    page = _page(request, "Map")

    def work() -> dict[str, Any]:
        data = page.studio.map_data(page.pairs)
        chosen = page.chosen = page.studio.chosen(page.pairs)
        labels = {c.name: c.label for c in chosen.rules.characteristics}
        compared = []
        if data["compared"]:
            for index, characteristic in enumerate(chosen.rules.characteristics):
                cells = [c["components"][index] for c in data["compared"]]
                texts = [_named_component_text(c) for c in cells]
                differs = len({c["component"] for c in cells}) > 1
                compared.append((characteristic.label, texts, differs))
        return {
            "data": data,
            "labels": labels,
            "compared": compared,
            "picked": [c["number"] for c in data["compared"]],
        }

    return page.render("map.html", **await run_in_threadpool(work))


async def configuration(request: Request) -> Response:
    page = _page(request, "Configuration")
    text = page.request.path_params["number"]
    number = int(text) if text.isdigit() and len(text) < 18 else -1

    def work() -> dict[str, Any]:
        data = page.studio.configuration_data(page.pairs, number)
        offset = _number(page.pairs, "offset", 0)
        pairs = _only_last(
            [
                *page.pairs,
                ("configuration", str(number)),
                ("offset", str(offset)),
                ("limit", str(PER_PAGE)),
            ]
        )
        robots = page.studio.robots_data(pairs)
        page.chosen = page.studio.chosen(page.pairs)
        return {
            "data": data,
            "robots": robots,
            "rows": [(e["characteristic"], _component_text(e)) for e in data["components"]],
            "offset": offset,
            "per_page": PER_PAGE,
            "names": page.chosen.rules.names,
        }

    return page.render("configuration.html", **await run_in_threadpool(work))


async def robots(request: Request) -> Response:
    page = _page(request, "Robots")

    def work() -> dict[str, Any]:
        offset = _number(page.pairs, "offset", 0)
        pairs = _only_last([*page.pairs, ("offset", str(offset)), ("limit", str(PER_PAGE))])
        data = page.studio.robots_data(pairs)
        chosen = page.chosen = page.studio.chosen(page.pairs)
        given = robot_pairs(page.pairs)
        answer = page.studio.assign_data(page.pairs) if any(given.values()) else None
        rows = []
        if answer is not None:
            rules = chosen.rules
            relevant = answer["relevant_components"]
            for characteristic in rules.characteristics:
                rows.append(
                    (
                        characteristic.label,
                        given.get(characteristic.name, ""),
                        ", ".join(relevant.get(characteristic.name, [])) or "-",
                    )
                )
        lookups = []
        for characteristic in chosen.rules.characteristics:
            values = [str(v) for v in characteristic.values]
            lookups.append(
                {
                    "name": characteristic.name,
                    "label": characteristic.label,
                    "values": values if len(values) <= 200 else [],
                    "value": given.get(characteristic.name, ""),
                }
            )
        return {
            "data": data,
            "answer": answer,
            "rows": rows,
            "lookups": lookups,
            "names": chosen.rules.names,
            "offset": offset,
            "per_page": PER_PAGE,
        }

    return page.render("robots.html", **await run_in_threadpool(work))


# -- charts, check, export ---------------------------------------------------------------------


async def charts(request: Request) -> Response:
    page = _page(request, "Charts")

    def work() -> None:
        page.chosen = page.studio.chosen(page.pairs)
        page.chosen.require()

    await run_in_threadpool(work)
    return page.render("charts.html", kinds=CHART_KINDS)


async def check(request: Request) -> Response:
    page = _page(request, "Check")

    def work() -> dict[str, Any]:
        data = page.studio.check_data(page.pairs)
        page.chosen = page.studio.chosen(page.pairs)
        return {"data": data, "selection_file": SELECTION_FILE}

    return page.render("check.html", **await run_in_threadpool(work))


async def rules_source(request: Request) -> Response:
    """The rule set's text with its lines numbered: where findings and constraints link to."""
    page = _page(request, "Rule set")

    def work() -> dict[str, Any]:
        _choose(page)
        source, text = page.studio.rules_text(page.pairs)
        return {"source": source, "lines": text.splitlines()}

    return page.render("rules_source.html", **await run_in_threadpool(work))


async def export(request: Request) -> Response:
    page = _page(request, "Export")

    def work() -> dict[str, Any]:
        page.chosen = page.studio.chosen(page.pairs)
        page.chosen.require()
        return {
            "yaml": page.studio.team_text(page.pairs),
            "layouts_refused": page.studio.layouts_refused(page.pairs),
        }

    return page.render("export.html", **await run_in_threadpool(work))


async def upload_team(request: Request) -> Response:
    page = _page(request, "Import")
    uploads, _ = await read_uploads(page.request)
    if len(uploads) != 1:
        raise InputError.at("<upload>", "choose one team file to import")
    query = await run_in_threadpool(page.studio.read_team, uploads[0], page.pairs)
    return RedirectResponse(f"/?{_query(query)}", status_code=303)


async def upload_rules(request: Request) -> Response:
    page = _page(request, "Rule set")
    uploads, _ = await read_uploads(page.request)
    if len(uploads) != 1:
        raise InputError.at("<upload>", "choose one rule set file to upload")
    source = await run_in_threadpool(page.studio.add_rules, uploads[0])
    return RedirectResponse(f"/?{_query([('rules', source.id)])}", status_code=303)


async def whatif_apply(request: Request) -> Response:
    """What-if's change to the rule set applied (a page without scripts posts here): the
    changed rule set kept, and the page of the same selection under it."""
    page = _page(request, "What-if")
    pairs = await run_in_threadpool(page.studio.whatif_apply, page.pairs)
    return RedirectResponse(f"/?{_query(pairs)}", status_code=303)


# -- designs (``--designs DIR``) ---------------------------------------------------------------


async def designs(request: Request) -> Response:
    """The design folder: every design (and every entry refused, escaped), a form to save the
    page's selection, and the change from one design to another (``a``, ``b``)."""
    page = _page(request, "Designs")
    first, second = _first(page.pairs, "a"), _first(page.pairs, "b")

    def work() -> dict[str, Any]:
        _choose(page)
        studio = page.studio
        if studio.designs is None:
            return {"entries": None, "left_out": 0, "diff": None}
        entries, left_out = studio.designs_list()
        diff = studio.design_diff(first, second) if first and second else None
        return {"entries": entries, "left_out": left_out, "diff": diff}

    return page.render(
        "designs.html",
        saved=_first(page.pairs, "saved") or "",
        a=first or "",
        b=second or "",
        **await run_in_threadpool(work),
    )


async def _form_field(request: Request, name: str) -> str:
    try:
        form = await request.form(max_files=0, max_fields=8)
    except HTTPException as error:
        raise InputError.at("<request>", f"refused: {error.detail}") from None
    try:
        value = form.get(name)
    finally:
        await form.close()
    if not isinstance(value, str):
        raise InputError.at("<request>", f"the form names no {name}", path=name)
    return value


async def design_save(request: Request) -> Response:
    page = _page(request, "Designs")
    name = await _form_field(request, "design")
    file = await run_in_threadpool(page.studio.save_design, name, selection_pairs(page.pairs))
    pairs = [(k, v) for k, v in selection_pairs(page.pairs) if k != "name"]
    query = _query([*pairs, ("name", file.removesuffix(".yaml"))], saved=file)
    return RedirectResponse(f"/designs?{query}", status_code=303)


async def design_delete(request: Request) -> Response:
    page = _page(request, "Designs")
    name = await _form_field(request, "design")
    await run_in_threadpool(page.studio.delete_design, name)
    return RedirectResponse(page.link("/designs"), status_code=303)


async def design_open(request: Request) -> Response:
    page = _page(request, "Designs")
    name = _first(page.pairs, "design") or ""
    query = await run_in_threadpool(page.studio.design_query, name)
    return RedirectResponse(f"/?{_query(query)}", status_code=303)


# -- fleet ---------------------------------------------------------------------------------------


async def fleet(request: Request) -> Response:
    page = _page(request, "Fleet")

    def work() -> None:
        _choose(page)

    await run_in_threadpool(work)
    return page.render("fleet.html", data=None, folders=page.studio.workspace.folders)


async def fleet_upload(request: Request) -> Response:
    page = _page(request, "Fleet")
    uploads, _ = await read_uploads(page.request)
    data = await run_in_threadpool(page.studio.identify_uploads, uploads, page.pairs)
    _choose(page)
    return page.render("fleet.html", data=data, folders=page.studio.workspace.folders)


async def fleet_folder(request: Request) -> Response:
    page = _page(request, "Fleet")
    index = _number([("i", page.request.path_params["index"])], "i", -1)
    data = await run_in_threadpool(page.studio.identify_folder, index, page.pairs)
    _choose(page)
    return page.render("fleet.html", data=data, folders=page.studio.workspace.folders)


async def fleet_team(request: Request) -> Response:
    page = _page(request, "Fleet")
    fleet_id = page.request.path_params["fleet"]
    data = await run_in_threadpool(page.studio.fleet_team, fleet_id, page.pairs)
    return RedirectResponse(f"/?{_query(data['query'])}", status_code=303)


# -- live, API -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class LiveChoice:
    """One value a robot's combinations take, as a button that selects it."""

    name: str
    value: str
    pressed: bool


@dataclass(frozen=True)
class LiveRow:
    """One robot of the Live view: its event's fields, the values it can be switched to (by
    characteristic label), the configuration its layout is shown for, and the layouts of
    the last answer naming it."""

    robot: dict[str, Any]
    active: bool
    choices: tuple[tuple[str, tuple[LiveChoice, ...]], ...]
    configuration: int | None
    layout_query: str
    answer: dict[str, Any] | None


def live_rows(state: Any, rules: RuleSet) -> list[LiveRow]:
    """The Live view's rows for ``state`` (:class:`solver.studio.live.LiveState`)."""
    selection = state.selection or {}
    asked = selection.get("active") or {}
    chosen = (selection.get("assignment") or {}).get("configuration")
    rows = []
    for robot in state.robots:
        name = robot.get("robot")
        active = name == selection.get("robot")
        combinations = robot.get("combinations") or []
        configuration = (
            chosen
            if active and isinstance(chosen, int)
            else next((c.get("configuration") for c in combinations), None)
        )
        query = (
            urlencode({"robot": name, "configuration": configuration, "v": robot.get("seq")})
            if configuration is not None
            else ""
        )
        choices = _live_choices(combinations, rules, asked if active else {})
        rows.append(LiveRow(robot, active, choices, configuration, query, state.answers.get(name)))
    return rows


def _live_choices(
    combinations: list[dict[str, Any]], rules: RuleSet, asked: dict[str, Any]
) -> tuple[tuple[str, tuple[LiveChoice, ...]], ...]:
    """The values a robot's combinations take, by characteristic (its kind left out: not the
    operator's to choose), each pressed when the operator asked for it."""
    found = [c.get("combination") or {} for c in combinations]
    choices = []
    for characteristic in rules.characteristics:
        name = characteristic.name
        values = list(dict.fromkeys(str(c[name]) for c in found if name in c))
        if values and name != rules.team_key:
            buttons = tuple(LiveChoice(name, value, asked.get(name) == value) for value in values)
            choices.append((characteristic.label, buttons))
    return tuple(choices)


async def live(request: Request) -> Response:
    page = _page(request, "Live")
    _choose(page)
    feed = page.studio.live
    state = None if feed is None else feed.state()
    rows = [] if feed is None else live_rows(state, feed.solution.rules)
    template = "live_body.html" if _first(page.pairs, "fragment") else "live.html"
    return page.render(template, state=state, rows=rows)


async def live_switch(request: Request) -> Response:
    """A robot's (or one of its values') button in the Live view, without scripts: the switch
    is made (:meth:`solver.studio.live.LiveFeed.switch`), then the Live view shows it."""
    page = _page(request, "Live")
    feed = page.studio.live
    if feed is None:
        raise InputError.at("<live>", "the studio was started without --ros2 or --master")
    try:
        form = await request.form(max_files=0, max_fields=8)
    except HTTPException as error:
        raise InputError.at("<request>", f"switch refused: {error.detail}") from None
    try:
        robot = form.get("robot")
        value = form.get("value")
    finally:
        await form.close()
    if not isinstance(robot, str) or not isinstance(value, str | None):
        raise InputError.at("<request>", "a switch names a robot (and a NAME=VALUE)")
    from solver import parse_combination

    values = parse_combination([value]) if value else {}
    await run_in_threadpool(feed.switch, robot, values)
    return RedirectResponse(page.link("/live"), status_code=303)


async def api_index(request: Request) -> Response:
    page = _page(request, "API")
    from solver.studio.api import routes as api_routes

    _choose(page)
    entries = [_endpoint(route) for route in api_routes() if isinstance(route, Route)]
    return page.render("api.html", entries=entries, max_page=MAX_PAGE)


def _endpoint(route: Route) -> dict[str, Any]:
    """One endpoint as the API page shows it: the OpenAPI document's part of it (the
    docstring's text, and after ``---`` its summary, parameters and responses), each text as
    parts of plain text and code (between backticks)."""
    from starlette.schemas import SchemaGenerator

    text = (route.endpoint.__doc__ or "").split("\n---")[0]
    schema = SchemaGenerator({}).parse_docstring(route.endpoint)
    parameters = [
        {
            "name": str(p.get("name", "")),
            "where": str(p.get("in", "")),
            "type": _schema_type(p.get("schema")),
            "description": _code_parts(str(p.get("description", ""))),
        }
        for p in schema.get("parameters", [])
        if isinstance(p, dict)
    ]
    responses = [
        (str(code), _code_parts(str(answer.get("description", ""))))
        for code, answer in (schema.get("responses") or {}).items()
        if isinstance(answer, dict)
    ]
    return {
        "path": route.path,
        "methods": sorted(route.methods or ()),
        "summary": str(schema.get("summary", "")),
        "text": _code_parts(" ".join(text.split())),
        "parameters": parameters,
        "responses": responses,
    }


def _schema_type(schema: object) -> str:
    """``integer``, ``array of string``: a parameter's schema in words."""
    if not isinstance(schema, dict):
        return ""
    kind = str(schema.get("type", ""))
    items = schema.get("items")
    if kind == "array" and isinstance(items, dict):
        return f"array of {items.get('type', '')}"
    if "enum" in schema:
        return f"{kind}: " + ", ".join(map(str, schema["enum"]))
    return kind


def _code_parts(text: str) -> list[tuple[str, bool]]:
    """``text`` as ``(part, is_code)``: the parts between backticks are code."""
    return [(part, index % 2 == 1) for index, part in enumerate(text.split("`")) if part]


def routes() -> list[BaseRoute]:
    return [
        Route("/", selection),
        Route("/configurations", configurations),
        Route("/configurations/{number}", configuration),
        Route("/map", configuration_map),
        Route("/robots", robots),
        Route("/charts", charts),
        Route("/check", check),
        Route("/rules/source", rules_source),
        Route("/export", export),
        Route("/designs", designs),
        Route("/designs", design_save, methods=["POST"]),
        Route("/designs/delete", design_delete, methods=["POST"]),
        Route("/designs/open", design_open),
        Route("/team", upload_team, methods=["POST"]),
        Route("/rules", upload_rules, methods=["POST"]),
        Route("/whatif/apply", whatif_apply, methods=["POST"]),
        Route("/fleet", fleet),
        Route("/fleet", fleet_upload, methods=["POST"]),
        Route("/fleet/folders/{index}", fleet_folder, methods=["POST"]),
        Route("/fleet/{fleet}/team", fleet_team, methods=["POST"]),
        Route("/live", live),
        Route("/live/switch", live_switch, methods=["POST"]),
        Route("/api", api_index),
    ]
