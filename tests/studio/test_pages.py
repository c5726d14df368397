"""The studio's pages in a real browser, used as a designer would: ticking the article's cases,
exporting the team, browsing configurations, looking a robot up, undoing a change.

The expected figures are the article's (Table 2, SPEC.md section 5) and the command line's
answers for the same team files, never the studio's own.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from pathlib import Path
from urllib.parse import parse_qsl, urlsplit

from markupsafe import escape
from playwright.sync_api import Page, expect

from benchmarks.conftest import Scale
from tests.conftest import ROOT, run_cli
from tests.studio.conftest import Server, StartStudio

# The article's selections (its Table 2), per kinematic type.
CASE_1 = {
    "UAV": (["Flight", "Waypoint"], ["2D Camera", "360 Camera", "RGB-D Camera"], 5),
}
CASE_2 = {
    **CASE_1,
    "UGV": (["Driving", "Waypoint"], ["2D Camera", "LIDAR", "Speaker", "Microphone"], 10),
}
CASE_3 = {
    **CASE_2,
    "Mobile Manipulator": (
        ["Joint", "Driving", "End Effector", "Waypoint"],
        ["2D Camera", "RGB-D Camera", "LIDAR", "Speaker", "Microphone", "Force Sensor"],
        13,
    ),
    "Humanoid": (
        ["Joint", "Walking", "Waypoint"],
        ["2D Camera", "3D Camera", "LIDAR", "RGB-D Camera", "Speaker", "Microphone"],
        25,
    ),
}


def tick_type(
    page: Page, kinematic_type: str, motions: Iterable[str], sensors: Iterable[str], most: int
) -> None:
    """Include ``kinematic_type`` and tick exactly these values, by clicking and typing."""
    fieldset = page.locator(f'fieldset.type[data-type="{kinematic_type}"]')
    fieldset.locator("legend").get_by_label(kinematic_type, exact=True).check()
    for key, wanted in (("motion_control", set(motions)), ("sensor_type", set(sensors))):
        group = page.locator(f'fieldset[data-key="{kinematic_type}.{key}"]')
        for box in group.locator("input[type=checkbox]").all():
            value = box.get_attribute("value")
            box.set_checked(value in wanted)
    slider = page.locator(f'fieldset[data-key="{kinematic_type}.sensor_count"]').get_by_label(
        "Most"
    )
    # A person with a keyboard: to the lowest count, then up one step at a time.
    slider.focus()
    slider.press("Home")
    for _ in range(most - 1):
        slider.press("ArrowRight")
    expect(slider).to_have_value(str(most))


def totals(page: Page) -> tuple[str, str]:
    return (
        page.locator("#total-robots").inner_text(),
        page.locator("#total-configurations").inner_text(),
    )


def test_ticking_the_articles_three_cases_shows_their_figures(
    studio: Server, page: Page, tmp_path: Path
) -> None:
    page.goto(studio.url)
    expect(page.locator("#change")).to_contain_text("No kinematic type selected yet")
    for kinematic_type, (motions, sensors, most) in CASE_1.items():
        tick_type(page, kinematic_type, motions, sensors, most)
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(page.locator("#total-configurations")).to_have_text("6")
    expect(page.locator("#published")).to_contain_text("30 valid robots / 6 UI configurations")
    expect(page.locator("#published")).to_contain_text("reproduced")

    tick_type(page, "UGV", *CASE_2["UGV"])
    expect(page.locator("#total-robots")).to_have_text("110")
    expect(page.locator("#total-configurations")).to_have_text("18")

    for kinematic_type in ("Mobile Manipulator", "Humanoid"):
        tick_type(page, kinematic_type, *CASE_3[kinematic_type])
    expect(page.locator("#total-robots")).to_have_text("872")
    expect(page.locator("#total-configurations")).to_have_text("102")
    published = page.locator("#published")
    expect(published).to_contain_text("820 valid robots / 99 UI configurations")
    expect(published).not_to_contain_text("published")  # the term beside it says it once
    expect(published).to_contain_text("NOT reproduced: these rules give 872 / 102")
    # The last change cost something, and says how much.
    expect(page.locator("#change")).to_contain_text("Last change:")

    # The address holds the selection: opened afresh, it shows the same team.
    bookmark = page.url
    other = page.context.new_page()
    other.goto(bookmark)
    expect(other.locator("#total-robots")).to_have_text("872")
    expect(other.locator("#total-configurations")).to_have_text("102")
    other.close()

    # Exported, the team file gives the command line the same numbers.
    page.get_by_role("link", name="Export").click()
    expect(page.locator("#team-yaml")).to_contain_text("Humanoid:")
    with page.expect_download() as download:
        page.get_by_role("link", name="Team YAML").click()
    team_file = tmp_path / "exported.yaml"
    download.value.save_as(team_file)
    solved = run_cli("solve", team_file, "--format", "json")
    assert solved.returncode == 0, solved.stderr
    data = json.loads(solved.stdout)
    assert (data["totals"]["valid_robots"], data["totals"]["ui_configurations"]) == (872, 102)
    assert data["published"]["valid_robots"] == 820
    by_case = json.loads(run_cli("solve", "case3", "--format", "json").stdout)
    assert data["by_type"] == by_case["by_type"]


def test_a_bookmarked_selection_of_the_article_is_the_cli_s_case(
    studio: Server, page: Page
) -> None:
    query = (
        "rules=paper&type=UAV&UAV.motion_control=Flight&UAV.motion_control=Waypoint"
        "&UAV.sensor_type=2D+Camera&UAV.sensor_type=360+Camera"
        "&UAV.sensor_type=RGB-D+Camera&UAV.sensor_count.max=5"
    )
    page.goto(studio.at(f"?{query}"))
    expect(page.locator("#total-robots")).to_have_text("30")
    fieldset = page.locator('fieldset[data-key="UAV.motion_control"]')
    expect(fieldset.get_by_label("Flight", exact=True)).to_be_checked()
    expect(fieldset.get_by_label("Joint", exact=True)).not_to_be_checked()


def test_undo_and_redo_walk_back_and_forth_through_changes(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case1")
    page.goto(server.url)
    expect(page.locator("#total-robots")).to_have_text("30")
    group = page.locator('fieldset[data-key="UAV.motion_control"]')
    group.get_by_label("Waypoint", exact=True).uncheck()
    expect(page.locator("#total-robots")).to_have_text("15")
    expect(page.locator("#change")).to_have_text("Last change: -3 configurations, -15 valid robots")
    group.get_by_label("Joint", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("30")
    page.get_by_role("button", name="Undo").click()
    expect(page.locator("#total-robots")).to_have_text("15")
    expect(group.get_by_label("Joint", exact=True)).not_to_be_checked()
    page.keyboard.press("Control+Z")
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(group.get_by_label("Waypoint", exact=True)).to_be_checked()
    page.get_by_role("button", name="Redo").click()
    expect(page.locator("#total-robots")).to_have_text("15")
    assert ("UAV.motion_control", "Flight") in parse_qsl(urlsplit(page.url).query)


def test_undo_and_the_browsers_back_walk_one_history(start_studio: StartStudio, page: Page) -> None:
    server = start_studio("case1")
    page.goto(server.url)
    expect(page.locator("#total-robots")).to_have_text("30")
    group = page.locator('fieldset[data-key="UAV.motion_control"]')
    group.get_by_label("Waypoint", exact=True).uncheck()
    expect(page.locator("#total-robots")).to_have_text("15")
    group.get_by_label("Joint", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("30")
    page.go_back()  # Joint unticked again
    expect(page.locator("#total-robots")).to_have_text("15")
    expect(group.get_by_label("Joint", exact=True)).not_to_be_checked()
    page.get_by_role("button", name="Undo").click()  # further back: Waypoint ticked again
    expect(group.get_by_label("Waypoint", exact=True)).to_be_checked()
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(page.get_by_role("button", name="Undo")).to_be_disabled()  # the page's first state
    page.go_forward()
    expect(group.get_by_label("Waypoint", exact=True)).not_to_be_checked()
    page.keyboard.press("Control+Shift+Z")  # redo after Forward: Joint ticked again
    expect(group.get_by_label("Joint", exact=True)).to_be_checked()
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(page.get_by_role("button", name="Redo")).to_be_disabled()
    # A rename is a change too, and the header names the team as the page has it.
    page.get_by_label("Team name").fill("My team")
    page.get_by_label("Team name").press("Enter")
    expect(page.locator("#context-team")).to_have_text("My team")
    page.get_by_role("button", name="Undo").click()
    expect(page.locator("#context-team")).to_have_text("Case 1")


def test_an_empty_choice_is_a_located_error_in_the_page_and_the_next_change_is_served(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case1")
    page.goto(server.url)
    group = page.locator('fieldset[data-key="UAV.motion_control"]')
    group.get_by_label("Flight", exact=True).uncheck()
    group.get_by_label("Waypoint", exact=True).uncheck()
    expect(page.locator("#faults")).to_contain_text("team.UAV.motion_control")
    expect(page.locator("#faults")).to_contain_text("empty selection for 'motion_control'")
    expect(group.locator("[data-faults-for]")).to_contain_text("empty selection")
    # The counts shown are the last selection's that could be solved, and say so.
    expect(page.locator("#totals")).to_have_attribute("data-stale", "")
    expect(page.locator("#change")).to_have_text(
        "Not updated: the selection has problems; the counts are the last ones without."
    )
    group.get_by_label("Flight", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("15")
    expect(page.locator("#faults")).to_be_empty()
    expect(page.locator("#totals")).not_to_have_attribute("data-stale", "")


def test_a_typo_in_the_address_is_shown_at_its_control(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case1")
    page.goto(server.at("?rules=paper&type=UAV&UAV.motion_control=Waypont"))
    expect(page.locator("#faults")).to_contain_text("team.UAV.motion_control")
    slot = page.locator('fieldset[data-key="UAV.motion_control"] [data-faults-for]')
    expect(slot).to_contain_text("'Waypont'")
    expect(page.locator("#change")).to_have_text(
        "Not solved: the selection has problems (above, and at their controls)."
    )


def test_on_a_phone_nothing_is_wider_than_the_screen(start_studio: StartStudio, page: Page) -> None:
    server = start_studio("case3")
    page.set_viewport_size({"width": 375, "height": 667})
    page.goto(server.url)
    expect(page.locator("#total-robots")).to_have_text("872")
    selection = urlsplit(page.url).query
    for address in (page.url, f"{server.base}configurations?{selection}"):
        page.goto(address)
        expect(page.locator("main")).to_be_visible()
        assert page.evaluate("document.documentElement.scrollWidth") <= 375, address


def test_on_a_phone_the_totals_come_first_stay_reachable_and_nothing_is_clipped(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.set_viewport_size({"width": 390, "height": 844})
    page.goto(server.url)
    robots = page.locator("#total-robots")
    expect(robots).to_have_text("872")
    # The totals are on the first screen, above the controls.
    box = robots.bounding_box()
    assert box is not None
    assert box["y"] + box["height"] <= 844
    first_control = page.locator("fieldset.type").first.bounding_box()
    assert first_control is not None
    assert box["y"] < first_control["y"]
    # Scrolled to the last control, one link brings the totals back.
    page.locator("#update").scroll_into_view_if_needed()
    expect(robots).not_to_be_in_viewport()
    page.get_by_role("link", name="Totals", exact=True).click()
    expect(robots).to_be_in_viewport()
    selection = urlsplit(page.url).query.split("#")[0]
    for path in ("/", "/map", "/configurations", "/designs", "/export"):
        page.goto(f"{server.base.rstrip('/')}{path}?{selection}")
        expect(page.locator("main")).to_be_visible()
        assert page.evaluate("document.documentElement.scrollWidth") <= 390, path
        clipped = page.evaluate(
            "[...document.querySelectorAll('caption')]"
            ".filter((c) => c.scrollWidth > c.clientWidth + 1).map((c) => c.textContent)"
        )
        assert clipped == [], path


def test_on_a_phone_the_totals_link_covers_no_what_if_suggestion(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.set_viewport_size({"width": 390, "height": 844})
    page.goto(server.url)
    suggestions = page.locator("#whatif li")
    expect(suggestions).to_have_count(10)
    link = page.get_by_role("link", name="Totals", exact=True)
    for where in ("#whatif li:last-child", "body"):
        # Scrolled as far as it goes (the item to the screen's bottom; the page to its end).
        page.locator(where).evaluate("(e) => e.scrollIntoView({block: 'end'})")
        last = suggestions.last.bounding_box()
        covering = link.bounding_box()
        assert last is not None
        assert covering is not None
        assert last["y"] + last["height"] <= covering["y"], where


def test_layouts_of_more_configurations_than_may_be_written_say_why_before_any_wait(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    # 1 type x 10 motion controls x 100 sensor types (100 groups of one) x 1..5 sensors (5
    # arrangements): 5,000 configurations, and the default's layout: 5,001 files.
    scale = Scale(types=1, motions=10, sensors=100, groups=100, counts=5, arrangements=5)
    scale.team(tmp_path)
    server = start_studio(str(tmp_path / "team.yaml"))
    page.goto(server.url)
    expect(page.locator("#total-configurations")).to_have_text("5000")
    page.get_by_role("link", name="Export").click()
    refused = page.locator("#export-layouts-refused")
    expect(refused).to_contain_text("5001 files to write")
    expect(refused).to_contain_text("at most 2000")
    expect(page.locator("#export-layouts")).to_have_count(0)
    # Asked for anyway, the zip is refused with the same reason (422, located).
    query = urlsplit(page.url).query
    status, body = server.get(f"/api/layouts.zip?{query}")
    assert status == 422
    assert "5001 files to write" in body.decode()
    # One motion control and at most one sensor: 100 configurations, offered.
    page.goto(server.at("/export?rules=start&type=T0&T0.motion_control=M0&T0.sensor_count.max=1"))
    expect(page.locator("#export-layouts")).to_be_visible()
    expect(page.locator("#export-layouts-refused")).to_have_count(0)


def test_the_articles_cases_and_every_shipped_team_are_one_click_from_the_top(
    studio: Server, page: Page
) -> None:
    page.goto(studio.url)
    starts = page.locator("nav.starts")
    top = starts.bounding_box()
    controls = page.locator("fieldset.type").first.bounding_box()
    assert top is not None
    assert controls is not None
    assert top["y"] < controls["y"]
    shipped = sorted((ROOT / "rules" / "teams").glob("*.yaml"))
    expect(starts.locator("a")).to_have_count(len(shipped))
    starts.get_by_role("link", name="Case 1", exact=True).click()
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(page.locator("#total-configurations")).to_have_text("6")
    # A team under another rule set: one click too, the rule set with it.
    marine = json.loads(run_cli("solve", "marine-survey", "--format", "json").stdout)["totals"]
    page.locator("nav.starts").get_by_role("link", name="Marine survey (example)").click()
    expect(page.get_by_label("Rule set", exact=True)).to_have_value("marine")
    expect(page.locator("#total-robots")).to_have_text(str(marine["valid_robots"]))
    expect(page.locator("#total-configurations")).to_have_text(str(marine["ui_configurations"]))


def test_a_type_ticked_starts_from_a_small_selection_and_says_which(
    studio: Server, page: Page, tmp_path: Path
) -> None:
    page.goto(studio.url)
    page.locator("legend").get_by_label("Humanoid", exact=True).check()
    note = page.locator('fieldset.type[data-type="Humanoid"] .start-note')
    expect(note).to_contain_text("Started from a small selection: motion_control ")
    found = re.fullmatch(
        r"Started from a small selection: motion_control (.+); sensor_type (.+); "
        r"sensor_count 1\.\.(\d+)\. Tick more values to widen it\.",
        note.inner_text(),
    )
    assert found is not None, note.inner_text()
    motion, sensor, most = found.groups()
    # What the page counts is what the command line counts for those values.
    team = tmp_path / "small.yaml"
    team.write_text(
        f"team:\n  Humanoid:\n    motion_control: [{motion}]\n    sensor_type: [{sensor}]\n"
        f"    sensor_count: {most}\n",
        encoding="utf-8",
    )
    data = json.loads(run_cli("solve", team, "--format", "json").stdout)
    expect(page.locator("#total-robots")).to_have_text(str(data["totals"]["valid_robots"]))
    assert data["totals"]["valid_robots"] <= int(most)
    # Every type of the article's rules, in full, counts far more.
    every = json.loads(run_cli("count", "rules/paper.yaml", "--format", "json").stdout)
    assert data["totals"]["valid_robots"] < every["totals"]["valid_robots"] / 100


def test_configurations_open_compare_and_a_robot_is_looked_up(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.goto(server.url)
    page.get_by_role("link", name="Configurations").click()
    table = page.locator("#configurations")
    expect(table.locator("tbody tr")).to_have_count(50)
    expect(table.locator("tbody tr").first).to_contain_text("visual display")

    # Open one: its components and the robots it serves.
    table.get_by_role("link", name="2", exact=True).click()
    expect(page.locator("h2#configuration-title")).to_have_text("UI configuration 2 (UAV)")
    expect(page.locator("#components")).to_contain_text("spherical display: 360 Camera")
    expect(page.locator("#robots tbody tr")).to_have_count(5)

    # Compare two: the sensor presentation differs, the kinematic type does not.
    page.get_by_role("link", name="Configurations").click()
    page.get_by_label("First").fill("1")
    page.get_by_label("Second").fill("4")
    page.get_by_role("button", name="Compare").click()
    rows = page.locator("#comparison tbody tr")
    expect(rows.filter(has_text="Robot Motion Control")).to_contain_text("differs")
    # By the names the rules give: "UAV", not the internal "kinematic_type" and "UAV: UAV".
    expect(rows.filter(has_text="Robot Kinematic Type")).to_have_text(
        re.compile(r"^\s*Robot Kinematic Type\s*UAV\s*UAV\s*same\s*$")
    )

    # Look up a robot, as `teleop-ui assign` does.
    page.get_by_role("link", name="Robots").click()
    page.get_by_label("Robot Kinematic Type").select_option("UGV")
    page.get_by_label("Robot Motion Control").select_option("Driving")
    page.get_by_label("Sensor Type").select_option("LIDAR")
    page.get_by_label("No. of Sensors").select_option("12")
    page.get_by_role("button", name="Look up").click()
    answer = page.locator("#answer")
    expected = json.loads(
        run_cli(
            "assign",
            "--team",
            "case3",
            "kinematic_type=UGV",
            "motion_control=Driving",
            "sensor_type=LIDAR",
            "sensor_count=12",
            "--format",
            "json",
        ).stdout
    )
    expect(answer.locator("h2")).to_have_text(
        f"Default UI configuration {expected['configuration']}"
    )
    expect(answer).to_contain_text(expected["reasons"][0])
    expect(page.locator("#why")).to_contain_text("point cloud")


def test_the_example_robots_uploaded_are_identified_and_made_a_team(
    studio: Server, page: Page, tmp_path: Path
) -> None:
    # The robots' files (examples/ also holds a rule set, profile and team of its own).
    examples = sorted(p for p in (ROOT / "examples").iterdir() if p.suffix in (".urdf", ".srdf"))
    page.goto(studio.at("/?rules=paper&name=The+team+before&type=UAV"))
    page.get_by_role("link", name="Fleet", exact=True).click()
    page.get_by_label("Robot descriptions").set_input_files(examples)
    page.get_by_role("button", name="Identify").click()
    fleet = page.locator("#fleet")
    expect(page.locator("#robots-title")).to_have_text("3 identified, 0 not")
    expect(fleet.locator("tr", has_text="quadrotor").first).to_contain_text("UAV")
    expect(fleet.locator("tr", has_text="diff_drive_lidar").first).to_contain_text("UGV")
    expect(fleet.locator("tr", has_text="arm_gripper").first).to_contain_text("Manipulator")
    # The arm has no sensor, and the rules cannot say "none": the page says what it takes.
    expect(page.locator("#narrowed")).to_contain_text(
        "arm_gripper (Manipulator): no Sensor Type identified"
    )
    expect(page.locator("#narrowed")).to_contain_text("Sensor Type 2D Camera, not every value")

    page.get_by_role("button", name="Make a team from these robots").click()
    expect(page.locator("#team-name")).to_have_value(
        "Fleet: arm_gripper, diff_drive_lidar, quadrotor"
    )
    # What the robots have (the arm: its two motion controls, and the smallest sensor
    # selection the rules allow, not all ten sensor types and 1..50 sensors), solved by the
    # command line.
    written = tmp_path / "fleet.yaml"
    written.write_text(
        "name: robots\nteam:\n"
        "  UAV: {motion_control: [Flight], sensor_type: [2D Camera], sensor_count: 1}\n"
        "  UGV: {motion_control: [Driving, Waypoint], sensor_type: [LIDAR], sensor_count: 1}\n"
        "  Manipulator: {motion_control: [Joint, End Effector], sensor_type: [2D Camera],"
        " sensor_count: 1}\n",
        encoding="utf-8",
    )
    expected = json.loads(run_cli("solve", written, "--format", "json").stdout)["totals"]
    expect(page.locator("#total-robots")).to_have_text(str(expected["valid_robots"]))
    expect(page.locator("#total-configurations")).to_have_text(str(expected["ui_configurations"]))
    # ... and it is a selection like any other, to edit.
    group = page.locator('fieldset[data-key="UAV.motion_control"]')
    expect(group.get_by_label("Flight", exact=True)).to_be_checked()
    group.get_by_label("Waypoint", exact=True).check()
    expect(page.locator("#change")).to_contain_text("+1 configuration")


BOMB = """<?xml version="1.0"?>
<!DOCTYPE robot [
  <!ENTITY a "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa">
  <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
  <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
  <!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">
]>
<robot name="&d;"><link name="base"/></robot>
"""


def test_a_hostile_urdf_is_a_located_failure_and_the_next_request_is_served(
    studio: Server, page: Page, tmp_path: Path
) -> None:
    bomb = tmp_path / "bomb.urdf"
    bomb.write_text(BOMB, encoding="utf-8")
    good = ROOT / "examples" / "quadrotor.urdf"
    page.goto(studio.at("fleet"))
    page.get_by_label("Robot descriptions").set_input_files([bomb, good])
    page.get_by_role("button", name="Identify").click()
    expect(page.locator("#robots-title")).to_have_text("1 identified, 1 not")
    failed = page.locator("#fleet tr.failed")
    expect(failed).to_contain_text("bomb.urdf:")
    expect(failed).to_contain_text("entit")
    expect(failed).not_to_contain_text(str(tmp_path))
    # A file larger than the readers' limit is refused before it is read.
    status, body = studio.request(
        "POST",
        "/api/identify",
        *_multipart("file", "huge.urdf", b"<robot>" + b" " * (16 * 1024 * 1024 + 1)),
    )
    assert status == 422
    assert json.loads(body)["faults"][0]["file"] == "huge.urdf"
    page.goto(studio.url)
    expect(page.locator("#change")).to_contain_text("No kinematic type selected yet")


def test_a_malformed_rule_file_uploaded_is_shown_with_its_line_and_the_studio_goes_on(
    studio: Server, page: Page, tmp_path: Path
) -> None:
    bad = tmp_path / "my-rules.yaml"
    bad.write_text(
        "name: mine\ncharacteristics:\n  kinematic_type:\n    values: [UAV, UAV]\n"
        "  sensor_count:\n    range: [1, 50]\n",
        encoding="utf-8",
    )
    page.goto(studio.url)
    page.locator("legend").get_by_label("UAV", exact=True).check()  # a selection under way
    page.get_by_label("Team name").fill("Mine")
    page.get_by_label("Team name").press("Enter")
    expect(page.locator("#context-team")).to_have_text("Mine")
    expect(page.locator("#total-robots")).not_to_have_text("0")  # the tick has been counted
    edited = totals(page)
    page.get_by_label("Upload a rule set").set_input_files(bad)
    page.get_by_role("button", name="Upload rule set").click()
    faults = page.locator("#faults")
    expect(faults).to_contain_text("my-rules.yaml:4:")
    expect(faults).to_contain_text("duplicate value 'UAV'")
    expect(faults).to_contain_text("my-rules.yaml:6:")
    expect(faults).not_to_contain_text(str(tmp_path))
    # The way back leads to the selection under way, which the page still names.
    expect(page.locator("#context-team")).to_have_text("Mine")
    page.get_by_role("link", name="back to the selection").click()
    expect(page.get_by_label("Team name")).to_have_value("Mine")
    expect(page.locator("#total-robots")).to_have_text(edited[0])
    # The next request is served, and a good rule set can still be uploaded and used.
    good = tmp_path / "good.yaml"
    good.write_text(
        "name: two robots\ncharacteristics:\n  kinematic_type:\n    values: [UAV, UGV]\n"
        "  sensor_count:\n    range: {min: 1, max: 4}\n",
        encoding="utf-8",
    )
    page.goto(studio.url)
    page.get_by_label("Upload a rule set").set_input_files(good)
    page.get_by_role("button", name="Upload rule set").click()
    expect(page.get_by_label("Rule set", exact=True)).to_contain_text("two robots")
    page.locator("legend").get_by_label("UGV", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("1")  # started small: 1 sensor
    most = page.locator('fieldset[data-key="UGV.sensor_count"]').get_by_label("Most")
    most.focus()
    most.press("End")
    expect(page.locator("#total-robots")).to_have_text("4")
    expect(page.locator("#total-configurations")).to_have_text("4")


def _multipart(field: str, name: str, data: bytes) -> tuple[bytes, dict[str, str]]:
    boundary = "studio-test-boundary"
    body = (
        (
            f'--{boundary}\r\nContent-Disposition: form-data; name="{field}"; '
            f'filename="{name}"\r\nContent-Type: application/octet-stream\r\n\r\n'
        ).encode()
        + data
        + f"\r\n--{boundary}--\r\n".encode()
    )
    return body, {"content-type": f"multipart/form-data; boundary={boundary}"}


# Every control a person can operate, and whether it has a name a screen reader says.
CONTROLS = """() => {
  const controls = [...document.querySelectorAll(
    "a[href], button, input:not([type=hidden]), select, textarea, [tabindex='0']")]
    .filter((e) => !e.matches(":disabled") && !e.closest("[hidden]") && e.getClientRects().length);
  controls.forEach((e, i) => { e.dataset.control = String(i); });
  const named = (e) => {
    if (e.matches("a, button")) { return e.textContent.trim() !== ""; }
    if (e.matches("pre")) { return true; }
    // A chart's value (an SVG group) has no labels: its aria-label names it.
  return (e.labels ? e.labels.length > 0 : false) || e.hasAttribute("aria-label");
  };
  return controls.map((e) => ({ index: e.dataset.control, named: named(e),
                                 what: e.outerHTML.slice(0, 120) }));
}"""


def tab_order(page: Page, limit: int) -> list[str]:
    """The controls Tab reaches, in order, once round (``data-control`` indices)."""
    page.locator("body").focus()
    reached: list[str] = []
    for _ in range(limit):
        page.keyboard.press("Tab")
        index = page.evaluate("() => document.activeElement.dataset.control || ''")
        if index in reached:
            break
        if index:
            reached.append(index)
    return reached


def test_every_control_of_every_view_is_reached_by_keyboard_and_labelled(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.goto(server.url)
    query = urlsplit(page.url).query
    for path in (
        "/",
        "/configurations",
        "/configurations/7",
        "/configurations/103",
        "/map",
        "/robots",
        "/charts",
        "/check",
        "/rules/source",
        "/fleet",
        "/export",
        "/designs",
        "/api",
    ):
        page.goto(f"{server.base.rstrip('/')}{path}?{query}")
        if path == "/":
            # What-if arrives after the page's load (its Apply links are controls too).
            expect(page.locator("#whatif-section")).to_have_attribute("data-state", "answered")
            # ... and the radar chart (its values are stops of the keyboard).
            expect(page.locator("form[data-selection]")).to_have_attribute(
                "data-settled", re.compile(".")
            )
        controls = page.evaluate(CONTROLS)
        assert [c["what"] for c in controls if not c["named"]] == [], path
        reached = tab_order(page, len(controls) + 10)
        assert sorted(reached, key=int) == [c["index"] for c in controls], path


def test_a_change_and_its_undo_are_made_with_the_keyboard_alone(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case1")
    page.goto(server.url)
    expect(page.locator("#total-robots")).to_have_text("30")
    waypoint = page.locator('fieldset[data-key="UAV.motion_control"]').get_by_label(
        "Waypoint", exact=True
    )
    page.locator("body").focus()
    for _ in range(200):
        page.keyboard.press("Tab")
        if waypoint.evaluate("(e) => e === document.activeElement"):
            break
    page.keyboard.press("Space")
    expect(page.locator("#total-robots")).to_have_text("15")
    undo = page.get_by_role("button", name="Undo")
    for _ in range(200):
        page.keyboard.press("Tab")
        if undo.evaluate("(e) => e === document.activeElement"):
            break
    page.keyboard.press("Enter")
    expect(page.locator("#total-robots")).to_have_text("30")
    expect(waypoint).to_be_checked()


def test_values_the_rules_exclude_are_shown_disabled_with_the_reason(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("rules/extended.yaml")
    page.goto(server.url)
    page.locator("legend").get_by_label("UAV", exact=True).check()
    walking = page.locator('fieldset[data-key="UAV.motion_control"]').get_by_label(
        "Walking", exact=True
    )
    expect(walking).to_be_disabled()
    expect(walking).not_to_be_checked()  # not in the team: shown as excluded, not ticked
    # Described by why it is excluded (and by the check's findings about it, none here).
    described = (walking.get_attribute("aria-describedby") or "").split()
    why = page.locator(f"#{described[0]}")
    expect(why).to_have_text(
        "excluded by 'Walking is for legged robots' (rules/extended.yaml:60:5)"
    )
    expect(page.locator(f"#{described[1]}")).to_be_empty()
    flight = page.locator('fieldset[data-key="UAV.motion_control"]').get_by_label(
        "Flight", exact=True
    )
    expect(flight).to_be_enabled()


# The smallest text of the radar chart beside the totals, in CSS pixels as the page shows it.
RADAR_TEXT_PX = """(svg) => {
  const scale = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
  const sizes = [...svg.querySelectorAll("text")].map(
    (text) => parseFloat(text.getAttribute("font-size")) * scale);
  return sizes.length ? Math.min(...sizes) : 0;
}"""


def test_the_radar_beside_the_totals_reads_at_a_desk_and_on_a_phone_and_says_each_value(
    start_studio: StartStudio, page: Page
) -> None:
    server = start_studio("case3")
    page.set_viewport_size({"width": 1280, "height": 800})
    page.goto(server.url)
    form = page.locator("form[data-selection]")
    expect(form).to_have_attribute("data-settled", re.compile("."))
    radar = page.locator("#radar svg")
    assert radar.evaluate(RADAR_TEXT_PX) >= 11

    # The keyboard reaches each type's values on each spoke and each legend entry, and the
    # page says the one it is on (4 types x 4 spokes, 4 legend entries).
    said: dict[str, str] = {}
    for _ in range(400):  # from the top of the page, past the selection's controls
        page.keyboard.press("Tab")
        label = page.evaluate(
            "() => document.activeElement.closest('#radar') ? "
            "document.activeElement.getAttribute('aria-label') : null"
        )
        if label is None and said:
            break
        if label is not None:
            expect(page.locator("#radar-value")).to_have_text(label)
            said[label] = label
    assert len(said) == 20
    assert "UAV: Robot Motion Control: Flight, Waypoint" in said
    assert "Humanoid: No. of Sensors: 1..25" in said
    assert "Mobile Manipulator: 312 valid robots, 48 UI configurations" in said
    # The pointer too: over a legend entry, its type's counts.
    page.get_by_role("img", name="UGV: 80 valid robots, 12 UI configurations").hover()
    expect(page.locator("#radar-value")).to_have_text("UGV: 80 valid robots, 12 UI configurations")

    # On a phone the chart keeps its size, in a frame of its own that scrolls sideways.
    page.set_viewport_size({"width": 390, "height": 844})
    assert radar.evaluate(RADAR_TEXT_PX) >= 11
    assert page.evaluate("() => document.documentElement.scrollWidth") <= 390


def test_the_radar_chart_is_redrawn_for_the_new_selection_and_an_export_reads_back(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    server = start_studio("case2")
    page.goto(server.url)
    figure = page.locator("#radar-figure")
    expect(figure).to_have_attribute("data-query", re.compile("UGV.sensor_count.max=10"))
    page.locator('fieldset[data-key="UGV.sensor_type"]').get_by_label(
        "Speaker", exact=True
    ).uncheck()
    # UGV: 2 motion controls x 3 sensor types x 10 counts (Microphone keeps audio).
    expect(page.locator("#total-robots")).to_have_text("90")
    expect(figure).not_to_have_attribute("data-query", re.compile("UGV.sensor_type=Speaker"))
    expect(figure).to_have_attribute("data-state", "drawn")
    robots = page.locator("#total-robots").inner_text()
    configurations = page.locator("#total-configurations").inner_text()
    expect(page.locator("#radar svg > title")).to_have_text(
        f"Case 2: {robots} valid robots, {configurations} UI configurations"
    )
    chosen = parse_qsl(urlsplit(page.url).query)

    # The exported file, imported again, is the same selection.
    page.get_by_role("link", name="Export").click()
    with page.expect_download() as download:
        page.get_by_role("link", name="Team YAML").click()
    exported = tmp_path / "team.yaml"
    download.value.save_as(exported)
    assert "  UGV:   # 60 valid robots, 12 UI configurations\n" in exported.read_text(
        encoding="utf-8"
    )
    page.get_by_role("link", name="Selection").click()
    page.get_by_label("Import a team file").set_input_files(exported)
    page.get_by_role("button", name="Import team").click()
    expect(page.locator("#total-robots")).to_have_text("90")
    assert sorted(parse_qsl(urlsplit(page.url).query)) == sorted(chosen)


GAPPY_RULES = """\
name: Gappy rules
characteristics:
  kinematic_type:
    label: Kind
    values: [Rover, Drone]
  sensor_type:
    label: Sensor Type
    values: [Camera, Lidar, Sonar]
    components:
      - {name: video, values: [Camera]}
      - {name: ranges, values: [Lidar]}
  sensor_count:
    label: Sensors
    range: {min: 1, max: 4}
"""


def test_check_findings_are_shown_at_the_values_they_concern_as_the_selection_changes(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    rules = tmp_path / "gappy.yaml"
    rules.write_text(GAPPY_RULES, encoding="utf-8")
    # What the command line's linter says about the rule set alone.
    checked = json.loads(run_cli("check", rules, "--format", "json").stdout)
    (gap,) = [f for f in checked["findings"] if f["check"] == "coverage-gap"]
    assert "Sonar" in gap["message"]

    server = start_studio(str(rules))
    page.goto(server.url)
    sonar = page.locator('fieldset[data-key="Rover.sensor_type"] li').filter(
        has=page.get_by_label("Sonar", exact=True)
    )
    # Before any type is included: the rule set's finding, at Sonar, in every type.
    for kind in ("Rover", "Drone"):
        here = page.locator(f'fieldset[data-key="{kind}.sensor_type"] li').filter(
            has=page.get_by_label("Sonar", exact=True)
        )
        expect(here.locator(".finding.error")).to_contain_text(f"coverage-gap {gap['message']}")
    described = sonar.get_by_label("Sonar", exact=True).get_attribute("aria-describedby") or ""
    expect(page.locator(f"#{described.split()[-1]}")).to_contain_text("coverage-gap")

    # Including Rover starts small (its first sensor type, one sensor); every value ticked
    # leaves its sensor types open: Sonar is selected and served by nothing, which the check
    # locates at the type.
    page.locator("legend").get_by_label("Rover", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("1")  # Camera, one sensor
    for value in ("Lidar", "Sonar"):
        page.locator('fieldset[data-key="Rover.sensor_type"]').get_by_label(
            value, exact=True
        ).check()
    most = page.locator('fieldset[data-key="Rover.sensor_count"]').get_by_label("Most")
    most.focus()
    most.press("End")
    expect(page.locator("#total-robots")).to_have_text("12")  # 3 sensor types x 4 counts
    rover = page.locator("#type-1-findings")
    expect(rover.locator(".finding.warning")).to_contain_text(
        "team-uncovered-value Rover leaves sensor_type open, so it selects sensor_type 'Sonar'"
    )
    # Camera unticked, the selection lists Sonar: the finding moves to Sonar's control.
    page.locator('fieldset[data-key="Rover.sensor_type"]').get_by_label(
        "Camera", exact=True
    ).uncheck()
    expect(page.locator("#total-robots")).to_have_text("8")
    uncovered = sonar.locator(".finding.warning")
    expect(uncovered).to_contain_text("team-uncovered-value Rover selects sensor_type 'Sonar'")
    expect(uncovered.locator("a.where")).to_have_text("<selection>: team.Rover.sensor_type[1]")
    expect(rover.locator(".finding")).to_have_count(0)
    # Unticked, the selection's finding goes; the rule set's stays.
    sonar.get_by_label("Sonar", exact=True).uncheck()
    expect(page.locator("#total-robots")).to_have_text("4")
    expect(uncovered).to_have_count(0)
    expect(sonar.locator(".finding.error")).to_contain_text("coverage-gap")
    # The selection's finding links to the Check page; the rule set's to its line.
    sonar.get_by_label("Sonar", exact=True).check()
    expect(uncovered).to_have_count(1)
    uncovered.locator("a.where").click()
    expect(page.locator(":target")).to_contain_text("team-uncovered-value")
    page.go_back()
    page.locator('fieldset[data-key="Rover.sensor_type"] li').filter(
        has=page.get_by_label("Sonar", exact=True)
    ).locator(".finding.error a.where").click()
    assert page.url.endswith(f"#L{gap['line']}")
    expect(page.locator(":target")).to_contain_text("values: [Camera, Lidar, Sonar]")


def test_the_chart_says_it_is_being_redrawn_until_it_shows_the_new_selection(
    start_studio: StartStudio, page: Page
) -> None:
    from xml.etree import ElementTree

    from playwright.sync_api import Route

    server = start_studio("case3")
    page.goto(server.url)
    form = page.locator("form[data-selection]")
    figure = page.locator("#radar-figure")
    expect(form).to_have_attribute("data-settled", re.compile("."))
    expect(figure).to_have_attribute("data-state", "drawn")

    held: list[Route] = []
    released = False

    def hold(route: Route) -> None:
        if released:
            route.continue_()
        else:
            held.append(route)

    page.route("**/api/charts/panel.svg?*", hold)
    page.locator('fieldset[data-key="Humanoid.motion_control"]').get_by_label(
        "Walking", exact=True
    ).uncheck()
    expect(page.locator("#total-robots")).to_have_text("722")
    # The totals answered; the chart has not: it says so, and the page is not settled.
    expect(figure).to_have_attribute("data-state", "stale")
    expect(figure).to_have_attribute("aria-busy", "true")
    expect(page.locator("#radar-state")).to_have_text("Redrawing the chart for this selection…")
    assert form.get_attribute("data-settled") is None
    # Let it through (one not held yet goes straight on).
    released = True
    for route in held:
        route.continue_()
    expect(figure).to_have_attribute("data-state", "drawn")
    expect(figure).to_have_attribute("aria-busy", "false")
    expect(page.locator("#radar-state")).to_have_text("")
    current = form.get_attribute("data-current")
    expect(form).to_have_attribute("data-settled", current or "")
    assert figure.get_attribute("data-query") == current
    # The chart drawn is the selection's: its title gives the totals the page shows.
    status, svg = server.get(f"/api/charts/radar.svg?{current}")
    assert status == 200
    title = ElementTree.fromstring(svg).findtext("{http://www.w3.org/2000/svg}title")
    assert title == "Case 3: 722 valid robots, 90 UI configurations"
    expect(page.locator("#radar svg > title")).to_have_text(title)
    expect(page.locator("#total-configurations")).to_have_text("90")


def test_a_rule_set_too_large_to_draw_whole_is_shown_a_type_at_a_time_and_keeps_the_rest(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    from solver.studio.pages import MAX_PAGE_CONTROLS

    # 30 types of 1,000 values, each value a component of its own: 30,000 value controls.
    values = ", ".join(f"v{i}" for i in range(1000))
    types = ", ".join(f"T{i}" for i in range(30))
    rules = tmp_path / "wide.yaml"
    rules.write_text(
        f"name: wide\ncharacteristics:\n  kind: {{values: [{types}]}}\n"
        f"  c: {{values: [{values}]}}\n",
        encoding="utf-8",
    )
    assert MAX_PAGE_CONTROLS < 30 * 1000
    server = start_studio(str(rules))
    # T1 keeps one value; the page, too large for every type, draws T0 alone.
    page.goto(server.at("?rules=start&type=T0&type=T1&T1.c=v7"))
    expect(page.locator("#total-robots")).to_have_text("1001")
    expect(page.locator('fieldset.type[data-type="T0"] fieldset.characteristic')).to_have_count(1)
    expect(page.locator('fieldset.type[data-type="T1"] fieldset.characteristic')).to_have_count(0)
    page.locator('fieldset[data-key="T0.c"]').get_by_label("v3", exact=True).uncheck()
    # T0 lost one value; T1's one value, not drawn, travelled on with the change.
    expect(page.locator("#total-robots")).to_have_text("1000")
    expect(page.locator("#total-configurations")).to_have_text("1000")
    assert ("T1.c", "v7") in parse_qsl(urlsplit(page.url).query)


def test_the_api_page_renders_the_openapi_document_as_a_page(studio: Server) -> None:
    status, body = studio.get("/api")
    html = body.decode()
    assert status == 200
    assert '"openapi"' not in html  # not the document as text
    document = studio.json("/openapi.json")
    # Every path of the document has its section, with its summary, parameters and answers.
    sections = {
        re.search(r"<code>([^<]*)</code>", part).group(1): part  # type: ignore[union-attr]
        for part in html.split('<section class="endpoint"')[1:]
    }
    assert set(sections) == set(document["paths"])
    for path, methods in document["paths"].items():
        section = sections[path]
        for operation in methods.values():
            if "summary" in operation:
                assert str(escape(operation["summary"])) in section, path
            for code in operation.get("responses", {}):
                assert f"<dt>{code}</dt>" in section, path
            for parameter in operation.get("parameters", []):
                assert f"<code>{parameter['name']}</code>" in section, path
    # Backticks of the descriptions are code, not backticks.
    assert "`" not in html
