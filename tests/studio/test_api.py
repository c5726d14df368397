"""The studio's JSON API speaks the command line's JSON: the same answers, byte for byte after
parsing, for the same team; pages of configurations and robots are slices of the whole lists.
"""

from __future__ import annotations

import json
from pathlib import Path
from urllib.parse import urlencode

import pytest

from solver import load_team
from solver.studio.selection import query_of
from tests.conftest import run_cli
from tests.studio.conftest import Server, StartStudio


def case_query(name: str) -> str:
    return urlencode(query_of(load_team(name), "paper"))


def cli_json(*args: str) -> object:
    result = run_cli(*args, "--format", "json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def without_files(data: object) -> object:
    """The answer without the team's name and file, which the studio's selection does not
    have (it is no file)."""
    assert isinstance(data, dict)
    return {k: v for k, v in data.items() if k not in ("team", "team_file")}


@pytest.fixture
def server(studio: Server) -> Server:
    return studio


@pytest.mark.parametrize("name", ["case1", "case2", "case3", "figure8"])
def test_solve_answers_what_the_cli_prints_for_the_same_team(server: Server, name: str) -> None:
    query = case_query(name)
    counted = server.json(f"/api/solve?{query}")
    assert without_files(counted) == without_files(cli_json("solve", name, "--count-only"))
    listed = server.json(f"/api/solve?{query}&list=1")
    assert without_files(listed) == without_files(cli_json("solve", name, "--list"))


def test_count_and_assign_answer_what_the_cli_prints(server: Server) -> None:
    query = case_query("case3")
    assert without_files(server.json(f"/api/count?{query}")) == without_files(
        cli_json("count", "case3")
    )
    robot = {
        "robot.kinematic_type": "UAV",
        "robot.motion_control": "Flight",
        "robot.sensor_type": "2D Camera",
        "robot.sensor_count": "3",
    }
    answer = server.json(f"/api/assign?{query}&{urlencode(robot)}")
    expected = cli_json("assign", "--team", "case3", *(f"{k[6:]}={v}" for k, v in robot.items()))
    assert without_files(answer) == without_files(expected)


def test_a_page_of_configurations_is_a_slice_of_solve_list(server: Server) -> None:
    query = case_query("case3")
    every = cli_json("solve", "case3", "--list")
    assert isinstance(every, dict)
    page = server.json(f"/api/configurations?{query}&offset=40&limit=25")
    assert (page["total"], page["offset"], page["limit"]) == (102, 40, 25)
    assert page["configurations"] == every["configurations"][40:65]
    one = server.json(f"/api/configurations/48?{query}")
    assert one == every["configurations"][47]


def test_a_page_of_robots_is_a_slice_of_teleop_ui_robots(server: Server) -> None:
    query = case_query("case2")
    lines = run_cli("robots", "case2", "--format", "jsonl").stdout.splitlines()
    every = [json.loads(line) for line in lines]
    page = server.json(f"/api/robots?{query}&offset=100&limit=50")
    assert page["total"] == 110
    assert page["robots"] == every[100:110]
    served = server.json(f"/api/robots?{query}&configuration=7&limit=500")
    assert served["robots"] == [robot for robot in every if robot["configuration"] == 7]


def test_check_answers_with_findings_located_at_the_selection(
    start_studio: StartStudio,
) -> None:
    server = start_studio("rules/extended.yaml")
    # The extended rules forbid walking for a UAV: the team selects it anyway.
    query = urlencode(
        [
            ("rules", "start"),
            ("type", "UAV"),
            ("UAV.motion_control", "Flight"),
            ("UAV.motion_control", "Walking"),
        ]
    )
    data = server.json(f"/api/check?{query}")
    forbidden = [f for f in data["findings"] if f["check"] == "team-forbidden-value"]
    assert [(f["file"], f["path"]) for f in forbidden] == [
        ("<selection>", "team.UAV.motion_control[1]")
    ]
    assert "Walking is for legged robots" in forbidden[0]["message"]
    assert data["files"] == ["rules/extended.yaml", "<selection>"]


def test_an_unknown_value_is_a_located_error_and_the_next_request_is_served(
    server: Server,
) -> None:
    status, body = server.get("/api/solve?type=UAV&UAV.motion_control=Waypont")
    assert status == 422
    (fault,) = json.loads(body)["faults"]
    assert fault["file"] == "<selection>"
    assert fault["path"] == "team.UAV.motion_control[0]"
    assert fault["message"] == "unknown robot motion control 'Waypont' (did you mean 'Waypoint'?)"
    assert server.json(f"/api/solve?{case_query('case1')}")["totals"]["valid_robots"] == 30


def test_exports_are_what_the_commands_write(server: Server) -> None:
    query = case_query("case1")
    status, uvl = server.get(f"/api/model.uvl?{query}")
    assert status == 200
    assert uvl.decode() == run_cli("export", "case1", "--format", "uvl").stdout
    status, report = server.get(f"/api/report.html?{query}")
    assert status == 200
    assert b"<svg" in report or b"data:image/svg+xml" in report
    status, archive = server.get(f"/api/layouts.zip?{query}")
    assert status == 200
    import io
    import zipfile

    names = zipfile.ZipFile(io.BytesIO(archive)).namelist()
    # Six configurations and the default, once for Foxglove/Lichtblick and once for RViz2.
    assert len([n for n in names if n.startswith("foxglove/")]) == 7
    assert len([n for n in names if n.startswith("rviz/")]) == 7


def test_the_api_is_described_by_openapi(server: Server) -> None:
    schema = server.json("/openapi.json")
    assert schema["openapi"].startswith("3.")
    assert {"/api/solve", "/api/assign", "/api/robots", "/api/identify"} <= set(schema["paths"])
    assert schema["paths"]["/api/solve"]["get"]["summary"] == "Solve the selected team"


def test_a_rule_set_whose_check_takes_minutes_gets_its_page_with_what_was_found_in_time(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    from tests.check.helpers import intricate_rules

    rules = tmp_path / "intricate.yaml"
    rules.write_text(intricate_rules(), encoding="utf-8")
    server = start_studio(str(rules))
    status, body = server.get("/")
    assert status == 200
    assert "check stopped after 2 s" in body.decode()
    findings = server.json("/api/findings")["findings"]
    assert [f["check"] for f in findings if f["level"] == "warning"][-1:] == ["unfinished"]
    # The next page is answered at once: the check's answer is kept.
    assert server.get("/")[0] == 200
