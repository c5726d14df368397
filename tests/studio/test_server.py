"""The studio's process: it prints an address that answers, and SIGTERM ends it cleanly, its
private folder of uploads removed."""

from __future__ import annotations

import os
import signal
from pathlib import Path

from tests.studio.conftest import StartStudio
from tests.studio.test_pages import _multipart


def test_sigterm_ends_the_studio_with_status_0_and_leaves_no_upload_behind(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    # A temporary folder of the studio's own: other programs' studios on this machine make
    # folders of the same name in the shared one.
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    server = start_studio(env={**os.environ, "TMPDIR": str(temporary)})
    body, headers = _multipart("file", "r.yaml", b"characteristics:\n  t: {values: [a]}\n")
    status, _ = server.request("POST", "/api/rules", body, headers)
    assert status == 200
    made = list(temporary.glob("teleop-ui-studio-*"))
    assert len(made) == 1
    (folder,) = made
    assert folder.stat().st_mode & 0o777 == 0o700
    os.killpg(server.process.pid, signal.SIGTERM)
    assert server.process.wait(timeout=60) == 0
    assert not folder.exists()


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
