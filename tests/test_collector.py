"""The cycle collector is held off for a block and left as the block found it."""

from __future__ import annotations

import gc

import pytest

from solver.collector import collector_paused


def test_a_block_holds_it_off_and_turns_it_back_on_even_when_it_raises() -> None:
    seen: list[bool] = []

    @collector_paused()
    def fails() -> None:
        seen.append(gc.isenabled())
        raise KeyError("x")

    assert gc.isenabled()
    with pytest.raises(KeyError):
        fails()
    assert seen == [False]
    assert gc.isenabled()


def test_nested_blocks_end_with_it_as_the_outermost_found_it() -> None:
    with collector_paused():
        with collector_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()  # the inner block found it off: it stays off
    assert gc.isenabled()


def test_a_block_that_found_it_off_leaves_it_off() -> None:
    gc.disable()
    try:
        with collector_paused():
            pass
        assert not gc.isenabled()
    finally:
        gc.enable()
