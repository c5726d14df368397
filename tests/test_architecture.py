"""The package's shape: no import circles, wings that import only downwards, docs that match.

After pip-tools' ``test_circular_imports.py`` (every module imports on its own) with a static
check beside it: the import graph read from the source (imports inside functions included,
and ``if TYPE_CHECKING:`` blocks: a circle of annotations is a circle of concepts) has no
cycle, and a module of one wing imports only from its own wing or from the wings below it
(the package docstring of :mod:`solver` states the layers; docs/development.md draws them).
"""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import solver
from tests.conftest import ROOT

PACKAGE = ROOT / "solver"

# Lowest first; a wing may import from its own layer and every layer below it.
LAYERS: tuple[frozenset[str], ...] = (
    frozenset({"errors", "extras", "untrusted", "limits", "deadline", "lazy", "collector"}),
    frozenset({"files", "ros"}),
    frozenset({"core"}),
    frozenset({"engines", "check"}),
    frozenset({"solving"}),
    frozenset({"layouts", "identify"}),
    frozenset({"reporting"}),
    frozenset({"live"}),
    frozenset({"cli", "studio", "__main__"}),
)


def module_files() -> dict[str, Path]:
    """Every module of the package by dotted name (a package by its own name)."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        found[".".join(parts)] = path
    return found


def import_graph() -> dict[str, set[str]]:
    """Module -> the project modules it imports at run time (lazily or not)."""
    modules = module_files()

    def owner(name: str) -> str:
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name

    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imported: set[str] = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("solver"):
                base = node.module or ""
                imported.update(owner(f"{base}.{alias.name}") for alias in node.names)
            elif isinstance(node, ast.Import):
                imported.update(owner(a.name) for a in node.names if a.name.startswith("solver"))
        # The root package only re-exports lazily; a module's own packages are its parents.
        graph[name] = {
            m for m in imported if m not in ("", "solver", name) and not name.startswith(m + ".")
        }
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def wing(module: str) -> str:
    return module.split(".")[1]


def layer(name: str) -> int:
    return next(i for i, wings in enumerate(LAYERS) if name in wings)


def test_the_cycle_finder_finds_a_circle_of_three() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert cycles(graph) == [["a", "b", "c"]]


def test_no_module_imports_itself_back_through_others() -> None:
    assert cycles(import_graph()) == []


def test_every_wing_is_placed_in_a_layer() -> None:
    wings = {wing(m) for m in module_files() if m != "solver"}
    assert wings <= set().union(*LAYERS)


def test_wings_import_only_their_own_layer_or_lower_ones() -> None:
    upward = sorted(
        f"{module} -> {target}"
        for module, targets in import_graph().items()
        if module != "solver"
        for target in targets
        if layer(wing(target)) > layer(wing(module))
    )
    assert upward == []


def test_a_module_importing_a_higher_wing_would_be_found() -> None:
    # The layering check above must be able to fail: core importing the CLI is upward, and so
    # is the model or an engine importing solving (a back-edge between solving and engines).
    assert layer(wing("solver.cli.solve")) > layer(wing("solver.core.rules"))
    assert layer(wing("solver.solving.solution")) > layer(wing("solver.engines.structure"))
    assert layer(wing("solver.engines.structure")) > layer(wing("solver.core.partition"))


def test_every_module_imports_on_its_own_in_a_fresh_interpreter() -> None:
    # One interpreter, a clean slate of the package's modules before each import, so a module
    # that only works once another has been imported first (a hidden circle) fails here.
    # solver.__main__ runs the command line when imported: it is `python -m solver`.
    names = sorted(m for m in module_files() if m != "solver.__main__")
    script = (
        "import importlib, sys\n"
        "failed = []\n"
        f"for name in {names!r}:\n"
        "    for loaded in [m for m in sys.modules if m == 'solver' or m.startswith('solver.')]:\n"
        "        del sys.modules[loaded]\n"
        "    try:\n"
        "        importlib.import_module(name)\n"
        "    except (Exception, SystemExit) as error:\n"
        "        failed.append(f'{name}: {error!r}')\n"
        "print('\\n'.join(failed))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == ""


def test_the_package_docstring_names_every_wing() -> None:
    doc = solver.__doc__ or ""
    wings = {wing(m) for m in module_files() if m.count(".") == 1 and m != "solver.__main__"}
    missing = sorted(w for w in wings if f"``{w}``" not in doc)
    assert missing == []


def test_the_development_page_maps_only_modules_that_exist() -> None:
    page = (ROOT / "docs" / "development.md").read_text(encoding="utf-8")
    named = set(re.findall(r"`(solver(?:/[a-z_]+)+(?:\.py)?/?)`", page))
    assert named, "docs/development.md names no module"
    missing = sorted(n for n in named if not (ROOT / n.rstrip("/")).exists())
    assert missing == []
