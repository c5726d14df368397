"""Network addresses: whether a host names this machine only.

One definition for every server and client of the tool (the studio's guard, the watch
server's, the ROS 1 master client's), in a module that imports nothing of the project, so
that asking costs no server's imports.
"""

from __future__ import annotations

import ipaddress

__all__ = ["loopback"]


def loopback(host: str) -> bool:
    """Whether ``host`` names this machine only (127.0.0.0/8, ::1, localhost; an IPv6
    address may be written in brackets)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False
