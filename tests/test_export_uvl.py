"""UVL export: flamapy counts the same configurations as our exact valid-robot counts."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from flamapy.interfaces.python import flamapy_feature_model as flamapy

from solver import load_team, solve
from solver.cli import main
from solver.uvl import ExportError, team_to_uvl


def flamapy_count(text: str, path: Path) -> int:
    path.write_text(text)
    return int(flamapy.FLAMAFeatureModel(str(path)).configurations_number())


@pytest.mark.parametrize("name", ["figure8", "case1", "case2", "case3", "case3-hypothesis"])
def test_flamapy_counts_the_shipped_teams_valid_robots(name: str, tmp_path: Path) -> None:
    team = load_team(name)
    assert flamapy_count(team_to_uvl(team), tmp_path / "m.uvl") == solve(team).totals.valid_robots


def random_rules_and_team(rng: random.Random, directory: Path) -> Path:
    kinds = [f"K{n}" for n in range(rng.randint(1, 3))]
    controls = [f"C{n}" for n in range(rng.randint(1, 3))]
    sensors = [f"S{n}" for n in range(rng.randint(1, 4))]
    (directory / "rules.yaml").write_text(
        "name: random\nteam_key: kind\ncharacteristics:\n"
        f"  kind:\n    values: [{', '.join(kinds)}]\n"
        f"  control:\n    values: [{', '.join(controls)}]\n"
        f"  sensor:\n    values: [{', '.join(sensors)}]\n"
        "  count:\n    range: {min: 1, max: 9}\n    components:\n"
        "      - {name: few, min: 1, max: 3, cluster_size: 1}\n"
        "      - {name: many, min: 4, max: 9, cluster_size: 3}\n"
    )
    lines = ["name: random team", "rules: rules.yaml", "team:"]
    for kind in rng.sample(kinds, rng.randint(1, len(kinds))):
        picked_controls = rng.sample(controls, rng.randint(1, len(controls)))
        picked_sensors = rng.sample(sensors, rng.randint(1, len(sensors)))
        lines += [
            f"  {kind}:",
            f"    control: [{', '.join(picked_controls)}]",
            f"    sensor: [{', '.join(picked_sensors)}]",
            f"    count: {rng.randint(1, 9)}",
        ]
    (directory / "team.yaml").write_text("\n".join(lines) + "\n")
    return directory / "team.yaml"


@pytest.mark.parametrize("seed", range(8))
def test_flamapy_counts_random_small_teams_valid_robots(seed: int, tmp_path: Path) -> None:
    team = load_team(random_rules_and_team(random.Random(seed), tmp_path))
    expected = solve(team).totals.valid_robots
    assert flamapy_count(team_to_uvl(team), tmp_path / "m.uvl") == expected


def test_export_refuses_a_rule_set_with_constraints_it_cannot_translate() -> None:
    with pytest.raises(ExportError, match="constraints"):
        team_to_uvl(load_team("search-and-rescue"))


def test_export_command_prints_the_model(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["export", "case1", "--format", "uvl"]) == 0
    out = capsys.readouterr().out
    assert "motion_control_Waypoint" in out
    assert out.startswith("namespace Team\n")
