"""ROS names: a topic with its message type, and message types spelled the ROS 1 way.

A :class:`Topic` is what a topic list, a bag and a live graph all give; ROS 2 spells types
``package/msg/Name`` where ROS 1 spells ``package/Name``, and :func:`normalise_type` makes
them one. :func:`full_topic_name_problem` says why a name is not one a ROS 2 node can publish or
subscribe as it is (rmw's own rules); :func:`topic_name_problem` why a name is not even one a
node could expand (rcl's rules: relative names and ``~`` allowed).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

__all__ = [
    "TOPIC_MAX_CHARS",
    "Topic",
    "common_namespace",
    "full_topic_name_problem",
    "in_namespace",
    "normalise_type",
    "topic_name_problem",
]

# RMW_TOPIC_MAX_NAME_LENGTH: 255 less the 8 characters rmw reserves for prefixes (``rt/``...).
TOPIC_MAX_CHARS = 247
_NAME_CHARS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_/")


@dataclass(frozen=True, slots=True)
class Topic:
    """A topic, its message type (``pkg/Name``) and, when known, the robot's direction."""

    name: str
    type: str
    direction: str | None = None  # "published", "subscribed" or None (unknown)


def normalise_type(text: str) -> str:
    """``sensor_msgs/msg/Image`` -> ``sensor_msgs/Image``; ROS 1 names unchanged."""
    parts = text.strip().split("/")
    if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
        return f"{parts[0]}/{parts[2]}"
    return text.strip()


def full_topic_name_problem(name: str) -> str | None:
    """Why ``name`` is not a fully qualified ROS 2 topic name, or None if it is one.

    The rules and their order are rmw's ``rmw_validate_full_topic_name`` (ros2/rmw
    ``rmw/src/validate_full_topic_name.c``, commit 33118c9d4dc2 of October 2024): not empty,
    absolute (a leading ``/``), no trailing ``/``, only ``[A-Za-z0-9_/]``, no ``//``, no name
    part that starts with a digit, at most :data:`TOPIC_MAX_CHARS` characters. A relative
    name (``robot1/points``) or a substitution (``~/x``, ``{node}``) must be expanded by a node
    first: a file that an operator's tool loads as it is names full topics.
    """
    if not name:
        return "is empty"
    if not name.startswith("/"):
        return "is not absolute (a ROS 2 topic name starts with '/')"
    if name.endswith("/"):
        return "ends with '/'"
    for index, char in enumerate(name):
        if char not in _NAME_CHARS:
            # The character itself is not shown: the name may be a stranger's.
            return f"has a character other than a letter, a digit, '_' or '/' at {index + 1}"
    for index in range(len(name) - 1):
        if name[index] == "/" and name[index + 1] == "/":
            return f"has '//' at character {index + 1}"
        if name[index] == "/" and name[index + 1].isdigit():
            return f"has a name part starting with a digit at character {index + 2}"
    if len(name) > TOPIC_MAX_CHARS:
        return f"is longer than {TOPIC_MAX_CHARS} characters ({len(name)})"
    return None


def common_namespace(names: Iterable[str]) -> str | None:
    """The namespace every name lies in (``/robot1`` for ``/robot1/cmd_vel`` and
    ``/robot1/front/points``), or None when they share none but the root (or there are none).

    Names are compared as written: a template ``<robot>/cmd_vel`` lies in ``<robot>``.
    """
    common: list[str] | None = None
    for name in names:
        parts = name.split("/")[:-1]
        if common is None:
            common = parts
            continue
        length = 0
        while length < min(len(common), len(parts)) and common[length] == parts[length]:
            length += 1
        common = common[:length]
    if not common or common == [""]:
        return None
    return "/".join(common)


def in_namespace(name: str, namespace: str) -> bool:
    """Is ``name`` inside ``namespace`` (``/robot1/cmd_vel`` in ``/robot1``; not ``/robot10/x``)?"""
    return name.startswith(namespace.rstrip("/") + "/")


def topic_name_problem(name: str) -> str | None:
    """Why ``name`` is not a ROS 2 topic name a node could use, or None if it is one.

    rcl's ``rcl_validate_topic_name`` (ros2/rcl ``rcl/src/rcl/validate_topic_name.c``, commit
    c19dab55e6a6 of March 2024): relative names (``scan``), a leading ``~`` and ``{sub}``
    substitutions are allowed; a node expands them in its namespace. Beyond rcl, ``//`` is
    refused here: the expanded name would fail rmw's check.
    """
    if not name:
        return "is empty"
    if name[0].isdigit():
        return "starts with a digit"
    if name.endswith("/"):
        return "ends with '/'"
    problem = _characters_problem(name)
    if problem:
        return problem
    for index in range(len(name) - 1):
        if name[index] == "/" and name[index + 1].isdigit():
            return f"has a name part starting with a digit at character {index + 2}"
        if name[index] == "/" and name[index + 1] == "/":
            return f"has '//' at character {index + 1}"
    if name.startswith("~") and len(name) > 1 and name[1] != "/":
        return "has '~' not followed by '/'"
    return None


def _characters_problem(name: str) -> str | None:
    """rcl's character scan: letters, digits, '_', '/', a leading '~', '{sub}' substitutions."""
    opened: int | None = None
    for index, char in enumerate(name):
        if char.isascii() and (char.isalnum() or char == "_"):
            if char.isdigit() and opened is not None and index == opened + 1:
                return f"has a substitution starting with a digit at character {index + 1}"
        elif (char == "/" and opened is None) or (char == "~" and index == 0):
            continue
        elif char == "~":
            return f"has '~' at character {index + 1}; only a name's first character may be '~'"
        elif char == "{" and opened is None:
            opened = index
        elif char == "}" and opened is not None:
            opened = None
        elif char == "}":
            return f"has an unmatched '}}' at character {index + 1}"
        else:
            return f"has a character other than a letter, a digit, '_' or '/' at {index + 1}"
    if opened is not None:
        return f"has an unmatched '{{' at character {opened + 1}"
    return None
