"""A secret file given where a command reads rules, a team, a profile or a topic list
(/etc/passwd, /etc/shadow, a vault) is named, never quoted: not in the messages, not in the
output, not in a batch's summaries, whatever shape the file parses as.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli.hostile import (
    YAML_READERS,
    reader_line,
    run_main,
    summaries,
    team_file,
    urdf,
)
from tests.conftest import run_cli

SECRET = "root:x:0:0:the-secret-line:/root:/bin/bash"


@pytest.mark.parametrize(
    "foreign",
    [
        f"{SECRET}\ndaemon:x:1:1::/:/bin/false\n",  # /etc/passwd: one plain scalar
        f"{SECRET}: 1\nother: [{SECRET}]\n",  # a mapping of the wrong shape
        f"- {SECRET}\n- x\n",  # a list
    ],
)
@pytest.mark.parametrize(
    "command",
    ["solve", "count", "robots", "check", "identify", "batch", "report", "assign", "reproduce"],
)
def test_a_rules_file_that_is_no_rule_set_is_named_never_quoted(
    tmp_path: Path, foreign: str, command: str
) -> None:
    (tmp_path / "passwd").write_text(foreign)
    team = team_file(tmp_path, rules="passwd")
    out = tmp_path / "out"
    args: dict[str, list[str | Path]] = {
        "check": ["check", team],
        "identify": ["identify", urdf(tmp_path), "--team", team],
        "batch": ["batch", team, "-o", out],
        "report": ["report", team, "-o", tmp_path / "r.html"],
        "assign": ["assign", "--team", team, "kinematic_type=UAV"],
    }
    result = run_cli(*args.get(command, [command, team]))
    assert result.returncode in (1, 2), result.stderr
    assert "Traceback" not in result.stderr
    assert "passwd" in result.stderr + result.stdout  # the file is named...
    for text in (result.stdout, result.stderr, *summaries(out)):
        assert "the-secret-line" not in text  # ...and nothing of it is quoted


@pytest.mark.parametrize("how", ["directly", "through a link"])
@pytest.mark.parametrize("reader", ["identify --topics", "layouts --topics"])
def test_a_secret_given_as_a_topic_list_is_named_never_quoted(
    tmp_path: Path, reader: str, how: str, capsys: pytest.CaptureFixture[str]
) -> None:
    secret = tmp_path / "shadow"
    secret.write_text(f"{SECRET}\nTOKEN=the-secret-token\nthe-secret-word\n")
    given = secret
    if how == "through a link":
        given = tmp_path / "robot.topics"
        given.symlink_to(secret)
    assert run_main(*reader_line(reader, tmp_path, given)) == 2
    shown = capsys.readouterr()
    assert shown.err.startswith(f"{given}:1: not a topic list: ")
    assert "the-secret" not in shown.out + shown.err


# /etc/shadow's lines end in ':' and so parse as a mapping: each line a key.
SHADOW = "root:$6$the-secret-hash:19000:0:99999:7:::\ndaemon:*:the-secret-day:0:99999:7:::\n"


@pytest.mark.parametrize("reader", list(YAML_READERS))
def test_a_secret_that_parses_as_a_mapping_is_named_never_quoted_by_every_yaml_reader(
    tmp_path: Path, reader: str, capsys: pytest.CaptureFixture[str]
) -> None:
    secret = tmp_path / "shadow"
    secret.write_text(SHADOW)
    assert run_main(*reader_line(reader, tmp_path, secret)) in (1, 2)  # 1: batch's failed row
    shown = capsys.readouterr()
    lines = (shown.out + shown.err).splitlines()
    refusal = next(line.strip() for line in lines if line.strip().startswith(f"{secret}:1:1: "))
    assert "not a" in refusal  # the file is named...
    for text in (shown.out, shown.err, *summaries(tmp_path / "batch")):
        assert "the-secret" not in text  # ...and none of its keys is quoted


# Files of other shapes where a profile or any YAML file is read (issue 36.13): /etc/passwd
# given as an identification profile was quoted ("must be a mapping, got a string ('root:x:...')").
FOREIGN_SHAPES = {
    "/etc/passwd": f"{SECRET}\ndaemon:x:1:1::/:/bin/false\n",
    "a scalar": "the-secret-password\n",
    "a list": "- the-secret-one\n- the-secret-two\n",
    "a syntax error on line 1": "the-secret: [the-secret, {\n",
    "a tag": "!the-secret-tag the-secret-value\n",
    "a key twice": "the-secret-key:\nthe-secret-key:\n",
    "an Ansible vault": "the-secret-name: !vault |\n  $ANSIBLE_VAULT;1.1;AES256\n  3132\n",
}
# Profiles read before anything goes on the network: each command ends at its profile.
PROFILE_READERS = {
    **YAML_READERS,
    "watch --profile": [
        *["watch", "--master", "http://127.0.0.1:9", "--team", "{team}", "--once"],
        *["--profile", "{file}"],
    ],
    "studio --profile": ["studio", "--profile", "{file}", "--host", "192.0.2.1", "--port", "0"],
}


@pytest.mark.parametrize("shape", list(FOREIGN_SHAPES))
@pytest.mark.parametrize("reader", list(PROFILE_READERS))
def test_a_file_of_no_kind_is_named_never_quoted_by_every_yaml_reader(
    tmp_path: Path, reader: str, shape: str, capsys: pytest.CaptureFixture[str]
) -> None:
    secret = tmp_path / "foreign"
    secret.write_text(FOREIGN_SHAPES[shape])
    assert run_main(*reader_line(reader, tmp_path, secret, PROFILE_READERS)) in (1, 2)
    shown = capsys.readouterr()
    assert f"{secret}:" in shown.out + shown.err  # the file is named...
    for text in (shown.out, shown.err, *summaries(tmp_path / "batch")):
        assert "the-secret" not in text  # ...and nothing of it is quoted
