"""The exact minimum cover behind partitions with overlapping components."""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from solver.partition import minimum_cover

Key = tuple[int, ...]

elements = st.lists(st.frozensets(st.tuples(st.integers(0, 6)), min_size=1, max_size=3),
                    min_size=1, max_size=8)


def brute_force_minimum(sets: list[frozenset[Key]]) -> int:
    keys = sorted(set().union(*sets))
    for size in range(1, len(keys) + 1):
        for chosen in itertools.combinations(keys, size):
            if all(s & set(chosen) for s in sets):
                return size
    raise AssertionError("unreachable: all keys together always cover")


@settings(max_examples=300, deadline=None)
@given(elements)
def test_minimum_cover_hits_every_element_with_the_fewest_keys(sets: list[frozenset[Key]]
                                                               ) -> None:
    cover, proven = minimum_cover(sets)
    assert proven
    assert all(s & cover for s in sets)
    assert len(cover) == brute_force_minimum(sets)


def test_minimum_cover_says_when_it_ran_out_of_search_nodes() -> None:
    # A cycle of pairs needs ceil(n/2) keys; with one node allowed the search cannot prove it.
    sets = [frozenset({(i,), ((i + 1) % 9,)}) for i in range(9)]
    cover, proven = minimum_cover(sets, node_limit=1)
    assert not proven
    assert all(s & cover for s in sets)
    assert minimum_cover(sets) == (minimum_cover(sets)[0], True)
    assert len(minimum_cover(sets)[0]) == 5
