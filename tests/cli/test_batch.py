"""``teleop-ui batch`` as a user runs it: many teams, parallel workers, a summary, bad files
reported, reruns skipped, a worker that dies or a Ctrl-C, links planted in its output.
"""

from __future__ import annotations

import csv
import io
import os
import shutil
import sys
from pathlib import Path

import pytest

from solver import load_team, solve
from solver.cli import main
from solver.files.output import dumps
from solver.reporting.batch import STAMPS
from solver.solving.solution import solution_data
from tests.conftest import RULES, TEAMS, run_cli
from tests.reporting.batches import BAD, write_teams


@pytest.fixture
def teams(tmp_path: Path) -> Path:
    """A folder of team files: three article cases, one of our own rules, two bad ones."""
    return write_teams(tmp_path)


def _batch(*args: str | Path, cwd: Path) -> tuple[int, str, str]:
    result = run_cli("batch", *args, cwd=cwd)
    assert "Traceback" not in result.stderr
    return result.returncode, result.stdout, result.stderr


def _summary(out: Path) -> dict[str, dict[str, str]]:
    with (out / "summary.csv").open(encoding="utf-8") as stream:
        return {row["file"]: row for row in csv.DictReader(stream)}


# ---- solving and the summary -----------------------------------------------------------------


def test_batch_writes_each_teams_json_as_solve_format_json_list_does(
    teams: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    status, _, _ = _batch("teams", "-o", "out", "--jobs", "2", cwd=tmp_path)
    assert status == 1  # the two bad files
    monkeypatch.chdir(tmp_path)
    for name in ("case1", "case2", "case3", "ours/harbour"):
        shown = f"teams/{name}.yaml"
        expected = dumps(
            solution_data(solve(load_team(Path(shown), display=shown)), configurations=True)
        )
        assert (tmp_path / "out" / "teams" / f"{name}.json").read_text(encoding="utf-8") == expected


def test_batch_reports_a_bad_team_file_with_its_error_and_solves_the_others(
    teams: Path, tmp_path: Path
) -> None:
    status, _, stderr = _batch("teams", "-o", "out", "--jobs", "2", cwd=tmp_path)
    assert status == 1
    assert (
        "teams/ours/bad.yaml:3:22: team.UAV.motion_control[0]: unknown robot motion control "
        "'Flite' (did you mean 'Flight'?)" in stderr
    )
    assert "teams/ours/broken.yaml:2:1: YAML syntax error" in stderr
    rows = _summary(tmp_path / "out")
    assert {f: r["status"] for f, r in rows.items()} == {
        "teams/case1.yaml": "ok",
        "teams/case2.yaml": "ok",
        "teams/case3.yaml": "ok",
        "teams/ours/bad.yaml": "failed",
        "teams/ours/broken.yaml": "failed",
        "teams/ours/harbour.yaml": "ok",
        "teams/ours/own.yaml": "skipped",
    }
    assert rows["teams/ours/bad.yaml"]["message"].startswith("teams/ours/bad.yaml:3:22: ")
    assert (
        rows["teams/ours/own.yaml"]["message"]
        == "not a team file: a rule set (it has 'characteristics:' and no 'team:')"
    )
    assert not (tmp_path / "out" / "teams" / "ours" / "bad.json").exists()


def test_batch_exits_0_when_every_team_is_solved(tmp_path: Path) -> None:
    status, stdout, stderr = _batch(str(TEAMS), "-o", tmp_path / "out", cwd=tmp_path)
    assert status == 0, stderr
    assert "Case 3 (hypothesis)" in stdout


def test_batch_summary_names_each_teams_rule_set(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    rows = _summary(tmp_path / "out")
    assert rows["teams/case3.yaml"]["rules"] == "Mortimer et al. 2017"
    assert rows["teams/case3.yaml"]["rules_file"].endswith("paper.yaml")
    assert rows["teams/ours/harbour.yaml"]["rules"] == "Two of our own"
    assert (
        rows["teams/ours/harbour.yaml"]["valid_robots"],
        rows["teams/ours/harbour.yaml"]["ui_configurations"],
    ) == ("2", "2")
    markdown = (tmp_path / "out" / "summary.md").read_text(encoding="utf-8")
    assert "7 team files: 4 ok, 2 failed, 1 skipped" in markdown
    assert "| teams/ours/harbour.yaml | ok | Harbour | Two of our own | 2 | 2 |" in markdown


def test_batch_summary_compares_published_figures(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    rows = _summary(tmp_path / "out")
    assert (rows["teams/case3.yaml"]["published"], rows["teams/case3.yaml"]["reproduced"]) == (
        "820 / 99",
        "no",
    )
    assert (rows["teams/case1.yaml"]["published"], rows["teams/case1.yaml"]["reproduced"]) == (
        "30 / 6",
        "yes",
    )


def test_batch_summary_is_the_same_with_one_worker_or_several(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "one", "--jobs", "1", cwd=tmp_path)
    _batch("teams", "-o", "two", "--jobs", "3", cwd=tmp_path)
    for name in ("summary.csv", "summary.md", "teams/case3.json", "teams/ours/harbour.json"):
        assert (tmp_path / "one" / name).read_bytes() == (tmp_path / "two" / name).read_bytes()


def test_batch_prints_one_plain_line_per_team_when_not_on_a_terminal(
    teams: Path, tmp_path: Path
) -> None:
    _, _, stderr = _batch("teams/case1.yaml", "teams/ours/bad.yaml", "-o", "out", cwd=tmp_path)
    lines = [line for line in stderr.splitlines() if line.startswith("[")]
    assert len(lines) == 2
    assert any(
        line.startswith("[1/2] solved     teams/case1.yaml: 30 valid robots, 6 UI configurations (")
        or line.startswith("[2/2] solved     teams/case1.yaml")
        for line in lines
    )
    assert any("FAILED     teams/ours/bad.yaml" in line for line in lines)
    assert "\x1b[" not in stderr  # no terminal control codes in logs


def test_batch_shows_a_progress_bar_on_a_terminal(
    teams: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    monkeypatch.chdir(tmp_path)
    status = main(["batch", "teams/case1.yaml", "teams/ours/bad.yaml", "-o", "out", "--jobs", "1"])
    shown = terminal.getvalue()
    assert status == 1
    assert "solving teams" in shown
    assert "2/2" in shown
    assert "FAILED" in shown
    assert "unknown robot motion control 'Flite'" in shown


def test_batch_can_write_a_report_per_team(teams: Path, tmp_path: Path) -> None:
    status, _, _ = _batch("teams/case1.yaml", "-o", "out", "--report", "markdown", cwd=tmp_path)
    assert status == 0
    assert sorted(p.name for p in (tmp_path / "out").iterdir() if p.is_file()) == [
        "summary.csv",
        "summary.md",
    ]
    assert sorted(p.name for p in (tmp_path / "out" / "teams").iterdir()) == [
        "case1-bars.png",
        "case1-radar.png",
        "case1.json",
        "case1.md",
    ]
    assert (
        _summary(tmp_path / "out")["teams/case1.yaml"]["output"]
        == "teams/case1.json teams/case1.md"
    )


# ---- up to date, --force, atomic -------------------------------------------------------------


def _stamps(out: Path) -> dict[str, int]:
    return {p.name: p.stat().st_mtime_ns for p in out.rglob("*.json")}


def test_rerun_skips_teams_whose_files_are_unchanged(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    before = _stamps(tmp_path / "out" / STAMPS)
    summary = (tmp_path / "out" / "summary.csv").read_bytes()
    status, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert status == 1
    assert stderr.count("up to date ") == 4
    assert "solved " not in stderr
    assert _stamps(tmp_path / "out" / STAMPS) == before
    assert (tmp_path / "out" / "summary.csv").read_bytes() == summary


def test_rerun_ignores_a_new_modification_time_without_new_content(
    teams: Path, tmp_path: Path
) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    os.utime(teams / "case1.yaml", (1, 1))
    _, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert "up to date teams/case1.yaml" in stderr


def test_rerun_solves_a_team_again_when_its_team_file_changes(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    text = (teams / "case1.yaml").read_text(encoding="utf-8")
    (teams / "case1.yaml").write_text(
        text.replace("sensor_count: 5", "sensor_count: 4"), encoding="utf-8"
    )
    _, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert "solved     teams/case1.yaml: 24 valid robots" in stderr
    assert stderr.count("up to date ") == 3


def test_rerun_solves_again_every_team_whose_rule_file_changes(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    with (teams / "ours" / "own.yaml").open("a", encoding="utf-8") as stream:
        stream.write("# a comment is a change too\n")
    _, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert "solved     teams/ours/harbour.yaml" in stderr
    assert stderr.count("up to date ") == 3


def test_force_solves_every_team_again(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    _, _, stderr = _batch("teams", "-o", "out", "--force", cwd=tmp_path)
    assert "up to date" not in stderr
    assert stderr.count("solved ") == 4


def test_a_team_that_breaks_leaves_no_stale_outputs(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", cwd=tmp_path)
    assert (tmp_path / "out" / "teams" / "case2.json").is_file()
    (teams / "case2.yaml").write_text(BAD, encoding="utf-8")
    _, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert "FAILED     teams/case2.yaml" in stderr
    assert not (tmp_path / "out" / "teams" / "case2.json").exists()
    assert not (tmp_path / "out" / STAMPS / "case2.json").exists()


def test_batch_leaves_no_temporary_files(teams: Path, tmp_path: Path) -> None:
    _batch("teams", "-o", "out", "--jobs", "2", cwd=tmp_path)
    assert [p for p in (tmp_path / "out").rglob("*") if p.name.endswith(".tmp")] == []


# ---- unusable input --------------------------------------------------------------------------


def test_batch_with_a_pattern_that_matches_nothing_exits_2(tmp_path: Path) -> None:
    status, _, stderr = _batch("nothing/*.yaml", "-o", "out", cwd=tmp_path)
    assert status == 2
    assert "nothing/*.yaml: pattern matches no file" in stderr
    assert not (tmp_path / "out").exists()


def test_batch_into_a_file_instead_of_a_folder_exits_2(tmp_path: Path) -> None:
    (tmp_path / "out").write_text("", encoding="utf-8")
    status, _, stderr = _batch(str(TEAMS / "case1.yaml"), "-o", "out", cwd=tmp_path)
    assert status == 2
    assert "out: is not a folder" in stderr


def test_batch_with_a_bad_rules_override_exits_2_once(tmp_path: Path) -> None:
    (tmp_path / "r.yaml").write_text("characteristics: [1]\n", encoding="utf-8")
    status, _, stderr = _batch(str(TEAMS), "-o", "out", "--rules", "r.yaml", cwd=tmp_path)
    assert status == 2
    assert stderr.startswith("r.yaml")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("jobs", ["0", "many"])
def test_batch_refuses_a_job_count_that_is_not_a_positive_number(jobs: str, tmp_path: Path) -> None:
    status, _, stderr = _batch(str(TEAMS), "-o", "out", "--jobs", jobs, cwd=tmp_path)
    assert status == 2
    assert "--jobs" in stderr


def test_batch_keeps_a_team_called_summary_apart_from_the_batch_summary(
    teams: Path, tmp_path: Path
) -> None:
    shutil.copy(teams / "case1.yaml", teams / "summary.yaml")
    status, _, stderr = _batch(
        "teams/summary.yaml", "-o", "out", "--report", "markdown", cwd=tmp_path
    )
    assert status == 0, stderr
    assert (
        (tmp_path / "out" / "summary.md")
        .read_text(encoding="utf-8")
        .startswith("# Batch summary\n")
    )
    assert (
        (tmp_path / "out" / "teams" / "summary.md")
        .read_text(encoding="utf-8")
        .startswith("# Case 1\n")
    )
    assert (tmp_path / "out" / "teams" / "summary.json").is_file()


def test_batch_accepts_shipped_team_names_as_other_commands_do(tmp_path: Path) -> None:
    status, _, stderr = _batch("case1", "case3", "-o", "out", "--jobs", "1", cwd=tmp_path)
    assert status == 0, stderr
    assert "[1/2] solved     rules/teams/case1.yaml: 30 valid robots" in stderr
    assert sorted(_summary(tmp_path / "out")) == [
        "rules/teams/case1.yaml",
        "rules/teams/case3.yaml",
    ]
    assert (tmp_path / "out" / "teams" / "case3.json").is_file()


def test_batch_summary_markdown_escapes_names_from_the_team_files(
    teams: Path, tmp_path: Path
) -> None:
    (teams / "html.yaml").write_text(
        "name: '<img src=x onerror=alert(1)> | *x*'\nrules: ../paper.yaml\nteam:\n  UAV: {}\n",
        encoding="utf-8",
    )
    status, _, stderr = _batch("teams/html.yaml", "-o", "out", cwd=tmp_path)
    assert status == 0, stderr
    markdown = (tmp_path / "out" / "summary.md").read_text(encoding="utf-8")
    assert "<img" not in markdown
    assert "| &lt;img src=x onerror=alert(1)&gt; \\| \\*x\\* |" in markdown


@pytest.mark.parametrize("pattern", ["", "  "])
def test_batch_refuses_an_empty_pattern_instead_of_batching_the_current_folder(
    pattern: str, teams: Path, tmp_path: Path
) -> None:
    status, _, stderr = _batch(pattern, "-o", "out", cwd=tmp_path)
    assert status == 2
    assert f"<arguments>: empty pattern {pattern!r}: name team files, folders or globs" in stderr
    assert not (tmp_path / "out").exists()


# ---- a team that crashes its worker ----------------------------------------------------------


def _workers(batch: int) -> list[int]:
    """The batch's worker processes: its grandchildren (the forkserver, a child of the batch,
    forks the workers; the resource tracker is a child too, with no children)."""
    parents = {}
    for entry in Path("/proc").iterdir():
        try:
            parents[int(entry.name)] = int(
                (entry / "stat").read_text().rsplit(")", 1)[1].split()[1]
            )
        except (ValueError, OSError, IndexError):
            continue
    return [pid for pid, parent in parents.items() if parents.get(parent) == batch]


@pytest.mark.parametrize("others", [0, 1], ids=["alone", "with a team after it"])
def test_a_team_whose_worker_is_killed_fails_alone_and_the_summary_is_written(
    tmp_path: Path, others: int
) -> None:
    import signal
    import subprocess
    import time

    from tests.conftest import ROOT

    folder = tmp_path / "teams"
    folder.mkdir()
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")
    # Its worker gets SIGSEGV: a team of 300,000 configurations keeps it busy for seconds, so
    # the kill lands while it holds the team (Case 3 was solved in 10 ms, sometimes before).
    kinds = [f"T{i}" for i in range(5)]
    (tmp_path / "wide.yaml").write_text(
        f"name: wide\ncharacteristics:\n  kinematic_type:\n    values: [{', '.join(kinds)}]\n"
        "  m:\n    values: [m0, m1, m2]\n  n:\n    range: {min: 1, max: 20000}\n",
        encoding="utf-8",
    )
    (folder / "a-crashes.yaml").write_text(
        "rules: ../wide.yaml\nteam:\n" + "".join(f"  {k}: {{}}\n" for k in kinds),
        encoding="utf-8",
    )
    for number in range(others):
        shutil.copy(TEAMS / "case1.yaml", folder / f"b-after-{number}.yaml")
    out = tmp_path / "out"
    process = subprocess.Popen(
        [sys.executable, "-m", "solver", "batch", folder, "-o", out, "--jobs", "1"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        # The first worker is handed the first team as soon as it starts: it dies holding it.
        while not (workers := _workers(process.pid)):
            assert process.poll() is None, process.communicate()
            time.sleep(0.005)
        os.kill(workers[0], signal.SIGSEGV)
        _, stderr = process.communicate(timeout=300)
    finally:
        process.kill()
    assert process.returncode == 1, stderr
    assert "Traceback" not in stderr
    rows = _summary(out)
    crashed = rows[str(folder / "a-crashes.yaml")]
    assert crashed["status"] == "failed"
    assert "the worker process solving it died (killed by SIGSEGV)" in crashed["message"]
    assert [row["status"] for name, row in rows.items() if "b-after" in name] == ["ok"] * others
    assert (out / "summary.md").is_file()
    assert not (out / "teams" / "a-crashes.json").exists()


def test_ctrl_c_ends_a_batch_with_no_traceback_and_every_team_written_whole_or_not_at_all(
    tmp_path: Path,
) -> None:
    import signal
    import subprocess
    import time

    from tests.conftest import ROOT

    folder = tmp_path / "teams"
    folder.mkdir()
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")
    names = [f"t{number}" for number in range(4)]
    for name in names:
        shutil.copy(TEAMS / "case3.yaml", folder / f"{name}.yaml")
    out = tmp_path / "out"
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "solver",
            "batch",
            folder,
            "-o",
            out,
            "--jobs",
            "1",
            "--report",
            "html",
        ],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # a process group of its own, as a shell gives a command
    )
    try:
        # Interrupted between a team's listing and its report: the worker is writing them.
        while not (out / "teams" / "t1.json").exists():
            assert process.poll() is None, process.communicate()
            time.sleep(0.005)
        os.killpg(process.pid, signal.SIGINT)  # Ctrl-C: the whole group gets SIGINT
        _, stderr = process.communicate(timeout=300)
    finally:
        process.kill()
    assert process.returncode == 130, stderr
    assert "Traceback" not in stderr
    for name in names:
        files = [out / STAMPS / f"{name}.json", out / "teams" / f"{name}.json"]
        files.append(out / "teams" / f"{name}.html")
        assert len({path.exists() for path in files}) == 1, (name, [p.exists() for p in files])
    assert not [path for path in out.rglob("*") if path.name.endswith(".tmp")]


# ---- orphans ---------------------------------------------------------------------------------


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
    import signal
    import subprocess
    import time

    from tests.conftest import ROOT

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


# ---- links in the output folder (issue 36.10) -----------------------------------------------


def _plant(out: Path, name: str) -> Path:
    """Someone else's folder linked where the batch writes ``OUT/<name>``; it holds a file."""
    elsewhere = out.parent / f"theirs-{name.strip('.')}"
    elsewhere.mkdir()
    (elsewhere / "case1.json").write_text("theirs\n", encoding="utf-8")
    out.mkdir(exist_ok=True)
    (out / name).symlink_to(elsewhere, target_is_directory=True)
    return elsewhere


@pytest.mark.parametrize("name", ["teams", STAMPS])
def test_a_folder_link_planted_in_the_output_folder_is_never_written_through(
    teams: Path, tmp_path: Path, name: str
) -> None:
    elsewhere = _plant(tmp_path / "out", name)
    status, _, stderr = _batch("teams/case1.yaml", "-o", "out", cwd=tmp_path)
    assert status == 1
    message = f"out/{name}: is a link inside the output folder; refused"
    assert message in stderr
    assert _summary(tmp_path / "out")["teams/case1.yaml"]["message"].startswith(message)
    assert [p.name for p in elsewhere.iterdir()] == ["case1.json"]
    assert (elsewhere / "case1.json").read_text(encoding="utf-8") == "theirs\n"


def test_a_link_planted_below_the_teams_folder_is_refused_there(
    teams: Path, tmp_path: Path
) -> None:
    (tmp_path / "out" / "teams").mkdir(parents=True)
    elsewhere = _plant(tmp_path / "out" / "teams", "ours")
    status, _, stderr = _batch("teams", "-o", "out", cwd=tmp_path)
    assert status == 1
    assert "out/teams/ours: is a link inside the output folder; refused" in stderr
    rows = _summary(tmp_path / "out")
    assert rows["teams/case1.yaml"]["status"] == "ok"  # the others are written
    assert rows["teams/ours/harbour.yaml"]["status"] == "failed"
    # A failing team's outputs are removed, never through the link.
    assert [p.name for p in elsewhere.iterdir()] == ["case1.json"]


def test_outputs_moved_behind_a_link_are_not_taken_for_up_to_date(
    teams: Path, tmp_path: Path
) -> None:
    _batch("teams/case1.yaml", "-o", "out", cwd=tmp_path)
    out = tmp_path / "out"
    (out / "teams").rename(tmp_path / "moved")
    (out / "teams").symlink_to(tmp_path / "moved", target_is_directory=True)
    status, _, stderr = _batch("teams/case1.yaml", "-o", "out", cwd=tmp_path)
    assert status == 1
    assert "up to date" not in stderr
    assert "out/teams: is a link inside the output folder" in stderr


def test_the_output_folder_may_be_given_through_a_link(teams: Path, tmp_path: Path) -> None:
    (tmp_path / "real").mkdir()
    (tmp_path / "out").symlink_to(tmp_path / "real", target_is_directory=True)
    status, _, stderr = _batch("teams/case1.yaml", "-o", "out", cwd=tmp_path)
    assert status == 0, stderr
    assert (tmp_path / "real" / "teams" / "case1.json").is_file()
