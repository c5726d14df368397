"""Xacro: compiled only when trusted, in a limited child process, fenced to its packages."""

from __future__ import annotations

from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify.identification import identify, identify_urdf
from solver.identify.urdf import parse_urdf
from solver.identify.xacro import XacroLimits, compile_xacro, find_packages, package_path_from_env
from tests.conftest import run_cli

PACKAGE_XML = (
    '<?xml version="1.0"?><package format="2"><name>{name}</name>'
    "<version>0.0.0</version><description>d</description>"
    '<maintainer email="a@b.c">a</maintainer><license>MIT</license></package>'
)
WHEEL_MACRO = (
    '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
    '<xacro:macro name="wheel" params="side"><link name="${side}_wheel"/>'
    '<joint name="${side}_wheel_joint" type="continuous"><parent link="base_link"/>'
    '<child link="${side}_wheel"/></joint></xacro:macro></robot>'
)
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
LASER = (
    '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="laser"/>'
    '<joint name="laser_joint" type="fixed"><parent link="base_link"/>'
    '<child link="laser"/></joint></robot>'
)
# Reaches the `os` module through the globals of a function xacro exposes, using only names
# xacro's expression check lets through: the escape seen in the wild.
ESCAPE = (
    "python.vars(python.type(python.vars(python.type(xacro.load_yaml))['__globals__']))"
    "['__get__'](python.vars(python.type(xacro.load_yaml))['__globals__'], "
    "xacro.load_yaml)"
)
FAST = XacroLimits(cpu_seconds=2, memory_bytes=512 * 2**20, wall_seconds=10.0)


def robot(body: str, name: str = "r") -> str:
    return (
        f'<?xml version="1.0"?>\n<robot name="{name}" '
        f'xmlns:xacro="http://www.ros.org/wiki/xacro">\n{body}\n</robot>\n'
    )


def escape_that_touches(marker: Path) -> str:
    """A description whose compilation would create ``marker`` if its code ran."""
    return robot(
        f'  <xacro:property name="g" value="${{{ESCAPE}}}"/>\n'
        f"  <link name=\"${{g['os'].system('touch {marker}') or 'base_link'}}\"/>"
    )


@pytest.fixture
def workspace(tmp_path: Path) -> tuple[Path, Path]:
    package = tmp_path / "ws" / "wheels_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML.format(name="wheels_description"))
    (package / "urdf" / "wheel.xacro").write_text(WHEEL_MACRO)
    path = tmp_path / "robot" / "xbot.urdf.xacro"
    path.parent.mkdir()
    path.write_text(ROBOT)
    (path.parent / "laser.xacro").write_text(LASER)
    return path, tmp_path / "ws"


def test_xacro_compiles_with_find_relative_includes_and_arguments(
    workspace: tuple[Path, Path],
) -> None:
    path, ws = workspace
    text = compile_xacro(path, args={"side": "middle"}, package_path=[ws]).text
    assert 'joint name="middle_wheel_joint"' in text
    assert '<link name="laser"/>' in text
    assert "package://nowhere/m.stl" in text  # meshes are left as written


def test_a_missing_package_is_named_with_its_line(workspace: tuple[Path, Path]) -> None:
    path, _ = workspace
    with pytest.raises(InputError) as caught:
        compile_xacro(path)
    fault = caught.value.faults[0]
    assert "package 'wheels_description' not found" in fault.message
    assert fault.location.line == 4
    assert fault.code == "xacro-package"


def test_an_include_with_an_entity_bomb_is_refused(workspace: tuple[Path, Path]) -> None:
    path, ws = workspace
    (path.parent / "laser.xacro").write_text(
        '<!DOCTYPE r [<!ENTITY a "aaaa"><!ENTITY b "&a;&a;">]>\n<robot><link name="&b;"/></robot>'
    )
    with pytest.raises(InputError, match="entity") as caught:
        compile_xacro(path, package_path=[ws])
    assert caught.value.faults[0].location.file.endswith("laser.xacro")


def test_xacro_errors_are_reported_not_raised_raw(tmp_path: Path) -> None:
    path = tmp_path / "bad.xacro"
    path.write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<link name="${undefined_thing}"/></robot>'
    )
    with pytest.raises(InputError, match=r"xacro: .*undefined_thing"):
        compile_xacro(path)


def test_the_package_path_comes_from_the_environment() -> None:
    assert package_path_from_env({"TELEOP_UI_PACKAGE_PATH": "/a:/b"}) == (Path("/a"), Path("/b"))


def test_packages_are_found_beside_the_description_and_on_the_package_path(tmp_path: Path) -> None:
    for name in ("robot_description", "robot_gazebo"):
        (tmp_path / "src" / name).mkdir(parents=True)
        (tmp_path / "src" / name / "package.xml").write_text(PACKAGE_XML.format(name=name))
    (tmp_path / "other" / "deep" / "tools").mkdir(parents=True)
    (tmp_path / "other" / "deep" / "tools" / "package.xml").write_text(
        PACKAGE_XML.format(name="tools")
    )
    source = tmp_path / "src" / "robot_description" / "urdf" / "r.urdf.xacro"
    found = find_packages(source, [tmp_path / "other"], environ={})
    assert sorted(found) == ["robot_description", "robot_gazebo", "tools"]


# --- trust -----------------------------------------------------------------------------------


def test_identify_refuses_xacro_unless_trusted_and_runs_none_of_it(tmp_path: Path) -> None:
    marker = tmp_path / "MARKER"
    path = tmp_path / "evil.urdf.xacro"
    path.write_text(escape_that_touches(marker))
    result = run_cli("identify", path)
    assert result.returncode == 2
    assert "--trust-xacro" in result.stderr
    assert "Traceback" not in result.stderr
    assert not marker.exists()


def test_a_urdf_that_declares_the_xacro_namespace_is_read_not_compiled(tmp_path: Path) -> None:
    marker = tmp_path / "MARKER"
    path = tmp_path / "expanded.urdf"
    path.write_text(
        robot(
            f'  <xacro:property name="g" value="${{{ESCAPE}}}"/>\n'
            f"  <link name=\"base_link\"/><link name=\"${{g['os'].system('touch {marker}')}}\"/>\n"
            '  <joint name="j" type="fixed"><parent link="base_link"/>'
            f"<child link=\"${{g['os'].system('touch {marker}')}}\"/></joint>"
        )
    )
    result = identify(path)
    assert result.robot == "r"
    assert not marker.exists()
    assert [(w.location.line, w.code) for w in result.warnings] == [(3, "xacro-ignored")]
    assert "<xacro:property> ignored" in result.warnings[0].message


def test_a_robot_description_with_xacro_elements_is_read_with_a_located_warning_each() -> None:
    text = robot(
        '  <link name="base_link"/>\n  <xacro:include filename="/etc/passwd"/>\n'
        '  <xacro:macro name="m" params=""><link name="inside_a_macro"/>'
        "</xacro:macro>"
    ).replace(' xmlns:xacro="http://www.ros.org/wiki/xacro"', "")
    result = identify_urdf(text, file="/robot_description")
    assert [w.location.line for w in result.warnings if w.code == "xacro-ignored"] == [4, 5]
    assert [link.name for link in parse_urdf(text, strict=False).links] == ["base_link"]


def test_a_fleet_folder_never_implies_trust(tmp_path: Path) -> None:
    marker = tmp_path / "MARKER"
    (tmp_path / "fleet").mkdir()
    (tmp_path / "fleet" / "evil.xacro").write_text(escape_that_touches(marker))
    (tmp_path / "fleet" / "good.urdf").write_text(
        '<robot name="good"><link name="base_link"/></robot>'
    )
    result = run_cli("fleet", tmp_path / "fleet")
    assert "--trust-xacro" in result.stdout + result.stderr
    assert "Traceback" not in result.stderr
    assert not marker.exists()


def test_a_trusted_escape_cannot_start_a_process(tmp_path: Path) -> None:
    marker = tmp_path / "MARKER"
    path = tmp_path / "evil.xacro"
    path.write_text(escape_that_touches(marker))
    result = run_cli("identify", "--trust-xacro", path)
    assert result.returncode == 2
    assert "may not start processes" in result.stderr
    assert "Traceback" not in result.stderr
    assert not marker.exists()


def test_the_trusted_cli_compiles_a_workspace(workspace: tuple[Path, Path]) -> None:
    path, ws = workspace
    result = run_cli(
        "identify",
        "--trust-xacro",
        path,
        "--package-path",
        ws,
        "--arg",
        "side:=left",
        "--format",
        "json",
    )
    assert result.returncode == 0, result.stderr
    assert '"structure": "UGV"' in result.stdout
    missing = run_cli("identify", "--trust-xacro", path)
    assert missing.returncode == 2
    assert "wheels_description" in missing.stderr
    assert "Traceback" not in missing.stderr


# --- limits ----------------------------------------------------------------------------------


def exponential_macros(levels: int) -> str:
    """``m{k}`` calls ``m{k-1}`` twice: 2**levels expansions of one link."""
    macros = ['<xacro:macro name="m0" params="p"><link name="l${p}"/></xacro:macro>']
    macros += [
        f'<xacro:macro name="m{k}" params="p"><xacro:m{k - 1} p="${{p}}a"/>'
        f'<xacro:m{k - 1} p="${{p}}b"/></xacro:macro>'
        for k in range(1, levels + 1)
    ]
    return robot("\n".join(macros) + f'\n<xacro:m{levels} p="x"/>')


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("exponential-macros", exponential_macros(22)),
        ("string-bomb", robot("<link name=\"${'a' * 10**11}\"/>")),
        ("power-bomb", robot('<link name="${9**9**9}"/>')),
        ("recursion", robot('<xacro:macro name="m" params=""><xacro:m/></xacro:macro><xacro:m/>')),
    ],
    ids=["exponential-macros", "string-bomb", "power-bomb", "recursion"],
)
def test_a_runaway_xacro_ends_with_a_located_error(name: str, text: str, tmp_path: Path) -> None:
    path = tmp_path / f"{name}.xacro"
    path.write_text(text)
    with pytest.raises(InputError) as caught:
        compile_xacro(path, limits=FAST)
    fault = caught.value.faults[0]
    assert fault.location.file == str(path)
    assert fault.code in {"xacro", "xacro-limit"}


@pytest.mark.parametrize(
    "target", ["/etc/hostname", "../outside.xacro", "/proc/self/environ", "/dev/zero"]
)
def test_an_include_outside_the_package_folders_is_refused(target: str, tmp_path: Path) -> None:
    (tmp_path / "outside.xacro").write_text('<robot><link name="secret"/></robot>')
    (tmp_path / "pkg").mkdir()
    path = tmp_path / "pkg" / "r.xacro"
    path.write_text(robot(f'<xacro:include filename="{target}"/><link name="base_link"/>'))
    with pytest.raises(InputError, match="outside the description's package folders"):
        compile_xacro(path, limits=FAST)


def test_load_yaml_outside_the_package_folders_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text(
        robot(
            '<xacro:property name="d" value="${xacro.load_yaml(\'/etc/passwd\')}"/>'
            '<link name="${d}"/>'
        )
    )
    with pytest.raises(InputError, match="outside the description's package folders") as caught:
        compile_xacro(path, limits=FAST)
    assert "root:" not in str(caught.value)


def test_load_yaml_inside_the_package_is_read(tmp_path: Path) -> None:
    (tmp_path / "config.yaml").write_text("name: from_yaml\n")
    path = tmp_path / "r.xacro"
    path.write_text(
        robot(
            '<xacro:property name="d" value="${xacro.load_yaml(\'config.yaml\')}"/>'
            "<link name=\"${d['name']}\"/>"
        )
    )
    assert '<link name="from_yaml"/>' in compile_xacro(path, limits=FAST).text


@pytest.mark.parametrize("lookup", ["$(env HOME)", "$(optenv PATH nothing)"])
def test_environment_lookups_are_refused(lookup: str, tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text(robot(f'<link name="{lookup}"/>'))
    with pytest.raises(InputError, match="environment lookups are refused") as caught:
        compile_xacro(path, limits=FAST)
    assert "/root" not in str(caught.value)
    assert "/usr/bin" not in str(caught.value)
