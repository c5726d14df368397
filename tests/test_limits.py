"""The table of limits: one place in the code, the same table in docs/security.md, and each
limit refusing just past its value with a located message, before the work starts."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path

import pytest

from solver import Team, limits, load_rules, load_team, solve
from solver.errors import Location, TooLargeError
from solver.limits import LIMITS, limit, readable, table
from tests.conftest import ROOT, run_cli

WriteFile = Callable[[str, str], Path]


def test_docs_security_shows_the_table_of_limits_the_code_holds() -> None:
    page = (ROOT / "docs" / "security.md").read_text(encoding="utf-8")
    shown = re.search(r"<!-- limits -->\n(.*?)<!-- /limits -->", page, re.DOTALL)
    assert shown is not None, "docs/security.md has no <!-- limits --> table"
    # Refresh with: python -c 'from solver.limits import table; print(table(), end="")'
    assert shown.group(1) == table()


def test_every_limit_has_a_distinct_name_and_a_positive_value() -> None:
    names = [entry.name for entry in LIMITS]
    assert len(names) == len(set(names))
    assert all(entry.value > 0 for entry in LIMITS)


def test_a_size_just_past_a_limit_is_refused_with_the_limit_named() -> None:
    entry = limit("characteristics")
    entry.check(entry.value, "rules.yaml", line=3, column=1)  # at the limit: accepted
    with pytest.raises(TooLargeError) as caught:
        entry.check(entry.value + 1, "rules.yaml", line=3, column=1, path="characteristics")
    assert str(caught.value) == (
        "rules.yaml:3:1: characteristics: 1001 characteristics; at most 1000 are accepted "
        "(limit 'characteristics', docs/security.md)"
    )
    assert caught.value.faults[0].location == Location("rules.yaml", 3, 1, "characteristics")
    assert caught.value.faults[0].code == "too-large"


def test_an_unknown_limit_is_a_key_error() -> None:
    with pytest.raises(KeyError):
        limit("no such limit")


# ---- each limit, just past it and at it, with small files the tests write ---------------------


def _lower(monkeypatch: pytest.MonkeyPatch, name: str, value: int) -> None:
    """Lower a limit for one test, where reaching the real one would take the test seconds."""
    # pylint: disable=protected-access
    monkeypatch.setitem(limits._BY_NAME, name, replace(limit(name), value=value))


def _rules(*characteristics: str, constraints: Sequence[str] = ()) -> str:
    text = "name: r\ncharacteristics:\n  kinematic_type:\n    values: [A, B]\n"
    text += "".join(characteristics)
    if constraints:
        text += "constraints:\n" + "".join(constraints)
    return text


def _named(name: str, count: int) -> str:
    return f"  {name}:\n    values: [{', '.join(f'v{i}' for i in range(count))}]\n"


def _range(name: str, count: int) -> str:
    return f"  {name}:\n    range: {{min: 1, max: {count}}}\n"


def _refused(error: pytest.ExceptionInfo[TooLargeError], name: str, size: int) -> str:
    message = str(error.value)
    assert f"{size} " in message
    assert f"at most {limit(name).value} are accepted (limit '{name}'" in message
    return message


def test_a_rule_set_of_1000_characteristics_is_read_and_1001_are_refused(
    write_file: WriteFile,
) -> None:
    others = limit("characteristics").value - 1  # and the kinematic type
    rules = load_rules(write_file("r.yaml", _rules(*(_named(f"c{i}", 2) for i in range(others)))))
    assert len(rules.characteristics) == limit("characteristics").value
    path = write_file("s.yaml", _rules(*(_named(f"c{i}", 2) for i in range(others + 1))))
    with pytest.raises(TooLargeError) as caught:
        load_rules(path)
    assert _refused(caught, "characteristics", others + 2).startswith(f"{path}:2:1: ")


def test_a_characteristic_of_100000_values_is_read_and_more_are_refused(
    write_file: WriteFile,
) -> None:
    most = limit("values").value
    assert (
        len(load_rules(write_file("r.yaml", _rules(_named("x", most)))).characteristic("x").values)
        == most
    )
    for text in (_named("x", most + 1), _range("x", most + 1)):
        with pytest.raises(TooLargeError) as caught:
            load_rules(write_file("s.yaml", _rules(text)))
        assert _refused(caught, "values", most + 1).startswith(f"{caught.value.faults[0].location}")
        assert caught.value.faults[0].location.line == 6


def test_ranges_of_all_the_values_a_rule_set_takes_are_read_and_one_more_is_refused(
    write_file: WriteFile,
) -> None:
    most, each = limit("all-values").value, limit("values").value
    # Full ranges, then the rest; the key's two values count too.
    full, rest = divmod(most - 2, each)
    assert rest > 0
    ranges = [_range(f"c{i}", each) for i in range(full)] + [_range("last", rest)]
    rules = load_rules(write_file("r.yaml", _rules(*ranges)))
    assert sum(len(c.values) for c in rules.characteristics) == most
    ranges[-1] = _range("last", rest + 1)
    with pytest.raises(TooLargeError) as caught:
        load_rules(write_file("s.yaml", _rules(*ranges)))
    assert "characteristics.last" in _refused(caught, "all-values", most + 1)


def test_components_up_to_the_limit_are_read_and_one_more_is_refused(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    _lower(monkeypatch, "components", 30)

    def grouped(count: int) -> str:
        listed = "".join(f"      - {{name: g{i}, values: v{i}}}\n" for i in range(count))
        return _named("x", count) + "    components:\n" + listed

    rules = load_rules(write_file("r.yaml", _rules(grouped(20), grouped(10).replace("x:", "y:"))))
    assert len(rules.characteristic("x").components) == 20
    with pytest.raises(TooLargeError) as caught:
        load_rules(write_file("s.yaml", _rules(grouped(31))))
    assert "characteristics.x.components" in _refused(caught, "components", 31)
    # The characteristics together: 20 and 11.
    with pytest.raises(TooLargeError) as caught:
        load_rules(write_file("t.yaml", _rules(grouped(20), grouped(11).replace("x:", "y:"))))
    assert "characteristics.y" in _refused(caught, "components", 31)


def test_2000_constraints_are_read_and_2001_are_refused(write_file: WriteFile) -> None:
    most = limit("constraints").value
    forbid = [f"  - forbid: {{kinematic_type: A, x: v{i}}}\n" for i in range(most + 1)]
    rules = load_rules(write_file("r.yaml", _rules(_named("x", most), constraints=forbid[:-1])))
    assert len(rules.constraints) == most
    with pytest.raises(TooLargeError) as caught:
        load_rules(write_file("s.yaml", _rules(_named("x", most), constraints=forbid)))
    assert "constraints" in _refused(caught, "constraints", most + 1)


def test_conditions_naming_a_million_values_are_read_and_more_are_refused(
    write_file: WriteFile,
) -> None:
    most, each = limit("condition-values").value, limit("values").value
    forbid = [f"  - forbid: {{x: {{min: 1, max: {each}}}}}\n"] * (most // each)
    rules = load_rules(write_file("r.yaml", _rules(_range("x", each), constraints=forbid)))
    assert len(rules.constraints) == most // each
    more = [*forbid, "  - forbid: {kinematic_type: A}\n"]
    with pytest.raises(TooLargeError) as caught:
        load_rules(write_file("s.yaml", _rules(_range("x", each), constraints=more)))
    assert f"constraints[{most // each}]" in _refused(caught, "condition-values", most + 1)


def test_a_team_of_20000_kinematic_types_is_read_and_20001_are_refused(
    write_file: WriteFile,
) -> None:
    most = limit("kinematic-types").value
    types = [f"K{i}" for i in range(most + 1)]
    write_file(
        "r.yaml",
        f"name: r\ncharacteristics:\n  kinematic_type:\n    values: [{', '.join(types)}]\n",
    )

    def team(count: int) -> str:
        return "rules: r.yaml\nteam:\n" + "".join(f"  {t}: {{}}\n" for t in types[:count])

    assert len(load_team(write_file("t.yaml", team(most))).selections) == most
    with pytest.raises(TooLargeError) as caught:
        load_team(write_file("u.yaml", team(most + 1)))
    assert _refused(caught, "kinematic-types", most + 1).startswith(
        f"{caught.value.faults[0].location}"
    )


def test_a_check_past_the_conflicts_of_its_sat_search_is_refused_at_the_constraints(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Every (a, b) forbidden: the solver needs two conflicts to see that no robot is left.
    every = [f"  - forbid: {{a: {a}, b: {b}}}\n" for a in ("a1", "a2") for b in ("b1", "b2")]
    text = _rules("  a:\n    values: [a1, a2]\n", "  b:\n    values: [b1, b2]\n", constraints=every)
    path = write_file("r.yaml", text)
    found = run_cli("check", path)
    assert found.returncode == 1, found.stderr
    assert "no valid robot at all" in found.stdout
    _lower(monkeypatch, "conflicts", 1)
    refused = run_cli("check", path)
    assert refused.returncode == 2
    assert refused.stdout == ""
    assert refused.stderr.startswith(f"{path}:10:5: constraints: the constraints are too intricate")
    assert "2 conflicts or more of the SAT search; at most 1 are accepted (limit 'conflicts'" in (
        refused.stderr
    )


# ---- solving ---------------------------------------------------------------------------------


def _huge_range_team(write_file: WriteFile, types: int, counts: int, motions: int = 2) -> Team:
    names = [f"T{i}" for i in range(types)]
    write_file(
        "rules.yaml",
        f"name: r\ncharacteristics:\n  kinematic_type:\n    values: [{', '.join(names)}]\n"
        f"{_named('m', motions)}{_range('sensor_count', counts)}",
    )
    team = "rules: rules.yaml\nteam:\n" + "".join(f"  {n}: {{}}\n" for n in names)
    return load_team(write_file("team.yaml", team))


def test_the_csp_engine_refuses_a_huge_count_range_before_enumerating(
    write_file: WriteFile,
) -> None:
    most = limit("csp-robots").value
    team = _huge_range_team(write_file, 1, most // 4 + 1, 4)  # 4 robots per count
    with pytest.raises(TooLargeError) as caught:
        solve(team, engine="csp")
    message = _refused(caught, "csp-robots", most + 4)
    assert message.startswith(f"{team.file}:3:3: team.T0: T0: ")
    assert "use --engine auto with --count-only" in message
    # The structure still counts it, without enumerating a robot.
    assert solve(team, count_only=True).totals.valid_robots == most + 4


def test_the_csp_engine_enumerates_up_to_its_limit(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    _lower(monkeypatch, "csp-robots", 20)
    assert solve(_huge_range_team(write_file, 1, 10), engine="csp").totals.valid_robots == 20
    with pytest.raises(TooLargeError, match="22 robots to enumerate"):
        solve(_huge_range_team(write_file, 1, 11), engine="csp")


def test_robots_with_the_csp_engine_obey_its_limit_per_kinematic_type(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    _lower(monkeypatch, "csp-robots", 20)
    two = _huge_range_team(write_file, 2, 6)  # 12 robots of each type, 24 in all
    listed = run_cli("robots", two.file, "--engine", "csp")
    assert listed.returncode == 0, listed.stderr
    assert len(listed.stdout.splitlines()) == 1 + 24  # a header, then a robot a line
    one = _huge_range_team(write_file, 1, 11)  # 22 robots of one type
    refused = run_cli("robots", one.file, "--engine", "csp")
    assert refused.returncode == 2
    assert refused.stderr.startswith(
        f"{one.file}:3:3: team.T0: T0: 22 robots to enumerate with python-constraint; at most "
        "20 are accepted (limit 'csp-robots', docs/security.md); list them with --engine fast"
    )


def test_the_fast_engine_refuses_more_value_classes_than_its_limit_before_enumerating(
    write_file: WriteFile, monkeypatch: pytest.MonkeyPatch
) -> None:
    most, counts = limit("fast-rows").value, limit("values").value
    # Each count is its own component, so its own class: motion controls x counts rows.
    team = _huge_range_team(write_file, 1, counts, most // counts + 1)
    with pytest.raises(TooLargeError) as caught:
        solve(team, engine="fast", count_only=True)
    _refused(caught, "fast-rows", most + counts)
    _lower(monkeypatch, "fast-rows", 30)
    team = _huge_range_team(write_file, 1, 10, 3)
    assert solve(team, engine="fast", count_only=True).totals.valid_robots == 30
    with pytest.raises(TooLargeError, match="33 value-class combinations"):
        solve(_huge_range_team(write_file, 1, 11, 3), engine="fast", count_only=True)


def test_listing_more_configurations_than_the_limit_is_refused_before_any_is_built(
    write_file: WriteFile,
) -> None:
    most = limit("configurations").value
    team = _huge_range_team(
        write_file, most // (2 * limit("values").value) + 1, limit("values").value
    )
    with pytest.raises(TooLargeError) as caught:
        solve(team)
    message = _refused(caught, "configurations", 600_000)
    assert message.startswith(f"{team.file}:2:1: team: ")  # at the team's `team:` key
    assert "use --count-only" in message
    assert solve(team, count_only=True).totals.ui_configurations == 600_000


# ---- charts, topics, files -------------------------------------------------------------------


def test_a_chart_of_100_kinematic_types_is_drawn_and_101_are_refused_before_solving(
    write_file: WriteFile,
) -> None:
    from solver.reporting.plot import check_chart_size

    most = limit("chart-types").value
    check_chart_size(_huge_range_team(write_file, most, 3))
    team = _huge_range_team(write_file, most + 1, 3)
    with pytest.raises(TooLargeError) as caught:
        check_chart_size(team)
    assert _refused(caught, "chart-types", most + 1).startswith(f"{team.file}:{most + 3}:3: ")
    result = run_cli("report", team.file, "-o", Path(team.file).with_suffix(".html"))
    assert result.returncode == 2, result.stderr
    assert "limit 'chart-types'" in result.stderr
    assert not Path(team.file).with_suffix(".html").exists()


def test_a_chart_of_more_characteristics_than_its_limit_is_refused(write_file: WriteFile) -> None:
    from solver.reporting.plot import check_chart_size

    most = limit("chart-characteristics").value
    write_file("rules.yaml", _rules(*(_named(f"c{i}", 2) for i in range(most))))
    team = load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  A: {}\n"))
    with pytest.raises(TooLargeError) as caught:
        check_chart_size(team)
    # At the first characteristic past the limit: c99, two lines each after kinematic_type's.
    assert _refused(caught, "chart-characteristics", most + 1).startswith(
        f"{team.rules.file}:{5 + 2 * (most - 1)}:3: characteristics.c{most - 1}: "
    )


def test_a_chart_of_a_type_with_more_robots_than_a_float_holds_is_refused(
    write_file: WriteFile,
) -> None:
    from solver.reporting.plot import check_chart_size

    def team(counts: int) -> Team:
        # Counts of 2,500 values each: 2500^88 is about 1.05 x 10^299 robots, 2500^89 10^302.
        write_file("rules.yaml", _rules(*(_range(f"c{i}", 2_500) for i in range(counts))))
        return load_team(write_file("team.yaml", "rules: rules.yaml\nteam:\n  B: {}\n  A: {}\n"))

    check_chart_size(team(88))
    with pytest.raises(TooLargeError) as caught:
        check_chart_size(team(89))
    message = str(caught.value)
    assert message.startswith(f"{caught.value.faults[0].location.file}:4:3: team.A: ")
    assert "robots; at most 10^300 are accepted (limit 'chart-robots'" in message


def test_topic_lines_past_the_limit_are_refused_at_the_line_past_it(write_file: WriteFile) -> None:
    from solver.identify.readers.topics import parse_topic_list, read_topic_list

    most = limit("topics").value
    text = "".join(f"/t{i} std_msgs/String\n" for i in range(most))
    assert len(parse_topic_list(text, "t.txt")) == most
    with pytest.raises(TooLargeError) as caught:
        parse_topic_list(text + "# a comment is no topic\n/last std_msgs/String\n", "t.txt")
    assert _refused(caught, "topics", most + 1).startswith(f"t.txt:{most + 2}: ")
    # The lists of one command count together.
    small = write_file("small.txt", "/a std_msgs/String\n/b std_msgs/String\n")
    with pytest.raises(TooLargeError) as caught:
        read_topic_list(small, before=most - 1)
    assert "with the lists before this one" in _refused(caught, "topics", most + 1)


def test_more_topic_lists_or_bags_than_their_limits_are_refused_before_any_is_read(
    tmp_path: Path,
) -> None:
    from solver.identify import identification

    urdf = tmp_path / "none.urdf"  # never read: the counts are refused first
    lists = [tmp_path / f"missing{i}" for i in range(limit("topic-lists").value + 1)]
    with pytest.raises(TooLargeError) as caught:
        identification.identify(urdf, topic_lists=lists)
    _refused(caught, "topic-lists", len(lists))
    bags = [tmp_path / f"missing{i}" for i in range(limit("bags").value + 1)]
    with pytest.raises(TooLargeError) as caught:
        identification.identify(urdf, bags=bags)
    _refused(caught, "bags", len(bags))


def test_more_files_than_check_files_are_refused_before_any_is_read() -> None:
    from solver.check import check_files

    files = [f"missing{i}.yaml" for i in range(limit("check-files").value + 1)]
    with pytest.raises(TooLargeError) as caught:
        check_files(files)
    _refused(caught, "check-files", len(files))


def test_a_batch_of_more_team_files_than_its_limit_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from solver.reporting.batch import find_teams

    _lower(monkeypatch, "batch-teams", 3)
    for i in range(4):
        (tmp_path / f"t{i}.yaml").write_text("team: {}\n")
    assert len(find_teams([str(tmp_path / "t[0-2].yaml")])) == 3
    with pytest.raises(TooLargeError, match=r"4 team files or more; at most 3 are accepted"):
        find_teams([str(tmp_path)])


@pytest.mark.parametrize(
    ("size", "shown"),
    [
        (1_000_000, "1000000"),
        (10**300, "10^300"),
        (137 * 10**2997 + 5, "about 1.37 x 10^2999"),
    ],
)
def test_a_size_past_16_digits_is_shown_short(size: int, shown: str) -> None:
    assert readable(size) == shown
    assert f"{shown} robots to enumerate; at most 100000000" in limit("robots").message(size)


def test_batch_starts_at_most_64_workers(tmp_path: Path) -> None:
    result = run_cli("batch", tmp_path, "-o", tmp_path / "out", "--jobs", "65")
    assert result.returncode == 2
    assert "65 worker processes; at most 64 are accepted (limit 'batch-jobs'" in result.stderr
    assert not (tmp_path / "out").exists()
