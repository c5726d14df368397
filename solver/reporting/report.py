"""Reports of a solved team, to take to a design meeting: HTML or Markdown.

A report holds the counts per kinematic type, the bound T and the default configuration, the
comparison with published figures when the team file carries them (``published:``), the radar chart
and the bar chart of :mod:`solver.reporting.plot`, the team's selections and every UI configuration
with its components.

* **HTML** is one self-contained file: the charts are SVG embedded as ``data:`` URIs, the style
  sheet is inline, and a Content-Security-Policy forbids fetching anything, so the page shows
  the same offline, attached to a mail or archived.
* **Markdown** links its charts as PNG files written beside it (``case3.md`` ->
  ``case3-radar.png``, ``case3-bars.png``): Markdown viewers (GitHub among them) do not show
  images from ``data:`` URIs.

Both are deterministic: the same team gives the same bytes, charts included.

Not here: the charts themselves (:mod:`solver.reporting.plot`), text/JSON/CSV output
(:mod:`solver.reporting.render`), many teams at once (:mod:`solver.reporting.batch`).
"""

from __future__ import annotations

import base64
import html
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, Literal

from solver.core.constraints import Value
from solver.core.partition import Configuration
from solver.core.ruleset import Characteristic
from solver.errors import InputError
from solver.files.atomic import write_all_atomic, write_atomic
from solver.reporting import markdown
from solver.reporting.chart import runs
from solver.reporting.plot import (
    PlotKind,
    bars_figure,
    figure_bytes,
    matrix_figure,
    radar_figure,
)
from solver.solving.contracts import configuration_data
from solver.solving.reproduce import published_note
from solver.solving.solution import Solution, TypeSummary, solution_warnings
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "REPORT_FORMATS",
    "image_names",
    "render_html",
    "render_markdown",
    "report_format",
    "reproduction_note",
    "write_report",
]

ReportFormat = Literal["html", "markdown"]
REPORT_FORMATS: dict[str, ReportFormat] = {
    ".html": "html",
    ".htm": "html",
    ".md": "markdown",
    ".markdown": "markdown",
}
_KINDS: tuple[PlotKind, ...] = ("radar", "bars")
# The HTML page embeds its charts, so it also shows the component matrix, first: it answers
# "which components does each type need?" at a glance, where the radar's fills overlap.
_HTML_KINDS: tuple[PlotKind, ...] = ("matrix", "radar", "bars")
_ALT = {
    "radar": "Radar chart: the selected values of each kinematic type, one spoke per "
    "characteristic",
    "bars": "Bar chart: valid robots and UI configurations per kinematic type",
    "matrix": "Component matrix: per kinematic type, the share of its robots whose "
    "configuration uses each component, and how many configurations do",
}

_STYLE = """
body { font-family: "DejaVu Sans", Verdana, sans-serif; margin: 2rem; padding: 0 1rem;
       color: #222; line-height: 1.4; }
p, ul { max-width: 62rem; }
nav.contents { font-size: 0.9rem; }
nav.contents a { margin-right: 1rem; }
details > summary { cursor: pointer; color: #0072B2; margin: 0.5rem 0; }
h1 { font-size: 1.6rem; margin-bottom: 0.2rem; }
h2 { font-size: 1.2rem; margin-top: 2rem; border-bottom: 1px solid #ccc; }
p.meta { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.8rem 0; font-size: 0.9rem; }
th, td { border: 1px solid #bbb; padding: 0.2rem 0.5rem; text-align: left;
         vertical-align: top; }
th { background: #eee; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
tr.total td { font-weight: bold; }
.note { border-left: 4px solid #0072B2; background: #f2f7fb; padding: 0.4rem 0.8rem; }
.note.differs { border-left-color: #D55E00; background: #fdf3ec; }
figure { margin: 1rem 0; }
figure img { max-width: 100%; height: auto; }
figcaption { color: #555; font-size: 0.85rem; }
figure.layout { display: inline-block; margin: 4px; }
@media print { h2 { break-after: avoid; } table, figure { break-inside: avoid; } }
"""


def report_format(path: str | Path) -> ReportFormat:
    """The report format a file name asks for (``.html``/``.htm``, ``.md``/``.markdown``)."""
    suffix = Path(path).suffix.lower()
    if suffix not in REPORT_FORMATS:
        given = shown(suffix, quoted=True) if suffix else "no extension"
        raise InputError.at(
            shown(str(path), limit=SHOWN_FILE_NAME_CHARS),
            f"cannot tell the report format from {given}; name the "
            f"file {', '.join(REPORT_FORMATS)}",
            code="unknown-format",
        )
    return REPORT_FORMATS[suffix]


def image_names(path: str | Path) -> dict[PlotKind, Path]:
    """The chart files a Markdown report at ``path`` links: ``<stem>-radar.png`` and so on."""
    target = Path(path)
    return {kind: target.with_name(f"{target.stem}-{kind}.png") for kind in _KINDS}


def reproduction_note(solution: Solution) -> tuple[str, bool] | None:
    """The published figures beside the computed ones, worded as ``teleop-ui solve`` does.

    ``None`` when the team carries no published figures; else the sentence and whether the
    figures agree. Nothing is adjusted to agree.
    """
    note = published_note(solution)
    if note is None:
        return None
    stated, verdict, agrees = note
    return f"{stated}: {verdict}", agrees


# ---- the content, independent of the markup ----------------------------------------------


def _ratio(summary: TypeSummary) -> str:
    ratio = summary.reduction_ratio
    return "" if ratio is None else f"{ratio:.2f}"


def _summary_rows(solution: Solution) -> list[list[Any]]:
    return [
        [s.kinematic_type, s.valid_robots, s.ui_configurations, _ratio(s)]
        for s in (*solution.by_type, solution.totals)
    ]


_SUMMARY_HEADERS = [
    "kinematic type",
    "valid robots",
    "UI configurations",
    "robots per configuration",
]


def _facts(solution: Solution) -> list[str]:
    rules = solution.rules
    factors = " x ".join(str(n) for n in rules.bound_factors)
    facts = [
        f"bound T = {solution.bound} ({factors}): the most UI configurations these rules "
        "could ever need",
        f"default UI configuration: {solution.default_configuration} (every component, "
        f"{sum(rules.bound_factors)} in all), given to any robot outside the team's "
        "selections",
    ]
    return facts + solution_warnings(solution)


def _values_text(characteristic: Characteristic, values: Sequence[Value]) -> str:
    """A selection as a reader writes it: ``1..13``, ``2D Camera, LIDAR``, ``all (6)``."""
    if characteristic.kind == "integer":
        return ", ".join(
            str(first) if first == last else f"{first}..{last}"
            for first, last in runs(characteristic, values)
        )
    if tuple(values) == characteristic.values:
        return f"all ({len(values)})"
    return ", ".join(str(v) for v in values)


def _selection_table(solution: Solution) -> tuple[list[str], list[list[str]]]:
    rules = solution.rules
    others = [(i, c) for i, c in enumerate(rules.characteristics) if c.name != rules.team_key]
    headers = [rules.key.label, *(c.label for _, c in others)]
    rows = [
        [s.kinematic_type, *(_values_text(c, s.domains[i]) for i, c in others)]
        for s in solution.team.selections
    ]
    return headers, rows


def _component_cell(entry: Mapping[str, Any]) -> str:
    name = str(entry["component"])
    if "range" in entry:
        low, high = entry["range"]
        few, many = entry["clusters"]
        span = f"{low}" if low == high else f"{low}..{high}"
        clusters = f"{few}" if few == many else f"{few}..{many}"
        return f"{name}: {span} ({clusters} clusters)"
    values = [str(v) for v in entry["values"]]
    if values == [name]:
        return name
    return f"{name}: {', '.join(values)}"


def _configuration_table(solution: Solution) -> tuple[list[str], list[list[Any]]]:
    rules = solution.rules
    headers = ["#", *(c.label for c in rules.characteristics), "valid robots"]
    rows: list[list[Any]] = []
    for configuration in solution.configurations:
        data = configuration_data(rules, configuration)
        rows.append(
            [
                configuration.number,
                *(_component_cell(e) for e in data["components"]),
                configuration.robots,
            ]
        )
    rows.append(
        [
            solution.default_configuration,
            "default: every component",
            *([""] * (len(rules.characteristics) - 1)),
            "",
        ]
    )
    return headers, rows


def _constraint_table(solution: Solution) -> tuple[list[str], list[list[str]]] | None:
    """Each rule constraint, where it is, and what it removes from this team's selections
    (:mod:`solver.core.forbidden`); ``None`` when the rule set has no constraints."""
    rules = solution.rules
    if not rules.constraints:
        return None
    # Whole values only: a constraint may also remove combinations of values that each
    # stay valid elsewhere (those robots are simply not counted).
    headers = ["constraint", "where", "selected values it excludes entirely"]
    rows = []
    for constraint in rules.constraints:
        removed = [r for r in solution.removed if constraint in r.constraints]
        text = "; ".join(
            f"{r.kinematic_type}: "
            + (
                f"{r.characteristic} {', '.join(str(v) for v in r.values)}"
                if r.characteristic
                else "every robot"
            )
            for r in removed
        )
        rows.append([constraint.describe(), str(constraint.location or ""), text or "none"])
    return headers, rows


def _subtitle(solution: Solution) -> str:
    team, rules = solution.team, solution.rules
    return f"team file {team.file}; rules: {rules.name} ({rules.file})"


# ---- HTML ------------------------------------------------------------------------------------


def _html_text(text: object) -> str:
    """``text`` as HTML text that shows exactly it: markup escaped, and a control, line break
    or invisible format character (a right-to-left override) shown as its escape
    (:func:`~solver.untrusted.shown`), as in the text output."""
    return html.escape(shown(str(text), limit=None))


_NUMBER = ' class="n"'
_TOTAL = ' class="total"'


def _html_table(
    headers: Sequence[str],
    rows: Sequence[Sequence[Any]],
    numbers: Sequence[bool],
    total_last: bool = False,
) -> str:
    e = _html_text
    lines = [
        "<table>",
        "<thead><tr>" + "".join(f"<th>{e(str(h))}</th>" for h in headers) + "</tr></thead>",
        "<tbody>",
    ]
    for index, row in enumerate(rows):
        total = total_last and index == len(rows) - 1
        cells = "".join(
            f"<td{_NUMBER if n else ''}>{e(str(v))}</td>" for v, n in zip(row, numbers, strict=True)
        )
        lines.append(f"<tr{_TOTAL if total else ''}>{cells}</tr>")
    lines += ["</tbody>", "</table>"]
    return "\n".join(lines)


# Tables longer than this are folded (<details>): the page stays navigable for large teams.
_FOLD_ROWS = 30


def _folded(table: str, rows: int) -> str:
    if rows <= _FOLD_ROWS:
        return table
    return f"<details>\n<summary>show all {rows} rows</summary>\n{table}\n</details>"


def _section(anchor: str, title: str) -> str:
    return f'<h2 id="{anchor}">{_html_text(title)}</h2>'


def _svg_uri(svg: bytes) -> str:
    return "data:image/svg+xml;base64," + base64.b64encode(svg).decode("ascii")


# At most this many layout thumbnails (the default configuration's first): each is a few KB of
# inline SVG, so a rule set with thousands of configurations still gives a small, fast page.
MAX_THUMBNAILS = 60
# A layout with more panels than this is named, not drawn (it would not be legible anyway).
MAX_THUMBNAIL_PANELS = 40
# More thumbnails than this are folded (<details>), as long tables are.
_FOLD_THUMBNAILS = 12


def _thumbnails(solution: Solution) -> str:
    """One SVG preview of each configuration's Foxglove layout (issue 17), capped and folded."""
    from solver.layouts import foxglove_layout, layout_filename, load_presentation
    from solver.layouts.preview import preview_svg
    from solver.layouts.tiling import tiles

    e = _html_text
    # The shipped profile serves every rule set: a component it omits is a placeholder panel.
    profile = load_presentation()
    default_file = layout_filename(solution.default_configuration, default=True)
    chosen: list[tuple[str, Configuration | None]] = [
        (f"default configuration ({default_file})", None)
    ]
    chosen += [
        (f"configuration {c.number} ({layout_filename(c.number)})", c)
        for c in solution.configurations[: MAX_THUMBNAILS - 1]
    ]

    def thumbnail(configuration: Configuration | None) -> str:
        # Tiles are capped before the layout is built: a sensor count of 1..100000 in clusters
        # of 1 would otherwise build 100000 panels per thumbnail. A layout past the cap is
        # named, not drawn, so no thumbnail shows fewer panels than the layout has.
        count = None
        if configuration is not None:
            count = min(tiles(solution.rules, configuration), MAX_THUMBNAIL_PANELS + 1)
        layout = foxglove_layout(solution, configuration, profile, tile_count=count)
        panels = len(layout["configById"])
        if panels > MAX_THUMBNAIL_PANELS:
            return f'<p class="meta">more than {MAX_THUMBNAIL_PANELS} panels: not drawn</p>'
        return preview_svg(layout, 240, 150)

    figures = "\n".join(
        f'<figure class="layout">{thumbnail(c)}<figcaption>{e(name)}</figcaption></figure>'
        for name, c in chosen
    )
    total = len(solution.configurations) + 1
    note = (
        f"<p>Each configuration's layout (<code>teleop-ui layouts</code>): panels as "
        f"rectangles coloured by panel type. Showing {len(chosen)} of {total}"
        + (
            f" (at most {MAX_THUMBNAILS}; <code>teleop-ui layouts TEAM -o DIR --preview</code> "
            "draws them all)."
            if len(chosen) < total
            else "."
        )
        + "</p>"
    )
    if len(chosen) <= _FOLD_THUMBNAILS:
        return note + "\n" + figures
    return (
        f"{note}\n<details>\n<summary>show {len(chosen)} layout thumbnails</summary>\n"
        f"{figures}\n</details>"
    )


def render_html(solution: Solution, charts: Mapping[PlotKind, bytes] | None = None) -> str:
    """The report as one self-contained HTML page.

    ``charts`` maps ``radar``/``bars`` to SVG bytes; by default they are drawn here.
    """
    if charts is None:
        charts = _charts(solution, "svg", _HTML_KINDS)
    e = _html_text
    team = solution.team
    title = f"{team.name}: UI configurations"
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en">',
        "<head>",
        '<meta charset="utf-8">',
        # Nothing may be fetched: the page must look the same offline and archived.
        '<meta http-equiv="Content-Security-Policy" content="default-src \'none\'; '
        "img-src data:; style-src 'unsafe-inline'\">",
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{e(title)}</title>",
        f"<style>{_STYLE}</style>",
        "</head>",
        "<body>",
        f"<h1>{e(team.name)}</h1>",
        f'<p class="meta">{e(_subtitle(solution))}</p>',
    ]
    if team.description:
        parts.append(f"<p>{'<br>'.join(e(line) for line in team.description.splitlines())}</p>")
    constraints = _constraint_table(solution)
    titles = {
        "counts": "Valid robots and UI configurations",
        "charts": "Charts",
        "constraints": f"Rule constraints ({len(solution.rules.constraints)})",
        "selections": "Team selections",
        "configurations": f"UI configurations ({len(solution.configurations)} and the default)",
        "layouts": "Layouts",
    }
    if constraints is None:
        del titles["constraints"]
    parts.append(
        '<nav class="contents">'
        + "".join(f'<a href="#{anchor}">{e(title)}</a>' for anchor, title in titles.items())
        + "</nav>"
    )
    parts += [
        _section("counts", titles["counts"]),
        _html_table(
            _SUMMARY_HEADERS, _summary_rows(solution), [False, True, True, True], total_last=True
        ),
        "<ul>",
        *(f"<li>{e(fact)}</li>" for fact in _facts(solution)),
        "</ul>",
    ]
    note = reproduction_note(solution)
    if note is not None:
        text, agrees = note
        parts.append(f'<p class="note{"" if agrees else " differs"}">{e(text)}</p>')
    parts.append(_section("charts", titles["charts"]))
    for kind in _HTML_KINDS:
        if kind in charts:
            parts += [
                "<figure>",
                f'<img src="{_svg_uri(charts[kind])}" alt="{e(_ALT[kind])}">',
                f"<figcaption>{e(_ALT[kind])}.</figcaption>",
                "</figure>",
            ]
    if constraints is not None:
        headers, rows = constraints
        parts += [
            _section("constraints", titles["constraints"]),
            _folded(_html_table(headers, rows, [False] * len(headers)), len(rows)),
        ]
    headers, rows = _selection_table(solution)
    parts += [
        _section("selections", titles["selections"]),
        _folded(_html_table(headers, rows, [False] * len(headers)), len(rows)),
    ]
    headers, rows = _configuration_table(solution)
    parts += [
        _section("configurations", titles["configurations"]),
        _folded(_html_table(headers, rows, [True, *[False] * (len(headers) - 2), True]), len(rows)),
        _section("layouts", titles["layouts"]),
        _thumbnails(solution),
        "</body>",
        "</html>",
    ]
    return "\n".join(parts) + "\n"


# ---- Markdown ----------------------------------------------------------------------------


def render_markdown(solution: Solution, images: Mapping[PlotKind, str] | None = None) -> str:
    """The report as Markdown; ``images`` maps ``radar``/``bars`` to the files to link.

    Every name from the rule and team files is escaped (:mod:`solver.reporting.markdown`), as the
    HTML report escapes it: a team called ``<script>`` shows as that text.
    """
    team = solution.team
    parts = [markdown.heading(1, team.name), "", f"_{markdown.escape(_subtitle(solution))}_", ""]
    if team.description:
        parts += [markdown.paragraph(team.description), ""]
    parts += [
        "## Valid robots and UI configurations",
        "",
        markdown.table(_SUMMARY_HEADERS, _summary_rows(solution), [False, True, True, True]).rstrip(
            "\n"
        ),
        "",
    ]
    parts += [f"- {markdown.escape(fact)}" for fact in _facts(solution)]
    note = reproduction_note(solution)
    if note is not None:
        parts += ["", f"> **{markdown.escape(note[0])}**"]
    if images:
        parts += ["", "## Charts", ""]
        for kind in _KINDS:
            if kind in images:
                parts += [
                    f"![{markdown.escape(_ALT[kind])}]({markdown.link_target(images[kind])})",
                    "",
                ]
    constraints = _constraint_table(solution)
    if constraints is not None:
        parts += [
            "",
            f"## Rule constraints ({len(solution.rules.constraints)})",
            "",
            markdown.table(*constraints).rstrip("\n"),
        ]
    headers, rows = _selection_table(solution)
    parts += ["", "## Team selections", "", markdown.table(headers, rows).rstrip("\n")]
    headers, rows = _configuration_table(solution)
    parts += [
        "",
        f"## UI configurations ({len(solution.configurations)} and the default)",
        "",
        markdown.table(headers, rows, [True, *[False] * (len(headers) - 2), True]).rstrip("\n"),
    ]
    text = "\n".join(parts) + "\n"
    while "\n\n\n" in text:
        text = text.replace("\n\n\n", "\n\n")
    return text


# ---- writing ---------------------------------------------------------------------------------


def _charts(
    solution: Solution, fmt: str, kinds: Sequence[PlotKind] = _KINDS
) -> dict[PlotKind, bytes]:
    draw = {"radar": radar_figure, "bars": bars_figure, "matrix": matrix_figure}
    return {kind: figure_bytes(draw[kind](solution), fmt) for kind in kinds}


def write_report(
    solution: Solution, path: str | Path, *, within: str | Path | None = None
) -> list[Path]:
    """Write the report to ``path`` (format by extension); returns every file written.
    ``within``: the output folder holding it (:func:`solver.files.atomic.write_all_atomic`).

    HTML is one file. Markdown also writes its two PNG charts beside it (see
    :func:`image_names`); the three are written together or not at all
    (:func:`solver.files.atomic.write_all_atomic`), so no page links a missing image and a failed
    report leaves no charts behind.
    """
    fmt = report_format(path)
    if fmt == "html":
        return [write_atomic(path, render_html(solution), within=within)]
    names = image_names(path)
    charts = _charts(solution, "png")
    links = {kind: names[kind].name for kind in _KINDS}
    files: dict[str | Path, str | bytes] = {names[kind]: charts[kind] for kind in _KINDS}
    files[path] = render_markdown(solution, links)
    return write_all_atomic(files, within=within)
