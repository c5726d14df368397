"""``teleop-ui reproduce``: every shipped article case, computed and compared."""

from __future__ import annotations

import json

from tests.conftest import TEAMS, run_cli


def test_reproduce_compares_every_shipped_article_case() -> None:
    result = run_cli("reproduce", "-f", "json")
    rows = {row["file"]: row for row in json.loads(result.stdout)}
    assert set(rows) == {
        f"rules/teams/{p.name}"
        for p in TEAMS.glob("*.yaml")
        if "\npublished:" in p.read_text(encoding="utf-8")
    }
    assert len(rows) == 5
    assert rows["rules/teams/case3.yaml"]["computed"] == {
        "valid_robots": 872,
        "ui_configurations": 102,
    }
    assert not rows["rules/teams/case3.yaml"]["reproduced"]
    assert all(row["reproduced"] for name, row in rows.items() if name != "rules/teams/case3.yaml")
