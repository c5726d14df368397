"""Identifications as JSON and as text (solver.identify.render): the documented contract's keys
in order, a live robot's summary, and text a person reads."""

from __future__ import annotations

from solver.core.team import load_team
from solver.identify import combinations, identification_data, identify_urdf, load_profile
from solver.identify.render import render_identification, summary_data
from solver.solving.solution import solve
from tests.conftest import TEAMS
from tests.identify import builders


def test_the_json_contract_has_exactly_the_documented_keys() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    result = identify_urdf(builders.sensing_rover(), file="rover.urdf")
    data = identification_data(result, combinations(result, solution, load_profile()), solution)
    assert list(data) == [
        "robot",
        "file",
        "structure",
        "kinematic_type",
        "confidence",
        "evidence",
        "roles",
        "sensors",
        "motion_controls",
        "combinations",
    ]
    assert list(data["roles"][0]) == ["joint", "role", "evidence"]
    assert list(data["sensors"][0]) == ["kind", "sensor_type", "count", "source"]
    assert list(data["motion_controls"][0]) == ["motion_control", "source"]
    assert (
        data["combinations"][0]["configuration"]
        == combinations(result, solution, load_profile())[0].assignment.number
    )


def test_a_robot_that_could_not_be_identified_has_an_empty_summary() -> None:
    assert summary_data(None) == {
        "name": None,
        "structure": None,
        "kinematic_type": None,
        "confidence": None,
        "sensor_count": None,
        "sensors": [],
        "motion_controls": [],
    }


def test_a_summary_gives_a_live_robot_its_name_kind_sensors_and_controls() -> None:
    summary = summary_data(identify_urdf(builders.sensing_rover()))
    assert (summary["name"], summary["kinematic_type"], summary["sensor_count"]) == (
        "rover",
        "UGV",
        2,
    )
    assert [s["kind"] for s in summary["sensors"]] == ["lidar", "camera"]


def test_the_text_names_the_robot_its_kind_and_a_line_per_combination() -> None:
    solution = solve(load_team(TEAMS / "case2.yaml"))
    result = identify_urdf(builders.sensing_rover(), file="rover.urdf")
    found = combinations(result, solution, load_profile())
    lines = render_identification(result, found, solution).splitlines()
    assert lines[0] == "rover  (rover.urdf)"
    assert "  kinematic type: UGV" in lines
    rows = lines[lines.index("  UI configurations in team 'Case 2':") + 2 :]
    assert [row.split()[0] for row in rows] == [str(c.assignment.number) for c in found]
    assert [row.split(maxsplit=1)[1].strip() for row in rows] == [
        f"UGV, {control}, {sensor}, 2"
        for control in ("Driving", "Waypoint")
        for sensor in ("LIDAR", "2D Camera")
    ]
