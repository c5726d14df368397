"""A folder of real robots -> identifications and a team selection ``teleop-ui solve`` accepts.

Layout: every ``NAME.urdf``, ``NAME.urdf.xacro`` or ``NAME.xacro`` directly in the folder is one
robot; ``NAME.srdf``, ``NAME.topics`` / ``NAME.topics.txt``, ``NAME.bag`` and
``NAME.teleop.yaml`` (its teleoperation description, whose declared values win) beside it are
used when present. Robots are identified in name order; one that cannot be identified (malformed,
unreadable, a missing xacro package, ...) is kept with its reason and the others still go
through. A folder that cannot be listed is an error.

A robot folder is often a stranger's (downloaded, unpacked, shared): the scan follows no link
out of the folder. A description or a file beside it that is a link to something outside the
folder (``robot.topics -> /etc/shadow``) is not read, and its robot fails with that reason. A
file beside a description is used only when it reads as its kind (a topic list, an SRDF, a
bag); the reason a robot fails quotes nothing of a file that did not, so nothing of such a
file reaches the output or the team file written.

The team selection (:func:`team_text`) has, per kinematic type of the rule set that at least one
robot maps to: the union of the robots' motion controls and sensor types (in the rule set's
order, values the rule set lacks left out) and the largest number of sensors with a
presentation. A characteristic with nothing identified is left out (a team file reads that as
every value), and a type with nothing to narrow at all is written ``{}``. Robots with no
kinematic type in the rule set are listed in a comment. The text is checked by
:func:`solver.core.team.parse_team` before it is returned.

Not here: printing progress (the caller passes a callback) or writing files.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import yaml

from solver.core.ruleset import RuleSet
from solver.core.team import parse_team
from solver.errors import InputError, MissingExtraError, SolverError
from solver.files.yamlio import parse_document
from solver.identify.identification import Identification, identify
from solver.identify.profile import MOTION_CONTROL, ROLES, SENSOR_COUNT, SENSOR_TYPE, Profile
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "Fleet",
    "FleetEntry",
    "find_descriptions",
    "identify_fleet",
    "rules_reference",
    "team_text",
]

_SUFFIXES = (".urdf.xacro", ".urdf", ".xacro")

Progress = Callable[[int, int, str], None]


@dataclass(frozen=True, slots=True)
class FleetEntry:
    name: str
    file: str
    identification: Identification | None = None
    error: str | None = None


@dataclass(frozen=True)
class Fleet:
    folder: str
    entries: tuple[FleetEntry, ...]

    @property
    def identified(self) -> tuple[Identification, ...]:
        return tuple(e.identification for e in self.entries if e.identification is not None)

    @property
    def failed(self) -> tuple[FleetEntry, ...]:
        return tuple(e for e in self.entries if e.identification is None)


def _stem(path: Path) -> str | None:
    return next((path.name[: -len(s)] for s in _SUFFIXES if path.name.endswith(s)), None)


def find_descriptions(folder: str | Path) -> tuple[Path, ...]:
    """The robot descriptions directly in ``folder``, in name order."""
    base = Path(folder)
    name = shown(str(folder), limit=SHOWN_FILE_NAME_CHARS)
    try:
        if not base.is_dir():
            raise InputError.at(name, "not a folder of robot descriptions", code="fleet")
        found = sorted(
            (p for p in base.iterdir() if _stem(p) and _is_robot_file(p)), key=lambda p: p.name
        )
    except OSError as error:
        # A folder without read or search permission cannot be used at all; an unreadable
        # file in a readable folder is a failed robot instead (identify_fleet).
        raise InputError.at(
            name, f"cannot list this folder: {error.strerror or error}", code="fleet"
        ) from None
    if not found:
        raise InputError.at(
            name,
            "no robot descriptions (*.urdf, *.urdf.xacro, *.xacro) in this folder",
            code="fleet",
        )
    return tuple(found)


def _is_robot_file(path: Path) -> bool:
    """A regular file, or a dangling or looping link (kept so it is reported as failed).

    Not a folder, a FIFO or a device: opening a FIFO would wait for a writer forever.
    """
    return path.is_file() or (path.is_symlink() and not path.exists())


def _companion(path: Path, *suffixes: str) -> Path | None:
    stem = _stem(path) or path.stem
    return next(
        (path.with_name(stem + s) for s in suffixes if path.with_name(stem + s).is_file()), None
    )


def _links_out(path: Path, folder: str) -> bool:
    """Whether ``path``, in ``folder`` (a resolved path), is a link to something outside it."""
    # realpath, not Path.resolve: a link loop is no error to it (the read reports it).
    return path.is_symlink() and os.path.commonpath([os.path.realpath(path), folder]) != folder


def _link_out(path: Path) -> str:
    return (
        f"{shown(str(path), limit=SHOWN_FILE_NAME_CHARS)}: a link to a file outside the "
        "folder; a folder scan follows no link out of its folder (copy the file in)"
    )


def identify_fleet(
    folder: str | Path,
    *,
    rules: RuleSet,
    profile: Profile,
    package_path: Sequence[str | Path] = (),
    xacro_args: Mapping[str, str] | None = None,
    progress: Progress | None = None,
    trust_xacro: bool = False,
    strict: bool = False,
) -> Fleet:
    """Identify every robot in ``folder``; failures are kept with their reason.

    With ``strict``, a robot whose description or SRDF has warnings is a failure too.

    Finding a ``.xacro`` file in a folder never means trusting it: without ``trust_xacro`` it
    is a failed robot whose reason says how to opt in. A missing extra (lxml, rosbags) is no
    robot's failure: its :class:`~solver.errors.MissingExtraError` is raised.
    """
    paths = find_descriptions(folder)
    inside = os.path.realpath(folder)
    entries = []
    for done, path in enumerate(paths):
        name = _stem(path) or path.name
        if progress is not None:
            progress(done, len(paths), name)
        srdf = _companion(path, ".srdf")
        topics = _companion(path, ".topics", ".topics.txt")
        bag = _companion(path, ".bag")
        teleop = _companion(path, ".teleop.yaml")
        outside = [p for p in (path, srdf, topics, bag, teleop) if p and _links_out(p, inside)]
        if outside:
            entries.append(FleetEntry(name, str(path), None, _link_out(outside[0])))
            continue
        try:
            result = identify(
                path,
                srdf=srdf,
                topic_lists=[topics] if topics else (),
                bags=[bag] if bag else (),
                xacro_args=xacro_args,
                package_path=package_path,
                rules=rules,
                profile=profile,
                trust_xacro=trust_xacro,
                teleop=teleop,
                look_beside=False,  # the one beside, checked for links out above
                look_around=False,  # a folder of robots: each file alone, no workspace
            )
        except MissingExtraError:
            raise  # not this robot's failure: every robot would fail for it
        except SolverError as error:
            entries.append(FleetEntry(name, str(path), None, str(error).splitlines()[0]))
            continue
        if strict and result.warnings:
            entries.append(FleetEntry(name, str(path), None, str(result.warnings[0])))
            continue
        entries.append(FleetEntry(name, str(path), result))
    if progress is not None:
        progress(len(paths), len(paths), "")
    return Fleet(str(folder), tuple(entries))


def team_text(
    fleet: Fleet, rules: RuleSet, profile: Profile, *, name: str, rules_reference: str | None = None
) -> str:
    """A team selection YAML for the fleet (see the module docstring), checked to load."""
    roles = {role: profile.role(role) for role in ROLES}
    by_type: dict[str, list[FleetEntry]] = {}
    for entry in fleet.entries:
        ident = entry.identification
        if ident is not None and ident.kinematic_type is not None:
            by_type.setdefault(ident.kinematic_type, []).append(entry)
    lines = [
        _comment(
            f"Team selection built by `teleop-ui fleet` from {fleet.folder}: "
            f"{len(fleet.identified)} robot(s) identified, {len(fleet.failed)} not."
        ),
        f"name: {_yaml(name)}",
    ]
    if rules_reference is not None:
        lines.append(f"rules: {_yaml(rules_reference)}")
    lines.append("team:")
    for kinematic_type in (str(v) for v in rules.key.values):
        entries = by_type.get(kinematic_type)
        if not entries:
            continue
        robots = ", ".join(e.name for e in entries)
        lines.append(f"  {_yaml(kinematic_type)}:   {_comment(robots)}")
        lines += _selection(entries, rules, roles)
    for entry in fleet.entries:
        ident = entry.identification
        if ident is not None and ident.kinematic_type is None:
            lines.append(_comment(f"not in the rule set: {entry.name} ({ident.structure})"))
    lines += [_comment(f"not identified: {e.name}: {e.error}") for e in fleet.failed]
    if not by_type:
        raise InputError.at(
            fleet.folder,
            "no robot in this folder maps to a kinematic type "
            f"of the rule set {shown(rules.name, quoted=True)}; no team written",
            code="fleet",
        )
    text = "\n".join(lines) + "\n"
    parse_team(parse_document(text, "<fleet team>"), rules)
    return text


def _selection(entries: list[FleetEntry], rules: RuleSet, roles: dict[str, str]) -> list[str]:
    idents = [e.identification for e in entries if e.identification is not None]
    lines = [
        *_union(
            rules,
            roles[MOTION_CONTROL],
            {c.motion_control for i in idents for c in i.motion_controls},
            "none identified",
        ),
        *_union(
            rules,
            roles[SENSOR_TYPE],
            {t for i in idents for t in i.sensor_types},
            "none with a presentation",
        ),
    ]
    count = roles[SENSOR_COUNT]
    if count in rules.names:
        characteristic = rules.characteristic(count)
        most = max(i.sensor_count for i in idents)
        top = max(int(v) for v in characteristic.values)
        low = min(int(v) for v in characteristic.values)
        if most > top:
            lines.append(f"    {_yaml(count)}: {_yaml(top)}   # capped: a robot has {most}")
        elif most >= low:
            lines.append(f"    {_yaml(count)}: {_yaml(most)}")
        else:
            lines.append(
                "    " + _comment(f"{count}: no sensors with a presentation (every value allowed)")
            )
    if all(line.lstrip().startswith("#") for line in lines):
        # A key followed only by comments loads as null, which a team file rejects; {} is
        # the team file's spelling of "every value of every characteristic".
        lines.append("    {}   # nothing identified to narrow: every value allowed")
    return lines


def _union(rules: RuleSet, name: str, chosen: set[str], nothing: str) -> list[str]:
    """The line selecting ``chosen`` values of characteristic ``name`` in the rule set's order.

    Values the rule set lacks are left out; with none left the line is a comment (a team file
    then allows every value). Nothing when the rule set has no such characteristic.
    """
    if name not in rules.names:
        return []
    values = [str(v) for v in rules.characteristic(name).values if str(v) in chosen]
    if values:
        return [f"    {_yaml(name)}: {_yaml(values)}"]
    return ["    " + _comment(f"{name}: {nothing} (every value allowed)")]


def _yaml(value: object) -> str:
    """``value`` as YAML, written by the YAML library's emitter on one line, quoted as needed.

    Names come from description files (their file names, too) and rule files: written by string
    formatting, a name holding a newline and ``UGV: ...`` would add a kinematic type to the team.
    """
    parts = value if isinstance(value, list) else [value]
    # Double quotes keep a line break or control character as an escape on this one line
    # (plain and single-quoted scalars would continue on the next line).
    style = None if all(str(part).isprintable() for part in parts) else '"'
    text = yaml.safe_dump(
        value, default_flow_style=True, default_style=style, allow_unicode=True, width=2**31 - 1
    )
    return text.removesuffix("\n...\n").rstrip("\n")


def _comment(text: str) -> str:
    """``# text`` with every character that could end the comment line (or hide text in it)
    written as its escape (:func:`~solver.untrusted.shown`)."""
    return "# " + shown(text, limit=None)


def rules_reference(rules_file: str | Path, team_file: str | Path) -> str:
    """``rules_file`` relative to the folder of ``team_file``."""
    folder = Path(team_file).resolve().parent
    return os.path.relpath(Path(rules_file).resolve(), folder)
