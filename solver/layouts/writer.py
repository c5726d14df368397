"""Writing a team's layouts: one per UI configuration plus the default, validated first."""

from __future__ import annotations

import json
from pathlib import Path

from solver.core.partition import Configuration
from solver.core.solution import Solution
from solver.errors import InputError
from solver.files.atomic import write_all_atomic
from solver.layouts.foxglove import foxglove_layout, layout_filename, validate_foxglove
from solver.layouts.profile import Profile
from solver.layouts.rviz import rviz_layout, rviz_text, validate_rviz

__all__ = ["FORMATS", "write_layouts"]

FORMATS = ("foxglove", "rviz")


def write_layouts(
    solution: Solution, profile: Profile, directory: str | Path, fmt: str = "foxglove"
) -> list[Path]:
    """Validate every layout, then write them all atomically; the written paths in order."""
    if fmt not in FORMATS:
        raise InputError.at(
            "--format", f"unknown layout format {fmt!r}; known: " + ", ".join(FORMATS)
        )
    extension = "json" if fmt == "foxglove" else "rviz"
    numbered: list[tuple[str, Configuration | None]] = [
        (layout_filename(c.number, extension=extension), c) for c in solution.configurations
    ]
    numbered.append(
        (layout_filename(solution.default_configuration, default=True, extension=extension), None)
    )
    files: dict[str | Path, str] = {}
    for name, configuration in numbered:
        if fmt == "foxglove":
            layout = foxglove_layout(solution, configuration, profile)
            validate_foxglove(layout, name)
            text = json.dumps(layout, indent=2, sort_keys=True) + "\n"
        else:
            text = rviz_text(rviz_layout(solution, configuration, profile))
            validate_rviz(text, name)
        files[Path(directory) / name] = text
    Path(directory).mkdir(parents=True, exist_ok=True)
    return write_all_atomic(files)
