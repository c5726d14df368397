"""Rendering solutions (solver.reporting.render): how counts were made, and listings streamed in
chunks that are the whole JSON or CSV."""

from __future__ import annotations

import json
from pathlib import Path

from solver import load_team, solve
from solver.files.output import json_printable
from solver.reporting.render import method_text, solution_chunks
from solver.solving.solution import solution_data
from tests.conftest import TEAMS


def test_the_method_says_which_engine_counted_in_words() -> None:
    team = load_team(TEAMS / "case3.yaml")
    assert method_text(solve(team)) == "counted from the rules' structure, no robots enumerated"
    assert (
        method_text(solve(team, engine="csp"))
        == "robots enumerated with python-constraint (csp engine)"
    )


def test_a_streamed_json_listing_is_the_json_of_the_solution_in_chunks(tmp_path: Path) -> None:
    # 1,200 configurations: three chunks of configurations between the head and the tail.
    (tmp_path / "rules.yaml").write_text(
        "name: wide\ncharacteristics:\n  kinematic_type:\n    values: [UGV, UAV]\n"
        "  sensor_count:\n    range: {min: 1, max: 600}\n",
        encoding="utf-8",
    )
    (tmp_path / "team.yaml").write_text(
        "name: wide\nrules: rules.yaml\nteam:\n  UGV: {}\n  UAV: {}\n", encoding="utf-8"
    )
    # Overlapping components (the values a configuration serves are a cover's share) and a
    # kinematic type whose name holds an unprintable character.
    (tmp_path / "overlapping.yaml").write_text(
        "name: overlapping\ncharacteristics:\n  kinematic_type:\n"
        '    values: [UGV, "Odd\\u202eType"]\n'
        "  sensor_type:\n    values: [a, b, c, d, e, f]\n    components:\n"
        "      - {name: one, values: [a, b, c]}\n      - {name: two, values: [c, d, e]}\n"
        "      - {name: three, values: [e, f, a]}\n"
        "  sensor_count:\n    range: {min: 1, max: 9}\n    components:\n"
        "      - {name: few, min: 1, max: 4}\n"
        "      - {name: many, min: 3, max: 9, cluster_size: 2}\n",
        encoding="utf-8",
    )
    (tmp_path / "odd.yaml").write_text(
        "name: odd\nrules: overlapping.yaml\nteam:\n  UGV: {}\n"
        '  "Odd\\u202eType": {sensor_count: 7}\n',
        encoding="utf-8",
    )
    # Counts with gaps (several runs in one component), names a JSON string must escape.
    (tmp_path / "gaps.yaml").write_text(
        "name: gaps\ncharacteristics:\n  kinematic_type:\n    values: [UGV]\n"
        '  sensor_type:\n    values: [\'q"uo\\\\te\', "caf\u00e9\\u2028x"]\n'
        "  sensor_count:\n    range: {min: 1, max: 9}\n    components:\n"
        "      - {name: 'all \"of\" them', min: 1, max: 9, cluster_size: 4}\n"
        "constraints:\n  - forbid: {sensor_count: 5}\n  - forbid: {sensor_count: 7}\n",
        encoding="utf-8",
    )
    (tmp_path / "gappy.yaml").write_text(
        "name: gappy\nrules: gaps.yaml\nteam:\n  UGV: {}\n", encoding="utf-8"
    )
    teams = [load_team(tmp_path / name) for name in ("odd.yaml", "team.yaml", "gappy.yaml")]
    for team in (*teams, load_team(TEAMS / "case3.yaml")):
        solution = solve(team)
        for listed in (True, False):
            chunks = list(solution_chunks(solution, "json", configurations=listed))
            data = solution_data(solution, configurations=listed)
            expected = json_printable(json.dumps(data, indent=2, ensure_ascii=False)) + "\n"
            assert "".join(chunks) == expected
    assert len(chunks) == 1
    assert (
        len(
            list(
                solution_chunks(
                    solve(load_team(tmp_path / "team.yaml")), "json", configurations=True
                )
            )
        )
        == 5
    )


def test_a_streamed_csv_listing_is_the_whole_csv_in_chunks() -> None:
    import csv
    import io

    solution = solve(load_team(TEAMS / "case3.yaml"))
    rows = list(
        csv.reader(io.StringIO("".join(solution_chunks(solution, "csv", configurations=True))))
    )
    assert rows[0] == ["number", *solution.rules.names, "valid_robots"]
    assert len(rows) == 1 + solution.totals.ui_configurations
    assert [int(row[0]) for row in rows[1:]] == [c.number for c in solution.configurations]
