"""Hostile and malformed input, tried as an attacker would: every case ends with a located
error (exit 2) or a result, never a traceback, a runaway read, a leak or an injection.

The property tests at the end feed random mutations of valid rule files, team files and URDFs
to every reader and command (bounded numbers of examples, so the suite stays quick).
"""

from __future__ import annotations

import csv
import errno
import io
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from solver.check.render import sarif_text
from solver.cli import main
from solver.cli._terminal import escape_controls
from solver.errors import SolverError
from solver.files.output import csv_cell
from solver.identify import identify_urdf
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown
from tests.conftest import ROOT, RULES, TEAMS, run_cli

TEAM = "name: {name}\nrules: {rules}\nteam:\n  UAV: {{motion_control: [Waypoint]}}\n"


def team_file(
    folder: Path, *, name: str = "t", rules: str = "rules.yaml", file: str = "team.yaml"
) -> Path:
    path = folder / file
    path.write_text(TEAM.format(name=name, rules=rules), encoding="utf-8")
    return path


def with_paper_rules(folder: Path) -> None:
    (folder / "rules.yaml").write_text((RULES / "paper.yaml").read_text(), encoding="utf-8")


def assert_located_refusal(result: subprocess.CompletedProcess[str], file: str) -> None:
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.startswith(file), result.stderr


# ---- unbounded reads ------------------------------------------------------------------------


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_batch_refuses_a_rules_file_that_never_ends_without_reading_it(
    tmp_path: Path, device: str
) -> None:
    team_file(tmp_path, rules=device)
    result = run_cli("batch", tmp_path / "team.yaml", "-o", tmp_path / "out")
    assert result.returncode == 1, result.stderr  # the team failed; the batch itself ran
    assert "Traceback" not in result.stderr
    assert "internal error" not in result.stderr
    assert f"cannot use rules file '{device}'" in result.stderr
    assert "is a character device, not a YAML file" in result.stderr


# ---- tracebacks that were ----------------------------------------------------------------


def test_a_nul_byte_in_the_rules_path_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, rules='"a\\0b"')
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:2:8: rules:")
    # Text holds no NUL (issue 36.14b): the YAML reader refuses it before any path is made.
    assert "contains a NUL character (\\0); not text" in result.stderr


def test_a_number_of_5000_digits_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name="9" * 5000)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "number too large" in result.stderr


def test_a_hexadecimal_number_too_large_to_print_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name="0x" + "f" * 5000)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")


def test_a_surrogate_escape_in_a_name_is_a_located_error(tmp_path: Path) -> None:
    team_file(tmp_path, name='"robot \\udcff"')
    result = run_cli("report", tmp_path / "team.yaml", "-o", tmp_path / "r.html")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:")
    assert not (tmp_path / "r.html").exists()


@pytest.mark.parametrize(
    "content",
    [b"\x89MCAP0\r\n", b"\x89MCAP0\r\n" + b"\x00" * 64, b"#ROSBAG V2.0\n", os.urandom(4096)],
)
@pytest.mark.parametrize("suffix", [".mcap", ".bag", ".db3"])
def test_a_corrupt_bag_is_a_located_error(tmp_path: Path, content: bytes, suffix: str) -> None:
    from solver.identify.readers.bags import read_bag_topics

    bag = tmp_path / f"run{suffix}"
    bag.write_bytes(content)
    with pytest.raises(SolverError) as raised:
        read_bag_topics(bag)
    assert str(raised.value).startswith(str(bag))


def test_a_device_given_as_a_bag_is_refused_without_reading_it() -> None:
    from solver.identify.readers.bags import read_bag_topics

    with pytest.raises(SolverError, match="not a bag file or folder"):
        read_bag_topics("/dev/zero")


def test_a_non_ascii_digit_is_no_sensor_count() -> None:
    from solver.core.rules import load_rules

    sensor_count = load_rules(RULES / "paper.yaml").characteristic("sensor_count")
    assert sensor_count.parse_value("3") == 3
    assert sensor_count.parse_value("\u0663") is None  # Arabic-Indic three
    # On the command line it is a usage mistake, located at the argument.
    result = run_cli(
        "assign",
        "--team",
        "case3",
        "kinematic_type=UAV",
        "motion_control=Waypoint",
        "sensor_count=\u0663",
    )
    assert_located_refusal(
        result, "<arguments>: sensor_count: '\u0663' has non-ASCII digits; write numbers as 0-9"
    )


def test_a_characteristic_without_a_name_is_a_located_error(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text("characteristics:\n  kind: {values: [A, B]}\n  '': {values: [x]}\n")
    (tmp_path / "t.yaml").write_text("rules: r.yaml\nteam:\n  A: {}\n")
    result = run_cli("solve", tmp_path / "t.yaml")
    assert_located_refusal(
        result,
        f"{rules}:3:3: characteristics.: a characteristic needs a "
        "name of visible characters, got ''",
    )
    assert run_cli("check", rules).returncode == 1  # check: the same fault, as a finding


@pytest.mark.parametrize("command", ["batch", "report-html", "report-md", "solve"])
def test_a_file_name_that_is_not_utf8_is_no_traceback(tmp_path: Path, command: str) -> None:
    with_paper_rules(tmp_path)
    team = Path(os.fsdecode(bytes(tmp_path) + b"/t\xff\x1b.yaml"))
    team_file(tmp_path, file=team.name)
    args: dict[str, list[str | Path]] = {
        "batch": ["batch", team, "-o", tmp_path / "out"],
        "report-html": ["report", team, "-o", tmp_path / "r\udcff.html"],
        "report-md": ["report", team, "-o", tmp_path / "r\udcff.md"],
        "solve": ["solve", team, "--format", "csv"],
    }
    result = subprocess.run(
        [sys.executable, "-m", "solver", *map(os.fsencode, args[command])],
        capture_output=True,
        cwd=ROOT,
        check=False,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    assert b"Traceback" not in result.stderr
    assert b"\x1b" not in result.stdout + result.stderr  # shown as the text "\x1b"


# ---- sizes: names, lines, whole files ------------------------------------------------------


def test_a_15_megabyte_team_name_is_refused_at_its_line(tmp_path: Path) -> None:
    team_file(tmp_path, name="x" * 15_000_000)
    result = run_cli("report", tmp_path / "team.yaml", "-o", tmp_path / "r.html")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "longer than 10000 characters" in result.stderr
    assert len(result.stderr) < 1000


def test_a_name_longer_than_200_characters_is_refused(tmp_path: Path) -> None:
    team_file(tmp_path, name="x" * 201)
    result = run_cli("solve", tmp_path / "team.yaml")
    assert_located_refusal(result, f"{tmp_path / 'team.yaml'}:1:7: name:")
    assert "team name is longer than 200 characters" in result.stderr


def test_a_15_megabyte_flow_style_line_is_refused_before_it_is_built(tmp_path: Path) -> None:
    path = tmp_path / "team.yaml"
    entries = ", ".join(f"a{i}: b" for i in range(1_500_000))
    path.write_text("name: t\nteam: {" + entries[:15_000_000] + "}\n")
    result = run_cli("solve", path)
    assert_located_refusal(result, f"{path}:2:")
    assert "more than 200000 values" in result.stderr


# ---- nesting: every YAML reader -------------------------------------------------------------

# A block nest composed by libyaml ended the process with SIGSEGV; a flow nest was quadratic.
DEEP_YAML = {"block": "- " * 50_000 + "x\n", "flow": "[" * 1_000_000 + "\n"}


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


def _command(
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
        "urdf": str(_urdf(folder / "robots")),
    }
    return [argument.format(**places) for argument in readers[reader]]


# ---- nesting: every YAML reader -------------------------------------------------------------

# A block nest composed by libyaml ended the process with SIGSEGV; a flow nest was quadratic.
DEEP_YAML = {"block": "- " * 50_000 + "x\n", "flow": "[" * 1_000_000 + "\n"}


@pytest.mark.parametrize("reader", list(YAML_READERS))
def test_a_block_nest_50000_deep_is_refused_by_every_reader(tmp_path: Path, reader: str) -> None:
    deep = tmp_path / "deep.yaml"
    deep.write_text(DEEP_YAML["block"])
    result = run_cli(*_command(reader, tmp_path, deep))  # a process: a signal is the point
    assert result.returncode in (1, 2), result.stderr  # 1: batch's failed row
    assert "Traceback" not in result.stderr
    assert f"{deep}:1:131: nested more than 64 levels deep; refused" in result.stderr


@pytest.mark.parametrize("reader", list(YAML_READERS))
def test_a_flow_nest_a_million_deep_is_refused_by_every_reader(
    tmp_path: Path, reader: str, capsys: pytest.CaptureFixture[str]
) -> None:
    deep = tmp_path / "deep.yaml"
    deep.write_text(DEEP_YAML["flow"])
    assert run_main(*_command(reader, tmp_path, deep)) in (1, 2)
    assert f"{deep}:1:66: nested more than 64 levels deep; refused" in capsys.readouterr().err


# ---- files that are not regular files: every reader -----------------------------------------


def _ends(command: list[str], stdin: int | None = None) -> subprocess.CompletedProcess[str]:
    """``command`` as a process that must end by itself (60 s: a last-resort ceiling; a
    refusal takes a fraction of a second, a hang never ends)."""
    return subprocess.run(
        [sys.executable, "-m", "solver", *command],
        stdin=subprocess.DEVNULL if stdin is None else stdin,
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=False,
        timeout=60,
    )


def refused_as_no_regular_file(reader: str, file: Path, kind: str) -> str:
    """The start of the message that refuses ``file``, of ``kind``, given to ``reader``."""
    if reader != "batch" or file == Path("/dev/stdin"):
        return f"{file}: is {kind}, not a "
    if kind == "a directory":  # batch reads the teams in a folder
        return f"{file}: folder holds no .yaml or .yml file"
    return f"{file}: not a regular file or folder"


@pytest.mark.parametrize("reader", list(FILE_READERS))
def test_a_fifo_is_refused_by_every_reader_without_waiting_for_a_writer(
    tmp_path: Path, reader: str
) -> None:
    fifo = tmp_path / "hostile"
    os.mkfifo(fifo)
    result = _ends(_command(reader, tmp_path, fifo))  # opening it for reading waited forever
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith(refused_as_no_regular_file(reader, fifo, "a pipe (FIFO)"))


@pytest.mark.parametrize("reader", ["solve", "check", "identify", "identify --topics"])
def test_standard_input_from_a_pipe_that_never_ends_is_refused(tmp_path: Path, reader: str) -> None:
    # `sleep 30 | teleop-ui solve /dev/stdin`: the writer holds the pipe open and sends nothing.
    stdin = Path("/dev/stdin")
    read_end, write_end = os.pipe()
    try:
        result = _ends(_command(reader, tmp_path, stdin), stdin=read_end)
    finally:
        os.close(read_end)
        os.close(write_end)
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith(refused_as_no_regular_file(reader, stdin, "a pipe (FIFO)"))


@pytest.mark.parametrize("kind", ["a directory", "a character device", "a socket"])
@pytest.mark.parametrize("reader", list(FILE_READERS))
def test_a_folder_a_device_or_a_socket_is_refused_by_every_reader(
    tmp_path: Path,
    reader: str,
    kind: str,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    special = {"a directory": tmp_path / "folder", "a character device": Path("/dev/zero")}
    if kind == "a directory":
        special[kind].mkdir()
    with socket.socket(socket.AF_UNIX) as server:
        if kind == "a socket":
            monkeypatch.chdir(tmp_path)  # a socket's path is short (108 bytes): a relative one
            server.bind("hostile")
            special[kind] = tmp_path / "hostile"
        assert run_main(*_command(reader, tmp_path, special[kind])) == 2
    error = capsys.readouterr().err
    assert error.startswith(refused_as_no_regular_file(reader, special[kind], kind)), error


# ---- leaks -------------------------------------------------------------------------------

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
        "identify": ["identify", _urdf(tmp_path), "--team", team],
        "batch": ["batch", team, "-o", out],
        "report": ["report", team, "-o", tmp_path / "r.html"],
        "assign": ["assign", "--team", team, "kinematic_type=UAV"],
    }
    result = run_cli(*args.get(command, [command, team]))
    assert result.returncode in (1, 2), result.stderr
    assert "Traceback" not in result.stderr
    assert "passwd" in result.stderr + result.stdout  # the file is named...
    for text in (result.stdout, result.stderr, *_summaries(out)):
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
    assert run_main(*_command(reader, tmp_path, given)) == 2
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
    assert run_main(*_command(reader, tmp_path, secret)) in (1, 2)  # 1: batch's failed row
    shown = capsys.readouterr()
    lines = (shown.out + shown.err).splitlines()
    refusal = next(line.strip() for line in lines if line.strip().startswith(f"{secret}:1:1: "))
    assert "not a" in refusal  # the file is named...
    for text in (shown.out, shown.err, *_summaries(tmp_path / "batch")):
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
    assert run_main(*_command(reader, tmp_path, secret, PROFILE_READERS)) in (1, 2)
    shown = capsys.readouterr()
    assert f"{secret}:" in shown.out + shown.err  # the file is named...
    for text in (shown.out, shown.err, *_summaries(tmp_path / "batch")):
        assert "the-secret" not in text  # ...and nothing of it is quoted


def _summaries(out: Path) -> list[str]:
    return [
        (out / name).read_text() for name in ("summary.csv", "summary.md") if (out / name).is_file()
    ]


def _urdf(folder: Path) -> Path:
    path = folder / "robot.urdf"
    path.write_text('<robot name="r"><link name="base"/></robot>\n')
    return path


# ---- injections ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("cell", "shown"),
    [
        ('=HYPERLINK("http://x")', '\'=HYPERLINK("http://x")'),
        ("+1+2", "'+1+2"),
        ("-2+3", "'-2+3"),
        ("@SUM(A1)", "'@SUM(A1)"),
        ("\tx", "'\tx"),
        ("\rx", "'\rx"),
        ("-3", "-3"),
        ("UAV", "UAV"),
        (5, 5),
    ],
)
def test_csv_cells_that_read_as_formulas_are_neutralised(cell: object, shown: object) -> None:
    assert csv_cell(cell) == shown


def test_batch_summary_and_solve_csv_neutralise_formula_names(tmp_path: Path) -> None:
    with_paper_rules(tmp_path)
    team = team_file(tmp_path, name="'=cmd|calc'")
    result = run_cli("batch", team, "-o", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out" / "summary.csv").read_text())))
    assert rows[0]["team"] == "'=cmd|calc"
    solved = run_cli("solve", team, "--format", "csv")
    assert "\n=" not in solved.stdout
    assert not solved.stdout.startswith("=")


def test_robots_csv_neutralises_formula_values(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text(
        "characteristics:\n  kind: {values: ['=1+1', B]}\n  n: {range: {min: -1, max: 0}}\n"
    )
    team = tmp_path / "t.yaml"
    team.write_text("rules: r.yaml\nteam:\n  '=1+1': {}\n")
    result = run_cli("robots", team)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[1:] == ["1,'=1+1,-1", "2,'=1+1,0"]


@pytest.mark.parametrize("sign", ["\uff1d", "\uff0b", "\uff0d", "\uff20", "\ufe66"])
def test_every_csv_the_tool_writes_neutralises_fullwidth_formula_starts(
    tmp_path: Path, sign: str
) -> None:
    # Issue 36.14d: U+FF1D HYPERLINK(...) got no leading quote; a spreadsheet reads it as "=".
    formula = f"{sign}HYPERLINK(x)"
    rules = tmp_path / "r.yaml"
    rules.write_text(
        f"name: '{formula}'\ncharacteristics:\n  kind: {{values: ['{formula}', B]}}\n"
        "  n: {range: {min: 1, max: 2}}\n",
        encoding="utf-8",
    )
    team = tmp_path / "t.yaml"
    team.write_text(f"name: '{formula}'\nrules: r.yaml\nteam:\n  '{formula}': {{}}\n", "utf-8")
    assert run_cli("batch", team, "-o", tmp_path / "out").returncode == 0
    outputs = [
        (tmp_path / "out" / "summary.csv").read_text(encoding="utf-8"),
        run_cli("solve", team, "--format", "csv").stdout,
        run_cli("solve", team, "--format", "csv", "--list").stdout,
        run_cli("robots", team).stdout,
    ]
    for output in outputs:
        cells = [cell for row in csv.reader(io.StringIO(output)) for cell in row]
        assert f"'{formula}" in cells, output
        assert formula not in cells, output


def test_sarif_messages_hold_no_link() -> None:
    assert sarif_text("[x](javascript:alert(1))") == "\\[x\\](javascript:alert(1))"
    assert sarif_text("a\\[b") == "a\\\\\\[b"
    assert sarif_text("plain (text)") == "plain (text)"


def test_sarif_output_of_check_escapes_a_bracketed_name(tmp_path: Path) -> None:
    rules = tmp_path / "r.yaml"
    rules.write_text(
        "characteristics:\n  kind: {values: [A, B]}\n  x: {values: [u, v]}\n"
        "constraints:\n  - name: '[x](javascript:alert(1))'\n"
        "    when: {kind: A}\n    require: {x: [u]}\n"
        "  - name: '[x](javascript:alert(1))'\n"
        "    when: {kind: A}\n    require: {x: [u]}\n"
    )
    result = run_cli("check", rules, "--format", "sarif")
    assert result.returncode in (0, 1), result.stderr
    texts = [r["message"]["text"] for r in json.loads(result.stdout)["runs"][0]["results"]]
    assert all("[x]" not in text for text in texts)


def test_terminal_output_shows_escape_sequences_escaped(tmp_path: Path) -> None:
    with_paper_rules(tmp_path)
    team = team_file(tmp_path, name='"\\e[2Jevil\\u202e"')
    result = run_cli("solve", team)
    assert result.returncode == 0, result.stderr
    assert "\x1b" not in result.stdout
    assert "\u202e" not in result.stdout
    assert result.stdout.startswith("\\x1b[2Jevil\\u202e")
    assert escape_controls("tab\tand\nnewline\x07") == "tab\tand\nnewline\\x07"


def test_terminal_errors_show_escape_sequences_escaped(tmp_path: Path) -> None:
    team = team_file(tmp_path, rules='"\\e]0;pwned\\a"')
    result = run_cli("solve", team)
    assert result.returncode == 2
    assert "\x1b" not in result.stderr
    assert "\x07" not in result.stderr


def test_fleet_writes_a_newline_in_a_robot_name_as_an_escape(tmp_path: Path) -> None:
    from tests.identify import builders

    folder = tmp_path / "robots"
    folder.mkdir()
    (folder / "rover\nUAV: {}\n#.urdf").write_text(builders.ugv().text())
    team = tmp_path / "team.yaml"
    result = run_cli("fleet", folder, "-o", team)
    assert result.returncode == 0, result.stderr
    from solver import load_team

    assert load_team(team).kinematic_types == ("UGV",)


# ---- orphans -------------------------------------------------------------------------------


def _descendants(pid: int) -> set[int]:
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            children.setdefault(int(fields[1]), []).append(int(entry.name))
    found, todo = set(), [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            if child not in found:
                found.add(child)
                todo.append(child)
    return found


def _alive(pid: int) -> bool:
    try:
        state = (Path("/proc") / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def test_the_worker_pool_exits_when_batch_is_killed(tmp_path: Path) -> None:
    teams = tmp_path / "teams"
    teams.mkdir()
    for number in range(400):
        (teams / f"t{number}.yaml").write_text(
            (TEAMS / "case3.yaml")
            .read_text()
            .replace("rules: ../paper.yaml", f"rules: {RULES / 'paper.yaml'}")
        )
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", "batch", teams, "-o", tmp_path / "out", "-j", "2"],
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    pool: set[int] = set()
    for _ in range(600):  # until the forkserver and both workers are up
        pool = _descendants(process.pid)
        if len(pool) >= 3 or process.poll() is not None:
            break
        time.sleep(0.05)
    assert process.poll() is None, "the batch ended before it was killed"
    assert len(pool) >= 3, "no worker pool was started"
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    for _ in range(200):  # the workers look every half second
        if not any(_alive(pid) for pid in pool):
            break
        time.sleep(0.1)
    left = [pid for pid in pool if _alive(pid)]
    for pid in left:  # do not leave them behind for the next test either
        os.kill(pid, signal.SIGKILL)
    assert left == []


# ---- random mutations of valid files ---------------------------------------------------------

HOSTILE = [
    b"\x00",
    b"\xff",
    b"\xed\xb3\xbf",
    b"9" * 4400,
    b".inf",
    b"1e999",
    b"&a",
    b"*a",
    b"!!python/object:os.system",
    b"[",
    b"{",
    b"]",
    b"}",
    b": ",
    b"\n",
    b"- ",
    b"\t",
    b'"\\udcff"',
    b"\x1b[2J",
    b"'",
    b'"',
    b"<<: *a",
    b"---",
    b"...",
    b"? ",
    b"|",
    b"<!DOCTYPE r [<!ENTITY e SYSTEM 'file:///etc/passwd'>]>",
    b"&e;",
    b"<",
    b">",
    b"</link>",
    b"<link name=''/>",
    b"0x" + b"f" * 40,
    b"\xd9\xa3",
    b"~",
    b"-1",
    b"1.5",
]


@st.composite
def mutations(draw: st.DrawFn, original: bytes) -> bytes:
    data = bytearray(original)
    for _ in range(draw(st.integers(1, 4))):
        start = draw(st.integers(0, len(data)))
        end = min(len(data), start + draw(st.integers(0, 12)))
        insert = draw(st.sampled_from(HOSTILE) | st.binary(max_size=8))
        data[start:end] = insert
    return bytes(data)


FUZZ = settings(
    max_examples=25,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)


def run_main(*args: str | Path) -> int:
    """The command line in this process: an exception other than SystemExit is a traceback."""
    try:
        return main([str(arg) for arg in args])
    except SystemExit as exit:  # argparse usage errors
        return int(exit.code or 0)


def _fuzz_commands(folder: Path, team: Path) -> list[list[str | Path]]:
    return [
        ["solve", team],
        ["count", team],
        ["robots", team, "--max-robots", "100000"],
        ["check", team],
        ["report", team, "-o", folder / "r.md"],
        ["batch", team, "-o", folder / "out"],
    ]


@FUZZ
@given(data=mutations((RULES / "paper.yaml").read_bytes()))
def test_mutated_rule_files_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    folder = tmp_path_factory.mktemp("rules")
    (folder / "rules.yaml").write_bytes(data)
    team = team_file(folder)
    for args in _fuzz_commands(folder, team):
        assert run_main(*args) in (0, 1, 2), args


@FUZZ
@given(
    data=mutations(
        (TEAMS / "case3.yaml").read_bytes().replace(b"rules: ../paper.yaml", b"rules: rules.yaml")
    )
)
def test_mutated_team_files_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    folder = tmp_path_factory.mktemp("team")
    with_paper_rules(folder)
    team = folder / "team.yaml"
    team.write_bytes(data)
    for args in _fuzz_commands(folder, team):
        assert run_main(*args) in (0, 1, 2), args


def _corpus_urdf() -> bytes:
    from tests.identify import builders

    return builders.ugv().text().encode()


@FUZZ
@given(data=mutations(_corpus_urdf()))
def test_mutated_urdfs_are_identified_or_refused(data: bytes) -> None:
    try:
        identify_urdf(data, file="fuzz.urdf")
    except SolverError as error:
        message = str(error)
    else:
        return
    assert message.startswith("fuzz.urdf")


# Bags (issue 23.3): length fields made huge or zero, bytes flipped, a region repeated (as the
# repeated chunk index was), the end cut off. Each mutated bag goes through `identify --bag`:
# its topics or a located refusal, never a traceback; the reader's own bounds end it.
BAG_HOSTILE = [
    b"\xff\xff\xff\xff",
    b"\xff" * 8,
    b"\x00\x00\x00\x00",
    b"\x7f\xff\xff\xff",
    b"\x00" * 9,
    b"op=\x07",
    b"op=\x06",
    b"zstd",
    b"lz4",
    b"\x89MCAP0\r\n",
    b"#ROSBAG V2.0\n",
]


@st.composite
def bag_mutations(draw: st.DrawFn, original: bytes) -> bytes:
    data = bytearray(original)
    for _ in range(draw(st.integers(1, 3))):
        start = draw(st.integers(0, len(data)))
        how = draw(st.sampled_from(["overwrite", "repeat", "cut"]))
        if how == "overwrite":
            insert = draw(st.sampled_from(BAG_HOSTILE) | st.binary(min_size=1, max_size=8))
            data[start : start + len(insert)] = insert
        elif how == "repeat":
            piece = data[start : start + draw(st.integers(1, 256))]
            data[start:start] = piece * draw(st.integers(1, 40))
        else:
            del data[start:]
    return bytes(data)


def _small_bag(kind: str) -> bytes:
    """A real small bag of ``kind`` (``.bag``, ``.db3``, ``.mcap``) written with rosbags."""
    import tempfile

    from rosbags.rosbag2 import StoragePlugin

    from tests.identify.readers import bagfiles

    with tempfile.TemporaryDirectory() as folder:
        if kind == ".bag":
            return bagfiles.ros1(Path(folder) / "run.bag").read_bytes()
        plugin = StoragePlugin.SQLITE3 if kind == ".db3" else StoragePlugin.MCAP
        return bagfiles.ros2(Path(folder) / "run", plugin).read_bytes()


BAG_FUZZ = settings(FUZZ, max_examples=15)


def _identify_with_bag(folder: Path, data: bytes, suffix: str) -> None:
    urdf = folder / "rover.urdf"
    urdf.write_bytes(_corpus_urdf())
    bag = folder / f"run{suffix}"
    bag.write_bytes(data)
    assert run_main("identify", urdf, "--bag", bag) in (0, 2)


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".bag")))
def test_mutated_ros1_bags_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".bag")


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".db3")))
def test_mutated_ros2_databases_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".db3")


@BAG_FUZZ
@given(data=bag_mutations(_small_bag(".mcap")))
def test_mutated_mcaps_are_read_or_refused(
    tmp_path_factory: pytest.TempPathFactory, data: bytes
) -> None:
    _identify_with_bag(tmp_path_factory.mktemp("bag"), data, ".mcap")


# ---- names drawn on charts, output streams that fail, command-line values ------------------

# Text a stranger may put in a name: TeX and mathtext syntax, markup, line breaks, controls,
# bidi and format characters, astral characters.
_NAME_CHARS = st.sampled_from(
    [*"$\\{}^_#%&~|[]()<>*`'\" \t\n\r", "\x1b", "\x85", "\u2028", "\u202e", "\u200d"]
) | st.characters(codec="utf-8")  # no lone surrogate: UTF-8 cannot hold one
_NAMES = st.text(_NAME_CHARS, min_size=1, max_size=40).filter(lambda n: n.strip() == n and n)


@FUZZ
@given(names=st.lists(_NAMES, min_size=4, max_size=4, unique=True))
def test_any_names_are_drawn_on_every_chart(
    tmp_path_factory: pytest.TempPathFactory, names: list[str]
) -> None:
    from solver import load_team, solve
    from solver.reporting.plot import bars_figure, figure_bytes, matrix_figure, radar_figure

    folder = tmp_path_factory.mktemp("chart")
    quoted = [json.dumps(name) for name in names]  # a JSON string is a YAML string
    (folder / "rules.yaml").write_text(
        f"name: {quoted[0]}\nteam_key: kind\ncharacteristics:\n"
        f"  kind:\n    label: {quoted[1]}\n    values: [{quoted[2]}, {quoted[3]}]\n"
        f"  count:\n    label: {quoted[0]}\n    range: {{min: 1, max: 3}}\n"
        f"    components:\n      - {{name: {quoted[3]}, min: 1, max: 3, cluster_size: 1}}\n",
        encoding="utf-8",
    )
    (folder / "team.yaml").write_text(
        f"name: {quoted[1]}\nrules: rules.yaml\nteam:\n  {quoted[2]}: {{}}\n  {quoted[3]}: {{}}\n",
        encoding="utf-8",
    )
    try:
        solution = solve(load_team(folder / "team.yaml"))
    except SolverError:
        return  # a name the rules refuse (a duplicate once stripped, say) is a located error
    for draw in (radar_figure, bars_figure, matrix_figure):
        assert figure_bytes(draw(solution), "svg")


class _FailingStream(io.StringIO):
    """Standard output that fails as a closed descriptor or a full disk does."""

    def __init__(self, error: int) -> None:
        super().__init__()
        self.error = error

    def write(self, text: str) -> int:  # noqa: ARG002 (nothing is written)
        raise OSError(self.error, os.strerror(self.error))

    def flush(self) -> None:
        raise OSError(self.error, os.strerror(self.error))


@FUZZ
@given(
    data=mutations(
        (TEAMS / "case3.yaml").read_bytes().replace(b"rules: ../paper.yaml", b"rules: rules.yaml")
    ),
    error=st.sampled_from([errno.EBADF, errno.ENOSPC, errno.EPIPE]),
)
def test_mutated_team_files_onto_a_failing_output_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory,
    monkeypatch: pytest.MonkeyPatch,
    data: bytes,
    error: int,
) -> None:
    folder = tmp_path_factory.mktemp("team")
    with_paper_rules(folder)
    team = folder / "team.yaml"
    team.write_bytes(data)
    for args in _fuzz_commands(folder, team):
        with monkeypatch.context() as patched:
            patched.setattr(sys, "stdout", _FailingStream(error))
            status = run_main(*args)
        # A broken pipe ends quietly (0); a closed or full output ends with status 2; a
        # command that wrote nothing to standard output ends as it would have.
        assert status in (0, 1, 2), args


@FUZZ
@given(
    name=st.sampled_from(["kinematic_type", "sensor_count", "sensor_type", "x"]),
    value=st.builds(
        lambda head, tail: f"{head}\nFORGED{tail}",
        st.text(_NAME_CHARS, max_size=100) | st.just("9" * 5000),
        st.text(_NAME_CHARS, max_size=100),
    ),
)
def test_any_command_line_value_is_answered_on_lines_of_its_own(
    capsys: pytest.CaptureFixture[str], name: str, value: str
) -> None:
    status = run_main("assign", "-t", "case3", f"{name}={value}")
    out, err = capsys.readouterr()
    assert status in (0, 2)
    assert len(out + err) < 5_000  # the value is echoed cut short
    assert not any(line.lstrip().startswith("FORGED") for line in (out + err).splitlines())
    assert not any(char in out + err for char in ("\x1b", "\x85", "\u2028", "\u202e"))


# ---- command-line values ---------------------------------------------------------------------

# Every command with a value in each place that takes one, all valid ({...} filled in by
# _command_line); the tests put a hostile value in one place at a time.
COMMAND_LINES = {
    "solve": ["solve", "{team}", "--rules", "{rules}", "--max-robots", "1000", "--plot", "p.png"],
    "assign": [
        *["assign", "--team", "{team}", "--rules", "{rules}", "kinematic_type=UAV"],
        *["motion_control=Flight", "sensor_count=3"],
    ],
    "count": ["count", "{team}", "--rules", "{rules}", "--max-robots", "1000"],
    "robots": ["robots", "{team}", "--max-robots", "1000"],
    "check": ["check", "{rules}", "{team}", "--rules", "{rules}", "--disable", "unknown-reference"],
    "identify": [
        *["identify", "{urdf}", "--topics", "{topics}", "--team", "{team}"],
        *["--profile", "{profile}", "--arg", "a:=b", "--package-path", ".", "--set"],
        "sensor_count=1",
    ],
    "fleet": ["fleet", "{robots}", "-o", "fleet.yaml", "--name", "n", "--rules", "{rules}"],
    "layouts": ["layouts", "{team}", "-o", "layouts", "--presentation", "{presentation}"],
    "layouts --robot": [
        *["layouts", "--robot", "{urdf}", "--team", "{team}", "--topics", "{topics}"],
        *["-o", "robot.json", "--profile", "{profile}", "--set", "sensor_count=1"],
    ],
    "export": ["export", "{team}", "--rules", "{rules}"],
    "report": ["report", "{team}", "-o", "r.html", "--rules", "{rules}"],
    "batch": ["batch", "{team}", "-o", "batch", "--jobs", "1"],
    "reproduce": ["reproduce", "{shipped}"],
}
# Where a command writes: (command, the argument after which the output is named).
OUTPUTS = [
    ("solve", "--plot"),
    ("fleet", "-o"),
    ("layouts", "-o"),
    ("layouts --robot", "-o"),
    ("report", "-o"),
    ("batch", "-o"),
]


def _values(command: str) -> list[int]:
    """The positions in ``command``'s line that hold a value (a file, a number, a name)."""
    line = COMMAND_LINES[command]
    return [i for i, argument in enumerate(line) if i > 0 and not argument.startswith("-")]


def _command_line(command: str, folder: Path) -> list[str]:
    """``command``'s line with every value valid, its files in ``folder`` (the current one)."""
    with_paper_rules(folder)
    (folder / "robots").mkdir(exist_ok=True)
    urdf = folder / "robots" / "rover.urdf"
    from tests.identify import builders

    urdf.write_text(builders.ugv().text())
    (folder / "robot.topics").write_text("/cmd_vel geometry_msgs/Twist\n")
    places = {
        "team": str(team_file(folder)),
        "rules": str(folder / "rules.yaml"),
        "urdf": str(urdf),
        "robots": str(folder / "robots"),
        "topics": str(folder / "robot.topics"),
        "profile": str(RULES / "identification.yaml"),
        "presentation": str(RULES / "presentation.yaml"),
        "shipped": str(TEAMS / "case1.yaml"),
    }
    return [argument.format(**places) for argument in COMMAND_LINES[command]]


@pytest.fixture
def here(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A temporary folder made the current one: what a command writes stays in it."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("command", list(COMMAND_LINES))
def test_every_command_line_of_the_table_runs(here: Path, command: str) -> None:
    # The baseline the hostile values are put into: each line works as it is.
    assert run_main(*_command_line(command, here)) in (0, 1)  # 1: findings of check


def test_a_5000_digit_number_in_assign_is_a_located_usage_error(
    capsys: pytest.CaptureFixture[str],
) -> None:
    args = ["assign", "--team", "case3", "kinematic_type=UAV", "sensor_count=" + "9" * 5000]
    assert run_main(*args) == 2
    assert capsys.readouterr().err == (
        "<arguments>: sensor_count: a value of 5,000 characters; no characteristic value is "
        "longer than 200\n"
    )


def test_a_5000_digit_number_given_to_assign_in_python_is_a_located_error() -> None:
    from solver import assign, load_team, solve

    solution = solve(load_team(TEAMS / "case3.yaml"))
    with pytest.raises(SolverError, match="sensor_count: a whole number too large"):
        assign(solution, kinematic_type="UAV", sensor_count=10**5000)
    unknown = assign(solution, kinematic_type="UAV", sensor_count="9" * 5000)
    assert unknown.is_default  # as text: no value of the rules, answered with the default


@pytest.mark.parametrize("option", ["--max-robots", "--jobs"])
def test_a_5000_digit_count_is_a_usage_error(
    option: str, capsys: pytest.CaptureFixture[str]
) -> None:
    command = "batch" if option == "--jobs" else "solve"
    args = [command, "case1", option, "9" * 5000] + (["-o", "x"] if command == "batch" else [])
    assert run_main(*args) == 2
    error = capsys.readouterr().err
    assert f"argument {option}" in error  # --jobs/-j: ...
    assert "expected a whole number of at most 18 digits 0-9, got '999" in error
    assert "(cut from 5,000 characters)" in error


def test_layouts_into_an_existing_file_is_a_located_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    existing = tmp_path / "notes.txt"
    existing.write_text("mine\n")
    assert run_main("layouts", "case1", "-o", existing) == 2
    assert capsys.readouterr().err == (
        f"{existing}: is not a folder: give a folder to write into\n"
    )
    assert existing.read_text() == "mine\n"


LONG_NAMES = {"a part of 300 bytes": "a" * 300, "5,000 bytes in all": "/".join(["b" * 200] * 25)}


@pytest.mark.parametrize("length", list(LONG_NAMES))
@pytest.mark.parametrize(
    ("command", "position"),
    [(command, position) for command in COMMAND_LINES for position in _values(command)],
)
def test_a_name_longer_than_the_system_allows_is_a_located_error(
    here: Path, command: str, position: int, length: str, capsys: pytest.CaptureFixture[str]
) -> None:
    line = _command_line(command, here)
    line[position] = LONG_NAMES[length]
    code = run_main(*line)
    error = capsys.readouterr().err
    if line[position - 1] == "--package-path":
        assert code == 0  # a folder to look for packages in: one that cannot be holds none
        return
    assert code == 2, error
    # Located: at the name (escaped, cut), at the arguments or the generated team (--name), at
    # the option (--set NAME=VALUE).
    named = shown(line[position], limit=SHOWN_FILE_NAME_CHARS)
    usage = f"teleop-ui {COMMAND_LINES[command][0]}: error: "
    places = (named, usage, "<arguments>: ", "<fleet team>:2:7: name:", f"{line[position - 1]}: ")
    assert error.splitlines()[-1].startswith(places), error


@pytest.mark.parametrize("kind", ["a fifo", "a link", "a link to a device"])
@pytest.mark.parametrize(("command", "option"), OUTPUTS)
def test_an_output_that_is_no_regular_file_is_refused_and_left_alone(
    here: Path, command: str, option: str, kind: str, capsys: pytest.CaptureFixture[str]
) -> None:
    # `-o /dev/full` as root replaced the device with a file, `-o /dev/stdout` its link.
    tmp_path = here
    line = _command_line(command, tmp_path)
    suffix = Path(line[line.index(option) + 1]).suffix  # the format is told by it
    output = tmp_path / f"out{suffix}"
    if kind == "a fifo":
        os.mkfifo(output)
    else:
        output.symlink_to("/dev/null" if kind == "a link to a device" else tmp_path / "elsewhere")
    line[line.index(option) + 1] = str(output)
    assert run_main(*line) == 2
    assert capsys.readouterr().err.splitlines()[-1].startswith(f"{output}: is ")
    assert output.is_fifo() if kind == "a fifo" else output.is_symlink()
    assert not (tmp_path / "elsewhere").exists()


# What a hostile or careless command line holds; {...} are made in the test's folder: a file,
# a folder, a name under a file, a FIFO, a link to a device, a link to nothing.
HOSTILE_VALUES = [
    "a" * 300,
    "/".join(["b" * 200] * 25),
    "9" * 5000,
    "sensor_count=" + "9" * 5000,
    "kinematic_type=" + "x" * 5000,
    "-1",
    "0",
    "",
    "-",
    ".",
    "..",
    "nan",
    "1e999",
    "\u0663",
    "x\udcff",
    "a\nb",
    "\x1b[2J",
    "=",
    "a:=",
    ":=b",
    "/proc/self/environ",
    "{file}",
    "{folder}",
    "{file}/x",
    "{fifo}",
    "{device link}",
    "{dangling link}",
]


def _hostile_places(folder: Path) -> dict[str, str]:
    places = {name: str(folder / name.replace(" ", "-")) for name in ("file", "folder", "fifo")}
    (folder / "file").write_text("mine\n")
    (folder / "folder").mkdir()
    os.mkfifo(folder / "fifo")
    for name, target in (("device link", "/dev/null"), ("dangling link", "nowhere")):
        (folder / name.replace(" ", "-")).symlink_to(target)
        places[name] = str(folder / name.replace(" ", "-"))
    return places


@settings(FUZZ, max_examples=60)
@given(command=st.sampled_from(list(COMMAND_LINES)), data=st.data())
def test_hostile_command_line_values_never_reach_a_traceback(
    tmp_path_factory: pytest.TempPathFactory, command: str, data: st.DataObject
) -> None:
    import contextlib

    folder = tmp_path_factory.mktemp("argv")
    line = _command_line(command, folder)
    places = _hostile_places(folder)
    for _ in range(data.draw(st.integers(1, 2))):  # one or two values at once
        position = data.draw(st.sampled_from(_values(command)))
        value = data.draw(st.sampled_from(HOSTILE_VALUES) | st.text(max_size=12))
        line[position] = places.get(value.strip("{}"), value) if value.startswith("{") else value
    with contextlib.chdir(folder):  # whatever a value makes a command write stays here
        assert run_main(*line) in (0, 1, 2), line
    assert (folder / "file").read_text() == "mine\n" or places["file"] in line  # an output
    assert (folder / "fifo").is_fifo()
    assert (folder / "device-link").is_symlink()


@pytest.mark.parametrize("option", ["--host", "--fleet"])
def test_the_studio_refuses_a_name_longer_than_the_system_allows(
    option: str, capsys: pytest.CaptureFixture[str]
) -> None:
    # Refused before anything listens: a traceback (UnicodeError, OSError) before.
    assert run_main("studio", "--port", "0", option, "a" * 400) == 2
    error = capsys.readouterr().err
    assert error.startswith("--host: cannot listen on 'aaa" if option == "--host" else "aaa")
    assert "(cut from 400 characters)" in error
