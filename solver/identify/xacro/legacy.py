"""ROS 1's xacro tags without the ``xacro:`` prefix, read as ROS 1's xacro (1.13 and older,
Melodic's) read them; xacro 2 (the compiler the sandbox runs) leaves them in the output.

Descriptions written before the prefix was required call their macros as plain elements
(``<quadrotor_base_macro/>``) and write ``<property>``, ``<macro>``, ``<include filename>``,
``<insert_block>``, ``<arg>``, ``<if>`` and ``<unless>``. Left as they are, the robot's links
and sensors inside those macros silently vanish from the URDF. So, in the child, every
document xacro parses (the file and each file it includes) has those keyword tags renamed
when they carry the attributes only xacro's own tag has (an SDF ``<include>`` names its model
by a ``<uri>`` child, never ``filename``); and an element that names a macro defined by then
is called as that macro, wherever it is, when it is written as a call of it: its attributes
are the macro's parameters (every one without a default among them), and it holds elements
only when the macro takes blocks. An element of another language a macro is named like (SDF's
``<light name type>`` inside ``<gazebo>``, a ``<camera>`` and its settings) does not fit and
keeps its name, and URDF's own elements (``link``, ``sensor``, ``plugin``, ...) are never
calls: a macro named like one is called with the prefix only, as xacro 2 does. Each tag so
read is a warning (once per tag, the first ten named), as ROS 1's xacro gave.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

__all__ = ["install"]

# Keyword tags and the attributes only xacro's own tag of that name carries.
_KEYWORDS: dict[str, tuple[str, ...]] = {
    "property": ("name",),
    "macro": ("name",),
    "include": ("filename",),
    "insert_block": ("name",),
    "arg": ("name", "default"),
    "if": ("value",),
    "unless": ("value",),
}
# URDF's own elements: never read as a macro call unprefixed (a modern file may name a
# macro ``sensor`` and write URDF sensors beside it).
_ELEMENTS = frozenset(
    {
        "robot", "link", "joint", "transmission", "gazebo", "material", "ros2_control",
        "sensor", "plugin", "visual", "collision", "inertial", "origin", "geometry",
    }
)  # fmt: skip
# At most this many tags are named in warnings (the child keeps 100 warnings in all).
_WARNED_TAGS = 10


def install(xacro: Any) -> None:
    """Read unprefixed tags in every document ``xacro`` parses and every macro call it
    makes (see the module docstring)."""
    parse: Callable[..., Any] = xacro.parse
    call: Callable[..., bool] = xacro.handle_macro_call
    warned: set[str] = set()

    def read_as_xacro(node: Any, what: str) -> None:
        tag = node.tagName
        node.tagName = node.nodeName = f"xacro:{tag}"
        if tag in warned or len(warned) > _WARNED_TAGS:
            return
        warned.add(tag)
        if len(warned) > _WARNED_TAGS:
            print("deprecated: more xacro tags without the 'xacro:' prefix", file=sys.stderr)
            return
        print(
            f"deprecated: xacro tag '{tag}' without the 'xacro:' prefix read as {what}, "
            "as ROS 1's xacro (1.13 and older) read it",
            file=sys.stderr,
        )

    def legacy_parse(*args: Any, **kwargs: Any) -> Any:
        document = parse(*args, **kwargs)
        _rename_keywords(document, read_as_xacro)
        return document

    def legacy_call(node: Any, macros: Any, symbols: Any) -> bool:
        tag = node.tagName
        if ":" not in tag and tag not in _ELEMENTS:
            macro = _macro(xacro, tag, macros, symbols)
            if macro is not None and _fits(node, macro):
                read_as_xacro(node, "a macro call")
        return call(node, macros, symbols)

    xacro.parse = legacy_parse
    xacro.handle_macro_call = legacy_call


def _macro(xacro: Any, name: str, macros: Any, symbols: Any) -> Any:
    """The macro ``name`` defined by now, or None (a dotted name whose head is no namespace
    is none either)."""
    try:
        return xacro.resolve_macro(name, macros, symbols)[2]
    except (KeyError, TypeError):
        return None


def _fits(node: Any, macro: Any) -> bool:
    """``node`` is written as a call of ``macro``: its attributes are the macro's parameters,
    every parameter without a default among them, and it holds elements only when the macro
    takes blocks. An element of another language that a macro is named like (SDF's ``<light
    name type>``, ``<camera>`` and its settings) does not fit, and is left as it is."""
    blocks = [p for p in macro.params if p.startswith("*")]
    plain = {p for p in macro.params if not p.startswith("*")}
    given = set(node.attributes.keys())
    required = {p for p in plain if p not in macro.defaultmap}
    holds = any(child.nodeType == child.ELEMENT_NODE for child in node.childNodes)
    return given <= plain and required <= given and (bool(blocks) or not holds)


def _rename_keywords(node: Any, rename: Callable[[Any, str], None]) -> None:
    """``rename`` the unprefixed keyword tags beneath ``node`` (a DOM node), iteratively (a
    deep document does not reach the recursion limit)."""
    stack = [node]
    while stack:
        here = stack.pop()
        for child in here.childNodes:
            if child.nodeType != child.ELEMENT_NODE:
                continue
            needed = _KEYWORDS.get(child.tagName)
            if needed is not None and all(child.hasAttribute(a) for a in needed):
                rename(child, "a keyword")
            stack.append(child)
