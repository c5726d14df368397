"""Where ``$(find pkg)`` leads (solver.identify.xacro.packages): packages beside the description,
then on the package path, then on ROS_PACKAGE_PATH, the first found winning; no link followed."""

from __future__ import annotations

from pathlib import Path

from solver.identify.xacro import find_packages, package_path_from_env
from solver.identify.xacro.packages import own_package_root

PACKAGE_XML = (
    '<?xml version="1.0"?><package format="2"><name>{name}</name>'
    "<version>0.0.0</version><description>d</description>"
    '<maintainer email="a@b.c">a</maintainer><license>MIT</license></package>'
)


def package(folder: Path, name: str) -> Path:
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(PACKAGE_XML.format(name=name))
    return folder


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


def test_the_first_package_of_a_name_found_wins_as_in_ros(tmp_path: Path) -> None:
    mine = package(tmp_path / "mine" / "tools", "tools")
    package(tmp_path / "ros" / "tools", "tools")
    package(tmp_path / "ros" / "nav", "nav")
    source = tmp_path / "elsewhere" / "r.urdf.xacro"
    found = find_packages(source, [tmp_path / "mine"], {"ROS_PACKAGE_PATH": str(tmp_path / "ros")})
    assert found == {"tools": str(mine.resolve()), "nav": str((tmp_path / "ros" / "nav").resolve())}


def test_a_link_in_the_package_path_is_never_followed(tmp_path: Path) -> None:
    package(tmp_path / "outside" / "secret", "secret")
    (tmp_path / "path").mkdir()
    (tmp_path / "path" / "linked").symlink_to(tmp_path / "outside", target_is_directory=True)
    assert find_packages(tmp_path / "r.urdf", [tmp_path / "path"], environ={}) == {}


def test_a_description_belongs_to_the_nearest_package_above_it_or_to_its_own_folder(
    tmp_path: Path,
) -> None:
    root = package(tmp_path / "src" / "robot_description", "robot_description")
    assert own_package_root(root / "urdf" / "parts" / "r.urdf.xacro") == root
    assert own_package_root(tmp_path / "loose" / "r.urdf.xacro") == tmp_path / "loose"
