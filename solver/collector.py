"""Python's cycle collector held off while many acyclic values are built.

Reading a document makes an object or more for every node, and solving makes one or more for
every configuration it lists; none of them is in a reference cycle. The collector walks every
live object each time its oldest generation has grown by a quarter, so while such values pile
up those walks are pure cost, and the larger the process's heap (a test runner's, a studio's)
the more: they made reading grow faster than the file (3.4x per doubling at 10,240 values, 2x
without them) and took half of listing 8,000 configurations. What is built meanwhile is
bounded (:mod:`solver.limits`), so what is held until the collector runs again is too.

Not here: what is read (:mod:`solver.files.yamlio`) or solved (:mod:`solver.solving.solution`).
"""

from __future__ import annotations

import contextlib
import gc
from collections.abc import Iterator

__all__ = ["collector_paused"]


@contextlib.contextmanager
def collector_paused() -> Iterator[None]:
    """The cycle collector off for the block (or the decorated call), then on again as it was.

    Nested or overlapping uses (threads of one studio) end with the collector as the first one
    found it: only a use that found it on turns it back on.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()
