"""The Fleet view's team: a name from the robots, and nothing selected that a robot lacks."""

from __future__ import annotations

import shutil
from pathlib import Path

from solver import solve
from solver.core.rules import load_rules
from solver.core.team import parse_team
from solver.files.yamlio import parse_document
from solver.identify import identify_fleet, load_profile, team_text
from solver.studio.fleetteam import fleet_name, narrowed, narrowings
from tests.conftest import ROOT


def _examples(tmp_path: Path, *names: str) -> Path:
    for name in names:
        shutil.copy(ROOT / "examples" / name, tmp_path / name)
    return tmp_path


def test_an_arm_with_no_sensors_selects_the_smallest_sensor_selection_not_every_one(
    tmp_path: Path,
) -> None:
    folder = _examples(
        tmp_path, "arm_gripper.urdf", "arm_gripper.srdf", "quadrotor.urdf", "diff_drive_lidar.urdf"
    )
    rules = load_rules(ROOT / "rules" / "paper.yaml")
    profile = load_profile()
    fleet = identify_fleet(folder, rules=rules, profile=profile)
    found = narrowings(fleet, rules, profile, {})
    # The arm has no sensor: its sensor type and count are taken as small as the rules allow.
    assert [(n.kinematic_type, n.characteristic, n.value) for n in found] == [
        ("Manipulator", "sensor_type", "2D Camera"),
        ("Manipulator", "sensor_count", "1"),
    ]
    assert found[1].sentence == (
        "arm_gripper (Manipulator): no No. of Sensors identified; the rules count from 1, "
        "never 0, so the team takes the smallest selection, No. of Sensors 1, not every value."
    )
    name = fleet_name(fleet)
    text = team_text(fleet, rules, profile, name=name)
    team = narrowed(parse_team(parse_document(text, "<fleet team>"), rules), found, name)
    counts = {t.kinematic_type: t for t in solve(team, count_only=True).by_type}
    # Joint or End Effector, one 2D Camera: 2 robots, 2 configurations (not 1,000 and 50).
    assert (counts["Manipulator"].valid_robots, counts["Manipulator"].ui_configurations) == (2, 2)
    assert (counts["UAV"].valid_robots, counts["UGV"].valid_robots) == (1, 2)


def test_a_value_a_constraint_excludes_for_the_type_is_not_the_one_taken(tmp_path: Path) -> None:
    folder = _examples(tmp_path, "arm_gripper.urdf", "arm_gripper.srdf")
    rules = load_rules(ROOT / "rules" / "paper.yaml")
    profile = load_profile()
    fleet = identify_fleet(folder, rules=rules, profile=profile)
    excluded = {("Manipulator", "sensor_type"): {"2D Camera": "a constraint"}}
    (sensor_type, _) = narrowings(fleet, rules, profile, excluded)
    assert sensor_type.value == "3D Camera"


def test_the_team_is_named_after_its_robots_and_counts_the_rest(tmp_path: Path) -> None:
    rules = load_rules(ROOT / "rules" / "paper.yaml")
    profile = load_profile()
    one = identify_fleet(_examples(tmp_path, "quadrotor.urdf"), rules=rules, profile=profile)
    assert fleet_name(one) == "Fleet: quadrotor"
    for copy in ("a", "b", "c"):
        shutil.copy(ROOT / "examples" / "quadrotor.urdf", tmp_path / f"{copy}.urdf")
    four = identify_fleet(tmp_path, rules=rules, profile=profile)
    assert fleet_name(four) == "Fleet: a, b, c and 1 more"
