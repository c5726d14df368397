"""Naming the layout file of the active robot's configuration in ``watch`` events.

``teleop-ui watch --layouts DIR`` adds ``"layout"`` (the path of the active configuration's
layout in DIR, ``null`` with no active robot) to each ``selection_changed`` JSON event, and a
``layout`` line to its text. Not here: the events themselves (:mod:`solver.live.events`).
"""

from __future__ import annotations

import json
from pathlib import Path

from solver.core.assignment import Assignment
from solver.layouts.foxglove import layout_filename
from solver.live.events import Event, SelectionChanged
from solver.reporting.render import dumps

__all__ = ["layout_path", "with_layout"]


def layout_path(assignment: Assignment, directory: str | Path, extension: str = "json") -> str:
    """The layout file of ``assignment``'s configuration (the default one's when it is)."""
    name = layout_filename(assignment.number, default=assignment.is_default, extension=extension)
    return str(Path(directory) / name)


def with_layout(text: str, event: Event, directory: str | Path, fmt: str) -> str:
    """``text`` (one rendered event) with the layout file added when it is a selection."""
    if not isinstance(event, SelectionChanged):
        return text
    assignment = event.selection.assignment if event.selection is not None else None
    path = layout_path(assignment, directory) if assignment is not None else None
    if fmt == "json":
        data = json.loads(text)
        data["layout"] = path
        return dumps(data, indent=None)
    return text + f"{'layout':<16}{path or '(no active robot)'}\n"
