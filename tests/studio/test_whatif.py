"""What-if: single changes of a team ranked by the UI configurations they save.

Each suggestion's counts are checked against the command line's ``solve`` of the changed team
written as a team file (the whole team, not the one type what-if counts), and against the
article's Case 3 hypothesis, whose file says what dropping the Mobile Manipulator's Force
Sensor costs (-52 robots, -12 configurations). In the browser: the top suggestion applied
gives the counts it promised, the exported team solves to them, and undo restores Case 3.
"""

from __future__ import annotations

import itertools
import json
import re
from html import unescape
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from solver import load_team, solve
from solver.solving.teamfile import team_yaml
from solver.studio.whatif import what_if
from tests.conftest import run_cli
from tests.studio.conftest import StartStudio


def cli_totals(path: Path) -> tuple[int, int]:
    answer = run_cli("solve", path, "--count-only", "--format", "json")
    assert answer.returncode == 0, answer.stderr
    totals = json.loads(answer.stdout)["totals"]
    return totals["valid_robots"], totals["ui_configurations"]


def test_every_suggestion_for_case_3_is_what_solve_gives_for_the_changed_team(
    tmp_path: Path,
) -> None:
    found = what_if(load_team("case3"))
    assert found.suggestions
    assert not found.left_out
    for number, suggestion in enumerate(found.suggestions):
        path = tmp_path / f"changed-{number}.yaml"
        path.write_text(team_yaml(suggestion.team), encoding="utf-8")
        assert cli_totals(path) == (
            872 - suggestion.robots_lost,
            102 - suggestion.configurations_saved,
        ), suggestion.text


def test_every_change_of_case_3_is_counted_by_structure_none_listed() -> None:
    for suggestion in what_if(load_team("case3")).suggestions:
        counted = solve(suggestion.team, count_only=True)
        assert {t.method for t in counted.by_type} == {"structure"}, suggestion.text


def test_suggestions_are_ranked_by_configurations_saved_then_robots_lost() -> None:
    ranks = [
        (-s.configurations_saved, s.robots_lost) for s in what_if(load_team("case3")).suggestions
    ]
    assert ranks == sorted(ranks)
    assert all(saved < 0 for saved, _ in ranks)


def test_dropping_the_force_sensor_costs_what_the_case_3_hypothesis_says() -> None:
    found = {s.text: s for s in what_if(load_team("case3")).suggestions}
    # Said in the words the rules give people (the labels), not the characteristics' keys.
    dropped = found["Mobile Manipulator: Sensor Type without Force Sensor"]
    assert (dropped.robots_lost, dropped.configurations_saved) == (52, 12)


def test_a_maximum_is_lowered_only_below_an_arrangement_of_the_rules() -> None:
    # Case 3's counts are arranged from 1, 6, 11, 16 and 26 (rules/paper.yaml): a lowered
    # maximum is one below an arrangement's start, within the type's range.
    found = what_if(load_team("case3")).suggestions
    lowered = {(s.kinematic_type, int(s.value)) for s in found if s.kind == "lower"}
    assert lowered <= {
        ("UGV", 5),
        ("Mobile Manipulator", 5),
        ("Mobile Manipulator", 10),
        ("Humanoid", 5),
        ("Humanoid", 10),
        ("Humanoid", 15),
    }
    assert ("Humanoid", 15) in lowered


def test_a_team_with_nothing_left_to_narrow_has_no_suggestion(tmp_path: Path) -> None:
    path = tmp_path / "t.yaml"
    path.write_text(
        "team:\n  UAV:\n    motion_control: Flight\n    sensor_type: 2D Camera\n"
        "    sensor_count: 1\n",
        encoding="utf-8",
    )
    found = what_if(load_team(path))
    assert found.suggestions == ()
    assert found.tried == 0


def test_changes_past_the_bound_are_left_untried_and_said(monkeypatch: pytest.MonkeyPatch) -> None:
    import solver.studio.whatif as module

    monkeypatch.setattr(module, "MAX_TRIED", 5)
    found = module.what_if(load_team("case3"))
    assert (found.tried, found.total) == (5, 36)
    assert "at most 5 changes" in found.stopped
    assert len(found.suggestions) <= 5


def test_case_3_has_36_single_changes_and_all_are_tried() -> None:
    # Drops: UAV 2 + 3, UGV 2 + 4, Mobile Manipulator 4 + 6, Humanoid 3 + 6 = 30 (one per
    # selected value of a characteristic with two or more); lowered maxima below the paper's
    # arrangements at 6, 11 and 16: UGV (1..10) 1, Mobile Manipulator (1..13) 2, Humanoid
    # (1..25) 3 = 6.
    found = what_if(load_team("case3"))
    assert (found.tried, found.total, found.stopped, found.left_out) == (36, 36, "", ())


def test_a_spent_time_budget_stops_trying_and_says_so() -> None:
    found = what_if(load_team("case3"), seconds=1e-9)
    assert found.tried == 0
    assert found.total == 36
    assert "1e-09 s" in found.stopped


def test_what_is_tried_is_a_prefix_of_one_order_wherever_the_cut_falls(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The cut (a bound, or the time budget on a slower machine) only decides how far along
    # one fixed order the answer goes: each cut's suggestions are the next cut's minus those
    # of the changes after it, never another set.
    import solver.studio.whatif as module

    answers = []
    for bound in range(37):
        monkeypatch.setattr(module, "MAX_TRIED", bound)
        answers.append(module.what_if(load_team("case3")))
    for bound, (shorter, longer) in enumerate(itertools.pairwise(answers)):
        assert shorter.tried == bound
        assert bool(shorter.stopped) == (bound < 36)
        assert {s.text for s in shorter.suggestions} <= {s.text for s in longer.suggestions}
        assert len(longer.suggestions) - len(shorter.suggestions) <= 1


def test_a_change_the_structure_cannot_count_is_left_out_with_why_never_listed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The structure counts a block of linked characteristics by its class combinations; with
    # room for none, every change of a type whose rules link characteristics would have to be
    # counted by listing robots: what-if leaves each out and says why.
    from solver.engines import structure

    monkeypatch.setattr(structure, "BLOCK_LIMIT", 0)
    found = what_if(load_team("case3"))
    assert found.tried == 36
    assert found.left_out
    assert len(found.left_out) + len(found.suggestions) <= 36
    for left in found.left_out:
        assert "the rules' structure cannot count it" in left.reason, left
        assert "what-if lists no robots" in left.reason
        assert left.change.split(": ")[0] in {"UAV", "UGV", "Mobile Manipulator", "Humanoid"}


def test_the_top_suggestion_applied_gives_its_counts_and_undo_restores_case_3(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    server = start_studio("case3")
    page.goto(server.url)
    expect(page.locator("#total-configurations")).to_have_text("102")
    expect(page.locator("#whatif-summary")).to_contain_text("36 of 36 changes tried")
    top = page.locator("#whatif li").first
    expect(top).to_be_visible()
    saved = int(top.get_attribute("data-saved") or "")
    lost = int(top.get_attribute("data-lost") or "")
    expected = what_if(load_team("case3")).suggestions[0]
    assert (saved, lost) == (expected.configurations_saved, expected.robots_lost)

    top.get_by_role("link", name="Apply").first.click()
    expect(page.locator("#total-configurations")).to_have_text(str(102 - saved))
    expect(page.locator("#total-robots")).to_have_text(str(872 - lost))
    # The suggestions follow the new selection.
    expect(page.locator("#whatif-section")).to_have_attribute("data-query", page.url.split("?")[1])

    # Undo (the apply is a change of the page's history) restores Case 3; Redo applies again.
    page.get_by_role("button", name="Undo").click()
    expect(page.locator("#total-configurations")).to_have_text("102")
    expect(page.locator("#total-robots")).to_have_text("872")
    page.get_by_role("button", name="Redo").click()
    expect(page.locator("#total-configurations")).to_have_text(str(102 - saved))

    # Exported, the changed team solves to the same counts by the command line.
    page.get_by_role("link", name="Export").click()
    with page.expect_download() as download:
        page.get_by_role("link", name="Team YAML").click()
    exported = tmp_path / "applied.yaml"
    download.value.save_as(exported)
    assert cli_totals(exported) == (872 - lost, 102 - saved)


def test_no_suggestion_is_the_same_team() -> None:
    team = load_team("case3")
    for suggestion in what_if(team).suggestions:
        assert suggestion.team.selections != team.selections
        assert suggestion.team.name == team.name


def test_the_selection_page_is_served_without_what_if_which_is_asked_for_after(
    start_studio: StartStudio,
) -> None:
    server = start_studio("case3")
    status, body = server.get("/")  # the started team's page (a redirect to its selection)
    html = body.decode()
    assert status == 200
    assert 'id="total-configurations"' in html
    assert "data-apply" not in html
    assert "changes tried" not in html
    # Without scripts, the page asks for it by a link: whatif=1 makes it with the page.
    link = re.search(r'href="(/\?[^"]*whatif=1)"', html)
    assert link is not None
    status, body = server.get(unescape(link.group(1)))
    assert status == 200
    assert "36 of 36 changes tried" in body.decode()
    assert "data-apply" in body.decode()


def test_quick_changes_ask_for_one_what_if_once_the_selection_rests(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    asked: list[str] = []
    page.on("request", lambda r: asked.append(r.url) if "/api/whatif" in r.url else None)
    page.goto(server.url)
    section = page.locator("#whatif-section")
    expect(section).to_have_attribute("data-state", "answered")
    assert len(asked) == 1  # after the page's load, never with it
    asked.clear()
    # Three values unticked in one go (one task of the page: no timer can run between them).
    page.evaluate(
        """() => {
        const boxes = document.querySelectorAll(
            'fieldset[data-key="Humanoid.sensor_type"] input[type=checkbox]:checked');
        for (const box of [...boxes].slice(0, 3)) {
            box.checked = false;
            box.dispatchEvent(new Event("change", { bubbles: true }));
        }
    }"""
    )
    form = page.locator("form[data-current]").first
    expect(section).to_have_attribute("data-query", form.get_attribute("data-current") or "")
    expect(section).to_have_attribute("data-state", "answered")
    assert len(asked) == 1, asked
    assert asked[0].endswith(form.get_attribute("data-current") or "")
