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
