"""The layout targets, one table: what each operator tool's layout file is made of.

A target turns one UI configuration (``None``: the default one) into the validated text of a
file its tool opens. Adding a target is one module that builds and validates its document and
one entry in :data:`TARGETS` (the command line's ``--format`` choices come from it).

>>> sorted(TARGETS)
['foxglove', 'rviz']
>>> TARGETS["rviz"].extension
'rviz'
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from solver.core.partition import Configuration
from solver.errors import InputError
from solver.layouts.foxglove import foxglove_layout, validate_foxglove
from solver.layouts.plan import Robot, plan_layout
from solver.layouts.presentation import Presentation
from solver.layouts.rviz import plan_rviz, rviz_note, rviz_text, validate_rviz
from solver.solving.solution import Solution
from solver.untrusted import shown

__all__ = ["TARGETS", "Target", "target"]


class Maker(Protocol):
    """Builds a target's file text for one configuration (unvalidated)."""

    def __call__(
        self,
        solution: Solution,
        configuration: Configuration | None,
        presentation: Presentation,
        *,
        robot: Robot,
        tile_count: int | None,
    ) -> str: ...


@dataclass(frozen=True)
class Target:
    """An operator tool's layout file: its name, file extension and how it is made."""

    name: str
    extension: str
    description: str
    make: Maker

    def render(
        self,
        solution: Solution,
        configuration: Configuration | None,
        presentation: Presentation,
        *,
        file: str,
        robot: Robot | None = None,
        tile_count: int | None = None,
    ) -> str:
        """The file's text, validated (a located :class:`~solver.errors.SolverError` if not).

        ``robot``: whom the layout is for (default: a template, see :mod:`solver.layouts.plan`).
        """
        text = self.make(
            solution,
            configuration,
            presentation,
            robot=robot if robot is not None else Robot(),
            tile_count=tile_count,
        )
        _VALIDATE[self.name](text, file)
        return text


def _foxglove(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    *,
    robot: Robot,
    tile_count: int | None,
) -> str:
    layout = foxglove_layout(
        solution, configuration, presentation, robot=robot, tile_count=tile_count
    )
    return json.dumps(layout, indent=2, sort_keys=True) + "\n"


def _rviz(
    solution: Solution,
    configuration: Configuration | None,
    presentation: Presentation,
    *,
    robot: Robot,
    tile_count: int | None,
) -> str:
    plan = plan_layout(
        solution, configuration, presentation, robot, tile_count=tile_count, relative=True
    )
    return rviz_text(plan_rviz(plan), rviz_note(plan))


def _validate_foxglove(text: str, file: str) -> None:
    validate_foxglove(json.loads(text), file)


_VALIDATE: dict[str, Callable[[str, str], None]] = {
    "foxglove": _validate_foxglove,
    "rviz": validate_rviz,
}

TARGETS: dict[str, Target] = {
    "foxglove": Target(
        "foxglove", "json", "Foxglove / Lichtblick layout JSON (Import layout)", _foxglove
    ),
    "rviz": Target("rviz", "rviz", "RViz2 .rviz display configuration", _rviz),
}


def target(name: str) -> Target:
    """The target called ``name``; a located usage error naming the known ones otherwise."""
    found = TARGETS.get(name)
    if found is None:
        raise InputError.at(
            "--format",
            f"unknown layout format {shown(name, quoted=True)}; known: " + ", ".join(TARGETS),
        )
    return found
