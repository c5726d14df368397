"""Every value a command takes, tried as an attacker would: digits no parser should take,
names longer than the system allows, outputs that are pipes or links, and random hostile values
in every argument of every command; each is answered on lines of its own, with a located usage
error (exit 2) or a result, never a traceback, and no output replaces what is not a file.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown
from tests.cli.hostile import assert_located_refusal, run_main, team_file, with_paper_rules
from tests.conftest import RULES, TEAMS, run_cli
from tests.hostile import FUZZ, NAME_CHARS

# ---- values of assign -----------------------------------------------------------------------


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


@FUZZ
@given(
    name=st.sampled_from(["kinematic_type", "sensor_count", "sensor_type", "x"]),
    value=st.builds(
        lambda head, tail: f"{head}\nFORGED{tail}",
        st.text(NAME_CHARS, max_size=100) | st.just("9" * 5000),
        st.text(NAME_CHARS, max_size=100),
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


# ---- every argument of every command ---------------------------------------------------------

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
