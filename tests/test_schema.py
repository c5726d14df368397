"""The documented JSON Schemas agree with the shipped files and with the loader."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import jsonschema
import pytest
import yaml

from tests.conftest import ROOT, RULES, TEAMS

SCHEMAS = ROOT / "docs" / "schema"


def schema(name: str) -> dict[str, Any]:
    loaded: dict[str, Any] = json.loads((SCHEMAS / f"{name}.schema.json").read_text("utf-8"))
    jsonschema.Draft202012Validator.check_schema(loaded)
    return loaded


@pytest.mark.parametrize(
    "path", [*sorted(RULES.glob("paper*.yaml")), RULES / "marine.yaml"], ids=lambda p: p.name
)
def test_shipped_rule_sets_follow_the_rules_schema(path: Path) -> None:
    jsonschema.validate(yaml.safe_load(path.read_text("utf-8")), schema("rules"))


@pytest.mark.parametrize("path", sorted(TEAMS.glob("*.yaml")), ids=lambda p: p.name)
def test_shipped_teams_follow_the_team_schema(path: Path) -> None:
    jsonschema.validate(yaml.safe_load(path.read_text("utf-8")), schema("team"))


@pytest.mark.parametrize(
    "document",
    [
        {"team": {"UAV": {"sensor_count": 5}}, "colour": "red"},
        {"team": {}},
        {"team": {"UAV": {"sensor_type": []}}},
        {"name": "no team"},
    ],
)
def test_the_team_schema_rejects_what_the_loader_rejects(document: dict[str, Any]) -> None:
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(document, schema("team"))


@pytest.mark.parametrize(
    "document",
    [
        {"characteristics": {"kinematic_type": {"values": ["UAV"], "range": {"min": 1, "max": 2}}}},
        {"characteristics": {}},
        {
            "characteristics": {"k": {"values": ["UAV"]}},
            "constraints": [{"require": {"k": "UAV"}, "forbid": {"k": "UAV"}}],
        },
        {
            "characteristics": {"k": {"values": ["UAV"]}},
            "constraints": [{"when": {"k": "UAV"}, "forbid": {"k": "UAV"}}],
        },
    ],
)
def test_the_rules_schema_rejects_what_the_loader_rejects(document: dict[str, Any]) -> None:
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(document, schema("rules"))


def test_the_shipped_teleoperation_description_follows_its_schema() -> None:
    example = ROOT / "examples" / "teleop" / "rover.teleop.yaml"
    jsonschema.validate(yaml.safe_load(example.read_text("utf-8")), schema("teleop"))


@pytest.mark.parametrize(
    "document",
    [
        {"robot": "no format key"},
        {"teleop": 2},
        {"teleop": 1, "motion_controls": [{"control": "Driving"}]},
        {"teleop": 1, "motion_controls": [{"control": "Driving", "topic": "/a", "action": "/b"}]},
        {"teleop": 1, "motion_controls": [{"control": "Driving", "topic": "cmd_vel"}]},
        {"teleop": 1, "sensors": [{"kind": "lidar", "count": 0}]},
        {"teleop": 1, "sensors": [{"kind": "lidar", "topic": "/a", "topics": ["/b"]}]},
        {"teleop": 1, "sensors": [{"count": 1}]},
        {"teleop": 1, "colour": "red"},
    ],
)
def test_the_teleop_schema_rejects_what_the_reader_rejects(document: dict[str, Any]) -> None:
    from solver.files.yamlio import parse_document
    from solver.ros.description import DescriptionError, parse_description

    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(document, schema("teleop"))
    with pytest.raises(DescriptionError):
        parse_description(parse_document(yaml.safe_dump(document), "d.teleop.yaml"))
