"""Packages that load what they export on first use (solver.lazy): a name is imported from its
module the first time it is asked for and kept, an unknown name is an AttributeError, and
``dir()`` lists what the package holds and what it can load."""

from __future__ import annotations

import json
import types
from typing import Any

import pytest

from solver.lazy import load, names

EXPORTS = {"dumps": "json", "SimpleNamespace": "types"}


def package() -> dict[str, Any]:
    return {"__name__": "example", "__doc__": None}


def test_a_name_is_imported_from_its_module_on_first_use_and_kept() -> None:
    namespace = package()
    assert load(namespace, EXPORTS, "dumps") is json.dumps
    assert namespace["dumps"] is json.dumps  # the next use finds it without asking again
    assert "SimpleNamespace" not in namespace  # nothing else was loaded


def test_a_name_the_package_does_not_export_is_no_attribute() -> None:
    with pytest.raises(AttributeError, match="module 'example' has no attribute 'loads'"):
        load(package(), EXPORTS, "loads")


def test_dir_lists_what_the_package_holds_and_what_it_can_load() -> None:
    namespace = package()
    namespace["SimpleNamespace"] = types.SimpleNamespace
    assert names(namespace, EXPORTS) == ["SimpleNamespace", "__doc__", "__name__", "dumps"]
