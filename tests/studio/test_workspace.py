"""What one studio holds is bounded: solutions by the memory they take (whatever names the
teams are given), kept rule sets by number and bytes (their files removed when dropped), and
nothing a request writes outlives it."""

from __future__ import annotations

import dataclasses
import gc
import threading
import time
import tracemalloc
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from benchmarks.conftest import Scale
from solver import Solution, solve
from solver.core.team import load_team
from solver.studio import workspace as workspace_module
from solver.studio.selection import Selection
from solver.studio.whatif import WhatIf, what_if
from solver.studio.workspace import RuleSource, Upload, Workspace, solution_bytes

# A ceiling on waiting for another thread (seconds), never a measure of speed.
WAIT_SECONDS = 60.0


def wait_until(condition: Callable[[], bool]) -> None:
    """Wait for ``condition`` to hold (another thread's doing), within the ceiling."""
    end = time.monotonic() + WAIT_SECONDS
    while not condition():
        assert time.monotonic() < end, "waited past the ceiling"
        time.sleep(0.01)


@pytest.fixture
def workspace(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Workspace]:
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", None)
    found = Workspace()
    yield found
    found.close()


def wide_rules(first: int, second: int) -> str:
    """A rule set whose one kinematic type has ``first x second`` configurations (each value
    a component of its own), written here."""
    a = ", ".join(f"a{i}" for i in range(first))
    b = ", ".join(f"b{i}" for i in range(second))
    return (
        "name: wide\nteam_key: kind\ncharacteristics:\n  kind: {values: [K]}\n"
        f"  a: {{values: [{a}]}}\n  b: {{values: [{b}]}}\n"
    )


def test_the_size_a_solution_is_taken_for_is_never_less_than_it_takes(tmp_path: Path) -> None:
    (tmp_path / "rules.yaml").write_text(wide_rules(300, 150), encoding="utf-8")
    (tmp_path / "team.yaml").write_text(
        "name: wide\nrules: rules.yaml\nteam:\n  K: {}\n", encoding="utf-8"
    )
    team = load_team(tmp_path / "team.yaml")
    gc.collect()
    tracemalloc.start()
    try:
        solution = solve(team)
        taken, _ = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(solution.configurations) == 300 * 150
    estimate = solution_bytes(solution)
    assert taken <= estimate <= 3 * taken


def test_solutions_are_kept_by_the_memory_they_take_whatever_the_names(
    workspace: Workspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    from solver.studio.selection import parse_query

    source = workspace.source("paper")
    one = [("type", "UAV")]
    two = [("type", "UAV"), ("name", "another name")]
    team = workspace.team(parse_query(one, source.rules, "paper"), source)
    workspace.solution(team, source)
    kept = workspace._solutions
    assert len(kept) == 1
    # A bound smaller than two solutions keeps the newest only.
    monkeypatch.setattr(kept, "most_bytes", kept.bytes + 1)
    workspace.solution(workspace.team(parse_query(two, source.rules, "paper"), source), source)
    assert len(kept) == 1
    assert "another name" in next(iter(kept))[1]
    assert kept.most_bytes is not None
    assert kept.bytes <= kept.most_bytes
    # A solution heavier than the bound alone is answered and not kept. The article's rules
    # give a type with nothing deselected 6 motion controls x 10 sensor types x 1..50 sensors.
    monkeypatch.setattr(kept, "most_bytes", 10)
    three = [("type", "Humanoid")]
    team = workspace.team(parse_query(three, source.rules, "paper"), source)
    assert workspace.solution(team, source).totals.valid_robots == 6 * 10 * 50
    assert all("Humanoid" not in key[1] for key in kept)


def test_kept_rule_sets_are_bounded_in_bytes_and_their_files_removed_when_dropped(
    workspace: Workspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    files = [(wide_rules(i + 2, 2) + "#" * 250).encode() for i in range(3)]
    # Room for the last two together, not for all three.
    monkeypatch.setattr(workspace._uploads, "most_bytes", len(files[1]) + len(files[2]))
    sources = [workspace.add_rules(Upload(f"r{i}.yaml", data)) for i, data in enumerate(files)]
    kept = [s.id for s in workspace.rule_sources if s.origin == "upload"]
    assert kept == [s.id for s in sources[1:]]
    assert not sources[0].path.exists()
    assert all(s.path.exists() for s in sources[1:])
    left = sorted(p.name for p in workspace.folder.rglob("*") if p.is_file())
    assert left == ["r1.yaml", "r2.yaml"]


def test_a_requests_scratch_folder_is_gone_when_it_is_done(workspace: Workspace) -> None:
    with workspace.scratch("check") as folder:
        (folder / "team.yaml").write_text("team: {}\n", encoding="utf-8")
    assert not folder.exists()
    with pytest.raises(RuntimeError), workspace.scratch("check") as folder:
        raise RuntimeError
    assert not folder.exists()


def test_the_private_folder_carries_the_process_id_for_the_next_studio_to_clean_up(
    workspace: Workspace,
) -> None:
    import os

    assert workspace.folder.name.startswith(f"{workspace_module.FOLDER_PREFIX}{os.getpid()}-")


# A heavy team: 2 kinematic types x 10 motion controls x 2,000 sensor types, 4,028 single
# changes for what-if to count.
HEAVY = Scale(types=2, motions=10, sensors=2000, groups=10, counts=10, arrangements=5)


def test_the_totals_of_a_change_are_answered_while_what_if_is_busy(
    workspace: Workspace, tmp_path: Path
) -> None:
    team = HEAVY.team(tmp_path)
    source = RuleSource("heavy", team.rules, Path(team.rules.file), "start")
    busy = threading.Event()
    release = threading.Event()
    answers: dict[str, object] = {}

    def held() -> WhatIf:
        # The real what-if of the heavy team, each held busy until the test has its totals.
        busy.set()
        release.wait(WAIT_SECONDS)
        return what_if(team)

    def ask(name: str) -> threading.Thread:
        selection = Selection("heavy", name, ("T0",), (), ())
        asked = workspace.whatifs_asked
        thread = threading.Thread(
            target=lambda: answers.__setitem__(
                name, workspace.kept_whatif(("heavy", selection, "what-if"), held)
            )
        )
        thread.start()
        wait_until(lambda: workspace.whatifs_asked > asked)
        return thread

    # A first what-if is being made (held busy); quick ticks ask for two more.
    first = ask("first")
    assert busy.wait(WAIT_SECONDS)
    older = ask("older")
    newest = ask("newest")

    # The totals of a change are answered while the what-if is still being made.
    changed = dataclasses.replace(team, selections=team.selections[:1])
    totals = threading.Thread(
        target=lambda: answers.__setitem__("totals", workspace.solution(changed, source))
    )
    totals.start()
    totals.join(WAIT_SECONDS)
    assert not totals.is_alive(), "the totals waited for what-if"
    assert not release.is_set()
    assert first.is_alive()
    solved = answers["totals"]
    assert isinstance(solved, Solution)
    assert solved.totals.valid_robots == HEAVY.robots // 2

    # The older what-if waiting for the slot is dropped (a newer one was asked): not made.
    older.join(WAIT_SECONDS)
    assert answers["older"] is None
    release.set()
    for thread in (first, newest):
        thread.join(WAIT_SECONDS)
    assert isinstance(answers["first"], WhatIf)
    assert isinstance(answers["newest"], WhatIf)
