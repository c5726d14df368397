"""What the batch tests share (tests/reporting/test_batch.py for the library,
tests/cli/test_batch.py for the command): a folder of team files, some of them bad."""

from __future__ import annotations

import shutil
from pathlib import Path

from tests.conftest import RULES, TEAMS

BAD = "team:\n  UAV:\n    motion_control: [Flite]\n"
BROKEN = "name: [oops\n"
OWN_RULES = """\
name: Two of our own
characteristics:
  kind:
    values: [Rover, Boat]
  camera:
    values: [Mono, Stereo, Thermal]
    components:
      - {name: video, values: [Mono, Stereo]}
      - {name: heat map, values: [Thermal]}
"""
OWN_TEAM = "name: Harbour\nrules: own.yaml\nteam:\n  Boat: {camera: [Mono, Thermal]}\n"


def write_teams(tmp_path: Path) -> Path:
    """A folder of team files: three article cases, one of our own rules, two bad ones."""
    folder = tmp_path / "teams"
    (folder / "ours").mkdir(parents=True)
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")
    for name in ("case1", "case2", "case3"):
        shutil.copy(TEAMS / f"{name}.yaml", folder / f"{name}.yaml")  # rules: ../paper.yaml
    (folder / "ours" / "own.yaml").write_text(OWN_RULES, encoding="utf-8")
    (folder / "ours" / "harbour.yaml").write_text(OWN_TEAM, encoding="utf-8")
    (folder / "ours" / "bad.yaml").write_text(BAD, encoding="utf-8")
    (folder / "ours" / "broken.yaml").write_text(BROKEN, encoding="utf-8")
    return folder
