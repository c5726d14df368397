"""What an expression in a trusted xacro file may reach: values, never a module, frame or code.

xacro evaluates ``${...}`` and ``$(eval ...)`` with Python's ``eval``. Its own checks are a name
filter (no ``__`` in the compiled names), and ``$(eval)`` runs with all of Python's builtins;
both are escaped in one line: ``python.vars(...)['__globals__']`` reaches xacro's module globals,
``exec(bytes.fromhex(...))`` runs anything, and from there ``__import__`` hands out every loaded
module (ctypes among them). In the child that compiles a trusted file
(:mod:`solver.identify.xacro.child`), :func:`install` replaces both evaluators with
:func:`safe_eval`, which

* parses the expression (:mod:`ast`) and refuses, before anything runs, a name starting with
  ``__``, an attribute starting with ``_`` or naming interpreter internals (``gi_frame``,
  ``f_globals``, ``tb_frame``...), and any assignment to an attribute or item;
* reads every attribute through a guard that also refuses, whatever its name, a value that is a
  module, frame, code object or traceback, and hands out ``str.format`` / ``format_map`` only
  for format strings that name no attribute or item starting with ``_``;
* gives ``$(eval ...)`` the builtins xacro documents for ``${...}`` (``len``, ``str``, ``range``,
  ``sorted``...) instead of all of Python's, and both ``type`` with one argument only (three
  build a class) and a ``vars`` that refuses (it hands out ``__dict__``, keyed by strings).

What holds: from an expression, no module object is reachable, so neither ``__import__`` nor
``ctypes``, ``os`` or ``_io``, and no function's globals; files are opened only through the
child's fenced ``open`` (``xacro.load_yaml``, includes). What is still possible: any
computation on values (bounded by the child's CPU and memory limits), and reading what the
fenced ``open`` allows. The kernel fences (:mod:`solver.identify.xacro.confine`) hold even if
this guard is escaped.

Not here: the file fence, the resource limits and the kernel fences
(:mod:`solver.identify.xacro.child`, :mod:`solver.identify.xacro.confine`).
"""

from __future__ import annotations

import ast
import builtins
import functools
import re
import string
import types
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["GuardError", "compile_guarded", "install", "safe_eval"]


class GuardError(Exception):
    """An expression reaching for what the guard refuses; reported as the compile error."""


# Attributes that lead from a value to the interpreter's internals, whatever their owner.
_INTERNALS = frozenset(
    {
        "ag_await",
        "ag_code",
        "ag_frame",
        "cr_await",
        "cr_code",
        "cr_frame",
        "cr_origin",
        "f_back",
        "f_builtins",
        "f_code",
        "f_globals",
        "f_locals",
        "f_trace",
        "gi_code",
        "gi_frame",
        "gi_yieldfrom",
        "tb_frame",
        "tb_next",
    }
)
_FORBIDDEN_VALUES = (types.ModuleType, types.FrameType, types.CodeType, types.TracebackType)
_FORMATTERS = ("format", "format_map")
_FIELD_PARTS = re.compile(r"[.\[\]]")

# The builtins xacro exposes to ${...} (its "python" namespace), for $(eval ...) too.
_EXPOSED = (
    "abs",
    "all",
    "any",
    "bool",
    "complex",
    "dict",
    "divmod",
    "enumerate",
    "filter",
    "float",
    "frozenset",
    "hash",
    "int",
    "isinstance",
    "issubclass",
    "len",
    "list",
    "map",
    "max",
    "min",
    "ord",
    "range",
    "repr",
    "reversed",
    "round",
    "set",
    "slice",
    "sorted",
    "str",
    "sum",
    "tuple",
    "zip",
)

_ATTRIBUTE = "__teleop_attribute__"  # names starting with "__" are refused in expressions


def type_of(value: object) -> type:
    """``type`` with one argument: what a value is, never a new class."""
    return type(value)


def no_vars(*_: object) -> None:
    """``vars`` refused: it hands out ``__dict__``, whose keys reach what names may not."""
    raise GuardError("vars(): refused in a xacro expression")


def _check_format(text: object) -> None:
    """Refuse a format string whose fields reach for attributes or items starting with ``_``.

    A format field reads attributes and items by name (``{0.__class__}``): every part of every
    field, nested format specifications included, is checked as an attribute would be.
    """
    if not isinstance(text, str):
        return
    for _, field, spec, _ in string.Formatter().parse(text):
        parts = _FIELD_PARTS.split(field or "")
        if any(part.startswith("_") or part in _INTERNALS for part in parts):
            raise GuardError(f"format field {field!r}: refused in a xacro expression")
        if spec:
            _check_format(spec)


def _format_checked(method: Callable[..., Any]) -> Callable[..., Any]:
    def checked(text: object, *args: Any, **kwargs: Any) -> Any:
        _check_format(text)
        return method(text, *args, **kwargs)

    return checked


def _attribute(value: object, name: str) -> Any:
    """``value.name`` as an expression may read it (see the module docstring)."""
    if name.startswith("_") or name in _INTERNALS:
        raise GuardError(f"attribute {name!r}: refused in a xacro expression")
    found = getattr(value, name)
    if isinstance(found, _FORBIDDEN_VALUES):
        raise GuardError(f"attribute {name!r} is a {type(found).__name__}: refused")
    if name in _FORMATTERS:
        if isinstance(value, str):
            _check_format(value)
        elif isinstance(value, type) and issubclass(value, str):
            return _format_checked(found)
    return found


class _Guard(ast.NodeTransformer):
    def visit_Name(self, node: ast.Name) -> ast.AST:
        if node.id.startswith("__"):
            raise GuardError(f"name {node.id!r}: refused in a xacro expression")
        return node

    def visit_arg(self, node: ast.arg) -> ast.AST:
        if node.arg.startswith("__"):
            raise GuardError(f"name {node.arg!r}: refused in a xacro expression")
        return node

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        if not isinstance(node.ctx, ast.Load):
            raise GuardError(f"assigning attribute {node.attr!r}: refused in a xacro expression")
        if node.attr.startswith("_") or node.attr in _INTERNALS:
            raise GuardError(f"attribute {node.attr!r}: refused in a xacro expression")
        value = self.visit(node.value)
        call = ast.Call(
            func=ast.Name(id=_ATTRIBUTE, ctx=ast.Load()),
            args=[value, ast.Constant(value=node.attr)],
            keywords=[],
        )
        return ast.copy_location(call, node)

    def visit_Subscript(self, node: ast.Subscript) -> ast.AST:
        if not isinstance(node.ctx, ast.Load):
            raise GuardError("assigning an item: refused in a xacro expression")
        self.generic_visit(node)
        return node


@functools.lru_cache(maxsize=4096)
def compile_guarded(expression: str) -> types.CodeType:
    """``expression`` compiled with every attribute read guarded; :class:`GuardError` if it
    names what the guard refuses, :class:`SyntaxError` if it is no expression."""
    tree = _Guard().visit(ast.parse(expression, "<expression>", "eval"))
    return compile(ast.fix_missing_locations(tree), "<expression>", "eval")


# Only the guard: ${...} finds xacro's own names in its symbol table, as xacro has it.
_GUARD_ONLY: dict[str, Any] = {_ATTRIBUTE: _attribute}
_EVAL_BUILTINS: dict[str, Any] = {
    **{name: getattr(builtins, name) for name in _EXPOSED},
    "type": type_of,
    _ATTRIBUTE: _attribute,
}


def safe_eval(
    expression: str, globals: dict[str, Any], locals: Mapping[str, Any] | None = None
) -> Any:
    """xacro's ``safe_eval``, guarded: the same names, nothing a module can be reached from."""
    code = compile_guarded(expression.strip())
    globals.update(__builtins__=_GUARD_ONLY)
    return eval(code, globals, locals)  # guarded above: see the module docstring


def install(xacro: Any, substitution_args: Any) -> None:
    """Replace xacro's two evaluators and take ``vars`` and class-building ``type`` away."""
    xacro.safe_eval = safe_eval
    python = xacro._global_symbols.get("python")
    if isinstance(python, dict):
        dict.__setitem__(python, "vars", no_vars)
        dict.__setitem__(python, "type", type_of)

    def guarded_eval(text: str, context: dict[str, Any]) -> str:
        context.setdefault("arg", {})

        def arg(name: str) -> Any:
            value = substitution_args._eval_arg(name, args=context["arg"])
            return substitution_args.convert_value(value, "auto")

        def dirname() -> Any:
            return substitution_args._eval_dirname(context["filename"])

        functions = {
            **{k: v for k, v in substitution_args._eval_dict.items() if not k.startswith("_")},
            "arg": arg,
            "dirname": dirname,
        }
        names = substitution_args._DictWrapper(context["arg"], functions)
        code = compile_guarded(text.strip())
        return str(eval(code, {"__builtins__": _EVAL_BUILTINS}, names))  # guarded

    substitution_args._eval = guarded_eval
