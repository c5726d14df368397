"""Whether a host names this machine only: one answer for the studio, the watch server and
the ROS 1 client."""

from __future__ import annotations

import subprocess
import sys

import pytest

from solver.addresses import loopback


@pytest.mark.parametrize("host", ["localhost", "127.0.0.1", "127.3.2.1", "::1", "[::1]"])
def test_this_machines_own_names_are_loopback(host: str) -> None:
    assert loopback(host)


@pytest.mark.parametrize(
    "host", ["0.0.0.0", "192.168.1.10", "example.org", "localhost.example.org", "", "[::]"]
)
def test_other_hosts_and_any_address_are_not(host: str) -> None:
    assert not loopback(host)


def test_asking_imports_no_server() -> None:
    code = "import sys, solver.addresses; print(sorted(m for m in sys.modules if 'solver.' in m))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "['solver.addresses', 'solver.lazy']"
