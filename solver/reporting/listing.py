"""Streaming every valid robot of a solved team with its UI configuration number.

The article's toolbox keeps "a list containing all valid robot combinations"; an operator
station looks a robot up in it. This writes that list as CSV or JSON lines while enumerating,
so memory stays constant however many robots there are.

Not here: choosing configurations (:mod:`solver.solving.solution`) or enumerating
(:mod:`solver.engines`).
"""

from __future__ import annotations

import csv
import io
import itertools
import json
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import TYPE_CHECKING, TextIO, TypeAlias

import numpy as np

from solver import engines
from solver.core.constraints import Value
from solver.core.ruleset import RuleSet
from solver.core.team import TypeSelection
from solver.engines import ENUMERATING, MAX_ROBOTS
from solver.engines.fast import BlockLayout, robot_blocks
from solver.engines.numbering import Numbers
from solver.errors import Fault, Location, TooLargeError
from solver.files.output import csv_cell, csv_row, json_printable
from solver.limits import limit
from solver.solving.solution import Solution

if TYPE_CHECKING:
    from numpy.typing import NDArray

__all__ = ["MAX_SKIPPED", "numbered_robots", "robots_page", "write_robots"]

# Robots a page may enumerate and drop to reach its first robot, where no closed form finds it
# (rule constraints, overlapping components): past this a page is refused, not computed slowly.
MAX_SKIPPED = 10**6

Cells: TypeAlias = "NDArray[np.object_]"  # text, one string per block row
Codes: TypeAlias = "NDArray[np.int64]"
# Rows written at once from a block whose robots have more configurations than this.
_SLICE = 1 << 13


def numbered_robots(
    solution: Solution, engine: str = ENUMERATING[0]
) -> Iterator[tuple[int, tuple[Value, ...]]]:
    """(configuration number, robot) for every valid robot, kinematic types in rule order.

    ``solution`` may be counted only (``count_only``): the numbers come from the structure, a
    type at a time, so the first robot comes at once. ``engine`` names the engine that
    enumerates (:func:`solver.engines.lookup`: an :class:`~solver.errors.InputError` for an
    unknown name).
    """
    enumerator = engines.lookup(engine)
    default = solution.default_configuration
    for selection, numbers in _numbers(solution):
        for robot in enumerator.robots(solution.rules, selection):
            number = numbers.number(robot)
            yield (default if number is None else number), robot


def _numbers(solution: Solution) -> Iterator[tuple[TypeSelection, Numbers]]:
    """Each kinematic type's selection with its configuration numbers, made when it is reached."""
    first = 1
    for selection, summary in zip(solution.team.selections, solution.by_type, strict=True):
        yield selection, Numbers(solution.rules, selection, first)
        first += summary.ui_configurations


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
    escape: Callable[[str], str] | None = None,
) -> int:
    """Write every numbered robot to ``stream``; returns how many were written.

    ``solution`` may be counted only (``solve(team, count_only=True)``): configuration numbers
    come from the structure a kinematic type at a time, so the first robot is written before
    the last configuration is known, and memory does not grow with the configurations.
    :class:`TooLargeError`, before writing anything, when there are more than ``max_robots``.

    ``escape``, when given, makes the rule set's text safe for where it goes (the command line
    gives its terminal escape, :func:`solver.cli._terminal.escape_controls`, and the stream below
    its escaping one): the output is what ``escape`` of the whole text would be, since it works
    a character at a time, but each value's text is escaped once, not every byte written.
    """
    total = solution.totals.valid_robots
    if total > max_robots:
        raise TooLargeError(
            Fault(
                solution.team.location or Location(solution.team.file),
                f"listing {total} robots is refused (more than {max_robots}, see --max-robots; "
                "limit 'robots', docs/security.md)",
                "too-large",
            )
        )
    if engine == "csp":
        _check_csp(solution)
    enumerator = engines.lookup(engine)
    names = solution.rules.names
    safe = escape or _as_it_is
    if fmt == "csv":
        # Names come from rule files: no cell may read as a spreadsheet formula.
        header = io.StringIO()
        csv.writer(header, lineterminator="\n").writerow(csv_row(["configuration", *names]))
        stream.write(safe(header.getvalue()))
    by_blocks = engine == "fast" and (fmt == "csv" or _plain(names))
    text = _Text(solution.rules, fmt, safe) if by_blocks else None
    written = 0
    for selection, numbers in _numbers(solution):
        serving = numbers.serving() if text is not None else None
        if text is not None and serving is not None:
            written += _write_blocks(solution, selection, numbers, text, stream, serving=serving)
        else:
            robots = enumerator.robots(solution.rules, selection)
            rows = stream if escape is None else _Escaping(stream, escape)
            written += _write_rows(solution, numbers, robots, fmt, rows)
    return written


def _as_it_is(text: str) -> str:
    return text


class _Escaping:
    """``stream`` written through ``escape``: rows made one at a time (any engine, any names)
    are escaped as written, quoted cells and all."""

    def __init__(self, stream: TextIO, escape: Callable[[str], str]) -> None:
        self.stream = stream
        self.escape = escape

    def write(self, text: str) -> int:
        self.stream.write(self.escape(text))
        return len(text)


def _write_rows(
    solution: Solution,
    numbers: Numbers,
    robots: Iterable[tuple[Value, ...]],
    fmt: str,
    stream: TextIO | _Escaping,
) -> int:
    """Robots one row at a time (any engine, any names)."""
    default = solution.default_configuration
    names = solution.rules.names
    written = 0

    def numbered() -> Iterator[tuple[int, tuple[Value, ...]]]:
        nonlocal written
        for robot in robots:
            written += 1
            number = numbers.number(robot)
            yield (default if number is None else number), robot

    if fmt == "csv":
        # Values are few and robots many, so each value's cell is made once.
        cells = [
            {value: csv_cell(value) for value in c.values} for c in solution.rules.characteristics
        ]
        csv.writer(stream, lineterminator="\n").writerows(
            [number, *[cell[value] for cell, value in zip(cells, robot, strict=True)]]
            for number, robot in numbered()
        )
        return written
    for number, robot in numbered():
        stream.write(
            json.dumps(
                {"configuration": number, **dict(zip(names, robot, strict=True))},
                ensure_ascii=False,
            )
            + "\n"
        )
    return written


def _one_component_each(solution: Solution) -> bool:
    """Every value in at most one component: a robot's configuration is its components."""
    return all(len(m) <= 1 for c in solution.rules.characteristics for m in c.membership)


def _check_csp(solution: Solution) -> None:
    """Refuse, at its line in the team, a kinematic type of more robots than python-constraint
    enumerates in seconds (``csp-robots``, per type as ``solve --engine csp`` counts it)."""
    which = limit("csp-robots")
    for summary in solution.by_type:
        if which.exceeded(summary.valid_robots):
            selection = solution.team.selection(summary.kinematic_type)
            at = (selection.location if selection else None) or Location(solution.team.file)
            message = which.message(summary.valid_robots)
            raise TooLargeError(
                Fault(
                    at,
                    f"{summary.kinematic_type}: {message}; list them with --engine fast",
                    "too-large",
                )
            )


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


class _Text:
    """The pieces of text the block writer joins: each value's cell made once."""

    def __init__(self, rules: RuleSet, fmt: str, safe: Callable[[str], str]) -> None:
        names = rules.names
        if fmt == "csv":
            field: Callable[[Value], str] = _csv_field
            labels = ["" for _ in names]
            self.opening, self.separator, self.closing = "", ",", "\n"
        else:
            field = _json_field
            labels = [json.dumps(name, ensure_ascii=False) + ": " for name in names]
            self.opening, self.separator, self.closing = '{"configuration": ', ", ", "}\n"
        self.rules = rules
        self.cells = [
            [safe(label + field(value)) for value in c.values]
            for label, c in zip(labels, rules.characteristics, strict=True)
        ]
        self.made: dict[tuple[tuple[str, ...], ...], Cells] = {}  # types often share a block


def _write_blocks(
    solution: Solution,
    selection: TypeSelection,
    numbers: Numbers,
    text: _Text,
    stream: TextIO,
    *,
    serving: Sequence[Callable[[Value], int]],
) -> int:
    """The robots of one kinematic type from the fast engine's blocks, byte for byte the text
    :func:`_write_rows` makes.

    Each value's cell text is made once and each block row's trailing cells once per kinematic
    type; a block of robots is then two numpy takes, one elementwise ``+`` and one write, and a
    configuration number is looked up once per distinct code of the block, not per robot.
    """
    rules = solution.rules
    separator = text.separator
    default = solution.default_configuration
    layout, blocks = robot_blocks(rules, selection, serving)
    selected = [
        [text.cells[i][rules.characteristics[i].positions[v]] for v in domain]
        for i, domain in enumerate(layout.domains)
    ]
    number_of = _numbers_by_code(layout, numbers)
    vector = numbers.by_codes(layout.components, layout.strides)
    width = len(layout.domains)
    # Leading block characteristics with one selected value (the kinematic type, often)
    # are the same text on every row: they join the text made once per code.
    first = layout.start
    while first < width - 1 and len(selected[first]) == 1:
        first += 1
    fixed = "".join(selected[i][0] + separator for i in range(layout.start, first))
    tails = _block_text(selected[first:], separator, text.closing, text.made)

    def numbered(codes: Codes) -> list[int]:
        if vector is None:
            return [number_of(code, default) for code in codes.tolist()]
        found = np.full(len(codes), default, dtype=np.int64)
        served = codes >= 0
        found[served] = vector(codes[served])
        return list(found.tolist())

    written = 0
    for block in blocks:
        head = "".join(selected[i][digit] + separator for i, digit in enumerate(block.head))
        # A block whose robots have many configurations goes in slices, each numbering only
        # the codes it uses: the first lines leave before the whole block is numbered.
        slices = [(0, len(block.rows))]
        if len(block.codes) > _SLICE:
            slices = [
                (a, min(a + _SLICE, len(block.rows))) for a in range(0, len(block.rows), _SLICE)
            ]
        for low, high in slices:
            which = block.which[low:high]
            codes = block.codes
            if (low, high) != (0, len(block.rows)):
                used, which = np.unique(which, return_inverse=True)
                codes = codes[used]
            starts = np.array(
                [f"{text.opening}{n}{separator}{head}{fixed}" for n in numbered(codes)],
                dtype=object,
            )
            # Interleaved and joined once: no string per robot is made, only pointers copied.
            pieces = np.empty((high - low, 2), dtype=object)
            np.take(starts, which.reshape(-1), out=pieces[:, 0])
            np.take(tails, block.rows[low:high], out=pieces[:, 1])
            stream.write("".join(pieces.reshape(-1).tolist()))
            written += high - low
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


def _numbers_by_code(layout: BlockLayout, numbers: Numbers) -> Callable[[int, int], int]:
    """Configuration numbers by the codes of :func:`robot_blocks` for one kinematic type
    (``code, default -> number``): the code read back as components, then numbered."""
    width = len(layout.components)
    sizes = [len(c) for c in layout.components]

    def number_of(code: int, default: int) -> int:
        if code < 0:
            return default
        key = []
        for i in range(width):
            key.append(layout.components[i][code // layout.strides[i] % sizes[i]])
        found = numbers.key_number(tuple(key))
        return default if found is None else found

    return number_of
