"""The exact minimum cover behind partitions with overlapping components.

When a value belongs to several components, a robot can use several configurations, and the
fewest configurations serving every robot is a minimum hitting set: choose keys so that every
element (the keys one class of robots can use) contains at least one. That is a small integer
program, solved here by HiGHS (``highspy``), a maintained MIP solver that proves its answers
optimal: one binary variable per key, minimise their sum, one ``>= 1`` row per element.

>>> sorted(minimum_cover([frozenset({(1,), (2,)}), frozenset({(2,), (3,)})]))
[(2,)]

Not here: which robots go to which chosen configuration
(:func:`solver.core.partition.partition_classes`).
"""

from __future__ import annotations

from collections.abc import Sequence

import highspy
import numpy as np

from solver.errors import StructureTooComplex

__all__ = ["minimum_cover"]

Key = tuple[int, ...]


def minimum_cover(elements: Sequence[frozenset[Key]]) -> frozenset[Key]:
    """The fewest keys such that every element contains at least one of them, proven minimal.

    :class:`~solver.errors.StructureTooComplex` if HiGHS ends without a proven optimum (it does
    not stop early: no time or node limit is set, so this means the solver itself failed).
    """
    # An element that contains another is hit whenever the smaller one is: drop it. What is
    # left is usually tiny, and singletons are forced choices.
    unique = sorted(set(elements), key=lambda e: (len(e), sorted(e)))
    reduced: list[frozenset[Key]] = []
    for element in unique:
        if not any(other <= element for other in reduced):
            reduced.append(element)
    forced = {next(iter(e)) for e in reduced if len(e) == 1}
    open_elements = [e for e in reduced if forced.isdisjoint(e)]
    if not open_elements:
        return frozenset(forced)
    keys = sorted(set().union(*open_elements))
    column = {key: i for i, key in enumerate(keys)}
    starts = [0]
    indices: list[int] = []
    for element in open_elements:
        indices.extend(sorted(column[key] for key in element))
        starts.append(len(indices))
    solver = highspy.Highs()  # type: ignore[no-untyped-call]  # highspy ships no hints here
    solver.setOptionValue("output_flag", False)
    # One thread: the same input gives the same cover on every machine and run.
    solver.setOptionValue("threads", 1)
    model = highspy.HighsLp()
    model.num_col_ = len(keys)
    model.num_row_ = len(open_elements)
    model.col_cost_ = np.ones(len(keys))
    model.col_lower_ = np.zeros(len(keys))
    model.col_upper_ = np.ones(len(keys))
    model.row_lower_ = np.ones(len(open_elements))
    model.row_upper_ = np.full(len(open_elements), highspy.kHighsInf)
    model.a_matrix_.format_ = highspy.MatrixFormat.kRowwise
    model.a_matrix_.start_ = np.array(starts, dtype=np.int32)
    model.a_matrix_.index_ = np.array(indices, dtype=np.int32)
    model.a_matrix_.value_ = np.ones(len(indices))
    model.integrality_ = [highspy.HighsVarType.kInteger] * len(keys)
    solver.passModel(model)
    solver.run()
    status = solver.getModelStatus()
    if status != highspy.HighsModelStatus.kOptimal:
        raise StructureTooComplex.at(
            "<cover>",
            "the minimum cover of overlapping components "
            "was not proven: "
            f"{solver.modelStatusToString(status)}",
        )
    values = solver.getSolution().col_value
    return frozenset(forced | {key for key, value in zip(keys, values, strict=True) if value > 0.5})
