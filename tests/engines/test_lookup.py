"""The engines as one family: looked up by name, the same answers, unknown names refused."""

from __future__ import annotations

import io
import os
import subprocess
import sys

import pytest

from solver import InputError, load_team, solve
from solver.engines import DESCRIPTIONS, ENUMERATING, NAMES, Memo, choose, lookup
from solver.reporting.listing import write_robots
from tests.conftest import ROOT, TEAMS


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


# Eight threads look the structure engine up at once in a fresh interpreter, its module not
# yet imported, and each asks it for ``count``; prints how many found it missing.
FIRST_USE_IN_THREADS = """
import threading
from solver import engines
barrier = threading.Barrier(8)
missing = []
def look():
    barrier.wait()
    if not hasattr(engines.lookup("structure"), "count"):
        missing.append(1)
threads = [threading.Thread(target=look) for _ in range(8)]
for thread in threads:
    thread.start()
for thread in threads:
    thread.join()
print(len(missing))
"""


def test_threads_looking_an_engine_up_on_its_first_use_each_get_it_whole() -> None:
    # The studio solves in a thread pool: the first requests import an engine's module, and
    # a thread that came second got the module half made (no `count` yet).
    done = subprocess.run(
        [sys.executable, "-c", FIRST_USE_IN_THREADS],
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        check=True,
    )
    assert done.stdout.strip() == "0"
