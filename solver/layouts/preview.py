"""A layout's panel tree as an SVG thumbnail, and a page of them (one per configuration).

What an operator will see, at a glance: each split divides its rectangle by its percentage;
each panel is a rectangle coloured by panel type and labelled with its title; a Tab panel (a
cluster of sensors, :mod:`solver.layouts.design`) is one rectangle naming its tabs. Not here:
rendering the panels' content.
"""

from __future__ import annotations

import html
from typing import Any

from solver.untrusted import shown

__all__ = ["preview_html", "preview_svg"]


def escape(text: str) -> str:
    """``text`` as XML text: markup escaped, and every control or invisible format character
    shown as its escape (an XML 1.0 document may hold no C0 control at all)."""
    return html.escape(shown(text, limit=None))


COLOURS = {
    "3D": "#4c72b0",
    "Image": "#55a868",
    "Indicator": "#8172b2",
    "Plot": "#c44e52",
    "Publish": "#ccb974",
    "RawMessages": "#8c8c8c",
    "Teleop": "#dd8452",
}


def preview_svg(layout: dict[str, Any], width: int = 320, height: int = 200) -> str:
    """The panel tree of a Foxglove layout as an SVG of ``width`` x ``height``."""
    shapes: list[str] = []

    def draw(node: Any, x: float, y: float, w: float, h: float) -> None:
        if isinstance(node, str):
            kind, title = _label(layout["configById"], node)
            shapes.append(
                f'<rect x="{x:.1f}" y="{y:.1f}" width="{w:.1f}" height="{h:.1f}" '
                f'fill="{COLOURS.get(kind, "#8c8c8c")}" stroke="#ffffff" stroke-width="2"/>'
                f'<text x="{x + 4:.1f}" y="{y + 14:.1f}" font-size="10" fill="#ffffff">'
                f"{escape(kind)}: {escape(title)}</text>"
            )
            return
        share = float(node.get("splitPercentage", 50)) / 100
        if node.get("direction") == "row":
            draw(node["first"], x, y, w * share, h)
            draw(node["second"], x + w * share, y, w * (1 - share), h)
        else:
            draw(node["first"], x, y, w, h * share)
            draw(node["second"], x, y + h * share, w, h * (1 - share))

    if layout.get("layout") is not None:
        draw(layout["layout"], 0, 0, width, height)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}">' + "".join(shapes) + "</svg>"
    )


def _label(configs: dict[str, Any], panel_id: str) -> tuple[str, str]:
    """The panel's type and what the app shows of it: its title, a Raw Messages panel's topic
    path; for a Tab panel (a cluster of sensors), its first tab's panel type and the tabs'
    titles."""
    kind = panel_id.partition("!")[0]
    config = configs.get(panel_id, {})
    if kind == "Tab":
        tabs = [tab for tab in config.get("tabs", []) if isinstance(tab, dict)]
        first = tabs[0].get("layout") if tabs else None
        inner = first.partition("!")[0] if isinstance(first, str) else kind
        return inner, "tabs " + " | ".join(str(tab.get("title", "")) for tab in tabs)
    return kind, str(config.get("foxglovePanelTitle", config.get("topicPath", kind)))


def preview_html(layouts: list[tuple[str, dict[str, Any]]]) -> str:
    """A self-contained page: one captioned thumbnail per (name, layout)."""
    figures = "".join(
        f"<figure>{preview_svg(layout)}<figcaption>{escape(name)}</figcaption></figure>"
        for name, layout in layouts
    )
    return (
        '<!DOCTYPE html><html><head><meta charset="utf-8"><title>layouts</title>'
        "<style>body{margin:8px;font-family:sans-serif}figure{display:inline-block;"
        "margin:4px}</style></head><body>" + figures + "</body></html>\n"
    )
