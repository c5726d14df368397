"""Published figures beside computed ones: does the project reproduce the article?

A team file may carry the figures a publication reports for it (``published:``). This module
solves such teams and sets the two side by side; it never adjusts anything to agree. The README's
reproduction table is this module's Markdown output, and a test keeps the two in step.

Not here: the hypothesis that explains a disagreement; it lives as data in
``rules/teams/case3-hypothesis.yaml`` and the README.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from solver.core.rules import shipped_name, shipped_path
from solver.core.team import Published, Team, load_team, resolve_team_path
from solver.errors import InputError
from solver.solving.solution import Solution, solve

__all__ = ["Comparison", "compare", "published_for", "published_note"]


@dataclass(frozen=True, slots=True)
class Comparison:
    """One team: what a publication reports and what the rules give."""

    file: str
    solution: Solution
    published: Published

    @property
    def agrees(self) -> bool:
        totals = self.solution.totals
        return (totals.valid_robots, totals.ui_configurations) == (
            self.published.valid_robots,
            self.published.ui_configurations,
        )


def published_note(solution: Solution) -> tuple[str, str, bool] | None:
    """The published figures and the verdict, as ``teleop-ui solve`` and reports word them.

    ``None`` when the team carries no published figures; else the line stating them, the
    verdict line, and whether they agree with the computed totals. Nothing is adjusted.
    """
    published = solution.team.published
    if published is None:
        return None
    totals = solution.totals
    agrees = (published.valid_robots, published.ui_configurations) == (
        totals.valid_robots,
        totals.ui_configurations,
    )
    source = f" ({published.source})" if published.source else ""
    stated = (
        f"published: {published.valid_robots} valid robots / "
        f"{published.ui_configurations} UI configurations{source}"
    )
    verdict = (
        "reproduced"
        if agrees
        else (
            f"NOT reproduced: these rules give {totals.valid_robots} / {totals.ui_configurations}"
        )
    )
    return stated, verdict, agrees


def compare(paths: Iterable[str | Path] | None = None) -> list[Comparison]:
    """Solve each team file and set its published figures beside the computed ones.

    Without ``paths``: every shipped team that carries published figures, by file name,
    shown as ``rules/teams/<name>.yaml``. A file given explicitly without published figures is an
    :class:`InputError`.
    """
    if paths is None:
        found = [
            (path, shipped_name(path) or str(path))
            for path in sorted(shipped_path("teams").glob("*.yaml"), key=lambda p: p.stem)
        ]
    else:
        found = [(resolve_team_path(str(path)), str(path)) for path in paths]
    comparisons = []
    for path, shown in found:
        team = load_team(path, display=shown)
        if team.published is None:
            if paths is None:
                continue
            raise InputError.at(shown, "has no 'published:' figures to compare with")
        comparisons.append(Comparison(shown, solve(team), team.published))
    return comparisons


@cache
def _published_teams() -> tuple[Team, ...]:
    """The shipped teams that carry published figures (shipped files do not change)."""
    teams = (
        load_team(path, display=shipped_name(path) or str(path))
        for path in sorted(shipped_path("teams").glob("*.yaml"))
    )
    return tuple(team for team in teams if team.published is not None)


def published_for(team: Team) -> Published | None:
    """The figures a publication reports for ``team``'s selection, if a shipped team with the
    same selections under the same rule set carries them (``None`` otherwise).

    A selection made by hand (in the studio, say) that equals the article's Case 3 gets the
    article's 820 / 99 beside the computed 872 / 102, as ``solve case3`` shows them.
    """
    if team.published is not None:
        return team.published
    for shipped in _published_teams():
        if shipped.rules.file == team.rules.file and shipped.selections == team.selections:
            return shipped.published
    return None
