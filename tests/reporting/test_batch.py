"""Batch runs from the library: the team files found (folders, globs, links that loop), the
jobs and their outputs, and the outcomes and summary of a run. The command, ``teleop-ui batch``, is
tested in tests/cli/test_batch.py.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

import solver
from solver.errors import InputError
from solver.reporting.batch import find_teams, make_jobs, run_batch, summary_csv, write_summary
from tests.reporting.batches import OWN_TEAM, write_teams


@pytest.fixture
def teams(tmp_path: Path) -> Path:
    """A folder of team files: three article cases, one of our own rules, two bad ones."""
    return write_teams(tmp_path)


# ---- finding files -------------------------------------------------------------------------


def test_find_teams_searches_folders_recursively_in_name_order(teams: Path) -> None:
    found = [shown for _, shown in find_teams([str(teams)])]
    assert found == [
        str(teams / n)
        for n in (
            "case1.yaml",
            "case2.yaml",
            "case3.yaml",
            "ours/bad.yaml",
            "ours/broken.yaml",
            "ours/harbour.yaml",
            "ours/own.yaml",
        )
    ]


def test_find_teams_expands_recursive_globs_and_counts_a_file_once(teams: Path) -> None:
    found = [
        shown
        for _, shown in find_teams(
            [f"{teams}/**/h*.yaml", f"{teams}/case1.yaml", f"{teams}/ours/harbour.yaml"]
        )
    ]
    assert found == [f"{teams}/ours/harbour.yaml", f"{teams}/case1.yaml"]


def test_find_teams_reports_every_pattern_that_names_nothing(teams: Path) -> None:
    with pytest.raises(InputError) as caught:
        find_teams([f"{teams}/case1.yaml", f"{teams}/*.yml", f"{teams}/nope.yaml"])
    assert [(f.location.file, f.message) for f in caught.value.faults] == [
        (f"{teams}/*.yml", "pattern matches no file"),
        (f"{teams}/nope.yaml", "no such file or folder"),
    ]


# ---- the jobs and a run ----------------------------------------------------------------------


def test_plan_mirrors_the_folders_below_the_common_one(teams: Path, tmp_path: Path) -> None:
    jobs = make_jobs(find_teams([str(teams)]), tmp_path / "out")
    assert [j.output.relative_to(tmp_path / "out" / "teams").as_posix() for j in jobs] == [
        "case1.json",
        "case2.json",
        "case3.json",
        "ours/bad.json",
        "ours/broken.json",
        "ours/harbour.json",
        "ours/own.json",
    ]


def test_library_batch_gives_one_outcome_per_team_and_a_summary(
    teams: Path, tmp_path: Path
) -> None:
    jobs = make_jobs(find_teams([str(teams / "case1.yaml"), str(teams / "ours")]), tmp_path / "o")
    outcomes = list(run_batch(jobs, workers=1))
    assert sorted(o.action for o in outcomes) == ["failed", "failed", "skipped", "solved", "solved"]
    rows, written = write_summary(outcomes, jobs, tmp_path / "o")
    assert [r.file for r in rows] == [j.shown for j in jobs]
    assert written[0].read_text(encoding="utf-8") == summary_csv(rows)


def test_a_team_naming_a_shipped_rule_set_is_stamped_with_that_set_and_skipped_next_time(
    tmp_path: Path,
) -> None:
    folder = tmp_path / "elsewhere"
    folder.mkdir()
    (folder / "mine.yaml").write_text(
        "name: mine\nrules: extended\nteam:\n  UAV: {}\n", encoding="utf-8"
    )
    first = list(run_batch(make_jobs(find_teams([str(folder)]), tmp_path / "out"), workers=1))
    assert [o.action for o in first] == ["solved"]
    stamp = json.loads((tmp_path / "out" / ".stamps" / "mine.json").read_text(encoding="utf-8"))
    shipped = Path(solver.__file__).parent / "rules" / "extended.yaml"
    assert Path(stamp["rules_file"]) == shipped.resolve()
    again = make_jobs(find_teams([str(folder)]), tmp_path / "out")
    assert [job.up_to_date for job in again] == [True]


# ---- links in the input (issue 36.12) ---------------------------------------------------------


@pytest.mark.parametrize("loops", [1, 3])
def test_a_recursive_glob_through_links_that_loop_ends_and_finds_each_file_once(
    teams: Path, loops: int
) -> None:
    # A folder linked to itself and to its parent: followed, `**` never ended (each link
    # another level, 2**40 paths with two of them).
    for index in range(loops):
        (teams / "ours" / f"self{index}").symlink_to(".", target_is_directory=True)
        (teams / "ours" / f"up{index}").symlink_to("..", target_is_directory=True)
    found = [shown for _, shown in find_teams([f"{teams}/**/*.yaml"])]
    assert sorted(found) == found
    assert [Path(f).relative_to(teams).as_posix() for f in found] == [
        "case1.yaml",
        "case2.yaml",
        "case3.yaml",
        "ours/bad.yaml",
        "ours/broken.yaml",
        "ours/harbour.yaml",
        "ours/own.yaml",
    ]


def test_a_recursive_glob_keeps_globs_meaning(teams: Path, tmp_path: Path) -> None:
    (teams / "ours" / ".hidden").mkdir()
    (teams / "ours" / ".hidden" / "x.yaml").write_text(OWN_TEAM, encoding="utf-8")
    (teams / ".dot.yaml").write_text(OWN_TEAM, encoding="utf-8")
    (teams / "ours" / "deeper" / "still").mkdir(parents=True)
    (teams / "ours" / "deeper" / "still" / "h.yaml").write_text(OWN_TEAM, encoding="utf-8")
    linked = tmp_path / "linked"
    linked.mkdir()
    (linked / "l.yaml").write_text(OWN_TEAM, encoding="utf-8")
    (teams / "link").symlink_to(linked, target_is_directory=True)

    def found(pattern: str) -> list[str]:
        return [
            Path(s).relative_to(teams).as_posix() for _, s in find_teams([str(teams / pattern)])
        ]

    # What Python's glob.glob(recursive=True) gives for these, without the loops:
    assert found("**/h*.yaml") == ["ours/deeper/still/h.yaml", "ours/harbour.yaml"]
    assert found("ours/**/*.yaml")[:2] == ["ours/bad.yaml", "ours/broken.yaml"]
    assert found("*/**/h.yaml") == ["ours/deeper/still/h.yaml"]
    assert found("**/l.yaml") == ["link/l.yaml"]  # a link to a folder is followed, once
    with pytest.raises(InputError, match="pattern matches no file"):
        found("**/x.yaml")  # hidden folders are not searched by `**`
    assert found("ours/.hidden/**/x.yaml") == ["ours/.hidden/x.yaml"]
    assert found(".*.yaml") == [".dot.yaml"]
    assert found("**") == found("**/*")


# ---- workers handed several teams at once (issue 42.4) ----------------------------------------


def _grandchildren() -> list[int]:
    """The batch's workers: children of this process's multiprocessing forkserver. Only those:
    other grandchildren (a ROS master a session fixture of this test worker started) are not
    this test's to kill."""
    parents = {}
    for entry in Path("/proc").iterdir():
        try:
            parents[int(entry.name)] = int(
                (entry / "stat").read_text().rsplit(")", 1)[1].split()[1]
            )
        except (ValueError, OSError, IndexError):
            continue
    servers = {pid for pid, parent in parents.items() if parent == os.getpid() and _forkserver(pid)}
    return [pid for pid, parent in parents.items() if parent in servers]


def _forkserver(pid: int) -> bool:
    try:
        return b"multiprocessing.forkserver" in Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return False


def test_a_worker_killed_among_the_teams_handed_to_it_fails_one_team_and_the_rest_are_solved(
    tmp_path: Path,
) -> None:
    import shutil
    import signal

    from tests.conftest import RULES, TEAMS

    folder = tmp_path / "teams"
    folder.mkdir()
    shutil.copy(RULES / "paper.yaml", tmp_path / "paper.yaml")
    for index in range(24):  # one worker is handed 6 at a time
        shutil.copy(TEAMS / "case1.yaml", folder / f"t{index:02d}.yaml")
    jobs = make_jobs(find_teams([str(folder)]), tmp_path / "out")
    outcomes = []
    for outcome in run_batch(jobs, 1):
        outcomes.append(outcome)
        if len(outcomes) == 2:  # among its first six, or just past them: either way one dies
            for worker in _grandchildren():
                os.kill(worker, signal.SIGKILL)
    assert sorted(o.job.shown for o in outcomes) == [job.shown for job in jobs]  # each once
    failed = [o for o in outcomes if o.failed]
    assert len(failed) == 1
    assert "the worker process solving it died (killed by SIGKILL)" in failed[0].row.message
    assert [o.action for o in outcomes if not o.failed] == ["solved"] * 23
    assert not (tmp_path / "out" / "teams" / f"{Path(failed[0].job.shown).stem}.json").exists()


# ---- crash safety: the stamp is a record, not a result (issue 42.4) ---------------------------


def test_a_stamp_naming_another_json_than_the_one_on_disk_is_not_up_to_date(
    teams: Path, tmp_path: Path
) -> None:
    # A crash that kept the stamp's rename and lost the JSON's: the previous JSON is there.
    jobs = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    list(run_batch(jobs, 1))
    output = tmp_path / "out" / "teams" / "case1.json"
    previous = json.loads(output.read_text(encoding="utf-8"))
    previous["totals"]["valid_robots"] = 1
    output.write_text(json.dumps(previous, indent=2) + "\n", encoding="utf-8")
    again = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    assert [job.up_to_date for job in again] == [False]


@pytest.mark.parametrize("stamp", ["", "{", "{}"], ids=["empty", "cut", "no fields"])
def test_a_stamp_emptied_or_cut_by_a_crash_means_solving_again(
    teams: Path, tmp_path: Path, stamp: str
) -> None:
    jobs = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    list(run_batch(jobs, 1))
    assert make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")[0].up_to_date
    (tmp_path / "out" / ".stamps" / "case1.json").write_text(stamp, encoding="utf-8")
    again = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    assert [job.up_to_date for job in again] == [False]
    assert [o.action for o in run_batch(again, 1)] == ["solved"]


def test_the_stamp_records_the_hash_of_the_json_bytes_written(teams: Path, tmp_path: Path) -> None:
    import hashlib

    jobs = make_jobs(find_teams([str(teams / "case3.yaml")]), tmp_path / "out")
    list(run_batch(jobs, 1))
    stamp = json.loads((tmp_path / "out" / ".stamps" / "case3.json").read_text(encoding="utf-8"))
    written = (tmp_path / "out" / "teams" / "case3.json").read_bytes()
    assert stamp["output_sha256"] == hashlib.sha256(written).hexdigest()


@pytest.mark.parametrize(
    ("field", "value"), [("totals", []), ("by_type", {}), ("warnings", "text")]
)
def test_a_json_of_another_shape_planted_under_a_matching_stamp_is_solved_again(
    teams: Path, tmp_path: Path, field: str, value: object
) -> None:
    import hashlib

    jobs = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    list(run_batch(jobs, 1))
    output = tmp_path / "out" / "teams" / "case1.json"
    planted = json.loads(output.read_text(encoding="utf-8"))
    planted[field] = value
    output.write_text(json.dumps(planted), encoding="utf-8")
    stamp_file = tmp_path / "out" / ".stamps" / "case1.json"
    stamp = json.loads(stamp_file.read_text(encoding="utf-8"))
    stamp["output_sha256"] = hashlib.sha256(output.read_bytes()).hexdigest()  # it matches
    stamp_file.write_text(json.dumps(stamp), encoding="utf-8")
    again = make_jobs(find_teams([str(teams / "case1.yaml")]), tmp_path / "out")
    assert [job.up_to_date for job in again] == [False]
    assert [o.action for o in run_batch(again, 1)] == ["solved"]


def test_the_forkserver_preloads_every_module_a_worker_imports_to_solve(
    teams: Path, tmp_path: Path
) -> None:
    import subprocess
    import sys

    # In a fresh interpreter, as the forkserver starts: the preload, then one team solved.
    code = (
        "import importlib, sys\n"
        "from solver.reporting import batch\n"
        "for name in batch._WORKER_MODULES: importlib.import_module(name)\n"
        "before = set(sys.modules)\n"
        f"jobs = batch.make_jobs(batch.find_teams([{str(teams / 'case3.yaml')!r}]), "
        f"{str(tmp_path / 'out')!r}, force=True)\n"
        "assert batch.run_job(jobs[0]).action == 'solved'\n"
        "print(sorted(m for m in set(sys.modules) - before if m.startswith('solver')))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout == "[]\n"
