"""The xacro sandbox: compiling a trusted ``.xacro`` file, a security boundary of its own.

Compiling xacro runs Python written in the file, so it happens only when the user trusts the
file (``--trust-xacro``), and then in a confined child process. Everything on either side of
that boundary lives here, and nothing else does:

===============  ============================================================================
``compiler``     the parent: when a file is xacro, starting the child, limits, reading its answer
``packages``     ``$(find pkg)``: ROS packages found with no ROS install (also the child's roots)
``child``        the child: resource limits, the file fence, ``$(env)`` refused, the compilation
``expressions``  the child's guard on ``${...}`` and ``$(eval ...)``: no module reachable
``confine``      the child's kernel fences (Landlock, seccomp), raw system calls through ctypes
===============  ============================================================================

What ``--trust-xacro`` guarantees and what it does not is documented in docs/security.md.
"""

from solver.identify.xacro.compiler import (
    CompiledXacro,
    XacroLimits,
    compile_xacro,
    is_xacro,
    uncompiled_xacro,
)
from solver.identify.xacro.packages import PACKAGE_PATH_ENV, find_packages, package_path_from_env

__all__ = [
    "PACKAGE_PATH_ENV",
    "CompiledXacro",
    "XacroLimits",
    "compile_xacro",
    "find_packages",
    "is_xacro",
    "package_path_from_env",
    "uncompiled_xacro",
]
