"""ROS 1's xacro tags without the ``xacro:`` prefix, read as ROS 1's xacro (1.13 and older,
Melodic's) read them; xacro 2 (the compiler the sandbox runs) leaves them in the output.

Descriptions written before the prefix was required call their macros as plain elements
(``<quadrotor_base_macro/>``) and write ``<property>``, ``<macro>``, ``<include filename>``,
``<insert_block>``, ``<arg>``, ``<if>`` and ``<unless>``. Left as they are, the robot's links
and sensors inside those macros silently vanish from the URDF. So, in the child, every
document xacro parses (the file and each file it includes) has those keyword tags renamed
when they carry the attributes only xacro's own tag has (an SDF ``<include>`` names its model
by a ``<uri>`` child, never ``filename``); and an element that names a macro defined by then
is called as that macro where a robot's parts are written (in ``<robot>``, a macro's body or
an ``if``), unless it is one of URDF's own elements there (``link``, ``joint``, ``gazebo``,
...); inside a ``<gazebo>`` block, SDF's elements keep their names (``<light>``, ``<camera>``:
a macro named like one is called with the prefix only, as xacro 2 does). Each tag so read
is a warning (once per tag), as ROS 1's xacro gave.
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
# Where a robot's parts are written: a macro call stands there (SDF's elements, inside a
# <gazebo> block, have names macros take too: <light>, <camera>).
_PLACES = frozenset({"robot", "xacro:macro", "xacro:if", "xacro:unless"})
# URDF's own elements at those places: never read as a macro call unprefixed.
_ELEMENTS = frozenset({"link", "joint", "transmission", "gazebo", "material", "ros2_control"})


def install(xacro: Any) -> None:
    """Read unprefixed tags in every document ``xacro`` parses and every macro call it
    makes (see the module docstring)."""
    parse: Callable[..., Any] = xacro.parse
    call: Callable[..., bool] = xacro.handle_macro_call
    warned: set[str] = set()

    def read_as_xacro(node: Any, what: str) -> None:
        tag = node.tagName
        node.tagName = node.nodeName = f"xacro:{tag}"
        if tag not in warned:
            warned.add(tag)
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
        if _legacy_call(node) and _defined(xacro, tag, macros, symbols):
            read_as_xacro(node, "a macro call")
        return call(node, macros, symbols)

    xacro.parse = legacy_parse
    xacro.handle_macro_call = legacy_call


def _legacy_call(node: Any) -> bool:
    """``node`` may be a macro call written without the prefix: an unprefixed element, not
    URDF's own, where a robot's parts are written."""
    tag = node.tagName
    parent = getattr(node.parentNode, "tagName", None)
    return ":" not in tag and tag not in _ELEMENTS and parent in _PLACES


def _defined(xacro: Any, name: str, macros: Any, symbols: Any) -> bool:
    try:
        xacro.resolve_macro(name, macros, symbols)
    except (KeyError, TypeError):
        return False
    return True


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
