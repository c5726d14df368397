"""A user's identification profile extends the shipped one in a few lines, without copying it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from solver.core.rules import load_rules
from solver.errors import SolverError
from solver.files.filekind import file_kind
from solver.files.yamlio import load_document
from solver.identify import identify_urdf
from solver.identify.profile import load_profile
from tests.conftest import RULES, run_cli
from tests.identify.builders import RobotText, leg, quadruped

# A rule set of this test's own: legged robots are "Legged Robot", six-legged ones "Hexapod".
LEGGED_RULES = """\
name: Legged fleet
characteristics:
  kinematic_type:
    values: [UGV, Legged Robot, Hexapod]
  motion_control:
    values: [Driving, Walking, Joint]
  sensor_type:
    values: [2D Camera, LIDAR, Thermal Camera]
  sensor_count:
    range: {min: 1, max: 5}
    components:
      - {name: individual, min: 1, max: 5, cluster_size: 1}
"""

THREE_LINES = """\
extends: shipped
structures:
  - {name: Quadruped, kinematic_types: [Legged Robot]}
"""


def hexapod() -> RobotText:
    robot = RobotText("spider")
    for corner in ("FL", "FR", "ML", "MR", "RL", "RR"):
        leg(robot, robot.root, corner, ("hip", "thigh", "calf"))
    return robot


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_three_lines_on_the_shipped_profile_map_a_quadruped_to_the_users_kinematic_type(
    tmp_path: Path,
) -> None:
    rules = load_rules(write(tmp_path / "legged.yaml", LEGGED_RULES))
    profile = load_profile(write(tmp_path / "mine.yaml", THREE_LINES))
    shipped = load_profile()
    found = identify_urdf(quadruped().text(), rules=rules, profile=profile)
    assert (found.structure, found.kinematic_type) == ("Quadruped", "Legged Robot")
    # Without the three lines the same dog has no type in this rule set.
    assert identify_urdf(quadruped().text(), rules=rules, profile=shipped).kinematic_type is None
    # Everything else is the shipped profile's, in the shipped order.
    assert profile.structure_names == shipped.structure_names
    assert profile.patterns == shipped.patterns
    assert profile.name == "mine"


def test_a_new_structure_is_tried_before_the_shipped_ones(tmp_path: Path) -> None:
    rules = load_rules(write(tmp_path / "legged.yaml", LEGGED_RULES))
    profile = load_profile(
        write(
            tmp_path / "six.yaml",
            "extends: shipped\n"
            "structures:\n"
            "  - {name: Insect, when: {legs: 6}, kinematic_types: [Hexapod], confidence: 0.9}\n"
            "  - {name: Quadruped, kinematic_types: [Legged Robot]}\n",
        )
    )
    assert profile.structure_names[0] == "Insect"
    assert profile.structure_names.count("Quadruped") == 1
    six = identify_urdf(hexapod().text(), rules=rules, profile=profile)
    four = identify_urdf(quadruped().text(), rules=rules, profile=profile)
    assert (six.structure, six.kinematic_type) == ("Insect", "Hexapod")
    assert (four.structure, four.kinematic_type) == ("Quadruped", "Legged Robot")


def test_mappings_merge_key_by_key_and_new_rules_come_first(tmp_path: Path) -> None:
    shipped = load_profile()
    profile = load_profile(
        write(
            tmp_path / "mine.yaml",
            "extends: shipped\n"
            "characteristics: {motion_control: control_mode}\n"
            "sensor_types: {camera: Thermal Camera}\n"
            "limbs: {arm_min_joints: 4}\n"
            "topics:\n"
            "  stream_segments: [thermal]\n"
            "  sensors:\n"
            "    - {kind: camera, types: [flir_msgs/Thermal]}\n",
        )
    )
    assert profile.role("motion_control") == "control_mode"
    assert profile.role("sensor_type") == shipped.role("sensor_type")
    for kind, sensor_type in (("camera", "Thermal Camera"), ("lidar", "LIDAR")):
        mapping = profile.sensor_type_mapping(kind)
        assert mapping is not None
        assert mapping.sensor_type == sensor_type
    assert profile.limb("arm_min_joints") == 4
    assert profile.limb("leg_min_joints") == shipped.limb("leg_min_joints")
    assert profile.stream_segments == shipped.stream_segments | {"thermal"}
    assert profile.topic_sensors[0].types == frozenset({"flir_msgs/Thermal"})
    assert profile.topic_sensors[1:] == shipped.topic_sensors
    assert profile.topic_controls == shipped.topic_controls


def test_a_users_frame_rules_come_before_the_shipped_ones(tmp_path: Path) -> None:
    shipped = load_profile()
    profile = load_profile(
        write(
            tmp_path / "mine.yaml",
            "extends: shipped\nsensors:\n  frames:\n    - {kind: thermal_camera, match: flir}\n",
        )
    )
    assert profile.frame_rules[0].kind == "thermal_camera"
    assert profile.frame_rules[1:] == shipped.frame_rules


def test_every_problem_of_a_composed_profile_is_located_in_the_users_file(
    tmp_path: Path,
) -> None:
    mine = write(
        tmp_path / "mine.yaml",
        "extends: shipped\n"
        "doubt_factor: 3\n"
        "structures:\n"
        "  - {name: Insect, when: {paws: 6}, kinematic_types: [Hexapod]}\n",
    )
    with pytest.raises(SolverError) as caught:
        load_profile(mine)
    found = sorted(
        (f.location.file, f.location.line, f.location.column, f.location.path, f.message)
        for f in caught.value.faults
    )
    assert [tuple(where) for *where, _ in found] == [
        (str(mine), 2, 15, "doubt_factor"),
        (str(mine), 4, 5, "structures[0].confidence"),
        (str(mine), 4, 27, "structures[0].when.paws"),
    ]
    messages = [message for *_, message in found]
    assert messages[0] == "doubt_factor must be a number in (0, 1], got a number (3)"
    assert messages[1] == "missing confidence"
    assert messages[2].startswith("unknown feature 'paws'; features: wheels, ")


def test_a_chain_of_profiles_is_followed_relative_to_each_file(tmp_path: Path) -> None:
    (tmp_path / "team").mkdir()
    write(tmp_path / "base.yaml", THREE_LINES)
    top = write(
        tmp_path / "team" / "top.yaml", "extends: ../base.yaml\nlimbs: {leg_min_joints: 3}\n"
    )
    profile = load_profile(top)
    quadruped_rule = next(s for s in profile.structures if s.name == "Quadruped")
    assert quadruped_rule.kinematic_types == ("Legged Robot",)
    assert profile.limb("leg_min_joints") == 3
    assert file_kind(load_document(top)) == "profile"


@pytest.mark.parametrize(
    ("extends", "message"),
    [
        ("missing.yaml", "cannot read the profile it extends ('missing.yaml'): "),
        ("loop.yaml", "a profile cannot extend itself, directly or through others"),
        ("[1, 2]", "extends names the profile this one adds to: 'shipped' or a file, got"),
    ],
)
def test_an_extends_that_cannot_be_followed_is_an_error_at_its_line(
    tmp_path: Path, extends: str, message: str
) -> None:
    loop = write(tmp_path / "loop.yaml", f"name: loop\nextends: {extends}\n")
    with pytest.raises(SolverError) as caught:
        load_profile(loop)
    (fault,) = caught.value.faults
    assert (fault.location.file, fault.location.line, fault.location.path) == (
        str(loop),
        2,
        "extends",
    )
    assert fault.message.startswith(message)


def test_identify_fleet_and_layouts_take_the_composed_profile(tmp_path: Path) -> None:
    write(tmp_path / "legged.yaml", LEGGED_RULES)
    write(tmp_path / "mine.yaml", THREE_LINES)
    write(tmp_path / "team.yaml", "name: Dogs\nrules: legged.yaml\nteam:\n  Legged Robot: {}\n")
    robots = tmp_path / "robots"
    robots.mkdir()
    write(robots / "dog.urdf", quadruped().text())
    identified = run_cli(
        "identify",
        robots / "dog.urdf",
        "--rules",
        tmp_path / "legged.yaml",
        "--profile",
        tmp_path / "mine.yaml",
        "-f",
        "json",
    )
    assert identified.returncode == 0, identified.stderr
    assert json.loads(identified.stdout)["kinematic_type"] == "Legged Robot"
    fleet = run_cli(
        "fleet",
        robots,
        "--rules",
        tmp_path / "legged.yaml",
        "--profile",
        tmp_path / "mine.yaml",
        "-o",
        tmp_path / "fleet.yaml",
    )
    assert fleet.returncode == 0, fleet.stderr
    assert "Legged Robot:" in (tmp_path / "fleet.yaml").read_text(encoding="utf-8")
    layouts = run_cli(
        "layouts",
        "--robot",
        robots / "dog.urdf",
        "--team",
        tmp_path / "team.yaml",
        "--profile",
        tmp_path / "mine.yaml",
        "-o",
        tmp_path / "dog.json",
    )
    assert layouts.returncode == 0, layouts.stderr


def test_the_shipped_profile_extends_nothing() -> None:
    assert "extends" not in (RULES / "identification.yaml").read_text(encoding="utf-8")


def test_the_studios_fleet_view_identifies_with_the_profile_given_at_start(
    tmp_path: Path,
) -> None:
    from solver.studio.service import Studio
    from solver.studio.workspace import Workspace

    robots = tmp_path / "robots"
    robots.mkdir()
    write(robots / "dog.urdf", quadruped().text())
    # The paper's rules have no type for a dog; this profile (only for the test) makes it a UGV.
    mine = write(
        tmp_path / "mine.yaml",
        "extends: shipped\nstructures:\n  - {name: Quadruped, kinematic_types: [UGV]}\n",
    )
    workspace = Workspace(folders=[robots])
    try:
        studio = Studio(workspace, None, load_profile(mine))
        answer = studio.identify_folder(0, [])
        shipped = Studio(workspace).identify_folder(0, [])
    finally:
        workspace.close()
    assert [r["kinematic_type"] for r in answer["robots"]] == ["UGV"]
    assert [r["kinematic_type"] for r in shipped["robots"]] == [None]
