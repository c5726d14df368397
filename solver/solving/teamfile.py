"""Writing a team selection as a team file: the inverse of :func:`solver.core.team.load_team`.

:func:`team_yaml` writes what a :class:`~solver.core.team.Team` selects in the shortest form a
team file reads back to the same selection: a characteristic left open (every value) is left
out, a run of counts from the domain's first is its maximum (``sensor_count: 5``), any other run
is ``{min: a, max: b}``, anything else a list in declared order. Counts per kinematic type, when
given, are comments, so a file says what it selects and what that costs. Every name is written
by the YAML library's emitter on one line (a name holding a newline cannot add a key) and every
comment has its line breaks and invisible characters escaped.

Not here: reading (:mod:`solver.core.team`), the selection a fleet of real robots makes
(:mod:`solver.identify.fleet`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import yaml

from solver.core.constraints import Value
from solver.untrusted import visible

if TYPE_CHECKING:
    from solver.core.ruleset import Characteristic
    from solver.core.team import Team
    from solver.solving.solution import Solution

__all__ = ["selection_form", "team_yaml", "yaml_comment", "yaml_inline"]


def yaml_inline(value: object) -> str:
    """``value`` as YAML on one line, quoted as needed (flow style for lists and mappings)."""
    parts: list[object] = list(value) if isinstance(value, list) else [value]
    # Double quotes keep a line break or a control character as an escape on this one line.
    style = None if all(str(part).isprintable() for part in parts) else '"'
    text = yaml.safe_dump(
        value, default_flow_style=True, default_style=style, allow_unicode=True, width=2**31 - 1
    )
    return text.removesuffix("\n...\n").rstrip("\n")


def yaml_comment(text: str) -> str:
    """``# text``, every character that could end the line (or hide text in it) escaped."""
    if not visible(text):
        text = "".join(
            c if visible(c) else c.encode("unicode_escape").decode("ascii") for c in text
        )
    return "# " + text


def selection_form(characteristic: Characteristic, domain: Sequence[Value]) -> object | None:
    """What a team file writes for ``domain`` of ``characteristic`` (``None``: every value,
    the key is left out)."""
    values = characteristic.values
    if len(domain) == len(values) and tuple(domain) == tuple(values):
        return None
    if characteristic.kind == "integer" and domain:
        counts = [int(v) for v in domain]
        if counts == list(range(counts[0], counts[-1] + 1)):
            if counts[0] == int(values[0]):
                return counts[-1]  # a lone number is a maximum: first..N
            if len(counts) > 1:
                return {"min": counts[0], "max": counts[-1]}
        return counts
    return list(domain)


def team_yaml(
    team: Team,
    *,
    solution: Solution | None = None,
    rules_reference: str | None = None,
    header: Sequence[str] = (),
) -> str:
    """``team`` as a team file; ``solution`` adds each type's counts as a comment.

    ``rules_reference`` is written as ``rules:`` (a path relative to where the file will be,
    or absolute); without it the file names no rule set and is read against the shipped rules
    (or ``--rules``). ``header`` lines come first, as comments.
    """
    rules = team.rules
    counts = {} if solution is None else {t.kinematic_type: t for t in solution.by_type}
    lines = [yaml_comment(line) for line in header]
    lines.append(f"name: {yaml_inline(team.name)}")
    if team.description:
        lines.append(f"description: {yaml_inline(team.description)}")
    if rules_reference is not None:
        lines.append(f"rules: {yaml_inline(rules_reference)}")
    lines.append("team:" if team.selections else "team: {}")
    for selection in team.selections:
        summary = counts.get(selection.kinematic_type)
        note = (
            ""
            if summary is None
            else "   "
            + yaml_comment(
                f"{summary.valid_robots} valid robots, "
                f"{summary.ui_configurations} UI configurations"
            )
        )
        entries = []
        for characteristic, domain in zip(rules.characteristics, selection.domains, strict=True):
            if characteristic.name == rules.team_key:
                continue
            form = selection_form(characteristic, domain)
            if form is not None:
                entries.append(f"    {yaml_inline(characteristic.name)}: {yaml_inline(form)}")
        head = f"  {yaml_inline(selection.kinematic_type)}:"
        lines.append(head + (note if entries else " {}" + note))
        lines += entries
    if team.published is not None:
        published = team.published
        lines.append("published:")
        if published.source:
            lines.append(f"  source: {yaml_inline(published.source)}")
        lines.append(f"  valid_robots: {published.valid_robots}")
        lines.append(f"  ui_configurations: {published.ui_configurations}")
    return "\n".join(lines) + "\n"
