"""The viewers' rules as shipped data: ``lichtblick.yaml`` and ``rviz2.yaml`` beside this module,
and the project's own limits for a layout an operator reads, ``quality.yaml``.

Each file names the upstream source and commit it was read from; this module only loads them
(once per process: they are the package's own files and never change while it runs) and walks
the small type language they use for config values. Not here: what a layout must satisfy
(:mod:`solver.layouts.checks.lichtblick`, :mod:`solver.layouts.checks.rviz`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any

from solver.files.yamlio import load_document
from solver.untrusted import shown

__all__ = [
    "FIELD_REFERENCE_HELP",
    "field_values",
    "lichtblick_rules",
    "quality_rules",
    "rviz_rules",
    "type_problems",
]

_HERE = Path(__file__).resolve().parent
FIELD_REFERENCE_HELP = "a.b: key b of a; a.{}: every key of map a; a.[]: every item of list a"


@functools.cache
def lichtblick_rules() -> Mapping[str, Any]:
    """``lichtblick.yaml``: layout shape, panel types, per-panel config types and defaults."""
    return load_document(_HERE / "lichtblick.yaml").data  # type: ignore[no-any-return]  # YAML data is Any


@functools.cache
def quality_rules() -> Mapping[str, Any]:
    """``quality.yaml``: the screen and the limits a layout for an operator meets."""
    return load_document(_HERE / "quality.yaml").data  # type: ignore[no-any-return]  # YAML data is Any


@functools.cache
def rviz_rules() -> Mapping[str, Any]:
    """``rviz2.yaml``: file sections, display and tool classes, their messages and properties."""
    return load_document(_HERE / "rviz2.yaml").data  # type: ignore[no-any-return]  # YAML data is Any


def type_problems(value: Any, spec: Any, path: str) -> Iterator[tuple[str, str]]:
    """(path, problem) for every place ``value`` is not of the data file's type ``spec``.

    ``topic`` and ``path`` are strings here; what they must spell is checked by the callers.
    """
    if isinstance(spec, str):
        if not _scalar_fits(value, spec):
            yield path, f"must be {_article(spec)} (got {_kind(value)})"
        return
    if not isinstance(spec, Mapping) or len(spec) != 1:
        raise ValueError(f"bad type in the rules data: {spec!r}")
    ((form, inner),) = spec.items()
    check = _FORMS.get(form)
    if check is None:
        raise ValueError(f"bad type form in the rules data: {form!r}")
    yield from check(value, inner, path)


def _enum(value: Any, choices: Any, path: str) -> Iterator[tuple[str, str]]:
    if not any(type(value) is type(choice) and value == choice for choice in choices):
        allowed = ", ".join(repr(choice) for choice in choices)
        yield path, f"must be one of {allowed} (got {_kind(value)})"


def _either(value: Any, options: Any, path: str) -> Iterator[tuple[str, str]]:
    if all(any(True for _ in type_problems(value, option, path)) for option in options):
        yield path, f"must be one of: {', '.join(_describe(o) for o in options)}"


def _list(value: Any, item_spec: Any, path: str) -> Iterator[tuple[str, str]]:
    if not isinstance(value, list):
        yield path, f"must be a list (got {_kind(value)})"
        return
    for index, item in enumerate(value):
        yield from type_problems(item, item_spec, f"{path}[{index}]")


def _tuple(value: Any, item_specs: Any, path: str) -> Iterator[tuple[str, str]]:
    if not isinstance(value, list) or len(value) != len(item_specs):
        yield path, f"must be a list of {len(item_specs)} (got {_kind(value)})"
        return
    for index, (item, item_spec) in enumerate(zip(value, item_specs, strict=True)):
        yield from type_problems(item, item_spec, f"{path}[{index}]")


def _map(value: Any, item_spec: Any, path: str) -> Iterator[tuple[str, str]]:
    if not isinstance(value, dict):
        yield path, f"must be an object (got {_kind(value)})"
        return
    for key, item in value.items():
        yield from type_problems(item, item_spec, f"{path}.{shown(key)}")


def _object(value: Any, keys: Any, path: str, *, closed: bool = True) -> Iterator[tuple[str, str]]:
    if not isinstance(value, dict):
        yield path, f"must be an object (got {_kind(value)})"
        return
    for key, item in value.items():
        if key in keys:
            yield from type_problems(item, keys[key], f"{path}.{key}")
        elif closed:
            known = ", ".join(sorted(keys))
            yield f"{path}.{shown(key)}", f"is not a key the viewer reads (it reads: {known})"


def _open(value: Any, keys: Any, path: str) -> Iterator[tuple[str, str]]:
    return _object(value, keys, path, closed=False)


_FORMS: dict[str, Callable[[Any, Any, str], Iterator[tuple[str, str]]]] = {
    "enum": _enum,
    "either": _either,
    "list": _list,
    "tuple": _tuple,
    "map": _map,
    "object": _object,
    "open": _open,
}


def field_values(config: Any, reference: str) -> Iterator[tuple[str, Any]]:
    """(path, value) of every value a field reference names in ``config`` (see the data files).

    ``a.{}`` yields the keys of map ``a`` (a topic named by a key); missing parts yield nothing.
    """
    found: list[tuple[str, Any]] = [("", config)]
    parts = reference.split(".")
    for index, part in enumerate(parts):
        step: list[tuple[str, Any]] = []
        for path, value in found:
            if part == "{}" and isinstance(value, dict):
                # The keys themselves are the values (topics named by map keys).
                step.extend((f"{path}.{shown(key)}" if path else shown(key), key) for key in value)
            elif part == "[]" and isinstance(value, list):
                step.extend((f"{path}[{i}]", item) for i, item in enumerate(value))
            elif isinstance(value, dict) and part in value:
                step.append((f"{path}.{part}" if path else part, value[part]))
        found = step
        if part == "{}" and index != len(parts) - 1:
            raise ValueError(f"'{{}}' must end a field reference: {reference!r}")
    yield from found


def _scalar_fits(value: Any, kind: str) -> bool:
    if kind == "any":
        return True
    if kind in ("string", "topic", "path"):
        return isinstance(value, str)
    if kind == "number":
        # JSON numbers; a bool is not one (Python's bool is an int).
        return (
            isinstance(value, (int, float))
            and not isinstance(value, bool)
            and not (isinstance(value, float) and not math.isfinite(value))
        )
    if kind == "boolean":
        return isinstance(value, bool)
    if kind == "null":
        return value is None
    raise ValueError(f"bad scalar type in the rules data: {kind!r}")


def _kind(value: Any) -> str:
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "an object"
    return "null" if value is None else type(value).__name__


def _article(kind: str) -> str:
    names = {"topic": "a topic name (string)", "path": "a message path (string)", "null": "null"}
    if kind in names:
        return names[kind]
    return ("an " if kind[0] in "aeiou" else "a ") + kind


def _describe(spec: Any) -> str:
    if isinstance(spec, str):
        return _article(spec)
    ((form, _inner),) = spec.items()
    names = {"list": "a list", "map": "an object", "object": "an object", "open": "an object"}
    return names.get(str(form), str(form))
