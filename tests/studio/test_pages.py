"""The studio's pages in a real browser, used as a designer would: ticking the article's cases,
exporting the team, browsing configurations, looking a robot up, undoing a change.

The expected figures are the article's (Table 2, SPEC.md section 5) and the command line's
answers for the same team files, never the studio's own.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path
from urllib.parse import parse_qsl, urlsplit

from playwright.sync_api import Page, expect

from tests.conftest import run_cli
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
    expect(published).to_contain_text("published: 820 valid robots / 99 UI configurations")
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
    page.goto(f"{studio.base}?{query}")
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
    group.get_by_label("Flight", exact=True).check()
    expect(page.locator("#total-robots")).to_have_text("15")
    expect(page.locator("#faults")).to_be_empty()


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
    expect(rows.filter(has_text="motion_control")).to_contain_text("differs")
    expect(rows.filter(has_text="kinematic_type")).to_contain_text("same")

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
