"""Measure, in the real Lichtblick, how fast the follower extension puts a switch on screen:
from the watcher's answer to the new tab's panels drawn (issue 38; goal: within 300 ms).

usage: python follow.py TEAM.json FOXE [--app URL] [--via url|topic] [--rounds N]
       [--ws-port P] [--sse-port P] [--shots DIR]

TEAM.json is a team layout as ``teleop-ui watch --layouts DIR`` writes it (``DIR/team.json``),
FOXE the follower extension (``viewer/lichtblick/teleop-ui-follower.foxe``). The tool stands in
for the robots and the watcher, in one process:

- a Foxglove WebSocket server (as foxglove_bridge is) on ``--ws-port``, announcing ROS 2, that
  plays live data for the layout's topics at 10 Hz (an image on every Image panel's topic, a
  LaserScan on 3D topics ending in ``scan``, a PointCloud2 on those ending in ``points``,
  ``/tf``; drawn by ``makebag.py``'s functions) and carries the answer topic
  ``/teleop_ui/ui_configuration`` (``std_msgs/msg/String``, the current answer sent to a new
  subscriber at once, as a transient-local topic reaches a late reader);
- an event stream of answers on ``--sse-port`` (``GET /answer/events``, one ``data:`` line per
  answer, the current one first, ``Access-Control-Allow-Origin`` for the app's origin only), the
  shape of ``teleop-ui watch --serve``'s.

Each answer goes out on both, as the watcher's does. With ``--via url`` (the default) the
layout's ``answerUrl`` is set to the event stream and ``answerTopic`` kept: the follower hears
each answer twice and acts on the first (the second is ``repeated``); with ``--via topic``
``answerUrl`` is null and the follower reads the topic only. Debian's headless
Chromium (never a browser of Playwright's own) opens the app on the WebSocket server, installs
FOXE and imports the layout through the app's hidden file input (``[data-puppeteer-file-upload]``,
as Lichtblick's own end-to-end tests do), then switches ``--rounds`` times through every tab,
one answer a second, and for each answer reads:

- ``sent``: when the tool sent it (this machine's clock);
- ``received``, ``applied``: when the follower got it and when the app took the Tab panel's new
  state (``window.__teleopUi.timings``, the page's ``performance.now()``);
- ``screen``: the first animation frame in which every panel of the new tab is in the page
  (``[data-testid="panel-mouseenter-container ID"]``), measured in the page.

Then it shows what the follower says of answers it cannot show: a robot that joined after the
layout was imported (``follow-joined.png``), a mode the robot does not offer
(``follow-not-offered.png``), a null answer (``follow-null.png``), a robot name holding a line
break and a right-to-left override (``follow-hostile.png``); the layout list after a switch
(``follow-layouts.png``: the unsaved-changes dot); and, in a layout where the follower is no
longer beside the Tab panel, what it says and what the app does (``follow-not-beside.png``).
It writes to ``--shots`` those, ``follow-N-ROBOT-CONFIG.png`` (each tab once, 1.5 s after its
switch, with data), and ``follow.report.json``: every switch's times, the console's errors and
warnings, and the medians, 95th percentiles and maxima printed at the end, overall and per tab.
Serve the app first (``serve.py BUILD_DIR 8080``).
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import logging
import re
import statistics
import time
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import makebag
from foxglove_websocket.server import FoxgloveServer, FoxgloveServerListener
from playwright.async_api import Page, async_playwright

CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-sync"]
ANSWER_TOPIC = "/teleop_ui/ui_configuration"
FOLLOWER = "teleop-ui.follower!follower"
TABS = "Tab!robots"
STORE = makebag.STORE
STRING = "std_msgs/msg/String"

# In the page: resolves with the page's clock (ms since the epoch) at the first animation
# frame in which every one of `ids` is drawn and none of `gone` (the tab before) is.
WAIT_FOR_PANELS = """
([ids, gone]) => new Promise((resolve) => {
  const selector = (id) => `[data-testid="panel-mouseenter-container ${id}"]`;
  const look = () => {
    if (
      ids.every((id) => document.querySelector(selector(id)) !== null) &&
      gone.every((id) => document.querySelector(selector(id)) === null)
    ) {
      resolve(performance.timeOrigin + performance.now());
    } else {
      requestAnimationFrame(look);
    }
  };
  requestAnimationFrame(look);
})
"""
# In the page: whether the panel `id` shows another text than `before`.
CHANGED = """
([id, before]) =>
  document.querySelector(`[data-testid="panel-mouseenter-container ${id}"]`)?.innerText !== before
"""
# The layouts whose row shows the unsaved-changes dot (as drive.py reads them).
UNSAVED = """
() => [...document.querySelectorAll("li")]
  .filter((row) => row.querySelector("[data-testid=layout-actions] circle"))
  .map((row) => row.querySelector("[data-testid=layout-list-item]")?.textContent ?? "")
"""
TIMINGS = (
    "() => (window.__teleopUi?.timings ?? []).map((t) => ({...t, origin: performance.timeOrigin}))"
)


def leaves(node: Any) -> list[str]:
    """The panel ids of a mosaic tree."""
    if isinstance(node, str):
        return [node]
    if isinstance(node, dict):
        return leaves(node.get("first")) + leaves(node.get("second"))
    return []


def values_of(title: str) -> list[str]:
    """``/uav1: 1 (UAV, Flight, 2D Camera, 1)`` -> the combination's values."""
    found = re.search(r"\(([^()]*)\)$", title)
    return found.group(1).split(", ") if found else []


def topics_of(team: dict[str, Any]) -> dict[str, str]:
    """The topics to play, each with its message type, from the layout's panels."""
    topics = {"/tf": "tf2_msgs/msg/TFMessage"}
    for panel_id, config in team["configById"].items():
        kind = panel_id.partition("!")[0]
        if kind == "Image" and config.get("imageMode", {}).get("imageTopic"):
            topics[config["imageMode"]["imageTopic"]] = "sensor_msgs/msg/Image"
        if kind == "3D":
            for topic in config.get("topics", {}):
                if topic.endswith("scan"):
                    topics[topic] = "sensor_msgs/msg/LaserScan"
                elif topic.endswith("points"):
                    topics[topic] = "sensor_msgs/msg/PointCloud2"
    return topics


def sample(kind: str, stamp: int, k: int) -> Any:
    if kind == "sensor_msgs/msg/Image":
        return makebag.image(stamp, 5 * k)
    if kind == "sensor_msgs/msg/LaserScan":
        return makebag.scan(stamp, k)
    if kind == "sensor_msgs/msg/PointCloud2":
        return makebag.cloud(stamp, k)
    return makebag.transforms(stamp)


class Answers(FoxgloveServerListener):
    """The current answer, on the answer topic and on every open event stream."""

    def __init__(self, origin: str) -> None:
        self.text = "null"
        self.origin = origin
        self.streams: set[asyncio.StreamWriter] = set()
        self.server: FoxgloveServer | None = None
        self.channel = -1

    def cdr(self) -> bytes:
        return bytes(STORE.serialize_cdr(STORE.types[STRING](data=self.text), STRING))

    async def on_subscribe(self, server: FoxgloveServer, channel_id: Any) -> None:
        if channel_id == self.channel:  # a new reader gets the current answer at once
            await server.send_message(channel_id, time.time_ns(), self.cdr())

    async def publish(self, text: str) -> float:
        """Sends ``text`` as the new answer; when it was sent (ms since the epoch)."""
        self.text = text
        sent = time.time() * 1000
        if self.server is not None:
            await self.server.send_message(self.channel, time.time_ns(), self.cdr())
        event = f"data: {text}\n\n".encode()
        for stream in list(self.streams):
            stream.write(event)
            with contextlib.suppress(ConnectionError):
                await stream.drain()
        return sent

    async def serve_stream(
        self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter
    ) -> None:
        """``GET /answer/events`` as ``watch --serve`` answers it; anything else 404."""
        try:
            head = (await asyncio.wait_for(reader.readuntil(b"\r\n\r\n"), 10)).decode("latin-1")
        except (asyncio.IncompleteReadError, asyncio.LimitOverrunError, TimeoutError):
            writer.close()
            return
        origin = re.search(r"(?im)^origin:\s*(\S+)", head)
        allowed = origin is not None and origin.group(1) == self.origin
        if not head.startswith("GET /answer/events ") or (origin is not None and not allowed):
            writer.write(
                b"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"
            )
            writer.close()
            return
        cors = f"Access-Control-Allow-Origin: {self.origin}\r\nVary: Origin\r\n" if allowed else ""
        writer.write(
            "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\n"
            f"{cors}\r\ndata: {self.text}\n\n".encode()
        )
        self.streams.add(writer)
        try:
            await reader.read()  # until the page goes
        finally:
            self.streams.discard(writer)
            writer.close()


async def play(server: FoxgloveServer, topics: dict[str, str]) -> None:
    """Live data on every topic at 10 Hz."""
    ids = {}
    for topic, kind in topics.items():
        ids[topic] = await server.add_channel(
            {
                "topic": topic,
                "encoding": "cdr",
                "schemaName": kind,
                "schema": STORE.generate_msgdef(kind)[0],
                "schemaEncoding": "ros2msg",
            }
        )
    k = 0
    while True:
        stamp = time.time_ns()
        for topic, kind in topics.items():
            data = STORE.serialize_cdr(sample(kind, stamp, k), kind)
            await server.send_message(ids[topic], stamp, bytes(data))
        k += 1
        await asyncio.sleep(0.1)


def layout_for(team: dict[str, Any], via: str, sse_port: int) -> dict[str, Any]:
    """The team layout with the follower reading this tool's answers."""
    follower = dict(team["configById"][FOLLOWER])
    follower["answerUrl"] = f"http://127.0.0.1:{sse_port}/answer/events" if via == "url" else None
    follower["answerTopic"] = ANSWER_TOPIC
    return {**team, "configById": {**team["configById"], FOLLOWER: follower}}


async def open_app(page: Page, args: argparse.Namespace, layout_file: Path) -> None:
    await page.goto(f"{args.app}?ds=foxglove-websocket&ds.url=ws://127.0.0.1:{args.ws_port}")
    upload = page.locator("[data-puppeteer-file-upload]")
    await upload.wait_for(state="attached", timeout=60_000)
    await upload.set_input_files(str(args.foxe))
    await page.get_by_text("Successfully installed all 1 extensions.").wait_for(timeout=60_000)
    await upload.set_input_files(str(layout_file))
    screen = page.locator(
        f'[data-testid="panel-mouseenter-container {FOLLOWER}"] [data-teleop-ui=screen]'
    )
    await screen.wait_for(timeout=60_000)


async def switch(
    page: Page, answers: Answers, text: str, ids: list[str], gone: list[str]
) -> dict[str, Any]:
    """One answer, and when its tab's panels were on screen (and the tab before gone)."""
    before = len(await page.evaluate(TIMINGS))
    waiting = asyncio.ensure_future(page.evaluate(WAIT_FOR_PANELS, [ids, gone]))
    await asyncio.sleep(0.05)  # the page's frame loop has started looking
    sent = await answers.publish(text)
    screen = await asyncio.wait_for(waiting, 30)
    timings = (await page.evaluate(TIMINGS))[before:]
    acted = next((t for t in timings if t["outcome"] != "repeated"), None)
    if acted is None:
        return {"sent": sent, "screen": screen, "timings": timings}
    origin = acted["origin"]
    return {
        "outcome": acted["outcome"],
        "source": acted["source"],
        "sent_to_received": origin + acted["received"] - sent,
        "received_to_applied": acted["applied"] - acted["received"],
        "received_to_screen": screen - origin - acted["received"],
        "sent_to_screen": screen - sent,
    }


def summary(rows: list[dict[str, Any]], key: str) -> str:
    values = sorted(row[key] for row in rows if key in row)
    if not values:
        return f"{key}: none"
    p95 = values[min(len(values) - 1, round(0.95 * (len(values) - 1)))]
    return (
        f"{key}: {len(values)} switches: median {statistics.median(values):.1f} ms, "
        f"95th percentile {p95:.1f} ms, max {values[-1]:.1f} ms"
    )


def by_tab(rows: list[dict[str, Any]], team: dict[str, Any]) -> list[str]:
    """received_to_screen per tab, with the kinds of panel the tab mounts (a 3D panel's
    renderer is the slow part)."""
    tabs = team["configById"][TABS]["tabs"]
    lines = []
    for tab in sorted({row["tab"] for row in rows}):
        kinds = ", ".join(i.partition("!")[0] for i in leaves(tabs[tab].get("layout")))
        mine = [row for row in rows if row["tab"] == tab]
        lines.append(
            f"  tab {tab + 1} ({mine[0]['robot']}: {kinds}) {summary(mine, 'received_to_screen')}"
        )
    return lines


async def extras(
    page: Page, answers: Answers, team: dict[str, Any], args: argparse.Namespace, shots: Path
) -> dict[str, str]:
    """What the follower says of answers it cannot show."""
    said: dict[str, str] = {}
    follower = page.locator(f'[data-testid="panel-mouseenter-container {FOLLOWER}"]')
    mapping = team["configById"][FOLLOWER]["tabs"]
    robot = mapping[0]["robot"]
    own = args.team.parent / robot.strip("/") / "config-999.json"
    cases = {
        # A robot that joined after the import: the watcher's team layout has a tab for it.
        "joined": {
            "robot": "/uav9",
            "configuration": 7,
            "layouts": {"team": {"path": str(args.team), "tab": len(mapping)}},
        },
        # A mode the robot does not offer: no team layout has a tab for it (the watcher's
        # answer then names no tab), only the robot's own layout of that configuration.
        "not-offered": {
            "robot": robot,
            "configuration": 999,
            "notes": [f"{robot} does not offer motion_control 'Waypoint'; using it as asked"],
            "layouts": {"foxglove": {"path": str(own)}, "team": {"path": str(args.team)}},
        },
        "null": None,
        "hostile": {"robot": "/uav1\nERROR: forged\u202etxt.exe", "configuration": 999},
    }
    for name, answer in cases.items():
        before = await follower.inner_text()
        await answers.publish(json.dumps(answer))
        await page.wait_for_function(CHANGED, arg=[FOLLOWER, before])
        said[name] = await follower.inner_text()
        await page.screenshot(path=str(shots / f"follow-{name}.png"))
    return said


async def not_beside(page: Page, answers: Answers, team: dict[str, Any], shots: Path) -> str:
    """The follower moved away from the Tab panel (another panel beside it): what it says, and
    what the app does with its switch (opens a new Tab panel beside it: addPanel's other path)."""
    layout = dict(team)
    layout["configById"] = {**team["configById"], "SourceInfo!moved": {}}
    layout["layout"] = {
        "direction": "row",
        "first": {"direction": "column", "first": FOLLOWER, "second": "SourceInfo!moved"},
        "second": TABS,
        "splitPercentage": 30,
    }
    moved = shots / "team-moved.json"
    moved.write_text(json.dumps(layout, indent=1))
    await answers.publish("null")
    await page.locator("[data-puppeteer-file-upload]").set_input_files(str(moved))
    await page.get_by_text("Waiting for the watcher's answer").wait_for(timeout=60_000)
    entry = team["configById"][FOLLOWER]["tabs"][-1]
    await answers.publish(
        json.dumps({"robot": entry["robot"], "configuration": entry["configuration"]})
    )
    warning = page.locator("[data-teleop-ui=warning]", has_text="not beside")
    await warning.wait_for(timeout=10_000)
    await page.wait_for_timeout(1000)
    await page.screenshot(path=str(shots / "follow-not-beside.png"))
    return await warning.inner_text()


def answer_for(entry: dict[str, Any], title: str, team: Path) -> str:
    """The watcher's answer for one tab of the team layout (the fields the follower reads)."""
    return json.dumps(
        {
            "robot": entry["robot"],
            "configuration": entry["configuration"],
            "default": False,
            "combination": dict(enumerate(values_of(title))),
            "layouts": {"team": {"path": str(team), "tab": entry["tab"]}},
            "watcher": "/teleop_ui_follow_check",
        }
    )


async def rounds(
    page: Page, answers: Answers, team: dict[str, Any], args: argparse.Namespace, shots: Path
) -> list[dict[str, Any]]:
    """Every tab in turn, ``--rounds`` times, starting with the second (the first is on screen
    after the import); a screenshot of each tab once, 1.5 s after its switch."""
    tabs = team["configById"][TABS]["tabs"]
    mapping = team["configById"][FOLLOWER]["tabs"]
    order = mapping[1:] + mapping[:1]
    rows: list[dict[str, Any]] = []
    shown_tabs: set[int] = set()
    previous = mapping[0]
    for round_ in range(args.rounds):
        for entry in order:
            ids = leaves(tabs[entry["tab"]].get("layout"))
            gone = [i for i in leaves(tabs[previous["tab"]].get("layout")) if i not in ids]
            row = await switch(
                page, answers, answer_for(entry, tabs[entry["tab"]]["title"], args.team), ids, gone
            )
            row.update(
                round=round_,
                robot=entry["robot"],
                configuration=entry["configuration"],
                tab=entry["tab"],
            )
            rows.append(row)
            previous = entry
            await page.wait_for_timeout(1000)  # an operator's pace; data flows into the new tab
            if entry["tab"] not in shown_tabs:
                shown_tabs.add(entry["tab"])
                robot = entry["robot"].strip("/").replace("/", "_")
                name = f"follow-{len(shown_tabs)}-{robot}-{entry['configuration']}.png"
                await page.wait_for_timeout(500)
                await page.screenshot(path=str(shots / name))
    return rows


async def unsaved(page: Page, shots: Path) -> list[str]:
    """The layouts the app marks as having unsaved changes (a switch rewrites the Tab panel)."""
    await page.locator("[data-tourid=left-sidebar-button]").click()
    await page.get_by_test_id("layouts-left").click()
    await page.wait_for_timeout(800)
    await page.screenshot(path=str(shots / "follow-layouts.png"))
    marked: list[str] = await page.evaluate(UNSAVED)
    await page.locator("[data-tourid=left-sidebar-button]").click()
    return marked


async def drive(
    server: FoxgloveServer,
    answers: Answers,
    team: dict[str, Any],
    args: argparse.Namespace,
    shots: Path,
) -> dict[str, Any]:
    layout_file = shots / f"team-{args.via}.json"
    layout_file.write_text(json.dumps(layout_for(team, args.via, args.sse_port), indent=1))
    player = asyncio.ensure_future(play(server, topics_of(team)))
    report: dict[str, Any] = {"team": str(args.team), "via": args.via}
    async with async_playwright() as playwright:
        browser = await playwright.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = await browser.new_page(viewport={"width": 1600, "height": 900})
        console: list[str] = []
        page.on("console", lambda m: console.append(f"{m.type}: {m.text[:300]}"))
        await open_app(page, args, layout_file)
        await page.locator("[data-tourid=left-sidebar-button]").click()  # room for the panels
        await page.wait_for_timeout(2000)
        await page.screenshot(path=str(shots / "follow-start.png"))
        report["switches"] = await rounds(page, answers, team, args, shots)
        # Away from the tab the layout was saved with: does the app mark the layout changed?
        last = team["configById"][FOLLOWER]["tabs"][-1]
        tabs = team["configById"][TABS]["tabs"]
        await switch(
            page,
            answers,
            answer_for(last, tabs[last["tab"]]["title"], args.team),
            leaves(tabs[last["tab"]].get("layout")),
            [],
        )
        report["unsaved_changes"] = await unsaved(page, shots)
        report["said"] = await extras(page, answers, team, args, shots)
        report["not_beside"] = await not_beside(page, answers, team, shots)
        report["console"] = [line for line in console if line.startswith(("error", "warning"))]
        await browser.close()
    player.cancel()
    return report


async def run(args: argparse.Namespace) -> dict[str, Any]:
    team = json.loads(args.team.read_text(encoding="utf-8"))
    shots = Path(args.shots)
    shots.mkdir(parents=True, exist_ok=True)
    app = urlsplit(args.app)
    answers = Answers(f"{app.scheme}://{app.netloc}")
    stream_server = await asyncio.start_server(answers.serve_stream, "127.0.0.1", args.sse_port)
    quiet = logging.getLogger("follow.foxglove")
    quiet.setLevel(logging.WARNING)
    async with FoxgloveServer(
        "127.0.0.1",
        args.ws_port,
        "teleop-ui follow check",
        capabilities=["clientPublish"],
        supported_encodings=["cdr"],
        metadata={"ROS_DISTRO": "jazzy"},
        logger=quiet,
    ) as server:
        answers.server = server
        server.set_listener(answers)
        answers.channel = await server.add_channel(
            {
                "topic": ANSWER_TOPIC,
                "encoding": "cdr",
                "schemaName": STRING,
                "schema": "string data",
                "schemaEncoding": "ros2msg",
            }
        )
        report = await drive(server, answers, team, args, shots)
    stream_server.close()
    rows = report["switches"]
    keys = ("received_to_screen", "sent_to_screen", "received_to_applied", "sent_to_received")
    report["summary"] = [summary(rows, key) for key in keys] + by_tab(rows, team)
    (shots / "follow.report.json").write_text(json.dumps(report, indent=1, default=str))
    return report


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument(
        "team", type=Path, help="a team layout (watch --layouts DIR: DIR/team.json)"
    )
    parser.add_argument("foxe", type=Path, help="the follower extension (.foxe)")
    parser.add_argument(
        "--app", default="http://127.0.0.1:8080/", help="where serve.py serves the app"
    )
    parser.add_argument("--via", choices=["url", "topic"], default="url")
    parser.add_argument("--rounds", type=int, default=4, help="times through every tab")
    parser.add_argument("--ws-port", type=int, default=8766)
    parser.add_argument("--sse-port", type=int, default=8770)
    parser.add_argument("--shots", default="shots")
    report = asyncio.run(run(parser.parse_args()))
    print("\n".join(report["summary"]))
    print(json.dumps({k: report[k] for k in ("said", "not_beside", "unsaved_changes")}, indent=1))


if __name__ == "__main__":
    main()
