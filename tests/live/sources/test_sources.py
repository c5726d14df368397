"""The graph sources are a family: neutral types in solver.live.graph, no source importing
another, and the watcher's machinery importing no source (but the default ROS 1 source, made
on demand when no source is given)."""

from __future__ import annotations

import ast
from pathlib import Path

from tests.conftest import ROOT

LIVE = ROOT / "solver" / "live"
SOURCES = ("ros1", "ros2")


def imported(path: Path, *, top_level_only: bool = False) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    nodes = tree.body if top_level_only else list(ast.walk(tree))
    names: set[str] = set()
    for node in nodes:
        if isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
        elif isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
    return names


def source_files(source: str) -> list[Path]:
    package = LIVE / "sources" / source
    return sorted(package.rglob("*.py")) if package.is_dir() else [package.with_suffix(".py")]


def test_no_source_imports_another() -> None:
    for source in SOURCES:
        others = [f"solver.live.sources.{other}" for other in SOURCES if other != source]
        for path in source_files(source):
            crossing = {
                name for name in imported(path) for other in others if name.startswith(other)
            }
            assert crossing == set(), f"{path.relative_to(ROOT)} imports {crossing}"


def test_the_shared_machinery_imports_no_source_at_module_level() -> None:
    """(That both sources are GraphSources is checked by mypy: the CLI's ``open_graph``
    returns either as one.) The package's ``__init__`` re-exports public names."""
    for path in sorted(LIVE.glob("*.py")):
        if path.name == "__init__.py":
            continue
        sources = {n for n in imported(path, top_level_only=True) if "solver.live.sources" in n}
        assert sources == set(), f"{path.relative_to(ROOT)} imports {sources}"
