"""Writing a team's layouts: one per UI configuration plus the default, validated first."""

from __future__ import annotations

from pathlib import Path

from solver.core.partition import Configuration
from solver.core.solution import Solution
from solver.files.atomic import make_folder, write_all_atomic
from solver.layouts.foxglove import layout_filename
from solver.layouts.presentation import Presentation
from solver.layouts.targets import TARGETS, target

__all__ = ["FORMATS", "write_layouts"]

FORMATS = tuple(TARGETS)


def write_layouts(
    solution: Solution, presentation: Presentation, directory: str | Path, fmt: str = "foxglove"
) -> list[Path]:
    """Validate every layout, then write them all atomically; the written paths in order."""
    chosen = target(fmt)
    numbered: list[tuple[str, Configuration | None]] = [
        (layout_filename(c.number, extension=chosen.extension), c) for c in solution.configurations
    ]
    numbered.append(
        (
            layout_filename(
                solution.default_configuration, default=True, extension=chosen.extension
            ),
            None,
        )
    )
    files: dict[str | Path, str] = {
        Path(directory) / name: chosen.render(solution, configuration, presentation, file=name)
        for name, configuration in numbered
    }
    make_folder(directory)
    return write_all_atomic(files)
