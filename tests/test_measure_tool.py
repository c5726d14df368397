"""tools/measure_identification.py measures any labelled set, per family and per source."""

from __future__ import annotations

import csv
import importlib.util
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

from tests.identify.builders import (
    gazebo_sensor,
    manipulator,
    mobile_manipulator,
    model_plugin,
    pan_tilt_only,
    parallel_gripper,
    snake,
    ugv,
)

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "measure_identification.py"
SPLIT_SCRIPT = ROOT / "tools" / "split_identification.py"
COLUMNS = [
    "robot",
    "file",
    "source",
    "kinematic_type",
    "evidence",
    "sensors",
    "motion_controls",
    "motion_control_kinds",
    "srdf",
    "sensor_tags",
    "sensor_detail",
    "uncertainty_note",
    "family",
    "licence",
]


def write_truth(folder: Path, rows: list[dict[str, str]]) -> None:
    with (folder / "truth.csv").open("w", encoding="utf-8", newline="") as stream:
        writer = csv.DictWriter(stream, COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({column: row.get(column, "") for column in COLUMNS})


def measure(*args: str) -> str:
    environment = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run(
        [sys.executable, str(SCRIPT), *args],
        cwd=ROOT,
        env=environment,
        capture_output=True,
        text=True,
        check=True,
    )
    return done.stdout


def row_of(output: str, first: str, second: str) -> list[str]:
    for line in output.splitlines():
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        if cells[:2] == [first, second]:
            return cells[2:]
    raise AssertionError(f"no row {first} | {second} in:\n{output}")


def with_urdfs(folder: Path, **files: str) -> Path:
    """``folder`` with each of ``files`` (name -> URDF text) written as ``urdf/<name>.urdf``."""
    (folder / "urdf").mkdir(parents=True)
    for name, text in files.items():
        (folder / "urdf" / f"{name}.urdf").write_text(text, encoding="utf-8")
    return folder


def tiny_set(folder: Path) -> None:
    rover = ugv()
    rover.add(gazebo_sensor("base_link", "ray", "front_laser"))
    rover.add(model_plugin("drive", "libgazebo_ros_skid_steer_drive.so"))
    with_urdfs(folder, rover=rover.text(), arm=manipulator().text())
    rows = [
        {
            "robot": "rover",
            "file": "urdf/rover.urdf",
            "source": "github someone/rovers@abc urdf/rover.urdf.xacro",
            "kinematic_type": "UGV",
            "sensors": "lidar:1;camera:1",
            "motion_control_kinds": "Driving",
            "family": "mobile base",
        },
        {
            "robot": "arm_called_humanoid",
            "file": "urdf/arm.urdf",
            "source": "PyPI some-arms 1.0 arm.urdf",
            "kinematic_type": "Humanoid",
            "family": "arm",
        },
        {
            "robot": "boat",
            "file": "urdf/boat.urdf",
            "source": "github someone/boats@def boat.urdf.xacro",
            "kinematic_type": "Surface vessel",
            "family": "surface vessel",
        },
    ]
    write_truth(folder, rows)


def test_a_set_is_reported_per_family_with_what_was_right(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    output = measure("--set", str(tmp_path / "tiny"))
    rover = row_of(output, "mobile base", "tiny")
    # robots, structure, lenient, exit 2, absent, sensor P, sensor R, control P, control R
    assert rover[:5] == ["1", "1/1 (100%)", "1/1 (100%)", "0", "0"]
    assert rover[6] == "1/2 (50%)"  # the labelled camera is not in the file
    assert rover[8] == "1/1 (100%)"
    assert row_of(output, "arm", "tiny")[:2] == ["1", "0/1 (0%)"]
    assert "arm_called_humanoid: structure Manipulator, labelled Humanoid" in output


def test_a_gripper_counts_for_a_hand_and_a_pan_tilt_unit_for_an_uncertain_manipulator(
    tmp_path: Path,
) -> None:
    folder = with_urdfs(
        tmp_path / "heads", ptu=pan_tilt_only().text(), jaws=parallel_gripper().text()
    )
    rows = [
        {"robot": "ptu_certain", "file": "urdf/ptu.urdf", "kinematic_type": "Manipulator"},
        {"robot": "ptu_doubted", "file": "urdf/ptu.urdf", "kinematic_type": "Manipulator?"},
        {"robot": "jaws", "file": "urdf/jaws.urdf", "kinematic_type": "Hand"},
    ]
    write_truth(folder, rows)
    output = measure("--set", str(folder))
    # The gripper is right as a Hand; the pan/tilt unit is right only as an uncertain arm.
    assert "structure correct: 1/3 strict, 2/3 lenient" in output
    assert "ptu_certain: structure Pan/Tilt Unit, labelled Manipulator" in output
    assert "jaws: structure" not in output


def test_the_corpus_readmes_short_name_mm_labels_a_mobile_manipulator(tmp_path: Path) -> None:
    folder = with_urdfs(tmp_path / "bases", mm=mobile_manipulator().text())
    write_truth(folder, [{"robot": "mm", "file": "urdf/mm.urdf", "kinematic_type": "MM"}])
    assert "structure correct: 1/1 strict, 1/1 lenient" in measure("--set", str(folder))


def test_a_row_whose_file_is_missing_is_counted_absent_not_measured(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    output = measure("--set", str(tmp_path / "tiny"))
    assert row_of(output, "surface vessel", "tiny")[:5] == ["0", "-", "-", "0", "1"]
    assert row_of(output, "**all**", "tiny")[:5] == ["2", "1/2 (50%)", "1/2 (50%)", "0", "1"]


def test_files_kept_elsewhere_are_found_with_files(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    elsewhere = tmp_path / "files" / "urdf"
    elsewhere.mkdir(parents=True)
    (elsewhere / "boat.urdf").write_text(
        '<robot name="boat"><link name="hull"/></robot>', encoding="utf-8"
    )
    output = measure("--set", str(tmp_path / "tiny"), "--files", str(tmp_path / "files"))
    assert row_of(output, "surface vessel", "tiny")[0] == "1"
    assert row_of(output, "github someone/boats", "tiny")[4] == "0"


def test_a_set_never_reads_another_sets_files_folder_under_one_file_name(tmp_path: Path) -> None:
    """Two sets label different robots under one file name; each set's files are in a
    ``--files`` folder of its own. The first set's boat is absent everywhere: it must be
    counted absent, not measured on the second set's boat file."""
    tiny_set(tmp_path / "tiny")  # its own rover and arm files; its boat nowhere
    other = tmp_path / "other"
    other.mkdir()
    write_truth(
        other,
        [
            {"robot": "raft", "file": "urdf/boat.urdf", "kinematic_type": "UGV", "family": "raft"},
            {"robot": "cart", "file": "urdf/cart.urdf", "kinematic_type": "UGV", "family": "cart"},
        ],
    )
    other_files = tmp_path / "other_files" / "urdf"
    other_files.mkdir(parents=True)
    (other_files / "boat.urdf").write_text(ugv().text(), encoding="utf-8")
    (other_files / "cart.urdf").write_text(ugv().text(), encoding="utf-8")
    output = measure(
        "--set", str(tmp_path / "tiny"), "--set", str(other),
        "--files", str(tmp_path / "other_files"),
    )  # fmt: skip
    assert row_of(output, "surface vessel", "tiny")[:5] == ["0", "-", "-", "0", "1"]
    assert row_of(output, "raft", "other")[:2] == ["1", "1/1 (100%)"]


def test_sets_are_reported_side_by_side(tmp_path: Path) -> None:
    tiny_set(tmp_path / "one")
    tiny_set(tmp_path / "two")
    output = measure("--set", str(tmp_path / "one"), "--set", str(tmp_path / "two"))
    lines = output.splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("| mobile base | one |"))
    assert lines[first + 1].startswith("| mobile base | two |")
    assert "| github someone/rovers | one |" in output


def test_a_folder_without_labels_is_said_and_skipped(tmp_path: Path) -> None:
    output = measure("--set", str(tmp_path))
    assert "truth.csv missing" in output


def test_another_profile_measures_what_a_rule_adds(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    shipped = (ROOT / "rules" / "identification.yaml").read_text(encoding="utf-8")
    without = tmp_path / "no-navigation.yaml"
    without.write_text(shipped[: shipped.index("  navigation:")], encoding="utf-8")
    # The rover is labelled Driving only: the Waypoint its drive and lidar suggest is an extra.
    guessed = row_of(measure("--set", str(tmp_path / "tiny")), "mobile base", "tiny")
    plain = row_of(
        measure("--set", str(tmp_path / "tiny"), "--profile", str(without)), "mobile base", "tiny"
    )
    assert (guessed[7], plain[7]) == ("1/2 (50%)", "1/1 (100%)")


def test_each_motion_control_gets_its_own_precision_and_recall(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    output = measure("--set", str(tmp_path / "tiny"))
    # The rover, labelled Driving, is read as Driving and (its lidar) a Waypoint guess.
    assert "| Driving | 1/1 (100%) | 1/1 (100%) |" in output.splitlines()
    assert "| Waypoint | 0/1 (0%) | - |" in output.splitlines()


def test_with_a_split_each_row_is_measured_in_its_part(tmp_path: Path) -> None:
    tiny_set(tmp_path / "tiny")
    split = tmp_path / "split.csv"
    split.write_text(
        "# seed 41, made by hand for this test\n"
        "set,robot,family,group,files_here,part\n"
        "tiny,rover,mobile base,g1,yes,development\n"
        "tiny,arm_called_humanoid,arm,g2,yes,held-out\n",
        encoding="utf-8",
    )
    output = measure("--set", str(tmp_path / "tiny"), "--split", str(split))
    assert row_of(output, "mobile base", "development")[:2] == ["1", "1/1 (100%)"]
    assert row_of(output, "arm", "held-out")[:2] == ["1", "0/1 (0%)"]
    # The boat is in no part the split lists: measured (here: absent) as unsplit.
    assert row_of(output, "**all**", "unsplit")[:5] == ["0", "-", "-", "0", "1"]


def test_a_fresh_set_the_split_does_not_list_is_held_out_whole_on_its_own_line(
    tmp_path: Path,
) -> None:
    tiny_set(tmp_path / "fresh_set_2")
    tiny_set(tmp_path / "fresh_set_3")
    split = tmp_path / "split.csv"
    # fresh_set_2 is listed (moved to development); fresh_set_3 is not: it is the blind one.
    split.write_text(
        "# seed 41, made by hand for this test\n"
        "set,robot,family,group,files_here,part\n"
        "fresh_set_2,rover,mobile base,g1,no,development\n"
        "fresh_set_2,arm_called_humanoid,arm,g2,no,development\n"
        "fresh_set_2,boat,surface vessel,g3,no,development\n",
        encoding="utf-8",
    )
    sets = ["--set", str(tmp_path / "fresh_set_2"), "--set", str(tmp_path / "fresh_set_3")]
    output = measure(*sets, "--split", str(split))
    # The rover (right), the arm (read as a manipulator, labelled humanoid) and the absent boat.
    for part in ("development", "held-out", "held-out (fresh)"):
        assert row_of(output, "**all**", part)[:5] == ["2", "1/2 (50%)", "1/2 (50%)", "0", "1"]
    assert "development 3, held-out 3, held-out (fresh) 3" in output
    # Its misses are counted, not listed: reading them would make it development data.
    blind_part = output[output.index("## Set `held-out (fresh)`") :]
    assert "arm_called_humanoid" not in blind_part
    # The rover's sensors and controls (a camera not in its file, a guessed Waypoint), the arm's
    # structure, the absent boat.
    assert "(4 misses of the blind set withheld: --read-blind lists them" in blind_part
    read = measure(*sets, "--split", str(split), "--read-blind")
    assert "arm_called_humanoid: structure Manipulator" in read[read.index("## Set `held-out`") :]


def test_two_fresh_sets_built_together_are_both_held_out_and_neither_is_listed(
    tmp_path: Path,
) -> None:
    tiny_set(tmp_path / "fresh_set_5")
    tiny_set(tmp_path / "fresh_set_6")
    split = tmp_path / "split.csv"
    split.write_text(
        "# seed 41, made by hand for this test\nset,robot,family,group,files_here,part\n",
        encoding="utf-8",
    )
    sets = ["--set", str(tmp_path / "fresh_set_5"), "--set", str(tmp_path / "fresh_set_6")]
    output = measure(*sets, "--split", str(split))
    assert "held-out 6, held-out (fresh) 6" in output
    assert "unsplit" not in output
    assert "arm_called_humanoid" not in output
    assert output.count("(8 misses of the blind set withheld") == 2


def test_a_fresh_set_the_split_lists_even_in_part_is_no_longer_blind(tmp_path: Path) -> None:
    tiny_set(tmp_path / "fresh_set_4")
    split = tmp_path / "split.csv"
    split.write_text(
        "# seed 41, made by hand for this test\n"
        "set,robot,family,group,files_here,part\n"
        "fresh_set_4,rover,mobile base,g1,no,development\n",
        encoding="utf-8",
    )
    output = measure("--set", str(tmp_path / "fresh_set_4"), "--split", str(split))
    # Listed: its rows are measured where the split puts them (unlisted rows: unsplit).
    assert "held-out" not in output
    assert "development 1, unsplit 2" in output


def _measure_tool() -> Any:
    spec = importlib.util.spec_from_file_location("measure_identification", SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


def test_every_fresh_set_the_split_does_not_list_is_blind(tmp_path: Path) -> None:
    tool = _measure_tool()
    split = {("fresh_set_1", "a"): "development", ("fresh_set_2", "b"): "development"}
    names = ["corpus", "fresh_set_1", "fresh_set_2", "fresh_set_3", "fresh_set_10", "fresh_set_x"]
    # Sets are built two at a time: both unlisted ones are held out, not only the highest.
    assert tool.blind_sets(names, split) == {"fresh_set_3", "fresh_set_10"}
    assert tool.blind_sets(["corpus", "fresh_set_1", "fresh_set_2"], split) == set()
    for name in ("fresh_set_10", "fresh_set_2", "fresh_set_1", "notes", "fresh_set_x"):
        (tmp_path / name).mkdir()
    assert [p.name for p in tool.fresh_sets(tmp_path)] == [
        "fresh_set_1",
        "fresh_set_2",
        "fresh_set_10",
    ]


def test_rows_of_the_first_fresh_set_are_measured_where_the_split_puts_them(
    tmp_path: Path,
) -> None:
    tiny_set(tmp_path / "fresh_set_1")
    split = tmp_path / "split.csv"
    split.write_text(
        "# seed 41, made by hand for this test\n"
        "set,robot,family,group,files_here,part\n"
        "fresh_set_1,rover,mobile base,g1,no,development\n"
        "fresh_set_1,arm_called_humanoid,arm,g2,no,development\n"
        "fresh_set_1,boat,surface vessel,g3,no,development\n",
        encoding="utf-8",
    )
    output = measure("--set", str(tmp_path / "fresh_set_1"), "--split", str(split))
    assert row_of(output, "**all**", "development")[:5] == ["2", "1/2 (50%)", "1/2 (50%)", "0", "1"]
    assert "held-out" not in output


def _split_tool() -> Any:
    spec = importlib.util.spec_from_file_location("split_identification", SPLIT_SCRIPT)
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_split_keeps_each_group_whole_and_is_the_same_whatever_the_order(
    tmp_path: Path,
) -> None:
    tool = _split_tool()
    rows = [
        {
            "robot": f"{family}-{source}-{n}",
            "file": "none.urdf",
            "source": f"repo{source}@v1",
            "kinematic_type": kinematic_type,
        }
        for family, kinematic_type in (("rover", "UGV"), ("drone", "UAV"), ("arm", "Manipulator"))
        for source in range(5)
        for n in range(1 + source % 3)
    ]
    for name, order in (("a", rows), ("b", list(reversed(rows)))):
        (tmp_path / name).mkdir()
        write_truth(tmp_path / name, order)
    first = tool.split_rows([("set", tmp_path / "a")])
    second = tool.split_rows([("set", tmp_path / "b")])
    assert sorted((e["robot"], e["part"]) for e in first) == sorted(
        (e["robot"], e["part"]) for e in second
    )
    parts: dict[str, set[str]] = {}
    for entry in first:
        parts.setdefault(entry["group"], set()).add(entry["part"])
    assert len(parts) == 15  # one source and one family a group
    assert all(len(found) == 1 for found in parts.values())
    for family in ("rover", "drone", "arm"):  # five groups each: both parts get some
        found = {e["part"] for e in first if e["robot"].startswith(f"{family}-")}
        assert found == {"development", "held-out"}


def test_the_shipped_split_holds_out_whole_groups_and_at_least_60_robots() -> None:
    """The corpus it was made from lives outside the project (`split_identification.py
    --check` re-makes it beside the corpus); what the file itself must be is checked here."""
    text = (ROOT / "tools" / "identification_split.csv").read_text(encoding="utf-8")
    assert "Seed 41." in text
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    parts: dict[str, set[str]] = {}
    for row in rows:
        parts.setdefault(row["group"], set()).add(row["part"])
    assert all(len(found) == 1 for found in parts.values())
    held = [row for row in rows if row["part"] == "held-out"]
    assert len(held) >= 60
    assert len({(row["set"], row["robot"]) for row in rows}) == len(rows)


def test_the_shipped_split_puts_every_row_of_the_measured_fresh_sets_in_development() -> None:
    text = (ROOT / "tools" / "identification_split.csv").read_text(encoding="utf-8")
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    tool = _split_tool()
    moved_sets = [f"fresh_set_{n}" for n in range(1, tool.LAST_MOVED + 1)]
    for name in moved_sets:
        with (ROOT / "tools" / name / "truth.csv").open(encoding="utf-8") as stream:
            moved = {row["robot"] for row in csv.DictReader(stream)}
        listed = {row["robot"]: row["part"] for row in rows if row["set"] == name}
        assert set(listed) == moved
        assert set(listed.values()) == {"development"}
    # The blind set is held out by the measurement tool, never listed here (nor read here).
    assert not [row for row in rows if row["set"] == f"fresh_set_{tool.BLIND_NEXT}"]
    assert "moved whole to the development" in text


NAMED_ONLY = (
    '<robot name="rover"><link name="base_link"/><link name="left_wheel"/>'
    '<link name="right_wheel"/><link name="0"/>'
    '<joint name="left_wheel_joint" type="revolute"><parent link="base_link"/>'
    '<child link="left_wheel"/><origin xyz="0 0.2 0"/><axis xyz="0 0 1"/>'
    '<limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
    '<joint name="right_wheel_joint" type="revolute"><parent link="base_link"/>'
    '<child link="right_wheel"/><origin xyz="0 -0.2 0"/><axis xyz="0 0 1"/>'
    '<limit lower="0" upper="1" effort="1" velocity="1"/></joint>'
    '<joint name="zero" type="fixed"><parent link="base_link"/><child link="0"/></joint>'
    '<gazebo reference="left_wheel"><mu1>0</mu1></gazebo></robot>'
)


def test_without_names_every_link_and_joint_is_renamed_wherever_it_is_written(
    tmp_path: Path,
) -> None:
    path = tmp_path / "rover.urdf"
    path.write_text(NAMED_ONLY, encoding="utf-8")
    text = _measure_tool().without_names(path).decode()
    for name in ("rover", "base_link", "wheel", "zero"):
        assert name not in text
    assert '<parent link="l0"/>' in text
    assert '<child link="l1"/>' in text
    assert '<gazebo reference="l1">' in text
    # A number stays a number, though a link is named "0".
    assert 'lower="0"' in text
    assert "<mu1>0</mu1>" in text


def test_no_names_measures_what_is_read_with_no_word_of_a_parts_name(tmp_path: Path) -> None:
    # Only the joints' names say these limited hinges are wheels: with them the rover is a UGV,
    # without them nothing says so.
    (tmp_path / "set" / "urdf").mkdir(parents=True)
    (tmp_path / "set" / "urdf" / "rover.urdf").write_text(NAMED_ONLY, encoding="utf-8")
    row = {"robot": "rover", "file": "urdf/rover.urdf", "kinematic_type": "UGV"}
    write_truth(tmp_path / "set", [row])
    named = row_of(measure("--set", str(tmp_path / "set")), "**all**", "set")
    nameless = row_of(measure("--set", str(tmp_path / "set"), "--no-names"), "**all**", "set")
    assert (named[1], nameless[1]) == ("1/1 (100%)", "0/1 (0%)")


def test_a_rows_kept_repository_is_read_for_the_controls_its_packages_ship(
    tmp_path: Path,
) -> None:
    tiny_set(tmp_path / "tiny")
    guessed = row_of(measure("--set", str(tmp_path / "tiny")), "mobile base", "tiny")
    assert guessed[7] == "1/2 (50%)"  # Driving, and Waypoint guessed from the drive and laser
    repository = tmp_path / "rovers"
    (repository / "rover_description" / "urdf").mkdir(parents=True)
    (repository / "rover_description" / "package.xml").write_text(
        "<package><name>rover_description</name></package>", encoding="utf-8"
    )
    kept = tmp_path / "workspaces.tsv"
    kept.write_text(
        f"tiny\trover\t{repository}\trover_description/urdf/rover.urdf.xacro\n", encoding="utf-8"
    )
    read = measure("--set", str(tmp_path / "tiny"), "--workspaces", str(kept))
    # Its packages ship no navigation: none is guessed.
    assert row_of(read, "mobile base", "tiny")[7:9] == ["1/1 (100%)", "1/1 (100%)"]


def test_a_rows_repository_of_no_package_is_read_under_the_descriptions_own_file_name(
    tmp_path: Path,
) -> None:
    tiny_set(tmp_path / "tiny")
    repository = tmp_path / "sims"
    (repository / "models").mkdir(parents=True)
    for name in ("rover_mk2", "drone_mk1"):  # two robots: its scripts are those naming it
        (repository / "models" / f"{name}.xacro").write_text("<robot/>", encoding="utf-8")
    (repository / "teleop.py").write_text("load('rover_mk2.xacro')", encoding="utf-8")
    (repository / "mission.py").write_text("load('drone_mk1.xacro'); follow_waypoints()")
    kept = tmp_path / "workspaces.tsv"
    kept.write_text(f"tiny\trover\t{repository}\tmodels/rover_mk2.xacro\n", encoding="utf-8")
    read = measure("--set", str(tmp_path / "tiny"), "--workspaces", str(kept))
    # The drone's mission is not the rover's: no navigation, none guessed.
    assert row_of(read, "mobile base", "tiny")[7:9] == ["1/1 (100%)", "1/1 (100%)"]


def test_the_briefs_snake_labels_a_serpentine_reading_in_a_label_and_in_a_note(
    tmp_path: Path,
) -> None:
    folder = with_urdfs(tmp_path / "snakes", snake=snake().text())
    rows = [
        {"robot": "named", "file": "urdf/snake.urdf", "kinematic_type": "Snake"},
        {
            "robot": "doubted",
            "file": "urdf/snake.urdf",
            "kinematic_type": "Manipulator?",
            "uncertainty_note": "Snake would also fit: its authors call it one.",
        },
        {
            "robot": "unnamed_in_note",
            "file": "urdf/snake.urdf",
            "kinematic_type": "Manipulator?",
            "uncertainty_note": "the snakes of its repository are other robots",
        },
    ]
    write_truth(folder, rows)
    # The label and the word in the note are the Serpentine structure; "snakes" names none.
    assert "structure correct: 1/3 strict, 2/3 lenient" in measure("--set", str(folder))


def test_a_structure_named_inside_a_longer_ones_name_in_a_note_is_not_named_by_it(
    tmp_path: Path,
) -> None:
    folder = with_urdfs(tmp_path / "flyers", arm=manipulator().text())
    rows = [
        {
            "robot": "in_a_longer_name",
            "file": "urdf/arm.urdf",
            "kinematic_type": "UAV?",
            "uncertainty_note": "an Aerial manipulator would also fit",
        },
        {
            "robot": "named_alone",
            "file": "urdf/arm.urdf",
            "kinematic_type": "UAV?",
            "uncertainty_note": "a Manipulator would also fit",
        },
    ]
    write_truth(folder, rows)
    # The arm is right only where the note names a Manipulator, not an Aerial manipulator.
    assert "structure correct: 0/2 strict, 1/2 lenient" in measure("--set", str(folder))
    structures = ["Manipulator", "Aerial Manipulator", "Mobile Manipulator", "UGV", "Hand", "Other"]
    named = _measure_tool().named_structures
    assert named("an aerial manipulator or two ugvs", structures) == {"Aerial Manipulator", "UGV"}
    # Its words as words, however joined: none inside another word.
    assert named("an aerial-manipulator, handheld, another", structures) == {"Aerial Manipulator"}
