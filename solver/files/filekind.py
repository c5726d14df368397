"""Which kind of file a loaded YAML document is: a team, a rule set, a profile, a description.

One answer for every command: ``check`` sorts its files with it, ``batch`` skips what is no
team, ``count`` reads a rule set as its whole design space, and ``solve`` (through
:func:`solver.core.team.parse_team`) says "this is a rule set; pass a team" instead of listing the
rule set's fields as unknown team fields. Decided by the top-level keys, in this order:

1. ``team:`` -> a team (whatever else it has: the team reader reports the rest);
   ``teleop:`` -> a robot's teleoperation description (``ROBOT.teleop.yaml`` beside its URDF,
   :mod:`solver.ros.description`);
   ``profile: presentation`` -> a presentation profile (``teleop-ui layouts --presentation``);
2. ``extends:`` -> an identification profile on top of another (``extends: shipped``);
   ``characteristics:`` -> an identification profile when it also has a profile-only section
   (``patterns``, ``structures``, ...), else a rule set;
3. ``rules:`` -> a team whose ``team:`` is missing (the team reader says so);
4. anything else -> ``None``: the caller says what it expected.

Not here: reading the file (:mod:`solver.files.yamlio`) or the kinds themselves
(:mod:`solver.core.team`, :mod:`solver.core.rules`, :mod:`solver.identify.profile`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from solver.errors import Fault, InputError
from solver.files.yamlio import declares_kind

if TYPE_CHECKING:
    from solver.files.yamlio import Document

__all__ = [
    "PROFILE_SECTIONS",
    "FileKind",
    "declares_kind",
    "describe",
    "file_kind",
    "require_kind",
    "why",
]

FileKind = Literal["team", "rules", "profile", "presentation", "teleop"]

# Sections only an identification profile has (rules/identification.yaml); a rule set with
# one of them is a profile, so `check` and `batch` do not read it as a broken rule set.
PROFILE_SECTIONS = frozenset(
    {
        "patterns",
        "plugins",
        "limbs",
        "doubt_factor",
        "structures",
        "sensors",
        "sensor_types",
        "topics",
        "motion",
        "body_packages",
    }
)

_WHAT: dict[FileKind, str] = {
    "team": "a team file",
    "rules": "a rule set",
    "profile": "an identification profile",
    "presentation": "a presentation profile",
    "teleop": "a teleoperation description",
}
_WHY: dict[FileKind, str] = {
    "team": "it has 'team:'",
    "rules": "it has 'characteristics:' and no 'team:'",
    "profile": "it has 'extends:', or 'characteristics:' and profile sections such as 'patterns:'",
    "presentation": "it has 'profile: presentation'",
    "teleop": "it has 'teleop:'",
}

# What to pass instead, per (kind found, kind wanted).
_INSTEAD: dict[tuple[FileKind, FileKind], str] = {
    ("rules", "team"): "pass a team (a file with 'rules:' naming this file and 'team:' "
    "selecting values per kinematic type, or a shipped team such as "
    "case3); `teleop-ui count FILE` counts every robot of a rule set",
    ("profile", "team"): "pass a team file; a profile is for `identify --profile`",
    ("team", "rules"): "pass a rule set (a file with 'characteristics:')",
    ("profile", "rules"): "pass a rule set; a profile is for `identify --profile`",
    (
        "presentation",
        "team",
    ): "pass a team file; a presentation profile is for `layouts --presentation`",
    (
        "presentation",
        "rules",
    ): "pass a rule set; a presentation profile is for `layouts --presentation`",
    ("teleop", "team"): "pass a team file; a teleoperation description is read by `identify` "
    "(beside its URDF, or with --teleop)",
    ("teleop", "rules"): "pass a rule set; a teleoperation description is read by `identify` "
    "(beside its URDF, or with --teleop)",
}


def file_kind(document: Document) -> FileKind | None:
    """The kind of ``document`` by its top-level keys (see the module docstring)."""
    data = document.data
    if not isinstance(data, dict):
        return None
    keys = {str(key) for key in data}
    if "team" in keys:
        return "team"
    if "teleop" in keys:
        return "teleop"
    if data.get("profile") == "presentation":
        return "presentation"
    if "extends" in keys:
        return "profile"
    if "characteristics" in keys:
        return "profile" if keys & PROFILE_SECTIONS else "rules"
    if "rules" in keys:
        return "team"
    return None


def describe(kind: FileKind) -> str:
    """``a rule set``, ``an identification profile``, ...: the kind in a sentence."""
    return _WHAT[kind]


def why(kind: FileKind) -> str:
    """What in a file makes it ``kind``: ``it has 'team:'``, ..."""
    return _WHY[kind]


def require_kind(document: Document, wanted: FileKind) -> None:
    """Raise a located :class:`InputError` when ``document`` is clearly another kind of file.

    A document of no recognisable kind passes: the reader for ``wanted`` lists what is wrong.
    """
    found = file_kind(document)
    if found is None or found == wanted:
        return
    location = document.location()
    message = f"this is {_WHAT[found]}, not {_WHAT[wanted]} ({_WHY[found]})"
    instead = _INSTEAD.get((found, wanted))
    raise InputError(Fault(location, message + (f"; {instead}" if instead else ""), "wrong-kind"))
