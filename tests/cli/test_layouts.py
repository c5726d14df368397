"""``teleop-ui layouts`` as a user runs it: what a second run says it replaced, namespaces,
the options that need another (``--robot``, ``--team``), presentations and previews.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver.cli import main
from tests.conftest import ROOT, run_cli

EXAMPLES = ROOT / "examples"


def test_a_second_run_replaces_its_layouts_and_removes_those_it_no_longer_writes(
    tmp_path: Path,
) -> None:
    out = tmp_path / "layouts"
    first = run_cli("layouts", "case2", "-o", out, "--preview")
    assert first.returncode == 0, first.stderr
    assert len(list(out.glob("config-*.json"))) == 19
    (out / "notes.txt").write_text("the operator's own notes\n")
    second = run_cli("layouts", "case1", "-o", out)
    assert second.returncode == 0, second.stderr
    assert second.stdout == (
        f"wrote 7 layouts to {out}\n"
        "consistency: 100.0% (21 of 21 pairs of configurations sharing a component put it in "
        "the same region)\n"
        "replaced 6 files of an earlier run: config-001.json, config-002.json, "
        "config-003.json, config-004.json, config-005.json, config-006.json\n"
        "removed 14 files of an earlier run: config-007.json, config-008.json, "
        "config-009.json, config-010.json, config-011.json, config-012.json and 8 more\n"
    )
    assert sorted(path.name for path in out.iterdir()) == [
        *(f"config-{n:03d}.json" for n in range(1, 7)),
        "config-007-default.json",
        "notes.txt",
    ]
    assert (out / "notes.txt").read_text() == "the operator's own notes\n"
    # docs/layouts.md shows this run's output.
    page = (ROOT / "docs" / "layouts.md").read_text(encoding="utf-8")
    assert (
        "$ teleop-ui layouts case1 -o layouts/\n" + second.stdout.replace(str(out), "layouts/")
        in page
    )


def test_layouts_for_a_namespace_put_every_topic_under_it(tmp_path: Path) -> None:
    result = run_cli("layouts", "case1", "-o", tmp_path, "--namespace", "/uav7/")
    assert result.returncode == 0, result.stderr
    layout = json.loads((tmp_path / "config-001.json").read_text())
    assert layout["configById"]["Teleop!p01"]["topic"] == "/uav7/cmd_vel"


def test_a_namespace_that_is_no_ros2_name_exits_2_and_writes_nothing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = run_cli("layouts", "case1", "-o", out, "--namespace", "uav 7")
    assert result.returncode == 2
    assert result.stderr == (
        "--namespace: 'uav 7' is not a ROS 2 namespace: it is not absolute (a ROS 2 topic name "
        "starts with '/')\n"
    )
    assert not out.exists()


def test_a_robot_whose_name_is_no_ros2_name_needs_a_namespace(tmp_path: Path) -> None:
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(
        '<robot name="my-rover"><link name="base_link"/><link name="wheel"/>'
        '<joint name="wheel_joint" type="continuous"><parent link="base_link"/>'
        '<child link="wheel"/></joint></robot>'
    )
    out = tmp_path / "rover.json"
    refused = run_cli("layouts", "--robot", urdf, "--team", "case2", "-o", out)
    assert refused.returncode == 2
    assert "the robot's name makes its namespace: give one with --namespace /NAME" in refused.stderr
    assert not out.exists()
    named = run_cli(
        "layouts", "--robot", urdf, "--team", "case2", "-o", out, "--namespace", "/rover"
    )
    assert named.returncode == 0, named.stderr
    assert '"/rover/' in out.read_text()


def test_robot_layout_without_a_team_exits_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert (
        main(
            ["layouts", "--robot", str(EXAMPLES / "quadrotor.urdf"), "-o", str(tmp_path / "y.json")]
        )
        == 2
    )
    assert "--robot needs --team" in capsys.readouterr().err


def test_topics_without_a_robot_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["layouts", "case1", "--topics", "t.txt", "-o", str(tmp_path)]) == 2
    assert "--topics: needs --robot URDF" in capsys.readouterr().err


def test_layouts_command_exits_2_on_an_unusable_presentation(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text("components: [1]\n")
    out = str(tmp_path / "out")
    assert main(["layouts", "case1", "-o", out, "--presentation", str(path)]) == 2
    assert "components" in capsys.readouterr().err


def test_an_identification_profile_for_layouts_needs_a_robot(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = str(tmp_path / "out")
    assert main(["layouts", "case1", "-o", out, "--profile", "rules/identification.yaml"]) == 2
    assert "--profile: needs --robot URDF" in capsys.readouterr().err


def test_layouts_preview_option_writes_one_thumbnail_per_layout(tmp_path: Path) -> None:
    from solver.cli import main

    assert main(["layouts", "case1", "-o", str(tmp_path), "--preview"]) == 0
    page = (tmp_path / "preview.html").read_text()
    assert page.count("<figure>") == 7
    assert "<figcaption>config-007-default.json</figcaption>" in page


def test_preview_with_rviz_format_exits_2_before_writing(tmp_path: Path) -> None:
    from solver.cli import main

    assert (
        main(["layouts", "case1", "-o", str(tmp_path / "out"), "--format", "rviz", "--preview"])
        == 2
    )
    assert not (tmp_path / "out").exists()
