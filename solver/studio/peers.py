"""Which account of this machine is at the other end of a TCP connection (Linux).

Loopback is shared by every account of a machine, and a browser sends a host's cookies to
every port of it: another account's server on 127.0.0.1 that the user visits receives the
studio's cookie. So the studio also asks the kernel who owns the client's socket, as ``ss -e``
does (one ``SOCK_DIAG_BY_FAMILY`` request over netlink for that exact connection: no list of
every socket is read), and serves only its own account.

:func:`account_of` answers ``None`` where it cannot tell: a client on another machine (its
socket is not this kernel's), a system without ``sock_diag`` (not Linux), or a netlink socket
refused. The token alone then decides (:mod:`solver.studio.security`).
"""

from __future__ import annotations

import ipaddress
import os
import socket
import struct

__all__ = ["account_of", "same_account"]

_SOCK_DIAG_BY_FAMILY = 20
_NLM_F_REQUEST = 1
_ALL_STATES = 0xFFFFFFFF
_NO_COOKIE = 0xFFFFFFFF
# struct nlmsghdr, then struct inet_diag_req_v2 with its struct inet_diag_sockid.
_HEADER = struct.Struct("=IHHII")
_REQUEST = struct.Struct("=BBBBI")
_SOCKID = struct.Struct("!HH16s16s")  # ports and addresses are in network order
_SOCKID_REST = struct.Struct("=III")  # interface, cookie
# struct inet_diag_msg: family, state, timer, retrans, the sockid, expires, rqueue, wqueue,
# uid, inode.
_MESSAGE_HEAD = struct.Struct("=BBBB")
_MESSAGE_TAIL = struct.Struct("=IIIII")


def account_of(client: tuple[str, int], server: tuple[str, int]) -> int | None:
    """The user id owning the socket of a TCP connection from ``client`` to ``server`` (both
    ``(address, port)`` as this end sees them), or ``None`` where it cannot be told."""
    try:
        source = ipaddress.ip_address(client[0])
        destination = ipaddress.ip_address(server[0])
    except ValueError:
        return None
    if source.version != destination.version:
        return None
    family = socket.AF_INET if source.version == 4 else socket.AF_INET6
    request = (
        _REQUEST.pack(family, socket.IPPROTO_TCP, 0, 0, _ALL_STATES)
        + _SOCKID.pack(
            client[1],
            server[1],
            source.packed.ljust(16, b"\0"),
            destination.packed.ljust(16, b"\0"),
        )
        + _SOCKID_REST.pack(0, _NO_COOKIE, _NO_COOKIE)
    )
    message = _HEADER.pack(_HEADER.size + len(request), _SOCK_DIAG_BY_FAMILY, _NLM_F_REQUEST, 1, 0)
    try:
        with socket.socket(socket.AF_NETLINK, socket.SOCK_DGRAM, 4) as netlink:  # NETLINK_SOCK_DIAG
            netlink.settimeout(1.0)
            netlink.send(message + request)
            answer = netlink.recv(8192)
    except (OSError, AttributeError):  # AttributeError: no AF_NETLINK (not Linux)
        return None
    return _uid(answer)


def _uid(answer: bytes) -> int | None:
    if len(answer) < _HEADER.size:
        return None
    _, kind, _, _, _ = _HEADER.unpack_from(answer)
    if kind != _SOCK_DIAG_BY_FAMILY:  # _NLMSG_ERROR: no such socket here
        return None
    offset = _HEADER.size + _MESSAGE_HEAD.size + _SOCKID.size + _SOCKID_REST.size
    if len(answer) < offset + _MESSAGE_TAIL.size:
        return None
    _, _, _, uid, _ = _MESSAGE_TAIL.unpack_from(answer, offset)
    return int(uid)


def same_account(client: tuple[str, int] | None, server: tuple[str, int] | None) -> bool:
    """Whether the connection is not known to come from another account of this machine."""
    if client is None or server is None:
        return True
    found = account_of(client, server)
    return found is None or found == os.getuid()
