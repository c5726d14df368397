"""The engines as one family: looked up by name, the same answers, unknown names refused."""

from __future__ import annotations

import io

import pytest

from solver import InputError, load_team, solve
from solver.engines import DESCRIPTIONS, ENUMERATING, NAMES, Memo, choose, lookup
from solver.reporting.listing import write_robots
from tests.conftest import TEAMS


@pytest.mark.parametrize("name", list(DESCRIPTIONS))
def test_every_engine_counts_and_partitions_case_3_alike(name: str) -> None:
    team = load_team(TEAMS / "case3.yaml")
    engine = lookup(name)
    reference = lookup("csp")
    for selection in team.selections:
        counts = engine.count(team.rules, selection, Memo())
        part = engine.partition(team.rules, selection, Memo())
        assert counts == reference.count(team.rules, selection, Memo())
        assert part == reference.partition(team.rules, selection, Memo())
        assert sorted(engine.robots(team.rules, selection), key=repr) == sorted(
            reference.robots(team.rules, selection), key=repr
        )


def test_an_unknown_engine_name_is_refused_everywhere() -> None:
    team = load_team(TEAMS / "case1.yaml")
    with pytest.raises(InputError, match="unknown engine 'quick'; choose from structure, fast"):
        lookup("quick")
    with pytest.raises(InputError, match="unknown engine 'quick'; choose from auto, structure"):
        solve(team, engine="quick")
    # Listing used to run the fast engine for any name it did not know.
    with pytest.raises(InputError, match="unknown engine 'quick'"):
        write_robots(solve(team), io.StringIO(), engine="quick")


def test_auto_takes_the_structure_and_names_the_engine_it_used() -> None:
    team = load_team(TEAMS / "case3.yaml")
    chosen = [choose(team, s, "auto", 10**8, Memo())[0] for s in team.selections]
    assert chosen == ["structure"] * len(team.selections)
    assert set(ENUMERATING) < set(NAMES)
    assert {t.method for t in solve(team, engine="csp").by_type} == {"csp"}
