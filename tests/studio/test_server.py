"""The studio's process: it prints an address that answers, and SIGTERM ends it cleanly, its
private folder of uploads removed."""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest

from tests.studio.conftest import StartStudio
from tests.studio.test_pages import _multipart


def test_sigterm_ends_the_studio_with_status_0_and_leaves_no_upload_behind(
    start_studio: StartStudio,
) -> None:
    server = start_studio()
    body, headers = _multipart("file", "r.yaml", b"characteristics:\n  t: {values: [a]}\n")
    status, _ = server.request("POST", "/api/rules", body, headers)
    assert status == 200
    folder = server.private
    assert folder.stat().st_mode & 0o777 == 0o700
    assert len(server.kept_files()) == 1
    os.killpg(server.process.pid, signal.SIGTERM)
    assert server.process.wait(timeout=60) == 0
    assert not folder.exists()


@pytest.mark.parametrize("signals", [("TERM", "INT"), ("INT", "INT"), ("TERM", "TERM")])
def test_two_signals_back_to_back_still_remove_the_private_folder_without_a_traceback(
    start_studio: StartStudio, signals: tuple[str, str]
) -> None:
    server = start_studio()
    body, headers = _multipart("file", "r.yaml", b"characteristics:\n  t: {values: [a]}\n")
    assert server.request("POST", "/api/rules", body, headers)[0] == 200
    folder = server.private
    for name in signals:
        os.kill(server.process.pid, getattr(signal, f"SIG{name}"))
    # A second signal that comes once the studio has cleaned up may end it as signals do.
    assert server.process.wait(timeout=60) in (0, -signal.SIGTERM, 130)
    assert not folder.exists()
    assert "Traceback" not in server.stderr.read_text(encoding="utf-8")


def test_a_folder_left_by_a_studio_killed_outright_is_removed_by_the_next(
    start_studio: StartStudio, tmp_path: Path
) -> None:
    first = start_studio()
    body, headers = _multipart("file", "r.yaml", b"characteristics:\n  t: {values: [a]}\n")
    assert first.request("POST", "/api/rules", body, headers)[0] == 200
    left = first.private
    os.killpg(first.process.pid, signal.SIGKILL)
    first.process.wait(timeout=60)
    assert left.exists()
    # Another account's folder, or one whose studio still runs, is not touched.
    running = first.temporary / f"teleop-ui-studio-{os.getpid()}-x"
    running.mkdir()
    second = start_studio(env={**os.environ, "TMPDIR": str(first.temporary)})
    assert second.get("/api/count?type=UAV")[0] == 200
    assert not left.exists()
    assert running.exists()


def test_a_request_cut_off_at_shutdown_is_one_line_not_a_traceback() -> None:
    import asyncio
    import logging

    from solver.studio.server import CutOffAtShutdown

    def record(error: BaseException) -> logging.LogRecord:
        return logging.LogRecord(
            "uvicorn.error",
            logging.ERROR,
            "h11_impl.py",
            1,
            "Exception in ASGI application\n",
            (),
            (type(error), error, None),
        )

    cut = record(asyncio.CancelledError("Task cancelled, timeout graceful shutdown exceeded"))
    assert CutOffAtShutdown().filter(cut)
    assert (cut.exc_info, cut.getMessage()) == (
        None,
        "a request still being answered was cut off: the studio stopped",
    )
    fault = record(ValueError("a real fault"))
    CutOffAtShutdown().filter(fault)
    assert fault.exc_info is not None  # anything else keeps its traceback
