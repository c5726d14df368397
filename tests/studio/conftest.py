"""The real studio for the studio's tests: a server process per test, and a real browser.

``start_studio(*args)`` runs ``python -m solver studio ARGS --port 0`` in a process group of its
own and returns once the server has printed its address (a line on stdout: an event, not a
sleep); the fixture ends the whole group afterwards, whatever the test did. ``browser`` is
Debian's headless Chromium driven by Playwright (never a browser Playwright downloads);
``page`` is a fresh tab per test. ``expect`` waits for what the page shows with a generous
ceiling, because the machine may be loaded: no test depends on how fast it answers.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Browser, Page, expect, sync_playwright

from tests.conftest import ROOT

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
# A ceiling on waiting for what a page shows (milliseconds), never a measure of speed.
WAIT_MS = 60_000
expect.set_options(timeout=WAIT_MS)


@dataclass
class Server:
    """A running studio: its address, its process (stderr kept in a file) and the temporary
    folder it was given (``TMPDIR``), where it makes its private folder."""

    url: str
    process: subprocess.Popen[str]
    stderr: Path
    temporary: Path

    @property
    def private(self) -> Path:
        """The studio's private folder."""
        (folder,) = self.temporary.glob(f"teleop-ui-studio-{self.process.pid}-*")
        return folder

    def kept_files(self) -> list[Path]:
        """Every file in the private folder now."""
        return sorted(p for p in self.private.rglob("*") if not p.is_dir())

    def get(self, path: str, headers: dict[str, str] | None = None) -> tuple[int, bytes]:
        return self.request("GET", path, None, headers)

    def request(
        self,
        method: str,
        path: str,
        body: bytes | None = None,
        headers: dict[str, str] | None = None,
    ) -> tuple[int, bytes]:
        request = urllib.request.Request(
            self.base + path.lstrip("/"),
            data=body,
            method=method,
            headers={"authorization": f"Bearer {self.token}", **(headers or {})},
        )
        try:
            with urllib.request.urlopen(request, timeout=120) as response:
                return response.status, response.read()
        except urllib.error.HTTPError as error:
            return error.code, error.read()

    def json(self, path: str) -> Any:
        status, body = self.get(path)
        assert status == 200, body
        return json.loads(body)

    @property
    def base(self) -> str:
        return self.url.split("?")[0]

    @property
    def token(self) -> str:
        """The token the studio printed in its address."""
        return self.url.split("?token=")[1]

    def at(self, path: str) -> str:
        """The address of ``path`` (with its query) with the token, as a person would open it
        after copying the printed address and changing its path."""
        joiner = "&" if "?" in path else "?"
        return f"{self.base}{path.lstrip('/')}{joiner}token={self.token}"


StartStudio = Callable[..., Server]


def studio_process(
    *args: str,
    tmp_path: Path,
    env: dict[str, str] | None = None,
    preexec_fn: Callable[[], None] | None = None,
) -> Server:
    number = len(list(tmp_path.glob("studio-*.err")))
    stderr = tmp_path / f"studio-{number}.err"
    # A temporary folder of the studio's own (unless the test gives one): other studios on this
    # machine make private folders of the same kind in the shared one.
    environment = dict(os.environ if env is None else env)
    if env is None or "TMPDIR" not in env:
        environment["TMPDIR"] = str(tmp_path / f"studio-{number}-tmp")
        Path(environment["TMPDIR"]).mkdir()
    temporary = Path(environment["TMPDIR"])
    with stderr.open("w") as errors:
        process = subprocess.Popen(
            [sys.executable, "-m", "solver", "studio", *args, "--port", "0"],
            cwd=ROOT,
            stdout=subprocess.PIPE,
            stderr=errors,
            text=True,
            start_new_session=True,
            env=environment,
            preexec_fn=preexec_fn,  # noqa: PLW1509 (resource limits of the studio alone)
        )
    assert process.stdout is not None
    line = process.stdout.readline()
    found = re.search(r"(http://\S+)", line)
    if found is None:
        stop(process)
        raise AssertionError(
            f"the studio did not start: {line!r}\n{stderr.read_text(encoding='utf-8')}"
        )
    return Server(found.group(1), process, stderr, temporary)


def stop(process: subprocess.Popen[str]) -> None:
    """End the studio's whole process group: SIGTERM, then SIGKILL if it lingers."""
    if process.poll() is None:
        try:
            os.killpg(process.pid, signal.SIGTERM)
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait(timeout=30)
        except ProcessLookupError:
            pass
    if process.stdout is not None:
        process.stdout.close()


@pytest.fixture
def start_studio(tmp_path: Path) -> Iterator[Callable[..., Server]]:
    started: list[Server] = []

    def start(
        *args: str,
        env: dict[str, str] | None = None,
        preexec_fn: Callable[[], None] | None = None,
    ) -> Server:
        started.append(studio_process(*args, tmp_path=tmp_path, env=env, preexec_fn=preexec_fn))
        return started[-1]

    yield start
    for server in started:
        stop(server.process)
        assert "Traceback" not in server.stderr.read_text(encoding="utf-8")


@pytest.fixture
def studio(start_studio: Callable[..., Server]) -> Server:
    """A studio started with nothing: the article's rules, no type selected."""
    return start_studio()


@pytest.fixture(scope="session")
def browser() -> Iterator[Browser]:
    if shutil.which(CHROMIUM) is None:
        pytest.fail("needs Debian's chromium (/usr/bin/chromium): tools/test.sh installs it")
    with sync_playwright() as playwright:
        found = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield found
        found.close()


@pytest.fixture
def page(browser: Browser) -> Iterator[Page]:
    context = browser.new_context(accept_downloads=True, viewport={"width": 1300, "height": 900})
    context.set_default_timeout(WAIT_MS)
    tab = context.new_page()
    errors: list[str] = []
    tab.on("pageerror", lambda error: errors.append(str(error)))
    yield tab
    context.close()
    assert errors == [], errors
