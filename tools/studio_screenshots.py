"""Screenshots of every view of the design studio, for docs/studio.md.

    python tools/studio_screenshots.py                       # starts a studio of its own
    python tools/studio_screenshots.py --url http://127.0.0.1:8765/   # a running studio

Without ``--url`` it starts ``teleop-ui studio case3 --fleet examples --port 0`` (loopback), takes
the pictures and stops it. Each view is driven as a person would (the fleet folder identified,
two configurations compared, a robot looked up) in Debian's headless Chromium
(``/usr/bin/chromium``, driven by Playwright's Python package; nothing is downloaded), and
written to ``docs/studio-<view>.png``.

A picture of the selection is taken once the page has settled: its totals, its radar chart and
the check's findings all answer the selection it holds (the page sets ``data-settled`` on its
form to that selection; nothing here waits a fixed time). The live view is taken on a real ROS
master: with Debian's ``roscore`` installed, a second studio follows one started here
(``--master``) with the demo fleet of ``tools/demo_fleet.py`` on it and the drone active; or
the studio given by ``--url``, if it follows a graph.
"""

from __future__ import annotations

import argparse
import re
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

from playwright.sync_api import Page, expect, sync_playwright

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


# True once the selection page shows one selection throughout: totals, chart and findings.
SETTLED = """() => {
  const form = document.querySelector("form[data-selection]");
  return form !== null && form.dataset.settled !== undefined
    && form.dataset.settled === form.dataset.current;
}"""


def settled(page: Page) -> None:
    """Wait until the selection page has settled (its radar chart is drawn into the page as
    SVG before it settles: nothing more to wait for)."""
    page.wait_for_function(SETTLED)


def start(*args: str) -> tuple[subprocess.Popen[str], str]:
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", "studio", *args, "--port", "0"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    assert process.stdout is not None
    found = re.search(r"http://\S+", process.stdout.readline())
    if found is None:
        process.kill()
        raise SystemExit("the studio did not start")
    return process, found.group(0)


def shoot(page: Page, out: Path, name: str, *, full: bool = False) -> None:
    """``docs/studio-NAME.png``; ``full``: the whole page, in a window as tall as the page, so
    that a panel that scrolls on its own in a window (the totals) is shown whole too."""
    path = out / f"studio-{name}.png"
    page.wait_for_load_state()
    size = page.viewport_size
    if full and size is not None:
        tall = page.evaluate("() => document.documentElement.scrollHeight")
        page.set_viewport_size({"width": size["width"], "height": max(size["height"], tall)})
    page.screenshot(path=path, full_page=full)
    if full and size is not None:
        page.set_viewport_size(size)
    print(f"wrote {path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}")


def stop(process: subprocess.Popen[str]) -> None:
    process.send_signal(signal.SIGTERM)
    process.wait(timeout=30)


def findings(page: Page, url: str, out: Path) -> None:
    """The check's findings at their controls: the extended rules, a UAV allowed to walk."""
    base = url.split("?", maxsplit=1)[0]
    page.goto(
        f"{base}?rules=extended&name=Walking+drones&type=UAV&UAV.motion_control=Flight"
        "&UAV.motion_control=Walking&UAV.sensor_type=2D+Camera&UAV.sensor_count.max=5&view=UAV"
    )
    settled(page)
    expect(page.locator("#whatif-section")).to_have_attribute("data-state", "answered")
    expect(page.locator(".control-findings .finding.warning")).not_to_have_count(0)
    shoot(page, out, "findings", full=True)
    page.go_back()
    settled(page)


def views(page: Page, url: str, out: Path) -> None:
    page.goto(url)
    expect(page.locator("#total-robots")).not_to_have_text("0")
    settled(page)
    # One type at a time, and one change, so the page shows what it cost.
    page.get_by_role("navigation", name="Kinematic types shown").get_by_role(
        "link", name="Humanoid"
    ).click()
    page.locator('fieldset[data-key="Humanoid.motion_control"]').get_by_label(
        "Walking", exact=True
    ).uncheck()
    expect(page.locator("#change")).to_contain_text("Last change")
    settled(page)
    # What-if comes once the selection has rested: the picture shows it answered.
    expect(page.locator("#whatif-section")).to_have_attribute("data-state", "answered")
    page.evaluate("window.scrollTo(0, 0)")
    shoot(page, out, "selection", full=True)
    page.get_by_role("button", name="Undo").click()
    expect(page.locator("#change")).to_contain_text("Last change")
    settled(page)
    findings(page, url, out)

    page.get_by_role("link", name="Configurations").click()
    page.get_by_label("First").fill("1")
    page.get_by_label("Second").fill("4")
    page.get_by_role("button", name="Compare").click()
    expect(page.locator("#comparison")).to_be_visible()
    shoot(page, out, "configurations")

    page.locator("#configurations").get_by_role("link", name="2", exact=True).click()
    shoot(page, out, "configuration")

    page.get_by_role("link", name="Robots").click()
    page.get_by_label("Robot Kinematic Type").select_option("UGV")
    page.get_by_label("Robot Motion Control").select_option("Driving")
    page.get_by_label("Sensor Type").select_option("LIDAR")
    page.get_by_label("No. of Sensors").select_option("12")
    page.get_by_role("button", name="Look up").click()
    shoot(page, out, "robots")

    page.get_by_role("link", name="Charts").click()
    expect(page.locator("img[data-chart]").first).to_be_visible()
    for image in page.locator("img[data-chart]").all():
        image.evaluate("(image) => image.decode()")
    shoot(page, out, "charts", full=True)

    page.get_by_role("link", name="Check").click()
    shoot(page, out, "check")

    page.get_by_role("link", name="Fleet", exact=True).click()
    folder = page.get_by_role("button", name=re.compile("^Identify .*examples"))
    if folder.count():
        folder.click()
        expect(page.locator("#robots-title")).to_be_visible()
    shoot(page, out, "fleet")

    page.get_by_role("link", name="Export").click()
    shoot(page, out, "export")

    page.get_by_role("link", name="API", exact=True).first.click()
    expect(page.locator("h1")).to_be_visible()
    shoot(page, out, "api")

    if page.get_by_role("link", name="Live", exact=True).count():
        page.get_by_role("link", name="Live", exact=True).click()
        expect(page.locator("#live-status")).to_contain_text("synced")
        shoot(page, out, "live")


def live(page: Page, out: Path, work: Path) -> None:
    """The live view of a studio following a real roscore, with the demo fleet on it."""
    from tests.live.fleet import put_drone, put_rover
    from tests.live.roscore import Roscore, TestNode, roscore_available

    if not roscore_available():
        print("no roscore (Debian's ros-core): the live view is not taken", file=sys.stderr)
        return
    core = Roscore(work)
    core.start()
    node = TestNode(core.uri)
    process = None
    try:
        process, url = start("case3", "--master", core.uri)
        put_drone(node, "/uav1")
        put_rover(node, "/ugv1")
        node.set_param("/teleop_ui/active_robot", "/uav1")
        page.goto(url)
        page.get_by_role("link", name="Live", exact=True).click()
        expect(page.locator('tr[data-robot="/uav1"]')).to_have_attribute("aria-current", "true")
        expect(page.locator('tr[data-robot="/ugv1"] td.configurations')).not_to_be_empty()
        expect(page.locator("#event-log li")).not_to_have_count(0)
        shoot(page, out, "live")
    finally:
        if process is not None:
            stop(process)
        node.clear()
        node.close()
        core.kill()


def design_views(page: Page, url: str, out: Path, suffix: str = "") -> None:
    """The views of issue 40: the selection's what-if, the configuration map (filtered, several
    compared), the designs folder with a comparison; ``suffix`` names the width (``-phone``)."""
    base = url.split("?", maxsplit=1)[0]
    page.goto(url)
    expect(page.locator("#whatif li")).not_to_have_count(0)
    settled(page)
    page.locator("#whatif-section").scroll_into_view_if_needed()
    shoot(page, out, f"whatif{suffix}")
    page.evaluate("window.scrollTo(0, 0)")
    shoot(page, out, f"selection{suffix}" if suffix else "selection-top")

    page.get_by_role("link", name="Map", exact=True).click()
    page.get_by_label("Only configurations with the component").select_option("sensor_type:audio")
    page.get_by_role("button", name="Filter").click()
    columns = page.locator("#map th[data-configuration]")
    for index in (0, 1):
        columns.nth(index).get_by_role("checkbox").check()
    columns.last.get_by_role("checkbox").check()
    page.get_by_role("button", name="Compare the picked configurations").click()
    expect(page.locator("#map-comparison")).to_be_visible()
    shoot(page, out, f"map{suffix}")

    page.goto(f"{base}designs")
    if page.locator("#designs").count():  # a studio started with --designs
        page.goto(url)
        settled(page)
        page.get_by_role("link", name="Designs", exact=True).click()
        page.get_by_label("Name").fill("Case 3")
        page.get_by_role("button", name="Save design").click()
        page.goto(url)
        settled(page)
        page.locator("#whatif a[data-apply]").first.click()
        expect(page.locator("#total-configurations")).not_to_have_text("102")
        page.get_by_role("link", name="Designs", exact=True).click()
        page.get_by_label("Name").fill("Case 3 smaller")
        page.get_by_role("button", name="Save design").click()
        page.get_by_label("From").select_option("Case 3")
        page.get_by_label("To").select_option("Case 3 smaller")
        page.get_by_role("button", name="Compare designs").click()
        expect(page.locator("#diff-changes")).to_be_visible()
        shoot(page, out, f"designs{suffix}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", help="a running studio (default: start one)")
    parser.add_argument("--out", type=Path, default=ROOT / "docs", help="folder (default: docs)")
    parser.add_argument(
        "--designs-only",
        action="store_true",
        help="only the views of issue 40 (what-if, map, designs), at 1280x800 and 390x844",
    )
    args = parser.parse_args()
    process = None
    url = args.url
    designs = tempfile.TemporaryDirectory(prefix="studio-designs-")
    if url is None:
        process, url = start("case3", "--fleet", str(ROOT / "examples"), "--designs", designs.name)
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path="/usr/bin/chromium", args=CHROMIUM_ARGS
            )
            for width, height, suffix in ((1280, 800, ""), (390, 844, "-phone")):
                for design in Path(designs.name).glob("*.yaml"):
                    design.unlink()
                narrow = browser.new_page(viewport={"width": width, "height": height})
                narrow.set_default_timeout(60_000)
                design_views(narrow, url, args.out, suffix)
                narrow.close()
            if args.designs_only:
                browser.close()
                return 0
            page = browser.new_page(viewport={"width": 1280, "height": 860})
            page.set_default_timeout(60_000)
            views(page, url, args.out)
            if args.url is None:
                with tempfile.TemporaryDirectory(prefix="studio-live-") as work:
                    live(page, args.out, Path(work))
            browser.close()
    finally:
        if process is not None:
            stop(process)
        designs.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
