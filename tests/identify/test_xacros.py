"""Xacro compiled with xacrodoc, packages found through the package path."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify.xacros import compile_xacro, package_path_from_env
from tests.conftest import run_cli

PACKAGE_XML = ('<?xml version="1.0"?><package format="2"><name>{name}</name>'
               '<version>0.0.0</version><description>d</description>'
               '<maintainer email="a@b.c">a</maintainer><license>MIT</license></package>')
WHEEL_MACRO = ('<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
               '<xacro:macro name="wheel" params="side"><link name="${side}_wheel"/>'
               '<joint name="${side}_wheel_joint" type="continuous"><parent link="base_link"/>'
               '<child link="${side}_wheel"/></joint></xacro:macro></robot>')
ROBOT = """<?xml version="1.0"?>
<robot name="xbot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="side" default="left"/>
  <xacro:include filename="$(find wheels_description)/urdf/wheel.xacro"/>
  <xacro:include filename="laser.xacro"/>
  <link name="base_link"><visual><geometry><mesh filename="package://nowhere/m.stl"/></geometry></visual></link>
  <xacro:wheel side="$(arg side)"/>
  <xacro:wheel side="right"/>
</robot>
"""
LASER = ('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="laser"/>'
         '<joint name="laser_joint" type="fixed"><parent link="base_link"/>'
         '<child link="laser"/></joint></robot>')


@pytest.fixture
def workspace(tmp_path: Path) -> tuple[Path, Path]:
    package = tmp_path / "ws" / "wheels_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML.format(name="wheels_description"))
    (package / "urdf" / "wheel.xacro").write_text(WHEEL_MACRO)
    robot = tmp_path / "robot" / "xbot.urdf.xacro"
    robot.parent.mkdir()
    robot.write_text(ROBOT)
    (robot.parent / "laser.xacro").write_text(LASER)
    return robot, tmp_path / "ws"


def test_xacro_compiles_with_find_relative_includes_and_arguments(
        workspace: tuple[Path, Path]) -> None:
    robot, ws = workspace
    text = compile_xacro(robot, args={"side": "middle"}, package_path=[ws]).text
    assert 'joint name="middle_wheel_joint"' in text
    assert '<link name="laser"/>' in text
    assert "package://nowhere/m.stl" in text  # meshes are left as written


def test_a_missing_package_is_named_with_its_line(workspace: tuple[Path, Path]) -> None:
    robot, _ = workspace
    with pytest.raises(InputError) as caught:
        compile_xacro(robot)
    fault = caught.value.faults[0]
    assert "package 'wheels_description' not found" in fault.message
    assert fault.location.line == 4
    assert fault.code == "xacro-package"


def test_an_include_with_an_entity_bomb_is_refused(workspace: tuple[Path, Path]) -> None:
    robot, ws = workspace
    (robot.parent / "laser.xacro").write_text(
        '<!DOCTYPE r [<!ENTITY a "aaaa"><!ENTITY b "&a;&a;">]>\n<robot><link name="&b;"/></robot>')
    with pytest.raises(InputError, match="entity") as caught:
        compile_xacro(robot, package_path=[ws])
    assert caught.value.faults[0].location.file.endswith("laser.xacro")


def test_xacro_errors_are_reported_not_raised_raw(tmp_path: Path) -> None:
    path = tmp_path / "bad.xacro"
    path.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    '<link name="${undefined_thing}"/></robot>')
    with pytest.raises(InputError, match="xacro: "):
        compile_xacro(path)


def test_the_package_path_comes_from_the_environment() -> None:
    assert package_path_from_env({"TELEOP_UI_PACKAGE_PATH": "/a:/b"}) == (Path("/a"), Path("/b"))


def test_identify_compiles_xacro_through_the_cli(workspace: tuple[Path, Path]) -> None:
    robot, ws = workspace
    result = run_cli("identify", robot, "--package-path", ws, "--arg", "side:=left",
                     "--format", "json")
    assert result.returncode == 0, result.stderr
    assert '"structure": "UGV"' in result.stdout
    missing = run_cli("identify", robot)
    assert missing.returncode == 2
    assert "wheels_description" in missing.stderr
    assert "Traceback" not in missing.stderr
