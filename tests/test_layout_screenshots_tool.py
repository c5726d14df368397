"""tools/layout_screenshots.py photographs a layout with a robot's recorded data in Chromium."""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import ROOT, run_cli

TOOLS = ROOT / "tools"


def _tool(*args: str | Path) -> str:
    environment = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run(
        [sys.executable, *map(str, args)],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=True,
    )
    return done.stdout


@pytest.fixture(scope="module")
def robot1(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """The case3 default layout under /robot1, and a bag of the presentation's topics there."""
    folder = tmp_path_factory.mktemp("shots")
    bag = folder / "bag"
    _tool(TOOLS / "lichtblick" / "makebag.py", bag, "/robot1")
    assert (
        run_cli("layouts", "case3", "-o", folder / "layouts", "--namespace", "/robot1").returncode
        == 0
    )
    return folder / "layouts" / "config-103-default.json", bag


def _colours(png: Path) -> int:
    from PIL import Image

    image = Image.open(png).convert("RGB")
    assert image.size == (1280, 720)
    colours = image.getcolors(maxcolors=1 << 24)
    assert colours is not None
    return len(colours)


def test_a_layout_is_photographed_with_its_robots_images_clouds_and_plots(
    robot1: tuple[Path, Path], tmp_path: Path
) -> None:
    layout, bag = robot1
    said = _tool(TOOLS / "layout_screenshots.py", layout, "--bag", bag, "-o", tmp_path / "with")
    assert said == f"{tmp_path / 'with' / 'config-103-default.png'}\n"
    _tool(TOOLS / "layout_screenshots.py", layout, "-o", tmp_path / "without")
    # Images, a coloured point cloud and plotted curves paint thousands of colours that panels
    # waiting for data (flat backgrounds, text, the grid) do not.
    with_data = _colours(tmp_path / "with" / "config-103-default.png")
    without = _colours(tmp_path / "without" / "config-103-default.png")
    assert with_data > 10_000
    assert without < 5_000


def test_each_panel_shows_its_topics_data_or_says_there_is_none(robot1: tuple[Path, Path]) -> None:
    spec = importlib.util.spec_from_file_location(
        "layout_screenshots", TOOLS / "layout_screenshots.py"
    )
    assert spec is not None
    assert spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    layout_file, bag = robot1
    layout = json.loads(layout_file.read_text())
    topics = tool.read_bag(bag)
    # The primary views are the tabs of one Tab panel; it opens on the camera's tab.
    page = tool.page(layout, topics, 1280, 720)
    assert page.count("data:image/png;base64,") == 1  # the visual display; the 360 is a tab
    assert "click to publish a goal pose on /robot1/goal_pose" in page
    assert "Twist on /robot1/cmd_vel while held; nothing on release" in page
    assert "(32 items)" not in page  # the raw audio is in a tab not shown
    # The operator picks the audio tab: its Raw Messages panel shows the last message.
    tabs = layout["configById"]["Tab!c01"]
    audio = [tab["title"] for tab in tabs["tabs"]].index("audio")
    tabs["activeTabIdx"] = audio
    page = tool.page(layout, topics, 1280, 720)
    assert "data: [0, 1, 2, 3, 4, 5, 6, 7, ...] (32 items)" in page
    assert ">/robot1/audio</div>" in page  # a Raw Messages panel's toolbar shows its path
    assert "data:image/png;base64," not in page
    tabs["activeTabIdx"] = 0
    empty = tool.page(layout, {}, 1280, 720)
    assert "no messages on /robot1/camera/image_raw" in empty


def test_a_cluster_of_sensors_shows_its_tab_strip_and_its_active_tab_only(tmp_path: Path) -> None:
    spec = importlib.util.spec_from_file_location(
        "layout_screenshots", TOOLS / "layout_screenshots.py"
    )
    assert spec is not None
    assert spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    out = tmp_path / "layouts"
    assert run_cli("layouts", "case2", "-o", out, "--namespace", "/robot1").returncode == 0
    layout = json.loads((out / "config-008.json").read_text())  # 10 cameras, clusters of 2
    page = tool.page(layout, {}, 1280, 720)
    assert page.count('<span class="tab on">') == 5  # a Tab panel per cluster
    assert '<span class="tab">camera 2</span>' in page  # a tab is titled by its short name
    assert "no messages on /robot1/camera/image_raw_3<" in page  # cluster 2's active tab
    assert "no messages on /robot1/camera/image_raw_2<" not in page  # an inactive tab
