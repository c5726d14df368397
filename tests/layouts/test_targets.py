"""The layout targets, one table (solver.layouts.targets): each operator tool's file is made for a
configuration, validated before it is handed over, and an unknown format is a located usage
error naming the known ones."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest
import yaml

from solver import load_team, solve
from solver.errors import InputError, SolverError
from solver.layouts.plan import Robot
from solver.layouts.presentation import load_presentation
from solver.layouts.targets import TARGETS, target


def test_each_target_is_found_by_its_name_with_its_files_extension() -> None:
    assert [(t.name, t.extension) for t in TARGETS.values()] == [
        ("foxglove", "json"),
        ("rviz", "rviz"),
    ]
    assert target("rviz") is TARGETS["rviz"]


def test_an_unknown_format_is_a_usage_error_naming_the_known_ones() -> None:
    with pytest.raises(InputError) as caught:
        target("rqt\n")
    assert str(caught.value) == ("--format: unknown layout format 'rqt\\n'; known: foxglove, rviz")


def test_a_foxglove_layout_is_json_whose_topics_are_under_the_robot() -> None:
    solution = solve(load_team("case1"))
    text = TARGETS["foxglove"].render(
        solution,
        solution.configurations[0],
        load_presentation(),
        file="uav.json",
        robot=Robot("/uav1"),
    )
    layout = json.loads(text)
    assert text.endswith("\n")
    topics = [c["topic"] for c in layout["configById"].values() if "topic" in c]
    assert topics
    assert all(topic.startswith("/uav1/") for topic in topics)


def test_an_rviz_layout_reads_as_yaml_for_the_default_configuration_too() -> None:
    solution = solve(load_team("case1"))
    text = TARGETS["rviz"].render(solution, None, load_presentation(), file="default.rviz")
    assert yaml.safe_load(text)["Visualization Manager"]["Displays"]


def test_a_file_that_fails_its_tools_rules_is_refused_located_not_handed_over() -> None:
    def orphan(*_: object, **__: object) -> str:
        return json.dumps({"layout": "Image!a", "configById": {"Image!a": {}, "Plot!b": {}}})

    broken = replace(TARGETS["foxglove"], make=orphan)
    solution = solve(load_team("case1"))
    with pytest.raises(SolverError) as caught:
        broken.render(solution, None, load_presentation(), file="bad.json")
    assert str(caught.value).startswith("bad.json")
    assert "orphan config" in str(caught.value)
