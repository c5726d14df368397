"""Designs kept as files and shared: a team exported or saved in the studio solves on another
machine (a shipped rule set named by its name), and a folder of designs (``--designs DIR``)
is listed, saved into, reopened, compared and deleted from the page, refusing what is no
design. The expected counts are the command line's for the same files, never the studio's own.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from tests.conftest import ROOT, run_cli
from tests.studio.conftest import Server, StartStudio

# A team under the shipped extended rules (not the article's): a drone and a rover.
EXTENDED = (
    "?rules=extended&name=Shared&type=UAV&UAV.motion_control=Flight"
    "&UAV.sensor_type=2D+Camera&UAV.sensor_type=Thermal+Camera&UAV.sensor_type=LIDAR"
    "&UAV.sensor_count.max=3&type=UGV&UGV.motion_control=Driving&UGV.sensor_count.max=2"
)


def solved_totals(path: Path) -> tuple[int, int]:
    answer = run_cli("solve", path, "--format", "json")
    assert answer.returncode == 0, answer.stderr
    totals = json.loads(answer.stdout)["totals"]
    return totals["valid_robots"], totals["ui_configurations"]


def test_an_exported_team_names_its_shipped_rule_set_and_solves_in_another_folder(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    server = start_studio()
    page.goto(server.at(EXTENDED))
    robots = page.locator("#total-robots")
    expect(robots).not_to_have_text("")
    shown = (int(robots.inner_text()), int(page.locator("#total-configurations").inner_text()))

    page.get_by_role("link", name="Export").click()
    with page.expect_download() as download:
        page.get_by_role("link", name="Team YAML").click()
    exported = tmp_path / "here" / "shared.yaml"
    exported.parent.mkdir()
    download.value.save_as(exported)
    text = exported.read_text(encoding="utf-8")
    assert "\nrules: extended\n" in text
    assert [line for line in text.splitlines() if line.startswith("rules:")] == ["rules: extended"]

    # Copied to a folder with nothing beside it, it solves to the same counts.
    elsewhere = tmp_path / "elsewhere" / "deep"
    elsewhere.mkdir(parents=True)
    copied = Path(shutil.copy(exported, elsewhere / "copy.yaml"))
    assert solved_totals(copied) == shown

    # And a new studio started with it opens the same selection.
    again = start_studio(str(copied))
    other = page.context.new_page()
    other.goto(again.url)
    expect(other.locator("#total-robots")).to_have_text(str(shown[0]))
    other.close()


def page_totals(page: Page) -> tuple[int, int]:
    robots = page.locator("#total-robots")
    expect(robots).not_to_have_text("")
    return int(robots.inner_text()), int(page.locator("#total-configurations").inner_text())


def save_design(page: Page, name: str) -> None:
    page.get_by_role("link", name="Designs", exact=True).click()
    page.get_by_label("Name").fill(name)
    page.get_by_role("button", name="Save design").click()
    expect(page.locator("#saved")).to_have_text(f"Saved as {name}.yaml.")


def test_designs_are_saved_listed_compared_reopened_and_deleted_as_team_files(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    folder = tmp_path / "designs"
    folder.mkdir()
    server = start_studio("--designs", str(folder))
    page.goto(server.at(EXTENDED))
    first = page_totals(page)
    save_design(page, "drone and rover")
    saved = folder / "drone and rover.yaml"
    assert "\nrules: extended\n" in saved.read_text(encoding="utf-8")
    # The saved file, copied elsewhere, solves to the counts the page showed.
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    assert solved_totals(Path(shutil.copy(saved, elsewhere / "x.yaml"))) == first

    # A smaller design: the drone without its thermal camera.
    page.get_by_role("link", name="Selection").click()
    page.locator('fieldset[data-key="UAV.sensor_type"]').get_by_label(
        "Thermal Camera", exact=True
    ).uncheck()
    expect(page.locator("#total-robots")).not_to_have_text(str(first[0]))
    second = page_totals(page)
    save_design(page, "no thermal")
    assert solved_totals(folder / "no thermal.yaml") == second
    expect(page.locator("#designs tbody tr")).to_have_count(2)

    # The change from one to the other: the value removed, and what it did to the counts.
    page.get_by_label("From").select_option("drone and rover")
    page.get_by_label("To").select_option("no thermal")
    page.get_by_role("button", name="Compare designs").click()
    expect(page.locator("#diff-changes")).to_have_text("UAV, sensor_type: removed Thermal Camera")
    expect(page.locator("#diff-robots")).to_have_text(f"{second[0] - first[0]:+d}")
    expect(page.locator("#diff-configurations")).to_have_text(f"{second[1] - first[1]:+d}")

    # Reopened, the first design is the selection again.
    page.get_by_role("link", name="Open drone and rover").click()
    expect(page.locator("#total-robots")).to_have_text(str(first[0]))
    expect(page.locator("#total-configurations")).to_have_text(str(first[1]))

    # Deleted, it is gone from the folder and the list.
    page.get_by_role("link", name="Designs", exact=True).click()
    page.get_by_role("button", name="Delete no thermal").click()
    expect(page.locator("#designs tbody tr")).to_have_count(1)
    assert sorted(p.name for p in folder.iterdir()) == ["drone and rover.yaml"]

    # A new studio on the same folder reopens what was saved.
    again = start_studio("--designs", str(folder))
    other = page.context.new_page()
    other.goto(again.at("/designs/open?design=drone+and+rover"))
    expect(other.locator("#total-robots")).to_have_text(str(first[0]))
    other.close()


TEAM = "name: outside\nteam:\n  UAV: {}\n"


def hostile_folder(tmp_path: Path) -> tuple[Path, Path]:
    """A design folder a stranger filled, and a folder outside it with what must stay
    unread and unchanged."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.yaml").write_text(TEAM, encoding="utf-8")
    (outside / "rules.yaml").write_text(
        (ROOT / "rules" / "paper.yaml").read_text(encoding="utf-8"), encoding="utf-8"
    )
    folder = tmp_path / "designs"
    folder.mkdir()
    (folder / "good.yaml").write_text(TEAM, encoding="utf-8")
    (folder / "line\nbreak.yaml").write_text(TEAM, encoding="utf-8")
    (folder / "\u202eevil.yaml").write_text(TEAM, encoding="utf-8")
    (folder / ".hidden.yaml").write_text(TEAM, encoding="utf-8")
    (folder / "link.yaml").symlink_to(outside / "secret.yaml")
    (folder / "folder.yaml").mkdir()
    (folder / "rules-file.yaml").write_text(
        (ROOT / "rules" / "paper.yaml").read_text(encoding="utf-8"), encoding="utf-8"
    )
    (folder / "noise.yaml").write_bytes(b"\xff\xfe not text")
    (folder / "escape.yaml").write_text(
        "name: escape\nrules: ../outside/rules.yaml\nteam:\n  UAV: {}\n", encoding="utf-8"
    )
    (folder / "absolute.yaml").write_text(
        f"name: absolute\nrules: {outside / 'rules.yaml'}\nteam:\n  UAV: {{}}\n",
        encoding="utf-8",
    )
    return folder, outside


def refusal(server: Server, page: Page, design: str) -> str:
    status, _ = server.get(f"/designs/open?design={design}")
    assert status == 422
    page.goto(server.at(f"/designs/open?design={design}"))
    faults = page.locator("#faults")
    expect(faults).to_contain_text("problem")
    return faults.inner_text()


def test_a_hostile_design_folder_is_refused_entry_by_entry_and_nothing_outside_is_touched(
    start_studio: StartStudio, page: Page, tmp_path: Path
) -> None:
    folder, outside = hostile_folder(tmp_path)
    before = {p.name: p.read_bytes() for p in outside.iterdir()}
    server = start_studio("--designs", str(folder))
    page.goto(server.at("/designs"))
    rows = page.locator("#designs tbody tr")
    listed = {row.locator("th").inner_text(): row.inner_text() for row in rows.all()}
    assert "refused" not in listed["good"]
    # Names the studio would not give a design are listed escaped, never opened.
    refused = "refused: not a name the studio gives a design; not opened"
    for name in ("line\\nbreak.yaml", "\\u202eevil.yaml", ".hidden.yaml"):
        assert refused in listed[name]
    assert "refused: a link" in listed["link"]
    assert "refused: not a regular file" in listed["folder"]

    # Each bad design opened is a located refusal in the page; the studio serves on.
    assert "link.yaml: no design: a link" in refusal(server, page, "link")
    assert "rules-file.yaml:6:1: this is a rule set, not a team file" in refusal(
        server, page, "rules-file"
    )
    assert "noise.yaml: no design: not UTF-8 text" in refusal(server, page, "noise")
    assert "escape.yaml:2:8: rules: rules '../outside/rules.yaml'" in refusal(
        server, page, "escape"
    )
    assert "this studio reads no other path" in refusal(server, page, "absolute")
    assert "is no design name" in refusal(server, page, "..%2Foutside%2Fsecret")
    assert "no such file" in refusal(server, page, "missing")

    # Saving over a link or deleting it never goes through it.
    page.goto(server.at(EXTENDED))
    page.get_by_role("link", name="Designs", exact=True).click()
    page.get_by_label("Name").fill("link")
    page.get_by_role("button", name="Save design").click()
    expect(page.locator("#faults")).to_contain_text("link.yaml: is a link; refused")
    status, _ = server.request(
        "POST",
        "/designs/delete",
        b"design=link",
        {"content-type": "application/x-www-form-urlencoded"},
    )
    assert status == 422
    page.goto(server.at("/designs/open?design=good"))
    expect(page.locator("#total-robots")).not_to_have_text("")
    assert {p.name: p.read_bytes() for p in outside.iterdir()} == before
    assert (folder / "link.yaml").is_symlink()


def test_the_new_views_keep_the_studios_fences(start_studio: StartStudio, tmp_path: Path) -> None:
    import urllib.error
    import urllib.request

    folder = tmp_path / "designs"
    folder.mkdir()
    server = start_studio("case3", "--designs", str(folder))
    query = "?rules=paper&type=UAV"
    for path in ("designs", "api/designs", "map" + query, "api/map" + query, "api/whatif" + query):
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(server.base + path, timeout=60)
        assert refused.value.code == 401, path
    # A save from another site, or with another site's Origin, does nothing.
    form = {"content-type": "application/x-www-form-urlencoded"}
    for headers in ({"sec-fetch-site": "cross-site"}, {"origin": "http://evil.example"}):
        status, _ = server.request("POST", "/designs" + query, b"design=x", {**form, **headers})
        assert status == 403, headers
    assert list(folder.iterdir()) == []
    # From the studio's own page, it saves.
    origin = {"origin": server.base.rstrip("/")}
    status, _ = server.request("POST", "/designs" + query, b"design=x", {**form, **origin})
    assert status == 200  # sent on (303) to the Designs page
    assert [p.name for p in folder.iterdir()] == ["x.yaml"]


def test_a_design_under_the_rule_set_given_at_start_names_it_relative_to_the_folder(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    project = tmp_path / "project"
    (project / "designs").mkdir(parents=True)
    rules = project / "my-rules.yaml"
    rules.write_text(
        (ROOT / "rules" / "paper.yaml")
        .read_text(encoding="utf-8")
        .replace("name: Mortimer et al. 2017", "name: my rules"),
        encoding="utf-8",
    )
    server = start_studio(str(rules), "--designs", str(project / "designs"))
    query = "?rules=start&type=UGV&UGV.motion_control=Driving&UGV.sensor_count.max=3"
    form = {"content-type": "application/x-www-form-urlencoded"}
    origin = {"origin": server.base.rstrip("/")}
    status, _ = server.request("POST", "/designs" + query, b"design=mine", {**form, **origin})
    assert status == 200
    design = project / "designs" / "mine.yaml"
    assert "\nrules: ../my-rules.yaml\n" in design.read_text(encoding="utf-8")
    expected = server.json("/api/solve" + query)["totals"]
    # The project folder moved elsewhere, the design still solves, and reopens.
    moved = Path(shutil.copytree(project, tmp_path / "moved"))
    assert solved_totals(moved / "designs" / "mine.yaml") == (
        expected["valid_robots"],
        expected["ui_configurations"],
    )
    again = start_studio(str(moved / "my-rules.yaml"), "--designs", str(moved / "designs"))
    status, body = again.get("/designs/open?design=mine")
    assert status == 200
    assert f'<td id="total-robots">{expected["valid_robots"]}</td>'.encode() in body


def test_a_design_folder_reached_through_a_link_reopens_a_design_under_the_start_rules(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    # The designer names the folder through a link to the project (a home folder often is);
    # the design's `rules: ../my-rules.yaml` is what `teleop-ui solve` reads through the same
    # link, and the studio that saved it reopens it.
    project = tmp_path / "real" / "project"
    (project / "designs").mkdir(parents=True)
    rules = project / "my-rules.yaml"
    rules.write_text(
        (ROOT / "rules" / "paper.yaml")
        .read_text(encoding="utf-8")
        .replace("name: Mortimer et al. 2017", "name: my rules"),
        encoding="utf-8",
    )
    link = tmp_path / "link"
    link.symlink_to(project, target_is_directory=True)
    server = start_studio(str(link / "my-rules.yaml"), "--designs", str(link / "designs"))
    query = "?rules=start&type=UGV&UGV.motion_control=Driving&UGV.sensor_count.max=3"
    form = {"content-type": "application/x-www-form-urlencoded"}
    origin = {"origin": server.base.rstrip("/")}
    status, _ = server.request("POST", "/designs" + query, b"design=mine", {**form, **origin})
    assert status == 200
    design = link / "designs" / "mine.yaml"
    assert "\nrules: ../my-rules.yaml\n" in design.read_text(encoding="utf-8")
    expected = server.json("/api/solve" + query)["totals"]
    assert solved_totals(design) == (expected["valid_robots"], expected["ui_configurations"])
    status, body = server.get("/designs/open?design=mine")
    assert status == 200, body
    assert f'<td id="total-robots">{expected["valid_robots"]}</td>'.encode() in body


def test_two_designs_under_rule_sets_that_order_the_characteristics_differently_compare_by_name(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    # The same rules with sensor types listed before motion controls: the same selection under
    # each is the same selection, whatever the order.
    paper = (ROOT / "rules" / "paper.yaml").read_text(encoding="utf-8")
    head, rest = paper.split("  motion_control:\n", 1)
    motion, rest = rest.split("  sensor_type:\n", 1)
    sensors, counts = rest.split("  sensor_count:\n", 1)
    reordered = tmp_path / "reordered.yaml"
    reordered.write_text(
        head.replace("name: Mortimer et al. 2017", "name: reordered")
        + "  sensor_type:\n"
        + sensors
        + "  motion_control:\n"
        + motion
        + "  sensor_count:\n"
        + counts,
        encoding="utf-8",
    )
    folder = tmp_path / "designs"
    folder.mkdir()
    team = (
        "team:\n  UGV:\n    motion_control: [Driving]\n    sensor_type: [2D Camera, LIDAR]\n"
        "    sensor_count: 3\n"
    )
    (folder / "under paper.yaml").write_text("name: a\n" + team, encoding="utf-8")
    (folder / "reordered.yaml").write_text(
        "name: b\nrules: ../reordered.yaml\n" + team, encoding="utf-8"
    )
    counts_of = {solved_totals(folder / name) for name in ("under paper.yaml", "reordered.yaml")}
    assert len(counts_of) == 1  # the command line: one and the same selection
    server = start_studio(str(reordered), "--designs", str(folder))
    diff = server.json("/api/designs/diff?a=under+paper&b=reordered")
    assert diff["changes"] == []
    assert diff["change"] == {"valid_robots": 0, "ui_configurations": 0}


def test_a_design_whose_rules_line_names_nothing_is_refused_as_solve_refuses_it(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    folder = tmp_path / "designs"
    folder.mkdir()
    design = folder / "empty rules.yaml"
    design.write_text("name: empty\nrules:\nteam:\n  UAV: {}\n", encoding="utf-8")
    answer = run_cli("solve", design, "--count-only")
    assert answer.returncode == 2
    assert ":2:" in answer.stderr  # the command line: located at the rules line
    server = start_studio("--designs", str(folder))
    status, body = server.get("/designs/open?design=empty+rules")
    assert status == 422
    assert b"empty rules.yaml:2:" in body
    # A design that names no rule set at all is the article's, as for `solve`.
    design.write_text("name: none\nteam:\n  UAV: {}\n", encoding="utf-8")
    assert run_cli("solve", design, "--count-only").returncode == 0
    status, _ = server.get("/designs/open?design=empty+rules")
    assert status == 200
