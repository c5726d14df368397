"""tools/pack_extension.py packs the follower extension (viewer/lichtblick/) into the .foxe an
operator installs: the same bytes from the same build, and a zip Lichtblick v1.19.0 installs.

What Lichtblick accepts is written here from its own source, not taken from the tool:
``packages/suite-base/src/services/IdbExtensionLoader.ts`` (the web app's loader: which files it
reads, ``validatePackageInfo``, the extension's id and qualified name) and
``providers/helpers/buildContributionPoints.ts`` (a panel's type is
``<qualifiedName>.<panel name>``). The built extension itself is made by ``tools/test.sh``
(``npm ci && npm run build`` in viewer/lichtblick) before pytest runs; nothing here builds it.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import Any

import pytest

from solver.layouts.team import FOLLOWER_PANEL
from tests.conftest import ROOT

TOOL = ROOT / "tools" / "pack_extension.py"
EXTENSION = ROOT / "viewer" / "lichtblick"
FOXE = EXTENSION / "teleop-ui-follower.foxe"

# IdbExtensionLoader.ts (v1.19.0): the files it reads from a .foxe; package.json and
# dist/extension.js are required (installExtension, loadExtension), the others optional.
ALLOWED_FILES = {"dist/extension.js", "package.json", "README.md", "CHANGELOG.md"}
REQUIRED_FILES = {"dist/extension.js", "package.json"}


def loader_info(package: dict[str, Any]) -> dict[str, str]:
    """What IdbExtensionLoader.installExtension makes of a package.json in the "local"
    namespace (validatePackageInfo, the id, qualifiedName), or ValueError with its message."""
    name = package.get("name")
    if not name:
        raise ValueError("Invalid extension: missing name")
    scoped = re.match(r"^@([^/]+)/(.+)", name)
    publisher = package.get("publisher")
    if publisher is None and scoped:
        publisher = scoped.group(1)
    if not publisher:
        raise ValueError("Invalid extension: missing publisher")
    short = (scoped.group(2) if scoped else name).lower()
    normalized = re.sub(r"[^A-Za-z0-9_\s]+", "", publisher)
    return {"id": f"{normalized}.{short}", "qualifiedName": package["displayName"]}


def _tool(*args: str | Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, str(TOOL), *map(str, args)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )


def _source(folder: Path, **package: Any) -> Path:
    """An extension folder of the test's own, its package.json changed by ``package`` (a key
    given ``...`` left out)."""
    info = {
        "name": "teleop-ui-follower",
        "displayName": "teleop-ui",
        "publisher": "teleop-ui",
        "version": "0.1.0",
        "main": "./dist/extension.js",
        **package,
    }
    (folder / "dist").mkdir(parents=True, exist_ok=True)
    (folder / "package.json").write_text(json.dumps({k: v for k, v in info.items() if v != ...}))
    (folder / "README.md").write_text("# a follower\n")
    (folder / "dist" / "extension.js").write_text("module.exports = { activate() {} };\n")
    return folder


def test_two_packs_of_one_build_are_the_same_bytes_whenever_made(tmp_path: Path) -> None:
    source = _source(tmp_path / "ext")
    assert _tool(tmp_path / "first.foxe", "--source", source).returncode == 0
    for file in (source / "package.json", source / "README.md", source / "dist" / "extension.js"):
        os.utime(file, (2_000_000_000, 2_000_000_000))
    os.chmod(source / "README.md", 0o600)
    done = _tool(tmp_path / "second.foxe", "--source", source)
    assert done.returncode == 0
    second = tmp_path / "second.foxe"
    assert done.stdout == f"wrote {second} ({second.stat().st_size:,} bytes)\n"
    assert (tmp_path / "first.foxe").read_bytes() == (tmp_path / "second.foxe").read_bytes()


def test_a_pack_holds_the_three_files_in_name_order_with_no_date_and_no_folder(
    tmp_path: Path,
) -> None:
    source = _source(tmp_path / "ext")
    assert _tool(tmp_path / "out.foxe", "--source", source).returncode == 0
    with zipfile.ZipFile(tmp_path / "out.foxe") as archive:
        entries = archive.infolist()
        assert [e.filename for e in entries] == ["README.md", "dist/extension.js", "package.json"]
        assert {e.date_time for e in entries} == {(1980, 1, 1, 0, 0, 0)}
        assert {e.external_attr >> 16 for e in entries} == {0o100644}
        assert archive.read("dist/extension.js") == (source / "dist/extension.js").read_bytes()


def _foxe_entries() -> dict[str, bytes]:
    with zipfile.ZipFile(FOXE) as archive:
        assert not [e.filename for e in archive.infolist() if e.is_dir()]
        return {e.filename: archive.read(e) for e in archive.infolist()}


def test_the_repository_s_foxe_installs_in_lichtblick_as_the_panel_the_team_layout_names() -> None:
    entries = _foxe_entries()
    assert REQUIRED_FILES <= set(entries) <= ALLOWED_FILES
    package = json.loads(entries["package.json"])
    info = loader_info(package)
    assert info == {"id": "teleopui.teleop-ui-follower", "qualifiedName": "teleop-ui"}
    registered = re.findall(r'PANEL_NAME = "([^"]+)"', entries["dist/extension.js"].decode())
    assert [f"{info['qualifiedName']}.{name}" for name in registered] == [FOLLOWER_PANEL]


def test_the_repository_s_foxe_is_the_pack_of_the_current_build(tmp_path: Path) -> None:
    built = EXTENSION / "dist" / "extension.js"
    assert built.is_file(), (
        f"{built}: missing; tools/test.sh builds it "
        "(cd viewer/lichtblick && npm ci && npm run build)"
    )
    done = _tool(tmp_path / "fresh.foxe")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "fresh.foxe").read_bytes() == FOXE.read_bytes(), (
        f"{FOXE} is not the pack of the current build: run python tools/pack_extension.py"
    )


def test_the_loader_s_rules_as_written_here_refuse_what_lichtblick_refuses() -> None:
    with pytest.raises(ValueError, match="missing name"):
        loader_info({"publisher": "p", "displayName": "d"})
    with pytest.raises(ValueError, match="missing publisher"):
        loader_info({"name": "follower", "displayName": "d"})
    assert loader_info({"name": "@Team-UI/Follower", "displayName": "d"}) == {
        "id": "TeamUI.follower",
        "qualifiedName": "d",
    }


@pytest.mark.parametrize(
    ("package", "said"),
    [
        (
            {"name": ""},
            "package.json: name: missing (Lichtblick: 'Invalid extension: missing name')",
        ),
        (
            {"publisher": ...},
            "package.json: publisher: missing, and the name has no @scope/ "
            "(Lichtblick: 'Invalid extension: missing publisher')",
        ),
        (
            {"displayName": "teleop ui"},
            "package.json: displayName: 'teleop ui' cannot name a panel in a layout "
            "(<displayName>.<panel>!<id>: no '!', '.' or space, not empty)",
        ),
        ({"displayName": "a!b"}, "package.json: displayName: 'a!b' cannot name a panel"),
        (
            {"main": "./dist/index.js"},
            "package.json: main: must be ./dist/extension.js, the file the web app loads",
        ),
    ],
)
def test_a_package_lichtblick_would_refuse_is_refused_by_file_and_field_and_nothing_written(
    tmp_path: Path, package: dict[str, Any], said: str
) -> None:
    source = _source(tmp_path / "ext", **package)
    out = tmp_path / "out.foxe"
    out.write_bytes(b"the operator's earlier file")
    done = _tool(out, "--source", source)
    assert done.returncode == 2
    assert done.stderr.startswith(f"pack_extension: {source / said}")
    assert out.read_bytes() == b"the operator's earlier file"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ext", "out.foxe"]


def test_a_scoped_name_is_its_own_publisher(tmp_path: Path) -> None:
    source = _source(tmp_path / "ext", name="@teleop-ui/follower", publisher=...)
    assert _tool(tmp_path / "out.foxe", "--source", source).returncode == 0


def test_an_unbuilt_extension_is_refused_with_how_to_build_it(tmp_path: Path) -> None:
    source = _source(tmp_path / "ext")
    (source / "dist" / "extension.js").unlink()
    done = _tool(tmp_path / "out.foxe", "--source", source)
    assert (done.returncode, done.stderr) == (
        2,
        f"pack_extension: {source / 'dist' / 'extension.js'}: missing "
        "(build it: cd viewer/lichtblick && npm ci && npm run build)\n",
    )
    assert not (tmp_path / "out.foxe").exists()


def test_a_runaway_build_is_refused_not_packed(tmp_path: Path) -> None:
    source = _source(tmp_path / "ext")
    (source / "dist" / "extension.js").write_bytes(b"x" * (5 * 1024 * 1024))
    done = _tool(tmp_path / "out.foxe", "--source", source)
    assert done.returncode == 2
    assert "5,242,880 bytes, more than 4,194,304" in done.stderr


def test_a_package_json_that_is_not_json_is_refused(tmp_path: Path) -> None:
    source = _source(tmp_path / "ext")
    (source / "package.json").write_text('{"name": "teleop-ui-follower",')
    done = _tool(tmp_path / "out.foxe", "--source", source)
    assert done.returncode == 2
    assert done.stderr.startswith(f"pack_extension: {source / 'package.json'}: not JSON: ")
