"""The constraint model (solver.core.model): the valid robots over a selection's domains, whether
there is one, and which declared rules a robot breaks; counted by hand (tests.handcounted)."""

from __future__ import annotations

from dataclasses import replace

from solver.core.constraints import Condition, RuleConstraint
from solver.core.model import build_problem, is_satisfiable, robots, violated_constraints
from solver.errors import Location
from tests.handcounted import rules_of, team_of

UAV_ROBOTS = [
    ("UAV", sensor, count) for sensor in ("camera", "lidar") for count in (1, 2, 3, 4, 5, 6)
]


def test_the_valid_robots_are_every_combination_the_rules_allow() -> None:
    team = team_of()
    ugv, uav = team.selections
    assert sorted(robots(team.rules, uav.domains), key=str) == sorted(UAV_ROBOTS, key=str)
    assert len(list(robots(team.rules, ugv.domains))) == 9  # 3 sensor types x 3 counts


def test_without_its_constraints_the_forbidden_robots_are_valid_again() -> None:
    team = team_of()
    _, uav = team.selections
    every = list(robots(team.rules, uav.domains, constraints=()))
    assert len(every) == 18  # 3 sensor types x 6 counts
    assert ("UAV", "microphone", 3) in every


def test_a_selection_only_the_rules_forbid_has_no_valid_robot() -> None:
    rules = rules_of()
    microphones = (("UAV",), ("microphone",), (1, 2))
    assert not is_satisfiable(rules, microphones)
    assert list(robots(rules, microphones)) == []
    assert is_satisfiable(rules, microphones, constraints=())


def test_an_empty_domain_is_no_problem_at_all() -> None:
    rules = rules_of()
    empty = (("UGV",), (), (1,))
    assert build_problem(rules, empty) is None
    assert list(robots(rules, empty)) == []
    assert not is_satisfiable(rules, empty)


def test_a_robot_is_told_the_rules_it_breaks_in_declared_order() -> None:
    rules = rules_of()
    (no_microphone,) = rules.constraints
    assert violated_constraints(rules, ("UAV", "microphone", 1)) == (no_microphone,)
    assert violated_constraints(rules, ("UGV", "microphone", 1)) == ()


def test_a_value_that_reads_as_python_is_compared_never_run() -> None:
    # python-constraint parses string constraints as Python; rules are never handed to it.
    code = "__import__('os')._exit(3)"
    rule = RuleConstraint(
        code, "forbid", (), (Condition("sensor_type", frozenset({code}), code),), Location("r")
    )
    rules = replace(rules_of(), constraints=(rule,))
    assert len(list(robots(rules, (("UGV",), ("camera", code), (1,))))) == 1
