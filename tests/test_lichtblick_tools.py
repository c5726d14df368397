"""tools/lichtblick/cover.py picks the layouts to drive in the app; verdict.py judges what the
app showed of them against the bag it played (drive.py itself needs a build of the app)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import ROOT, run_cli

TOOLS = ROOT / "tools" / "lichtblick"


def _tool(*args: str | Path) -> subprocess.CompletedProcess[str]:
    environment = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, *map(str, args)],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=False,
    )


@pytest.fixture(scope="module")
def case3(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, Path]:
    """case3's layouts under /robot1 and in the root namespace, and a bag of /robot1's topics."""
    folder = tmp_path_factory.mktemp("lichtblick")
    assert _tool(TOOLS / "makebag.py", folder / "bag", "/robot1").returncode == 0
    for where, namespace in (("robot1", ["--namespace", "/robot1"]), ("root", [])):
        assert run_cli("layouts", "case3", "-o", folder / where, *namespace).returncode == 0
    return folder / "robot1", folder / "root", folder / "bag"


def _titles(layout: Path) -> set[tuple[str, str]]:
    configs = json.loads(layout.read_text())["configById"]
    return {
        (key.split("!")[0], config.get("lichtblickPanelTitle", ""))
        for key, config in configs.items()
    }


def test_the_layouts_to_drive_hold_every_panel_of_the_team_default_first(
    case3: tuple[Path, Path, Path],
) -> None:
    folder = case3[0]
    done = _tool(TOOLS / "cover.py", folder)
    chosen = [Path(line) for line in done.stdout.splitlines()]
    assert chosen[0].name == "config-103-default.json"
    assert len(chosen) < 103 / 10
    every = set().union(*(_titles(file) for file in folder.glob("*.json")))
    assert set().union(*(_titles(file) for file in chosen)) == every
    assert done.stderr.startswith(f"{folder}: {len(chosen)} of 103 layouts hold its ")


def _seen(layout: Path, advertised: list[str]) -> dict[str, Any]:
    """A report as drive.py writes it of an app that showed every panel's data."""
    configs = json.loads(layout.read_text())["configById"]
    panels = {
        key: {
            "present": True,
            "text": "audio_common_msgs/msg/AudioData @ 1700000000.0 sec"
            if key.startswith("RawMessages")
            else config.get("lichtblickPanelTitle", ""),
            "hues": 12,
        }
        for key, config in configs.items()
    }
    return {
        "layout": str(layout),
        "snackbars": [],
        "panels": panels,
        "export_diff": [],
        "unsaved_changes": ["Default"],
        "advertised": advertised,
        "console": [],
    }


def test_a_layout_whose_panels_show_the_bags_topics_passes_and_one_of_other_topics_fails(
    case3: tuple[Path, Path, Path], tmp_path: Path
) -> None:
    robot1, root, bag = case3
    good = tmp_path / "robot1.report.json"
    good.write_text(json.dumps(_seen(robot1 / "config-103-default.json", ["/robot1/cmd_vel"])))
    done = _tool(TOOLS / "verdict.py", bag, "/robot1", good)
    assert done.returncode == 0, done.stdout
    assert done.stdout.splitlines()[0] == (
        "robot1: ok: 9 panels: 1 control, 5 data, 3 no data expected"
    )
    # The root namespace's layout against /robot1's bag: its topics are not there, and the
    # click tools it advertises lie outside the robot.
    report = _seen(root / "config-103-default.json", ["/cmd_vel", "/clicked_point"])
    report["panels"]["Image!p05"]["text"] = "visual display\nImage topic does not exist."
    report["unsaved_changes"].append("root")
    bad = tmp_path / "root.report.json"
    bad.write_text(json.dumps(report))
    done = _tool(TOOLS / "verdict.py", bag, "/robot1", good, bad)
    assert done.returncode == 1
    faults = done.stdout.splitlines()
    assert faults[0].startswith("robot1: ok")
    assert faults[1].startswith("root: FAIL")
    assert "    the layout list marks it as having unsaved changes" in faults
    assert "    advertises /cmd_vel, outside /robot1" in faults
    assert "    Image!p05: shows 'does not exist'" in faults
    assert "    Image!p05: /camera/image_raw is not in the bag" in faults
    assert "    Plot!p08: /wrench is not in the bag" in faults
    assert faults[-1] == "1 of 2 layouts pass"


def test_panels_in_a_tab_the_app_does_not_show_are_named_not_failed(
    case3: tuple[Path, Path, Path], tmp_path: Path
) -> None:
    # The default configuration's primary views are the tabs of one Tab panel: the app mounts
    # the active tab's panel only; the others are not on the screen, and that is no fault.
    robot1, _, bag = case3
    layout = robot1 / "config-103-default.json"
    report = _seen(layout, ["/robot1/cmd_vel"])
    tabs = json.loads(layout.read_text())["configById"]["Tab!c01"]["tabs"]
    for tab in tabs[1:]:
        report["panels"][tab["layout"]]["present"] = False
    seen = tmp_path / "robot1.report.json"
    seen.write_text(json.dumps(report))
    done = _tool(TOOLS / "verdict.py", bag, "/robot1", seen)
    assert done.returncode == 0, done.stdout
    assert f"{len(tabs) - 1} in a tab not shown" in done.stdout.splitlines()[0]
    # A panel of the active tab that is not on the screen still fails.
    report["panels"][tabs[0]["layout"]]["present"] = False
    seen.write_text(json.dumps(report))
    done = _tool(TOOLS / "verdict.py", bag, "/robot1", seen)
    assert done.returncode == 1
    assert f"    {tabs[0]['layout']}: not on the screen" in done.stdout.splitlines()


def test_a_panel_seen_in_a_tab_clicked_open_is_judged_like_any_other(
    case3: tuple[Path, Path, Path], tmp_path: Path
) -> None:
    # drive.py --tabs clicks each tab the app does not show on opening and reports its panels
    # as on the screen, each with its tab: a point cloud that draws nothing there fails.
    robot1, _, bag = case3
    layout = robot1 / "config-103-default.json"
    report = _seen(layout, ["/robot1/cmd_vel"])
    tabs = json.loads(layout.read_text())["configById"]["Tab!c01"]["tabs"]
    cloud = next(tab for tab in tabs[1:] if tab["layout"].startswith("3D!"))
    report["panels"][cloud["layout"]].update(hues=1, tab=cloud["title"])
    seen = tmp_path / "robot1.report.json"
    seen.write_text(json.dumps(report))
    done = _tool(TOOLS / "verdict.py", bag, "/robot1", seen)
    assert done.returncode == 1
    assert "in a tab not shown" not in done.stdout
    fault = f"    {cloud['layout']}: 1 hues: no image or point cloud drawn"
    assert fault in done.stdout.splitlines()
