"""The xacro sandbox: compiling a trusted ``.xacro`` file, a security boundary of its own.

Compiling xacro runs Python written in the file, so it happens only when the user trusts the
file (``--trust-xacro``), and then in a confined child process. Everything on either side of
that boundary lives here, and nothing else does:

===============  ============================================================================
``compiler``     the parent: starting the child, its limits, reading its answer
``packages``     ``$(find pkg)``: ROS packages found with no ROS install (also the child's roots)
``child``        the child: resource limits, the file fence, no environment read, the compilation
``legacy``       the child's reading of ROS 1's unprefixed xacro tags, as xacro 1.13 read them
``expressions``  the child's guard on ``${...}`` and ``$(eval ...)``: no module reachable
``confine``      the child's kernel fences (Landlock, seccomp), raw system calls through ctypes
===============  ============================================================================

What ``--trust-xacro`` guarantees and what it does not is documented in docs/security.md.
"""

# Loaded lazily (PEP 562): reading a package path (``$(find pkg)``, ``--package-path``) needs
# ``packages`` only, and a plain URDF never starts the compiler (nor its child process code).
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from solver.lazy import load as _load
from solver.lazy import names as _names

if TYPE_CHECKING:
    from solver.identify.xacro.compiler import CompiledXacro, XacroLimits, compile_xacro
    from solver.identify.xacro.packages import (
        PACKAGE_PATH_ENV,
        find_packages,
        package_path_from_env,
    )

_EXPORTS = {
    "CompiledXacro": "solver.identify.xacro.compiler",
    "PACKAGE_PATH_ENV": "solver.identify.xacro.packages",
    "XacroLimits": "solver.identify.xacro.compiler",
    "compile_xacro": "solver.identify.xacro.compiler",
    "find_packages": "solver.identify.xacro.packages",
    "package_path_from_env": "solver.identify.xacro.packages",
}

__all__ = [
    "PACKAGE_PATH_ENV",
    "CompiledXacro",
    "XacroLimits",
    "compile_xacro",
    "find_packages",
    "package_path_from_env",
]


def __getattr__(name: str) -> Any:
    return _load(globals(), _EXPORTS, name)


def __dir__() -> list[str]:
    return _names(globals(), _EXPORTS)
