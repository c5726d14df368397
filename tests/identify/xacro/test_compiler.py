"""Xacro: compiled only when trusted, in a limited child process, fenced to its packages."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from solver.errors import InputError
from solver.identify.identification import identify, identify_urdf
from solver.identify.readers.urdf import parse_urdf
from solver.identify.xacro import (
    XacroLimits,
    compile_xacro,
    confine,
)
from tests.conftest import ROOT, run_cli

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


def test_a_xacro_namespace_that_is_no_uri_is_compiled_as_xacro_reads_it(tmp_path: Path) -> None:
    # A markdown link pasted as the namespace (a real robot's file): libxml2 calls it no URI,
    # xacro's minidom does not check; the file compiles, with the flaw's line in a warning.
    path = tmp_path / "copter.xacro"
    path.write_text(
        '<?xml version="1.0"?>\n<robot name="copter" '
        'xmlns:xacro="[http://www.ros.org/wiki/xacro](http://www.ros.org/wiki/xacro)">\n'
        '<xacro:macro name="arm" params="n"><link name="arm_${n}"/></xacro:macro>\n'
        '<link name="base_link"/><xacro:arm n="1"/><xacro:arm n="2"/>\n</robot>\n'
    )
    compiled = compile_xacro(path)
    assert '<link name="arm_1"/>' in compiled.text
    assert '<link name="arm_2"/>' in compiled.text
    assert any(
        w.startswith(f"{path}:2:") and "is not a valid URI" in w for w in compiled.warnings
    ), compiled.warnings


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
    assert "refused in a xacro expression" in result.stderr
    assert "Traceback" not in result.stderr
    assert not marker.exists()


def eval_of(code: str) -> str:
    """``$(eval code)`` through a property: xacro's lexer ends ``$(...)`` at the first ``)``."""
    return f'<xacro:property name="c" value="{code}"/>\n  <link name="$(eval ${{c}})"/>'


CONFINE = confine.__name__
GLOBALS = f'<xacro:property name="g" value="${{{ESCAPE}}}"/>\n  '
# Issue 23.8: each escape seen in the wild, aimed at files outside the description's package:
# MARKER must not appear, OUTSIDE must keep its mode and times, SECRET must not be read.
TRUSTED_ESCAPES = {
    "os-through-function-globals": GLOBALS
    + "<link name=\"${g['os'].chmod('OUTSIDE', 511) or g['os'].mknod('MARKER')}\"/>",
    "io-open-through-function-globals": GLOBALS
    + "<link name=\"${g['sys'].modules['_io'].open('SECRET').read()}\"/>",
    "import-in-eval": eval_of("__import__('os').mknod('MARKER')"),
    "ctypes-through-the-confinement-code": eval_of(
        "__import__('solver.identify.xacro.confine').identify.xacro.confine.ctypes"
        ".CDLL(None).chmod(b'OUTSIDE', 511)"
    ),
    "exec-in-eval": eval_of("exec(bytes.fromhex('HEX_CODE').decode())"),
    "io-open-in-the-interpreters-folders": GLOBALS
    + "<link name=\"${g['sys'].modules['_io'].open('LIBRARY_FILE').read()}\"/>",
    "getattr-in-eval": eval_of("getattr(find, 'func_globals')"),
    "generator-frame": '<link name="${[g for g in [(x for x in [1]).gi_frame.f_globals]][0]'
    "['os'].utime('OUTSIDE', (0, 0))}\"/>",
    "format-string": "<link name=\"${'{0.__globals__[os].mknod}'.format(xacro.load_yaml)}\"/>",
    "class-building-type": "<link name=\"${python.type('X', (python.str,), python.dict())}\"/>",
}


@pytest.mark.parametrize("escape", TRUSTED_ESCAPES.values(), ids=TRUSTED_ESCAPES.keys())
def test_a_trusted_xacro_reaches_no_module_and_no_file_outside_its_package(
    escape: str, tmp_path: Path
) -> None:
    package = tmp_path / "pkg"
    package.mkdir()
    marker = tmp_path / "MARKER"
    outside = tmp_path / "outside.txt"
    outside.write_text("untouched")
    outside.chmod(0o640)
    os.utime(outside, (1_000_000_000, 1_000_000_000))
    secret = tmp_path / "secret.xml"
    secret.write_text("<secret>hunter2</secret>")
    # exec'd code that reaches ctypes through the confinement code: chmod, utime, mknod (no
    # assignment: $(eval) runs with a mapping that takes none).
    code = (
        f"(lambda c: (c.chmod({str(outside).encode()!r}, 511), "
        f"c.utime({str(outside).encode()!r}, None)))"
        f"(__import__({CONFINE!r}, fromlist=['x']).ctypes.CDLL(None)); "
        f"__import__('os').mknod({str(marker)!r})"
    )
    hex_code = code.encode().hex()
    path = package / "evil.xacro"
    body = escape
    for placeholder, value in [
        ("MARKER", str(marker)),
        ("OUTSIDE", str(outside)),
        ("SECRET", str(secret)),
        ("HEX_CODE", hex_code),
        ("LIBRARY_FILE", str(ROOT / "pyproject.toml")),
    ]:
        body = body.replace(placeholder, value)
    path.write_text(robot(body))
    with pytest.raises(InputError) as caught:
        compile_xacro(path, limits=FAST)
    assert caught.value.faults[0].location.file == str(path)
    assert not marker.exists()
    status = outside.stat()
    assert (status.st_mode & 0o777, status.st_mtime) == (0o640, 1_000_000_000)
    assert "hunter2" not in str(caught.value)
    assert "[project]" not in str(caught.value)


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


def test_the_environment_is_never_read(tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text(robot('<link name="$(env HOME)"/>'))
    with pytest.raises(InputError, match="environment lookups are refused") as caught:
        compile_xacro(path, limits=FAST)
    assert "/root" not in str(caught.value)
    assert "--arg HOME:=VALUE" in str(caught.value)


def test_an_optional_environment_variable_takes_its_default_as_if_unset(tmp_path: Path) -> None:
    """As xacro with the variable unset: PATH is set here, and not read."""
    path = tmp_path / "r.xacro"
    path.write_text(robot('<link name="$(optenv PATH no_path)"/><link name="$(optenv EMPTY)x"/>'))
    text = compile_xacro(path, limits=FAST).text
    assert '<link name="no_path"/>' in text
    assert '<link name="x"/>' in text
    assert "/usr/bin" not in text


def test_an_argument_gives_an_environment_variable_its_value(tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text(
        robot('<link name="$(env ROBOT_PREFIX)base"/><link name="$(optenv ARM none)"/>')
    )
    text = compile_xacro(path, args={"ROBOT_PREFIX": "left_", "ARM": "ur5"}, limits=FAST).text
    assert '<link name="left_base"/>' in text
    assert '<link name="ur5"/>' in text


def test_an_included_file_that_does_not_exist_is_said_to_be_missing(tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text(robot('<xacro:include filename="parts.xacro"/>'))
    with pytest.raises(InputError, match=r"parts\.xacro: no such file") as caught:
        compile_xacro(path, limits=FAST)
    assert "not a regular file" not in str(caught.value)


def test_a_file_that_is_no_regular_file_is_refused(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "config.yaml")  # a read would wait for a writer for ever
    path = tmp_path / "r.xacro"
    path.write_text(
        robot(
            '<xacro:property name="d" value="${xacro.load_yaml(\'config.yaml\')}"/>'
            '<link name="${d}"/>'
        )
    )
    with pytest.raises(InputError, match=r"config\.yaml: not a regular file; refused"):
        compile_xacro(path, limits=FAST)


def test_ros1_tags_without_the_prefix_are_read_as_ros1_xacro_read_them(tmp_path: Path) -> None:
    """Melodic's xacro (1.13) read unprefixed keywords and macro calls; xacro 2 drops them."""
    (tmp_path / "parts.xacro").write_text(
        robot(
            '<macro name="wheel" params="side"><link name="${side}_${size}"/></macro>'
            '<macro name="hokuyo" params="*origin"><sensor name="scan" type="ray">'
            '<xacro:insert_block name="origin"/></sensor></macro>'
            '<macro name="link" params=""><link name="never_called"/></macro>'
            '<xacro:macro name="light" params="reference"><link name="never_lit"/></xacro:macro>'
            '<xacro:macro name="camera" params=""><link name="never_seen"/></xacro:macro>'
        )
    )
    path = tmp_path / "r.xacro"
    path.write_text(
        robot(
            '<arg name="which" default="small"/><property name="size" value="$(arg which)"/>'
            '<include filename="parts.xacro"/>'
            '<link name="base_link"/><wheel side="left"/><wheel side="right"/>'
            '<if value="false"><link name="dropped"/></if><unless value="false">'
            '<link name="kept"/></unless><gazebo><include><uri>model://gps</uri></include>'
            '<light name="lamp" type="spot"/></gazebo>'
            '<gazebo reference="base_link"><hokuyo><pose>0 0 1 0 0 0</pose></hokuyo>'
            "<sensor><camera><horizontal_fov>1</horizontal_fov></camera></sensor></gazebo>"
        )
    )
    compiled = compile_xacro(path, limits=FAST)
    urdf = parse_urdf(compiled.text, "r.urdf", strict=False)
    assert [link.name for link in urdf.links] == ["base_link", "left_small", "right_small", "kept"]
    # A call inside a <gazebo> block is a call: the macro's sensor, with the block passed in.
    assert '<sensor name="scan" type="ray"><pose>0 0 1 0 0 0</pose></sensor>' in compiled.text
    # What is not written as a call is left as it is: an SDF include (no filename), SDF's
    # light (attributes no parameter of the `light` macro), a camera and its settings (a macro
    # of no block holds no elements).
    assert "<uri>model://gps</uri>" in compiled.text
    assert '<light name="lamp" type="spot"/>' in compiled.text
    assert "<camera><horizontal_fov>1</horizontal_fov></camera>" in compiled.text
    said = [w.split("'")[1] for w in compiled.warnings if "without the 'xacro:' prefix" in w]
    assert sorted(said) == [
        "arg",
        "hokuyo",
        "if",
        "include",
        "macro",
        "property",
        "unless",
        "wheel",
    ]


def test_many_unprefixed_tags_are_named_in_ten_warnings_and_one_more(tmp_path: Path) -> None:
    macros = "".join(f'<macro name="m{n}" params=""><link name="l{n}"/></macro>' for n in range(15))
    path = tmp_path / "r.xacro"
    path.write_text(robot(macros + "".join(f"<m{n}/>" for n in range(15))))
    compiled = compile_xacro(path, limits=FAST)
    said = [w for w in compiled.warnings if "without the 'xacro:' prefix" in w]
    assert len(said) == 11  # macro and m0 .. m8, then one line for the rest
    assert said[-1] == "deprecated: more xacro tags without the 'xacro:' prefix"
    assert len(parse_urdf(compiled.text, "r.urdf", strict=False).links) == 15
