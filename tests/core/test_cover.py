"""The exact minimum cover behind partitions with overlapping components."""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from solver.core.cover import minimum_cover

Key = tuple[int, ...]

elements = st.lists(
    st.frozensets(st.tuples(st.integers(0, 6)), min_size=1, max_size=3), min_size=1, max_size=8
)


def brute_force_minimum(sets: list[frozenset[Key]]) -> int:
    keys = sorted(set().union(*sets))
    for size in range(1, len(keys) + 1):
        for chosen in itertools.combinations(keys, size):
            if all(s & set(chosen) for s in sets):
                return size
    raise AssertionError("unreachable: all keys together always cover")


@settings(max_examples=300, deadline=None)
@given(elements)
def test_minimum_cover_hits_every_element_with_the_fewest_keys(sets: list[frozenset[Key]]) -> None:
    cover = minimum_cover(sets)
    assert all(s & cover for s in sets)
    assert len(cover) == brute_force_minimum(sets)


def test_a_cycle_of_pairs_needs_half_its_keys_rounded_up() -> None:
    sets = [frozenset({(i,), ((i + 1) % 9,)}) for i in range(9)]
    cover = minimum_cover(sets)
    assert all(s & cover for s in sets)
    assert len(cover) == 5
