"""Identification grows with the description, not with its square.

Counted in function calls (Python's and the C functions it calls), which are the same on a busy
machine as on an idle one: a description four times as big costs about four times the calls
where the work is linear, sixteen where it is quadratic. ``benchmarks/bench_identify.py`` times
three of them in seconds. A rule that compared every two of a palm's single hinges (``f6d3d11``)
made a star of 80,000 links take 442 s there, unseen for four stops, as no test failed: the star
here costs 10.2x the calls at 4x the links with that comparison, 3.9x with the box around the
hinges telling (:func:`solver.identify.pose.within`).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from types import FrameType
from typing import Any

import pytest

from solver.core.rules import default_rules_path, load_rules
from solver.identify import identify_urdf, load_profile
from tests.identify.shapes import SHAPES

SMALL, BIG = 500, 2000  # links; BIG is four times SMALL
GROWTH_LIMIT = 5.0  # at most this many times the calls for four times the links
PROFILE = load_profile()
RULES = load_rules(default_rules_path())


def calls(read: Callable[[], object]) -> int:
    """How many function calls ``read()`` makes."""
    count = 0

    def counted(_frame: FrameType, _event: str, _arg: Any) -> None:
        nonlocal count
        count += 1

    sys.setprofile(counted)
    try:
        read()
    finally:
        sys.setprofile(None)
    return count


@pytest.mark.parametrize("shape", list(SHAPES))
def test_a_description_four_times_as_big_costs_at_most_five_times_the_calls(shape: str) -> None:
    build = SHAPES[shape]
    small, big = build(SMALL), build(BIG)
    small_calls = calls(lambda: identify_urdf(small, rules=RULES, profile=PROFILE))
    big_calls = calls(lambda: identify_urdf(big, rules=RULES, profile=PROFILE))
    assert big_calls <= GROWTH_LIMIT * small_calls, (
        f"{shape}: {big_calls / small_calls:.1f}x the calls for {BIG // SMALL}x the links"
    )
