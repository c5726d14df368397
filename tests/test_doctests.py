"""The examples in the package's docstrings run, and print what they say."""

from __future__ import annotations

import doctest
import importlib
import pkgutil
from pathlib import Path

import pytest

import solver

ROOT = Path(__file__).resolve().parent.parent


def modules_with_examples() -> list[str]:
    names = ["solver"]
    for module_info in pkgutil.walk_packages(solver.__path__, "solver."):
        # __main__ runs the command line on import; the ROS 2 source needs rclpy.
        if module_info.name.endswith("__main__") or module_info.name.startswith(
            "solver.live.sources.ros2"
        ):
            continue
        names.append(module_info.name)
    found = []
    for name in names:
        module = importlib.import_module(name)
        if any(test.examples for test in doctest.DocTestFinder().find(module)):
            found.append(name)
    return found


@pytest.mark.parametrize("name", modules_with_examples())
def test_docstring_examples_run(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    # The examples name shipped files relative to the repository, as the docs do.
    monkeypatch.chdir(ROOT)
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0
    assert result.failed == 0
