"""The reference engine: every valid robot from python-constraint's solution iterator.

Slow but obviously right: each robot comes from :func:`solver.core.model.robots`, the same
constraint model ``check`` and ``assign`` use, and is partitioned one by one
(:func:`solver.core.partition.partition`). The property tests hold the other engines to its answers.

Not here: the constraint model itself (:mod:`solver.core.model`).
"""

from __future__ import annotations

from collections.abc import Iterator

from solver.core import model
from solver.core import partition as partitioning
from solver.core.constraints import Value
from solver.core.partition import Partition
from solver.core.ruleset import RuleSet
from solver.core.team import TypeSelection
from solver.engines.shared import Counts

__all__ = ["count", "partition", "robots"]


def count(rules: RuleSet, selection: TypeSelection, _memo: object = None) -> Counts:
    """Valid robots and UI configurations of one kinematic type, by enumerating them."""
    part = partition(rules, selection)
    return Counts(
        selection.kinematic_type, part.valid_robots, len(part.classes), part.unserved_robots
    )


def partition(rules: RuleSet, selection: TypeSelection, _memo: object = None) -> Partition:
    """The configurations of one kinematic type (the memo is unused)."""
    return partitioning.partition(rules, selection.kinematic_type, robots(rules, selection))


def robots(rules: RuleSet, selection: TypeSelection) -> Iterator[tuple[Value, ...]]:
    """Every valid robot of one kinematic type, in python-constraint's order."""
    return model.robots(rules, selection.domains)
