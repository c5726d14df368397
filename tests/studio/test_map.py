"""The configuration map in a real browser: Case 3's configurations as columns (the default
one too), filtered by a component, sorted by the robots served, the default opened, several
compared by the components' names in the rules. Expected figures are the command line's
(`solve --list --format json`)."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Page, expect

from benchmarks.conftest import Scale
from solver import RuleSet
from solver.core.partition import Configuration
from solver.solving import contracts
from solver.studio import service
from solver.studio.selection import query_of
from solver.studio.service import Studio
from solver.studio.workspace import Workspace
from tests.conftest import run_cli
from tests.studio.conftest import StartStudio


def listed(team: str) -> dict[str, Any]:
    answer = run_cli("solve", team, "--list", "--format", "json")
    assert answer.returncode == 0, answer.stderr
    data: dict[str, Any] = json.loads(answer.stdout)
    return data


def test_the_map_of_case_3_has_a_column_per_configuration_and_the_default(
    start_studio: StartStudio, page: Page
) -> None:
    cli = listed("case3")
    server = start_studio("case3")
    page.goto(server.url)
    expect(page.locator("#total-configurations")).to_have_text("102")
    page.get_by_role("link", name="Map", exact=True).click()
    columns = page.locator("#map thead tr").first.locator("th[data-configuration]")
    expect(columns).to_have_count(103)
    assert len(cli["configurations"]) + 1 == 103
    expect(columns.last).to_have_attribute("data-configuration", "103")
    # A row per component the rules name, as the rules name it.
    rows = page.locator("#map tbody tr")
    expect(rows).to_have_count(sum(len(v) for v in cli["default_components"].values()))
    expect(page.locator('#map tr[data-component="sensor_type:audio"] th')).to_have_text(
        "Sensor Type: audio"
    )

    # Filtered by a component: the configurations that have it, and the default (it has all).
    with_audio = [
        c["number"]
        for c in cli["configurations"]
        if any(e["component"] == "audio" for e in c["components"])
    ]
    page.get_by_label("Only configurations with the component").select_option("sensor_type:audio")
    page.get_by_role("button", name="Filter").click()
    expect(columns).to_have_count(len(with_audio) + 1)
    # The caption names the filter as the rows do, by the rules' label.
    expect(page.locator("#map caption")).to_contain_text("with Sensor Type: audio")
    shown = [
        int(n or 0)
        for n in columns.evaluate_all("(cells) => cells.map((cell) => cell.dataset.configuration)")
    ]
    assert shown == [*with_audio, 103]

    # Picked together, configurations are compared by the components' names in the rules.
    first, second = with_audio[0], with_audio[1]
    for number in (first, second, 103):
        page.get_by_label(f"Pick configuration {number}", exact=True).check()
    page.get_by_role("button", name="Compare the picked configurations").click()
    comparison = page.locator("#map-comparison")
    expect(comparison.locator("thead th")).to_have_text(
        ["characteristic", str(first), str(second), "103 (default)", "same?"]
    )
    by_number = {c["number"]: c for c in cli["configurations"]}
    sensors = comparison.locator("tbody tr").nth(2)
    expect(sensors.locator("td").first).to_contain_text(
        by_number[first]["components"][2]["component"]
    )
    expect(sensors.locator("td").nth(2)).to_contain_text("every component: visual display")

    # The default configuration opens like any other.
    page.get_by_role("link", name="Open configuration 103 (the default)").click()
    expect(page.locator("#configuration-title")).to_have_text("The default UI configuration 103")
    expect(page.locator("#components")).to_contain_text("every component: visual display")


def test_the_map_writes_out_only_the_columns_of_the_page_it_shows(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 1 type x 10 motion controls x 100 sensor types (100 groups of one) x 1..5 sensors (5
    # arrangements): 10 x 100 x 5 = 5,000 configurations, and the default one.
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    monkeypatch.setattr(tempfile, "tempdir", None)
    scale = Scale(types=1, motions=10, sensors=100, groups=100, counts=5, arrangements=5)
    folder = tmp_path / "team"
    folder.mkdir()
    team = scale.team(folder)
    workspace = Workspace(start=folder / "team.yaml")
    studio = Studio(workspace)
    pairs = list(query_of(team, "start"))
    written: list[int] = []
    real = contracts.configuration_data

    def spied(rules: RuleSet, configuration: Configuration) -> dict[str, Any]:
        written.append(configuration.number)
        return real(rules, configuration)

    monkeypatch.setattr(service, "configuration_data", spied)
    try:
        last = studio.map_data([*pairs, ("offset", "4600")])
        assert last["total"] == 5001
        assert [c["number"] for c in last["columns"]] == list(range(4601, 5002))
        assert last["columns"][-1]["default"]
        assert sorted(written) == list(range(4601, 5001))

        written.clear()
        # Sensor type group G7 is one of 100: 10 motion controls x 5 arrangements have it.
        filtered = studio.map_data([*pairs, ("component", "sensor_type:G7")])
        assert filtered["total"] == 10 * 5 + 1
        assert len(written) == 10 * 5
        assert all(
            cell == "S7"
            for column in filtered["columns"][:-1]
            for row, cell in zip(filtered["rows"], column["cells"], strict=True)
            if row["component"] == "G7"
        )
    finally:
        workspace.close()


def test_the_map_of_case_3_sorted_by_robots_puts_the_configuration_serving_most_first(
    start_studio: StartStudio, page: Page
) -> None:
    cli = listed("case3")
    robots = {c["number"]: c["valid_robots"] for c in cli["configurations"]}
    # Of those serving the most, the lowest number first (ties keep the numbered order).
    most = min(robots, key=lambda number: (-robots[number], number))
    server = start_studio("case3")
    page.goto(server.url)
    page.get_by_role("link", name="Map", exact=True).click()
    page.get_by_role("link", name="valid robots served (most first)").click()
    expect(page.locator(".map-sort strong")).to_have_text("valid robots served (most first)")
    columns = page.locator("#map thead tr").first.locator("th[data-configuration]")
    expect(columns).to_have_count(len(robots) + 1)
    numbers = [
        int(n or 0)
        for n in columns.evaluate_all("(cells) => cells.map((cell) => cell.dataset.configuration)")
    ]
    counts = [int(t) for t in page.locator("#map thead tr").nth(2).locator("td").all_inner_texts()]
    assert numbers[0] == most
    assert numbers[-1] == cli["default_configuration"]
    assert counts[:-1] == [robots[n] for n in numbers[:-1]]
    assert counts == sorted(counts, reverse=True)
    assert sorted(numbers[:-1]) == sorted(robots)

    # The API answers the same order; an order it does not know is refused, naming those it does.
    query = page.url.split("?", 1)[1]
    api = server.json(f"/api/map?{query}")
    assert [c["number"] for c in api["columns"]] == numbers
    status, body = server.get(f"/api/map?{query.replace('sort=robots', 'sort=biggest')}")
    assert status == 422
    assert "sort by one of number, robots, type" in body.decode()
    page.goto(server.at(f"/map?{query.replace('sort=robots', 'sort=biggest')}"))
    expect(page.locator("main")).to_contain_text("no map order 'biggest'")
