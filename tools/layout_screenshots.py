"""Screenshots of Lichtblick layouts with a robot's data, for docs/layouts.md.

    python tools/layout_screenshots.py LAYOUT.json [LAYOUT.json ...] --bag BAG -o DIR

Each layout is drawn as the app arranges it (its split tree at the given window size) with
what each panel shows of the recorded robot: an Image panel the last image on its topic, a 3D
panel its point cloud or laser scan from above over the reference grid (coloured as the layout
says), a Plot its series over the recording, a Raw Messages panel its last message, and the
command panels as the operator sees them (a Teleop pad and its topic, a Publish panel's
message and button, an Indicator's label); a Tab panel (a cluster of sensors, or the default
configuration's primary views) its tab strip and its active tab's panels. The panel's toolbar
shows what the app shows there: its title, or a Raw Messages panel's topic path. A panel whose
topic has no message in the bag says so. The page is photographed by Debian's headless
Chromium (``/usr/bin/chromium``) into ``DIR/NAME.png``.

This is a preview of a layout with data, drawn by this tool; it is not Lichtblick (see
tools/lichtblick_check.md for the app itself). A bag to draw from:
``python tools/lichtblick/makebag.py /tmp/robot1 /robot1 --scan`` (the presentation's topics
under a namespace; ``/`` for the root namespace).
"""

from __future__ import annotations

import argparse
import base64
import html
import io
import json
import math
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_typestore

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from solver.layouts.checks.messagepath import Name, Slice, parse_message_path  # noqa: E402

# The most messages kept per topic (a plot's series; images and clouds keep the last).
MAX_MESSAGES = 2000
TURBO = ["#30123b", "#4686fb", "#1ae4b6", "#a2fc3c", "#faba39", "#e4460a", "#7a0403"]
CSS = """
body{margin:0;background:#15151a;font:12px sans-serif;color:#e1e1e4}
.split{display:flex;width:100%;height:100%}
.panel{display:flex;flex-direction:column;min-width:0;min-height:0;border:1px solid #2d2d36;
  box-sizing:border-box;width:100%;height:100%;background:#1f1f26}
.bar{padding:3px 6px;background:#27272f;color:#d0d0d8;white-space:nowrap;overflow:hidden;
  text-overflow:ellipsis;flex:none}
.body{flex:1;min-height:0;display:flex;align-items:center;justify-content:center;
  overflow:hidden;position:relative}
.body img{max-width:100%;max-height:100%;image-rendering:pixelated}
.tabs{display:flex;gap:2px;padding:0}
.tab{padding:3px 8px;color:#9a9aa6;overflow:hidden;text-overflow:ellipsis}
.tab.on{color:#e1e1e4;border-bottom:2px solid #9480ed}
.body svg{width:100%;height:100%}
.note{color:#8a8a96;padding:8px;text-align:center}
pre{margin:0;padding:6px;align-self:stretch;overflow:hidden;color:#c6e3a0;font-size:11px}
.pad{display:grid;grid-template-columns:40px 40px 40px;grid-template-rows:40px 40px 40px;gap:4px}
.pad div{background:#3a3a46;border-radius:4px;display:flex;align-items:center;
  justify-content:center;font-size:18px}
.button{margin:6px;padding:6px 14px;background:#6f3be8;border-radius:4px;color:#fff}
.bulb{width:28px;height:28px;border-radius:50%;margin-right:8px}
"""


def read_bag(bag: Path) -> dict[str, list[Any]]:
    """Topic -> its messages in the bag, decoded (at most :data:`MAX_MESSAGES` each)."""
    found: dict[str, list[Any]] = {}
    store = get_typestore(Stores.ROS2_JAZZY)
    with AnyReader([bag], default_typestore=store) as reader:
        for connection, _stamp, raw in reader.messages():
            kept = found.setdefault(connection.topic, [])
            if len(kept) < MAX_MESSAGES:
                kept.append(reader.deserialize(raw, connection.msgtype))
    return found


def _png(pixels: np.ndarray) -> str:
    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, "PNG")
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode()


def image_tag(message: Any) -> str:
    """An <img> of a sensor_msgs Image (rgb8, bgr8, mono8) or CompressedImage."""
    if hasattr(message, "format"):  # CompressedImage: the bytes are a JPEG or PNG already
        kind = "png" if "png" in message.format else "jpeg"
        data = base64.b64encode(bytes(message.data)).decode()
        return f'<img src="data:image/{kind};base64,{data}">'
    data = np.asarray(message.data, dtype=np.uint8)
    channels = {"rgb8": 3, "bgr8": 3, "mono8": 1}.get(message.encoding)
    if channels is None:
        return f'<div class="note">image encoding {html.escape(message.encoding)} not drawn</div>'
    rows = data.reshape(message.height, message.step)[:, : message.width * channels]
    pixels = rows.reshape(message.height, message.width, channels)
    if message.encoding == "bgr8":
        pixels = pixels[:, :, ::-1]
    return f'<img src="{_png(pixels.squeeze())}" style="width:100%;height:100%;object-fit:contain">'


def _colour(value: float, low: float, high: float) -> str:
    share = 0.0 if high <= low else (value - low) / (high - low)
    return TURBO[min(len(TURBO) - 1, max(0, int(share * len(TURBO))))]


def cloud_points(message: Any, field: str) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) and colour values of a PointCloud2 (float32 fields) or a LaserScan."""
    if hasattr(message, "ranges"):
        ranges = np.asarray(message.ranges, dtype=float)
        angles = message.angle_min + message.angle_increment * np.arange(len(ranges))
        values = np.asarray(message.intensities, dtype=float)
        if field == "range" or len(values) != len(ranges):
            values = ranges
        return np.stack([ranges * np.cos(angles), ranges * np.sin(angles)], 1), values
    offsets = {f.name: f.offset for f in message.fields if f.datatype == 7}  # FLOAT32
    raw = np.asarray(message.data, dtype=np.uint8).tobytes()
    count = message.width * message.height

    def column(name: str) -> np.ndarray:
        return np.ndarray((count,), np.float32, raw, offsets[name], (message.point_step,)).astype(
            float
        )

    xy = np.stack([column("x"), column("y")], 1)
    colour = field if field in offsets else "x"  # the app colours by x without the field
    return xy, column(colour)


def scene(config: dict[str, Any], topics: dict[str, list[Any]]) -> str:
    """A 3D panel from above: the grid layer, then each visible topic's points."""
    size, shapes = 10.0, []
    for layer in config.get("layers", {}).values():
        if layer.get("layerId") == "foxglove.Grid" and layer.get("visible", True):
            size = float(layer.get("size", 10))
            step = size / int(layer.get("divisions", 10))
            lines = np.arange(-size / 2, size / 2 + step / 2, step)
            shapes += [
                f'<line x1="{v:.2f}" y1="{-size / 2}" x2="{v:.2f}" y2="{size / 2}"/>'
                f'<line x1="{-size / 2}" y1="{v:.2f}" x2="{size / 2}" y2="{v:.2f}"/>'
                for v in lines
            ]
    grid = (
        f'<g stroke="{html.escape(_grid_colour(config))}" stroke-width="0.02">{"".join(shapes)}</g>'
    )
    dots, waiting = [], []
    for topic, settings in config.get("topics", {}).items():
        messages = topics.get(topic)
        if not messages:
            waiting.append(topic)
            continue
        last = messages[-1]
        if not (hasattr(last, "ranges") or hasattr(last, "fields")):
            continue  # a goal pose topic: nothing recorded to draw
        xy, values = cloud_points(last, settings.get("colorField", "x"))
        low, high = float(np.nanmin(values)), float(np.nanmax(values))
        dots += [
            f'<circle cx="{x:.2f}" cy="{-y:.2f}" r="0.06" fill="{_colour(v, low, high)}"/>'
            for (x, y), v in zip(xy, values, strict=True)
            if math.isfinite(x) and math.isfinite(y)
        ]
    half = size / 2 + 0.5
    svg = (
        f'<svg viewBox="{-half} {-half} {2 * half} {2 * half}" preserveAspectRatio="xMidYMid meet">'
        f"{grid}{''.join(dots)}</svg>"
    )
    publish = config.get("publish", {})
    if publish.get("type") == "pose":
        svg += _caption(f"click to publish a goal pose on {publish.get('poseTopic', '')}")
    elif waiting:
        svg += _caption(f"no messages on {', '.join(waiting)}")
    return svg


def _caption(text: str) -> str:
    style = "position:absolute;bottom:4px"
    return f'<div class="note" style="{style}">{html.escape(text)}</div>'


def _grid_colour(config: dict[str, Any]) -> str:
    for layer in config.get("layers", {}).values():
        if layer.get("layerId") == "foxglove.Grid":
            return str(layer.get("color", "#248eff"))
    return "#248eff"


def _field(message: Any, path: str) -> float | None:
    """The number at ``path``'s fields in ``message`` (names and single indexes only)."""
    value = message
    for part in parse_message_path(path).parts:
        if isinstance(part, Name):
            value = getattr(value, part.name, None)
        elif isinstance(part, Slice) and isinstance(part.start, int) and part.start == part.end:
            value = value[part.start] if value is not None and len(value) > part.start else None
        else:
            return None
    return float(value) if isinstance(value, (int, float, np.number)) else None


def plot(config: dict[str, Any], topics: dict[str, list[Any]]) -> str:
    series, names = [], []
    for index, path in enumerate(p for p in config.get("paths", []) if p.get("enabled", True)):
        messages = topics.get(parse_message_path(path["value"]).topic, [])
        values = [v for v in (_field(m, path["value"]) for m in messages) if v is not None]
        if values:
            series.append((TURBO[(2 * index + 1) % len(TURBO)], values))
            names.append(path.get("label") or path["value"])  # as the app's legend names it
    if not series:
        return '<div class="note">no messages on the plotted paths</div>'
    low = min(min(v) for _, v in series)
    high = max(max(v) for _, v in series)
    span = (high - low) or 1.0
    lines = "".join(
        f'<polyline fill="none" stroke="{colour}" stroke-width="1.5" points="'
        + " ".join(
            f"{100 * i / max(1, len(v) - 1):.2f},{95 - 90 * (x - low) / span:.2f}"
            for i, x in enumerate(v)
        )
        + '" vector-effect="non-scaling-stroke"/>'
        for colour, v in series
    )
    legend = "".join(
        f'<div><span style="color:{colour}">&#9632;</span> {html.escape(name)}</div>'
        for (colour, _), name in zip(series, names, strict=True)
    )
    return (
        f'<svg viewBox="0 0 100 100" preserveAspectRatio="none">{lines}</svg>'
        f'<div style="position:absolute;top:4px;left:8px">{legend}</div>'
    )


def raw(message: Any, depth: int = 0) -> Iterator[str]:
    """A message as indented ``field: value`` lines (long arrays cut)."""
    for name in getattr(message, "__dataclass_fields__", {}):
        if name.startswith("__"):
            continue
        value = getattr(message, name)
        if hasattr(value, "__dataclass_fields__"):
            yield "  " * depth + f"{name}:"
            yield from raw(value, depth + 1)
            continue
        if isinstance(value, np.ndarray | list):
            items = [str(x) for x in list(value)[:8]]
            value = f"[{', '.join(items)}{', ...' if len(value) > 8 else ''}] ({len(value)} items)"
        yield "  " * depth + f"{name}: {value}"


def panel_body(kind: str, config: dict[str, Any], topics: dict[str, list[Any]]) -> str:
    e = html.escape
    if kind == "Image":
        topic = config.get("imageMode", {}).get("imageTopic", "")
        messages = topics.get(topic)
        return (
            image_tag(messages[-1])
            if messages
            else f'<div class="note">no messages on {e(topic)}</div>'
        )
    if kind == "3D":
        return scene(config, topics)
    if kind == "Plot":
        return plot(config, topics)
    if kind == "RawMessages":
        topic = config.get("topicPath", "")
        messages = topics.get(parse_message_path(topic).topic) if topic else None
        if not messages:
            return f'<div class="note">no messages on {e(topic)}</div>'
        return f"<pre>{e(chr(10).join(raw(messages[-1])))}</pre>"
    if kind == "Teleop":
        arrows = ["", "&#9650;", "", "&#9664;", "", "&#9654;", "", "&#9660;", ""]
        pad = "".join(f"<div>{a}</div>" if a else "<span></span>" for a in arrows)
        return (
            f'<div style="text-align:center"><div class="pad">{pad}</div>'
            f'<div class="note">Twist on {e(config.get("topic", ""))} while held; '
            "nothing on release</div></div>"
        )
    if kind == "Publish":
        return (
            f'<div style="display:flex;flex-direction:column;align-self:stretch;width:100%">'
            f"<pre>{e(config.get('value', '{}'))}</pre>"
            '<div style="text-align:right"><span class="button">'
            f"{e(config.get('buttonText', 'Publish'))}</span></div></div>"
        )
    if kind == "Indicator":
        colour = e(config.get("fallbackColor", "#a0a0a0"))
        label = e(config.get("fallbackLabel", ""))
        bulb = f'<div class="bulb" style="background:{colour}"></div>'
        # The app's label breaks only at its own newlines (Indicator.style.ts whiteSpace pre).
        return (
            f'<div style="display:flex;align-items:center;padding:8px">{bulb}'
            f'<span style="white-space:pre">{label}</span></div>'
        )
    return f'<div class="note">{e(kind)} panel</div>'


def toolbar(kind: str, config: dict[str, Any]) -> str:
    """What the app shows above a panel: its title, or a Raw Messages panel's topic path."""
    if kind == "RawMessages":
        return str(config.get("topicPath", ""))
    return str(config.get("lichtblickPanelTitle") or config.get("foxglovePanelTitle") or kind)


def page(layout: dict[str, Any], topics: dict[str, list[Any]], width: int, height: int) -> str:
    configs = layout["configById"]

    def node(tree: Any) -> str:
        if isinstance(tree, str):
            kind = tree.partition("!")[0]
            config = configs.get(tree, {})
            if kind == "Tab":
                return tabs(config)
            return (
                f'<div class="panel"><div class="bar">{html.escape(toolbar(kind, config))}</div>'
                f'<div class="body">{panel_body(kind, config, topics)}</div></div>'
            )
        share = float(tree.get("splitPercentage", 50))
        row = tree.get("direction") == "row"
        size = "width" if row else "height"
        other = "height" if row else "width"
        first = f"{size}:{share}%;{other}:100%;display:flex"
        second = f"{size}:{100 - share}%;{other}:100%;display:flex"
        return (
            f'<div class="split" style="flex-direction:{"row" if row else "column"}">'
            f'<div style="{first}">{node(tree["first"])}</div>'
            f'<div style="{second}">{node(tree["second"])}</div></div>'
        )

    def tabs(config: dict[str, Any]) -> str:
        # A Tab panel (a cluster of sensors): its tab strip, the active tab's panels below it
        # (the app mounts the active tab only).
        entries = config.get("tabs", [])
        active = int(config.get("activeTabIdx", 0))
        strip = "".join(
            f'<span class="tab{" on" if index == active else ""}">'
            f"{html.escape(str(entry.get('title', '')))}</span>"
            for index, entry in enumerate(entries)
        )
        inner = entries[active].get("layout") if 0 <= active < len(entries) else None
        shown = node(inner) if inner is not None else ""
        return (
            f'<div class="panel"><div class="bar tabs">{strip}</div>'
            f'<div class="body" style="align-items:stretch">{shown}</div></div>'
        )

    body = node(layout["layout"]) if layout.get("layout") else ""
    return (
        f'<!DOCTYPE html><html><head><meta charset="utf-8"><style>{CSS}'
        f"html,body{{width:{width}px;height:{height}px}}</style></head><body>{body}</body></html>"
    )


def screenshot(html_page: str, out: Path, width: int, height: int) -> None:
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("needs Debian's chromium (apt-get install chromium)")
    with tempfile.TemporaryDirectory() as scratch:
        source = Path(scratch) / "page.html"
        source.write_text(html_page, encoding="utf-8")
        subprocess.run(
            [
                chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--hide-scrollbars", f"--user-data-dir={scratch}/profile",
                f"--screenshot={out}", f"--window-size={width},{height}", source.as_uri(),
            ],
            check=True,
            capture_output=True,
            timeout=120,
        )  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("layouts", nargs="+", type=Path, help="Lichtblick layout JSON files")
    parser.add_argument("--bag", type=Path, help="a bag of the robot's topics to draw")
    parser.add_argument("-o", "--output", type=Path, required=True, help="folder for NAME.png")
    parser.add_argument("--size", default="1280x720", help="window size, WIDTHxHEIGHT")
    args = parser.parse_args(argv)
    width, height = (int(n) for n in args.size.split("x"))
    topics = read_bag(args.bag) if args.bag else {}
    args.output.mkdir(parents=True, exist_ok=True)
    for path in args.layouts:
        layout = json.loads(path.read_text(encoding="utf-8"))
        out = args.output / f"{path.stem}.png"
        screenshot(page(layout, topics, width, height), out, width, height)
        print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
