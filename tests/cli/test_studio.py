"""``teleop-ui studio`` as a user runs it: ``--open`` with no browser to open says so and
serves on. (The studio's process, its signals and its private folder: tests/studio.)
"""

from __future__ import annotations

import os
from pathlib import Path

from tests.studio.conftest import StartStudio


def test_open_with_no_browser_to_open_says_so_and_goes_on_serving(
    start_studio: StartStudio,
) -> None:
    # No display, and the only browser Python's webbrowser may try is `false`, which fails.
    environment = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    server = start_studio("case3", "--open", env={**environment, "BROWSER": "false"})
    # The page answers only once the server runs, after the browser was tried and the
    # warning written.
    status, _ = server.get("/")
    assert status == 200
    assert server.stderr.read_text(encoding="utf-8") == (
        "teleop-ui studio: warning: no browser could be opened here: "
        "open the address above in one\n"
    )


def test_a_design_folder_that_is_no_folder_is_a_located_error(tmp_path: Path) -> None:
    from tests.conftest import run_cli

    missing = tmp_path / "nowhere"
    answer = run_cli("studio", "--designs", missing, "--port", "0")
    assert answer.returncode == 2
    assert answer.stderr == f"{missing}: --designs needs a folder (make it first)\n"
    assert not missing.exists()
