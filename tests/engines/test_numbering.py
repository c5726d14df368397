"""A robot's configuration number without listing the configurations (solver.engines.numbering):
the place of a key among a product of parts, and the number each robot of a team is given;
numbers worked out by hand (tests.handcounted)."""

from __future__ import annotations

import numpy as np
import pytest

from solver.engines.numbering import Numbers, Ranks
from tests.handcounted import OVERLAPPING_RULES, team_of


def test_a_key_is_ranked_among_the_product_of_the_parts_in_lexicographic_order() -> None:
    # Place 0 takes 0 or 2, place 1 takes 1, 3 or 4: (0,1) (0,3) (0,4) (2,1) (2,3) (2,4).
    ranks = Ranks([((0,), np.array([[0], [2]])), ((1,), np.array([[1], [3], [4]]))])
    assert ranks.size == 6
    assert [ranks.rank(key) for key in [(0, 1), (0, 4), (2, 1), (2, 3), (2, 4)]] == [0, 2, 3, 4, 5]
    assert ranks.rank((1, 1)) is None
    assert ranks.rank((2, 2)) is None


def test_parts_over_places_that_interleave_rank_keys_place_by_place() -> None:
    # One part holds places 0 and 2 ((0,0) or (1,1)), the other place 1 (5 or 6).
    ranks = Ranks([((0, 2), np.array([[0, 0], [1, 1]])), ((1,), np.array([[5], [6]]))])
    keys = [(0, 5, 0), (0, 6, 0), (1, 5, 1), (1, 6, 1)]
    assert [ranks.rank(key) for key in keys] == [0, 1, 2, 3]
    assert ranks.rank((0, 5, 1)) is None


@pytest.mark.parametrize(
    ("robot", "number"),
    [
        (("UGV", "camera", 1), 1),  # visual, few
        (("UGV", "lidar", 5), 2),  # visual, many
        (("UGV", "microphone", 2), 3),  # audio, few
        (("UGV", "microphone", 5), 4),  # audio, many
        (("UAV", "camera", 1), 5),  # the UAV's first: after the UGV's four
        (("UAV", "lidar", 6), 6),
    ],
)
def test_each_robot_of_the_team_is_given_its_configurations_number(
    robot: tuple[str, str, int], number: int
) -> None:
    team = team_of()
    ugv, uav = team.selections
    numbers = {"UGV": Numbers(team.rules, ugv, 1), "UAV": Numbers(team.rules, uav, 5)}
    assert numbers[robot[0]].number(robot) == number


def test_each_kinematic_type_knows_how_many_configurations_it_has() -> None:
    team = team_of()
    assert [Numbers(team.rules, s, 1).size for s in team.selections] == [4, 2]


def test_with_overlapping_components_a_robot_gets_the_lowest_numbered_it_can_use() -> None:
    team = team_of("team: {UGV: {}}", OVERLAPPING_RULES)
    (ugv,) = team.selections
    numbers = Numbers(team.rules, ugv, 1)
    assert numbers.size == 2
    assert [numbers.number(("UGV", sensor)) for sensor in ("camera", "lidar", "microphone")] == [
        1,
        1,
        2,
    ]
    assert numbers.number(("UGV", "sonar")) is None  # in no component: the default
    assert numbers.number(("UGV", "radar")) is None  # no value of the rules
