"""Streaming every valid robot of a solved team with its UI configuration number.

The article's toolbox keeps "a list containing all valid robot combinations"; an operator
station looks a robot up in it. This writes that list as CSV or JSON lines while enumerating,
so memory stays constant however many robots there are.

Not here: choosing configurations (:mod:`solver.solution`) or enumerating (:mod:`solver.stream`,
:mod:`solver.model`).
"""

from __future__ import annotations

import csv
import json
from collections.abc import Iterator
from typing import TextIO

from solver.constraints import Value
from solver.solution import MAX_ROBOTS, Solution, TooLargeError

__all__ = ["numbered_robots", "write_robots"]


def numbered_robots(solution: Solution, engine: str = "fast"
                    ) -> Iterator[tuple[int, tuple[Value, ...]]]:
    """(configuration number, robot) for every valid robot, kinematic types in rule order."""
    rules = solution.rules
    for selection in solution.team.selections:
        if engine == "csp":
            from solver.model import robots

            stream = robots(rules, selection.domains)
        else:
            from solver.stream import robots_stream

            stream = robots_stream(rules, selection)
        for robot in stream:
            configuration = solution.configuration_for(robot)
            number = solution.default_configuration if configuration is None \
                else configuration.number
            yield number, robot


def write_robots(solution: Solution, stream: TextIO, *, fmt: str = "csv",
                 engine: str = "fast", max_robots: int = MAX_ROBOTS) -> int:
    """Write every numbered robot to ``stream``; returns how many were written.

    :class:`TooLargeError`, before writing anything, when there are more than ``max_robots``.
    """
    total = solution.totals.valid_robots
    if total > max_robots:
        raise TooLargeError.at(solution.team.file, f"listing {total} robots is refused (more "
                                                   f"than {max_robots}, see --max-robots)")
    names = solution.rules.names
    written = 0
    if fmt == "csv":
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(["configuration", *names])
        for number, robot in numbered_robots(solution, engine):
            writer.writerow([number, *robot])
            written += 1
        return written
    for number, robot in numbered_robots(solution, engine):
        stream.write(json.dumps({"configuration": number, **dict(zip(names, robot, strict=True))},
                                ensure_ascii=False) + "\n")
        written += 1
    return written
