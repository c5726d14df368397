"""Drive the real Lichtblick as an operator would: import a layout, watch live data, press what
publishes, export the layout, and report what was seen.

usage: python drive.py LAYOUT.json NAME [--app URL] [--ws URL] [--record FILE] [--act]
       [--tabs] [--shots DIR] [--size WIDTHxHEIGHT]

Debian's headless Chromium (never a browser of playwright's own) opens the app connected to a
Foxglove WebSocket server (``wsserver.py``), imports LAYOUT.json through the app's own menu
(View > Import layout from file...; the file picker is answered with the layout), waits for
data, and writes to --shots: NAME.png (the screen), NAME-layouts.png (the layout list: a dot
marks unsaved changes), NAME-variables.png (the Variables sidebar: the layout's global
variables), NAME.exported.json (the app's own Export layout) and NAME.report.json: the
import's error messages, each panel's text, the keys the app added (``export_diff``), the
layouts the list marks as having unsaved changes (``unsaved_changes``: the app's own
"Default" is one; the imported layout must not be), the global variables as the sidebar
shows them, the topics the app advertised once the layout was imported (``advertised``; the
app's own default layout advertises its click-to-publish topics before that:
``advertised_before_import``), and with --act what each Teleop pad (held 1.5 s), Publish
button and 3D click tool sent, decoded by the server. The app mounts a Tab panel's active tab
only; with --tabs, once all that is done (a tab clicked changes the layout), each other tab is
clicked and its panels looked at after three seconds of data, as ``panels`` (each with its
``tab``) and a screenshot NAME-Tab-ID-INDEX.png.
"""

from __future__ import annotations

import argparse
import asyncio
import io
import json
import time
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image
from playwright.async_api import Locator, Page, async_playwright

CHROMIUM = "/usr/bin/chromium"
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
# The app imports through window.showOpenFilePicker: answer it with the layout under test.
PICKER = """
window.showOpenFilePicker = async () => [{
  getFile: async () =>
    new File([window.__layoutText], window.__layoutName, { type: "application/json" }),
}];
"""

# The layouts whose row shows the unsaved-changes dot (LayoutBrowser/LayoutRow.tsx draws it as
# a circle in the row's action button when the layout has a working copy).
UNSAVED = """
() => [...document.querySelectorAll("li")]
  .filter((row) => row.querySelector("[data-testid=layout-actions] circle"))
  .map((row) => row.querySelector("[data-testid=layout-list-item]")?.textContent ?? "")
"""


async def hues(box: Locator) -> int:
    """How many of twelve hues a panel's body shows (toolbar cut off): 0 for a grey panel, 1
    for a 3D grid alone, more for an image, a coloured point cloud or a plot's lines."""
    shot = np.asarray(Image.open(io.BytesIO(await box.screenshot())).convert("HSV"))[30:]
    hue, saturation, value = shot[..., 0], shot[..., 1], shot[..., 2]
    counts = np.bincount(
        hue[(saturation > 80) & (value > 60)].astype(int) * 12 // 256, minlength=12
    )
    return int((counts > 20).sum())


async def panel(page: Page, panel_id: str) -> dict[str, Any]:
    """A panel as the app shows it: there or not, its text, its hues."""
    box = page.get_by_test_id(f"panel-mouseenter-container {panel_id}")
    present = await box.count() > 0
    text = (await box.first.inner_text())[:400] if present else None
    shown = await hues(box.first) if present else 0
    return {"present": present, "text": text, "hues": shown}


async def panels(page: Page, layout: dict[str, Any]) -> dict[str, Any]:
    """Each panel of the layout as the app shows it."""
    return {panel_id: await panel(page, panel_id) for panel_id in layout.get("configById", {})}


def leaves(node: Any) -> list[str]:
    """The panel ids of a split tree (a tab's layout)."""
    if isinstance(node, str):
        return [node]
    if isinstance(node, dict):
        return leaves(node.get("first")) + leaves(node.get("second"))
    return []


async def visit_tabs(page: Page, layout: dict[str, Any], shots: Path, name: str) -> dict[str, Any]:
    """Click each tab a Tab panel does not show on opening, as an operator would, and look at
    its panels after three seconds of data; a screenshot of each (NAME-Tab-ID-INDEX.png)."""
    seen: dict[str, Any] = {}
    for panel_id, config in layout.get("configById", {}).items():
        if not panel_id.startswith("Tab!"):
            continue
        strip = page.get_by_test_id(f"panel-mouseenter-container {panel_id}").first
        for index, tab in enumerate(config.get("tabs", [])):
            if index == config.get("activeTabIdx", 0):
                continue
            # Its own strip comes first in the page: a nested Tab panel's is inside a tab.
            await strip.get_by_test_id("toolbar-tab").nth(index).click()
            await page.wait_for_timeout(3000)
            picture = f"{name}-{panel_id.replace('!', '-')}-{index}.png"
            await page.screenshot(path=str(shots / picture))
            for inner in leaves(tab.get("layout")):
                seen[inner] = {**await panel(page, inner), "tab": tab.get("title"), "shot": picture}
    return seen


def records(path: Path, since: float) -> list[dict[str, Any]]:
    if not path.exists():
        return []
    lines = (json.loads(line) for line in path.read_text(encoding="utf-8").splitlines())
    return [item for item in lines if item["t"] >= since]


def added(before: Any, after: Any, path: str = "") -> list[tuple[str, str, Any]]:
    """What ``after`` adds to, drops from or changes in ``before``, by JSON path."""
    if not (isinstance(before, dict) and isinstance(after, dict)):
        return [] if before == after else [("changed", path, [before, after])]
    out: list[tuple[str, str, Any]] = []
    for key in sorted(set(before) | set(after)):
        where = f"{path}.{key}" if path else key
        if key not in before:
            out.append(("added", where, after[key]))
        elif key not in after:
            out.append(("removed", where, before[key]))
        else:
            out.extend(added(before[key], after[key], where))
    return out


async def menu(page: Page, item: str) -> None:
    await page.get_by_test_id("AppMenuButton").click()
    # By its test id: a 3D panel's settings, once shown, have a "View" section too.
    await page.get_by_test_id("app-menu-view").click()
    await page.get_by_text(item).click()


async def run(args: argparse.Namespace) -> dict[str, Any]:
    shots, record = Path(args.shots), Path(args.record)
    shots.mkdir(parents=True, exist_ok=True)
    text = Path(args.layout).read_text(encoding="utf-8")
    layout = json.loads(text)
    report: dict[str, Any] = {"layout": args.layout}
    async with async_playwright() as playwright:
        browser = await playwright.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        context = await browser.new_context(
            viewport=dict(zip(("width", "height"), args.size, strict=True)),
            accept_downloads=True,
        )
        await context.add_init_script(PICKER)
        page = await context.new_page()
        console: list[tuple[float, str]] = []
        page.on("console", lambda m: console.append((time.time(), f"{m.type}: {m.text[:300]}")))
        started = time.time()
        await page.goto(f"{args.app}?ds=foxglove-websocket&ds.url={args.ws}", wait_until="load")
        await page.wait_for_timeout(4000)
        await page.evaluate(
            "([t, n]) => { window.__layoutText = t; window.__layoutName = n; }",
            [text, f"{args.name}.json"],
        )
        imported = time.time()
        await menu(page, "Import layout from file…")
        await page.wait_for_timeout(args.wait)
        looked = time.time()
        report["snackbars"] = await page.locator("#notistack-snackbar").all_inner_texts()
        await page.screenshot(path=str(shots / f"{args.name}.png"))
        report["panels"] = await panels(page, layout)
        if args.act:
            report["actions"] = await act(page, layout, record)
        async with page.expect_download() as download:
            await menu(page, "Export layout to file…")
        exported = json.loads(Path(await (await download.value).path()).read_text())
        (shots / f"{args.name}.exported.json").write_text(json.dumps(exported, indent=2))
        report["export_diff"] = added(layout, exported)
        await page.get_by_test_id("layouts-left").click()
        await page.wait_for_timeout(800)
        await page.screenshot(path=str(shots / f"{args.name}-layouts.png"))
        report["unsaved_changes"] = await page.evaluate(UNSAVED)
        await page.get_by_test_id("right-sidebar-button").click()
        await page.get_by_test_id("variables-right").click()
        await page.wait_for_timeout(800)
        report["variables"] = await page.get_by_test_id("sidebar-right").inner_text()
        await page.screenshot(path=str(shots / f"{args.name}-variables.png"))
        if args.tabs:  # last: a tab clicked is a change to the layout (its activeTabIdx)
            await page.get_by_test_id("right-sidebar-button").click()
            report["tabs"] = await visit_tabs(page, layout, shots, args.name)
            report["panels"].update(report["tabs"])
        adverts = [r for r in records(record, started) if r["op"] == "advertise"]
        report["advertised_before_import"] = sorted(
            {r["topic"] for r in adverts if r["t"] < imported}
        )
        report["advertised"] = sorted({r["topic"] for r in adverts if r["t"] >= imported})
        report["console"] = [line for _, line in console if line.startswith(("error", "warning"))]
        # What the app still complained of once the data had had 3 s to arrive.
        report["late_console"] = [
            line
            for t, line in console
            if imported + 3 <= t <= looked and line.startswith(("error", "warning"))
        ]
        await browser.close()
    (shots / f"{args.name}.report.json").write_text(json.dumps(report, indent=1, default=str))
    return report


async def act(page: Page, layout: dict[str, Any], record: Path) -> list[dict[str, Any]]:
    """Hold each Teleop pad's up button, press each Publish button, click each 3D goal tool."""
    done: list[dict[str, Any]] = []
    for panel_id, config in layout["configById"].items():
        kind = panel_id.split("!")[0]
        box = page.get_by_test_id(f"panel-mouseenter-container {panel_id}")
        if await box.count() == 0:
            continue
        start = time.time()
        if kind == "Teleop":
            pad = box.locator("svg g[role=button]").first
            if await pad.count() == 0:
                done.append({"panel": panel_id, "pad": False})
                continue
            bounds = await pad.bounding_box()
            assert bounds is not None
            await page.mouse.move(
                bounds["x"] + bounds["width"] / 2, bounds["y"] + bounds["height"] / 3
            )
            await page.mouse.down()
            await page.wait_for_timeout(1500)
            released = time.time()
            await page.mouse.up()
            await page.wait_for_timeout(2000)
            sent = [r for r in records(record, start) if r["op"] == "message"]
            done.append(
                {
                    "panel": panel_id,
                    "while_held": sum(1 for r in sent if r["t"] < released),
                    "after_release": [r["msg"] for r in sent if r["t"] >= released][:3],
                    "topics": sorted({r["topic"] for r in sent}),
                    "first": sent[0]["msg"] if sent else None,
                }
            )
        elif kind == "Publish":
            button = box.get_by_role("button", name=config.get("buttonText") or "Publish")
            enabled = await button.count() > 0 and await button.is_enabled()
            if enabled:
                await button.click()
                await page.wait_for_timeout(1500)
            sent = [(r["topic"], r["msg"]) for r in records(record, start) if r["op"] == "message"]
            done.append({"panel": panel_id, "button_enabled": enabled, "sent": sent[:2]})
        elif kind == "3D" and "publish" in config:
            tool = box.locator("button[title*='ublish'], button[aria-label*='ublish']").first
            if await tool.count() > 0:
                bounds = await box.bounding_box()
                assert bounds is not None
                x, y = bounds["x"] + bounds["width"] / 2, bounds["y"] + bounds["height"] / 2
                await tool.click()
                await page.mouse.click(x, y)
                await page.wait_for_timeout(300)
                await page.mouse.click(x + 40, y)
                await page.wait_for_timeout(1500)
            sent = [(r["topic"], r["msg"]) for r in records(record, start) if r["op"] == "message"]
            done.append({"panel": panel_id, "sent": sent[:2]})
    return done


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("layout")
    parser.add_argument("name")
    parser.add_argument("--app", default="http://127.0.0.1:8765/")
    parser.add_argument("--ws", default="ws://127.0.0.1:8766")
    parser.add_argument("--record", default="record.jsonl")
    parser.add_argument("--shots", default="shots")
    parser.add_argument("--wait", type=int, default=6000, help="ms of live data before looking")
    parser.add_argument(
        "--size",
        type=lambda text: tuple(int(side) for side in text.split("x")),
        default=(1600, 1000),
        help="the window, WIDTHxHEIGHT (1920x1080: the operator's screen of the quality check)",
    )
    parser.add_argument("--act", action="store_true", help="press what publishes")
    parser.add_argument(
        "--tabs",
        action="store_true",
        help="then click each tab a Tab panel does not show on opening and look at its panels",
    )
    report = asyncio.run(run(parser.parse_args()))
    summary = {
        k: report[k]
        for k in (
            "snackbars",
            "unsaved_changes",
            "advertised",
            "export_diff",
            "variables",
            "actions",
        )
        if k in report
    }
    print(json.dumps(summary, indent=1, default=str))


if __name__ == "__main__":
    main()
