"""Listing every valid robot with its configuration: the block writer, pages of the list."""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Callable
from pathlib import Path

import pytest

from solver import Solution, load_team, solve
from solver.cli._terminal import escape_controls
from solver.engines import fast
from solver.errors import TooLargeError
from solver.files.output import csv_row
from solver.reporting.listing import numbered_robots, write_robots


@pytest.mark.parametrize(
    "components",
    [
        # One component per value, with a gap (d in none): the lookup tables.
        "[{name: X, values: [a, b]}, {name: Y, values: [c]}]",
        # b in two components: the search over configurations.
        "[{name: X, values: [a, b]}, {name: Y, values: [b, c]}]",
    ],
)
def test_each_listed_robot_has_the_configuration_the_solution_gives_it(
    components: str, write_file: Callable[[str, str], Path]
) -> None:
    write_file(
        "rules.yaml",
        f"""\
characteristics:
  kinematic_type: {{values: [T, U]}}
  part:
    values: [a, b, c, d]
    components: {components}
constraints:
  - forbid: {{kinematic_type: U, part: a}}
""",
    )
    solution = solve(
        load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n  U: {}\n"))
    )
    listed = list(numbered_robots(solution))
    assert len(listed) == 7
    for number, robot in listed:
        configuration = solution.configuration_for(robot)
        assert number == (
            solution.default_configuration if configuration is None else configuration.number
        )
    assert {number for number, robot in listed if robot[1] == "d"} == {
        solution.default_configuration
    }


def written(solution: Solution, fmt: str) -> str:
    buffer = io.StringIO()
    write_robots(solution, buffer, fmt=fmt)
    return buffer.getvalue()


def written_robot_by_robot(solution: Solution, fmt: str) -> str:
    """The listing as it was written before the block writer: one row per numbered robot."""
    buffer = io.StringIO()
    names = solution.rules.names
    if fmt == "csv":
        writer = csv.writer(buffer, lineterminator="\n")
        writer.writerow(csv_row(["configuration", *names]))
        for number, robot in numbered_robots(solution):
            writer.writerow([number, *csv_row(robot)])
        return buffer.getvalue()
    for number, robot in numbered_robots(solution):
        line = {"configuration": number, **dict(zip(names, robot, strict=True))}
        buffer.write(json.dumps(line, ensure_ascii=False) + "\n")
    return buffer.getvalue()


@pytest.mark.parametrize("fmt", ["csv", "jsonl"])
def test_the_block_writer_writes_case3_exactly_as_robot_by_robot(fmt: str) -> None:
    solution = solve(load_team("rules/teams/case3.yaml"))
    text = written(solution, fmt)
    assert text == written_robot_by_robot(solution, fmt)
    assert len(text.splitlines()) == 872 + (fmt == "csv")


@pytest.mark.parametrize("fmt", ["csv", "jsonl"])
def test_the_block_writer_writes_a_constrained_team_with_awkward_values_exactly(
    fmt: str, write_file: Callable[[str, str], Path], monkeypatch: pytest.MonkeyPatch
) -> None:
    # A tiny block: many prefixes, masks shared between prefixes, unserved values (gap) in the
    # prefix and in the block, and values CSV must quote or defuse.
    monkeypatch.setattr(fast, "BLOCK", 4)
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: [T, U]}
  mode:
    values: ["=1+1", "a,b", "say \\"hi\\"", ü, gap]
    components:
      - {name: X, values: ["=1+1", "a,b"]}
      - {name: Y, values: ["say \\"hi\\"", ü]}
  count:
    values: [1, 2, 3, 4, 5]
    components: [{name: few, values: [1, 2]}, {name: many, values: [3, 4]}]
  colour: {values: [red, "-5", "+x"]}
constraints:
  - forbid: {kinematic_type: U, mode: "a,b"}
  - require: {count: [1, 2]}
    when: {colour: red}
""",
    )
    solution = solve(
        load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n  U: {}\n"))
    )
    text = written(solution, fmt)
    assert text == written_robot_by_robot(solution, fmt)
    # 5 modes x 5 counts x 3 colours, less red with 3..5 (3 x 5 modes), less U with "a,b" (12).
    assert len(text.splitlines()) == 2 * 60 - 12 + (fmt == "csv")
    assert solution.default_configuration in {number for number, _ in numbered_robots(solution)}


@pytest.mark.parametrize("name", ["case1", "case3", "search-and-rescue"])
def test_a_page_of_robots_is_that_slice_of_the_whole_list(name: str) -> None:
    from solver.reporting.listing import robots_page

    solution = solve(load_team(name))
    every = list(numbered_robots(solution))
    for offset in (0, 7, len(every) - 3, len(every) + 5):
        assert robots_page(solution, offset, 11) == every[offset : offset + 11]
    for configuration in solution.configurations[:: max(1, len(solution.configurations) // 7)]:
        served = [entry for entry in every if entry[0] == configuration.number]
        page = robots_page(solution, 2, 9, configuration=configuration.number)
        assert page == served[2:11]


def test_a_page_deep_in_ten_million_robots_is_found_without_listing_them(
    tmp_path: Path,
) -> None:
    from benchmarks.conftest import Scale
    from solver.reporting.listing import robots_page

    # 10 types x 10 motion controls x 100 sensor types (10 groups) x 1..1000 sensors
    # (5 arrangements of 200): type T9's robots start at 9,000,000, in product order, and
    # its first configuration is 9 x 500 + 1.
    scale = Scale(types=10, motions=10, sensors=100, groups=10, counts=1_000, arrangements=5)
    solution = solve(scale.team(tmp_path))
    assert robots_page(solution, 9_000_000, 2) == [
        (4501, ("T9", "M0", "S0", 1)),
        (4501, ("T9", "M0", "S0", 2)),
    ]
    # Robot 201 of T0/M0/S0 has 201 sensors: the second arrangement, configuration 2.
    assert robots_page(solution, 200, 1) == [(2, ("T0", "M0", "S0", 201))]


def test_a_page_past_the_enumeration_limit_is_refused_where_constraints_apply(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from solver.errors import TooLargeError
    from solver.reporting import listing

    monkeypatch.setattr(listing, "MAX_SKIPPED", 100)
    solution = solve(load_team("search-and-rescue"))
    with pytest.raises(TooLargeError, match="a page starting at robot 102 is refused"):
        listing.robots_page(solution, 101, 5)


class _FirstLines(io.StringIO):
    """A reader that closes after a few lines, as ``head`` does."""

    def __init__(self, lines: int) -> None:
        super().__init__()
        self.left = lines

    def write(self, text: str) -> int:
        if self.left <= 0:
            raise BrokenPipeError
        self.left -= text.count("\n")
        return super().write(text)


def test_robots_stream_from_a_team_whose_configurations_are_too_many_to_list(
    write_file: Callable[[str, str], Path],
) -> None:
    values = ", ".join(f"v{i}" for i in range(110))
    write_file(
        "rules.yaml",
        f"characteristics:\n  kinematic_type: {{values: [T]}}\n"
        f"  a: {{values: [{values}]}}\n  b: {{values: [{values}]}}\n  c: {{values: [{values}]}}\n",
    )
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  T: {}\n"))
    with pytest.raises(TooLargeError, match="1331000 UI configurations to list; at most"):
        solve(team)
    stream = _FirstLines(3)
    with pytest.raises(BrokenPipeError):
        write_robots(solve(team, count_only=True), stream)
    assert stream.getvalue().splitlines()[:4] == [
        "configuration,kinematic_type,a,b,c",
        "1,T,v0,v0,v0",
        "2,T,v0,v0,v1",
        "3,T,v0,v0,v2",
    ]


def test_robots_numbered_from_the_counts_are_numbered_as_the_solution_numbers_them() -> None:
    team = load_team("rules/teams/search-and-rescue.yaml")
    listed = solve(team)
    counted = solve(team, count_only=True)
    for number, robot in numbered_robots(counted):
        found = listed.configuration_for(robot)
        assert number == (listed.default_configuration if found is None else found.number)


@pytest.mark.parametrize(("engine", "fmt"), [("fast", "csv"), ("fast", "jsonl"), ("csp", "csv")])
def test_values_escaped_once_each_give_the_text_escaping_every_byte_gives(
    engine: str, fmt: str, write_file: Callable[[str, str], Path]
) -> None:
    write_file(
        "rules.yaml",
        """\
characteristics:
  kinematic_type: {values: ["T\\e[2J", U]}
  mode:
    values: ["\\u202eevil", "a\\rb", "tab\\there", "say \\"hi\\"", plain]
  count: {values: [1, 2]}
""",
    )
    team = load_team(
        write_file("team.yaml", 'rules: rules.yaml\nteam:\n  "T\\e[2J": {}\n  U: {}\n')
    )
    solution = solve(team)
    plain = io.StringIO()
    write_robots(solution, plain, fmt=fmt, engine=engine)
    once = io.StringIO()
    count = write_robots(solution, once, fmt=fmt, engine=engine, escape=escape_controls)
    assert count == 2 * 5 * 2
    assert once.getvalue() == escape_controls(plain.getvalue())
    if fmt == "csv":  # CSV keeps the rule set's text (JSON escapes controls itself)
        assert "\x1b[2J" in plain.getvalue()
        assert "\\x1b[2J" in once.getvalue()
        assert "\\u202e" in once.getvalue()
