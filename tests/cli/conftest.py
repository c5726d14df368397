"""Fixtures the command line's tests share with the live tests (tests/live/conftest.py): the
same fixtures, imported, not copies.

``watch`` and ``assign`` on a real ROS master (tests/cli/test_watch.py, tests/cli/test_assign.py)
share one roscore: ``shared_roscore`` is per test session here (one per pytest-xdist worker that
runs either module), where the live wing's is per module; ``master`` empties it after each
test. ``own_roscore`` is a roscore of the test's own, which it may kill; ``domain`` a DDS domain
of the test's own on loopback, for ``--ros2``; ``start_studio`` a studio process
(tests/studio/conftest.py).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pytest

from tests.live.conftest import domain, master, node, own_roscore, solution, web_server
from tests.live.roscore import Roscore, roscore_available
from tests.live.watching import WatchProcess
from tests.studio.conftest import start_studio

# Imported for pytest, which takes the fixtures a conftest module holds.
__all__ = [
    "domain",
    "master",
    "node",
    "own_roscore",
    "shared_roscore",
    "solution",
    "start_studio",
    "watch_process",
    "web_server",
]


@pytest.fixture(scope="session")
def shared_roscore(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Roscore]:
    if not roscore_available():
        pytest.fail(
            "roscore is not installed: install Debian's ros-core "
            "(tools/test.sh does); the live tests need a real ROS master"
        )
    core = Roscore(tmp_path_factory.mktemp("ros"))
    core.start()
    yield core
    core.kill()


@pytest.fixture
def watch_process() -> Iterator[Callable[..., WatchProcess]]:
    """`teleop-ui watch` processes a test starts, each killed at its end."""
    started: list[WatchProcess] = []

    def start(*args: str, env: dict[str, str] | None = None) -> WatchProcess:
        started.append(WatchProcess(*args, env=env))
        return started[-1]

    yield start
    for process in started:
        process.kill()
