"""What the engines share: the counts every engine answers, and the memo one team's kinematic
types share while they are solved.

A leaf of the engines' wing: the interface (:mod:`solver.engines`) and every engine import it,
and it imports no engine, so the wing holds no circle.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from solver.core.cover import Cover

__all__ = ["Counts", "Memo"]


@dataclass(frozen=True, slots=True)
class Counts:
    """Exact counts for one kinematic type."""

    kinematic_type: str
    valid_robots: int
    ui_configurations: int
    unserved_robots: int


class Memo:
    """What one team's kinematic types can share: counts by selection structure, and the
    value classes of whole domains (most selections leave most characteristics whole).

    Only the structure engine (:mod:`solver.engines.structure`) reads and fills it; its value
    classes and blocks are that engine's own types, so they are ``Any`` here."""

    def __init__(self) -> None:
        self.counts: dict[tuple[object, ...], Counts] = {}
        # The structure engine's value classes of whole domains, by characteristic position.
        self.whole: dict[int, list[Any]] = {}
        # The blocks count() built for each kinematic type, for partition() to reuse.
        self.blocks: dict[str, list[Any]] = {}
        # The shape of the whole-domain class lists above, by identity.
        self.shapes: dict[int, tuple[tuple[int, int], ...]] = {}
        # The minimum cover count() found for each kinematic type whose values overlap.
        self.covers: dict[str, Cover] = {}
