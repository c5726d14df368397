"""Streaming every valid robot of a solved team with its UI configuration number.

The article's toolbox keeps "a list containing all valid robot combinations"; an operator
station looks a robot up in it. This writes that list as CSV or JSON lines while enumerating,
so memory stays constant however many robots there are.

Not here: choosing configurations (:mod:`solver.core.solution`) or enumerating
(:mod:`solver.engines`).
"""

from __future__ import annotations

import csv
import io
import itertools
import json
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, TextIO, TypeAlias

import numpy as np

from solver import engines
from solver.core.constraints import Value
from solver.core.solution import Solution
from solver.engines import ENUMERATING, MAX_ROBOTS
from solver.engines.fast import BlockLayout, robot_blocks
from solver.errors import TooLargeError
from solver.reporting.render import csv_cell, csv_row, json_printable

if TYPE_CHECKING:
    from numpy.typing import NDArray

__all__ = ["MAX_SKIPPED", "numbered_robots", "robots_page", "write_robots"]

# Robots a page may enumerate and drop to reach its first robot, where no closed form finds it
# (rule constraints, overlapping components): past this a page is refused, not computed slowly.
MAX_SKIPPED = 10**6

Cells: TypeAlias = "NDArray[np.object_]"  # text, one string per block row


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


def robots_page(
    solution: Solution, offset: int, limit: int, *, configuration: int | None = None
) -> list[tuple[int, tuple[Value, ...]]]:
    """Robots ``offset`` .. ``offset + limit - 1`` of :func:`numbered_robots` (of those
    ``configuration`` serves, when given), each with its configuration number: one page of a
    list that may hold millions.

    Where the rules have no constraints and every value is in at most one component, a page is
    found in closed form (the valid robots of a type, or of a configuration, are a product of
    value lists, and robot ``k`` of a product is read off ``k``'s digits), so page 1,000,000
    costs what page 1 costs. Otherwise robots are enumerated up to the page: a
    :class:`TooLargeError` past :data:`MAX_SKIPPED` of them. ``solution`` must be listed
    (solved without ``count_only``); ``ValueError`` otherwise, or for a negative offset or
    limit.
    """
    if not solution.listed:
        raise ValueError("robots_page needs a listed solution (solved without count_only)")
    if offset < 0 or limit < 0:
        raise ValueError(f"offset and limit must not be negative (got {offset}, {limit})")
    rules = solution.rules
    chosen = None
    if configuration is not None:
        chosen = next((c for c in solution.configurations if c.number == configuration), None)
        if chosen is None:
            return []
    if not rules.constraints and _one_component_each(solution):
        if chosen is not None:
            return [(chosen.number, robot) for robot in _product_page(chosen.served, offset, limit)]
        return _closed_form_page(solution, offset, limit)
    if offset > MAX_SKIPPED:
        raise TooLargeError.at(
            solution.team.file,
            f"a page starting at robot {offset + 1} is refused: the rule set's constraints (or "
            f"overlapping components) mean enumerating the {offset} robots before it (more "
            f"than {MAX_SKIPPED}); teleop-ui robots lists them all",
        )
    found = numbered_robots(solution)
    if chosen is not None:
        found = (entry for entry in found if entry[0] == chosen.number)
    return list(itertools.islice(found, offset, offset + limit))


def _product_page(
    domains: Sequence[Sequence[Value]], offset: int, limit: int
) -> list[tuple[Value, ...]]:
    """Members ``offset`` .. of the product of ``domains`` (the last varying fastest)."""
    total = 1
    for domain in domains:
        total *= len(domain)
    page = []
    for position in range(offset, min(offset + limit, total)):
        digits = []
        rest = position
        for domain in reversed(domains):
            rest, digit = divmod(rest, len(domain))
            digits.append(domain[digit])
        page.append(tuple(reversed(digits)))
    return page


def _closed_form_page(
    solution: Solution, offset: int, limit: int
) -> list[tuple[int, tuple[Value, ...]]]:
    """:func:`robots_page` of a team whose robots are the products of its selections."""
    rules = solution.rules
    numbers = {c.key: c.number for c in solution.configurations}
    default = solution.default_configuration
    page: list[tuple[int, tuple[Value, ...]]] = []
    for selection in solution.team.selections:
        size = selection.size
        if offset >= size:
            offset -= size
            continue
        for robot in _product_page(selection.domains, offset, limit - len(page)):
            key = []
            for characteristic, value in zip(rules.characteristics, robot, strict=True):
                members = characteristic.membership[characteristic.positions[value]]
                key.append(members[0] if members else -1)
            page.append((numbers.get(tuple(key), default), robot))
        offset = 0
        if len(page) >= limit:
            break
    return page


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
    if engine == "fast" and _one_component_each(solution) and (fmt == "csv" or _plain(names)):
        return _write_blocks(solution, stream, fmt)
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
            json_printable(
                json.dumps(
                    {"configuration": number, **dict(zip(names, robot, strict=True))},
                    ensure_ascii=False,
                )
            )
            + "\n"
        )
        written += 1
    return written


def _one_component_each(solution: Solution) -> bool:
    """Every value in at most one component: a robot's configuration is its components."""
    return all(len(m) <= 1 for c in solution.rules.characteristics for m in c.membership)


def _plain(names: Sequence[str]) -> bool:
    """Names that make a JSON object of their own: distinct, none called ``configuration``."""
    return len(set(names)) == len(names) and "configuration" not in names


def _csv_field(value: Value) -> str:
    """``value`` exactly as :func:`csv.writer` writes it inside a row (quoted when needed)."""
    buffer = io.StringIO()
    # A second, empty cell: a row of one empty cell is written as ``""``, inside a row as nothing.
    csv.writer(buffer, lineterminator="\n").writerow([csv_cell(value), ""])
    return buffer.getvalue()[: -len(",\n")]


def _json_field(value: Value) -> str:
    return json_printable(json.dumps(value, ensure_ascii=False))


def _write_blocks(solution: Solution, stream: TextIO, fmt: str) -> int:
    """:func:`write_robots` from the fast engine's blocks, byte for byte the same text.

    Each value's cell text is made once and each block row's trailing cells once per kinematic
    type; a block of robots is then two numpy takes, one elementwise ``+`` and one write, and a
    configuration number is looked up once per distinct code of the block, not per robot.
    """
    rules = solution.rules
    names = rules.names
    if fmt == "csv":
        csv.writer(stream, lineterminator="\n").writerow(csv_row(["configuration", *names]))
        field: Callable[[Value], str] = _csv_field
        labels = ["" for _ in names]
        opening, separator, closing = "", ",", "\n"
    else:
        field = _json_field
        labels = [json_printable(json.dumps(name, ensure_ascii=False)) + ": " for name in names]
        opening, separator, closing = '{"configuration": ', ", ", "}\n"
    cells = [
        [label + field(value) for value in c.values]
        for label, c in zip(labels, rules.characteristics, strict=True)
    ]
    numbers = {c.key: c.number for c in solution.configurations}
    default = solution.default_configuration
    written = 0
    made: dict[tuple[tuple[str, ...], ...], Cells] = {}  # kinematic types often share a block
    for selection in solution.team.selections:
        layout, blocks = robot_blocks(rules, selection)
        selected = [
            [cells[i][rules.characteristics[i].positions[v]] for v in domain]
            for i, domain in enumerate(layout.domains)
        ]
        codes = _numbers_by_code(layout, numbers)
        width = len(layout.domains)
        # Leading block characteristics with one selected value (the kinematic type, often)
        # are the same text on every row: they join the text made once per code.
        first = layout.start
        while first < width - 1 and len(selected[first]) == 1:
            first += 1
        fixed = "".join(selected[i][0] + separator for i in range(layout.start, first))
        tails = _block_text(selected[first:], separator, closing, made)
        for block in blocks:
            head = "".join(selected[i][digit] + separator for i, digit in enumerate(block.head))
            starts = np.array(
                [
                    f"{opening}{codes.get(code, default)}{separator}{head}{fixed}"
                    for code in block.codes.tolist()
                ],
                dtype=object,
            )
            # Interleaved and joined once: no string per robot is made, only pointers copied.
            pieces = np.empty((len(block.rows), 2), dtype=object)
            np.take(starts, block.which, out=pieces[:, 0])
            np.take(tails, block.rows, out=pieces[:, 1])
            stream.write("".join(pieces.reshape(-1).tolist()))
            written += len(block.rows)
    return written


def _block_text(
    selected: list[list[str]],
    separator: str,
    closing: str,
    made: dict[tuple[tuple[str, ...], ...], Cells],
) -> Cells:
    """The text of every row of a block over the ``selected`` cells, in product order (the last
    varying fastest), built one characteristic at a time: an outer sum of strings per step."""
    key = tuple(tuple(cells) for cells in selected)
    if key not in made:
        text = np.array([cell + closing for cell in selected[-1]], dtype=object)
        for cells in reversed(selected[:-1]):
            leading = np.array([cell + separator for cell in cells], dtype=object)
            text = np.add.outer(leading, text).reshape(-1)
        made.clear()  # one block at a time in memory
        made[key] = text
    return made[key]


def _numbers_by_code(layout: BlockLayout, numbers: dict[tuple[int, ...], int]) -> dict[int, int]:
    """Configuration numbers by the codes of :func:`robot_blocks` for one kinematic type: the
    configurations whose components this type's selection reaches."""
    where = [{component: k for k, component in enumerate(c)} for c in layout.components]
    found = {}
    for key, number in numbers.items():
        code = 0
        for position, component, stride in zip(where, key, layout.strides, strict=True):
            k = position.get(component)
            if k is None:
                break
            code += k * stride
        else:
            found[code] = number
    return found
