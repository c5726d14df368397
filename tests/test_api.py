"""The public API: small, explicit, lazily loaded, and consistent with itself."""

from __future__ import annotations

import ast
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import solver
from tests.conftest import ROOT


def test_every_exported_name_resolves_from_its_module() -> None:
    for name in solver.__all__:
        value = getattr(solver, name)
        assert value is getattr(sys.modules[solver._EXPORTS[name]], name)


def _checker_imports(package: str) -> dict[str, str | None]:
    """What ``package``'s ``if TYPE_CHECKING:`` block imports: {name: module}."""
    path = ROOT / Path(*package.split(".")) / "__init__.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    guarded = next(node for node in tree.body if isinstance(node, ast.If))
    return {
        alias.name: node.module
        for node in guarded.body
        if isinstance(node, ast.ImportFrom)
        for alias in node.names
    }


def test_the_type_checking_imports_match_the_lazy_exports() -> None:
    imported = _checker_imports("solver")
    assert imported == solver._EXPORTS
    assert solver.__all__ == sorted(imported)


def test_importing_the_package_loads_no_heavy_dependency() -> None:
    heavy = ("numpy", "sympy", "matplotlib", "constraint", "lxml", "rich")
    code = (
        f"import sys, solver, solver.cli; print(sorted(m for m in {heavy!r} if m in sys.modules))"
    )
    loaded = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.strip()
    assert loaded == "[]"


def test_importing_every_module_keeps_the_functions_the_package_exports() -> None:
    import importlib
    import pkgutil

    for module in pkgutil.walk_packages(solver.__path__, "solver."):
        if not module.name.endswith("__main__"):  # running it would start the CLI
            importlib.import_module(module.name)
    assert callable(solver.solve)
    assert callable(solver.assign)


@pytest.mark.parametrize("package", ["solver.identify", "solver.identify.xacro"])
def test_a_wing_loaded_lazily_exports_each_name_from_the_module_its_checker_imports(
    package: str,
) -> None:
    module = importlib.import_module(package)
    imported = _checker_imports(package)
    assert imported == module._EXPORTS
    assert set(imported) <= set(module.__all__)
    for name, source in module._EXPORTS.items():
        assert getattr(module, name) is getattr(sys.modules[source], name)
