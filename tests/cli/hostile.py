"""What the command line's hostile tests share: a valid team beside a hostile file, every way a
file reaches a reader, and the command line run in this process.

:data:`YAML_READERS` lists every way a YAML file reaches a reader, :data:`FILE_READERS` every
other file a command reads; :func:`reader_line` fills one in with the hostile file in its place,
beside a valid team (``team.yaml`` on the article's rules) and a folder of one robot.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from solver.cli import main
from tests.conftest import RULES

TEAM = "name: {name}\nrules: {rules}\nteam:\n  UAV: {{motion_control: [Waypoint]}}\n"


def team_file(
    folder: Path, *, name: str = "t", rules: str = "rules.yaml", file: str = "team.yaml"
) -> Path:
    path = folder / file
    path.write_text(TEAM.format(name=name, rules=rules), encoding="utf-8")
    return path


def with_paper_rules(folder: Path) -> None:
    (folder / "rules.yaml").write_text((RULES / "paper.yaml").read_text(), encoding="utf-8")


def urdf(folder: Path) -> Path:
    path = folder / "robot.urdf"
    path.write_text('<robot name="r"><link name="base"/></robot>\n')
    return path


def summaries(out: Path) -> list[str]:
    """The summaries a batch wrote into ``out``, if it wrote any."""
    return [
        (out / name).read_text() for name in ("summary.csv", "summary.md") if (out / name).is_file()
    ]


def assert_located_refusal(result: subprocess.CompletedProcess[str], file: str) -> None:
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.startswith(file), result.stderr


def run_main(*args: str | Path) -> int:
    """The command line in this process: an exception other than SystemExit is a traceback."""
    try:
        return main([str(arg) for arg in args])
    except SystemExit as exit:  # argparse usage errors
        return int(exit.code or 0)


# Every way a YAML file reaches a reader: {file} is the hostile file, beside a valid team
# ({team}, rules.yaml) and a folder of one robot ({robots}, {urdf}).
YAML_READERS = {
    "solve": ["solve", "{file}"],
    "solve --rules": ["solve", "{team}", "--rules", "{file}"],
    "count": ["count", "{file}"],
    "robots": ["robots", "{file}"],
    "check": ["check", "{folder}/rules.yaml", "{file}"],
    "check --rules": ["check", "{team}", "--rules", "{file}"],
    "assign --team": ["assign", "--team", "{file}", "kinematic_type=UAV"],
    "identify --team": ["identify", "{urdf}", "--team", "{file}"],
    "identify --profile": ["identify", "{urdf}", "--profile", "{file}"],
    "fleet --profile": ["fleet", "{robots}", "--profile", "{file}"],
    "layouts --presentation": [
        *["layouts", "{team}", "-o", "{folder}/out", "--presentation", "{file}"]
    ],
    "layouts --robot --profile": [
        *["layouts", "--robot", "{urdf}", "--team", "{team}", "-o", "{folder}/l.json"],
        *["--profile", "{file}"],
    ],
    "report": ["report", "{file}", "-o", "{folder}/r.html"],
    "batch": ["batch", "{file}", "-o", "{folder}/batch"],
    "export": ["export", "{file}"],
    "reproduce": ["reproduce", "{file}"],
}
# ... and every other file a command reads.
FILE_READERS = {
    **YAML_READERS,
    "identify": ["identify", "{file}"],
    "identify --srdf": ["identify", "{urdf}", "--srdf", "{file}"],
    "identify --topics": ["identify", "{urdf}", "--topics", "{file}"],
    "layouts --robot": ["layouts", "--robot", "{file}", "--team", "{team}", "-o", "{folder}/l"],
    "layouts --topics": [
        *["layouts", "--robot", "{urdf}", "--team", "{team}"],
        *["--topics", "{file}", "-o", "{folder}/l.json"],
    ],
}


def reader_line(
    reader: str, folder: Path, file: Path, readers: dict[str, list[str]] = FILE_READERS
) -> list[str]:
    """The command line of ``reader`` with ``file`` in the hostile place, in ``folder``."""
    with_paper_rules(folder)
    (folder / "robots").mkdir()
    places = {
        "file": str(file),
        "team": str(team_file(folder)),
        "folder": str(folder),
        "robots": str(folder / "robots"),
        "urdf": str(urdf(folder / "robots")),
    }
    return [argument.format(**places) for argument in readers[reader]]
