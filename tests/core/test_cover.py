"""The exact minimum cover behind partitions with overlapping components."""

from __future__ import annotations

import itertools
import json
import random
from collections.abc import Collection, Sequence
from dataclasses import replace
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from solver import limits
from solver.core.cover import Options, Pieces, factors, minimum_cover, product_cover
from solver.limits import limit
from tests.conftest import run_cli, run_process

Key = tuple[int, ...]

# Families over one position: each element the components one value belongs to.
options = st.lists(st.integers(0, 4), min_size=1, max_size=3, unique=True).map(
    lambda found: tuple(sorted(found))
)
families = st.lists(options, min_size=1, max_size=5).map(lambda found: {(o,) for o in found})
# Smaller, for products whose minimum is found by trying every set of keys (16 keys at most).
small_options = st.lists(st.integers(0, 3), min_size=1, max_size=2, unique=True).map(
    lambda found: tuple(sorted(found))
)
small_families = st.lists(small_options, min_size=1, max_size=4).map(
    lambda found: {(o,) for o in found}
)


def keys_of(element: Options) -> set[Key]:
    return set(itertools.product(*element))


def brute_force_minimum(elements: list[Options]) -> int:
    """The fewest keys hitting every element, trying every set of keys by size."""
    sets = [keys_of(element) for element in elements]
    keys = sorted(set().union(*sets))
    for size in range(1, len(keys) + 1):
        for chosen in itertools.combinations(keys, size):
            if all(s & set(chosen) for s in sets):
                return size
    raise AssertionError("unreachable: all keys together always cover")


def fewest_keys(elements: Sequence[Options]) -> int:
    """The fewest keys hitting every element, by an exhaustive search: every cover holds a key of
    each element, so branching on the keys of an element not yet hit visits a smallest cover;
    a branch stops when it holds as many keys as the best found, with the elements it misses
    that share no key counted as keys still to come (each needs one of its own). Sets of keys
    are bit masks."""
    keys = sorted(set().union(*map(keys_of, elements)))
    bit = {key: 1 << i for i, key in enumerate(keys)}
    masks = sorted({sum(bit[key] for key in keys_of(element)) for element in elements})
    best = len(keys)

    def search(chosen: int, size: int) -> None:
        nonlocal best
        missed = [mask for mask in masks if not mask & chosen]
        if not missed:
            best = min(best, size)
            return
        taken = apart = 0
        for mask in missed:
            if not mask & taken:
                taken |= mask
                apart += 1
        if size + apart >= best:
            return
        branch = min(missed, key=int.bit_count)
        while branch:
            low = branch & -branch
            search(chosen | low, size + 1)
            branch ^= low

    search(0, 0)
    return best


def ring(first: int, size: int) -> set[Options]:
    """Values each in two of ``size`` components numbered from ``first``, in a cycle."""
    return {
        ((first + i, first + (i + 1) % size),) if i + 1 < size else ((first, first + i),)
        for i in range(size)
    }


@st.composite
def apart_pieces(draw: st.DrawFn, keys: int) -> set[Options]:
    """A family over one position made of pieces that share no component: rings (odd ones
    cover with more keys than they pack), runs of pairs, or random options, at most ``keys``
    components in all, sometimes with unused components between pieces."""
    family: set[Options] = set()
    first = 0
    while first < keys - 1 and (not family or draw(st.integers(0, 3)) > 0):
        size = draw(st.integers(2, min(5, keys - first)))
        kind = draw(st.sampled_from(["ring", "ring", "run", "random"]))
        if kind == "ring" and size >= 3:
            family |= ring(first, size)
        elif kind == "run":
            family |= {((first + i, first + i + 1),) for i in range(size - 1)}
        else:
            found = draw(
                st.lists(
                    st.lists(st.integers(0, size - 1), min_size=1, max_size=2, unique=True),
                    min_size=1,
                    max_size=4,
                )
            )
            family |= {(tuple(sorted(first + c for c in option)),) for option in found}
        first += size + draw(st.integers(0, 1))
    return family


def product(*parts: Collection[Options]) -> list[Options]:
    """Every element of the product of families over consecutive positions."""
    return [tuple(o for element in choice for o in element) for choice in itertools.product(*parts)]


def assert_is_a_cover(elements: Sequence[Options], chosen: list[Key]) -> None:
    assert all(keys_of(element) & set(chosen) for element in elements)


@settings(max_examples=300, deadline=None)
@given(families)
def test_minimum_cover_hits_every_element_with_the_fewest_keys(family: set[Options]) -> None:
    elements = sorted(family)
    cover = minimum_cover(elements)
    assert_is_a_cover(elements, cover.chosen())
    assert cover.size == len(cover.chosen()) == brute_force_minimum(elements)


@settings(max_examples=150, deadline=None)
@given(st.lists(small_families, min_size=2, max_size=2))
def test_a_product_of_families_is_covered_with_the_fewest_keys(parts: list[set[Options]]) -> None:
    elements = product(*parts)
    cover = minimum_cover(elements)
    assert_is_a_cover(elements, cover.chosen())
    assert cover.size == brute_force_minimum(elements)


@settings(max_examples=150, deadline=None)
@given(st.lists(families, min_size=2, max_size=3))
def test_a_product_given_in_parts_has_the_cover_of_its_elements_listed(
    parts: list[set[Options]],
) -> None:
    listed = minimum_cover(product(*parts))
    given_in_parts = product_cover(len(parts), [((i,), part) for i, part in enumerate(parts)])
    assert given_in_parts.chosen() == listed.chosen()
    for element in product(*parts):
        assert given_in_parts.first(element) == listed.first(element)


@settings(max_examples=150, deadline=None)
@given(st.lists(families, min_size=1, max_size=3))
def test_each_element_is_given_the_lowest_chosen_key_it_allows(parts: list[set[Options]]) -> None:
    elements = product(*parts)
    cover = minimum_cover(elements)
    for element in elements:
        allowed = sorted(keys_of(element) & set(cover.chosen()))
        assert cover.first(element) == allowed[0]


def test_a_cycle_of_pairs_needs_half_its_keys_rounded_up() -> None:
    elements: list[Options] = [((i, (i + 1) % 9),) for i in range(9)]
    cover = minimum_cover(elements)
    assert_is_a_cover(elements, cover.chosen())
    assert cover.size == 5


def test_two_triangles_are_covered_by_three_keys_not_the_product_of_two_each() -> None:
    # Three values each in two of three components: any two values share a component, so one
    # diagonal of three keys serves the product; the product of the two covers would be four.
    triangle: set[Options] = {((0, 1),), ((1, 2),), ((0, 2),)}
    elements = product(triangle, triangle)
    cover = minimum_cover(elements)
    assert_is_a_cover(elements, cover.chosen())
    assert cover.size == 3


@settings(max_examples=200, deadline=None)
@given(
    st.one_of(
        st.lists(apart_pieces(6), min_size=2, max_size=2),
        st.tuples(apart_pieces(4), apart_pieces(3), apart_pieces(3)).map(list),
    )
)
def test_a_product_of_families_in_apart_pieces_is_covered_with_the_fewest_keys(
    parts: list[set[Options]],
) -> None:
    elements = product(*parts)
    cover = product_cover(len(parts), [((i,), part) for i, part in enumerate(parts)])
    chosen = cover.chosen()
    assert_is_a_cover(elements, chosen)
    assert cover.size == len(chosen) == len(set(chosen)) == fewest_keys(elements)
    listed = minimum_cover(elements)
    assert listed.chosen() == chosen
    for element in elements:
        lowest = min(keys_of(element) & set(chosen))
        assert cover.first(element) == listed.first(element) == lowest


def test_three_rings_of_three_need_five_keys_and_no_fewer() -> None:
    # 27 elements of eight keys each among 27 keys: at least four; the search finds that no
    # four serve every element (see benchmarks/bench_overlap.py, which counts on this).
    triangle = ring(0, 3)
    elements = product(triangle, triangle, triangle)
    assert fewest_keys(elements) == 5
    assert not any(
        all(keys_of(element) & set(chosen) for element in elements)
        for chosen in itertools.combinations(sorted(keys_of(((0, 1, 2),) * 3)), 4)
    )
    cover = product_cover(3, [((i,), triangle) for i in range(3)])
    assert cover.size == 5
    assert_is_a_cover(elements, cover.chosen())


def test_rings_over_apart_blocks_add_over_each_choice_of_blocks_without_listing_them() -> None:
    # 400 blocks of three components in a ring per characteristic: each choice of one block
    # per characteristic needs 3 (two characteristics) or 5 (three); none is listed to count.
    blocks = set().union(*(ring(3 * b, 3) for b in range(400)))
    two = product_cover(2, [((i,), blocks) for i in range(2)])
    three = product_cover(3, [((i,), blocks) for i in range(3)])
    assert (two.size, three.size) == (3 * 400**2, 5 * 400**3)
    group = three.groups[0]
    assert isinstance(group, Pieces)
    element = ((3, 5), (6, 7), (9, 11))  # a value of the second ring in each, and so on
    key = three.first(element)
    assert key == group.first(element)
    assert all(map(tuple.__contains__, element, key))


def test_pieces_of_a_factor_over_two_positions_are_covered_between_the_others() -> None:
    # A factor over positions 0 and 2 (the second always repeats the first: not a product),
    # in two pieces, each a ring of three; rings of three at positions 1 and 3. A choice of
    # pieces is then three or four rings: 3 and 5 keys, twice.
    diagonal: set[Options] = {
        ((f + a, f + b), (f + a, f + b)) for f in (0, 3) for a, b in ((0, 1), (1, 2), (0, 2))
    }
    triangle = ring(0, 3)
    two: list[Options] = [(a[0], b[0], a[1]) for a in diagonal for b in triangle]
    three: list[Options] = [
        (a[0], b[0], a[1], c[0]) for a in diagonal for b in triangle for c in triangle
    ]
    cases: list[tuple[int, list[Options], list[tuple[tuple[int, ...], set[Options]]], int]] = [
        (3, two, [((0, 2), diagonal), ((1,), triangle)], 2 * 3),
        (4, three, [((0, 2), diagonal), ((1,), triangle), ((3,), triangle)], 2 * 5),
    ]
    for width, elements, parts, expected in cases:
        cover = product_cover(width, parts)
        chosen = cover.chosen()
        assert cover.size == len(chosen) == expected
        assert chosen == minimum_cover(elements).chosen()
        for element in elements:
            assert cover.first(element) == min(keys_of(element) & set(chosen))
    assert fewest_keys(two) == 2 * 3


def test_sliding_windows_multiply_their_covers() -> None:
    # Windows of four values sliding by two over 40 values: a value in two windows; each
    # characteristic needs 10 windows, and three of them 1,000 configurations.
    windows = {(tuple(s for s in range(19) if 2 * s <= v <= 2 * s + 3),) for v in range(40)}
    cover = product_cover(3, [((i,), windows) for i in range(3)])
    assert cover.size == 1000


def test_a_product_is_split_into_its_factors_and_a_linked_pair_is_not() -> None:
    linked: set[Options] = {((0,), (0,)), ((1,), (1,))}  # the first position decides the second
    free: set[Options] = {((0, 1),), ((2,),)}
    elements = set(product(linked, free))
    found = factors((0, 1, 2), elements)
    assert [positions for positions, _ in found] == [(0, 1), (2,)]
    assert found[0][1] == linked
    assert found[1][1] == free


def test_a_cover_of_many_programs_shares_one_time_limit_and_is_refused_past_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Three characteristics of 12 rings of five components, each ring in an order of its own
    # (so no two have the same shape): 1,728 choices of rings, each its own small program, none
    # near the limit alone. Refused once their sum is past the limit, lowered to 1 s.
    orders = [(0, *rest) for rest in itertools.permutations(range(1, 5)) if rest[0] < rest[-1]]
    lines = ["characteristics:", "  kinematic_type: {values: [A]}"]
    for c in range(3):
        lines += [f"  c{c}:", f"    values: [{', '.join(f'v{i}' for i in range(60))}]"]
        lines.append("    components:")
        for r, order in enumerate(orders):
            # Value i of ring r is in the ring's components order[i] and order[i + 1].
            for k in range(5):
                holds = [f"v{5 * r + i}" for i in range(5) if k in (order[i], order[(i + 1) % 5])]
                lines.append(f"      - {{name: r{r}k{k}, values: [{', '.join(holds)}]}}")
    rules = tmp_path / "rings.yaml"
    rules.write_text("\n".join(lines) + "\n", encoding="utf-8")
    monkeypatch.setitem(limits._BY_NAME, "cover-seconds", replace(limit("cover-seconds"), value=1))
    result = run_cli("count", rules)
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr == (
        f"{rules}: the minimum cover of overlapping components stopped after 1 s "
        "(limit 'cover-seconds', docs/security.md)\n"
    )


def test_overlapping_counts_in_json_are_json_alone(tmp_path: Path) -> None:
    # HiGHS prints a banner on the standard output's file descriptor unless told not to first.
    rules = {
        "characteristics": {
            "kinematic_type": {"values": ["T0"]},
            "c": {
                "values": ["a", "b", "c"],
                "components": [
                    {"name": "X", "values": ["a", "b"]},
                    {"name": "Y", "values": ["b", "c"]},
                ],
            },
        }
    }
    (tmp_path / "rules.yaml").write_text(yaml.safe_dump(rules, sort_keys=False), encoding="utf-8")
    (tmp_path / "team.yaml").write_text("rules: rules.yaml\nteam:\n  T0: {}\n", encoding="utf-8")
    done = run_process("count", tmp_path / "team.yaml", "--format", "json")
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["totals"]["ui_configurations"] == 2


def test_a_cover_past_its_time_limit_is_refused_naming_the_rule_set_and_the_limit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 300 sensor types in 100 overlapping groups of 30 (seeded): a set cover HiGHS took
    # 111 s to prove minimal. Refused at the limit, lowered here to its least, 1 s.
    chosen = random.Random(2)
    values = [f"s{i}" for i in range(300)]
    groups = [sorted(chosen.sample(range(300), 30)) for _ in range(100)]
    rules = tmp_path / "overlapping.yaml"
    rules.write_text(
        "characteristics:\n  kinematic_type: {values: [A]}\n"
        f"  sensor:\n    values: [{', '.join(values)}]\n    components:\n"
        + "".join(
            f"      - {{name: g{g}, values: [{', '.join(values[i] for i in members)}]}}\n"
            for g, members in enumerate(groups)
        ),
        encoding="utf-8",
    )
    monkeypatch.setitem(limits._BY_NAME, "cover-seconds", replace(limit("cover-seconds"), value=1))
    result = run_cli("count", rules)
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == (
        f"{rules}: the minimum cover of overlapping components stopped after 1 s "
        "(limit 'cover-seconds', docs/security.md)\n"
    )
