"""tools/rebuild_set_files.py makes the sets' files again from the repositories their rows name."""

from __future__ import annotations

import csv
import importlib.util
import os
import subprocess
import sys
from pathlib import Path
from types import ModuleType

from tests.identify.builders import manipulator

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "rebuild_set_files.py"

PACKAGE = """<?xml version="1.0"?>
<package format="3"><name>NAME</name><version>0.0.1</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
</package>
"""
XACRO = """<?xml version="1.0"?>
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="arm_name" default="short"/>
  <xacro:include filename="$(find demo_parts)/urdf/parts.xacro"/>
  <link name="base_link"/>
  <link name="$(arg arm_name)_link"/>
  <xacro:wheel side="left"/>
  <joint name="to_arm" type="revolute">
    <parent link="base_link"/><child link="$(arg arm_name)_link"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>
"""
PARTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side">
    <link name="${side}_wheel"/>
    <joint name="${side}_wheel_joint" type="continuous">
      <parent link="base_link"/><child link="${side}_wheel"/><axis xyz="0 1 0"/>
    </joint>
  </xacro:macro>
</robot>
"""
SRDF = (
    '<?xml version="1.0"?><robot name="demo">'
    '<group name="arm"><joint name="to_arm"/></group></robot>\n'
)


def load() -> ModuleType:
    spec = importlib.util.spec_from_file_location("rebuild_set_files", SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def git(folder: Path, *args: str) -> str:
    done = subprocess.run(
        ["git", "-C", str(folder), *args],
        capture_output=True,
        text=True,
        check=True,
        env={
            **os.environ,
            "GIT_AUTHOR_NAME": "t",
            "GIT_AUTHOR_EMAIL": "t@t",
            "GIT_COMMITTER_NAME": "t",
            "GIT_COMMITTER_EMAIL": "t@t",
        },
    )
    return done.stdout.strip()


def committed(work: Path) -> str:
    git(work, "init", "-q")
    git(work, "add", ".")
    git(work, "commit", "-q", "-m", "demo")
    return git(work, "rev-parse", "HEAD")


def mirrored_repository(mirror: Path) -> str:
    """owner/demo under ``mirror`` as the workplace's fetch leaves it, and other/parts, whose
    package its xacro finds though its rows never name it; owner/demo's commit."""
    # Two repositories hold demo_parts as deep: the one named like it is taken, not the copy
    # (whose macro would make no wheel) that comes first by name.
    for holder, parts_text in (
        ("aaa+vendored", PARTS.replace("_wheel", "_cog")),
        ("other+demo_parts", PARTS),
    ):
        parts = mirror / holder / "repo"
        (parts / "demo_parts" / "urdf").mkdir(parents=True)
        (parts / "demo_parts" / "package.xml").write_text(
            PACKAGE.replace("NAME", "demo_parts"), encoding="utf-8"
        )
        (parts / "demo_parts" / "urdf" / "parts.xacro").write_text(parts_text, encoding="utf-8")
        committed(parts)
    work = mirror / "owner+demo" / "repo"
    (work / "pkg" / "urdf").mkdir(parents=True)
    (work / "pkg" / "config").mkdir()
    (work / "pkg" / "package.xml").write_text(
        PACKAGE.replace("NAME", "demo_description"), encoding="utf-8"
    )
    (work / "pkg" / "urdf" / "demo.urdf.xacro").write_text(XACRO, encoding="utf-8")
    (work / "pkg" / "urdf" / "arm.urdf").write_text(manipulator().text(), encoding="utf-8")
    # A link to a link (listed before it) to a file.
    (work / "pkg" / "urdf" / "a_linked.urdf").symlink_to("z_link.urdf")
    (work / "pkg" / "urdf" / "z_link.urdf").symlink_to("arm.urdf")
    (work / "pkg" / "config" / "demo.srdf").write_text(SRDF, encoding="utf-8")
    return committed(work)


def labelled_set(folder: Path, commit: str) -> None:
    folder.mkdir(parents=True)
    rows = [
        {
            "robot": "demo",
            "file": "urdf/demo.urdf",
            "srdf": "srdf/demo.srdf",
            "source": f"github owner/demo@{commit[:8]} (MIT) pkg/urdf/demo.urdf.xacro "
            "[xacro->urdf with arm_name:=long, as its launch passes; paths=.../x dropped; "
            "SRDF verbatim copy of pkg/config/demo.srdf; meshes from ghost/absent@0123abcd]",
        },
        {
            "robot": "arm",
            "file": "urdf/arm.urdf",
            "srdf": "",
            "source": f"https://github.com/owner/demo @{commit}, pkg/urdf/a_linked.urdf [plain]",
            "kinematic_type": "Manipulator",
            "family": "arm",
        },
        {"robot": "pypi", "file": "urdf/p.urdf", "srdf": "", "source": "PyPI example 1.0 p.urdf"},
        {
            "robot": "gone",
            "file": "urdf/gone.urdf",
            "srdf": "",
            "source": f"github owner/demo@{commit[:8]} pkg/urdf/gone.urdf [plain URDF]",
        },
    ]
    columns = ["robot", "file", "srdf", "source", "kinematic_type", "family", "sensors"]
    columns += ["motion_controls", "motion_control_kinds", "sensor_tags"]
    with (folder / "truth.csv").open("w", encoding="utf-8", newline="") as stream:
        writer = csv.DictWriter(stream, columns, restval="")
        writer.writeheader()
        writer.writerows(rows)


def rebuild(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, str(SCRIPT), *args],
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        check=False,
    )


def test_a_source_names_the_repository_commit_file_arguments_and_srdf() -> None:
    tool = load()
    source = tool.parse_source(
        "github a/b@0123abcd (BSD, package.xml) src/b_description/urdf/b.urdf.xacro [xacro->urdf "
        "with use_gazebo:=true prefix:=left_ imu:='1 2 3', kinematics:=.../x.yaml, as "
        "launch/x.launch.py; SRDF b_moveit/config/b.srdf; $(find c_description) from github "
        "c/c@89abcdef, $(find d) resolved to d/d@deadbeef; use_gazebo:=false would drop the "
        "plugins; ns:='' tf:=<that package>/tf.yaml]",
        srdf=True,
    )
    assert source.repository == "a/b"
    assert source.commit == "0123abcd"
    assert source.path == "src/b_description/urdf/b.urdf.xacro"
    # The recipe's values: the first of each name, quoted ones whole.
    # An empty quoted value is a value; a placeholder the tool cannot fill is left out.
    assert source.args == (
        ("use_gazebo", "true"),
        ("prefix", "left_"),
        ("imu", "1 2 3"),
        ("ns", ""),
    )
    assert source.srdf == "b_moveit/config/b.srdf"
    # A second repository, named with "github" or bare.
    assert source.others == (("c/c", "89abcdef"), ("d/d", "deadbeef"))
    assert source.xacro
    assert tool.parse_source("PyPI example-robot-data 6.0.0 robots/x.urdf", srdf=False) is None


def test_a_file_the_licence_note_names_is_not_the_description() -> None:
    tool = load()
    source = tool.parse_source(
        "github a/b@0123abcd (LICENCE: BSD, in the header of old/b_v1.urdf (kept); no LICENSE "
        "file) src/b_description/urdf/b.urdf.xacro [xacro->urdf]",
        srdf=False,
    )
    assert source.path == "src/b_description/urdf/b.urdf.xacro"
    # How the file was made is read right after it, past a long note.
    made = tool.parse_source(
        "github a/b@0123abcd (BSD, as the package.xml of the description package says it, "
        "with no LICENSE file in the repository) urdf/b.urdf [xacro->urdf, no args]",
        srdf=False,
    )
    assert (made.path, made.xacro) == ("urdf/b.urdf", True)
    # A note left open, or one that names the only file, is read as the rest of the text.
    unclosed = tool.parse_source("github a/b@0123abcd (BSD urdf/b.urdf [plain URDF]", srdf=False)
    assert unclosed.path == "urdf/b.urdf"
    inside = tool.parse_source("github a/b@0123abcd (BSD; the file: urdf/b.urdf)", srdf=False)
    assert inside.path == "urdf/b.urdf"
    # Arguments, the SRDF and other repositories are read in the whole text, the note too.
    noted = tool.parse_source(
        "github a/b@0123abcd (BSD; with arm:=true as launch/a.launch passes it, SRDF "
        "moveit/b.srdf, $(find c) from github c/c@89abcdef) urdf/b.urdf.xacro [xacro->urdf]",
        srdf=True,
    )
    assert (noted.path, noted.args, noted.srdf, noted.others) == (
        "urdf/b.urdf.xacro",
        (("arm", "true"),),
        "moveit/b.srdf",
        (("c/c", "89abcdef"),),
    )


def test_a_description_kept_as_text_is_that_file_and_a_backups_name_is_none() -> None:
    tool = load()
    text = tool.parse_source("github a/b@0123abcd urdf/my_robot.urdf.txt [plain URDF]", srdf=False)
    assert (text.path, text.xacro) == ("urdf/my_robot.urdf.txt", False)
    backup = tool.parse_source("github a/b@0123abcd urdf/old.urdf.bak, urdf/b.urdf", srdf=False)
    assert backup.path == "urdf/b.urdf"


def test_a_file_xacro_expands_under_another_name_and_an_environment_it_sets_are_read() -> None:
    tool = load()
    source = tool.parse_source(
        "github a/b@0123abcd rotors/urdf/generic.gazebo [xacro->urdf, mav_name:=iris; "
        "environment unset except SPOT_ARM=1: the MIT licence]",
        srdf=False,
    )
    assert source.path == "rotors/urdf/generic.gazebo"
    assert source.xacro
    assert source.args == (("mav_name", "iris"), ("SPOT_ARM", "1"))
    upper = tool.parse_source(
        "github a/b@0123abcd (manifest.xml says BSD) robots/B.URDF [plain URDF]", srdf=False
    )
    assert upper.path == "robots/B.URDF"
    plain = tool.parse_source("github a/b@0123abcd urdf/b.urdf [plain URDF, not xacro]", srdf=False)
    assert not plain.xacro
    expanded = tool.parse_source(
        "github a/b@0123abcd urdf/b.urdf [xacro->urdf, no args]", srdf=False
    )
    assert expanded.xacro


def test_plain_says_a_urdf_is_copied_only_where_the_bracket_begins_with_it() -> None:
    tool = load()
    named = tool.parse_source(
        "github a/b@0123abcd urdf/plain_vehicle.urdf [xacro->urdf: the plain vehicle's launch]",
        srdf=False,
    )
    assert named.xacro
    run_on = tool.parse_source(
        "github a/b@0123abcd urdf/arm.urdf [xacro->urdf without arguments (a plain URDF)]",
        srdf=False,
    )
    assert run_on.xacro
    for copied in (
        "urdf/b.urdf [ Plain URDF, xacro output]",
        "urdf/b.urdf (plain URDF, the xacro output, copied)",
        "urdf/b.urdf with config/b.srdf.xacro [plain URDF]",
        "urdf/b.urdf plain URDF, the xacro output",
    ):
        assert not tool.parse_source(f"github a/b@0123abcd {copied}", srdf=False).xacro, copied


def test_a_description_path_with_spaces_is_read_whole_between_backquotes() -> None:
    tool = load()
    source = tool.parse_source(
        "github a/b@0123abcd (MIT) `Mechanical Design/Fusion to URDF/bot_description/urdf/"
        "bot.xacro` [xacro->urdf, no args]",
        srdf=False,
    )
    assert source.path == "Mechanical Design/Fusion to URDF/bot_description/urdf/bot.xacro"
    assert source.xacro
    # A path with no space is read as before, quoted or not.
    quoted = tool.parse_source("github a/b@0123abcd `urdf/b.urdf` [plain URDF]", srdf=False)
    assert quoted.path == "urdf/b.urdf"


def test_rows_are_made_from_the_mirrored_commit_and_those_that_cannot_be_are_said(
    tmp_path: Path,
) -> None:
    commit = mirrored_repository(tmp_path / "mirror")
    labelled_set(tmp_path / "tools" / "fresh_set_1", commit)
    out = tmp_path / "out"
    done = rebuild(
        "--mirror",
        str(tmp_path / "mirror"),
        "--out",
        str(out),
        "--set",
        str(tmp_path / "tools" / "fresh_set_1"),
    )
    assert done.returncode == 0, done.stderr
    made = (out / "fresh_set_1" / "urdf" / "demo.urdf").read_text(encoding="utf-8")
    # The source's argument is passed, and $(find ...) resolved in the mirrored repository
    # that has the package.
    assert 'link name="long_link"' in made
    assert 'joint name="left_wheel_joint" type="continuous"' in made
    # A symbolic link to a file of the tree is that file.
    assert (out / "fresh_set_1" / "srdf" / "demo.srdf").read_text(encoding="utf-8") == SRDF
    assert (out / "fresh_set_1" / "urdf" / "arm.urdf").read_text(
        encoding="utf-8"
    ) == manipulator().text()
    assert "fresh_set_1 pypi: not made: its source names no GitHub repository" in done.stderr
    assert "fresh_set_1 gone: not made: " in done.stderr
    assert "has no file pkg/urdf/gone.urdf" in done.stderr
    report = (out / "report.tsv").read_text(encoding="utf-8").splitlines()
    assert [line.split("\t")[2] for line in report[1:]] == ["yes", "yes", "no", "no"]
    # A second repository the mirror lacks is left out, and said.
    assert report[1].split("\t")[3] == (
        "without ghost/absent (not in the mirror); package demo_parts taken from other/demo_parts"
    )
    # One tree for the commit, however the rows spell it (8 hex digits, 40).
    assert [folder.name for folder in (out / "trees").iterdir() if "owner+demo" in folder.name] == [
        f"owner+demo@{commit}"
    ]
    tree = out / "trees" / f"owner+demo@{commit}" / "repo"  # the full hash
    assert (out / "workspaces.tsv").read_text(encoding="utf-8").splitlines()[0] == (
        f"fresh_set_1\tdemo\t{tree}\tpkg/urdf/demo.urdf.xacro"
    )


def test_a_row_not_made_keeps_no_file_of_an_earlier_run(tmp_path: Path) -> None:
    commit = mirrored_repository(tmp_path / "mirror")
    labelled = tmp_path / "tools" / "fresh_set_1"
    labelled_set(labelled, commit)
    out = tmp_path / "out"
    stale = out / "fresh_set_1" / "urdf" / "gone.urdf"
    stale.parent.mkdir(parents=True)
    stale.write_text("<robot name='stale'/>", encoding="utf-8")
    rebuild("--mirror", str(tmp_path / "mirror"), "--out", str(out), "--set", str(labelled))
    assert not stale.exists()
    assert (out / "fresh_set_1" / "urdf" / "demo.urdf").is_file()


def test_one_set_made_again_keeps_the_other_sets_lines(tmp_path: Path) -> None:
    commit = mirrored_repository(tmp_path / "mirror")
    first, second = tmp_path / "tools" / "fresh_set_1", tmp_path / "tools" / "fresh_set_2"
    labelled_set(first, commit)
    labelled_set(second, commit)
    out = tmp_path / "out"
    for labelled in (first, second):
        rebuild("--mirror", str(tmp_path / "mirror"), "--out", str(out), "--set", str(labelled))
    rebuild("--mirror", str(tmp_path / "mirror"), "--out", str(out), "--set", str(first))
    lines = (out / "workspaces.tsv").read_text(encoding="utf-8").splitlines()
    assert sorted(line.split("\t")[:2] for line in lines) == [
        ["fresh_set_1", "arm"],
        ["fresh_set_1", "demo"],
        ["fresh_set_2", "arm"],
        ["fresh_set_2", "demo"],
    ]
    report = (out / "report.tsv").read_text(encoding="utf-8").splitlines()
    assert len(report) == 1 + 2 * 4
    assert report[0].startswith("set\trobot\tmade")


def test_rows_that_cannot_be_made_here_are_listed_and_the_run_succeeds(tmp_path: Path) -> None:
    folder = tmp_path / "fresh_set_1"
    labelled_set(folder, "0123abcd")  # owner/demo is not mirrored: nothing could be made
    done = rebuild("--mirror", str(tmp_path), "--out", str(tmp_path / "out"), "--set", str(folder))
    assert done.returncode == 0, done.stderr
    assert "fresh_set_1 demo: not made: owner/demo is not under" in done.stderr
    assert "4 rows not made, 0 of them with their repository here" in done.stderr


def test_the_repositories_to_bring_are_listed_once_each(tmp_path: Path) -> None:
    labelled_set(tmp_path / "fresh_set_1", "0123abcd")
    done = rebuild("--repos", "--set", str(tmp_path / "fresh_set_1"))
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ["owner/demo", "ghost/absent"]


def test_the_measure_tool_reads_the_files_made_with_rebuilt(tmp_path: Path) -> None:
    commit = mirrored_repository(tmp_path / "mirror")
    labelled = tmp_path / "tools" / "fresh_set_1"
    labelled_set(labelled, commit)
    out = tmp_path / "out"
    rebuild("--mirror", str(tmp_path / "mirror"), "--out", str(out), "--set", str(labelled))
    measure = [sys.executable, str(ROOT / "tools" / "measure_identification.py")]
    done = subprocess.run(
        [*measure, "--set", str(labelled), "--rebuilt", str(out)],
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    family = next(line for line in done.stdout.splitlines() if line.startswith("| arm |"))
    # The rebuilt arm is measured (read right), not counted absent.
    assert [cell.strip() for cell in family.strip("|").split("|")][3:6] == [
        "1/1 (100%)",
        "1/1 (100%)",
        "0",
    ]
