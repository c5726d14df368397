"""Writing a team's layouts into a folder: one per UI configuration plus the default's.

The folder is written as one unit: every layout is built and validated first, then all are
written atomically (:func:`~solver.files.atomic.write_all_atomic`), and the files an earlier
run wrote there that this run does not (``config-008.json`` of a team that now has seven
configurations, the ``.json`` layouts when ``.rviz`` ones are written, a ``preview.html``) are
removed, so no stale layout is left beside the new ones. Files of other names are never
touched. :class:`FolderWrite` says what was written, replaced and removed.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from solver.core.partition import Configuration
from solver.errors import InputError
from solver.files.atomic import Content, make_folder, write_all_atomic
from solver.layouts.foxglove import layout_filename
from solver.layouts.plan import Robot
from solver.layouts.presentation import Presentation
from solver.layouts.targets import TARGETS, target
from solver.limits import limit
from solver.solving.solution import Solution
from solver.untrusted import SHOWN_FILE_NAME_CHARS, shown

__all__ = [
    "FORMATS",
    "PREVIEW",
    "FolderWrite",
    "check_layout_count",
    "layout_texts",
    "write_layout_folder",
    "write_layouts",
]

FORMATS = tuple(TARGETS)
PREVIEW = "preview.html"
# The names of the files this module writes: an earlier run's are replaced or removed.
_OURS = re.compile(
    r"config-\d{3,}(-default)?\.("
    + "|".join(sorted({t.extension for t in TARGETS.values()}))
    + r")|"
    + re.escape(PREVIEW)
)


@dataclass(frozen=True)
class FolderWrite:
    """What one run did to the folder: the files written (layouts in configuration order,
    then the preview), those of them that were there before, and the earlier run's files
    no longer written, now removed (names, sorted)."""

    paths: tuple[Path, ...]
    replaced: tuple[str, ...]
    removed: tuple[str, ...]


def write_layouts(
    solution: Solution,
    presentation: Presentation,
    directory: str | Path,
    fmt: str = "foxglove",
    *,
    namespace: str | None = None,
) -> list[Path]:
    """Validate every layout, then write the folder as one unit; the layouts' paths in order."""
    return list(
        write_layout_folder(solution, presentation, directory, fmt, namespace=namespace).paths
    )


def write_layout_folder(
    solution: Solution,
    presentation: Presentation,
    directory: str | Path,
    fmt: str = "foxglove",
    *,
    namespace: str | None = None,
    preview: bool = False,
) -> FolderWrite:
    """Every configuration's layout for the robot under ``namespace`` (None: templates, see
    :mod:`solver.layouts.plan`), and with ``preview`` a page of their thumbnails
    (:data:`PREVIEW`, foxglove only), written into ``directory`` as one unit.

    More files than the ``written-files`` limit are refused before any layout is built.
    Without a preview each layout is built as its file is written, so the layouts are never
    all in memory and the ``written-bytes`` limit stops a team whose layouts would fill the
    disk; on any refusal no file is changed.
    """
    check_layout_count(len(solution.configurations), directory, extra=1 if preview else 0)
    folder = Path(directory)
    texts: dict[str, Content] = dict(layout_texts(solution, presentation, fmt, namespace))
    if preview:
        from solver.layouts.preview import preview_html

        # The preview draws every layout: these are built first, all of them.
        made = {name: "".join(text) for name, text in texts.items()}  # type: ignore[arg-type]  # layouts are text, never bytes
        made[PREVIEW] = preview_html([(name, json.loads(text)) for name, text in made.items()])
        texts = dict(made)
    make_folder(folder)
    before = _ours(folder)
    paths = write_all_atomic({folder / name: text for name, text in texts.items()}, within=folder)
    removed = sorted(before - set(texts))
    for name in removed:
        (folder / name).unlink(missing_ok=True)
    return FolderWrite(tuple(paths), tuple(sorted(before & set(texts))), tuple(removed))


def layout_texts(
    solution: Solution,
    presentation: Presentation,
    fmt: str = "foxglove",
    namespace: str | None = None,
) -> Iterator[tuple[str, Iterator[str]]]:
    """Each layout's file name and its text, in configuration order and the default's last;
    a text is built when it is read, so the layouts need never be all in memory at once."""
    chosen = target(fmt)
    robot = Robot(namespace)
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

    def built(name: str, configuration: Configuration | None) -> Iterator[str]:
        yield chosen.render(solution, configuration, presentation, file=name, robot=robot)

    for name, configuration in numbered:
        yield name, built(name, configuration)


def check_layout_count(configurations: int, directory: str | Path, *, extra: int = 0) -> None:
    """Refuse to write the layouts of ``configurations`` (and the default's, and ``extra``
    more files) when they are more files than the ``written-files`` limit."""
    limit("written-files").check(
        configurations + 1 + extra,
        str(directory),
        noun="files to write (a layout per UI configuration and the default's)",
    )


def _ours(folder: Path) -> set[str]:
    """The names in ``folder`` this module writes (regular files only)."""
    try:
        return {
            entry.name
            for entry in folder.iterdir()
            if _OURS.fullmatch(entry.name) and entry.is_file() and not entry.is_symlink()
        }
    except OSError as error:
        where = shown(str(folder), limit=SHOWN_FILE_NAME_CHARS)
        raise InputError.at(
            where, f"cannot read this folder: {error.strerror or error}", code="bad-output"
        ) from None
