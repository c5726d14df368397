"""What-if: single changes of a team ranked by the UI configurations they save.

Each suggestion's counts are checked against the command line's ``solve`` of the changed team
written as a team file (the whole team, not the one type what-if counts), and against the
article's Case 3 hypothesis, whose file says what dropping the Mobile Manipulator's Force
Sensor costs (-52 robots, -12 configurations). A change to the rule set (two components
merged, a constraint removed) is checked against ``solve`` under a rule file the test writes
by hand. In the browser: the top suggestion applied gives the counts it promised, the exported
team solves to them, and undo restores Case 3; a change to the rule set applied is kept as an
upload, and Back and Undo return to the rule set before.
"""

from __future__ import annotations

import itertools
import json
import re
from html import unescape
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from solver import InputError, load_team, solve
from solver.core.rules import shipped_path
from solver.solving.teamfile import team_yaml
from solver.studio.whatif import changed_rules_text, what_if
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
    team_changes = [s for s in found.suggestions if not s.rules_change]
    assert team_changes
    for number, suggestion in enumerate(team_changes):
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
    assert (found.tried, found.total) == (5, 61)
    assert "at most 5 changes" in found.stopped
    assert len(found.suggestions) <= 5


def test_case_3_has_36_single_changes_and_25_of_the_rules_and_all_are_tried() -> None:
    # Drops: UAV 2 + 3, UGV 2 + 4, Mobile Manipulator 4 + 6, Humanoid 3 + 6 = 30 (one per
    # selected value of a characteristic with two or more); lowered maxima below the paper's
    # arrangements at 6, 11 and 16: UGV (1..10) 1, Mobile Manipulator (1..13) 2, Humanoid
    # (1..25) 3 = 6. Merges: the team uses all 5 sensor groups (10 pairs) and all 6 motion
    # controls, each its own component (15 pairs); rules/paper.yaml has no constraint.
    found = what_if(load_team("case3"))
    assert (found.tried, found.total, found.stopped, found.left_out) == (61, 61, "", ())
    merges = [s for s in found.suggestions if s.kind == "merge"]
    assert {s.characteristic for s in merges} == {"sensor_type", "motion_control"}


def test_a_spent_time_budget_stops_trying_and_says_so() -> None:
    found = what_if(load_team("case3"), seconds=1e-9)
    assert found.tried == 0
    assert found.total == 61
    assert "1e-09 s" in found.stopped


def test_what_is_tried_is_a_prefix_of_one_order_wherever_the_cut_falls(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The cut (a bound, or the time budget on a slower machine) only decides how far along
    # one fixed order the answer goes: each cut's suggestions are the next cut's minus those
    # of the changes after it, never another set.
    import solver.studio.whatif as module

    answers = []
    for bound in range(62):
        monkeypatch.setattr(module, "MAX_TRIED", bound)
        answers.append(module.what_if(load_team("case3")))
    for bound, (shorter, longer) in enumerate(itertools.pairwise(answers)):
        assert shorter.tried == bound
        assert bool(shorter.stopped) == (bound < 61)
        assert {s.text for s in shorter.suggestions} <= {s.text for s in longer.suggestions}
        assert len(longer.suggestions) - len(shorter.suggestions) <= 1


def test_a_change_the_structure_cannot_count_is_left_out_with_why_never_listed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The structure counts a block of linked characteristics by its class combinations; with
    # room for none, every change of a type whose rules link characteristics would have to be
    # counted by listing robots: what-if leaves each out and says why. (Rules without
    # constraints link nothing: their counts are products, whatever the limit; so the team is
    # one under the extended rules, which have constraints.)
    from solver.engines import structure

    monkeypatch.setattr(structure, "BLOCK_LIMIT", 0)
    team = load_team("search-and-rescue")
    found = what_if(team)
    assert found.tried == found.total
    assert found.left_out
    assert len(found.left_out) + len(found.suggestions) <= found.tried
    for left in found.left_out:
        assert "the rules' structure cannot count it" in left.reason, left
        assert "what-if lists no robots" in left.reason
        changed = left.change.split(": ")[0]
        assert changed in team.kinematic_types or changed.startswith(
            ("merge ", "remove the constraint ")
        )


def test_the_top_suggestion_applied_gives_its_counts_and_undo_restores_case_3(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    server = start_studio("case3")
    page.goto(server.url)
    expect(page.locator("#total-configurations")).to_have_text("102")
    expect(page.locator("#whatif-summary")).to_contain_text("61 of 61 changes tried")
    expect(page.locator("#whatif")).to_contain_text(", 0 valid robots")  # a merge: no sign
    expect(page.locator("#whatif")).not_to_contain_text("-0 valid robots")
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
        if suggestion.rules_change:
            assert suggestion.team.selections == team.selections
            assert suggestion.team.rules != team.rules
        else:
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
    assert "61 of 61 changes tried" in body.decode()
    assert "data-apply" in body.decode()
    # A merge loses no robot: "0 valid robots", never "-0" (the page's script writes the same).
    assert "-0 valid robots" not in body.decode()
    assert re.search(
        r"merge Sensor Type: [^<]*</span>: <strong>-\d+ configurations</strong>, 0 valid robots",
        body.decode(),
    )


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


# -- changes to the rule set ------------------------------------------------------------------

VISUAL = "      - name: visual display\n        values: [2D Camera, 3D Camera]\n"
POINT_CLOUD = (
    "      - name: point cloud\n        values: [2D Scanning, 3D Scanning, LIDAR, RGB-D Camera]\n"
)


def team_file(folder: Path, rules_text: str, name: str) -> Path:
    """Case 3 (without its published figures) under ``rules_text``, both written to
    ``folder``."""
    (folder / f"{name}-rules.yaml").write_text(rules_text, encoding="utf-8")
    case3 = shipped_path("teams", "case3.yaml").read_text(encoding="utf-8")
    team = case3.split("published:")[0].replace("rules: ../paper.yaml", f"rules: {name}-rules.yaml")
    path = folder / f"{name}.yaml"
    path.write_text(team, encoding="utf-8")
    return path


def test_the_top_rule_change_for_case_3_saves_what_solve_gives_under_the_rules_written_by_hand(
    tmp_path: Path,
) -> None:
    found = what_if(load_team("case3"))
    top = next(s for s in found.suggestions if s.rules_change)
    assert top.text == "merge Sensor Type: visual display and point cloud"
    assert top.configurations_saved > 0
    # The rule file with the two groups written as one, by hand.
    paper = shipped_path("paper.yaml").read_text(encoding="utf-8")
    assert VISUAL in paper
    assert POINT_CLOUD in paper
    merged = paper.replace(POINT_CLOUD, "").replace(
        VISUAL,
        "      - name: seen\n"
        "        values: [2D Camera, 3D Camera, 2D Scanning, 3D Scanning, LIDAR, RGB-D Camera]\n",
    )
    assert cli_totals(team_file(tmp_path, merged, "merged")) == (
        872 - top.robots_lost,
        102 - top.configurations_saved,
    )


def test_removing_a_constraint_gains_the_robots_solve_gives_without_it(tmp_path: Path) -> None:
    paper = shipped_path("paper.yaml").read_text(encoding="utf-8")
    constrained = paper + (
        "\nconstraints:\n"
        "  - name: no 360 camera in flight\n"
        "    forbid: {motion_control: Flight, sensor_type: 360 Camera}\n"
    )
    with_it = team_file(tmp_path, constrained, "constrained")
    without = team_file(tmp_path, paper, "plain")
    found = what_if(load_team(with_it))
    (removal,) = [s for s in found.suggestions if s.kind == "remove"]
    assert removal.text.startswith("remove the constraint at ")
    assert "constrained-rules.yaml:" in removal.text
    assert (
        "'no 360 camera in flight' (forbid motion_control is Flight and sensor_type is 360 Camera)"
        in removal.text
    )
    assert removal.robots_lost < 0  # it gains robots
    robots, configurations = cli_totals(with_it)
    assert cli_totals(without) == (
        robots - removal.robots_lost,
        configurations - removal.configurations_saved,
    )


@pytest.mark.parametrize(
    "key",
    [
        "",
        "merge",
        "merge:sensor_type:4:0",
        "merge:sensor_type:0:0",
        "merge:sensor_type:0:99",
        "merge:sensor_type:0:1:2",
        "merge:kinematic_type:0:1",
        "merge:sensor_count:0:1",
        "merge:nothing:0:1",
        "remove:0",
        "remove:-1",
        "drop:UAV",
        "../../etc/passwd",
    ],
)
def test_a_change_the_rules_do_not_offer_is_refused_located(key: str) -> None:
    with pytest.raises(InputError) as raised:
        changed_rules_text(load_team("case3").rules, key)
    (fault,) = raised.value.faults
    assert (fault.location.path, fault.code) == ("change", "unknown-reference")


def test_the_changes_to_the_rules_tried_are_bounded(monkeypatch: pytest.MonkeyPatch) -> None:
    import solver.studio.whatif as module

    monkeypatch.setattr(module, "MAX_MERGES", 3)
    changes = module.rule_changes(load_team("case3"))
    # The first three pairs in the rules' order: motion controls as rules/paper.yaml lists them.
    assert [c.text for c in changes] == [
        "merge Robot Motion Control: Joint and Flight",
        "merge Robot Motion Control: Joint and Driving",
        "merge Robot Motion Control: Joint and Walking",
    ]
    assert module.what_if(load_team("case3")).total == 36 + 3


def test_a_change_to_the_rules_is_applied_by_the_api_and_kept_as_an_upload(
    start_studio: StartStudio,
) -> None:
    server = start_studio("case3")
    selection = "rules=paper&name=UAVs&type=UAV&UAV.sensor_type=2D+Camera&UAV.sensor_type=LIDAR"
    answer = server.json("/api/whatif?" + selection)
    wanted = "merge Sensor Type: visual display and point cloud"
    (merge,) = [s for s in answer["suggestions"] if s["change"] == wanted]
    assert merge["rules_change"] == "merge:sensor_type:0:4"
    status, body = server.request("POST", "/api/whatif/apply?" + merge["query"])
    assert status == 200, body
    query = json.loads(body)["query"]
    assert "rules=upload-" in query
    assert "paper-whatif.yaml" in [p.name for p in server.kept_files()]
    # The same selection under the changed rules: the counts the suggestion promised.
    assert query.replace(query.split("&")[0], "") == selection.replace("rules=paper", "")
    totals = server.json("/api/count?" + query)["totals"]
    assert (totals["ui_configurations"], totals["valid_robots"]) == (
        merge["after"]["ui_configurations"],
        merge["after"]["valid_robots"],
    )
    status, body = server.request("POST", "/api/whatif/apply?rules=paper&type=UAV&change=remove:0")
    assert status == 422
    assert json.loads(body)["faults"][0]["path"] == "change"


def test_a_merge_applied_in_the_page_and_back_and_undo_return_to_the_rules_before(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.goto(server.url)
    total = page.locator("#total-configurations")
    rules = page.locator("select#rules")
    expect(total).to_have_text("102")
    expect(rules).to_have_value("paper")
    merge = page.locator("#whatif li").filter(
        has_text="merge Sensor Type: visual display and point cloud"
    )
    expect(merge).to_have_count(1)
    saved = int(merge.get_attribute("data-saved") or "")
    lost = int(merge.get_attribute("data-lost") or "")

    merge.get_by_role("button", name="Apply").click()
    expect(rules).to_have_value(re.compile(r"^upload-"))
    expect(total).to_have_text(str(102 - saved))
    expect(page.locator("#total-robots")).to_have_text(str(872 - lost))
    assert "paper-whatif.yaml" in [p.name for p in server.kept_files()]

    page.go_back()
    expect(rules).to_have_value("paper")
    expect(total).to_have_text("102")
    page.go_forward()
    expect(rules).to_have_value(re.compile(r"^upload-"))
    expect(total).to_have_text(str(102 - saved))
    # The page's Undo walks the same history back into the rule set before; Redo forward.
    page.get_by_role("button", name="Undo").click()
    expect(rules).to_have_value("paper")
    expect(total).to_have_text("102")
    page.get_by_role("button", name="Redo").click()
    expect(rules).to_have_value(re.compile(r"^upload-"))
    expect(total).to_have_text(str(102 - saved))
