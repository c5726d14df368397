"""Packages that load what they export on first use (:pep:`562`'s module ``__getattr__``).

``solver``, ``solver.identify`` and ``solver.identify.xacro`` name each export's module in a
table, ``{name: module}``, and import the module the first time the name is asked for, so a
command loads only what it uses (``identify`` of a URDF never loads the solving stack). Their
type-checker imports, under ``TYPE_CHECKING``, list the same names from the same modules
(``tests/test_api.py`` keeps the two in step).
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from typing import Any

__all__ = ["load", "names"]


def load(namespace: dict[str, Any], exports: Mapping[str, str], name: str) -> Any:
    """Export ``name`` of the package whose globals are ``namespace``, imported from its
    module and kept in ``namespace`` (the next use finds it there); ``AttributeError`` when
    the package exports no such name."""
    module = exports.get(name)
    if module is None:
        raise AttributeError(f"module {namespace['__name__']!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    namespace[name] = value
    return value


def names(namespace: Mapping[str, Any], exports: Mapping[str, str]) -> list[str]:
    """What ``dir()`` of the package lists: what it holds and what it can load."""
    return sorted({*namespace, *exports})
