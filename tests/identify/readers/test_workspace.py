"""The robot's workspace: its packages found around the description, read as text, bounded."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from solver.identify.readers import workspace as reader
from solver.identify.readers.workspace import (
    _uncommented,
    description_package,
    read_repository,
    read_workspace,
    workspace_of,
)


def package(folder: Path, name: str, files: dict[str, str] | None = None) -> Path:
    """A ROS package ``name`` in ``folder/name`` holding ``files`` (relative path -> text)."""
    root = folder / name
    root.mkdir(parents=True)
    (root / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n</package>\n'
    )
    for relative, text in (files or {}).items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def rover_workspace(tmp_path: Path) -> Path:
    """A description, a bringup that finds it and includes a navigation package, and another
    robot's package that runs navigation too; the description's package folder."""
    src = tmp_path / "ws" / "src"
    described = package(src, "rover_description", {"urdf/rover.urdf": "<robot name='rover'/>"})
    package(
        src,
        "rover_bringup",
        {
            "launch/bringup.launch.py": (
                "get_package_share_directory('rover_description')\n"
                "IncludeLaunchDescription('rover_navigation')\n"
            )
        },
    )
    package(src, "rover_navigation", {"launch/nav.launch.py": "nav2_bringup"})
    package(src, "drone_navigation", {"launch/nav.launch.py": "nav2_bringup"})
    package(src, "drone_description", {"urdf/drone.urdf": "<robot name='drone'/>"})
    return described


def read(described: Path, root: Path | None = None, robot: str | None = None) -> reader.Workspace:
    found = read_workspace(described, root, robot)
    assert found is not None
    return found


def test_the_description_package_is_the_nearest_folder_above_with_a_package_xml(
    tmp_path: Path,
) -> None:
    described = rover_workspace(tmp_path)
    assert description_package(described / "urdf" / "rover.urdf") == described


def test_a_file_in_no_package_has_no_package(tmp_path: Path) -> None:
    (tmp_path / "a" / "b").mkdir(parents=True)
    assert description_package(tmp_path / "a" / "b" / "robot.urdf") is None


def test_the_robots_packages_are_its_own_those_that_use_it_and_those_they_use(
    tmp_path: Path,
) -> None:
    found = read(rover_workspace(tmp_path))
    assert found.package == "rover_description"
    assert found.packages == ("rover_description", "rover_bringup", "rover_navigation")
    assert [f.path for f in found.files] == [
        "rover_bringup/launch/bringup.launch.py",
        "rover_navigation/launch/nav.launch.py",
    ]


def test_another_robots_package_is_not_read_however_much_it_holds(tmp_path: Path) -> None:
    found = read(rover_workspace(tmp_path))
    assert "drone_navigation" not in found.packages
    assert all(f.package != "drone_navigation" for f in found.files)


def beside_two_navigations(src: Path, described: str) -> Path:
    """The package ``described`` in ``src``, beside a Jackal's and a Husky's navigation
    packages (each runs move_base, neither names ``described``) and the Husky's description."""
    for robot in ("jackal", "husky"):
        package(src, f"{robot}_navigation", {"launch/amcl.launch": "<node pkg='move_base'/>"})
    package(src, "husky_description", {"urdf/husky.urdf.xacro": "<robot name='husky'/>"})
    return package(src, described)


def test_packages_named_for_the_robot_are_its_own_though_they_never_name_its_description(
    tmp_path: Path,
) -> None:
    described = beside_two_navigations(tmp_path / "src", "jackal_description")
    assert read(described).packages == ("jackal_description", "jackal_navigation")


def test_a_description_kept_beside_the_robots_description_package_takes_in_the_robots_packages(
    tmp_path: Path,
) -> None:
    # The URDF lives in jackal_control; jackal_description beside it names the robot, and
    # jackal_navigation is the robot's too. With no jackal_description, the name alone says
    # nothing of a robot (control packages are named ROBOT_control and ros_control alike).
    src = tmp_path / "src"
    described = beside_two_navigations(src, "jackal_control")
    assert read(described).packages == ("jackal_control",)
    package(src, "jackal_description")
    assert read(described).packages == (
        "jackal_control",
        "jackal_description",
        "jackal_navigation",
    )


def test_a_description_in_a_package_named_for_the_robot_its_urdf_names_takes_in_its_packages(
    tmp_path: Path,
) -> None:
    # No jackal_description: the URDF in jackal_bringup names the robot ``jackal``, and the
    # bringup's name begins with it; a URDF naming another robot takes in nothing more (one
    # the workspace holds no description of: a URDF naming ``husky`` is the Husky's, whose
    # description is there, and the workspace is then one robot's).
    described = beside_two_navigations(tmp_path / "src", "jackal_bringup")
    assert read(described, robot="Jackal").packages == ("jackal_bringup", "jackal_navigation")
    for robot in (None, "summit", "jackal_bringup"):
        assert read(described, robot=robot).packages == ("jackal_bringup",)
    # Named ``husky``: the only other description is the Husky's own, so the source workspace
    # is that robot's alone and read whole.
    assert read(described, robot="husky").packages == (
        "jackal_bringup",
        "husky_description",
        "husky_navigation",
        "jackal_navigation",
    )


def test_a_robot_named_as_no_robot_in_particular_names_no_packages(tmp_path: Path) -> None:
    for stem in ("robot", "mobile_robot"):
        described = beside_two_navigations(tmp_path / stem, f"{stem}_bringup")
        package(tmp_path / stem, f"{stem}_navigation")
        for nobody in ("", " ", stem, stem.title()):
            assert read(described, robot=nobody).packages == (f"{stem}_bringup",)


def test_of_the_stems_beside_it_and_the_robots_own_the_longest_names_the_robot(
    tmp_path: Path,
) -> None:
    src = tmp_path / "src"
    described = package(src / "m", "abb_irb_control")
    package(src / "a", "abb_description", {"urdf/yumi.xacro": "<robot name='yumi'/>"})
    package(src / "z", "abb_irb_description")
    package(src / "b", "abb_yumi_bringup", {"launch/a.launch": "<node pkg='move_base'/>"})
    assert read(described).packages == ("abb_irb_control", "abb_irb_description")
    # With no abb_irb_description, the URDF's name for the robot, abb_irb, is the longest.
    (src / "z" / "abb_irb_description" / "package.xml").unlink()
    assert read(described, robot="abb_irb").packages == ("abb_irb_control",)
    package(src / "n", "abb_irb_navigation")
    assert read(described, robot="abb_irb").packages == ("abb_irb_control", "abb_irb_navigation")


def test_a_name_inside_a_longer_word_is_no_use(tmp_path: Path) -> None:
    src = tmp_path / "src"
    described = package(src, "arm")
    package(src, "farm_tools", {"launch/a.launch": "<node pkg='farming_arms'/>"})
    package(src, "tractor_description", {"urdf/tractor.urdf": "<robot name='tractor'/>"})
    assert read(described).packages == ("arm",)


def test_build_test_and_hidden_folders_and_files_in_no_package_are_not_read(
    tmp_path: Path,
) -> None:
    src = tmp_path / "src"
    described = package(
        src,
        "rover_description",
        {
            "build/gen.py": "nav2_bringup",
            "test/test_nav.py": "nav2_bringup",
            ".git/config.yaml": "nav2_bringup",
            "launch/view.launch": "<launch/>",
        },
    )
    (src / "notes.py").write_text("rover_description nav2_bringup")
    assert [f.path for f in read(described).files] == ["rover_description/launch/view.launch"]


def test_links_are_never_followed(tmp_path: Path) -> None:
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "nav.launch.py").write_text("nav2_bringup")
    described = package(tmp_path / "src", "rover_description")
    os.symlink(outside / "nav.launch.py", described / "nav.launch.py")
    os.symlink(outside, described / "linked")
    assert read(described).files == ()


def test_a_fifo_is_passed_by_without_waiting_on_it(tmp_path: Path) -> None:
    described = package(tmp_path / "src", "rover_description", {"a.yaml": "x: 1"})
    os.mkfifo(described / "b.launch")
    assert [f.path for f in read(described).files] == ["rover_description/a.yaml"]


def test_xml_comments_are_removed_from_launch_files(tmp_path: Path) -> None:
    described = package(
        tmp_path / "src",
        "rover_description",
        {"launch/a.launch": "<launch><!-- <node pkg='move_base'/> --><arg/></launch>"},
    )
    assert read(described).files[0].text == "<launch><arg/></launch>"


def test_a_block_of_encoded_data_is_left_out_and_the_code_around_it_kept(tmp_path: Path) -> None:
    blob = "".join(f"{n}mIK{'x_Z9?' * 14}\n" for n in range(3))
    described = package(
        tmp_path / "src",
        "rover_description",
        {"get.py": f'import base64\nDATA = b"""\n{blob}"""\nmain()\n'},
    )
    assert read(described).files[0].text == 'import base64\nDATA = b"""\n"""\nmain()\n'
    # At the end of a file with no line break after it, too.
    ending = package(tmp_path / "ws2", "rover_description", {"b.py": f"x = 1\n{blob.rstrip()}"})
    assert read(ending).files[0].text == "x = 1\n"


def test_long_lines_of_code_that_space_their_words_or_stand_alone_are_kept(
    tmp_path: Path,
) -> None:
    spaced = "ik = solve_ik(target_pose, seed=current_joint_positions, timeout=0.05)\n" * 3
    alone = f"{'pub=rospy.Publisher(' * 4}\nx = 1\n{'ik_solver=IKSolver(' * 4}\n"
    # Code written with no space, three lines in a row: its calls, lists and quotes say so.
    unspaced = "pub=rospy.Publisher('/mobile_base/commands/velocity',Twist,queue_size=10)\n" * 3
    described = package(
        tmp_path / "src", "rover_description", {"a.py": spaced, "b.py": alone, "c.py": unspaced}
    )
    assert [f.text for f in read(described).files] == [spaced, alone, unspaced]


def test_an_unclosed_comment_runs_to_the_end_of_the_text() -> None:
    assert _uncommented("a<!--b-->c<!--d") == "ac"
    assert _uncommented("<!--" * 100_000) == ""


def test_a_file_is_read_up_to_its_bound(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(reader, "MAX_FILE_BYTES", 10)
    described = package(tmp_path / "src", "rover_description", {"a.yaml": "0123456789nav2"})
    assert read(described).files[0].text == "0123456789"


def test_past_the_file_bound_a_located_warning_says_the_rest_is_not_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(reader, "MAX_FILES", 2)
    described = package(
        tmp_path / "src", "rover_description", {f"{n}.yaml": "x: 1" for n in "abcd"}
    )
    found = read(described)
    assert len(found.files) == 2
    assert found.notes == (
        f"workspace {tmp_path / 'src'}: more than 2 files; the rest of it is not read "
        "(docs/identify.md, The robot's packages)",
    )
    assert not found.complete


def test_past_the_entry_bound_the_walk_stops_with_a_warning(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(reader, "MAX_ENTRIES", 4)
    described = package(tmp_path / "src", "rover_description", {"a.yaml": "x: 1"})
    for name in "bcde":
        package(tmp_path / "src", f"rover_{name}", {"a.yaml": "rover_description"})
    found = read(described)
    assert "more than 4 entries" in found.notes[0]
    assert found.packages == ("rover_description",)


def test_a_package_xml_without_a_name_is_no_package(tmp_path: Path) -> None:
    folder = tmp_path / "src" / "nameless"
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text("<package format='3'></package>")
    assert read_workspace(folder) is None


ROSBUILD_MANIFEST = """<!-- a rosbuild package: ROS 1 before catkin -->
<package>
  <description brief="navigation">Moves the vehicle from point to point</description>
  <depend package="move_base"/>
</package>
"""


def test_a_rosbuild_package_is_named_by_its_folder_and_read(tmp_path: Path) -> None:
    # ROS 1 packages before catkin (to 2013) have a manifest.xml and no package.xml.
    folder = tmp_path / "stack" / "auv_navigation"
    (folder / "description").mkdir(parents=True)
    (folder / "launch").mkdir()
    (folder / "manifest.xml").write_text(ROSBUILD_MANIFEST)
    (folder / "launch" / "move_base.launch").write_text('<node pkg="move_base" type="move_base"/>')
    assert description_package(folder / "description" / "auv.urdf") == folder
    found = read(folder)
    assert found.package == "auv_navigation"
    assert [f.path for f in found.files] == ["auv_navigation/launch/move_base.launch"]


@pytest.mark.parametrize(
    "text",
    [
        '<?xml version="1.0"?><manifest xmlns:android="http://x"><application/></manifest>',
        "<assembly><package>not a ROS package</package></assembly>",
        "<!-- <package> -->\n<manifest/>",
    ],
)
def test_a_manifest_xml_of_another_tool_is_no_package(text: str, tmp_path: Path) -> None:
    folder = tmp_path / "app"
    folder.mkdir()
    (folder / "manifest.xml").write_text(text)
    assert description_package(folder / "robot.urdf") is None
    assert read_workspace(folder) is None


def test_a_workspace_that_does_not_exist_leaves_the_package_read_alone(tmp_path: Path) -> None:
    described = package(tmp_path / "src", "rover_description", {"a.yaml": "x: 1"})
    found = read(described, tmp_path / "no such folder")
    assert found.packages == ("rover_description",)
    assert [f.package for f in found.files] == ["rover_description"]


def test_a_dependency_shared_with_another_robot_brings_none_of_that_robots_packages(
    tmp_path: Path,
) -> None:
    src = tmp_path / "src"
    described = package(src, "rover_description", {"launch/sim.launch": "field_worlds"})
    package(src, "field_worlds")
    package(
        src,
        "drone_gazebo",
        {"launch/sim.launch": "field_worlds drone_navigation", "urdf/drone.urdf": "<robot/>"},
    )
    package(src, "drone_navigation", {"launch/nav.launch": "move_base"})
    assert read(described).packages == ("rover_description", "field_worlds")


def test_a_name_most_packages_write_is_no_evidence_that_its_package_is_used(
    tmp_path: Path,
) -> None:
    src = tmp_path / "src"
    described = package(src, "rover_description")
    launch = "rover_description robot_description robot_state_publisher"
    package(src, "rover_bringup", {"launch/a.launch": launch})
    for name in ("arm_bringup", "cam_bringup", "lidar_bringup", "sim_bringup"):
        package(src, name, {"launch/a.launch": "robot_description"})
    package(
        src,
        "robot_description",
        {"launch/display.launch": "move_base", "urdf/other.urdf": "<robot name='other'/>"},
    )
    assert read(described).packages == ("rover_description", "rover_bringup")


def test_a_neighbours_robot_description_parameter_does_not_use_a_package_of_that_name(
    tmp_path: Path,
) -> None:
    # A repository of demos: the rover's description package is named like the parameter every
    # launch file sets; the arm's demo sets its own parameter and plans with a pose goal.
    src = tmp_path / "src"
    described = package(src, "robot_description")
    launch = (
        "robot_description = {'robot_description': doc.toxml()}\n"
        "Node(package='robot_state_publisher', parameters=[robot_description])\n"
        "Node(package='gazebo_ros', arguments=['-topic', '/robot_description'])\n"
    )
    package(src, "arm_demo", {"launch/arm.launch.py": launch, "urdf/arm.urdf": "<robot/>"})
    assert read(described).packages == ("robot_description",)


@pytest.mark.parametrize(
    "reference",
    [
        "$(find-pkg-share robot_description)/launch/rsp.launch.py",
        "$(find robot_description)/urdf/rover.xacro",
        "get_package_share_directory('robot_description')",
        'FindPackageShare(package="robot_description")',
        "package://robot_description/meshes/base.dae",
        "Node(package='robot_description', executable='state_publisher')",
        "pkg_name = 'robot_description'",
        "roslaunch robot_description display.launch",
        "ros2 launch robot_description rsp.launch.py",
        'ros::package::getPath("robot_description")',
    ],
)
def test_a_package_named_like_the_parameter_is_used_where_a_file_names_it_as_a_package(
    tmp_path: Path, reference: str
) -> None:
    src = tmp_path / "src"
    described = package(src, "robot_description")
    package(src, "rover_gazebo", {"launch/sim.launch": reference})
    assert read(described).packages == ("robot_description", "rover_gazebo")


@pytest.mark.parametrize(
    "assignment",
    ["robot_description_pkg = 'robot_description'", 'description_package = "robot_description"'],
)
def test_a_package_named_like_the_parameter_is_used_where_a_variable_named_for_a_package_holds_it(
    tmp_path: Path, assignment: str
) -> None:
    # A bringup keeps the package's name in a variable it finds the package with; another
    # package of the repository holds a description too (a simulated opponent), so the
    # repository is not one robot's.
    src = tmp_path / "src"
    described = package(src, "robot_description")
    launch = f"{assignment}\nshare = FindPackageShare({assignment.split(maxsplit=1)[0]})\n"
    package(src, "rover_bringup", {"launch/rover.launch.py": launch})
    package(src, "arena_gazebo", {"models/opponent.xacro": "<robot/>"})
    assert read(described).packages == ("robot_description", "rover_bringup")


@pytest.mark.parametrize(
    "export",
    [
        "<export><metapackage/></export>",
        "<export>\n  <metapackage />\n</export>",
        "<export><metapackage></metapackage></export>",
    ],
)
def test_a_metapackage_grouping_every_robot_of_a_repository_uses_none_of_them(
    tmp_path: Path, export: str
) -> None:
    src = tmp_path / "src"
    described = package(src, "irb5400_support", {"urdf/irb5400.xacro": "<robot/>"})
    group = package(src, "vendor")
    (group / "package.xml").write_text(
        "<package><name>vendor</name><exec_depend>irb5400_support</exec_depend>"
        f"<exec_depend>irb2400_moveit_config</exec_depend>{export}</package>"
    )
    package(
        src,
        "irb2400_moveit_config",
        {"launch/demo.launch": "move_group", "config/irb2400.urdf.xacro": "<robot/>"},
    )
    assert read(described).packages == ("irb5400_support",)


@pytest.mark.parametrize(
    "where",
    [
        "<description>not a <metapackage/></description><export><build_type/></export>",
        "<!-- <export><metapackage/></export> -->",
    ],
    ids=["outside its export", "in a comment"],
)
def test_a_metapackage_tag_not_exported_leaves_a_package_that_uses_its_names(
    tmp_path: Path, where: str
) -> None:
    src = tmp_path / "src"
    described = package(src, "irb5400_support")
    bringup = package(src, "cell_bringup", {"launch/cell.launch": "irb5400_support"})
    (bringup / "package.xml").write_text(
        f"<package><name>cell_bringup</name><exec_depend>irb5400_support</exec_depend>{where}"
        "</package>"
    )
    assert read(described).packages == ("irb5400_support", "cell_bringup")


def test_a_generic_stem_names_no_robot(tmp_path: Path) -> None:
    src = tmp_path / "src"
    described = package(src, "robot_description")
    package(src, "robot_localization", {"launch/ekf.launch": "x"})
    package(src, "arm_description", {"urdf/arm.urdf": "<robot name='arm'/>"})
    assert read(described).packages == ("robot_description",)


def test_two_packages_of_one_name_are_both_read(tmp_path: Path) -> None:
    src = tmp_path / "src"
    described = package(src, "rover_description")
    for folder in ("ros1", "ros2"):
        package(src / folder, "rover_bringup", {"launch/a.launch": f"rover_description {folder}"})
    found = read(described)
    assert [f.path for f in found.files] == [
        "ros1/rover_bringup/launch/a.launch",
        "ros2/rover_bringup/launch/a.launch",
    ]


def test_the_robots_packages_are_read_before_a_vendored_library_spends_the_bound(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(reader, "MAX_FILES", 3)
    src = tmp_path / "src"
    described = package(src, "rover_description")
    package(src, "AAA_autopilot", {f"{n}.cpp": "waypoint" for n in range(10)})
    package(src, "rover_navigation", {"launch/nav.launch": "move_base"})
    found = read(described)
    assert found.packages == ("rover_description", "rover_navigation")
    assert [f.path for f in found.files] == ["rover_navigation/launch/nav.launch"]
    assert not found.complete


def test_ros1_scripts_without_a_suffix_are_read(tmp_path: Path) -> None:
    described = package(
        tmp_path / "src",
        "rover_description",
        {"scripts/teleop": "#!/usr/bin/env python\n", "meshes/base": "solid"},
    )
    assert [f.path for f in read(described).files] == ["rover_description/scripts/teleop"]


def test_a_nodes_headers_are_read_and_a_vendors_c_header_is_not(tmp_path: Path) -> None:
    # A node class is often written whole in its header, in include/<package>/ (a ROS 2
    # .hpp, a ROS 1 .h); a .h elsewhere is mostly a vendor's SDK.
    described = package(
        tmp_path / "src",
        "arm_controller",
        {
            "include/arm_controller/node.hpp": "create_subscription",
            "include/arm_controller/goal_publisher.h": "subscribe(goal)",
            "include/sdk/can.h": "struct frame;",
            "src/can.h": "struct frame;",
        },
    )
    assert [f.path for f in read(described).files] == [
        "arm_controller/include/arm_controller/goal_publisher.h",
        "arm_controller/include/arm_controller/node.hpp",
    ]


def test_whole_line_comments_of_code_are_left_out_and_the_code_kept(tmp_path: Path) -> None:
    described = package(
        tmp_path / "src",
        "rover_navigation",
        {
            "scripts/goals.py": (
                "#!/usr/bin/env python\n  # go_to_pose(x, y)\nrun()  # trailing\na\x0b#b\n"
            ),
            "src/node.cpp": "#include <rclcpp/rclcpp.hpp>\n// move_base\nspin(node);\n",
        },
    )
    texts = {f.path: f.text for f in read(described).files}
    assert texts == {
        "rover_navigation/scripts/goals.py": "#!/usr/bin/env python\nrun()  # trailing\na\x0b#b\n",
        "rover_navigation/src/node.cpp": "#include <rclcpp/rclcpp.hpp>\nspin(node);\n",
    }


def test_the_workspace_is_the_src_folder_above_a_repository(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    described = package(src / "rover", "rover_description")
    package(src / "rover_robot", "rover_bringup", {"launch/a.launch": "rover_description"})
    assert workspace_of(described) == src
    assert read(described).packages == ("rover_description", "rover_bringup")
    assert workspace_of(tmp_path / "repo" / "pkg") == tmp_path / "repo"


def installed(prefix: Path, name: str, files: dict[str, str] | None = None) -> Path:
    """A package installed under ``prefix`` as colcon installs it, ``PREFIX/share/NAME``."""
    return package(prefix / "share", name, files)


def test_an_installed_description_is_read_with_the_packages_installed_beside_it(
    tmp_path: Path,
) -> None:
    # colcon's isolated install: install/NAME/share/NAME, a build folder beside it.
    install = tmp_path / "ws" / "install"
    described = installed(install / "rover_description", "rover_description")
    installed(install / "rover_bringup", "rover_bringup", {"launch/a.launch": "rover_description"})
    package(tmp_path / "ws" / "build", "rover_bringup", {"launch/b.launch": "rover_description"})
    assert workspace_of(described) == install
    found = read(described)
    assert found.packages == ("rover_description", "rover_bringup")
    assert [f.path for f in found.files] == ["rover_bringup/share/rover_bringup/launch/a.launch"]
    # A merged install (or /opt/ros/DISTRO): the share folder.
    merged = installed(tmp_path / "opt", "dog_description")
    installed(tmp_path / "opt", "dog_bringup", {"launch/a.launch": "dog_description"})
    assert workspace_of(merged) == tmp_path / "opt" / "share"
    assert read(merged).packages == ("dog_description", "dog_bringup")


def test_a_skipped_folder_holding_the_description_is_walked_and_no_other(tmp_path: Path) -> None:
    # A repository that commits its install space, read from its top.
    repo = tmp_path / "repo"
    described = installed(repo / "install" / "car_description", "car_description")
    installed(
        repo / "install" / "car_bringup", "car_bringup", {"launch/a.launch": "car_description"}
    )
    package(repo / "build", "car_teleop", {"launch/t.launch": "car_description"})
    package(repo / "src" / "test", "car_tests", {"launch/t.launch": "car_description"})
    assert read(described, repo).packages == ("car_description", "car_bringup")


def test_a_share_folder_outside_an_install_space_is_no_install_prefix(tmp_path: Path) -> None:
    described = installed(tmp_path / "home" / "robot_description", "robot_description")
    package(tmp_path / "home" / "thesis", "exp_bringup", {"launch/a.launch": "robot_description"})
    assert workspace_of(described) == described.parent
    assert read(described).packages == ("robot_description",)


def test_only_the_install_space_a_description_lies_in_is_walked(tmp_path: Path) -> None:
    # A description kept in a test folder: the folder stays skipped for its neighbours.
    src = tmp_path / "ws" / "src"
    fixture = package(src / "urdf_tools" / "test", "fixture_description")
    package(src / "urdf_tools" / "test", "test_planning", {"a.launch": "fixture_description"})
    assert read(fixture, src).packages == ("fixture_description",)
    # Another install space beside the one read is not walked.
    repo = tmp_path / "repo"
    described = installed(repo / "install" / "car_description", "car_description")
    package(repo / "old" / "install", "car_teleop", {"launch/t.launch": "car_description"})
    assert read(described, repo).packages == ("car_description",)


@pytest.mark.parametrize("named", [False, True], ids=["found", "named"])
def test_an_install_prefix_is_walked_in_its_share_folder_alone(
    named: bool, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Libraries and headers beside share/ belong to no package: listing them would spend the
    walk's bound and leave the robot's packages read in part. Named as the workspace, an
    install space's libraries are no files in no package of the robot's either."""
    monkeypatch.setattr(reader, "MAX_ENTRIES", 200)
    install = tmp_path / "ws" / "install"
    described = installed(install / "dog_description", "dog_description")
    installed(install / "dog_bringup", "dog_bringup", {"launch/a.launch": "dog_description"})
    for prefix in ("dog_description", "dog_bringup"):
        for folder in ("lib", "include"):
            many = install / prefix / folder / prefix
            many.mkdir(parents=True)
            for n in range(150):
                (many / f"f{n}.py").write_text("nav2_bringup")
    found = read(described, install if named else None)
    assert found.complete
    assert found.packages == ("dog_description", "dog_bringup")


def test_a_named_install_spaces_setup_scripts_are_no_files_of_the_robots(tmp_path: Path) -> None:
    install = tmp_path / "ws" / "install"
    described = installed(install / "dog_description", "dog_description")
    for name in ("setup.sh", "local_setup.sh", "_local_setup_util_sh.py"):
        (install / name).write_text("nav2_bringup")
    for top in (install, tmp_path / "ws"):
        assert read(described, top).packages == ("dog_description",)


def test_a_repository_inside_an_install_prefix_is_read_whole(tmp_path: Path) -> None:
    # A simulator's repository installed as a prefix: its files in no package are its own.
    repo = tmp_path / "install" / "simrepo"
    for relative in ("models/bot.urdf", "bin/teleop.py", "lib/ctl.py", "share/x.yaml"):
        (repo / relative).parent.mkdir(parents=True, exist_ok=True)
        (repo / relative).write_text("<robot name='bot'/>" if relative.endswith("urdf") else "")
    found = read_repository(repo, repo / "models" / "bot.urdf", "bot")
    assert found is not None
    assert sorted(f.path for f in found.files) == ["bin/teleop.py", "lib/ctl.py", "share/x.yaml"]


def test_a_source_folder_shaped_like_an_install_prefix_is_walked_whole(tmp_path: Path) -> None:
    repo = tmp_path / "ws" / "src" / "myrepo"
    described = package(repo, "rover_description")
    package(repo, "rover_navigation", {"launch/nav.launch": "rover_description move_base"})
    (repo / "share").mkdir()
    (repo / "lib").mkdir()
    assert read(described).packages == ("rover_description", "rover_navigation")


def test_folders_deeper_than_the_bound_are_not_walked_and_a_note_says_so(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(reader, "MAX_DEPTH", 2)
    described = package(
        tmp_path / "src", "rover_description", {"a/b.yaml": "x: 1", "a/b/c/d.yaml": "x: 1"}
    )
    found = read(described)
    assert [f.path for f in found.files] == ["rover_description/a/b.yaml"]
    assert "folders deeper than 2 levels are not walked" in found.notes[0]


def test_a_package_xml_that_is_a_folder_or_a_fifo_is_no_package(tmp_path: Path) -> None:
    folder = tmp_path / "src" / "odd"
    (folder / "package.xml").mkdir(parents=True)
    assert read_workspace(folder) is None
    other = tmp_path / "src" / "odder"
    other.mkdir()
    os.mkfifo(other / "package.xml")
    assert read_workspace(other) is None


def test_many_packages_shown_are_cut_with_a_count(tmp_path: Path) -> None:
    src = tmp_path / "src"
    described = package(src, "rover_description")
    for n in range(20):
        package(src, f"user_{n:02d}", {"a.launch": "rover_description"})
    found = read(described)
    assert len(found.packages) == 21
    assert found.shown_packages.endswith(", user_10 and 9 more")


def test_a_manifest_of_many_unclosed_exports_is_read_once_through() -> None:
    manifest = "<package><name>x</name>" + "<export>" * 20_000 + "</package>"
    assert not reader._exports_metapackage(manifest)
    assert reader._exports_metapackage(manifest + "<export><metapackage/></export>")


@pytest.mark.parametrize(
    ("manifest", "meta"),
    [
        ("<export /><description>a <metapackage/></description>", False),
        ("<export/><metapackage/>", False),
        ('<export lang="en">\n<metapackage />\n</export >', True),
        ("<exports><metapackage/></exports>", False),
    ],
)
def test_only_a_metapackage_inside_an_export_block_counts(manifest: str, meta: bool) -> None:
    assert reader._exports_metapackage(manifest) is meta


def one_robots_repository(src: Path) -> Path:
    """A repository of one robot in ``src``: its description package, named like the
    parameter and named as a package by none of the others, its navigation package and a
    mission package that sends it navigation goals; the description's package folder."""
    described = package(src, "robot_description", {"urdf/amr.urdf.xacro": "<robot name='amr'/>"})
    package(src, "robot_navigation", {"config/nav2_params.yaml": "bt_navigator:"})
    package(src, "mission_manager", {"mission_manager/node.py": "NavigateToPose"})
    return described


def test_a_workspace_where_no_other_package_holds_a_description_is_all_the_robots(
    tmp_path: Path,
) -> None:
    found = read(one_robots_repository(tmp_path / "ws" / "src"))
    assert found.packages == ("robot_description", "mission_manager", "robot_navigation")
    assert found.neighbours == ()


def test_a_simulators_ros_interface_vendored_in_a_one_robot_workspace_is_not_the_robots(
    tmp_path: Path,
) -> None:
    src = tmp_path / "ws" / "src"
    described = one_robots_repository(src)
    plugin = {"src/gazebo_ros_force_system.cpp": "target_pose = model->WorldPose();"}
    package(src / "gazebo_ros_pkgs", "gazebo_ros", plugin)
    assert read(described).packages == (
        "robot_description",
        "mission_manager",
        "robot_navigation",
    )


def test_a_simulators_ros_interface_a_robots_package_uses_is_not_the_robots(
    tmp_path: Path,
) -> None:
    described = rover_workspace(tmp_path)
    package(described.parent, "gazebo_ros", {"src/api_plugin.cpp": "target_pose = pose;"})
    uses = "<package><name>rover_gazebo</name><depend>rover_description</depend>"
    package(
        described.parent,
        "rover_gazebo",
        {"package.xml": uses + "<depend>gazebo_ros</depend></package>"},
    )
    found = read(described)
    assert found is not None
    assert "rover_gazebo" in found.packages
    assert "gazebo_ros" not in found.packages


def repository_with_loose_files(root: Path) -> Path:
    """A repository at ``root`` holding one robot's description package and, in no package,
    its top-level navigation launch file and parameters; the description's package folder."""
    files = {"urdf/ugv.urdf": "<robot name='ugv'/>", "launch/view.launch": "<launch/>"}
    described = package(root, "robot_description", files)
    (root / "launch").mkdir()
    (root / "launch" / "nav.launch.py").write_text("nav2_bringup")
    (root / "config").mkdir()
    (root / "config" / "nav2_params.yaml").write_text("bt_navigator:")
    return described


def test_files_in_no_package_of_a_named_one_robot_repository_are_the_robots(
    tmp_path: Path,
) -> None:
    described = repository_with_loose_files(tmp_path / "repo")
    found = read(described, tmp_path / "repo", robot="ugv")
    assert found.packages == ("robot_description", reader.NO_PACKAGE)
    assert [(f.package, f.path) for f in found.files] == [
        ("robot_description", "robot_description/launch/view.launch"),
        (reader.NO_PACKAGE, "config/nav2_params.yaml"),
        (reader.NO_PACKAGE, "launch/nav.launch.py"),
    ]


def test_files_in_no_package_are_shown_under_no_name_a_package_or_a_rule_could_have(
    tmp_path: Path,
) -> None:
    # A clone folder named like a gait package, or like a package of the workspace.
    for folder in ("quadruped_walking", "robot_description"):
        described = repository_with_loose_files(tmp_path / folder / "x")
        found = read(described, tmp_path / folder / "x", robot="ugv")
        assert found.packages == ("robot_description", reader.NO_PACKAGE)


def test_files_in_no_package_are_read_with_what_the_packages_left_of_the_bounds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(reader, "MAX_FILES", 3)
    described = repository_with_loose_files(tmp_path / "repo")
    for n in range(5):
        (tmp_path / "repo" / "launch" / f"more{n}.launch.py").write_text("nav2_bringup")
    found = read(described, tmp_path / "repo", robot="ugv")
    assert found.complete
    assert len([f for f in found.files if f.package == reader.NO_PACKAGE]) == 2


def test_files_in_no_package_beside_a_macro_file_are_not_read(tmp_path: Path) -> None:
    described = repository_with_loose_files(tmp_path / "repo")
    (tmp_path / "repo" / "urdf").mkdir()
    (tmp_path / "repo" / "urdf" / "wheel.xacro").write_text("<robot/>")
    assert read(described, tmp_path / "repo", robot="ugv").packages == ("robot_description",)


def test_files_in_no_package_beside_a_copy_of_the_robots_own_description_are_read(
    tmp_path: Path,
) -> None:
    described = repository_with_loose_files(tmp_path / "repo")
    (tmp_path / "repo" / "ugv.urdf").write_text("<robot name='ugv'/>")
    found = read(described, tmp_path / "repo", robot="ugv")
    assert found.packages == ("robot_description", reader.NO_PACKAGE)


def test_files_in_no_package_beside_another_robots_description_are_not_read(
    tmp_path: Path,
) -> None:
    described = repository_with_loose_files(tmp_path / "repo")
    (tmp_path / "repo" / "models").mkdir()
    (tmp_path / "repo" / "models" / "drone.urdf").write_text("<robot name='drone'/>")
    found = read(described, tmp_path / "repo", robot="ugv")
    assert found.packages == ("robot_description",)


def test_files_in_no_package_of_a_workspace_found_around_the_description_are_not_read(
    tmp_path: Path,
) -> None:
    described = repository_with_loose_files(tmp_path / "ws" / "src")
    assert read(described, robot="ugv").packages == ("robot_description",)


def test_a_second_description_in_the_workspace_leaves_the_others_unread(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    described = one_robots_repository(src)
    package(src, "arm_description", {"urdf/arm.urdf": "<robot name='arm'/>"})
    assert read(described).packages == ("robot_description",)


def test_a_second_copy_of_the_robots_own_description_leaves_the_workspace_the_robots(
    tmp_path: Path,
) -> None:
    # The bringup package keeps the URDF made from the description's xacro, named for the
    # robot: the same robot's file, no other robot's.
    src = tmp_path / "ws" / "src"
    described = one_robots_repository(src)
    package(src, "amr_bringup", {"urdf/amr.urdf": "<robot name='amr'/>"})
    found = read(described, robot="amr")
    assert found.packages == (
        "robot_description",
        "amr_bringup",
        "mission_manager",
        "robot_navigation",
    )


def test_a_folder_that_is_no_source_workspace_is_nobodys_whole(tmp_path: Path) -> None:
    # Packages beside one another in a folder not named src (a share folder of installed
    # packages): only the caller, naming it the robot's workspace, makes it one robot's.
    described = one_robots_repository(tmp_path / "share")
    assert read(described).packages == ("robot_description",)
    named = read(described, root=tmp_path / "share")
    assert named.packages == ("robot_description", "mission_manager", "robot_navigation")


def files_of(found: reader.Workspace | None) -> list[str]:
    assert found is not None
    return [shipped.path for shipped in found.files]


def repository(root: Path, files: dict[str, str]) -> Path:
    """A repository at ``root`` holding ``files`` (relative path -> text) and no package."""
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def test_a_repository_of_one_description_is_read_whole_as_the_robots(tmp_path: Path) -> None:
    root = repository(
        tmp_path / "leg_sim",
        {"model/leg.urdf": "<robot name='leg'/>", "sim/sim.py": "inverse_kinematics(target)"},
    )
    found = read_repository(root, root / "model" / "leg.urdf", "leg")
    assert found is not None
    assert (found.package, found.packages, files_of(found)) == (
        "leg_sim",
        ("leg_sim",),
        ["sim/sim.py"],
    )


def test_of_a_repository_of_several_robots_only_the_files_naming_this_one_are_its(
    tmp_path: Path,
) -> None:
    root = repository(
        tmp_path / "gym",
        {
            "robots/go2_arx/go2_arx.urdf": "<robot name='go2_arx'/>",
            "robots/airbot/airbot.urdf": "<robot name='airbot'/>",
            "robots/leg/leg.urdf": "<robot name='leg'/>",
            "envs/go2_arx/config.py": "asset = 'go2_arx.urdf'",  # its file name
            "envs/go2_arx/robot.py": "from .go2_arx_config import Cfg",  # a name made of it
            "envs/airbot/airbot_robot.py": "ee_goal = 1",  # its path names airbot
            "envs/leg/sim.py": "p.loadURDF('leg.urdf')",  # leg, named by its file name alone
            "envs/play.py": "legs = 4",  # a plain word is no robot's name
        },
    )
    go2 = files_of(read_repository(root, root / "robots/go2_arx/go2_arx.urdf", "go2_arx"))
    assert go2 == ["envs/go2_arx/config.py", "envs/go2_arx/robot.py"]
    airbot = files_of(read_repository(root, root / "robots/airbot/airbot.urdf", "airbot"))
    assert airbot == ["envs/airbot/airbot_robot.py"]
    assert files_of(read_repository(root, root / "robots/leg/leg.urdf", "leg")) == [
        "envs/leg/sim.py"
    ]


def test_a_repository_named_robot_names_nothing_by_its_paths(tmp_path: Path) -> None:
    root = repository(
        tmp_path / "examples",
        {
            "a/robot.urdf": "<robot name='robot'/>",
            "b/robot.urdf": "<robot name='robot'/>",
            "robot/teleop.py": "teleop_twist_keyboard",
        },
    )
    assert files_of(read_repository(root, root / "a" / "robot.urdf", "robot")) == []


def test_the_ros_packages_inside_a_repository_are_read_as_a_workspaces(tmp_path: Path) -> None:
    root = repository(tmp_path / "ship", {"models/ship.urdf": "<robot name='ship'/>"})
    package(root, "ship_control", {"scripts/drive.py": "teleop_twist_keyboard"})
    found = read_repository(root, root / "models" / "ship.urdf", "ship")
    assert found is not None
    assert found.packages == ("ship", "ship_control")
    assert files_of(found) == ["ship_control/scripts/drive.py"]


def test_a_package_keeping_the_robots_urdf_made_from_the_repositorys_xacro_is_the_robots(
    tmp_path: Path,
) -> None:
    # The xacro source outside any package; the ROS package beside it holds the URDF made
    # from it (named for the robot), its drive node and its navigation.
    root = repository(tmp_path / "rover", {"xacro/common.urdf.xacro": "<robot name='rover'/>"})
    package(
        root,
        "rover_ros",
        {"rover.urdf": "<robot name='rover'/>", "launch/robot.py": "teleop_twist_joy"},
    )
    found = read_repository(root, root / "xacro" / "common.urdf.xacro", "rover")
    assert found is not None
    assert found.packages == ("rover", "rover_ros")
    assert files_of(found) == ["rover_ros/launch/robot.py"]
    other = read_repository(root, root / "xacro" / "common.urdf.xacro", "lander")
    assert other is not None
    assert other.packages == ("rover",)


def test_a_package_holding_a_description_named_like_the_robots_file_is_another_robots(
    tmp_path: Path,
) -> None:
    # Files named ``main`` or ``common`` may be any robot's: only the robot's own name counts.
    root = repository(tmp_path / "robots", {"rover/urdf/main.urdf.xacro": "<robot name='rover'/>"})
    package(root, "lander_description", {"urdf/main.urdf.xacro": "<robot name='lander'/>"})
    package(root, "lander_control", {"launch/drive.py": "teleop_twist_keyboard"})
    found = read_repository(root, root / "rover" / "urdf" / "main.urdf.xacro", "rover")
    assert found is not None
    assert found.packages == ("robots",)


def test_a_repository_that_is_no_folder_is_no_evidence(tmp_path: Path) -> None:
    assert read_repository(tmp_path / "gone", tmp_path / "gone" / "r.urdf") is None
