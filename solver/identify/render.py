"""Identifications as JSON (the documented contract) and as text for a person.

:func:`identification_data` builds the contract of ``teleop-ui identify --format json``::

    {"robot", "file", "structure", "kinematic_type", "confidence", "evidence",
     "roles": [{"joint", "role", "evidence"}],     # every moving joint: what it does, and why
     "sensors": [{"kind", "sensor_type", "count", "source"}],
     "motion_controls": [{"motion_control", "source"}],
     "combinations": [...],      # assignment JSON of `teleop-ui assign`, with --team
     "missing": [...],           # with --team: characteristics nothing gave (only if some)
     "warnings": [{"file", "line", "message"}],   # flaws read past; only when there are some
     "declared": "robot.teleop.yaml",   # the teleoperation description read; only with one
     "disagreements": [...],     # where it differs from what was read; only when some do
     "decision": [...]}          # with explain: the structure rules tried, in order

``fleet`` prints a list of these; a live graph's robot events carry :func:`summary_data`, the
same fields in brief (``name`` for ``robot``; ``null`` and empty lists for a robot that could
not be identified). Output is deterministic: declared orders, no timestamps.

Not here: computing any of it.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from solver.errors import Fault
from solver.files.output import text_table
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

if TYPE_CHECKING:
    from solver.identify.combinations import Combination
    from solver.identify.identification import Identification
    from solver.solving.solution import Solution

__all__ = ["identification_data", "render_identification", "summary_data"]


def summary_data(identification: Identification | None) -> dict[str, Any]:
    """What a live robot event says of an identification (see the module docstring)."""
    found = identification
    if found is None:
        scalars: dict[str, Any] = dict.fromkeys(
            ("name", "structure", "kinematic_type", "confidence", "sensor_count")
        )
        return {**scalars, "sensors": [], "motion_controls": []}
    return {
        "name": found.robot,
        "structure": found.structure,
        "kinematic_type": found.kinematic_type,
        "confidence": found.confidence,
        "sensor_count": found.sensor_count,
        "sensors": _sensors(found),
        "motion_controls": _controls(found),
    }


def _sensors(found: Identification) -> list[dict[str, Any]]:
    return [
        {"kind": s.kind, "sensor_type": s.sensor_type, "count": s.count, "source": s.source}
        for s in found.sensors
    ]


def _controls(found: Identification) -> list[dict[str, Any]]:
    return [{"motion_control": c.motion_control, "source": c.source} for c in found.motion_controls]


def identification_data(
    identification: Identification,
    combinations: Sequence[Combination] = (),
    solution: Solution | None = None,
    *,
    explain: bool = False,
    missing: Sequence[str] = (),
) -> dict[str, Any]:
    data: dict[str, Any] = {
        "robot": identification.robot,
        "file": identification.file,
        "structure": identification.structure,
        "kinematic_type": identification.kinematic_type,
        "confidence": identification.confidence,
        "evidence": list(identification.evidence),
        "roles": [
            {"joint": r.joint, "role": r.role, "evidence": r.evidence} for r in identification.roles
        ],
        "sensors": _sensors(identification),
        "motion_controls": _controls(identification),
        "combinations": [] if solution is None else _combinations(solution, combinations),
    }
    if explain:
        data["decision"] = list(identification.decision)
    if identification.notes:
        data["notes"] = list(identification.notes)
    if missing:
        data["missing"] = list(missing)
    if identification.warnings:
        data["warnings"] = [
            {"file": w.location.file, "line": w.location.line, "message": _message(w)}
            for w in identification.warnings
        ]
    if identification.declared is not None:
        data["declared"] = identification.declared
    if identification.disagreements:
        data["disagreements"] = list(identification.disagreements)
    return data


def _message(fault: Fault) -> str:
    return f"{fault.location.path}: {fault.message}" if fault.location.path else fault.message


def render_identification(
    identification: Identification,
    combinations: Sequence[Combination] = (),
    solution: Solution | None = None,
    *,
    explain: bool = False,
    missing: Sequence[str] = (),
) -> str:
    """A readable report: reading, evidence, sensors, controls, configurations; ``missing``:
    the rule set's characteristics nothing gave a value, each said with how to give it.

    The robot's name and every name from its files are escaped and its name cut short
    (:func:`~solver.untrusted.shown`): no name starts a forged line.
    """
    kinematic = identification.kinematic_type or "none in the rule set (default configuration)"
    lines = [
        f"{shown(identification.robot)}  "
        f"({shown(identification.file, limit=SHOWN_FILE_NAME_CHARS)})",
        f"  structure:      {shown(identification.structure)}  "
        f"(confidence {identification.confidence:.2f})",
        f"  kinematic type: {shown(kinematic, limit=None)}",
        "  evidence:",
    ]
    lines += [f"    - {shown(line, limit=None)}" for line in identification.evidence]
    if identification.body is not None and identification.body.roles:
        lines.append("  joint roles (what decided each):")
        lines += [f"    - {shown(line, limit=None)}" for line in identification.body.role_lines()]
    if explain:
        lines.append("  decision path (structure rules in order):")
        lines += [
            f"    {i}. {shown(line, limit=None)}"
            for i, line in enumerate(identification.decision, 1)
        ]
    lines += [f"  note: {shown(note, limit=None)}" for note in identification.notes]
    lines += [f"  warning: {warning}" for warning in identification.warnings]
    if identification.disagreements:
        lines.append("  declared and read differ (the declared value wins):")
        lines += [f"    - {shown(line, limit=None)}" for line in identification.disagreements]
    # Sections (each ending its last line) with a blank line between them, none after the last.
    sections = ["\n".join(lines) + "\n"]
    if identification.sensors:
        rows = [[s.kind, s.sensor_type or "-", s.count, s.source] for s in identification.sensors]
        table = text_table(
            ["sensor kind", "sensor type", "count", "source"], rows, [False, False, True, False]
        )
        count = f"  {identification.sensor_count} sensor(s) with a presentation in the rule set\n"
        sections.append(_indent(table) + count)
    else:
        sections.append("  no sensors found\n")
    if identification.motion_controls:
        rows = [[c.motion_control, c.source] for c in identification.motion_controls]
        sections.append(_indent(text_table(["motion control", "source"], rows)))
    else:
        sections.append("  no motion controls found (give --topics or --bag)\n")
    if solution is not None:
        sections.append(_configurations(combinations, solution, missing))
    return "\n".join(sections)


def _configurations(
    combinations: Sequence[Combination], solution: Solution, missing: Sequence[str]
) -> str:
    """The configuration of each combination in the team, and what nothing gave."""
    team = shown(solution.team.name, limit=None, quoted=True)
    text = f"  UI configurations in team {team}:\n"
    rows = []
    for combination in combinations:
        values = ", ".join(value for _, value in combination.values)
        assignment = combination.assignment
        if assignment.is_default:
            rows.append([f"{assignment.number} (default)", values, "; ".join(assignment.reasons)])
        else:
            rows.append([str(assignment.number), values, ""])
    text += _indent(text_table(["configuration", "combination", "why default"], rows), "    ")
    return text + "".join(_missing_line(name, solution) for name in missing)


def _missing_line(name: str, solution: Solution) -> str:
    values = solution.rules.characteristic(name).values
    listed = ", ".join(shown(str(value)) for value in values[:6]) + (
        ", ..." if len(values) > 6 else ""
    )
    return (
        f"  no {shown(name)}: identification does not give it; give it with --set "
        f"{shown(name)}=VALUE ({listed})\n"
    )


def _indent(text: str, prefix: str = "  ") -> str:
    return "".join(prefix + line + "\n" for line in text.splitlines())


def _combinations(solution: Solution, combinations: Sequence[Combination]) -> list[dict[str, Any]]:
    """Each combination's assignment as ``assign --format json`` gives it (solving is loaded
    only when there is a team to solve: identifying a URDF alone does not)."""
    from solver.solving.assignment import assignment_data

    return [assignment_data(solution, c.assignment) for c in combinations]
