"""The guarded evaluator: values in, values out; no module, frame or code object reachable."""

from __future__ import annotations

import math
import os
import types
from typing import Any

import pytest

from solver.identify.xacro.expressions import GuardError, no_vars, safe_eval, type_of


def load_yaml(name: str) -> str:
    """Stands for a function xacro exposes: its globals hold ``os``."""
    return name


def names() -> dict[str, Any]:
    python = types.SimpleNamespace(
        len=len, range=range, sorted=sorted, str=str, type=type_of, vars=no_vars
    )
    return {
        "python": python,
        "xacro": types.SimpleNamespace(load_yaml=load_yaml, modules=types.SimpleNamespace(os=os)),
        "math": types.SimpleNamespace(pi=math.pi),
        "prefix": "left",
        "d": {"a": 1, "__globals__": 2},
    }


@pytest.mark.parametrize(
    ("expression", "value"),
    [
        ("1 + 2 * 3", 7),
        ("prefix + '_wheel'", "left_wheel"),
        ("'%s_link' % prefix", "left_link"),
        ("'{}_{:.2f}'.format(prefix, math.pi)", "left_3.14"),
        ("'{0[a]}'.format(d)", "1"),
        ("python.str.format('{}!', prefix)", "left!"),
        ("f'{prefix}_{d[\"a\"]:03d}'", "left_001"),
        ("python.len([x for x in python.range(4) if x % 2])", 2),
        ("[0 for _ in python.range(2)]", [0, 0]),
        ("(lambda q: q * 2)(3)", 6),
        ("python.type(1) == int", True),
        ("python.sorted(d)[0]", "__globals__"),
        ("prefix.upper()", "LEFT"),
    ],
)
def test_expressions_of_real_descriptions_evaluate_as_before(expression: str, value: Any) -> None:
    assert safe_eval(expression, {"int": int, **names()}) == value


ESCAPES = {
    "dunder-name": "__import__('os')",
    "builtins": "__builtins__",
    "underscore-attribute": "prefix._x",
    "dunder-attribute": "load_yaml.__globals__",
    "vars": "python.vars(python.type(xacro.load_yaml))['__globals__']",
    "class-building-type": "python.type('X', (), {})",
    "module-value": "xacro.modules.os",
    "generator-frame": "(x for x in [1]).gi_frame",
    "frame-globals": "python.len.f_globals",
    "format-attribute": "'{0.__globals__}'.format(xacro.load_yaml)",
    "format-item": "'{0[__globals__]}'.format(d)",
    "nested-format": "'{0:{1.__class__}}'.format(1, 2)",
    "unbound-format": "python.str.format('{0.__class__}', 1)",
    "format-map": "'{x.__class__}'.format_map(d)",
    "attribute-target": "[0 for python.len in [1]]",
    "item-target": "[0 for d['a'] in [1]]",
}


@pytest.mark.parametrize("expression", ESCAPES.values(), ids=ESCAPES.keys())
def test_every_known_way_out_is_refused(expression: str) -> None:
    with pytest.raises((GuardError, TypeError, KeyError)) as caught:
        safe_eval(expression, names())
    if not isinstance(caught.value, GuardError):
        # Refused by Python itself once the guard left nothing to reach with: a one-argument
        # type, a name that is not there.
        assert expression in (ESCAPES["class-building-type"], ESCAPES["builtins"])


def test_a_module_is_refused_whatever_the_attribute_is_called() -> None:
    with pytest.raises(GuardError, match="is a module"):
        safe_eval("xacro.modules.os", names())


def test_the_symbol_table_of_an_evaluation_gets_only_the_guard_as_builtins() -> None:
    table = names()
    safe_eval("1", table)
    assert sorted(table["__builtins__"]) == ["__teleop_attribute__"]
