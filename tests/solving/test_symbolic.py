"""Symbolic counts: formulas of each type's maximum, checked against the exact counter."""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest
import sympy
from hypothesis import given, settings

from solver import InputError, Team, load_rules, load_team
from solver.core.team import full_team
from solver.engines.structure import count
from solver.errors import TimeLimitError
from solver.solving.symbolic import formulas, symbol_name
from tests.conftest import TEAMS, run_cli
from tests.test_properties import problems

WriteFile = Callable[[str, str], Path]


def check_every_maximum(team: Team) -> None:
    """At every maximum n of every type, the formulas equal the exact counter."""
    growth = formulas(team)
    rules = team.rules
    for selection, formula in zip(team.selections, growth.types, strict=True):
        position = rules.names.index(formula.characteristic)
        for n in range(formula.low, formula.high + 1):
            domains = list(selection.domains)
            domains[position] = tuple(range(formula.low, n + 1))
            exact = count(rules, replace(selection, domains=tuple(domains)))
            values = {formula.symbol: n}
            assert growth.evaluate(formula.robots, values) == exact.valid_robots
            assert growth.evaluate(formula.configurations, values) == exact.ui_configurations


def test_case_3_grows_linearly_in_robots_and_by_arrangements_in_configurations() -> None:
    growth = formulas(load_team(TEAMS / "case3.yaml"))
    ((name, _, definition),) = growth.functions
    n = sympy.Symbol("n", integer=True)
    assert name == "A_sensor_count"
    assert definition == sympy.Piecewise(
        (1, n <= 5), (2, n <= 10), (3, n <= 15), (4, n <= 25), (5, n <= 50)
    )
    uav = growth.types[0]
    assert sympy.sstr(uav.robots) == "6*n_UAV"
    assert sympy.sstr(uav.configurations) == "6*A_sensor_count(n_UAV)"
    maxima = growth.at_team_maxima()
    assert growth.evaluate(growth.total_robots, maxima) == 872
    assert growth.evaluate(growth.total_configurations, maxima) == 102


@pytest.mark.parametrize("case", ["figure8", "case1", "case2", "case3", "case3-hypothesis"])
def test_formulas_equal_the_exact_count_at_every_maximum(case: str) -> None:
    check_every_maximum(load_team(TEAMS / f"{case}.yaml"))


def test_a_constraint_on_the_count_makes_the_formulas_piecewise(write_file: WriteFile) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [UAV]}
  sensor_type: {values: [camera, lidar]}
  sensor_count:
    range: {min: 1, max: 20}
    components:
      - {name: few, min: 1, max: 8}
      - {name: many, min: 9, max: 20, cluster_size: 4}
constraints:
  - name: lidars come alone or in pairs
    forbid: {sensor_type: lidar, sensor_count: {min: 3}}
""",
    )
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  UAV: {}\n"))
    (uav,) = formulas(team).types
    assert isinstance(uav.robots, sympy.Piecewise)
    check_every_maximum(team)


@settings(max_examples=60, deadline=None)
@given(problems(irregular=True))
def test_formulas_equal_the_exact_count_on_random_teams(team: Team) -> None:
    integers = [c for c in team.rules.characteristics if c.kind == "integer"]
    if len(integers) != 1:
        with pytest.raises(InputError, match="exactly one whole-number characteristic"):
            formulas(team)
        return
    check_every_maximum(team)


def test_symbol_names_are_identifiers() -> None:
    assert symbol_name("Mobile Manipulator", "sensor_count", False) == "n_Mobile_Manipulator"
    assert symbol_name("UAV", "sensor_count", True) == "n_UAV_sensor_count"


def test_types_whose_names_read_alike_get_distinct_symbols(write_file: WriteFile) -> None:
    write_file(
        "rules.yaml",
        "characteristics:\n"
        "  kinematic_type: {values: [Mobile Manipulator, Mobile-Manipulator]}\n"
        "  sensor_count: {range: {min: 1, max: 9}}\n",
    )
    team = load_team(
        write_file(
            "team.yaml",
            "rules: rules.yaml\nteam:\n"
            "  Mobile Manipulator: {sensor_count: 3}\n"
            "  Mobile-Manipulator: {sensor_count: 7}\n",
        )
    )
    growth = formulas(team)
    assert [str(t.symbol) for t in growth.types] == [
        "n_Mobile_Manipulator",
        "n_Mobile_Manipulator_",
    ]
    check_every_maximum(team)


def test_counts_from_zero_or_below_keep_every_piece(write_file: WriteFile) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [UAV]}
  sensor_count:
    range: {min: -3, max: 10}
    components:
      - {name: none or less, max: 0}
      - {name: some, min: 1, max: 10}
""",
    )
    team = load_team(
        write_file(
            "team.yaml", "rules: rules.yaml\nteam:\n  UAV: {sensor_count: {min: -3, max: 4}}\n"
        )
    )
    check_every_maximum(team)


def test_a_constraint_too_large_for_the_structure_is_refused_with_status_2(
    write_file: WriteFile,
) -> None:
    # a, b and c have 101 classes each (a component per value): linked by one 3-way rule they
    # make over 10^6 class combinations, more than the structure counts; n is what grows.
    lines = ["characteristics:", "  kinematic_type: {values: [T]}"]
    for name in "abc":
        values = ", ".join(f"{name}{i}" for i in range(1, 102))
        lines += [f"  {name}:", f"    values: [{values}]", "    components:"]
        lines += [f"      - {{name: {name}{i}, values: [{name}{i}]}}" for i in range(1, 102)]
    lines += ["  n: {range: {min: 1, max: 5}}"]
    lines += ["constraints:", "  - forbid: {a: a1, b: b1, c: c1}"]
    write_file("rules.yaml", "\n".join(lines) + "\n")
    team = write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n")
    result = run_cli("count", team, "--symbolic")
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    assert "constraints link a, b, c into 1030301 class combinations" in result.stderr


def _one_component_per_count(write_file: WriteFile, counts: int, constraint: str = "") -> Path:
    """A rule set of two types whose counts 1..``counts`` each have a component of their own."""
    components = "".join(
        f"      - {{name: c{i}, min: {i}, max: {i}}}\n" for i in range(1, counts + 1)
    )
    return write_file(
        "rules.yaml",
        "characteristics:\n  kinematic_type: {values: [A, B]}\n"
        "  sensor_type: {values: [camera, lidar]}\n"
        f"  sensor_count:\n    range: {{min: 1, max: {counts}}}\n    components:\n"
        + components
        + constraint,
    )


def test_5000_components_make_an_arrangement_function_of_5000_pieces(
    write_file: WriteFile,
) -> None:
    # Each count reaches a component more: A(n) = n, one piece per count. sympy simplified
    # each piece against the ones before, and evaluated A piece by piece: 44 s.
    rules = _one_component_per_count(write_file, 5000)
    result = run_cli("count", rules, "--symbolic", "-f", "json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    definition = data["functions"]["A_sensor_count"]["definition"]
    assert definition.startswith("Piecewise((1, n <= 1), (2, n <= 2), (3, n <= 3), ")
    assert definition.endswith(", (5000, n <= 5000))")
    assert data["at_team_maxima"] == {
        "maxima": {"n_A": 5000, "n_B": 5000},
        "valid_robots": 2 * 2 * 5000,
        "ui_configurations": 2 * 2 * 5000,
        "equal_to_exact_count": True,
    }


def test_an_arrangement_function_is_evaluated_at_every_count_as_the_exact_counter_says(
    write_file: WriteFile,
) -> None:
    _one_component_per_count(write_file, 300)
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  A: {}\n"))
    growth = formulas(team)
    (uav,) = growth.types
    for n in (1, 2, 150, 299, 300):
        domains = list(team.selections[0].domains)
        domains[2] = tuple(range(1, n + 1))
        exact = count(team.rules, replace(team.selections[0], domains=tuple(domains)))
        assert growth.evaluate(uav.configurations, {uav.symbol: n}) == exact.ui_configurations


def test_formulas_past_their_time_limit_are_refused_naming_the_team_and_the_limit(
    write_file: WriteFile,
) -> None:
    # A constraint on every other count: 2,000 runs of counts, two exact counts each, the
    # later ones over ever longer prefixes (36 s in full).
    odd = ", ".join(str(i) for i in range(1, 2001, 2))
    forbid = f"constraints:\n  - forbid: {{sensor_type: lidar, sensor_count: [{odd}]}}\n"
    rules = _one_component_per_count(write_file, 2000, forbid)
    result = run_cli("count", rules, "--symbolic", "--time-limit", "0.5")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == (
        f"{rules}: count --symbolic stopped after 0.5 s (limit 'symbolic-seconds', "
        "docs/security.md; --time-limit sets it)\n"
    )
    with pytest.raises(TimeLimitError, match=r"count --symbolic stopped after 0\.5 s"):
        formulas(full_team(load_rules(rules)), time_limit=0.5)
