"""Topic lists: what ``rostopic`` and ``ros2 topic`` print, read into (name, type, direction).

Accepted, in one file or mixed:

* ``rostopic list -v`` / ``ros2 topic list -v``: ``Published topics:`` and ``Subscribed
  topics:`` sections of `` * /scan [sensor_msgs/LaserScan] 1 publisher`` lines; the section
  gives each topic its direction, as the robot's nodes see it.
* ``ros2 topic list -t``: ``/scan [sensor_msgs/msg/LaserScan]``.
* ``rostopic list`` joined with ``rostopic type``: ``/scan sensor_msgs/LaserScan`` per line
  (``for t in $(rostopic list); do echo "$t $(rostopic type $t)"; done``).

Blank lines and ``#`` comments are skipped. A topic with no message type, or a type that is not
``package/Name`` (ROS 2's ``package/msg/Name`` is accepted and normalised), is a located error;
every bad line of a file is reported at once.

A file is read as a topic list only when its first line (after blanks and comments) is a
section heading or starts with a topic name (``/scan``, or `` * /scan``). Anything else (a
password file, a key, a ``.env`` given by mistake or linked from a robot folder) is "not a
topic list", located at that line and quoting nothing of it: what an error quotes of a bad line
(at most 60 characters, escaped) comes only from a file that reads as a topic list.

Each line becomes a :class:`solver.ros.names.Topic`, as a bag
(:mod:`solver.identify.readers.bags`) and a live graph give: the shared currency of
:mod:`solver.identify.interfaces`.

Not here: what a topic means (:mod:`solver.identify.interfaces`).
"""

from __future__ import annotations

import re
from pathlib import Path

from solver.errors import Fault, InputError, Location, TooLargeError
from solver.files.inputfile import read_text
from solver.identify.readers.safexml import MAX_XML_BYTES
from solver.limits import limit
from solver.ros.names import Topic, normalise_type
from solver.untrusted import shown

__all__ = ["parse_topic_list", "read_topic_list"]

_SECTION = re.compile(r"^\s*(published|subscribed)\s+topics\s*:\s*$", re.IGNORECASE)
_BRACKETED = re.compile(r"^\s*(?:\*\s*)?(\S+)\s+\[([^\]]*)\](?:\s+\d+\s+\w+)?\s*$")
_PLAIN = re.compile(r"^\s*(?:\*\s*)?(\S+)(?:\s+(\S+))?\s*$")
_TYPE = re.compile(r"^[A-Za-z][\w]*/(?:(?:msg|srv|action)/)?[A-Za-z][\w]*$")
_NAME = re.compile(r"^/?[A-Za-z~{][\w/{}~]*$")
# The head of a topic list's first line: a section heading, or a topic name from the root.
_HEAD = re.compile(r"^\s*(?:\*\s*)?/[A-Za-z~{][\w/{}~]*(?:\s|$)")


def read_topic_list(
    path: str | Path, *, display: str | None = None, before: int = 0
) -> tuple[Topic, ...]:
    """Read a topic list file (see the module docstring); ``before``: topic lines read from
    the other lists of the same command, which count against the same limit."""
    name = display if display is not None else str(path)
    text = read_text(path, display=name, limit=MAX_XML_BYTES, what="topic list")
    return parse_topic_list(text, name, before=before)


def parse_topic_list(text: str, name: str = "<topics>", *, before: int = 0) -> tuple[Topic, ...]:
    """Parse topic list text; :class:`InputError` lists every malformed line (see the module
    docstring for when a file is not read as a topic list at all).

    More topic lines than the ``topics`` limit (with the ``before`` lines of other lists) is
    refused at the line past it, before that line is read."""
    faults: list[Fault] = []
    found: list[Topic] = []
    direction: str | None = None
    first = True
    lines = 0
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        lines += 1
        if limit("topics").exceeded(before + lines):
            noun = "topic lines or more" + (" with the lists before this one" if before else "")
            fault = limit("topics").fault(Location(name, number), before + lines, noun=noun)
            raise TooLargeError(fault)
        section = _SECTION.match(line)
        if first and not section and not _HEAD.match(line):
            raise InputError.at(
                name,
                "not a topic list: this line is neither a section heading nor a topic "
                "(expected `rostopic list -v`, `ros2 topic list -t` or 'TOPIC TYPE' lines; "
                "nothing of a file that is not a topic list is shown)",
                line=number,
                code="topics",
            )
        first = False
        if section:
            direction = section.group(1).lower()
            continue
        match = _BRACKETED.match(line) or _PLAIN.match(line)
        topic, kind = (match.group(1), match.group(2)) if match else (stripped, None)
        column = line.find(topic) + 1 if topic in line else 1
        if not match or not _NAME.match(topic):
            faults.append(
                Fault(
                    Location(name, number, column),
                    f"not a topic line: {shown(stripped, quoted=True)}",
                    "topics",
                )
            )
            continue
        if not kind:
            faults.append(
                Fault(
                    Location(name, number, column, shown(topic)),
                    f"topic {shown(topic, quoted=True)} has no message type (give `rostopic "
                    "list -v`, `ros2 topic list -t`, or 'TOPIC TYPE' lines)",
                    "topics",
                )
            )
            continue
        if not _TYPE.match(kind.strip()):
            faults.append(
                Fault(
                    Location(name, number, line.find(kind) + 1, shown(topic)),
                    f"{shown(kind.strip(), quoted=True)} is not a message type (package/Name)",
                    "topics",
                )
            )
            continue
        found.append(Topic(topic, normalise_type(kind), direction))
    if faults:
        raise InputError(faults)
    if not found:
        raise InputError.at(name, "no topics in this file", code="topics")
    return tuple(found)
