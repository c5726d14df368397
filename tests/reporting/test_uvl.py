"""UVL export: flamapy counts the same configurations as our exact valid-robot counts."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from flamapy.interfaces.python import flamapy_feature_model as flamapy

from solver import load_team, solve
from solver.reporting.uvl import team_to_uvl


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


def test_declared_constraints_become_uvl_constraints() -> None:
    team = load_team("search-and-rescue")
    text = team_to_uvl(team)
    assert "    !((motion_control_Flight) & (sensor_type_Force_Sensor))\n" in text
    assert (
        "    (motion_control_Flight) => (kinematic_type_UAV | kinematic_type_Aerial_Manipulator)\n"
    ) in text


def test_flamapy_counts_the_search_and_rescue_team_with_its_constraints(tmp_path: Path) -> None:
    team = load_team("search-and-rescue")
    assert flamapy_count(team_to_uvl(team), tmp_path / "m.uvl") == solve(team).totals.valid_robots


def _random_constraints(rng: random.Random, rules: Path) -> None:
    # Random require and forbid rules over the random rule set's values (and counts).
    text = rules.read_text()
    values = {
        name: text.split(f"  {name}:\n    values: [", 1)[1].split("]", 1)[0].split(", ")
        for name in ("kind", "control", "sensor")
    }
    lines = ["constraints:"]
    for number in range(rng.randint(1, 3)):
        a, b = rng.sample(sorted(values), 2)
        pick_a = rng.sample(values[a], rng.randint(1, len(values[a])))
        pick_b = rng.sample(values[b], rng.randint(1, len(values[b])))
        if rng.random() < 0.5:
            lines += [
                f"  - name: rule {number}",
                f"    when: {{{a}: [{', '.join(pick_a)}]}}",
                f"    require: {{{b}: [{', '.join(pick_b)}]}}",
            ]
        else:
            count = rng.randint(1, 9)
            lines += [
                f"  - name: rule {number}",
                f"    forbid: {{{a}: [{', '.join(pick_a)}], count: {{min: {count}, max: 9}}}}",
            ]
    rules.write_text(text + "\n".join(lines) + "\n")


@pytest.mark.parametrize("seed", range(8))
def test_flamapy_counts_random_small_teams_with_constraints(seed: int, tmp_path: Path) -> None:
    rng = random.Random(1000 + seed)
    team_file = random_rules_and_team(rng, tmp_path)
    _random_constraints(rng, tmp_path / "rules.yaml")
    team = load_team(team_file)
    assert team.rules.constraints
    expected = solve(team).totals.valid_robots
    assert flamapy_count(team_to_uvl(team), tmp_path / "m.uvl") == expected


# ---- names that are UVL syntax, keywords or collide are written safely ---------------------

HOSTILE_RULES = r"""name: hostile
team_key: mandatory
characteristics:
  mandatory:
    values: ["UAV\nconstraints\n    Team", "a {abstract}", "x\" | y", "kind.UGV", "50%"]
  "a b {abstract}":
    values: [u, "u_", "é ロボ", Team, "constraints", "é.\"%\nx"]
  Team:
    values: ["1", "2"]
constraints:
  - name: "a name\nconstraints\n    !Team"
    when: {mandatory: ["a {abstract}"]}
    require: {"a b {abstract}": [u, "é ロボ"]}
"""
HOSTILE_TEAM = r"""name: hostile team
rules: rules.yaml
team:
  "UAV\nconstraints\n    Team": {}
  "a {abstract}": {}
  "x\" | y": {"a b {abstract}": ["u_", Team, "é.\"%\nx"]}
  "kind.UGV": {}
  "50%": {Team: ["2"]}
"""


def test_names_that_are_uvl_syntax_add_no_feature_or_constraint(tmp_path: Path) -> None:
    from flamapy.metamodels.fm_metamodel.transformations import UVLReader

    (tmp_path / "rules.yaml").write_text(HOSTILE_RULES, encoding="utf-8")
    (tmp_path / "team.yaml").write_text(HOSTILE_TEAM, encoding="utf-8")
    team = load_team(tmp_path / "team.yaml")
    text = team_to_uvl(team)
    assert "\nconstraints\n" in text
    assert text.count("\nconstraints\n") == 1  # no name opened a second section
    model_file = tmp_path / "m.uvl"
    # flamapy's own reader: the features are the root, one per characteristic and one per
    # value, all distinct; its count of configurations is ours.
    assert flamapy_count(text, model_file) == solve(team).totals.valid_robots
    features = [feature.name for feature in UVLReader(str(model_file)).transform().get_features()]
    values = sum(len(c.values) for c in team.rules.characteristics)
    assert len(features) == len(set(features)) == 1 + len(team.rules.characteristics) + values
    assert '"mandatory"' in text  # a keyword is quoted
    # Exact where no plain identifier fits; what a quoted UVL name cannot hold is encoded.
    assert '"a b {abstract}_é%2E%22%25%0Ax"' in text
