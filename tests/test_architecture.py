"""The package's shape: no import circles, wings that import only downwards, docs that match.

After pip-tools' ``test_circular_imports.py`` (every module imports on its own) with a static
check beside it: the import graph read from the source (imports inside functions included,
and ``if TYPE_CHECKING:`` blocks: a circle of annotations is a circle of concepts) has no
cycle, and a module of one wing imports only from its own wing or from the wings below it
(the package docstring of :mod:`solver` states the layers; docs/development.md draws them);
and no command of the command line imports another command (:data:`solver.cli.COMMANDS`).
The tests mirror the package: every module has its tests/<wing path>/test_<module>.py, or an
entry in :data:`TESTED_ELSEWHERE` saying where it is tested.
"""

from __future__ import annotations

import ast
import functools
import re
import subprocess
import sys
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

import solver
from solver.cli import COMMANDS
from tests.conftest import ROOT

PACKAGE = ROOT / "solver"

# Lowest first; a wing may import from its own layer and every layer below it.
LAYERS: tuple[frozenset[str], ...] = (
    frozenset(
        {"errors", "extras", "untrusted", "limits", "deadline", "lazy", "collector", "addresses"}
    ),
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


def commands_importing_commands(graph: dict[str, set[str]], commands: set[str]) -> list[str]:
    """``a -> b`` for each command module ``a`` importing another command module ``b``."""
    return sorted(
        f"{module} -> {target}"
        for module in commands
        for target in graph.get(module, ())
        if target in commands
    )


def test_no_command_imports_another_command() -> None:
    # A command imports the library and the shared options (solver/cli/_*.py) only: what two
    # commands share is the library's, or a shared option's.
    commands = set(COMMANDS.values())
    assert commands <= set(module_files())
    assert commands_importing_commands(import_graph(), commands) == []


def test_a_command_importing_a_command_would_be_found() -> None:
    graph = {
        "solver.cli.assign": {"solver.cli._common", "solver.cli.watch", "solver.live"},
        "solver.cli.watch": {"solver.cli._common"},
    }
    commands = {"solver.cli.assign", "solver.cli.watch"}
    assert commands_importing_commands(graph, commands) == ["solver.cli.assign -> solver.cli.watch"]


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


# ---- tests mirror the package ----------------------------------------------------------------

# Modules whose tests live somewhere other than their own tests/<wing path>/test_<module>.py,
# and where. Short on purpose: a new module gets a test module of its own. An entry must name
# a module that needs tests and has no test module of its own yet, and a file that exists.
TESTED_ELSEWHERE: dict[str, str] = {
    # ``python -m solver``: the same command line as ``teleop-ui``, tested with main().
    "solver.__main__": "tests/cli/test_cli.py",
    # Packages whose code is their lazy exports or their lookup.
    "solver": "tests/test_api.py",
    "solver.engines": "tests/engines/test_lookup.py",
    "solver.identify": "tests/test_api.py",
    "solver.identify.xacro": "tests/test_api.py",
    # Child processes, run by the tests of the readers that start them.
    "solver.identify.readers.bag_child": "tests/identify/readers/test_bags.py",
    "solver.identify.xacro.child": "tests/identify/xacro/test_compiler.py",
    "solver.identify.xacro.legacy": "tests/identify/xacro/test_compiler.py",
    # Types tested where they are used.
    "solver.engines.shared": "tests/engines/test_structure.py",
    "solver.ros.joints": "tests/identify/test_joints.py",
    # The live watcher's pieces, on a real master or DDS graph.
    "solver.live.events": "tests/live/test_render.py",
    "solver.live.given": "tests/live/test_own_rules.py",
    "solver.live.graph": "tests/live/test_watcher.py",
    "solver.live.query": "tests/cli/test_assign.py",
    "solver.live.robot": "tests/live/test_selection.py",
    "solver.live.sources.ros1.descriptions": "tests/live/sources/ros1/test_node.py",
    "solver.live.sources.ros1.source": "tests/live/test_watcher.py",
    # The studio, through its server and its API.
    "solver.studio.app": "tests/studio/test_security.py",
    "solver.studio.findings": "tests/studio/test_api.py",
    "solver.studio.service": "tests/studio/test_api.py",
}


def mirrored_test(module: str) -> Path:
    """Where the tests of ``module`` live: ``tests/<wing path>/test_<name>.py``, a private
    module's ``_`` dropped (``solver.cli._common``: ``tests/cli/test_common.py``) and a package
    named inside its own folder (``solver.live.sources``: ``tests/live/sources/test_sources.py``).
    """
    *folders, name = module.split(".")
    if name.startswith("_") and not name.startswith("__"):
        name = name[1:]
    if module in packages():
        folders.append(name)
    return Path("tests", *folders[1:], f"test_{name}.py")


@functools.cache
def packages() -> frozenset[str]:
    """The package's packages (their ``__init__`` modules), by dotted name."""
    return frozenset(m for m, path in module_files().items() if path.name == "__init__.py")


def modules_to_test() -> list[str]:
    """Every module of the package; a package only when its ``__init__`` defines a function or
    a class (one that documents and re-exports is its modules' map, tested through them)."""
    found = []
    for name, path in module_files().items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        defines = any(
            isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
            for node in tree.body
        )
        if path.name != "__init__.py" or defines:
            found.append(name)
    return found


def untested(
    modules: Iterable[str], exists: Callable[[Path], bool], elsewhere: Mapping[str, str]
) -> list[str]:
    """The modules with no test module of their own and no entry in ``elsewhere``."""
    return sorted(m for m in modules if m not in elsewhere and not exists(mirrored_test(m)))


def stale(
    modules: Iterable[str], exists: Callable[[Path], bool], elsewhere: Mapping[str, str]
) -> list[str]:
    """The entries of ``elsewhere`` that say no more than the truth no longer: a module gone
    (or with nothing to test), a module with a test module of its own, a file that is not."""
    wanted = set(modules)
    return sorted(
        f"{module}: {where}"
        for module, where in elsewhere.items()
        if module not in wanted or exists(mirrored_test(module)) or not exists(Path(where))
    )


def in_repository(path: Path) -> bool:
    return (ROOT / path).is_file()


def test_every_module_has_its_test_module_or_says_where_it_is_tested() -> None:
    assert untested(modules_to_test(), in_repository, TESTED_ELSEWHERE) == []


def test_the_table_of_tests_elsewhere_names_only_modules_without_their_own() -> None:
    assert stale(modules_to_test(), in_repository, TESTED_ELSEWHERE) == []


def test_a_module_without_a_test_module_would_be_found() -> None:
    # The mirror check above must be able to fail: a new module of the model with no test
    # module, and a table entry left behind once a module has a test module of its own.
    present = {Path("tests/core/test_rules.py"), Path("tests/test_cli.py")}
    modules = ["solver.core.rules", "solver.core.novel", "solver.cli.solve"]
    table = {"solver.cli.solve": "tests/test_cli.py", "solver.core.rules": "tests/test_cli.py"}
    assert untested(modules, present.__contains__, table) == ["solver.core.novel"]
    assert stale(modules, present.__contains__, table) == ["solver.core.rules: tests/test_cli.py"]
    assert stale(modules, set().__contains__, {"solver.cli.solve": "tests/gone.py"}) == [
        "solver.cli.solve: tests/gone.py"
    ]


def test_a_modules_test_module_is_named_after_its_wing_path_and_its_name() -> None:
    assert mirrored_test("solver.core.rules") == Path("tests/core/test_rules.py")
    assert mirrored_test("solver.errors") == Path("tests/test_errors.py")
    assert mirrored_test("solver.cli._common") == Path("tests/cli/test_common.py")
    assert mirrored_test("solver.live.sources") == Path("tests/live/sources/test_sources.py")
    assert mirrored_test("solver.identify.readers.urdf") == Path(
        "tests/identify/readers/test_urdf.py"
    )
