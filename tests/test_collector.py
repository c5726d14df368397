"""The cycle collector is held off for a block and left as the block found it.

The collector's switch is one per process: a block that another test's thread (a studio or a
watcher left serving in the same test worker) holds open would turn it off under these checks.
So each check runs in an interpreter of its own, where no other thread uses it.
"""

from __future__ import annotations

import textwrap

from tests.conftest import holds_alone


def holds(check: str) -> None:
    """Run ``check`` (Python, with ``gc``, ``pytest`` and ``collector_paused`` imported) in a
    fresh interpreter; its assertions must hold."""
    holds_alone(
        "import gc\nimport pytest\nfrom solver.collector import collector_paused\n"
        + textwrap.dedent(check)
    )


def test_a_block_holds_it_off_and_turns_it_back_on_even_when_it_raises() -> None:
    holds(
        """
        seen = []

        @collector_paused()
        def fails():
            seen.append(gc.isenabled())
            raise KeyError("x")

        assert gc.isenabled()
        with pytest.raises(KeyError):
            fails()
        assert seen == [False]
        assert gc.isenabled()
        """
    )


def test_nested_blocks_end_with_it_as_the_outermost_found_it() -> None:
    holds(
        """
        with collector_paused():
            with collector_paused():
                assert not gc.isenabled()
            assert not gc.isenabled()  # the inner block found it off: it stays off
        assert gc.isenabled()
        """
    )


def test_a_block_that_found_it_off_leaves_it_off() -> None:
    holds(
        """
        gc.disable()
        with collector_paused():
            pass
        assert not gc.isenabled()
        """
    )
