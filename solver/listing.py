"""Streaming every valid robot of a solved team with its UI configuration number.

The article's toolbox keeps "a list containing all valid robot combinations"; an operator
station looks a robot up in it. This writes that list as CSV or JSON lines while enumerating,
so memory stays constant however many robots there are.

Not here: choosing configurations (:mod:`solver.solution`) or enumerating
(:mod:`solver.engines`).
"""

from __future__ import annotations

import csv
import json
from collections.abc import Iterator
from typing import TextIO

from solver import engines
from solver.constraints import Value
from solver.engines import ENUMERATING, MAX_ROBOTS
from solver.errors import TooLargeError
from solver.render import csv_cell, csv_row
from solver.solution import Solution

__all__ = ["numbered_robots", "write_robots"]


def numbered_robots(
    solution: Solution, engine: str = ENUMERATING[0]
) -> Iterator[tuple[int, tuple[Value, ...]]]:
    """(configuration number, robot) for every valid robot, kinematic types in rule order.

    ``engine`` names the engine that enumerates (:func:`solver.engines.lookup`: an
    :class:`~solver.errors.InputError` for an unknown name).
    """
    rules = solution.rules
    enumerator = engines.lookup(engine)
    default = solution.default_configuration
    # Where every value has at most one component (the article's case), a robot's configuration
    # is a table lookup per characteristic: no search over configurations per robot.
    simple = all(len(m) <= 1 for c in rules.characteristics for m in c.membership)
    tables = [
        {
            value: members[0]
            for value, members in zip(c.values, c.membership, strict=True)
            if members
        }
        for c in rules.characteristics
    ]
    numbers = {c.key: c.number for c in solution.configurations}
    for selection in solution.team.selections:
        for robot in enumerator.robots(rules, selection):
            if simple:
                try:
                    key = tuple([table[value] for table, value in zip(tables, robot, strict=True)])
                except KeyError:  # a value in no component: unserved
                    yield default, robot
                    continue
                yield numbers.get(key, default), robot
                continue
            configuration = solution.configuration_for(robot)
            yield (default if configuration is None else configuration.number), robot


def write_robots(
    solution: Solution,
    stream: TextIO,
    *,
    fmt: str = "csv",
    engine: str = ENUMERATING[0],
    max_robots: int = MAX_ROBOTS,
) -> int:
    """Write every numbered robot to ``stream``; returns how many were written.

    :class:`TooLargeError`, before writing anything, when there are more than ``max_robots``.
    """
    total = solution.totals.valid_robots
    if total > max_robots:
        raise TooLargeError.at(
            solution.team.file,
            f"listing {total} robots is refused (more than {max_robots}, see --max-robots)",
        )
    names = solution.rules.names
    written = 0
    if fmt == "csv":
        writer = csv.writer(stream, lineterminator="\n")
        # Names come from rule files: no cell may read as a spreadsheet formula. Values are
        # few and robots many, so each value's cell is made once.
        writer.writerow(csv_row(["configuration", *names]))
        cells = [
            {value: csv_cell(value) for value in c.values} for c in solution.rules.characteristics
        ]

        def rows() -> Iterator[list[object]]:
            nonlocal written
            for number, robot in numbered_robots(solution, engine):
                written += 1
                yield [number, *[cell[value] for cell, value in zip(cells, robot, strict=True)]]

        writer.writerows(rows())
        return written
    for number, robot in numbered_robots(solution, engine):
        stream.write(
            json.dumps(
                {"configuration": number, **dict(zip(names, robot, strict=True))},
                ensure_ascii=False,
            )
            + "\n"
        )
        written += 1
    return written
